"""Homography estimation: normalised DLT, the exact four-point solution, the batched solver."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers, invertible_matrices

from pgsym.errors import (
    CollinearPointsError,
    DegenerateConfigurationError,
    DimensionError,
    IdealPointError,
    NonFiniteError,
)
from pgsym.projective_plane import Point, collinear
from pgsym.vision.homography import (
    apply_homography,
    dlt_homography,
    exact_homography,
    homographies_from_four,
    normalize_homography,
    normalizing_transform,
    reprojection_error,
)

# H0 has h33 = 0: it sends the origin (0, 0, 1) to the ideal point (0, 3, 0).
# det H0 = 2 (1*0 - 3*1) - 1 (0*0 - 3*1) + 0 = -6 + 3 = -3, so it is invertible.
H0 = [[2, 1, 0], [0, 1, 3], [1, 1, 0]]
# Its images of four points, by hand:
#   (1, 0, 1) -> (2, 3, 1)      = (2, 3)
#   (0, 1, 1) -> (1, 4, 1)      = (1, 4)
#   (1, 1, 1) -> (3, 4, 2)      = (3/2, 2)
#   (3, 2, 1) -> (8, 5, 5)      = (8/5, 1)
# and no three of the four source points are collinear (checked by hand: no line x = 1, y = 1 or x + y = 1
# holds for a third point).
SRC0 = [(1, 0), (0, 1), (1, 1), (3, 2)]
DST0 = [(2, 3), (1, 4), (Fraction(3, 2), 2), (Fraction(8, 5), 1)]


def test_exact_four_point_homography_with_h33_zero():
    H = exact_homography(SRC0, DST0)
    # H0 has integer entries with gcd 1 and a positive first entry: it is already canonical
    assert H == sympy.ImmutableMatrix(H0)


def test_dlt_and_batch_recover_h33_zero():
    src = np.array(SRC0, float)
    dst = np.array(DST0, float)
    expected = normalize_homography(np.array(H0, float))
    H = dlt_homography(src, dst)
    assert abs(H[2, 2]) < 1e-12
    assert np.abs(H - expected).max() < 1e-12
    B = homographies_from_four(src[None], dst[None])
    assert abs(B[0, 2, 2]) < 1e-12 and np.abs(B[0] - expected).max() < 1e-12


def test_exact_homography_with_ideal_points():
    # the unit square to a frame with two ideal points: e1 = (1,0,0), e2 = (0,1,0), origin, (1,1,1)
    src = [Point(1, 0), Point(0, 1), Point(0, 0), Point(1, 1)]
    dst = [Point(1, 0, 0), Point(0, 1, 0), Point(0, 0), Point(1, 1)]
    H = exact_homography(src, dst)
    for p, q in zip(src, dst, strict=True):
        image = H * sympy.Matrix(p.coords)
        assert Point(*image) == q


def test_exact_result_is_canonical():
    # scaling the destination frame does not change the canonical matrix; x -> 2x, y -> y by hand
    H = exact_homography([(0, 0), (1, 0), (1, 1), (0, 1)], [(0, 0), (2, 0), (2, 1), (0, 1)])
    assert H == sympy.ImmutableMatrix([[2, 0, 0], [0, 1, 0], [0, 0, 1]])
    H2 = exact_homography([(0, 0), (1, 0), (1, 1), (0, 1)], [Point(0, 0, 3), Point(6, 0, 3), Point(2, 1), (0, 1)])
    assert H2 == H


small = integers(6)


@st.composite
def four_points_in_general_position(draw):
    triples = [(draw(small), draw(small), draw(st.sampled_from([0, 1, 1, 2]))) for _ in range(4)]
    assume(all(t != (0, 0, 0) for t in triples))
    pts = [Point(*t) for t in triples]
    assume(not any(collinear(a, b, c) for a, b, c in
                   [(pts[0], pts[1], pts[2]), (pts[0], pts[1], pts[3]), (pts[0], pts[2], pts[3]),
                    (pts[1], pts[2], pts[3])]))
    return pts


def matrix_up_to_scale_equal(A, B) -> bool:
    # A ~ B  iff  every 2x2 "cross" a_i b_j - a_j b_i vanishes
    a, b = list(A), list(B)
    return all(sympy.expand(a[i] * b[j] - a[j] * b[i]) == 0 for i in range(9) for j in range(9))


@settings(max_examples=25, deadline=None)
@given(four_points_in_general_position(), invertible_matrices().map(sympy.Matrix))
def test_exact_homography_recovers_a_known_rational_homography(pts, M):
    images = [Point(*(M * sympy.Matrix(p.coords))) for p in pts]
    H = exact_homography(pts, images)
    assert matrix_up_to_scale_equal(H, M)


def random_problem(rng, n, h33_zero=False):
    H = rng.normal(size=(3, 3))
    H[2, :2] *= 0.2
    if h33_zero:
        H[2, 2] = 0.0
    src = rng.uniform(-1, 1, size=(n, 2))
    if h33_zero:
        src = src + np.sign(src.sum(axis=1, keepdims=True) + 1e-3) * 0.5
    return H, src, apply_homography(H, src)


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(4, 60), st.booleans(), st.sampled_from([1.0, 100.0, 1000.0]))
def test_dlt_recovers_a_known_homography_to_1e10(seed, n, h33_zero, scale):
    rng = np.random.default_rng(seed)
    H, src, dst = random_problem(rng, n, h33_zero)
    # pixel-like coordinates: conjugate by a scaling on both sides
    S = np.diag([scale, scale, 1.0])
    Hs = S @ H @ np.linalg.inv(S)
    src, dst = src * scale, dst * scale
    w = (np.c_[src, np.ones(n)] @ Hs.T)[:, 2]
    assume(np.all(np.abs(w) > 1e-3 * np.abs(Hs).max() * scale))
    assume(np.linalg.cond(Hs) < 1e6 and np.abs(dst).max() < 1e4 * scale)
    try:
        est = dlt_homography(src, dst)
    except DegenerateConfigurationError:  # collinear, or so nearly so (σ ratio ≤ 1e-5) that the DLT refuses
        assume(False)
    assert np.abs(est - normalize_homography(Hs)).max() < 1e-10 * np.linalg.cond(Hs)
    assert reprojection_error(est, src, dst).max() < 1e-10 * max(1.0, np.abs(dst).max())


def test_dlt_reprojection_on_1000_pixel_points_below_1e10():
    rng = np.random.default_rng(7)
    H = np.array([[1.1, 0.2, 30.0], [-0.1, 0.9, 12.0], [2e-4, 1e-4, 1.0]])
    src = rng.uniform(0, 1000, (1000, 2))
    dst = apply_homography(H, src)
    assert reprojection_error(dlt_homography(src, dst), src, dst).max() < 1e-10


def test_dlt_least_squares_with_noise_is_close():
    rng = np.random.default_rng(3)
    H = np.array([[1.0, 0.1, 5.0], [0.05, 1.2, -3.0], [1e-3, 2e-3, 1.0]])
    src = rng.uniform(0, 200, (200, 2))
    dst = apply_homography(H, src) + rng.normal(scale=0.1, size=(200, 2))
    assert np.sqrt(np.mean(reprojection_error(dlt_homography(src, dst), src, dst) ** 2)) < 0.2


def test_batched_equals_per_problem():
    rng = np.random.default_rng(11)
    problems = [random_problem(rng, 4, h33_zero=(i % 3 == 0)) for i in range(200)]
    src = np.stack([p[1] for p in problems])
    dst = np.stack([p[2] for p in problems])
    B = homographies_from_four(src, dst)
    per = np.stack([dlt_homography(s, d) for s, d in zip(src, dst, strict=True)])
    truth = normalize_homography(np.stack([p[0] for p in problems]))
    assert B.shape == (200, 3, 3)
    assert np.abs(B - per).max() < 1e-8
    assert np.abs(B - truth).max() < 1e-8


def test_batched_matches_the_exact_solution():
    exact = np.array(exact_homography(SRC0, DST0).tolist(), float)
    B = homographies_from_four(np.array([SRC0], float), np.array([DST0], float))
    assert np.abs(B[0] - normalize_homography(exact)).max() < 1e-14


def test_normalizing_transform_centres_and_scales():
    pts = np.array([[0, 0], [4, 0], [4, 2], [0, 2], [1, 1]], float)
    T = normalizing_transform(pts)
    q = pts @ T[:2, :2].T + T[:2, 2]
    assert np.allclose(q.mean(axis=0), 0)
    assert np.sqrt((q**2).sum(axis=1).mean()) == pytest.approx(np.sqrt(2))


@pytest.mark.parametrize(
    "src",
    [
        [(0, 0), (1, 1), (2, 2), (0, 1)],  # points 1, 2, 3 on y = x
        [(0, 1), (5, 0), (1, 0), (3, 0)],  # points 2, 3, 4 on y = 0
    ],
)
def test_three_collinear_points_raise(src):
    dst = [(0, 0), (1, 0), (1, 1), (0, 1)]
    with pytest.raises(CollinearPointsError, match="collinear"):
        exact_homography(src, dst)
    with pytest.raises(CollinearPointsError, match="collinear"):
        dlt_homography(np.array(src, float), np.array(dst, float))
    with pytest.raises(CollinearPointsError, match="collinear"):
        dlt_homography(np.array(dst, float), np.array(src, float))
    with pytest.raises(CollinearPointsError, match="problem 1"):
        homographies_from_four(np.array([dst, src], float), np.array([dst, dst], float))


def test_all_points_on_one_line_raise():
    src = np.c_[np.arange(10.0), 2 * np.arange(10.0) + 1]
    with pytest.raises(CollinearPointsError):
        dlt_homography(src, src + 1)


@pytest.mark.parametrize(
    ("call", "error"),
    [
        (lambda: dlt_homography(np.zeros((3, 2)), np.zeros((3, 2))), DimensionError),
        (lambda: dlt_homography(np.zeros((4, 3)), np.zeros((4, 3))), DimensionError),
        (lambda: dlt_homography(np.eye(4, 2), np.eye(5, 2)), DimensionError),
        (lambda: exact_homography([(0, 0)] * 3, [(0, 0)] * 3), DimensionError),
        (lambda: homographies_from_four(np.zeros((2, 3, 2)), np.zeros((2, 3, 2))), DimensionError),
        (lambda: dlt_homography([[0, 0], [1, 0], [1, 1], [np.nan, 1]], np.eye(4, 2)), NonFiniteError),
    ],
)
def test_bad_shapes(call, error):
    with pytest.raises(error):
        call()


def test_empty_batch_and_apply_homography():
    assert homographies_from_four(np.zeros((0, 4, 2)), np.zeros((0, 4, 2))).shape == (0, 3, 3)
    # a point on the line sent to infinity has no image: a named error, or a mask when asked for
    with pytest.raises(IdealPointError):
        apply_homography(np.array(H0, float), [[0.0, 0.0]])
    out, finite = apply_homography(np.array(H0, float), [[0.0, 0.0]], ideal="mask")
    assert finite.tolist() == [False] and np.isnan(out).all()


def test_numeric_homography_path_does_not_load_sympy():
    import subprocess
    import sys

    code = (
        "import sys\n"
        "import numpy as np\n"
        "from pgsym.vision.homography import dlt_homography\n"
        "src = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])\n"
        "dlt_homography(src, 2 * src + 1)\n"
        "print('sympy' in sys.modules)\n"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "False"
