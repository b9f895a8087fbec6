"""Shared hypothesis strategies: exact random configurations, ideal elements included.

One home for the random data of the property tests, so that "a random point" means the same thing
in every test file.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import assume
from hypothesis import strategies as st

from pgsym import Line, Plane, Point, Point3, Transformation
from pgsym.ring import det


def integers(bound: int) -> st.SearchStrategy[int]:
    """Integers from ``-bound`` to ``bound``: small entries keep exact examples fast."""
    return st.integers(min_value=-bound, max_value=bound)


def rationals(bound: int, max_denominator: int) -> st.SearchStrategy[Fraction]:
    """Fractions from ``-bound`` to ``bound`` with denominators up to ``max_denominator``."""
    return st.fractions(min_value=-bound, max_value=bound, max_denominator=max_denominator)


def nonzero_rationals(bound: int, max_denominator: int) -> st.SearchStrategy[Fraction]:
    """:func:`rationals` without zero (scale factors, parameters that must not vanish)."""
    return rationals(bound, max_denominator).filter(lambda f: f != 0)


small = integers(12)
nonzero_rational = nonzero_rationals(9, 7)


@st.composite
def homogeneous_vectors(draw, k: int = 3, allow_ideal: bool = True, entries: st.SearchStrategy[int] = small
                        ) -> tuple[int, ...]:
    """Integer k-vectors that are not the zero vector; a third of them ideal (last entry 0) when allowed."""
    if allow_ideal:
        last = 0 if draw(st.integers(0, 2)) == 0 else draw(entries)
    else:
        last = draw(entries.filter(lambda v: v != 0))
    head = [draw(entries) for _ in range(k - 1)]
    if not any(head) and last == 0:
        head[0] = 1
    return (*head, last)


def homogeneous_triples(allow_ideal: bool = True) -> st.SearchStrategy[tuple[int, ...]]:
    """Integer triples that are not the zero vector; a third of them ideal when allowed."""
    return homogeneous_vectors(3, allow_ideal)


@st.composite
def invertible_matrices(draw, n: int = 3, bound: int = 6) -> list[list[int]]:
    """Integer n×n matrices with entries up to ``bound`` and a nonzero (exact) determinant, as lists of rows."""
    rows = [[draw(integers(bound)) for _ in range(n)] for _ in range(n)]
    assume(det(rows) != 0)
    return rows


def transformations(n: int = 3, bound: int = 6) -> st.SearchStrategy[Transformation]:
    """Invertible transformations of P^(n−1) with integer entries up to ``bound``."""
    return invertible_matrices(n, bound).map(Transformation)


def points3(allow_ideal: bool = True, bound: int = 9) -> st.SearchStrategy[Point3]:
    """Points of P³ with integer coordinates up to ``bound``; a third of them ideal when allowed."""
    return homogeneous_vectors(4, allow_ideal, integers(bound)).map(lambda t: Point3(*t))


def planes(bound: int = 9) -> st.SearchStrategy[Plane]:
    """Planes with integer coordinates up to ``bound``; a third of them through the origin (last coordinate 0)."""
    return homogeneous_vectors(4, True, integers(bound)).map(lambda t: Plane(*t))


def points(allow_ideal: bool = True, bound: int = 12) -> st.SearchStrategy[Point]:
    """Points of P² with integer coordinates up to ``bound``; a third of them ideal when allowed."""
    return homogeneous_vectors(3, allow_ideal, integers(bound)).map(lambda t: Point(*t))


def lines(bound: int = 12) -> st.SearchStrategy[Line]:
    """Lines of P² with integer coordinates up to ``bound``; a third of them through the origin."""
    return homogeneous_vectors(3, True, integers(bound)).map(lambda t: Line(*t))


def scaled(obj, factor: Fraction):
    """The same projective object with every coordinate multiplied by ``factor``."""
    return type(obj)(*(c * factor for c in obj.coords))
