"""Affine and Euclidean properties of conics: their type, centre, axes and foci, and conics from metric data.

Projectively all non-degenerate real conics are alike; what tells an ellipse from a hyperbola is
how the conic meets the line at infinity ``l∞`` (an affine notion), and what makes a circle, an
axis or a focus is the absolute, the circular points ``I = (1, i, 0)``, ``J = (1, −i, 0)``
(Hartley & Zisserman 2.7; Richter-Gebert, *Perspectives on Projective Geometry*, ch. 19):

* a conic meets ``l∞`` in two real points (hyperbola), one double point (parabola) or two complex
  conjugate points (ellipse) — the sign of ``Conic.discriminant(l∞)``, i.e. of ``b² − 4ac`` for
  ``a x² + b xy + c y² + …``; a circle is the ellipse through ``I`` and ``J``;
* the centre is the pole of ``l∞`` (an ideal point, the axis direction, for a parabola);
* the foci are the points whose joins with ``I`` and ``J`` touch the conic: the real intersections
  of the tangents from ``I`` with those from ``J``. Every focus returned here is checked exactly
  against that definition.

>>> from pgsym.conics import Conic
>>> E = Conic.from_coefficients(1, 0, 4, 0, 0, -4)          # x²/4 + y² = 1
>>> affine_type(E), center(E), semi_axes(E)
('ellipse', Point(0, 0, 1), (2, 1))
>>> foci(E)                                                  # c² = a² − b² = 3
(Point(-sqrt(3), 0, 1), Point(sqrt(3), 0, 1))
"""

from __future__ import annotations

import sympy
from sympy import Expr, Integer, Matrix

from .conics import Conic, circular_points
from .errors import (
    CoincidentPointsError,
    DegenerateConfigurationError,
    DegenerateConicError,
    InvalidCoordinatesError,
    ObjectTypeError,
)
from .exact import Scalar, is_zero, sign, to_exact
from .homogeneous import require
from .matrices import adjugate, proportional
from .metric import rotation, squared_distance
from .projective_plane import Line, Point, cross, join, line_at_infinity
from .transformations import Transformation

__all__ = [
    "CONIC_TYPES",
    "affine_type",
    "axes",
    "center",
    "conic_from_foci",
    "cos_intersection_angle",
    "ellipse",
    "foci",
    "hyperbola",
    "inversion",
    "parabola",
    "radius",
    "semi_axes",
    "squared_radius",
]

CONIC_TYPES = (
    "ellipse",
    "circle",
    "hyperbola",
    "parabola",
    "imaginary ellipse",
    "imaginary circle",
    "intersecting lines",
    "point ellipse",
    "parallel lines",
    "imaginary parallel lines",
    "line and line at infinity",
    "double line",
    "double line at infinity",
)
"""Every answer of :func:`affine_type`: the real affine classification of conics (with the circle)."""


def _is_circular(C: Conic) -> bool:
    """True when the conic passes through I and J: ``a = c`` and ``b = 0`` (I, J are conjugate)."""
    m = C.matrix
    return is_zero(m[0, 0] - m[1, 1]) and is_zero(m[0, 1])


def _real(conic: Conic, what: str) -> Conic:
    """A real representative of the conic (signs are scale-free only for real scales), or a named error
    when there is none (``C ∝ C̄`` fails); symbols count as real parameters."""
    require(conic, Conic, what)
    entries = list(conic.matrix)
    symbols = set().union(*(e.free_symbols for e in entries))
    real = {s: sympy.Dummy(s.name, real=True) for s in symbols}
    mine = [e.xreplace(real) for e in entries]
    conj = [sympy.expand(sympy.conjugate(e)) for e in mine]
    if not proportional(mine, conj):
        raise InvalidCoordinatesError(
            f"{what}: {conic!r} is not a real conic (no real multiple of its matrix is real); the affine "
            "type, centre, axes and foci are defined here for real conics"
        )
    if all(is_zero(sympy.expand(a - b)) for a, b in zip(mine, conj, strict=True)):
        return conic
    pivot = next(e for e in entries if not is_zero(e))
    return Conic._from_exact(conic.matrix.applyfunc(lambda e: sympy.expand(sympy.radsimp(e / pivot))))


