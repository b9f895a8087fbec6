"""Moodle XML renderer: one question category per exercise slot, one Cloze question per variant.

Import the file into a Moodle question bank and add a "random question" from each category to a
quiz: every attempt draws a variant. Numbers are asked in canonical form (homogeneous answers as
primitive integers with the first nonzero entry positive), since Cloze compares each field on its own;
integer fields are NUMERICAL, fractions SHORTANSWER in lowest terms, choices MULTICHOICE.

Exercise text goes through :func:`~pgsym.escaping.to_moodle`: HTML-escaped, with the Cloze
characters ``{ } ~ = # :`` (and ``$ [ ] \\`` of Moodle's TeX filter) as numeric entities, so the only
Cloze fields are the ones made here from the answer key; question names are XML-escaped text.

>>> from pgsym.exercises.sheets import build_sheet
>>> xml = render_quiz([build_sheet(["join"], "s1", "", 1)])
>>> xml.startswith('<?xml version="1.0"') and "{1:NUMERICAL:=" in xml
True
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from fractions import Fraction
from xml.sax.saxutils import escape

from ..escaping import one_line, to_moodle
from .model import Answer, Exercise, Sheet


def _field(value: Fraction) -> str:
    if value.denominator == 1:
        return f"{{1:NUMERICAL:={value.numerator}:0}}"
    return f"{{1:SHORTANSWER:={value.numerator}\\/{value.denominator}}}"


def _cloze(answer: Answer, choices: Sequence[str]) -> str:
    if answer.kind == "choice":
        letters = "ABCDEFGH"[: len(choices)]
        return "{1:MULTICHOICE:" + "~".join(("=" if c == answer.value else "") + c for c in letters) + "}"
    if answer.kind in ("projective", "vector"):
        return "(" + ", ".join(_field(Fraction(v)) for v in answer.value) + ")"
    if answer.kind in ("scalar", "integer"):
        return _field(Fraction(answer.value))
    rows = ["<tr>" + "".join(f"<td>{_field(Fraction(v))}</td>" for v in row) + "</tr>" for row in answer.value]
    return "<table>" + "".join(rows) + "</table>"


def _cdata(text: str) -> str:
    """A CDATA section holding ``text`` (a ``]]>`` inside is split over two sections)."""
    return "<![CDATA[" + text.replace("]]>", "]]]]><![CDATA[>") + "]]>"


_CANONICAL = {"projective": " (canonical form: coprime integers, first nonzero entry positive)",
              "matrix": " (canonical form: coprime integers, first nonzero entry positive)",
              "vector": " (fractions in lowest terms, e.g. -2/3)", "scalar": " (a fraction in lowest terms, e.g. -2/3)",
              "matrix_exact": " (fractions in lowest terms)", "integer": "", "choice": ""}


def _question(sheet: Sheet, ex: Exercise, solutions: bool) -> str:
    text = [f"<p>{to_moodle(ex.statement)}</p>"]
    for p in ex.parts:
        text.append(f"<p><b>[{p.label}]</b> {to_moodle(p.prompt)}{_CANONICAL[p.answer.kind]}</p>")
        if p.choices:
            text.append("<ol type=\"A\">" + "".join(f"<li>{to_moodle(c)}</li>" for c in p.choices) + "</ol>")
        text.append(f"<p>{_cloze(p.answer, p.choices)}</p>")  # the only Cloze fields: made here from the key
    feedback = ""
    if solutions:
        feedback = "<ol>" + "".join(f"<li>{to_moodle(s)}</li>" for s in ex.solution) + "</ol>"
    name = one_line(f"{ex.slot}. {ex.title} [{sheet.form_id} / {sheet.student_id}]")
    return (f'  <question type="cloze">\n    <name><text>{escape(name)}</text></name>\n'
            f'    <questiontext format="html"><text>{_cdata("".join(text))}</text></questiontext>\n'
            f'    <generalfeedback format="html"><text>{_cdata(feedback)}</text></generalfeedback>\n'
            "    <penalty>0.3333333</penalty>\n    <hidden>0</hidden>\n  </question>\n")


def render_quiz(sheets: Sequence[Sheet], solutions: bool = False, course: str = "pgsym") -> str:
    """The Moodle XML of every variant, grouped in one category per exercise slot."""
    out = ['<?xml version="1.0" encoding="UTF-8"?>\n', "<quiz>\n"]
    if not sheets:
        return "".join(out) + "</quiz>\n"
    for index, first in enumerate(sheets[0].exercises):
        topic = re.sub(r"[^A-Za-z0-9_-]", "_", first.topic)  # a path in Moodle: no '/' from a template name
        category = f"$course$/{one_line(course)}/{first.slot:02d}-{topic}-level{first.level}"
        out.append(f'  <question type="category">\n    <category><text>{escape(category)}</text></category>\n'
                   "  </question>\n")
        out += [_question(sheet, sheet.exercises[index], solutions) for sheet in sheets]
    out.append("</quiz>\n")
    return "".join(out)
