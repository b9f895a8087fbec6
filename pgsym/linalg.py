"""Null spaces, ranks and the SVD: the linear algebra behind joins and meets in P³.

Finding the plane through three points (or the point on three planes) means
solving a homogeneous system ``M x = 0`` with a 3×4 matrix ``M`` of rank 3:
the answer is the one-dimensional null space of ``M``. This module offers the
two ways of computing it that the lecture presents, each exactly and
numerically:

* **method #1**, the null space itself: :func:`nullspace_exact` (SymPy, exact)
  and :func:`nullspace_svd` (numpy: the right singular vectors of the zero
  singular values);
* **method #2**, fixing one homogeneous coordinate to 1 and solving the square
  system that remains: :func:`solve_by_fixing_coordinate`.

:func:`plane_through_numeric` and :func:`point_on_planes_numeric` are the
floating-point counterparts of :func:`pgsym.space.plane_through` and
:func:`pgsym.space.point_on_planes`; :func:`svd_steps` splits a 2×2 matrix into
the rotate–stretch–rotate factors of its SVD.

>>> nullspace_exact([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]])
[(1, 2, 3, 1)]
>>> rank_exact([[1, 2], [2, 4]])
1
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from typing import Any, NamedTuple

import numpy as np
import sympy
from sympy import Expr, Matrix

from . import matrices
from .errors import (
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
    InvalidCoordinatesError,
    NonFiniteError,
    ZeroCoordinateError,
)
from .exact import canonical_coords
from .homogeneous import HomogeneousVector, is_zero
from .matrices import exact_matrix, is_zero_entry

__all__ = [
    "SVDSteps",
    "ZeroCoordinateError",
    "nullspace_exact",
    "nullspace_svd",
    "numeric_rank",
    "plane_through_numeric",
    "point_on_planes_numeric",
    "rank_exact",
    "solve_by_fixing_coordinate",
    "svd_steps",
]


# -- exact ---------------------------------------------------------------------------------------------


def _exact_matrix(M: Any) -> Matrix:
    """The system matrix, exactly (rows may be homogeneous vectors); a mutable copy for row operations."""
    return Matrix(exact_matrix(M, what="M"))


def nullspace_exact(M: Any) -> list[tuple[Expr, ...]]:
    """An exact basis of the null space ``{x : M x = 0}``, as a list of tuples.

    ``M`` may be nested sequences, a SymPy or numpy matrix, or a list of
    homogeneous vectors (one per row). Each basis vector is a tuple of SymPy
    numbers, one per column of ``M``; rational vectors are scaled by a positive
    factor to coprime integers. The list is empty when ``M`` has full column
    rank. Row reduction uses an exact zero test, so for symbolic entries the
    result is the generic null space (valid where no pivot vanishes).

    >>> nullspace_exact([[1, 1, 1, -1], [1, -1, 0, 0]])
    [(-1, -1, 2, 0), (1, 1, 0, 2)]
    >>> nullspace_exact([[1, 0], [0, 1]])
    []
    """
    matrix = _exact_matrix(M)
    basis = matrix.nullspace(iszerofunc=is_zero_entry)
    return [canonical_coords(list(v), keep_sign=True) for v in basis]


def rank_exact(M: Any) -> int:
    """The rank of ``M`` computed exactly (generic rank for symbolic entries).

    >>> rank_exact([[1, 2, 3, 4], [2, 4, 6, 8], [0, 0, 1, 1]])
    2
    """
    return matrices.rank(_exact_matrix(M))


def solve_by_fixing_coordinate(M: Any, index: int = 3) -> tuple[Expr, ...]:
    """Method #2: solve ``M x = 0`` for an ``(n-1)×n`` matrix by setting ``x[index] = 1``.

    With the coordinate fixed, the remaining ``n-1`` unknowns solve the square
    system ``M' y = -m`` (``M'`` is ``M`` without column ``index``, ``m`` that
    column), solved exactly with the adjugate. This works only when the
    solution has a nonzero coordinate at ``index``: when it is zero (for
    ``index = 3`` and three planes, the meeting point is ideal; for three points,
    their plane passes through the origin), :class:`ZeroCoordinateError` is
    raised and names the indices that can be fixed instead. When ``M`` has rank
    below ``n-1`` the solution is not unique: rows given as
    :class:`~pgsym.space.Point3` raise :class:`CollinearPointsError`, rows given
    as :class:`~pgsym.space.Plane` raise :class:`DependentPlanesError`, other
    matrices :class:`DegenerateConfigurationError`.

    The result is a tuple of exact numbers whose entry ``index`` is 1.

    >>> solve_by_fixing_coordinate([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]])
    (1, 2, 3, 1)
    >>> solve_by_fixing_coordinate([[1, 1, 1, -1], [1, -1, 0, 0], [0, 0, 1, 0]], index=0)
    (1, 1, 0, 2)
    """
    from .space import Plane, Point3

    matrix = _exact_matrix(M)
    rows, cols = matrix.shape
    if rows != cols - 1:
        raise DimensionError(
            f"solve_by_fixing_coordinate needs an (n-1)×n matrix (e.g. 3×4), got {rows}×{cols}; "
            f"use nullspace_exact() for other shapes"
        )
    if isinstance(index, bool) or not isinstance(index, numbers.Integral) or not 0 <= int(index) < cols:
        raise DimensionError(f"index must be an integer from 0 to {cols - 1}, got {index!r}")
    index = int(index)
    rank = rank_exact(matrix)
    if rank < rows:
        kinds = {type(r) for r in M} if not isinstance(M, (sympy.MatrixBase, np.ndarray)) else set()
        message = (
            f"the {rows}×{cols} matrix has rank {rank} < {rows}, so the solutions form a space of dimension "
            f"{cols - rank} and fixing one coordinate does not single one out"
        )
        if kinds == {Point3}:
            raise CollinearPointsError(message + "; the points are collinear: choose a point off their line")
        if kinds == {Plane}:
            raise DependentPlanesError(message + "; the planes share a line: replace one of them")
        raise DegenerateConfigurationError(message + "; use nullspace_exact() to see all solutions")
    reduced = matrix.copy()
    reduced.col_del(index)
    det = sympy.expand(reduced.det(method="bareiss"))
    if is_zero(det):
        solution = nullspace_exact(matrix)[0]
        good = [i for i, v in enumerate(solution) if not is_zero(v)]
        raise ZeroCoordinateError(
            f"coordinate {index} (counting from 0) is zero in every solution {solution} of M x = 0, so it cannot "
            f"be set to 1 (the square matrix without column {index} is singular); fix another coordinate, one of "
            f"{good}"
        )
    rhs = -matrix[:, index]
    y = reduced.adjugate(method="bareiss") * rhs
    values = [sympy.cancel(v / det) for v in y]
    values.insert(index, sympy.Integer(1))
    return tuple(values)


# -- numeric -------------------------------------------------------------------------------------------


def _float_matrix(A: Any, name: str = "A") -> np.ndarray:
    if isinstance(A, HomogeneousVector):
        raise DimensionError(f"{name} must be a 2D array, got the single vector {A!r}")
    try:
        if isinstance(A, Sequence) and A and all(isinstance(r, HomogeneousVector) for r in A):
            A = [[float(v) for v in r.coords] for r in A]
        array = np.asarray(A, dtype=float)
    except (TypeError, ValueError) as err:
        raise InvalidCoordinatesError(
            f"{name} must be an array of real numbers (substitute values for any symbols first): {err}"
        ) from None
    if array.ndim != 2 or 0 in array.shape:
        raise DimensionError(f"{name} must be a non-empty 2D array, got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise NonFiniteError(f"{name} contains NaN or infinite entries; remove or repair those rows")
    return array


def _unit_scaled(array: np.ndarray) -> np.ndarray:
    """``array`` times the power of two that brings its largest entry to [0.5, 1).

    The scaling is exact, so the SVD sees no overflow or underflow and the ratios of singular
    values, which are all that rank decisions use, are unchanged.
    """
    largest = float(np.abs(array).max())
    return np.ldexp(array, -int(np.frexp(largest)[1])) if largest > 0 else array


def _tolerance(singular_values: np.ndarray, shape: tuple[int, int], rtol: float | None) -> float:
    from .numeric.tolerances import RANK_EPS

    largest = float(singular_values.max()) if singular_values.size else 0.0
    if rtol is None:
        rtol = max(shape) * RANK_EPS
    elif not (isinstance(rtol, numbers.Real) and math.isfinite(rtol) and rtol >= 0):
        raise InvalidCoordinatesError(f"rtol must be a finite number >= 0, got {rtol!r}")
    return float(rtol) * largest


def numeric_rank(A: Any, rtol: float | None = None) -> int:
    """The numerical rank: the number of singular values above ``rtol · σ_max``.

    The default ``rtol`` is ``max(m, n) · ε`` (machine epsilon), the default of
    :func:`numpy.linalg.matrix_rank`.

    >>> numeric_rank([[1.0, 2.0], [2.0, 4.0 + 1e-17]])
    1
    """
    array = _unit_scaled(_float_matrix(A))
    singular_values = np.linalg.svd(array, compute_uv=False)
    return int(np.sum(singular_values > _tolerance(singular_values, array.shape, rtol)))


def nullspace_svd(A: Any, rtol: float | None = None) -> np.ndarray:
    """An orthonormal basis of the numerical null space of ``A`` (shape ``(m, n)``), by the SVD.

    With ``A = U Σ Vᵀ`` (full SVD), the columns of ``V`` whose singular values
    are (numerically) zero span the null space. A singular value counts as zero
    when it is at most ``rtol · σ_max``; the default ``rtol = max(m, n) · ε``
    is the rule of :func:`numpy.linalg.matrix_rank`. For a wide matrix
    (``m < n``) the last ``n - m`` columns of ``V`` always belong to the null
    space. Returns an array of shape ``(n, k)`` whose ``k`` columns are the
    basis vectors (``k = 0`` for full column rank).

    >>> N = nullspace_svd([[1.0, 0.0, 0.0, -1.0], [0.0, 1.0, 0.0, -2.0], [0.0, 0.0, 1.0, -3.0]])
    >>> N.shape, bool(np.allclose(N[:, 0] / N[3, 0], [1, 2, 3, 1]))
    ((4, 1), True)
    """
    array = _unit_scaled(_float_matrix(A))
    _, singular_values, vt = np.linalg.svd(array, full_matrices=True)
    rank = int(np.sum(singular_values > _tolerance(singular_values, array.shape, rtol)))
    return vt[rank:].T.copy()


def _sign_normalised(v: np.ndarray) -> np.ndarray:
    """Unit vector with its largest-magnitude entry positive (a deterministic representative)."""
    v = v / np.linalg.norm(v)
    return v if v[np.argmax(np.abs(v))] > 0 else -v


def _smallest_right_singular_vector(rows: Any, name: str, error: type[Exception], what: str, rtol: float | None):
    array = _float_matrix(rows, name)
    if array.shape[1] != 4 or array.shape[0] < 3:
        raise DimensionError(f"{name} must have shape (n, 4) with n >= 3 {what}, got {array.shape}")
    # The rank is decided after a change of units, exactly (powers of two): each row (a point or plane,
    # defined up to scale) to largest entry of order one, then the homogeneous column against the other
    # three. That keeps the null space (once the column scaling is undone), and the decision no longer
    # depends on whether coordinates are in millimetres or kilometres.
    rows_max = np.abs(array).max(axis=1, keepdims=True)
    balanced = np.ldexp(array, -np.frexp(np.where(rows_max > 0, rows_max, 1.0))[1])
    head, last = float(np.abs(balanced[:, :3]).max()), float(np.abs(balanced[:, 3]).max())
    shift = int(np.frexp(head)[1] - np.frexp(last)[1]) if head > 0 and last > 0 else 0
    balanced[:, 3] = np.ldexp(balanced[:, 3], shift)
    _, singular_values, vt = np.linalg.svd(balanced, full_matrices=True)
    rank = int(np.sum(singular_values > _tolerance(singular_values, balanced.shape, rtol)))
    if rank < 3:
        raise error(rank)
    if array.shape[0] == 3:  # the exact null vector: the balanced matrix gives it to full relative accuracy
        v = vt[-1].copy()
        v[3] = np.ldexp(v[3], shift)  # back to the given units: x·π = x'·π' with x'_4 = 2^shift x_4
    else:  # least squares: min ‖A π‖ for the rows as given (weights are part of the problem), scaled exactly
        v = np.linalg.svd(_unit_scaled(array), full_matrices=True)[2][-1]
    return _sign_normalised(np.ldexp(v, -int(np.frexp(np.abs(v).max())[1])))


def plane_through_numeric(points: Any, rtol: float | None = None) -> np.ndarray:
    """The plane through three (or, in the least-squares sense, more) points given as homogeneous rows.

    ``points`` has shape ``(n, 4)`` with ``n >= 3``. The plane is the right
    singular vector of the smallest singular value: the exact null vector for
    three points, the least-squares plane (minimising ``‖A π‖`` with ``‖π‖ = 1``)
    for more. It is returned as a unit 4-vector with its largest-magnitude entry
    positive. Raises :class:`CollinearPointsError` when the numerical rank (see
    :func:`numeric_rank`) is below 3.

    >>> pi = plane_through_numeric([[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]])
    >>> bool(np.allclose(pi / pi[0], [1, 1, 1, -1]))
    True
    """

    def error(rank: int) -> Exception:
        return CollinearPointsError(
            f"the matrix of the points has numerical rank {rank} < 3: they are collinear or coincide, so no "
            f"unique plane passes through them; add a point off their line (or pass a smaller rtol)"
        )

    return _smallest_right_singular_vector(points, "points", error, "(one homogeneous point per row)", rtol)


def point_on_planes_numeric(planes: Any, rtol: float | None = None) -> np.ndarray:
    """The point on three (or, least squares, more) planes given as rows ``(a, b, c, d)``.

    The dual of :func:`plane_through_numeric`: the right singular vector of the
    smallest singular value, as a unit 4-vector with its largest-magnitude entry
    positive; an ideal point has last entry (numerically) zero. Raises
    :class:`DependentPlanesError` when the numerical rank is below 3 (the
    planes share a line, or repeat).

    >>> X = point_on_planes_numeric([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]])
    >>> bool(np.allclose(X[:3] / X[3], [1, 2, 3]))
    True
    """

    def error(rank: int) -> Exception:
        return DependentPlanesError(
            f"the matrix of the planes has numerical rank {rank} < 3: they share a line or repeat, so they do not "
            f"meet in a single point; replace one plane by a plane not through that line (or pass a smaller rtol)"
        )

    return _smallest_right_singular_vector(planes, "planes", error, "(one plane per row)", rtol)


class SVDSteps(NamedTuple):
    """The factors of ``A = U Σ Vᵀ`` for a 2×2 matrix, applied as ``x ↦ Vᵀx ↦ Σ Vᵀx ↦ U Σ Vᵀx``."""

    V: np.ndarray
    """Right singular vectors (columns); the first step applies ``V.T``."""
    Sigma: np.ndarray
    """Diagonal 2×2 matrix of the singular values ``σ1 ≥ σ2 ≥ 0``."""
    U: np.ndarray
    """Left singular vectors (columns); the last step applies ``U``."""


def svd_steps(A: Any) -> SVDSteps:
    """The SVD of a real 2×2 matrix as rotate, stretch, rotate: ``A = U Σ Vᵀ``.

    ``Vᵀ`` turns the right singular vectors onto the axes, ``Σ`` stretches the
    axes by ``σ1 ≥ σ2 ≥ 0`` and ``U`` turns the axes onto the left singular
    vectors. Signs are chosen so that ``V`` is always a rotation
    (``det V = 1``) whose first column has its largest-magnitude entry
    positive (so the result does not depend on the LAPACK build); ``U`` is
    then a rotation too when ``det A ≥ 0`` and a reflection when ``det A < 0``
    (no rotation–stretch–rotation can reverse orientation).

    >>> V, S, U = svd_steps([[3.0, 0.0], [0.0, -2.0]])
    >>> np.diag(S).tolist(), round(float(np.linalg.det(V)), 12)
    ([3.0, 2.0], 1.0)
    >>> bool(np.allclose(U @ S @ V.T, [[3, 0], [0, -2]]))
    True
    """
    given = _float_matrix(A)
    if given.shape != (2, 2):
        raise DimensionError(f"svd_steps takes a 2×2 matrix, got shape {given.shape}")
    # factor the matrix scaled by a power of two to unit size (exact), so that A v / σ stays a unit
    # vector even for entries near the ends of the float64 range; Σ is scaled back at the end
    largest = float(np.abs(given).max())
    exponent = int(np.frexp(largest)[1]) if largest > 0 else 0
    array = np.ldexp(given, -exponent)
    _, s, vt = np.linalg.svd(array)
    tol = _tolerance(s, (2, 2), None)
    v1 = vt[0] if vt[0][np.argmax(np.abs(vt[0]))] > 0 else -vt[0]  # a deterministic sign
    v = np.column_stack([v1, [-v1[1], v1[0]]])  # the second column makes V a rotation
    u = np.empty((2, 2))
    u[:, 0] = array @ v[:, 0] / s[0] if s[0] > tol else [1.0, 0.0]
    # u2 is ±u1 turned by 90°; dividing A v2 by a small σ2 would lose orthogonality, so take only its sign
    perpendicular = np.array([-u[1, 0], u[0, 0]])
    flip = s[1] > tol and float(perpendicular @ (array @ v[:, 1])) < 0
    u[:, 1] = -perpendicular if flip else perpendicular  # σ2 = 0: U a rotation too
    return SVDSteps(V=v, Sigma=np.diag(np.ldexp(s, exponent)), U=u)
