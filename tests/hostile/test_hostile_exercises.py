"""Hostile input to the exercise tools: injection payloads × every output format, TeX confinement,
CSV formula injection, readers of pipes, devices and deep nesting, and grading that survives bad rows.

Each payload is put everywhere user text reaches a sheet: the student's name and id, an instructor
template's title, statement, prompt, choices and solution. Each renderer's output is then read back
the way its reader would (MyST's own Markdown parser, Python's HTML and XML parsers, pdftotext) and
must show the payload as literal text and nothing else: no math, role, directive, tag, Cloze field,
file content or command.
"""

from __future__ import annotations

import csv
import html
import io
import json
import os
import re
import shutil
import subprocess
import sys
import time
import unicodedata
from fractions import Fraction
from html.parser import HTMLParser
from pathlib import Path
from xml.etree import ElementTree

import pytest
from _installed import run_pgsym
from click.testing import CliRunner

from pgsym.cli import main
from pgsym.csv_cells import csv_text, safe_cell
from pgsym.errors import InputLimitError
from pgsym.escaping import REPLACEMENT, math_is_safe, one_line
from pgsym.exercises import html_math, render_html, render_ipynb, render_md, render_moodle, render_stack, render_tex
from pgsym.exercises.errors import AnswersFileError, ManifestError, RosterError, TeXFailedError
from pgsym.exercises.grading import read_answers
from pgsym.exercises.model import Answer, Exercise, Part, Sheet
from pgsym.exercises.sheets import build_sheets, load_manifest, read_roster
from pgsym.exercises.template import load_template_folder
from pgsym.limits import MAX_ANSWER_CHARS, MAX_NESTING

SECRET = "PGSYMSECRETTOKEN"  # the content of an instructor's file that must never reach a sheet


@pytest.fixture(scope="module")
def secret_file(tmp_path_factory) -> Path:
    # a long path: a word wider than the line must still print whole (nothing may run off the page)
    path = tmp_path_factory.mktemp("private-" + "long-folder-name-" * 4) / "secret.tex"
    path.write_text(SECRET + "\n")
    return path


def payloads(secret: Path) -> dict[str, str]:
    """Every payload by a short name; the secret file's absolute path is filled in."""
    return {
        "input-math": f"$\\input{{{secret}}}$",
        "input-text": f"\\input{{{secret}}} and \\include{{{secret}}}",
        "openin": f"$\\openin5={secret} \\read5 to\\x \\x$",
        "write18": "\\immediate\\write18{touch HACKED}$\\write18{touch HACKED}$",
        "def-loop": "$\\def\\x{\\x}\\x$ \\def\\y{\\y}\\y",
        "catcode": "$\\catcode`\\^^5c=12 \\catcode92=11$ \\catcode`|=0",
        "caret-notation": f"^^5cinput^^7b{secret}^^7d $^^5cinput{{x}}$",
        "unbalanced": "{{{ $}x$ }}} $\\frac{1}{$ {",
        "tex-specials": "100% #1 ~tilde_x & a--b <<c>> ,,d",
        "long-name": "Ada " * 2500,
        "control-chars": "A\x00B\x1b[31mC\x07D\x7fE",
        "rtl-marks": "abc\u202eevil\u202cdef\u2067x\u2069\u200fend",
        "script-tag": "</script><script>alert(1)</script><img src=x onerror=alert(2)>&amp;",
        "myst-directive": "```{eval-rst}\n.. raw:: html\n\n   <b>x</b>\n```\n:::{note}\nhi\n:::",
        "myst-role": "{abbr}`x (y)` {{ sub }} (target)= % comment [link](javascript:alert(1))",
        "mathjax": "\\(\\href{javascript:alert(1)}{x}\\) $$\\require{html}\\class{x}{y}$$ $\\unicode{65}$",
        "cdata-end": "]]><question/><![CDATA[ ]]>",
        "cloze": "{1:SA:=x} {#1} {2:MULTICHOICE:=a~b#c}",
    }


def hostile_sheet(name: str, payload: str) -> Sheet:
    """A sheet on which every piece of user text is the payload (the instructor template's text too)."""
    exercise = Exercise(
        topic="hostile", title=payload, level=1, slot=1, seed=0,
        statement=f"Statement {payload} with math $x_1 + 1$.",
        parts=(Part("1", f"Prompt {payload}", Answer.scalar(Fraction(1, 2))),
               Part("2", "Choose.", Answer.choice("B"), (f"Choice {payload}", "Other"))),
        solution=(f"Step {payload}",), params={})
    return Sheet(f"id-{name}", payload, "F-0000000000", 0, (exercise,))


NAMES = list(payloads(Path("/x")))


def visible(payload: str) -> str:
    """The payload as a reader should see it in text formats: cleaned, on one line."""
    return one_line(payload)


