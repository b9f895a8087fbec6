"""The structure of the built book in a real browser: short visible code cells, exercises with solutions.

Uses the local server and the Chromium launch of the browser test. The lecture chapters are the pages of
Parts I to V of the table of contents (the lecture's mathematics, its proofs and its two exercises), not
the introduction, the instructors' and engineers' parts or the appendix; the rule on code cells holds on
every page.
"""

from __future__ import annotations

import pytest
import yaml
from _browser import ROOT, open_page, toc_pages

MAX_VISIBLE_LINES = 25
MIN_EXERCISES = 4


def lecture_chapters() -> list[str]:
    """The chapters that follow the lecture: the pages of Parts I to V."""
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    lecture = ("Part I", "Part II", "Part III", "Part IV", "Part V")
    parts = [p for p in toc["parts"] if p.get("caption", "").split(":")[0] in lecture]
    return [chapter["file"] for part in parts for chapter in part["chapters"]]


# Line counts of the code cells a reader sees; a cell inside a collapsed <details> is not rendered.
VISIBLE_CODE_LINES = """() => Array.from(document.querySelectorAll("div.cell_input pre"))
    .filter(pre => pre.checkVisibility())
    .map(pre => pre.innerText.replace(/\\n+$/, "").split("\\n").length)"""

# Every exercise with the ids of the solutions that link back to it.
EXERCISES = """() => Array.from(document.querySelectorAll("div.exercise")).map(ex => ({
    id: ex.id,
    solutions: Array.from(document.querySelectorAll(".solution")).filter(
        s => s.querySelector(`.admonition-title a[href="#${ex.id}"]`)).map(s => ({
            dropdown: s.classList.contains("dropdown"),
            hidden: s.classList.contains("toggle-hidden"),
        })),
}))"""


def test_the_lecture_chapters_are_found():
    chapters = lecture_chapters()
    assert "book/homogeneous-coordinates" in chapters and "book/rectification" in chapters
    assert len(chapters) == 18 and "book/exercise-sheets" not in chapters and "book/pgsym-errors" not in chapters
    assert "book/intro" not in chapters and all(page in toc_pages() for page in chapters)


@pytest.mark.parametrize("page_path", toc_pages())
def test_no_visible_code_cell_is_longer_than_25_lines(browser, server, page_path):
    page, _ = open_page(browser, f"{server}/{page_path}.html")
    try:
        counts = page.evaluate(VISIBLE_CODE_LINES)
        too_long = [n for n in counts if n > MAX_VISIBLE_LINES]
        assert too_long == [], f"visible code cells with {too_long} lines"
    finally:
        page.close()


def test_the_line_count_sees_a_long_cell_once_it_is_opened(browser, server):
    # the import cell of the 3D hierarchy chapter is longer than 25 lines and collapsed: opening it must
    # make the check above fail, so that the check can fail at all
    page, _ = open_page(browser, f"{server}/book/hierarchy-3d.html")
    try:
        assert max(page.evaluate(VISIBLE_CODE_LINES), default=0) <= MAX_VISIBLE_LINES
        details = page.locator("details.hide.above-input").first
        details.locator("summary").click()
        page.wait_for_function("() => document.querySelector('details.hide.above-input').open")
        assert max(page.evaluate(VISIBLE_CODE_LINES)) > MAX_VISIBLE_LINES
    finally:
        page.close()


@pytest.mark.parametrize("page_path", lecture_chapters())
def test_chapter_has_four_exercises_with_dropdown_solutions(browser, server, page_path):
    page, _ = open_page(browser, f"{server}/{page_path}.html")
    try:
        # sphinx-togglebutton collapses the dropdowns after load: wait for it before looking
        page.wait_for_function(
            "() => Array.from(document.querySelectorAll('.solution.dropdown'))"
            ".every(s => s.classList.contains('toggle'))"
        )
        exercises = page.evaluate(EXERCISES)
        assert len(exercises) >= MIN_EXERCISES, f"{len(exercises)} exercises"
        for ex in exercises:
            assert ex["solutions"], f"exercise {ex['id']} has no solution"
            assert all(s["dropdown"] and s["hidden"] for s in ex["solutions"]), f"{ex['id']}: solution not collapsed"
    finally:
        page.close()


# Code and printed output a reader sees that does not fit the page's width: at the default 1280 px viewport
# a code cell shows 75 characters. A <pre> wider than its box scrolls horizontally.
WIDE_BLOCKS = """() => Array.from(document.querySelectorAll("div.cell pre"))
    .filter(pre => pre.checkVisibility() && pre.scrollWidth > pre.clientWidth + 1)
    .map(pre => pre.innerText.split("\\n").reduce((a, b) => (b.length > a.length ? b : a), "").slice(0, 90))"""


@pytest.mark.parametrize("page_path", toc_pages())
def test_no_visible_code_or_output_is_wider_than_the_page(browser, server, page_path):
    page, _ = open_page(browser, f"{server}/{page_path}.html")
    try:
        assert page.viewport_size["width"] == 1280
        wide = page.evaluate(WIDE_BLOCKS)
        assert wide == [], f"{len(wide)} code or output blocks scroll sideways; their longest lines: {wide}"
    finally:
        page.close()


def test_the_width_check_sees_a_line_that_is_too_long(browser, server):
    # a line of 120 characters written into a visible cell must be found, so that the check can fail at all
    page, _ = open_page(browser, f"{server}/book/points-and-lines.html")
    try:
        page.evaluate("""() => { const pre = Array.from(document.querySelectorAll("div.cell_input pre"))
            .find(p => p.checkVisibility()); pre.textContent += "\\n" + "x".repeat(120); }""")
        assert len(page.evaluate(WIDE_BLOCKS)) >= 1
    finally:
        page.close()
