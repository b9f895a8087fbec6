"""The STACK export, run for real: the potential response trees of stack.xml, extracted from the XML and
evaluated by Maxima, give the same verdicts (and name the same mistake) as ``pgsym check`` grading the
same answers from a Moodle Responses report.

Maxima is Debian's ``maxima`` package (``make system-deps``); a missing Maxima is a failure, not a skip.
"""

from __future__ import annotations

import csv
import io
import shutil
import subprocess
from fractions import Fraction

import pytest
from _installed import run_pgsym
from lxml import etree

MAXIMA = shutil.which("maxima")
TOPICS = ("join,meet:2,ideal:2,apply-point,apply-line,apply-conic,homography4,cross-ratio:2,classify:2,decompose,"
          "plane3,point3,plucker,homogeneous:2,perpendicular,angle,conic-type")


run = run_pgsym


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    base = tmp_path_factory.mktemp("stack")
    (base / "roster.csv").write_text("id,name\ns1,Ada\ns2,Alan\ns3,Emmy\n")
    result = run("sheet", "--topics", TOPICS, "--roster", str(base / "roster.csv"), "--seed", "2026",
                 "--format", "stack", "--points", "classify=1+2,decompose=1+2+2,default=1", "--out",
                 str(base / "out"))
    assert result.returncode == 0, result.stderr
    return base


def _questions(xml: bytes) -> list[etree._Element]:
    return etree.fromstring(xml).findall("question[@type='stack']")


def _maxima_value(kind: str, value: object) -> str:
    """How a student types a value in STACK: a list, a number, matrix([...],...), a letter."""
    def num(v: Fraction) -> str:
        return str(v.numerator) if v.denominator == 1 else f"{v.numerator}/{v.denominator}"
    if kind in ("projective", "vector"):
        return "[" + ",".join(num(Fraction(v)) for v in value) + "]"
    if kind in ("matrix", "matrix_exact"):
        return "matrix(" + ",".join("[" + ",".join(num(Fraction(v)) for v in row) + "]" for row in value) + ")"
    if kind in ("scalar", "integer"):
        return num(Fraction(value))
    return str(value)


def _scaled(kind: str, value: object, factor: Fraction) -> object:
    if kind == "projective":
        return [Fraction(v) * factor for v in value]
    if kind == "matrix":
        return [[Fraction(v) * factor for v in row] for row in value]
    return value


def _cases(part: dict) -> list[tuple[str, str]]:
    """(what, Maxima text) answers for one part: right, scaled, every stored mistake, unreadable, wrong."""
    kind, value = part["kind"], part["value"]
    cases = [("right", _maxima_value(kind, value))]
    if kind in ("projective", "matrix"):
        # -3/2 times the key: right up to scale, with fractions (so no string match could accept it)
        cases.append(("scaled", _maxima_value(kind, _scaled(kind, value, Fraction(-3, 2)))))
    for m in part.get("mistakes", []):
        cases.append((f"mistake {m['code']}", _maxima_value(m["kind"], _scaled(m["kind"], m["value"], Fraction(-2)))))
    cases.append(("unreadable", "x"))
    if kind in ("projective", "vector"):
        cases.append(("unreadable", "[1,2]" if len(value) != 2 else "[1,2,3]"))
    if kind in ("scalar", "integer"):
        cases.append(("wrong", _maxima_value(kind, Fraction(value) + 1000)))
    return cases


def _walk(nodes: list[etree._Element], values: list[bool]) -> tuple[str, str]:
    """Follow the tree from node 0 with the booleans Maxima computed; the final (score, answer note)."""
    by_name = {n.findtext("name"): (i, n) for i, n in enumerate(nodes)}
    index, node = by_name["0"]
    while True:
        branch = "true" if values[index] else "false"
        score, note, nxt = (node.findtext(f"{branch}score"), node.findtext(f"{branch}answernote"),
                            node.findtext(f"{branch}nextnode"))
        if nxt == "-1":
            return score, note
        index, node = by_name[nxt]