# ----------------------------------------------------------------------------------- Markdown / MyST

def myst_tokens(text: str):  # type: ignore[no-untyped-def]
    from markdown_it.renderer import RendererHTML
    from myst_parser.config.main import MdParserConfig
    from myst_parser.parsers.mdit import create_md_parser

    config = MdParserConfig(enable_extensions={"dollarmath", "amsmath", "colon_fence", "deflist", "html_image",
                                               "substitution", "strikethrough", "tasklist"})
    return create_md_parser(config, RendererHTML).parse(text)


def inline_text(tokens) -> str:  # type: ignore[no-untyped-def]
    out = []
    for tok in tokens:
        for child in tok.children or []:
            out.append(child.content if child.type in ("text", "code_inline") else " ")
        if tok.type in ("paragraph_close", "heading_close"):
            out.append(" ")
    return " ".join("".join(out).split())


ALLOWED_MD = {"heading_open", "heading_close", "paragraph_open", "paragraph_close", "inline", "bullet_list_open",
              "bullet_list_close", "list_item_open", "list_item_close", "ordered_list_open", "ordered_list_close",
              "fence"}
ALLOWED_INLINE = {"text", "strong_open", "strong_close", "em_open", "em_close", "math_inline", "code_inline",
                  "softbreak"}


def check_markdown(text: str, payload: str, fences: int) -> None:
    """Parsed by MyST: only our own structure; the payload is text (or code, which no math scanner
    reads: Jupyter's skips code spans before Markdown, MathJax skips <code>)."""
    tokens = myst_tokens(text)
    assert {t.type for t in tokens} <= ALLOWED_MD
    assert sum(t.type == "fence" for t in tokens) == fences  # only our own solution dropdown
    children = [c for t in tokens for c in t.children or []]
    assert {c.type for c in children} <= ALLOWED_INLINE
    # the only math is the template's own $x_1 + 1$ (and answers), never the payload's
    assert all(math_is_safe(c.content) and "input" not in c.content for c in children if c.type == "math_inline")
    assert visible(payload) in inline_text(tokens)
    # a backslash or dollar in plain text could start math in a notebook: they only appear in code
    assert not [c.content for c in children if c.type == "text" and ("\\" in c.content or "$" in c.content)]


@pytest.mark.parametrize("name", NAMES)
def test_markdown_shows_payload_literally(name, secret_file):
    payload = payloads(secret_file)[name]
    page = render_md.render_sheet(hostile_sheet(name, payload), solutions=False)
    check_markdown(page, payload, fences=0)
    tokens = myst_tokens(page)
    statement = inline_text(tokens)
    assert f"Statement {visible(payload)} with math" in statement and f"Prompt {visible(payload)}" in statement


@pytest.mark.parametrize("name", NAMES)
def test_notebook_markdown_cells_show_payload_literally(name, secret_file):
    payload = payloads(secret_file)[name]
    nb = json.loads(render_ipynb.render_sheet(hostile_sheet(name, payload), solutions=True))
    cells = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown"]
    check_markdown(cells[0], payload, fences=0)  # the title cell with the name
    check_markdown(cells[1], payload, fences=0)  # the exercise
    assert f"Step {visible(payload)}" in inline_text(myst_tokens(cells[2]))
    code = "".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code")
    assert "Statement" not in code and "HACKED" not in code  # no user text in code cells


# ----------------------------------------------------------------------------------- HTML and Moodle

class _Page(HTMLParser):
    """Visible text of a page, its tags, and the text MathJax would look at (outside ignored spans)."""

    def __init__(self, ignore_class: str = "tex2jax_ignore") -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[str] = []
        self.text: list[str] = []
        self.math_text: list[str] = []
        self.ignore_class = ignore_class
        self.stack: list[bool] = []
        self.in_script = self.in_title = False

    def handle_starttag(self, tag, attrs):  # type: ignore[no-untyped-def]
        self.tags.append(tag)
        self.in_script = tag in ("script", "style")
        self.in_title = tag == "title"  # MathJax typesets the body only
        if tag in ("meta", "br", "img", "hr", "input", "link"):
            return
        ignored = self.ignore_class in (dict(attrs).get("class") or "").split()
        self.stack.append(ignored or (bool(self.stack) and self.stack[-1]))

    def handle_endtag(self, tag):  # type: ignore[no-untyped-def]
        self.in_script = self.in_title = False
        if self.stack:
            self.stack.pop()

    def handle_data(self, data):  # type: ignore[no-untyped-def]
        if self.in_script:
            return
        self.text.append(data)
        if not (self.stack and self.stack[-1]) and not self.in_title:
            self.math_text.append(data)


def parse_page(text: str) -> _Page:
    page = _Page()
    page.feed(text)
    page.close()
    return page


