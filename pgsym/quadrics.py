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
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy
from sympy import Expr, ImmutableMatrix, Matrix

from .errors import (
    DegenerateConicError,
    DimensionError,
    InvalidCoordinatesError,
    NotOnQuadricError,
    ObjectTypeError,
    ZeroVectorError,
)
from .exact import all_zero, latex
from .homogeneous import Scalar, _format_entry, is_zero, to_exact
from .kinds import Kind
from .space import Plane, Point3

__all__ = ["NotOnQuadricError", "Quadric"]


def _exact_square(M: Any, size: int) -> ImmutableMatrix:
    if isinstance(M, sympy.MatrixBase):
        rows = M.tolist()
    else:
        if hasattr(M, "tolist"):
            M = M.tolist()
        try:
            rows = [list(r) for r in M]
        except TypeError:
            raise DimensionError(f"a quadric needs a {size}×{size} matrix, got {type(M).__name__} {M!r}") from None
    if len(rows) != size or any(len(r) != size for r in rows):
        shape = f"{len(rows)} rows of lengths {[len(r) for r in rows]}"
        raise DimensionError(f"a quadric needs a symmetric {size}×{size} matrix, got {shape}")
    return ImmutableMatrix([[to_exact(v) for v in r] for r in rows])


class Quadric(Kind, kind="quadric"):
    """A quadric surface ``Xᵀ Q X = 0`` of P³, from a symmetric 4×4 matrix.

    The matrix entries are exact (integers, fractions, symbols). Two quadrics
    are equal when their matrices are proportional. An asymmetric matrix is
    rejected with :class:`InvalidCoordinatesError` (only the symmetric part
    ``(M + Mᵀ)/2`` matters for the equation; pass that if it is what you mean),
    a matrix of the wrong size with :class:`DimensionError`, the zero matrix
    with :class:`ZeroVectorError`.

    >>> Q = Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 0]])   # the cone x² + y² = z²
    >>> Q.rank, Q.is_degenerate, Q.contains(Point3(3, 4, 5))
    (3, True, True)
    >>> Q == Quadric(2 * Q.matrix)
    True
    """

    __slots__ = ("_matrix",)

    def __init__(self, M: Any) -> None:
        matrix = _exact_square(M, 4)
        for i in range(4):
            for j in range(i + 1, 4):
                if not is_zero(matrix[i, j] - matrix[j, i]):
                    raise InvalidCoordinatesError(
                        f"a quadric matrix must be symmetric, but entry ({i}, {j}) is {matrix[i, j]} and entry "
                        f"({j}, {i}) is {matrix[j, i]}; use the symmetric part (M + M.T)/2, which gives the same "
                        f"equation"
                    )
        if all_zero(matrix):
            raise ZeroVectorError("the zero matrix is not a quadric: every point would satisfy 0 = 0")
        self._matrix = matrix

    # -- constructors ---------------------------------------------------------------------
    @classmethod
    def sphere(cls, center: Sequence[Scalar], radius: Scalar) -> Quadric:
        """The sphere ``(x-a)² + (y-b)² + (z-c)² = r²`` with ``center = (a, b, c)``.

        Its matrix is ``[[I, -c], [-cᵀ, |c|² - r²]]``. The radius must be nonzero
        (a zero radius gives a point-cone, build it with :class:`Quadric` directly).

        >>> Quadric.sphere((1, 2, 3), 2).matrix.tolist()
        [[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3], [-1, -2, -3, 10]]
        """
        try:
            a, b, c = (to_exact(v) for v in center)
        except (TypeError, ValueError):
            raise DimensionError(f"the centre of a sphere takes 3 coordinates (a, b, c), got {center!r}") from None
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

    # -- access -----------------------------------------------------------------------------
    @property
    def matrix(self) -> ImmutableMatrix:
        """The symmetric 4×4 matrix ``Q`` (as stored, not normalised)."""
        return self._matrix

    @property
    def rank(self) -> int:
        """The rank of ``Q`` (4 for a non-degenerate quadric; generic rank for symbolic entries).

        >>> Quadric([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, -1]]).rank   # the planes x = ±1
        2
        """
        return int(Matrix(self._matrix).rank(iszerofunc=lambda v: is_zero(sympy.sympify(v))))

    @property
    def is_degenerate(self) -> bool:
        """True when ``det Q = 0`` (cones, plane pairs, double planes).

        >>> Quadric.sphere((0, 0, 0), 3).is_degenerate
        False
        """
        return is_zero(sympy.expand(self._matrix.det(method="bareiss")))

    # -- geometry -----------------------------------------------------------------------------
    def _value(self, X: Point3) -> Expr:
        if not isinstance(X, Point3):
            raise ObjectTypeError(f"expected a Point3, got {type(X).__name__} {X!r}")
        v = X.vector
        return sympy.expand((v.T * self._matrix * v)[0, 0])

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
        if not isinstance(X, Point3):
            raise ObjectTypeError(f"polar expects a Point3, got {type(X).__name__} {X!r}")
        coords = tuple(sympy.expand(v) for v in self._matrix * X.vector)
        if all_zero(coords):
            raise DegenerateConicError(
                f"Q X = 0 for X = {X!r}: the point is a singular point (vertex) of this degenerate quadric, "
                f"so it has no polar or tangent plane"
            )
        return Plane._from_exact(coords)

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

    # -- equality and rendering -----------------------------------------------------------------
    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Quadric):
            return NotImplemented
        a, b = list(self._matrix), list(other._matrix)
        return all(is_zero(a[i] * b[j] - a[j] * b[i]) for i in range(16) for j in range(i + 1, 16))

    def __hash__(self) -> int:
        entries = list(self._matrix)
        if all(v.is_Rational for v in entries):
            pivot = next(v for v in entries if v != 0)
            return hash(("Quadric", tuple(v / pivot for v in entries)))
        return hash("Quadric")

    def __repr__(self) -> str:
        rows = ", ".join("[" + ", ".join(_format_entry(v) for v in self._matrix.row(i)) + "]" for i in range(4))
        return f"Quadric([{rows}])"

    def latex(self) -> str:
        """LaTeX of the matrix (without math delimiters)."""
        return latex(self._matrix, mat_delim="[")

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"

