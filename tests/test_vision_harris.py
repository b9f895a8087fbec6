"""The Harris detector: known corners of synthetic images, hand-derived filter values, errors."""

from __future__ import annotations

import cv2
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pgsym.vision.errors import ImageError
from pgsym.vision.harris import _suppress, harris, harris_response
from pgsym.vision.images import check_image, display_uint8, read_image, to_float_image, write_image


def square_image(h=64, w=80, top=16, left=20, bottom=48, right=60) -> np.ndarray:
    img = np.zeros((h, w), np.float32)
    img[top:bottom, left:right] = 1.0
    return img


def true_corners(top, left, bottom, right) -> np.ndarray:
    # the white pixels are rows top..bottom-1 and columns left..right-1, so the geometric corners of the
    # square lie on the pixel boundaries, half a pixel outside the outermost white pixel centres
    return np.array([[left - 0.5, top - 0.5], [right - 0.5, top - 0.5], [right - 0.5, bottom - 0.5],
                     [left - 0.5, bottom - 0.5]])


def nearest_distances(found: np.ndarray, truth: np.ndarray) -> np.ndarray:
    return np.array([np.min(np.linalg.norm(found - t, axis=1)) for t in truth])


def test_white_square_gives_its_four_corners_within_one_pixel():
    img = square_image()
    r = harris(img, k=0.05, sigma=1.5, threshold=0.1, min_distance=5)
    assert len(r.corners) == 4
    assert nearest_distances(r.corners, true_corners(16, 20, 48, 60)).max() <= 1.0


@settings(max_examples=25, deadline=None)
@given(
    top=st.integers(6, 20), left=st.integers(6, 20), height=st.integers(12, 30), width=st.integers(12, 30),
    sigma=st.sampled_from([0.8, 1.0, 1.5]), k=st.sampled_from([0.04, 0.05, 0.06]),
)
def test_squares_anywhere_give_their_corners_within_two_pixels(top, left, height, width, sigma, k):
    img = square_image(60, 60, top, left, top + height, left + width)
    r = harris(img, k=k, sigma=sigma, threshold=0.1, min_distance=4)
    assert len(r.corners) == 4
    assert nearest_distances(r.corners, true_corners(top, left, top + height, left + width)).max() <= 2.0


def test_sobel_gradient_of_a_vertical_step_is_four():
    # I = 0 for x < 10 and 1 for x >= 10. The Sobel kernel [[-1,0,1],[-2,0,2],[-1,0,1]] on the columns
    # x = 9 (neighbours 0 | 1) and x = 10 (neighbours 0 | 1) gives (1 + 2 + 1) * (1 - 0) = 4, and 0 elsewhere;
    # the step is constant along y, so Iy = 0 and hence Ixy = Syy = Sxy = 0 and det M = 0 exactly.
    img = np.zeros((20, 20), np.float32)
    img[:, 10:] = 1.0
    r = harris(img, k=0.05, sigma=1.0, threshold=0.01, min_distance=2)
    assert np.all(r.Ix[:, 9:11] == 4.0)
    assert np.all(r.Ix[:, :9] == 0.0) and np.all(r.Ix[:, 11:] == 0.0)
    assert np.all(r.Iy == 0.0) and np.all(r.Ixx[:, 9:11] == 16.0)
    assert np.all(r.det == 0.0)
    # an edge: R = -k (trace M)^2 <= 0 everywhere, hence no corners at all
    assert np.allclose(r.response, -0.05 * r.Sxx**2)
    assert r.response.max() <= 0 and len(r.corners) == 0


def test_intermediates_fit_together():
    img = to_float_image(np.random.default_rng(1).integers(0, 256, (40, 50), dtype=np.uint8))
    r = harris(img, k=0.04, sigma=1.3)
    assert np.array_equal(r.Ixx, r.Ix * r.Ix) and np.array_equal(r.Ixy, r.Ix * r.Iy)
    ksize = 2 * int(np.ceil(4 * 1.3)) + 1
    assert np.allclose(r.Sxx, cv2.GaussianBlur(r.Ixx, (ksize, ksize), 1.3, borderType=cv2.BORDER_REFLECT_101))
    assert np.allclose(r.det, r.Sxx * r.Syy - r.Sxy**2, rtol=1e-5, atol=1e-6)
    assert np.allclose(r.response, r.det - 0.04 * r.trace**2, rtol=1e-5, atol=1e-5)
    assert np.allclose(harris_response(img, k=0.04, sigma=1.3), r.response, rtol=1e-5, atol=1e-5)
    assert set(r.intermediates) >= {"Ix", "Iy", "Ixx", "Iyy", "Ixy", "Sxx", "Syy", "Sxy", "det", "trace", "response"}
    # the threshold is relative to the maximum response
    assert r.threshold_value == pytest.approx(0.01 * r.max_response)
    assert np.all(r.strengths > r.threshold_value)
    assert np.all(np.diff(r.strengths) <= 0)


