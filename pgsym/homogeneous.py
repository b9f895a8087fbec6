"""Homogeneous coordinate vectors with exact SymPy entries.

A homogeneous vector stands for the one-dimensional subspace it spans: ``v`` and
``k v`` (``k`` nonzero) describe the same projective object. This module holds
what every projective object shares: exact coercion of coordinates, equality up
to scale, the canonical form and rendering (the scalar rules are in :mod:`pgsym.exact`).

>>> from pgsym import Point
>>> Point(2, 4, 2) == Point(1, 2)
True
>>> Point(2, 4, 6).canonical()
Point(1, 2, 3)
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Iterator, Sequence
from fractions import Fraction  # noqa: F401 (doctests)
from typing import Any, ClassVar, TypeVar

import sympy
from sympy import Expr, Matrix

from .errors import DimensionError, IdealPointError, ObjectTypeError, UndecidableError, ZeroVectorError
from .exact import Scalar, all_zero, canonical_coords, format_entry, is_zero, latex, to_exact
from .kinds import Kind
from .matrices import proportional
from .ring import Action, dot

__all__ = ["HomogeneousHyperplane", "HomogeneousPoint", "HomogeneousVector", "is_zero", "to_exact"]

_format_entry = format_entry  # the name the other modules import

_V = TypeVar("_V", bound="HomogeneousVector")


def require(obj: object, cls: type, operation: str, hint: str = "") -> None:
    """Raise :class:`ObjectTypeError` unless ``obj`` is a ``cls``; ``hint`` suggests the right call.

    >>> require(3, HomogeneousVector, "join", "; pass points")
    Traceback (most recent call last):
    ...
    pgsym.errors.ObjectTypeError: join expects HomogeneousVectors, got int 3; pass points
    """
    if not isinstance(obj, cls):
        raise ObjectTypeError(f"{operation} expects {cls.__name__}s, got {type(obj).__name__} {obj!r}{hint}")


class HomogeneousVector(Kind):
    """Base class of projective objects given by one homogeneous vector.

    Subclasses set ``size`` (the number of homogeneous coordinates). Instances
    are immutable; ``==`` compares up to a nonzero scale.
    """

    size: int = 3
    _kind: str = "vector"
    # the n of the space Pⁿ the object lives in (None: not acted on by transformations); how the object
    # transforms is its ``image`` rule
    ambient_dim: ClassVar[int | None] = None

    __slots__ = ("_coords",)

    def __init__(self, *coords: Scalar) -> None:
        if len(coords) == 1 and not isinstance(coords[0], (numbers.Number, Expr)) and _is_sequence(coords[0]):
            coords = tuple(coords[0])
        self._coords = self._check(tuple(to_exact(c) for c in self._complete(coords)))

    @classmethod
    def _complete(cls, coords: tuple[Scalar, ...]) -> tuple[Scalar, ...]:
        """Hook for subclasses that accept inhomogeneous coordinates too."""
        return coords

    @classmethod
    def _check(cls, coords: tuple[Expr, ...]) -> tuple[Expr, ...]:
        if len(coords) != cls.size:
            raise DimensionError(f"a {cls._kind} needs {cls.size} homogeneous coordinates, got {len(coords)}: {coords}")
        if all_zero(coords):
            raise ZeroVectorError(f"the zero vector is not a {cls._kind}: at least one coordinate must be nonzero")
        return coords

    @classmethod
    def _from_exact(cls: type[_V], coords: tuple[Expr, ...]) -> _V:
        """Build from coordinates already converted (internal: skips coercion)."""
        obj = cls.__new__(cls)
        obj._coords = cls._check(coords)
        return obj

    @classmethod
    def _from_nonzero(
        cls: type[_V], coords: tuple[Expr, ...], error: type[Exception], message: Callable[[], str]
    ) -> _V:
        """Build from computed coordinates that vanish exactly for a degenerate input: then raise ``error``.

        ``message`` is called only then (the reprs in it are costly for symbolic objects).
        """
        if all_zero(coords):
            raise error(message())
        return cls._from_exact(coords)

    # -- access ---------------------------------------------------------------
    @property
    def coords(self) -> tuple[Expr, ...]:
        """The homogeneous coordinates as stored (not normalised)."""
        return self._coords

    @property
    def vector(self) -> Matrix:
        """The homogeneous coordinates as a SymPy column matrix."""
        return Matrix(self._coords)

    def __iter__(self) -> Iterator[Expr]:
        return iter(self._coords)

    def __len__(self) -> int:
        return self.size

    def __getitem__(self, index: int) -> Expr:
        return self._coords[index]

    @property
    def free_symbols(self) -> set[sympy.Symbol]:
        """The symbols the coordinates depend on."""
        return set().union(*(c.free_symbols for c in self._coords))

    def subs(self: _V, *args: Any, **kwargs: Any) -> _V:
        """Substitute values for symbols, as :meth:`sympy.Expr.subs` does."""
        return type(self)._from_exact(tuple(sympy.sympify(c).subs(*args, **kwargs) for c in self._coords))

    # -- projective equality ----------------------------------------------------
    def is_proportional(self, other: HomogeneousVector) -> bool:
        """True when the two vectors differ by a nonzero factor (all 2×2 minors vanish)."""
        try:
            return proportional(self._coords, other._coords)
        except UndecidableError as err:
            raise UndecidableError(f"cannot decide whether {self!r} and {other!r} are equal: {err}") from err

    @property
    def is_real(self) -> bool:
        """True when some multiple of the coordinates is real: the vector and its complex conjugate agree up to scale.

        >>> from sympy import I
        >>> from pgsym import Point
        >>> Point(I, 2*I, 3*I).is_real, Point(1, I, 0).is_real      # i·(1, 2, 3) is real; a circular point is not
        (True, False)
        """
        return self.is_proportional(type(self)._from_exact(tuple(sympy.conjugate(c) for c in self._coords)))

    def __eq__(self, other: object) -> bool:
        if type(self) is not type(other):
            return NotImplemented
        assert isinstance(other, HomogeneousVector)
        return self.is_proportional(other)

    def __hash__(self) -> int:
        if all(c.is_Rational for c in self._coords):
            return hash((type(self).__name__, self.canonical()._coords))
        return hash((type(self).__name__, self.size))

    # -- canonical form ---------------------------------------------------------
    def canonical(self: _V) -> _V:
        """The canonical representative: equal objects have identical canonical forms.

        For rational entries this is the primitive integer vector with its first
        nonzero entry positive; for symbolic entries, the common denominator is
        cleared and the polynomial content removed; algebraic entries (``sqrt(2)``,
        ``I``) are normalised in their number field. The rules are in
        :mod:`pgsym.exact`. Never divides by the last coordinate, so ideal points are fine.

        >>> from pgsym import Line
        >>> Line(Fraction(1, 2), Fraction(-1, 3), 0).canonical()
        Line(3, -2, 0)
        """
        return type(self)._from_exact(canonical_coords(self._coords))

    # -- action of a transformation ----------------------------------------------------------------
    @classmethod
    def image(cls, coords: Sequence[Any], H: Action) -> tuple[Any, ...]:
        """The coordinates of the image under the matrix action ``H``, in any ring: a point maps by ``H x``.

        >>> from pgsym import Point
        >>> Point.image((1, 2, 1), Action([[2, 0, 0], [0, 2, 0], [0, 0, 1]]))
        (2, 4, 1)
        """
        return H.point(coords)

    def _transformed_by(self: _V, H: Any) -> _V:
        """The image under the transformation ``H`` (checked by ``H.apply``), by the class's :meth:`image` rule."""
        return type(self)._from_exact(tuple(sympy.expand(e) for e in type(self).image(self._coords, H.action)))

    # -- rendering ----------------------------------------------------------------
    def __repr__(self) -> str:
        return f"{type(self).__name__}({', '.join(_format_entry(c) for c in self._coords)})"

    def _latex_entries(self) -> list[str]:
        return [latex(c) for c in self._coords]

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"

    def latex(self) -> str:
        """LaTeX of the coordinates as a column vector (without math delimiters)."""
        return r"\begin{bmatrix}" + r" \\ ".join(self._latex_entries()) + r"\end{bmatrix}"


