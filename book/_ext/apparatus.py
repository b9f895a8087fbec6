"""Sphinx extension for the book's appendix: the API reference and the proof index.

* ``{pgsym-public-names}``: every name of ``pgsym.__all__`` documented with autodoc, one section per
  module where the names live (the directive's content gives the order of the modules); a module with
  public names that the content omits, or a listed module without any, is a build warning, so the
  reference stays complete as the package grows.
* ``{statement-keywords}``: the reserved words of the statement language, read when the book is built
  from ``pgsym.proofs.language.KEYWORDS``.
* the proof index of sphinx-proof lists theorems by their titles (with the kind and the chapter) instead
  of their labels.
"""

from __future__ import annotations

import importlib
import inspect
import sys
import types
from collections import defaultdict
from pathlib import Path
from typing import Any, ClassVar

from docutils import nodes
from docutils.parsers.rst import directives
from docutils.statemachine import StringList
from sphinx.domains import Index
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective
from sphinx.util.nodes import get_node_source, make_refnode, nested_parse_with_titles

logger = logging.getLogger(__name__)

KEYWORD_COLUMNS = 6


def _home(package: types.ModuleType, name: str) -> str:
    """The module that defines the public ``name`` of ``package`` (a subpackage for a module itself)."""
    value = getattr(package, name)
    if isinstance(value, types.ModuleType):
        return value.__name__
    module = getattr(value, "__module__", None)
    root = package.__name__.split(".")[0]
    if isinstance(module, str) and module.startswith(root + "."):
        return module
    # a constant (a tuple of classes, say): the module that lists it in its __all__
    for modname in sorted(m for m in list(sys.modules) if m.startswith(package.__name__ + ".")):
        mod = sys.modules[modname]
        if name in getattr(mod, "__all__", ()) and getattr(mod, name, None) is value:
            return modname
    raise ValueError(f"cannot tell where {package.__name__}.{name} is defined")


def _summary(module: types.ModuleType) -> str:
    """The first sentence of a module's docstring, without its full stop."""
    first = (module.__doc__ or module.__name__).strip().split("\n\n")[0].replace("\n", " ")
    return first.split(". ")[0].rstrip(".")


