"""Pencils of conics, exactly: where two conics meet, and the conics through four points touching a line.

Two conics ``C₁``, ``C₂`` span the *pencil* ``μC₁ + λC₂``; every member passes through the four
points (counted with multiplicity) that ``C₁`` and ``C₂`` share. Its degenerate members are the
roots of the cubic ``det(μC₁ + λC₂) = 0``, and a degenerate member is a pair of lines
(:meth:`Conic.split <pgsym.conics.Conic.split>`). So the intersection of two conics is the
intersection of one conic with two lines (Richter-Gebert, *Perspectives on Projective Geometry*,
11.4), each a quadratic equation (:meth:`Conic.intersections <pgsym.conics.Conic.intersections>`):

>>> from pgsym.conics import Conic
>>> from pgsym.projective_plane import Point
>>> C1, C2 = Conic.circle(0, 0, 5), Conic.circle(4, 0, 3)   # x² + y² = 25, (x − 4)² + y² = 9
>>> sorted(p.dehomogenize() for p in intersect_conics(C1, C2) if not p.is_ideal)
[(4, -3), (4, 3)]

(the other two of the four points are the circular points ``I`` and ``J``, on every circle).

**What is exact.** The cubic is factored over the field of the conics' coefficients (ℚ, a number
field such as ℚ(√2, i), or rational functions in symbols). A root found there gives a degenerate
member with coefficients in that field, and its lines and the points need at most two nested
square roots. When the cubic has no root in that field (an irreducible cubic, as for two random
conics) the points would need Cardano's formula nested under square roots; this is not attempted
and :class:`~pgsym.errors.UndecidableError` says so — never an approximate point. (Two common points
with coordinates in the field suffice for a root: the line pair through them and through the other two
is fixed by every conjugation.) Every point
returned is checked exactly (:func:`pgsym.exact.is_zero`) to lie on both conics.
"""

from __future__ import annotations

from itertools import combinations
from typing import Any

import sympy
from sympy import Expr, Matrix, Rational  # noqa: F401 (Rational: doctest)

from .conics import Conic, conic_through  # noqa: F401 (conic_through: doctest)
from .errors import (
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DegenerateConicError,
    DimensionError,
    NotOnConicError,
    ObjectTypeError,
    UndecidableError,
)
from .exact import Scalar, algebraic_normal_form, is_zero, to_exact
from .homogeneous import require
from .projective_plane import Line, Point, collinear, join
from .transformations import Transformation, homography_from_points

__all__ = [
    "conic_from_cross_ratio",
    "conics_through_tangent",
    "degenerate_members",
    "homography_from_points_and_conics",
    "intersect_conics",
]

_T = sympy.Dummy("t")


def _member(c1: Conic, c2: Conic, mu: Expr, lam: Expr) -> Conic:
    return Conic._from_exact((mu * Matrix(c1.matrix) + lam * Matrix(c2.matrix)).applyfunc(sympy.expand))


def degenerate_members(c1: Conic, c2: Conic) -> list[Conic]:
    """The degenerate conics ``μC₁ + λC₂`` of the pencil whose parameter lies in the coefficients' field.

    These are the roots of ``det(C₁ + t C₂)`` found by factoring over that field, plus ``C₂``
    itself when it is degenerate (the root ``t = ∞``). All members are degenerate when the conics
    share a line; then ``C₁`` (and ``C₂``) are returned. An empty list means the cubic is
    irreducible over the field (the usual case for random conics).

    >>> from pgsym.conics import Conic
    >>> [D.split() for D in degenerate_members(Conic.circle(0, 0, 1), Conic.circle(1, 0, 1))]
    [(Line(0, 0, 1), Line(2, 0, -1))]
    """
    require(c1, Conic, "degenerate_members")
    require(c2, Conic, "degenerate_members")
    found: list[Conic] = []
    if c2.is_degenerate:
        found.append(c2)
    if c1.is_degenerate:
        found.append(c1)
    cubic = sympy.expand((Matrix(c1.matrix) + _T * Matrix(c2.matrix)).det(method="bareiss"))
    if is_zero(cubic):
        return found  # every member is degenerate: c1 and c2 are
    try:
        _, factors = sympy.factor_list(cubic, _T, extension=True)
    except (sympy.polys.polyerrors.PolynomialError, NotImplementedError, ValueError) as err:
        raise UndecidableError(f"the cubic det(C1 + t C2) = {cubic} could not be factored exactly ({err})") from err
    for factor, _ in factors:
        poly = sympy.Poly(factor, _T)
        if poly.degree() == 1:
            a1, a0 = poly.all_coeffs()
            t = sympy.radsimp(-a0 / a1)
            if not is_zero(t):  # t = 0 is c1 itself, already listed
                member = _member(c1, c2, sympy.Integer(1), t)
                if not any(member == f for f in found):
                    found.append(member)
    return found


