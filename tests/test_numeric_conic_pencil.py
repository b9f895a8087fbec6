"""pgsym.numeric.intersect_conics against the exact pgsym.conic_pencil.intersect_conics.

The conic pairs are built as the exact tests build them, so that the pencil has a rational line pair and
the exact answer exists: two conics through four random integer points (two more points pick the conics),
and random circles, which meet in the circular points I, J besides their two (possibly complex) points.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import pgsym.numeric as pn
from pgsym.conic_pencil import intersect_conics
from pgsym.conics import Conic, conic_through
from pgsym.errors import DegenerateConfigurationError, NonFiniteError
from pgsym.projective_plane import Line, Point, collinear
from tests.strategies import integers

FAST = settings(max_examples=10, deadline=None)  # the exact side takes a second or more per pair


def matrix(C: Conic) -> np.ndarray:
    return np.array([[float(c) for c in row] for row in sympy.Matrix(C.matrix).tolist()])


def apart(p, q) -> float:
    """``|p × q| / (|p| |q|)``: 0 exactly when the complex points p, q are one projective point."""
    return float(np.linalg.norm(np.cross(p, q)) / (np.linalg.norm(p) * np.linalg.norm(q)))


def same_points(got: np.ndarray, exact, tol: float = 1e-6) -> bool:
    """The four numeric points are the exact ones with multiplicity (a double root keeps half the digits)."""
    left = list(got)
    for e in exact:
        target = np.array([complex(sympy.N(c, 30)) for c in e.coords])
        distances = [apart(p, target) for p in left]
        k = int(np.argmin(distances))
        if distances[k] > tol:
            return False
        left.pop(k)
    return True


@given(st.lists(st.tuples(integers(6), integers(6)), min_size=6, max_size=6, unique=True))
@FAST
def test_two_conics_through_four_points_agree_with_exact(coords):
    pts = [Point(x, y) for x, y in coords]
    assume(not any(collinear(*trio) for trio in itertools.combinations(pts, 3)))
    C1, C2 = conic_through(*pts[:4], pts[4]), conic_through(*pts[:4], pts[5])
    assume(C1 != C2)
    got = pn.intersect_conics(matrix(C1), matrix(C2))
    assert got.shape == (4, 3)
    assert same_points(got, intersect_conics(C1, C2))


@given(st.tuples(integers(5), integers(5), st.integers(1, 6)), st.tuples(integers(5), integers(5), st.integers(1, 6)))
@FAST
def test_random_circles_agree_with_exact(c1, c2):
    C1, C2 = Conic.circle(*c1), Conic.circle(*c2)
    assume(C1 != C2)
    assert same_points(pn.intersect_conics(matrix(C1), matrix(C2)), intersect_conics(C1, C2))


def test_a_batch_broadcasts_and_agrees_row_by_row():
    circles = [Conic.circle(0, 0, 5), Conic.circle(0, 0, 1), Conic.circle(1, 1, 2)]
    other = Conic.circle(4, 0, 3)
    got = pn.intersect_conics(np.stack([matrix(c) for c in circles]), matrix(other))
    assert got.shape == (3, 4, 3)
    for row, c in zip(got, circles, strict=True):
        assert same_points(row, intersect_conics(c, other))


def test_by_hand():
    # x² + y² = 25 and (x − 4)² + y² = 9: subtracting, 8x − 16 = 16, x = 4, y = ±3; and I = (1, i, 0), J = (1, −i, 0)
    got = pn.intersect_conics(np.diag([1.0, 1, -25]), [[1.0, 0, -4], [0, 1, 0], [-4, 0, 7]])
    expected = [(4, 3, 1), (4, -3, 1), (1, 1j, 0), (1, -1j, 0)]
    assert same_points(got, [Point(*(sympy.sympify(c) for c in e)) for e in expected], tol=1e-12)
    # y = x² and x² + (y − 1)² = 1: y(y − 1) = 0, so (±1, 1) and the origin twice (the conics touch there)
    P, C = Conic.from_coefficients(1, 0, 0, 0, -1, 0), Conic.circle(0, 1, 1)
    got = pn.intersect_conics(matrix(P), matrix(C))
    assert same_points(got, [Point(1, 1), Point(-1, 1), Point(0, 0), Point(0, 0)])


def test_degenerate_and_non_finite_pairs_raise_or_mask():
    C = np.diag([1.0, 1, -25])
    with pytest.raises(DegenerateConfigurationError):
        pn.intersect_conics(C, 2 * C)  # one conic
    # x(x − y) and x(y + 3) share the line x = 0
    l1 = Conic.from_lines(Line(1, 0, 0), Line(1, -1, 0))
    l2 = Conic.from_lines(Line(1, 0, 0), Line(0, 1, 3))
    with pytest.raises(DegenerateConfigurationError):
        pn.intersect_conics(matrix(l1), matrix(l2))
    pts, ok = pn.intersect_conics(np.stack([C, matrix(l1)]), np.stack([2 * C, matrix(Conic.circle(4, 0, 3))]),
                                  degenerate="mask")
    assert ok.tolist() == [False, True] and np.isnan(pts[0]).all()
    bad = C.copy()
    bad[0, 0] = np.nan
    with pytest.raises(NonFiniteError):
        pn.intersect_conics(bad, C)


@pytest.mark.parametrize(("s1", "s2"), [(1e200, 1e-200), (1e-200, 1e-200), (-1e150, 3.0)])
def test_any_scale_of_either_conic_gives_the_same_points(s1, s2):
    # the circles of test_by_hand, each at another scale: the same four points
    C, E = np.diag([1.0, 1, -25]), np.array([[1.0, 0, -4], [0, 1, 0], [-4, 0, 7]])
    got = pn.intersect_conics(s1 * C, s2 * E)
    expected = [(4, 3, 1), (4, -3, 1), (1, 1j, 0), (1, -1j, 0)]
    assert same_points(got, [Point(*(sympy.sympify(c) for c in e)) for e in expected], tol=1e-12)