def math_delimited(text: str) -> list[str]:
    return re.findall(r"\\\((.*?)\\\)|\$\$(.*?)\$\$|\\\[(.*?)\\\]", text, re.S)


@pytest.mark.parametrize("name", NAMES)
def test_html_shows_payload_literally(name, secret_file):
    payload = payloads(secret_file)[name]
    page_text = render_html.render_sheet(hostile_sheet(name, payload), solutions=True)
    page = parse_page(page_text)
    assert set(page.tags) <= {"html", "head", "meta", "title", "style", "body", "h1", "h2", "p", "code",
                              "div", "b", "i", "ol", "li", "details", "summary", "span"} | html_math.ELEMENTS
    assert "script" not in page.tags  # math is MathML made at generation time: no script at all
    shown = " ".join("".join(page.text).split())
    assert visible(payload) in shown
    # no TeX delimiters are left for any script to typeset
    for groups in math_delimited("".join(page.math_text)):
        assert math_is_safe("".join(groups)), groups


def cloze_fields(text: str) -> list[str]:
    # Moodle's Cloze syntax: {n:TYPE:...} and {#n}
    return re.findall(r"\{\d*:[A-Z_]+:[^}]*\}|\{#\d+\}", text)


@pytest.mark.parametrize("name", NAMES)
def test_moodle_shows_payload_literally(name, secret_file):
    payload = payloads(secret_file)[name]
    xml = render_moodle.render_quiz([hostile_sheet(name, payload)], solutions=True)
    root = ElementTree.fromstring(xml.encode())  # well-formed XML: no control character, no broken CDATA
    questions = root.findall("question[@type='cloze']")
    assert len(questions) == 1 and len(root.findall("question")) == 2
    text = questions[0].find("questiontext/text").text
    assert cloze_fields(text) == ["{1:SHORTANSWER:=1\\/2}", "{1:MULTICHOICE:A~=B}"]  # the key's fields only
    assert "$$" not in text and "[tex]" not in text  # nothing for Moodle's TeX filter
    page = parse_page(text)
    shown = " ".join("".join(page.text).split())
    assert f"Statement {visible(payload)}" in shown and f"Choice {visible(payload)}" in shown
    for groups in math_delimited(html.unescape("".join(page.math_text))):
        assert math_is_safe("".join(groups)), groups
    feedback = questions[0].find("generalfeedback/text").text
    assert f"Step {visible(payload)}" in " ".join("".join(parse_page(feedback).text).split())
    assert questions[0].find("name/text").text.endswith("[pgsym F-0000000000#1]")  # the variant, not the student


@pytest.mark.parametrize("name", NAMES)
def test_stack_shows_payload_literally(name, secret_file):
    # STACK reads CASText in the question text: {@...@} and {#...#} run Maxima, [[...]] are inputs and
    # blocks. The only ones left are those made from the key; the Maxima code holds the key only.
    payload = payloads(secret_file)[name]
    xml = render_stack.render_stack_quiz([hostile_sheet(name, payload)])
    root = ElementTree.fromstring(xml.encode())
    (question,) = root.findall("question[@type='stack']")
    texts = [question.find(f"{f}/text").text or "" for f in ("questiontext", "generalfeedback")]
    # every CASText field (all <text> but the question's name, which STACK shows as plain text)
    texts += [n.text for field in question if field.tag != "name" for n in field.iter("text") if n.text]
    for text in texts:
        assert "{@" not in text and "{#" not in text, text[:200]
        assert re.findall(r"\[\[[^\]]*\]\]", text) in ([], ["[[input:ans1]]", "[[validation:ans1]]",
                                                          "[[feedback:prt1]]", "[[input:ans2]]",
                                                          "[[validation:ans2]]", "[[feedback:prt2]]"])
    shown = " ".join("".join(parse_page(question.find("questiontext/text").text).text).split())
    assert f"Statement {visible(payload)}" in shown
    maxima = question.findtext("questionvariables/text") + "".join(p.findtext("feedbackvariables/text")
                                                                   for p in question.findall("prt"))
    assert set(maxima) <= set("abcdefghijklmnopqrstuvwxyzABCDEFGH0123456789:;[](),=/-_\n \"") , maxima
    assert question.find("name/text").text.endswith("[pgsym F-0000000000#1]")


# ----------------------------------------------------------------------------------- LaTeX and PDF

def tex_visible(payload: str) -> str:
    """What LuaLaTeX prints for a payload: every character as is, U+FFFD (what :func:`one_line` makes of
    control characters and bidi overrides) as '?', invisible format characters not at all, no whitespace."""
    text = one_line(payload).replace(REPLACEMENT, "?")
    shown = "".join(c for c in text if unicodedata.category(c) != "Cf")
    return re.sub(r"\s+", "", shown)


