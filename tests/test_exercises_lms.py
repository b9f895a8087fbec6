"""The round trip through Canvas and Moodle: ``pgsym check`` grades the platforms' own quiz reports (the
fixtures in tests/data/lms, whose README cites the documented formats and derives every expected grade),
writes both gradebooks in points and one feedback page per student; hostile reports get named errors."""

from __future__ import annotations

import csv
import io
from pathlib import Path

import pytest
from _installed import run_pgsym
from click.testing import CliRunner
from hypothesis import given
from hypothesis import strategies as st
from lxml import html as lxml_html

from pgsym.cli import main
from pgsym.exercises.lms import MAX_COLUMNS, split_parts

DATA = Path(__file__).parent / "data" / "lms"


run = run_pgsym


@pytest.fixture(scope="module")
def week(tmp_path_factory):
    """The manifest of the quiz both reports answer (the command of tests/data/lms/README.md)."""
    base = tmp_path_factory.mktemp("week")
    result = run("sheet", "--topics", "join,classify:2", "--roster", str(DATA / "roster.csv"), "--seed", "2026",
                 "--format", "qti,stack", "--out", str(base / "week"))
    assert result.returncode == 0, result.stderr
    return base


def _rows(path: Path) -> list[list[str]]:
    return list(csv.reader(io.StringIO(path.read_text(encoding="utf-8"))))


def test_canvas_student_analysis_round_trip(week):
    out = week / "canvas-run"
    result = run("check", "--manifest", str(week / "week" / "manifest.json"), "--answers",
                 str(DATA / "canvas-student-analysis.csv"), "--out", str(out / "graded.csv"), "--canvas",
                 str(out / "gradebook.csv"), "--canvas-title", "Week 4", "--canvas-id", "77", "--feedback",
                 str(out / "feedback"), "--report", str(out / "report"))
    assert result.returncode == 3, result.stderr  # Dorothy's formula cannot be read; everything else graded
    # the README's derivations: Grace 3, Katherine 2, Dorothy 0, Mary 2 of 3 points
    assert result.stdout.splitlines() == ["student,right,questions,score,points", "g001,3,3,3,3", "g002,2,3,2,3",
                                          "g003,0,3,0,3", "g004,2,3,2,3"]
    graded = {(r[0], r[1]): r for r in _rows(out / "graded.csv")[1:]}
    assert graded[("g002", "1")][2] == "(\u22124, \u22122, 0)" and graded[("g002", "1")][3] == "1"  # U+2212 minus
    assert graded[("g001", "1")][3] == "1"  # (0.5, -1, -6.5): a multiple with decimals, read exactly
    assert graded[("g003", "1")][5] == "dual"  # the given point of the variant Dorothy drew
    assert graded[("g003", "2a")][2].startswith("'=HYPERLINK")  # neutralised for spreadsheets
    # the Canvas gradebook: the Canvas user id and the SIS User ID from the report, the points
    assert _rows(out / "gradebook.csv") == [
        ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Week 4 (77)"],
        ["Points Possible", "", "", "", "", "3"],
        ["Grace Hopper", "9001", "g001", "", "", "3"], ["Katherine Johnson", "9002", "g002", "", "", "2"],
        ["Dorothy Vaughan", "9003", "g003", "", "", "0"], ["Mary Jackson", "9004", "g004", "", "", "2"]]
    # the report sums the same points
    import json

    report = json.loads((out / "report" / "report.json").read_text())
    assert [(s["id"], s["score"], s["points"]) for s in report["students"]] == [
        ("g001", "3", "3"), ("g002", "2", "3"), ("g003", "0", "3"), ("g004", "2", "3")]
    pages = sorted(p.name for p in (out / "feedback").iterdir())
    assert pages == ["feedback-g001.html", "feedback-g002.html", "feedback-g003.html", "feedback-g004.html",
                     "index.html"]
    dorothy = (out / "feedback" / "feedback-g003.html").read_text()
    assert "Mistake: a given point, not the line through both points" in dorothy
    assert "<script" not in dorothy
    tree = lxml_html.fromstring(dorothy)
    assert tree.get_element_by_id("score").text_content() == "Score: 0 of 3 points."
    assert 'HYPERLINK("http://example.com","A")' in tree.text_content()  # shown as typed, as text
    assert tree.xpath("//a") == []  # never a link
    assert tree.xpath("//details/summary")[0].text == "Worked solution" and "<math" in dorothy


