"""The internal representation of exercise sheets, shared by every renderer.

A :class:`Sheet` holds one student's exercises; an :class:`Exercise` holds the statement, the parts
to answer (each with an :class:`Answer`) and the worked solution. Text is Markdown with inline math
``$...$`` and display math ``$$...$$``; every renderer converts from this one form.

>>> a = Answer.projective([2, -4, 0])
>>> a.value, a.display()
((1, -2, 0), '(1, -2, 0)')
>>> Answer.from_json(a.to_json()) == a
True
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

from ..ring import primitive_integer_matrix, primitive_integers

#: Answer kinds. ``projective`` and ``matrix`` compare up to a nonzero scale; the others exactly.
KINDS = ("projective", "vector", "scalar", "integer", "matrix", "matrix_exact", "choice")

#: What the student is told to type for each kind.
KIND_HINTS = {
    "projective": "a vector such as (1, -2, 0); any nonzero multiple is accepted",
    "vector": "a vector such as (1/2, -3); fractions are exact",
    "scalar": "a number such as -3/4",
    "integer": "an integer",
    "matrix": "a matrix such as [[1, 0, 2], [0, 1, 0], [0, 0, 1]]; any nonzero multiple is accepted",
    "matrix_exact": "a matrix such as [[1, 1/2], [0, 1]]",
    "choice": "one letter",
}


def _int(value: Any) -> int:
    """An integer entry of a manifest: plain ``int`` for the usual digits (fast), else through Fraction."""
    try:
        return int(value)
    except (ValueError, TypeError):
        return int(Fraction(value))


def _fraction_text(value: Fraction) -> str:
    return str(value.numerator) if value.denominator == 1 else f"{value.numerator}/{value.denominator}"


def _latex_number(value: Fraction) -> str:
    if value.denominator == 1:
        return str(value.numerator)
    sign = "-" if value < 0 else ""
    return rf"{sign}\tfrac{{{abs(value.numerator)}}}{{{value.denominator}}}"


@dataclass(frozen=True)
class Answer:
    """The expected answer of one part, in canonical form.

    ``projective`` vectors are stored as primitive integers with the first nonzero entry positive,
    ``matrix`` answers likewise (all entries together); ``vector``, ``scalar`` and ``matrix_exact``
    answers as exact fractions; ``choice`` answers as one capital letter.

    >>> Answer.scalar(Fraction(-6, 4)).display()
    '-3/2'
    """

    kind: str
    value: Any

    @classmethod
    def projective(cls, values: Any) -> Answer:
        """A homogeneous vector, compared up to a nonzero scale."""
        return cls("projective", primitive_integers(values))

    @classmethod
    def vector(cls, values: Any) -> Answer:
        """An exact (inhomogeneous) vector."""
        return cls("vector", tuple(Fraction(v) for v in values))

    @classmethod
    def scalar(cls, value: Any) -> Answer:
        """An exact rational number."""
        return cls("scalar", Fraction(value))

    @classmethod
    def integer(cls, value: int) -> Answer:
        """An integer."""
        return cls("integer", int(value))

    @classmethod
    def matrix(cls, rows: Any) -> Answer:
        """A matrix compared up to a nonzero scale."""
        return cls("matrix", primitive_integer_matrix(rows))

    @classmethod
    def matrix_exact(cls, rows: Any) -> Answer:
        """A matrix compared exactly."""
        return cls("matrix_exact", tuple(tuple(Fraction(x) for x in row) for row in rows))

    @classmethod
    def choice(cls, letter: str) -> Answer:
        """A multiple-choice key."""
        return cls("choice", letter.upper())

    def flat(self) -> list[Fraction]:
        """All numbers of the answer in reading order (empty for a choice)."""
        if self.kind in ("projective", "vector"):
            return [Fraction(v) for v in self.value]
        if self.kind in ("scalar", "integer"):
            return [Fraction(self.value)]
        if self.kind in ("matrix", "matrix_exact"):
            return [Fraction(v) for row in self.value for v in row]
        return []

    def display(self) -> str:
        """Plain text, in the syntax the answer parser reads."""
        if self.kind in ("projective", "vector"):
            return "(" + ", ".join(_fraction_text(Fraction(v)) for v in self.value) + ")"
        if self.kind in ("scalar", "integer"):
            return _fraction_text(Fraction(self.value))
        if self.kind in ("matrix", "matrix_exact"):
            return "[" + ", ".join("[" + ", ".join(_fraction_text(Fraction(v)) for v in row) + "]"
                                   for row in self.value) + "]"
        return str(self.value)

    def latex(self) -> str:
        """LaTeX (without math delimiters)."""
        if self.kind == "projective":
            return r"\begin{pmatrix}" + r" \\ ".join(str(v) for v in self.value) + r"\end{pmatrix}"
        if self.kind == "vector":
            return "(" + ", ".join(_latex_number(Fraction(v)) for v in self.value) + ")"
        if self.kind in ("scalar", "integer"):
            return _latex_number(Fraction(self.value))
        if self.kind in ("matrix", "matrix_exact"):
            return matrix_latex(self.value)
        return rf"\text{{{self.value}}}"

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict; fractions become strings such as ``"-2/3"``."""
        if self.kind in ("projective", "vector"):
            value: Any = [_fraction_text(Fraction(v)) for v in self.value]
        elif self.kind in ("scalar", "integer"):
            value = _fraction_text(Fraction(self.value))
        elif self.kind in ("matrix", "matrix_exact"):
            value = [[_fraction_text(Fraction(v)) for v in row] for row in self.value]
        else:
            value = self.value
        return {"kind": self.kind, "value": value}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> Answer:
        """Inverse of :meth:`to_json`."""
        kind, value = data["kind"], data["value"]
        if kind not in KINDS:
            raise ValueError(f"unknown answer kind {kind!r}; expected one of {', '.join(KINDS)}")
        if kind == "projective":
            return cls(kind, tuple(_int(v) for v in value))
        if kind == "vector":
            return cls(kind, tuple(Fraction(v) for v in value))
        if kind == "scalar":
            return cls(kind, Fraction(value))
        if kind == "integer":
            return cls(kind, int(Fraction(value)))
        if kind == "matrix":
            return cls(kind, tuple(tuple(_int(v) for v in row) for row in value))
        if kind == "matrix_exact":
            return cls(kind, tuple(tuple(Fraction(v) for v in row) for row in value))
        return cls(kind, str(value))


