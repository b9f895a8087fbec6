"""Hostile input for the numeric path: extreme but finite scales, NaN and ±inf, ideal points.

Three promises are checked here. Float classification and every singularity or rank test
give the same answer in any units (the data of a photograph in pixels, kilometres or
1e-200). NaN and infinity never pass silently: every public kernel of ``pgsym.numeric``
and of the numeric vision modules raises :class:`NonFiniteError` for them (or masks them
where it offers ``nonfinite="mask"``); the kernels are enumerated from ``__all__``, so a new
kernel without a case here fails :func:`test_every_public_kernel_has_a_case`. And the DLT
works for data from 1e-200 to 1e200.
"""

from __future__ import annotations

import inspect
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import pgsym.numeric as pn
from pgsym.errors import IdealPointError, InputLimitError, NonFiniteError, SingularTransformationError
from pgsym.hierarchy import classify, rotation_2d
from pgsym.linalg import nullspace_svd, numeric_rank, plane_through_numeric, point_on_planes_numeric
from pgsym.vision import harris, homography, rectify, warp
from pgsym.vision.errors import ImageError
from pgsym.vision.homography import (
    apply_homography,
    dlt_homography,
    homographies_from_four,
    normalize_homography,
    reprojection_error,
)

BAD = [math.nan, math.inf, -math.inf]

# A rotation with cos θ = 3/5, sin θ = 4/5 (the 3-4-5 triangle), so R is exact in binary up to rounding.
R = np.array([[0.6, -0.8, 0.0], [0.8, 0.6, 0.0], [0.0, 0.0, 1.0]])


def translation(tx: float, ty: float) -> np.ndarray:
    return np.array([[1.0, 0, tx], [0, 1, ty], [0, 0, 1]])


# -- classification in any units ------------------------------------------------------------------------

CLASSIFIED = [
    # A = I and t = (1920, 1080): a translation by one HD frame is a proper isometry.
    ("translation by 1920x1080", translation(1920, 1080), "euclidean2"),
    ("translation by 1e6", translation(1e6, -1e6), "euclidean2"),
    ("3D translation by 1e6", np.block([[np.eye(3), np.full((3, 1), 1e6)], [np.zeros((1, 3)), 1.0]]), "euclidean3"),
    # A = 1e-5 I: AᵀA = 1e-10 I is a multiple of I, and the multiple is not 1, so a similarity (scale 1e-5).
    ("diag(1e-5, 1e-5, 1)", np.diag([1e-5, 1e-5, 1.0]), "similarity2"),
    ("diag(1e5, 1e5, 1)", np.diag([1e5, 1e5, 1.0]), "similarity2"),
    # λH is H projectively: a rotation times 1e±100 is still a rotation.
    ("rotation times 1e100", 1e100 * R, "euclidean2"),
    ("rotation times 1e-100", 1e-100 * R, "euclidean2"),
    # [[k R, 0], [0, 1]] with k = 1e±100 is a similarity of ratio k.
    ("similarity of ratio 1e100", np.diag([1e100, 1e100, 1.0]) @ R, "similarity2"),
    ("similarity of ratio 1e-100", np.diag([1e-100, 1e-100, 1.0]) @ R, "similarity2"),
    # diag(1, -1, 1): det A = -1, AᵀA = I: an isometry with a reflection, at any overall scale.
    ("reflection times 1e-150", 1e-150 * np.diag([1.0, -1, 1]), "isometry2"),
    # A shear [[1, 1], [0, 1]]: AᵀA = [[1, 1], [1, 2]] is no multiple of I; moved by 1e6 pixels.
    ("shear with a 1e6 translation", np.array([[1.0, 1, 1e6], [0, 1, 0], [0, 0, 1]]), "affine2"),
    # last row (1e-6, 0, 1) with t = 0: in units 1e6 times larger it is (1, 0, 1), plainly projective.
    ("perspectivity 1e-6", np.array([[1.0, 0, 0], [0, 1, 0], [1e-6, 0, 1]]), "projective2"),
    ("perspectivity in km", np.array([[1.0, 0, 2e-3], [0, 1, 0], [3e3, 0, 1]]), "projective2"),
]


