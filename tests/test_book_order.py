"""The book reads in order: no chapter needs a later one.

Read from the sources (no build needed). The reading order is the table of contents; the front matter
(the introduction and "About this book") and the appendix pages (errors, notation, glossary, API,
bibliography) are reference material that any chapter may point to. Inside a chapter:

- a `{doc}`, `{ref}`, `{prf:ref}`, `{eq}` or `{numref}` reference points to the same or an earlier
  chapter, except inside a section headed "What comes next", which may point forward;
- a symbol of the notation page is not used before the chapter that the page says defines it.
"""

from __future__ import annotations

import json
import re
from functools import cache
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
FORWARD_SECTION = "What comes next"

# {role}`text <target>` or {role}`target`
ROLE = re.compile(r"\{(doc|ref|prf:ref|eq|numref)\}`(?:[^`<]*<)?([^`>]+)>?`")
# where labels are defined: MyST targets, directive options, labelled display math, figure metadata
TARGET = re.compile(r"^\((?P<a>[\w:.-]+)\)=\s*$|^:(?:label|name):\s*(?P<b>[\w:.-]+)\s*$|\$\$\s*\((?P<c>[\w:.-]+)\)",
                    re.M)
HEADING = re.compile(r"^(#{1,6})\s+(.*)$", re.M)


def _parts() -> list[tuple[str, list[str]]]:
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text(encoding="utf-8"))
    return [(part.get("caption", ""), [c["file"] for c in part["chapters"]]) for part in toc["parts"]]


@cache
def reading_order() -> list[str]:
    """The chapters in the order a student reads them: every numbered part before the appendix."""
    return [page for caption, pages in _parts() for page in pages
            if caption not in ("About this book", "Appendix")]