def _verdict_of_note(note: str) -> tuple[str, str]:
    tail = note.split("-", 1)[1]
    if tail == "right":
        return "right", ""
    if tail.startswith("mistake-"):
        return "wrong", tail.removeprefix("mistake-")
    return ("unreadable", "") if tail == "unreadable" else ("wrong", "")


def test_maxima_agrees_with_pgsym_check(exported):
    assert MAXIMA, "Maxima is missing: run `make system-deps` (apt-get install maxima)"
    import json

    manifest = json.loads((exported / "out" / "manifest.json").read_text())
    xml = (exported / "out" / "stack.xml").read_bytes()
    parts_of = {}
    for student in manifest["students"]:
        for ex in student["exercises"]:
            parts_of[f"{student['form_id']}#{ex['slot']}"] = ex["parts"]
    script = ["display2d:false$"]
    responses = [["Surname", "First name", "Email address", "State", "Question 1", "Response 1"]]
    cases = []  # (case id, node elements, what, label)
    for question in _questions(xml):
        note = question.findtext("questionnote/text")
        vid = note.removeprefix("pgsym ")
        qvars = question.findtext("questionvariables/text")
        for k, prt in enumerate(question.findall("prt"), start=1):
            assert prt.findtext("name") == f"prt{k}"
            part = parts_of[vid][k - 1]
            fvars = prt.findtext("feedbackvariables/text")
            nodes = prt.findall("node")
            variables = [n.findtext("sans") for n in nodes]
            assert all(n.findtext("answertest") == "AlgEquiv" and n.findtext("tans") == "true" for n in nodes)
            for what, answer in _cases(part):
                case = len(cases)
                cases.append((case, nodes, what, part["label"]))
                # the question's variables, the student's input, the PRT's feedback variables: as in the XML
                script += ["kill(all)$", "display2d:false$", qvars, f"ans{k}:{answer}$", fvars,
                           f'print("CASE",{case},[{",".join(variables)}])$']
                responses.append([f"case{case}", "T", f"case{case}@example.org", "Finished", note,
                                  f"Seed: 1; ans{k}: {answer} [score]; prt{k}: # = 0 | x"])
    assert len(cases) > 150
    out = subprocess.run([MAXIMA, "--very-quiet"], input="\n".join(script) + "\nquit()$\n", capture_output=True,
                         text=True, timeout=600)
    assert out.returncode == 0, out.stderr[-2000:]
    values = {}
    for line in out.stdout.splitlines():
        if line.startswith("CASE "):
            _, case, rest = line.split(" ", 2)
            values[int(case)] = [v.strip() == "true" for v in rest.strip("[] ").split(",")]
    assert sorted(values) == list(range(len(cases))), out.stdout[-2000:]

    buf = io.StringIO()
    csv.writer(buf).writerows(responses)
    (exported / "responses.csv").write_text(buf.getvalue())
    result = run("check", "--manifest", str(exported / "out" / "manifest.json"), "--answers",
                 str(exported / "responses.csv"), "--out", str(exported / "graded.csv"))
    assert result.returncode == 3, result.stderr[-2000:]  # 3: the unreadable answers were reported, all graded
    graded = {(r["student"], r["question"]): r for r in csv.DictReader(io.StringIO((exported / "graded.csv")
                                                                                    .read_text()))}
    kinds = set()
    for case, nodes, what, label in cases:
        score, note = _walk(nodes, values[case])
        maxima = _verdict_of_note(note)
        row = graded[(f"case{case}@example.org", label)]
        pgsym = ("right", "") if row["correct"] == "1" else (
            ("unreadable", "") if row["reason"].startswith("cannot read") else ("wrong", row["mistake"]))
        assert maxima == pgsym, (what, label, note, row)
        assert (score == "1") == (maxima[0] == "right")
        # independent expectations: the key and its multiples are right, the unreadable ones are unreadable
        if what in ("right", "scaled"):
            assert maxima == ("right", ""), (what, note)
        elif what == "unreadable":
            assert maxima == ("unreadable", "")
        elif what.startswith("mistake"):
            assert maxima[0] == "wrong" and maxima[1], (what, note)  # a stored mistake is always named
        kinds.add(what.split()[0])
    assert kinds == {"right", "scaled", "mistake", "unreadable", "wrong"}