def affine_type(conic: Conic) -> str:
    """The affine type of a real conic, one of :data:`CONIC_TYPES`, decided exactly.

    Non-degenerate conics by how they meet ``l∞``: the sign of ``Conic.discriminant(l∞)``
    (``= b²/4 − ac`` up to a positive square) is positive for a hyperbola (two real points at
    infinity), zero for a parabola (tangent to ``l∞``) and negative for an ellipse, which is real
    when ``a·det C < 0`` and a circle when it also passes through ``I`` and ``J``. Degenerate
    conics: a double line (rank 1), or a line pair whose lines are real when the diagonal of
    ``adj C = −p pᵀ`` is negative and complex conjugate when it is positive (:meth:`Conic.split
    <pgsym.conics.Conic.split>`), intersecting when the vertex ``p`` is finite.

    Every sign is scale-free (``C → kC`` multiplies it by an even power of k) and decided by
    :func:`pgsym.exact.sign`; a conic with symbolic or complex coefficients whose sign is not
    determined raises :class:`~pgsym.errors.UndecidableError`; a conic that is not real (symbols are
    taken as real parameters) raises :class:`~pgsym.errors.InvalidCoordinatesError`.

    >>> [affine_type(Conic.from_coefficients(*c)) for c in [(1, 0, 1, 0, 0, -1), (1, 0, -1, 0, 0, -1),
    ...                                                   (1, 0, 0, 0, -1, 0), (1, 0, 2, 0, 0, 1)]]
    ['circle', 'hyperbola', 'parabola', 'imaginary ellipse']
    >>> [affine_type(Conic.from_coefficients(*c)) for c in [(1, 0, -1, 0, 0, 0), (1, 0, 0, 0, 0, -1),
    ...                                                   (1, 0, 0, 0, 0, 1), (0, 0, 0, 1, 0, 0)]]
    ['intersecting lines', 'parallel lines', 'imaginary parallel lines', 'line and line at infinity']
    """
    conic = _real(conic, "affine_type")
    m = conic.matrix
    meets = sign(conic.discriminant(line_at_infinity()))  # +: two real ideal points, 0: one, −: none
    if not conic.is_degenerate:
        if meets > 0:
            return "hyperbola"
        if meets == 0:
            return "parabola"
        real = sign(sympy.expand(m[0, 0] * conic.determinant)) < 0
        kind = "circle" if _is_circular(conic) else "ellipse"
        return kind if real else f"imaginary {kind}"
    if conic.rank == 1:
        line = conic.split()[0]
        return "double line at infinity" if line.is_at_infinity else "double line"
    if meets > 0:
        return "intersecting lines"
    if meets < 0:
        return "point ellipse"
    if is_zero(m[0, 0]) and is_zero(m[0, 1]) and is_zero(m[1, 1]):
        return "line and line at infinity"
    B = adjugate(m)
    i = next(k for k in range(2) if not is_zero(B[k, k]))  # the vertex is ideal, so p1 or p2 ≠ 0
    return "parallel lines" if sign(B[i, i]) < 0 else "imaginary parallel lines"


def _affine(p: Point) -> Point:
    """A finite point as ``(x, y, 1)`` with simplified radicals; an ideal point in canonical form."""
    if p.is_ideal:
        return p.canonical()
    x, y = p.dehomogenize()
    return Point._from_exact((sympy.radsimp(x), sympy.radsimp(y), Integer(1)))


def center(conic: Conic) -> Point:
    """The centre: the pole of ``l∞``, ``adj(C) (0, 0, 1)ᵀ`` (for a parabola the ideal point of its axis).

    Raises :class:`~pgsym.errors.DegenerateConicError` for a degenerate conic.

    >>> center(Conic.circle(3, -1, 2)), center(Conic.from_coefficients(1, 0, 0, 0, -1, 0))   # y = x²
    (Point(3, -1, 1), Point(0, 1, 0))
    """
    conic = _real(conic, "center")
    return _affine(conic.pole(line_at_infinity()))


