"""Points: the one definition of what each part of an exercise is worth.

Every part carries its ``points`` (:attr:`pgsym.exercises.model.Part.points`, 1 by default); the
manifest stores them, and every output reads them from there: the QTI items' ``points_possible``,
the STACK questions' default mark and the value of each potential response tree, the Cloze fields'
weights, the Canvas and Moodle gradebooks and the grade report. A part is graded on its own
(partial credit per part): a right part earns its points, a wrong one none.

Weights come from the command line (``pgsym sheet --points``) or from a template's class attribute
``points`` (a number for every part, or one number per part); the command line wins.

>>> spec = parse_points("join=2, classify=1+3, default=1/2")
>>> spec["join"], spec["classify"]
((Fraction(2, 1),), (Fraction(1, 1), Fraction(3, 1)))
>>> part_points(spec, "classify", 2), part_points(spec, "meet", 1)
((Fraction(1, 1), Fraction(3, 1)), (Fraction(1, 2),))
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import replace
from fractions import Fraction

from .errors import TemplateError
from .model import Sheet
from .registry import get_template

__all__ = ["MAX_POINTS", "apply_points", "parse_points", "part_points", "points_text"]

#: The largest number of points one part may be worth (a typo such as 1000 is refused).
MAX_POINTS = 100


def _number(text: str, where: str) -> Fraction:
    try:
        value = Fraction(text.strip())
    except (ValueError, ZeroDivisionError):
        raise TemplateError(f"{where}: {text.strip()[:40]!r} is not a number of points (e.g. 2 or 1/2)") from None
    if value <= 0 or value > MAX_POINTS:
        raise TemplateError(f"{where}: points must be positive and at most {MAX_POINTS}, not {value}")
    return value


def parse_points(spec: str) -> dict[str, tuple[Fraction, ...]]:
    """Read ``"join=2,classify=1+3,default=1"``: a topic's points for each part (one number for all
    parts, or ``+``-separated numbers, one per part; fractions such as ``1/2`` allowed); ``default``
    applies to the other topics.

    >>> parse_points("decompose=1+2+2")["decompose"]
    (Fraction(1, 1), Fraction(2, 1), Fraction(2, 1))
    >>> parse_points("join")
    Traceback (most recent call last):
    ...
    pgsym.exercises.errors.TemplateError: --points: 'join' should be TOPIC=POINTS, e.g. join=2 or classify=1+3
    """
    out: dict[str, tuple[Fraction, ...]] = {}
    for item in (i.strip() for i in spec.split(",")):
        if not item:
            continue
        topic, sep, value = item.partition("=")
        if not sep or not topic.strip() or not value.strip():
            raise TemplateError(f"--points: {item[:40]!r} should be TOPIC=POINTS, e.g. join=2 or classify=1+3")
        out[topic.strip()] = tuple(_number(v, f"--points {topic.strip()}") for v in value.split("+"))
    return out


def part_points(spec: Mapping[str, Sequence[Fraction]], topic: str, parts: int,
                declared: Sequence[Fraction] | Fraction | int | None = None) -> tuple[Fraction, ...]:
    """The points of the ``parts`` parts of ``topic``: from ``spec`` (the command line), else from the
    template's ``declared`` points, else ``spec["default"]``, else 1 each.

    >>> part_points({}, "join", 1, declared=3)
    (Fraction(3, 1),)
    """
    chosen: Sequence[Fraction] | None = spec.get(topic)
    if chosen is None and declared is not None:
        chosen = (Fraction(declared),) if isinstance(declared, (int, Fraction)) else tuple(map(Fraction, declared))
    if chosen is None:
        chosen = spec.get("default", (Fraction(1),))
    if len(chosen) == 1:
        return tuple(chosen) * parts
    if len(chosen) != parts:
        raise TemplateError(f"points of {topic!r}: {len(chosen)} numbers given for {parts} parts; give one number "
                            "for every part, or one per part")
    return tuple(chosen)


def apply_points(sheets: Iterable[Sheet], spec: Mapping[str, Sequence[Fraction]] | None = None) -> list[Sheet]:
    """The sheets with the points of every part set (see :func:`part_points`)."""

    spec = spec or {}
    out = []
    for sheet in sheets:
        exercises = []
        for ex in sheet.exercises:
            declared = getattr(get_template(ex.topic), "points", None)  # an optional template attribute
            values = part_points(spec, ex.topic, len(ex.parts), declared)
            exercises.append(replace(ex, parts=tuple(replace(p, points=v) for p, v in zip(ex.parts, values,
                                                                                        strict=True))))
        out.append(replace(sheet, exercises=tuple(exercises)))
    return out


def points_text(value: Fraction | int) -> str:
    """Points as a short decimal text for LMS files (``2``, ``0.5``, ``0.3333333``).

    >>> points_text(Fraction(3, 2)), points_text(Fraction(1, 3)), points_text(2)
    ('1.5', '0.3333333', '2')
    """
    value = Fraction(value)
    if value.denominator == 1:
        return str(value.numerator)
    return f"{float(value):.7f}".rstrip("0")
