"""Planes through three points and points on three planes in P³, on float64 arrays.

The numeric twin of :mod:`pgsym.space`. Both constructions are the same formula,
:func:`pgsym.space.triple_cross`: for three 4-vectors ``u, v, w`` the vector ``n`` with
``n · x = det[x; u; v; w]``, whose entries are the signed 3×3 minors of ``[u; v; w]``,

    n_i = (−1)^i det([u; v; w] without column i).

Each minor is expanded along ``u`` with the six 2×2 minors ``m_jk = v_j w_k − v_k w_j``:
``det(columns j<k<l) = u_j m_kl − u_k m_jl + u_l m_jk``. Collinear points (or three
planes through one line) make every minor zero: :func:`plane_through` then raises
:class:`~pgsym.errors.CollinearPointsError` and :func:`point_on_planes`
:class:`~pgsym.errors.DependentPlanesError`, or, with ``degenerate="mask"``, they return
NaN rows and a mask (the policy of :mod:`pgsym.numeric`). :func:`triple_cross` is the bare
formula, zero vectors included.

>>> plane_through([1.0, 0, 0, 1], [0.0, 1, 0, 1], [0.0, 0, 1, 1])   # x + y + z = 1
array([ 1.,  1.,  1., -1.])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import CollinearPointsError, DependentPlanesError
from ._arrays import DEGENERATE, check_option, construction, rowwise

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


def _minors(
    function: str, inputs: list[tuple[Any, int, str]], out: Any, axis: int, nonfinite: str, degenerate: str,
    error: type[Exception], what: str,
) -> Any:
    check_option(degenerate, DEGENERATE, "degenerate", function)  # no "zero": these raise by default
    return construction(_triple_cross_kernel, function, inputs, 4, out, axis, 7, nonfinite, degenerate, error, what)


def plane_through(
    p: Any, q: Any, r: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise",
) -> Any:
    """The planes through triples of points of P³.

    Collinear or coincident points (all minors exactly zero) raise
    :class:`~pgsym.errors.CollinearPointsError`; with ``degenerate="mask"`` the result is
    ``(planes, ok)`` with NaN rows where ``ok`` is False (also for rows masked by ``nonfinite="mask"``).

    >>> plane_through([0.0, 0, 0, 1], [1.0, 0, 0, 1], [0.0, 1, 0, 1])        # the plane z = 0
    array([0., 0., 1., 0.])
    >>> plane_through([0.0, 0, 0, 1], [1.0, 0, 0, 1], [[0.0, 1, 0, 1], [2, 0, 0, 1]], degenerate="mask")
    (array([[ 0.,  0.,  1.,  0.],
           [nan, nan, nan, nan]]), array([ True, False]))
    """
    what = "are collinear points (every 3×3 minor is zero), through which no single plane passes"
    inputs = [(p, 4, "p"), (q, 4, "q"), (r, 4, "r")]
    return _minors("plane_through", inputs, out, axis, nonfinite, degenerate, CollinearPointsError, what)


def point_on_planes(
    a: Any, b: Any, c: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise",
) -> Any:
    """The points where triples of planes of P³ meet: :class:`~pgsym.errors.DependentPlanesError` for planes
    through one line (all minors exactly zero), or NaN rows and a mask as in :func:`plane_through`.

    >>> point_on_planes([1.0, 0, 0, -1], [0.0, 1, 0, -2], [0.0, 0, 1, -3])   # (1, 2, 3), up to scale
    array([-1., -2., -3., -1.])
    """
    what = "are planes through one line (every 3×3 minor is zero), which meet in no single point"
    inputs = [(a, 4, "a"), (b, 4, "b"), (c, 4, "c")]
    return _minors("point_on_planes", inputs, out, axis, nonfinite, degenerate, DependentPlanesError, what)