def tex_commands(tex: str) -> set[str]:
    return set(re.findall(r"\\([A-Za-z]+)", tex))


@pytest.mark.parametrize("name", NAMES)
def test_latex_source_escapes_payload(name, secret_file):
    payload = payloads(secret_file)[name]
    body = render_tex.render_sheet_body(hostile_sheet(name, payload), solutions=True)
    # the commands are the renderer's own and those of the template's allowed math: none from the payload
    assert tex_commands(body) <= {"sheetstart", "sheettitle", "texttt", "hfill", "exercisetitle", "textbf", "emph",
                                  "begin", "end", "item", "Alph", "ifsolutions", "par", "fi", "tfrac",
                                  "textbackslash", "textasciitilde", "textasciicircum", "text", "allowbreak"}
    assert "^^" not in body.replace(r"\textasciicircum{}", "")
    assert max(len(line) for line in body.splitlines()) < 1200  # TeX reads lines into a fixed buffer


@pytest.fixture(scope="module")
def hostile_pdf_text(secret_file, tmp_path_factory) -> str:
    """All payload sheets in one PDF, read back with pdftotext (TeX and pdftotext are required)."""
    assert shutil.which("lualatex") and shutil.which("pdftotext"), "run `make system-deps` (TeX, poppler-utils)"
    sheets = [hostile_sheet(name, payload) for name, payload in payloads(secret_file).items()]
    folder = tmp_path_factory.mktemp("pdf")
    started = time.monotonic()
    (folder / "s.pdf").write_bytes(render_tex.compile_sheets(sheets, solutions=True))
    assert time.monotonic() - started < render_tex.tex_time_limit(len(sheets))
    # -raw: the text in the order it was typeset (a widely stretched line is not read as two columns)
    result = subprocess.run(["pdftotext", "-raw", "-enc", "UTF-8", str(folder / "s.pdf"), "-"], capture_output=True,
                            text=True, timeout=60)
    assert not list(folder.glob("HACKED")) and not Path("HACKED").exists()
    return result.stdout


@pytest.mark.parametrize("name", NAMES)
def test_pdf_prints_payload_and_leaks_nothing(name, secret_file, hostile_pdf_text):
    payload = payloads(secret_file)[name]
    assert SECRET not in hostile_pdf_text
    # TeX may hyphenate a word at a line end: compare without any hyphen
    text = re.sub(r"\n\s*\d+\s*\n\s*\x0c", "", hostile_pdf_text)  # page numbers inside a long text
    squeezed = re.sub(r"\s+|-", "", text).replace("’", "'").replace("‘", "`")
    for ligature, letters in (("ﬁ", "fi"), ("ﬀ", "ff"), ("ﬂ", "fl"), ("ﬃ", "ffi"), ("ﬄ", "ffl")):
        squeezed = squeezed.replace(ligature, letters)
    shown = tex_visible(payload).replace("-", "")
    assert "Statement" + shown + "withmath" in squeezed
    assert "Prompt" + shown in squeezed and "Step" + shown in squeezed and "Choice" + shown in squeezed


def test_tex_itself_is_confined(tmp_path, secret_file, monkeypatch):
    """Even TeX code that bypassed escaping cannot read a file by absolute path, write one or run a command."""
    def document(body: str) -> str:
        return render_tex.PREAMBLE + "\\begin{document}\n" + body + "\n\\end{document}\n"

    with pytest.raises(TeXFailedError, match="not found"):
        render_tex.compile_pdf(document(f"X\\input{{{secret_file}}}Y"), timeout=60)
    pdf = render_tex.compile_pdf(document(f"\\immediate\\write18{{touch {tmp_path}/HACKED}}ok"), timeout=60)
    assert pdf.startswith(b"%PDF") and not (tmp_path / "HACKED").exists()
    target = tmp_path / "written.tex"
    with pytest.raises(TeXFailedError, match="can't write"):
        render_tex.compile_pdf(document(f"\\newwrite\\w\\immediate\\openout\\w={target}\\immediate\\write\\w{{x}}"),
                               timeout=60)
    assert not target.exists()
    opened = render_tex.compile_pdf(document(f"\\newread\\r\\openin\\r={secret_file} "
                                             "\\ifeof\\r CLOSED\\else\\read\\r to\\x \\x\\fi"), timeout=60)
    (tmp_path / "o.pdf").write_bytes(opened)
    text = subprocess.run(["pdftotext", str(tmp_path / "o.pdf"), "-"], capture_output=True, text=True,
                          timeout=60).stdout
    assert "CLOSED" in text and SECRET not in text