class HomogeneousPoint(HomogeneousVector):
    """A point of Pⁿ (``size`` n + 1): a finite point may be given by its n inhomogeneous coordinates
    (a 1 is appended), and the point is ideal when its last coordinate is zero.

    >>> from pgsym import Point, Point3
    >>> Point(2, 4, 2).dehomogenize(), Point3(1, 2, 3, 0).is_ideal, Point3(1, 2, 3).is_ideal
    ((1, 2), True, False)
    >>> Point(1, 1, 0).dehomogenize()  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.IdealPointError: Point(1, 1, 0) is an ideal point (x3 = 0) and has no ...
    """

    __slots__ = ()
    _inhomogeneous: ClassVar[str] = "(x, y)"  # how errors name the inhomogeneous coordinates

    @classmethod
    def _complete(cls, coords: tuple[Scalar, ...]) -> tuple[Scalar, ...]:
        n = cls.size
        if len(coords) == n - 1:
            return (*coords, 1)
        if len(coords) != n:
            names = ", ".join(f"x{i + 1}" for i in range(n))
            raise DimensionError(
                f"a {cls._kind} takes {n - 1} inhomogeneous coordinate{'s' if n > 2 else ''} {cls._inhomogeneous} "
                f"or {n} homogeneous ones ({names}), got {len(coords)}: {coords}"
            )
        return coords

    @property
    def is_ideal(self) -> bool:
        """True for a point at infinity (last coordinate zero)."""
        return is_zero(self._coords[-1])

    def dehomogenize(self) -> Any:
        """The inhomogeneous coordinates ``(x1/xₙ₊₁, …, xₙ/xₙ₊₁)``; an ideal point raises :class:`IdealPointError`."""
        *xs, w = self._coords
        if self.is_ideal:
            raise IdealPointError(
                f"{self!r} is an ideal point (x{self.size} = 0) and has no inhomogeneous coordinates; "
                f"its direction is ({', '.join(str(x) for x in xs)})"
            )
        return tuple(sympy.cancel(x / w) for x in xs)


