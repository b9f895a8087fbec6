"""Points and lines of the projective plane P², exactly.

A point ``x = (x1, x2, x3)`` and a line ``l = (a, b, c)`` are both homogeneous
3-vectors; the point lies on the line when ``lᵀx = a x1 + b x2 + c x3 = 0``.
The line through two points is their cross product, and so is the point where
two lines meet. Points with ``x3 = 0`` are ideal (at infinity); they all lie on
the line at infinity ``(0, 0, 1)``.

>>> from pgsym import Point, Line, join, meet
>>> l = join(Point(0, 0), Point(1, 1))
>>> l
Line(-1, 1, 0)
>>> meet(l, Line(1, 0, -2))
Point(-2, -2, -1)
>>> meet(Line(1, -1, 0), Line(1, -1, 3))   # parallel lines meet at infinity
Point(-3, -3, 0)
"""

from __future__ import annotations

from collections.abc import Sequence

import sympy
from sympy import Expr, Integer

from . import ring
from .errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    DegenerateConfigurationError,
    ObjectTypeError,
)
from .homogeneous import (
    HomogeneousHyperplane,
    HomogeneousPoint,
    HomogeneousVector,
    Scalar,
    incidence,
    is_zero,
    require,
    to_exact,
)

__all__ = [
    "Line",
    "Point",
    "collinear",
    "concurrent",
    "cross",
    "dual",
    "ideal_point",
    "incident",
    "join",
    "line_at_infinity",
    "meet",
]


def cross(u: Sequence[Expr], v: Sequence[Expr]) -> tuple[Expr, Expr, Expr]:
    """The cross product of two 3-vectors, expanded exactly.

    >>> cross((1, 0, 0), (0, 1, 0))
    (0, 0, 1)
    """
    u1, u2, u3 = (sympy.sympify(c) for c in u)
    v1, v2, v3 = (sympy.sympify(c) for c in v)
    return tuple(sympy.expand(e) for e in ring.cross((u1, u2, u3), (v1, v2, v3)))  # type: ignore[return-value]


class Point(HomogeneousPoint, kind="point"):
    """A point of the projective plane.

    ``Point(x, y)`` is the Euclidean point ``(x, y)``, stored as ``(x, y, 1)``;
    ``Point(x1, x2, x3)`` gives homogeneous coordinates directly, and ``x3 = 0``
    makes an ideal point. Points are printed as column vectors.

    >>> Point(3, 4)
    Point(3, 4, 1)
    >>> Point(6, 8, 2) == Point(3, 4)
    True
    >>> Point(1, 2, 0).is_ideal
    True
    """

    size = 3
    _kind = "point of P²"
    ambient_dim = 2
    __slots__ = ()

    def lies_on(self, line: Line) -> bool:
        """True when the point lies on ``line`` (``lᵀx = 0`` identically)."""
        return incident(self, line)

    def join(self, other: Point) -> Line:
        """The line through this point and ``other`` (see :func:`join`)."""
        return join(self, other)

    def dual(self) -> Line:
        """The line with the same homogeneous coordinates."""
        return Line._from_exact(self._coords)


class Line(HomogeneousHyperplane, kind="line"):
    """A line ``a x + b y + c w = 0`` of the projective plane, given by ``(a, b, c)``.

    Lines are printed as row vectors, so that ``lᵀ x`` reads as a row times a column.

    >>> l = Line(1, 2, -5)
    >>> Point(1, 2).lies_on(l)
    True
    >>> l.direction
    Point(2, -1, 0)
    """

    size = 3
    _kind = "line of P²"
    ambient_dim = 2
    __slots__ = ()

    @property
    def direction(self) -> Point:
        """The ideal point of the line: where it meets the line at infinity, ``(b, -a, 0)``."""
        if self.is_at_infinity:
            raise DegenerateConfigurationError(
                "the line at infinity has no single direction: every ideal point lies on it"
            )
        a, b, _ = self._coords
        return Point._from_exact((b, -a, Integer(0)))

    def contains(self, point: Point) -> bool:
        """True when ``point`` lies on the line."""
        return incident(point, self)

    def meet(self, other: Line) -> Point:
        """The point where this line meets ``other`` (see :func:`meet`)."""
        return meet(self, other)

    def dual(self) -> Point:
        """The point with the same homogeneous coordinates."""
        return Point._from_exact(self._coords)




