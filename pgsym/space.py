"""Points and planes of projective 3-space P³, exactly.

A point ``X = (x1, x2, x3, x4)`` and a plane ``π = (a, b, c, d)`` are both
homogeneous 4-vectors; the point lies on the plane when
``πᵀX = a x1 + b x2 + c x3 + d x4 = 0``. Points with ``x4 = 0`` are ideal (at
infinity): they all lie on the plane at infinity ``π∞ = (0, 0, 0, 1)``.

Three points in general position span a plane, and three planes in general
position meet in a point. Both constructions are the same computation: the
null space of a 3×4 matrix of rank 3, here obtained exactly from its four 3×3
minors with alternating signs (the 4D analogue of the cross product).

>>> from pgsym.space import Point3, Plane, plane_through, point_on_planes
>>> plane_through(Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1))
Plane(1, 1, 1, -1)
>>> point_on_planes(Plane(1, 0, 0, -1), Plane(0, 1, 0, -2), Plane(0, 0, 1, -3)).dehomogenize()
(1, 2, 3)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any, TypeVar

import sympy
from sympy import Expr

from . import ring
from .errors import (
    CollinearPointsError,
    DependentPlanesError,
    DimensionError,
    ObjectTypeError,
)
from .homogeneous import HomogeneousHyperplane, HomogeneousPoint, HomogeneousVector, incidence, is_zero, require

__all__ = [
    "Plane",
    "Point3",
    "coplanar",
    "dual",
    "incident",
    "plane_at_infinity",
    "plane_through",
    "point_on_planes",
    "triple_cross",
]

_H = TypeVar("_H", bound=HomogeneousVector)


def triple_cross(u: Sequence[Expr], v: Sequence[Expr], w: Sequence[Expr]) -> tuple[Expr, Expr, Expr, Expr]:
    """The vector ``n`` with ``n·x = det[x; u; v; w]`` for every 4-vector ``x``, expanded exactly.

    Its entries are the 3×3 minors of the 3×4 matrix ``[u; v; w]`` with
    alternating signs: ``n_i = (-1)^i det(M without column i)`` (``i`` from 0).
    So ``n`` is orthogonal to ``u``, ``v`` and ``w``; it spans the null space of
    the matrix when the rank is 3, and it is the zero vector when the rank is
    smaller.

    >>> triple_cross((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0))
    (0, 0, 0, -1)
    """
    rows = [[sympy.sympify(c) for c in r] for r in (u, v, w)]
    for r in rows:
        if len(r) != 4:
            raise DimensionError(f"triple_cross takes three 4-vectors, got one of length {len(r)}: {tuple(r)}")
    return tuple(sympy.expand(e) for e in ring.plane_through(*rows))  # type: ignore[return-value]


class Point3(HomogeneousPoint, kind="point3"):
    """A point of projective 3-space.

    ``Point3(x, y, z)`` is the Euclidean point ``(x, y, z)``, stored as
    ``(x, y, z, 1)``; ``Point3(x1, x2, x3, x4)`` gives homogeneous coordinates
    directly, and ``x4 = 0`` makes an ideal point (a direction). Points are
    printed as column vectors.

    >>> Point3(1, 2, 3)
    Point3(1, 2, 3, 1)
    >>> Point3(2, 4, 6, 2) == Point3(1, 2, 3)
    True
    >>> Point3(1, 0, 0, 0).is_ideal
    True
    """

    size = 4
    _kind = "point of P³"
    _inhomogeneous = "(x, y, z)"
    ambient_dim = 3
    __slots__ = ()

    def lies_on(self, plane: Plane) -> bool:
        """True when the point lies on ``plane`` (``πᵀX = 0`` identically).

        >>> Point3(1, 1, 1).lies_on(Plane(1, 1, 1, -3))
        True
        """
        return incident(self, plane)

    def dual(self) -> Plane:
        """The plane with the same homogeneous coordinates.

        >>> Point3(1, 2, 3).dual()
        Plane(1, 2, 3, 1)
        """
        return Plane._from_exact(self._coords)


class Plane(HomogeneousHyperplane, kind="plane"):
    """A plane ``a x + b y + c z + d w = 0`` of projective 3-space, given by ``(a, b, c, d)``.

    Planes are printed as row vectors, so that ``πᵀX`` reads as a row times a column.

    >>> pi = Plane(0, 0, 1, -2)        # the plane z = 2
    >>> pi.contains(Point3(5, -1, 2)), pi.normal
    (True, (0, 0, 1))
    """

    size = 4
    _kind = "plane of P³"
    ambient_dim = 3
    __slots__ = ()

    def contains(self, point: Point3) -> bool:
        """True when ``point`` lies on the plane.

        >>> Plane(1, 1, 1, -1).contains(Point3(0, 0, 1))
        True
        """
        return incident(point, self)

    def dual(self) -> Point3:
        """The point with the same homogeneous coordinates.

        >>> Plane(0, 0, 0, 1).dual()
        Point3(0, 0, 0, 1)
        """
        return Point3._from_exact(self._coords)




def incident(point: Point3, plane: Plane) -> bool:
    """True when ``point`` lies on ``plane``: ``πᵀX = 0`` (identically, for symbols).

    The arguments may come in either order, since incidence is symmetric.

    >>> incident(Point3(1, 2, 3), Plane(1, 1, 1, -6)), incident(Plane(1, 1, 1, -6), Point3(0, 0, 0))
    (True, False)
    """
    return incidence(point, plane, Point3, Plane)


def _coincident_pair(objs: Sequence[HomogeneousVector]) -> tuple[int, int] | None:
    for i in range(len(objs)):
        for j in range(i + 1, len(objs)):
            if objs[i].is_proportional(objs[j]):
                return i, j
    return None


def _incident_with_three(
    cls: type[_H], objs: tuple[HomogeneousVector, ...], error: type[Exception], message: Callable[[Any], str]
) -> _H:
    """The plane through three points, or the point on three planes: their triple cross product.

    It vanishes exactly when the three have rank < 3; ``message`` gets the first coincident pair (or None).
    """
    coords = triple_cross(*(o.coords for o in objs))
    return cls._from_nonzero(coords, error, lambda: message(_coincident_pair(objs)))


def plane_through(p: Point3, q: Point3, r: Point3) -> Plane:
    """The plane through three points that do not lie on one line.

    The plane ``π`` solves ``[pᵀ; qᵀ; rᵀ] π = 0``, a 3×4 homogeneous system; its
    solution is computed exactly by :func:`triple_cross` (the signed 3×3 minors),
    so that ``π·X = det[X; p; q; r]``. When the matrix has rank < 3 the points
    are collinear and every plane through their line contains them: this raises
    :class:`CollinearPointsError`. Two coincident points are a special case of
    this and raise the same error (the message names the coincident pair).

    >>> plane_through(Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0))   # the plane z = 0
    Plane(0, 0, 1, 0)
    >>> plane_through(Point3(0, 0, 0), Point3(1, 1, 1), Point3(2, 2, 2))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.CollinearPointsError: cannot find the plane through ... lie on one line...
    """
    for x in (p, q, r):
        require(x, Point3, "plane_through", "; use point_on_planes() for three planes")
    return _incident_with_three(Plane, (p, q, r), CollinearPointsError, lambda pair: (
        f"cannot find the plane through {p!r}, {q!r}, {r!r}: they lie on one line"
        + (f" (points {pair[0] + 1} and {pair[1] + 1} coincide)" if pair else "")
        + ", so the 3×4 matrix has rank < 3 and a whole pencil of planes contains them; choose a point off that line"))


def point_on_planes(a: Plane, b: Plane, c: Plane) -> Point3:
    """The point where three planes meet, when they meet in exactly one point.

    The dual of :func:`plane_through`: the point ``X`` solves ``[aᵀ; bᵀ; cᵀ] X = 0``.
    The point may be ideal: three planes two of which are parallel but
    distinct still meet, in a point at infinity. When the matrix has rank < 3 —
    the three planes share a line (a pencil), or two of them are the same plane
    — there is no single common point and :class:`DependentPlanesError` is
    raised.

    >>> point_on_planes(Plane(1, 0, 0, 0), Plane(0, 1, 0, 0), Plane(0, 0, 1, -1))
    Point3(0, 0, -1, -1)
    >>> point_on_planes(Plane(0, 0, 1, 0), Plane(0, 0, 1, -1), Plane(1, 0, 0, 0))  # z=0 ∥ z=1: ideal point
    Point3(0, 1, 0, 0)
    """
    for x in (a, b, c):
        require(x, Plane, "point_on_planes", "; use plane_through() for three points")
    return _incident_with_three(Point3, (a, b, c), DependentPlanesError, lambda pair: (
        f"the planes {a!r}, {b!r}, {c!r} do not meet in a single point: "
        + (f"planes {pair[0] + 1} and {pair[1] + 1} are the same plane" if pair else "they share a line")
        + ", so the 3×4 matrix has rank < 3; replace one plane by a plane not through their common line"))


def coplanar(p: Point3, q: Point3, r: Point3, s: Point3) -> bool:
    """True when four points lie on one plane: ``det[p q r s] = 0``.

    >>> coplanar(Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(3, 4, 0))
    True
    >>> coplanar(Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1))
    False
    """
    for x in (p, q, r, s):
        require(x, Point3, "coplanar", "")
    det = ring.det([x.coords for x in (p, q, r, s)])
    return is_zero(sympy.expand(det))


def dual(obj: Point3 | Plane) -> Plane | Point3:
    """The dual object: a point becomes the plane with the same coordinates, and vice versa.

    Incidence is preserved: ``X`` lies on ``π`` exactly when ``dual(π)`` lies on ``dual(X)``.

    >>> dual(Point3(1, 2, 3, 4))
    Plane(1, 2, 3, 4)
    """
    if not isinstance(obj, (Point3, Plane)):
        raise ObjectTypeError(f"dual expects a Point3 or a Plane, got {type(obj).__name__} {obj!r}")
    return obj.dual()


def plane_at_infinity() -> Plane:
    """The plane at infinity ``π∞ = (0, 0, 0, 1)``, on which every ideal point lies.

    >>> plane_at_infinity().contains(Point3(3, -1, 2, 0))
    True
    """
    return Plane(0, 0, 0, 1)
