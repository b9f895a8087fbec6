"""Parallels and midpoints on float64 arrays: the numeric twin of :mod:`pgsym.affine`.

Arrays have shape ``(..., k)`` (or ``(k, ...)`` with ``axis=0``) and broadcast, as everywhere in
:mod:`pgsym.numeric`: ``k = 3`` for points and lines of P², ``4`` for points and planes of space,
``6`` for lines of space (Plücker coordinates, :func:`is_parallel` only). The formulas are the
exact ones, so small integer data give the same numbers as the exact core. The policy of
:mod:`pgsym.numeric` holds: NaN or ±inf raise :class:`~pgsym.errors.NonFiniteError`
(``nonfinite="mask"``), a line or plane at infinity (it has no direction) and an ideal point where
a finite one is needed raise :class:`~pgsym.errors.IdealPointError` (``ideal="mask"``), and input
that fixes no unique answer raises its named error (``degenerate="mask"``). Products that under- or
overflow float64 (entries near 1e±200) are recomputed after scaling by powers of two.

>>> parallel_line([1.0, 2, 0], [[0.0, 1, 1], [1, 0, 0]])   # x + 2y = 2, and l∞ through an ideal point
array([[ 1.,  2., -2.],
       [ 0.,  0., -1.]])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import CoincidentPointsError, DegenerateConfigurationError
from ._arrays import DEGENERATE, check_option
from .euclid import (
    PART,
    add_square,
    check_options,
    either_point_ideal,
    euclid_arrays,
    flag_unsafe,
    resolve,
    run,
    scaled,
)
from .tolerances import INCIDENT_RTOL

__all__ = ["is_parallel", "midpoint", "parallel_line"]


# -- parallel_line ------------------------------------------------------------------------------------
def _parallel_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    h, x = ins
    t, s = ws
    k = x.shape[-1]
    last = o[..., k - 1]
    for i in range(k - 1):  # (w n, −n·x): the join of x with the ideal point of h, or the plane of normal n
        np.multiply(h[..., i], x[..., k - 1], out=o[..., i])
        if i == 0:
            np.multiply(h[..., 0], x[..., 0], out=last)
        else:
            np.multiply(h[..., i], x[..., i], out=t)
            np.add(last, t, out=last)
    np.negative(last, out=last)
    np.multiply(o[..., 0], o[..., 0], out=s)  # 0 for a target at infinity and for degenerate rows: looked at again
    for i in range(1, k):
        np.multiply(o[..., i], o[..., i], out=t)
        np.add(s, t, out=s)
    flag_unsafe(s, o)


def _parallel_formula(rows: list[np.ndarray]) -> np.ndarray:
    h, x = (scaled(r) for r in rows)  # exact: powers of two keep the products' zeros
    out = np.empty_like(x)
    out[:, :-1] = h[:, :-1] * x[:, -1:]
    out[:, -1] = -np.einsum("ij,ij->i", h[:, :-1], x[:, :-1])
    return out


def _parallel_robust(rows: list[np.ndarray]) -> np.ndarray:
    return scaled(_parallel_formula(rows))


def _target_at_infinity(rows: list[np.ndarray]) -> np.ndarray:
    return np.all(rows[0][:, :-1] == 0, axis=-1)


def _parallel_degenerate(rows: list[np.ndarray]) -> np.ndarray:
    with np.errstate(invalid="ignore", over="ignore"):  # rows with NaN are told apart by the caller
        return np.all(_parallel_formula(rows) == 0, axis=-1)


def parallel_line(
    target: Any,
    point: Any,
    *,
    ideal: str = "raise",
    nonfinite: str = "raise",
    degenerate: str = "raise",
    axis: int = -1,
    out: np.ndarray | None = None,
) -> Any:
    """The lines of P² (k = 3) or planes (k = 4) through ``point`` parallel to ``target``: ``(w n, −n·x)``.

    The numeric :func:`pgsym.affine.parallel_line`, homogeneous and right for any scale of the point
    ``(x, w)``. Through an ideal point the parallel is the line (plane) at infinity, unless the point is
    the target's own direction: then no parallel is singled out and the row raises
    :class:`~pgsym.errors.CoincidentPointsError` (a plane: :class:`~pgsym.errors.DegenerateConfigurationError`)
    or is masked with ``degenerate="mask"``. A target at infinity raises :class:`~pgsym.errors.IdealPointError`.

    >>> parallel_line([1.0, 2, 2, 7], [1.0, 0, 0, 1])               # x + 2y + 2z = 1
    array([ 1.,  2.,  2., -1.])
    """
    check_options(ideal, nonfinite, "parallel_line")
    check_option(degenerate, DEGENERATE, "degenerate", "parallel_line")
    arrays = euclid_arrays([(target, "target"), (point, "point")], axis, "parallel_line", (3, 4))
    k = arrays[0].shape[-1]
    result = run(_parallel_kernel, "parallel_line", [(target, k, "target"), (point, k, "point")], k, out, axis, 2)
    error = CoincidentPointsError if k == 3 else DegenerateConfigurationError
    checks = (degenerate, _parallel_degenerate, error, "are ideal points in the target's own direction")
    return resolve(
        result, arrays, "parallel_line", ideal, nonfinite, axis, _target_at_infinity, _parallel_robust, None, checks
    )


# -- is_parallel ---------------------------------------------------------------------------------------
def _sin2_kernel(part: tuple[int, ...]) -> Any:
    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        a, b = ins
        t, u, na, nb = ws
        for n, v in ((na, a), (nb, b)):
            np.multiply(v[..., part[0]], v[..., part[0]], out=n)
            for i in part[1:]:
                np.multiply(v[..., i], v[..., i], out=t)
                np.add(n, t, out=n)
        pairs = [(0, 1)] if len(part) == 2 else [(1, 2), (2, 0), (0, 1)]
        for j, (p, q) in enumerate(pairs):  # |n_a × n_b|², the signs of a direction cancel in the squares
            np.multiply(a[..., part[p]], b[..., part[q]], out=t)
            np.multiply(a[..., part[q]], b[..., part[p]], out=u)
            np.subtract(t, u, out=t)
            add_square(t, o, j == 0)
        np.multiply(na, nb, out=t)
        with np.errstate(divide="ignore"):  # an object at infinity: reported afterwards
            np.divide(o, t, out=o)
        flag_unsafe(na, o)
        flag_unsafe(nb, o)

    return kernel


def _sin2_robust(part: tuple[int, ...]) -> Any:
    def robust(rows: list[np.ndarray]) -> np.ndarray:
        a, b = (scaled(r[:, list(part)]) for r in rows)
        if len(part) == 2:
            c2 = (a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]) ** 2
        else:
            c = np.cross(a, b)
            c2 = np.einsum("ij,ij->i", c, c)
        return c2 / (np.einsum("ij,ij->i", a, a) * np.einsum("ij,ij->i", b, b))

    return robust


def is_parallel(
    a: Any, b: Any, *, rtol: float = INCIDENT_RTOL, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1
) -> Any:
    """True where ``|sin θ| ≤ rtol``: lines of P² (k = 3), planes (k = 4) or lines of space (k = 6, Plücker).

    The numeric :func:`pgsym.affine.is_parallel`: normals (directions) proportional, judged by the sine of
    their angle, ``|n_a × n_b| ≤ rtol |n_a| |n_b|``, so it is scale-free like
    :func:`~pgsym.numeric.is_perpendicular` (same default tolerance); ``rtol=0`` asks for an exact zero.
    Equal objects are parallel. An object at infinity raises :class:`~pgsym.errors.IdealPointError`.

    >>> is_parallel([1.0, 2, 3, 4], [[-2.0, -4, -6, 0], [0, 1, 0, 0]])
    array([ True, False])
    """
    check_options(ideal, nonfinite, "is_parallel")
    arrays = euclid_arrays([(a, "a"), (b, "b")], axis, "is_parallel", (3, 4, 6))
    k = arrays[0].shape[-1]
    part = PART[k]
    result = run(_sin2_kernel(part), "is_parallel", [(a, k, "a"), (b, k, "b")], None, None, axis, 4)

    def at_infinity(rows: list[np.ndarray]) -> np.ndarray:
        return np.logical_or.reduce([np.all(r[:, list(part)] == 0, axis=-1) for r in rows])

    values = resolve(result, arrays, "is_parallel", ideal, nonfinite, axis, at_infinity, _sin2_robust(part))
    if isinstance(values, tuple):
        s2, ok = values
        return np.asarray(np.nan_to_num(s2, nan=1.0) <= rtol * rtol) & ok, ok
    return np.asarray(values <= rtol * rtol)


# -- midpoint ------------------------------------------------------------------------------------------
def _midpoint_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    x, y = ins
    (t,) = ws
    k = x.shape[-1]
    v, w = y[..., k - 1], x[..., k - 1]
    for i in range(k - 1):  # v x + w y over 2 v w: no division, right for any representatives
        np.multiply(v, x[..., i], out=o[..., i])
        np.multiply(w, y[..., i], out=t)
        np.add(o[..., i], t, out=o[..., i])
    last = o[..., k - 1]
    np.multiply(v, w, out=last)
    np.add(last, last, out=last)
    np.multiply(last, last, out=t)  # 0 for an ideal point (and an underflow): looked at again
    flag_unsafe(t, o)


def _midpoint_robust(rows: list[np.ndarray]) -> np.ndarray:
    x, y = (scaled(r) for r in rows)
    v, w = y[:, -1:], x[:, -1:]
    out = np.empty_like(x)
    out[:, :-1] = v * x[:, :-1] + w * y[:, :-1]
    out[:, -1:] = 2 * v * w
    return scaled(out)


def midpoint(
    a: Any, b: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1, out: np.ndarray | None = None
) -> Any:
    """Midpoints of finite points of P² (k = 3) or of space (k = 4): ``(v x + w y, 2 v w)``, homogeneous.

    The numeric :func:`pgsym.affine.midpoint` for ``a = (x, w)`` and ``b = (y, v)``: right for any
    homogeneous scale of either point. Ideal points raise :class:`~pgsym.errors.IdealPointError`
    (or are masked with ``ideal="mask"``).

    >>> midpoint([0.0, 0, 0, 1], [2.0, 4, 6, 2])                      # (1/2, 1, 3/2)
    array([2., 4., 6., 4.])
    """
    check_options(ideal, nonfinite, "midpoint")
    arrays = euclid_arrays([(a, "a"), (b, "b")], axis, "midpoint", (3, 4))
    k = arrays[0].shape[-1]
    result = run(_midpoint_kernel, "midpoint", [(a, k, "a"), (b, k, "b")], k, out, axis, 1)
    return resolve(result, arrays, "midpoint", ideal, nonfinite, axis, either_point_ideal, _midpoint_robust)