@pytest.mark.parametrize(("label", "H", "key"), CLASSIFIED, ids=[c[0] for c in CLASSIFIED])
def test_classification_does_not_depend_on_units(label, H, key):
    assert classify(H).key == key


SINGULAR = [
    # row 2 = 2 · row 1 exactly (doubling is exact in binary), so rank 2 at every power-of-ten scale
    *[(f"rank 2 times 1e{e}", np.array([[1.0, 2, 3], [2, 4, 6], [0, 0, 1]]) * 10.0**e) for e in (-200, -100, 0, 200)],
    ("projection onto a line", np.diag([1e150, 0.0, 1e150]), None),
    ("zero matrix", np.zeros((3, 3)), None),
    ("rank 3 in 3D", np.diag([1e-100, 1e-100, 1e-100, 0.0]), None),
]


@pytest.mark.parametrize("case", SINGULAR, ids=[c[0] for c in SINGULAR])
def test_truly_singular_matrices_raise_at_any_scale(case):
    H = case[1]
    with pytest.raises(SingularTransformationError):
        classify(H)
    with pytest.raises(SingularTransformationError):
        pn.transform_lines(H, [1.0, 0, 0]) if H.shape == (3, 3) else pn.transform_planes(H, [1.0, 0, 0, 0])
    if H.shape == (3, 3):
        with pytest.raises(SingularTransformationError):
            warp.check_homography(H)


@pytest.mark.parametrize("bad", BAD)
@pytest.mark.parametrize("where", [(0, 0), (2, 2), (1, 2)])
def test_non_finite_matrices_raise_non_finite_error(bad, where):
    H = np.eye(3)
    H[where] = bad
    for f in (classify, warp.check_homography, lambda m: pn.transform_points(m, [1.0, 0, 1])):
        with pytest.raises(NonFiniteError):
            f(H)
    with pytest.raises(NonFiniteError):
        classify(np.pad(H, ((0, 1), (0, 1))) + np.diag([0, 0, 0, 1.0]))


def _rotation(theta: float) -> np.ndarray:
    return np.array([[math.cos(theta), -math.sin(theta)], [math.sin(theta), math.cos(theta)]])


@st.composite
def member(draw):
    """A float matrix of a class known by construction, and that class's key."""
    key = draw(st.sampled_from(["euclidean2", "isometry2", "similarity2", "affine2", "projective2"]))
    coord = st.floats(-10, 10, allow_nan=False)
    # Translations are 0 or at least 0.01: the map's only length is |t| / |A|, and a projective row v
    # with |v| |t| ≈ 1e-300 is affine to within any tolerance (a class that no construction can promise).
    length = st.one_of(st.just(0.0), st.floats(0.01, 10), st.floats(-10, -0.01))
    t = np.array([draw(length), draw(length)])
    A = _rotation(draw(st.floats(-3.1, 3.1)))
    v = np.zeros(2)
    if key == "isometry2":
        A = A @ np.diag([1.0, -1.0])  # a reflection: det A = -1, AᵀA = I
    elif key == "similarity2":
        A = draw(st.one_of(st.floats(0.2, 0.9), st.floats(1.1, 5.0))) * A  # a ratio clearly not 1
    elif key in ("affine2", "projective2"):
        A = np.array([[draw(coord), draw(coord)], [draw(coord), draw(coord)]])
        G = A.T @ A
        g = np.trace(G) / 2
        assume(abs(np.linalg.det(A)) > 0.1 and np.abs(G - g * np.eye(2)).max() > 1e-3 * g)
        if key == "projective2":
            v = np.array([draw(coord), draw(coord)])
            assume(np.abs(v).max() > 0.1)
    H = np.block([[A, t[:, None]], [v[None, :], np.ones((1, 1))]])
    assume(np.linalg.svd(H, compute_uv=False)[-1] > 1e-3 * np.abs(H).max())
    return H, key


