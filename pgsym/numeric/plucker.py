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

from ..errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
)
from ._arrays import (
    DEGENERATE,
    ZERO_OR_DEGENERATE,
    as_float_array,
    check_option,
    construction,
    degenerate_result,
    nonfinite_result,
    rowwise,
)
from .tolerances import INCIDENT_RTOL

__all__ = [
    "intersect_plane",
    "klein_form",
    "meet_lines",
    "plane_through_lines",
    "plane_through_point",
    "plucker_join",
    "plucker_meet",
]

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


# The Plücker matrix L from the coordinates c = (l12, l13, l14, l23, l42, l34): entry (i, j) is
# sign · c[index] (L is skew, l24 = −l42). The dual matrix L* has the same layout on the reversed
# coordinates (the rewrite rule with factor 1, as in pgsym.plucker).
_MATRIX = {
    (0, 1): (1, 0), (0, 2): (1, 1), (0, 3): (1, 2), (1, 2): (1, 3), (1, 3): (-1, 4), (2, 3): (1, 5),
    (1, 0): (-1, 0), (2, 0): (-1, 1), (3, 0): (-1, 2), (2, 1): (-1, 3), (3, 1): (1, 4), (3, 2): (-1, 5),
}


def _entry(coords: np.ndarray, i: int, j: int, dual: bool) -> tuple[int, np.ndarray] | None:
    if (i, j) not in _MATRIX:
        return None
    sign, index = _MATRIX[i, j]
    return sign, coords[..., 5 - index if dual else index]


def _matrix_vector_kernel(dual: bool) -> Any:
    """``o = L x`` (or ``L* x``) for Plücker coordinates and 4-vectors, three products a row."""

    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        line, x = ins
        t = ws[0]
        for i in range(4):
            oi = o[..., i]
            first = True
            for j in range(4):
                e = _entry(line, i, j, dual)
                if e is None:
                    continue
                sign, c = e
                if first:
                    np.multiply(c, x[..., j], out=oi)
                    if sign < 0:
                        np.negative(oi, out=oi)
                    first = False
                else:
                    np.multiply(c, x[..., j], out=t)
                    (np.add if sign > 0 else np.subtract)(oi, t, out=oi)

    return kernel


def intersect_plane(
    lines: Any, planes: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise",
) -> Any:
    """The points ``X = L π`` where lines of P³ meet planes (the numeric :meth:`pgsym.plucker.Line3.intersect_plane`).

    A line parallel to its plane meets it in an ideal point; a line lying in its plane (``L π = 0``)
    raises :class:`~pgsym.errors.DependentPlanesError`, or gives a NaN row and a mask with
    ``degenerate="mask"``.

    >>> x_axis = plucker_join([0.0, 0, 0, 1], [1.0, 0, 0, 1])
    >>> intersect_plane(x_axis, [[1.0, 0, 0, -3], [0, 1, 0, -1], [0, 1, 0, 0]], degenerate="mask")
    (array([[ 3.,  0., -0.,  1.],
           [ 1.,  0., -0.,  0.],
           [nan, nan, nan, nan]]), array([ True,  True, False]))

    (The x-axis meets ``x = 3`` in ``(3, 0, 0)``, the parallel plane ``y = 1`` in its ideal point, and lies in
    ``y = 0``.)
    """
    check_option(degenerate, DEGENERATE, "degenerate", "intersect_plane")
    what = "are lines lying in their plane, which share every point of the line instead of one"
    inputs = [(lines, 6, "lines"), (planes, 4, "planes")]
    return construction(_matrix_vector_kernel(False), "intersect_plane", inputs, 4, out, axis, 1, nonfinite,
                        degenerate, DependentPlanesError, what)


def plane_through_point(
    lines: Any, points: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "raise",
) -> Any:
    """The planes ``π = L* X`` through lines and points of P³ (numeric :meth:`pgsym.plucker.Line3.plane_through_point`).

    A point on its line (``L* X = 0``) raises :class:`~pgsym.errors.CollinearPointsError`, or gives a NaN
    row and a mask with ``degenerate="mask"``.

    >>> x_axis = plucker_join([0.0, 0, 0, 1], [1.0, 0, 0, 1])
    >>> plane_through_point(x_axis, [0.0, 1, 0, 1]) + 0.0     # the plane z = 0
    array([0., 0., 1., 0.])
    """
    check_option(degenerate, DEGENERATE, "degenerate", "plane_through_point")
    what = "are points on their line, through which infinitely many planes pass"
    inputs = [(lines, 6, "lines"), (points, 4, "points")]
    return construction(_matrix_vector_kernel(True), "plane_through_point", inputs, 4, out, axis, 1, nonfinite,
                        degenerate, CollinearPointsError, what)


