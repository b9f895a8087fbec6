"""Shared pieces of the browser tests: Debian's Chromium driven by Playwright, the built book on loopback.

`make test` builds the book first; a missing build is a failure, not a skip. The fixtures are
registered for every test module by tests/conftest.py.
"""

from __future__ import annotations

import contextlib
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


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: object) -> None:
        pass


@contextlib.contextmanager
def serve(directory: Path = HTML) -> Iterator[str]:
    """Serve ``directory`` on a free loopback port; yields the base URL."""
    handler = functools.partial(_QuietHandler, directory=str(directory))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{httpd.server_address[1]}"
    finally:
        httpd.shutdown()


@pytest.fixture(scope="module")
def server() -> Iterator[str]:
    assert (HTML / "index.html").is_file(), "the book is not built: run `make book` (make test does it first)"
    with serve(HTML) as url:
        yield url


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


# A page with live cells starts Python as soon as it opens unless the reader asked to save data (the
# Save-Data preference). Tests of the page's text, figures and layout say so, so that each page does not
# boot Python in the background while it is measured; tests/test_live_cells.py opens pages without it.
SAVE_DATA = "Object.defineProperty(navigator, 'connection', {value: {saveData: true}})"


def open_page(browser: Browser, url: str, python: bool = False) -> tuple[Page, PageProblems]:
    """A page of the book, loaded, with MathJax done; ``python=True`` lets its live cells start Python."""
    page = browser.new_page()
    if not python:
        page.add_init_script(SAVE_DATA)
    problems = PageProblems(page)
    page.goto(url, wait_until="load")
    # MathJax typesets asynchronously; wait until its startup promise has settled. Sphinx loads MathJax only
    # on pages with mathematics (the bibliography has none).
    if not page.evaluate("() => !!document.querySelector('script[src*=\"mathjax\"]')"):
        page.wait_for_load_state("networkidle")
        return page, problems
    try:
        page.wait_for_function(
            "() => window.MathJax && window.MathJax.startup && window.MathJax.startup.promise", timeout=15000
        )
    except PlaywrightTimeout:
        raise AssertionError(f"MathJax never started on {url}; " + "; ".join(problems.items)) from None
    page.evaluate("() => window.MathJax.startup.promise")
    page.wait_for_load_state("networkidle")
    return page, problems
