"""``pgsym check --report`` and ``--canvas``: the numbers of the page, its JSON and the Canvas CSV agree
with the graded CSV; hostile names and answers stay text; the page opens in Chromium without errors."""

from __future__ import annotations

import csv
import io
import json
import re
from collections import Counter
from pathlib import Path

import pytest
from _browser import PageProblems, serve
from click.testing import CliRunner

from pgsym.cli import main
from pgsym.exercises.sheets import build_sheets, manifest_json, parse_topics

HOSTILE_NAME = "<script>alert(1)</script> =HYPERLINK(\"x\")"
HOSTILE_ANSWER = "</code><img src=x onerror=alert(1)>"


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    """A class of 12 with right answers, recognised mistakes, other wrong, unreadable and missing ones."""
    base = tmp_path_factory.mktemp("report")
    topics = parse_topics(["ideal:2", "apply-line:2", "cross-ratio", "classify:3"])
    students = [(f"s{i:02d}", HOSTILE_NAME if i == 3 else f"Student {i}") for i in range(12)]
    sheets = build_sheets(topics, students, 3)
    (base / "manifest.json").write_text(manifest_json(sheets, topics))
    rows = [["id", "question", "answer"]]
    for i, sheet in enumerate(sheets):
        for j, part in enumerate(p for ex in sheet.exercises for p in ex.parts):
            pick = (i + j) % 5
            if pick in (0, 1):
                text = part.answer.display()
            elif pick == 2 and part.mistakes and part.mistakes[0].answer.kind == part.answer.kind:
                text = part.mistakes[0].answer.display()
            elif pick == 3:
                text = HOSTILE_ANSWER if i == 3 else "7"
            else:
                continue  # no answer
            rows.append([sheet.student_id, part.label, text])
    with (base / "answers.csv").open("w", newline="") as f:
        csv.writer(f).writerows(rows)
    result = CliRunner().invoke(main, ["check", "--manifest", str(base / "manifest.json"), "--answers",
                                       str(base / "answers.csv"), "--out", str(base / "grades.csv"),
                                       "--report", str(base / "report"), "--canvas", str(base / "canvas.csv"),
                                       "--canvas-title", "Week 4", "--canvas-id", "42"], catch_exceptions=False)
    assert result.exit_code == 3, result.output  # the hostile answer cannot be read; all others graded
    return base


def _graded_rows(base: Path) -> list[dict[str, str]]:
    return list(csv.DictReader(io.StringIO((base / "grades.csv").read_text())))


def test_report_json_matches_the_graded_csv(graded):
    rows = _graded_rows(graded)
    data = json.loads((graded / "report" / "report.json").read_text())
    right = Counter(r["student"] for r in rows if r["correct"] == "1")
    assert {s["id"]: s["right"] for s in data["students"]} == {f"s{i:02d}": right[f"s{i:02d}"] for i in range(12)}
    assert data["summary"]["right"] == sum(right.values())
    assert sum(data["histogram"]) == 12 and data["summary"]["questions"] == 5
    for q in data["questions"]:
        assert q["right"] == sum(r["correct"] == "1" for r in rows if r["question"] == q["question"])
    mistakes = Counter(r["mistake"] for r in rows if r["mistake"])
    assert {m["mistake"]: m["count"] for m in data["mistakes"]} == dict(mistakes)
    assert data["summary"]["recognised"] == sum(mistakes.values()) > 0
    assert sorted(p.name for p in (graded / "report").iterdir()) == ["index.html", "questions.svg", "report.json",
                                                                     "scores.svg"]


def test_report_page_is_static_and_escapes_user_text(graded):
    page = (graded / "report" / "index.html").read_text()
    assert "<script" not in page and "<img" not in page
    # nothing to fetch: every src or href is inline data or a fragment of the page itself
    assert re.findall(r'(?:src|href)="(?!data:|#)', page) == []
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in page
    assert "Content-Security-Policy" in page and page.count("<svg") == 2
    for svg in ("scores.svg", "questions.svg"):
        text = (graded / "report" / svg).read_text()
        assert text.lstrip().startswith("<?xml") and "<script" not in text


def test_canvas_gradebook_csv(graded):
    rows = list(csv.reader(io.StringIO((graded / "canvas.csv").read_text())))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Week 4 (42)"]
    assert rows[1] == ["Points Possible", "", "", "", "", "5"]
    right = Counter(r["student"] for r in _graded_rows(graded) if r["correct"] == "1")
    assert {r[2]: int(r[5]) for r in rows[2:]} == {f"s{i:02d}": right[f"s{i:02d}"] for i in range(12)}
    assert rows[5][0] == HOSTILE_NAME  # csv-quoted, and no formula: the cell starts with '<'
    assert rows[3][0] == "Student 1" and rows[3][1] == "" and rows[3][3] == ""


def test_same_grades_same_report_bytes_and_a_used_folder_is_refused(graded, tmp_path):
    args = ["check", "--manifest", str(graded / "manifest.json"), "--answers", str(graded / "answers.csv")]
    result = CliRunner().invoke(main, [*args, "--report", str(tmp_path / "again")], catch_exceptions=False)
    assert result.exit_code == 3
    for name in ("index.html", "report.json", "scores.svg", "questions.svg"):
        assert (tmp_path / "again" / name).read_bytes() == (graded / "report" / name).read_bytes(), name
    result = CliRunner().invoke(main, [*args, "--report", str(tmp_path / "again")], catch_exceptions=False)
    assert result.exit_code == 1 and "not empty" in result.output


def test_report_opens_in_chromium_without_errors_and_its_numbers_match(graded, browser):
    right = Counter(r["student"] for r in _graded_rows(graded) if r["correct"] == "1")
    with serve(graded / "report") as url:
        page = browser.new_page()
        problems = PageProblems(page)
        try:
            page.goto(f"{url}/index.html", wait_until="load")
            page.wait_for_function("() => document.querySelectorAll('table.students tbody tr').length === 12")
            shown = page.evaluate("""() => Array.from(document.querySelectorAll('table.students tbody tr'))
                .map(tr => Array.from(tr.cells).slice(0, 4).map(td => td.textContent))""")
            assert {row[0]: int(row[2]) for row in shown} == {f"s{i:02d}": right[f"s{i:02d}"] for i in range(12)}
            assert all(row[3] == "5" for row in shown)
            assert shown[3][1] == HOSTILE_NAME  # shown as the text it is
            assert page.locator("svg").count() == 2 and page.locator("script").count() == 0
            summary = page.locator("#summary").inner_text()
            assert summary.startswith("12 students, 5 questions")
            assert problems.items == [], "\n".join(problems.items)
        finally:
            page.close()
