"""The built book in a real browser: Debian's Chromium driven by Playwright, pages served on loopback.

`make test` builds the book first; a missing build is a failure, not a skip.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from _browser import ROOT, PageProblems, open_page, toc_pages

# chapters are notebooks; prose pages (the introduction, "Using this book") have no boxes to check
CHAPTERS = [page for page in toc_pages() if (ROOT / f"{page}.ipynb").is_file()]


@pytest.mark.parametrize("page_path", toc_pages())
def test_page_renders_math_and_images_without_errors(browser, server, page_path):
    page, problems = open_page(browser, f"{server}/{page_path}.html")
    try:
        source = next(ROOT.glob(f"{page_path}.*")).read_text(encoding="utf-8")
        if "$" in source:  # a page with mathematics (the bibliography has none, so Sphinx loads no MathJax)
            assert page.locator("mjx-container").count() > 0, "no typeset math (MathJax output) on the page"
        text = page.locator("main").inner_text()
        # the text outside code and scripts: a docstring may show a delimiter as code (``$$...$$`` in the API
        # reference), and the live cells' description of a page (a script) holds the cells' sources
        text = page.evaluate("""() => { const main = document.querySelector('main').cloneNode(true);
            main.querySelectorAll('code, pre, script, style').forEach(c => c.remove()); return main.innerText; }""")
        for raw in ("\\[", "\\(", "$$"):
            assert raw not in text, f"untypeset math delimiter {raw!r} left in the page text"
        broken = page.evaluate(
            "() => Array.from(document.images).filter(i => !i.complete || i.naturalWidth === 0).map(i => i.src)"
        )
        assert broken == [], f"images that did not load: {broken}"
        assert problems.items == [], "\n".join(problems.items)
    finally:
        page.close()


@pytest.mark.parametrize("page_path", CHAPTERS)
def test_chapter_has_a_notebook_download_and_numbered_boxes(browser, server, page_path):
    page, _ = open_page(browser, f"{server}/{page_path}.html")
    try:
        link = page.locator(f"a[href$='{Path(page_path).name}.ipynb']")
        assert link.count() >= 1, "no .ipynb download link"
        response = page.request.get(f"{server}/_sources/{page_path}.ipynb")
        assert response.ok and '"cells"' in response.text()
        assert page.locator(".proof .caption-number, .proof .caption").count() > 0, "no sphinx-proof box"
        assert page.locator("div.solution, details.solution, .dropdown.solution").count() > 0, "no solution"
    finally:
        page.close()


def test_search_finds_the_cross_product(browser, server):
    page = browser.new_page()
    problems = PageProblems(page)
    try:
        page.goto(f"{server}/search.html?q=cross+product", wait_until="load")
        # Sphinx fills the result list one item at a time; its summary line changes only at the end
        page.wait_for_function(
            """() => {
                const summary = document.querySelector('.search-summary');
                return summary && /Search finished|did not match/.test(summary.textContent);
            }""",
            timeout=20000,
        )
        hits = page.locator("ul.search li a").all_inner_texts()
        assert any("Points and lines" in hit for hit in hits), hits
        assert problems.items == [], "\n".join(problems.items)
    finally:
        page.close()
