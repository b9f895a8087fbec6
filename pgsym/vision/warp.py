"""Warping an image by a homography, with bilinear interpolation.

``warp(image, H, (W, H_out))`` produces the output image ``J`` with
``J(x') = I(H⁻¹ x')``: ``H`` maps *input* pixel coordinates to *output* pixel
coordinates (pixel centres at integer coordinates), and every output pixel is
looked up in the input by the inverse map and interpolated bilinearly from the
four neighbouring input pixels. Outside the input the value is 0.

:func:`warp` uses OpenCV's ``warpPerspective``; :func:`warp_numpy` is the same
computation in plain NumPy (a slower reference, used as a baseline).

>>> import numpy as np
>>> img = np.arange(16, dtype=np.float32).reshape(4, 4)
>>> shift = np.array([[1.0, 0, 1], [0, 1, 0], [0, 0, 1]])  # one pixel to the right
>>> warp(img, shift, (4, 4))[1].tolist()
[0.0, 4.0, 5.0, 6.0]
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import DimensionError, NonFiniteError, SingularTransformationError
from ..numeric.conditioning import require_finite, singular
from .errors import ImageError
from .images import check_image

__all__ = ["check_homography", "warp", "warp_numpy"]


def check_homography(H: Any) -> np.ndarray:
    """Return ``H`` as a finite, invertible float64 ``3 × 3`` array, or raise a named error.

    >>> check_homography(np.eye(3)).shape
    (3, 3)
    >>> check_homography(np.zeros((3, 3)))
    Traceback (most recent call last):
    ...
    pgsym.errors.SingularTransformationError: the homography is singular (det H = 0 up to rounding): ...
    """
    M = np.asarray(H, dtype=np.float64)
    if M.shape != (3, 3):
        raise DimensionError(f"a homography of the plane is a 3×3 matrix, got shape {M.shape}")
    require_finite(M, "H", "check_homography")
    if not M.any() or singular(M):
        raise SingularTransformationError(
            "the homography is singular (det H = 0 up to rounding): it collapses the plane onto a line or a "
            "point and cannot be inverted to warp an image"
        )
    return M


def _check_size(size: Any) -> tuple[int, int]:
    try:
        values = [float(v) for v in size]
    except (TypeError, ValueError):
        raise ImageError(f"the output size must be a pair (width, height) of integers, got {size!r}") from None
    if len(values) != 2:
        raise ImageError(f"the output size must be a pair (width, height) of integers, got {size!r}")
    if not all(np.isfinite(values)):
        raise NonFiniteError(f"the output size must be finite, got {size!r}")
    w, h = int(values[0]), int(values[1])
    if w < 1 or h < 1 or w > 32767 or h > 32767:
        raise ImageError(f"the output size must be between 1 and 32767 pixels per side, got {w}×{h}")
    return w, h


def warp(image: np.ndarray, H: Any, size: tuple[int, int]) -> np.ndarray:
    """Warp a float32 ``(H, W)`` image by the homography ``H`` into an output of ``size = (width, height)``.

    >>> import numpy as np
    >>> img = np.ones((10, 10), np.float32)
    >>> out = warp(img, np.diag([0.5, 0.5, 1.0]), (5, 5))
    >>> out.shape, float(out[2, 2])
    ((5, 5), 1.0)
    """
    import cv2  # noqa: PLC0415 — OpenCV loads on first use: vision modules load without it

    check_image(image)
    M = check_homography(H)
    w, h = _check_size(size)
    return cv2.warpPerspective(image, M, (w, h), flags=cv2.INTER_LINEAR,
                               borderMode=cv2.BORDER_CONSTANT, borderValue=0.0)


def warp_numpy(image: np.ndarray, H: Any, size: tuple[int, int]) -> np.ndarray:
    """The same bilinear warp as :func:`warp`, in plain NumPy (reference implementation).

    Each output pixel ``(x', y')`` is mapped back by ``H⁻¹``; the four surrounding
    input pixels are weighted by the fractional parts; neighbours outside the image count as 0.

    >>> import numpy as np
    >>> img = np.arange(16, dtype=np.float32).reshape(4, 4)
    >>> half = np.array([[1.0, 0, 0.5], [0, 1, 0], [0, 0, 1]])  # half a pixel to the right
    >>> warp_numpy(img, half, (4, 4))[1].tolist()
    [2.0, 4.5, 5.5, 6.5]
    """
    check_image(image)
    M = check_homography(H)
    w, h = _check_size(size)
    Minv = np.linalg.inv(M)
    ys, xs = np.mgrid[0:h, 0:w]
    X = Minv[0, 0] * xs + Minv[0, 1] * ys + Minv[0, 2]
    Y = Minv[1, 0] * xs + Minv[1, 1] * ys + Minv[1, 2]
    Z = Minv[2, 0] * xs + Minv[2, 1] * ys + Minv[2, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        u = X / Z
        v = Y / Z
    valid = np.isfinite(u) & np.isfinite(v) & (Z != 0)
    u = np.where(valid, u, -2.0)
    v = np.where(valid, v, -2.0)
    x0 = np.floor(u).astype(np.int64)
    y0 = np.floor(v).astype(np.int64)
    fx = (u - x0).astype(np.float32)
    fy = (v - y0).astype(np.float32)
    ih, iw = image.shape
    padded = np.zeros((ih + 2, iw + 2), np.float32)
    padded[1:-1, 1:-1] = image
    xi = np.clip(x0 + 1, 0, iw)  # indices into the padded image; clipping lands on the zero border
    yi = np.clip(y0 + 1, 0, ih)
    outside = (x0 < -1) | (x0 > iw - 1) | (y0 < -1) | (y0 > ih - 1)
    a = padded[yi, xi]
    b = padded[yi, xi + 1]
    c = padded[yi + 1, xi]
    d = padded[yi + 1, xi + 1]
    out = (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy
    out[outside] = 0.0
    return out.astype(np.float32)
