"""Classifying a float transformation matrix in the hierarchy, by scale-free tests.

The numeric half of :func:`pgsym.hierarchy.classify`, which calls :func:`classify_matrix` for
float input (NumPy arrays, lists of floats) or whenever a tolerance is given. The answer is
the key of the smallest class (``"euclidean2"``, ``"isometry2"``, ``"similarity2"``,
``"affine2"``, ``"projective2"``; ``"euclidean3"``, ``"isometry3"``, ``"similarity3"``, ``"affine3"``,
``"projective3"``), which :func:`pgsym.hierarchy.class_by_key` turns into the class; this
module imports neither SymPy nor the exact core.

With ``H = [[A, t], [vᵀ, w]]`` (max-norms ``α, τ, ν, ω``): singular when the balanced
matrix has ``σ_min ≤ SINGULAR_RTOL σ_max``; affine when ``ν τ ≤ tol α ω`` (and ``ν = 0`` if
``τ = 0``: with no translation, units can make any ``v ≠ 0`` as large as ``A``); a similarity when
``AᵀA`` is within ``tol`` of a multiple of ``I``; an isometry when that multiple is ``w²``.
Every test is a ratio that conjugating ``H`` by ``diag(s, …, s, 1)`` or scaling it leaves unchanged
(the tolerances are explained in :mod:`pgsym.numeric.tolerances`).

>>> classify_matrix([[0.0, -2, 5], [2, 0, 1], [0, 0, 1]])
'similarity2'
>>> classify_matrix([[1.0, 0, 0, 1e6], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
'euclidean3'
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..errors import DimensionError, SingularTransformationError
from .conditioning import require_finite, singular
from .tolerances import CLASS_RTOL, SINGULAR_RTOL

__all__ = ["classify_matrix"]

_KEYS = {
    3: ("euclidean2", "isometry2", "similarity2", "affine2", "projective2"),
    4: ("euclidean3", "isometry3", "similarity3", "affine3", "projective3"),
}


def classify_matrix(H: Any, tol: float | None = None) -> str:
    """The key of the smallest class of the hierarchy that holds the 3×3 or 4×4 float matrix ``H``.

    ``H`` may be anything :func:`numpy.array` reads as numbers (a matrix with a ``tolist``
    method is read through it). Raises :class:`~pgsym.errors.SingularTransformationError` for a
    singular matrix, :class:`~pgsym.errors.NonFiniteError` for NaN or infinity. ``tol`` is the
    relative tolerance of the class tests (default :data:`~pgsym.numeric.tolerances.CLASS_RTOL`).

    >>> classify_matrix(np.diag([1.0, -1, 1]))                       # a reflection
    'isometry2'
    >>> classify_matrix(np.diag([1.0, 1, -1, 1]))                    # a mirror of space
    'isometry3'
    >>> classify_matrix([[1.0, 0, 0], [0, 1, 0], [1e-3, 0, 1]])     # a projective row
    'projective2'
    """
    if tol is None:
        tol = CLASS_RTOL
    try:
        M = np.array(H.tolist() if hasattr(H, "tolist") else H, dtype=float)
    except (TypeError, ValueError) as err:
        raise DimensionError(f"classify needs a square 3×3 or 4×4 matrix of numbers, got {H!r}") from err
    if M.shape not in ((3, 3), (4, 4)):
        raise DimensionError(f"classify needs a 3×3 or 4×4 matrix, got shape {M.shape}")
    require_finite(M, "H", "classify")
    if not np.abs(M).max() > 0 or singular(M):
        raise SingularTransformationError(
            f"the matrix {M.tolist()} is singular (σ_min ≤ {SINGULAR_RTOL} σ_max in balanced units): no projective "
            "transformation"
        )
    n = M.shape[0]
    k = n - 1
    M = np.ldexp(M, -int(np.frexp(np.abs(M).max())[1]))  # exact power-of-two scale: no overflow below
    A, t, v, w = M[:k, :k], M[:k, k], M[k, :k], float(M[k, k])
    alpha, tau, nu, omega = float(np.abs(A).max()), float(np.abs(t).max()), float(np.abs(v).max()), abs(w)
    keys = _KEYS[n]
    if nu > 0:
        if tau == 0 or omega == 0:
            return keys[-1]
        if math.log(nu) + math.log(tau) > math.log(tol) + math.log(alpha) + math.log(omega):
            return keys[-1]
    G = (A / alpha).T @ (A / alpha)
    g = float(np.trace(G)) / k
    if np.abs(G - g * np.eye(k)).max() > tol * g:
        return keys[-2]
    # orientation of the affine map x ↦ (A x + t) / w: the sign of det(A / w) = det(A) / wᵏ, whatever the scale of H
    proper = bool(np.linalg.det(A / alpha) * np.sign(w) ** k > 0)
    # the similarity ratio r = √g α / |w|; an isometry when |r² − 1| ≤ tol (computed in logarithms)
    log_r2 = math.log(g) + 2 * (math.log(alpha) - math.log(omega))
    isometry = abs(log_r2) < 1 and abs(math.expm1(log_r2)) <= tol
    if not isometry:
        return keys[2]
    return keys[0] if proper else keys[1]
