"""Live cells: readers run the book's derivations in the page, offline (Pyodide in a Web Worker).

The browser tests open chapters of the built book from a loopback server in Debian's Chromium with
every other host unreachable (a resolver rule) and every request elsewhere aborted (a route). Expected
outputs come from the notebooks' stored outputs, read at test time, or from pgsym in this process.
"""

from __future__ import annotations

import ast
import json
import os
import re
import subprocess
import sys
from collections.abc import Iterator
from importlib.metadata import version
from urllib.parse import urlparse

import pytest
from _browser import CHROMIUM, CHROMIUM_ARGS, HTML, ROOT, SAVE_DATA, PageProblems
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
    """The code cells of a chapter that its page shows (a cell tagged remove-cell is not in the page)."""
    notebook = json.loads((ROOT / "book" / f"{chapter}.ipynb").read_text(encoding="utf-8"))
    return [cell for cell in notebook["cells"] if cell["cell_type"] == "code"
            and "remove-cell" not in cell.get("metadata", {}).get("tags", [])]


def source(cell: dict) -> str:
    return "".join(cell["source"])


def shown(cell: dict) -> bool:
    """Whether the reader sees the cell's code (hidden cells, the chapters' imports, have no controls)."""
    return not {"hide-input", "hide-cell", "remove-input"} & set(cell.get("metadata", {}).get("tags", []))


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
                assert decided["reason"].endswith("which the page cannot load")
    # the chapter on points and lines is exact: every cell but its figures runs in the page
    chapter = "points-and-lines"
    decided = classified(chapter)
    exact = [d for c, d in zip(code_cells(chapter), decided, strict=True) if not PLOT_OR_ARRAY.search(source(c))]
    assert all(d["live"] for d in exact) and len(exact) >= len(decided) - 2
    # the Harris chapter needs OpenCV and NumPy for its images; its SymPy derivations run in the page
    harris = [(source(c), d) for c, d in zip(code_cells("harris"), classified("harris"), strict=True)]
    assert all("np." not in src and "cv2." not in src for src, d in harris if d["live"])
    assert any("sp.symbols" in src for src, d in harris if d["live"])


def test_rule_follows_pgsym_imports():
    assert live_cells.missing_package("pgsym.transformations") is None
    assert live_cells.missing_package("pgsym.proofs") is None
    assert live_cells.missing_package("pgsym.vision.harris") == "numpy"
    [cell] = live_cells.classify_cells([("from pgsym.numeric import meet\nmeet([0, 1, 2], [1, 0, 3])", [])])
    assert cell == {"source": cell["source"], "live": False, "stubs": ["pgsym.numeric"],
                    "quiet": cell["source"].split("\n")[0],
                    "reason": "Uses meet from pgsym.numeric, which needs NumPy, which the page cannot load"}
    # the book's own modules: _show is pure (shipped to the page), _plot draws with Matplotlib
    assert [p.name for p in live_cells.local_modules()] == ["_show.py"]
    [show, plot] = live_cells.classify_cells([("from _show import dot\ndot((1, 2), (3, 4))", []),
                                              ("import _plot\n_plot.meet_of_two_lines(1, 2, 3)", [])])
    assert show["live"] and plot["reason"] == "Draws with Matplotlib (through _plot), which the page cannot load"


def test_a_cell_that_cannot_run_still_defines_its_sympy_names():
    # the chapters' import cells set a Matplotlib option: the cell cannot run, its SymPy import can
    first, second = live_cells.classify_cells([
        ("import matplotlib.pyplot as plt\nimport sympy as sp\n"
         "plt.rcParams['figure.dpi'] = 150\nx = sp.Integer(2)", []),
        ("print(x ** 2, sp.sqrt(x))", [])])
    assert not first["live"] and second["live"]
    assert first["quiet"] == "import matplotlib.pyplot as plt\nimport sympy as sp\nx = sp.Integer(2)"
    # in the page (here: a package this process lacks too), the quiet code defines x for the next cell
    first, second = live_cells.classify_cells([
        ("import no_such_package as nsp\nimport sympy as sp\nnsp.draw()\nx = sp.Integer(2)", []),
        ("print(x ** 2, sp.sqrt(x))", [])])
    kernel = live_kernel.Kernel()
    assert kernel.run(first["quiet"], first["stubs"]) == []
    assert kernel.run(second["source"]) == [{"type": "stream", "name": "stdout", "text": "4 sqrt(2)\n"}]
    # a list filled by a statement that cannot run is not usable afterwards
    cells = live_cells.classify_cells([("import numpy as np\npts = []\npts.append(np.ones(2))", []), ("len(pts)", [])])
    assert [c["live"] for c in cells] == [False, False]
    assert cells[1]["reason"] == "Uses pts, which depends on NumPy, which the page cannot load"


