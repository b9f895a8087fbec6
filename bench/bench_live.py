"""Live cells in the page: headless Chromium against the built book on a loopback server, offline.

Each case is the median of 3 fresh pages. The first result of the first live cell of "Points and
lines" is timed from the click on Run. The page starts Python when it is idle (or when the reader
points at a cell), so the reader who clicks after reading a little finds it ready: the case clicks
once the page reports ``data-live-python="ready"``. The baseline is the previous behaviour, Python
started by the click (the same page with the idle start switched off), timed the same way. Then a
later join/meet cell once Python runs, and ``prove("pappus")`` typed into a cell. The first line
also reports ``node_reference_s``, the same start-up in Node, which shows how loaded the machine was.
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from playwright.sync_api import Page, sync_playwright
from timing import report

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
from _browser import CHROMIUM, CHROMIUM_ARGS, HTML, serve  # noqa: E402

OFFLINE = [*CHROMIUM_ARGS, "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"]
TIMEOUT_MS = 180_000


# The same steps in Node, outside any browser: how fast this machine runs Pyodide right now. On a
# loaded machine every case slows down by about the same factor as this reference.
NODE_REFERENCE = """
import { loadPyodide } from "%(pyodide)s";
import { readFileSync } from "node:fs";
const start = performance.now();
const py = await loadPyodide({ indexURL: "%(index)s" });
for (const name of %(wheels)s) py.unpackArchive(new Uint8Array(readFileSync("%(wheels_dir)s/" + name)), "wheel");
py.runPython("import sympy\\nfrom pgsym import Point, join\\njoin(Point(1, 2), Point(3, 4))");
console.log((performance.now() - start) / 1000);
"""


def node_reference_s() -> float:
    """Seconds for Node to boot Pyodide, unpack the book's wheels, import SymPy and compute one join."""
    live = HTML / "_static" / "live"
    wheels = json.loads((live / "wheels" / "manifest.json").read_text())["wheels"]
    script = NODE_REFERENCE % {"pyodide": (live / "pyodide" / "pyodide.mjs").as_uri(),
                               "index": f"{live / 'pyodide'}/", "wheels": json.dumps(wheels),
                               "wheels_dir": live / "wheels"}
    with tempfile.NamedTemporaryFile("w", suffix=".mjs") as f:
        f.write(script)
        f.flush()
        out = subprocess.run(["node", f.name], capture_output=True, text=True, check=True, timeout=300)
    return float(out.stdout.split()[-1])


def run_cell(page: Page, index: int) -> float:
    """Click Run on a cell; seconds until its output is shown."""
    runs = int(page.locator(f".live-cell-{index}").get_attribute("data-live-runs") or 0)
    start = time.perf_counter()
    page.locator(f".live-cell-{index}").get_by_role("button", name="Run this cell (Shift+Enter)").click()
    page.wait_for_function(
        "([i, runs]) => Number(document.querySelector(`.live-cell-${i}`).dataset.liveRuns || 0) > runs",
        arg=[index, runs], timeout=TIMEOUT_MS, polling=10)
    elapsed = time.perf_counter() - start
    state = page.locator(f".live-cell-{index}").get_attribute("data-live-state")
    assert state == "done", page.locator(f".live-cell-{index} .live-output").inner_text()
    return elapsed


NO_IDLE_START = "window.requestIdleCallback = () => 0;"  # the previous behaviour: Python starts on Run


def first_result(browser, base: str, *, idle_start: bool) -> tuple[float, float]:
    """Seconds from the click on the first live cell of "Points and lines" to its output, and from the
    page's load event to Python being ready (0 when Python is started by the click)."""
    context = browser.new_context()
    if not idle_start:
        context.add_init_script(NO_IDLE_START)
    page = context.new_page()
    page.goto(f"{base}/book/points-and-lines.html", wait_until="load")
    loaded = time.perf_counter()
    if idle_start:
        page.wait_for_function("() => document.documentElement.dataset.livePython === 'ready'",
                               timeout=TIMEOUT_MS, polling=10)
    ready = time.perf_counter() - loaded if idle_start else 0.0
    first = page.locator(".live-cell[data-live-state='idle']:not([data-live-hidden])").first
    index = int(next(c for c in first.get_attribute("class").split() if c.startswith("live-cell-"))[10:])
    elapsed = run_cell(page, index)
    context.close()
    return elapsed, ready


def main() -> None:
    assert (HTML / "index.html").is_file(), "the book is not built: run `make book`"
    with serve(HTML) as base, sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=OFFLINE, headless=True)
        idle = [first_result(browser, base, idle_start=True) for _ in range(3)]
        before = statistics.median(first_result(browser, base, idle_start=False)[0] for _ in range(3))
        report("live cell: first result on Points and lines, clicked once the page is idle (median of 3)",
               statistics.median(t for t, _ in idle), "Python started by the click (previous behaviour)", before,
               budget_s=3.0, ready_after_load_s=round(statistics.median(r for _, r in idle), 3),
               node_reference_s=round(node_reference_s(), 3))

        page = browser.new_page()
        page.goto(f"{base}/book/points-and-lines.html", wait_until="load")
        page.wait_for_function("() => document.documentElement.dataset.livePython === 'ready'", timeout=TIMEOUT_MS)
        # a later join/meet cell: the meet of two lines, rendered by MathJax
        later = page.locator(".live-cell", has_text="meet(Line(1, 0, -1), Line(0, 1, -1))").first
        later_index = int(next(c for c in later.get_attribute("class").split() if c.startswith("live-cell-"))[10:])
        run_cell(page, later_index)  # runs the cells in between once
        times = [run_cell(page, later_index) for _ in range(3)]
        report("live cell: a later join/meet cell (median of 3)", statistics.median(times), "budget 0.2 s", 0.2)

        # prove("pappus") typed into a cell (the page's first proof of it)
        cell = page.locator(f".live-cell-{later_index}")
        cell.get_by_role("button", name="Edit this cell").click()
        cell.locator(".cm-content").click()
        page.keyboard.press("Control+a")
        page.keyboard.insert_text('from pgsym.proofs import prove\nassert prove("pappus").proved')
        report('live cell: prove("pappus") in the page', run_cell(page, later_index), "budget 5 s", 5.0)
        browser.close()


if __name__ == "__main__":
    main()
