"""Homogeneous coordinate vectors with exact SymPy entries.

A homogeneous vector stands for the one-dimensional subspace it spans: ``v`` and
``k v`` (``k`` nonzero) describe the same projective object. This module holds
what every projective object shares: exact coercion of coordinates, equality up
to scale, the canonical primitive-integer form and rendering.

>>> from pgsym import Point
>>> Point(2, 4, 2) == Point(1, 2)
True
>>> Point(2, 4, 6).canonical()
Point(1, 2, 3)
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterator
from fractions import Fraction
from typing import Any, TypeVar

import sympy
from sympy import Expr, Integer, Matrix, Rational
from sympy.printing.str import StrPrinter

from .errors import DimensionError, NonNumericError, ObjectTypeError, ZeroVectorError

__all__ = ["HomogeneousVector", "is_zero", "to_exact"]

Scalar = Any
"""A coordinate: int, Fraction, float (read as the decimal it prints as), or a SymPy expression."""

_V = TypeVar("_V", bound="HomogeneousVector")


def to_exact(value: Scalar) -> Expr:
    """Convert one coordinate to an exact SymPy expression.

    Integers, fractions and SymPy expressions are kept exactly. A float is read
    as the shortest decimal that prints it (``0.1`` becomes ``1/10``), since the
    exact binary value of a float is rarely what the user meant. Strings, ``None``,
    booleans, NaN and infinities are rejected with :class:`NonNumericError`.

    >>> to_exact(0.25), to_exact(Fraction(2, 6)), to_exact(3)
    (1/4, 1/3, 3)
    """
    if isinstance(value, bool) or value is None or isinstance(value, (str, bytes)):
        raise NonNumericError(
            f"coordinates must be numbers or SymPy expressions, got {value!r} "
            f"of type {type(value).__name__}; use Fraction('1/2') or sympy.Rational(1, 2) for fractions"
        )
    if isinstance(value, Expr):
        result = value
    elif isinstance(value, numbers.Integral):
        result = Integer(int(value))
    elif isinstance(value, Fraction):
        result = Rational(value.numerator, value.denominator)
    elif isinstance(value, numbers.Real):
        as_float = float(value)
        if not math.isfinite(as_float):
            raise NonNumericError(f"coordinates must be finite, got {value!r}; use an ideal point for directions")
        result = Rational(repr(as_float))
    elif isinstance(value, numbers.Complex):
        result = to_exact(value.real) + sympy.I * to_exact(value.imag)
    else:
        raise NonNumericError(
            f"coordinates must be numbers or SymPy expressions, got {value!r} of type {type(value).__name__}"
        )
    if isinstance(result, sympy.Float):
        return to_exact(float(result))
    if result.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo):
        raise NonNumericError(f"coordinates must be finite, got {value!r}; use an ideal point for directions")
    return result


def is_zero(expr: Expr) -> bool:
    """Exact test that an expression vanishes identically.

    Rational numbers are compared directly; expressions with symbols are brought
    to one fraction and its numerator expanded, a decision procedure for
    rational functions (no ``simplify`` heuristics).

    >>> a = sympy.Symbol("a")
    >>> is_zero((a + 1) ** 2 - a**2 - 2 * a - 1), is_zero(a)
    (True, False)
    """
    if expr.is_Rational:
        return bool(expr == 0)
    # a fraction vanishes iff its numerator expands to zero; no gcd (cancel) needed
    numerator, _ = sympy.fraction(sympy.together(expr))
    return sympy.expand(numerator) == 0


class _ReprPrinter(StrPrinter):
    """Prints fractions as ``S(1)/2`` so that ``repr`` evaluates back to exact numbers."""

    def _print_Rational(self, expr: Rational) -> str:
        return f"S({expr.p})/{expr.q}"


def require(obj: object, cls: type, operation: str, hint: str = "") -> None:
    """Raise :class:`ObjectTypeError` unless ``obj`` is a ``cls``; ``hint`` suggests the right call.

    >>> require(3, HomogeneousVector, "join", "; pass points")
    Traceback (most recent call last):
    ...
    pgsym.errors.ObjectTypeError: join expects HomogeneousVectors, got int 3; pass points
    """
    if not isinstance(obj, cls):
        raise ObjectTypeError(f"{operation} expects {cls.__name__}s, got {type(obj).__name__} {obj!r}{hint}")


def _format_entry(entry: Expr) -> str:
    """The Python source of one coordinate, so that ``repr`` round-trips."""
    return _ReprPrinter().doprint(entry)


class HomogeneousVector:
    """Base class of projective objects given by one homogeneous vector.

    Subclasses set ``size`` (the number of homogeneous coordinates). Instances
    are immutable; ``==`` compares up to a nonzero scale.
    """

    size: int = 3
    _kind: str = "vector"

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
        if all(is_zero(c) for c in coords):
            raise ZeroVectorError(f"the zero vector is not a {cls._kind}: at least one coordinate must be nonzero")
        return coords

    @classmethod
    def _from_exact(cls: type[_V], coords: tuple[Expr, ...]) -> _V:
        """Build from coordinates already converted (internal: skips coercion)."""
        obj = cls.__new__(cls)
        obj._coords = cls._check(coords)
        return obj

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
        a, b = self._coords, other._coords
        if len(a) != len(b):
            return False
        return all(is_zero(a[i] * b[j] - a[j] * b[i]) for i in range(len(a)) for j in range(i + 1, len(a)))

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
        """The representative with coprime integer (or polynomial) entries, first nonzero entry positive.

        For rational entries this is the primitive integer vector; for symbolic
        entries, the common denominator is cleared and the polynomial content
        removed. Never divides by the last coordinate, so ideal points are fine.

        >>> from pgsym import Line
        >>> Line(Fraction(1, 2), Fraction(-1, 3), 0).canonical()
        Line(3, -2, 0)
        """
        coords = [sympy.together(c) for c in self._coords]
        if all(c.is_Rational for c in coords):
            denominator = sympy.ilcm(*[c.q for c in coords]) if len(coords) > 1 else coords[0].q
            ints = [int(c * denominator) for c in coords]
            content = math.gcd(*ints)
            ints = [i // content for i in ints]
            sign = -1 if next(i for i in ints if i != 0) < 0 else 1
            return type(self)._from_exact(tuple(Integer(sign * i) for i in ints))
        numerators, denominators = zip(*(sympy.fraction(c) for c in coords), strict=False)
        common = sympy.lcm_list(list(denominators))
        polys = [sympy.expand(sympy.cancel(n * common / d)) for n, d in zip(numerators, denominators, strict=False)]
        content = sympy.gcd_list([p for p in polys if p != 0])
        polys = [sympy.expand(sympy.cancel(p / content)) for p in polys]
        lead = next(p for p in polys if p != 0)
        if sympy.Poly(lead, *sorted(lead.free_symbols, key=str) or [sympy.Symbol("_")]).LC() < 0:
            polys = [-p for p in polys]
        return type(self)._from_exact(tuple(polys))

    # -- rendering ----------------------------------------------------------------
    def __repr__(self) -> str:
        return f"{type(self).__name__}({', '.join(_format_entry(c) for c in self._coords)})"

    def _latex_entries(self) -> list[str]:
        return [sympy.latex(c) for c in self._coords]

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"

    def latex(self) -> str:
        """LaTeX of the coordinates as a column vector (without math delimiters)."""
        return r"\begin{bmatrix}" + r" \\ ".join(self._latex_entries()) + r"\end{bmatrix}"


def _is_sequence(value: Any) -> bool:
    try:
        iter(value)
    except TypeError:
        return False
    return not isinstance(value, (str, bytes))
