"""The Harris corner detector, with every intermediate result kept.

For a grey image ``I`` the detector computes

1. the gradients ``Ix``, ``Iy`` (3×3 Sobel filters, OpenCV),
2. their products ``Ix²``, ``Iy²``, ``Ix Iy``,
3. the structure tensor ``M = G_σ * [[Ix², Ix Iy], [Ix Iy, Iy²]]`` (each entry
   smoothed by a Gaussian of standard deviation ``σ`` truncated at ``4σ``: OpenCV's
   Gaussian kernel, applied as a separable filter),
4. the response ``R = det M − k (trace M)²``,
5. the threshold: a pixel is a candidate when ``R > threshold · max R`` (the
   threshold is *relative* to the strongest response, so it does not depend on
   the contrast of the image; if ``max R ≤ 0`` there are no corners),
6. non-maximum suppression: a candidate survives when it is the maximum of ``R``
   in the ``(2d+1)×(2d+1)`` window around it (``d = min_distance``); of several
   equal maxima closer than ``d`` (Chebyshev distance) the first in raster order is kept,
7. the corner list, strongest first.

This is scikit-image's definition (``corner_harris(method="k")``) with OpenCV's
primitives; the Sobel filters are not normalised, so ``R`` scales with the
fourth power of the image contrast.

>>> import numpy as np
>>> img = np.zeros((40, 40), np.float32); img[10:30, 10:30] = 1
>>> result = harris(img, sigma=1.5, min_distance=5)
>>> sorted(map(tuple, np.round(result.corners).astype(int).tolist()))
[(10, 10), (10, 29), (29, 10), (29, 29)]
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..errors import NonFiniteError
from .errors import ImageError
from .images import check_image

__all__ = ["HarrisResult", "harris", "harris_response"]


@dataclass(frozen=True)
class HarrisResult:
    """Everything the Harris detector computed, for display and analysis.

    All arrays have the shape ``(H, W)`` of the input and dtype ``float32``,
    except ``candidates``/``maxima`` (bool), ``corners`` (``(n, 2)`` float64, columns
    ``x, y``) and ``strengths`` (``(n,)``, the response at each corner, descending).

    >>> import numpy as np
    >>> r = harris(np.zeros((8, 8), np.float32))
    >>> r.corners.shape, r.max_response, r.threshold_value
    ((0, 2), 0.0, 0.0)
    """

    image: np.ndarray
    Ix: np.ndarray
    Iy: np.ndarray
    Ixx: np.ndarray
    Iyy: np.ndarray
    Ixy: np.ndarray
    Sxx: np.ndarray
    Syy: np.ndarray
    Sxy: np.ndarray
    det: np.ndarray
    trace: np.ndarray
    response: np.ndarray
    candidates: np.ndarray
    maxima: np.ndarray
    corners: np.ndarray
    strengths: np.ndarray
    k: float
    sigma: float
    threshold: float
    min_distance: int
    max_response: float
    threshold_value: float
    parameters: dict = field(default_factory=dict)

    @property
    def intermediates(self) -> dict[str, np.ndarray]:
        """The named intermediate images, in the order they are computed.

        >>> import numpy as np
        >>> list(harris(np.zeros((8, 8), np.float32)).intermediates)[:3]
        ['image', 'Ix', 'Iy']
        """
        names = ["image", "Ix", "Iy", "Ixx", "Iyy", "Ixy", "Sxx", "Syy", "Sxy", "det", "trace", "response"]
        out = {n: getattr(self, n) for n in names}
        out["candidates"] = self.candidates
        out["maxima"] = self.maxima
        return out


def _check_parameters(k: float, sigma: float, threshold: float, min_distance: int) -> None:
    for name, value in (("k", k), ("sigma", sigma), ("threshold", threshold), ("min_distance", min_distance)):
        if isinstance(value, (float, np.floating)) and not np.isfinite(value):
            raise NonFiniteError(f"harris: {name} must be a finite number, got {value}")
    if not (np.isfinite(k) and 0 <= k < 0.25):
        raise ImageError(f"k must lie in [0, 0.25), got {k}; typical values are 0.04 to 0.06")
    if not (np.isfinite(sigma) and sigma > 0):
        raise ImageError(f"sigma must be a positive number of pixels, got {sigma}")
    if not (np.isfinite(threshold) and 0 <= threshold < 1):
        raise ImageError(f"threshold is relative to the maximum response and must lie in [0, 1), got {threshold}")
    if int(min_distance) != min_distance or min_distance < 1:
        raise ImageError(f"min_distance must be a positive whole number of pixels, got {min_distance}")


def _structure_tensor(image: np.ndarray, sigma: float):  # type: ignore[no-untyped-def]
    import cv2  # noqa: PLC0415 — OpenCV loads on first use: vision modules load without it

    border = cv2.BORDER_REFLECT_101
    Ix = cv2.Sobel(image, cv2.CV_32F, 1, 0, ksize=3, borderType=border)
    Iy = cv2.Sobel(image, cv2.CV_32F, 0, 1, ksize=3, borderType=border)
    Ixx = cv2.multiply(Ix, Ix)
    Iyy = cv2.multiply(Iy, Iy)
    Ixy = cv2.multiply(Ix, Iy)
    ksize = 2 * int(np.ceil(4.0 * sigma)) + 1  # truncate the Gaussian at 4 sigma (as SciPy does)
    g = cv2.getGaussianKernel(ksize, sigma, cv2.CV_32F)  # the kernel of cv2.GaussianBlur, applied separably
    Sxx = cv2.sepFilter2D(Ixx, -1, g, g, borderType=border)
    Syy = cv2.sepFilter2D(Iyy, -1, g, g, borderType=border)
    Sxy = cv2.sepFilter2D(Ixy, -1, g, g, borderType=border)
    return Ix, Iy, Ixx, Iyy, Ixy, Sxx, Syy, Sxy


def harris_response(image: np.ndarray, k: float = 0.05, sigma: float = 1.0) -> np.ndarray:
    """Only the Harris response ``R = det M − k (trace M)²`` (float32, shape of the image).

    >>> import numpy as np
    >>> img = np.zeros((20, 20), np.float32); img[5:15, 5:15] = 1
    >>> R = harris_response(img)
    >>> tuple(int(v) for v in np.unravel_index(np.argmax(R), R.shape)) in {(5, 5), (5, 14), (14, 5), (14, 14)}
    True
    """
    check_image(image)
    _check_parameters(k, sigma, 0.0, 1)
    *_, Sxx, Syy, Sxy = _structure_tensor(image, sigma)
    trace = Sxx + Syy
    return Sxx * Syy - Sxy * Sxy - np.float32(k) * trace * trace


def _sparse_nonzero(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.nonzero`` for a sparse boolean image, in raster order, scanning only the rows that hold a pixel."""
    rows = np.flatnonzero(mask.view(np.uint8).max(axis=1))
    r, c = np.nonzero(mask[rows])
    return rows[r], c