def matrix_latex(rows: Any) -> str:
    """LaTeX of a matrix of rationals (a ``bmatrix``).

    >>> matrix_latex([[1, Fraction(1, 2)], [0, 1]])
    '\\\\begin{bmatrix} 1 & \\\\tfrac{1}{2} \\\\\\\\ 0 & 1 \\\\end{bmatrix}'
    """
    return (r"\begin{bmatrix} " + r" \\ ".join(" & ".join(_latex_number(Fraction(v)) for v in row) for row in rows)
            + r" \end{bmatrix}")


def vector_latex(values: Any) -> str:
    """LaTeX of a column vector of rationals.

    >>> vector_latex([1, -2])
    '\\\\begin{pmatrix} 1 \\\\\\\\ -2 \\\\end{pmatrix}'
    """
    return r"\begin{pmatrix} " + r" \\ ".join(_latex_number(Fraction(v)) for v in values) + r" \end{pmatrix}"


def tuple_latex(values: Any) -> str:
    """LaTeX of a row tuple ``(a, b, c)`` of rationals.

    >>> tuple_latex([1, Fraction(-1, 2)])
    '(1, -\\\\tfrac{1}{2})'
    """
    return "(" + ", ".join(_latex_number(Fraction(v)) for v in values) + ")"


@dataclass(frozen=True)
class Mistake:
    """A common wrong answer of one part: a class ``code`` (see :data:`pgsym.exercises.mistakes.MISTAKE_CLASSES`,
    or a template's own), the feedback ``message`` and the wrong ``answer``.

    The kind of ``answer`` decides the comparison, as in grading: a ``projective`` (or ``matrix``)
    candidate for an exact key stands for every nonzero multiple of it (an answer right only up to a
    scale that is not allowed).

    >>> m = Mistake("sign", "a sign lost in coordinate 2", Answer.projective([1, 2, 0]))
    >>> Mistake.from_json(m.to_json()) == m
    True
    """

    code: str
    message: str
    answer: Answer

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict (stored in the manifest with the key)."""
        return {"code": self.code, "message": self.message, **self.answer.to_json()}

    @classmethod
    def from_json(cls, data: dict[str, Any]) -> Mistake:
        """Inverse of :meth:`to_json`."""
        return cls(str(data["code"]), str(data["message"]), Answer.from_json(data))


@dataclass(frozen=True)
class Part:
    """One thing to answer: a label such as ``"3"`` or ``"3b"``, a prompt, the answer and, for a
    multiple-choice part, the options (in order A, B, C, …); ``mistakes`` are the common wrong
    answers that ``pgsym check`` recognises."""

    label: str
    prompt: str
    answer: Answer
    choices: tuple[str, ...] = ()
    mistakes: tuple[Mistake, ...] = ()
    points: Fraction = Fraction(1)


@dataclass(frozen=True)
class Exercise:
    """One exercise instance: statement, parts, worked solution and the parameters that produced it."""

    topic: str
    title: str
    level: int
    slot: int
    seed: int
    statement: str
    parts: tuple[Part, ...]
    solution: tuple[str, ...]
    params: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready dict (the manifest entry of this variant)."""
        return {
            "slot": self.slot,
            "topic": self.topic,
            "level": self.level,
            "seed": self.seed,
            "params": self.params,
            "title": self.title,
            "statement": self.statement,
            "solution": list(self.solution),
            "parts": [{"label": p.label, "prompt": p.prompt, "choices": list(p.choices), **p.answer.to_json(),
                       "points": _fraction_text(Fraction(p.points)),
                       **({"mistakes": [m.to_json() for m in p.mistakes]} if p.mistakes else {})}
                      for p in self.parts],
        }

    @property
    def points(self) -> Fraction:
        """The points of the whole exercise: the sum over its parts."""
        return sum((Fraction(p.points) for p in self.parts), Fraction(0))


