"""Angles, perpendicularity, distances, feet of perpendiculars and reflections on float64 arrays.

The numeric twin of :mod:`pgsym.metric`, with the same formulas in the absolute
(``C*∞ = diag(1, 1, 0)`` for lines of P², ``Q*∞ = diag(1, 1, 1, 0)`` for planes, ``Ω∞`` on the
directions of lines of space). Arrays have shape ``(..., k)`` (or ``(k, ...)`` with ``axis=0``) and
broadcast; the kind of object follows from ``k`` where it can: 3 for points and lines of P², 4 for
points and planes of space, 6 for lines of space (Plücker coordinates in pgsym's order). Arrays
carry no type, so the distances have one name per pair of kinds.

The policy of :mod:`pgsym.numeric` holds: NaN or ±inf inputs raise
:class:`~pgsym.errors.NonFiniteError` (or are masked with ``nonfinite="mask"``), and ideal elements
(an ideal point, the line or plane at infinity, a line at infinity) raise
:class:`~pgsym.errors.IdealPointError` (or are masked with ``ideal="mask"``). With either mask the
result is ``(values, ok)``: ``ok`` is False, and the values NaN (False for booleans), on the
rows that are masked. The fast formula runs first; only rows whose result is not finite are looked
at again, to tell an ideal element and a bad input from an intermediate overflow, which is
recomputed after scaling by powers of two.

>>> import numpy as np
>>> cos_angle([0.0, 1, 0], [[1.0, -1, 0], [1, 0, 5]])          # y = 0 against y = x and x = −5
array([-0.70710678,  0.        ])
>>> point_line_distance([[0.0, 0, 1], [1, 1, 0]], [1.0, 1, -2], ideal="mask")
(array([1.41421356,        nan]), array([ True, False]))
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from ..errors import CoincidentLinesError, CoincidentPointsError
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

__all__ = [
    "angle_bisectors",
    "cos_angle",
    "cos_squared_angle",
    "is_perpendicular",
    "orthogonal_projection",
    "perpendicular_line",
    "point_distance",
    "point_line_distance",
    "point_plane_distance",
    "reflect",
    "signed_angle",
    "sin_angle",
]

# -- angles -----------------------------------------------------------------------------------------
def _cos_kernel(part: tuple[int, ...]) -> Callable[[list[np.ndarray], np.ndarray, list[np.ndarray]], None]:
    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        a, b = ins
        t, na, nb = ws
        first = True
        for i in part:
            ai, bi = a[..., i], b[..., i]
            if first:
                np.multiply(ai, bi, out=o)
                np.multiply(ai, ai, out=na)
                np.multiply(bi, bi, out=nb)
                first = False
                continue
            np.multiply(ai, bi, out=t)
            np.add(o, t, out=o)
            np.multiply(ai, ai, out=t)
            np.add(na, t, out=na)
            np.multiply(bi, bi, out=t)
            np.add(nb, t, out=nb)
        np.multiply(na, nb, out=na)
        np.sqrt(na, out=t)
        with np.errstate(divide="ignore"):  # a line at infinity: reported as ideal afterwards
            np.divide(o, t, out=o)
        flag_unsafe(na, o)

    return kernel


def _cos_rows(part: tuple[int, ...]) -> Callable[[list[np.ndarray]], np.ndarray]:
    def robust(rows: list[np.ndarray]) -> np.ndarray:
        a, b = (scaled(r[:, list(part)]) for r in rows)
        return np.einsum("ij,ij->i", a, b) / np.sqrt(np.einsum("ij,ij->i", a, a) * np.einsum("ij,ij->i", b, b))

    return robust


def _no_part(part: tuple[int, ...]) -> Callable[[list[np.ndarray]], np.ndarray]:
    return lambda rows: np.logical_or.reduce([np.all(r[:, list(part)] == 0, axis=-1) for r in rows])


def cos_angle(
    a: Any, b: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1, out: np.ndarray | None = None
) -> Any:
    """``cos θ = aᵀAb / √((aᵀAa)(bᵀAb))`` for broadcast arrays of oriented lines of P² (k = 3), planes
    (k = 4, ``A = Q*∞``) or lines of space (k = 6, their directions): the numeric :func:`pgsym.metric.cos_angle`.

    >>> cos_angle([1.0, 0, 0, 0], [1.0, 1, 1, 1])                   # planes: 1 / √3
    np.float64(0.5773502691896258)
    >>> cos_angle([0.0, 0, 1], [1.0, 0, 0])   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.IdealPointError: cos_angle: 1 of the 1 rows hold an ideal element...
    """
    check_options(ideal, nonfinite, "cos_angle")
    arrays = euclid_arrays([(a, "a"), (b, "b")], axis, "cos_angle", (3, 4, 6))
    part = PART[arrays[0].shape[-1]]
    k = arrays[0].shape[-1]
    result = run(_cos_kernel(part), "cos_angle", [(a, k, "a"), (b, k, "b")], None, out, axis, 3)
    values = resolve(result, arrays, "cos_angle", ideal, nonfinite, axis, _no_part(part), _cos_rows(part))
    if not isinstance(values, tuple) and values.ndim == 0:
        return values[()]
    return values


def cos_squared_angle(a: Any, b: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1) -> Any:
    """``cos² θ``, independent of the orientation of either object: the numeric :func:`pgsym.metric.cos_squared_angle`.

    Lines of P² (k = 3), planes (k = 4) or lines of space (k = 6), with the policy of :func:`cos_angle`.

    >>> cos_squared_angle([1.0, 0, 0], [[1.0, 1, 5], [-1, 0, 2]])   # 45°, and the same line reversed
    array([0.5, 1. ])
    """
    result = cos_angle(a, b, ideal=ideal, nonfinite=nonfinite, axis=axis)
    if isinstance(result, tuple):
        return result[0] * result[0], result[1]
    return result * result


def is_perpendicular(
    a: Any, b: Any, *, rtol: float = INCIDENT_RTOL, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1
) -> Any:
    """True where ``|cos θ| ≤ rtol``: lines of P² (k = 3), planes (k = 4) or lines of space (k = 6).

    The test is on a cosine, so it is scale-free, as :func:`pgsym.numeric.incident` is (same default
    tolerance, :data:`~pgsym.numeric.tolerances.INCIDENT_RTOL`); ``rtol=0`` asks for an exact zero.

    >>> is_perpendicular([1.0, 2, 3], [[2.0, -1, 7], [1, 1, 0]])
    array([ True, False])
    """
    result = cos_angle(a, b, ideal=ideal, nonfinite=nonfinite, axis=axis)
    if isinstance(result, tuple):
        c, ok = result
        return np.asarray(np.abs(np.nan_to_num(c, nan=1.0)) <= rtol) & ok, ok
    return np.asarray(np.abs(result) <= rtol)


# -- distances --------------------------------------------------------------------------------------
def _incidence_and_normal(x: np.ndarray, h: np.ndarray, dot: np.ndarray, nn: np.ndarray, t: np.ndarray) -> None:
    """In place: ``dot = hᵀx`` over all k entries, and ``nn = |n|²`` for the normal ``n`` of h (its first k − 1)."""
    k = x.shape[-1]
    np.multiply(x[..., 0], h[..., 0], out=dot)
    np.multiply(h[..., 0], h[..., 0], out=nn)
    for i in range(1, k):
        np.multiply(x[..., i], h[..., i], out=t)
        np.add(dot, t, out=dot)
        if i < k - 1:
            np.multiply(h[..., i], h[..., i], out=t)
            np.add(nn, t, out=nn)


def _hyper_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    x, h = ins
    t, nn = ws
    k = x.shape[-1]
    _incidence_and_normal(x, h, o, nn, t)
    np.sqrt(nn, out=t)
    np.multiply(t, x[..., k - 1], out=t)
    with np.errstate(divide="ignore"):  # an ideal point or a line at infinity: reported afterwards
        np.divide(o, t, out=o)
    np.abs(o, out=o)
    flag_unsafe(nn, o)


def _hyper_rows(rows: list[np.ndarray]) -> np.ndarray:
    x, h = (scaled(r) for r in rows)
    n = h[:, :-1]
    return np.abs(np.einsum("ij,ij->i", x, h)) / (np.sqrt(np.einsum("ij,ij->i", n, n)) * np.abs(x[:, -1]))


def _hyper_ideal(rows: list[np.ndarray]) -> np.ndarray:
    x, h = rows
    return (x[:, -1] == 0) | np.all(h[:, :-1] == 0, axis=-1)


def _point_hyperplane(x: Any, h: Any, k: int, function: str, ideal: str, nonfinite: str, axis: int) -> Any:
    check_options(ideal, nonfinite, function)
    arrays = euclid_arrays([(x, "x"), (h, "h")], axis, function, (k,))
    result = run(_hyper_kernel, function, [(x, k, "x"), (h, k, "h")], None, None, axis, 2)
    values = resolve(result, arrays, function, ideal, nonfinite, axis, _hyper_ideal, _hyper_rows)
    return values[()] if not isinstance(values, tuple) and values.ndim == 0 else values


def point_line_distance(x: Any, l: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1) -> Any:
    """``|lᵀx| / (√(l1² + l2²) |x3|)``: distances of points of P² from lines (numeric :func:`pgsym.metric.distance`).

    >>> point_line_distance([1.0, 2, 1], [3.0, 4, 0])               # (3 + 8) / 5
    np.float64(2.2)
    """
    return _point_hyperplane(x, l, 3, "point_line_distance", ideal, nonfinite, axis)


def point_plane_distance(x: Any, p: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1) -> Any:
    """``|πᵀX| / (|n| |x4|)``: distances of points of space from planes with normals ``n``.

    >>> point_plane_distance([[1.0, 2, 3, 1], [0, 0, 0, 1]], [0.0, 0, 2, 0])
    array([3., 0.])
    """
    return _point_hyperplane(x, p, 4, "point_plane_distance", ideal, nonfinite, axis)


def _point_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    x, y = ins
    t, u, rx, ry = ws
    k = x.shape[-1]
    with np.errstate(divide="ignore"):  # ideal points: reported afterwards
        np.reciprocal(x[..., k - 1], out=rx)
        np.reciprocal(y[..., k - 1], out=ry)
    for i in range(k - 1):
        np.multiply(x[..., i], rx, out=t)
        np.multiply(y[..., i], ry, out=u)
        np.subtract(t, u, out=t)
        add_square(t, o, i == 0)
    np.sqrt(o, out=o)


def point_distance(x: Any, y: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1) -> Any:
    """Euclidean distances between broadcast arrays of points of P² (k = 3) or of space (k = 4).

    >>> point_distance([[3.0, 4, 1], [2, 2, 2]], [0.0, 0, 1])
    array([5.        , 1.41421356])
    """
    check_options(ideal, nonfinite, "point_distance")
    arrays = euclid_arrays([(x, "x"), (y, "y")], axis, "point_distance", (3, 4))
    k = arrays[0].shape[-1]
    result = run(_point_kernel, "point_distance", [(x, k, "x"), (y, k, "y")], None, None, axis, 4)
    values = resolve(result, arrays, "point_distance", ideal, nonfinite, axis, either_point_ideal, _robust_point)
    return values[()] if not isinstance(values, tuple) and values.ndim == 0 else values


def _robust_point(rows: list[np.ndarray]) -> np.ndarray:
    x, y = rows
    d = x[:, :-1] / x[:, -1:] - y[:, :-1] / y[:, -1:]
    return np.hypot.reduce(d, axis=-1)


# -- feet of perpendiculars and reflections ----------------------------------------------------------
def _foot_kernel(factor: float) -> Callable[[list[np.ndarray], np.ndarray, list[np.ndarray]], None]:
    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        x, h = ins
        t, s, d = ws
        k = x.shape[-1]
        _incidence_and_normal(x, h, d, s, t)
        if factor != 1.0:
            np.multiply(d, factor, out=d)
        for i in range(k - 1):  # s x_i − factor (h·x) n_i
            oi = o[..., i]
            np.multiply(s, x[..., i], out=oi)
            np.multiply(d, h[..., i], out=t)
            np.subtract(oi, t, out=oi)
        np.multiply(s, x[..., k - 1], out=o[..., k - 1])
        flag_unsafe(s, o)

    return kernel


def _foot_rows(factor: float) -> Callable[[list[np.ndarray]], np.ndarray]:
    def robust(rows: list[np.ndarray]) -> np.ndarray:
        x, h = (scaled(r) for r in rows)
        n = h[:, :-1]
        s = np.einsum("ij,ij->i", n, n)[:, None]
        d = factor * np.einsum("ij,ij->i", x, h)[:, None]
        out = s * x
        out[:, :-1] -= d * n
        return scaled(out)

    return robust


def orthogonal_projection(
    x: Any, h: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1, out: np.ndarray | None = None
) -> Any:
    """Feet of the perpendiculars from points onto lines of P² (k = 3) or planes (k = 4), homogeneous.

    ``s x − (hᵀx)(n, 0)`` with ``n`` the normal and ``s = n·n``, the formula of
    :func:`pgsym.metric.orthogonal_projection` (the same numbers on integer data). Ideal points and
    the line or plane at infinity raise :class:`~pgsym.errors.IdealPointError` (or are masked).

    >>> orthogonal_projection([2.0, 0, 1], [1.0, -1, 0])               # onto y = x: (2, 2, 2)
    array([2., 2., 2.])
    """
    check_options(ideal, nonfinite, "orthogonal_projection")
    arrays = euclid_arrays([(x, "x"), (h, "h")], axis, "orthogonal_projection", (3, 4))
    k = arrays[0].shape[-1]
    ins = [(x, k, "x"), (h, k, "h")]
    result = run(_foot_kernel(1.0), "orthogonal_projection", ins, k, out, axis, 3)
    last = np.moveaxis(result[0], axis, -1)[..., -1]
    return resolve(
        result, arrays, "orthogonal_projection", ideal, nonfinite, axis, _hyper_ideal, _foot_rows(1.0), last == 0
    )


def reflect(
    x: Any,
    mirror: Any,
    *,
    ideal: str = "raise",
    nonfinite: str = "raise",
    axis: int = -1,
    out: np.ndarray | None = None,
) -> Any:
    """Mirror images of points of P² in lines (k = 3), or of points of space in planes (k = 4), homogeneous.

    ``s x − 2 (mirrorᵀx)(n, 0)``, the matrix of :func:`pgsym.metric.reflection` applied to ``x``. Ideal
    points are reflected like any point (directions are mirrored); a mirror at infinity raises
    :class:`~pgsym.errors.IdealPointError` (or is masked).

    >>> reflect([[2.0, 5, 1], [1, 0, 0]], [1.0, -1, 0])               # in y = x
    array([[10.,  4.,  2.],
           [ 0.,  2.,  0.]])
    """
    check_options(ideal, nonfinite, "reflect")
    arrays = euclid_arrays([(x, "x"), (mirror, "mirror")], axis, "reflect", (3, 4))
    k = arrays[0].shape[-1]
    ins = [(x, k, "x"), (mirror, k, "mirror")]
    result = run(_foot_kernel(2.0), "reflect", ins, k, out, axis, 3)
    at_infinity = np.all(arrays[1][..., :-1] == 0, axis=-1)
    extra = np.broadcast_to(at_infinity, result[1].shape) if at_infinity.any() else None

    def mirror_ideal(rows: list[np.ndarray]) -> np.ndarray:
        return np.all(rows[1][:, :-1] == 0, axis=-1)

    return resolve(result, arrays, "reflect", ideal, nonfinite, axis, mirror_ideal, _foot_rows(2.0), extra)


# -- perpendiculars and bisectors of lines of P² ------------------------------------------------------
def _perpendicular_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    l, x = ins
    t, s = ws
    o0, o1, o2 = o[..., 0], o[..., 1], o[..., 2]
    np.multiply(x[..., 2], l[..., 1], out=o0)  # x × (l1, l2, 0) = (−x3 l2, x3 l1, x1 l2 − x2 l1)
    np.negative(o0, out=o0)
    np.multiply(x[..., 2], l[..., 0], out=o1)
    np.multiply(x[..., 0], l[..., 1], out=o2)
    np.multiply(x[..., 1], l[..., 0], out=t)
    np.subtract(o2, t, out=o2)
    # (o1, o2) = x3 (−l2, l1) is 0 exactly for an ideal point or the line at infinity, and tiny or huge when
    # the products under- or overflow: all are looked at again
    np.multiply(o0, o0, out=s)
    np.multiply(o1, o1, out=t)
    np.add(s, t, out=s)
    flag_unsafe(s, o)


def _perpendicular_rows(rows: list[np.ndarray]) -> np.ndarray:
    l, x = (scaled(r) for r in rows)
    normal = l.copy()
    normal[:, 2] = 0
    return scaled(np.cross(x, normal))


def _point_or_line_ideal(rows: list[np.ndarray]) -> np.ndarray:
    l, x = rows
    return (x[:, 2] == 0) | np.all(l[:, :2] == 0, axis=-1)


def perpendicular_line(
    line: Any, point: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1,
    out: np.ndarray | None = None,
) -> Any:
    """The lines through points of P² perpendicular to lines of P²: ``x × (l1, l2, 0)``, homogeneous.

    The join of the point with the ideal point of the normal, the formula of :func:`pgsym.metric.perpendicular_line`
    (the same numbers on integer data). An ideal point or the line at infinity raises
    :class:`~pgsym.errors.IdealPointError` (or is masked with ``ideal="mask"``).

    >>> perpendicular_line([1.0, -1, 0], [[2.0, 0, 1], [0, 0, 1]])   # to y = x: x + y = 2 and x + y = 0
    array([[ 1.,  1., -2.],
           [ 1.,  1., -0.]])
    """
    check_options(ideal, nonfinite, "perpendicular_line")
    arrays = euclid_arrays([(line, "line"), (point, "point")], axis, "perpendicular_line", (3,))
    ins = [(line, 3, "line"), (point, 3, "point")]
    result = run(_perpendicular_kernel, "perpendicular_line", ins, 3, out, axis, 2)
    return resolve(
        result, arrays, "perpendicular_line", ideal, nonfinite, axis, _point_or_line_ideal, _perpendicular_rows
    )


def _bisector_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    l, m = ins
    t, u, na, nb, d = ws
    np.multiply(l[..., 0], l[..., 0], out=na)
    np.multiply(l[..., 1], l[..., 1], out=t)
    np.add(na, t, out=na)
    np.multiply(m[..., 0], m[..., 0], out=nb)
    np.multiply(m[..., 1], m[..., 1], out=t)
    np.add(nb, t, out=nb)
    np.multiply(l[..., 0], m[..., 1], out=d)  # 0 for parallel (or equal) lines: looked at again
    np.multiply(l[..., 1], m[..., 0], out=t)
    np.subtract(d, t, out=d)
    with np.errstate(divide="ignore"):  # the line at infinity: reported afterwards
        np.sqrt(na, out=t)
        np.reciprocal(t, out=t)
        np.sqrt(nb, out=u)
        np.reciprocal(u, out=u)
    for i in range(3):  # l/|l| ± m/|m|
        np.multiply(l[..., i], t, out=o[..., i])
        np.multiply(m[..., i], u, out=o[..., 3 + i])
        np.subtract(o[..., i], o[..., 3 + i], out=o[..., 3 + i])
        np.add(o[..., i], o[..., i], out=o[..., i])
        np.subtract(o[..., i], o[..., 3 + i], out=o[..., i])
    flag_unsafe(na, o)
    flag_unsafe(nb, o)
    if not d.all():
        o[d == 0] = np.nan


def _bisector_rows(rows: list[np.ndarray]) -> np.ndarray:
    l, m = (scaled(r) for r in rows)
    u = l / np.hypot(l[:, 0], l[:, 1])[:, None]
    v = m / np.hypot(m[:, 0], m[:, 1])[:, None]
    out = np.concatenate([u + v, u - v], axis=-1)
    # parallel lines: the normals cancel in one of u ± v; rounding leaves a tiny normal there, which is 0
    parallel = l[:, 0] * m[:, 1] - l[:, 1] * m[:, 0] == 0
    if parallel.any():
        small_plus = np.hypot(out[:, 0], out[:, 1]) < np.hypot(out[:, 3], out[:, 4])
        out[parallel & small_plus, :2] = 0
        out[parallel & ~small_plus, 3:5] = 0
    return out


def _line_at_infinity(rows: list[np.ndarray]) -> np.ndarray:
    return np.logical_or.reduce([np.all(r[:, :2] == 0, axis=-1) for r in rows])


def _coincident(rows: list[np.ndarray]) -> np.ndarray:
    with np.errstate(invalid="ignore", over="ignore"):  # rows with NaN are told apart by the caller
        l, m = (scaled(r) for r in rows)  # exact: scaling by powers of two keeps the products' zeros
        return np.all(np.cross(l, m) == 0, axis=-1)


def angle_bisectors(
    l: Any, m: Any, *, ideal: str = "raise", nonfinite: str = "raise", degenerate: str = "raise", axis: int = -1
) -> Any:
    """The two bisectors ``l/|l| ± m/|m|`` of lines of P² (``|l| = √(l1² + l2²)``), as a pair of arrays.

    The numeric :func:`pgsym.metric.angle_bisectors`: the first halves the angle between the oriented
    normals given, the second is perpendicular to it; for parallel lines they are the midline and the line at
    infinity ``(0, 0, 1)`` (up to scale). The line at infinity raises :class:`~pgsym.errors.IdealPointError`
    (``ideal="mask"``); equal lines make no angle and raise :class:`~pgsym.errors.CoincidentLinesError`
    (``degenerate="mask"``). With a mask the result is ``((plus, minus), ok)``.

    >>> plus, minus = angle_bisectors([1.0, 0, 0], [3.0, 4, 0])     # (1, 0) ± (3, 4)/5
    >>> plus, minus
    (array([1.6, 0.8, 0. ]), array([ 0.4, -0.8,  0. ]))
    """
    check_options(ideal, nonfinite, "angle_bisectors")
    check_option(degenerate, DEGENERATE, "degenerate", "angle_bisectors")
    arrays = euclid_arrays([(l, "l"), (m, "m")], axis, "angle_bisectors", (3,))
    result = run(_bisector_kernel, "angle_bisectors", [(l, 3, "l"), (m, 3, "m")], 6, None, axis, 5)
    checks = (degenerate, _coincident, CoincidentLinesError, "are the same line, which makes no angle")
    values = resolve(
        result, arrays, "angle_bisectors", ideal, nonfinite, axis, _line_at_infinity, _bisector_rows, None, checks
    )
    if isinstance(values, tuple):
        plus, minus = np.split(values[0], 2, axis=axis)
        return (plus, minus), values[1]
    plus, minus = np.split(values, 2, axis=axis)
    return plus, minus


# -- signed angles ---------------------------------------------------------------------------------
def _sin_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    l, m = ins
    t, na, nb = ws
    np.multiply(l[..., 0], m[..., 1], out=o)
    np.multiply(l[..., 1], m[..., 0], out=t)
    np.subtract(o, t, out=o)
    for n, v in ((na, l), (nb, m)):
        np.multiply(v[..., 0], v[..., 0], out=n)
        np.multiply(v[..., 1], v[..., 1], out=t)
        np.add(n, t, out=n)
    np.multiply(na, nb, out=t)
    np.sqrt(t, out=t)
    with np.errstate(divide="ignore"):  # the line at infinity: reported afterwards
        np.divide(o, t, out=o)
    flag_unsafe(na, o)
    flag_unsafe(nb, o)


def _sin_rows(rows: list[np.ndarray]) -> np.ndarray:
    l, m = (scaled(r[:, :2]) for r in rows)
    return (l[:, 0] * m[:, 1] - l[:, 1] * m[:, 0]) / (np.hypot(l[:, 0], l[:, 1]) * np.hypot(m[:, 0], m[:, 1]))


def sin_angle(
    l: Any, m: Any, *, ideal: str = "raise", nonfinite: str = "raise", axis: int = -1, out: np.ndarray | None = None
) -> Any:
    """The signed ``sin θ = (l1 m2 − l2 m1) / (|l| |m|)`` of oriented lines of P² (:func:`pgsym.metric.sin_angle`).

    θ turns the normal of ``l`` counterclockwise onto the normal of ``m``, so that ``cos_angle + i sin_angle``
    is ``e^{iθ}``. The line at infinity raises :class:`~pgsym.errors.IdealPointError` (or is masked).

    >>> sin_angle([1.0, 0, 0], [[0.0, 1, 0], [3, -4, 1]])            # 1, and (1·(−4) − 0·3) / 5
    array([ 1. , -0.8])
    """
    check_options(ideal, nonfinite, "sin_angle")
    arrays = euclid_arrays([(l, "l"), (m, "m")], axis, "sin_angle", (3,))
    result = run(_sin_kernel, "sin_angle", [(l, 3, "l"), (m, 3, "m")], None, out, axis, 3)
    values = resolve(result, arrays, "sin_angle", ideal, nonfinite, axis, _line_at_infinity, _sin_rows)
    return values[()] if not isinstance(values, tuple) and values.ndim == 0 else values


def _signed_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    v, p, q = ins
    u0, u1, w0, w1, t, na = ws
    c, s = o[..., 0], o[..., 1]
    # the rays as homogeneous differences p_xy v_w − v_xy p_w: no division, exact zeros for p = v
    for (a, b), x in (((u0, u1), p), ((w0, w1), q)):
        for i, d in ((0, a), (1, b)):
            np.multiply(x[..., i], v[..., 2], out=d)
            np.multiply(v[..., i], x[..., 2], out=t)
            np.subtract(d, t, out=d)
    np.multiply(u0, w0, out=c)
    np.multiply(u1, w1, out=t)
    np.add(c, t, out=c)
    np.multiply(u0, w1, out=s)
    np.multiply(u1, w0, out=t)
    np.subtract(s, t, out=s)
    np.multiply(u0, u0, out=na)
    np.multiply(u1, u1, out=t)
    np.add(na, t, out=na)
    np.multiply(w0, w0, out=u0)  # u0 is free now: |w|²
    np.multiply(w1, w1, out=t)
    np.add(u0, t, out=u0)
    np.multiply(na, u0, out=t)
    np.sqrt(t, out=t)
    with np.errstate(divide="ignore"):  # p or q at the vertex: looked at again
        np.reciprocal(t, out=t)
    # the rays were scaled by p_w v_w and q_w v_w: their signs, through p_w q_w, fix the orientation
    np.multiply(p[..., 2], q[..., 2], out=w0)
    np.copysign(t, w0, out=t)
    np.multiply(c, t, out=c)
    np.multiply(s, t, out=s)
    flag_unsafe(na, o)
    flag_unsafe(u0, o)
    for x in (v, p, q):  # an ideal point gives a finite but meaningless ray: looked at again
        if not x[..., 2].all():
            o[x[..., 2] == 0] = np.nan


def _rays(rows: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    v, p, q = (scaled(r) for r in rows)  # exact: powers of two keep the zeros
    u = p[:, :2] * v[:, 2:] - v[:, :2] * p[:, 2:]
    w = q[:, :2] * v[:, 2:] - v[:, :2] * q[:, 2:]
    return u, w


def _signed_rows(rows: list[np.ndarray]) -> np.ndarray:
    u, w = (scaled(r) for r in _rays(rows))
    sign = np.sign(rows[1][:, 2]) * np.sign(rows[2][:, 2])
    norm = np.hypot(u[:, 0], u[:, 1]) * np.hypot(w[:, 0], w[:, 1])
    c = sign * (u[:, 0] * w[:, 0] + u[:, 1] * w[:, 1]) / norm
    s = sign * (u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]) / norm
    return np.stack([c, s], axis=-1)


def _at_vertex(rows: list[np.ndarray]) -> np.ndarray:
    with np.errstate(invalid="ignore", over="ignore"):  # rows with NaN are told apart by the caller
        u, w = _rays(rows)
        return ~u.any(axis=-1) | ~w.any(axis=-1)


def signed_angle(
    vertex: Any, p: Any, q: Any, *, ideal: str = "raise", nonfinite: str = "raise", degenerate: str = "raise",
    axis: int = -1,
) -> Any:
    """``(cos θ, sin θ)`` of the angles at ``vertex`` turning the ray to ``p`` counterclockwise onto the ray to ``q``.

    The numeric :func:`pgsym.metric.signed_angle` on points of P², as two arrays. The rays are the
    homogeneous differences ``p_xy v_w − v_xy p_w`` (no division, so ``p = vertex`` is decided exactly),
    their orientation restored by the sign of ``p_w q_w``. Ideal points raise
    :class:`~pgsym.errors.IdealPointError` (``ideal="mask"``); ``p`` or ``q`` at the vertex fixes no ray and
    raises :class:`~pgsym.errors.CoincidentPointsError` (``degenerate="mask"``). With a mask the result is
    ``((cos, sin), ok)``.

    >>> signed_angle([0.0, 0, 1], [1.0, 0, 1], [[0.0, 2, 1], [0, -2, 1]])   # a quarter turn either way
    (array([0., 0.]), array([ 1., -1.]))
    """
    check_options(ideal, nonfinite, "signed_angle")
    check_option(degenerate, DEGENERATE, "degenerate", "signed_angle")
    arrays = euclid_arrays([(vertex, "vertex"), (p, "p"), (q, "q")], axis, "signed_angle", (3,))
    ins = [(vertex, 3, "vertex"), (p, 3, "p"), (q, 3, "q")]
    result = run(_signed_kernel, "signed_angle", ins, 2, None, axis, 6)

    def ideal_rows(rows: list[np.ndarray]) -> np.ndarray:
        return np.logical_or.reduce([r[:, 2] == 0 for r in rows])

    checks = (degenerate, _at_vertex, CoincidentPointsError, "put p or q at the vertex, which fixes no ray")
    values = resolve(result, arrays, "signed_angle", ideal, nonfinite, axis, ideal_rows, _signed_rows, None, checks)
    if isinstance(values, tuple):
        c, s = np.moveaxis(values[0], axis, 0)
        return (c, s), values[1]
    c, s = np.moveaxis(values, axis, 0)
    return (c[()], s[()]) if c.ndim == 0 else (c, s)
