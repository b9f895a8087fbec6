"""The apparatus of the built book in a real browser: bibliography, glossary, index, figures, API reference.

Each check reads what a reader sees: the entries of the bibliography and the glossary, the links to them
from the chapters, the general and the proof index, the figures of the chapters and the API pages. The
chapters are the notebooks of the table of contents (the appendix pages are prose).
"""

from __future__ import annotations

import json
import re

import pytest
import yaml
from _browser import ROOT, open_page, toc_pages

CHAPTERS = [page for page in toc_pages() if (ROOT / f"{page}.ipynb").is_file()]
MIN_WORKS = 15
MIN_INDEX_ENTRIES_PER_CHAPTER = 3


def lecture_chapters() -> list[str]:
    """The chapters of Parts I to V (the lecture), where the book's rules ask for index entries."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    lecture = ("Part I", "Part II", "Part III", "Part IV", "Part V")
    return [c["file"] for p in toc["parts"] if p.get("caption", "").split(":")[0] in lecture for c in p["chapters"]]


def glossary_terms() -> list[str]:
    """The terms of book/glossary.md: the unindented lines of its glossary directive."""
    text = (ROOT / "book" / "glossary.md").read_text()
    block = text.split("```{glossary}", 1)[1].split("```", 1)[0]
    return [line.strip() for line in block.splitlines() if line.strip() and not line[0].isspace()]


# the fragments (#id) of the links of a page that point to another page of the book, by that page's name
LINKS_TO = """(target) => Array.from(document.querySelectorAll("main a[href]"))
    .map(a => new URL(a.href))
    .filter(u => u.pathname.endsWith("/" + target + ".html") && u.hash)
    .map(u => decodeURIComponent(u.hash.slice(1)))"""


def links_from_chapters(browser, server, target: str) -> dict[str, set[str]]:
    """For each fragment of book/<target>.html, the chapters that link to it."""
    found: dict[str, set[str]] = {}
    for chapter in CHAPTERS:
        page, _ = open_page(browser, f"{server}/{chapter}.html")
        try:
            for fragment in page.evaluate(LINKS_TO, target):
                found.setdefault(fragment, set()).add(chapter)
        finally:
            page.close()
    return found


@pytest.fixture(scope="module")
def bibliography(browser, server) -> list[str]:
    """The ids of the works listed on the bibliography page."""
    page, _ = open_page(browser, f"{server}/book/bibliography.html")
    try:
        return page.evaluate("() => Array.from(document.querySelectorAll('main .citation')).map(c => c.id)")
    finally:
        page.close()


def test_the_bibliography_lists_enough_works_each_cited_from_a_chapter(browser, server, bibliography):
    assert len(bibliography) >= MIN_WORKS, f"the bibliography lists {len(bibliography)} works"
    # every id names its work (bibtex_cite_id), so that a failure says which work is not cited
    assert all(re.fullmatch(r"cite-[a-z0-9]+", work) for work in bibliography), bibliography
    cited = links_from_chapters(browser, server, "bibliography")
    uncited = [work for work in bibliography if work not in cited]
    assert uncited == [], f"works no chapter cites: {uncited}"


def test_the_glossary_has_its_terms_each_linked_from_a_chapter(browser, server):
    terms = glossary_terms()
    assert len(terms) >= 30 and "cross-ratio" in terms and "homogeneous coordinates" in terms
    page, _ = open_page(browser, f"{server}/book/glossary.html")
    try:
        shown = page.evaluate("""() => Array.from(document.querySelectorAll('main dl.glossary > dt'))
            .map(dt => [dt.id, dt.textContent.replace(/[#¶]\\s*$/, '').trim()])""")
    finally:
        page.close()
    assert [text for _, text in shown] == terms, "the glossary page does not show the terms of glossary.md"
    linked = links_from_chapters(browser, server, "glossary")
    unlinked = [text for term_id, text in shown if term_id not in linked]
    assert unlinked == [], f"glossary terms no chapter links: {unlinked}"


def test_the_general_index_has_entries_for_the_api_and_for_every_lecture_chapter(browser, server):
    page, _ = open_page(browser, f"{server}/genindex.html")
    try:
        targets = page.evaluate("""() => Array.from(document.querySelectorAll('table.indextable a[href]'))
            .map(a => new URL(a.href).pathname.replace(/^\\//, '').replace(/\\.html$/, ''))""")
    finally:
        page.close()
    assert targets.count("book/api") >= 100, "the API reference adds no index entries"
    few = {c: targets.count(c) for c in lecture_chapters() if targets.count(c) < MIN_INDEX_ENTRIES_PER_CHAPTER}
    assert few == {}, f"lecture chapters with fewer than {MIN_INDEX_ENTRIES_PER_CHAPTER} index entries: {few}"


# a labelled box of sphinx-proof in a chapter's source: ```{prf:theorem} Title, then :label: name
BOX = re.compile(r"```\{prf:[a-z]+\} ?([^\n]*)\n:label: ?([^\s]+)")


def test_the_proof_index_shows_titles_not_labels(browser, server):
    boxes = [m.groups() for c in CHAPTERS
             for cell in json.loads((ROOT / f"{c}.ipynb").read_text())["cells"] if cell["cell_type"] == "markdown"
             for m in BOX.finditer("".join(cell["source"]))]
    titles = {title.replace("$", "").strip() for title, _ in boxes if title.strip()}
    assert len(titles) >= 20, "the chapters' boxes are not found"
    page, _ = open_page(browser, f"{server}/prf-prf.html")
    try:
        entries = page.evaluate("""() => Array.from(document.querySelectorAll('table.indextable td > a'))
            .map(a => a.textContent.trim())""")
    finally:
        page.close()
    assert titles <= set(entries), f"titles missing from the proof index: {sorted(titles - set(entries))[:10]}"
    # a label (thm-pl-meet) where a title belongs: the box has no title
    labels = [e for e in entries if re.fullmatch(r"[a-z0-9]+(-[a-z0-9]+)+", e)]
    assert labels == [], f"proof boxes without a title: {labels}"


# every image of a cell output, with whether it sits in a numbered figure with a caption
FIGURES = """() => Array.from(document.querySelectorAll('main .cell_output img')).map(img => {
    const figure = img.closest('figure');
    const caption = figure && figure.querySelector('figcaption');
    return {
        src: img.getAttribute('src'),
        id: figure ? figure.id : null,
        number: caption ? (caption.querySelector('.caption-number') || {}).textContent || null : null,
        text: caption ? (caption.querySelector('.caption-text') || {}).textContent || '' : '',
    };
})"""


@pytest.mark.parametrize("page_path", CHAPTERS)
def test_every_figure_of_a_chapter_is_numbered_with_a_caption(browser, server, page_path):
    page, _ = open_page(browser, f"{server}/{page_path}.html")
    try:
        images = page.evaluate(FIGURES)
    finally:
        page.close()
    bad = [image["src"] for image in images
           if not (image["id"] and image["number"] and re.fullmatch(r"Fig\. \d+\.\d+ ?", image["number"])
                   and image["text"].strip())]
    assert bad == [], f"images of cell outputs without a numbered figure and caption: {bad}"


def test_the_api_reference_documents_the_core_and_the_prover(browser, server):
    from pgsym.proofs.language import KEYWORDS

    page, problems = open_page(browser, f"{server}/book/api.html")
    try:
        for name in ("Point", "Line", "join", "meet"):
            entry = page.locator(f"dt[id='pgsym.{name}']")
            assert entry.count() == 1 and name in entry.inner_text(), name
        assert problems.items == [], problems.items
    finally:
        page.close()
    page, _ = open_page(browser, f"{server}/book/api-proofs.html")
    try:
        assert page.locator("dt[id='pgsym.proofs.prove']").count() == 1
        assert page.locator("dt[id='pgsym.proofs.Claim']").count() == 1
        words = page.evaluate("() => Array.from(document.querySelectorAll('table.statement-keywords code'))"
                              ".map(c => c.textContent)")
    finally:
        page.close()
    assert sorted(words) == sorted(KEYWORDS) and "join" in words and "collinear" in words