class PublicNames(SphinxDirective):
    """Autodoc entries for the public names of a package, grouped by the module that defines them.

    The directive is for MyST pages (it writes MyST). The content lists the modules (relative to the
    package) in the order of the page. A line
    ``MODULE = PREFIX`` says that the names from MODULE are documented on another page as
    ``PREFIX.name``: they are listed at the end with a link there instead of being documented twice.
    A module outside the package (a re-exported error class) is written in full: ``pgsym.errors = pgsym``.
    """

    required_arguments = 1  # the package, e.g. pgsym
    has_content = True
    # ``Class.member ...``: members left out of a class's entry (a docstring that is not valid reST)
    option_spec: ClassVar[dict[str, Any]] = {"exclude-members": directives.unchanged}

    def run(self) -> list[nodes.Node]:
        excluded: dict[str, list[str]] = defaultdict(list)
        for item in self.options.get("exclude-members", "").split():
            cls, _, member = item.partition(".")
            excluded[cls].append(member)
        package = importlib.import_module(self.arguments[0])
        groups: dict[str, list[str]] = defaultdict(list)
        for name in package.__all__:
            groups[_home(package, name)].append(name)
        order: dict[str, str | None] = {}
        for line in self.content:
            module, _, prefix = (part.strip() for part in line.partition("="))
            if module:
                absolute = module.startswith(package.__name__.split(".")[0] + ".")
                order[module if absolute else f"{package.__name__}.{module}"] = prefix or None
        for missing in sorted(set(groups) - set(order)):
            logger.warning(f"{package.__name__} exports {', '.join(groups[missing])} from {missing}, "
                           "which the list of modules of the API page omits", location=self.get_location())
        for extra in sorted(set(order) - set(groups)):
            logger.warning(f"{extra} is listed on the API page but {package.__name__} exports nothing from it",
                           location=self.get_location())
        lines: list[str] = []
        elsewhere: list[str] = []
        for modname, prefix in order.items():
            if modname not in groups:
                continue
            if prefix is not None:
                elsewhere += [self._link(package, name, prefix) for name in groups[modname]]
                continue
            lines += [f"## `{modname}`: {_summary(importlib.import_module(modname))}", ""]
            for name in groups[modname]:
                lines += [*self._entry(package, name, excluded.get(name, [])), ""]
        if elsewhere:
            lines += ["## Names documented with their subpackage", "", *sorted(elsewhere), ""]
        content = StringList(lines, source=self.get_source_info()[0])
        section = nodes.section()
        section.document = self.state.document
        nested_parse_with_titles(self.state, content, section)
        return section.children

    @staticmethod
    def _entry(package: types.ModuleType, name: str, excluded: list[str]) -> list[str]:
        full = f"{package.__name__}.{name}"
        value = getattr(package, name)
        # autodoc writes reStructuredText: MyST reads it inside eval-rst
        if isinstance(value, type):
            exclude = [f"   :exclude-members: {', '.join(excluded)}"] if excluded else []
            return ["```{eval-rst}", f".. autoclass:: {full}", "   :members:", "   :show-inheritance:", *exclude,
                    "```"]
        if callable(value):
            return ["```{eval-rst}", f".. autofunction:: {full}", "```"]
        return ["```{eval-rst}", f".. autodata:: {full}", "   :no-value:", "```"]

    @staticmethod
    def _link(package: types.ModuleType, name: str, prefix: str) -> str:
        value = getattr(package, name)
        if isinstance(value, types.ModuleType):
            return f"- `{package.__name__}.{name}`: the subpackage {{py:mod}}`{value.__name__}`"
        return f"- `{package.__name__}.{name}`: {{py:obj}}`{prefix}.{value.__name__}`"


class StatementKeywords(SphinxDirective):
    """A table of the reserved words of the statement language, as pgsym has them."""

    def run(self) -> list[nodes.Node]:
        from pgsym.proofs.language import KEYWORDS

        words = sorted(KEYWORDS)
        rows = [words[i:i + KEYWORD_COLUMNS] for i in range(0, len(words), KEYWORD_COLUMNS)]
        table = nodes.table(classes=["statement-keywords"])
        group = nodes.tgroup(cols=KEYWORD_COLUMNS)
        table += group
        group += [nodes.colspec(colwidth=1) for _ in range(KEYWORD_COLUMNS)]
        body = nodes.tbody()
        group += body
        for row in rows:
            tr = nodes.row()
            for word in row + [""] * (KEYWORD_COLUMNS - len(row)):
                entry = nodes.entry()
                entry += nodes.paragraph("", "", *([nodes.literal(word, word)] if word else []))
                tr += entry
            body += tr
        return [table]


_MISSING = object()


def _module(name: str) -> types.ModuleType | None:
    """An imported module, or a module of pgsym imported now; nothing else is imported."""
    if name not in sys.modules and (name == "pgsym" or name.startswith("pgsym.")):
        try:
            importlib.import_module(name)
        except ImportError:
            return None
    return sys.modules.get(name)


def _find(dotted: str) -> Any:
    """The object of a dotted name, or _MISSING."""
    parts = dotted.split(".")
    for cut in range(len(parts), 0, -1):
        module = _module(".".join(parts[:cut]))
        if module is None:
            continue
        value: Any = module
        for attr in parts[cut:]:
            value = getattr(value, attr, _MISSING)
            if value is _MISSING:
                return _MISSING
        return value
    return _MISSING


def _documented(env: Any) -> dict[int, str]:
    """id(object) -> the name under which the book documents it (the first name, in sorted order)."""
    cache = env.__dict__.get("apparatus_documented")
    if cache is None:
        cache = {}
        for name in sorted(env.get_domain("py").objects):
            value = _find(name)
            if value is not _MISSING and not isinstance(value, (int, float, str, bytes, tuple, frozenset, bool)):
                cache.setdefault(id(value), name)
        env.__dict__["apparatus_documented"] = cache
    return cache


