"""Rectifying a planar image: from four points, from the vanishing line, from orthogonal lines.

A photograph of a plane is related to a fronto-parallel view of that plane by a
homography. This module computes rectifying homographies ``H`` (image → rectified
plane) at three levels of knowledge about the world (Hartley & Zisserman, §2.7):

- :func:`rectangle_homography`: four image points whose world positions are
  the corners of a rectangle of known size — the full projective map (8 DoF).
- :func:`affine_rectification`: two pairs of image lines that are parallel in the
  world. Their intersections are two vanishing points; the line ``l`` through them
  is the image of the line at infinity, and ``H_P = [[1,0,0],[0,1,0],[l1,l2,l3]]``
  sends it back to ``(0, 0, 1)``. Parallel lines become parallel; angles and
  length ratios in different directions remain distorted (an affinity).
- :func:`metric_rectification`: additionally two pairs of lines orthogonal in
  the world. In the affinely rectified image, the dual conic ``C*∞`` appears as
  ``[[S, 0], [0ᵀ, 0]]`` with ``S = K Kᵀ`` symmetric positive definite; each
  orthogonal pair ``(l, m)`` gives one linear equation ``(l1 m1, l1 m2 + l2 m1, l2 m2) · (s11, s12, s22) = 0``;
  the upgrade is ``[[K, 0], [0ᵀ, 1]]⁻¹``. The result is the world up to a similarity.
- :func:`metric_rectification_from_orthogonal_pairs`: five (or more) pairs of lines orthogonal in the
  world, in the original image, and nothing else (H&Z §2.7.5). Each pair gives one linear equation
  ``lᵀ C*∞′ m = 0`` in the six coefficients of the image ``C*∞′ = H C*∞ Hᵀ`` of the dual conic; five
  pairs fix it up to scale, and its eigendecomposition ``U diag(λ1, λ2, 0) Uᵀ`` gives the world-to-image
  map ``U diag(√λ1, √λ2, 1)`` up to a similarity, whose inverse rectifies in one step.

Lines are homogeneous 3-vectors ``(a, b, c)`` for ``a x + b y + c = 0`` in pixel
coordinates; :func:`line_through` builds them from two points. Joins, meets and the
image of lines under a homography (:func:`transform_lines`, which is
:func:`pgsym.numeric.transform_lines`: ``l' ∝ H⁻ᵀ l`` by the adjugate) are the kernels of
:mod:`pgsym.numeric`.

>>> import numpy as np
>>> H = rectangle_homography([[10, 10], [50, 12], [48, 40], [12, 38]], (101, 51))
>>> (np.round(apply_homography(H, [[50, 12]]), 9) + 0.0).tolist()
[[100.0, 0.0]]
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from ..errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    DegenerateConfigurationError,
    DimensionError,
    InconsistentDataError,
)
from ..numeric.conditioning import require_finite
from ..numeric.plane import join, meet
from ..numeric.transform import transform_lines
from .homography import apply_homography, dlt_homography

__all__ = [
    "affine_rectification",
    "apply_homography",
    "dual_conic_from_orthogonal_pairs",
    "fit_to_size",
    "line_through",
    "metric_rectification",
    "metric_rectification_from_orthogonal_pairs",
    "metric_upgrade",
    "rectangle_homography",
    "transform_lines",
    "vanishing_line",
]


def line_through(p: Sequence[float], q: Sequence[float]) -> np.ndarray:
    """The line through two image points, ``(p, 1) × (q, 1)``, scaled to ``a² + b² = 1``.

    >>> line_through((0, 1), (2, 1)).tolist()   # y = 1
    [0.0, 1.0, -1.0]
    """
    a = require_finite(np.array([p[0], p[1], 1.0], dtype=np.float64), "p", "line_through")
    b = require_finite(np.array([q[0], q[1], 1.0], dtype=np.float64), "q", "line_through")
    l = join(a, b)
    # a − b is exactly zero only for equal points, so a zero normal (a, b) means p = q
    n = float(np.hypot(l[0], l[1]))
    if n == 0:
        raise CoincidentPointsError(f"the points {tuple(p)} and {tuple(q)} coincide; they do not fix a line")
    return l / n


def _line(value: Any) -> np.ndarray:
    l = np.asarray(value, dtype=np.float64)
    if l.shape != (3,):
        raise DimensionError(f"a line is a homogeneous 3-vector (a, b, c), got {value!r}")
    require_finite(l, "a line", "rectify")
    l = l / np.ldexp(1.0, np.frexp(np.abs(l).max())[1])  # exact power-of-two scale: no product overflows
    if not l[:2].any():
        raise DegenerateConfigurationError("the line (0, 0, c) is the line at infinity (or zero), not an image line")
    return l


def _meet(l: np.ndarray, m: np.ndarray) -> np.ndarray:
    v = meet(l, m)
    if np.linalg.norm(v) <= 1e-12 * np.linalg.norm(l) * np.linalg.norm(m):
        raise CoincidentLinesError(f"the lines {l.tolist()} and {m.tolist()} coincide; they have no single meet")
    return v


def vanishing_line(pair1: Sequence[Any], pair2: Sequence[Any]) -> np.ndarray:
    """The image of the line at infinity from two pairs of lines parallel in the world.

    ``v1 = l1 × l1'``, ``v2 = l2 × l2'`` are the vanishing points of the two
    directions and ``l∞' = v1 × v2``; the result is scaled to unit norm.

    >>> vanishing_line([[1, 0, 0], [1, 0, -1]], [[0, 1, 0], [0, 1, -1]]).tolist()   # parallel in the image too
    [0.0, 0.0, 1.0]
    """
    l1, m1 = (_line(v) for v in pair1)
    l2, m2 = (_line(v) for v in pair2)
    v1 = _meet(l1, m1)
    v2 = _meet(l2, m2)
    v1 = v1 / np.linalg.norm(v1)
    v2 = v2 / np.linalg.norm(v2)
    l = join(v1, v2)
    n = np.linalg.norm(l)
    if n <= 1e-12:
        raise DegenerateConfigurationError(
            "the two pairs of lines have the same vanishing point; they must have two different directions in the world"
        )
    l = l / n
    return l * np.sign(l[np.argmax(np.abs(l))]) + 0.0


def affine_rectification(line_at_infinity: Any, reference: Sequence[float] = (0.0, 0.0)) -> np.ndarray:
    """The projective part ``H_P = [[1,0,0],[0,1,0],[l1,l2,l3]]`` that sends the vanishing line ``l`` to infinity.

    ``l`` is scaled so that ``lᵀ(reference, 1) = 1``: the reference point (e.g. the
    image centre) keeps its position and the scale near it is preserved.
    Raises :class:`~pgsym.errors.DegenerateConfigurationError` if the reference
    point lies on the vanishing line, or if ``l`` is the line at infinity already
    (then the identity is the answer).

    >>> H = affine_rectification([0.0, -0.01, 1.0])   # the horizon y = 100
    >>> H.tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -0.01, 1.0]]
    """
    l = np.asarray(line_at_infinity, dtype=np.float64)
    if l.shape != (3,) or not l.any():
        raise DimensionError(f"the vanishing line is a nonzero homogeneous 3-vector, got {line_at_infinity!r}")
    require_finite(l, "the vanishing line", "affine_rectification")
    reference = tuple(require_finite(np.asarray(reference, dtype=np.float64), "reference", "affine_rectification"))
    l = l / np.ldexp(1.0, np.frexp(np.abs(l).max())[1])
    value = l[0] * reference[0] + l[1] * reference[1] + l[2]
    if abs(value) <= 1e-12 * np.linalg.norm(l) * max(1.0, float(np.hypot(*reference))):
        raise DegenerateConfigurationError(
            f"the reference point {tuple(reference)} lies on the vanishing line {l.tolist()}: the image of the "
            "line at infinity must not pass through the part of the image you want to rectify"
        )
    l = l / value
    H = np.eye(3)
    H[2] = l
    return H


def metric_upgrade(orthogonal_pairs: Sequence[Any]) -> np.ndarray:
    """The affine map ``[[K, 0], [0, 1]]⁻¹`` that makes an affinely rectified image metric.

    ``orthogonal_pairs`` holds at least two pairs ``(l, m)`` of lines that are
    orthogonal in the world, in the affinely rectified image, with different
    directions. Each pair gives ``(l1 m1, l1 m2 + l2 m1, l2 m2) · (s11, s12, s22) = 0``;
    the null vector gives ``S = [[s11, s12], [s12, s22]] = K Kᵀ`` (Cholesky factor ``K``).

    >>> # a world square seen through the affinity x' = 2x: its sides and diagonals
    >>> pairs = [([1, 0, 0], [0, 1, 0]), ([1, -2, 0], [1, 2, -2])]
    >>> A = metric_upgrade(pairs)
    >>> (np.round(A[:2, :2] / A[1, 1], 9) + 0.0).tolist()
    [[0.5, 0.0], [0.0, 1.0]]
    """
    rows = []
    for pair in orthogonal_pairs:
        if len(pair) != 2:
            raise DimensionError("each orthogonal pair must hold exactly two lines")
        l, m = (_line(v) for v in pair)
        l, m = l / np.hypot(l[0], l[1]), m / np.hypot(m[0], m[1])
        rows.append([l[0] * m[0], l[0] * m[1] + l[1] * m[0], l[1] * m[1]])
    if len(rows) < 2:
        raise DimensionError(f"metric rectification needs at least two orthogonal line pairs, got {len(rows)}")
    _, sv, Vt = np.linalg.svd(np.array(rows), full_matrices=True)
    if len(sv) >= 2 and sv[1] <= 1e-9 * sv[0]:
        raise DegenerateConfigurationError(
            "the orthogonal line pairs give only one independent constraint: use pairs with different "
            "directions (e.g. the sides and the diagonals of a square)"
        )
    s = Vt[-1]
    S = np.array([[s[0], s[1]], [s[1], s[2]]])
    if S[0, 0] < 0:
        S = -S
    if np.linalg.det(S) <= 1e-12 * np.trace(S) ** 2:
        raise InconsistentDataError(
            "the orthogonal line pairs are inconsistent: the image of the dual conic C*∞ they give is not "
            "positive definite (check that each pair really is orthogonal in the world, after affine rectification)"
        )
    S = S / np.sqrt(np.linalg.det(S))
    K = np.linalg.cholesky(S)
    A = np.eye(3)
    A[:2, :2] = np.linalg.inv(K)
    return A


def metric_rectification(
    parallel_pairs: Sequence[Any],
    orthogonal_pairs: Sequence[Any],
    reference: Sequence[float] = (0.0, 0.0),
) -> np.ndarray:
    """A rectifying homography up to a similarity: affine step from parallels, then metric step from right angles.

    ``parallel_pairs`` are two pairs of image lines parallel in the world,
    ``orthogonal_pairs`` two (or more) pairs of image lines orthogonal in the
    world (all in the original image). Returns ``H = H_A⁻¹ H_P``.

    >>> Hw = np.array([[1.0, 0.3, 0], [0.1, 1.2, 0], [0.001, 0.002, 1]])  # world → image
    >>> img = lambda *pts: apply_homography(Hw, pts)
    >>> a, b, c, d = img([0, 0], [100, 0], [100, 100], [0, 100])   # a world square
    >>> sides = [(line_through(a, b), line_through(d, c)), (line_through(a, d), line_through(b, c))]
    >>> right = [(line_through(a, b), line_through(a, d)), (line_through(a, c), line_through(b, d))]
    >>> H = metric_rectification(sides, right, reference=a)
    >>> r = apply_homography(H, [a, b, c, d])
    >>> e1, e2 = r[1] - r[0], r[3] - r[0]
    >>> round(float(e1 @ e2), 9), round(float(np.linalg.norm(e1) / np.linalg.norm(e2)), 9)
    (0.0, 1.0)
    """
    if len(parallel_pairs) != 2:
        raise DimensionError(
            f"affine rectification needs exactly two pairs of parallel lines, got {len(parallel_pairs)}"
        )
    HP = affine_rectification(vanishing_line(*parallel_pairs), reference)
    mapped = []
    for pair in orthogonal_pairs:
        if len(pair) != 2:
            raise DimensionError("each orthogonal pair must hold exactly two lines")
        mapped.append(tuple(transform_lines(HP, [_line(v)])[0] for v in pair))
    return metric_upgrade(mapped) @ HP


def _orthogonality_row(l: np.ndarray, m: np.ndarray) -> list[float]:
    """The coefficients of ``lᵀ C m`` in ``(c11, c12, c22, c13, c23, c33)`` of a symmetric ``C``."""
    return [l[0] * m[0], l[0] * m[1] + l[1] * m[0], l[1] * m[1], l[0] * m[2] + l[2] * m[0],
            l[1] * m[2] + l[2] * m[1], l[2] * m[2]]


def dual_conic_from_orthogonal_pairs(orthogonal_pairs: Sequence[Any]) -> np.ndarray:
    """The image ``C*∞′`` of the dual conic at infinity from five or more pairs of lines orthogonal in the world.

    Each pair ``(l, m)`` gives ``lᵀ C*∞′ m = 0``, linear in the six coefficients of the symmetric ``C*∞′``;
    the least-squares null vector of the stacked equations (the right singular vector of the smallest
    singular value) is ``C*∞′`` up to scale. Returned with unit Frobenius norm and its two largest
    eigenvalues positive. Fewer than five independent equations raise
    :class:`~pgsym.errors.DegenerateConfigurationError`.

    >>> # perpendicular pairs of an undistorted image: C*∞′ is diag(1, 1, 0) itself, up to scale
    >>> pairs = [([1, 0, 0], [0, 1, 0]), ([1, 0, -2], [0, 1, -1]), ([1, 1, 0], [1, -1, 0]),
    ...          ([1, 1, -3], [1, -1, 1]), ([1, 2, 0], [2, -1, 1])]
    >>> C = dual_conic_from_orthogonal_pairs(pairs)
    >>> (np.round(C * np.sqrt(2), 12) + 0.0).tolist()
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]]
    """
    rows = []
    for pair in orthogonal_pairs:
        if len(pair) != 2:
            raise DimensionError("each orthogonal pair must hold exactly two lines")
        l, m = (_line(v) for v in pair)
        l, m = l / np.linalg.norm(l), m / np.linalg.norm(m)
        rows.append(_orthogonality_row(l, m))
    if len(rows) < 5:
        raise DimensionError(
            f"metric rectification from orthogonal pairs alone needs at least five pairs, got {len(rows)}"
        )
    _, sv, Vt = np.linalg.svd(np.array(rows), full_matrices=True)
    if sv[4] <= 1e-9 * sv[0]:
        raise DegenerateConfigurationError(
            "the orthogonal line pairs give fewer than five independent constraints on C*∞′: use pairs in "
            "several directions and at several places (e.g. sides and diagonals of squares in different places)"
        )
    c = Vt[-1]
    C = np.array([[c[0], c[1], c[3]], [c[1], c[2], c[4]], [c[3], c[4], c[5]]])
    eig = np.linalg.eigvalsh(C)
    if eig[-1] + eig[0] < 0:  # the two eigenvalues of largest size must be positive
        C = -C
    return C / np.linalg.norm(C)


def metric_rectification_from_orthogonal_pairs(
    orthogonal_pairs: Sequence[Any], reference: Sequence[float] = (0.0, 0.0), scale: float = 1.0
) -> np.ndarray:
    """A rectifying homography up to a similarity, in one step, from five or more orthogonal line pairs.

    The lines are taken in the coordinates ``(x − reference) / scale`` (pass the image centre and
    about half the image size: the six coefficients of ``C*∞′`` are then of comparable size, which
    conditions the null space), and the result is composed back, so it maps pixels. ``C*∞′`` from
    :func:`dual_conic_from_orthogonal_pairs` has the eigendecomposition ``U diag(λ1, λ2, λ3) Uᵀ``
    with ``λ1 ≥ λ2 > 0`` and ``λ3 ≈ 0`` (it is ``0`` for exact data: ``C*∞′`` has rank 2); then
    ``C*∞′ ≈ G C*∞ Gᵀ`` with ``G = U diag(√λ1, √λ2, 1)``, and ``H = G⁻¹ = diag(1/√λ1, 1/√λ2, 1) Uᵀ``.
    ``H`` is oriented so that the reference point stays on the positive side (``w > 0``) and the
    image is not mirrored there. Pairs whose ``C*∞′`` is not positive semi-definite (``λ2 ≤ 0``:
    the lines are not orthogonal in any world) raise :class:`~pgsym.errors.InconsistentDataError`.

    >>> Hw = np.array([[1.0, 0.3, 0], [0.1, 1.2, 0], [0.001, 0.002, 1]])   # world → image
    >>> img = lambda *pts: apply_homography(Hw, pts)
    >>> pairs = []
    >>> for x, y, plus in [(0, 0, 1), (100, 20, 1), (20, 100, 0), (60, 40, 0), (90, 90, 0)]:   # "+" or "x" shapes
    ...     a, b, c, d = img([x, y], [x + 1, y], [x, y + 1], [x + 1, y + 1])
    ...     pairs.append((line_through(a, b), line_through(a, c)) if plus else (line_through(a, d), line_through(b, c)))
    >>> H = metric_rectification_from_orthogonal_pairs(pairs, reference=(150, 100), scale=150)
    >>> r = apply_homography(H, img([0, 0], [100, 0], [100, 100], [0, 100]))
    >>> e1, e2 = r[1] - r[0], r[3] - r[0]
    >>> round(float(e1 @ e2 / (e1 @ e1)), 9) + 0.0, round(float(np.linalg.norm(e1) / np.linalg.norm(e2)), 9)
    (0.0, 1.0)
    """
    ref = require_finite(np.asarray(reference, dtype=np.float64), "reference", "metric_rectification")
    s = float(require_finite(np.asarray(scale, dtype=np.float64), "scale", "metric_rectification"))
    if ref.shape != (2,) or not s > 0:
        raise DimensionError(f"reference is a point (x, y) and scale a positive number, got {reference!r}, {scale!r}")
    T = np.array([[1 / s, 0, -ref[0] / s], [0, 1 / s, -ref[1] / s], [0, 0, 1]])  # pixels → conditioned coordinates
    T_lines = np.array([[s, 0, 0], [0, s, 0], [ref[0], ref[1], 1]])  # lines: l′ = T⁻ᵀ l
    conditioned = []
    for pair in orthogonal_pairs:
        if len(pair) != 2:
            raise DimensionError("each orthogonal pair must hold exactly two lines")
        conditioned.append(tuple(T_lines @ _line(v) for v in pair))
    C = dual_conic_from_orthogonal_pairs(conditioned)
    lam, U = np.linalg.eigh(C)  # ascending: λ3 ≈ 0 first, then λ2, λ1
    if lam[1] <= 1e-9 * lam[2]:
        raise InconsistentDataError(
            "the orthogonal line pairs are inconsistent: the image of the dual conic C*∞ they give is not "
            f"positive semi-definite of rank 2 (eigenvalues {np.round(lam / lam[2], 6).tolist()}); check that each "
            "pair really is orthogonal in the world"
        )
    H = np.diag([1 / np.sqrt(lam[2]), 1 / np.sqrt(lam[1]), 1.0]) @ U[:, [2, 1, 0]].T @ T
    centre = np.array([ref[0], ref[1], 1.0])
    w = H[2] @ centre
    if w < 0:
        H = -H
        w = -w
    if np.linalg.det(H) / w**3 < 0:  # the Jacobian at the reference point: undo a mirror image
        H = np.diag([1.0, -1.0, 1.0]) @ H
    return H


def rectangle_homography(image_points: Any, size: tuple[int, int]) -> np.ndarray:
    """The homography sending four image points to the corners of a ``width × height`` output image.

    The points are taken in the order top-left, top-right, bottom-right,
    bottom-left of the world rectangle; they go to the outermost pixel centres
    ``(0, 0)``, ``(W−1, 0)``, ``(W−1, H−1)``, ``(0, H−1)``. Three collinear points
    raise :class:`~pgsym.errors.CollinearPointsError`.

    >>> H = rectangle_homography([[0, 0], [9, 0], [9, 9], [0, 9]], (19, 10))
    >>> (np.round(H / H[2, 2], 9) + 0.0).tolist()
    [[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    """
    w, h = _size(size)
    if w < 2 or h < 2:
        raise DimensionError(f"the output rectangle needs at least 2×2 pixels, got {w}×{h}")
    p = np.asarray(image_points, dtype=np.float64)
    if p.shape != (4, 2):
        raise DimensionError(f"rectification needs exactly four image points (x, y), got shape {p.shape}")
    corners = np.array([[0, 0], [w - 1, 0], [w - 1, h - 1], [0, h - 1]], dtype=np.float64)
    return dlt_homography(p, corners)


def _size(size: Any) -> tuple[int, int]:
    """An output size ``(width, height)`` as two integers; NonFiniteError for NaN or infinity."""
    values = np.asarray(size, dtype=np.float64)
    if values.shape != (2,):
        raise DimensionError(f"the output size is a pair (width, height), got {size!r}")
    require_finite(values, "size", "rectify")
    return int(values[0]), int(values[1])


def fit_to_size(H: Any, points: Any, size: tuple[int, int], margin: int = 0) -> np.ndarray:
    """Compose ``H`` with a uniform scaling and translation so the mapped ``points`` fill ``size``, centred.

    Used to frame an affinely or metrically rectified image: ``points`` (e.g. the
    image corners or a region of interest) must map to finite points on one side
    of the vanishing line, else :class:`~pgsym.errors.DegenerateConfigurationError`.

    >>> H = fit_to_size(np.eye(3), [[0, 0], [10, 0], [10, 5], [0, 5]], (21, 21))
    >>> apply_homography(H, [[0, 0], [10, 5]]).tolist()
    [[0.0, 5.0], [20.0, 15.0]]
    """
    M = require_finite(np.asarray(H, dtype=np.float64), "H", "fit_to_size")
    p = require_finite(np.asarray(points, dtype=np.float64).reshape(-1, 2), "points", "fit_to_size")
    w_out, h_out = _size(size)
    with np.errstate(over="ignore", invalid="ignore"):
        hom = require_finite(p @ M[:, :2].T + M[:, 2], "the mapped points (they overflow)", "fit_to_size")
    if not (np.all(hom[:, 2] > 0) or np.all(hom[:, 2] < 0)) or np.min(np.abs(hom[:, 2])) < 1e-12:
        raise DegenerateConfigurationError(
            "the vanishing line crosses the region to be shown: part of it would be mapped through infinity; "
            "check the lines, or frame a smaller region"
        )
    q = hom[:, :2] / hom[:, 2:3]
    lo, hi = q.min(axis=0), q.max(axis=0)
    extent = np.maximum(hi - lo, 1e-300)
    s = min((w_out - 1 - 2 * margin) / extent[0], (h_out - 1 - 2 * margin) / extent[1])
    centre_out = np.array([(w_out - 1) / 2, (h_out - 1) / 2])
    t = centre_out - s * (lo + hi) / 2
    S = np.array([[s, 0, t[0]], [0, s, t[1]], [0, 0, 1.0]])
    return S @ M