# A package as a reason names it: the modules whose loading brings it in.
PACKAGE_MODULES = {"NumPy": {"numpy"}, "Matplotlib": {"matplotlib", "mpl_toolkits"}, "OpenCV": {"cv2"},
                   "scikit-image": {"skimage"}, "SciPy": {"scipy"}, "Pillow": {"PIL"}}


def _loads(module: str, package_modules: set[str], cache: dict) -> bool:
    """Whether importing ``module`` really loads one of ``package_modules`` (in a fresh interpreter)."""
    key = (module, frozenset(package_modules))
    if key not in cache:
        if module.split(".")[0] in package_modules:
            cache[key] = True
        else:
            tops = sorted(package_modules)
            check = f"import sys, {module}; print(any(m.split('.')[0] in {tops!r} for m in sys.modules))"
            env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), str(ROOT / "book")])}
            out = subprocess.run([sys.executable, "-c", check], capture_output=True, text=True, env=env,
                                 cwd=ROOT / "book")
            cache[key] = out.stdout.strip() == "True"
    return cache[key]


def _imports_of(tree: ast.AST) -> list[str]:
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.append(node.module)
    return found


def _bound(stmt: ast.stmt) -> set[str]:
    names = {n.id for n in ast.walk(stmt) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
    names |= {d.name for d in ast.walk(stmt) if isinstance(d, ast.FunctionDef | ast.ClassDef)}
    for node in ast.walk(stmt):
        if isinstance(node, ast.Import | ast.ImportFrom):
            names |= {(a.asname or a.name).split(".")[0] for a in node.names}
    return names


def _loaded(stmt: ast.stmt) -> set[str]:
    return {n.id for n in ast.walk(stmt) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)}


def test_every_disabled_cell_of_the_book_gives_a_true_reason():
    """The package a disabled cell names is really loaded by an import among the statements it comes
    from: the cell's own, or for "Uses X" the statement that last bound X, followed back through the
    names those statements use to the statements that bound them. So "Uses sp, which depends on
    Matplotlib" is false when sp comes from ``import sympy as sp``; no reason names a book module."""
    cache: dict = {}
    disabled = 0
    for chapter in sorted(p.stem for p in (ROOT / "book").glob("*.ipynb")):
        cells = code_cells(chapter)
        stmts = [(k, stmt) for k, c in enumerate(cells) for stmt in ast.parse(source(c)).body]

        def definer(name: str, before: int, stmts: list = stmts) -> list[int]:
            found = [i for i in range(before) if name in _bound(stmts[i][1])]
            return found[-1:]

        for index, decided in enumerate(classified(chapter)):
            if decided["live"] or "only locally" in decided["reason"]:
                continue
            disabled += 1
            reason = decided["reason"]
            assert reason.endswith(", which the page cannot load"), (chapter, index, reason)
            named = [name for name in PACKAGE_MODULES if name in reason]
            assert len(named) == 1 and reason.count(named[0]) == 1, (chapter, index, reason)
            own = [i for i, (k, _) in enumerate(stmts) if k == index]
            uses = re.match(r"Uses (\w+)(,| from)", reason)
            todo = definer(uses.group(1), own[-1] + 1) if uses and uses.group(1) not in PACKAGE_MODULES else own
            assert todo, (chapter, index, reason)
            seen: set[int] = set()
            while todo:
                i = todo.pop()
                if i in seen:
                    continue
                seen.add(i)
                for name in _loaded(stmts[i][1]):
                    todo += definer(name, i)
            modules = PACKAGE_MODULES[named[0]]
            imported = [m for i in seen for m in _imports_of(stmts[i][1])]
            assert any(_loads(m, modules, cache) for m in imported), (chapter, index, reason)
    assert disabled > 0  # the book has figures; every one of them was checked above


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


