"""Scale-free decisions about transformation matrices: balancing by a change of units, then singular values.

A transformation of Pᵏ written in blocks ``H = [[A, t], [vᵀ, w]]`` (``A`` the k×k linear
part, ``t`` the translation, ``vᵀ`` the projective row) changes with the units of its source
and target: measuring the source in units ``2^b`` and the target in units ``2^a`` gives
``[[2^(a−b) A, 2^a t], [2^(−b) vᵀ, w]]``, and the overall scale of a homogeneous matrix is
free too. :func:`balance` picks the three exponents (by least squares on the binary exponents
of the four blocks) so that every nonzero block is of order one, as Hartley's normalisation
does for the data of a DLT. Powers of two make the scaling exact, so the rank is kept
exactly, and no entry can overflow. :func:`singular` then compares the singular values of
the balanced matrix: a translation by ``(1920, 1080)`` or ``diag(1e-5, 1e-5, 1)`` is as far
from singular as the identity, and a rank-2 matrix is singular at any scale.

>>> import numpy as np
>>> bool(singular(np.array([[1.0, 0, 1920], [0, 1, 1080], [0, 0, 1]]))), bool(singular(np.diag([1e100, 1e100, 0])))
(False, True)
"""

from __future__ import annotations

import functools

import numpy as np

from ..errors import NonFiniteError
from .tolerances import SINGULAR_RTOL

__all__ = ["balance", "require_finite", "singular"]

# rows: the exponent added to each block by (a, b, overall): A gets a − b + λ, t gets a + λ, vᵀ gets −b + λ, w gets λ
_DESIGN = np.array([[1.0, -1.0, 1.0], [1.0, 0.0, 1.0], [0.0, -1.0, 1.0], [0.0, 0.0, 1.0]])


def require_finite(a: np.ndarray, name: str, function: str) -> np.ndarray:
    """``a`` unchanged when every entry is finite, else :class:`~pgsym.errors.NonFiniteError` naming the first bad one.

    One reduction decides the common case: the sum of a finite array is finite unless it
    overflows, and only then is every entry tested.

    >>> require_finite(np.array([1.0, np.inf]), "x", "f")
    Traceback (most recent call last):
    ...
    pgsym.errors.NonFiniteError: f: x holds 1 NaN or infinite entries, the first at index (1,) (inf); ...
    """
    with np.errstate(over="ignore", invalid="ignore"):
        if np.isfinite(np.sum(a)):
            return a
    bad = ~np.isfinite(a)
    if not bad.any():
        return a
    first = tuple(int(i) for i in np.argwhere(bad)[0])
    raise NonFiniteError(
        f"{function}: {name} holds {int(bad.sum())} NaN or infinite entries, the first at index {first} "
        f"({a[first]}); the numeric path computes only with finite numbers: remove or repair those entries"
    )


def _block_exponents(h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Binary exponents of max|block| for the blocks A, t, vᵀ, w (shape (..., 4)) and which blocks are nonzero."""
    k = h.shape[-1] - 1
    blocks = (h[..., :k, :k], h[..., :k, k:], h[..., k:, :k], h[..., k:, k:])
    largest = np.stack([np.max(np.abs(b), axis=(-2, -1)) for b in blocks], axis=-1)
    return np.frexp(largest)[1].astype(np.float64), largest > 0


@functools.cache
def _pinv(present: tuple[bool, ...]) -> np.ndarray:
    return np.linalg.pinv(_DESIGN * np.array(present)[:, None])


def balance(H: np.ndarray) -> np.ndarray:
    """``2^λ diag(2^a I, 1) H diag(2^(−b) I, 1)``: ``H`` (or a stack) in units where its nonzero blocks are of order 1.

    The scaling is exact (powers of two), so the rank and the ratio ``|t| |v| / (|A| |w|)`` are
    unchanged; only the units are. ``H`` must be finite.

    >>> balance(np.array([[1.0, 0, 1920], [0, 1, 1080], [0, 0, 1]]))
    array([[0.5       , 0.        , 0.9375    ],
           [0.        , 0.5       , 0.52734375],
           [0.        , 0.        , 0.5       ]])
    """
    e, present = _block_exponents(H)
    # least squares  design @ (a, b, λ) ≈ −e  over the nonzero blocks (the pseudo-inverse handles absent ones)
    if H.ndim == 2:  # one matrix: the pseudo-inverse of its pattern of nonzero blocks, computed once
        z = np.rint(_pinv(tuple(present.tolist())) @ (-e * present)).astype(np.int64)
    else:
        design = _DESIGN * present[..., None]
        z = np.rint(np.einsum("...ij,...j->...i", np.linalg.pinv(design), -e * present)).astype(np.int64)
    a, b, lam = z[..., 0], z[..., 1], z[..., 2]
    n = H.shape[-1]
    row = np.zeros((*H.shape[:-2], n), np.int64) + (a + lam)[..., None]
    row[..., -1] = lam
    col = np.zeros((*H.shape[:-2], n), np.int64) - b[..., None]
    col[..., -1] = 0
    return np.ldexp(H, row[..., :, None] + col[..., None, :])


def singular(H: np.ndarray, rtol: float = SINGULAR_RTOL) -> np.ndarray:
    """True where ``σ_min ≤ rtol · σ_max`` for the balanced matrix (``H`` finite, square, possibly a stack).

    >>> bool(singular(np.array([[1.0, 2, 3], [2, 4, 6], [0, 0, 1]]) * 1e-200))
    True
    >>> bool(singular(np.diag([1e-5, 1e-5, 1.0])))
    False
    """
    s = np.linalg.svd(balance(H), compute_uv=False)
    return np.asarray(s[..., -1] <= rtol * s[..., 0])
