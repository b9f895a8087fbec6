"""Projective transformations acting on float64 arrays of points, lines, planes, conics and quadrics.

The numeric twin of :meth:`pgsym.transformations.Transformation.apply`, with the same
rules (``H`` the matrix, ``adj(H) = det(H) H⁻¹`` its adjugate, equality up to scale):

* points ``x' = H x``;
* lines (P²) and planes (P³) ``l' = adj(H)ᵀ l ∝ H⁻ᵀ l``;
* conics and quadrics ``C' = adj(H)ᵀ C adj(H) ∝ H⁻ᵀ C H⁻¹``; dual conics ``C*' = H C* Hᵀ``.

The adjugate is computed from cofactors (cross products in P², :func:`triple_cross` in
P³), so no inverse is formed and no scale is fixed, exactly as in the exact core. A
singular ``H`` raises :class:`~pgsym.errors.SingularTransformationError`: singular means
``σ_min ≤ rtol · σ_max`` for ``H`` balanced by a change of units
(:func:`pgsym.numeric.conditioning.singular`, ``rtol`` defaults to
:data:`~pgsym.numeric.tolerances.SINGULAR_RTOL`), so the verdict does not depend on the
units of the coordinates. NaN or infinity in ``H``, in the data or in a result raises
:class:`~pgsym.errors.NonFiniteError` (``nonfinite="mask"`` on the point, line and plane maps).

>>> import numpy as np
>>> H = np.array([[0.0, -1, 0], [1, 0, 0], [0, 0, 1]])          # rotation by 90°
>>> transform_points(H, [1.0, 0, 1]), transform_lines(H, [1.0, 0, -1])   # x = 1 becomes y = 1
(array([0., 1., 1.]), array([ 0.,  1., -1.]))
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import DimensionError, NonFiniteError, SingularTransformationError
from ._arrays import CHUNK, NONFINITE, as_float_array, block_finite, check_option, nonfinite_result
from .conditioning import require_finite, singular
from .plane import cross
from .space import triple_cross
from .tolerances import SINGULAR_RTOL

__all__ = ["adjugate", "transform_conics", "transform_dual_conics", "transform_lines", "transform_planes",
           "transform_points", "transform_quadrics"]


def _square(H: Any, function: str, sizes: tuple[int, ...] = (2, 3, 4)) -> np.ndarray:
    h = as_float_array(H, "H", function)
    if h.ndim < 2 or h.shape[-1] != h.shape[-2] or h.shape[-1] not in sizes:
        wanted = " or ".join(f"{k}×{k}" for k in sizes)
        raise DimensionError(f"{function}: H must be a {wanted} matrix (or a stack of them), got shape {h.shape}")
    return require_finite(h, "H", function)


def adjugate(H: Any) -> np.ndarray:
    """The adjugates ``adj(H) = det(H) H⁻¹`` of 2×2, 3×3 or 4×4 matrices (stacks broadcast), from cofactors.

    >>> adjugate([[2.0, 0, 0], [0, 3, 0], [0, 0, 1]])
    array([[3., 0., 0.],
           [0., 2., 0.],
           [0., 0., 6.]])
    """
    h = _square(H, "adjugate")
    k = h.shape[-1]
    # The cofactors of a matrix scaled to unit size cannot overflow; the scaling (a power of two per matrix,
    # exact) changes no digit, so it is paid only when some matrix has entries far from 1 in size.
    with np.errstate(over="ignore", under="ignore"):
        size = np.einsum("...ij,...ij->...", h, h)
    scaled = not np.all((size > 2.0**-300) & (size < 2.0**300))
    if scaled:
        exponent = np.frexp(np.max(np.abs(h), axis=(-2, -1)))[1]
        h = np.ldexp(h, -exponent[..., None, None])
    adj = np.empty(h.shape)
    if k == 2:
        adj[..., 0, 0], adj[..., 0, 1] = h[..., 1, 1], -h[..., 0, 1]
        adj[..., 1, 0], adj[..., 1, 1] = -h[..., 1, 0], h[..., 0, 0]
    elif k == 3:  # row i of adj(H) = (column i+1) × (column i+2): the cofactors, already transposed
        for i in range(3):
            cross(h[..., :, (i + 1) % 3], h[..., :, (i + 2) % 3], out=adj[..., i, :])
    else:  # cofactor row i = (−1)^i triple_cross(the other rows, in order); adj(H) is their transpose
        cof = np.swapaxes(adj, -1, -2)
        for i in range(4):
            others = [r for r in range(4) if r != i]
            triple_cross(h[..., others[0], :], h[..., others[1], :], h[..., others[2], :], out=cof[..., i, :])
            if i % 2:
                np.negative(cof[..., i, :], out=cof[..., i, :])
    if scaled:
        with np.errstate(over="ignore"):
            adj = np.ldexp(adj, ((k - 1) * exponent)[..., None, None])
    return _finite_result(adj, "adjugate", "the adjugate")


def _finite_result(r: np.ndarray, function: str, what: str) -> np.ndarray:
    """``r`` when finite; NonFiniteError when its entries overflow float64 (the inputs were finite)."""
    with np.errstate(over="ignore", invalid="ignore"):
        if np.isfinite(np.sum(r)):
            return r
    if np.isfinite(r).all():
        return r
    raise NonFiniteError(
        f"{function}: {what} overflows float64 (entries beyond about 1.8e308); rescale the input, e.g. divide "
        "the matrix by its largest entry, which changes nothing projectively"
    )


def _checked(H: Any, function: str, k: int, rtol: float) -> tuple[np.ndarray, np.ndarray]:
    """The matrix and its adjugate; SingularTransformationError where the balanced ``σ_min ≤ rtol σ_max``."""
    h = _square(H, function, (k,))
    if np.any(singular(h, rtol)):
        raise SingularTransformationError(
            f"{function}: the transformation matrix is singular (σ_min ≤ {rtol} σ_max, in balanced units), so it "
            "maps the plane or space onto a lower-dimensional set and has no action on lines, planes or conics; "
            "check the matrix, or lower rtol if it is merely ill-conditioned"
        )
    return h, adjugate(h)


def _apply(
    M: np.ndarray, x: Any, function: str, what: str, out: np.ndarray | None, axis: int, nonfinite: str
) -> Any:
    """The vectors ``M x`` for an array ``x`` of ``(..., k)`` vectors, finite or masked (see :func:`_matvec`)."""
    check_option(nonfinite, NONFINITE, "nonfinite", function)
    result, suspect = _matvec(M, x, function, what, out, axis)
    if not suspect and nonfinite == "raise":
        return result
    moved = np.moveaxis(result, axis, -1)
    finite = np.isfinite(moved).all(axis=-1)
    a = np.moveaxis(as_float_array(x, what, function), axis, -1)
    checked = nonfinite_result(moved, finite, nonfinite, function, [a])
    return (result, checked[1]) if nonfinite == "mask" else result


def _matvec(M: np.ndarray, x: Any, function: str, what: str, out: np.ndarray | None, axis: int) -> tuple[Any, bool]:
    """``M x`` block by block, and whether a NaN or infinity may be in it (one sum per block, in cache)."""
    k = M.shape[-1]
    a = as_float_array(x, what, function)
    if a.ndim == 0 or not -a.ndim <= axis < a.ndim or a.shape[axis] != k:
        raise DimensionError(
            f"{function}: {what} must have {k} homogeneous coordinates along axis {axis}, "
            f"got an array of shape {a.shape}"
        )
    if M.ndim == 2 and a.ndim == 2 and axis in (0, -2):
        # component-major (k, N): one matrix product (column blocks would be strided outputs, which
        # matmul cannot hand to BLAS), then one dot product per contiguous component row
        result = np.empty(a.shape) if out is None else out
        if result.shape != a.shape:
            raise DimensionError(f"{function}: out has shape {result.shape}, the result has shape {a.shape}")
        with np.errstate(over="ignore", invalid="ignore"):
            np.matmul(M, a, out=result)
        return result, not _sum_finite(result.T)  # components on the last axis
    a = np.moveaxis(a, axis, -1)
    fast_out = out is None or out.flags.c_contiguous
    if M.ndim == 2 and a.ndim == 2 and a.flags.c_contiguous and fast_out:
        result = np.empty(a.shape) if out is None else out
        if result.shape != a.shape:
            raise DimensionError(f"{function}: out has shape {result.shape}, the result has shape {a.shape}")
        mt = np.ascontiguousarray(M.T)
        suspect = False
        with np.errstate(over="ignore", invalid="ignore"):
            for start in range(0, a.shape[0], CHUNK):  # block by block: the product stays in cache
                block = result[start : start + CHUNK]
                np.dot(a[start : start + CHUNK], mt, out=block)
                suspect = suspect or not _sum_finite(block)
        return result, suspect
    with np.errstate(over="ignore", invalid="ignore"):
        product = np.matmul(M, a[..., None])[..., 0]
    product = np.moveaxis(product, -1, axis)
    if out is None:
        return product, not _sum_finite(product)
    np.copyto(out, product)
    return out, not _sum_finite(out)


def _sum_finite(block: np.ndarray) -> bool:
    return block.size == 0 or block_finite(block)


def transform_points(
    H: Any, x: Any, *, out: np.ndarray | None = None, axis: int = -1, rtol: float = SINGULAR_RTOL,
    nonfinite: str = "raise",
) -> Any:
    """The images ``H x`` of an array of points (P¹, P² or P³: ``H`` is 2×2, 3×3 or 4×4).

    ``H`` may also be a stack of matrices that broadcasts against the points.

    >>> transform_points([[1.0, 2, 0], [0, 1, 0], [0, 0, 1]], [[0.0, 0, 1], [1, 1, 1]])   # a shear
    array([[0., 0., 1.],
           [3., 1., 1.]])
    """
    h = _square(H, "transform_points")
    h, _ = _checked(h, "transform_points", h.shape[-1], rtol)
    return _apply(h, x, "transform_points", "x", out, axis, nonfinite)


def transform_lines(
    H: Any, l: Any, *, out: np.ndarray | None = None, axis: int = -1, rtol: float = SINGULAR_RTOL,
    nonfinite: str = "raise",
) -> Any:
    """The images ``adj(H)ᵀ l ∝ H⁻ᵀ l`` of an array of lines of P² under the point map ``H`` (3×3).

    >>> H = np.array([[1.0, 2, 0], [0, 1, 0], [0, 0, 1]])
    >>> transform_lines(H, [-1.0, 1, 0])      # y = x through (0, 0) and (1, 1) → through (0, 0) and (3, 1)
    array([-1.,  3.,  0.])
    """
    _, adj = _checked(H, "transform_lines", 3, rtol)
    return _apply(np.swapaxes(adj, -1, -2), l, "transform_lines", "l", out, axis, nonfinite)


def transform_planes(
    H: Any, planes: Any, *, out: np.ndarray | None = None, axis: int = -1, rtol: float = SINGULAR_RTOL,
    nonfinite: str = "raise",
) -> Any:
    """The images ``adj(H)ᵀ π ∝ H⁻ᵀ π`` of an array of planes of P³ under the point map ``H`` (4×4).

    >>> H = np.diag([1.0, 1, 1, 1]); H[2, 3] = 5                         # translate by 5 along z
    >>> transform_planes(H, [0.0, 0, 1, 0])                              # z = 0 becomes z = 5
    array([ 0.,  0.,  1., -5.])
    """
    _, adj = _checked(H, "transform_planes", 4, rtol)
    return _apply(np.swapaxes(adj, -1, -2), planes, "transform_planes", "planes", out, axis, nonfinite)


def _congruence(A: np.ndarray, C: Any, function: str, k: int) -> np.ndarray:
    c = as_float_array(C, "C", function)
    if c.ndim < 2 or c.shape[-2:] != (k, k):
        raise DimensionError(f"{function}: C must be a {k}×{k} matrix (or a stack of them), got shape {c.shape}")
    require_finite(c, "C", function)
    with np.errstate(over="ignore", invalid="ignore"):
        image = np.matmul(np.matmul(np.swapaxes(A, -1, -2), c), A)
    return _finite_result(image, function, "the transformed matrix")


def transform_conics(H: Any, C: Any, *, rtol: float = SINGULAR_RTOL) -> np.ndarray:
    """The images ``adj(H)ᵀ C adj(H) ∝ H⁻ᵀ C H⁻¹`` of an array ``(..., 3, 3)`` of conic matrices.

    >>> H = np.diag([2.0, 1, 1])                               # stretch x by 2
    >>> transform_conics(H, np.diag([1.0, 1, -1]))             # the unit circle becomes x²/4 + y² = 1
    array([[ 1.,  0.,  0.],
           [ 0.,  4.,  0.],
           [ 0.,  0., -4.]])
    """
    _, adj = _checked(H, "transform_conics", 3, rtol)
    return _congruence(adj, C, "transform_conics", 3)


def transform_dual_conics(H: Any, C: Any, *, rtol: float = SINGULAR_RTOL) -> np.ndarray:
    """The images ``H C* Hᵀ`` of an array ``(..., 3, 3)`` of dual conic matrices.

    >>> transform_dual_conics(np.diag([2.0, 1, 1]), np.diag([1.0, 1, -1]))
    array([[ 4.,  0.,  0.],
           [ 0.,  1.,  0.],
           [ 0.,  0., -1.]])
    """
    h, _ = _checked(H, "transform_dual_conics", 3, rtol)
    return _congruence(np.swapaxes(h, -1, -2), C, "transform_dual_conics", 3)


def transform_quadrics(H: Any, Q: Any, *, rtol: float = SINGULAR_RTOL) -> np.ndarray:
    """The images ``adj(H)ᵀ Q adj(H) ∝ H⁻ᵀ Q H⁻¹`` of an array ``(..., 4, 4)`` of quadric matrices.

    >>> H = np.diag([1.0, 1, 1, 1]); H[0, 3] = 1                         # translate by 1 along x
    >>> transform_quadrics(H, np.diag([1.0, 1, 1, -1]))[0]               # the unit sphere moves to x = 1
    array([ 1.,  0.,  0., -1.])
    """
    _, adj = _checked(H, "transform_quadrics", 4, rtol)
    return _congruence(adj, Q, "transform_quadrics", 4)