@cache
def reference_pages() -> set[str]:
    """Pages any chapter may point to: the root, the front matter and the appendix."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text(encoding="utf-8"))
    front_back = {page for caption, pages in _parts() for page in pages
                  if caption in ("About this book", "Appendix")}
    return front_back | {toc["root"]}


def _source(page: str) -> list[tuple[str, str, dict]]:
    """The cells of a page as (cell type, source, metadata); a Markdown page is one cell."""
    path = ROOT / f"{page}.ipynb"
    if path.exists():
        nb = json.loads(path.read_text(encoding="utf-8"))
        return [(c["cell_type"], "".join(c["source"]), c.get("metadata", {})) for c in nb["cells"]]
    return [("markdown", (ROOT / f"{page}.md").read_text(encoding="utf-8"), {})]


def _markdown(page: str) -> str:
    return "\n\n".join(src for kind, src, _ in _source(page) if kind == "markdown")


@cache
def label_pages() -> dict[str, str]:
    """Every label of the book and the page that defines it."""
    labels: dict[str, str] = {}
    for page in reading_order() + sorted(reference_pages()):
        for kind, src, meta in _source(page):
            if kind == "markdown":
                for m in TARGET.finditer(src):
                    labels[m.group("a") or m.group("b") or m.group("c")] = page
            name = meta.get("mystnb", {}).get("figure", {}).get("name")
            if name:
                labels[name] = page
    return labels


def references_outside_forward_sections(text: str) -> list[tuple[str, str]]:
    """The (role, target) references of a Markdown text that are not inside a "What comes next" section.

    >>> text = "See {doc}`a`.\\n## What comes next\\n{doc}`b`\\n## Exercises\\n{ref}`c <x>`"
    >>> references_outside_forward_sections(text)
    [('doc', 'a'), ('ref', 'x')]
    """
    found: list[tuple[str, str]] = []
    forward_level: int | None = None
    pos = 0
    pieces: list[tuple[str, bool]] = []
    for m in HEADING.finditer(text):
        pieces.append((text[pos:m.start()], forward_level is not None))
        level = len(m.group(1))
        if forward_level is not None and level <= forward_level:
            forward_level = None
        if m.group(2).strip().rstrip(".").lower() == FORWARD_SECTION.lower():
            forward_level = level
        pos = m.start()
    pieces.append((text[pos:], forward_level is not None))
    for chunk, forward in pieces:
        if not forward:
            found += [(m.group(1), m.group(2).strip()) for m in ROLE.finditer(chunk)]
    return found


def _target_page(page: str, role: str, target: str) -> str | None:
    if role == "doc":
        return str((Path(page).parent / target).as_posix()) if not target.startswith("/") else target.lstrip("/")
    return label_pages().get(target)


def test_the_order_is_the_table_of_contents():
    order = reading_order()
    assert order.index("book/conics") < order.index("book/absolute") < order.index("book/euclidean-geometry")
    assert order.index("book/lines-in-3d") < order.index("book/absolute")
    assert order.index("book/null-space-and-svd") < order.index("book/dlt") < order.index("book/rectification")
    assert "book/notation" in reference_pages() and "book/glossary" in reference_pages()


def test_the_reference_finder_sees_forward_references():
    # a reference to a later chapter outside the forward section is found; inside it is not
    text = "Uses {prf:ref}`thm-x`.\n\n### What comes next\n\nSee {doc}`later`.\n\n## Next\n{eq}`eq-y`"
    assert references_outside_forward_sections(text) == [("prf:ref", "thm-x"), ("eq", "eq-y")]


@pytest.mark.parametrize("page", reading_order())
def test_a_chapter_refers_only_to_itself_and_earlier_chapters(page):
    order = reading_order()
    here = order.index(page)
    forward, unknown = [], []
    for role, target in references_outside_forward_sections(_markdown(page)):
        where = _target_page(page, role, target)
        if where is None:
            unknown.append(f"{role}:{target}")
        elif where in reference_pages():
            continue
        elif where not in order:
            unknown.append(f"{role}:{target} -> {where}")
        elif order.index(where) > here:
            forward.append(f"{{{role}}}`{target}` (in {where})")
    assert unknown == [], f"references to labels this test cannot place: {unknown}"
    assert forward == [], (f"{page} refers forward outside '## {FORWARD_SECTION}': {forward}")


# The symbols of the notation page, each with how the sources write it. The test below checks that this
# table and the page list the same symbols, so a symbol added to the page needs its pattern here.
NOTATION_PATTERNS: dict[str, str] = {
    r"\mathbf{x} \sim \lambda\mathbf{x}": r"\\sim",
    r"\mathbb{P}^n": r"\\mathbb\{P\}\^n",
    r"\mathbb{P}^2": r"\\mathbb\{P\}\^2",
    r"\mathbb{P}^1": r"\\mathbb\{P\}\^1|ℙ¹",
    r"[A\,B]": r"\[\s*\w\s*\\,\s*\w\s*\]",
    r"\operatorname{adj}(H)": r"\\operatorname\{adj\}|\\mathrm\{adj\}",
    r"\mathbb{P}^3": r"\\mathbb\{P\}\^3",
    r"\mathbf{x} \vee \mathbf{y}": r"\\vee|∨",
    r"\mathbf{l} \wedge \mathbf{m}": r"\\wedge|∧",
    r"\mathbf{l}_\infty": r"l\}?_\{?\\infty|l∞",
    r"\mathrm{PGL}(3)": r"PGL\}?\(3\)|PGL_3",
    r"\mathrm{PGL}(4)": r"PGL\}?\(4\)|PGL_4",
    r"(A, B; C, D)": r"\(\s*\\?\w+\s*,\s*\\?\w+\s*;\s*\\?\w+\s*,\s*\\?\w+\s*\)",
    r"\mathbf{I}": r"circular point",
    r"C^*": r"dual conic",
    r"C^*_\infty": r"C\^\{?\*\}?_\{?\\infty|C_\{?\\infty\}?\^\{?\*|C\*∞",
    r"\boldsymbol{\pi}_\infty": r"\\pi\}?_\{?\\infty|π∞",
    r"\mathbf{L}": r"Plücker matri",
    r"\Omega_\infty": r"\\Omega_\{?\\infty|Ω∞",
    r"Q^*_\infty": r"Q\^\{?\*\}?_\{?\\infty|Q_\{?\\infty\}?\^\{?\*|Q\*∞",
}

ROW = re.compile(r"^\|\s*\$(?P<symbol>[^$]+)\$.*\|\s*\{doc\}`(?P<page>[^`]+)`\s*\|\s*$", re.M)


@cache
def notation_rows() -> list[tuple[str, str]]:
    """(first symbol of the row, page that defines it) for each row of the notation page."""
    text = (ROOT / "book/notation.md").read_text(encoding="utf-8")
    return [(m.group("symbol").strip(), f"book/{m.group('page')}") for m in ROW.finditer(text)]


def test_every_symbol_of_the_notation_page_has_a_pattern():
    rows = notation_rows()
    assert len(rows) >= 12
    assert {symbol for symbol, _ in rows} == set(NOTATION_PATTERNS)
    assert all(page in reading_order() for _, page in rows), rows


@pytest.mark.parametrize("symbol", sorted(NOTATION_PATTERNS))
def test_a_symbol_is_defined_before_its_first_use(symbol):
    defining = dict(notation_rows())[symbol]
    pattern = re.compile(NOTATION_PATTERNS[symbol], re.I)
    order = reading_order()
    early = [page for page in order[:order.index(defining)] if pattern.search(_strip_forward(_markdown(page)))]
    assert early == [], f"{symbol} is defined in {defining} but used earlier in {early}"


def _strip_forward(text: str) -> str:
    """The text without its "What comes next" sections (a pointer forward may name what comes)."""
    out, skip_level = [], None
    for line in text.splitlines():
        m = HEADING.match(line)
        if m:
            level = len(m.group(1))
            if skip_level is not None and level <= skip_level:
                skip_level = None
            if m.group(2).strip().rstrip(".").lower() == FORWARD_SECTION.lower():
                skip_level = level
        if skip_level is None:
            out.append(line)
    return "\n".join(out)
