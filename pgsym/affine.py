"""Affine geometry read off the line (plane) at infinity: parallels and midpoints, exactly.

Affine geometry is projective geometry with one fixed hyperplane, ``l∞ = (0, 0, 1)`` in the plane
and ``π∞ = (0, 0, 0, 1)`` in space (Hartley & Zisserman §2.4.2, §3.4.1). Two lines are parallel when
they meet on ``l∞``; the parallel to a line through a point joins the point with the line's ideal
point; the midpoint of ``A`` and ``B`` is the harmonic conjugate of their ideal point with respect
to them. Everything here is a formula in homogeneous coordinates, right for any representative
(``(2, 4, 2)`` and ``(1, 2, 1)`` are the same point and have the same midpoint with ``(3, 0, 1)``).

Ideal input where a finite object is needed raises :class:`~pgsym.errors.IdealPointError`: the
midpoint of an ideal point, the parallel to ``l∞``.

>>> from pgsym import Line, Point
>>> parallel_line(Line(1, 1, 0), Point(2, 0))           # x + y = 0 moved through (2, 0): x + y − 2 = 0
Line(1, 1, -2)
>>> is_parallel(Line(1, 1, 0), Line(2, 2, 5)), is_parallel(Line(1, 1, 0), Line(1, -1, 0))
(True, False)
>>> midpoint(Point(2, 4, 2), Point(3, 0)).dehomogenize()   # (1, 2) and (3, 0) → (2, 1)
(2, 1)
"""

from __future__ import annotations

from .errors import IdealPointError, ObjectTypeError
from .homogeneous import HomogeneousPoint
from .matrices import proportional
from .plucker import Line3
from .projective_plane import Line, Point, join, line_at_infinity, meet
from .space import Plane, Point3

__all__ = ["is_parallel", "midpoint", "parallel_line"]


def _finite(p: HomogeneousPoint, what: str) -> None:
    if p.is_ideal:
        raise IdealPointError(f"{what} needs finite points; {p!r} is an ideal point")


def _finite_direction(obj: Line | Plane) -> None:
    if obj.is_at_infinity:
        raise IdealPointError(f"{obj!r} lies at infinity and has no direction to be parallel to")


def parallel_line(target: Line | Line3 | Plane, point: Point | Point3) -> Line | Line3 | Plane:
    """The line (plane) through ``point`` parallel to ``target``.

    In the plane: the join of ``point`` with the ideal point ``target ∧ l∞``. A line of space: the
    join of ``point`` with the line's ideal point. A plane: the plane through ``point`` with the same
    normal, ``(n, −n·x/w)``. When ``point`` is ideal the answer is still a line (a plane) through it:
    the parallel through an ideal point of the plane is ``l∞`` unless the point is the target's own
    direction, which gives no unique line (:class:`~pgsym.errors.CoincidentPointsError`).

    >>> from pgsym import Line3, Plane, Point3
    >>> parallel_line(Plane(1, 2, 2, 7), Point3(1, 0, 0))         # x + 2y + 2z = 1
    Plane(1, 2, 2, -1)
    >>> parallel_line(Line3.join(Point3(0, 0, 0), Point3(1, 1, 1)), Point3(1, 0, 0)) == Line3.join(
    ...     Point3(1, 0, 0), Point3(2, 1, 1))
    True
    """
    if isinstance(target, Line) and isinstance(point, Point):
        _finite_direction(target)
        return join(point, meet(target, line_at_infinity()))
    if isinstance(target, Plane) and isinstance(point, Point3):
        _finite_direction(target)
        *n, _ = target.coords
        *x, w = point.coords
        return Plane(*(c * w for c in n), -sum(a * b for a, b in zip(n, x, strict=True)))
    if isinstance(target, Line3) and isinstance(point, Point3):
        if target.is_at_infinity:
            raise IdealPointError(f"{target!r} lies at infinity and has no direction to be parallel to")
        return Line3.join(point, target.direction)
    raise ObjectTypeError(
        f"parallel_line takes a Line and a Point, or a Line3 or Plane and a Point3; got "
        f"{type(target).__name__} and {type(point).__name__}"
    )


def is_parallel(a: Line | Line3 | Plane, b: Line | Line3 | Plane) -> bool:
    """True when ``a`` and ``b`` meet at infinity (or coincide): lines of P², lines of P³ or planes.

    Two lines of the plane are parallel when their normals are proportional (their meet lies on
    ``l∞``); lines of space when their directions are; planes when their normals are. An object at
    infinity has no direction and raises :class:`~pgsym.errors.IdealPointError`.

    >>> from pgsym import Plane
    >>> is_parallel(Plane(1, 2, 3, 4), Plane(-2, -4, -6, 0)), is_parallel(Plane(1, 0, 0, 0), Plane(0, 1, 0, 0))
    (True, False)
    """
    if type(a) is not type(b) or not isinstance(a, Line | Line3 | Plane):
        raise ObjectTypeError(
            f"is_parallel takes two lines of the plane, two lines of space or two planes; got "
            f"{type(a).__name__} and {type(b).__name__}"
        )
    if isinstance(a, Line3):
        if a.is_at_infinity or b.is_at_infinity:
            raise IdealPointError("a line at infinity has no direction to compare")
        return proportional(a.direction.coords[:3], b.direction.coords[:3])
    _finite_direction(a)
    _finite_direction(b)
    return proportional(a.normal, b.normal)


def midpoint(a: Point | Point3, b: Point | Point3) -> Point | Point3:
    """The midpoint of two finite points, right for any homogeneous representatives.

    With ``a = (x, w)`` and ``b = (y, v)`` the midpoint is ``(x/w + y/v)/2``, i.e. the homogeneous
    vector ``v·x + w·y`` over ``2·v·w`` — no division, so it is exact and polynomial. It is the
    harmonic conjugate of the ideal point of the line ``ab`` with respect to ``a`` and ``b``.

    >>> from pgsym import Point3
    >>> midpoint(Point3(0, 0, 0), Point3(2, 4, 6, 2)).dehomogenize()
    (1/2, 1, 3/2)
    """
    if type(a) is not type(b) or not isinstance(a, Point | Point3):
        raise ObjectTypeError(f"midpoint takes two points of the same space; got {type(a).__name__} and "
                              f"{type(b).__name__}")
    _finite(a, "a midpoint")
    _finite(b, "a midpoint")
    *x, w = a.coords
    *y, v = b.coords
    return type(a)(*(v * xi + w * yi for xi, yi in zip(x, y, strict=True)), 2 * v * w)
