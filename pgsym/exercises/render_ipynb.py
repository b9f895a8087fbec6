"""Jupyter notebook renderer: one notebook per sheet in which students type answers and check them
with pgsym (against salted digests, so the notebook does not reveal the key).

Markdown cells are escaped like the Markdown pages (:func:`~pgsym.escaping.md_escape`,
:func:`~pgsym.escaping.to_md`); the JSON itself is written by ``json.dumps``, and the code
cells hold only labels and digests pgsym made.

>>> import json
>>> from pgsym.exercises.sheets import build_sheet
>>> nb = json.loads(render_sheet(build_sheet(["meet"], "s1", "", 1)))
>>> nb["nbformat"], nb["cells"][0]["cell_type"]
(4, 'markdown')
"""

from __future__ import annotations

import json
from typing import Any

from ..escaping import md_escape
from .answers import answer_digest
from .model import KIND_HINTS, Sheet
from .render_md import to_md  # the cached conversion


def _md(text: str) -> dict[str, Any]:
    return {"cell_type": "markdown", "metadata": {}, "source": text.splitlines(keepends=True)}


def _code(text: str) -> dict[str, Any]:
    return {"cell_type": "code", "execution_count": None, "metadata": {}, "outputs": [],
            "source": text.splitlines(keepends=True)}


def render_sheet(sheet: Sheet, solutions: bool = False) -> str:
    """The notebook (JSON text, nbformat 4) of one sheet."""
    who = sheet.student_name or sheet.student_id
    keys = {}
    for ex in sheet.exercises:
        for p in ex.parts:
            salt = f"{sheet.form_id}:{p.label}"
            keys[p.label] = [salt, p.answer.kind, answer_digest(salt, p.answer)]
    cells = [_md(f"# Exercise sheet: {md_escape(who)}\n\nForm id: **{md_escape(sheet.form_id)}**\n\n"
                 "Type each answer as text in the cell below its exercise, then run the cell: pgsym reads the "
                 "answer exactly and says whether it is right (homogeneous answers up to a nonzero scale)."),
             _code("from pgsym.exercises.answers import self_check\n\n"
                   f"KEYS = {json.dumps(keys, indent=1, sort_keys=True)}\n\n\n"
                   "def check(label, text):\n"
                   "    \"\"\"Print whether the answer typed for question `label` is right.\"\"\"\n"
                   "    salt, kind, digest = KEYS[label]\n"
                   "    print(label, 'right' if self_check(salt, kind, digest, text) else 'not right yet')\n")]
    for ex in sheet.exercises:
        body = [f"## Exercise {ex.slot}: {md_escape(ex.title)}", "", to_md(ex.statement), ""]
        for p in ex.parts:
            body.append(f"**[{p.label}]** {to_md(p.prompt)} *Answer format: {KIND_HINTS[p.answer.kind]}.*")
            body += [f"- **{letter}.** {to_md(c)}" for letter, c in zip("ABCDEFGH", p.choices, strict=False)]
            body.append("")
        cells.append(_md("\n".join(body)))
        cells.append(_code("\n".join(f'check("{p.label}", "")  # type your answer between the quotes'
                                     for p in ex.parts)))
        if solutions:
            sol = ["**Solution**", ""] + [f"{i}. {to_md(s)}" for i, s in enumerate(ex.solution, start=1)] + [""]
            sol += [f"Answer [{p.label}]: {to_md('$' + p.answer.latex() + '$')}" for p in ex.parts]
            cells.append(_md("\n".join(sol)))
    nb = {"cells": cells, "metadata": {"kernelspec": {"display_name": "Python 3 (ipykernel)", "language": "python",
                                                      "name": "python3"},
                                       "language_info": {"name": "python"}},
          "nbformat": 4, "nbformat_minor": 5}
    for i, cell in enumerate(nb["cells"]):
        cell["id"] = f"cell-{i}"
    return json.dumps(nb, indent=1, sort_keys=True, ensure_ascii=False) + "\n"
