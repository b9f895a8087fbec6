"""Euclidean geometry read off the absolute: angles, perpendiculars, distances and similarities, exactly.

Projective geometry has no angles and no distances; Euclidean geometry is projective geometry
together with a fixed object at infinity, *the absolute* (Hartley & Zisserman, ch. 2–3;
Richter-Gebert, *Perspectives on Projective Geometry*, ch. 18):

* in the plane, the circular points ``I = (1, i, 0)``, ``J = (1, −i, 0)`` and their dual conic
  ``C*∞ = diag(1, 1, 0)`` (:func:`pgsym.conics.dual_conic_at_infinity`);
* in space, the absolute conic ``Ω∞``: ``x² + y² + z² = 0`` on the plane at infinity, and the
  absolute dual quadric ``Q*∞ = diag(1, 1, 1, 0)`` (:func:`absolute_dual_quadric`).

Every metric notion here is a formula in these objects. Two lines ``l``, ``m`` make the angle θ with

    cos θ = lᵀC*∞m / √((lᵀC*∞l)(mᵀC*∞m)),

they are perpendicular when they are conjugate (``lᵀC*∞m = 0``), and Laguerre's formula
``θ = (1/2i) log cr(l, m; p∨I, p∨J)`` (``p`` where the lines meet) says the same through the
circular points: :func:`laguerre_cross_ratio` returns the cross-ratio ``e^{2iθ}``. Lines and planes of
space use the same form on their directions (conjugate w.r.t. ``Ω∞``) and normals (``Q*∞``).

Results are exact: squared distances and squared cosines are rational for rational data, the plain
values are algebraic numbers (SymPy ``sqrt``). A homogeneous line ``(a, b, c)`` and ``(−a, −b, −c)``
are the same line but have opposite normals, so :func:`cos_angle` and :func:`sin_angle` describe the
*oriented* representatives given; :func:`cos_squared_angle` does not depend on them.

**Ideal elements.** Distances, angles and feet of perpendiculars need finite points and
lines with a direction. An ideal point, the line at infinity, the plane at infinity or a line of
space at infinity raises :class:`~pgsym.errors.IdealPointError` (never a NaN or ``zoo``).

>>> from pgsym.projective_plane import Point, Line
>>> l, m = Line(0, 1, 0), Line(1, -1, 0)            # y = 0 and y = x
>>> cos_angle(l, m), cos_squared_angle(l, m)        # lᵀC*∞m = −1, lᵀC*∞l = 1, mᵀC*∞m = 2
(-sqrt(2)/2, 1/2)
>>> distance(Point(3, 4), Point(0, 0)), squared_distance(Point(0, 0), Line(1, 1, -2))
(5, 2)
>>> reflection(Line(1, -1, 0))(Point(2, 5)).dehomogenize()    # the mirror y = x swaps the coordinates
(5, 2)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy
from sympy import Expr, ImmutableMatrix, Integer

from .conics import circular_points, dual_conic_at_infinity
from .errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    DegenerateConfigurationError,
    DimensionError,
    IdealPointError,
    InvalidCoordinatesError,
    ObjectTypeError,
)
from .exact import Scalar, all_zero, is_zero, to_exact
from .plucker import Line3
from .projective_line import cross_ratio_lines
from .projective_plane import Line, Point, collinear, join, meet
from .ring import cross, dot, matvec
from .space import Plane, Point3
from .transformations import Transformation

__all__ = [
    "absolute_dual_quadric",
    "angle_bisectors",
    "common_perpendicular",
    "cos_angle",
    "cos_squared_angle",
    "distance",
    "is_concyclic",
    "is_perpendicular",
    "laguerre_cross_ratio",
    "orthogonal_projection",
    "perpendicular_line",
    "perpendicular_plane",
    "point_distance",
    "point_line_distance",
    "point_plane_distance",
    "reflect",
    "reflection",
    "rotation",
    "scaling",
    "signed_angle",
    "sin_angle",
    "squared_distance",
    "translation",
]


def absolute_dual_quadric() -> ImmutableMatrix:
    """The absolute dual quadric ``Q*∞ = diag(1, 1, 1, 0)``: planes ``π``, ``σ`` are perpendicular iff ``πᵀQ*∞σ = 0``.

    Its dual is the absolute conic ``Ω∞`` on the plane at infinity, the identity form on directions.
    This is the matrix the formulas here use; the same object as a
    :class:`~pgsym.quadrics.DualQuadric` (which knows how it transforms, ``Q*' = H Q* Hᵀ``) is
    :meth:`DualQuadric.absolute() <pgsym.quadrics.DualQuadric.absolute>`.

    >>> absolute_dual_quadric()
    Matrix([
    [1, 0, 0, 0],
    [0, 1, 0, 0],
    [0, 0, 1, 0],
    [0, 0, 0, 0]])
    """
    return ImmutableMatrix(sympy.diag(1, 1, 1, 0))


# -- the absolute as a bilinear form on the objects' Euclidean parts -------------------------------
def _line_part(l: Line) -> tuple[Expr, ...]:
    if l.is_at_infinity:
        raise IdealPointError(f"{l!r} is the line at infinity: it has no direction, so no angle and no distance")
    return tuple(l.coords)


def _direction3(L: Line3) -> tuple[Expr, Expr, Expr]:
    if L.is_at_infinity:
        raise IdealPointError(f"{L!r} lies in the plane at infinity: it has no direction, so no angle and no distance")
    return L.direction_moment()[0]


def _normal3(p: Plane) -> tuple[Expr, Expr, Expr]:
    if p.is_at_infinity:
        raise IdealPointError(f"{p!r} is the plane at infinity: it has no normal, so no angle and no distance")
    return p.normal


def _form(a: Any, b: Any, what: str) -> tuple[Expr, Expr, Expr]:
    """``(aᵀAb, aᵀAa, bᵀAb)`` for the absolute ``A`` of the pair's kind (C*∞, Ω∞ on directions, or Q*∞)."""
    if isinstance(a, Line) and isinstance(b, Line):
        C = dual_conic_at_infinity().matrix
        u, v = _line_part(a), _line_part(b)
        return tuple(sympy.expand(dot(x, matvec(C.tolist(), y))) for x, y in ((u, v), (u, u), (v, v)))  # type: ignore[return-value]
    if isinstance(a, Line3) and isinstance(b, Line3):
        u, v = _direction3(a), _direction3(b)  # Ω∞ is the identity form on directions
    elif isinstance(a, Plane) and isinstance(b, Plane):
        Q = absolute_dual_quadric()
        _normal3(a)  # the plane at infinity has no normal
        _normal3(b)
        u, v = matvec(Q.tolist(), a.coords)[:3], matvec(Q.tolist(), b.coords)[:3]
    else:
        raise ObjectTypeError(
            f"{what} takes two Lines of P², two Line3s or two Planes, got {type(a).__name__} and {type(b).__name__}"
        )
    return sympy.expand(dot(u, v)), sympy.expand(dot(u, u)), sympy.expand(dot(v, v))


def _nonisotropic(n: Expr, obj: Any) -> None:
    if is_zero(n):
        raise DegenerateConfigurationError(
            f"{obj!r} is isotropic (it passes through a circular point, or its direction lies on Ω∞): "
            "its Euclidean length is 0, so it makes no angle with anything"
        )


# -- angles -----------------------------------------------------------------------------------------
def cos_squared_angle(a: Line | Line3 | Plane, b: Line | Line3 | Plane) -> Expr:
    """``cos² θ = (aᵀAb)² / ((aᵀAa)(bᵀAb))`` for the absolute ``A``: rational for rational data.

    Independent of the scale (and sign) of either representative. Takes two lines of P²
    (``A = C*∞``), two lines of space (their directions, ``A = Ω∞``) or two planes (``A = Q*∞``).

    >>> cos_squared_angle(Line(1, 0, 0), Line(1, 1, 5))            # x = 0 and x + y = −5: 45°
    1/2
    >>> cos_squared_angle(Plane(1, 0, 0, 0), Plane(1, 1, 1, 1))    # (1·1)² / (1 · 3)
    1/3
    """
    ab, aa, bb = _form(a, b, "cos_squared_angle")
    _nonisotropic(aa, a)
    _nonisotropic(bb, b)
    return sympy.cancel(ab**2 / (aa * bb))


def cos_angle(a: Line | Line3 | Plane, b: Line | Line3 | Plane) -> Expr:
    """``cos θ = aᵀAb / √((aᵀAa)(bᵀAb))`` for the *oriented* representatives given (normals, or directions).

    Replacing ``a`` by ``−a`` (the same projective object) changes the sign: the angle between the
    unoriented objects is the one with cosine ``|cos θ|``.

    >>> cos_angle(Line(0, 1, 0), Line(1, -1, 0))     # y = 0, y = x: −1/√(1·2)
    -sqrt(2)/2
    >>> cos_angle(Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)), Line3.join(Point3(0, 0, 0), Point3(1, 1, 0)))
    sqrt(2)/2
    """
    ab, aa, bb = _form(a, b, "cos_angle")
    _nonisotropic(aa, a)
    _nonisotropic(bb, b)
    return sympy.radsimp(ab / sympy.sqrt(aa * bb))


def sin_angle(l: Line, m: Line) -> Expr:
    """The signed ``sin θ = (l1 m2 − l2 m1) / √((lᵀC*∞l)(mᵀC*∞m))`` of two oriented lines of P².

    θ turns the normal ``(l1, l2)`` of ``l`` counterclockwise onto the normal of ``m``, so that
    ``cos_angle(l, m) + i sin_angle(l, m)`` is ``e^{iθ}``.

    >>> sin_angle(Line(1, 0, 0), Line(0, 1, 0)), sin_angle(Line(0, 1, 0), Line(1, 0, 0))
    (1, -1)
    """
    for x in (l, m):
        if not isinstance(x, Line):
            raise ObjectTypeError(f"sin_angle takes two Lines of P², got {type(x).__name__} {x!r}")
    _, ll, mm = _form(l, m, "sin_angle")
    _nonisotropic(ll, l)
    _nonisotropic(mm, m)
    return sympy.radsimp(sympy.expand(l[0] * m[1] - l[1] * m[0]) / sympy.sqrt(ll * mm))


def laguerre_cross_ratio(l: Line, m: Line) -> Expr:
    """Laguerre's cross-ratio ``cr(l, m; p∨I, p∨J)``, with ``p = l ∧ m`` and ``I``, ``J`` the circular points.

    It equals ``e^{−2iθ}`` for the angle θ of :func:`cos_angle` / :func:`sin_angle`, so Laguerre's formula
    ``θ = (1/2i) log cr`` (up to the orientation sign) is the projective definition of the angle. The
    value does not depend on the scale of ``l`` and ``m``, as the doubled angle does not. Parallel lines
    have cross-ratio 1 (angle 0); equal lines raise :class:`~pgsym.errors.CoincidentLinesError`.

    >>> l, m = Line(0, 1, 0), Line(1, -1, 0)     # cos θ = sin θ = −1/√2: θ = −3π/4, cr = e^{3iπ/2}
    >>> laguerre_cross_ratio(l, m)
    -I
    >>> c, s = cos_angle(l, m), sin_angle(l, m)
    >>> sympy.expand((c - sympy.I * s) ** 2) == laguerre_cross_ratio(l, m)
    True
    """
    for x in (l, m):
        if not isinstance(x, Line):
            raise ObjectTypeError(f"laguerre_cross_ratio takes two Lines of P², got {type(x).__name__} {x!r}")
    _form(l, m, "laguerre_cross_ratio")  # rejects the line at infinity
    p = meet(l, m)
    I_, J_ = circular_points()
    if p.is_ideal:  # parallel: p∨I = p∨J = l∞, and cr(l, m; l∞, l∞) = 1
        return Integer(1)
    return sympy.expand(sympy.radsimp(cross_ratio_lines(l, m, join(p, I_), join(p, J_))))


def _finite(p: Point | Point3, what: str) -> tuple[Expr, ...]:
    if p.is_ideal:
        raise IdealPointError(f"{what}: {p!r} is an ideal point, at infinite distance from every finite point")
    return p.dehomogenize()


def signed_angle(vertex: Point, p: Point, q: Point) -> tuple[Expr, Expr]:
    """``(cos θ, sin θ)`` of the angle at ``vertex`` turning the ray to ``p`` counterclockwise onto the ray to ``q``.

    All three points must be finite and ``p``, ``q`` distinct from ``vertex``.

    >>> signed_angle(Point(0, 0), Point(1, 0), Point(0, 2)), signed_angle(Point(0, 0), Point(0, 2), Point(1, 0))
    ((0, 1), (0, -1))
    >>> signed_angle(Point(1, 1), Point(2, 1), Point(2, 2))
    (sqrt(2)/2, sqrt(2)/2)
    """
    for x in (vertex, p, q):
        if not isinstance(x, Point):
            raise ObjectTypeError(f"signed_angle takes three Points of P², got {type(x).__name__} {x!r}")
    v, a, b = (_finite(x, "signed_angle") for x in (vertex, p, q))
    u = [sympy.cancel(a[i] - v[i]) for i in range(2)]
    w = [sympy.cancel(b[i] - v[i]) for i in range(2)]
    for d, x in ((u, p), (w, q)):
        if all_zero(d):
            raise CoincidentPointsError(f"signed_angle: {x!r} is the vertex {vertex!r}, so it fixes no ray")
    norm = sympy.sqrt(sympy.expand((u[0] ** 2 + u[1] ** 2) * (w[0] ** 2 + w[1] ** 2)))
    cos = sympy.radsimp(sympy.expand(u[0] * w[0] + u[1] * w[1]) / norm)
    sin = sympy.radsimp(sympy.expand(u[0] * w[1] - u[1] * w[0]) / norm)
    return cos, sin


# -- perpendicularity -------------------------------------------------------------------------------
def is_perpendicular(a: Line | Line3 | Plane, b: Line | Line3 | Plane) -> bool:
    """True when ``a`` and ``b`` are conjugate with respect to the absolute.

    Two lines of P²: ``lᵀC*∞m = 0``; two lines of space: their directions are conjugate w.r.t. ``Ω∞``
    (skew lines can be perpendicular); two planes: ``πᵀQ*∞σ = 0``; a line of space and a plane: the
    direction of the line is the pole of the plane's ideal line w.r.t. ``Ω∞`` (the normal direction).
    Elements at infinity raise :class:`~pgsym.errors.IdealPointError`.

    >>> is_perpendicular(Line(1, 2, 3), Line(2, -1, 7)), is_perpendicular(Plane(1, 1, 0, 0), Plane(1, 1, 1, 1))
    (True, False)
    >>> is_perpendicular(Line3.join(Point3(0, 0, 0), Point3(0, 0, 1)), Plane(0, 0, 2, 5))
    True
    """
    if isinstance(a, Plane) and isinstance(b, Line3):
        a, b = b, a
    if isinstance(a, Line3) and isinstance(b, Plane):
        d, n = _direction3(a), _normal3(b)
        return all_zero([sympy.expand(c) for c in cross(d, n)])
    ab, _, _ = _form(a, b, "is_perpendicular")
    return is_zero(ab)


def perpendicular_line(target: Line | Plane | Line3, point: Point | Point3) -> Line | Line3:
    """The line through ``point`` perpendicular to a line of P², to a plane, or meeting a line of space at right angles.

    In P² it is ``x × C*∞l = x × (l1, l2, 0)``: the join of the point with the pole of ``l`` w.r.t.
    ``C*∞`` (the ideal point of the normal). For a plane it is the join of the point with the ideal
    point of the normal, ``Q*∞π``. For a line of space it is the join of the point with its foot on
    the line (a point on the line raises :class:`~pgsym.errors.CoincidentPointsError`). The point
    must be finite.

    >>> perpendicular_line(Line(1, -1, 0), Point(2, 0))        # to y = x through (2, 0): x + y = 2
    Line(1, 1, -2)
    >>> perpendicular_line(Plane(0, 0, 1, -3), Point3(1, 2, 5)) == Line3.join(Point3(1, 2, 5), Point3(1, 2, 0))
    True
    >>> x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    >>> perpendicular_line(x_axis, Point3(4, 0, 2)) == Line3.join(Point3(4, 0, 2), Point3(4, 0, 0))
    True
    """
    if isinstance(target, Line) and isinstance(point, Point):
        a, b, _ = _line_part(target)
        _finite(point, "perpendicular_line")
        return join(point, Point(a, b, 0))
    if isinstance(target, Plane) and isinstance(point, Point3):
        n = matvec(absolute_dual_quadric().tolist(), target.coords)
        _normal3(target)
        _finite(point, "perpendicular_line")
        return Line3.join(point, Point3(*n))
    if isinstance(target, Line3) and isinstance(point, Point3):
        foot = orthogonal_projection(point, target)
        if foot == point:
            raise CoincidentPointsError(
                f"perpendicular_line: {point!r} lies on {target!r}, so every line through it in the "
                "perpendicular plane meets the line at right angles; use perpendicular_plane for that plane"
            )
        return Line3.join(point, foot)
    raise ObjectTypeError(
        "perpendicular_line takes (Line, Point), (Plane, Point3) or (Line3, Point3), "
        f"got {type(target).__name__}, {type(point).__name__}"
    )


def perpendicular_plane(line: Line3, point: Point3) -> Plane:
    """The plane through ``point`` perpendicular to a line of space: normal = the line's direction ``d``.

    For ``X = (x, w)`` it is ``(w d, −d·x)``.

    >>> perpendicular_plane(Line3.join(Point3(0, 0, 0), Point3(1, 1, 0)), Point3(1, 0, 7))   # x + y = 1
    Plane(1, 1, 0, -1)
    """
    if not (isinstance(line, Line3) and isinstance(point, Point3)):
        raise ObjectTypeError(
            f"perpendicular_plane takes a Line3 and a Point3, got {type(line).__name__}, {type(point).__name__}"
        )
    d = _direction3(line)
    _finite(point, "perpendicular_plane")
    x, w = point.coords[:3], point.coords[3]
    return Plane._from_exact((*(sympy.expand(w * c) for c in d), sympy.expand(-dot(d, x))))


def common_perpendicular(l: Line3, m: Line3) -> Line3:
    """The line meeting two non-parallel lines of space at right angles to both (their common perpendicular).

    Its direction is ``n = d_l × d_m``; it passes through the point where ``m`` meets the plane spanned
    by ``l`` and ``n``. For lines that meet, it is the perpendicular to their plane through the common
    point. Parallel lines have a whole family of common perpendiculars and raise
    :class:`~pgsym.errors.DegenerateConfigurationError`.

    >>> x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    >>> skew = Line3.join(Point3(0, 0, 3), Point3(0, 1, 3))          # the line x = 0, z = 3
    >>> common_perpendicular(x_axis, skew) == Line3.join(Point3(0, 0, 0), Point3(0, 0, 1))
    True
    """
    for x in (l, m):
        if not isinstance(x, Line3):
            raise ObjectTypeError(f"common_perpendicular takes two Line3s, got {type(x).__name__} {x!r}")
    n = tuple(sympy.expand(c) for c in cross(_direction3(l), _direction3(m)))
    if all_zero(n):
        raise DegenerateConfigurationError(
            f"{l!r} and {m!r} are parallel: every line perpendicular to both that meets both is a common "
            "perpendicular, so there is no single one (their distance is still defined: use distance())"
        )
    ideal = Point3(*n, 0)
    foot = m.intersect_plane(l.plane_through_point(ideal))
    return Line3.join(foot, ideal)


# -- feet of perpendiculars and distances ------------------------------------------------------------
def orthogonal_projection(point: Point | Point3, target: Line | Plane | Line3) -> Point | Point3:
    """The foot of the perpendicular from a finite point to a line of P², a plane or a line of space.

    For a line ``l = (a, b, c)`` of P² and ``x = (x1, x2, x3)``, with ``s = a² + b²``:
    ``x − (lᵀx / s)(a, b, 0)`` scaled by ``s``, i.e.
    ``(b² x1 − ab x2 − ac x3, −ab x1 + a² x2 − bc x3, s x3)``; for a plane the same with
    ``n = (a, b, c)``; for a line of space the point where the perpendicular plane through ``x``
    meets it. Rational for rational data; the map is idempotent and the residual is perpendicular.

    >>> orthogonal_projection(Point(2, 0), Line(1, -1, 0))            # onto y = x
    Point(2, 2, 2)
    >>> orthogonal_projection(Point3(1, 2, 3), Plane(0, 0, 1, 0)).dehomogenize()
    (1, 2, 0)
    >>> orthogonal_projection(Point3(5, 1, 1), Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))).dehomogenize()
    (5, 0, 0)
    """
    if isinstance(point, Point) and isinstance(target, Line):
        n = _line_part(target)[:2]
    elif isinstance(point, Point3) and isinstance(target, Plane):
        n = _normal3(target)
    elif isinstance(point, Point3) and isinstance(target, Line3):
        _finite(point, "orthogonal_projection")
        return target.intersect_plane(perpendicular_plane(target, point))
    else:
        raise ObjectTypeError(
            "orthogonal_projection takes (Point, Line), (Point3, Plane) or (Point3, Line3), "
            f"got {type(point).__name__}, {type(target).__name__}"
        )
    _finite(point, "orthogonal_projection")
    x, t = point.coords, target.coords
    s, lx = dot(n, n), dot(t, x)
    k = len(n)
    coords = [sympy.expand(s * x[i] - lx * n[i]) for i in range(k)] + [sympy.expand(s * x[k])]
    return type(point)._from_exact(tuple(coords))


def _point_point(p: Point | Point3, q: Point | Point3) -> Expr:
    a, b = _finite(p, "distance"), _finite(q, "distance")
    return sympy.cancel(sum(((u - v) ** 2 for u, v in zip(a, b, strict=True)), Integer(0)))


def _point_hyperplane(p: Point | Point3, h: Line | Plane) -> Expr:
    n = _line_part(h)[:2] if isinstance(h, Line) else _normal3(h)
    _finite(p, "distance")
    w = p.coords[-1]
    return sympy.cancel(dot(h.coords, p.coords) ** 2 / (dot(n, n) * w**2))


def _point_line3(p: Point3, L: Line3) -> Expr:
    d = _direction3(L)
    _finite(p, "distance")
    m = L.direction_moment()[1]
    x, w = p.coords[:3], p.coords[3]
    r = [cross(x, d)[i] - w * m[i] for i in range(3)]  # |x×d − w m| / (|w| |d|)
    return sympy.cancel(dot(r, r) / (w**2 * dot(d, d)))


def _line3_line3(l: Line3, m: Line3) -> Expr:
    d1, d2 = _direction3(l), _direction3(m)
    m1, m2 = l.direction_moment()[1], m.direction_moment()[1]
    n = [sympy.expand(c) for c in cross(d1, d2)]
    if not all_zero(n):  # skew or meeting: |d1·m2 + d2·m1| / |d1 × d2|
        return sympy.cancel((dot(d1, m2) + dot(d2, m1)) ** 2 / dot(n, n))
    # parallel, d2 = k d1 with k = d1·d2 / d1·d1: the distance is |m2/k − m1| / |d1|
    k_num, k_den = dot(d1, d2), dot(d1, d1)
    r = [k_den * m2[i] - k_num * m1[i] for i in range(3)]
    return sympy.cancel(dot(r, r) / (k_num**2 * k_den))


def squared_distance(a: Any, b: Any) -> Expr:
    """The squared Euclidean distance between two objects: rational for rational data.

    Pairs (either order): two points of P², two points of space, a point and a line of P², a
    point and a plane, a point and a line of space, two lines of space (skew, meeting or parallel).
    An ideal point, or a line or plane at infinity, raises :class:`~pgsym.errors.IdealPointError`.

    >>> squared_distance(Point(1, 2), Line(3, 4, 0))           # (3 + 8)² / 25
    121/25
    >>> squared_distance(Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)), Line3.join(Point3(0, 0, 3), Point3(0, 1, 3)))
    9
    >>> squared_distance(Point(1, 1, 0), Point(0, 0))        # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.IdealPointError: distance: Point(1, 1, 0) is an ideal point, at infinite distance ...
    """
    if isinstance(b, (Point, Point3)) and not isinstance(a, (Point, Point3)):
        a, b = b, a
    pairs = (
        (Point, Point, _point_point),
        (Point3, Point3, _point_point),
        (Point, Line, _point_hyperplane),
        (Point3, Plane, _point_hyperplane),
        (Point3, Line3, _point_line3),
        (Line3, Line3, _line3_line3),
    )
    for ta, tb, f in pairs:
        if isinstance(a, ta) and isinstance(b, tb):
            return f(a, b)
    raise ObjectTypeError(
        "distance takes two points, a point and a line or plane, or two Line3s, "
        f"got {type(a).__name__} and {type(b).__name__}"
    )


def distance(a: Any, b: Any) -> Expr:
    """The Euclidean distance, ``√squared_distance(a, b)``, as an exact algebraic number.

    For complex points this is the principal square root of the *bilinear* squared distance
    ``(x₁ − x₂)² + (y₁ − y₂)²``, the form the absolute defines (C*∞ and Q*∞ are bilinear, not Hermitian): so
    ``(0, 0)`` and ``(3i, 0)`` are ``√−9 = 3i`` apart, and a point on an isotropic line, ``(1, i)``, is at
    distance 0 from ``(0, 0)``. (A float library that takes the Hermitian norm, such as geometer, returns 3
    and √2 instead; real points get the same distance either way.)

    >>> distance(Point(0, 0), Point(1, 1)), distance(Point3(1, 2, 3), Plane(0, 0, 2, 0))
    (sqrt(2), 3)
    >>> distance(Point(0, 0), Point(3 * sympy.I, 0)), distance(Point(0, 0), Point(1, sympy.I))
    (3*I, 0)
    """
    return sympy.sqrt(squared_distance(a, b))


def point_distance(p: Point | Point3, q: Point | Point3) -> Expr:
    """The distance of two finite points of P² or of space (the name of the numeric kernel).

    >>> point_distance(Point3(1, 2, 3), Point3(1, 0, 3, 1))
    2
    """
    if not (isinstance(p, (Point, Point3)) and type(p) is type(q)):
        raise ObjectTypeError(
            f"point_distance takes two Points or two Point3s, got {type(p).__name__}, {type(q).__name__}"
        )
    return distance(p, q)


def point_line_distance(p: Point | Point3, line: Line | Line3) -> Expr:
    """The distance of a finite point from a line of P² or of space (the name of the numeric kernel).

    >>> point_line_distance(Point(1, 2), Line(3, 4, 0)), point_line_distance(Point3(0, 3, 4), Line3(0, 0, 1, 0, 0, 0))
    (11/5, 5)
    """
    if not (isinstance(p, Point) and isinstance(line, Line)) and not (
        isinstance(p, Point3) and isinstance(line, Line3)
    ):
        raise ObjectTypeError(
            f"point_line_distance takes (Point, Line) or (Point3, Line3), got {type(p).__name__}, {type(line).__name__}"
        )
    return distance(p, line)


def point_plane_distance(p: Point3, plane: Plane) -> Expr:
    """The distance of a finite point of space from a plane (the name of the numeric kernel).

    >>> point_plane_distance(Point3(1, 2, 3), Plane(2, 0, 0, 0))
    1
    """
    if not (isinstance(p, Point3) and isinstance(plane, Plane)):
        raise ObjectTypeError(
            f"point_plane_distance takes a Point3 and a Plane, got {type(p).__name__}, {type(plane).__name__}"
        )
    return distance(p, plane)


# -- similarities as transformations -------------------------------------------------------------------
def reflection(mirror: Line | Plane) -> Transformation:
    """The reflection in a line of P² (3×3) or a plane (4×4), an involutive isometry.

    With ``n`` the normal and ``s = n·n``: ``x ↦ s x − 2 (mirrorᵀx)(n, 0)``, i.e. the matrix
    ``s I − 2 (n, 0) mirrorᵀ`` (exact, rational for rational mirrors).

    >>> reflection(Line(0, 1, -1)).matrix                     # in y = 1: (x, y) ↦ (x, 2 − y)
    Matrix([
    [1,  0, 0],
    [0, -1, 2],
    [0,  0, 1]])
    """
    if isinstance(mirror, Line):
        n = _line_part(mirror)[:2]
    elif isinstance(mirror, Plane):
        n = _normal3(mirror)
    else:
        raise ObjectTypeError(f"reflection takes a Line of P² or a Plane, got {type(mirror).__name__} {mirror!r}")
    s = dot(n, n)
    _nonisotropic(sympy.expand(s), mirror)
    k = len(n) + 1
    v = (*n, Integer(0))
    return Transformation(
        [[sympy.expand((s if i == j else 0) - 2 * v[i] * mirror.coords[j]) for j in range(k)] for i in range(k)]
    )


def reflect(obj: Any, mirror: Line | Plane) -> Any:
    """The mirror image of any object the transformations act on: ``reflection(mirror)(obj)``.

    >>> reflect(Point3(1, 2, 3), Plane(0, 0, 1, 0))
    Point3(1, 2, -3, 1)
    """
    return reflection(mirror)(obj)


def _center(center: Point | Point3 | None, dim: int, what: str) -> tuple[Expr, ...]:
    if center is None:
        return (Integer(0),) * dim
    if not isinstance(center, (Point, Point3)) or len(center) != dim + 1:
        raise ObjectTypeError(f"{what}: the center must be a finite point of the same space, got {center!r}")
    return _finite(center, what)


def translation(*offset: Scalar) -> Transformation:
    """The translation by ``(dx, dy)`` (of P²) or ``(dx, dy, dz)`` (of P³).

    >>> translation(1, 2)(Point(0, 0)), translation(1, 2, 3)(Point3(0, 0, 0))
    (Point(1, 2, 1), Point3(1, 2, 3, 1))
    """
    if len(offset) == 1 and isinstance(offset[0], Sequence):
        offset = tuple(offset[0])
    if len(offset) not in (2, 3):
        raise DimensionError(f"translation takes 2 offsets (P²) or 3 (P³), got {len(offset)}: {offset}")
    t = [to_exact(c) for c in offset]
    k = len(t)
    return Transformation([[1 if i == j else 0 for j in range(k)] + [t[i]] for i in range(k)] + [[0] * k + [1]])


def scaling(factor: Scalar, center: Point | Point3 | None = None, *, dim: int = 2) -> Transformation:
    """The uniform scaling ``x ↦ c + f (x − c)`` of P² (``dim=2``) or P³ about ``center`` (the origin by default).

    A zero factor is singular: :class:`~pgsym.errors.SingularTransformationError`.

    >>> scaling(3, Point(1, 1))(Point(2, 1))
    Point(4, 1, 1)
    """
    if isinstance(center, Point3):
        dim = 3
    elif isinstance(center, Point):
        dim = 2
    if dim not in (2, 3):
        raise DimensionError(f"scaling acts on P² or P³ (dim 2 or 3), got dim={dim!r}")
    f, c = to_exact(factor), _center(center, dim, "scaling")
    rows = [[f if i == j else 0 for j in range(dim)] + [sympy.expand((1 - f) * c[i])] for i in range(dim)]
    return Transformation([*rows, [0] * dim + [1]])


def rotation(cos: Scalar, sin: Scalar, center: Point | None = None) -> Transformation:
    """The rotation of the plane by the angle with the given exact ``cos`` and ``sin`` about ``center``.

    ``cos² + sin² = 1`` is checked exactly (:class:`~pgsym.errors.InvalidCoordinatesError`
    otherwise); every angle is allowed, the half-turn ``(−1, 0)`` and quarter-turns ``(0, ±1)``
    included, and algebraic values such as ``(1/2, √3/2)``. Symbolic values are allowed when the
    identity is decidable (rational functions, e.g. ``((1 − t²)/(1 + t²), 2t/(1 + t²))``); ``cos(t)``
    and ``sin(t)`` of a symbol raise :class:`~pgsym.errors.UndecidableError`, as every exact
    decision about them does.

    >>> rotation(0, 1)(Point(1, 0)), rotation(-1, 0, Point(1, 1))(Point(0, 0))
    (Point(0, 1, 1), Point(2, 2, 1))
    >>> rotation(3, 4)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.InvalidCoordinatesError: rotation: (cos, sin) = (3, 4) is not on the unit circle: ...
    """
    c, s = to_exact(cos), to_exact(sin)
    if not is_zero(sympy.expand(c**2 + s**2 - 1)):
        raise InvalidCoordinatesError(
            f"rotation: (cos, sin) = ({c}, {s}) is not on the unit circle: cos² + sin² = "
            f"{sympy.expand(c**2 + s**2)} ≠ 1; divide both by √(cos² + sin²) for a rotation by that angle"
        )
    x, y = _center(center, 2, "rotation")
    tx, ty = sympy.expand(x - c * x + s * y), sympy.expand(y - s * x - c * y)
    return Transformation([[c, -s, tx], [s, c, ty], [0, 0, 1]])


def angle_bisectors(l: Line, m: Line) -> tuple[Line, Line]:
    """The two bisectors ``l/|l| ± m/|m|`` of two lines of P², with ``|l| = √(lᵀC*∞l)``.

    Exact: for rational lines the coordinates are algebraic (square roots). The first bisector
    halves the angle between the oriented normals given, the second is perpendicular to it. For
    parallel lines one "bisector" is the midline and the other the line at infinity; equal lines
    raise :class:`~pgsym.errors.CoincidentLinesError`.

    >>> angle_bisectors(Line(0, 1, 0), Line(1, 0, 0))      # the axes: y = −x and y = x
    (Line(1, 1, 0), Line(1, -1, 0))
    >>> angle_bisectors(Line(1, 0, 0), Line(3, 4, 0))      # |l| = 1, |m| = 5: (1, 0) ± (3, 4)/5
    (Line(2, 1, 0), Line(1, -2, 0))
    """
    for x in (l, m):
        if not isinstance(x, Line):
            raise ObjectTypeError(f"angle_bisectors takes two Lines of P², got {type(x).__name__} {x!r}")
    if l == m:
        raise CoincidentLinesError(f"angle_bisectors: {l!r} and {m!r} are the same line, which makes no angle")
    _, ll, mm = _form(l, m, "angle_bisectors")
    _nonisotropic(ll, l)
    _nonisotropic(mm, m)
    u = [sympy.radsimp(c / sympy.sqrt(ll)) for c in l.coords]
    v = [sympy.radsimp(c / sympy.sqrt(mm)) for c in m.coords]
    plus = tuple(sympy.radsimp(a + b) for a, b in zip(u, v, strict=True))
    minus = tuple(sympy.radsimp(a - b) for a, b in zip(u, v, strict=True))
    return Line._from_exact(plus).canonical(), Line._from_exact(minus).canonical()


def is_concyclic(a: Point, b: Point, c: Point, d: Point) -> bool:
    """True when one circle passes through the four finite points.

    A circle is a conic through the circular points, so its equation is
    ``λ(x² + y²) + μx + νy + ρ = 0``; four points lie on one such curve exactly when the 4×4
    determinant of the rows ``(x² + y², xw, yw, w²)`` vanishes (homogeneous coordinates, so any
    representative works). That curve may be the degenerate "circle" line ∪ l∞, so points on a line
    are told apart: three or more distinct collinear points lie on no circle. Two equal points leave
    three to pass a circle through. Ideal points raise :class:`~pgsym.errors.IdealPointError`.

    >>> is_concyclic(Point(1, 0), Point(0, 1), Point(-1, 0), Point(3, 4, 5))   # on x² + y² = 1
    True
    >>> is_concyclic(Point(1, 0), Point(0, 1), Point(-1, 0), Point(0, 2))
    False
    """
    pts = [a, b, c, d]
    for p in pts:
        if not isinstance(p, Point):
            raise ObjectTypeError(f"is_concyclic takes four Points of P², got {type(p).__name__} {p!r}")
        _finite(p, "is_concyclic")
    rows = [(x * x + y * y, x * w, y * w, w * w) for x, y, w in (p.coords for p in pts)]
    if not is_zero(sympy.Matrix(rows).det()):
        return False
    distinct: list[Point] = []
    for p in pts:
        if all(p != q for q in distinct):
            distinct.append(p)
    if len(distinct) <= 2:
        return True
    return not all(collinear(*distinct[:2], r) for r in distinct[2:])
