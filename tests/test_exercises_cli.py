"""The instructor commands of the installed ``pgsym`` command: sheet, check, templates."""

from __future__ import annotations

import csv
import io
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from _installed import run_pgsym
from click.testing import CliRunner

from pgsym.cli import main


def run(*args: str, cwd: Path | None = None, env: dict | None = None) -> subprocess.CompletedProcess[str]:
    return run_pgsym(*args, cwd=cwd, env=env, timeout=120)


def run_here(*args: str):  # type: ignore[no-untyped-def]
    """The same command in this process (for the many error cases; the flows above use the installed script)."""
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    """A roster of three students, their sheets (md, ipynb, moodle, with solutions) and the manifest."""
    base = tmp_path_factory.mktemp("class")
    (base / "students.csv").write_text("id,name\ns1,Ada\ns2,Alan\ns3,Emmy\n")
    result = run("sheet", "--topics", "join,ideal:2,cross-ratio,classify", "--roster", str(base / "students.csv"),
                 "--seed", "11", "--format", "md,ipynb,moodle", "--solutions", "--out", str(base / "out"))
    assert result.returncode == 0, result.stderr
    return base


def test_sheet_writes_every_format_and_the_manifest(made):
    out = made / "out"
    assert sorted(p.name for p in (out / "md").iterdir()) == ["sheet-s1.md", "sheet-s2.md", "sheet-s3.md"]
    assert (out / "moodle.xml").is_file() and (out / "ipynb" / "sheet-s2.ipynb").is_file()
    manifest = json.loads((out / "manifest.json").read_text())
    assert [s["id"] for s in manifest["students"]] == ["s1", "s2", "s3"]
    assert manifest["students"][0]["form_id"] in (out / "md" / "sheet-s1.md").read_text()
    labels = [p["label"] for e in manifest["students"][0]["exercises"] for p in e["parts"]]
    assert labels == ["1", "2", "3", "4a", "4b"]
    # different students, different variants
    params = [json.dumps([e["params"] for e in s["exercises"]]) for s in manifest["students"]]
    assert len(set(params)) == 3


def test_check_grades_right_scaled_wrong_and_hostile(made):
    manifest = json.loads((made / "out" / "manifest.json").read_text())
    s1 = {p["label"]: p for e in manifest["students"][0]["exercises"] for p in e["parts"]}
    line = s1["1"]["value"]
    scaled = "(" + ", ".join(str(-2 * int(v)) for v in line) + ")"
    ideal = "(" + ", ".join(str(3 * int(v)) for v in s1["2"]["value"]) + ")"
    rows = ["id,1,2,3,4a,4b",
            f's1,"{scaled}","{ideal}",{s1["3"]["value"]},{s1["4a"]["value"]},{s1["4b"]["value"]}',
            "s2,\"__import__('os').system('touch HACKED')\",\"(0, 0, 0)\",1/0,"
            "Z,999999999999999999999999999999999999999999",
            "s3,,,,,"]
    (made / "answers.csv").write_text("\n".join(rows) + "\n")
    result = run("check", "--manifest", str(made / "out" / "manifest.json"), "--answers", str(made / "answers.csv"),
                 "--out", str(made / "grades.csv"), cwd=made)
    assert result.returncode == 3, result.stderr  # some answers could not be read; all others graded
    # right answers, questions, then points earned of points possible (1 per part by default)
    assert result.stdout.splitlines() == ["student,right,questions,score,points", "s1,5,5,5,5", "s2,0,5,0,5",
                                          "s3,0,5,0,5"]
    assert "cannot read the answer: unexpected character '_'" in result.stderr
    assert "division by zero" in result.stderr and "more than 40 digits" in result.stderr
    assert not (made / "HACKED").exists()
    assert (made / "grades.csv").read_text().startswith("student,question,answer,correct,reason,mistake,feedback")