def _principal(conic: Conic) -> list[tuple[tuple[Expr, Expr], Expr]]:
    """``[(direction, s)]`` for the two axes of a real ellipse or hyperbola, with ``s`` the squared semi-axis.

    With the centre moved to the origin the conic is ``uᵀSu + f' = 0``, ``S`` the upper-left 2×2 block
    and ``f' = det C / det S``; along an eigenvector of ``S`` with eigenvalue λ the conic is at
    ``t² = −f'/λ``. The eigenvalues are ``((a + c) ± r)/2`` with ``r = √((a − c)² + 4h²)`` (h the
    off-diagonal entry), eigenvectors ``(2h, c − a ± r)``. The first axis is the major axis of an
    ellipse (larger s) or the transverse axis of a hyperbola (``s > 0``).
    """
    conic = _real(conic, "axes")
    kind = affine_type(conic)
    if kind not in ("ellipse", "hyperbola"):
        raise DegenerateConfigurationError(
            f"the conic {conic!r} is a {kind}; axes and semi-axes are defined here for real ellipses (not circles, "
            "whose every diameter is an axis) and hyperbolas"
            + ("; a parabola has one axis, see axes()" if kind == "parabola" else "")
        )
    m = conic.matrix
    a, h, c = m[0, 0], m[0, 1], m[1, 1]
    fprime = sympy.radsimp(conic.determinant / sympy.expand(a * c - h**2))
    if is_zero(h):
        pairs = [((Integer(1), Integer(0)), a), ((Integer(0), Integer(1)), c)]
    else:
        r = sympy.sqrt(sympy.expand((a - c) ** 2 + 4 * h**2))
        pairs = [((2 * h, sympy.expand(c - a + s * r)), (a + c + s * r) / 2) for s in (1, -1)]
    out = [(d, sympy.radsimp(-fprime / lam)) for d, lam in pairs]
    if sign(sympy.expand(out[0][1] - out[1][1])) < 0:
        out.reverse()
    return out


def semi_axes(conic: Conic) -> tuple[Expr, Expr]:
    """``(a, b)``: the semi-major and semi-minor axis of a real ellipse (``(r, r)`` for a circle), or the
    transverse and conjugate semi-axis of a hyperbola (``x²/a² − y²/b² = 1`` in its own frame), exact.

    >>> semi_axes(Conic.from_coefficients(1, 0, 4, 0, 0, -4)), semi_axes(Conic.from_coefficients(1, 0, -1, 0, 0, -2))
    ((2, 1), (sqrt(2), sqrt(2)))
    """
    conic = _real(conic, "semi_axes")
    if affine_type(conic) == "circle":
        r = radius(conic)
        return r, r
    (_, s1), (_, s2) = _principal(conic)
    return sympy.sqrt(s1), sympy.sqrt(s2 if sign(s2) > 0 else sympy.radsimp(-s2))


def axes(conic: Conic) -> tuple[Line, ...]:
    """The axes of symmetry: two for a real ellipse (major first) or hyperbola (transverse first), one for a
    parabola (through its focus, towards its ideal point). A circle raises, as every diameter is an axis.

    >>> axes(Conic.from_coefficients(5, 6, 5, 0, 0, -8))     # 5x² + 6xy + 5y² = 8: major axis y = −x
    (Line(1, 1, 0), Line(1, -1, 0))
    """
    conic = _real(conic, "axes")
    if affine_type(conic) == "parabola":
        return (join(foci(conic)[0], center(conic)).canonical(),)
    z = center(conic)
    return tuple(Line._from_exact(cross(z.coords, (d[0], d[1], Integer(0)))).canonical() for d, _ in _principal(conic))


def _conjugate(v: tuple[Expr, ...]) -> tuple[Expr, ...]:
    return tuple(sympy.expand(sympy.conjugate(e)) for e in v)