@settings(max_examples=200, deadline=None)
@given(member(), st.floats(-6, 6), st.floats(-6, 6))
def test_classification_is_invariant_under_a_change_of_units(case, log_s, log_scale):
    H, key = case
    # New units x' = s x: the matrix becomes D H D⁻¹ with D = diag(s, s, 1); any overall factor is free too.
    s = 10.0**log_s
    D, D_inv = np.diag([s, s, 1.0]), np.diag([1 / s, 1 / s, 1.0])
    assert classify(H).key == key
    assert classify(10.0**log_scale * (D @ H @ D_inv)).key == key


# -- numeric kernels under the policy -------------------------------------------------------------------

P3 = np.array([[1.0, 2, 1], [3, -1, 2]])
L3 = np.array([[1.0, -1, 0], [0, 1, -2]])
P4 = np.array([[1.0, 2, 3, 1], [0, 1, -1, 2]])
H3 = np.array([[2.0, 1, 0], [0, 1, 3], [1, 1, 4]])
# two lines through the origin O and two others through O as well: each pair meets in O
LINES3 = pn.plucker_join([0.0, 0, 0, 1], np.array([[1.0, 2, 3, 1], [0, 1, -1, 2]]))
MEETING3 = pn.plucker_join([0.0, 0, 0, 1], np.array([[1.0, 0, 0, 1], [0, 0, 1, 1]]))
H4 = np.array([[2.0, 1, 0, 0], [0, 1, 3, 0], [1, 1, 4, 0], [0, 0, 1, 1]])