def test_check_names_the_mistake_per_student(made, tmp_path):
    manifest = json.loads((made / "out" / "manifest.json").read_text())
    s2 = {p["label"]: p for e in manifest["students"][1]["exercises"] for p in e["parts"]}
    direction = [int(v) for v in s2["2"]["value"]]  # question 2 (ideal:2) asks for an ideal point (a, b, 0)
    assert direction[2] == 0
    finite = f"({direction[0]}, {direction[1]}, 1)"  # the direction read as a finite point
    (tmp_path / "a.csv").write_text(f'id,question,answer\ns2,2,"{finite}"\ns2,4b,9\n')
    result = run("check", "--manifest", str(made / "out" / "manifest.json"), "--answers", str(tmp_path / "a.csv"),
                 "--out", str(tmp_path / "g.csv"), "--canvas", str(tmp_path / "canvas.csv"), "--details")
    assert result.returncode == 0, result.stderr
    graded = {(r["student"], r["question"]): r for r in csv.DictReader(io.StringIO((tmp_path / "g.csv").read_text()))}
    assert graded[("s2", "2")]["mistake"] == "ideal-as-finite"
    assert "ideal point given as a finite one" in graded[("s2", "2")]["feedback"]
    assert "s2 [2]: wrong (an ideal point given as a finite one" in result.stderr
    assert graded[("s2", "4b")]["correct"] == "0" and graded[("s2", "4b")]["mistake"] == ""  # wrong, no known mistake
    assert (tmp_path / "canvas.csv").read_text().splitlines()[:2] == [
        "Student,ID,SIS User ID,SIS Login ID,Section,pgsym exercises", "Points Possible,,,,,5"]


def test_same_seed_same_bytes_other_seed_differs(tmp_path):
    args = ["sheet", "--topics", "meet,plucker:3", "--count", "2", "--seed", "5", "--format", "md,tex,moodle,ipynb"]
    assert run(*args, "--out", str(tmp_path / "a")).returncode == 0
    assert run(*args, "--out", str(tmp_path / "b")).returncode == 0
    files = sorted(p.relative_to(tmp_path / "a") for p in (tmp_path / "a").rglob("*") if p.is_file())
    # manifest, 2 md, 2 ipynb, sheets.tex, moodle.xml; the key: 2 md, 2 ipynb, key.tex; the key table: md, ipynb, tex
    assert len(files) == 15
    for f in files:
        assert (tmp_path / "a" / f).read_bytes() == (tmp_path / "b" / f).read_bytes()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--topics", "join,warp"], "unknown topic 'warp'"),
        (["--topics", "join:9"], "levels [1, 2, 3], not 9"),
        (["--topics", "join", "--format", "md,docx"], "unknown format(s) docx"),
        (["--topics", "join", "--roster", "ROSTER_NO_ID"], "needs a header row with an 'id' column"),
        (["--topics", "join", "--roster", "ROSTER_DUP"], "appears twice"),
        (["--topics", "join", "--roster", "MISSING.csv"], "the roster 'MISSING.csv' does not exist"),
    ],
)
def test_sheet_errors_are_clear_and_leave_nothing(tmp_path, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "ROSTER_NO_ID").write_text("name\nAda\n")
    (tmp_path / "ROSTER_DUP").write_text("id\ns1\ns1\n")
    result = run_here("sheet", *args, "--out", "new")
    assert result.exit_code != 0
    assert message in result.output
    assert not (tmp_path / "new").exists()


def test_an_error_exits_nonzero_from_the_installed_command(tmp_path):
    result = run("sheet", "--topics", "join,warp", "--out", "new", cwd=tmp_path)
    assert result.returncode == 1 and "UnknownTopicError: unknown topic 'warp'" in result.stderr
    assert not (tmp_path / "new").exists()


def test_unwritable_or_nonempty_output_folder(tmp_path):
    (tmp_path / "blocker").write_text("")
    result = run_here("sheet", "--topics", "join", "--out", str(tmp_path / "blocker" / "out"))
    assert result.exit_code == 1 and "OutputError: cannot write" in result.output
    (tmp_path / "used").mkdir()
    (tmp_path / "used" / "keep.txt").write_text("x")
    result = run_here("sheet", "--topics", "join", "--out", str(tmp_path / "used"))
    assert result.exit_code == 1 and "not empty" in result.output
    assert (tmp_path / "used" / "keep.txt").read_text() == "x"