def test_tex_loop_stops_names_the_student_and_leaves_nothing(tmp_path, monkeypatch):
    """A sheet on which TeX loops for ever (code that bypassed escaping) is stopped after the time limit
    of its document; the error names the student and no folder is left behind."""
    monkeypatch.setattr(render_tex, "TEX_BASE_SECONDS", 8.0)  # a sheet compiles in about 1 s: margin for load
    monkeypatch.setattr(render_tex, "TEX_SECONDS_PER_SHEET", 1.0)
    body = render_tex.render_sheet_body

    def looping(sheet, solutions, *heading):  # type: ignore[no-untyped-def]
        extra = "\\def\\x{\\x}\\x\n" if sheet.student_id == "s2" else ""
        return body(sheet, solutions, *heading) + extra

    monkeypatch.setattr(render_tex, "render_sheet_body", looping)
    (tmp_path / "roster.csv").write_text("id,name\ns1,Ada\ns2,Alan\n")
    started = time.monotonic()
    result = CliRunner().invoke(main, ["sheet", "--topics", "join", "--roster", str(tmp_path / "roster.csv"),
                                       "--format", "md,pdf", "--out", str(tmp_path / "out")])
    elapsed = time.monotonic() - started
    # whole document 8 + 2 × 1 = 10 s, then halves: [s1] ok (~1 s), [s2] 9 s; about 20 s
    assert elapsed < 45
    assert result.exit_code == 1 and "TeXFailedError" in result.output
    assert "student s2 (Alan)" in result.output and "longer than" in result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["roster.csv"]  # no out/, no .out.partial-*


def test_tex_time_limit_is_documented():
    from pgsym.cli.exercises import sheet_command

    assert render_tex.tex_time_limit(10) == render_tex.TEX_BASE_SECONDS + 10 * render_tex.TEX_SECONDS_PER_SHEET
    epilog = " ".join(sheet_command.epilog.split())
    assert (f"at most {render_tex.TEX_BASE_SECONDS:.0f} s + {render_tex.TEX_SECONDS_PER_SHEET:.0f} s per sheet"
            in epilog)
    assert "openin_any=p and openout_any=p" in epilog