def foci(conic: Conic) -> tuple[Point, ...]:
    """The real foci: two for a real ellipse or hyperbola (on the major / transverse axis), one for a
    parabola, the centre for a circle. Exact (nested square roots in general). The two foci come in the
    order ``centre − c·u``, ``centre + c·u``.

    A focus is a point whose joins with the circular points ``I`` and ``J`` touch the conic; each
    point returned is checked exactly to be one. For an ellipse or hyperbola they are
    ``centre ± c·u`` along the first axis (unit direction u) with ``c² = s₁ − s₂`` from the squared
    semi-axes of :func:`semi_axes` (``a² − b²`` and ``a² + b²``). For a parabola the tangents from
    ``I`` are ``l∞`` and one more line ``t``: the pair ``(IᵀCI) C − (CI)(CI)ᵀ = l∞ tᵀ + t l∞ᵀ`` gives
    ``t`` by reading off a column, and the focus is ``t ∧ t̄``, where the tangent from ``J`` meets it.

    >>> foci(Conic.from_coefficients(1, 0, 0, 0, -4, 0))       # x² = 4y: the focus (0, 1)
    (Point(0, 1, 1),)
    >>> foci(Conic.from_coefficients(1, 0, -1, 0, 0, -2))      # x² − y² = 2: c² = 2 + 2
    (Point(-2, 0, 1), Point(2, 0, 1))
    """
    conic = _real(conic, "foci")
    kind = affine_type(conic)
    I_, J_ = circular_points()
    if kind == "circle":
        found: list[Point] = [center(conic)]
    elif kind == "parabola":
        C = Matrix(conic.matrix)
        ci = C * Matrix(I_.coords)
        T = (sympy.expand((Matrix(I_.coords).T * ci)[0, 0]) * C - ci * ci.T).applyfunc(sympy.expand)
        t = (T[0, 2], T[1, 2], T[2, 2] / 2)
        found = [_affine(Point._from_exact(cross(t, _conjugate(t))))]
    else:
        (d, s1), (_, s2) = _principal(conic)
        z = center(conic).dehomogenize()
        k = sympy.sqrt(sympy.radsimp((s1 - s2) / (d[0] ** 2 + d[1] ** 2)))
        found = [
            Point._from_exact((*(sympy.radsimp(z[i] + s * k * d[i]) for i in range(2)), Integer(1)))
            for s in (-1, 1)
        ]
    for f in found:
        if not (conic.is_tangent(join(f, I_)) and conic.is_tangent(join(f, J_))):  # pragma: no cover - guard
            raise DegenerateConfigurationError(f"foci: {f!r} could not be verified as a focus of {conic!r}")
    return tuple(found)


# -- conics from metric data -------------------------------------------------------------------------
def _frame(center: Point | tuple[Scalar, Scalar], direction: tuple[Scalar, Scalar], what: str) -> Transformation:
    """The motion taking the origin to ``center`` and the x-axis to ``direction`` = (cos, sin)."""
    if isinstance(center, Point):
        if center.is_ideal:
            raise InvalidCoordinatesError(f"{what}: the centre {center!r} is an ideal point")
        cx, cy = center.dehomogenize()
    else:
        try:
            cx, cy = (to_exact(v) for v in center)
        except (TypeError, ValueError):
            raise ObjectTypeError(f"{what}: the centre must be a Point or a pair (x, y), got {center!r}") from None
    R = rotation(*direction)  # checks cos² + sin² = 1 exactly
    (c, s) = R.matrix[0, 0], R.matrix[1, 0]
    return Transformation([[c, -s, cx], [s, c, cy], [0, 0, 1]])


def _nonzero(value: Scalar, name: str, what: str) -> Expr:
    v = to_exact(value)
    if is_zero(v):
        raise DegenerateConfigurationError(f"{what}: {name} = 0 gives a degenerate conic; lengths must be nonzero")
    return v


