"""Live cells: readers run the book's derivations in the page, offline (Pyodide in a Web Worker).

The browser tests open chapters of the built book from a loopback server in Debian's Chromium with
every other host unreachable (a resolver rule) and every request elsewhere aborted (a route). Expected
outputs come from the notebooks' stored outputs, read at test time, or from pgsym in this process.
"""

from __future__ import annotations

import ast
import json
import re
import sys
from collections.abc import Iterator
from urllib.parse import urlparse

import pytest
from _browser import CHROMIUM, CHROMIUM_ARGS, HTML, ROOT, PageProblems
from playwright.sync_api import Browser, BrowserContext, Locator, Page, sync_playwright

import pgsym

sys.path.insert(0, str(ROOT / "book" / "_ext"))
sys.path.insert(0, str(ROOT / "book" / "_ext" / "live"))
import live_cells
import live_kernel

# Booting Python and SymPy takes seconds on a loaded two-core machine; a run waits for its result.
RUN_TIMEOUT_MS = 180_000
PLOT_OR_ARRAY = re.compile(r"\b(plt|np|cv2|_plot)\.")


def code_cells(chapter: str) -> list[dict]:
    notebook = json.loads((ROOT / "book" / f"{chapter}.ipynb").read_text(encoding="utf-8"))
    return [cell for cell in notebook["cells"] if cell["cell_type"] == "code"]


def source(cell: dict) -> str:
    return "".join(cell["source"])


def stored_stdout(cell: dict) -> str | None:
    """The cell's stored output when it is printed text only, else None."""
    outputs = cell["outputs"]
    if not outputs or any(o["output_type"] != "stream" or o["name"] != "stdout" for o in outputs):
        return None
    return "".join("".join(o["text"]) for o in outputs)


def classified(chapter: str) -> list[dict]:
    return live_cells.classify_cells([(source(c), c.get("metadata", {}).get("tags", [])) for c in code_cells(chapter)])


# ---------------------------------------------------------------- the rule and the kernel, in this process


def test_rule_disables_exactly_the_cells_that_use_plots_or_arrays():
    for chapter in ("points-and-lines", "hierarchy-2d", "classical-theorems", "harris"):
        for index, (cell, decided) in enumerate(zip(code_cells(chapter), classified(chapter), strict=True)):
            if PLOT_OR_ARRAY.search(source(cell)):
                assert not decided["live"], (chapter, index)
                assert "does not run in the page" in decided["reason"]
    # the chapter on points and lines is exact: every cell but its figures runs in the page
    chapter = "points-and-lines"
    decided = classified(chapter)
    exact = [d for c, d in zip(code_cells(chapter), decided, strict=True) if not PLOT_OR_ARRAY.search(source(c))]
    assert all(d["live"] for d in exact) and len(exact) >= len(decided) - 2
    # the Harris chapter needs OpenCV and NumPy: only its pure-SymPy exercise checks run in the page
    harris = [(source(c), d) for c, d in zip(code_cells("harris"), classified("harris"), strict=True)]
    assert all("import sympy as sp" in src and "np." not in src for src, d in harris if d["live"])
    assert sum(not d["live"] for _, d in harris) > len(harris) // 2


def test_rule_follows_pgsym_imports():
    assert live_cells.missing_package("pgsym.transformations") is None
    assert live_cells.missing_package("pgsym.proofs") is None
    assert live_cells.missing_package("pgsym.vision.harris") == "numpy"
    [cell] = live_cells.classify_cells([("from pgsym.numeric import meet\nmeet([0, 1, 2], [1, 0, 3])", [])])
    assert cell == {"source": cell["source"], "live": False, "stubs": ["pgsym.numeric"],
                    "reason": "Uses meet, which needs NumPy, which does not run in the page"}


def test_kernel_outputs_are_those_of_a_notebook():
    kernel = live_kernel.Kernel()
    assert kernel.run("from pgsym import Point, join\nl = join(Point(0, 0), Point(1, 1))") == []
    [stream, result] = kernel.run("print(l.canonical())\nl")
    assert stream == {"type": "stream", "name": "stdout", "text": "Line(1, -1, 0)\n"}
    assert result["data"]["text/plain"] == repr(pgsym.join(pgsym.Point(0, 0), pgsym.Point(1, 1)))
    assert result["data"]["text/latex"] == pgsym.Line(-1, 1, 0)._repr_latex_()
    [error] = kernel.run("join(Point(1, 2), Point(2, 4, 2))")
    assert error["ename"] == "CoincidentPointsError"
    assert "<cell 3>" in error["traceback"] and "live_kernel" not in error["traceback"]


