"""No import cycle in pgsym/exercises, counting imports inside functions too.

The graph is read from the source with ``ast``: every ``import`` / ``from … import`` of a module of
the package (at load or in a function body), ``from . import name`` resolved to the submodule it
names. A cycle is a strongly connected component of more than one module (or a module importing itself).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pgsym.exercises

ROOT = Path(pgsym.exercises.__file__).parent


def module_names(root: Path, package: str) -> dict[str, Path]:
    """Dotted module name → file, for every .py below ``root`` (package ``package``)."""
    out = {}
    for path in root.rglob("*.py"):
        parts = list(path.relative_to(root).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join([package, *parts])] = path
    return out


def import_graph(root: Path, package: str) -> dict[str, set[str]]:
    """module → the modules of the package it imports (anywhere in its source)."""
    modules = module_names(root, package)
    graph: dict[str, set[str]] = {name: set() for name in modules}
    for name, path in modules.items():
        here = name if path.name == "__init__.py" else name.rsplit(".", 1)[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = here.split(".")[: len(here.split(".")) - (node.level - 1)] if node.level else []
                source = ".".join(base + ([node.module] if node.module else []))
                submodules = [f"{source}.{alias.name}" for alias in node.names if f"{source}.{alias.name}" in modules]
                # "from . import x" imports the submodule x; "from .m import f" imports m
                targets = submodules if len(submodules) == len(node.names) else [source, *submodules]
            graph[name].update(t for t in targets if t in modules and t != name)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_the_checker_finds_a_cycle_through_a_function_level_import(tmp_path):
    pkg = tmp_path / "p"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "sub" / "__init__.py").write_text("from .b import B\n")
    (pkg / "a.py").write_text("class A: ...\n\ndef registry():\n    from .sub import B\n    return B\n")
    (pkg / "sub" / "b.py").write_text("from ..a import A\n\nclass B(A): ...\n")
    assert cycles(import_graph(pkg, "p")) == [["p.a", "p.sub", "p.sub.b"]]


def test_no_import_cycle_in_the_exercises_package():
    graph = import_graph(ROOT, "pgsym.exercises")
    assert "pgsym.exercises.template_base" in graph["pgsym.exercises.templates.plane"]  # the graph is read
    assert cycles(graph) == []


def test_the_old_public_names_still_import():
    from pgsym.exercises.registry import get_template
    from pgsym.exercises.template import Draft, Template, all_templates, check, load_template_folder
    from pgsym.exercises.template import get_template as old_get_template
    from pgsym.exercises.template_base import Template as BaseTemplate

    assert Template is BaseTemplate and old_get_template is get_template
    assert callable(check) and callable(all_templates) and callable(load_template_folder) and Draft
