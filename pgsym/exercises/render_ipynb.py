"""Jupyter notebook renderer: one notebook per sheet in which students type their answers.

With the self-check (the default) each answer cell says whether the answer is right, against a salted
digest of the key. That is a *practice* aid, not a secret: an answer with few possible values (a
small integer, a choice among four, a short integer vector) is found by trying candidates against the
digest in well under a second. For a graded sheet, hand out notebooks without it
(``self_check=False``, ``pgsym sheet --no-self-check``): the cells then only collect the answers.
An empty or unreadable answer prints a message; it never stops "Run all".

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


_CHECK = """from pgsym.errors import PgsymError
from pgsym.exercises.answers import self_check

KEYS = {keys}


def check(label, text):
    \"\"\"Print whether the answer typed for question `label` is right (practice: the key's digests are here).\"\"\"
    if not text.strip():
        print(label, 'no answer yet')
        return
    salt, kind, digest = KEYS[label]
    try:
        right = self_check(salt, kind, digest, text)
    except PgsymError as err:
        print(label, 'cannot read the answer:', err)
        return
    print(label, 'right' if right else 'not right yet')
"""

_COLLECT = """ANSWERS = {}


def answer(label, text):
    \"\"\"Keep the answer typed for question `label` (it is graded later, not here).\"\"\"
    ANSWERS[label] = text
"""


def render_sheet(sheet: Sheet, solutions: bool = False, self_check: bool = True) -> str:
    """The notebook (JSON text, nbformat 4) of one sheet; ``self_check=False`` leaves the digests out
    (a graded sheet: the answers are only collected)."""
    who = sheet.student_name or sheet.student_id
    keys = {}
    for ex in sheet.exercises:
        for p in ex.parts:
            salt = f"{sheet.form_id}:{p.label}"
            keys[p.label] = [salt, p.answer.kind, answer_digest(salt, p.answer)]
    how = ("Type each answer as text in the cell below its exercise, then run the cell: pgsym reads the answer "
           "exactly and says whether it is right (homogeneous answers up to a nonzero scale). This check is for "
           "practice." if self_check else
           "Type each answer as text between the quotes in the cell below its exercise, then save the notebook "
           "and hand it in; the answers are graded afterwards.")
    cells = [_md(f"# Exercise sheet: {md_escape(who)}\n\nForm id: **{md_escape(sheet.form_id)}**\n\n{how}"),
             _code(_CHECK.format(keys=json.dumps(keys, indent=1, sort_keys=True)) if self_check else _COLLECT)]
    call = "check" if self_check else "answer"
    for ex in sheet.exercises:
        body = [f"## Exercise {ex.slot}: {md_escape(ex.title)}", "", to_md(ex.statement), ""]
        for p in ex.parts:
            body.append(f"**[{p.label}]** {to_md(p.prompt)} *Answer format: {KIND_HINTS[p.answer.kind]}.*")
            body += [f"- **{letter}.** {to_md(c)}" for letter, c in zip("ABCDEFGH", p.choices, strict=False)]
            body.append("")
        cells.append(_md("\n".join(body)))
        cells.append(_code("\n".join(f'{call}("{p.label}", "")  # type your answer between the quotes'
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
