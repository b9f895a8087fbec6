"""The policy the Euclidean float kernels share (:mod:`pgsym.numeric.metric`, :mod:`pgsym.numeric.affine`).

Reading the arguments (:func:`euclid_arrays`), checking the options (:func:`check_options`), running a kernel
row by row (:func:`run`) and sorting the rows that came out non-finite into bad input, ideal elements,
degenerate input and intermediate overflows, recomputed after exact power-of-two scaling (:func:`resolve`).

>>> scaled(np.array([[3.0, 4.0, 1024.0]]))          # divided by 2¹¹: exact, and projectively nothing
array([[0.00146484, 0.00195312, 0.5       ]])
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from ..errors import DimensionError, IdealPointError
from ._arrays import NONFINITE, as_float_array, check_option, nonfinite_result, rowwise

__all__ = ["IDEAL", "PART", "add_square", "check_options", "either_point_ideal", "euclid_arrays", "flag_unsafe",
           "resolve", "run", "scaled"]

IDEAL = ("raise", "mask")

# the Euclidean part of each kind: the normal (a, b) of a line of P², (a, b, c) of a plane, and the
# direction (−l14, l42, −l34) of a line of space; the signs cancel in every product of two of them
PART = {3: (0, 1), 4: (0, 1, 2), 6: (2, 4, 5)}

# a squared norm outside [2⁻⁹⁶⁸, 2⁹⁶⁸] has overflowed, underflowed, or is about to lose digits in the
# division that follows; such rows are recomputed after scaling (well inside float64's 2^±1022)
SQUARE_LO, SQUARE_HI = 2.0**-968, 2.0**968


def add_square(t: np.ndarray, o: np.ndarray, first: bool) -> None:
    """``o = t²`` for the first term of a sum of squares, else ``o += t²``; in place (``t`` is overwritten).

    >>> o, t = np.zeros(2), np.array([3.0, 1.0])
    >>> add_square(t, o, True); add_square(np.array([4.0, 1.0]), o, False); o
    array([25.,  2.])
    """
    if first:
        np.multiply(t, t, out=o)
    else:
        np.multiply(t, t, out=t)
        np.add(o, t, out=o)


def flag_unsafe(square: np.ndarray, o: np.ndarray) -> None:
    """Set to NaN the rows of ``o`` whose squared norm is out of the safe range, for the second look.

    A quotient by an infinite norm would be a wrong but finite 0; two reductions over the block,
    while it is in cache, decide the common case.
    """
    if not (square.min() >= SQUARE_LO and square.max() <= SQUARE_HI):
        o[~((square >= SQUARE_LO) & (square <= SQUARE_HI))] = np.nan


def euclid_arrays(inputs: list[tuple[Any, str]], axis: int, function: str, sizes: tuple[int, ...]) -> list[np.ndarray]:
    out = []
    for x, name in inputs:
        a = as_float_array(x, name, function)
        if a.ndim == 0 or not -a.ndim <= axis < a.ndim or a.shape[axis] not in sizes:
            raise DimensionError(
                f"{function}: {name} must have {' or '.join(map(str, sizes))} homogeneous coordinates along "
                f"axis {axis}, got an array of shape {a.shape}"
            )
        out.append(np.moveaxis(a, axis, -1))
    if len({a.shape[-1] for a in out}) != 1:
        raise DimensionError(
            f"{function}: the arguments must be of one space, got {[a.shape[-1] for a in out]} coordinates"
        )
    return out


def scaled(rows: np.ndarray) -> np.ndarray:
    """Each row divided by the power of two nearest its largest entry: exact, projectively nothing."""
    big = np.max(np.abs(rows), axis=-1, keepdims=True)
    return np.ldexp(rows, -np.frexp(np.where(big > 0, big, 1.0))[1])


def resolve(
    result: Any,
    arrays: list[np.ndarray],
    function: str,
    ideal: str,
    nonfinite: str,
    axis: int,
    is_ideal: Callable[[list[np.ndarray]], np.ndarray],
    robust: Callable[[list[np.ndarray]], np.ndarray] | None,
    extra_bad: np.ndarray | None = None,
    degenerate: tuple[str, Callable[[list[np.ndarray]], np.ndarray], type[Exception], str] | None = None,
) -> Any:
    """Apply the policy to a kernel's ``(values, finite)``: sort the rows that are not finite (or ``extra_bad``)
    into bad inputs, ideal elements, degenerate input and overflows; recompute overflows with ``robust``; raise
    or mask. ``degenerate`` is ``(option, test, error, what)`` for a construction that can be undetermined."""
    values, ok = result
    shape = ok.shape
    vals = values if values.ndim == ok.ndim else np.moveaxis(values, axis, -1)
    if ok.ndim == 0:  # one row: work on views of shape (1, ...)
        vals, ok = vals[None], ok.reshape(1)
        extra_bad = None if extra_bad is None else np.reshape(extra_bad, 1)
    bad = ~ok if extra_bad is None else ~ok | extra_bad
    masked = ideal == "mask" or nonfinite == "mask" or (degenerate is not None and degenerate[0] == "mask")
    if not bad.any():
        return (values, ok.reshape(shape)) if masked else values
    index = tuple(np.nonzero(bad))
    batch = ok.shape
    rows = [np.broadcast_to(a, (*batch, a.shape[-1]))[index] for a in arrays]
    bad_input = np.zeros(len(index[0]) if index else 1, bool)
    for r in rows:
        bad_input |= ~np.isfinite(r).all(axis=-1)
    ideal_rows = ~bad_input & is_ideal(rows)
    degenerate_rows = np.zeros_like(ideal_rows)
    if degenerate is not None:
        degenerate_rows = ~bad_input & ~ideal_rows & degenerate[1](rows)
    rest = ~bad_input & ~ideal_rows & ~degenerate_rows
    if robust is not None and rest.any():
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            again = robust([r[rest] for r in rows])
        good = np.isfinite(again) if again.ndim == 1 else np.isfinite(again).all(axis=-1)
        sub = tuple(i[rest] for i in index)
        vals[tuple(i[good] for i in sub)] = again[good]
        rest_idx = np.nonzero(rest)[0]
        rest[rest_idx[good]] = False
    ok = np.ones(batch, bool)
    ok[index] = ~(bad_input | ideal_rows | degenerate_rows | rest)
    not_finite = np.ones(batch, bool)
    not_finite[index] = ~(bad_input | rest)
    if nonfinite == "raise" and not not_finite.all():
        nonfinite_result(vals, not_finite, "raise", function, arrays)
    if ideal == "raise" and ideal_rows.any():
        first = tuple(int(i[np.argmax(ideal_rows)]) for i in index)
        n = int(ideal_rows.sum())
        example = [np.broadcast_to(a, (*batch, a.shape[-1]))[first].tolist() for a in arrays]
        raise IdealPointError(
            f"{function}: {n} of the {ok.size} rows hold an ideal element (an ideal point, or a line or plane at "
            f"infinity), the first at index {first}: {example}; "
            "they have no finite distance, angle or foot. Pass ideal='mask' to get the other rows with a mask"
        )
    if degenerate is not None and degenerate[0] == "raise" and degenerate_rows.any():
        first = tuple(int(i[np.argmax(degenerate_rows)]) for i in index)
        raise degenerate[2](
            f"{function}: {int(degenerate_rows.sum())} of the {ok.size} inputs {degenerate[3]}, the first at index "
            f"{first}; pass degenerate='mask' to get NaN rows there and a mask of the good ones"
        )
    if masked:
        vals[~ok] = False if vals.dtype == bool else np.nan
        return values, ok.reshape(shape)
    return values


def run(
    kernel: Callable[[list[np.ndarray], np.ndarray, list[np.ndarray]], None],
    function: str,
    ins: list[tuple[Any, int, str]],
    k_out: int | None,
    out: np.ndarray | None,
    axis: int,
    n_scratch: int,
) -> tuple[np.ndarray, np.ndarray]:
    """The kernel's ``(values, finite)`` by :func:`~pgsym.numeric._arrays.rowwise` (which also takes empty batches)."""
    return rowwise(kernel, function, ins, k_out, out, axis, n_scratch, "mask")  # type: ignore[return-value]


def check_options(ideal: str, nonfinite: str, function: str) -> None:
    check_option(ideal, IDEAL, "ideal", function)
    check_option(nonfinite, NONFINITE, "nonfinite", function)


def either_point_ideal(rows: list[np.ndarray]) -> np.ndarray:
    """The rows where either of two points is ideal (last coordinate zero)."""
    return (rows[0][:, -1] == 0) | (rows[1][:, -1] == 0)