def ellipse(center: Point | tuple[Scalar, Scalar], a: Scalar, b: Scalar,
            direction: tuple[Scalar, Scalar] = (1, 0)) -> Conic:
    """The ellipse with the given centre and semi-axes, the a-axis along ``direction = (cos θ, sin θ)``.

    In its own frame ``x²/a² + y²/b² = 1``, i.e. ``b²x² + a²y² − a²b² = 0``; moved by the rotation
    by θ and the translation to the centre (``C' ∝ H⁻ᵀ C H⁻¹``). ``a = b`` is the circle.

    >>> ellipse((1, 2), 3, 2)                         # 4(x − 1)² + 9(y − 2)² = 36
    Conic.from_coefficients(4, 0, 9, -8, -36, 4)
    >>> ellipse((0, 0), 2, 1, direction=(0, 1))       # the long axis vertical: 4x² + y² = 4
    Conic.from_coefficients(4, 0, 1, 0, 0, -4)
    """
    a, b = _nonzero(a, "a", "ellipse"), _nonzero(b, "b", "ellipse")
    C = Conic.from_coefficients(b**2, 0, a**2, 0, 0, -(a**2) * b**2)
    return _frame(center, direction, "ellipse")(C).canonical()


def hyperbola(center: Point | tuple[Scalar, Scalar], a: Scalar, b: Scalar,
              direction: tuple[Scalar, Scalar] = (1, 0)) -> Conic:
    """The hyperbola ``x²/a² − y²/b² = 1`` in the frame with origin ``center`` and x-axis ``direction``.

    >>> hyperbola((0, 0), 1, 1)                       # the rectangular hyperbola x² − y² = 1
    Conic.from_coefficients(1, 0, -1, 0, 0, -1)
    """
    a, b = _nonzero(a, "a", "hyperbola"), _nonzero(b, "b", "hyperbola")
    C = Conic.from_coefficients(b**2, 0, -(a**2), 0, 0, -(a**2) * b**2)
    return _frame(center, direction, "hyperbola")(C).canonical()


def parabola(vertex: Point | tuple[Scalar, Scalar], p: Scalar, direction: tuple[Scalar, Scalar] = (1, 0)) -> Conic:
    """The parabola ``y² = 4px`` in the frame with origin ``vertex`` and x-axis ``direction``: its focus is at
    distance ``p`` from the vertex along ``direction``.

    >>> parabola((0, 0), 1), parabola((0, 0), 1, direction=(0, 1))     # y² = 4x and x² = 4y
    (Conic.from_coefficients(0, 0, 1, -4, 0, 0), Conic.from_coefficients(1, 0, 0, 0, -4, 0))
    """
    p = _nonzero(p, "p", "parabola")
    C = Conic.from_coefficients(0, 0, 1, -4 * p, 0, 0)
    return _frame(vertex, direction, "parabola")(C).canonical()


def conic_from_foci(f1: Point, f2: Point, a: Scalar) -> Conic:
    """The conic with foci ``f1``, ``f2`` and (transverse) semi-axis ``a``: ``|PF₁| ± |PF₂| = 2a``.

    An ellipse when ``2a > |F₁F₂|``, a hyperbola when ``2a < |F₁F₂|``, the circle of radius a when the
    foci coincide. No square root is needed: with ``d_k = |P − F_k|²``, squaring ``√d₁ = 2a ∓ √d₂`` twice
    gives ``16a²d₂ = (4a² + d₂ − d₁)²``, and ``d₂ − d₁`` is linear in P, so this is the conic's equation.
    ``2a = |F₁F₂|`` gives a degenerate conic (the segment's line, doubled):
    :class:`~pgsym.errors.DegenerateConicError`.

    >>> conic_from_foci(Point(-3, 0), Point(3, 0), 5)     # b² = 25 − 9 = 16: x²/25 + y²/16 = 1
    Conic.from_coefficients(16, 0, 25, 0, 0, -400)
    """
    for f in (f1, f2):
        require(f, Point, "conic_from_foci")
        if f.is_ideal:
            raise InvalidCoordinatesError(f"conic_from_foci: the focus {f!r} is an ideal point")
    a = _nonzero(a, "a", "conic_from_foci")
    x, y = sympy.Dummy("x"), sympy.Dummy("y")
    (u1, v1), (u2, v2) = f1.dehomogenize(), f2.dehomogenize()
    d1, d2 = (x - u1) ** 2 + (y - v1) ** 2, (x - u2) ** 2 + (y - v2) ** 2
    poly = sympy.Poly(sympy.expand(16 * a**2 * d2 - (4 * a**2 + d2 - d1) ** 2), x, y)
    coeffs = [poly.coeff_monomial(mono) for mono in (x**2, x * y, y**2, x, y, 1)]
    C = Conic.from_coefficients(*coeffs).canonical()
    if C.is_degenerate:
        raise DegenerateConicError(
            f"conic_from_foci: 2a = {2 * a} equals the distance of the foci, so the 'conic' is the line through "
            "them (the segment F1F2, counted twice); take 2a larger (ellipse) or smaller (hyperbola)"
        )
    return C


