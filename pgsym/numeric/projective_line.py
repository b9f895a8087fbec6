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

from ..errors import UndefinedCrossRatioError
from ._arrays import check_option, nonfinite_result, rowwise

__all__ = ["bracket", "cross_ratio", "cross_ratio_homogeneous"]


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
    return rowwise(_bracket_kernel, "bracket", [(p, 2, "p"), (q, 2, "q")], None, out, axis, 1, nonfinite)


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
