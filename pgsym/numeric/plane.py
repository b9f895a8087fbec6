"""Join, meet and incidence in the projective plane P², on float64 arrays.

The numeric twin of :mod:`pgsym.projective_plane`: the line through two points and
the point on two lines are both the cross product, computed with the same formula as
:func:`pgsym.projective_plane.cross`,

    (u2 v3 − u3 v2,  u3 v1 − u1 v3,  u1 v2 − u2 v1).

Arrays have shape ``(..., 3)`` (or ``(3, ...)`` with ``axis=0``) and broadcast. Nothing
is normalised: the result is the raw cross product, exactly as in the exact core, so
integer data gives the same numbers. Coincident inputs give the zero vector, which is
no projective object: :func:`join` and :func:`meet` return it by default
(``degenerate="zero"``; test for it with :func:`pgsym.numeric.is_zero_vector`), raise
:class:`~pgsym.errors.CoincidentPointsError` / :class:`~pgsym.errors.CoincidentLinesError`
with ``degenerate="raise"``, or mask it with ``degenerate="mask"``.

>>> import numpy as np
>>> meet(np.array([[1.0, 0, -1], [1, -1, 0]]), np.array([0.0, 1, -2]))   # x = 1 and y = x, with y = 2
array([[1., 2., 1.],
       [2., 2., 1.]])
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import CoincidentLinesError, CoincidentPointsError, DimensionError
from ._arrays import as_numeric_arrays, construction, rowwise
from .conditioning import require_finite
from .tolerances import INCIDENT_RTOL

__all__ = ["cross", "incident", "is_zero_vector", "join", "meet"]

_CYCLE = ((0, 1, 2), (1, 2, 0), (2, 0, 1))


def _cross_kernel(ins: list[np.ndarray], o: np.ndarray, ws: list[np.ndarray]) -> None:
    u, v = ins
    t = ws[0]
    for i, j, k in _CYCLE:  # o_i = u_j v_k − u_k v_j
        oi = o[..., i]
        np.multiply(u[..., j], v[..., k], out=oi)
        np.multiply(u[..., k], v[..., j], out=t)
        np.subtract(oi, t, out=oi)


def cross(
    u: Any, v: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise"
) -> Any:
    """The cross products ``u × v`` of broadcast arrays of 3-vectors.

    ``out`` (optional) receives the result; ``axis`` is the component axis (0 for a
    component-major ``(3, N)`` layout, the fastest one).

    >>> cross([1.0, 0, 0], [0.0, 1, 0])
    array([0., 0., 1.])
    >>> cross(np.array([[1.0, 0], [0, 1], [0, 0]]), np.array([[0.0, 0], [0, 0], [1, 1]]), axis=0)
    array([[ 0.,  1.],
           [-1.,  0.],
           [ 0.,  0.]])
    """
    return rowwise(_cross_kernel, "cross", [(u, 3, "u"), (v, 3, "v")], 3, out, axis, 1, nonfinite, complex_ok=True)


def join(
    p: Any, q: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise", degenerate: str = "zero"
) -> Any:
    """The lines ``p × q`` through pairs of points of P² (the numeric :func:`pgsym.projective_plane.join`).

    Coincident points give the zero vector (``degenerate="zero"``), raise
    :class:`~pgsym.errors.CoincidentPointsError` (``"raise"``), or a NaN row and a mask (``"mask"``).

    >>> join([0.0, 0, 1], [[1.0, 1, 1], [1, 0, 0]])   # y = x, and the x-axis through an ideal point
    array([[-1.,  1.,  0.],
           [ 0.,  1.,  0.]])
    >>> join([1.0, 2, 1], [[2.0, 4, 2], [0, 0, 1]], degenerate="mask")
    (array([[nan, nan, nan],
           [ 2., -1.,  0.]]), array([False,  True]))
    """
    error, what = CoincidentPointsError, "are pairs of coincident points, which fix no line"
    return construction(_cross_kernel, "join", [(p, 3, "p"), (q, 3, "q")], 3, out, axis, 1, nonfinite, degenerate,
                        error, what, complex_ok=True)


def meet(
    l: Any, m: Any, *, out: np.ndarray | None = None, axis: int = -1, nonfinite: str = "raise", degenerate: str = "zero"
) -> Any:
    """The points ``l × m`` where pairs of lines of P² meet (the numeric :func:`pgsym.projective_plane.meet`).

    Parallel lines meet in an ideal point (last coordinate 0); equal lines give the zero
    vector, :class:`~pgsym.errors.CoincidentLinesError` or a masked row, as ``degenerate`` says
    (see :func:`join`).

    >>> meet([1.0, -1, 0], [1.0, -1, 3])
    array([-3., -3.,  0.])

    Complex arrays are accepted (so are they by :func:`cross` and :func:`join`): the circular points
    ``I = (1, i, 0)``, ``J = (1, −i, 0)`` span the line at infinity, ``I × J = (0, 0, −2i)``.

    >>> join([1, 1j, 0], [1, -1j, 0])
    array([0.+0.j, 0.+0.j, 0.-2.j])
    """
    error, what = CoincidentLinesError, "are pairs of equal lines, which meet in no single point"
    return construction(_cross_kernel, "meet", [(l, 3, "l"), (m, 3, "m")], 3, out, axis, 1, nonfinite, degenerate,
                        error, what, complex_ok=True)


def incident(x: Any, y: Any, *, rtol: float = INCIDENT_RTOL, axis: int = -1) -> np.ndarray:
    """True where ``x`` and ``y`` are incident: ``|x · y| ≤ rtol |x| |y|``.

    Works in any dimension: a point and a line of P², a point and a plane of P³. The test
    is scale-invariant: it compares the cosine of the angle between the two coordinate
    vectors with ``rtol``; ``rtol=0`` asks for an exact zero.

    >>> incident([[1.0, 1, 1], [1, 2, 1]], [1.0, -1, 0])     # is the point on y = x?
    array([ True, False])
    >>> incident([1.0, 1, 1], [1.0, -1, 1e-12]), incident([1.0, 1, 1], [1.0, -1, 1e-12], rtol=0)
    (array(True), array(False))

    Complex coordinates are accepted: the dot product is bilinear (no conjugation), as incidence is,
    and the norms are the Hermitian ones. ``I = (1, i, 0)`` lies on the line at infinity and on the
    isotropic line ``x + i y = 0`` (``1·1 + i·i = 0``); ``J = (1, −i, 0)`` does not (``1 + (−i)(i) = 2``).

    >>> incident([[1, 1j, 0], [1, 1j, 0], [1, -1j, 0]], [[0, 0, 1], [1, 1j, 0], [1, 1j, 0]]).tolist()
    [True, True, False]
    """
    a, b = as_numeric_arrays([(x, "x"), (y, "y")], "incident", complex_ok=True)
    a, b = require_finite(a, "x", "incident"), require_finite(b, "y", "incident")
    if a.ndim == 0 or b.ndim == 0 or a.shape[axis] != b.shape[axis]:
        raise DimensionError(
            f"incident: x and y need the same number of homogeneous coordinates along axis {axis}, "
            f"got shapes {a.shape} and {b.shape}"
        )
    a, b = np.moveaxis(a, axis, -1), np.moveaxis(b, axis, -1)
    # each vector scaled by the power of two nearest its largest entry (exact, and projectively nothing),
    # so that no square overflows or underflows
    a = a * np.ldexp(1.0, -np.frexp(np.max(np.abs(a), axis=-1, keepdims=True))[1])
    b = b * np.ldexp(1.0, -np.frexp(np.max(np.abs(b), axis=-1, keepdims=True))[1])
    dot = np.einsum("...i,...i->...", a, b)
    square_a = np.einsum("...i,...i->...", a, a.conj()).real
    bound = rtol * np.sqrt(square_a * np.einsum("...i,...i->...", b, b.conj()).real)
    return np.asarray(np.abs(dot) <= bound)


def is_zero_vector(x: Any, *, atol: float = 0.0, axis: int = -1) -> np.ndarray:
    """True where every coordinate is at most ``atol`` in size: no projective object.

    A join of two coincident points (or a meet of two equal lines) is the zero vector.

    >>> is_zero_vector(join([[1.0, 2, 1], [1, 2, 1]], [[2.0, 4, 2], [0, 0, 1]]))
    array([ True, False])
    """
    (a,) = as_numeric_arrays([(x, "x")], "is_zero_vector", complex_ok=True)
    a = np.moveaxis(require_finite(a, "x", "is_zero_vector"), axis, -1)
    return np.asarray(np.all(np.abs(a) <= atol, axis=-1))