def variant_id(form: str, slot: int) -> str:
    """The identity of one exercise variant: the form id of its sheet and its slot, e.g. ``F-0A1B2C3D4E#2``.

    It travels with every LMS question (title, question text, STACK question note) so that an answer
    typed in Moodle or Canvas is graded against the variant the student actually saw.

    >>> variant_id("F-0A1B2C3D4E", 2)
    'F-0A1B2C3D4E#2'
    >>> VARIANT_PATTERN.search("[pgsym F-0A1B2C3D4E#2] Join").group(0)
    'F-0A1B2C3D4E#2'
    """
    return f"{form}#{int(slot)}"


#: A variant id inside a longer text (a question title, a question's text or note).
VARIANT_PATTERN = re.compile(r"F-[0-9A-F]{10}#[0-9]{1,3}")


@dataclass(frozen=True)
class Sheet:
    """The exercise sheet of one student (or one anonymous form)."""

    student_id: str
    student_name: str
    form_id: str
    master_seed: int
    exercises: tuple[Exercise, ...]

    @property
    def file_stem(self) -> str:
        """A file-name-safe stem: the student id with anything unusual replaced by ``_``, plus a short
        hash of the id when something was replaced (so ``é1`` and ``ü1`` do not collide).

        >>> Sheet("s-01", "", "F", 0, ()).file_stem, Sheet("é1", "", "F", 0, ()).file_stem
        ('sheet-s-01', 'sheet-_1-31a84a')
        """
        safe = "".join(c if c.isascii() and (c.isalnum() or c in "-_") else "_" for c in self.student_id)[:60]
        if safe != self.student_id:

            safe += "-" + hashlib.blake2b(self.student_id.encode(), digest_size=3).hexdigest()
        return "sheet-" + safe