def test_moodle_responses_round_trip(week):
    out = week / "moodle-run"
    result = run("check", "--manifest", str(week / "week" / "manifest.json"), "--answers",
                 str(DATA / "moodle-responses.csv"), "--out", str(out / "graded.csv"), "--moodle-grades",
                 str(out / "moodle-grades.csv"), "--canvas-title", "Week 4", "--feedback", str(out / "feedback"))
    assert result.returncode == 3, result.stderr  # Mary's attempt is in progress: reported, not graded
    assert "an attempt in state 'In progress' was not graded" in result.stderr
    assert result.stdout.splitlines() == ["student,right,questions,score,points", "grace@example.edu,3,3,3,3",
                                          "katherine@example.edu,2,3,2,3", "dorothy@example.edu,1,3,1,3"]
    graded = {(r[0], r[1]): r for r in _rows(out / "graded.csv")[1:]}
    # pgsym's verdicts are those of the STACK answer notes in the report (prt1-mistake-dual, prt1-wrong, ...)
    assert graded[("dorothy@example.edu", "1")][5] == "dual"
    assert graded[("katherine@example.edu", "2a")][3] == "0" and graded[("katherine@example.edu", "2b")][3] == "1"
    assert _rows(out / "moodle-grades.csv") == [
        ["Email address", "ID number", "Username", "Full name", "Week 4", "Feedback"],
        ["grace@example.edu", "", "", "Grace Hopper", "3", "3 of 3 points"],
        ["katherine@example.edu", "", "", "Katherine Johnson", "2", "2 of 3 points; not right: 2a"],
        ["dorothy@example.edu", "", "", "Dorothy Vaughan", "1", "1 of 3 points; not right: 1 (dual), 2b"]]
    assert len(list((out / "feedback").iterdir())) == 4  # three pages and the index


def test_points_from_the_manifest_reach_both_gradebooks(tmp_path):
    result = run("sheet", "--topics", "join,classify:2", "--roster", str(DATA / "roster.csv"), "--seed", "2026",
                 "--format", "stack", "--points", "join=2,classify=1/2+3", "--out", str(tmp_path / "w"))
    assert result.returncode == 0, result.stderr
    result = run("check", "--manifest", str(tmp_path / "w" / "manifest.json"), "--answers",
                 str(DATA / "moodle-responses.csv"), "--moodle-grades", str(tmp_path / "m.csv"))
    # Grace: 2 + 1/2 + 3 = 5.5; Katherine: 2 + 0 + 3 = 5; Dorothy: 0 + 1/2 + 0 = 0.5, of 5.5 each
    assert result.stdout.splitlines()[1:] == ["grace@example.edu,3,3,5.5,5.5", "katherine@example.edu,2,3,5,5.5",
                                              "dorothy@example.edu,1,3,0.5,5.5"]
    assert [r[4] for r in _rows(tmp_path / "m.csv")[1:]] == ["5.5", "5", "0.5"]


def check_here(*args: str):  # type: ignore[no-untyped-def]
    return CliRunner().invoke(main, ["check", *args], catch_exceptions=False)


def test_a_report_matching_no_question_is_an_error_not_zeros(week, tmp_path):
    manifest = str(week / "week" / "manifest.json")
    # a Canvas report of another quiz: its questions carry no pgsym variant id
    (tmp_path / "other.csv").write_text("name,id,sis_id,section,section_id,section_sis_id,submitted,attempt,"
                                        "\"55: What is 2+2?\",1.0,n correct,n incorrect,score\n"
                                        "Ada,1,a1,S,1,,2026-01-01,1,4,1.0,1,0,1.0\n")
    result = check_here("--manifest", manifest, "--answers", str(tmp_path / "other.csv"))
    assert result.exit_code == 1
    assert "LmsReportError: no question of the Canvas report 'other.csv' carries a variant id" in result.output
    assert "55: What is 2+2?" in result.output
    # a Moodle report downloaded without "Question text": nothing says which variant was drawn
    (tmp_path / "noq.csv").write_text("Surname,First name,Email address,State,Response 1\n"
                                      "L,A,a@x.org,Finished,Seed: 1; ans1: [1,2,3] [score]\n")
    result = check_here("--manifest", manifest, "--answers", str(tmp_path / "noq.csv"))
    assert result.exit_code == 1 and "with 'Question text' ticked" in result.output
    # the right platform, the wrong manifest (another seed): its variant ids are unknown here
    assert run("sheet", "--topics", "join,classify:2", "--roster", str(DATA / "roster.csv"), "--seed", "1",
               "--format", "stack", "--out", str(tmp_path / "other-week")).returncode == 0
    result = check_here("--manifest", str(tmp_path / "other-week" / "manifest.json"), "--answers",
                        str(DATA / "moodle-responses.csv"))
    assert result.exit_code == 1 and "carries a variant id of this manifest" in result.output


