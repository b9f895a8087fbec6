"""Sphinx extension: live cells that readers edit and run in the page (Pyodide in a Web Worker).

The one rule for "runs in the browser" lives here and is decided from the page's imports: a module runs
in the page when it is in the standard library, SymPy, mpmath, ``IPython.display`` (the page provides
a small replacement) or a pgsym module whose own imports, followed through the package, stay inside
that set. A cell runs in the page unless it uses a module that does not, directly or through a name
(``np`` after ``import numpy as np``, a function that calls it, a variable a cell that cannot run
assigned). The cell tags ``live`` and ``no-live`` override the rule.

Each code cell of a page gets the class ``live-cell-N`` (N its index among the page's code cells) and
the page gets a JSON description of its cells, which ``_static/live/live-cells.js`` turns into the
Edit / Run / Reset controls. Pages without code cells load nothing.
"""

from __future__ import annotations

import ast
import hashlib
import importlib.util
import json
import shutil
import sys
from functools import cache
from pathlib import Path
from typing import Any

from docutils import nodes
from sphinx.util import logging

logger = logging.getLogger(__name__)

# Third-party packages the page ships (as wheels, next to Pyodide) or replaces with a small shim.
BROWSER_PACKAGES = frozenset({"sympy", "mpmath", "pgsym"})
BROWSER_SHIMS = frozenset({"IPython", "IPython.display"})
FORCE_ON, FORCE_OFF = "live", "no-live"
HIDDEN = frozenset({"hide-input", "hide-cell", "remove-input"})
ASSETS = "_live/_static/live"  # built by `make live`, relative to the book's root
# The chapters' own modules (book/_show.py, book/_plot.py): those whose imports the page can load are
# copied to the page's Python with the wheels (`from _show import report` works in a live cell).
BOOK = Path(__file__).resolve().parents[1]
LOCAL = "modules"  # their folder below _static/live
# How the reason names a package a reader knows by another name.
# What a statement does with a package, for the reason a cell gives ("Draws with Matplotlib, ...").
VERBS = {"matplotlib": "Draws with", "mpl_toolkits": "Draws with", "numpy": "Computes with"}
PACKAGE_NAMES = {"numpy": "NumPy", "matplotlib": "Matplotlib", "mpl_toolkits": "Matplotlib", "cv2": "OpenCV",
                 "skimage": "scikit-image", "scipy": "SciPy", "PIL": "Pillow", "flint": "python-flint"}


def _module_level_imports(tree: ast.Module, package: str | None) -> list[str]:
    """Absolute names of the modules a module imports when it loads.

    Imports inside functions run later (pgsym loads NumPy lazily that way) and an import guarded by
    ``except ImportError`` is optional, so neither counts.
    """
    found: list[str] = []

    def visit(stmts: list[ast.stmt]) -> None:
        for stmt in stmts:
            if isinstance(stmt, ast.Import):
                found.extend(alias.name for alias in stmt.names)
            elif isinstance(stmt, ast.ImportFrom):
                base = stmt.module or ""
                if stmt.level:
                    parts = (package or "").split(".")
                    parts = parts[: len(parts) - stmt.level + 1]
                    base = ".".join([*parts, base] if base else parts)
                found.append(base)
                # `from pkg import sub` may name a submodule
                found.extend(f"{base}.{alias.name}" for alias in stmt.names if alias.name != "*")
            elif isinstance(stmt, ast.Try):
                optional = any(_catches_import_error(h) for h in stmt.handlers)
                if not optional:
                    visit(stmt.body)
                for handler in stmt.handlers:
                    visit(handler.body)
                visit(stmt.orelse)
                visit(stmt.finalbody)
            elif isinstance(stmt, ast.If):
                if not (isinstance(stmt.test, ast.Name) and stmt.test.id == "TYPE_CHECKING"):
                    visit(stmt.body)
                visit(stmt.orelse)
            elif isinstance(stmt, ast.ClassDef | ast.With):
                visit(stmt.body)

    visit(tree.body)
    return [name for name in found if name]


