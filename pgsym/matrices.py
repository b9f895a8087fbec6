"""Exact SymPy matrices: the one coercion, the adjugate, and equality up to scale.

Every matrix the exact core accepts (a transformation, a conic, a quadric, a Plücker
matrix, the system of a null-space computation) goes through :func:`exact_matrix`, so
the same bad inputs raise the same named errors with the same kind of message.

>>> exact_matrix([[1, 0.5], [0, 2]], shape=(2, 2), what="the matrix of a map of P¹")
Matrix([
[1, 1/2],
[0,   2]])
>>> exact_matrix([[1, 2], [3]], what="M")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
pgsym.errors.DimensionError: M must be a matrix, but its rows have lengths [2, 1]
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy
from sympy import ImmutableMatrix

from .errors import DimensionError
from .exact import is_zero, to_exact

__all__ = ["adjugate", "exact_matrix", "expanded", "is_zero_entry", "proportional", "rank"]


def exact_matrix(
    value: Any, shape: tuple[int, int] | None = None, what: str = "the matrix", square: bool = False
) -> ImmutableMatrix:
    """Coerce nested sequences, a SymPy or NumPy matrix (or an object with an exact ``.matrix``) exactly.

    ``shape`` demands a shape, ``square`` any square shape; ``what`` names the matrix in the
    errors. A value that is no sequence of rows, an empty matrix, ragged rows or the wrong
    shape raise :class:`~pgsym.errors.DimensionError`; entries that are no numbers raise
    :class:`~pgsym.errors.NonNumericError` (floats are read as the decimals they print as).

    >>> exact_matrix(5, shape=(2, 2), what="the matrix of a map of P¹")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.DimensionError: the matrix of a map of P¹ must be a 2×2 matrix (a sequence of rows), got int 5
    >>> exact_matrix([[1, 0, 0], [0, 1, 0]], square=True, what="a transformation matrix")
    Traceback (most recent call last):
    ...
    pgsym.errors.DimensionError: a transformation matrix must be a square matrix (n rows of n entries), got 2×3
    """
    inner = getattr(value, "matrix", None)
    if isinstance(inner, sympy.MatrixBase) and not callable(inner):
        value = inner
    expected = f"a {shape[0]}×{shape[1]} matrix" if shape else "a square matrix" if square else "a matrix"
    try:
        if isinstance(value, (str, bytes, set, frozenset, dict)):
            raise TypeError  # no rows, or rows in no fixed order
        rows = [list(r) for r in (value.tolist() if hasattr(value, "tolist") else value)]
        if any(isinstance(e, (list, tuple)) for r in rows for e in r):
            raise TypeError  # a 3-index array is no matrix
    except TypeError:
        raise DimensionError(
            f"{what} must be {expected} (a sequence of rows), got {type(value).__name__} {value!r}"
        ) from None
    if not rows or not rows[0]:
        raise DimensionError(f"{what} must be {expected} with at least one row and one column, got {value!r}")
    if any(len(r) != len(rows[0]) for r in rows):
        raise DimensionError(f"{what} must be {expected}, but its rows have lengths {[len(r) for r in rows]}")
    got = (len(rows), len(rows[0]))
    if (shape is not None and got != tuple(shape)) or (square and got[0] != got[1]):
        detail = " (n rows of n entries)" if square and shape is None else ""
        raise DimensionError(f"{what} must be {expected}{detail}, got {got[0]}×{got[1]}")
    return ImmutableMatrix([[to_exact(e) for e in r] for r in rows])


def expanded(m: Any) -> ImmutableMatrix:
    """The matrix with every entry expanded (products of symbolic matrices stay polynomial and small).

    >>> a = sympy.Symbol("a")
    >>> expanded(sympy.Matrix([[(a + 1) ** 2]]))
    Matrix([[a**2 + 2*a + 1]])
    """
    return ImmutableMatrix(sympy.Matrix(m).applyfunc(sympy.expand))


def adjugate(matrix: Any) -> ImmutableMatrix:
    """The adjugate ``adj(M)`` (transposed cofactor matrix), expanded: ``M adj(M) = det(M) I``.

    It is the inverse up to the scale ``det M``, without division, so symbolic matrices stay polynomial.

    >>> adjugate([[2, 0], [0, 3]])
    Matrix([
    [3, 0],
    [0, 2]])
    """
    m = matrix if isinstance(matrix, sympy.MatrixBase) else exact_matrix(matrix, square=True)
    return expanded(m.adjugate(method="bareiss"))


def is_zero_entry(value: Any) -> bool:
    """The exact zero test as SymPy's row reduction wants it (``iszerofunc``).

    >>> is_zero_entry(sympy.sqrt(2) ** 2 - 2)
    True
    """
    return is_zero(sympy.sympify(value))


def rank(matrix: Any) -> int:
    """The exact rank (the generic rank for symbolic entries), by row reduction with the exact zero test.

    >>> rank([[1, 2], [2, 4]]), rank(sympy.eye(3))
    (1, 3)
    """
    m = matrix if isinstance(matrix, sympy.MatrixBase) else exact_matrix(matrix)
    return int(sympy.Matrix(m).rank(iszerofunc=is_zero_entry))


def proportional(u: Sequence[Any], v: Sequence[Any]) -> bool:
    """True when the entries of ``v`` are a nonzero multiple of those of ``u`` (every 2×2 minor vanishes).

    Both are taken to be nonzero; entries are compared with the exact zero test, so an undecidable
    entry raises :class:`~pgsym.errors.UndecidableError`.

    >>> proportional([1, 2, 0], [-2, -4, 0]), proportional([1, 2], [1, 3]), proportional([1, 2], [1, 2, 3])
    (True, False, False)
    """
    a, b = ([e if isinstance(e, sympy.Basic) else to_exact(e) for e in w] for w in (u, v))
    if len(a) != len(b):
        return False
    k = next((i for i, e in enumerate(a) if (e.is_Rational and e != 0)), None)
    if k is None:
        k = next(i for i, e in enumerate(a) if not is_zero(e))
    # against one nonzero pivot entry a_k: v ∝ u iff v_k ≠ 0 and a_k b_i = a_i b_k for every i (n tests, not n²)
    return not is_zero(b[k]) and all(is_zero(a[k] * b[i] - a[i] * b[k]) for i in range(len(a)) if i != k)
