"""The built book in a real browser: Debian's Chromium driven by Playwright, pages served on loopback.

`make test` builds the book first; a missing build is a failure, not a skip.
"""

from __future__ import annotations

import functools
import http.server
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest
import yaml
from playwright.sync_api import Browser, Page, sync_playwright
from playwright.sync_api import TimeoutError as PlaywrightTimeout

ROOT = Path(__file__).resolve().parents[1]
HTML = ROOT / "_build" / "html"
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
]


def toc_pages() -> list[str]:
    """Every page of the table of contents, as a path below the book root without suffix."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    pages = [toc["root"]]
    for part in toc.get("parts", []):
        pages += [chapter["file"] for chapter in part["chapters"]]
    return pages


CHAPTERS = [page for page in toc_pages() if not page.endswith("intro")]


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: object) -> None:
        pass


@pytest.fixture(scope="module")
def server() -> Iterator[str]:
    assert (HTML / "index.html").is_file(), "the book is not built: run `make book` (make test does it first)"
    handler = functools.partial(_QuietHandler, directory=str(HTML))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()


@pytest.fixture(scope="module")
def browser() -> Iterator[Browser]:
    assert Path(CHROMIUM).exists(), "Debian's chromium is missing: apt-get install chromium (make test does it as root)"
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
        yield browser
        browser.close()


class PageProblems:
    """Console errors, uncaught exceptions and failed requests seen while a page loads."""

    def __init__(self, page: Page) -> None:
        self.items: list[str] = []
        page.on("console", lambda msg: msg.type == "error" and self.items.append(f"console: {msg.text}"))
        page.on("pageerror", lambda exc: self.items.append(f"exception: {exc}"))
        page.on("requestfailed", lambda req: self.items.append(f"request failed: {req.url}"))
        page.on("response", lambda res: res.status >= 400 and self.items.append(f"HTTP {res.status}: {res.url}"))


def open_page(browser: Browser, url: str) -> tuple[Page, PageProblems]:
    page = browser.new_page()
    problems = PageProblems(page)
    page.goto(url, wait_until="load")
    # MathJax typesets asynchronously; wait until its startup promise has settled.
    try:
        page.wait_for_function(
            "() => window.MathJax && window.MathJax.startup && window.MathJax.startup.promise", timeout=15000
        )
    except PlaywrightTimeout:
        raise AssertionError(f"MathJax never started on {url}; " + "; ".join(problems.items)) from None
    page.evaluate("() => window.MathJax.startup.promise")
    page.wait_for_load_state("networkidle")
    return page, problems


@pytest.mark.parametrize("page_path", toc_pages())
def test_page_renders_math_and_images_without_errors(browser, server, page_path):
    page, problems = open_page(browser, f"{server}/{page_path}.html")
    try:
        assert page.locator("mjx-container").count() > 0, "no typeset math (MathJax output) on the page"
        text = page.locator("main").inner_text()
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
