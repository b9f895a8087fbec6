"""The student notebooks: "Run all" with empty and unreadable answers, and notebooks without the self-check."""

from __future__ import annotations

import json
import os
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

from pgsym.exercises.render_ipynb import render_sheet
from pgsym.exercises.sheets import build_sheet

ROOT = Path(__file__).resolve().parents[1]


def _run(text: str, monkeypatch: pytest.MonkeyPatch) -> nbformat.NotebookNode:
    nb = nbformat.reads(text, as_version=4)
    # the kernel imports this checkout's pgsym; monkeypatch restores the environment for the other tests
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    NotebookClient(nb, timeout=120, kernel_name="python3").execute()  # raises CellExecutionError on any error
    return nb


def _outputs(nb: nbformat.NotebookNode) -> str:
    return "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.outputs)


def test_run_all_with_an_empty_an_unreadable_and_a_right_answer(monkeypatch):
    sheet = build_sheet(["join", "meet", "cross-ratio"], "s1", "Ada", 7)
    nb = json.loads(render_sheet(sheet))
    right = sheet.exercises[1].parts[0].answer.value
    typed = {2: f'check("2", "{tuple(int(x) * 3 for x in right)}")',  # a multiple of the key: right
             3: 'check("3", "((((")'}  # not an answer at all
    answer_cells = [c for c in nb["cells"] if c["cell_type"] == "code"][1:]
    for slot, source in typed.items():
        answer_cells[slot - 1]["source"] = [source]
    out = _outputs(_run(json.dumps(nb), monkeypatch))
    assert "1 no answer yet" in out  # question 1 left empty: a message, and the next cells still ran
    assert "2 right" in out
    assert "3 cannot read the answer:" in out


def test_a_graded_notebook_has_no_digest_and_collects_the_answers(monkeypatch):
    sheet = build_sheet(["join", "meet"], "s1", "Ada", 7)
    with_check, without = render_sheet(sheet), render_sheet(sheet, self_check=False)
    from pgsym.exercises.answers import answer_digest

    digest = answer_digest(f"{sheet.form_id}:1", sheet.exercises[0].parts[0].answer)
    assert digest in with_check and digest not in without and "self_check" not in without
    nb = json.loads(without)
    cells = [c for c in nb["cells"] if c["cell_type"] == "code"]
    cells[1]["source"] = ['answer("1", "(1, 2, 3)")']
    cells.append({"cell_type": "code", "execution_count": None, "id": "probe", "metadata": {}, "outputs": [],
                  "source": ["print(ANSWERS)"]})
    nb["cells"].append(cells[-1])
    assert "{'1': '(1, 2, 3)', '2': ''}" in _outputs(_run(json.dumps(nb), monkeypatch))


def test_the_cli_writes_graded_notebooks_on_request(tmp_path):
    from click.testing import CliRunner

    from pgsym.cli import main

    result = CliRunner().invoke(main, ["sheet", "--topics", "join", "--count", "1", "--format", "ipynb",
                                       "--no-self-check", "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    page = (tmp_path / "out" / "ipynb" / "sheet-form-001.ipynb").read_text()
    assert "self_check" not in page and "ANSWERS" in page
