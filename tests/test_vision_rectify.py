"""Rectification (four points, vanishing line, orthogonal pairs) and warping, on synthetic views of a grid."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pgsym.errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DimensionError,
    InconsistentDataError,
    SingularTransformationError,
)
from pgsym.vision.errors import ImageError
from pgsym.vision.harris import harris
from pgsym.vision.homography import apply_homography
from pgsym.vision.rectify import (
    affine_rectification,
    fit_to_size,
    line_through,
    metric_rectification,
    metric_upgrade,
    rectangle_homography,
    transform_lines,
    vanishing_line,
)
from pgsym.vision.warp import check_homography, warp, warp_numpy

# A perspective view of the world plane: world (X, Y) in [0, 100]^2 -> image pixels.
HW = np.array([[2.0, 0.4, 40.0], [0.1, 1.6, 30.0], [0.0015, 0.0025, 1.0]])


def img(*world_points):
    return apply_homography(HW, np.array(world_points, float))


def direction_angle(line):
    """Angle (degrees, in [0, 180)) of the direction of a line (a, b, c)."""
    return np.degrees(np.arctan2(-line[0], line[1])) % 180.0


def angle_between(l, m):
    d = abs(direction_angle(l) - direction_angle(m)) % 180.0
    return min(d, 180.0 - d)


def world_grid_lines():
    """Image lines of a 5 × 5 world grid: five 'horizontal' and five 'vertical' lines."""
    ts = np.linspace(0, 100, 5)
    horizontal = [line_through(*img([0, t], [100, t])) for t in ts]
    vertical = [line_through(*img([t, 0], [t, 100])) for t in ts]
    return horizontal, vertical


def square_lines():
    a, b, c, d = img([0, 0], [100, 0], [100, 100], [0, 100])
    parallel = [(line_through(a, b), line_through(d, c)), (line_through(a, d), line_through(b, c))]
    orthogonal = [(line_through(a, b), line_through(a, d)), (line_through(a, c), line_through(b, d))]
    return (a, b, c, d), parallel, orthogonal


def test_the_view_really_is_distorted():
    horizontal, vertical = world_grid_lines()
    spread = max(direction_angle(l) for l in horizontal) - min(direction_angle(l) for l in horizontal)
    assert spread > 3.0  # image lines of world-parallel lines converge
    assert abs(angle_between(horizontal[0], vertical[0]) - 90.0) > 5.0


def test_affine_rectification_restores_parallelism_on_the_whole_grid():
    _, parallel, _ = square_lines()
    l_inf = vanishing_line(*parallel)
    # the vanishing line is the image of the line at infinity: H_W^{-T} (0, 0, 1), up to scale
    expected = np.linalg.solve(HW.T, [0.0, 0.0, 1.0])
    assert np.linalg.norm(np.cross(l_inf, expected)) < 1e-12 * np.linalg.norm(expected)
    H = affine_rectification(l_inf, reference=img([50, 50])[0])
    horizontal, vertical = world_grid_lines()
    h = transform_lines(H, horizontal)
    v = transform_lines(H, vertical)
    assert max(angle_between(h[0], x) for x in h) < 1e-9
    assert max(angle_between(v[0], x) for x in v) < 1e-9
    # the composite world -> rectified map is affine: last row (0, 0, *)
    A = H @ HW
    assert np.abs(A[2, :2]).max() < 1e-12 * abs(A[2, 2])
    # but angles are not yet right in general
    assert abs(angle_between(h[0], v[0]) - 90.0) > 1.0


def test_metric_rectification_restores_right_angles_and_ratios():
    corners, parallel, orthogonal = square_lines()
    H = metric_rectification(parallel, orthogonal, reference=corners[0])
    horizontal, vertical = world_grid_lines()
    h = transform_lines(H, horizontal)
    v = transform_lines(H, vertical)
    assert max(abs(angle_between(a, b) - 90.0) for a in h for b in v) < 1e-8
    # world -> rectified is a similarity: A = s R (+ t)
    S = H @ HW
    S = S / S[2, 2]
    B = S[:2, :2]
    assert np.allclose(B @ B.T, np.eye(2) * (B @ B.T)[0, 0], rtol=1e-9, atol=1e-12)
    r = apply_homography(H, np.array(corners))
    sides = np.linalg.norm(np.roll(r, -1, axis=0) - r, axis=1)
    assert sides.max() / sides.min() == pytest.approx(1.0, abs=1e-9)


@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(-0.3, 0.3), min_size=6, max_size=6), st.floats(-0.003, 0.003), st.floats(-0.003, 0.003))
def test_metric_rectification_for_random_views(entries, g, h):
    a, b, c, d, e, f = entries
    Hw = np.array([[1 + a, b, 10 + 50 * c], [d, 1 + e, 10 + 50 * f], [g, h, 1.0]])
    assume(abs(np.linalg.det(Hw)) > 0.3)
    world = np.array([[0, 0], [100, 0], [100, 100], [0, 100]], float)
    q = np.c_[world, np.ones(4)] @ Hw.T
    assume(np.all(q[:, 2] > 0.2))
    A, B, C, D = q[:, :2] / q[:, 2:]
    parallel = [(line_through(A, B), line_through(D, C)), (line_through(A, D), line_through(B, C))]
    orthogonal = [(line_through(A, B), line_through(A, D)), (line_through(A, C), line_through(B, D))]
    H = metric_rectification(parallel, orthogonal, reference=(A + C) / 2)
    r = apply_homography(H, np.array([A, B, C, D]))
    e1, e2 = r[1] - r[0], r[3] - r[0]
    cos = e1 @ e2 / (np.linalg.norm(e1) * np.linalg.norm(e2))
    assert abs(cos) < 1e-8
    assert np.linalg.norm(e1) / np.linalg.norm(e2) == pytest.approx(1.0, abs=1e-8)


def checkerboard(size=200, square=25):
    y, x = np.mgrid[0:size, 0:size]
    return (((x // square) + (y // square)) % 2).astype(np.float32)


def test_four_point_rectification_of_a_warped_checkerboard():
    world = checkerboard()
    # warp the world image (pixel = world unit) into a 320 x 260 "photograph"
    H = np.array([[1.0, 0.25, 40.0], [0.05, 0.9, 20.0], [0.0012, 0.0008, 1.0]])
    photo = warp(world, H, (320, 260))
    corners = apply_homography(H, [[0, 0], [199, 0], [199, 199], [0, 199]])
    R = rectangle_homography(corners, (200, 200))
    back = warp(photo, R, (200, 200))
    # away from the square boundaries (where two rounds of interpolation blur an edge) the image is restored
    y, x = np.mgrid[0:200, 0:200]
    inner = ((x % 25) >= 3) & ((x % 25) <= 21) & ((y % 25) >= 3) & ((y % 25) <= 21)
    assert np.abs(back - world)[inner].max() < 0.02
    assert np.abs(back - world).mean() < 0.05
    # Harris on the rectified board: its inner corners on the 25-pixel lattice (within 2.5 px), rows straight
    corners_found = harris(back, sigma=1.5, threshold=0.1, min_distance=8).corners
    inner_lattice = np.array([[i * 25 - 0.5, j * 25 - 0.5] for i in range(1, 8) for j in range(1, 8)])
    dist = np.array([np.min(np.linalg.norm(corners_found - p, axis=1)) for p in inner_lattice])
    assert dist.max() <= 2.5 and dist.mean() <= 1.0


def test_vanishing_line_of_parallel_image_lines_is_at_infinity():
    l = vanishing_line([[1, 0, 0], [1, 0, -5]], [[0, 1, 0], [0, 1, -3]])
    assert np.allclose(l, [0, 0, 1])
    with pytest.raises(DegenerateConfigurationError, match="reference"):
        affine_rectification([1.0, 0.0, -5.0], reference=(5, 3))


def test_degenerate_inputs():
    with pytest.raises(CoincidentPointsError):
        line_through((1, 2), (1, 2))
    with pytest.raises(CoincidentLinesError):
        vanishing_line([[1, 0, 0], [2, 0, 0]], [[0, 1, 0], [0, 1, -1]])
    with pytest.raises(DegenerateConfigurationError, match="same vanishing point"):
        vanishing_line([[1, 0, 0], [1, 0, -1]], [[1, 0, -2], [1, 0, -3]])
    with pytest.raises(DegenerateConfigurationError, match="line at infinity"):
        vanishing_line([[0, 0, 1], [1, 0, -1]], [[0, 1, 0], [0, 1, -1]])
    with pytest.raises(DimensionError):
        vanishing_line([[1, 0], [1, 0, -1]], [[0, 1, 0], [0, 1, -1]])
    # two pairs with the same directions give one constraint only
    with pytest.raises(DegenerateConfigurationError, match="one independent"):
        metric_upgrade([([1, 0, 0], [0, 1, 0]), ([1, 0, 5], [0, 1, 7])])
    # "orthogonal" pairs that no affinity can make orthogonal: both pairs are the same two directions swapped.
    # Rows (l1 m1, l1 m2 + l2 m1, l2 m2) of the unit normals: (1, 1, 0)/√2 and (0, 1, -1)/√2; null vector
    # (1, -1, -1), so S = [[1, -1], [-1, -1]] with det S = -2 < 0: no S = K Kᵀ. The data are inconsistent,
    # not a special case, and the error says so (and is still a DegenerateConfigurationError for old callers)
    with pytest.raises(InconsistentDataError, match="inconsistent"):
        metric_upgrade([([1, 0, 0], [1, 1, 0]), ([1, -1, 0], [0, 1, 0])])
    assert issubclass(InconsistentDataError, DegenerateConfigurationError)
    with pytest.raises(DimensionError):
        metric_upgrade([([1, 0, 0], [0, 1, 0])])
    with pytest.raises(CollinearPointsError):
        rectangle_homography([[0, 0], [1, 1], [2, 2], [0, 5]], (10, 10))
    with pytest.raises(DimensionError):
        rectangle_homography([[0, 0], [1, 1], [2, 2]], (10, 10))
    with pytest.raises(DegenerateConfigurationError, match="crosses"):
        fit_to_size(affine_rectification([1.0, 0.0, -5.0]), [[0, 0], [10, 0], [10, 10], [0, 10]], (50, 50))


def test_warp_matches_the_numpy_reference_and_checks_its_input():
    rng = np.random.default_rng(5)
    image = rng.random((60, 80), dtype=np.float32)
    H = np.array([[0.9, 0.1, 5.0], [-0.05, 1.1, 3.0], [1e-4, 2e-4, 1.0]])
    a = warp(image, H, (90, 70))
    b = warp_numpy(image, H, (90, 70))
    # OpenCV quantises the interpolation weights to 1/32 of a pixel: differences stay below 1/32
    assert np.abs(a - b)[2:-2, 2:-2].max() < 1 / 32 + 1e-6
    assert np.array_equal(warp(image, np.eye(3), (80, 60)), image)
    assert np.allclose(warp_numpy(image, np.eye(3), (80, 60)), image)
    with pytest.raises(SingularTransformationError):
        warp(image, np.ones((3, 3)), (10, 10))
    with pytest.raises(DimensionError):
        check_homography(np.eye(2))
    with pytest.raises(ImageError):
        warp(image, np.eye(3), (0, 10))
    with pytest.raises(ImageError):
        warp(image.astype(float), np.eye(3), (10, 10))


def test_transform_lines_has_one_meaning_the_image_of_the_lines_by_the_adjugate():
    import pgsym.numeric as pn

    assert transform_lines is pn.transform_lines
    # H = diag(2, 1, 1) stretches x: adj(H) = diag(1·1, 2·1, 2·1) = diag(1, 2, 2), so the line x = 1, (1, 0, −1),
    # goes to adj(H)ᵀ (1, 0, −1) = (1, 0, −2): the line x = 2, which is H⁻ᵀ l = (1/2, 0, −1) up to scale
    assert transform_lines(np.diag([2.0, 1.0, 1.0]), [[1.0, 0.0, -1.0]]).tolist() == [[1.0, 0.0, -2.0]]