def test_sheet_command_with_hostile_roster_writes_every_format(tmp_path, secret_file):
    names = payloads(secret_file)
    rows = ["id,name"] + [f"{i},\"{names[k].replace(chr(34), chr(34) * 2)}\"" for i, k in
                          enumerate(["input-math", "def-loop", "cloze", "script-tag", "myst-role"], start=1)]
    rows.append('=cmd|" /C calc"!A0,"@SUM(1+1)"')
    (tmp_path / "roster.csv").write_text("\n".join(rows) + "\n")
    result = CliRunner().invoke(main, ["sheet", "--topics", "join,preserved", "--roster", str(tmp_path / "roster.csv"),
                                       "--format", "md,tex,pdf,html,ipynb,moodle,qti", "--solutions",
                                       "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    text = subprocess.run(["pdftotext", str(tmp_path / "out" / "sheets.pdf"), "-"], capture_output=True, text=True,
                          timeout=60).stdout
    assert SECRET not in text and "{1:SA:=x}" in text and "Exercisesheet:" in re.sub(r"\s", "", text)


def _mathjax() -> Path:
    return render_html.find_mathjax()


# ----------------------------------------------------------------------------------- CSV formula injection

@pytest.mark.parametrize("cell", ["=1+1", "+1+1", "-1+1", "@SUM(A1)", "\t=1", "\r=1", "=HYPERLINK(\"http://x\")",
                                  "-2+3+cmd|' /C calc'!A0"])
def test_formula_cells_are_neutralised(cell):
    assert safe_cell(cell) == "'" + cell
    assert csv_text([[cell]]).lstrip('"').startswith("'")


@pytest.mark.parametrize("cell", ["-3", "+2", "-0.5", "(1, -2, 0)", "s001", "", "Ada"])
def test_plain_cells_are_kept(cell):
    assert safe_cell(cell) == cell


@pytest.fixture()
def made(tmp_path):
    """Two students with formula-like ids, their sheets and manifest (written by the CLI in-process)."""
    (tmp_path / "roster.csv").write_text('id,name\n"=1+2",Ada\n"@SUM(1)",Alan\ns3,Emmy\n')
    result = CliRunner().invoke(main, ["sheet", "--topics", "join,cross-ratio", "--roster",
                                       str(tmp_path / "roster.csv"), "--seed", "3", "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text())
    keys = {s["id"]: {p["label"]: p for e in s["exercises"] for p in e["parts"]} for s in manifest["students"]}
    return tmp_path, keys


def right(part: dict) -> str:
    value = part["value"]
    return "(" + ", ".join(value) + ")" if isinstance(value, list) else str(value)


def check(*args: str):  # type: ignore[no-untyped-def]
    return CliRunner().invoke(main, ["check", *args])


def test_grades_csv_neutralises_formulas(made):
    base, keys = made
    rows = ["id,1,2", f'"=1+2","{right(keys["=1+2"]["1"])}","=2+5"', '"@SUM(1)",-1+1,"+999/1000"']
    (base / "answers.csv").write_text("\n".join(rows) + "\n")
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", str(base / "answers.csv"),
                   "--out", str(base / "grades.csv"))
    assert result.exit_code == 3  # =2+5 and -1+1 cannot be read as answers
    cells = [c for row in csv.reader(io.StringIO((base / "grades.csv").read_text())) for c in row]
    assert len(cells) > 20 and not [c for c in cells if c.startswith(("=", "+", "-", "@", "\t", "\r"))]
    assert "'=1+2,1," in (base / "grades.csv").read_text() and "'=2+5" in (base / "grades.csv").read_text()
    assert "'-1+1" in (base / "grades.csv").read_text() and "'+999/1000" in (base / "grades.csv").read_text()
    assert result.stdout.splitlines()[1:3] == ["'=1+2,1,2,1,2", "'@SUM(1),0,2,0,2"]  # right, questions, points


# ----------------------------------------------------------------------------------- readers

def test_fifo_answers_are_refused_at_once(made):
    base, _ = made
    os.mkfifo(base / "answers.fifo")
    started = time.monotonic()
    result = run_pgsym("check", "--manifest", "out/manifest.json", "--answers", "answers.fifo", cwd=base)
    assert time.monotonic() - started < 30
    assert result.returncode == 1 and "InputLimitError" in result.stderr and "not a regular file" in result.stderr


def test_fifo_roster_and_template_are_refused_at_once(tmp_path):
    os.mkfifo(tmp_path / "roster.csv")
    (tmp_path / "tpl").mkdir()
    os.mkfifo(tmp_path / "tpl" / "evil.py")
    result = run_pgsym("sheet", "--topics", "join", "--roster", "roster.csv", "--out", "o", cwd=tmp_path)
    assert result.returncode == 1 and "not a regular file" in result.stderr
    result = run_pgsym("templates", "list", "--templates", "tpl", cwd=tmp_path)
    assert result.returncode == 1 and "not a regular file" in result.stderr and "evil.py" in result.stderr


@pytest.mark.parametrize("reader", [read_answers, read_roster, load_manifest])
def test_dev_zero_is_refused(reader):
    with pytest.raises(InputLimitError, match="not a regular file"):
        reader("/dev/zero")


def test_dev_zero_answers_on_the_command_line(made):
    base, _ = made
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", "/dev/zero")
    assert result.exit_code == 1 and "not a regular file" in result.stderr


def test_deeply_nested_manifest(tmp_path):
    (tmp_path / "m.json").write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(ManifestError, match=f"more than {MAX_NESTING} deep"):
        load_manifest(tmp_path / "m.json")
    (tmp_path / "answers.csv").write_text("id,1\ns1,1\n")
    result = check("--manifest", str(tmp_path / "m.json"), "--answers", str(tmp_path / "answers.csv"))
    assert result.exit_code == 1 and "ManifestError" in result.stderr and "Traceback" not in result.stderr


def test_nesting_inside_strings_does_not_count(tmp_path):
    (tmp_path / "m.json").write_text(json.dumps({"format": "pgsym-exercises", "students": [], "x": "[" * 1000}))
    assert load_manifest(tmp_path / "m.json") == {}


@pytest.mark.parametrize("text", ["{", '{"format": "pgsym-exercises", "students": [{"id": 1, "exercises": '
                                  '[{"parts": [{"label": "1", "kind": "scalar", "value": "1/0"}]}]}]}',
                                  '{"format": "pgsym-exercises", "students": [{"id": "a", "exercises": [{"parts": '
                                  '[{"label": "1", "kind": "vector", "value": [' + "9" * 5000 + ']}]}]}]}'])
def test_damaged_manifests_are_named(tmp_path, text):
    (tmp_path / "m.json").write_text(text)
    with pytest.raises(ManifestError):
        load_manifest(tmp_path / "m.json")


def test_roster_limits_and_bad_bytes(tmp_path):
    # 0x81 is neither UTF-8 nor Windows-1252 (the fallback for other non-UTF-8 bytes)
    (tmp_path / "r.csv").write_bytes(b"id,name\ns1,\xff\x81\n")
    with pytest.raises(RosterError, match=r"neither UTF-8, UTF-16 nor Windows-1252.*CSV UTF-8"):
        read_roster(tmp_path / "r.csv")
    (tmp_path / "r.csv").write_text("id,name\ns1," + "x" * 200_000 + "\n")  # past the csv module's own limit
    with pytest.raises(RosterError, match="longer than 20000"):
        read_roster(tmp_path / "r.csv")
    (tmp_path / "r.csv").write_text("id,name\ns1," + "Ada " * 2500 + "\n")  # a 10 kB name is fine
    assert read_roster(tmp_path / "r.csv")[0][1] == ("Ada " * 2500).strip()


def test_template_file_with_deep_nesting_is_a_template_error(tmp_path):
    from pgsym.exercises.errors import TemplateError

    (tmp_path / "deep.py").write_text("x = " + "(" * 100_000 + ")" * 100_000 + "\n")
    with pytest.raises(TemplateError, match=r"deep\.py"):
        load_template_folder(tmp_path)


# ----------------------------------------------------------------------------------- one bad answer

def test_ten_megabyte_cell_costs_only_that_answer(made):
    base, keys = made
    good = right(keys["s3"]["1"])
    rows = ["id,question,answer", f"s3,1,\"{good}\"", f"s3,2,{keys['s3']['2']['value']}",
            '"=1+2",1,"' + "1" * 10_000_000 + '"', f'"=1+2",2,{keys["=1+2"]["2"]["value"]}']
    (base / "answers.csv").write_text("\n".join(rows) + "\n")
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", str(base / "answers.csv"),
                   "--out", str(base / "grades.csv"))
    assert result.exit_code == 3
    assert result.stdout.splitlines() == ["student,right,questions,score,points", "'=1+2,1,2,1,2", "'@SUM(1),0,2,0,2",
                                          "s3,2,2,2,2"]
    assert f"=1+2 [1]: cannot read the answer: it is 10000000 characters long; at most {MAX_ANSWER_CHARS}" \
        in result.stderr
    grades = (base / "grades.csv").read_text()
    assert "10000000 characters long" in grades and len(grades) < 5000  # the cell is not copied


def test_file_larger_than_the_limit_is_refused_whole(tmp_path):
    (tmp_path / "a.csv").write_text("id,1\n" + ("s1," + "1" * 1000 + "\n") * 21_000)
    with pytest.raises(InputLimitError, match="larger than 20000000 bytes"):
        read_answers(tmp_path / "a.csv")


def test_two_answers_to_one_question_are_reported(made):
    base, keys = made
    good = right(keys["s3"]["1"])
    rows = ["id,question,answer", f"s3,1,\"{good}\"", "s3,1,\"(1, 2, 3)\"", f"s3,2,{keys['s3']['2']['value']}"]
    (base / "answers.csv").write_text("\n".join(rows) + "\n")
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", str(base / "answers.csv"),
                   "--out", str(base / "grades.csv"))
    assert result.exit_code == 3
    assert "s3 [1]: answered 2 times; not graded" in result.stderr
    assert result.stdout.splitlines()[-1] == "s3,1,2,1,2"
    assert "answered 2 times" in (base / "grades.csv").read_text()
    # the same in the wide format: a label twice in the header, with different answers
    (base / "wide.csv").write_text(f'id,1,1,2\ns3,"{good}","(1, 2, 3)",{keys["s3"]["2"]["value"]}\n')
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", str(base / "wide.csv"))
    assert result.exit_code == 3 and "s3 [1]: answered 2 times" in result.stderr
    # the same answer twice (a row pasted again) is one answer, graded
    (base / "wide.csv").write_text(f'id,1,1,2\ns3,"{good}","{good}",{keys["s3"]["2"]["value"]}\n')
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", str(base / "wide.csv"))
    assert result.exit_code == 0 and result.stdout.splitlines()[-1] == "s3,2,2,2,2"  # 2 of 2 right: 2 of 2 points


