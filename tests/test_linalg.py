"""Null spaces, ranks, method #2 and the SVD: worked values by hand and properties against the exact core."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers
from sympy import Matrix, Rational, symbols

from pgsym.errors import (
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
    InvalidCoordinatesError,
)
from pgsym.linalg import (
    ZeroCoordinateError,
    nullspace_exact,
    nullspace_svd,
    numeric_rank,
    plane_through_numeric,
    point_on_planes_numeric,
    rank_exact,
    solve_by_fixing_coordinate,
    svd_steps,
)
from pgsym.space import Plane, Point3, plane_through, point_on_planes

small = integers(9)
FAST = settings(max_examples=60, deadline=None)


@st.composite
def rank3_rows(draw) -> list[tuple[int, int, int, int]]:
    """Three integer 4-vectors of rank 3 (some with last entry 0)."""
    rows = [tuple(draw(small) for _ in range(4)) for _ in range(3)]
    assume(Matrix(rows).rank() == 3)
    return rows


def proportional(u, v) -> bool:
    """Exact: all 2×2 minors of [u; v] vanish and neither is zero."""
    u, v = list(u), list(v)
    return any(x != 0 for x in u) and all(u[i] * v[j] == u[j] * v[i] for i in range(4) for j in range(4))


def parallel_numeric(u, v) -> bool:
    u, v = np.asarray(u, float), np.asarray(v, float)
    u, v = u / np.linalg.norm(u), v / np.linalg.norm(v)
    return bool(np.isclose(abs(u @ v), 1.0, atol=1e-9))


# -- exact: worked examples -----------------------------------------------------------------------------


def test_nullspace_of_the_three_shifted_coordinate_planes():
    # x - w = 0, y - 2w = 0, z - 3w = 0: w is free, x = w, y = 2w, z = 3w -> (1, 2, 3, 1)
    assert nullspace_exact([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]]) == [(1, 2, 3, 1)]


def test_nullspace_clears_denominators_and_accepts_rows_of_points():
    # x/2 + y/3 = 0, z = 0, w = 0: the free variable y = 1 gives x = -2/3, cleared to (-2, 3, 0, 0)
    basis = nullspace_exact([[Rational(1, 2), Rational(1, 3), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    assert basis == [(-2, 3, 0, 0)]
    # rows given as points (1,0,0,1), ...: a + d = b + d = c + d = 0 with d = 1 free gives (-1, -1, -1, 1),
    # the plane x + y + z - w = 0 up to the factor -1
    assert nullspace_exact([Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)]) == [(-1, -1, -1, 1)]
    assert nullspace_exact(np.array([[1, 1], [1, 1]])) == [(-1, 1)]


def test_nullspace_of_full_rank_is_empty_and_rank():
    assert nullspace_exact([[1, 2], [3, 4]]) == []
    assert rank_exact([[1, 2], [3, 4]]) == 2
    assert rank_exact([[0, 0, 0]]) == 0
    assert len(nullspace_exact([[0, 0, 0]])) == 3


def test_symbolic_nullspace_is_generic():
    a = symbols("a")
    (v,) = nullspace_exact([[a, 1]])
    assert Matrix([[a, 1]]) * Matrix(v) == Matrix([[0]])


def test_fixing_the_last_coordinate_reproduces_the_point():
    assert solve_by_fixing_coordinate([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]]) == (1, 2, 3, 1)


def test_fixing_a_coordinate_that_is_zero_raises_and_suggests_others():
    # planes z = 0, z = 1, x = 0 meet in the ideal point (0, 1, 0, 0): x4 = 0 cannot be set to 1
    M = [Plane(0, 0, 1, 0), Plane(0, 0, 1, -1), Plane(1, 0, 0, 0)]
    with pytest.raises(ZeroCoordinateError, match=r"one of \[1\]"):
        solve_by_fixing_coordinate(M)
    assert solve_by_fixing_coordinate(M, index=1) == (0, 1, 0, 0)
    assert issubclass(ZeroCoordinateError, DegenerateConfigurationError)


def test_fixing_a_coordinate_of_a_rank_deficient_system_raises_the_named_error():
    with pytest.raises(CollinearPointsError):
        solve_by_fixing_coordinate([Point3(0, 0, 0), Point3(1, 1, 1), Point3(2, 2, 2)])
    with pytest.raises(DependentPlanesError):
        solve_by_fixing_coordinate([Plane(1, 0, 0, 0), Plane(0, 1, 0, 0), Plane(1, 1, 0, 0)])
    with pytest.raises(DegenerateConfigurationError, match="rank 2"):
        solve_by_fixing_coordinate([[1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0]])


def test_bad_shapes_and_indices():
    with pytest.raises(DimensionError, match=r"\(n-1\)×n"):
        solve_by_fixing_coordinate([[1, 0, 0, 0], [0, 1, 0, 0]])
    with pytest.raises(DimensionError, match="index"):
        solve_by_fixing_coordinate([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]], index=4)
    with pytest.raises(DimensionError):
        nullspace_exact([[1, 2], [3]])
    with pytest.raises(DimensionError):
        nullspace_exact([])
    with pytest.raises(DimensionError):
        rank_exact(5)


# -- numeric: worked examples ------------------------------------------------------------------------


def test_nullspace_svd_shape_and_tolerance():
    # diag(1, 1e-20): numerically rank 1 with the default tolerance, rank 2 with rtol = 0
    A = np.diag([1.0, 1e-20])
    assert nullspace_svd(A).shape == (2, 1)
    assert np.allclose(np.abs(nullspace_svd(A)[:, 0]), [0, 1])
    assert nullspace_svd(A, rtol=0).shape == (2, 0)
    assert numeric_rank(A) == 1 and numeric_rank(A, rtol=0) == 2
    assert nullspace_svd(np.zeros((2, 3))).shape == (3, 3)


def test_plane_through_numeric_three_and_more_points():
    pi = plane_through_numeric(np.array([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]], float))
    assert np.allclose(pi, np.array([1, 1, 1, -1]) / 2)  # unit norm, largest entry positive
    # four points on z = 2 plus a tiny error: least squares recovers z = 2
    pts = np.array([[0, 0, 2, 1], [1, 0, 2, 1], [0, 1, 2.000001, 1], [1, 1, 2, 1]])
    pi = plane_through_numeric(pts)
    assert np.allclose(pi / pi[2], [0, 0, 1, -2], atol=1e-5)


def test_point_on_planes_numeric_finite_and_ideal():
    X = point_on_planes_numeric([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]])
    assert np.allclose(X[:3] / X[3], [1, 2, 3])
    X = point_on_planes_numeric([[0, 0, 1, 0], [0, 0, 1, -1], [1, 0, 0, 0]])
    assert np.allclose(X, [0, 1, 0, 0])


def test_numeric_functions_accept_rows_of_points_and_planes():
    pi = plane_through_numeric([Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)])
    assert parallel_numeric(pi, [1, 1, 1, -1])
    X = point_on_planes_numeric([Plane(1, 0, 0, -1), Plane(0, 1, 0, -2), Plane(0, 0, 1, -3)])
    assert parallel_numeric(X, [1, 2, 3, 1])
    a = symbols("a")
    with pytest.raises(InvalidCoordinatesError, match="symbols"):
        plane_through_numeric([Point3(a, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1)])


def test_numeric_errors():
    with pytest.raises(CollinearPointsError):
        plane_through_numeric([[0, 0, 0, 1], [1, 1, 1, 1], [2, 2, 2, 1]])
    with pytest.raises(DependentPlanesError):
        point_on_planes_numeric([[1, 0, 0, 0], [0, 1, 0, 0], [1, 1, 0, 0]])
    with pytest.raises(DimensionError):
        plane_through_numeric([[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(DimensionError):
        point_on_planes_numeric([[1, 0, 0, 0], [0, 1, 0, 0]])
    with pytest.raises(InvalidCoordinatesError, match="NaN"):
        nullspace_svd([[np.nan, 1.0]])
    with pytest.raises(InvalidCoordinatesError):
        nullspace_svd([["a", 1.0]])
    with pytest.raises(InvalidCoordinatesError, match="rtol"):
        nullspace_svd([[1.0, 1.0]], rtol=-1)
    with pytest.raises(DimensionError):
        svd_steps(np.eye(3))


def test_svd_steps_of_a_rotation_times_a_stretch():
    # A = R(90°) diag(2, 1): the unit circle becomes an ellipse with semi-axes 2 and 1
    A = np.array([[0.0, -1.0], [1.0, 0.0]]) @ np.diag([2.0, 1.0])
    V, S, U = svd_steps(A)
    assert np.allclose(np.diag(S), [2, 1])
    assert np.allclose(U @ S @ V.T, A)
    assert np.isclose(np.linalg.det(V), 1) and np.isclose(np.linalg.det(U), 1)


def test_svd_steps_reflection_and_singular_matrices():
    V, S, U = svd_steps([[1.0, 0.0], [0.0, -3.0]])  # det < 0: U must be a reflection
    assert np.isclose(np.linalg.det(V), 1) and np.isclose(np.linalg.det(U), -1)
    V, S, U = svd_steps([[1.0, 2.0], [2.0, 4.0]])  # rank 1: both can be rotations
    assert np.isclose(S[1, 1], 0) and np.isclose(np.linalg.det(U), 1) and np.isclose(np.linalg.det(V), 1)
    # the right singular vector of σ2 = 0 spans the null space: (2, -1)/√5 up to sign
    assert np.isclose(abs(V[:, 1] @ np.array([2, -1])) / np.sqrt(5), 1)


# -- properties -------------------------------------------------------------------------------------------


@FAST
@given(rank3_rows())
def test_exact_nullspace_is_the_triple_cross_and_svd_agrees_up_to_scale(rows):
    (exact,) = nullspace_exact(rows)
    assert proportional(exact, plane_through(*(Point3(*r) for r in rows)).coords)  # rank 3: no zero row
    numeric = nullspace_svd(np.array(rows, float))
    assert numeric.shape == (4, 1)
    assert parallel_numeric(numeric[:, 0], exact)
    assert parallel_numeric(plane_through_numeric(rows), exact)
    assert parallel_numeric(point_on_planes_numeric(rows), point_on_planes(*(Plane(*r) for r in rows)).coords)


@FAST
@given(rank3_rows(), st.integers(0, 3))
def test_fixing_a_coordinate_agrees_with_the_null_space(rows, index):
    (exact,) = nullspace_exact(rows)
    if exact[index] == 0:
        with pytest.raises(ZeroCoordinateError):
            solve_by_fixing_coordinate(rows, index)
    else:
        solution = solve_by_fixing_coordinate(rows, index)
        assert solution[index] == 1
        assert proportional(solution, exact)


@FAST
@given(st.lists(st.lists(small, min_size=4, max_size=4), min_size=1, max_size=4))
def test_rank_and_nullity_add_up_and_numeric_rank_matches(rows):
    r = rank_exact(rows)
    basis = nullspace_exact(rows)
    assert r + len(basis) == 4
    for v in basis:
        assert Matrix(rows) * Matrix(v) == Matrix.zeros(len(rows), 1)
    assert numeric_rank(np.array(rows, float)) == r
    assert nullspace_svd(np.array(rows, float)).shape == (4, 4 - r)


@FAST
@given(st.lists(st.floats(-5, 5, allow_nan=False), min_size=4, max_size=4))
def test_svd_steps_recompose_the_matrix(entries):
    A = np.array(entries).reshape(2, 2)
    V, S, U = svd_steps(A)
    assert np.allclose(U @ S @ V.T, A, atol=1e-9)
    assert np.allclose(V.T @ V, np.eye(2)) and np.allclose(U.T @ U, np.eye(2))
    assert np.isclose(np.linalg.det(V), 1)
    assert S[0, 0] >= S[1, 1] >= 0


def test_importing_linalg_loads_no_numpy_and_the_numeric_names_come_from_pgsym_numeric():
    # exact cells must run where NumPy is absent: the module and its exact functions never load it
    code = (
        "import sys\n"
        "import pgsym.linalg as la\n"
        "assert la.nullspace_exact([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]]) == [(1, 2, 3, 1)]\n"
        "assert la.solve_by_fixing_coordinate([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]]) == (1, 2, 3, 1)\n"
        "print('numpy' in sys.modules)\n"
    )
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout == "False\n"
    import pgsym.linalg as la
    import pgsym.numeric as pn

    for name in ("nullspace_svd", "numeric_rank", "plane_through_numeric", "point_on_planes_numeric", "svd_steps",
                 "SVDSteps"):
        assert getattr(la, name) is getattr(pn, name)
    # an ndarray is still read exactly once NumPy is loaded (integer entries stay integers)
    assert la.nullspace_exact(np.array([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]])) == [(1, 2, 3, 1)]
    with pytest.raises(AttributeError, match="no attribute 'nullspace_numeric'"):
        la.nullspace_numeric  # noqa: B018


# -- the ring kit's determinant (skips zero entries) agrees with SymPy's ----------------------------------


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 5).flatmap(lambda n: st.lists(st.lists(st.integers(-2, 2), min_size=n, max_size=n),
                                                     min_size=n, max_size=n)))
def test_ring_det_matches_sympy(rows):
    from fractions import Fraction

    from pgsym import ring

    assert ring.det(rows) == Matrix(rows).det()
    assert ring.det([[Fraction(e) for e in r] for r in rows]) == Matrix(rows).det()


def test_nullspace_keeps_the_direction_of_a_basis_vector():
    # x + 2y = 0 in 2 unknowns: SymPy's basis vector is (-2, 1); a positive factor keeps it, the
    # canonical form (first entry positive) would have flipped it to (2, -1)
    assert nullspace_exact([[1, 2]]) == [(-2, 1)]
    assert nullspace_exact([[Rational(1, 2), 1]]) == [(-2, 1)]
