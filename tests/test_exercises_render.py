"""Every renderer from one internal representation; byte-identical output for the same seed; the PDF."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path
from xml.etree import ElementTree

import pytest

from pgsym.atomic import write_new_folder
from pgsym.errors import OutputError
from pgsym.exercises import render_html, render_ipynb, render_md, render_moodle, render_tex
from pgsym.exercises.output import render_all
from pgsym.exercises.render_tex import TeXMissingError, compile_pdf
from pgsym.exercises.sheets import build_sheets

TOPICS = ["join", "meet:2", "incidence:2", "classify:3", "cross-ratio:3", "decompose:3"]
STUDENTS = [("s001", "Ada Lovelace"), ("s002", "Alan_Turing & Co")]


@pytest.fixture(scope="module")
def sheets():
    return build_sheets(TOPICS, STUDENTS, master_seed=2026)


def test_markdown_page(sheets):
    page = render_md.render_sheet(sheets[0], solutions=False)
    assert page.startswith("# Exercise sheet: Ada Lovelace (s001)")
    assert sheets[0].form_id in page
    for ex in sheets[0].exercises:
        assert ex.statement in page and f"## Exercise {ex.slot}: {ex.title}" in page
    assert "Solution" not in page and "Answer [" not in page
    with_solutions = render_md.render_sheet(sheets[0], solutions=True)
    assert with_solutions.count("```{admonition} Solution") == len(TOPICS)
    assert ":class: dropdown" in with_solutions


def test_latex_document(sheets):
    tex = render_tex.render_document(sheets, solutions=True)
    assert tex.count(r"\sheettitle{Exercise sheet:") == 2 and r"\solutionstrue" in tex
    assert r"Alan\_Turing \& Co" in tex  # prose is escaped
    assert r"\begin{bmatrix}" in tex  # math is kept
    assert r"\solutionsfalse" in render_tex.render_document(sheets, solutions=False)
    assert r"\textbf{Solution.}" not in render_tex.render_document(sheets, solutions=False)


def test_html_page_carries_mathml_and_no_script(sheets):
    page = render_html.render_sheet(sheets[1], solutions=True)
    assert "<script" not in page and "src=" not in page and "href=" not in page
    # the only address is the MathML namespace, which no browser fetches
    assert set(re.findall(r"https?://[^\"]*", page)) == {"http://www.w3.org/1998/Math/MathML"}
    assert page.count("<math ") >= len(TOPICS) and "<mtable>" in page  # matrices too
    assert "Alan_Turing &amp; Co" in page and "<details>" in page
    assert page.count("<h2>") == len(TOPICS)


def test_notebook_is_valid_and_checks_answers(sheets, capsys):
    nb = json.loads(render_ipynb.render_sheet(sheets[0], solutions=False))
    # the fields nbformat 4.5 requires (full schema validation is slow to import, so checked by hand)
    assert (nb["nbformat"], nb["nbformat_minor"]) == (4, 5) and nb["metadata"]["kernelspec"]["name"] == "python3"
    assert all({"cell_type", "id", "metadata", "source"} <= set(c) for c in nb["cells"])
    assert all(c["outputs"] == [] for c in nb["cells"] if c["cell_type"] == "code")
    setup = "".join(nb["cells"][1]["source"])
    namespace: dict = {}
    exec(setup, namespace)  # our own generated code (the student's self-check helper), not user input
    first = sheets[0].exercises[0].parts[0]
    namespace["check"](first.label, first.answer.display())
    namespace["check"](first.label, "(1, 2, 3)" if first.answer.display() != "(1, 2, 3)" else "(1, 2, 4)")
    out = capsys.readouterr().out.splitlines()
    assert out == [f"{first.label} right", f"{first.label} not right yet"]
    assert first.answer.display() not in setup  # the key itself is not in the notebook


def test_moodle_xml(sheets):
    xml = render_moodle.render_quiz(sheets, solutions=True)
    root = ElementTree.fromstring(xml.encode())
    categories = root.findall("question[@type='category']")
    questions = root.findall("question[@type='cloze']")
    assert len(categories) == len(TOPICS) and len(questions) == len(TOPICS) * len(STUDENTS)
    text = questions[0].find("questiontext/text").text
    assert "{1:NUMERICAL:=" in text and r"\(" in text
    choice = root.findall("question[@type='cloze']")[2 * len(STUDENTS)].find("questiontext/text").text
    assert "{1:MULTICHOICE:" in choice


def test_cloze_says_what_it_cannot_do_and_always_has_the_solution():
    from pgsym.exercises.points import parse_points

    sheets = build_sheets(["join", "classify"], [("s1", "")], 4, points=parse_points("join=3,classify=1+2"))
    root = ElementTree.fromstring(render_moodle.render_quiz(sheets, solutions=False).encode())
    join, classify = root.findall("question[@type='cloze']")
    text = join.find("questiontext/text").text
    # never a claim that multiples are accepted: the text says the opposite
    assert "Another multiple of a right answer is marked wrong here" in text and "any nonzero multiple" not in text
    # 3 points over the 3 coordinate boxes of the line: weight 1 each; the mark of the question is 3
    assert re.findall(r"\{(\d+):NUMERICAL", text) == ["1", "1", "1"] and join.findtext("defaultgrade") == "3"
    # classify: the letter worth 1, the degrees of freedom worth 2 (weights 1 and 2), 3 in all
    assert re.findall(r"\{(\d+):[A-Z]+", classify.find("questiontext/text").text) == ["1", "2"]
    assert classify.findtext("defaultgrade") == "3"
    # the worked solution is the general feedback even when the sheets carry no solutions
    assert join.find("generalfeedback/text").text.startswith("<ol><li>")


def _render(tmp: Path, formats, sheets, **kw) -> dict[str, bytes]:
    render_all(sheets, [(t.split(":")[0], int(t.split(":")[1]) if ":" in t else 1) for t in TOPICS], formats, tmp, **kw)
    return {str(p.relative_to(tmp)): p.read_bytes() for p in sorted(tmp.rglob("*")) if p.is_file()
            and "mathjax" not in p.parts}


def test_same_seed_gives_byte_identical_outputs(tmp_path):
    formats = ["md", "tex", "html", "ipynb", "moodle"]
    a = _render(tmp_path / "a", formats, build_sheets(TOPICS, STUDENTS, 2026), solutions=True)
    b = _render(tmp_path / "b", formats, build_sheets(TOPICS, STUDENTS, 2026), solutions=True)
    assert a == b and len(a) >= 8
    c = _render(tmp_path / "c", formats, build_sheets(TOPICS, STUDENTS, 2027), solutions=True)
    assert a["manifest.json"] != c["manifest.json"]


def require(tool: str) -> None:
    """The PDF tests need TeX and pdftotext, which `make test` installs: a missing tool is a failure."""
    assert shutil.which(tool), f"{tool} is missing: run `make system-deps` (apt-get install {tool})"


def test_pdf_contains_the_questions(tmp_path, sheets):
    require("lualatex")
    require("pdftotext")
    pdf = compile_pdf(render_tex.render_document(sheets, solutions=False))
    assert pdf.startswith(b"%PDF")
    (tmp_path / "s.pdf").write_bytes(pdf)
    text = subprocess.run(["pdftotext", str(tmp_path / "s.pdf"), "-"], capture_output=True, text=True).stdout
    squeezed = re.sub(r"\s+", "", text)
    for sheet in sheets:
        assert sheet.form_id in squeezed
        for ex in sheet.exercises:
            assert f"Exercise{ex.slot}:" in squeezed
            assert re.sub(r"\s+", "", ex.title) in squeezed
    assert "Givethematrix" not in squeezed  # a prompt of a topic not on the sheet
    assert "Givethecross-ratio" in squeezed


def test_pdf_is_reproducible(sheets):
    require("lualatex")
    tex = render_tex.render_document(sheets[:1])
    assert compile_pdf(tex) == compile_pdf(tex)


def test_missing_tex_gives_a_clear_message(monkeypatch):
    monkeypatch.setattr(render_tex.shutil, "which", lambda name: None)
    with pytest.raises(TeXMissingError, match="apt-get install texlive"):
        compile_pdf("\\documentclass{article}\\begin{document}x\\end{document}")


def test_atomic_output_leaves_nothing_on_error(tmp_path, sheets, monkeypatch):
    def boom(tex, timeout=600):
        raise TeXMissingError("no TeX here")

    monkeypatch.setattr("pgsym.exercises.render_tex.compile_pdf", boom)
    with pytest.raises(TeXMissingError):
        write_new_folder(tmp_path / "out", lambda d: render_all(sheets, [("join", 1)], ["md", "pdf"], d))
    assert list(tmp_path.iterdir()) == []
    (tmp_path / "full").mkdir()
    (tmp_path / "full" / "x").write_text("old")
    with pytest.raises(OutputError, match="not empty"):
        write_new_folder(tmp_path / "full", lambda d: None)
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(OutputError, match="cannot write"):
        write_new_folder(blocker / "out", lambda d: None)


def test_html_output_needs_no_mathjax(tmp_path, sheets):
    render_all(sheets, [("join", 1)], ["html"], tmp_path, mathjax=tmp_path / "ignored")
    assert not (tmp_path / "html" / "mathjax").exists()
    assert sorted(p.name for p in (tmp_path / "html").iterdir()) == ["sheet-s001.html", "sheet-s002.html"]
    with pytest.raises(render_html.MathJaxMissingError):
        render_html.find_mathjax(tmp_path / "nowhere")


def test_one_run_writes_sheets_key_and_key_table(tmp_path, sheets):
    formats = ["md", "tex", "html", "ipynb", "moodle", "qti"]
    render_all(sheets, [(t.split(":")[0], 1) for t in TOPICS], formats, tmp_path)
    names = {str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*") if p.is_file()}
    for fmt in ("md", "html", "ipynb"):
        for s in sheets:
            assert f"{fmt}/{s.file_stem}.{fmt}" in names and f"key/{fmt}/{s.file_stem}.{fmt}" in names
        assert f"key-table.{fmt}" in names
    assert {"sheets.tex", "key.tex", "key-table.tex", "moodle.xml", "qti.zip", "manifest.json"} <= names
    # the sheets hide the solutions, the key shows every student's
    first = sheets[0].exercises[0].parts[0].answer
    for fmt in ("md", "html"):
        sheet = (tmp_path / fmt / f"{sheets[0].file_stem}.{fmt}").read_text()
        key = (tmp_path / "key" / fmt / f"{sheets[0].file_stem}.{fmt}").read_text()
        assert "Solution" not in sheet and key.count("Solution") >= len(TOPICS)
    assert r"\solutionsfalse" in (tmp_path / "sheets.tex").read_text()
    assert r"\solutionstrue" in (tmp_path / "key.tex").read_text()
    # the key table: one row per student with the canonical answer of every question
    table = (tmp_path / "key-table.md").read_text().splitlines()
    assert table[2].startswith("| Name | Id | 1 | 2 | 3 |")
    row = next(line for line in table if "| s001 |" in line)
    assert f"`{first.display()}`" in row
    assert all(f"`{p.answer.display()}`" in row for ex in sheets[0].exercises for p in ex.parts)
    nb = json.loads((tmp_path / "key-table.ipynb").read_text())
    assert "".join(nb["cells"][0]["source"]) == (tmp_path / "key-table.md").read_text()
    html_table = (tmp_path / "key-table.html").read_text()
    assert html_table.count("<tr>") == 1 + len(sheets) and "Alan_Turing &amp; Co" in html_table


def test_practice_sheets_and_no_key(tmp_path, sheets):
    render_all(sheets, [("join", 1)], ["md"], tmp_path, solutions=True, key=False)
    assert sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*") if p.is_file()) == [
        "manifest.json", "md/sheet-s001.md", "md/sheet-s002.md"]
    assert "Solution" in (tmp_path / "md" / "sheet-s001.md").read_text()


def test_unicode_ids_get_distinct_file_names(tmp_path):
    sheets = build_sheets(["join"], [("é1", "Émilie"), ("ü1", "Jürgen"), ("../etc", "x")], 1)
    stems = {s.file_stem for s in sheets}
    assert len(stems) == 3 and all("/" not in s and "." not in s for s in stems)
    render_all(sheets, [("join", 1)], ["md"], tmp_path)
    assert len(list((tmp_path / "md").iterdir())) == 3


def test_stop_running_kills_tex_started_from_another_thread():
    # the PDFs of one run compile in worker threads; an error or Ctrl-C in the main thread stops them
    import threading
    import time

    require("lualatex")
    looping = "\\documentclass{article}\\begin{document}\\def\\x{\\x}\\x\\end{document}"
    errors: list[Exception] = []

    def compile_forever() -> None:
        try:
            compile_pdf(looping, timeout=600)
        except render_tex.TeXFailedError as err:
            errors.append(err)

    worker = threading.Thread(target=compile_forever)
    worker.start()
    deadline = time.monotonic() + 30
    while not render_tex._RUNNING and time.monotonic() < deadline:
        time.sleep(0.05)  # until TeX has started
    assert render_tex._RUNNING
    started = time.monotonic()
    render_tex.stop_running()
    try:
        worker.join(timeout=30)
        assert not worker.is_alive() and time.monotonic() - started < 30
        assert errors and "failed" in str(errors[0]) and not render_tex._RUNNING
        with pytest.raises(render_tex.TeXFailedError, match="stopped before TeX started"):
            compile_pdf(looping, timeout=600)
    finally:
        render_tex.allow_running()