def _catches_import_error(handler: ast.ExceptHandler) -> bool:
    names = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
    return any(isinstance(n, ast.Name) and n.id in {"ImportError", "ModuleNotFoundError"} for n in names)


@cache
def _source(module: str) -> tuple[Path, bool] | None:
    """The file of a pgsym module and whether it is a package, found without importing anything."""
    spec = importlib.util.find_spec("pgsym")
    if spec is None or not spec.submodule_search_locations:
        return None
    path = Path(next(iter(spec.submodule_search_locations))).parent.joinpath(*module.split("."))
    if (path / "__init__.py").is_file():
        return path / "__init__.py", True
    if path.with_suffix(".py").is_file():
        return path.with_suffix(".py"), False
    return None  # `from pgsym import Point` names an attribute, not a module


@cache
def _direct_imports(module: str) -> tuple[str, ...]:
    """What a pgsym module imports when it loads; nothing for names that are not modules."""
    found = _source(module)
    if found is None:
        return ()
    path, is_package = found
    package = module if is_package else module.rpartition(".")[0]
    return tuple(_module_level_imports(ast.parse(path.read_text(encoding="utf-8")), package))


def _local(module: str) -> Path | None:
    """The file of one of the book's own modules (``_show``), or None."""
    path = BOOK / f"{module}.py"
    return path if "." not in module and path.is_file() else None


@cache
def _local_imports(module: str) -> tuple[str, ...]:
    path = _local(module)
    return tuple(_module_level_imports(ast.parse(path.read_text(encoding="utf-8")), None)) if path else ()


def local_modules() -> list[Path]:
    """The book's own modules that the page can load (they are copied next to the wheels)."""
    return [path for path in sorted(BOOK.glob("*.py")) if missing_package(path.stem) is None]


@cache
def missing_package(module: str) -> str | None:
    """The first package ``module`` needs at import time that the page cannot load, or None.

    >>> missing_package("pgsym.projective_plane"), missing_package("pgsym.numeric"), missing_package("cv2")
    (None, 'numpy', 'cv2')
    >>> missing_package("_show"), missing_package("_plot")
    (None, 'matplotlib')
    """
    seen: set[str] = set()
    todo = [module]
    while todo:
        name = todo.pop(0)  # in import order, so that the first package the module needs is named
        if name in seen:
            continue
        seen.add(name)
        top = name.split(".")[0]
        if top in sys.stdlib_module_names or name in BROWSER_SHIMS:
            continue
        if _local(top):  # the book's own module: it loads when what it imports does
            todo.extend(_local_imports(top))
            continue
        if top not in BROWSER_PACKAGES:
            return top
        if top == "pgsym":  # SymPy and mpmath are pure Python: the page has them whole
            todo.extend(_direct_imports(name))
    return None


