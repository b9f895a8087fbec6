"""The SVD of a 2×2 matrix as rotate, stretch, rotate: the picture behind every singular value.

Also reachable as :func:`pgsym.linalg.svd_steps` (resolved lazily there).

>>> V, S, U = svd_steps([[2.0, 0.0], [0.0, 1.0]])
>>> np.diag(S).tolist()
[2.0, 1.0]
"""

from __future__ import annotations

from typing import Any, NamedTuple

import numpy as np

from ..errors import DimensionError
from .nullspace import float_matrix, rank_tolerance

__all__ = ["SVDSteps", "svd_steps"]


class SVDSteps(NamedTuple):
    """The factors of ``A = U Σ Vᵀ`` for a 2×2 matrix, applied as ``x ↦ Vᵀx ↦ Σ Vᵀx ↦ U Σ Vᵀx``."""

    V: np.ndarray
    """Right singular vectors (columns); the first step applies ``V.T``."""
    Sigma: np.ndarray
    """Diagonal 2×2 matrix of the singular values ``σ1 ≥ σ2 ≥ 0``."""
    U: np.ndarray
    """Left singular vectors (columns); the last step applies ``U``."""


def svd_steps(A: Any) -> SVDSteps:
    """The SVD of a real 2×2 matrix as rotate, stretch, rotate: ``A = U Σ Vᵀ``.

    ``Vᵀ`` turns the right singular vectors onto the axes, ``Σ`` stretches the
    axes by ``σ1 ≥ σ2 ≥ 0`` and ``U`` turns the axes onto the left singular
    vectors. Signs are chosen so that ``V`` is always a rotation
    (``det V = 1``) whose first column has its largest-magnitude entry
    positive (so the result does not depend on the LAPACK build); ``U`` is
    then a rotation too when ``det A ≥ 0`` and a reflection when ``det A < 0``
    (no rotation–stretch–rotation can reverse orientation).

    >>> V, S, U = svd_steps([[3.0, 0.0], [0.0, -2.0]])
    >>> np.diag(S).tolist(), round(float(np.linalg.det(V)), 12)
    ([3.0, 2.0], 1.0)
    >>> bool(np.allclose(U @ S @ V.T, [[3, 0], [0, -2]]))
    True
    """
    given = float_matrix(A)
    if given.shape != (2, 2):
        raise DimensionError(f"svd_steps takes a 2×2 matrix, got shape {given.shape}")
    # factor the matrix scaled by a power of two to unit size (exact), so that A v / σ stays a unit
    # vector even for entries near the ends of the float64 range; Σ is scaled back at the end
    largest = float(np.abs(given).max())
    exponent = int(np.frexp(largest)[1]) if largest > 0 else 0
    array = np.ldexp(given, -exponent)
    _, s, vt = np.linalg.svd(array)
    tol = rank_tolerance(s, (2, 2), None)
    v1 = vt[0] if vt[0][np.argmax(np.abs(vt[0]))] > 0 else -vt[0]  # a deterministic sign
    v = np.column_stack([v1, [-v1[1], v1[0]]])  # the second column makes V a rotation
    u = np.empty((2, 2))
    u[:, 0] = array @ v[:, 0] / s[0] if s[0] > tol else [1.0, 0.0]
    # u2 is ±u1 turned by 90°; dividing A v2 by a small σ2 would lose orthogonality, so take only its sign
    perpendicular = np.array([-u[1, 0], u[0, 0]])
    flip = s[1] > tol and float(perpendicular @ (array @ v[:, 1])) < 0
    u[:, 1] = -perpendicular if flip else perpendicular  # σ2 = 0: U a rotation too
    return SVDSteps(V=v, Sigma=np.diag(np.ldexp(s, exponent)), U=u)
