"""The students' table of the grade report stays within the page for very long names (Chromium)."""

from __future__ import annotations

from pgsym.exercises.grading import grade_rows
from pgsym.exercises.model import Answer
from pgsym.exercises.report import report_data, report_html

LONG = "Ä" * 800  # one word of 800 characters: nothing to break at


def _page() -> str:
    keys = {"s1": {"1": Answer.integer(3)}, "s2": {"1": Answer.integer(3)}}
    report = grade_rows(keys, [("s1", "1", "3"), ("s2", "1", "4")])
    data = report_data(report, {"s1": LONG, "s2": "Ada"}, {"1": "join"}, [])
    return report_html(data, "<svg></svg>", "<svg></svg>")


def test_a_long_name_is_cut_with_the_whole_name_in_the_title():
    page = _page()
    assert f'title="{LONG}"' in page and "Ä" * 80 + "…</td>" in page and "Ä" * 81 + "…" not in page


def test_the_table_fits_the_window_in_chromium(browser):
    page = browser.new_page(viewport={"width": 800, "height": 600})
    try:
        page.set_content(_page())
        page.wait_for_selector("table.students")
        widths = page.evaluate("""() => [document.querySelector('table.students').getBoundingClientRect().width,
                                         document.documentElement.scrollWidth,
                                         document.querySelector('td.who[title]').title.length]""")
    finally:
        page.close()
    table, scroll, title = widths
    assert table <= 800 and scroll <= 800 and title == 800  # it was 5774 px wide