def test_all_readable_exits_zero_and_help_documents_exit_codes(made):
    base, keys = made
    rows = ["id,question,answer"] + [f"{sid},{label},\"{right(p)}\"" for sid, parts in keys.items()
                                     for label, p in parts.items()]
    (base / "answers.csv").write_text("\n".join(rows) + "\n")
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", str(base / "answers.csv"))
    assert result.exit_code == 0 and result.stdout.splitlines()[1:] == ["'=1+2,2,2,2,2", "'@SUM(1),2,2,2,2",
                                                                        "s3,2,2,2,2"]
    helptext = " ".join(CliRunner().invoke(main, ["check", "--help"]).output.split())
    assert "Exit status: 0 every answer was read and graded" in helptext
    assert "3 some answers could not be read or were given twice" in helptext


def test_control_characters_never_reach_the_terminal(made):
    base, _ = made
    (base / "answers.csv").write_text('id,question,answer\ns3,1,"\x1b[2J\x1b]0;owned\x07"\n')
    result = check("--manifest", str(base / "out" / "manifest.json"), "--answers", str(base / "answers.csv"),
                   "--details")
    assert result.exit_code == 3 and "\x1b" not in result.stderr + result.stdout
    assert REPLACEMENT not in result.stdout


def test_answers_file_errors_are_named(tmp_path):
    with pytest.raises(AnswersFileError, match="does not exist"):
        read_answers(tmp_path / "missing.csv")
    (tmp_path / "a.csv").write_bytes(b"id,1\ns1,\x81\n")  # no encoding pgsym reads has byte 0x81 there
    with pytest.raises(AnswersFileError, match="neither UTF-8, UTF-16 nor Windows-1252"):
        read_answers(tmp_path / "a.csv")