class HomogeneousHyperplane(HomogeneousVector):
    """A line of P² or a plane of P³: ``(n, d)`` with Euclidean normal ``n``; it maps covariantly, by ``H⁻ᵀ``.

    Printed as a row vector, so that ``lᵀx`` reads as a row times a column.

    >>> from pgsym import Line, Plane
    >>> Line(3, 4, 5).normal, Plane(0, 0, 0, 2).is_at_infinity, Line(1, 0, 0).is_at_infinity
    ((3, 4), True, False)
    """

    __slots__ = ()

    @classmethod
    def image(cls, coords: Sequence[Any], H: Action) -> tuple[Any, ...]:
        """A line or plane maps by the cofactor matrix, ``adj(H)ᵀ l ∝ H⁻ᵀ l``, which keeps the incidence ``lᵀx = 0``.

        >>> from pgsym import Line
        >>> Line.image((1, 0, 0), Action([[1, 0, 5], [0, 1, 0], [0, 0, 1]]))     # x = 0 moved by 5: x = 5
        (1, 0, -5)
        """
        return H.hyperplane(coords)

    @property
    def normal(self) -> tuple[Expr, ...]:
        """The Euclidean normal vector: every coordinate but the last (zero only for the one at infinity)."""
        return self._coords[:-1]

    @property
    def is_at_infinity(self) -> bool:
        """True for the line (plane) at infinity ``(0, …, 0, 1)``."""
        return all_zero(self._coords[:-1])

    def latex(self) -> str:
        """LaTeX of the coordinates as a row vector (without math delimiters)."""
        return r"\begin{bmatrix}" + " & ".join(self._latex_entries()) + r"\end{bmatrix}"


def incidence(point: Any, hyperplane: Any, point_cls: type, hyperplane_cls: type) -> bool:
    """``lᵀx = 0`` exactly, for a point and a hyperplane given in either order (incidence is symmetric).

    >>> from pgsym import Line, Point
    >>> incidence(Line(1, -1, 0), Point(2, 2), Point, Line)
    True
    """
    if isinstance(point, hyperplane_cls) and isinstance(hyperplane, point_cls):
        point, hyperplane = hyperplane, point
    pair = f" (a {point_cls.__name__} and a {hyperplane_cls.__name__})"
    require(point, point_cls, "incident", pair)
    require(hyperplane, hyperplane_cls, "incident", pair)
    return is_zero(sympy.expand(dot(point.coords, hyperplane.coords)))


def _is_sequence(value: Any) -> bool:
    try:
        iter(value)
    except TypeError:
        return False
    return not isinstance(value, (str, bytes))
