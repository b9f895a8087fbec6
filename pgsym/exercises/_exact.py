"""Small exact helpers on :class:`fractions.Fraction` used to build exercise instances quickly.

The templates build every instance backwards from its answer with these helpers (plain rational
arithmetic is about a hundred times faster than SymPy for 3×3 integer data); the stress check then
re-verifies every answer with the pgsym core objects, independently of these helpers.

>>> canonical_ints([Fraction(1, 2), Fraction(-1, 3), 0])
(3, -2, 0)
>>> det([[1, 2], [3, 4]])
Fraction(-2, 1)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction

Vector = Sequence[Fraction | int]
Matrix = Sequence[Sequence[Fraction | int]]


def canonical_ints(values: Vector) -> tuple[int, ...]:
    """The primitive integer representative of a nonzero vector, first nonzero entry positive.

    Never divides by the last entry, so ideal points keep their zero.

    >>> canonical_ints([0, -4, 6])
    (0, 2, -3)
    """
    if all(type(v) is int for v in values):  # fast paths: integers need no common denominator
        ints = list(values)  # type: ignore[arg-type]
    elif all(type(v) is Fraction and v.denominator == 1 for v in values):
        ints = [v.numerator for v in values]  # type: ignore[union-attr]
    else:
        fr = [Fraction(v) for v in values]
        den = math.lcm(*[v.denominator for v in fr])
        ints = [int(v * den) for v in fr]
    if not any(ints):
        raise ValueError("the zero vector has no canonical form")
    g = math.gcd(*ints)
    sign = -1 if next(i for i in ints if i != 0) < 0 else 1
    return tuple(sign * i // g for i in ints)


def matmul(a: Matrix, b: Matrix) -> list[list[Fraction]]:
    """The product of two matrices given as lists of rows.

    >>> matmul([[1, 2]], [[3], [4]])
    [[Fraction(11, 1)]]
    """
    return [[sum((Fraction(x) * y for x, y in zip(row, col, strict=True)), Fraction(0)) for col in zip(*b, strict=True)]
            for row in a]


def matvec(a: Matrix, v: Vector) -> list[Fraction]:
    """The product of a matrix and a vector.

    >>> matvec([[1, 1], [0, 1]], [2, 3])
    [Fraction(5, 1), Fraction(3, 1)]
    """
    return [sum((Fraction(x) * y for x, y in zip(row, v, strict=True)), Fraction(0)) for row in a]


def transpose(a: Matrix) -> list[list[Fraction]]:
    """The transpose.

    >>> transpose([[1, 2]])
    [[Fraction(1, 1)], [Fraction(2, 1)]]
    """
    return [[Fraction(x) for x in col] for col in zip(*a, strict=True)]


def _minor(a: Matrix, i: int, j: int) -> list[list[Fraction | int]]:
    return [list(row[:j]) + list(row[j + 1:]) for k, row in enumerate(a) if k != i]


def det(a: Matrix) -> Fraction:
    """The determinant by cofactor expansion (the matrices here are at most 4×4).

    >>> det([[2, 0, 0], [0, 3, 0], [0, 0, 4]])
    Fraction(24, 1)
    """
    n = len(a)
    if n == 1:
        return Fraction(a[0][0])
    if n == 2:
        return Fraction(a[0][0]) * a[1][1] - Fraction(a[0][1]) * a[1][0]
    return sum((Fraction((-1) ** j) * a[0][j] * det(_minor(a, 0, j)) for j in range(n) if a[0][j] != 0), Fraction(0))


def adjugate(a: Matrix) -> list[list[Fraction]]:
    """The adjugate (transposed cofactor matrix): ``A adj(A) = det(A) I``.

    >>> adjugate([[1, 2], [3, 4]])
    [[Fraction(4, 1), Fraction(-2, 1)], [Fraction(-3, 1), Fraction(1, 1)]]
    """
    n = len(a)
    if n == 2:
        return [[Fraction(a[1][1]), -Fraction(a[0][1])], [-Fraction(a[1][0]), Fraction(a[0][0])]]
    return [[Fraction((-1) ** (i + j)) * det(_minor(a, j, i)) for j in range(n)] for i in range(n)]


def cross(u: Vector, v: Vector) -> list[Fraction]:
    """The cross product of two 3-vectors.

    >>> cross([1, 0, 0], [0, 1, 0])
    [Fraction(0, 1), Fraction(0, 1), Fraction(1, 1)]
    """
    u = [x if type(x) is int else Fraction(x) for x in u]
    v = [x if type(x) is int else Fraction(x) for x in v]
    return [Fraction(u[1] * v[2] - u[2] * v[1]), Fraction(u[2] * v[0] - u[0] * v[2]),
            Fraction(u[0] * v[1] - u[1] * v[0])]


def dot(u: Vector, v: Vector) -> Fraction:
    """The dot product.

    >>> dot([1, 2, 3], [1, 1, 1])
    Fraction(6, 1)
    """
    return sum((Fraction(x) * y for x, y in zip(u, v, strict=True)), Fraction(0))


def canonical_matrix(a: Matrix) -> tuple[tuple[int, ...], ...]:
    """The primitive integer representative of a nonzero matrix up to scale (first nonzero entry positive).

    >>> canonical_matrix([[2, 0], [0, -4]])
    ((1, 0), (0, -2))
    """
    n = len(a[0])
    flat = canonical_ints([x for row in a for x in row])
    return tuple(tuple(flat[i:i + n]) for i in range(0, len(flat), n))