def test_sigterm_during_writing_leaves_nothing(tmp_path):
    """A run killed with SIGTERM while writing removes its temporary folder (a real process: the signal)."""
    script = ("import os, signal, sys, time\n"
              "from pgsym.atomic import write_new_folder, Terminated\n"
              "def fill(tmp):\n"
              "    (tmp / 'half.txt').write_text('x')\n"
              "    os.kill(os.getpid(), signal.SIGTERM)\n"
              "    time.sleep(30)\n"
              "try:\n"
              f"    write_new_folder({str(tmp_path / 'out')!r}, fill)\n"
              "except Terminated:\n"
              "    sys.exit(143)\n")
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert result.returncode == 143, result.stderr
    assert list(tmp_path.iterdir()) == []


def test_hostile_names_through_real_templates():
    """The same escaping with the built-in templates' own text around the name."""
    payload = payloads(Path("/x"))["cloze"] + " " + payloads(Path("/x"))["input-math"]
    sheet = build_sheets(["join", "preserved"], [("a", payload)], 1)[0]
    page = render_md.render_sheet(sheet, solutions=True)
    check_markdown(page, payload, fences=2)  # the two solution dropdowns are ours
    assert visible(payload) + " (a)" in inline_text(myst_tokens(page))
    tex = render_tex.render_sheet_body(sheet, solutions=True)
    assert "\\{1:SA:=x\\}" in tex and "\\textbackslash{}input" in tex and "\\input" not in tex
    assert visible(payload) in " ".join("".join(parse_page(render_html.render_sheet(sheet)).text).split())


def test_mathjax_copy_skips_links_out_and_refuses_pipes(tmp_path, secret_file):
    src = tmp_path / "es5"
    src.mkdir()
    (src / "tex-chtml.js").write_text("// MathJax")
    (src / "leak.js").symlink_to(secret_file)
    render_html.copy_mathjax(tmp_path / "out", src)
    assert sorted(p.name for p in (tmp_path / "out" / "mathjax").iterdir()) == ["tex-chtml.js"]
    os.mkfifo(src / "pipe.js")
    with pytest.raises(render_html.MathJaxMissingError, match="not a regular file"):
        render_html.copy_mathjax(tmp_path / "out2", src)


def test_answer_keys_in_html_go_through_the_math_check():
    exercise = Exercise("t", "T", 1, 1, 0, "S", (Part("1", "P", Answer.choice("B}\\input{x")),), ("s",), {})
    page = render_html.render_sheet(Sheet("s1", "", "F-1", 0, (exercise,)), solutions=True)
    assert "\\(\\text{B}\\input{x}\\)" not in page and "tex2jax_ignore" in page


def test_a_template_failing_for_one_student_names_the_student(tmp_path):
    (tmp_path / "boom.py").write_text(
        "from pgsym.exercises.template import Template, Draft\n"
        "class Boom(Template):\n"
        "    name = 'boom-hostile'\n"
        "    title = 'Boom'\n"
        "    def build(self, rng, level):\n"
        "        return 1 / 0\n")
    (tmp_path / "roster.csv").write_text("id,name\ns1,Ada\n")
    result = CliRunner().invoke(main, ["sheet", "--templates", str(tmp_path), "--topics", "boom-hostile",
                                       "--roster", str(tmp_path / "roster.csv"), "--out", str(tmp_path / "out")])
    assert result.exit_code == 1 and "the sheet of student s1" in result.output
    assert "ZeroDivisionError" in result.output and "Traceback" not in result.output
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("name", ["Ada #", "Ada ##", "Ada\n===", "x\n- [ ] y", ": term"])
def test_markdown_headings_keep_every_character(name):
    page = render_md.render_sheet(Sheet("s1", name, "F-1", 0, ()))
    tokens = myst_tokens(page)
    assert [t.type for t in tokens][:3] == ["heading_open", "inline", "heading_close"]
    assert tokens[1].content.replace("\\", "") == f"Exercise sheet: {one_line(name)} (s1)"


@pytest.mark.parametrize("text", ["8¹", "٣", "1/²", "(1, ³, 0)"])
def test_unicode_digits_are_a_named_error(text):
    from pgsym.exercises.answers import parse_answer
    from pgsym.exercises.errors import UnparsableAnswerError

    with pytest.raises(UnparsableAnswerError, match="unexpected character"):
        parse_answer(text)