def _resolve(app: Any, env: Any, node: Any, contnode: nodes.Element) -> nodes.Element | None:
    """A Python reference the Python domain did not find.

    A docstring names an object by the module that defines it (``pgsym.projective_plane.join``) while the
    reference documents it where users import it (``pgsym.join``): link to that entry. An object that
    exists but is not part of the documented API (a private helper, NumPy's ndarray, a type variable) is
    shown as code without a link. A name that is no object at all stays a warning.
    """
    if node.get("refdomain") != "py" or node["reftarget"].startswith("."):
        return None
    target, module, cls = node["reftarget"], node.get("py:module"), node.get("py:class")
    candidates = [f"{module}.{cls}.{target}"] if module and cls else []
    candidates += [f"{module}.{target}"] if module else []
    # a docstring's short names are those of the module that holds it, wherever it is documented
    try:
        source = str(get_node_source(node)).partition("docstring of ")[2]
    except ValueError:  # a reference with no source anywhere up its tree
        source = ""
    candidates += [f"{source.rsplit('.', cut)[0]}.{target}" for cut in range(1, source.count(".") + 1)]
    candidates.append(target)
    for name in candidates:
        value = _find(name)
        if value is _MISSING:
            continue
        documented = _documented(env).get(id(value))
        if documented is None:
            return contnode
        entry = env.get_domain("py").objects[documented]
        return make_refnode(app.builder, node["refdoc"], entry.docname, entry.node_id, contnode, documented)
    return None