def _names(node: ast.AST) -> tuple[set[str], set[str]]:
    """Names a statement binds, and names it reads that it did not bind first.

    Loop and comprehension variables and parameters are bound before they are read, so reading them
    does not count as using an earlier cell's name.
    """
    bound: set[str] = set()
    loaded: set[str] = set()
    local: set[str] = set()
    for sub in ast.walk(node):
        if isinstance(sub, ast.Name):
            (loaded if isinstance(sub.ctx, ast.Load) else bound).add(sub.id)
        elif isinstance(sub, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            bound.add(sub.name)
        elif isinstance(sub, ast.Import | ast.ImportFrom):
            bound.update((a.asname or a.name).split(".")[0] for a in sub.names if a.name != "*")
        elif isinstance(sub, ast.comprehension | ast.For | ast.AsyncFor):
            local.update(n.id for n in ast.walk(sub.target) if isinstance(n, ast.Name))
        elif isinstance(sub, ast.arg):
            local.add(sub.arg)
    return bound, loaded - local


def _imported(node: ast.AST) -> list[str]:
    """Every absolute module an import inside ``node`` may load (``from pgsym import s`` may load pgsym.s)."""
    modules: list[str] = []
    for sub in ast.walk(node):
        if isinstance(sub, ast.Import):
            modules.extend(a.name for a in sub.names)
        elif isinstance(sub, ast.ImportFrom) and sub.module and not sub.level:
            modules.append(sub.module)
            if sub.module.split(".")[0] == "pgsym":  # elsewhere the package decides for its parts
                modules.extend(f"{sub.module}.{a.name}" for a in sub.names if a.name != "*")
    return modules


def _import_bindings(stmt: ast.Import | ast.ImportFrom) -> list[tuple[str, str | None]]:
    """(module that must load, name bound to it or to one of its attributes) for each part of an import.

    ``import a.b`` binds ``a`` (None when ``a`` itself can load, as ``a.b`` is then reached through it).
    """
    if isinstance(stmt, ast.Import):
        out: list[tuple[str, str | None]] = []
        for alias in stmt.names:
            if alias.asname or "." not in alias.name:
                out.append((alias.name, alias.asname or alias.name))
            else:
                top = alias.name.split(".")[0]
                out.append((alias.name, top if missing_package(top) else None))
        return out
    module = stmt.module or ""
    out = []
    for alias in stmt.names:
        sub = f"{module}.{alias.name}"
        # `from pgsym import linalg` loads a submodule; `from pgsym import Point` an attribute
        target = sub if module.split(".")[0] == "pgsym" and _source(sub) else module
        out.append((target, None if alias.name == "*" else alias.asname or alias.name))
    return out


def _name(package: str) -> str:
    return PACKAGE_NAMES.get(package, package)


def _cannot(package: str) -> str:
    return f"{_name(package)}, which the page cannot load"


class _Taint:
    """Why a name cannot be used in the page: the package it needs and how it came to need it.

    ``module`` is set when an import bound the name: to the module itself (``np``, ``plt``, ``_plot``;
    ``attribute`` False) or to a name taken from it (``harris`` from ``pgsym.vision.harris``). A package
    of None means the name comes from a cell marked to run only locally.
    """

    def __init__(self, package: str | None, module: str | None = None, attribute: bool = False) -> None:
        self.package, self.module, self.attribute = package, module, attribute

    def reason(self, name: str) -> str:
        if self.package is None:
            return f"Uses {name}, which comes from a cell marked to run only locally"
        if self.module is None:
            return f"Uses {name}, which depends on {_cannot(self.package)}"
        if self.attribute:
            return f"Uses {name} from {self.module}, which needs {_cannot(self.package)}"
        verb = VERBS.get(self.package, "Uses")
        if self.module.split(".")[0] == self.package:
            return f"{verb} {_cannot(self.package)}"
        return f"{verb} {_name(self.package)} (through {self.module}), which the page cannot load"


def _mutated(node: ast.AST) -> set[str]:
    """Names a statement may change in place: receivers of method calls made for their effect
    (``pts.append(p)``, not ``H.det()`` inside an expression), targets of item and attribute stores."""
    out: set[str] = set()
    for sub in ast.walk(node):
        target = None
        call = sub.value if isinstance(sub, ast.Expr) else None
        if isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute):
            target = call.func.value
        elif isinstance(sub, ast.Subscript | ast.Attribute) and isinstance(sub.ctx, ast.Store | ast.Del):
            target = sub.value
        while isinstance(target, ast.Attribute | ast.Subscript):
            target = target.value
        if isinstance(target, ast.Name):
            out.add(target.id)
    return out