def _plainness(lines: tuple[Line, Line]) -> int:
    """0 for a double line, 1 for two rational lines, 2 otherwise: the fewer radicals, the better."""
    l, m = lines
    if l == m:
        return 0
    return 1 if all(c.is_Rational for c in (*l.coords, *m.coords)) else 2


def intersect_conics(c1: Conic, c2: Conic) -> tuple[Point, Point, Point, Point]:
    """The four points shared by two conics, with multiplicity (Bézout), in exact coordinates.

    A degenerate member ``D = l ∪ m`` of the pencil is split into its lines, and the points are
    ``E ∩ l`` and ``E ∩ m`` for the other conic ``E`` (``C₁``, or ``C₂`` when ``D`` is ``C₁``). Since
    the pencil is spanned by ``D`` and ``E``, and the intersection multiplicity is additive over the
    lines of ``D``, a point of tangency appears twice (three or four times for higher contact), and a
    double line counts each of its points twice. Points may be complex or ideal.

    Raises :class:`~pgsym.errors.DegenerateConfigurationError` when the conics are the same conic,
    :class:`~pgsym.errors.DegenerateConicError` when they share a line (infinitely many common
    points), and :class:`~pgsym.errors.UndecidableError` when no degenerate member has exact
    coefficients (see the module docstring).

    >>> from pgsym.conics import Conic
    >>> P = Conic.from_coefficients(1, 0, 0, 0, -1, 0)          # the parabola y = x²
    >>> [p.dehomogenize() for p in intersect_conics(P, Conic.circle(0, 1, 1))]
    [(1, 1), (-1, 1), (0, 0), (0, 0)]

    (``x² + (y − 1)² = 1`` with ``x² = y`` gives ``y(y − 1) = 0``: the two points at ``y = 1``, and the origin
    twice, where the parabola and the circle touch.)
    """
    require(c1, Conic, "intersect_conics")
    require(c2, Conic, "intersect_conics")
    if c1 == c2:
        raise DegenerateConfigurationError(
            f"intersect_conics: the two conics are the same conic {c1!r}, so every one of its points is common"
        )
    members = degenerate_members(c1, c2)
    if not members:
        raise UndecidableError(
            "intersect_conics: det(C1 + t C2) has no root in the field of the conics' coefficients, so the "
            "common points would need the roots of an irreducible cubic nested under square roots (Cardano); "
            "pgsym does not produce them exactly (pgsym.numeric.intersect_conics gives them in floats); two known "
            "common points with coordinates in that field, or a degenerate conic among the two, make the question exact"
        )
    candidates = [(D, D.split()) for D in members]
    D, (l, m) = min(candidates, key=lambda c: _plainness(c[1]))
    E = c2 if D == c1 else c1
    points: list[Point] = []
    for line in (l, m):
        try:
            points.extend(E.intersections(line))
        except DegenerateConicError:
            raise DegenerateConicError(
                f"intersect_conics: the conics share the line {line!r}, so they have infinitely many common points"
            ) from None
    points = [_nice(p) for p in points]
    for p in points:
        if not (c1.contains(p) and c2.contains(p)):  # pragma: no cover - a guard: never return an unverified point
            raise UndecidableError(f"intersect_conics: the point {p!r} could not be verified on both conics")
    return tuple(points)  # type: ignore[return-value]


def _simple(c: Expr) -> bool:
    """True when every radical in ``c`` is of a rational number (``√31``, ``i``), none nested."""
    return all(e.exp.is_Integer or e.base.is_Rational for e in c.atoms(sympy.Pow))


def _nice(p: Point) -> Point:
    """Rational points in canonical form; others scaled by a coordinate without nested radicals (the last one
    where it has none, so that a finite point reads ``(x, y, 1)``), those coordinates in the normal form of
    :func:`pgsym.exact.algebraic_normal_form`. Nested radicals are left as computed: their normal form
    would cost a minimal polynomial of high degree, and dividing by them nests them in denominators."""
    if all(c.is_Rational for c in p.coords):
        return p.canonical()
    nonzero = [i for i in range(3) if not is_zero(p.coords[i])]
    simple = [i for i in nonzero if _simple(p.coords[i])]
    if not simple:
        return p
    k = 2 if 2 in simple else simple[0]
    out = []
    for c in p.coords:
        c = sympy.expand(sympy.radsimp(c / p.coords[k]))
        if not (c.is_Rational or c.free_symbols) and _simple(c):
            c = algebraic_normal_form(c)
        out.append(c)
    return Point._from_exact(tuple(out))


