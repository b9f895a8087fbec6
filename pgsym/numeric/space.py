"""Planes through three points and points on three planes in P³, on float64 arrays.

The numeric twin of :mod:`pgsym.space`. Both constructions are the same formula,
:func:`pgsym.space.triple_cross`: for three 4-vectors ``u, v, w`` the vector ``n`` with
``n · x = det[x; u; v; w]``, whose entries are the signed 3×3 minors of ``[u; v; w]``,

    n_i = (−1)^i det([u; v; w] without column i).

Each minor is expanded along ``u`` with the six 2×2 minors ``m_jk = v_j w_k − v_k w_j``:
``det(columns j<k<l) = u_j m_kl − u_k m_jl + u_l m_jk``. Collinear points (or three
planes through one line) give the zero vector.

>>> plane_through([1.0, 0, 0, 1], [0.0, 1, 0, 1], [0.0, 0, 1, 1])   # x + y + z = 1
array([ 1.,  1.,  1., -1.])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ._arrays import rowwise

__all__ = ["plane_through", "point_on_planes", "triple_cross"]

_PAIRS = ((0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3))
# n_i = sign * (u_a m_bc − u_b m_ac + u_c m_ab) over the columns (a, b, c) other than i
_ROWS = ((0, 1.0, (1, 2, 3)), (1, -1.0, (0, 2, 3)), (2, 1.0, (0, 1, 3)), (3, -1.0, (0, 1, 2)))


def _triple_cross_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    u, v, w = ins
    t = ws[6]
    m = {}
    for (j, k), buf in zip(_PAIRS, ws[:6], strict=True):
        np.multiply(v[..., j], w[..., k], out=buf)
        np.multiply(v[..., k], w[..., j], out=t)
        np.subtract(buf, t, out=buf)
        m[j, k] = buf
    for i, sign, (a, b, c) in _ROWS:
        oi = o[..., i]
        first, second = (a, b) if sign > 0 else (b, a)  # a negative sign swaps the first two terms
        np.multiply(u[..., first], m[(b, c) if sign > 0 else (a, c)], out=oi)
        np.multiply(u[..., second], m[(a, c) if sign > 0 else (b, c)], out=t)
        np.subtract(oi, t, out=oi)
        np.multiply(u[..., c], m[a, b], out=t)
        (np.add if sign > 0 else np.subtract)(oi, t, out=oi)


def triple_cross(
    u: Any, v: Any, w: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise"
) -> Any:
    """The vectors ``n`` with ``n · x = det[x; u; v; w]`` (the numeric :func:`pgsym.space.triple_cross`).

    >>> triple_cross([1.0, 0, 0, 0], [0.0, 1, 0, 0], [0.0, 0, 1, 0])
    array([ 0.,  0.,  0., -1.])
    """
    inputs = [(u, 4, "u"), (v, 4, "v"), (w, 4, "w")]
    return rowwise(_triple_cross_kernel, "triple_cross", inputs, 4, out, axis, 7, nonfinite)


def plane_through(
    p: Any, q: Any, r: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise"
) -> Any:
    """The planes through triples of points of P³ (zero where the points are collinear).

    >>> from pgsym.numeric import is_zero_vector
    >>> planes = plane_through([0.0, 0, 0, 1], [1.0, 0, 0, 1], [[0.0, 1, 0, 1], [2, 0, 0, 1]])
    >>> planes[0], is_zero_vector(planes)                      # the plane z = 0; then collinear points
    (array([0., 0., 1., 0.]), array([False,  True]))
    """
    inputs = [(p, 4, "p"), (q, 4, "q"), (r, 4, "r")]
    return rowwise(_triple_cross_kernel, "plane_through", inputs, 4, out, axis, 7, nonfinite)


def point_on_planes(
    a: Any, b: Any, c: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise"
) -> Any:
    """The points where triples of planes of P³ meet (zero where the planes share a line).

    >>> point_on_planes([1.0, 0, 0, -1], [0.0, 1, 0, -2], [0.0, 0, 1, -3])   # (1, 2, 3), up to scale
    array([-1., -2., -3., -1.])
    """
    inputs = [(a, 4, "a"), (b, 4, "b"), (c, 4, "c")]
    return rowwise(_triple_cross_kernel, "point_on_planes", inputs, 4, out, axis, 7, nonfinite)
