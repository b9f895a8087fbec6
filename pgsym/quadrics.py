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

import sympy
from sympy import Expr

from .errors import (
    DegenerateConicError,
    DimensionError,
    InvalidCoordinatesError,
    NotOnQuadricError,
)
from .homogeneous import Scalar, is_zero, require, to_exact
from .space import Plane, Point3
from .symmetric_form import SymmetricForm

__all__ = ["NotOnQuadricError", "Quadric"]


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