# name → (function, the valid arguments, keyword arguments): each array argument is spoiled in turn.
NUMERIC = {
    "adjugate": (pn.adjugate, [H3], {}),
    "classify_matrix": (pn.classify_matrix, [H3], {}),
    "bracket": (pn.bracket, [np.array([[1.0, 2], [3, 1]]), np.array([[2.0, 1], [1, 1]])], {}),
    "cross": (pn.cross, [P3, L3], {}),
    "cross_ratio": (pn.cross_ratio, [np.array([float(x), 1]) for x in (0, 1, 2, 3)], {}),
    "cross_ratio_homogeneous": (
        pn.cross_ratio_homogeneous,
        [np.array([[0.0, 1]] * 2), np.array([1.0, 1]), np.array([2.0, 1]), np.array([3.0, 1])],
        {},
    ),
    "dehomogenize": (pn.dehomogenize, [P3], {}),
    "from_array": (pn.from_array, [np.array([1.0, 2, 1])], {"kind": "point"}),
    "homogenize": (pn.homogenize, [np.array([[1.0, 2], [3, 4]])], {}),
    "incident": (pn.incident, [P3, L3], {}),
    "is_ideal": (pn.is_ideal, [P3], {}),
    "is_zero_vector": (pn.is_zero_vector, [P3], {}),
    "join": (pn.join, [P3, P3[::-1].copy()], {}),
    "klein_form": (pn.klein_form, [np.array([[0.0, 0, -1, 0, 0, 0], [1, 2, 3, 0, 0, 0]])], {}),
    "meet": (pn.meet, [L3, L3[::-1].copy()], {}),
    "nullspace_svd": (pn.nullspace_svd, [P4], {}),
    "numeric_rank": (pn.numeric_rank, [P4], {}),
    "plane_through_numeric": (pn.plane_through_numeric, [np.vstack([P4, [0.0, 0, 1, 1]])], {}),
    "point_on_planes_numeric": (pn.point_on_planes_numeric, [np.vstack([P4, [0.0, 0, 1, 1]])], {}),
    "svd_steps": (pn.svd_steps, [H3[:2, :2]], {}),
    "plane_through": (pn.plane_through, [P4, P4[::-1].copy(), np.array([0.0, 0, 1, 1])], {}),
    "plucker_join": (pn.plucker_join, [P4, P4[::-1].copy()], {}),
    "plucker_meet": (pn.plucker_meet, [P4, P4[::-1].copy()], {}),
    "point_on_planes": (pn.point_on_planes, [P4, P4[::-1].copy(), np.array([0.0, 0, 1, 1])], {}),
    "transform_conics": (pn.transform_conics, [H3, np.diag([1.0, 1, -1])], {}),
    "transform_dual_conics": (pn.transform_dual_conics, [H3, np.diag([1.0, 1, -1])], {}),
    "transform_lines": (pn.transform_lines, [H3, L3], {}),
    "transform_planes": (pn.transform_planes, [H4, P4], {}),
    "transform_points": (pn.transform_points, [H3, P3], {}),
    "transform_quadrics": (pn.transform_quadrics, [H4, np.diag([1.0, 1, 1, -1])], {}),
    "triple_cross": (pn.triple_cross, [P4, P4[::-1].copy(), np.array([0.0, 0, 1, 1])], {}),
    "cos_angle": (pn.cos_angle, [L3, L3[::-1].copy()], {}),
    "is_perpendicular": (pn.is_perpendicular, [L3, L3[::-1].copy()], {}),
    "orthogonal_projection": (pn.orthogonal_projection, [P3, L3], {}),
    "point_distance": (pn.point_distance, [P3, P3[::-1].copy()], {}),
    "point_line_distance": (pn.point_line_distance, [P3, L3], {}),
    "point_plane_distance": (pn.point_plane_distance, [P4, P4[::-1].copy()], {}),
    "reflect": (pn.reflect, [P3, L3], {}),
    "perpendicular_line": (pn.perpendicular_line, [L3, P3], {}),
    "angle_bisectors": (pn.angle_bisectors, [L3, L3[::-1].copy()], {}),
    "parallel_line": (pn.parallel_line, [L3, P3], {}),
    "signed_angle": (pn.signed_angle, [np.array([0.0, 0, 1]), P3, P3[::-1].copy()], {}),
    "sin_angle": (pn.sin_angle, [L3, L3[::-1].copy()], {}),
    "cos_squared_angle": (pn.cos_squared_angle, [P4, P4[::-1].copy()], {}),
    "is_parallel": (pn.is_parallel, [P4, P4[::-1].copy()], {}),
    "midpoint": (pn.midpoint, [P3, P3[::-1].copy()], {}),
    # two pairs of circles (a batch of 3×3 matrices): x² + y² = 25 and = 4 against two circles about (4, 0)
    "intersect_conics": (
        pn.intersect_conics,
        [np.stack([np.diag([1.0, 1, -25]), np.diag([1.0, 1, -4])]),
         np.stack([[[1.0, 0, -4], [0, 1, 0], [-4, 0, 7]], [[1.0, 0, -4], [0, 1, 0], [-4, 0, 12]]])],
        {},
    ),
    "form_value": (pn.form_value, [np.diag([1.0, 1, -1]), P3], {}),
    "polar": (pn.polar, [np.diag([1.0, 1, -1]), P3], {}),
    "tangent_at": (pn.tangent_at, [np.diag([1.0, 1, -25]), np.array([[3.0, 4, 1], [5, 0, 1]])], {}),
    "tangent_plane": (pn.tangent_plane, [np.diag([1.0, 1, 1, -1]), np.array([[1.0, 0, 0, 1], [0, 0.6, 0.8, 1]])], {}),
    "harmonic_conjugate": (
        pn.harmonic_conjugate, [np.array([[0.0, 1], [-1, 1]]), np.array([4.0, 1]), np.array([1.0, 1])], {}
    ),
    "intersect_plane": (pn.intersect_plane, [LINES3, np.array([[1.0, 0, 0, -3], [0, 0, 1, -5]])], {}),
    "plane_through_point": (pn.plane_through_point, [LINES3, np.array([[0.0, 0, 1, 1], [1, 0, 0, 1]])], {}),
    "meet_lines": (pn.meet_lines, [LINES3, MEETING3], {}),
    "plane_through_lines": (pn.plane_through_lines, [LINES3, MEETING3], {}),
}
FORMS = {"form_value", "polar", "tangent_at", "tangent_plane"}  # one form (a matrix) serves the batch
# a constant, an error class, a result class; to_array takes exact objects
NOT_KERNELS = {"CHUNK", "OptionError", "SVDSteps", "to_array"}