def _suppress(response: np.ndarray, candidates: np.ndarray, d: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Local maxima of ``response`` among ``candidates`` (mask, rows, columns); plateau ties kept in raster order."""
    import cv2  # noqa: PLC0415 — OpenCV loads on first use: vision modules load without it

    kernel = np.ones((2 * d + 1, 2 * d + 1), np.uint8)
    dilated = cv2.dilate(response, kernel, borderType=cv2.BORDER_CONSTANT, borderValue=-np.inf)
    maxima = candidates & (response >= dilated)
    # Peaks with different values are more than d apart by construction; only plateaus (equal
    # values within a window) can leave several maxima close together. Keep the first in raster order.
    ys, xs = _sparse_nonzero(maxima)
    if len(ys) > 1:
        from scipy.spatial import cKDTree  # noqa: PLC0415 — SciPy loads on first use: vision modules load without it

        pairs = cKDTree(np.stack([ys, xs], axis=1)).query_pairs(r=d, p=np.inf, output_type="ndarray")
        if len(pairs):
            close: dict[int, list[int]] = {}
            for a, b in pairs.tolist():
                close.setdefault(max(a, b), []).append(min(a, b))
            dropped: set[int] = set()
            for i in sorted(close):  # indices follow raster order
                if any(j not in dropped for j in close[i]):
                    dropped.add(i)
            drop = np.fromiter(sorted(dropped), dtype=np.int64)
            maxima[ys[drop], xs[drop]] = False
            keep = np.ones(len(ys), bool)
            keep[drop] = False
            ys, xs = ys[keep], xs[keep]
    return maxima, ys, xs


def harris(
    image: np.ndarray,
    k: float = 0.05,
    sigma: float = 1.0,
    threshold: float = 0.01,
    min_distance: int = 5,
) -> HarrisResult:
    """Run the Harris detector and return every intermediate result.

    Parameters: ``image`` a float32 ``(H, W)`` array (see
    :func:`~pgsym.vision.images.to_float_image`); ``k`` the sensitivity in
    ``R = det M − k (trace M)²`` (``0 ≤ k < 0.25``); ``sigma`` the standard
    deviation of the Gaussian window in pixels; ``threshold`` the fraction of the
    maximum response a corner must exceed; ``min_distance`` the half-width of the
    non-maximum-suppression window in pixels.

    Returns a :class:`HarrisResult`; ``result.corners`` holds the corners as
    ``(x, y)`` pixel coordinates (column, row), strongest first.

    >>> import numpy as np
    >>> img = np.zeros((30, 30), np.float32); img[8:22, 8:22] = 1
    >>> r = harris(img, k=0.04, sigma=1.0, threshold=0.1, min_distance=3)
    >>> len(r.corners), r.Ix.shape, r.response.dtype.name
    (4, (30, 30), 'float32')
    >>> harris(img.astype(float))
    Traceback (most recent call last):
    ...
    pgsym.vision.errors.ImageError: image must have dtype float32, got float64; convert it with to_float_image()
    """
    check_image(image)
    _check_parameters(k, sigma, threshold, min_distance)
    d = int(min_distance)
    Ix, Iy, Ixx, Iyy, Ixy, Sxx, Syy, Sxy = _structure_tensor(image, sigma)
    det = Sxx * Syy
    det -= Sxy * Sxy
    trace = Sxx + Syy
    response = trace * trace
    response *= np.float32(-k)
    response += det
    max_response = float(response.max())
    threshold_value = threshold * max_response if max_response > 0 else 0.0
    if max_response > 0:
        candidates = response > np.float32(threshold_value)
    else:
        candidates = np.zeros(response.shape, bool)
    if candidates.any():
        maxima, ys, xs = _suppress(response, candidates, d)
    else:
        maxima, ys, xs = candidates.copy(), np.zeros(0, np.int64), np.zeros(0, np.int64)
    strengths = response[ys, xs].astype(np.float64)
    order = np.lexsort((xs, ys, -strengths))  # strongest first, ties in raster order
    corners = np.stack([xs[order], ys[order]], axis=1).astype(np.float64).reshape(-1, 2)
    return HarrisResult(
        image=image, Ix=Ix, Iy=Iy, Ixx=Ixx, Iyy=Iyy, Ixy=Ixy, Sxx=Sxx, Syy=Syy, Sxy=Sxy,
        det=det, trace=trace, response=response, candidates=candidates, maxima=maxima,
        corners=corners, strengths=strengths[order], k=float(k), sigma=float(sigma),
        threshold=float(threshold), min_distance=d, max_response=max_response,
        threshold_value=float(threshold_value),
        parameters={"k": float(k), "sigma": float(sigma), "threshold": float(threshold), "min_distance": d},
    )
