"""Numerical rank, null spaces by the SVD, and the plane (point) fitted to many points (planes) of P³.

The floating-point counterparts of :func:`pgsym.linalg.rank_exact` and
:func:`pgsym.linalg.nullspace_exact` (method #1 of the lecture: the null space itself),
and of :func:`pgsym.space.plane_through` / :func:`pgsym.space.point_on_planes` for three
or, in the least-squares sense, more rows. Every rank decision is scale-free: singular
values count as zero below ``max(m, n) · RANK_EPS · σ_max``
(:data:`pgsym.numeric.tolerances.RANK_EPS`), after exact power-of-two changes of units.

These functions are also reachable under their old names in :mod:`pgsym.linalg`
(resolved lazily there, so that the exact module does not load NumPy).

>>> numeric_rank([[1.0, 2.0], [2.0, 4.0]])
1
>>> nullspace_svd([[1.0, 0.0], [0.0, 0.0]]).round(12).tolist()
[[0.0], [1.0]]
"""

from __future__ import annotations

import math
import numbers
import sys
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..errors import (
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
    InvalidCoordinatesError,
    NonFiniteError,
)
from .tolerances import RANK_EPS

__all__ = ["nullspace_svd", "numeric_rank", "plane_through_numeric", "point_on_planes_numeric"]


def _is_homogeneous_vector(x: Any) -> bool:
    # an exact pgsym object exists only once pgsym.homogeneous is loaded: asking sys.modules keeps SymPy unloaded
    module = sys.modules.get("pgsym.homogeneous")
    return module is not None and isinstance(x, module.HomogeneousVector)