SQUARE = np.array([[0.0, 0], [1, 0], [1, 1], [0, 1]])
QUAD = np.array([[3.0, -1], [4, -0.9], [4.2, 1.1], [3.2, 1]])  # the image of SQUARE under HB below
HB = np.array([[1.0, 0.2, 3], [0.1, 2, -1], [0.0, 0.0, 1]])
IMAGE = np.zeros((16, 16), np.float32)
IMAGE[4:12, 4:12] = 1
LINES = np.array([[[1.0, 0, 0], [1, 0, -1]], [[0.0, 1, 0], [0, 1, -1]]])  # two pairs of parallel lines
RIGHT = np.array([[[1.0, 0, 0], [0, 1, 0]], [[1, -2, 0], [1, 2, -2]]])  # sides and diagonals of x' = 2x
# five right angles of an undistorted image: "+" at (0, 0) and (2, 1), "x" at (0, 0), (3, 0) and (1, 2)
FIVE_RIGHT = np.array([[[1.0, 0, 0], [0, 1, 0]], [[1, 0, -2], [0, 1, -1]], [[1, 1, 0], [1, -1, 0]],
                       [[1, 1, -3], [1, -1, -3]], [[1, 1, -3], [1, -1, 1]]])

VISION = {
    "apply_homography": (homography.apply_homography, [HB, SQUARE], {}),
    "check_homography": (warp.check_homography, [HB], {}),
    "dlt_homography": (homography.dlt_homography, [SQUARE, QUAD], {}),
    "exact_homography": (homography.exact_homography, [SQUARE, QUAD], {}),
    "homographies_from_four": (homography.homographies_from_four, [SQUARE[None], QUAD[None]], {}),
    "normalize_homography": (homography.normalize_homography, [HB], {}),
    "normalizing_transform": (homography.normalizing_transform, [SQUARE], {}),
    "reprojection_error": (homography.reprojection_error, [HB, SQUARE, QUAD], {}),
    "affine_rectification": (rectify.affine_rectification, [np.array([0.0, -0.01, 1]), np.array([0.0, 0])], {}),
    "fit_to_size": (rectify.fit_to_size, [np.eye(3), SQUARE * 10, np.array([21.0, 21])], {}),
    "line_through": (rectify.line_through, [np.array([0.0, 1]), np.array([2.0, 1])], {}),
    "metric_rectification": (rectify.metric_rectification, [LINES, RIGHT, np.array([0.0, 0])], {}),
    "metric_upgrade": (rectify.metric_upgrade, [RIGHT], {}),
    "dual_conic_from_orthogonal_pairs": (rectify.dual_conic_from_orthogonal_pairs, [FIVE_RIGHT], {}),
    "metric_rectification_from_orthogonal_pairs": (
        rectify.metric_rectification_from_orthogonal_pairs, [FIVE_RIGHT, np.array([1.0, 1]), 2.0], {}
    ),
    "rectangle_homography": (rectify.rectangle_homography, [QUAD * 10, np.array([11.0, 6])], {}),
    "transform_lines": (rectify.transform_lines, [HB, L3], {}),
    "vanishing_line": (rectify.vanishing_line, [LINES[0], LINES[1]], {}),
    "harris": (harris.harris, [IMAGE, 0.05, 1.0, 0.01, 5.0], {}),
    "harris_response": (harris.harris_response, [IMAGE, 0.05, 1.0], {}),
    "warp": (warp.warp, [IMAGE, HB, np.array([8.0, 8])], {}),
    "warp_numpy": (warp.warp_numpy, [IMAGE, HB, np.array([8.0, 8])], {}),
}
VISION_MODULES = (homography, rectify, harris, warp)
NOT_VISION_KERNELS = {"HarrisResult"}  # a result class


