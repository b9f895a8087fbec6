"""Conics and quadrics on float64 arrays: the value of the form, polars and tangents, in batches.

The numeric twin of :meth:`pgsym.conics.Conic.value`, :meth:`~pgsym.conics.Conic.polar`,
:meth:`~pgsym.conics.Conic.tangent_at` and :meth:`pgsym.quadrics.Quadric.polar`,
:meth:`~pgsym.quadrics.Quadric.tangent_plane`: a symmetric form ``C`` (a ``k×k`` matrix, ``k = 3`` for
conics, 4 for quadrics) takes a point ``x`` to the number ``xᵀ C x`` and to the polar ``C x``, which is
the tangent at a point of the conic or quadric. Forms have shape ``(..., k, k)`` and points
``(..., k)``; the batch axes broadcast, so one form serves a million points (the common case, computed
block by block with one BLAS product per block), or one point a million forms. With ``axis=0`` the
points are component-major ``(k, N)`` and the forms ``(k, k, N)``.

The degeneracy policy of :mod:`pgsym.numeric` holds: ``C x = 0`` (a vertex of a degenerate form)
raises :class:`~pgsym.errors.DegenerateConicError`; a point off the conic or quadric has no tangent
(:class:`~pgsym.errors.NotOnConicError`, :class:`~pgsym.errors.NotOnQuadricError`), where "on" means
``|xᵀ C x| ≤ rtol |x| |C x|`` — the point is incident with its polar, as :func:`pgsym.numeric.incident`
decides. ``degenerate="mask"`` gives NaN rows and a mask instead. These kernels take real arrays only.

>>> import numpy as np
>>> sphere = np.diag([1.0, 1, 1, -1])                    # x² + y² + z² = 1
>>> tangent_plane(sphere, [[1.0, 0, 0, 1], [0, 0.6, 0.8, 1]])
array([[ 1. ,  0. ,  0. , -1. ],
       [ 0. ,  0.6,  0.8, -1. ]])
>>> form_value(np.diag([1.0, 1, -1]), [[3.0, 4, 5], [1, 1, 1]])   # the unit circle: 9 + 16 − 25, 1 + 1 − 1
array([0., 1.])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import DegenerateConicError, DimensionError, NotOnConicError, NotOnQuadricError
from ._arrays import (
    CHUNK,
    DEGENERATE,
    NONFINITE,
    as_float_array,
    block_finite,
    check_option,
    construction,
    degenerate_result,
    finite_and_no_zero_row,
    nonfinite_result,
    rowwise,
)
from .tolerances import INCIDENT_RTOL

__all__ = ["form_value", "polar", "tangent_at", "tangent_plane"]


def _inputs(forms: Any, points: Any, axis: int, function: str, sizes: tuple[int, ...]) -> tuple[list, int]:
    """The rowwise inputs: each form flattened to ``k²`` entries on the component axis, and the points."""
    x = as_float_array(points, "points", function)
    if x.ndim == 0 or not -x.ndim <= axis < x.ndim or x.shape[axis] not in sizes:
        wanted = " or ".join(map(str, sizes))
        raise DimensionError(
            f"{function}: points need {wanted} homogeneous coordinates along axis {axis}, got shape {x.shape}"
        )
    k = x.shape[axis]
    q = as_float_array(forms, "forms", function)
    if axis in (-1, x.ndim - 1):
        if q.ndim < 2 or q.shape[-2:] != (k, k):
            raise DimensionError(f"{function}: forms must be {k}×{k} matrices (shape (..., {k}, {k})), got {q.shape}")
        flat = q.reshape(*q.shape[:-2], k * k)
        return [(flat, k * k, "forms"), (x, k, "points")], k
    if axis != 0 or q.ndim < 2 or q.shape[:2] != (k, k):
        raise DimensionError(
            f"{function}: with axis={axis} the forms must be component-major ({k}, {k}, ...), got shape {q.shape}"
        )
    return [(q.reshape(k * k, *q.shape[2:]), k * k, "forms"), (x, k, "points")], k


_BLOCK = 8 * CHUNK  # rows a block of the one-form path: a BLAS product amortises its call over more rows


def _one_form(forms: Any, points: Any, axis: int, function: str) -> tuple[np.ndarray, np.ndarray] | None:
    """``(C, x)`` when there is one form and a C-contiguous ``(N, k)`` batch of points: one BLAS product serves."""
    if axis != -1 or not isinstance(points, np.ndarray) or points.ndim != 2 or not points.flags.c_contiguous:
        return None
    q = as_float_array(forms, "forms", function)
    k = points.shape[1]
    if q.shape != (k, k) or points.dtype != np.float64 or k not in (3, 4):
        return None
    return q, points


def _blocked_product(q: np.ndarray, x: np.ndarray) -> tuple[np.ndarray, bool]:
    """``x @ qᵀ`` block by block, each block checked while in cache: True when every row is finite and nonzero."""
    n = x.shape[0]
    result = np.empty(x.shape)
    qt = np.ascontiguousarray(q.T)
    clean = True
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):  # reported by name by the caller
        for start in range(0, n, _BLOCK):
            block = result[start : start + _BLOCK]
            np.matmul(x[start : start + _BLOCK], qt, out=block)
            if clean and not finite_and_no_zero_row(block):
                clean = False
    return result, clean


def _checked(result: np.ndarray, function: str, nonfinite: str, inputs: list[np.ndarray]) -> Any:
    """The policy on a result computed in one call: one dot product decides the common, finite case."""
    check_option(nonfinite, NONFINITE, "nonfinite", function)
    with np.errstate(over="ignore"):  # squares beyond 1e308 are a false alarm that the full test clears
        finite_sum = block_finite(result)
    if finite_sum:
        return (result, np.ones(result.shape[0], bool)) if nonfinite == "mask" else result
    finite = np.isfinite(result) if result.ndim == 1 else np.isfinite(result).all(axis=-1)
    return nonfinite_result(result, finite, nonfinite, function, [np.atleast_2d(a) for a in inputs])


def _single(q: np.ndarray) -> bool:
    """True when every row of the block is one and the same form (a broadcast of a single matrix)."""
    return q.shape[0] <= 1 or q.strides[0] == 0


def _polar_kernel(k: int) -> Any:
    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        q, x = ins
        if _single(q) and x.ndim == 2 and o.ndim == 2:
            np.matmul(x, q[0].reshape(k, k).T, out=o)  # one BLAS product for the block: o = (C x)ᵀ
            return
        t = ws[0]
        for i in range(k):
            oi = o[..., i]
            np.multiply(q[..., i * k], x[..., 0], out=oi)
            for j in range(1, k):
                np.multiply(q[..., i * k + j], x[..., j], out=t)
                np.add(oi, t, out=oi)

    return kernel


def _value_kernel(k: int) -> Any:
    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        q, x = ins
        if _single(q) and x.ndim == 2:
            y = x @ q[0].reshape(k, k)  # xᵀ C, then the row-wise dot product with x
            np.einsum("ij,ij->i", y, x, out=o)
            return
        t, s = ws
        o[...] = 0
        for i in range(k):
            np.multiply(q[..., i * k], x[..., 0], out=s)
            for j in range(1, k):
                np.multiply(q[..., i * k + j], x[..., j], out=t)
                np.add(s, t, out=s)
            np.multiply(s, x[..., i], out=s)
            np.add(o, s, out=o)

    return kernel


def form_value(forms: Any, points: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise"
               ) -> Any:
    """The values ``xᵀ C x`` of conics (3×3) or quadrics (4×4) at points (the numeric :meth:`pgsym.conics.Conic.value`).

    Zero exactly on the conic or quadric; its sign tells the two sides of a real non-degenerate one
    apart (for a fixed representative ``C``).

    >>> form_value(np.diag([1.0, 1, 1, -4]), [[2.0, 0, 0, 1], [0, 0, 0, 1]])   # the sphere of radius 2
    array([ 0., -4.])
    """
    one = _one_form(forms, points, axis, "form_value") if out is None else None
    if one is not None:
        q, x = one
        with np.errstate(over="ignore", invalid="ignore"):  # reported by name in _checked
            value = np.einsum("ij,ij->i", x @ q, x)
        return _checked(value, "form_value", nonfinite, [q.reshape(-1), x])
    inputs, k = _inputs(forms, points, axis, "form_value", (3, 4))
    return rowwise(_value_kernel(k), "form_value", inputs, None, out, axis, 2, nonfinite)


def polar(
    forms: Any, points: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise",
) -> Any:
    """The polars ``C x`` of points: lines for conics (3×3), planes for quadrics (4×4).

    The numeric :meth:`pgsym.conics.Conic.polar` and :meth:`pgsym.quadrics.Quadric.polar`. A vertex of a
    degenerate form (``C x = 0``) raises :class:`~pgsym.errors.DegenerateConicError`, or gives a NaN row and
    a mask with ``degenerate="mask"``.

    >>> polar(np.diag([1.0, 1, -1]), [2.0, 0, 1])            # the unit circle's polar of (2, 0): x = 1/2
    array([ 2.,  0., -1.])
    >>> polar(np.diag([1.0, 0, 0]), [[0.0, 1, 0], [1, 0, 0]], degenerate="mask")   # x² = 0: a double line
    (array([[nan, nan, nan],
           [ 1.,  0.,  0.]]), array([False,  True]))
    """
    check_option(degenerate, DEGENERATE, "degenerate", "polar")
    what = "are vertices of their degenerate form (C x = 0), which have no polar"
    return _polars("polar", forms, points, out, axis, nonfinite, degenerate, what)


def _polars(function: str, forms: Any, points: Any, out: Any, axis: int, nonfinite: str, degenerate: str,
            what: str, sizes: tuple[int, ...] = (3, 4)) -> Any:
    """``C x`` under both policies: one BLAS product for one form and a plain batch, else block by block."""
    one = _one_form(forms, points, axis, function) if out is None else None
    if one is not None and one[1].shape[1] in sizes:
        q, x = one
        product, clean = _blocked_product(q, x)
        if clean and nonfinite == "raise" and degenerate == "raise":
            return product
        value = _checked(product, function, nonfinite, [q.reshape(-1), x])
        return degenerate_result(value, degenerate, -1, function, DegenerateConicError, what)
    inputs, k = _inputs(forms, points, axis, function, sizes)
    return construction(_polar_kernel(k), function, inputs, k, out, axis, 1, nonfinite, degenerate,
                        DegenerateConicError, what)


def _tangent(
    function: str, k: int, error: type[Exception], forms: Any, points: Any, out: Any, axis: int, nonfinite: str,
    degenerate: str, rtol: float,
) -> Any:
    check_option(degenerate, DEGENERATE, "degenerate", function)
    what = "are vertices of their degenerate form (C x = 0), with no tangent"
    value = _polars(function, forms, points, out, axis, nonfinite, degenerate, what, (k,))
    values, ok = value if isinstance(value, tuple) else (value, None)
    planes = np.moveaxis(values, axis, -1)
    x = np.broadcast_to(np.moveaxis(as_float_array(points, "points", function), axis, -1), planes.shape)
    off = _off(x, planes, rtol)
    if off.any():
        if degenerate == "raise":
            first = tuple(int(i) for i in np.argwhere(off)[0]) if off.ndim else ()
            kind = "conic" if k == 3 else "quadric"
            raise error(
                f"{function}: {int(off.sum())} of the {off.size} points are not on their {kind} "
                f"(|xᵀ C x| > rtol |x| |C x|, rtol = {rtol:g}), the first at index {first}: "
                f"{x[first].tolist()}; use polar() for the polar of a point off the {kind}, "
                "or pass degenerate='mask'"
            )
        planes[off] = np.nan
        ok = ~off if ok is None else ok & ~off
    return (values, np.asarray(ok)) if ok is not None else values


def _off(x: np.ndarray, planes: np.ndarray, rtol: float) -> np.ndarray:
    """Rows where ``x`` is not on its own polar: ``(x · Cx)² > rtol² |x|² |Cx|²`` (so x is off the form).

    Squares beyond float64's safe range (overflow, underflow) are recomputed on the rows scaled by powers of two.
    NaN rows (masked already) compare False.
    """
    if x.ndim == 2 and x.shape[0] > _BLOCK:  # block by block, in cache
        return np.concatenate([_off(x[s : s + _BLOCK], planes[s : s + _BLOCK], rtol) for s in range(0, len(x), _BLOCK)])
    with np.errstate(invalid="ignore", over="ignore", under="ignore"):
        ones = np.ones(x.shape[-1])  # row sums as a matrix–vector product: faster than einsum over 3 or 4 entries
        dot = np.dot(x * planes, ones)
        xx = np.dot(x * x, ones)
        pp = np.dot(planes * planes, ones)
        off = dot * dot > (rtol * rtol) * (xx * pp)
        lo, hi = 2.0**-480, 2.0**480
        safe = xx.size == 0 or (xx.min() > lo and xx.max() < hi and pp.min() > lo and pp.max() < hi)  # NaN: not safe
        unsafe = None if safe else ~((xx > lo) & (xx < hi) & (pp > lo) & (pp < hi)) & ~np.isnan(pp)
        if unsafe is not None and unsafe.any():
            xs, ps = x[unsafe], planes[unsafe]
            xs = xs * np.ldexp(1.0, -np.frexp(np.max(np.abs(xs), axis=-1, keepdims=True))[1])
            big = np.max(np.abs(ps), axis=-1, keepdims=True)
            ps = ps * np.ldexp(1.0, -np.frexp(np.where(big > 0, big, 1.0))[1])
            d = np.einsum("...i,...i->...", xs, ps)
            norms = np.einsum("...i,...i->...", xs, xs) * np.einsum("...i,...i->...", ps, ps)
            off[unsafe] = d * d > (rtol * rtol) * norms
    return off


def tangent_at(
    conics: Any, points: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise", rtol: float = INCIDENT_RTOL,
) -> Any:
    """The tangent lines ``C x`` of conics at their points (the numeric :meth:`pgsym.conics.Conic.tangent_at`).

    A point off its conic raises :class:`~pgsym.errors.NotOnConicError`, a vertex
    :class:`~pgsym.errors.DegenerateConicError`; ``degenerate="mask"`` masks both.

    >>> tangent_at(np.diag([1.0, 1, -25]), [[3.0, 4, 1], [5, 0, 1]])       # the circle of radius 5
    array([[  3.,   4., -25.],
           [  5.,   0., -25.]])
    """
    return _tangent("tangent_at", 3, NotOnConicError, conics, points, out, axis, nonfinite, degenerate, rtol)


def tangent_plane(
    quadrics: Any, points: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise", rtol: float = INCIDENT_RTOL,
) -> Any:
    """The tangent planes ``Q X`` of quadrics at points on them (numeric :meth:`pgsym.quadrics.Quadric.tangent_plane`).

    A point off its quadric raises :class:`~pgsym.errors.NotOnQuadricError`, a vertex (of a cone, say)
    :class:`~pgsym.errors.DegenerateConicError`; ``degenerate="mask"`` masks both.

    >>> cone = np.diag([1.0, 1, -1, 0])                       # x² + y² = z², vertex at the origin
    >>> tangent_plane(cone, [[3.0, 4, 5, 1], [0, 0, 0, 1], [1, 0, 0, 1]], degenerate="mask")
    (array([[ 3.,  4., -5.,  0.],
           [nan, nan, nan, nan],
           [nan, nan, nan, nan]]), array([ True, False, False]))
    """
    return _tangent("tangent_plane", 4, NotOnQuadricError, quadrics, points, out, axis, nonfinite, degenerate, rtol)
