"""Shared hypothesis strategies: exact random configurations of P², ideal points included."""

from __future__ import annotations

from fractions import Fraction

from _browser import browser, server  # noqa: F401  (fixtures of the browser tests)
from hypothesis import settings
from hypothesis import strategies as st

from pgsym import Line, Point

# Exact symbolic examples vary widely in cost, and the machine may be shared: a per-example time
# limit would only make runs flaky, so the suite checks results, not speed (speed lives in bench/).
settings.register_profile("pgsym", deadline=None, print_blob=True)
settings.load_profile("pgsym")

small = st.integers(min_value=-12, max_value=12)
nonzero_rational = st.fractions(min_value=-9, max_value=9, max_denominator=7).filter(lambda f: f != 0)


@st.composite
def homogeneous_triples(draw, allow_ideal: bool = True) -> tuple[int, int, int]:
    """Integer triples that are not the zero vector; a third of them ideal when allowed."""
    if allow_ideal:
        last = 0 if draw(st.integers(0, 2)) == 0 else draw(small)
    else:
        last = draw(small.filter(lambda v: v != 0))
    x1, x2 = draw(small), draw(small)
    if (x1, x2, last) == (0, 0, 0):
        x1 = 1
    return x1, x2, last


def points(allow_ideal: bool = True) -> st.SearchStrategy[Point]:
    return homogeneous_triples(allow_ideal).map(lambda t: Point(*t))


def lines() -> st.SearchStrategy[Line]:
    return homogeneous_triples(True).map(lambda t: Line(*t))


def scaled(obj, factor: Fraction):
    """The same projective object with every coordinate multiplied by ``factor``."""
    return type(obj)(*(c * factor for c in obj.coords))