def test_agrees_with_scikit_image_away_from_the_border():
    from skimage.data import camera
    from skimage.feature import corner_harris

    img = to_float_image(camera()[100:260, 150:330])
    ours = harris(img, k=0.05, sigma=1.0).response
    theirs = corner_harris(img, k=0.05, sigma=1.0)  # pads with zeros, so compare the interior
    b = 6
    corr = np.corrcoef(ours[b:-b, b:-b].ravel(), theirs[b:-b, b:-b].ravel())[0, 1]
    assert corr > 0.999999


def test_rotating_the_image_by_90_degrees_rotates_the_corners():
    img = square_image(50, 60, 10, 12, 35, 40)
    a = harris(img, sigma=1.2, threshold=0.1)
    b = harris(np.ascontiguousarray(np.rot90(img)), sigma=1.2, threshold=0.1)
    # np.rot90 sends pixel (x, y) of a W-wide image to (y, W - 1 - x)
    w = img.shape[1]
    rotated = {(int(y), int(w - 1 - x)) for x, y in a.corners}
    assert rotated == {(int(x), int(y)) for x, y in b.corners}


def test_threshold_and_min_distance():
    from skimage.data import checkerboard

    img = to_float_image(checkerboard())
    low = harris(img, threshold=0.01, min_distance=3)
    high = harris(img, threshold=0.5, min_distance=3)
    assert {tuple(c) for c in high.corners} <= {tuple(c) for c in low.corners}
    for d in (3, 8, 15):
        c = harris(img, threshold=0.01, min_distance=d).corners
        cheb = np.abs(c[:, None, :] - c[None, :, :]).max(axis=2) + np.eye(len(c)) * 1e9
        assert cheb.min() > d


def test_plateau_keeps_one_maximum_in_raster_order():
    response = np.zeros((10, 10), np.float32)
    response[3:6, 4:7] = 1.0  # nine equal maxima within distance 2 of each other
    response[8, 8] = 0.5
    maxima, ys, xs = _suppress(response, response > 0.1, 2)
    assert [tuple(p) for p in np.argwhere(maxima).tolist()] == [(3, 4), (8, 8)]
    assert ys.tolist() == [3, 8] and xs.tolist() == [4, 8]


def test_constant_image_has_no_corners():
    r = harris(np.full((16, 16), 0.5, np.float32))
    assert r.corners.shape == (0, 2) and r.max_response == 0.0 and not r.candidates.any()


@pytest.mark.parametrize(
    ("image", "message"),
    [
        (np.zeros((5, 5)), "dtype float32"),
        (np.zeros((5, 5, 3), np.float32), "shape (H, W)"),
        (np.zeros((0, 5), np.float32), "empty"),
        (np.array([[np.nan]], np.float32), "NaN"),
        ([[0.0, 1.0]], "NumPy array"),
    ],
)
def test_bad_images_raise_image_error(image, message):
    with pytest.raises(ImageError, match=message.replace("(", r"\(").replace(")", r"\)")):
        harris(image)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [({"k": 0.3}, "k must"), ({"sigma": 0}, "sigma"), ({"threshold": 1.5}, "threshold"), ({"min_distance": 0}, "min")],
)
def test_bad_parameters_raise_image_error(kwargs, message):
    with pytest.raises(ImageError, match=message):
        harris(np.zeros((8, 8), np.float32), **kwargs)


def test_image_helpers(tmp_path):
    assert check_image(np.zeros((1, 1), np.float32)).shape == (1, 1)
    rgb = np.zeros((2, 2, 3), np.uint8)
    rgb[..., 0] = 255  # pure red: grey 0.299
    assert to_float_image(rgb)[0, 0] == pytest.approx(0.299, abs=1e-6)
    assert to_float_image(np.array([[True, False]])).tolist() == [[1.0, 0.0]]
    assert to_float_image(np.array([[0, 65535]], np.uint16)).tolist() == [[0.0, 1.0]]
    with pytest.raises(ImageError):
        to_float_image(np.zeros((2, 2, 2, 2)))
    with pytest.raises(ImageError):
        to_float_image(np.array([], np.uint8))
    img = np.linspace(0, 1, 12, dtype=np.float32).reshape(3, 4)
    write_image(tmp_path / "a.png", img)
    assert np.abs(read_image(tmp_path / "a.png") - img).max() <= 0.5 / 255 + 1e-6
    (tmp_path / "junk.png").write_bytes(b"not an image")
    with pytest.raises(ImageError, match="cannot read"):
        read_image(tmp_path / "junk.png")
    assert display_uint8(np.zeros((2, 2))).tolist() == [[0, 0], [0, 0]]
    assert display_uint8(np.zeros((1, 1)), signed=True).tolist() == [[128]]
