"""Metric rectification in one step from five or more orthogonal line pairs (H&Z 2.7.5), and its error analysis.

The synthetic cases know the world-to-image map ``Hw``: the rectified map ``H Hw`` must then be a
similarity, ``[[s R, t], [0, 1]]`` up to scale, which is checked on the matrix itself (``AᵀA = s² I``,
last row ``(0, 0, 1)``). The photograph is the chapter's keystoned checkerboard: its corners are *measured*
(OpenCV's chessboard detector with sub-pixel refinement), lines are fitted through them, and the
rectified right angles are compared with 90° — for this method and for the two-step method.
"""

from __future__ import annotations

import cv2
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pgsym.errors import DegenerateConfigurationError, DimensionError, InconsistentDataError
from pgsym.vision.homography import apply_homography
from pgsym.vision.rectify import (
    dual_conic_from_orthogonal_pairs,
    line_through,
    metric_rectification,
    metric_rectification_from_orthogonal_pairs,
    transform_lines,
)
from pgsym.vision.warp import warp


def similarity_defect(M: np.ndarray) -> float:
    """How far ``M`` (up to scale) is from a similarity: 0 exactly for ``[[s R, t], [0, 1]]`` with R orthogonal."""
    M = M / M[2, 2]
    A = M[:2, :2]
    G = A.T @ A
    g = np.trace(G) / 2
    return float(max(np.abs(G - g * np.eye(2)).max() / g, np.abs(M[2, :2]).max() * np.sqrt(g)))


def grid_pairs(Hw: np.ndarray, n: int = 5) -> list[tuple[np.ndarray, np.ndarray]]:
    """Image lines of an orthonormal world grid 0..n: each row with each column, each diagonal with each anti-diagonal
    through a common grid point (every such pair is a right angle in the world)."""
    def line(p, q):
        return line_through(*apply_homography(Hw, np.array([p, q], float)))

    rows = [line([0, t], [1, t]) for t in range(n + 1)]
    cols = [line([t, 0], [t, 1]) for t in range(n + 1)]
    pairs = [(r, c) for r in rows for c in cols]
    for k in range(-n + 1, n):  # x − y = k against x + y = k + 2j, meeting at the grid point (j + k, j)
        for j in range(max(0, -k), min(n, n - k) + 1):
            pairs.append((line([k, 0], [k + 1, 1]), line([j + k + 1, j - 1], [j + k - 1, j + 1])))
    return pairs


HW = np.array([[2.0, 0.4, 40.0], [0.1, 1.6, 30.0], [0.0015, 0.0025, 1.0]])  # world (0..100)² → image


def test_a_known_view_of_an_orthonormal_grid_is_rectified_to_a_similarity():
    world = 20.0 * np.eye(3)
    world[2, 2] = 1.0  # the grid 0..5 scaled to 0..100
    Hw = HW @ world
    H = metric_rectification_from_orthogonal_pairs(grid_pairs(Hw), reference=(200, 150), scale=200)
    assert similarity_defect(H @ Hw) < 1e-9
    # and with exactly five pairs: three "+" shapes (rows and columns) and two "x" shapes, in different places
    pairs = grid_pairs(Hw)
    five = [pairs[0], pairs[14], pairs[35], pairs[40], pairs[-1]]
    assert similarity_defect(metric_rectification_from_orthogonal_pairs(five, (200, 150), 200) @ Hw) < 1e-9


def test_the_image_of_the_dual_conic_is_hw_cstar_hwt():
    # C*∞′ = Hw diag(1, 1, 0) Hwᵀ, up to scale: compare after normalising both to unit Frobenius norm
    C = dual_conic_from_orthogonal_pairs(grid_pairs(HW / 100))
    expected = HW @ np.diag([1.0, 1, 0]) @ HW.T
    expected /= np.linalg.norm(expected)
    assert np.abs(C - expected).max() < 1e-6  # pixel-sized lines unconditioned: still six digits


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-0.4, 0.4), min_size=6, max_size=6), st.floats(-0.002, 0.002), st.floats(-0.002, 0.002))
def test_random_views_are_rectified_to_similarities(entries, g, h):
    a, b, c, d, e, f = entries
    Hw = np.array([[1 + a, b, 10 + 50 * c], [d, 1 + e, 10 + 50 * f], [g, h, 1.0]]) @ np.diag([20.0, 20, 1])
    assume(abs(np.linalg.det(Hw[:2, :2])) > 0.3 * 400)
    corners = np.c_[[0, 5, 5, 0], [0, 0, 5, 5], np.ones(4)] @ Hw.T
    assume(np.all(corners[:, 2] > 0.3))  # the whole grid in front of the camera
    H = metric_rectification_from_orthogonal_pairs(grid_pairs(Hw), reference=(60, 60), scale=100)
    assert similarity_defect(H @ Hw) < 1e-8
    # no mirror image: Hw keeps orientation (det of its linear part > 0, w > 0), and so does the similarity
    M = H @ Hw
    assert M[2, 2] > 0 and np.linalg.det(M[:2, :2]) > 0


