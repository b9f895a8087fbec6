"""Brackets and cross-ratios on the projective line P¹, on float64 arrays.

The numeric twin of :mod:`pgsym.projective_line`, with the same convention: the bracket
of two points is ``[P Q] = p1 q2 − p2 q1`` and the cross-ratio of four points is

    (A, B; C, D) = [A C][B D] / ([A D][B C]),

``(a − c)(b − d) / ((a − d)(b − c))`` for finite points. Points are arrays of shape
``(..., 2)``; the ideal point is ``(1, 0)``. A zero denominator (``A = D`` or ``B = C``,
or three coincident points) makes the cross-ratio undefined: it raises
:class:`~pgsym.errors.UndefinedCrossRatioError`, or with ``undefined="mask"`` the
function returns the values and a mask, never a silent infinity or NaN.

>>> cross_ratio([0.0, 1], [1.0, 1], [2.0, 1], [3.0, 1])     # 4/3
array(1.33333333)
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import DimensionError, UndefinedCrossRatioError
from ._arrays import (
    DEGENERATE,
    as_numeric_arrays,
    check_option,
    degenerate_result,
    no_zero_row,
    nonfinite_result,
    rowwise,
)
from .tolerances import INCIDENT_RTOL

__all__ = ["bracket", "cross_ratio", "cross_ratio_homogeneous", "harmonic_conjugate"]


def _bracket_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    p, q = ins
    np.multiply(p[..., 0], q[..., 1], out=o)
    np.multiply(p[..., 1], q[..., 0], out=ws[0])
    np.subtract(o, ws[0], out=o)


def bracket(
    p: Any, q: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise"
) -> Any:
    """The brackets ``[P Q] = p1 q2 − p2 q1``: zero exactly where ``P`` and ``Q`` coincide.

    >>> bracket([[5.0, 1], [1, 0]], [[2.0, 1], [7, 1]])
    array([3., 1.])
    """
    return rowwise(_bracket_kernel, "bracket", [(p, 2, "p"), (q, 2, "q")], None, out, axis, 1, nonfinite,
                   complex_ok=True)


def _ratio_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    a, b, c, d = ins
    x, y = ws[0], ws[1]
    num, den = o[..., 0], o[..., 1]
    _bracket_kernel([a, c], num, [x])  # [A C]
    _bracket_kernel([b, d], y, [x])  # [B D]
    np.multiply(num, y, out=num)
    _bracket_kernel([a, d], den, [x])  # [A D]
    _bracket_kernel([b, c], y, [x])  # [B C]
    np.multiply(den, y, out=den)


def cross_ratio_homogeneous(a: Any, b: Any, c: Any, d: Any, *, axis: int = -1, nonfinite: str = "raise") -> Any:
    """The pairs ``([A C][B D], [A D][B C])``: the cross-ratio as a point of P¹, defined unless both are 0.

    >>> cross_ratio_homogeneous([0.0, 1], [1.0, 1], [1.0, 1], [2.0, 1]) + 0.0   # B = C: the value ∞ = (1, 0)
    array([1., 0.])
    """
    inputs = [(a, 2, "a"), (b, 2, "b"), (c, 2, "c"), (d, 2, "d")]
    return rowwise(_ratio_kernel, "cross_ratio", inputs, 2, None, axis, 2, nonfinite)


def cross_ratio(
    a: Any, b: Any, c: Any, d: Any, *, undefined: str = "raise", rtol: float = 0.0, axis: int = -1
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """The cross-ratios ``(A, B; C, D) = [A C][B D] / ([A D][B C])`` of broadcast arrays of points of P¹.

    The value is undefined where ``|[A D][B C]| ≤ rtol · |A||B||C||D|`` (an exact zero when
    ``rtol=0``). Then ``undefined="raise"`` (default) raises
    :class:`~pgsym.errors.UndefinedCrossRatioError`; ``undefined="mask"`` returns
    ``(values, defined)`` with NaN where ``defined`` is False.

    >>> cross_ratio([-1.0, 1], [1.0, 1], [0.0, 1], [1.0, 0])     # harmonic, with D at infinity
    array(-1.)
    >>> cross_ratio([[0.0, 1], [0, 1]], [1.0, 1], [[2.0, 1], [1, 1]], [3.0, 1], undefined="mask")
    (array([1.33333333,        nan]), array([ True, False]))
    """
    check_option(undefined, ("raise", "mask"), "undefined", "cross_ratio")
    pair = np.moveaxis(cross_ratio_homogeneous(a, b, c, d, axis=axis), axis, -1)
    num, den = pair[..., 0], pair[..., 1]
    if rtol == 0:
        bad = den == 0
    else:
        norms = [np.linalg.norm(np.moveaxis(np.asarray(x, dtype=np.float64), axis, -1), axis=-1) for x in (a, b, c, d)]
        bad = np.abs(den) <= rtol * norms[0] * norms[1] * norms[2] * norms[3]
    if undefined == "raise" and bad.any():
        first = tuple(int(i) for i in np.argwhere(bad)[0]) if bad.ndim else ()
        raise UndefinedCrossRatioError(
            f"cross_ratio: {int(bad.sum())} of the {bad.size} cross-ratios have a zero denominator [A D][B C] "
            f"(A = D or B = C, or three points coincide), the first at index {first}; reorder the points, or "
            "pass undefined='mask' (values and a mask) or use cross_ratio_homogeneous (the value as a point of P¹)"
        )
    values = np.full(num.shape, np.nan)
    with np.errstate(over="ignore"):
        np.divide(num, den, out=values, where=~bad)
    overflow = ~bad & ~np.isfinite(values)
    if overflow.any():  # a tiny nonzero denominator: the value exceeds float64, report it rather than return inf
        nonfinite_result(values, ~overflow, "raise", "cross_ratio")
    return (values, np.asarray(~bad)) if undefined == "mask" else values


def _harmonic_kernel_p1(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    a, b, c = ins
    ac, bc, ab, t = ws
    _bracket_kernel([a, c], ac, [t])
    _bracket_kernel([b, c], bc, [t])
    _bracket_kernel([a, b], ab, [t])
    for i in range(2):  # D = [A C] B + [B C] A
        oi = o[..., i]
        np.multiply(ac, b[..., i], out=oi)
        np.multiply(bc, a[..., i], out=t)
        np.add(oi, t, out=oi)
    np.multiply(ab, ac, out=t)
    np.multiply(t, bc, out=t)
    if not t.all():  # a zero bracket (or an underflow, sorted out here): two equal points have no conjugate
        coincident = (ab == 0) | (ac == 0) | (bc == 0)
        o[coincident] = 0


def _cross_into(u: np.ndarray, v: np.ndarray, out: list[np.ndarray], t: np.ndarray) -> None:
    for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        np.multiply(u[..., j], v[..., k], out=out[i])
        np.multiply(u[..., k], v[..., j], out=t)
        np.subtract(out[i], t, out=out[i])


def _dot_into(u: list[np.ndarray], v: list[np.ndarray], out: np.ndarray, t: np.ndarray) -> None:
    np.multiply(u[0], v[0], out=out)
    for i in (1, 2):
        np.multiply(u[i], v[i], out=t)
        np.add(out, t, out=out)


def _harmonic_kernel_p2(rtol: float) -> Any:
    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        a, b, c = ins
        n, u, t = ws[0:3], ws[3:6], ws[6]
        alpha, beta, zero = ws[7], ws[8], ws[9]
        _cross_into(a, b, n, t)  # n = a × b; for c = α a + β b: c × b = α n and a × c = β n
        _cross_into(c, b, u, t)
        _dot_into(u, n, alpha, t)  # α |n|²
        degenerate = (u[0] == 0) & (u[1] == 0) & (u[2] == 0)  # B = C
        _cross_into(a, c, u, t)
        _dot_into(u, n, beta, t)  # β |n|²
        degenerate |= (u[0] == 0) & (u[1] == 0) & (u[2] == 0)  # A = C
        for i in range(3):  # D = α a − β b, scaled by |n|²
            oi = o[..., i]
            np.multiply(alpha, a[..., i], out=oi)
            np.multiply(beta, b[..., i], out=t)
            np.subtract(oi, t, out=oi)
        # collinear: |det[a b c]| = |c · n| ≤ rtol |c| |n| (A = B makes n = 0 and D = 0 by itself)
        _dot_into([c[..., 0], c[..., 1], c[..., 2]], n, zero, t)
        det = np.abs(zero)
        _dot_into(n, [x.conj() for x in n], zero, t)
        norm_n = np.sqrt(np.abs(zero))
        c_norm = np.sqrt(np.abs(c[..., 0]) ** 2 + np.abs(c[..., 1]) ** 2 + np.abs(c[..., 2]) ** 2)
        degenerate |= det > rtol * norm_n * c_norm
        if degenerate.any():
            o[degenerate] = 0

    return kernel


def harmonic_conjugate(
    a: Any, b: Any, c: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise", rtol: float = INCIDENT_RTOL,
) -> Any:
    """The harmonic conjugates ``D`` of ``C`` with respect to ``A``, ``B``: ``(A, B; C, D) = −1``.

    Points of P¹ (2 coordinates) use the formula of :func:`pgsym.projective_line.harmonic_conjugate`,
    ``D = [A C] B + [B C] A``, with the same numbers on the same data. Collinear points of P² (3 coordinates)
    use ``D = α A − β B`` for ``C = α A + β B``, read off the cross products ``C × B = α (A × B)`` and
    ``A × C = β (A × B)`` and scaled by ``|A × B|²`` — no division, so ideal points are fine (the exact
    :func:`pgsym.projective_line.harmonic_conjugate` takes both kinds of input as well). Two equal
    points (exactly), or three points of P² that are not collinear (``|det[A B C]| > rtol |C| |A × B|``),
    have no conjugate: :class:`~pgsym.errors.UndefinedCrossRatioError`, or with ``degenerate="mask"``
    NaN rows and a mask. Complex arrays are accepted.

    >>> harmonic_conjugate([0.0, 1], [4.0, 1], [1.0, 1])          # −2 = (−4, 2): (0, 4; 1, −2) = −1
    array([-4.,  2.])
    >>> d = harmonic_conjugate([0.0, 0, 1], [4.0, 4, 1], [1.0, 1, 1])   # the same, on the line y = x
    >>> (d[:2] / d[2]).tolist()
    [-2.0, -2.0]
    >>> harmonic_conjugate([[-1.0, 1], [0, 1]], [1.0, 1], [[0.0, 1], [1, 1]], degenerate="mask")   # (−1, 1; 0, ∞) = −1
    (array([[-2.,  0.],
           [nan, nan]]), array([ True, False]))
    """
    check_option(degenerate, DEGENERATE, "degenerate", "harmonic_conjugate")
    first = as_numeric_arrays([(a, "a")], "harmonic_conjugate", complex_ok=True)[0]
    if first.ndim == 0 or not -first.ndim <= axis < first.ndim or first.shape[axis] not in (2, 3):
        raise DimensionError(
            f"harmonic_conjugate: points have 2 (P¹) or 3 (collinear points of P²) coordinates along axis {axis}, "
            f"got an array of shape {first.shape}"
        )
    k = first.shape[axis]
    formula, n_scratch = (_harmonic_kernel_p1, 4) if k == 2 else (_harmonic_kernel_p2(rtol), 10)
    zero_seen = []

    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        formula(ins, o, ws)
        if not zero_seen and not no_zero_row(o):  # in cache: a zero row, or a false alarm
            zero_seen.append(True)

    what = "are not three distinct (and, in P², collinear) points, which have no harmonic conjugate"
    inputs = [(a, k, "a"), (b, k, "b"), (c, k, "c")]
    value = rowwise(kernel, "harmonic_conjugate", inputs, k, out, axis, n_scratch, nonfinite, complex_ok=True)
    if not zero_seen and degenerate == "raise":  # no row can be zero: the policy has nothing to do
        return value
    return degenerate_result(value, degenerate, axis, "harmonic_conjugate", UndefinedCrossRatioError, what)