def test_every_public_kernel_has_a_case():
    numeric = set(pn.__all__) - NOT_KERNELS
    vision = {n for m in VISION_MODULES for n in m.__all__} - NOT_VISION_KERNELS
    assert numeric == set(NUMERIC), "a kernel of pgsym.numeric has no non-finite case here (or a case is stale)"
    assert vision == set(VISION), "a kernel of pgsym.vision has no non-finite case here (or a case is stale)"


def _spoiled(args, i, bad):
    out = list(args)
    a = np.array(args[i], dtype=np.float64 if not isinstance(args[i], np.ndarray) else args[i].dtype, copy=True)
    a.reshape(-1)[0] = bad
    out[i] = a if a.ndim else a.item()
    return out


CASES = [(name, f, args, kw, i) for table in (NUMERIC, VISION) for name, (f, args, kw) in table.items()
         for i in range(len(args))]


@pytest.mark.parametrize("bad", BAD, ids=["nan", "inf", "-inf"])
@pytest.mark.parametrize(("name", "f", "args", "kw", "i"), CASES, ids=[f"{c[0]}-arg{c[4]}" for c in CASES])
def test_every_kernel_raises_non_finite_error(name, f, args, kw, i, bad):
    f(*args, **kw)  # the valid call works
    # an image is checked by images.check_image, which names NaN/inf pixels with ImageError (the policy, item 5)
    expected = ImageError if isinstance(args[i], np.ndarray) and args[i].dtype == np.float32 else NonFiniteError
    with pytest.raises(expected, match=r"NaN|nan|inf|finite"):
        f(*_spoiled(args, i, bad), **kw)


MASKED = [(name, f, args, kw, i) for name, f, args, kw, i in CASES
          if "nonfinite" in inspect.signature(f).parameters and not (name.startswith("transform") and i == 0)]


def _row(name, j, a):
    """One object of argument ``j`` (the matrix of a transform stays whole: one H for all points)."""
    a = np.asarray(a, dtype=np.float64)
    return a if ((name.startswith("transform") or name in FORMS) and j == 0) or a.ndim == 1 else a[0]


@pytest.mark.parametrize("bad", BAD, ids=["nan", "inf", "-inf"])
@pytest.mark.parametrize(("name", "f", "args", "kw", "i"), MASKED, ids=[f"{c[0]}-arg{c[4]}" for c in MASKED])
def test_mask_mode_masks_exactly_the_spoiled_rows(name, f, args, kw, i, bad):
    # argument i becomes two rows, the first spoiled; every other argument is one object, broadcast
    rows = [_row(name, j, a) for j, a in enumerate(args)]
    batch = np.stack([rows[i], rows[i]])
    batch[0, 0] = bad
    values, finite = f(*rows[:i], batch, *rows[i + 1 :], nonfinite="mask", **kw)
    expected = f(*rows, **kw)
    if isinstance(values, tuple):  # a pair of results (angle_bisectors, signed_angle): one array of both
        values, expected = np.stack(values, axis=-1), np.stack(expected, axis=-1)
    assert finite.tolist() == [False, True]
    if values.dtype.kind == "b":  # a predicate (is_perpendicular) says False on a masked row
        assert not values[0].any()
    else:
        assert np.isnan(values[0]).all()
    assert np.array_equal(values[1], expected)


def test_dehomogenize_tells_nan_from_ideal_and_masks_both():
    with pytest.raises(NonFiniteError):
        pn.dehomogenize([math.nan, 1, 1])  # today's bug: this was called "an ideal point (w = 0)"
    coords, finite = pn.dehomogenize([[math.nan, 1, 1], [1, 1, 0], [4, 2, 2]], ideal="mask", nonfinite="mask")
    # (4, 2, 2) → (4/2, 2/2) = (2, 1); the NaN row and the ideal row are masked
    assert finite.tolist() == [False, False, True] and coords[2].tolist() == [2.0, 1.0] and np.isnan(coords[:2]).all()
    with pytest.raises(IdealPointError):
        pn.dehomogenize([[1.0, 1, 0], [4, 2, 2]], nonfinite="mask")


