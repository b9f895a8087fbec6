"""Null spaces, ranks and the SVD: the linear algebra behind joins and meets in P³.

Finding the plane through three points (or the point on three planes) means
solving a homogeneous system ``M x = 0`` with a 3×4 matrix ``M`` of rank 3:
the answer is the one-dimensional null space of ``M``. This module offers the
two ways of computing it that the lecture presents, each exactly and
numerically:

* **method #1**, the null space itself: :func:`nullspace_exact` (SymPy, exact)
  and ``nullspace_svd`` (NumPy: the right singular vectors of the zero
  singular values);
* **method #2**, fixing one homogeneous coordinate to 1 and solving the square
  system that remains: :func:`solve_by_fixing_coordinate`.

The numeric functions live in :mod:`pgsym.numeric` and are reachable here under their
names, loaded on first use so that this module does not import NumPy:
``numeric_rank``, ``nullspace_svd``, ``plane_through_numeric`` and ``point_on_planes_numeric``
(:mod:`pgsym.numeric.nullspace`: the floating-point counterparts of
:func:`pgsym.space.plane_through` and :func:`pgsym.space.point_on_planes`), and ``svd_steps`` /
``SVDSteps`` (:mod:`pgsym.numeric.svd`: the rotate–stretch–rotate factors of a 2×2 SVD).

>>> nullspace_exact([[1, 0, 0, -1], [0, 1, 0, -2], [0, 0, 1, -3]])
[(1, 2, 3, 1)]
>>> rank_exact([[1, 2], [2, 4]])
1
"""

from __future__ import annotations

import importlib
import numbers
import sys
from typing import Any

import sympy
from sympy import Expr, Matrix

from . import matrices
from .errors import (
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
    ZeroCoordinateError,
)
from .exact import canonical_coords
from .homogeneous import is_zero
from .matrices import exact_matrix, is_zero_entry
from .space import Plane, Point3

__all__ = [
    "ZeroCoordinateError",
    "nullspace_exact",
    "rank_exact",
    "solve_by_fixing_coordinate",
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
        kinds = {type(r) for r in M} if not (isinstance(M, sympy.MatrixBase) or _is_ndarray(M)) else set()
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


# -- the numeric names, at home in pgsym.numeric ---------------------------------------------------

_NUMERIC = {
    "SVDSteps": "svd",
    "svd_steps": "svd",
    "nullspace_svd": "nullspace",
    "numeric_rank": "nullspace",
    "plane_through_numeric": "nullspace",
    "point_on_planes_numeric": "nullspace",
}


def __getattr__(name: str) -> Any:
    """The numeric functions under their names here, loaded from :mod:`pgsym.numeric` on first use (PEP 562).

    ``from pgsym.linalg import nullspace_svd`` is :func:`pgsym.numeric.nullspace.nullspace_svd`; NumPy loads
    then, not with this module, so the exact functions run where NumPy is absent.
    """
    if name in _NUMERIC:
        value = getattr(importlib.import_module(f".numeric.{_NUMERIC[name]}", __package__), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_NUMERIC))


def _is_ndarray(M: Any) -> bool:
    # an ndarray exists only once NumPy is loaded: asking sys.modules keeps this module NumPy-free
    np = sys.modules.get("numpy")
    return np is not None and isinstance(M, np.ndarray)