def test_ipython_stand_in_displays_in_order():
    display = live_kernel.ipython_display_module()
    kernel = live_kernel.Kernel()
    kernel.namespace.update(display=display.display, Math=display.Math, Markdown=display.Markdown)
    outputs = kernel.run("print('a')\ndisplay(Math('x^2'), Markdown('| a |\\n|---|\\n| $b$ |'))\nprint('c')")
    assert [o["type"] for o in outputs] == ["stream", "display", "display", "stream"]
    assert outputs[1]["data"]["text/latex"] == "$\\displaystyle x^2$"
    table = "<table><thead><tr><th>a</th></tr></thead><tbody><tr><td>\\(b\\)</td></tr></tbody></table>"
    assert outputs[2]["data"]["text/html"] == table


def test_assets_are_in_the_built_book_and_small_enough():
    live = HTML / "_static" / "live"
    names = {"pyodide.mjs", "pyodide.asm.mjs", "pyodide.asm.wasm", "python_stdlib.zip", "pyodide-lock.json"}
    assert names <= {p.name for p in (live / "pyodide").iterdir()}
    wheels = json.loads((live / "wheels" / "manifest.json").read_text())["wheels"]
    assert sorted(w.split("-")[0] for w in wheels) == ["mpmath", "pgsym", "sympy"]
    assert all((live / "wheels" / w).is_file() for w in wheels)
    size = sum(p.stat().st_size for p in live.rglob("*") if p.is_file())
    assert size < 30e6, f"live cells add {size / 1e6:.1f} MB to the book (budget 30 MB)"


# ---------------------------------------------------------------- in the browser, offline


class Offline:
    """A browser context that reaches only the loopback server, with every request recorded."""

    def __init__(self, context: BrowserContext, server: str) -> None:
        self.requests: list[str] = []
        self.blocked: list[str] = []
        host = urlparse(server).netloc
        context.on("request", lambda req: self.requests.append(req.url))

        def route(r) -> None:
            if urlparse(r.request.url).netloc == host or r.request.url.startswith(("data:", "blob:")):
                r.continue_()
            else:
                self.blocked.append(r.request.url)
                r.abort()

        context.route("**/*", route)


@pytest.fixture(scope="module")
def offline_browser() -> Iterator[Browser]:
    # No name resolves except loopback, so nothing can leave the machine even past the route below.
    args = [*CHROMIUM_ARGS, "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"]
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=args, headless=True)
        yield browser
        browser.close()


@pytest.fixture
def chapter_page(offline_browser, server) -> Iterator:
    contexts = []

    def open_chapter(path: str) -> tuple[Page, PageProblems, Offline]:
        context = offline_browser.new_context()
        contexts.append(context)
        offline = Offline(context, server)
        page = context.new_page()
        problems = PageProblems(page)
        page.goto(f"{server}/{path}", wait_until="load")
        page.wait_for_function("() => window.MathJax && window.MathJax.startup && window.MathJax.startup.promise")
        page.evaluate("() => window.MathJax.startup.promise")
        return page, problems, offline

    yield open_chapter
    for context in contexts:
        context.close()


def live_cell(page: Page, index: int) -> Locator:
    return page.locator(f".live-cell-{index}")


def run(page: Page, index: int, *, keyboard: bool = False) -> Locator:
    """Run a cell (by its button, or Shift+Enter where the focus is) and wait for this run's output."""
    cell = live_cell(page, index)
    runs = int(cell.get_attribute("data-live-runs") or 0)
    if keyboard:
        page.keyboard.press("Shift+Enter")
    else:
        cell.get_by_role("button", name="Run this cell (Shift+Enter)").click()
    page.wait_for_function(
        "([i, runs]) => Number(document.querySelector(`.live-cell-${i}`).dataset.liveRuns || 0) > runs",
        arg=[index, runs],
        timeout=RUN_TIMEOUT_MS,
    )
    return cell