def test_pdf_without_tex_fails_cleanly(tmp_path):
    env = {**os.environ, "PATH": str(Path(sys.executable).parent)}  # no TeX on this PATH
    result = run("sheet", "--topics", "join", "--format", "md,pdf", "--out", str(tmp_path / "o"), env=env)
    assert result.returncode == 1
    assert "LuaLaTeX is not installed" in result.stderr and "apt-get install" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_check_errors(tmp_path, made):
    (tmp_path / "m.json").write_text("{}")
    (tmp_path / "a.csv").write_text("name\nx\n")
    result = run_here("check", "--manifest", str(tmp_path / "m.json"), "--answers", str(tmp_path / "a.csv"))
    assert result.exit_code == 1 and "not a pgsym exercise manifest" in result.output
    result = run_here("check", "--manifest", str(tmp_path / "none.json"), "--answers", str(tmp_path / "a.csv"))
    assert result.exit_code == 1 and "does not exist" in result.output
    result = run_here("check", "--manifest", str(made / "out" / "manifest.json"), "--answers", str(tmp_path / "a.csv"))
    assert result.exit_code == 1 and "needs a header with an 'id' column" in result.output


def test_templates_new_then_check_then_use(tmp_path):
    result = run("templates", "new", "midpoint", "--dir", "mine", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "mine" / "midpoint.py").is_file()
    result = run_here("templates", "check", "midpoint", "--templates", str(tmp_path / "mine"), "--seeds", "200")
    assert result.exit_code == 0, result.output
    assert "midpoint: 200 instances" in result.output and "OK" in result.output
    result = run("sheet", "--templates", "mine", "--topics", "midpoint:2,join", "--count", "2", "--out", "o",
                 cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "The midpoint of two points" in (tmp_path / "o" / "md" / "sheet-form-001.md").read_text()
    assert run_here("templates", "new", "midpoint", "--dir", str(tmp_path / "mine")).exit_code == 1
    assert run_here("templates", "new", "Bad-Name", "--dir", str(tmp_path / "mine")).exit_code == 2


def test_templates_check_reports_a_broken_template(tmp_path):
    (tmp_path / "t").mkdir()
    (tmp_path / "t" / "broken.py").write_text(
        "from pgsym.exercises.model import Answer\n"
        "from pgsym.exercises.template import Draft, Template, check\n\n\n"
        "class Broken(Template):\n"
        "    name = 'broken'\n"
        "    levels = (1,)\n\n"
        "    def build(self, rng, level):\n"
        "        return Draft('x', [('y', Answer.scalar(rng.randint(0, 1)), ())], [])\n\n"
        "    def verify(self, ex):\n"
        "        check(ex.parts[0].answer.value == 1, 'the answer should be 1')\n")
    result = run_here("templates", "check", "broken", "--templates", str(tmp_path / "t"), "--seeds", "50")
    assert result.exit_code == 1
    assert "FAIL" in result.output and "the answer should be 1" in result.output


def test_templates_list_and_help():
    result = run_here("templates", "list")
    assert result.exit_code == 0 and "homography4" in result.output and "decompose" in result.output
    result = run("sheet", "--help")
    assert result.returncode == 0 and "Examples:" in result.stdout and "--roster" in result.stdout
    assert "Examples:" in run_here("check", "--help").output
    assert "sheet" in run_here("--help").output


def test_check_outputs_that_cannot_be_written_are_named_errors(made, tmp_path):
    (tmp_path / "blocker").write_text("")
    (tmp_path / "a.csv").write_text("id,1\ns1,1\n")
    base = ["check", "--manifest", str(made / "out" / "manifest.json"), "--answers", str(tmp_path / "a.csv")]
    for option in ("--out", "--canvas", "--report"):
        result = run_here(*base, option, str(tmp_path / "blocker" / "x"))
        assert result.exit_code == 1 and "OutputError: cannot write" in result.output, (option, result.output)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.csv", "blocker"]  # nothing half-written
