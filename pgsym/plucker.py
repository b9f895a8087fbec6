"""Lines of projective 3-space P³: Plücker matrices and Plücker coordinates, exactly.

A line of P³ is the join of two distinct points ``A``, ``B`` or the meet of two
distinct planes ``P``, ``Q``. It has four degrees of freedom: six homogeneous
Plücker coordinates, minus one for the overall scale, minus one for the Klein
constraint below.

Conventions (Hartley & Zisserman, *Multiple View Geometry*, §3.2.2)
--------------------------------------------------------------------
* The **Plücker matrix** of the join of ``A`` and ``B`` is the 4×4 skew-symmetric
  matrix ``L = A Bᵀ − B Aᵀ`` of rank 2, with entries ``l_ij = A_i B_j − B_i A_j``
  (indices 1…4; entry ``l_ij`` is ``L[i-1, j-1]`` in code).
* The **dual Plücker matrix** of the meet of ``P`` and ``Q`` is ``L* = P Qᵀ − Q Pᵀ``.
* The **Plücker coordinates** are the six entries above the diagonal, in the order

      (l12, l13, l14, l23, l42, l34)         -- note l42 = −l24.

  ``Line3.coordinates`` returns them in this order, and ``Line3(l12, l13, l14, l23, l42, l34)``
  takes them in this order.
* The **Klein constraint** ``l12 l34 + l13 l42 + l14 l23 = 0`` holds for every line
  (it is the Pfaffian of L; ``det L`` is its square, so it says ``rank L = 2``).
* The **rewrite rule** between ``L`` and ``L*`` is
  ``l12 : l13 : l14 : l23 : l42 : l34 = l*34 : l*42 : l*23 : l*14 : l*13 : l*12``;
  in the order above, the dual coordinates are the primal ones *reversed*. pgsym
  applies it with factor 1, so ``Line3.join(A, B).matrix == A Bᵀ − B Aᵀ`` and
  ``Line3.meet(P, Q).dual_matrix == P Qᵀ − Q Pᵀ`` hold exactly, and ``L L* = 0``.
* The **reciprocal product** of two lines is ``(L|M) = Σ l_ij m*_ij``, the dot product of
  the coordinates of one line with the reversed coordinates of the other; for lines
  ``A ∨ B`` and ``C ∨ D`` it equals ``det[A B C D]``. Two lines meet (are coplanar) iff it is 0.
* **Direction and moment.** For finite points ``A = (a, 1)``, ``B = (b, 1)`` the
  classical pair is ``d = b − a`` and ``m = a × b``. In the order above,
  ``d = (−l14, l42, −l34)`` and ``m = (l23, −l13, l12)``; then ``d · m = 0`` is the
  Klein constraint, up to sign. See :meth:`Line3.direction_moment` and
  :meth:`Line3.from_direction_moment`.

Equality is up to a nonzero scale of the six coordinates, as for every homogeneous object.

>>> from pgsym.space import Point3, Plane
>>> x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
>>> x_axis
Line3(0, 0, -1, 0, 0, 0)
>>> x_axis == Line3.meet(Plane(0, 1, 0, 0), Plane(0, 0, 1, 0))
True
>>> x_axis.intersect_plane(Plane(1, 0, 0, -3)) == Point3(3, 0, 0)
True
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy
from sympy import Expr, ImmutableMatrix, Integer

from . import ring
from .errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
    NotAPencilError,
    NotOnKleinQuadricError,
    NotSkewSymmetricError,
    SkewLinesError,
    UndefinedCrossRatioError,
    ZeroVectorError,
)
from .exact import all_zero, latex
from .homogeneous import HomogeneousVector, Scalar, is_zero, require, to_exact
from .matrices import exact_matrix
from .projective_line import Point1, cross_ratio
from .space import Plane, Point3

__all__ = [
    "COORDINATE_ORDER",
    "Line3",
    "NotAPencilError",
    "NotSkewSymmetricError",
    "cross_ratio_planes",
    "klein_form",
    "meet_lines",
    "plane_through_lines",
    "reciprocal_product",
]

COORDINATE_ORDER: tuple[str, ...] = ("l12", "l13", "l14", "l23", "l42", "l34")
"""Names of the six Plücker coordinates, in the order pgsym stores them."""

# (row, column) of each coordinate in the 4×4 Plücker matrix, 0-based: l12, l13, l14, l23, l42, l34
_POSITIONS: tuple[tuple[int, int], ...] = ((0, 1), (0, 2), (0, 3), (1, 2), (3, 1), (2, 3))






def _wedge(u: Sequence[Expr], v: Sequence[Expr]) -> tuple[Expr, ...]:
    """The six entries ``u_i v_j − v_i u_j`` of ``u vᵀ − v uᵀ``, in the order (12, 13, 14, 23, 42, 34)."""
    w = ring.wedge(u, v)
    return tuple(sympy.expand(w[i][j]) for i, j in _POSITIONS)


def _matrix(coords: Sequence[Expr]) -> ImmutableMatrix:
    """The skew-symmetric 4×4 matrix whose (12, 13, 14, 23, 42, 34) entries are ``coords``."""
    m = sympy.zeros(4, 4)
    for (i, j), c in zip(_POSITIONS, coords, strict=True):
        m[i, j] = c
        m[j, i] = -c
    return ImmutableMatrix(m)


def _klein(coords: Sequence[Expr]) -> Expr:
    l12, l13, l14, l23, l42, l34 = coords
    return sympy.expand(l12 * l34 + l13 * l42 + l14 * l23)




class Line3(HomogeneousVector, kind="line3"):
    """A line of projective 3-space, stored by its six Plücker coordinates ``(l12, l13, l14, l23, l42, l34)``.

    Build one with :meth:`join` (two points), :meth:`meet` (two planes),
    :meth:`from_matrix`, :meth:`from_dual_matrix`, :meth:`from_coordinates` or
    :meth:`from_direction_moment`; ``Line3(l12, l13, l14, l23, l42, l34)`` is the
    same as :meth:`from_coordinates`. Six numbers that violate the Klein constraint
    raise :class:`~pgsym.errors.NotOnKleinQuadricError`. ``==`` compares up to scale.

    >>> Line3(0, 0, 1, 0, 0, 0).matrix      # the x-axis, up to sign
    Matrix([
    [ 0, 0, 0, 1],
    [ 0, 0, 0, 0],
    [ 0, 0, 0, 0],
    [-1, 0, 0, 0]])
    >>> Line3(1, 0, 0, 0, 0, 1)              # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.NotOnKleinQuadricError: ...
    """

    size = 6
    _kind = "line of P³ (six Plücker coordinates l12, l13, l14, l23, l42, l34)"
    ambient_dim = 3
    __slots__ = ()

    @classmethod
    def _check(cls, coords: tuple[Expr, ...]) -> tuple[Expr, ...]:
        coords = super()._check(coords)
        value = _klein(coords)
        if not is_zero(value):
            raise NotOnKleinQuadricError(
                f"the six numbers {tuple(coords)} are no Plücker coordinates of a line: the Klein constraint "
                f"l12*l34 + l13*l42 + l14*l23 = 0 fails (it is {value}); build the line with Line3.join or "
                f"Line3.meet, or check the order (l12, l13, l14, l23, l42, l34) and the sign of l42 = -l24"
            )
        return coords

    @classmethod
    def _from_wedge(cls, coords: tuple[Expr, ...]) -> Line3:
        """Build from coordinates ``u vᵀ − v uᵀ`` already known to be nonzero.

        Such coordinates satisfy the Klein constraint identically, so the check (costly for
        symbolic entries) is skipped.
        """
        obj = cls.__new__(cls)
        obj._coords = coords
        return obj


    @classmethod
    def image(cls, coords: Sequence[Any], H: ring.Action) -> tuple[Any, ...]:
        """The Plücker coordinates of the image line, in any ring: the Plücker matrix maps like a dual conic,
        ``L' = H L Hᵀ`` (``L = A Bᵀ − B Aᵀ`` goes to ``(HA)(HB)ᵀ − (HB)(HA)ᵀ``).

        >>> H = ring.Action([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 1, 0, 1]])
        >>> A, B = (0, 0, 0, 1), (0, 1, 0, 0)                        # the y-axis
        >>> Line3.image(Line3.join(Point3(*A), Point3(*B)).coords, H)
        (0, 0, 0, 0, 1, 0)
        >>> _ == Line3.join(Point3(*H.point(A)), Point3(*H.point(B))).coords
        True
        """
        zero = coords[0] * 0
        m = [[zero] * 4 for _ in range(4)]
        for (i, j), c in zip(_POSITIONS, coords, strict=True):
            m[i][j], m[j][i] = c, -c
        image = H.hyperplane_form(m)
        return tuple(image[i][j] for i, j in _POSITIONS)

    def _transformed_by(self, H: Any) -> Line3:
        """The image line under the transformation ``H`` (checked by ``H.apply``), by :meth:`image`."""
        return type(self)(*(sympy.expand(e) for e in type(self).image(self._coords, H.action)))

    # -- constructions ------------------------------------------------------------------------
    @classmethod
    def join(cls, a: Point3, b: Point3) -> Line3:
        """The line through two distinct points; its Plücker matrix is exactly ``L = A Bᵀ − B Aᵀ``.

        Raises :class:`~pgsym.errors.CoincidentPointsError` when ``a`` and ``b`` are the same point.

        >>> L = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))   # the x-axis
        >>> L.coordinates
        (0, 0, -1, 0, 0, 0)
        >>> L.contains(Point3(5, 0, 0)), L.contains(Point3(1, 0, 0, 0)), L.contains(Point3(0, 1, 0))
        (True, True, False)
        """
        require(a, Point3, "Line3.join", "; use Line3.meet for two planes")
        require(b, Point3, "Line3.join", "; use Line3.meet for two planes")
        coords = _wedge(a.coords, b.coords)
        if all_zero(coords):
            raise CoincidentPointsError(
                f"cannot join {a!r} and {b!r}: they are the same point, so no unique line passes through them"
            )
        return cls._from_wedge(coords)

    @classmethod
    def meet(cls, p: Plane, q: Plane) -> Line3:
        """The line where two distinct planes meet; its dual Plücker matrix is exactly ``L* = P Qᵀ − Q Pᵀ``.

        Parallel planes meet in a line at infinity. The same plane twice raises
        :class:`~pgsym.errors.DependentPlanesError`.

        >>> L = Line3.meet(Plane(0, 0, 1, 0), Plane(0, 0, 1, -1))   # z = 0 and z = 1: parallel
        >>> L.is_at_infinity, L.contains(Point3(1, 1, 0, 0))
        (True, True)
        """
        require(p, Plane, "Line3.meet", "; use Line3.join for two points")
        require(q, Plane, "Line3.meet", "; use Line3.join for two points")
        dual = _wedge(p.coords, q.coords)
        if all_zero(dual):
            raise DependentPlanesError(
                f"cannot meet {p!r} and {q!r}: they are the same plane, so they share every line in it"
            )
        return cls._from_wedge(tuple(reversed(dual)))

    @classmethod
    def from_coordinates(cls, coordinates: Sequence[Scalar]) -> Line3:
        """The line with Plücker coordinates ``(l12, l13, l14, l23, l42, l34)``.

        Raises :class:`~pgsym.errors.DimensionError` unless there are six numbers,
        :class:`~pgsym.errors.ZeroVectorError` for six zeros, and
        :class:`~pgsym.errors.NotOnKleinQuadricError` when ``l12 l34 + l13 l42 + l14 l23 ≠ 0``.

        >>> Line3.from_coordinates([0, 0, 0, 0, 0, 1])   # l34 only: the line through e3 and e4
        Line3(0, 0, 0, 0, 0, 1)
        """
        if isinstance(coordinates, (str, bytes)) or not hasattr(coordinates, "__iter__"):
            raise DimensionError(f"Line3.from_coordinates expects a sequence of six numbers, got {coordinates!r}")
        return cls(*coordinates)

    @classmethod
    def from_matrix(cls, matrix: Any) -> Line3:
        """The line with Plücker matrix ``matrix`` (4×4, skew-symmetric, rank 2).

        Raises :class:`~pgsym.errors.DimensionError` for another shape,
        :class:`NotSkewSymmetricError` unless ``Lᵀ = −L``, :class:`~pgsym.errors.ZeroVectorError`
        for the zero matrix, and :class:`~pgsym.errors.NotOnKleinQuadricError` for rank 4
        (a nonzero skew 4×4 matrix has rank 2 exactly when its Pfaffian, the Klein form, vanishes).

        >>> L = Line3.join(Point3(1, 2, 3), Point3(0, 1, 0, 0))
        >>> Line3.from_matrix(L.matrix) == L
        True
        """
        m = _square4(matrix, "Plücker matrix")
        return cls(*_coords_of(m))

    @classmethod
    def from_dual_matrix(cls, matrix: Any) -> Line3:
        """The line with dual Plücker matrix ``matrix`` (4×4, skew-symmetric, rank 2), by the rewrite rule.

        >>> L = Line3.join(Point3(1, 2, 3), Point3(4, 5, 7))
        >>> Line3.from_dual_matrix(L.dual_matrix) == L
        True
        """
        m = _square4(matrix, "dual Plücker matrix")
        return cls(*reversed(_coords_of(m)))

    @classmethod
    def from_direction_moment(cls, direction: Sequence[Scalar], moment: Sequence[Scalar]) -> Line3:
        """The line with direction ``d`` and moment ``m``; for finite points ``a``, ``b``: ``d = b − a``, ``m = a × b``.

        ``d = 0`` gives a line at infinity. Raises :class:`~pgsym.errors.NotOnKleinQuadricError`
        unless ``d · m = 0``.

        >>> Line3.from_direction_moment((1, 0, 0), (0, 0, 0)) == Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
        True
        """
        try:
            d, m = tuple(direction), tuple(moment)
        except TypeError as err:
            raise DimensionError(f"direction and moment are 3-vectors, got {direction!r} and {moment!r}") from err
        if len(d) != 3 or len(m) != 3:
            raise DimensionError(f"direction and moment are 3-vectors, got {direction!r} and {moment!r}")
        d1, d2, d3 = (to_exact(c) for c in d)
        m1, m2, m3 = (to_exact(c) for c in m)
        # d = (-l14, l42, -l34), m = (l23, -l13, l12)
        return cls._from_exact((m3, -m2, -d1, m1, d2, -d3))

    # -- the three representations -------------------------------------------------------------
    @property
    def coordinates(self) -> tuple[Expr, ...]:
        """The six Plücker coordinates ``(l12, l13, l14, l23, l42, l34)`` as stored (not normalised)."""
        return self._coords

    @property
    def matrix(self) -> ImmutableMatrix:
        """The Plücker matrix ``L`` (4×4, skew-symmetric, rank 2); ``A Bᵀ − B Aᵀ`` for ``Line3.join(A, B)``."""
        return _matrix(self._coords)

    @property
    def dual_coordinates(self) -> tuple[Expr, ...]:
        """The coordinates ``(l*12, l*13, l*14, l*23, l*42, l*34)`` of ``L*``: the primal ones reversed.

        >>> Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)).dual_coordinates   # l*23 = l14 = -1
        (0, 0, 0, -1, 0, 0)
        """
        return tuple(reversed(self._coords))

    @property
    def dual_matrix(self) -> ImmutableMatrix:
        """The dual Plücker matrix ``L*`` by the rewrite rule; ``P Qᵀ − Q Pᵀ`` for ``Line3.meet(P, Q)``.

        >>> L = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
        >>> (L.matrix * L.dual_matrix).is_zero_matrix
        True
        """
        return _matrix(self.dual_coordinates)

    def direction_moment(self) -> tuple[tuple[Expr, Expr, Expr], tuple[Expr, Expr, Expr]]:
        """The direction ``d = (−l14, l42, −l34)`` and moment ``m = (l23, −l13, l12)`` of the line.

        For ``Line3.join(Point3(*a), Point3(*b))`` these are exactly ``b − a`` and ``a × b``.

        >>> Line3.join(Point3(0, 1, 0), Point3(1, 1, 0)).direction_moment()
        ((1, 0, 0), (0, 0, -1))
        """
        l12, l13, l14, l23, l42, l34 = self._coords
        return (-l14, l42, -l34), (l23, -l13, l12)

    # -- incidence ------------------------------------------------------------------------------
    def contains(self, point: Point3) -> bool:
        """True when ``point`` lies on the line: ``L* X = 0``.

        >>> Line3.join(Point3(0, 0, 0), Point3(1, 1, 1)).contains(Point3(2, 2, 2))
        True
        """
        require(point, Point3, "Line3.contains", "; use Line3.lies_in for a plane")
        return all(is_zero(e) for e in self.dual_matrix * point.vector)

    def lies_in(self, plane: Plane) -> bool:
        """True when the line lies in ``plane``: ``L π = 0``.

        >>> Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)).lies_in(Plane(0, 0, 1, 0))
        True
        """
        require(plane, Plane, "Line3.lies_in", "; use Line3.contains for a point")
        return all(is_zero(e) for e in self.matrix * plane.vector)

    def intersect_plane(self, plane: Plane) -> Point3:
        """The point where the line meets ``plane``: ``X = L π``.

        For ``L = A Bᵀ − B Aᵀ`` this is ``X = (Bᵀπ) A − (Aᵀπ) B``. A line parallel to the
        plane meets it in an ideal point. A line lying in the plane raises
        :class:`~pgsym.errors.DependentPlanesError` (the plane and the two planes through
        the line share that line, so they do not fix a point).

        >>> Line3.join(Point3(0, 0, 0), Point3(1, 1, 1)).intersect_plane(Plane(0, 0, 1, -2))
        Point3(2, 2, 2, 1)
        """
        require(plane, Plane, "Line3.intersect_plane", "; use Line3.plane_through_point for a point")
        return Point3._from_nonzero(_times(self.matrix, plane), DependentPlanesError, lambda: (
            f"the line {self!r} lies in the plane {plane!r}, so they share every point of the line "
            "instead of meeting in one; choose a plane that does not contain the line"))

    def plane_through_point(self, point: Point3) -> Plane:
        """The plane spanned by the line and ``point``: ``π = L* X``.

        A point on the line raises :class:`~pgsym.errors.CollinearPointsError` (the point and
        two points of the line are collinear, so they do not fix a plane).

        >>> Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)).plane_through_point(Point3(0, 1, 0))
        Plane(0, 0, 1, 0)
        """
        require(point, Point3, "Line3.plane_through_point", "; use Line3.intersect_plane for a plane")
        return Plane._from_nonzero(_times(self.dual_matrix, point), CollinearPointsError, lambda: (
            f"the point {point!r} lies on the line {self!r}, so infinitely many planes contain both; "
            "choose a point off the line"))

    def meets(self, other: Line3) -> bool:
        """True when the two lines are coplanar, i.e. meet in a point (possibly ideal) or coincide.

        The test is the reciprocal product ``(L|M) = 0`` (see :func:`reciprocal_product`).

        >>> x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
        >>> x_axis.meets(Line3.join(Point3(0, 0, 0), Point3(0, 1, 0)))     # the y-axis
        True
        >>> x_axis.meets(Line3.join(Point3(0, 0, 1), Point3(0, 1, 1)))     # skew
        False
        """
        return is_zero(reciprocal_product(self, other))

    def points(self) -> tuple[Point3, Point3]:
        """Two distinct points spanning the line: two independent columns of ``L``.

        >>> Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)).points()
        (Point3(0, 0, 0, 1), Point3(-1, 0, 0, 0))
        """
        return _two_columns(self.matrix, Point3)

    def planes(self) -> tuple[Plane, Plane]:
        """Two distinct planes whose meet is the line: two independent columns of ``L*``.

        >>> Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)).planes()
        (Plane(0, 0, 1, 0), Plane(0, -1, 0, 0))
        """
        return _two_columns(self.dual_matrix, Plane)

    @property
    def is_at_infinity(self) -> bool:
        """True for a line in the plane at infinity (its direction ``(l14, l24, l34)`` is zero)."""
        return all(is_zero(c) for c in (self._coords[2], self._coords[4], self._coords[5]))

    @property
    def direction(self) -> Point3:
        """The ideal point of the line, ``L π∞ = (l14, l24, l34, 0)``; a line at infinity has none.

        >>> Line3.join(Point3(1, 2, 3), Point3(2, 2, 3)).direction
        Point3(-1, 0, 0, 0)
        """
        if self.is_at_infinity:
            raise DegenerateConfigurationError(
                f"{self!r} lies in the plane at infinity and has no single direction: all its points are ideal"
            )
        return self.intersect_plane(Plane(0, 0, 0, 1))

    # -- rendering --------------------------------------------------------------------------------
    def latex(self) -> str:
        """LaTeX of the Plücker matrix ``L`` (without math delimiters)."""
        return latex(self.matrix, mat_delim="[", mat_str="matrix")


def reciprocal_product(l: Line3, m: Line3) -> Expr:
    """The reciprocal product ``(L|M) = l12 m34 + l34 m12 + l13 m42 + l42 m13 + l14 m23 + l23 m14``.

    It equals ``det[A B C D]`` for ``L = A ∨ B`` and ``M = C ∨ D`` (with the matrices as given
    by :meth:`Line3.join`), so it vanishes exactly when the two lines are coplanar.

    >>> from sympy import Matrix
    >>> A, B, C, D = Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1), Point3(0, 0, 0)
    >>> reciprocal_product(Line3.join(A, B), Line3.join(C, D)) == Matrix([A, B, C, D]).det()
    True
    """
    require(l, Line3, "reciprocal_product")
    require(m, Line3, "reciprocal_product")
    return sympy.expand(sum((a * b for a, b in zip(l.coordinates, m.dual_coordinates, strict=True)), Integer(0)))


def _meeting(l: Line3, m: Line3, function: str, what: str) -> ImmutableMatrix:
    """``L M*`` for two distinct lines that meet: the rank-one matrix ``X πᵀ`` of their common point X and plane π.

    With X on both lines, ``L = X Bᵀ − B Xᵀ`` for a second point B of l, and ``M* X = 0`` gives
    ``L M* = X (Bᵀ M*)``: a multiple of X in every column, and ``Bᵀ M* = −(M* B)ᵀ``, the plane through m and
    B (nonzero as B is off m), in every row.
    """
    for name, line in (("first", l), ("second", m)):
        require(line, Line3, function, f"; pass the {name} line as a Line3 (Line3.join of two points)")
    if l == m:
        raise CoincidentLinesError(
            f"{function}: {l!r} and {m!r} are the same line, which has every one of its points and lies in every "
            f"plane through it: two equal lines have no single {what}; pass two distinct lines")
    product = reciprocal_product(l, m)
    if not is_zero(product):
        raise SkewLinesError(
            f"{function}: the lines {l!r} and {m!r} are skew (their reciprocal product is {product}, not 0): they "
            f"do not meet and lie in no common plane, so they have no {what}; pass two coplanar lines")
    return ImmutableMatrix((l.matrix * m.dual_matrix).applyfunc(sympy.expand))


def meet_lines(l: Line3, m: Line3) -> Point3:
    """The point where two distinct coplanar lines of space meet (ideal when they are parallel): a nonzero column
    of ``L M* = X πᵀ``.

    Skew lines raise :class:`~pgsym.errors.SkewLinesError`, equal lines
    :class:`~pgsym.errors.CoincidentLinesError`. The float kernel is :func:`pgsym.numeric.meet_lines`.

    >>> x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    >>> meet_lines(x_axis, Line3.join(Point3(2, 0, 0), Point3(2, 1, 0))).dehomogenize()    # the line x = 2, z = 0
    (2, 0, 0)
    >>> meet_lines(x_axis, Line3.join(Point3(0, 0, 1), Point3(0, 1, 1)))       # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.SkewLinesError: meet_lines: the lines ... are skew (their reciprocal product is 1, not 0): ...
    """
    product = _meeting(l, m, "meet_lines", "meet")
    return Point3._from_exact(next(c for c in (tuple(product[:, k]) for k in range(4)) if not all_zero(c)))


def plane_through_lines(l: Line3, m: Line3) -> Plane:
    """The plane spanned by two distinct lines of space that meet (or are parallel): a nonzero row of
    ``L M* = X πᵀ``.

    Skew lines raise :class:`~pgsym.errors.SkewLinesError`, equal lines
    :class:`~pgsym.errors.CoincidentLinesError`. The float kernel is :func:`pgsym.numeric.plane_through_lines`.

    >>> x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    >>> plane_through_lines(x_axis, Line3.join(Point3(2, 0, 0), Point3(2, 1, 0))) == Plane(0, 0, 1, 0)    # z = 0
    True
    >>> plane_through_lines(x_axis, Line3.join(Point3(0, 5, 0), Point3(1, 5, 0))) == Plane(0, 0, 1, 0)    # parallel
    True
    """
    product = _meeting(l, m, "plane_through_lines", "common plane")
    return Plane._from_exact(next(r for r in (tuple(product[k, :]) for k in range(4)) if not all_zero(r)))


def klein_form(coordinates: Sequence[Scalar]) -> Expr:
    """The Klein quadratic form ``l12 l34 + l13 l42 + l14 l23`` of six numbers (zero exactly for lines).

    >>> klein_form([1, 0, 0, 0, 0, 1]), klein_form(Line3.join(Point3(1, 2, 3), Point3(4, 5, 6)).coordinates)
    (1, 0)
    """
    values = tuple(to_exact(c) for c in coordinates)
    if len(values) != 6:
        raise DimensionError(f"the Klein form takes six Plücker coordinates, got {len(values)}: {values}")
    return _klein(values)


def cross_ratio_planes(p1: Plane, p2: Plane, p3: Plane, p4: Plane) -> Expr:
    """The cross-ratio of four planes through one line (a pencil of planes).

    A transversal line that does not meet the common axis cuts the four planes in four
    collinear points; the result is their cross-ratio
    ``(X1, X2; X3, X4) = [X1 X3][X2 X4] / ([X1 X4][X2 X3])`` along the transversal, the
    convention of :func:`pgsym.projective_line.cross_ratio`. It does not depend on the
    transversal. pgsym uses the coordinate line ``e_i ∨ e_j`` for the first pair ``(i, j)``
    whose complementary Plücker coordinate of the axis is nonzero; the plane ``π`` cuts
    it in ``π_j e_i − π_i e_j``, with coordinates ``(π_j, −π_i)`` along it.

    Raises :class:`NotAPencilError` when the planes do not all contain one line, and
    :class:`~pgsym.errors.UndefinedCrossRatioError` when they are all equal or when the
    cross-ratio is undefined (``p1 = p4`` or ``p2 = p3``).

    >>> # four planes through the z-axis: x = 0, y = 0, x - y = 0, x + y = 0
    >>> cross_ratio_planes(Plane(1, 0, 0, 0), Plane(0, 1, 0, 0), Plane(1, -1, 0, 0), Plane(1, 1, 0, 0))
    -1
    """
    planes = (p1, p2, p3, p4)
    for p in planes:
        require(p, Plane, "cross_ratio_planes", "; pass four planes of one pencil")
    axis = None
    for q in planes[1:]:
        if p1 != q:
            axis = Line3.meet(p1, q)
            break
    if axis is None:
        raise UndefinedCrossRatioError(
            f"the four planes are all the same plane {p1!r}: they contain infinitely many common lines "
            f"and have no cross-ratio; pass planes of which at least two differ"
        )
    for k, p in enumerate(planes, start=1):
        if not axis.lies_in(p):
            raise NotAPencilError(
                f"plane {k}, {p!r}, does not contain the line {axis!r} common to the others, so the four planes "
                f"are not a pencil and have no cross-ratio; pass four planes through one line"
            )
    # the coordinate line e_i ∨ e_j has the single coordinate l_ij; its reciprocal product with
    # the axis is the axis' complementary coordinate, so pick a nonzero one.
    complementary = tuple(reversed(axis.coordinates))
    k = next(k for k, c in enumerate(complementary) if not is_zero(c))
    i, j = _POSITIONS[k]
    points = [Point1(p.coords[j], -p.coords[i]) for p in planes]
    return cross_ratio(*points)


def _square4(matrix: Any, what: str) -> ImmutableMatrix:
    m = exact_matrix(matrix, shape=(4, 4), what=f"a {what}")
    if not all(is_zero(m[i, j] + m[j, i]) for i in range(4) for j in range(i, 4)):
        raise NotSkewSymmetricError(
            f"a {what} is skew-symmetric (its transpose is its negative), and this one is not:\n{m};\n"
            f"build it as A*B.T - B*A.T from two points (or P*Q.T - Q*P.T from two planes)"
        )
    if all_zero(m):
        raise ZeroVectorError(f"the zero matrix is no {what}: a line needs a nonzero matrix of rank 2")
    return m


def _times(m: ImmutableMatrix, x: HomogeneousVector) -> tuple[Expr, ...]:
    """``M x``, expanded."""
    return tuple(sympy.expand(e) for e in m * x.vector)


def _coords_of(m: ImmutableMatrix) -> tuple[Expr, ...]:
    return tuple(m[i, j] for i, j in _POSITIONS)


def _two_columns(m: ImmutableMatrix, cls: type) -> tuple[Any, Any]:
    columns = [tuple(sympy.expand(e) for e in m[:, k]) for k in range(4)]
    nonzero = [c for c in columns if not all_zero(c)]
    first = nonzero[0]
    for c in nonzero[1:]:
        if not all(is_zero(first[a] * c[b] - first[b] * c[a]) for a in range(4) for b in range(a + 1, 4)):
            return cls._from_exact(first), cls._from_exact(c)
    raise AssertionError("a Plücker matrix of rank 2 has two independent columns")  # pragma: no cover