def test_python_starts_while_the_page_loads_and_hidden_cells_have_no_controls(chapter_page, server):
    page, problems, offline = chapter_page("index.html")
    page.wait_for_load_state("networkidle")
    assert not [u for u in offline.requests if "/_static/live/" in u]  # a page without code cells
    page.goto(f"{server}/book/points-and-lines.html", wait_until="load")
    # Python (and the book's pure modules) load with the page, before any Run, from the book's snapshot
    page.wait_for_function("() => document.documentElement.dataset.livePython === 'ready'", timeout=RUN_TIMEOUT_MS)
    assert page.evaluate("document.documentElement.dataset.livePythonStart") == "snapshot"
    assert any(u.endswith("/_static/live/pyodide/snapshot.bin") for u in offline.requests)
    assert any(u.endswith("/_static/live/modules/_show.py") for u in offline.requests)
    assert not [u for u in offline.requests if "editor.js" in u]  # the editor waits for Edit
    # the chapter's hidden import cell runs with the others but shows no controls
    cells = code_cells("points-and-lines")
    hidden = [i for i, c in enumerate(cells) if "hide-input" in c.get("metadata", {}).get("tags", [])]
    assert hidden
    for index in hidden:
        assert live_cell(page, index).locator(".live-toolbar").count() == 0
        assert live_cell(page, index).get_attribute("data-live-hidden") == ""
    shown = next(i for i, c in enumerate(cells) if i not in hidden)
    assert live_cell(page, shown).locator(".live-toolbar button").count() == 3
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_python_waits_for_the_reader_when_the_browser_saves_data(offline_browser, server):
    """With Save-Data on, the page loads nothing for Python until the reader points at a live cell."""
    context = offline_browser.new_context()
    context.add_init_script(SAVE_DATA)
    offline = Offline(context, server)
    page = context.new_page()
    problems = PageProblems(page)
    page.goto(f"{server}/book/points-and-lines.html", wait_until="load")
    page.wait_for_load_state("networkidle")
    assert not [u for u in offline.requests if "/_static/live/pyodide/" in u or u.endswith("/worker.js")]
    assert page.evaluate("document.documentElement.dataset.livePython") is None
    index = first_cell("points-and-lines", shown)
    live_cell(page, index).hover()
    page.wait_for_function("() => document.documentElement.dataset.livePython === 'ready'", timeout=RUN_TIMEOUT_MS)
    assert any(u.endswith("/_static/live/pyodide/snapshot.bin") for u in offline.requests)
    context.close()
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def marks(page: Page) -> list[str]:
    """The names of the start-up's moments the page recorded (performance marks ``live:*``)."""
    return page.evaluate("performance.getEntriesByType('mark').map((m) => m.name)")


def test_a_run_at_the_load_event_shows_the_result_from_the_snapshot(offline_browser, server):
    """The reader clicks Run as soon as the page has loaded: the cell waits for Python, which the page
    restores from the book's snapshot (SymPy and pgsym already imported), then shows the cell's result."""
    context = offline_browser.new_context()
    offline = Offline(context, server)
    page = context.new_page()
    problems = PageProblems(page)
    page.goto(f"{server}/book/points-and-lines.html", wait_until="load")
    cells = code_cells("points-and-lines")
    index = next(i for i, c in enumerate(cells) if shown(c) and classified("points-and-lines")[i]["live"])
    cell = run(page, index)
    assert cell.get_attribute("data-live-state") == "done", cell.inner_text()
    # the cell displays a line as LaTeX (typeset by the page's MathJax), as its stored output does
    assert "text/latex" in cells[index]["outputs"][0]["data"]
    assert cell.locator(".live-output mjx-container").count() == len(cells[index]["outputs"])
    seen = marks(page)
    assert "live:python-restored" in seen and "live:sympy-imported" not in seen
    assert seen.index("live:python-restored") < seen.index("live:ready") < seen.index("live:shown")
    context.close()
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_modules_the_snapshot_did_not_import_load_from_the_wheels(chapter_page):
    """After a restore the packages' files are still there: a SymPy module nobody imported yet loads,
    the installed versions are those of this checkout's environment, and `random` differs per page."""
    chapter = "points-and-lines"
    values = []
    for _ in range(2):
        page, problems, _ = chapter_page(f"book/{chapter}.html")
        index = first_cell(chapter, lambda c: shown(c))
        edit(page, index, "from sympy.combinatorics.graycode import GrayCode\n"
                          "from importlib.metadata import version\nimport random\n"
                          "print(list(GrayCode(2).generate_gray()), version('sympy'), version('pgsym'))\n"
                          "print(random.random())")
        cell = run(page, index)
        assert cell.get_attribute("data-live-state") == "done", cell.inner_text()
        assert page.evaluate("document.documentElement.dataset.livePythonStart") == "snapshot"
        codes, value = stream_text(cell).splitlines()
        # the binary reflected Gray code of length 2: 00, 01, 11, 10
        assert codes == f"['00', '01', '11', '10'] {version('sympy')} {version('pgsym')}"
        values.append(float(value))
        assert problems.items == []
    # the snapshot fixed the generator's state; the page seeds it afresh
    assert values[0] != values[1]