def test_the_tree_starts_up_to_scale_and_names_the_mistakes(exported):
    questions = _questions((exported / "out" / "stack.xml").read_bytes())
    line = next(q for q in questions if "A homography applied to a line" in q.findtext("name/text"))
    prt = line.find("prt")
    fvars = prt.findtext("feedbackvariables/text")
    assert "right1:if wf1 then (is(rank(matrix(sa1))=1) and is(rank(matrix(sa1,[" in fvars
    notes = [n.findtext("trueanswernote") for n in prt.findall("node")]
    assert notes[0] == "prt1-right" and "prt1-mistake-line-as-point" in notes
    feedback = [n.findtext("truefeedback/text") for n in prt.findall("node")]
    assert any("lines map by H⁻ᵀ" in (f or "") for f in feedback)
    # the worked solution is the general feedback, the variant id the question note
    assert "<ol><li>" in line.findtext("generalfeedback/text")
    assert line.findtext("questionnote/text").startswith("pgsym F-")


def test_points_are_the_prt_values(exported):
    import json

    manifest = json.loads((exported / "out" / "manifest.json").read_text())
    first = manifest["students"][0]
    worth = {ex["topic"]: [Fraction(p["points"]) for p in ex["parts"]] for ex in first["exercises"]}
    assert worth["classify"] == [1, 2] and worth["decompose"] == [1, 2, 2] and worth["join"] == [1]
    questions = _questions((exported / "out" / "stack.xml").read_bytes())
    decompose = next(q for q in questions if first["form_id"] in q.findtext("name/text")
                     and "Decompose" in q.findtext("name/text"))
    assert [Fraction(p.findtext("value")) for p in decompose.findall("prt")] == [1, 2, 2]
    assert Fraction(decompose.findtext("defaultgrade")) == 5  # 1 + 2 + 2


def test_the_question_tests_in_the_xml_pass_in_maxima(exported):
    """STACK's own question tests, as exported (key, multiple, each mistake), give their expected notes."""
    questions = _questions((exported / "out" / "stack.xml").read_bytes())
    script, jobs = [], []
    for question in questions:
        qvars = question.findtext("questionvariables/text")
        prts = question.findall("prt")
        for test in question.findall("qtest"):
            inputs = {t.findtext("name"): t.findtext("value") for t in test.findall("testinput")}
            expected = {e.findtext("name"): (e.findtext("expectedscore"), e.findtext("expectedanswernote"))
                        for e in test.findall("expected")}
            assert set(expected) == {p.findtext("name") for p in prts}
            for prt in prts:
                nodes = prt.findall("node")
                job = len(jobs)
                jobs.append((nodes, expected[prt.findtext("name")], test.findtext("description")))
                script += ["kill(all)$", "display2d:false$", qvars, *[f"{k}:{v}$" for k, v in inputs.items()],
                           prt.findtext("feedbackvariables/text"),
                           f'print("CASE",{job},[{",".join(n.findtext("sans") for n in nodes)}])$']
    assert len(jobs) > 200
    out = subprocess.run([MAXIMA, "--very-quiet"], input="\n".join(script) + "\nquit()$\n", capture_output=True,
                         text=True, timeout=600)
    values = {}
    for line in out.stdout.splitlines():
        if line.startswith("CASE "):
            _, case, rest = line.split(" ", 2)
            values[int(case)] = [v.strip() == "true" for v in rest.strip("[] ").split(",")]
    assert sorted(values) == list(range(len(jobs))), out.stdout[-2000:]
    described = set()
    for job, (nodes, (score, note), description) in enumerate(jobs):
        assert _walk(nodes, values[job]) == (score, note), (description, note)
        described.add(description.split(":")[0])
    assert {"the key", "a multiple of the key (right up to scale)"} <= described