def _drop_inherited_data_docstring(app: Any, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    """A constant without a docstring of its own would show its type's (``dict``'s): show none instead."""
    type_doc = getattr(type(obj), "__doc__", None)
    if what == "data" and type_doc and "\n".join(lines).strip() == inspect.cleandoc(type_doc).strip():
        lines.clear()


def _titles(app: Any, doctree: nodes.document) -> None:
    """Record the title of every labelled proof box of the page (sphinx-proof keeps only the label)."""
    env = app.env
    store = env.__dict__.setdefault("apparatus_proof_titles", {})
    before, _, after = app.config.proof_title_format.partition("%t")
    for node in doctree.findall(nodes.Element):
        if "realtype" in node and "label" in node and node.get("title"):
            title = node["title"]
            title = title[len(before):] if title.startswith(before) else title
            title = title[: -len(after)] if after and title.endswith(after) else title
            store[node["label"]] = (env.docname, title.strip())


def _purge(app: Any, env: Any, docname: str) -> None:
    store = env.__dict__.get("apparatus_proof_titles", {})
    for label in [k for k, (doc, _) in store.items() if doc == docname]:
        del store[label]


def _merge(app: Any, env: Any, docnames: Any, other: Any) -> None:
    env.__dict__.setdefault("apparatus_proof_titles", {}).update(other.__dict__.get("apparatus_proof_titles", {}))


class TitledProofIndex(Index):
    """The proof index by title: "Pappus's hexagon theorem", with its kind and chapter beside it."""

    name = "prf"
    localname = "Proof Index"
    shortname = "Proof"

    def generate(self, docnames: Any = None) -> tuple[list[tuple[str, list[Any]]], bool]:
        env = self.domain.env
        proofs = getattr(env, "proof_list", {})
        titles = env.__dict__.get("apparatus_proof_titles", {})
        content: dict[str, list[Any]] = defaultdict(list)
        for label, values in proofs.items():
            if values.get("nonumber") and label not in titles:
                continue
            title = titles.get(label, (None, label))[1].replace("$", "")  # index entries are plain text
            chapter = env.titles[values["docname"]].astext() if values["docname"] in env.titles else ""
            entry = (title, 0, values["docname"], label, values["realtype"], "", chapter)
            content[title[:1].upper()].append(entry)
        result = [(letter, sorted(entries, key=lambda e: e[0].lower())) for letter, entries in sorted(content.items())]
        return result, True


# LuaLaTeX's font cache (luaotfload's *.luc files) is rewritten by its runs, and by other documents typeset
# at the same time; it is no input of the book, but latexmk saw it change and ran LuaLaTeX the maximum five
# times instead of the three the cross-references need.
LATEXMKRC_EXTRA = """
# added by book/_ext/apparatus.py: a changed luaotfload cache is no reason to run LuaLaTeX again
$hash_calc_ignore_pattern{'luc'} = '^';
"""


def _latexmkrc(app: Any, exception: Exception | None) -> None:
    """Append LATEXMKRC_EXTRA to the latexmkrc that Sphinx's LaTeX builder writes (latexmk reads it)."""
    path = Path(app.outdir) / "latexmkrc"
    if exception is None and app.builder.name == "latex" and path.is_file():
        text = path.read_text()
        if LATEXMKRC_EXTRA not in text:
            path.write_text(text + LATEXMKRC_EXTRA)


def _exercise_labels_for_latex(app: Any) -> None:
    """sphinx-exercise labels an exercise in LaTeX only as ``exercise:LABEL``, the form its own references
    use; a {ref} from another chapter asks for Sphinx's ``DOCNAME:LABEL`` and stayed undefined in the PDF.
    Its LaTeX visitors are wrapped to write both labels."""
    from sphinx.writers.latex import LaTeXTranslator
    from sphinx_exercise import nodes as exercise_nodes

    def wrap(visit: Any) -> Any:
        def visit_with_label(self: Any, node: Any) -> None:
            # before the box: inside it, the label would become part of the box's title argument
            if isinstance(self, LaTeXTranslator) and node.get("label"):
                self.body.append(self.hypertarget(node["label"]) + "\n")
            visit(self, node)
        return visit_with_label

    for node_class, visit, depart in (
        (exercise_nodes.exercise_node, exercise_nodes.visit_exercise_node, exercise_nodes.depart_exercise_node),
        (exercise_nodes.exercise_enumerable_node, exercise_nodes.visit_exercise_enumerable_node,
         exercise_nodes.depart_exercise_enumerable_node),
    ):
        app.add_node(node_class, override=True, latex=(wrap(visit), depart))


def _proof_labels_for_latex() -> None:
    """sphinx-proof finds the chapter of a box, for its LaTeX label and number, by matching the chapter's
    title against the names of a section; a title with an apostrophe ("Appendix: pgsym's errors") is
    typeset with a curly one and never matches, so the boxes of that chapter were labelled ``None:LABEL``,
    unnumbered, and every reference to them was undefined in the PDF. The chapter of a node is the nearest
    enclosing node that names its document (in LaTeX, the start of each included file)."""
    from sphinx_proof import nodes as proof_nodes

    def find_parent(env: Any, node: Any, parent_tag: str) -> str | None:
        node = node.parent
        while node is not None:
            if node.get("docname") in env.titles:
                return node["docname"]
            node = node.parent
        return None

    proof_nodes.find_parent = find_parent


def setup(app: Any) -> dict[str, Any]:
    app.setup_extension("sphinx.ext.autodoc")
    app.setup_extension("sphinx_proof")
    app.setup_extension("sphinx_exercise")
    _exercise_labels_for_latex(app)
    from sphinx_proof.domain import ProofDomain

    ProofDomain.indices = [TitledProofIndex]
    _proof_labels_for_latex()
    # MathJax on every page, also on those without a formula (the API reference, the indexes): the pages
    # behave alike, and the browser tests wait for MathJax on each page they open
    app.set_html_assets_policy("always")
    app.add_directive("pgsym-public-names", PublicNames)
    app.add_directive("statement-keywords", StatementKeywords)
    app.connect("missing-reference", _resolve)
    app.connect("autodoc-process-docstring", _drop_inherited_data_docstring)
    app.connect("build-finished", _latexmkrc)
    app.connect("doctree-read", _titles)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