def wait_for_editor_text(page: Page, index: int, code: str) -> None:
    """Wait until the cell's editor shows exactly ``code`` (CodeMirror renders one element per line)."""
    page.wait_for_function(
        """([i, code]) => Array.from(document.querySelectorAll(`.live-cell-${i} .cm-line`))
                 .map((line) => line.innerText.replace(/\\n$/, "")).join("\\n") === code""",
        arg=[index, code],
    )


def edit(page: Page, index: int, code: str) -> None:
    cell = live_cell(page, index)
    cell.get_by_role("button", name="Edit this cell").click()
    editor = cell.locator(".cm-content")
    editor.wait_for()
    editor.click()
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(code)
    wait_for_editor_text(page, index, code)


def first_cell(chapter: str, predicate) -> int:
    live = classified(chapter)
    for index, cell in enumerate(code_cells(chapter)):
        if live[index]["live"] and predicate(cell):
            return index
    raise AssertionError(f"no such cell in {chapter}")


def outside(offline: Offline, server: str) -> list[str]:
    return [u for u in offline.requests if not u.startswith((server, "data:", "blob:"))]


def stream_text(cell: Locator) -> str:
    return "".join(cell.locator(".live-output .live-stream").all_text_contents())


def test_first_page_loads_no_python_until_run(chapter_page, server):
    page, problems, offline = chapter_page("index.html")
    page.wait_for_load_state("networkidle")
    intro_requests = list(offline.requests)
    assert not [u for u in intro_requests if "/_static/live/" in u]
    page.goto(f"{server}/book/points-and-lines.html", wait_until="load")
    page.wait_for_load_state("networkidle")
    assert live_cell(page, 0).get_by_role("button", name="Run this cell (Shift+Enter)").is_enabled()
    # the controls are there, but Python and the editor are fetched only by Run and Edit
    assert not [u for u in offline.requests if "/pyodide/" in u or "worker.js" in u or "editor.js" in u]
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_points_and_lines_run_edit_and_named_error(chapter_page, server):
    chapter = "points-and-lines"
    page, problems, offline = chapter_page(f"book/{chapter}.html")
    cells = code_cells(chapter)

    # a derivation with a meet, run as stored: the earlier cells run first, then this one
    index = first_cell(chapter, lambda c: stored_stdout(c) and "meet(Line(" in source(c))
    cell = run(page, index)
    assert cell.get_attribute("data-live-state") == "done", cell.inner_text()
    assert stream_text(cell) == stored_stdout(cells[index])
    assert cell.locator(".cell_output").is_hidden()
    assert any("/pyodide/pyodide.asm.wasm" in u for u in offline.requests)

    # edit a coordinate of its first line; pgsym in this process says what the page must print
    original = source(cells[index])
    first_line = re.search(r"meet\(Line\((-?\d+), (-?\d+), (-?\d+)\), Line\((-?\d+), (-?\d+), (-?\d+)\)\)", original)
    a, b, c, d, e, f = (int(v) for v in first_line.groups())
    edited = f"X = meet(Line({a}, {b}, {c + 5}), Line({d}, {e}, {f}))\nprint(X, X.dehomogenize())"
    expected = pgsym.meet(pgsym.Line(a, b, c + 5), pgsym.Line(d, e, f))
    edit(page, index, edited)
    run(page, index, keyboard=True)  # Shift+Enter in the focused editor
    assert stream_text(cell) == f"{expected} {expected.dehomogenize()}\n"

    # a deliberately degenerate input: the named error and its message, the traceback folded away
    edit(page, index, "join(Point(1, 2), Point(2, 4, 2))")
    run(page, index)
    with pytest.raises(pgsym.CoincidentPointsError) as caught:
        pgsym.join(pgsym.Point(1, 2), pgsym.Point(2, 4, 2))
    assert cell.get_attribute("data-live-state") == "error"
    assert cell.locator(".live-error-name").inner_text() == "CoincidentPointsError"
    assert cell.locator(".live-error-message").inner_text() == f"CoincidentPointsError: {caught.value}"
    assert cell.locator(".live-traceback").get_attribute("open") is None
    assert cell.locator(".live-traceback pre").is_hidden()

    # Reset brings back the book's code and stored output
    cell.get_by_role("button", name="Reset this cell to the book's code and output").click()
    wait_for_editor_text(page, index, original)
    assert cell.locator(".cell_output").is_visible() and cell.locator(".live-output").is_hidden()

    # a later join/meet cell reuses the running Python: rendered as LaTeX by the page's MathJax
    later = first_cell(chapter, lambda c: "display(X)" in source(c) and "meet(Line(1, 0, -1)" in source(c))
    cell = run(page, later)
    assert cell.get_attribute("data-live-state") == "done"
    assert cell.locator(".live-output mjx-container").count() == 1
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_hierarchy_runs_proofs_and_disables_plots(chapter_page, server):
    chapter = "hierarchy-2d"
    page, problems, offline = chapter_page(f"book/{chapter}.html")
    cells = code_cells(chapter)
    index = first_cell(chapter, lambda c: stored_stdout(c) and "show_proofs(" in source(c))
    cell = run(page, index)
    assert cell.get_attribute("data-live-state") == "done", cell.inner_text()
    assert stream_text(cell) == stored_stdout(cells[index])

    # a Matplotlib cell: its controls are disabled, with the reason and the local command
    decided = classified(chapter)
    plot = next(i for i, c in enumerate(cells) if "plt." in source(c))
    plot_cell = live_cell(page, plot)
    assert plot_cell.get_attribute("data-live-state") == "disabled"
    run_button = plot_cell.get_by_role("button", name="Run this cell (not available in the page)")
    assert run_button.is_disabled()
    reason = plot_cell.locator(".live-reason")
    assert reason.inner_text() == f"{decided[plot]['reason']}. Run it locally: make lab NB={chapter}"
    assert "Matplotlib" in reason.inner_text()
    assert run_button.get_attribute("aria-describedby") == reason.get_attribute("id")
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_numpy_cell_is_disabled_with_its_reason(chapter_page, server):
    page, problems, offline = chapter_page("book/harris.html")
    page.wait_for_load_state("networkidle")
    index = next(i for i, c in enumerate(code_cells("harris")) if "np." in source(c))
    cell = live_cell(page, index)
    assert cell.get_attribute("data-live-state") == "disabled"
    for label in ("Edit this cell", "Run this cell", "Reset this cell"):
        assert cell.get_by_role("button", name=f"{label} (not available in the page)").is_disabled()
    assert "NumPy" in cell.locator(".live-reason").inner_text()
    assert "make lab NB=harris" in cell.locator(".live-reason").inner_text()
    assert not [u for u in offline.requests if "/pyodide/" in u]
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_classical_theorems_prove_pappus_in_the_page(chapter_page, server):
    chapter = "classical-theorems"
    page, problems, offline = chapter_page(f"book/{chapter}.html")
    cells = code_cells(chapter)
    index = first_cell(chapter, lambda c: stored_stdout(c) and 'summary("pappus")' in source(c))
    cell = run(page, index)
    assert cell.get_attribute("data-live-state") == "done", cell.inner_text()
    assert stream_text(cell) == stored_stdout(cells[index])
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_the_rule_in_the_page_matches_the_build(chapter_page):
    page, _, _ = chapter_page("book/classical-theorems.html")
    states = page.eval_on_selector_all(".live-cell", "cells => cells.map(c => c.dataset.liveState)")
    expected = ["idle" if c["live"] else "disabled" for c in classified("classical-theorems")]
    assert states == expected


def test_built_pages_describe_every_code_cell():
    """Each chapter carries its code cells' sources and classes for the controls; the first page none."""
    for chapter in ("points-and-lines", "hierarchy-2d", "classical-theorems"):
        html = (HTML / "book" / f"{chapter}.html").read_text(encoding="utf-8")
        count = len(code_cells(chapter))
        assert all(f"live-cell-{i}" in html for i in range(count))
        data = re.search(r'<script type="application/json" id="live-cells-data">(.*?)</script>', html, re.S)
        cells = json.loads(data.group(1).replace("<\\/", "</"))["cells"]
        assert [c["source"] for c in cells] == [source(c) for c in code_cells(chapter)]
        ast.parse(cells[0]["source"])
    assert "live-cells" not in (HTML / "index.html").read_text(encoding="utf-8")

