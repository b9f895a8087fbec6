"""Homogenising and dehomogenising arrays of points, with ideal points flagged.

A point ``(x1, …, xk, w)`` with ``w = 0`` is ideal: it has no inhomogeneous
coordinates. :func:`dehomogenize` never divides by such a ``w``: it raises
:class:`~pgsym.errors.IdealPointError`, or, with ``ideal="mask"``, returns the finite
points together with a boolean mask and fills the rows of ideal points with ``fill``
(NaN by default), so no infinity or NaN appears without the caller asking for it. A NaN or
infinite input coordinate is no point at all: it raises :class:`~pgsym.errors.NonFiniteError`,
or with ``nonfinite="mask"`` is masked like an ideal point.

>>> import numpy as np
>>> dehomogenize(np.array([[2.0, 4, 2], [1, 1, 0]]), ideal="mask")
(array([[ 1.,  2.],
       [nan, nan]]), array([ True, False]))
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import DimensionError, IdealPointError, NonFiniteError
from ._arrays import NONFINITE, as_float_array, check_option
from .conditioning import require_finite

__all__ = ["dehomogenize", "homogenize", "is_ideal"]


def homogenize(x: Any, w: float = 1.0, *, axis: int = -1) -> np.ndarray:
    """Append the coordinate ``w`` (1 by default) to every point: ``(..., k)`` → ``(..., k + 1)``.

    >>> homogenize([[1.0, 2], [3, 4]])
    array([[1., 2., 1.],
           [3., 4., 1.]])
    """
    a = require_finite(as_float_array(x, "x", "homogenize"), "x", "homogenize")
    if not np.isfinite(w):
        raise NonFiniteError(f"homogenize: w must be a finite number, got {w}")
    if a.ndim == 0:
        raise DimensionError("homogenize: x must be an array of points (shape (..., k)), got a scalar")
    a = np.moveaxis(a, axis, -1)
    result = np.empty((*a.shape[:-1], a.shape[-1] + 1))
    result[..., :-1] = a
    result[..., -1] = w
    return np.moveaxis(result, -1, axis)


def is_ideal(x: Any, *, rtol: float = 0.0, axis: int = -1) -> np.ndarray:
    """True where the last coordinate is zero: ``|w| ≤ rtol · max|x_i|`` (exactly zero when ``rtol=0``).

    >>> is_ideal([[1.0, 2, 0], [1, 2, 1e-17]]), is_ideal([[1.0, 2, 0], [1, 2, 1e-17]], rtol=1e-12)
    (array([ True, False]), array([ True,  True]))
    """
    a = np.moveaxis(require_finite(as_float_array(x, "x", "is_ideal"), "x", "is_ideal"), axis, -1)
    if a.ndim == 0 or a.shape[-1] < 2:
        raise DimensionError(f"is_ideal: x must hold at least 2 homogeneous coordinates, got shape {a.shape}")
    w = np.abs(a[..., -1])
    if rtol == 0:
        return np.asarray(w == 0)
    return np.asarray(w <= rtol * np.max(np.abs(a), axis=-1))


def dehomogenize(
    x: Any, *, ideal: str = "raise", rtol: float = 0.0, fill: float = np.nan, axis: int = -1, nonfinite: str = "raise"
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """The inhomogeneous coordinates ``(x1/w, …, xk/w)`` of an array of points ``(..., k + 1)``.

    Points with ``|w| ≤ rtol · max|x_i|`` are ideal (with the default ``rtol=0`` only an
    exact zero is), and so are points whose quotient would overflow to infinity. With
    ``ideal="raise"`` (default) any ideal point raises
    :class:`~pgsym.errors.IdealPointError`, naming how many there are and the first one.
    With ``ideal="mask"`` the result is ``(coords, finite)``: ``finite`` is False for
    ideal points, whose rows of ``coords`` hold ``fill``. A point with a NaN or infinite
    coordinate raises :class:`~pgsym.errors.NonFiniteError`; with ``nonfinite="mask"`` it is
    masked (and filled) in the same way, and the result is ``(coords, finite)`` whatever ``ideal`` is.

    >>> dehomogenize([[2.0, 4, 2], [3, 3, 3]])
    array([[1., 2.],
           [1., 1.]])
    >>> dehomogenize([[2.0, 4, 2], [1, 1, 0]])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.IdealPointError: dehomogenize: 1 of the 2 points is ideal (w = 0), the first at index (1,)...
    """
    check_option(ideal, ("raise", "mask"), "ideal", "dehomogenize")
    check_option(nonfinite, NONFINITE, "nonfinite", "dehomogenize")
    a = np.moveaxis(as_float_array(x, "x", "dehomogenize"), axis, -1)
    if a.ndim == 0 or a.shape[-1] < 2:
        raise DimensionError(f"dehomogenize: x must hold at least 2 homogeneous coordinates, got shape {a.shape}")
    if nonfinite == "raise":
        require_finite(a, "x", "dehomogenize")
        input_ok = np.ones(a.shape[:-1], bool)
    else:
        input_ok = np.isfinite(a).all(axis=-1)
    with np.errstate(invalid="ignore"):
        bad = ~input_ok | (np.abs(a[..., -1]) <= rtol * np.max(np.abs(a), axis=-1) if rtol else a[..., -1] == 0)
    ideal_only = bad & input_ok
    w = a[..., -1:]
    coords = np.full((*a.shape[:-1], a.shape[-1] - 1), fill)
    with np.errstate(over="ignore"):
        np.divide(a[..., :-1], w, out=coords, where=~bad[..., None])
    overflow = ~bad & ~np.all(np.isfinite(coords), axis=-1)
    if overflow.any():
        bad = bad | overflow
        ideal_only = ideal_only | overflow
        coords[overflow] = fill
    if ideal == "raise" and ideal_only.any():
        first = tuple(int(i) for i in np.argwhere(ideal_only)[0])
        verb = "is" if ideal_only.sum() == 1 else "are"
        raise IdealPointError(
            f"dehomogenize: {int(ideal_only.sum())} of the {bad.size} points {verb} ideal (w = 0), the first at index "
            f"{first}: {a[first].tolist()}; ideal points have no inhomogeneous coordinates. Pass ideal='mask' "
            "to get the finite ones with a mask, or keep homogeneous coordinates"
        )
    coords = np.moveaxis(coords, -1, axis)
    masked = ideal == "mask" or nonfinite == "mask"
    return (coords, np.asarray(~bad)) if masked else coords