def conics_through_tangent(points: tuple[Point, Point, Point, Point], line: Line) -> tuple[Conic, ...]:
    """The conics through four points (no three collinear) that touch a line: generally two, exact.

    The conics through the four points form the pencil ``μD₁ + λD₂`` spanned by two of their line
    pairs, ``D₁ = (p₁p₂)(p₃p₄)`` and ``D₂ = (p₁p₃)(p₂p₄)``. On the line each member restricts to a
    binary form whose coefficients ``(A, B, C')`` are linear in ``(μ, λ)``, so the tangency condition
    ``B² − AC' = 0`` (:meth:`Conic.discriminant <pgsym.conics.Conic.discriminant>`) is a quadratic
    ``δ₁μ² + 2kμλ + δ₂λ² = 0``: two solutions with ``√(k² − δ₁δ₂)``, complex when that is negative,
    one when it vanishes (also when the line passes through one of the points: the conic touching it
    there). A line pair of the pencil that contains the line (the line through two of the points)
    counts as touching it. Each conic returned is checked exactly to pass through the points and
    touch the line.

    Raises :class:`~pgsym.errors.CollinearPointsError` when three of the points are collinear, and
    :class:`~pgsym.errors.DegenerateConfigurationError` when every conic of the pencil touches the line.

    >>> from pgsym.projective_plane import Point, Line
    >>> square = (Point(1, 1), Point(-1, 1), Point(-1, -1), Point(1, -1))
    >>> conics_through_tangent(square, Line(0, 1, -2))     # touching y = 2
    (Conic.from_coefficients(0, 0, 1, 0, 0, -1), Conic.from_coefficients(3, 0, 1, 0, 0, -4))

    (The pencil is ``α(x² − 1) + β(y² − 1)``; on ``y = 2`` it is ``αx² + 3β − α``, a double root when
    ``α = 0`` — the parallel pair ``y = ±1``, whose vertex at infinity lies on the line — or ``α = 3β``:
    the ellipse ``3x² + y² = 4``.)
    """
    if len(points) != 4:
        raise DimensionError(f"conics_through_tangent needs four points, got {len(points)}")
    for p in points:
        require(p, Point, "conics_through_tangent")
    require(line, Line, "conics_through_tangent")
    p1, p2, p3, p4 = points
    for trio in ((p1, p2, p3), (p1, p2, p4), (p1, p3, p4), (p2, p3, p4)):
        if collinear(*trio):
            raise CollinearPointsError(
                f"conics_through_tangent: the points {trio!r} are collinear (or two coincide); the conics through "
                "four points form a pencil only when no three of them are collinear"
            )
    D1 = Conic.from_lines(join(p1, p2), join(p3, p4))
    D2 = Conic.from_lines(join(p1, p3), join(p2, p4))
    a1, b1, c1 = D1.restricted_form(line)
    a2, b2, c2 = D2.restricted_form(line)
    d1 = sympy.expand(b1**2 - a1 * c1)
    d2 = sympy.expand(b2**2 - a2 * c2)
    k = sympy.expand(b1 * b2 - (a1 * c2 + a2 * c1) / 2)
    if is_zero(d1) and is_zero(d2) and is_zero(k):
        raise DegenerateConfigurationError(
            f"conics_through_tangent: every conic through the four points touches {line!r}"
        )
    # roots (μ : λ) of d1 μ² + 2k μλ + d2 λ²
    if is_zero(d1):
        params = [(sympy.Integer(1), sympy.Integer(0)), (-d2, 2 * k)] if not is_zero(k) else [(1, 0)]
    else:
        root = sympy.sqrt(sympy.expand(k**2 - d1 * d2))
        params = [(sympy.radsimp(-k + s * root), d1) for s in (1, -1)]
    found: list[Conic] = []
    for mu, lam in params:
        conic = _member(D1, D2, sympy.sympify(mu), sympy.sympify(lam)).canonical()
        if not (all(conic.contains(p) for p in points) and conic.is_tangent(line)):  # pragma: no cover - guard
            raise UndecidableError(f"conics_through_tangent: {conic!r} could not be verified")
        if not any(conic == f for f in found):  # a double root gives one conic
            found.append(conic)
    return tuple(found)


