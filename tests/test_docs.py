"""The README's promises, and the rules every chapter notebook follows."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import nbformat
import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]


def python_blocks(markdown: str) -> list[str]:
    return re.findall(r"```python\n(.*?)```", markdown, flags=re.S)


@pytest.mark.parametrize("page", ["README.md", "book/intro.md"])
def test_five_line_example_prints_what_its_comments_say(page):
    block = python_blocks((ROOT / page).read_text())[0]
    lines = block.strip().splitlines()
    assert len(lines) == 5
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(block, {})  # the project's own documentation, not user input
    printed = out.getvalue().splitlines()
    expected = [line.split("#", 1)[1].strip() for line in lines if line.startswith("print(")]
    assert printed[0] == expected[0]
    assert printed[1] == expected[1].split(":")[-1].strip()


def toc_files() -> list[str]:
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    return [toc["root"]] + [c["file"] for part in toc["parts"] for c in part["chapters"]]


NOTEBOOKS = [ROOT / f"{name}.ipynb" for name in toc_files() if (ROOT / f"{name}.ipynb").exists()]


def test_every_toc_entry_exists_and_chapters_are_notebooks():
    for name in toc_files():
        assert (ROOT / f"{name}.ipynb").exists() or (ROOT / f"{name}.md").exists(), name
    prose = {name for name in toc_files() if not (ROOT / f"{name}.ipynb").exists()}
    toc = yaml.safe_load((ROOT / "_toc.yml").read_text())
    appendix = {c["file"] for part in toc["parts"] if part.get("caption") == "Appendix" for c in part["chapters"]}
    # the reference pages of the appendix (notation, glossary, bibliography, API) are prose; chapters are not
    assert prose - appendix == {"book/intro", "book/using-this-book"}, "every chapter is a notebook"
    assert {"book/notation", "book/glossary", "book/bibliography"} <= prose


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_is_committed_executed(path):
    nb = nbformat.read(path, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert code, "a chapter without code cells"
    assert all(c.execution_count is not None for c in code), "unexecuted cells are silently not compared by nbval"
    counts = [c.execution_count for c in code]
    assert counts == list(range(1, len(code) + 1)), "execute the notebook top to bottom in one fresh kernel"
    assert not any(o.get("output_type") == "error" for c in code for o in c.outputs)
    # a warning on stderr (a glyph missing from the figure's font, a deprecation) shows the reader the
    # machine's file paths and says something went wrong: chapters print none
    stderr = [o.get("text", "")[:120] for c in code for o in c.outputs if o.get("name") == "stderr"]
    assert stderr == [], f"outputs on stderr: {stderr}"
    assert nb.metadata.kernelspec.name == "python3"


BOX = re.compile(r"```\{prf:(definition|theorem|lemma|proposition|corollary|example|property)\}")


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_stated_claim_is_followed_by_a_cell_that_asserts_it(path):
    nb = nbformat.read(path, as_version=4)
    cells = nb.cells
    claims = 0
    for i, cell in enumerate(cells):
        if cell.cell_type == "markdown" and BOX.search(cell.source):
            claims += 1
            following = next((c for c in cells[i + 1 :] if c.cell_type == "code"), None)
            assert following is not None and "assert" in following.source, cell.source[:80]
    assert claims >= 2


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_every_chapter_has_an_exercise_with_a_toggled_solution(path):
    text = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "markdown")
    assert "```{exercise}" in text
    assert re.search(r"```\{solution\}[^\n]*\n:class: dropdown", text)


def test_every_python_example_in_the_readme_runs():
    blocks = python_blocks((ROOT / "README.md").read_text())
    assert len(blocks) >= 2
    for block in blocks:
        with contextlib.redirect_stdout(io.StringIO()):
            exec(block, {})  # the project's own documentation, not user input
