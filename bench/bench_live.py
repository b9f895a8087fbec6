"""Live cells in the page: headless Chromium against the built book on a loopback server, offline.

Each case is the median of 3 fresh pages of "Points and lines", timed from the click on Run of its
first live cell until that cell's output is shown and typeset: the page's own time, between the marks
``live:run`` (its click handler) and ``live:shown``. ``wall_s`` is the same seen from this script, which
adds the browser driver's work (a tenth of a second or more on a loaded machine).

1. The reader clicks Run as soon as the page has loaded (its load event): Python is still starting.
   The page starts it as soon as it is parsed, from the memory snapshot made when the book was built;
   the baseline is the same page when the snapshot cannot be loaded (Python started in full, SymPy and
   pgsym imported in the page). The line also gives the median of each phase of the start-up, from the
   worker's own timestamps (``performance.mark`` entries ``live:*``), and the Node reference.
2. The reader clicks once the page reports ``data-live-python="ready"`` (budget 3 s).
3. A later join/meet cell once Python runs (budget 0.2 s), and ``prove("pappus")`` typed into a cell
   (budget 5 s).

``node_reference_s`` on the first line is the same start-up in Node (Pyodide, the wheels, importing
SymPy and pgsym, one join), without a browser and without the snapshot: how loaded the machine was.
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from playwright.sync_api import Browser, Page, sync_playwright
from timing import report

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
from _browser import CHROMIUM, CHROMIUM_ARGS, HTML, serve  # noqa: E402

OFFLINE = [*CHROMIUM_ARGS, "--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1"]
TIMEOUT_MS = 180_000
CHAPTER = "book/points-and-lines.html"


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


def cell_index(page: Page, selector: str) -> int:
    classes = page.locator(selector).first.get_attribute("class").split()
    return int(next(c for c in classes if c.startswith("live-cell-"))[len("live-cell-"):])


# The page's own time of the last run: from its click handler (mark live:run) to the output shown and
# typeset (mark live:shown), in seconds.
PAGE_TIME = """() => {
  const last = (name) => performance.getEntriesByName(name).at(-1).startTime;
  return (last("live:shown") - last("live:run")) / 1000;
}"""


def run_cell(page: Page, index: int) -> tuple[float, float]:
    """Click Run on a cell and wait for its output: the page's time from the click to the output shown,
    and the wall time seen from here (which adds the browser driver's own work, large on a loaded machine)."""
    cell = page.locator(f".live-cell-{index}")
    runs = int(cell.get_attribute("data-live-runs") or 0)
    start = time.perf_counter()
    cell.get_by_role("button", name="Run this cell (Shift+Enter)").click()
    page.wait_for_function(
        "([i, runs]) => Number(document.querySelector(`.live-cell-${i}`).dataset.liveRuns || 0) > runs",
        arg=[index, runs], timeout=TIMEOUT_MS, polling=10)
    wall = time.perf_counter() - start
    assert cell.get_attribute("data-live-state") == "done", cell.locator(".live-output").inner_text()
    return page.evaluate(PAGE_TIME), wall


# The phases of the start-up, between the worker's marks (seconds; a phase the page skipped is absent).
PHASES = {
    "worker_s": ("navigation", "live:worker"),  # from the navigation to the worker's script running
    "python_s": ("live:worker", "live:python-restored|live:python-started"),  # snapshot or full start
    "install_s": ("live:python-restored|live:python-started", "live:wheels-installed"),  # wheels, kernel
    "sympy_s": ("live:wheels-installed", "live:sympy-imported"),  # only without the snapshot
    "wait_after_click_s": ("live:run", "live:ready"),  # how long the click waited for Python
    # the chapter's hidden import cell (from pgsym import ...), then the clicked cell, run and typeset
    "import_cell_s": ("live:ready|live:run", "first cell"),
    "clicked_cell_s": ("first cell", "live:shown"),
}


def phases(page: Page) -> dict[str, float]:
    # the last mark of each name (a dict keeps the last)
    marks = dict(page.evaluate("performance.getEntriesByType('mark').map(m => [m.name, m.startTime])"))
    marks["load"] = page.evaluate("performance.getEntriesByType('navigation')[0].loadEventStart")
    marks["navigation"] = 0.0
    cells = sorted(t for name, t in marks.items() if name.startswith("live:cell-"))
    if cells:
        marks["first cell"] = cells[0]
    out = {"load_event_s": marks["load"] / 1000}  # from the navigation to the page's load event
    for phase, (start, end) in PHASES.items():
        # the first of the alternatives the page recorded; for the cells, the later of ready and the click
        found = [marks[m] for m in start.split("|") if m in marks]
        a = (max(found) if phase == "import_cell_s" else found[0]) if found else None
        b = next((marks[m] for m in end.split("|") if m in marks), None)
        if a is not None and b is not None:
            out[phase] = max(0.0, (b - a) / 1000)
    return out


def first_result(browser: Browser, base: str, *, at_load: bool, snapshot: bool = True) -> tuple[float, dict]:
    """Seconds from the click on the first live cell of the chapter to its output (the page's time),
    clicked at the load event or once Python is ready; and the phases of the start-up."""
    context = browser.new_context()
    if not snapshot:
        context.route("**/pyodide/snapshot.*", lambda route: route.fulfill(status=404))
    page = context.new_page()
    page.goto(f"{base}/{CHAPTER}", wait_until="load")
    if not at_load:
        page.wait_for_function("() => document.documentElement.dataset.livePython === 'ready'",
                               timeout=TIMEOUT_MS, polling=10)
    index = cell_index(page, ".live-cell[data-live-state='idle']:not([data-live-hidden])")
    elapsed, wall = run_cell(page, index)
    detail = {**phases(page), "wall_s": wall}
    context.close()
    return elapsed, detail


def medians(runs: list[tuple[float, dict]]) -> tuple[float, dict[str, float]]:
    keys = sorted({k for _, d in runs for k in d})
    return (statistics.median(t for t, _ in runs),
            {k: round(statistics.median(d[k] for _, d in runs if k in d), 3) for k in keys})


def main() -> None:
    assert (HTML / "index.html").is_file(), "the book is not built: run `make book`"
    assert (HTML / "_static" / "live" / "pyodide" / "snapshot.bin").is_file(), "no snapshot: run `make live`"
    reference = node_reference_s()
    with serve(HTML) as base, sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=OFFLINE, headless=True)
        # the two ways alternate, so that both see the same machine load
        ours, without = [], []
        for _ in range(3):
            ours.append(first_result(browser, base, at_load=True))
            without.append(first_result(browser, base, at_load=True, snapshot=False))
        ours_s, ours_phases = medians(ours)
        without_s, without_phases = medians(without)
        report("live cell: first result on Points and lines, Run clicked at the page's load event (median of 3)",
               ours_s, "the same without the snapshot (Python started in full in the page)", without_s,
               budget_s=3.0, phases=ours_phases, baseline_phases=without_phases,
               node_reference_s=round(reference, 3))

        ready, ready_phases = medians([first_result(browser, base, at_load=False) for _ in range(3)])
        report("live cell: first result on Points and lines, Run clicked once Python is ready (median of 3)",
               ready, "budget 3 s", 3.0, phases=ready_phases)

        page = browser.new_page()
        page.goto(f"{base}/{CHAPTER}", wait_until="load")
        page.wait_for_function("() => document.documentElement.dataset.livePython === 'ready'", timeout=TIMEOUT_MS)
        # a later join/meet cell: the meet of two lines, rendered by MathJax
        later = cell_index(page, ".live-cell:has-text('meet(Line(1, 0, -1), Line(0, 1, -1))')")
        run_cell(page, later)  # runs the cells in between once
        times = [run_cell(page, later) for _ in range(3)]
        report("live cell: a later join/meet cell (median of 3)", statistics.median(t for t, _ in times),
               "budget 0.2 s", 0.2, wall_s=round(statistics.median(w for _, w in times), 3))

        # prove("pappus") typed into a cell (the page's first proof of it)
        cell = page.locator(f".live-cell-{later}")
        cell.get_by_role("button", name="Edit this cell").click()
        cell.locator(".cm-content").click()
        page.keyboard.press("Control+a")
        page.keyboard.insert_text('from pgsym.proofs import prove\nassert prove("pappus").proved')
        proof, wall = run_cell(page, later)
        report('live cell: prove("pappus") in the page', proof, "budget 5 s", 5.0, wall_s=round(wall, 3),
               node_reference_s=round(node_reference_s(), 3))
        browser.close()


if __name__ == "__main__":
    main()
