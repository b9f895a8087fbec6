"""The degeneracy policy of the numeric constructions: the named error, or NaN rows and a mask."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import integers

import pgsym.numeric as pn
from pgsym.errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    CollinearPointsError,
    DependentPlanesError,
    OptionError,
)

# Rows 0 and 2 are degenerate, row 1 is not:
# row 0: (0,0,0,1), (1,1,1,1), (2,2,2,1) lie on the line through the origin with direction (1,1,1), so every
#        3×3 minor of the 3×4 matrix vanishes (its first three columns are rank 1, the last column (1,1,1));
# row 1: (0,0,0,1), (1,0,0,1), (0,1,0,1) span z = 0: minors n = (0, 0, 1, 0) after the sign rule
#        (n_2 = +det[[0,0,1],[1,0,1],[0,1,1]] = 1, the others have a zero column);
# row 2: a point repeated, (1,2,3,1) twice.
P = np.array([[0.0, 0, 0, 1], [0.0, 0, 0, 1], [1, 2, 3, 1]])
Q = np.array([[1.0, 1, 1, 1], [1, 0, 0, 1], [1, 2, 3, 1]])
R = np.array([[2.0, 2, 2, 1], [0, 1, 0, 1], [0, 0, 1, 1]])


def test_plane_through_raises_the_named_error_for_degenerate_rows():
    with pytest.raises(CollinearPointsError, match=r"2 of the 3 inputs are collinear points.*index \(0,\)"):
        pn.plane_through(P, Q, R)
    assert pn.plane_through(P[1], Q[1], R[1]).tolist() == [0, 0, 1, 0]


def test_plane_through_masks_like_dehomogenize():
    planes, ok = pn.plane_through(P, Q, R, degenerate="mask")
    assert ok.tolist() == [False, True, False]
    assert planes[1].tolist() == [0, 0, 1, 0] and np.isnan(planes[[0, 2]]).all()
    # the same shapes as the ideal-point mask: values (n, k), mask (n,)
    coords, finite = pn.dehomogenize(np.array([[1.0, 2, 1], [1, 1, 0], [2, 2, 2]]), ideal="mask")
    assert (planes.shape[:-1], ok.shape, ok.dtype) == (coords.shape[:-1], finite.shape, finite.dtype)


def test_component_major_layout_and_out_are_masked_in_place():
    out = np.empty((4, 3))
    planes, ok = pn.plane_through(P.T, Q.T, R.T, axis=0, out=out, degenerate="mask")
    assert planes is out and ok.tolist() == [False, True, False]
    assert out[:, 1].tolist() == [0, 0, 1, 0] and np.isnan(out[:, [0, 2]]).all()


def test_non_finite_and_degenerate_masks_combine():
    p = P.copy()
    p[1, 0] = np.nan  # row 1 now non-finite, rows 0 and 2 still degenerate
    planes, ok = pn.plane_through(p, Q, R, nonfinite="mask", degenerate="mask")
    assert ok.tolist() == [False, False, False] and np.isnan(planes).all()
    values, finite = pn.plane_through(p[1:2], Q[1:2], R[1:2], nonfinite="mask")  # non-finite only: no raise
    assert finite.tolist() == [False] and np.isnan(values).all()


def test_point_on_planes_raises_or_masks_planes_through_one_line():
    # x = 0, y = 0 and x + y = 0 all contain the z-axis: the third row is the sum of the first two
    a, b, c = np.array([1.0, 0, 0, 0]), np.array([0.0, 1, 0, 0]), np.array([[1.0, 1, 0, 0], [0, 0, 1, -3]])
    with pytest.raises(DependentPlanesError, match="one line"):
        pn.point_on_planes(a, b, c)
    points, ok = pn.point_on_planes(a, b, c, degenerate="mask")
    # x = 0, y = 0, z = 3 meet in (0, 0, 3): minors of [[1,0,0,0],[0,1,0,0],[0,0,1,-3]] give (0, 0, 3, 1) up to sign
    assert ok.tolist() == [False, True] and np.isnan(points[0]).all()
    assert points[1].tolist() == [0, 0, -3, -1]


def test_join_and_meet_keep_the_zero_vector_by_default_and_offer_the_policy():
    p, q = np.array([[1.0, 2, 1], [0, 0, 1]]), np.array([[2.0, 4, 2], [1, 0, 1]])  # (1, 2) twice; then two points
    assert pn.join(p, q)[0].tolist() == [0, 0, 0]
    with pytest.raises(CoincidentPointsError, match="coincident points"):
        pn.join(p, q, degenerate="raise")
    lines, ok = pn.join(p, q, degenerate="mask")
    # (0, 0, 1) × (1, 0, 1) = (0·1 − 1·0, 1·1 − 0·1, 0·0 − 0·1) = (0, 1, 0): the x-axis
    assert ok.tolist() == [False, True] and lines[1].tolist() == [0, 1, 0] and np.isnan(lines[0]).all()
    with pytest.raises(CoincidentLinesError, match="equal lines"):
        pn.meet([1.0, -1, 0], [-2.0, 2, 0], degenerate="raise")
    point, ok = pn.meet([1.0, -1, 0], [-2.0, 2, 0], degenerate="mask")
    assert not ok and np.isnan(point).all()


def test_plucker_join_and_meet_offer_the_policy_too():
    a, b = np.array([[1.0, 2, 3, 1], [0, 0, 0, 1]]), np.array([[2.0, 4, 6, 2], [1, 0, 0, 1]])  # one point twice
    assert pn.plucker_join(a, b)[0].tolist() == [0] * 6
    with pytest.raises(CoincidentPointsError, match="coincident points"):
        pn.plucker_join(a, b, degenerate="raise")
    lines, ok = pn.plucker_join(a, b, degenerate="mask")
    # the x-axis through (0,0,0,1) and (1,0,0,1): l14 = A1 B4 − B1 A4 = 0·1 − 1·1 = −1, every other l_ij is 0
    assert ok.tolist() == [False, True] and lines[1].tolist() == [0, 0, -1, 0, 0, 0] and np.isnan(lines[0]).all()
    with pytest.raises(DependentPlanesError, match="equal planes"):
        pn.plucker_meet([0.0, 1, 0, 0], [0.0, -2, 0, 0], degenerate="raise")


@pytest.mark.parametrize("f", [pn.plane_through, pn.point_on_planes, pn.join, pn.meet, pn.plucker_join])
def test_an_unknown_option_is_an_option_error(f):
    args = {pn.plane_through: (P, Q, R), pn.point_on_planes: (P, Q, R), pn.plucker_join: (P, Q)}.get(
        f, (P[:, :3], Q[:, :3])
    )
    with pytest.raises(OptionError, match="degenerate='ignore'"):
        f(*args, degenerate="ignore")


def test_the_bare_formulas_keep_zero_vectors():
    assert pn.triple_cross(P, Q, R)[0].tolist() == [0, 0, 0, 0]
    assert pn.cross([1.0, 2, 1], [2.0, 4, 2]).tolist() == [0, 0, 0]


INTS = integers(3).map(float)


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.lists(INTS, min_size=4, max_size=4), min_size=3, max_size=3),
    st.lists(st.sampled_from([-2.0, -1.0, 0.5, 3.0]), min_size=3, max_size=3),
)
def test_the_mask_is_projective_scaling_a_row_changes_nothing(rows, scales):
    p, q, r = (np.array([row]) for row in rows)
    _, ok = pn.plane_through(p, q, r, degenerate="mask")
    _, ok_scaled = pn.plane_through(scales[0] * p, scales[1] * q, scales[2] * r, degenerate="mask")
    assert ok.tolist() == ok_scaled.tolist()
    # masked exactly where the numerical rank of the three points is below 3 (small integers: no rounding)
    assert ok[0] == (np.linalg.matrix_rank(np.vstack([p, q, r])) == 3)