def test_without_a_usable_snapshot_python_starts_in_full(offline_browser, server):
    """A snapshot the page cannot use (here: its bytes replaced) is reported on the console and Python
    starts in full, importing SymPy in the page; the cell's result is the same."""
    context = offline_browser.new_context()
    offline = Offline(context, server)
    context.route("**/pyodide/snapshot.bin", lambda route: route.fulfill(status=200, body=b"\0" * 65536))
    page = context.new_page()
    warnings: list[str] = []
    page.on("console", lambda msg: msg.type == "warning" and warnings.append(msg.text))
    page.goto(f"{server}/book/points-and-lines.html", wait_until="load")
    chapter = "points-and-lines"
    index = first_cell(chapter, lambda c: stored_stdout(c) and "meet(Line(" in source(c))
    cell = run(page, index)
    assert cell.get_attribute("data-live-state") == "done", cell.inner_text()
    assert stream_text(cell) == stored_stdout(code_cells(chapter)[index])
    assert page.evaluate("document.documentElement.dataset.livePythonStart") == "full"
    assert "live:sympy-imported" in marks(page) and "live:python-restored" not in marks(page)
    assert any("the Python snapshot did not load" in w for w in warnings), warnings
    context.close()
    assert offline.blocked == [] and outside(offline, server) == []


def test_a_cell_after_a_plot_uses_the_sympy_of_the_import_cell(chapter_page):
    """The DLT chapter's import cell sets a Matplotlib option; its SymPy import still runs in the page."""
    chapter = "dlt"
    page, problems, _ = chapter_page(f"book/{chapter}.html")
    cells, decided = code_cells(chapter), classified(chapter)
    assert not decided[0]["live"] and "import sympy as sp" in decided[0]["quiet"]
    index = first_cell(chapter, lambda c: "sp.symbols" in source(c))
    cell = run(page, index)
    assert cell.get_attribute("data-live-state") == "done", cell.inner_text()
    if stored_stdout(cells[index]) is not None:
        assert stream_text(cell) == stored_stdout(cells[index])
    assert problems.items == []


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

    # the figures are drawn by hidden Matplotlib cells: they cannot run, and show no controls
    decided = classified(chapter)
    plot = next(i for i, c in enumerate(cells) if "plt." in source(c))
    assert not shown(cells[plot]) and "Matplotlib" in decided[plot]["reason"]
    plot_cell = live_cell(page, plot)
    assert plot_cell.get_attribute("data-live-state") == "disabled"
    assert plot_cell.locator(".live-toolbar").count() == 0
    assert problems.items == [] and offline.blocked == [] and outside(offline, server) == []


def test_numpy_cell_is_disabled_with_its_reason(chapter_page, server):
    page, problems, offline = chapter_page("book/harris.html")
    page.wait_for_load_state("networkidle")
    index = next(i for i, c in enumerate(code_cells("harris")) if "np." in source(c) and shown(c))
    cell = live_cell(page, index)
    assert cell.get_attribute("data-live-state") == "disabled"
    for label in ("Edit this cell", "Run this cell", "Reset this cell"):
        assert cell.get_by_role("button", name=f"{label} (not available in the page)").is_disabled()
    reason = cell.locator(".live-reason")
    decided = classified("harris")[index]
    assert reason.inner_text() == f"{decided['reason']}. Run it locally: make lab NB=harris"
    assert "NumPy" in reason.inner_text()
    run_button = cell.get_by_role("button", name="Run this cell (not available in the page)")
    assert run_button.get_attribute("aria-describedby") == reason.get_attribute("id")
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

