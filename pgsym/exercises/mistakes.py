"""Common wrong answers, recognised so that ``pgsym check`` can say *which* mistake a student made.

At sheet time every template proposes, for each part, the wrong answers its students typically
give (:meth:`pgsym.exercises.template.Template.mistakes`; the defaults here come from the answer's
kind); :func:`admissible` keeps only the candidates that are really wrong and distinct, and the
manifest stores them with the key. ``pgsym check`` then compares a wrong answer with the candidates
using the same equivalence as grading (:func:`recognise`), so it needs no templates.

>>> key = Answer.projective([1, -2, 0])  # an ideal point
>>> found = admissible(key, default_mistakes(key))
>>> [(m.code, m.answer.display()) for m in found]
[('sign', '(1, 2, 0)'), ('ideal-as-finite', '(1, -2, 1)'), ('ideal-as-finite', '(1, -2, -1)')]
>>> recognise(key, found, (Fraction(2), Fraction(-4), Fraction(2))).code
'ideal-as-finite'
>>> recognise(key, found, (Fraction(-1), Fraction(2), Fraction(0))) is None  # right: never a mistake
True
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from fractions import Fraction
from typing import Any

from ..ring import adjugate, det, transpose
from .answers import matches
from .model import Answer, Mistake

__all__ = ["MISTAKE_CLASSES", "Mistake", "admissible", "default_mistakes", "mistake", "recognise"]

#: The mistake classes pgsym knows, with the feedback a student gets; templates may add their own codes.
MISTAKE_CLASSES: dict[str, str] = {
    "dual": "the dual object: a point where a line (or plane) was asked, or the other way round",
    "sign": "a sign lost in one coordinate",
    "transposed": "the matrix transposed",
    "inverted": "the inverse matrix: the map taken in the wrong direction",
    "line-as-point": "H applied to a line as to a point; lines map by H⁻ᵀ",
    "ideal-as-finite": "an ideal point given as a finite one (last coordinate 1 instead of 0)",
    "scale": "right only up to a scale, but here the exact value is asked",
    "order": "the points taken in another order",
}

#: Candidates per part kept at most (a bound on the manifest, whatever a template proposes).
MAX_MISTAKES = 24


def mistake(code: str, answer: Answer, message: str | None = None) -> Mistake:
    """A :class:`Mistake` with the standard feedback of ``code`` unless ``message`` is given.

    >>> mistake("transposed", Answer.matrix([[1, 2], [0, 1]])).message
    'the matrix transposed'
    """
    return Mistake(code, message or MISTAKE_CLASSES.get(code, code), answer)


def default_mistakes(key: Answer) -> list[Mistake]:
    """The generic candidates of an answer kind: a sign lost in one coordinate, an ideal point given
    as finite (projective vectors ending in 0), a transposed or inverted matrix, a nonzero multiple where
    the exact value is asked (exact vectors and matrices).

    >>> [m.answer.display() for m in default_mistakes(Answer.vector([Fraction(1, 2), 3]))]
    ['(-1/2, 3)', '(1/2, -3)', '(1, 6)']
    """
    out: list[Mistake] = []
    if key.kind in ("projective", "vector"):
        values = list(key.value)  # integers for a projective key: canonical forms take the fast path
        make = Answer.projective if key.kind == "projective" else Answer.vector
        for i, v in enumerate(values):
            if v != 0:
                flipped = [-w if j == i else w for j, w in enumerate(values)]
                out.append(mistake("sign", make(flipped), f"a sign lost in coordinate {i + 1}"))
        if key.kind == "projective" and len(values) in (3, 4) and values[-1] == 0 and any(values[:-1]):
            # the direction, of either sign, with a 1 appended: (v, 1) and (-v, 1) ~ (v, -1)
            for last in (1, -1):
                out.append(mistake("ideal-as-finite", Answer.projective([*values[:-1], last])))
        if key.kind == "vector" and len(values) >= 2 and any(values):
            # a projective candidate stands for every multiple; the key itself is graded right first
            out.append(mistake("scale", Answer.projective(values), "a multiple of the right vector; here the "
                               "exact coordinates are asked (divide by the last homogeneous coordinate)"))
    elif key.kind == "scalar" and key.value != 0:
        out.append(mistake("sign", Answer.scalar(-key.value), "the sign is wrong"))
    elif key.kind in ("matrix", "matrix_exact"):
        rows = [[Fraction(x) for x in row] for row in key.value]
        make = Answer.matrix if key.kind == "matrix" else Answer.matrix_exact
        out.append(mistake("transposed", make(transpose(rows))))
        if len(rows) == len(rows[0]) and det(rows) != 0:
            d = det(rows)  # the inverse; up to scale the adjugate is enough
            inverse = [[x / d for x in row] for row in adjugate(rows)]
            out.append(mistake("inverted", make(inverse)))
        if key.kind == "matrix_exact" and any(x for row in rows for x in row):
            out.append(mistake("scale", Answer.matrix(rows), "a multiple of the right matrix; here the exact "
                               "matrix is asked (check its normalisation)"))
    return out


def _shape(answer: Answer) -> tuple[int, ...]:
    if answer.kind in ("projective", "vector"):
        return (len(answer.value),)
    if answer.kind in ("matrix", "matrix_exact"):
        # every row counts: a ragged matrix (from a damaged manifest) fits no key
        return (len(answer.value), *sorted({len(row) for row in answer.value}))
    return ()


# the kinds a candidate may have for a key of each kind: the same, or the up-to-scale one ("scale")
_COMPATIBLE = {"projective": ("projective",), "vector": ("vector", "projective"), "scalar": ("scalar",),
               "integer": ("integer",), "matrix": ("matrix",), "matrix_exact": ("matrix_exact", "matrix"),
               "choice": ("choice",)}


def _stands_for_many(key: Answer, candidate: Answer) -> bool:
    return candidate.kind != key.kind  # an up-to-scale candidate of an exact key


def admissible(key: Answer, candidates: Iterable[Mistake]) -> list[Mistake]:
    """The candidates worth storing: of a compatible kind and shape, really wrong (a candidate of the
    key's kind that grades right is dropped, e.g. a sign "lost" in a zero coordinate), and not a
    repeat of an earlier one (the first wins). At most :data:`MAX_MISTAKES`.

    >>> key = Answer.projective([0, 1, 0])  # negating its only nonzero entry gives the same point
    >>> admissible(key, default_mistakes(key))[0].code
    'ideal-as-finite'
    """
    kept: list[Mistake] = []
    seen: set[tuple[str, Any]] = set()
    for m in candidates:
        if not isinstance(m, Mistake) or m.answer.kind not in _COMPATIBLE.get(key.kind, ()):
            continue
        if _shape(m.answer) != _shape(key):
            continue
        if not _stands_for_many(key, m.answer) and matches(key, m.answer.value):
            continue  # equivalent to the right answer: never store it
        ident = (m.answer.kind, m.answer.value)
        if ident in seen:
            continue
        seen.add(ident)
        kept.append(m)
        if len(kept) == MAX_MISTAKES:
            break
    return kept


def recognise(key: Answer, candidates: Sequence[Mistake], value: Any) -> Mistake | None:
    """The first candidate a value (already read as the key's kind) matches, or None; a right answer
    is never a mistake. A concrete wrong answer is preferred to one standing for every multiple of the
    key (it says more); candidates that do not fit the key (a damaged manifest) are skipped."""
    if matches(key, value):
        return None
    concrete = [m for m in candidates if m.answer.kind == key.kind]
    for m in [*concrete, *(m for m in candidates if m.answer.kind != key.kind)]:
        if m.answer.kind not in _COMPATIBLE.get(key.kind, ()) or _shape(m.answer) != _shape(key):
            continue
        try:
            if matches(m.answer, value):
                return m
        except (ValueError, TypeError, IndexError, ArithmeticError):
            continue
    return None
