"""Plücker coordinates of lines of P³, on float64 arrays.

The numeric twin of :mod:`pgsym.plucker`, in the same order
``(l12, l13, l14, l23, l42, l34)`` with ``l_ij = A_i B_j − B_i A_j`` for the join of the
points ``A`` and ``B`` (note ``l42 = −l24``). The meet of two planes ``P``, ``Q`` has the
dual coordinates ``P_i Q_j − Q_i P_j`` in the same order, and its primal coordinates are
those reversed (the rewrite rule, with factor 1, as in :meth:`pgsym.plucker.Line3.meet`).

>>> plucker_join([0.0, 0, 0, 1], [1.0, 0, 0, 1])      # the x-axis
array([ 0.,  0., -1.,  0.,  0.,  0.])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import CoincidentPointsError, DependentPlanesError, DimensionError
from ._arrays import as_float_array, construction, nonfinite_result

__all__ = ["klein_form", "plucker_join", "plucker_meet"]

_POSITIONS = ((0, 1), (0, 2), (0, 3), (1, 2), (3, 1), (2, 3))


def _wedge_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    a, b = ins
    t = ws[0]
    for n, (i, j) in enumerate(_POSITIONS):
        on = o[..., n]
        np.multiply(a[..., i], b[..., j], out=on)
        np.multiply(b[..., i], a[..., j], out=t)
        np.subtract(on, t, out=on)


def _reversed_wedge_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    _wedge_kernel(ins, o[..., ::-1], ws)


def plucker_join(
    a: Any, b: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise", degenerate: str = "zero"
) -> Any:
    """Plücker coordinates ``(l12, l13, l14, l23, l42, l34)`` of the lines through pairs of points.

    Equal to ``Line3.join(A, B).coordinates`` on the same data. Coincident points give zeros
    (``degenerate="zero"``), :class:`~pgsym.errors.CoincidentPointsError` (``"raise"``) or NaN
    rows and a mask (``"mask"``), as :func:`pgsym.numeric.join` does.

    >>> plucker_join([[0.0, 0, 0, 1]], [[1.0, 2, 3, 0]])   # through the origin, direction (1, 2, 3)
    array([[ 0.,  0., -1.,  0.,  2., -3.]])
    """
    what = "are pairs of coincident points, which fix no line"
    inputs = [(a, 4, "a"), (b, 4, "b")]
    return construction(
        _wedge_kernel, "plucker_join", inputs, 6, out, axis, 1, nonfinite, degenerate, CoincidentPointsError, what
    )


def plucker_meet(
    p: Any, q: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise", degenerate: str = "zero"
) -> Any:
    """Plücker coordinates of the lines where pairs of planes meet (``Line3.meet(P, Q).coordinates``).

    Equal planes give zeros, :class:`~pgsym.errors.DependentPlanesError` or a mask, as ``degenerate`` says.

    >>> plucker_meet([0.0, 1, 0, 0], [0.0, 0, 1, 0])      # y = 0 and z = 0: the x-axis again
    array([0., 0., 1., 0., 0., 0.])
    """
    what = "are pairs of equal planes, which meet in no single line"
    inputs = [(p, 4, "p"), (q, 4, "q")]
    return construction(
        _reversed_wedge_kernel, "plucker_meet", inputs, 6, out, axis, 1, nonfinite, degenerate, DependentPlanesError,
        what,
    )


def klein_form(lines: Any, *, axis: int = -1) -> np.ndarray:
    """The Klein form ``l12 l34 + l13 l42 + l14 l23``: zero for the coordinates of every line.

    >>> klein_form(plucker_join([1.0, 2, 3, 1], [4.0, 5, 7, 1]))
    array(0.)
    """
    a = np.moveaxis(as_float_array(lines, "lines", "klein_form"), axis, -1)
    if a.ndim == 0 or a.shape[-1] != 6:
        raise DimensionError(f"klein_form: lines need 6 Plücker coordinates along axis {axis}, got shape {a.shape}")
    with np.errstate(over="ignore", invalid="ignore"):
        form = np.asarray(a[..., 0] * a[..., 5] + a[..., 1] * a[..., 4] + a[..., 2] * a[..., 3])
    if not np.isfinite(np.sum(form)):
        nonfinite_result(form, np.isfinite(form), "raise", "klein_form", [a])
    return form