def test_overflow_of_finite_input_is_named():
    # (1e200, 1, 1) × (1, 1e200, 3): the third component 1e200 · 1e200 − 1 · 1 overflows float64 (max ≈ 1.8e308)
    with pytest.raises(NonFiniteError, match="overflow"):
        pn.join([1e200, 1, 1], [1.0, 1e200, 3])
    with pytest.raises(NonFiniteError):
        pn.to_array(__import__("pgsym.projective_plane", fromlist=["Point"]).Point(10**400, 1, 1))


def test_distances_to_ideal_points_raise():
    # H sends (x, y) to (x, y, x): the point (0, 0) goes to (0, 0, 0)... use H0 whose third row is (1, 0, 0):
    # (0, 0, 1) ↦ (0, 0, 0 + 0 + 0)? No: take H = [[1,0,0],[0,1,0],[1,0,0]], (0, 1, 1) ↦ (0, 1, 0), an ideal point.
    H = np.array([[1.0, 0, 0], [0, 1, 0], [1, 0, 0]])
    with pytest.raises(IdealPointError):
        reprojection_error(H, [[0.0, 1.0]], [[0.0, 1.0]])
    with pytest.raises(IdealPointError):
        apply_homography(H, [[0.0, 1.0]])
    # (2, 1, 1) ↦ (2, 1, 2) = (1, 0.5): masked mode keeps it and flags the ideal one
    coords, finite = apply_homography(H, [[0.0, 1.0], [2.0, 1.0]], ideal="mask")
    assert finite.tolist() == [False, True] and coords[1].tolist() == [1.0, 0.5]


@pytest.mark.parametrize("t", [1e200, -1e200, 1e20])
def test_rotation_2d_of_a_huge_parameter_is_finite_and_right(t):
    # θ = 2 arctan t → ±π as t → ±∞. With u = 1/t: cos θ = (u² − 1)/(u² + 1), sin θ = 2u/(u² + 1); for
    # |t| ≥ 1e20, u² ≤ 1e-40 is below rounding next to 1, so cos θ = -1 and sin θ = 2u exactly in float64.
    (c, minus_s), (s, c2) = rotation_2d(t)
    assert c == c2 == -1.0 and s == -minus_s == pytest.approx(2 / t, rel=1e-15)


@pytest.mark.parametrize("t", BAD)
def test_rotation_2d_of_a_non_finite_parameter_raises(t):
    with pytest.raises(NonFiniteError):
        rotation_2d(t)


def test_linalg_rank_and_null_space_in_any_units():
    # Three points at distance 1e6 along the axes: the plane x + y + z = 1e6, i.e. (1, 1, 1, -1e6) up to scale.
    pi = plane_through_numeric([[1e6, 0, 0, 1], [0, 1e6, 0, 1], [0, 0, 1e6, 1]])
    assert np.allclose(pi / pi[0], [1, 1, 1, -1e6], rtol=1e-12)
    # the same at 1e-200: the plane x + y + z = 1e-200
    pi = plane_through_numeric([[1e-200, 0, 0, 1], [0, 1e-200, 0, 1], [0, 0, 1e-200, 1]])
    assert np.allclose(pi[:3], pi[0], rtol=1e-15) and pi[3] / pi[0] == pytest.approx(-1e-200, rel=1e-12)
    # planes x = 1e200, y = 2e200, z = 3e200 meet in (1e200, 2e200, 3e200)
    X = point_on_planes_numeric([[1, 0, 0, -1e200], [0, 1, 0, -2e200], [0, 0, 1, -3e200]])
    assert np.allclose(X[:3] / X[3], [1e200, 2e200, 3e200], rtol=1e-12)
    # rank 2 at any scale: row 2 = 2 · row 1
    for e in (-300, 0, 300):
        M = np.array([[1.0, 2, 3], [2, 4, 6], [0, 0, 1]]) * 10.0**e
        assert numeric_rank(M) == 2 and nullspace_svd(M).shape == (3, 1)
    with pytest.raises(NonFiniteError):
        numeric_rank([[math.inf, 1.0]])