def test_too_few_or_dependent_or_inconsistent_pairs_raise():
    pairs = grid_pairs(HW)
    with pytest.raises(DimensionError, match="five"):
        metric_rectification_from_orthogonal_pairs(pairs[:4])
    # rows against columns only: the constraints leave the aspect ratio free (at most four independent)
    rows_cols = pairs[:36]
    with pytest.raises(DegenerateConfigurationError, match="independent"):
        metric_rectification_from_orthogonal_pairs(rows_cols, reference=(200, 150), scale=200)
    # "right angles" that are not: a row against itself shifted, five times
    line = line_through((0, 0), (1, 0.2))
    bad = [(line, line_through((0, t), (1, 0.2 + t * 1.1))) for t in (1, 2, 3, 4, 5, 6)]
    with pytest.raises(DegenerateConfigurationError, match="independent"):
        metric_rectification_from_orthogonal_pairs(bad)
    # pairs l = (a, b, c), m = (b, a, d) satisfy l1 m1 - l2 m2 = ab - ba = 0: the null vector of the system is
    # diag(1, -1, 0) (eigenvalues 1, 0, -1), indefinite, while the image of C*∞ is positive semi-definite for
    # every real camera. No world has these right angles: inconsistent data, not a degenerate configuration
    abcd = [(1, 2, 3, 5), (2, -1, 1, 4), (3, 1, -2, 1), (1, 4, 2, -3), (2, 3, -1, 2)]
    hyperbolic = [((a, b, c), (b, a, d)) for a, b, c, d in abcd]
    with pytest.raises(InconsistentDataError, match="inconsistent"):
        metric_rectification_from_orthogonal_pairs(hyperbolic)
    assert issubclass(InconsistentDataError, DegenerateConfigurationError)


# -- the chapter's photograph ---------------------------------------------------------------------------

# The rectification chapter's camera: world (an 8 × 8 board of 30-pixel squares) → a 640 × 400 photograph.
HW_BOOK = np.array([[3, 1, 60], [1 / 5, 2, 40], [1 / 800, 1 / 500, 1]])


@pytest.fixture(scope="module")
def measured_grid() -> np.ndarray:
    yy, xx = np.mgrid[0:240, 0:240]
    world = np.where(((xx // 30) + (yy // 30)) % 2 == 0, 0.85, 0.15).astype(np.float32)
    photo = np.round(warp(world, HW_BOOK, (640, 400)) * 255).astype(np.uint8)
    found, corners = cv2.findChessboardCorners(photo, (7, 7))
    assert found
    criteria = (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 100, 1e-4)
    c = cv2.cornerSubPix(photo, corners, (5, 5), (-1, -1), criteria).reshape(-1, 2).astype(float)
    # the inner corners are the world points (30 i − ½, 30 j − ½) (pixel centres at integers): match by distance
    truth = apply_homography(HW_BOOK, np.array([[30 * i - 0.5, 30 * j - 0.5] for j in range(1, 8)
                                                for i in range(1, 8)]))
    distance = np.linalg.norm(c[:, None] - truth[None], axis=2)
    assert distance.min(axis=0).max() < 0.5  # every corner measured to half a pixel
    return c[distance.argmin(axis=0)].reshape(7, 7, 2)  # [row j, column i]


def fit(points: np.ndarray) -> np.ndarray:
    centre = points.mean(axis=0)
    n = np.linalg.svd(points - centre)[2][1]
    return np.array([n[0], n[1], -n @ centre])


def worst_right_angle(H: np.ndarray) -> float:
    """The largest deviation from 90° (degrees) between the true rows and columns of the board, rectified by H."""
    ts = np.arange(0, 241, 30)
    rows = [line_through(*apply_homography(HW_BOOK, [[0, t], [240, t]])) for t in ts]
    cols = [line_through(*apply_homography(HW_BOOK, [[t, 0], [t, 240]])) for t in ts]
    R, C = transform_lines(H, rows)[:, :2], transform_lines(H, cols)[:, :2]
    cos = np.abs(R @ C.T) / np.outer(np.linalg.norm(R, axis=1), np.linalg.norm(C, axis=1))
    return float(np.degrees(np.arcsin(cos.max())))


def test_rectifying_the_photograph_from_measured_lines(measured_grid):
    G = measured_grid
    rows, cols = [fit(G[j]) for j in range(7)], [fit(G[:, i]) for i in range(7)]
    diag = {k: fit(np.array([G[j, j + k] for j in range(7) if 0 <= j + k < 7])) for k in range(-4, 5)}
    anti = {k: fit(np.array([G[j, k - j] for j in range(7) if 0 <= k - j < 7])) for k in range(2, 11)}
    centre = (319.5, 199.5)
    every = [(r, c) for r in rows for c in cols] + [(diag[a], anti[b]) for a in diag for b in anti]
    five = [(rows[0], cols[0]), (rows[6], cols[6]), (rows[3], cols[3]), (diag[0], anti[6]), (diag[3], anti[5])]
    two_step = metric_rectification([(rows[0], rows[6]), (cols[0], cols[6])], [(rows[0], cols[0]), (diag[0], anti[6])],
                                    reference=centre)
    errors = {
        "all pairs": worst_right_angle(metric_rectification_from_orthogonal_pairs(every, centre, 320)),
        "five pairs": worst_right_angle(metric_rectification_from_orthogonal_pairs(five, centre, 320)),
        "two-step": worst_right_angle(two_step),
    }
    # the photograph itself is far from right-angled
    assert worst_right_angle(np.eye(3)) > 10
    # measured to about 0.05 px, the corners give right angles to a few hundredths of a degree with all 130
    # pairs, and to about a tenth with the minimal five; the two-step method, from its four outer lines and
    # the diagonals, is as good as all pairs here
    assert errors["all pairs"] < 0.05 and errors["five pairs"] < 0.25 and errors["two-step"] < 0.05
    assert errors["all pairs"] < errors["five pairs"]
