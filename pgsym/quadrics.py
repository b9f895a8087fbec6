"""Quadrics of projective 3-space: surfaces ``Xᵀ Q X = 0`` with a symmetric 4×4 matrix ``Q``.

A quadric has 9 degrees of freedom: the 10 independent entries of a symmetric
4×4 matrix, less one for the overall scale. The plane ``π = Q X`` is the polar
plane of the point ``X``; when ``X`` lies on the quadric it is the tangent
plane there. A quadric is degenerate when ``det Q = 0`` (cones, pairs of
planes, ...).

>>> from pgsym.quadrics import Quadric
>>> from pgsym.space import Point3
>>> S = Quadric.sphere((0, 0, 0), 1)
>>> S.contains(Point3(0, 0, 1)), S.tangent_plane(Point3(0, 0, 1))
(True, Plane(0, 0, 1, -1))

Beside the point quadric there is the dual quadric ``π ᵀ Q* π = 0`` of planes
(:class:`DualQuadric`): the tangent planes of a non-degenerate ``Q`` form ``Q* = adj Q``,
and the absolute dual quadric ``Q*∞ = diag(1, 1, 1, 0)`` of the metric is a rank-3 one.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy
from sympy import Expr

from .errors import (
    CoincidentPointsError,
    DegenerateConicError,
    DimensionError,
    IdealPointError,
    InvalidCoordinatesError,
    LineOnQuadricError,
    NotASphereError,
    NotOnQuadricError,
    ObjectTypeError,
)
from .exact import sign
from .homogeneous import Scalar, is_zero, require, to_exact
from .linalg import nullspace_exact
from .matrices import adjugate
from .plucker import Line3
from .space import Plane, Point3
from .symmetric_form import DualForm, SymmetricForm, roots_on_line

__all__ = ["DualQuadric", "LineOnQuadricError", "NotASphereError", "NotOnQuadricError", "Quadric"]


def _triple(values: Sequence[Scalar], what: str) -> tuple[Expr, Expr, Expr]:
    try:
        a, b, c = (to_exact(v) for v in values)
    except (TypeError, ValueError):
        raise DimensionError(f"{what} takes 3 coordinates (x, y, z), got {values!r}") from None
    return a, b, c


def _finite(p: Point3 | Sequence[Scalar], what: str) -> tuple[Expr, Expr, Expr]:
    """The Euclidean coordinates of a finite point (a Point3 or three numbers)."""
    if isinstance(p, Point3):
        if p.is_ideal:
            raise IdealPointError(f"{what} must be a finite point, got the ideal point {p!r}")
        x, y, z, w = p.coords
        return sympy.cancel(x / w), sympy.cancel(y / w), sympy.cancel(z / w)
    return _triple(p, what)


def _around_point(a: Sequence[Expr], M3: Any, corner: Expr = sympy.S.Zero) -> sympy.Matrix:
    """``Bᵀ M3 B + corner e4 e4ᵀ`` with ``B = [I | −a]``: the form ``yᵀ M3 y + corner w²`` in ``y = x − w a``."""
    B = sympy.Matrix([[1, 0, 0, -a[0]], [0, 1, 0, -a[1]], [0, 0, 1, -a[2]]])
    Q = B.T * sympy.Matrix(M3) * B
    Q[3, 3] += corner
    return Q.applyfunc(sympy.expand)


class Quadric(SymmetricForm, kind="quadric"):
    """A quadric surface ``Xᵀ Q X = 0`` of P³, from a symmetric 4×4 matrix.

    The matrix entries are exact (integers, fractions, symbols). Two quadrics
    are equal when their matrices are proportional. An asymmetric matrix is
    rejected with :class:`InvalidCoordinatesError` (only the symmetric part
    ``(M + Mᵀ)/2`` matters for the equation; pass that if it is what you mean),
    a matrix of the wrong size with :class:`DimensionError`, the zero matrix
    with :class:`ZeroVectorError` (the checks of :class:`~pgsym.symmetric_form.SymmetricForm`).

    >>> Q = Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 0]])   # the cone x² + y² = z²
    >>> Q.rank, Q.is_degenerate, Q.contains(Point3(3, 4, 5))
    (3, True, True)
    >>> Q == Quadric(2 * Q.matrix)
    True

    **How a quadric transforms.** Under a homography ``X' = H X`` the image quadric is
    ``Q' = H⁻ᵀ Q H⁻¹`` (so that ``X'ᵀ Q' X' = Xᵀ Q X``), and the dual quadric of its
    tangent planes maps by ``Q*' = H Q* Hᵀ``; pgsym uses ``adj H`` for ``H⁻¹`` (same
    scale class, no division). The two rules agree: the image of the dual is the dual
    of the image.

    >>> from pgsym.transformations import Transformation
    >>> H = Transformation([[2, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    >>> S = Quadric.sphere((0, 0, 0), 1)
    >>> Hinv = H.matrix.inv()
    >>> H(S) == Quadric(Hinv.T * S.matrix * Hinv), H(S.dual()) == DualQuadric(H.matrix * S.dual().matrix * H.matrix.T)
    (True, True)
    >>> H(S.dual()) == H(S).dual() and H(S).contains(H(Point3(0, 0, 1)))
    True
    """

    __slots__ = ()
    size = 4
    ambient_dim = 3
    _kind = "quadric"

    # -- constructors ---------------------------------------------------------------------
    @classmethod
    def sphere(cls, center: Sequence[Scalar], radius: Scalar) -> Quadric:
        """The sphere ``(x-a)² + (y-b)² + (z-c)² = r²`` with ``center = (a, b, c)``.

        Its matrix is ``[[I, -c], [-cᵀ, |c|² - r²]]``. The radius must be nonzero
        (a zero radius gives a point-cone, build it with :class:`Quadric` directly).

        >>> Quadric.sphere((1, 2, 3), 2).matrix.tolist()
        [[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3], [-1, -2, -3, 10]]
        """
        a, b, c = _triple(center, "the centre of a sphere")
        r = to_exact(radius)
        if is_zero(r):
            raise InvalidCoordinatesError("a sphere needs a nonzero radius; radius 0 gives a degenerate point-cone")
        last = sympy.expand(a**2 + b**2 + c**2 - r**2)
        return cls(
            [
                [1, 0, 0, -a],
                [0, 1, 0, -b],
                [0, 0, 1, -c],
                [-a, -b, -c, last],
            ]
        )

    # -- geometry -----------------------------------------------------------------------------
    def _value(self, X: Point3) -> Expr:
        require(X, Point3, "Quadric")
        return self._form(X.coords, X.coords)

    def contains(self, X: Point3) -> bool:
        """True when ``Xᵀ Q X = 0`` (identically, for symbols).

        >>> Quadric.sphere((0, 0, 0), 5).contains(Point3(3, 4, 0))
        True
        """
        return is_zero(self._value(X))

    def polar(self, X: Point3) -> Plane:
        """The polar plane ``π = Q X`` of a point.

        For a point on the quadric this is the tangent plane. Raises
        :class:`DegenerateConicError` when ``Q X = 0`` (``X`` is a vertex of a
        degenerate quadric, whose polar is undefined).

        >>> Quadric.sphere((0, 0, 0), 1).polar(Point3(0, 0, 2))   # the plane z = 1/2
        Plane(0, 0, 2, -1)
        """
        require(X, Point3, "Quadric.polar")
        return Plane._from_nonzero(self._image(X.coords), DegenerateConicError, lambda: (
            f"Q X = 0 for X = {X!r}: the point is a singular point (vertex) of this degenerate quadric, "
            "so it has no polar or tangent plane"))

    def tangent_plane(self, X: Point3) -> Plane:
        """The tangent plane ``π = Q X`` at a point ``X`` of the quadric.

        Raises :class:`NotOnQuadricError` when ``X`` is not on the quadric (use
        :meth:`polar` for the polar plane of such a point) and
        :class:`DegenerateConicError` at a vertex of a degenerate quadric.

        >>> Quadric.sphere((1, 1, 1), 1).tangent_plane(Point3(2, 1, 1))   # the plane x = 2
        Plane(1, 0, 0, -2)
        """
        if not self.contains(X):
            raise NotOnQuadricError(
                f"{X!r} does not lie on the quadric (XᵀQX = {self._value(X)} ≠ 0), so it has no tangent plane "
                f"there; use polar() for the polar plane of a point off the quadric"
            )
        return self.polar(X)

    def equation(self, x: Expr | None = None, y: Expr | None = None, z: Expr | None = None) -> Expr:
        """The inhomogeneous equation ``XᵀQX`` at ``X = (x, y, z, 1)``, expanded.

        >>> Quadric.sphere((0, 0, 1), 2).equation()
        x**2 + y**2 + z**2 - 2*z - 3
        """
        x = sympy.Symbol("x") if x is None else x
        y = sympy.Symbol("y") if y is None else y
        z = sympy.Symbol("z") if z is None else z
        return self._value(Point3(x, y, z))

    # -- cones and cylinders -------------------------------------------------------------------------
    @classmethod
    def cone(cls, apex: Point3 | Sequence[Scalar], base_center: Point3 | Sequence[Scalar], radius: Scalar) -> Quadric:
        """The right circular cone with ``apex`` through the circle of ``radius`` about ``base_center``.

        The circle lies in the plane through ``base_center`` perpendicular to the axis
        ``d = base_center − apex``. With ``h² = |d|²``, a point ``X`` is on the cone when
        the angle between ``X − apex`` and ``d`` has ``cos² = h² / (h² + r²)``:
        ``((X − a)·d)² (h² + r²) = h⁴ |X − a|²`` — rational in the data, no square root.
        The apex is the null vector of the rank-3 matrix.

        >>> K = Quadric.cone((0, 0, 0), (0, 0, 1), 1)      # x² + y² = z²
        >>> K.equation(), K.apex, K.kind_of_quadric()
        (-x**2 - y**2 + z**2, Point3(0, 0, 0, 1), 'cone')
        """
        a = _finite(apex, "the apex of a cone")
        c = _finite(base_center, "the centre of the base circle")
        r = to_exact(radius)
        d = sympy.Matrix([c[i] - a[i] for i in range(3)])
        h2 = sympy.expand((d.T * d)[0])
        if is_zero(h2) or is_zero(r):
            raise InvalidCoordinatesError(
                f"a cone needs an apex apart from the base centre and a nonzero radius, got apex {a}, base centre "
                f"{c}, radius {r}"
            )
        return cls(_around_point(a, (h2 + r**2) * d * d.T - h2**2 * sympy.eye(3)))

    @classmethod
    def cylinder(cls, point: Point3 | Sequence[Scalar], direction: Sequence[Scalar], radius: Scalar) -> Quadric:
        """The circular cylinder of ``radius`` about the axis through ``point`` with ``direction`` u.

        A point is at distance r from the axis when ``|y|²|u|² − (y·u)² = r²|u|²`` with
        ``y = X − point``. Its apex is the ideal point ``(u, 0)``: a cylinder is a cone with
        its apex at infinity.

        >>> Z = Quadric.cylinder((0, 0, 0), (0, 0, 1), 2)    # x² + y² = 4
        >>> Z.equation(), Z.apex, Z.kind_of_quadric()
        (x**2 + y**2 - 4, Point3(0, 0, 1, 0), 'cylinder')
        """
        a = _finite(point, "a point of the axis")
        u = sympy.Matrix(_triple(direction, "the direction of a cylinder"))
        r = to_exact(radius)
        u2 = sympy.expand((u.T * u)[0])
        if is_zero(u2) or is_zero(r):
            raise InvalidCoordinatesError(
                f"a cylinder needs a direction u with |u|² ≠ 0 and a nonzero radius, got u = {tuple(u)}, radius {r}"
            )
        return cls(_around_point(a, u2 * sympy.eye(3) - u * u.T, -(r**2) * u2))

    @property
    def apex(self) -> Point3:
        """The apex (vertex) of a rank-3 quadric: the null vector of ``Q``, an ideal point for a cylinder.

        Raises :class:`~pgsym.errors.DegenerateConicError` unless the rank is 3 (a non-degenerate
        quadric has no singular point; a plane pair has a whole line of them).

        >>> Quadric([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]).apex   # x² − y² + 1 = 0
        Point3(0, 0, 1, 0)
        """
        if self.rank != 3:
            raise DegenerateConicError(
                f"only a quadric of rank 3 (a cone or cylinder) has one apex; {self!r} has rank {self.rank}"
            )
        return Point3._from_exact(nullspace_exact(self._matrix)[0])

    @property
    def is_cone(self) -> bool:
        """True for a rank-3 quadric with a finite apex (real or imaginary cone)."""
        return self.rank == 3 and not self.apex.is_ideal

    @property
    def is_cylinder(self) -> bool:
        """True for a rank-3 quadric whose apex is ideal (elliptic, hyperbolic or parabolic cylinder).

        >>> Quadric.cylinder((1, 2, 3), (1, 1, 0), 1).is_cylinder, Quadric.sphere((0, 0, 0), 1).is_cylinder
        (True, False)
        """
        return self.rank == 3 and self.apex.is_ideal

    def kind_of_quadric(self) -> str:
        """The projective type over ℝ from the rank and the signature (real numeric entries).

        ``'oval quadric'`` (sphere, ellipsoid, paraboloid, hyperboloid of two sheets; signature
        (3, 1)), ``'ruled quadric'`` (hyperboloid of one sheet, hyperbolic paraboloid; (2, 2)),
        ``'imaginary quadric'`` (no real point; (4, 0)), ``'cone'`` / ``'cylinder'`` (rank 3,
        (2, 1), apex finite / ideal), ``'imaginary cone'`` (rank 3, (3, 0): the apex is its only
        real point; ``'imaginary cylinder'`` when that apex is ideal), ``'plane pair'`` (rank 2,
        (1, 1)), ``'complex plane pair'`` (rank 2, (2, 0): conjugate planes through a real line) and
        ``'double plane'`` (rank 1). Symbolic entries raise :class:`~pgsym.errors.UndecidableError`.

        >>> Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]]).kind_of_quadric()
        'ruled quadric'
        """
        p, n = self.signature()
        rank = p + n
        if rank == 4:
            return {(4, 0): "imaginary quadric", (3, 1): "oval quadric", (2, 2): "ruled quadric"}[(p, n)]
        if rank == 3:
            if n == 0:
                return "imaginary cone" if not self.apex.is_ideal else "imaginary cylinder"
            return "cylinder" if self.apex.is_ideal else "cone"
        if rank == 2:
            return "plane pair" if n == 1 else "complex plane pair"
        return "double plane"

    def planes(self) -> tuple[Plane, Plane]:
        """The two planes of a quadric of rank 2 (exact; complex conjugate for ``x² + y² = 0``), a double plane twice.

        Raises :class:`~pgsym.errors.DegenerateConicError` for rank 3 or 4.

        >>> Quadric([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]).planes()     # 2xy = 0
        (Plane(1, 0, 0, 0), Plane(0, 1, 0, 0))
        >>> Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]).planes()     # x² + y² = 0
        (Plane(1, -I, 0, 0), Plane(1, I, 0, 0))
        """
        a, b = self._split()
        return Plane._from_exact(a).canonical(), Plane._from_exact(b).canonical()

    # -- spheres ---------------------------------------------------------------------------------------
    def _sphere_parts(self) -> tuple[tuple[Expr, Expr, Expr], Expr]:
        m = self._matrix
        k = m[0, 0]
        if is_zero(k) or not all(is_zero(m[i, i] - k) for i in (1, 2)) or not all(
            is_zero(m[i, j]) for i in range(3) for j in range(3) if i != j
        ):
            raise NotASphereError(
                f"{self!r} is no sphere: a sphere's matrix is a multiple of [[I, −c], [−cᵀ, |c|² − r²]] (equal "
                "diagonal x², y², z² coefficients, no xy, xz or yz terms)"
            )
        c = tuple(sympy.cancel(-m[i, 3] / k) for i in range(3))
        r2 = sympy.cancel(sum(ci**2 for ci in c) - m[3, 3] / k)
        return c, r2  # type: ignore[return-value]

    def sphere_center(self) -> Point3:
        """The centre of a sphere (also of a point-sphere or imaginary sphere: the pole of the plane at infinity).

        >>> Quadric.sphere((1, -2, 3), 5).sphere_center()
        Point3(1, -2, 3, 1)
        """
        return Point3(*self._sphere_parts()[0])

    def sphere_radius(self) -> Expr:
        """The radius ``r > 0`` of a real sphere (exact; a square root when r² is not a rational square).

        Raises :class:`~pgsym.errors.NotASphereError` for a quadric that is not a sphere, and for
        the spheres with ``r² = 0`` (a point-cone) or ``r² < 0`` (no real point).

        >>> Quadric.sphere((0, 0, 0), sympy.sqrt(3)).sphere_radius()
        sqrt(3)
        >>> Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]).sphere_radius()  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        pgsym.errors.NotASphereError: ...
        """
        _, r2 = self._sphere_parts()
        if r2.free_symbols:
            return sympy.sqrt(r2)
        sg = sign(r2)
        if sg <= 0:
            raise NotASphereError(
                f"{self!r} has the form of a sphere with r² = {r2}: "
                + ("a point-cone (radius 0), not a sphere" if sg == 0 else "an imaginary sphere with no real point")
            )
        return sympy.sqrt(r2)

    # -- lines --------------------------------------------------------------------------------------
    def _line_points(self, line: Line3 | Point3, other: Point3 | None) -> tuple[tuple[Expr, ...], tuple[Expr, ...]]:
        if other is None:
            if not isinstance(line, Line3):
                raise ObjectTypeError(
                    f"a quadric meets a Line3 or the line through two Point3s, got {type(line).__name__} {line!r}"
                )
            p, q = line.points()
        else:
            require(line, Point3, "Quadric.intersections")
            require(other, Point3, "Quadric.intersections")
            p, q = line, other
            if p == q:
                raise CoincidentPointsError(f"the two points {p!r} and {q!r} coincide: they span no line")
        return p.coords, q.coords

    def restricted_form(self, line: Line3 | Point3, other: Point3 | None = None) -> tuple[Expr, Expr, Expr]:
        """``(A, B, C)`` with ``Q(s p + t q) = A s² + 2B st + C t²`` for two points p, q spanning the line.

        The points are the two given, or :meth:`Line3.points` of a line. The line is tangent
        exactly when ``B² − A C = 0``, and lies on the quadric when ``A = B = C = 0``.

        >>> Quadric.sphere((0, 0, 0), 1).restricted_form(Point3(0, 0, 0), Point3(1, 0, 0))   # s·O + t·(1, 0, 0)
        (-1, -1, 0)
        """
        p, q = self._line_points(line, other)
        return self._form(p, p), self._form(p, q), self._form(q, q)

    def contains_line(self, line: Line3 | Point3, other: Point3 | None = None) -> bool:
        """True when every point of the line lies on the quadric (a ruling, or a line of a plane pair).

        >>> H = Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]])   # x² + y² = z² + 1
        >>> H.contains_line(Point3(1, 0, 0), Point3(1, 1, 1))
        True
        """
        return all(is_zero(v) for v in self.restricted_form(line, other))

    def is_tangent(self, line: Line3 | Point3, other: Point3 | None = None) -> bool:
        """True when the line meets the quadric in a double point (``B² − AC = 0``).

        A line on the quadric counts as tangent too (every point of it is a double point).

        >>> S = Quadric.sphere((0, 0, 0), 1)
        >>> S.is_tangent(Point3(1, 0, 0), Point3(1, 1, 0)), S.is_tangent(Point3(0, 0, 0), Point3(1, 1, 0))
        (True, False)
        """
        a, b, c = self.restricted_form(line, other)
        return is_zero(sympy.expand(b**2 - a * c))

    def intersections(self, line: Line3 | Point3, other: Point3 | None = None) -> tuple[Point3, ...]:
        """The points where a line meets the quadric: two (exact, possibly irrational or complex) or one if tangent.

        The line is a :class:`~pgsym.plucker.Line3` or given by two points. Raises
        :class:`~pgsym.errors.LineOnQuadricError` when the line lies on the quadric. Use
        :meth:`real_intersections` for the real points only.

        >>> S = Quadric.sphere((0, 0, 0), 1)
        >>> [p.dehomogenize() for p in S.intersections(Line3.join(Point3(0, 0, 0), Point3(1, 1, 1)))]
        [(sqrt(3)/3, sqrt(3)/3, sqrt(3)/3), (-sqrt(3)/3, -sqrt(3)/3, -sqrt(3)/3)]
        >>> S.intersections(Point3(1, 0, 0), Point3(1, 1, 0))          # the tangent x = 1, z = 0
        (Point3(1, 0, 0, 1),)
        """
        p, q = self._line_points(line, other)
        a, b, c = self._form(p, p), self._form(p, q), self._form(q, q)
        if is_zero(a) and is_zero(b) and is_zero(c):
            raise LineOnQuadricError(f"the line lies on the quadric {self!r}: every point of it is common to both")
        return tuple(Point3._from_exact(x) for x in roots_on_line(a, b, c, p, q))

    def real_intersections(self, line: Line3 | Point3, other: Point3 | None = None) -> tuple[Point3, ...]:
        """The real points where a real line meets a real quadric: none, one (tangent) or two.

        The count is the sign of the discriminant ``B² − AC``, decided exactly
        (:func:`pgsym.exact.sign`; symbolic data raise :class:`~pgsym.errors.UndecidableError`).

        >>> S = Quadric.sphere((0, 0, 0), 1)
        >>> len(S.real_intersections(Point3(2, 0, 0), Point3(2, 1, 0))), len(S.real_intersections(Point3(0, 0, 0),
        ...                                                                      Point3(0, 3, 4)))
        (0, 2)
        """
        a, b, c = self.restricted_form(line, other)
        if not (is_zero(a) and is_zero(b) and is_zero(c)) and sign(sympy.expand(b**2 - a * c)) < 0:
            return ()
        return self.intersections(line, other)

    # -- duality ------------------------------------------------------------------------------------
    def dual(self) -> DualQuadric:
        """The dual quadric ``Q* = adj Q`` of the tangent planes (Q non-degenerate).

        A degenerate quadric raises :class:`~pgsym.errors.DegenerateConicError` (its tangent
        planes do not form a quadric: for a cone they all pass through the apex).

        >>> Quadric.sphere((0, 0, 0), 1).dual()
        DualQuadric([[-1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]])
        """
        if self.is_degenerate:
            raise DegenerateConicError(
                f"{self!r} is degenerate (rank {self.rank}), so its tangent planes do not form a dual quadric"
            )
        return DualQuadric._from_exact(adjugate(self._matrix))


class DualQuadric(DualForm, SymmetricForm, kind="dual_quadric"):
    """A dual quadric: the planes π with ``πᵀ Q* π = 0``, from a symmetric 4×4 matrix.

    For a non-degenerate quadric Q its tangent planes form ``Q* = adj Q``; degenerate dual
    quadrics are allowed (the absolute dual quadric ``Q*∞`` has rank 3). It transforms by
    ``Q*' = H Q* Hᵀ``.

    >>> Qs = Quadric.sphere((0, 0, 0), 2).dual()
    >>> Qs.contains_plane(Plane(0, 0, 1, -2)), Qs.contains_plane(Plane(0, 0, 1, -1))
    (True, False)
    """

    __slots__ = ()
    size = 4
    ambient_dim = 3
    _kind = "dual quadric"

    @classmethod
    def absolute(cls) -> DualQuadric:
        """The absolute dual quadric ``Q*∞ = diag(1, 1, 1, 0)`` (:func:`pgsym.metric.absolute_dual_quadric`).

        Its planes are those tangent to the absolute conic Ω∞; a similarity fixes it.

        >>> DualQuadric.absolute().rank, DualQuadric.absolute().contains_plane(Plane(1, sympy.I, 0, 5))
        (3, True)
        """
        return cls(sympy.diag(1, 1, 1, 0))

    def _repr_latex_(self) -> str:
        return f"$Q^{{*}} = {self.latex()}$"

    def value(self, plane: Plane) -> Expr:
        """``πᵀ Q* π``, expanded.

        >>> DualQuadric.absolute().value(Plane(1, 2, 2, 7))
        9
        """
        require(plane, Plane, "DualQuadric.value")
        return self._form(plane.coords, plane.coords)

    def contains_plane(self, plane: Plane) -> bool:
        """True when ``πᵀ Q* π = 0``: for the dual of a quadric Q, when π is tangent to Q."""
        return is_zero(self.value(plane))

    def dual(self) -> Quadric:
        """The point quadric ``adj Q*`` whose tangent planes these are (Q* non-degenerate).

        ``adj(adj Q) = det(Q)² Q`` for 4×4 matrices, so ``Q.dual().dual() == Q``.

        >>> Quadric.sphere((1, 2, 3), 4).dual().dual() == Quadric.sphere((1, 2, 3), 4)
        True
        """
        if self.is_degenerate:
            raise DegenerateConicError(
                f"{self!r} is degenerate (rank {self.rank}): its planes are not the tangent planes of a point quadric"
            )
        return Quadric._from_exact(adjugate(self._matrix))