def conic_from_cross_ratio(cr: Scalar, a: Point, b: Point, c: Point, d: Point) -> Conic:
    """Steiner's conic: the points ``x`` from which ``a, b, c, d`` are seen under the cross-ratio ``cr``.

    The lines ``x∨a, …, x∨d`` have the cross-ratio ``[xac][xbd] / ([xad][xbc])`` (the convention of
    :func:`~pgsym.projective_line.cross_ratio`), and ``[xac] = (a×c)ᵀx``. So the locus is the member

        (a×c)(b×d)ᵀ + (b×d)(a×c)ᵀ − cr · ((a×d)(b×c)ᵀ + (b×c)(a×d)ᵀ)

    of the pencil of conics through the four points: Steiner's theorem says the cross-ratio is
    constant along each conic of the pencil, and every conic through ``a, b, c, d`` arises for one
    value. At ``cr = 0`` and ``cr = 1`` the member is the line pair ``ac, bd`` and ``ab, cd``
    (returned as such). No three of the points may be collinear (:class:`CollinearPointsError`).

    >>> a, b, c, d = Point(0, 1), Point(0, -1), Point(3, 1, 2), Point(3, -1, 2)
    >>> conic_from_cross_ratio(Rational(1, 3), a, b, c, d) == conic_through(a, b, c, d, Point(-3, 1, 2))
    True
    """
    points = (a, b, c, d)
    for p in points:
        require(p, Point, "conic_from_cross_ratio")
    for i, j, k in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
        if collinear(points[i], points[j], points[k]):
            raise CollinearPointsError(
                f"conic_from_cross_ratio: {points[i]!r}, {points[j]!r}, {points[k]!r} are collinear; the conics "
                "through four points need no three of them on a line"
            )
    k = to_exact(cr)
    first = Conic.from_lines(join(a, c), join(b, d)).matrix
    second = Conic.from_lines(join(a, d), join(b, c)).matrix
    return Conic(first - k * second).canonical()


def homography_from_points_and_conics(src: list[Point], dst: list[Point], conic: Any, image: Any) -> Transformation:
    """The homography that maps the conic ``conic`` onto ``image`` and three of its points ``src`` to ``dst``.

    The points must lie on their (non-degenerate) conics. **There is exactly one solution**: a
    homography that maps C to C' maps the tangents at ``a``, ``b`` to the tangents at ``a'``, ``b'``,
    so it maps their meet ``P = (C a) × (C b)``, the pole of the chord ``ab``, to ``P'``. The four points
    ``a, b, c, P`` are in general position (``P`` lies on neither the chord nor, since ``c ≠ a, b``, the
    lines ``ac``, ``bc``; three points of a conic are never collinear), so the four pairs fix one
    homography (:func:`~pgsym.transformations.homography_from_points`); it maps C onto C', because C is the
    only conic through ``a, b, c`` that touches the lines ``Pa`` and ``Pb`` at ``a`` and ``b``.

    Named errors: :class:`~pgsym.errors.NotOnConicError` for a point off its conic,
    :class:`~pgsym.errors.DegenerateConicError` for a degenerate conic,
    :class:`~pgsym.errors.CoincidentPointsError` for repeated points.

    >>> C = Conic.circle(0, 0, 1)
    >>> H = homography_from_points_and_conics([Point(1, 0), Point(0, 1), Point(-1, 0)],
    ...                                       [Point(0, 1), Point(-1, 0), Point(0, -1)], C, C)
    >>> H == Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])          # the quarter turn
    True
    """
    quads = []
    for pts, C, side in ((src, conic, "source"), (dst, image, "image")):
        if not isinstance(C, Conic):
            raise ObjectTypeError(f"the {side} conic must be a Conic, got {type(C).__name__} {C!r}")
        if not isinstance(pts, (list, tuple)) or len(pts) != 3 or not all(isinstance(p, Point) for p in pts):
            raise DimensionError(f"three Points on the {side} conic are needed, got {pts!r}")
        if C.is_degenerate:
            raise DegenerateConicError(f"the {side} conic {C!r} is degenerate: it has no tangents at every point")
        for i, p in enumerate(pts):
            if not C.contains(p):
                raise NotOnConicError(f"{side} point {i + 1}, {p!r}, does not lie on the {side} conic {C!r}")
        for (i, p), (j, q) in combinations(enumerate(pts), 2):
            if p == q:
                raise CoincidentPointsError(f"{side} points {i + 1} and {j + 1} coincide ({p!r})")
        a, b, _ = pts
        pole = Point._from_exact(tuple(sympy.expand(e) for e in Matrix(C.polar(a).coords).cross(
            Matrix(C.polar(b).coords))))
        quads.append([*pts, pole])
    return homography_from_points(quads[0], quads[1])
