"""The common points of two conics on float64 arrays: the numeric twin of :func:`pgsym.conic_pencil.intersect_conics`.

The method is the exact one: a degenerate member ``D`` of the pencil ``C₁ + λC₂`` (``λ`` a real root of the
cubic ``det(C₁ + λC₂)``, which always has one) is split into two lines, and each line is met with another
conic ``E`` of the pencil. The four points, with multiplicity, are complex in general (two circles meet in
the circular points ``I``, ``J``), so the result is a complex array of shape ``(..., 4, 3)``, each point
scaled so that its largest coordinate is 1. Only NumPy is used: the cubics of a batch are solved at once
as eigenvalues of their companion matrices, the best separated real root is taken (a double root, such as
the double line l∞ of two concentric circles, is known to half the digits only), and refined by Newton steps.

The policy of :mod:`pgsym.numeric` holds: NaN or ±inf raise :class:`~pgsym.errors.NonFiniteError`
(``nonfinite="mask"``); the same conic twice, or conics sharing a line, have infinitely many common points
and raise :class:`~pgsym.errors.DegenerateConfigurationError` (``degenerate="mask"``), decided to the
relative tolerance :data:`~pgsym.numeric.tolerances.INCIDENT_RTOL`.

>>> P = [[1.0, 0, 0], [0, 0, -0.5], [0, -0.5, 0]]                   # the parabola y = x²
>>> C = [[1.0, 0, 0], [0, 1, -1], [0, -1, 0]]                      # the circle x² + (y − 1)² = 1
>>> pts = intersect_conics(P, C)
>>> sorted((round(float(p[0].real / p[2].real), 9) + 0.0, round(float(p[1].real / p[2].real), 9) + 0.0) for p in pts)
[(-1.0, 1.0), (0.0, 0.0), (0.0, 0.0), (1.0, 1.0)]
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import DegenerateConfigurationError, DimensionError, NonFiniteError
from ._arrays import DEGENERATE, NONFINITE, as_float_array, check_option
from .tolerances import INCIDENT_RTOL
from .transform import adjugate

__all__ = ["intersect_conics"]


def _unit(m: np.ndarray, axes: tuple[int, ...]) -> np.ndarray:
    """``m`` divided by its largest modulus over ``axes`` (left alone where it is zero)."""
    big = np.max(np.abs(m), axis=axes, keepdims=True)
    return m / np.where(big > 0, big, 1.0)


def _real_root(c: np.ndarray) -> np.ndarray:
    """A real root of each cubic ``c[..., 3] t³ + c[..., 2] t² + c[..., 1] t + c[..., 0]`` with ``|c3| ≥ |c0|``."""
    lead = c[..., 3]
    zero = lead == 0  # then c0 = 0 too: t = 0 is a root
    a = c[..., :3] / np.where(zero, 1.0, lead)[..., None]
    companion = np.zeros((*c.shape[:-1], 3, 3))
    companion[..., 0, :] = -a[..., ::-1]
    companion[..., 1, 0] = companion[..., 2, 1] = 1.0
    roots = np.linalg.eigvals(companion)
    # the best separated real root (LAPACK returns real eigenvalues with imaginary part exactly 0): a double
    # root, e.g. the double line l∞ of two concentric circles, is known to half the digits only
    gap = np.stack([np.minimum(np.abs(roots[..., i] - roots[..., (i + 1) % 3]),
                               np.abs(roots[..., i] - roots[..., (i + 2) % 3])) for i in range(3)], axis=-1)
    score = np.where(roots.imag == 0, gap, -np.abs(roots.imag))
    t = np.take_along_axis(roots, np.argmax(score, axis=-1)[..., None], axis=-1)[..., 0].real
    for _ in range(2):  # Newton on the monic cubic: the eigenvalue solver leaves a few ulps of the root
        f = ((t + a[..., 2]) * t + a[..., 1]) * t + a[..., 0]
        df = (3 * t + 2 * a[..., 2]) * t + a[..., 1]
        step = np.divide(f, df, out=np.zeros_like(f), where=df != 0)
        t = np.where(np.abs(step) < 1e-3 * (1 + np.abs(t)), t - step, t)
    return np.where(zero, 0.0, t)


def _cross_matrix(p: np.ndarray) -> np.ndarray:
    z = np.zeros_like(p[..., 0])
    return np.stack([np.stack([z, p[..., 2], -p[..., 1]], -1),
                     np.stack([-p[..., 2], z, p[..., 0]], -1),
                     np.stack([p[..., 1], -p[..., 0], z], -1)], -2)


def _split(D: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The two lines of degenerate conics ``D = l mᵀ + m lᵀ`` (complex), by ``adj D = −(l × m)(l × m)ᵀ``."""
    B = adjugate(D)
    diag = np.diagonal(B, axis1=-2, axis2=-1)
    i = np.argmax(np.abs(diag), axis=-1)[..., None]
    beta = np.sqrt(-np.take_along_axis(diag, i, axis=-1).astype(complex))
    column = np.take_along_axis(B, i[..., None], axis=-1)[..., 0]
    p = np.divide(column, beta, out=np.zeros(column.shape, complex), where=beta != 0)  # 0 for a double line
    M = D + _cross_matrix(p)  # rank one: l mᵀ up to scale
    flat = np.argmax(np.abs(M).reshape(*M.shape[:-2], 9), axis=-1)
    r, c = (flat // 3)[..., None], (flat % 3)[..., None]
    l = np.take_along_axis(M, c[..., None], axis=-1)[..., 0]
    m = np.take_along_axis(M, r[..., None], axis=-2)[..., 0, :]
    return _unit(l, (-1,)), _unit(m, (-1,))


def _meet_line(E: np.ndarray, l: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The two points of conics ``E`` on lines ``l``, and where ``l`` lies on ``E`` (a shared line)."""
    i = np.argmax(np.abs(l), axis=-1)
    basis = np.eye(3)
    j, k = (i + 1) % 3, (i + 2) % 3
    a = np.cross(l, basis[j])  # two independent points of l: (l × e_j) × (l × e_k) = ±l_i l ≠ 0
    b = np.cross(l, basis[k])
    Ea, Eb = np.einsum("...ij,...j->...i", E, a), np.einsum("...ij,...j->...i", E, b)
    A, B, C = (a * Ea).sum(-1), (a * Eb).sum(-1), (b * Eb).sum(-1)  # A s² + 2B st + C t² on s a + t b
    root = np.sqrt(B * B - A * C)
    sign = np.where((np.conj(B) * root).real >= 0, 1.0, -1.0)
    q = -(B + sign * root)  # no cancellation: the roots are (q : A) and (C : q)
    x1 = q[..., None] * a + A[..., None] * b
    x2 = C[..., None] * a + q[..., None] * b
    # a double root at a (A = B = 0) or at b (C = B = 0) leaves one form 0 · a + 0 · b: the other is the point
    n1, n2 = np.linalg.norm(x1, axis=-1), np.linalg.norm(x2, axis=-1)
    x1 = np.where((n1 <= INCIDENT_RTOL * n2)[..., None], x2, x1)
    x2 = np.where((n2 <= INCIDENT_RTOL * n1)[..., None], x1, x2)
    size = np.max(np.abs(E), axis=(-2, -1))
    on = np.maximum(np.maximum(np.abs(A), np.abs(B)), np.abs(C)) <= INCIDENT_RTOL * size
    return x1, x2, on


def intersect_conics(C1: Any, C2: Any, *, nonfinite: str = "raise", degenerate: str = "raise") -> Any:
    """The four common points, with multiplicity, of conics ``C1``, ``C2`` (symmetric ``(..., 3, 3)``, broadcast).

    Returns a complex array ``(..., 4, 3)``; see the module docstring for the method and the policy.

    >>> pts = intersect_conics(np.diag([1.0, 1, -25]), [[1.0, 0, -4], [0, 1, 0], [-4, 0, 7]])
    >>> np.round(pts, 12) + 0                                       # (4, ±3), and the circular points
    array([[ 1.  +0.j,  0.75+0.j,  0.25+0.j],
           [ 1.  +0.j, -0.75+0.j,  0.25+0.j],
           [ 1.  +0.j,  0.  +1.j,  0.  +0.j],
           [ 1.  +0.j,  0.  -1.j,  0.  +0.j]])
    """
    check_option(nonfinite, NONFINITE, "nonfinite", "intersect_conics")
    check_option(degenerate, DEGENERATE, "degenerate", "intersect_conics")
    mats = [as_float_array(x, name, "intersect_conics") for x, name in ((C1, "C1"), (C2, "C2"))]
    for m, name in zip(mats, ("C1", "C2"), strict=True):
        if m.ndim < 2 or m.shape[-2:] != (3, 3):
            raise DimensionError(f"intersect_conics: {name} must be 3×3 conic matrices, got shape {m.shape}")
    batch = np.broadcast_shapes(mats[0].shape[:-2], mats[1].shape[:-2])
    A, B = (np.broadcast_to(m, (*batch, 3, 3)) for m in mats)
    finite = np.isfinite(A).all(axis=(-2, -1)) & np.isfinite(B).all(axis=(-2, -1))
    if nonfinite == "raise" and not finite.all():
        first = tuple(int(i) for i in np.argwhere(~finite)[0])
        raise NonFiniteError(
            f"intersect_conics: {int((~finite).sum())} of the {finite.size} conic pairs hold NaN or infinity, "
            f"the first at index {first}; pass nonfinite='mask' to get the finite results with a mask"
        )
    A, B = (np.where(finite[..., None, None], m, np.eye(3)) for m in (A, B))
    A, B = (_unit(m, (-2, -1)) for m in (A, B))
    c0, c3 = np.linalg.det(A), np.linalg.det(B)
    c1 = np.einsum("...ij,...ji->...", adjugate(A), B)  # det(A + λB) = c0 + c1 λ + c2 λ² + c3 λ³
    c2 = np.einsum("...ij,...ji->...", A, adjugate(B))
    swap = np.abs(c3) < np.abs(c0)  # solve for the end with the larger leading coefficient
    cubic = np.where(swap[..., None], np.stack([c3, c2, c1, c0], -1), np.stack([c0, c1, c2, c3], -1))
    t = _real_root(cubic)[..., None, None]
    D = np.where(swap[..., None, None], t * A + B, A + t * B)  # a degenerate member
    E = np.where(swap[..., None, None], A, B)  # another conic of the pencil
    # C1 ∝ C2 (after scaling both to unit size, C1 = ±C2 up to rounding)
    same = np.minimum(np.max(np.abs(A - B), axis=(-2, -1)), np.max(np.abs(A + B), axis=(-2, -1))) <= INCIDENT_RTOL
    l, m = _split(_unit(D, (-2, -1)))
    p1, p2, on_l = _meet_line(E, l)
    p3, p4, on_m = _meet_line(E, m)
    points = _unit(np.stack([p1, p2, p3, p4], axis=-2), (-1,))
    big = np.take_along_axis(points, np.argmax(np.abs(points), axis=-1)[..., None], axis=-1)
    points = points / np.where(big != 0, big, 1.0)
    bad = same | on_l | on_m
    if degenerate == "raise" and (bad & finite).any():
        first = tuple(int(i) for i in np.argwhere(bad & finite)[0])
        raise DegenerateConfigurationError(
            f"intersect_conics: {int((bad & finite).sum())} of the {bad.size} conic pairs are one conic or share a "
            f"line, so they have infinitely many common points, the first at index {first}; "
            "pass degenerate='mask' to get NaN rows there and a mask of the good ones"
        )
    ok = finite & ~bad
    if nonfinite == "mask" or degenerate == "mask":
        points[~ok] = np.nan
        return points, ok
    return points
