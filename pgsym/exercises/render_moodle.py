"""Moodle XML renderer: one question category per exercise slot, one Cloze question per variant.

Cloze cannot grade projective geometry properly, and every question says so to the student: each
coordinate is its own box compared on its own with the canonical form (homogeneous answers as
coprime integers with the first nonzero entry positive, fractions as exact strings in lowest
terms), so a right answer written as another multiple scores 0, ``-2/6`` is not ``-1/3`` and a sign
slip in one of three coordinates still earns two thirds of the part. For grading up to scale, with
pgsym's mistake feedback, use the STACK export (:mod:`pgsym.exercises.render_stack`). Integer fields
are NUMERICAL, fractions SHORTANSWER, choices MULTICHOICE; the boxes of a part share the part's
points (:mod:`pgsym.exercises.points`), the question's default mark is the exercise's points, and the
worked solution is always the general feedback (Moodle shows it after the attempt, as the quiz's
review options allow). The variant id is in the name and the text.

Exercise text goes through :func:`~pgsym.escaping.to_moodle`: HTML-escaped, with the Cloze
characters ``{ } ~ = # :`` (and ``$ [ ] \\`` of Moodle's TeX filter) as numeric entities, so the only
Cloze fields are the ones made here from the answer key; question names are XML-escaped text.

>>> from pgsym.exercises.sheets import build_sheet
>>> xml = render_quiz([build_sheet(["join"], "s1", "", 1)])
>>> xml.startswith('<?xml version="1.0"') and "{1:NUMERICAL:=" in xml
True
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from fractions import Fraction
from xml.sax.saxutils import escape

from ..escaping import moodle_escape, one_line, to_moodle
from .model import Answer, Exercise, Sheet, variant_id
from .points import points_text


def _field(value: Fraction, weight: int = 1) -> str:
    if value.denominator == 1:
        return f"{{{weight}:NUMERICAL:={value.numerator}:0}}"
    return f"{{{weight}:SHORTANSWER:={value.numerator}\\/{value.denominator}}}"


def _boxes(answer: Answer) -> int:
    return 1 if answer.kind == "choice" else len(answer.flat())


def _weights(ex: Exercise) -> list[int]:
    """The integer weight of every box of each part, so that a part's boxes share its points."""
    shares = [Fraction(p.points) / _boxes(p.answer) for p in ex.parts]
    scale = math.lcm(*(s.denominator for s in shares))
    return [int(s * scale) for s in shares]


def _cloze(answer: Answer, choices: Sequence[str], weight: int = 1) -> str:
    if answer.kind == "choice":
        letters = "ABCDEFGH"[: len(choices)]
        return f"{{{weight}:MULTICHOICE:" + "~".join(("=" if c == answer.value else "") + c for c in letters) + "}"
    if answer.kind in ("projective", "vector"):
        return "(" + ", ".join(_field(Fraction(v), weight) for v in answer.value) + ")"
    if answer.kind in ("scalar", "integer"):
        return _field(Fraction(answer.value), weight)
    rows = ["<tr>" + "".join(f"<td>{_field(Fraction(v), weight)}</td>" for v in row) + "</tr>"
            for row in answer.value]
    return "<table>" + "".join(rows) + "</table>"


def _cdata(text: str) -> str:
    """A CDATA section holding ``text`` (a ``]]>`` inside is split over two sections)."""
    return "<![CDATA[" + text.replace("]]>", "]]]]><![CDATA[>") + "]]>"


_CANONICAL = {"projective": " (canonical form: coprime integers, first nonzero entry positive)",
              "matrix": " (canonical form: coprime integers, first nonzero entry positive)",
              "vector": " (fractions in lowest terms, e.g. -2/3)", "scalar": " (a fraction in lowest terms, e.g. -2/3)",
              "matrix_exact": " (fractions in lowest terms)", "integer": "", "choice": ""}


#: What every Cloze question tells the student about its limits (no claim of grading up to scale).
LIMITS = ("This question compares each box with one exact text: homogeneous answers only in the canonical "
          "form, fractions only in lowest terms. Another multiple of a right answer is marked wrong here, "
          "and each box scores on its own.")


def _question(sheet: Sheet, ex: Exercise, solutions: bool) -> str:
    del solutions  # the worked solution is always the general feedback, shown after the attempt
    vid = variant_id(sheet.form_id, ex.slot)
    text = [f"<p>{to_moodle(ex.statement)}</p>"]
    for p, weight in zip(ex.parts, _weights(ex), strict=True):
        text.append(f"<p><b>[{p.label}]</b> {to_moodle(p.prompt)}{_CANONICAL[p.answer.kind]}</p>")
        if p.choices:
            text.append("<ol type=\"A\">" + "".join(f"<li>{to_moodle(c)}</li>" for c in p.choices) + "</ol>")
        text.append(f"<p>{_cloze(p.answer, p.choices, weight)}</p>")  # the only Cloze fields: made from the key
    if any(p.answer.kind not in ("choice", "integer") for p in ex.parts):
        text.append(f"<p><i>{moodle_escape(LIMITS)}</i></p>")
    text.append(f"<p>pgsym {moodle_escape(vid)}</p>")
    feedback = "<ol>" + "".join(f"<li>{to_moodle(s)}</li>" for s in ex.solution) + "</ol>"
    name = one_line(f"{ex.slot}. {ex.title} [pgsym {vid}]")
    return (f'  <question type="cloze">\n    <name><text>{escape(name)}</text></name>\n'
            f'    <questiontext format="html"><text>{_cdata("".join(text))}</text></questiontext>\n'
            f'    <generalfeedback format="html"><text>{_cdata(feedback)}</text></generalfeedback>\n'
            f"    <defaultgrade>{points_text(ex.points)}</defaultgrade>\n"
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