def float_matrix(A: Any, name: str = "A") -> np.ndarray:
    """``A`` (nested sequences, an array, or rows of exact pgsym vectors) as a finite, non-empty 2D float array.

    >>> float_matrix([[1, 2], [3, 4]]).dtype
    dtype('float64')
    """
    if _is_homogeneous_vector(A):
        raise DimensionError(f"{name} must be a 2D array, got the single vector {A!r}")
    try:
        if isinstance(A, Sequence) and A and all(_is_homogeneous_vector(r) for r in A):
            A = [[float(v) for v in r.coords] for r in A]
        array = np.asarray(A, dtype=float)
    except (TypeError, ValueError) as err:
        raise InvalidCoordinatesError(
            f"{name} must be an array of real numbers (substitute values for any symbols first): {err}"
        ) from None
    if array.ndim != 2 or 0 in array.shape:
        raise DimensionError(f"{name} must be a non-empty 2D array, got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise NonFiniteError(f"{name} contains NaN or infinite entries; remove or repair those rows")
    return array


def unit_scaled(array: np.ndarray) -> np.ndarray:
    """``array`` times the power of two that brings its largest entry to [0.5, 1).

    The scaling is exact, so the SVD sees no overflow or underflow and the ratios of singular
    values, which are all that rank decisions use, are unchanged.

    >>> unit_scaled(np.array([3.0, -6.0])).tolist()
    [0.375, -0.75]
    """
    largest = float(np.abs(array).max())
    return np.ldexp(array, -int(np.frexp(largest)[1])) if largest > 0 else array


def rank_tolerance(singular_values: np.ndarray, shape: tuple[int, int], rtol: float | None) -> float:
    """The absolute threshold ``rtol · σ_max`` (default ``rtol = max(m, n) · RANK_EPS``) below which σ counts as 0.

    >>> rank_tolerance(np.array([2.0, 1.0]), (2, 2), 0.5)
    1.0
    """
    largest = float(singular_values.max()) if singular_values.size else 0.0
    if rtol is None:
        rtol = max(shape) * RANK_EPS
    elif not (isinstance(rtol, numbers.Real) and math.isfinite(rtol) and rtol >= 0):
        raise InvalidCoordinatesError(f"rtol must be a finite number >= 0, got {rtol!r}")
    return float(rtol) * largest


def numeric_rank(A: Any, rtol: float | None = None) -> int:
    """The numerical rank: the number of singular values above ``rtol · σ_max``.

    The default ``rtol`` is ``max(m, n) · ε`` (machine epsilon), the default of
    :func:`numpy.linalg.matrix_rank`.

    >>> numeric_rank([[1.0, 2.0], [2.0, 4.0 + 1e-17]])
    1
    """
    array = unit_scaled(float_matrix(A))
    singular_values = np.linalg.svd(array, compute_uv=False)
    return int(np.sum(singular_values > rank_tolerance(singular_values, array.shape, rtol)))


def nullspace_svd(A: Any, rtol: float | None = None) -> np.ndarray:
    """An orthonormal basis of the numerical null space of ``A`` (shape ``(m, n)``), by the SVD.

    With ``A = U Σ Vᵀ`` (full SVD), the columns of ``V`` whose singular values
    are (numerically) zero span the null space. A singular value counts as zero
    when it is at most ``rtol · σ_max``; the default ``rtol = max(m, n) · ε``
    is the rule of :func:`numpy.linalg.matrix_rank`. For a wide matrix
    (``m < n``) the last ``n - m`` columns of ``V`` always belong to the null
    space. Returns an array of shape ``(n, k)`` whose ``k`` columns are the
    basis vectors (``k = 0`` for full column rank).

    >>> N = nullspace_svd([[1.0, 0.0, 0.0, -1.0], [0.0, 1.0, 0.0, -2.0], [0.0, 0.0, 1.0, -3.0]])
    >>> N.shape, bool(np.allclose(N[:, 0] / N[3, 0], [1, 2, 3, 1]))
    ((4, 1), True)
    """
    array = unit_scaled(float_matrix(A))
    _, singular_values, vt = np.linalg.svd(array, full_matrices=True)
    rank = int(np.sum(singular_values > rank_tolerance(singular_values, array.shape, rtol)))
    return vt[rank:].T.copy()


def _sign_normalised(v: np.ndarray) -> np.ndarray:
    """Unit vector with its largest-magnitude entry positive (a deterministic representative)."""
    v = v / np.linalg.norm(v)
    return v if v[np.argmax(np.abs(v))] > 0 else -v


def _smallest_right_singular_vector(
    rows: Any, name: str, what: str, rtol: float | None, error: type[DegenerateConfigurationError], message: str
) -> np.ndarray:
    """The fitted plane (point) of ``rows``; ``error(message.format(rank=…))`` when the rank is below 3."""
    array = float_matrix(rows, name)
    if array.shape[1] != 4 or array.shape[0] < 3:
        raise DimensionError(f"{name} must have shape (n, 4) with n >= 3 {what}, got {array.shape}")
    # The rank is decided after a change of units, exactly (powers of two): each row (a point or plane,
    # defined up to scale) to largest entry of order one, then the homogeneous column against the other
    # three. That keeps the null space (once the column scaling is undone), and the decision no longer
    # depends on whether coordinates are in millimetres or kilometres.
    rows_max = np.abs(array).max(axis=1, keepdims=True)
    balanced = np.ldexp(array, -np.frexp(np.where(rows_max > 0, rows_max, 1.0))[1])
    head, last = float(np.abs(balanced[:, :3]).max()), float(np.abs(balanced[:, 3]).max())
    shift = int(np.frexp(head)[1] - np.frexp(last)[1]) if head > 0 and last > 0 else 0
    balanced[:, 3] = np.ldexp(balanced[:, 3], shift)
    _, singular_values, vt = np.linalg.svd(balanced, full_matrices=True)
    rank = int(np.sum(singular_values > rank_tolerance(singular_values, balanced.shape, rtol)))
    if rank < 3:
        raise error(message.format(rank=rank))
    if array.shape[0] == 3:  # the exact null vector: the balanced matrix gives it to full relative accuracy
        v = vt[-1].copy()
        v[3] = np.ldexp(v[3], shift)  # back to the given units: x·π = x'·π' with x'_4 = 2^shift x_4
    else:  # least squares: min ‖A π‖ for the rows as given (weights are part of the problem), scaled exactly
        v = np.linalg.svd(unit_scaled(array), full_matrices=True)[2][-1]
    return _sign_normalised(np.ldexp(v, -int(np.frexp(np.abs(v).max())[1])))


def plane_through_numeric(points: Any, rtol: float | None = None) -> np.ndarray:
    """The plane through three (or, in the least-squares sense, more) points given as homogeneous rows.

    ``points`` has shape ``(n, 4)`` with ``n >= 3``. The plane is the right
    singular vector of the smallest singular value: the exact null vector for
    three points, the least-squares plane (minimising ``‖A π‖`` with ``‖π‖ = 1``)
    for more. It is returned as a unit 4-vector with its largest-magnitude entry
    positive. Raises :class:`CollinearPointsError` when the numerical rank (see
    :func:`numeric_rank`) is below 3.

    >>> pi = plane_through_numeric([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]])
    >>> bool(np.allclose(pi / pi[0], [1, 1, 1, -1]))
    True
    """
    message = (
        "the matrix of the points has numerical rank {rank} < 3: they are collinear or coincide, so no unique "
        "plane passes through them; add a point off their line (or pass a smaller rtol)"
    )
    what = "(one homogeneous point per row)"
    return _smallest_right_singular_vector(points, "points", what, rtol, CollinearPointsError, message)


def point_on_planes_numeric(planes: Any, rtol: float | None = None) -> np.ndarray:
    """The point on three (or, least squares, more) planes given as rows ``(a, b, c, d)``.

    The dual of :func:`plane_through_numeric`: the right singular vector of the
    smallest singular value, as a unit 4-vector with its largest-magnitude entry
    positive; an ideal point has last entry (numerically) zero. Raises
    :class:`DependentPlanesError` when the numerical rank is below 3 (the
    planes share a line, or repeat).

    >>> X = point_on_planes_numeric([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]])
    >>> bool(np.allclose(X[:3] / X[3], [1, 2, 3]))
    True
    """
    message = (
        "the matrix of the planes has numerical rank {rank} < 3: they share a line or repeat, so they do not meet "
        "in a single point; replace one plane by a plane not through that line (or pass a smaller rtol)"
    )
    return _smallest_right_singular_vector(planes, "planes", "(one plane per row)", rtol, DependentPlanesError, message)