def squared_radius(circle: Conic) -> Expr:
    """``r²`` of a real circle: for ``a(x² + y²) + 2dx + 2ey + f = 0`` it is ``(d² + e² − af)/a²``.

    Anything but a real circle (an ellipse, an imaginary or a point circle) raises
    :class:`~pgsym.errors.DegenerateConfigurationError` naming its type.

    >>> squared_radius(Conic.circle(1, 2, 3)), radius(Conic.from_coefficients(2, 0, 2, 0, 0, -1))
    (9, sqrt(2)/2)
    """
    circle = _real(circle, "radius")
    kind = affine_type(circle)
    if kind != "circle":
        raise DegenerateConfigurationError(f"the conic {circle!r} is a {kind}, not a real circle: it has no radius")
    m = circle.matrix
    a, d, e, f = m[0, 0], m[0, 2], m[1, 2], m[2, 2]
    return sympy.radsimp(sympy.expand(d * d + e * e - a * f) / (a * a))


def radius(circle: Conic) -> Expr:
    """The radius of a real circle, exact (a square root where ``r²`` is not a square); see :func:`squared_radius`."""
    return sympy.sqrt(squared_radius(circle))


def cos_intersection_angle(c1: Conic, c2: Conic) -> Expr:
    """The cosine of the angle at which two circles cross: ``(r₁² + r₂² − d²) / (2 r₁ r₂)``, ``d`` the distance
    of the centres (the angle between the radii to a common point, which equals the angle between the tangents
    there). ``0`` means the circles are orthogonal; a value outside [−1, 1] means they do not meet in real points.

    >>> cos_intersection_angle(Conic.circle(0, 0, 1), Conic.circle(1, 1, 1))     # r₁ = r₂ = 1, d² = 2
    0
    """
    r1, r2 = squared_radius(c1), squared_radius(c2)
    d2 = squared_distance(center(c1), center(c2))
    return sympy.radsimp((r1 + r2 - d2) / (2 * sympy.sqrt(r1 * r2)))


def inversion(point: Point, circle: Conic) -> Point:
    """The inverse of a point in a real circle with centre ``O`` and radius ``r``: ``O + r² (X − O)/|X − O|²``.

    The inverse lies on the ray from the centre through the point, at the distance ``r²/|OX|``; points of
    the circle are fixed, an ideal point goes to the centre, and the centre itself (whose inverse is at
    infinity in every direction) raises :class:`~pgsym.errors.CoincidentPointsError`.

    >>> C = Conic.circle(1, 0, 2)                          # centre (1, 0), r² = 4
    >>> inversion(Point(3, 0), C), inversion(Point(2, 0), C), inversion(Point(1, 1, 0), C)
    (Point(3, 0, 1), Point(5, 0, 1), Point(1, 0, 1))
    """
    if not isinstance(point, Point) or not isinstance(circle, Conic):
        raise ObjectTypeError(f"inversion takes a Point and a circle (Conic), got {type(point).__name__} and "
                              f"{type(circle).__name__}")
    o = center(circle)
    r2 = squared_radius(circle)
    if point.is_ideal:
        return o
    (x, y), (ox, oy) = point.dehomogenize(), o.dehomogenize()
    u, v = x - ox, y - oy
    d = sympy.expand(u * u + v * v)
    if is_zero(d):
        raise CoincidentPointsError(f"inversion: {point!r} is the centre of {circle!r}, whose inverse is at infinity")
    return _affine(Point(ox + r2 * u / d, oy + r2 * v / d))