def join(p: Point, q: Point) -> Line:
    """The line through two distinct points: ``l = p × q``.

    Raises :class:`CoincidentPointsError` when ``p`` and ``q`` are the same
    projective point, since infinitely many lines pass through one point.

    >>> join(Point(1, 0), Point(0, 1))
    Line(-1, -1, 1)
    """
    require(p, Point, "join", "; use meet() for two lines")
    require(q, Point, "join", "; use meet() for two lines")
    return Line._from_nonzero(cross(p.coords, q.coords), CoincidentPointsError, lambda: (
        f"cannot join {p!r} and {q!r}: they are the same point, so no unique line passes through them"))


def meet(l: Line, m: Line) -> Point:
    """The point where two distinct lines meet: ``x = l × m``.

    Parallel lines meet in an ideal point; the same line twice raises
    :class:`CoincidentLinesError`.

    >>> meet(Line(1, 0, -1), Line(0, 1, -2))
    Point(1, 2, 1)
    """
    require(l, Line, "meet", "; use join() for two points")
    require(m, Line, "meet", "; use join() for two points")
    return Point._from_nonzero(cross(l.coords, m.coords), CoincidentLinesError, lambda: (
        f"cannot meet {l!r} and {m!r}: they are the same line, so they share every point"))


def incident(point: Point, line: Line) -> bool:
    """True when ``point`` lies on ``line``: ``lᵀx = 0`` (identically, for symbols).

    The arguments may come in either order, since incidence is symmetric.

    >>> incident(Point(1, 1), Line(1, -1, 0)), incident(Line(1, -1, 0), Point(1, 2))
    (True, False)
    """
    return incidence(point, line, Point, Line)


def _det3(rows: Sequence[HomogeneousVector]) -> Expr:
    return sympy.expand(ring.det([r.coords for r in rows]))


def collinear(p: Point, q: Point, r: Point) -> bool:
    """True when three points lie on one line: ``det[p q r] = 0``.

    >>> collinear(Point(0, 0), Point(1, 1), Point(5, 5)), collinear(Point(0, 0), Point(1, 1), Point(1, 0))
    (True, False)
    """
    for x in (p, q, r):
        require(x, Point, "collinear", "; use concurrent() for lines")
    return is_zero(_det3((p, q, r)))


def concurrent(l: Line, m: Line, n: Line) -> bool:
    """True when three lines pass through one point (possibly ideal): ``det[l m n] = 0``.

    >>> concurrent(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, 0))
    True
    """
    for x in (l, m, n):
        require(x, Line, "concurrent", "; use collinear() for points")
    return is_zero(_det3((l, m, n)))


def dual(obj: Point | Line) -> Line | Point:
    """The dual object: a point becomes the line with the same coordinates, and vice versa.

    Incidence is preserved: ``x`` lies on ``l`` exactly when ``dual(l)`` lies on ``dual(x)``.

    >>> dual(Point(1, 2, 3))
    Line(1, 2, 3)
    """
    if not isinstance(obj, (Point, Line)):
        raise ObjectTypeError(f"dual expects a Point or a Line, got {type(obj).__name__} {obj!r}")
    return obj.dual()


def line_at_infinity() -> Line:
    """The line at infinity ``l∞ = (0, 0, 1)``, on which every ideal point lies.

    >>> line_at_infinity().contains(Point(3, -1, 0))
    True
    """
    return Line(0, 0, 1)


def ideal_point(dx: Scalar, dy: Scalar) -> Point:
    """The ideal point in direction ``(dx, dy)``: ``(dx, dy, 0)``.

    >>> ideal_point(1, 2) == Line(2, -1, 7).direction
    True
    """
    return Point(to_exact(dx), to_exact(dy), 0)
