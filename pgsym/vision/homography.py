"""Estimating plane homographies ``x' ~ H x`` from point correspondences.

Three solvers, one convention: ``H`` maps source points ``(x, y)`` to
destination points ``(x', y')``, ``(x', y', 1)ᵀ ~ H (x, y, 1)ᵀ``; numeric
results are scaled to unit Frobenius norm with the entry of largest absolute
value positive. No entry is ever fixed to 1, so homographies with ``h33 = 0``
(those that send the origin to infinity) are found as well as any other.

- :func:`dlt_homography`: the normalised direct linear transformation for
  ``n ≥ 4`` correspondences (Hartley & Zisserman, Algorithm 4.2).
- :func:`exact_homography`: the exact rational homography from exactly four
  correspondences, computed in the exact core with SymPy.
- :func:`homographies_from_four`: many four-point problems at once, ``(N, 4, 2) → (N, 3, 3)``.

>>> import numpy as np
>>> src = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
>>> dst = np.array([[0, 0], [2, 0], [2, 1], [0, 1]], float)
>>> H = dlt_homography(src, dst)
>>> np.round(apply_homography(H, [[0.5, 0.5]]), 12).tolist()
[[1.0, 0.5]]
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import combinations
from typing import TYPE_CHECKING, Any

import numpy as np

from ..errors import (
    CollinearPointsError,
    DegenerateConfigurationError,
    DimensionError,
    InputLimitError,
    NonFiniteError,
    SingularTransformationError,
)
from ..numeric.conditioning import require_finite
from ..numeric.homogeneous import dehomogenize
from ..numeric.plane import cross
from ..numeric.tolerances import COLLINEAR_RTOL, DLT_EIGEN_GAP_RTOL, DLT_RTOL, DLT_SNAP_RTOL, SINGULAR_RTOL
from ..numeric.transform import adjugate

if TYPE_CHECKING:  # the exact four-point path loads SymPy only when it is used
    import sympy

    from ..projective_plane import Point

__all__ = [
    "apply_homography",
    "dlt_homography",
    "exact_homography",
    "homographies_from_four",
    "normalize_homography",
    "normalizing_transform",
    "reprojection_error",
]

_RTOL = DLT_RTOL


def _pow2(x: Any) -> Any:
    """The power of two nearest above ``|x|`` (1 for 0): dividing by it is exact and brings ``x`` to [0.5, 1)."""
    return np.ldexp(1.0, np.frexp(x)[1])


def _points(points: Any, name: str, min_count: int = 1) -> np.ndarray:
    try:
        p = np.asarray(points, dtype=np.float64)
    except (TypeError, ValueError):
        raise DimensionError(f"{name} must be an array of (x, y) coordinates") from None
    if p.ndim != 2 or p.shape[1] != 2:
        raise DimensionError(f"{name} must have shape (n, 2) with columns x, y; got shape {p.shape}")
    if p.shape[0] < min_count:
        raise DimensionError(f"{name} needs at least {min_count} points, got {p.shape[0]}")
    return require_finite(p, name, "homography")


def normalize_homography(H: Any) -> np.ndarray:
    """Scale ``H`` (or a stack ``(..., 3, 3)``) to unit Frobenius norm, largest-magnitude entry positive.

    Two homographies are equal up to scale exactly when their normalised forms agree.

    >>> normalize_homography(np.diag([-2.0, -2.0, 0.0])).round(6).tolist()
    [[0.707107, 0.0, 0.0], [0.0, 0.707107, 0.0], [0.0, 0.0, 0.0]]
    """
    H = require_finite(_matrices(H, "normalize_homography"), "H", "normalize_homography")
    flat = H.reshape(*H.shape[:-2], 9)
    largest = np.max(np.abs(flat), axis=-1, keepdims=True)
    if not np.all(largest > 0):
        raise SingularTransformationError("normalize_homography: the zero matrix is no homography")
    given = flat
    flat = flat / _pow2(largest)  # exact; the squares in the norm below can then neither overflow nor vanish
    if np.any((given != 0) & (np.abs(flat) < 2**53 * np.finfo(np.float64).tiny)):
        # an entry would end below the normal range once the norm is one: its digits would be lost
        raise InputLimitError(
            "normalize_homography: the entries of H span more than the float64 range holds at unit norm (largest/"
            "smallest beyond about 1e292), so scaling it would flush small entries to zero and change the map; "
            "this happens when both point sets lie at extreme scales (e.g. 1e200): measure them in units nearer one"
        )
    norm = np.linalg.norm(flat, axis=-1, keepdims=True)
    idx = np.argmax(np.abs(flat), axis=-1)[..., None]
    sign = np.sign(np.take_along_axis(flat, idx, axis=-1))
    sign[sign == 0] = 1.0
    return (flat / (norm * sign)).reshape(H.shape) + 0.0  # + 0.0 turns -0.0 into 0.0


def _matrices(H: Any, function: str) -> np.ndarray:
    try:
        M = np.asarray(H, dtype=np.float64)
    except (TypeError, ValueError):
        raise DimensionError(f"{function}: H must be a 3×3 array of numbers") from None
    if M.ndim < 2 or M.shape[-2:] != (3, 3):
        raise DimensionError(f"{function}: H must be a 3×3 matrix (or a stack of them), got shape {M.shape}")
    return M


def apply_homography(H: Any, points: Any, *, ideal: str = "raise") -> Any:
    """Map ``(n, 2)`` points by ``H`` and dehomogenise, as :func:`pgsym.numeric.dehomogenize` does.

    A point that ``H`` sends to infinity (onto the line ``H`` maps to the line at infinity)
    raises :class:`~pgsym.errors.IdealPointError`; with ``ideal="mask"`` the result is
    ``(points, finite)`` with NaN rows where ``finite`` is False. NaN or infinity in ``H`` or
    the points raises :class:`~pgsym.errors.NonFiniteError`.

    >>> apply_homography(np.diag([2.0, 3.0, 1.0]), [[1, 1], [2, 0]]).tolist()
    [[2.0, 3.0], [4.0, 0.0]]
    >>> apply_homography([[1.0, 0, 0], [0, 1, 0], [1, 0, 0]], [[0, 0], [1, 0]], ideal="mask")[1].tolist()
    [False, True]
    """
    H = require_finite(_matrices(H, "apply_homography"), "H", "apply_homography")
    p = _points(points, "points")
    with np.errstate(over="ignore", invalid="ignore"):
        q = p @ H[:, :2].T + H[:, 2]
    return dehomogenize(q, ideal=ideal)


def reprojection_error(H: Any, src: Any, dst: Any) -> np.ndarray:
    """Euclidean distances ``|dst_i − H(src_i)|`` in pixels, one per correspondence.

    A source point that ``H`` sends to infinity has no distance: it raises
    :class:`~pgsym.errors.IdealPointError` (as :func:`apply_homography` does).

    >>> reprojection_error(np.eye(3), [[0, 0], [1, 1]], [[0, 0], [1, 2]]).tolist()
    [0.0, 1.0]
    """
    with np.errstate(over="ignore", invalid="ignore"):
        d = np.hypot(*(apply_homography(H, src) - _points(dst, "dst")).T)
    return require_finite(d, "the distances (they overflow float64)", "reprojection_error")


def _normalize(x: np.ndarray, y: np.ndarray, name: str) -> tuple[np.ndarray, np.ndarray, float, float, float]:
    """Centre and scale coordinates (RMS distance √2); raise when all points lie on one line.

    The coordinates are first divided by a power of two near their largest magnitude (exact), so
    that no sum or square below overflows or underflows for data anywhere in the float64 range.
    """
    n = len(x)
    unit = float(_pow2(max(np.abs(x).max(), np.abs(y).max())))
    x, y = x / unit, y / unit
    cx, cy = x.sum() / n, y.sum() / n
    dx, dy = x - cx, y - cy
    sxx, syy, sxy = float(dx @ dx), float(dy @ dy), float(dx @ dy)
    tr = sxx + syy
    lam_max = tr / 2 + np.sqrt(max((sxx - syy) ** 2 / 4 + sxy * sxy, 0.0))
    if tr == 0 or (sxx * syy - sxy * sxy) / lam_max <= _RTOL**2 * lam_max:
        raise CollinearPointsError(f"the {name} points all lie on one line (or coincide); a homography needs "
                                   "four points, no three of them collinear")
    s = float(np.sqrt(2.0 * n / tr))
    return dx * s, dy * s, s / unit, float(cx) * unit, float(cy) * unit


def normalizing_transform(points: Any) -> np.ndarray:
    """Hartley's normalisation: the similarity moving the centroid to the origin, RMS distance √2.

    Raises :class:`~pgsym.errors.CollinearPointsError` when the points all lie on one line.

    >>> T = normalizing_transform([[0, 0], [2, 0], [2, 2], [0, 2]])
    >>> np.round(T, 6).tolist()
    [[1.0, 0.0, -1.0], [0.0, 1.0, -1.0], [0.0, 0.0, 1.0]]
    """
    p = _points(points, "points")
    _, _, s, cx, cy = _normalize(p[:, 0].copy(), p[:, 1].copy(), "given")
    return np.array([[s, 0.0, -s * cx], [0.0, s, -s * cy], [0.0, 0.0, 1.0]])


def _check_no_three_collinear(pn: np.ndarray, name: str) -> None:
    """For four normalised points: raise when some three are collinear (relative tolerance)."""
    for i, j, k in combinations(range(4), 3):
        a, b, c = pn[i], pn[j], pn[k]
        area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        scale = max(np.linalg.norm(b - a) * np.linalg.norm(c - a), 1e-300)
        if abs(area) <= COLLINEAR_RTOL * scale:
            raise CollinearPointsError(
                f"{name} points {i + 1}, {j + 1} and {k + 1} are collinear; four correspondences determine "
                "a homography only when no three of the points lie on one line"
            )


def dlt_homography(src: Any, dst: Any) -> np.ndarray:
    """The homography mapping ``src`` to ``dst`` by the normalised DLT (least squares for ``n > 4``).

    Both point sets are first normalised (:func:`normalizing_transform`); the
    ``2n × 9`` system ``A h = 0`` (two rows per correspondence from
    ``x' × H x = 0``) is solved through the eigenvector of the smallest eigenvalue
    of the ``9 × 9`` matrix ``AᵀA`` (assembled from moments, without forming ``A``);
    when the eigenvalue gap says that this could lose accuracy (nearly degenerate
    configurations), the null vector is taken from the reduced SVD of ``A`` instead.
    It is then denormalised, ``H = T'⁻¹ Ĥ T``. The
    result has unit Frobenius norm (see :func:`normalize_homography`).

    Raises :class:`~pgsym.errors.CollinearPointsError` for collinear
    configurations (three of exactly four points on a line, or all points on one
    line) and :class:`~pgsym.errors.DimensionError` for fewer than four points.

    >>> src = [[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.2]]
    >>> H = np.array([[1.0, 0.2, 3.0], [0.1, 2.0, -1.0], [0.01, 0.02, 1.0]])
    >>> dst = apply_homography(H, src)
    >>> bool(np.allclose(dlt_homography(src, dst), normalize_homography(H), atol=1e-12))
    True
    >>> dlt_homography([[0, 0], [1, 1], [2, 2], [0, 1]], [[0, 0], [1, 0], [1, 1], [0, 1]])
    Traceback (most recent call last):
    ...
    pgsym.errors.CollinearPointsError: source points 1, 2 and 3 are collinear; ...
    """
    p = _points(src, "src", 4)
    q = _points(dst, "dst", 4)
    if p.shape != q.shape:
        raise DimensionError(f"src and dst must hold the same number of points, got {len(p)} and {len(q)}")
    x, y, s, cx, cy = _normalize(p[:, 0].copy(), p[:, 1].copy(), "source")
    u, v, sd, cu, cv = _normalize(q[:, 0].copy(), q[:, 1].copy(), "destination")
    if len(p) == 4:
        _check_no_three_collinear(np.stack([x, y], axis=1), "source")
        _check_no_three_collinear(np.stack([u, v], axis=1), "destination")
    # AᵀA of the 2n × 9 DLT matrix (rows [aᵀ, 0, -u aᵀ] and [0, aᵀ, -v aᵀ], a = (x, y, 1)) is
    # assembled from the moments  Σ w·m  for the weights w ∈ {1, u, v, u² + v²} and the
    # monomials m ∈ {x², xy, x, y², y, 1}, without forming A itself.
    ones = np.ones(len(x))
    moments = np.stack([ones, u, v, u * u + v * v]) @ np.stack([x * x, x * y, x, y * y, y, ones]).T
    gram = moments[:, [0, 1, 2, 1, 3, 4, 2, 4, 5]].reshape(4, 3, 3)
    g0, gu, gv, guv = gram
    AtA = np.zeros((9, 9))
    AtA[0:3, 0:3] = g0
    AtA[3:6, 3:6] = g0
    AtA[0:3, 6:9] = -gu
    AtA[6:9, 0:3] = -gu.T
    AtA[3:6, 6:9] = -gv
    AtA[6:9, 3:6] = -gv.T
    AtA[6:9, 6:9] = guv
    w, V = np.linalg.eigh(AtA)
    if w[1] <= _RTOL * max(w[-1], 1e-300):
        raise DegenerateConfigurationError(
            "the correspondences do not determine a unique homography (the DLT system has a "
            "two-dimensional null space); add points in general position"
        )
    if np.finfo(float).eps * w[-1] > DLT_EIGEN_GAP_RTOL * w[1]:
        # The eigenvector of AᵀA is accurate to about eps · w_max / w_2 (AᵀA squares the condition number
        # of A). When that bound exceeds 1e-13, solve with the SVD of A itself, which is accurate to eps · σ_max / σ_2.
        A = np.zeros((2 * len(x), 9))
        n = len(x)
        A[:n, 0], A[:n, 1], A[:n, 2] = x, y, 1.0
        A[:n, 6], A[:n, 7], A[:n, 8] = -u * x, -u * y, -u
        A[n:, 3], A[n:, 4], A[n:, 5] = x, y, 1.0
        A[n:, 6], A[n:, 7], A[n:, 8] = -v * x, -v * y, -v
        # (for n = 4, A is 8 × 9 and the null vector is the ninth row of the full V ᵀ)
        Hn = np.linalg.svd(A, full_matrices=2 * n < 9)[2][-1].reshape(3, 3)
    else:
        Hn = V[:, 0].reshape(3, 3)
    # H = T'⁻¹ Ĥ T (see _denormalized)
    # Entries of Ĥ below its rounding error are noise; zero them, which changes Ĥ by less than its own
    # error, so that denormalising cannot blow noise up (v̂ = 1e-17 becomes 1e183 for data near 1e-200).
    Hn = np.where(np.abs(Hn) <= DLT_SNAP_RTOL * np.abs(Hn).max(), 0.0, Hn)
    s_n = np.linalg.svd(Hn, compute_uv=False)  # Ĥ is in the normalised frames: balanced already
    if s_n[-1] <= SINGULAR_RTOL * s_n[0]:
        raise DegenerateConfigurationError("the estimated homography is singular; the correspondences are degenerate")
    return _denormalized(Hn, np.float64(s), np.array([cx, cy]), np.float64(sd), np.array([cu, cv]), "dlt_homography")


def _denormalized(
    Hn: np.ndarray, sp: np.ndarray, cp: np.ndarray, sq: np.ndarray, cq: np.ndarray, function: str
) -> np.ndarray:
    """``H = Tq⁻¹ Ĥ Tp`` for one ``Ĥ`` (3, 3) or a stack (N, 3, 3), at unit norm; entries past float64 raise.

    ``Tp = [[sp I, −sp cp], [0, 1]]`` normalised the sources (scales ``sp``: a scalar or (N,), centroids
    ``cp``: (2,) or (N, 2)), ``Tq`` the destinations; ``Tq⁻¹ = [[I / sq, cq], [0, 1]]``, not the
    integer-looking multiple ``sq Tq⁻¹``, whose corner ``sq`` overflows for data near 1e-200.
    """
    Tp = np.zeros(Hn.shape)
    Tp[..., 0, 0] = Tp[..., 1, 1] = sp
    Tp[..., :2, 2] = -sp[..., None] * cp
    Tp[..., 2, 2] = 1.0
    Tq_inv = np.zeros(Hn.shape)
    Tq_inv[..., 0, 0] = Tq_inv[..., 1, 1] = 1.0 / sq
    Tq_inv[..., :2, 2] = cq
    Tq_inv[..., 2, 2] = 1.0
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        H = Tq_inv @ Hn @ Tp
    if not np.isfinite(H).all():
        raise NonFiniteError(
            f"{function}: the homography between these point sets has entries beyond the float64 range "
            "(source and destination differ in scale by more than about 1e300); rescale one of them"
        )
    return normalize_homography(H)


def _as_exact_point(value: Any, name: str, i: int) -> Point:
    from ..projective_plane import Point  # noqa: PLC0415 — vision → core by design: vision modules load without SymPy

    if isinstance(value, Point):
        return value
    try:
        coords = tuple(value)
    except TypeError:
        raise DimensionError(f"{name} point {i + 1} must be a Point or a tuple of 2 or 3 coordinates") from None
    if any(isinstance(c, (float, np.floating)) and not np.isfinite(c) for c in coords):
        raise NonFiniteError(f"exact_homography: {name} point {i + 1} {coords} has a NaN or infinite coordinate")
    return Point(*coords)




def exact_homography(src: Sequence[Any], dst: Sequence[Any]) -> sympy.ImmutableMatrix:
    """The exact homography mapping four points to four points, in primitive integer form when rational.

    Points may be :class:`~pgsym.projective_plane.Point` objects (ideal points
    allowed) or tuples ``(x, y)`` / ``(x1, x2, x3)`` of exact numbers. With
    ``A`` the matrix sending the standard frame ``e1, e2, e3, (1, 1, 1)`` to the
    source points (columns ``λᵢ pᵢ`` with ``λ = adj[p1 p2 p3] p4``) and ``B`` the
    same for the destination points, ``H = B adj(A)``; no inverse and no division is needed.

    The result is scaled to integer entries with greatest common divisor 1 and
    first nonzero entry positive, so equal homographies give equal matrices.

    >>> from fractions import Fraction
    >>> exact_homography([(0, 0), (1, 0), (1, 1), (0, 1)], [(0, 0), (2, 0), (2, 1), (0, 1)])
    Matrix([
    [2, 0, 0],
    [0, 1, 0],
    [0, 0, 1]])
    >>> exact_homography([(0, 0), (1, 1), (2, 2), (0, 1)], [(0, 0), (1, 0), (1, 1), (0, 1)])
    Traceback (most recent call last):
    ...
    pgsym.errors.CollinearPointsError: source points 1, 2 and 3 (Point(0, 0, 1), Point(1, 1, 1), Point(2, 2, 1)) ...
    """
    if len(src) != 4 or len(dst) != 4:
        raise DimensionError(f"exact_homography needs exactly four source and four destination points, "
                             f"got {len(src)} and {len(dst)}; use dlt_homography for more")
    from ..transformations import homography_from_points  # noqa: PLC0415 — vision → core by design: vision modules load without SymPy

    P = [_as_exact_point(v, "source", i) for i, v in enumerate(src)]
    Q = [_as_exact_point(v, "destination", i) for i, v in enumerate(dst)]
    return _canonical_matrix(homography_from_points(P, Q).matrix)


def _canonical_matrix(H: sympy.Matrix) -> sympy.ImmutableMatrix:
    """``H`` in the core's canonical form for homogeneous coordinates (:func:`pgsym.exact.canonical_coords`)."""
    import sympy  # noqa: PLC0415 — vision → core by design: vision modules load without SymPy

    from ..exact import canonical_coords  # noqa: PLC0415 — vision → core by design: vision modules load without SymPy

    return sympy.ImmutableMatrix(3, 3, list(canonical_coords(list(H))))


def _frames(p: np.ndarray) -> np.ndarray:
    """(N, 4, 3) homogeneous points → (N, 3, 3) matrices sending the standard frame to them.

    With M = [p1 p2 p3], the scales are λ = adj(M) p4, whose entries are the
    triple products det[p4 p2 p3], det[p1 p4 p3], det[p1 p2 p4].
    """
    p1, p2, p3, p4 = p[:, 0], p[:, 1], p[:, 2], p[:, 3]
    l1 = np.einsum("ni,ni->n", p4, cross(p2, p3))
    l2 = np.einsum("ni,ni->n", p1, cross(p4, p3))
    l3 = np.einsum("ni,ni->n", p1, cross(p2, p4))
    return np.stack([p1 * l1[:, None], p2 * l2[:, None], p3 * l3[:, None]], axis=2)


def _normalize_batch(p: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    unit = _pow2(np.abs(p).max(axis=(1, 2)))[:, None, None]  # exact rescale first: no square overflows
    q = p / unit
    c = q.mean(axis=1, keepdims=True)
    d = np.hypot(*np.moveaxis(q - c, 2, 0)).mean(axis=1, keepdims=True)
    s = np.sqrt(2.0) / np.where(d > 0, d, 1.0)
    return (q - c) * s[..., None], s[:, 0] / unit[:, 0, 0], c[:, 0] * unit[:, 0]


def homographies_from_four(src: Any, dst: Any) -> np.ndarray:
    """Solve many four-point problems at once: ``src``, ``dst`` of shape ``(N, 4, 2)`` → ``(N, 3, 3)``.

    Each problem is normalised (centroid to the origin, mean distance √2) and solved
    in closed form through the standard projective frame, ``H = B adj(A)`` with
    all adjugates and triple products vectorised over the batch. Results have unit
    Frobenius norm, largest entry positive (:func:`normalize_homography`); no entry
    is fixed to 1, so ``h33 = 0`` is no special case.

    Raises :class:`~pgsym.errors.CollinearPointsError` when three points of some
    problem are collinear (the message names the first such problem).

    >>> src = np.array([[[0, 0], [1, 0], [1, 1], [0, 1]]], float)
    >>> H = homographies_from_four(src, 2 * src)
    >>> np.round(H[0] / H[0, 2, 2], 12).tolist()
    [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 1.0]]
    """
    p = np.asarray(src, dtype=np.float64)
    q = np.asarray(dst, dtype=np.float64)
    if p.ndim == 2:
        p, q = p[None], q[None]
    if p.shape != q.shape or p.ndim != 3 or p.shape[1:] != (4, 2):
        raise DimensionError(f"src and dst must both have shape (N, 4, 2), got {p.shape} and {q.shape}")
    require_finite(p, "src", "homographies_from_four")
    require_finite(q, "dst", "homographies_from_four")
    n = p.shape[0]
    if n == 0:
        return np.zeros((0, 3, 3))
    pn, sp_, cp = _normalize_batch(p)
    qn, sq, cq = _normalize_batch(q)
    ones = np.ones((n, 4, 1))
    A = _frames(np.concatenate([pn, ones], axis=2))
    B = _frames(np.concatenate([qn, ones], axis=2))
    for label, pts in (("source", pn), ("destination", qn)):
        a, b, c, d = (pts[:, i] for i in range(4))
        bad = np.zeros(n, bool)
        for u, v, w in ((a, b, c), (a, b, d), (a, c, d), (b, c, d)):
            area = (v[:, 0] - u[:, 0]) * (w[:, 1] - u[:, 1]) - (v[:, 1] - u[:, 1]) * (w[:, 0] - u[:, 0])
            scale = np.linalg.norm(v - u, axis=1) * np.linalg.norm(w - u, axis=1)
            bad |= np.abs(area) <= COLLINEAR_RTOL * scale
        if bad.any():
            i = int(np.argmax(bad))
            raise CollinearPointsError(
                f"{int(bad.sum())} of the {n} problems have three collinear {label} points (first: problem {i}); "
                "four correspondences determine a homography only when no three points lie on one line"
            )
    Hn = B @ adjugate(A)
    Hn = np.where(np.abs(Hn) <= DLT_SNAP_RTOL * np.abs(Hn).max(axis=(1, 2), keepdims=True), 0.0, Hn)  # as in the DLT
    return _denormalized(Hn, sp_, cp, sq, cq, "homographies_from_four")
