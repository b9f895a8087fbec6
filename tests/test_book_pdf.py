"""The PDF of the whole book: `make pdf` runs (once, at the start of this module) and the PDF is complete
and its text readable.

LaTeX's log must show no undefined reference and no character missing from the fonts; the text that
pdftotext reads back holds the title of every page of the table of contents and formulas of the chapters.
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
LATEX = ROOT / "_build" / "latex"
PDF = LATEX / "book.pdf"
LOG = LATEX / "book.log"


def toc_files() -> list[str]:
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    return [c["file"] for part in toc["parts"] for c in part["chapters"]]


def first_heading(name: str) -> str:
    """The title of a page: the first level-1 heading of its notebook or Markdown source, as plain text."""
    path = ROOT / f"{name}.ipynb"
    if path.exists():
        cells = json.loads(path.read_text())["cells"]
        text = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")
    else:
        text = (ROOT / f"{name}.md").read_text()
    heading = next(line for line in text.splitlines() if line.startswith("# "))
    return heading[2:].replace("`", "").strip()


def squeeze(text: str) -> str:
    """Text with every run of white space (line breaks of the PDF included) as one space."""
    return re.sub(r"\s+", " ", text).strip()


@pytest.fixture(scope="module", autouse=True)
def built_pdf() -> Path:
    """The README's command, really run: LuaLaTeX typesets the whole book (about 4 minutes on 2 cores)."""
    for old in (PDF, LOG):  # a PDF left by an earlier build must not pass for this one
        old.unlink(missing_ok=True)
    done = subprocess.run(["make", "--no-print-directory", "pdf"], cwd=ROOT, capture_output=True, text=True,
                          timeout=1800)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert PDF.is_file() and f"PDF: {PDF}" in done.stdout
    return PDF


@pytest.fixture(scope="module")
def pdf_text() -> str:
    out = subprocess.run(["pdftotext", "-enc", "UTF-8", str(PDF), "-"], capture_output=True, text=True, check=True)
    # a word hyphenated at the end of a line comes back as "hyphen-\nated"; apostrophes are typeset curly
    return squeeze(re.sub(r"(\w)-\n(\w)", r"\1\2", out.stdout)).replace("\u2019", "'")


def test_the_latex_log_has_no_undefined_reference_and_no_missing_character():
    log = LOG.read_text(errors="replace")
    assert "Output written on book.pdf" in log
    problems = [line for line in log.splitlines()
                if "undefined references" in line or "Missing character" in line
                or re.search(r"(Reference|Citation|Hyper reference) `[^']*' on page \d+ undefined", line)]
    assert problems == [], "\n".join(problems[:20])


def test_the_pdf_holds_the_title_of_every_page(pdf_text):
    titles = [first_heading(name) for name in toc_files()]
    assert "Homogeneous coordinates" in titles and len(titles) == len(toc_files())
    missing = [title for title in titles if squeeze(title) not in pdf_text]
    assert missing == [], f"titles not found in the PDF's text: {missing}"


# Formulas of the chapters' Markdown and how pdftotext reads the typeset formula back, compared without
# spaces (their width varies with the line): bold vectors come back as plain letters, an italic C as the
# mathematical italic 𝐶 (U+1D436), ^\top as ⊤.
FORMULAS = [
    # the incidence of a point and a line (ideal-points and others)
    (r"\mathbf{l}^\top \mathbf{x} = 0", "l⊤x=0"),
    # the points of a conic (conics)
    (r"\mathbf{x}^\top C \mathbf{x} = 0", "x⊤𝐶x=0"),
    # the line at infinity (ideal-points and others)
    (r"\mathbf{l}_\infty = (0, 0, 1)^\top", "l∞=(0,0,1)⊤"),
]


@pytest.mark.parametrize(("source", "typeset"), FORMULAS)
def test_formulas_of_the_chapters_are_in_the_pdf(pdf_text, source, typeset):
    chapters = "".join(json.dumps(json.loads((ROOT / f"{n}.ipynb").read_text())) for n in toc_files()
                       if (ROOT / f"{n}.ipynb").exists())
    assert json.dumps(source)[1:-1] in chapters, f"no chapter writes {source}"
    assert typeset in pdf_text.replace(" ", ""), f"{typeset!r} not in the PDF's text"