def _product_kernel(column: bool, rtol: float) -> Any:
    """The meet point (``column``) or the common plane of two lines, from ``K = L M*``.

    For lines that meet in ``X`` and span the plane ``π``, ``K = L M* = X πᵀ`` (rank one): every column is a
    multiple of ``X``, every row a multiple of ``π``. The kernel takes the column (or row) of largest norm.
    For skew lines ``K`` has rank two and no column is the answer: rows with a reciprocal product
    ``|(L|M)| > rtol |L| |M|`` are set to zero, as are equal lines (``K = 0``).
    """

    def kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
        l, m = ins
        t, best, norm = ws[16], ws[17], ws[18]
        K = [[ws[4 * i + j] for j in range(4)] for i in range(4)]
        for i in range(4):
            for j in range(4):
                kij = K[i][j]
                kij[...] = 0
                for k in range(4):
                    a, b = _entry(l, i, k, False), _entry(m, k, j, True)
                    if a is None or b is None:
                        continue
                    np.multiply(a[1], b[1], out=t)
                    (np.add if a[0] * b[0] > 0 else np.subtract)(kij, t, out=kij)
        for n in range(4):  # the column (row) of largest norm; the first is taken as it is, so NaN stays NaN
            vec = [K[i][n] for i in range(4)] if column else K[n]
            np.multiply(vec[0], vec[0], out=norm)
            for v in vec[1:]:
                np.multiply(v, v, out=t)
                np.add(norm, t, out=norm)
            if n == 0:
                np.copyto(best, norm)
                for i in range(4):
                    np.copyto(o[..., i], vec[i])
                continue
            take = norm > best
            np.copyto(best, norm, where=take)
            for i in range(4):
                np.copyto(o[..., i], vec[i], where=take)
        # skew lines: |(L|M)| = |Σ l_i m_(5−i)| against rtol |L| |M|
        np.multiply(l[..., 0], m[..., 5], out=t)
        for i in range(1, 6):
            t += l[..., i] * m[..., 5 - i]
        np.abs(t, out=t)
        np.einsum("...i,...i->...", l, l, out=norm)
        np.einsum("...i,...i->...", m, m, out=best)
        np.multiply(norm, best, out=norm)
        np.sqrt(norm, out=norm)
        broken = ~(np.isfinite(t) & np.isfinite(norm))  # NaN or inf anywhere in l or m, or an overflow
        skew = (t > rtol * norm) & ~broken
        if skew.any():
            o[skew] = 0
        if broken.any():  # the column taken may not hold the NaN: mark the row for the policy
            o[broken] = np.nan

    return kernel


def _line_pair(
    function: str, column: bool, l: Any, m: Any, out: Any, axis: int, nonfinite: str, degenerate: str, rtol: float,
    what: str,
) -> Any:
    check_option(degenerate, ZERO_OR_DEGENERATE, "degenerate", function)
    inputs = [(l, 6, "l"), (m, 6, "m")]
    value = rowwise(_product_kernel(column, rtol), function, inputs, 4, out, axis, 19, nonfinite)
    if degenerate != "raise":
        return degenerate_result(value, degenerate, axis, function, CoincidentLinesError, what)
    result = value[0] if isinstance(value, tuple) else value
    zero = ~np.moveaxis(result, axis, -1).any(axis=-1)
    if zero.any():  # tell equal lines from skew ones by name
        first = tuple(int(i) for i in np.argwhere(zero)[0]) if zero.ndim else ()
        a = np.broadcast_to(np.moveaxis(as_float_array(l, "l", function), axis, -1), (*zero.shape, 6))[first]
        b = np.broadcast_to(np.moveaxis(as_float_array(m, "m", function), axis, -1), (*zero.shape, 6))[first]
        equal = np.linalg.matrix_rank(np.stack([a, b])) < 2
        error = CoincidentLinesError if equal else DegenerateConfigurationError
        cause = "equal lines" if equal else "skew lines (they do not meet)"
        raise error(
            f"{function}: {int(zero.sum())} of the {zero.size} pairs of lines {what}; the first, at index {first}, "
            f"are {cause}: {a.tolist()} and {b.tolist()}. Pass degenerate='mask' to get NaN rows there and a mask"
        )
    return value


def meet_lines(
    l: Any, m: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "zero", rtol: float = INCIDENT_RTOL,
) -> Any:
    """The points where pairs of lines of P³ meet: a column of ``L M* = X πᵀ``.

    Lines meet when their reciprocal product is zero (:meth:`pgsym.plucker.Line3.meets`); here, in
    floats, when ``|(L|M)| ≤ rtol |L| |M|``. Equal lines and skew lines have no single meet: as for
    the meets of P² (:func:`pgsym.numeric.meet`) the default ``degenerate="zero"`` gives the zero vector,
    ``"raise"`` :class:`~pgsym.errors.CoincidentLinesError` (equal lines) or
    :class:`~pgsym.errors.DegenerateConfigurationError` (skew lines), ``"mask"`` NaN rows and a mask.
    The exact construction is :func:`pgsym.plucker.meet_lines`.

    >>> x_axis = plucker_join([0.0, 0, 0, 1], [1.0, 0, 0, 1])
    >>> y_line = plucker_join([2.0, 0, 0, 1], [2.0, 1, 0, 1])     # x = 2 in the plane z = 0
    >>> skew = plucker_join([0.0, 0, 1, 1], [0.0, 1, 1, 1])
    >>> meet_lines(x_axis, [y_line, skew])
    array([[2., 0., 0., 1.],
           [0., 0., 0., 0.]])
    """
    what = "are equal or skew, and meet in no single point"
    return _line_pair("meet_lines", True, l, m, out, axis, nonfinite, degenerate, rtol, what)


def plane_through_lines(
    l: Any, m: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise",
    degenerate: str = "zero", rtol: float = INCIDENT_RTOL,
) -> Any:
    """The planes spanned by pairs of meeting lines of P³: a row of ``L M* = X πᵀ``.

    Equal and skew lines span no single plane: zeros, an error or a mask, as in :func:`meet_lines`. The exact
    construction is :func:`pgsym.plucker.plane_through_lines`.

    >>> x_axis = plucker_join([0.0, 0, 0, 1], [1.0, 0, 0, 1])
    >>> y_line = plucker_join([2.0, 0, 0, 1], [2.0, 1, 0, 1])
    >>> plane_through_lines(x_axis, y_line)          # the plane z = 0
    array([0., 0., 2., 0.])
    """
    what = "are equal or skew, and span no single plane"
    return _line_pair("plane_through_lines", False, l, m, out, axis, nonfinite, degenerate, rtol, what)