def classify_cells(cells: list[tuple[str, list[str]]]) -> list[dict[str, Any]]:
    """Decide for each ``(source, tags)`` of a page, in order, whether it runs in the browser.

    The decision is made statement by statement. An import does not stop a cell: the page binds
    ``np`` in ``import numpy as np`` to a placeholder module listed in ``stubs``, and only the statements
    that use such a name (or a name computed from one) cannot run. A cell runs in the page when all its
    statements can; otherwise its ``quiet`` code, the statements that can, runs silently in its place,
    so that the names it computes with SymPy and pgsym exist for the cells after it.

    >>> cells = classify_cells([("import numpy as np\\nfrom pgsym import Point", []), ("x = np.ones(3)", []),
    ...                         ("def f():\\n    return np.zeros(2)", []), ("f()", []), ("Point(1, 2)", [])])
    >>> [c["live"] for c in cells], cells[0]["stubs"]
    ([True, False, True, False, True], ['numpy'])
    >>> cells[1]["reason"]
    'Computes with NumPy, which the page cannot load'
    >>> cells[3]["reason"]
    'Uses f, which depends on NumPy, which the page cannot load'
    >>> classify_cells([("from cv2 import imread", ["live"])])[0]["live"]
    True
    >>> classify_cells([("1 + 1", ["no-live"])])[0]["reason"]
    'Marked to run only locally'
    >>> cells = classify_cells([
    ...     ("import matplotlib.pyplot as plt\\nimport sympy as sp\\nplt.rcParams['a'] = 1", []),
    ...     ("sp.Integer(2)", [])])
    >>> [c["live"] for c in cells], cells[0]["reason"]
    ([False, True], 'Draws with Matplotlib, which the page cannot load')
    >>> cells[0]["quiet"]
    'import matplotlib.pyplot as plt\\nimport sympy as sp'
    """
    tainted: dict[str, _Taint] = {}
    modules: set[str] = set()  # names an import bound to a module the page loads (sp, pgsym)
    result = []
    for source, tags in cells:
        reason: str | None = None
        stubs: list[str] = []
        runnable: list[ast.stmt] = []
        try:
            tree = ast.parse(source)
        except SyntaxError:
            tree = None
            reason = "Uses notebook-only syntax, which the page cannot run"
        statements = tree.body if tree is not None else []
        force_off = FORCE_OFF in tags
        for stmt in statements:
            bound, loaded = _names(stmt)
            if force_off:
                for name in bound | _mutated(stmt):
                    tainted[name] = _Taint(None)
                continue
            if isinstance(stmt, ast.Import | ast.ImportFrom) and not getattr(stmt, "level", 0):
                for module, name in _import_bindings(stmt):
                    if package := missing_package(module):
                        stubs.append(module)
                        if name:
                            tainted[name] = _Taint(package, module, isinstance(stmt, ast.ImportFrom))
                    elif name:
                        tainted.pop(name, None)
                        modules.add(name)
                runnable.append(stmt)
                continue
            package = next((p for p in map(missing_package, _imported(stmt)) if p), None)
            used = sorted(loaded & tainted.keys())
            if isinstance(stmt, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
                # defining runs; calling it needs what its body needs
                if package:
                    tainted[stmt.name] = _Taint(package)
                elif used:
                    tainted[stmt.name] = _Taint(tainted[used[0]].package)
                else:
                    tainted.pop(stmt.name, None)
                runnable.append(stmt)
                continue
            if package or used:
                why = f"Imports {_cannot(package)}" if package else tainted[used[0]].reason(used[0])
                reason = reason or why
                cause = package or tainted[used[0]].package
                # a module is not changed by calling its functions
                for name in bound | (_mutated(stmt) - modules):
                    if name in bound or name not in tainted:
                        tainted[name] = _Taint(cause)
                modules -= bound
                continue
            runnable.append(stmt)
            for name in bound:
                tainted.pop(name, None)
            modules -= bound
        if force_off:
            reason, runnable = "Marked to run only locally", []
        elif FORCE_ON in tags:
            reason = None
        quiet = ""
        if reason is not None:
            quiet = "\n".join(ast.get_source_segment(source, stmt) or "" for stmt in runnable)
        result.append({"source": source, "live": reason is None, "reason": reason or "",
                       "stubs": list(dict.fromkeys(stubs)), "quiet": quiet})
    return result


def _code_cells(doctree: nodes.document) -> list[nodes.container]:
    return [node for node in doctree.findall(nodes.container) if node.get("nb_element") == "cell_code"]


def _cell_source(cell: nodes.container) -> str:
    for block in cell.findall(nodes.literal_block):
        return block.astext()
    return ""


def _annotate(app: Any, doctree: nodes.document) -> None:
    cells = _code_cells(doctree)
    if not cells:
        return
    tags = [list((cell.get("cell_metadata") or {}).get("tags", [])) for cell in cells]
    decided = classify_cells([(_cell_source(cell), t) for cell, t in zip(cells, tags, strict=True)])
    for index, cell in enumerate(cells):
        cell["classes"].append(f"live-cell-{index}")
        # a cell whose code the reader does not see (the chapter's imports) runs with the others but
        # shows no controls
        decided[index]["hidden"] = bool(HIDDEN & set(tags[index]))
    env = app.env
    if not hasattr(env, "live_cells"):
        env.live_cells = {}
    env.live_cells[env.docname] = decided


def _fingerprint() -> str:
    """The rule's inputs besides the pages: this file, the book's modules and pgsym's sources."""
    digest = hashlib.sha256(Path(__file__).read_bytes())
    for path in sorted(BOOK.glob("*.py")):
        digest.update(path.read_bytes())
    found = _source("pgsym")
    if found is not None:
        for path in sorted(found[0].parent.rglob("*.py")):
            digest.update(path.read_bytes())
    return digest.hexdigest()


def _outdated(app: Any, env: Any, added: set[str], changed: set[str], removed: set[str]) -> list[str]:
    """Re-read every page with code cells when the rule or pgsym changed since the last build."""
    fingerprint = _fingerprint()
    if getattr(env, "live_cells_fingerprint", None) == fingerprint:
        return []
    env.live_cells_fingerprint = fingerprint
    return sorted(set(getattr(env, "live_cells", {})) - removed)


def _purge(app: Any, env: Any, docname: str) -> None:
    getattr(env, "live_cells", {}).pop(docname, None)


def _merge(app: Any, env: Any, docnames: set[str], other: Any) -> None:
    if not hasattr(env, "live_cells"):
        env.live_cells = {}
    env.live_cells.update({d: c for d, c in getattr(other, "live_cells", {}).items() if d in docnames})


def _page(app: Any, pagename: str, templatename: str, context: dict[str, Any], doctree: Any) -> None:
    cells = getattr(app.env, "live_cells", {}).get(pagename)
    if not cells:
        return
    chapter = Path(pagename).name
    data = {"cells": cells, "local": f"make lab NB={chapter}"}
    # `</` cannot end the script element early once escaped
    payload = json.dumps(data).replace("</", "<\\/")
    context["body"] = context.get("body", "") + (
        f'<script type="application/json" id="live-cells-data">{payload}</script>'
    )
    if any(cell["live"] for cell in cells):
        # read in the head by live-cells.js, which starts Python before the body is parsed
        context["metatags"] = context.get("metatags", "") + '<meta name="live-cells-python" content="start" />'
    app.add_css_file("live/live-cells.css")
    app.add_js_file("live/live-cells.js", type="module", **{"async": "async"})


def _copy_assets(app: Any, exception: Exception | None) -> None:
    """Copy the assets `make live` built (Pyodide, wheels, scripts) to _static/live of the HTML output.

    Sphinx's own copy of extra files neither overwrites what exists nor runs when no page changed, so
    a rebuilt asset would not reach the book; this copy runs after every HTML build.
    """
    if exception is not None or app.builder.format != "html":
        return
    source = Path(app.confdir) / ASSETS
    if not (source / "live-cells.js").is_file():
        logger.warning("live cells: %s is missing; build it with `make live`", ASSETS)
        return
    target = Path(app.outdir) / "_static" / "live"
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(source, target, ignore=shutil.ignore_patterns(".*"))
    (target / LOCAL).mkdir()
    shipped = local_modules()
    for path in shipped:
        shutil.copyfile(path, target / LOCAL / path.name)
    (target / LOCAL / "manifest.json").write_text(json.dumps({"modules": [p.name for p in shipped]}))


def setup(app: Any) -> dict[str, Any]:
    app.connect("doctree-read", _annotate)
    app.connect("env-get-outdated", _outdated)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    app.connect("html-page-context", _page)
    app.connect("build-finished", _copy_assets)
    return {"parallel_read_safe": True, "parallel_write_safe": True, "env_version": 1}