def test_hostile_reports_are_bounded(week, tmp_path):
    manifest = str(week / "week" / "manifest.json")
    header = ["name", "id", "sis_id", "n correct", "n incorrect", "score"] + [f"{i}: q" for i in range(MAX_COLUMNS)]
    (tmp_path / "wide.csv").write_text(",".join(header) + "\n")
    result = check_here("--manifest", manifest, "--answers", str(tmp_path / "wide.csv"))
    assert result.exit_code == 1 and f"at most {MAX_COLUMNS} are read" in result.output
    # one enormous answer costs only that answer; its neighbours are graded
    text = (DATA / "canvas-student-analysis.csv").read_text()
    (tmp_path / "long.csv").write_text(text.replace("(0.5, -1, -6.5)", "9" * 100_000))
    result = check_here("--manifest", manifest, "--answers", str(tmp_path / "long.csv"))
    assert result.exit_code == 3 and "at most 2000 are read" in result.output
    assert "g001,2,3,2,3" in result.output
    # a hostile name and SIS id: the page stays inside the folder, the name shows as text
    hostile = text.replace("Grace Hopper,9001,g001", '"<script>alert(1)</script>",9001,../../evil')
    (tmp_path / "hostile.csv").write_text(hostile)
    result = check_here("--manifest", manifest, "--answers", str(tmp_path / "hostile.csv"), "--feedback",
                        str(tmp_path / "fb"))
    assert result.exit_code == 3
    names = sorted(p.name for p in (tmp_path / "fb").iterdir())
    assert len(names) == 5 and all("/" not in n and not n.startswith(".") for n in names)
    assert not (tmp_path.parent / "evil").exists() and not list(tmp_path.parent.glob("*evil*"))
    page = next((tmp_path / "fb").glob("feedback-______evil-*.html")).read_text()
    assert "<script>" not in page and "&lt;script&gt;alert(1)&lt;/script&gt;" in page
    # not UTF-8: a named error, no traceback
    (tmp_path / "bin.csv").write_bytes(b"name,id,sis_id\n\xff\xfe\n")
    result = check_here("--manifest", manifest, "--answers", str(tmp_path / "bin.csv"))
    assert result.exit_code == 1 and "is not UTF-8 text" in result.output and "Traceback" not in result.output


def test_check_help_documents_the_round_trip():
    result = run("check", "--help")
    assert result.returncode == 0
    for phrase in ("Student Analysis", "Responses", "--moodle-grades", "--feedback", "SIS User ID"):
        assert phrase in result.stdout, phrase
    result = run("sheet", "--help")
    for phrase in ("stack.xml", "--points", "Canvas does not grade"):
        assert phrase in result.stdout, phrase


labels_strategy = st.lists(st.from_regex(r"[1-9][a-d]", fullmatch=True), min_size=2, max_size=4, unique=True)
answer_text = st.from_regex(r"\(?-?[0-9]{1,3}(, -?[0-9]{1,3}){0,3}\)?|[A-H]", fullmatch=True)


@given(labels_strategy, st.data())
def test_labelled_lines_reach_their_parts_in_any_order(labels, data):
    answers = {label: data.draw(answer_text) for label in labels}
    order = data.draw(st.permutations(labels))
    style = data.draw(st.sampled_from(["{l}: {a}", "[{l}] {a}", "{l} = {a}", "<p>{l}: {a}</p>"]))
    text = "\n".join(style.format(l=label, a=answers[label]) for label in order)
    assert split_parts(text, labels) == answers
    # unlabelled lines fill the parts in order
    assert split_parts("\n".join(answers[label] for label in labels), labels) == answers