# -- the DLT at extreme scales --------------------------------------------------------------------------

HP = np.array([[1.0, 0.2, 3], [0.1, 2, -1], [0.5, 0.25, 1]])  # a projective map (last row not (0, 0, 1))
SRC5 = np.vstack([SQUARE, [[0.3, 0.6]]])


def _image(H, pts):  # independent of pgsym: x' = (H (x, y, 1)ᵀ) dehomogenised
    q = np.c_[pts, np.ones(len(pts))] @ H.T
    return q[:, :2] / q[:, 2:]


SOLVERS = [
    ("dlt, 4 points", lambda a, b: dlt_homography(a, b), SQUARE),
    ("dlt, 5 points", lambda a, b: dlt_homography(a, b), SRC5),
    ("four-point batch", lambda a, b: homographies_from_four(a[None], b[None])[0], SQUARE),
]


@pytest.mark.parametrize("s", [1e-200, 1e200])
@pytest.mark.parametrize(("label", "solve", "src"), SOLVERS, ids=[c[0] for c in SOLVERS])
def test_dlt_source_at_extreme_scale(label, solve, src, s):
    # dst = HP(src); with src' = s · src the map is H = HP · diag(1/s, 1/s, 1). So H · diag(s, s, 1) ∝ HP:
    # compare there, in units where the answer is of order one.
    H = solve(src * s, _image(HP, src))
    assert np.abs(normalize_homography(H @ np.diag([s, s, 1.0])) - normalize_homography(HP)).max() < 1e-12
    assert np.abs(apply_homography(H, src * s) - _image(HP, src)).max() < 1e-12


@pytest.mark.parametrize("s", [1e-200, 1e200])
@pytest.mark.parametrize(("label", "solve", "src"), SOLVERS, ids=[c[0] for c in SOLVERS])
def test_dlt_both_sets_at_extreme_scale(label, solve, src, s):
    # A map M in units s is H = S M S⁻¹ with S = diag(s, s, 1), so S⁻¹ H S ∝ M. Compare there: in the
    # given units the translation of H is known only to ε · s (1e184 for s = 1e200), like the data.
    # (H @ S first: S⁻¹ H would push the 1e-184 linear part of H below the float64 range.)
    S, S_inv = np.diag([s, s, 1.0]), np.diag([1 / s, 1 / s, 1.0])
    # The unit square scaled by s onto itself is the identity (today's bug: "collinear").
    H = solve(src * s, src * s)
    assert np.abs(normalize_homography(S_inv @ (H @ S)) - normalize_homography(np.eye(3))).max() < 1e-12
    # An affine map HB in units s
    H = solve(src * s, _image(HB, src) * s)
    assert np.abs(normalize_homography(S_inv @ (H @ S)) - normalize_homography(HB)).max() < 1e-12
    assert np.abs(apply_homography(H, src * s) / s - _image(HB, src)).max() < 1e-12
    # A projective map in units s has entries from 1e-200 to 1e200 (v / s against s t): no unit-norm
    # float64 matrix holds it, and the answer says so rather than flushing v to zero.
    with pytest.raises(InputLimitError):
        solve(src * s, _image(HP, src) * s)


@pytest.mark.parametrize(("f", "k", "matrix"), [
    (pn.join, 3, None), (pn.meet, 3, None), (pn.cross, 3, None), (pn.incident, 3, None),
    (pn.plucker_join, 4, None), (pn.cos_angle, 3, None), (pn.point_distance, 3, None),
    (pn.transform_points, 3, np.eye(3)), (pn.transform_lines, 3, np.eye(3)),
], ids=lambda v: getattr(v, "__name__", None) or str(v))
def test_an_empty_batch_gives_an_empty_result(f, k, matrix):
    empty = np.zeros((0, k))
    args = (matrix, empty) if matrix is not None else (empty, empty)
    assert np.asarray(f(*args)).shape[0] == 0
