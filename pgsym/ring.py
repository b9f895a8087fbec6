"""Exact linear algebra written once for every commutative ring: the one kit of the package.

The same formulas run on SymPy expressions and polynomial-ring elements (the core, the
invariant proofs, the proof engine's certificates), on integers modulo a prime (the proof
engine's fast random pass), on :class:`fractions.Fraction` (exercise instances,
counterexamples) and on Python integers. The functions use only ``+``, ``-`` and ``*``, never
division, so they work unchanged for all of them and never leave the ring. Rational vectors and
matrices reach their primitive integer form (the canonical answer of an exercise) by one fast
path, :func:`primitive_integers` and :func:`primitive_integer_matrix`.

>>> cross((1, 0, 0), (0, 1, 0))
(0, 0, 1)
>>> det([[1, 2], [3, 4]])
-2
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from itertools import combinations
from typing import Any

__all__ = [
    "Action",
    "Quotient",
    "adjugate",
    "cross",
    "det",
    "dot",
    "matmul",
    "matvec",
    "minors",
    "plane_through",
    "primitive_integer_matrix",
    "primitive_integers",
    "squared_distance_fraction",
    "transpose",
    "wedge",
]

Vector = tuple[Any, ...]
Matrix = tuple[tuple[Any, ...], ...]


def _sum(terms: Sequence[Any]) -> Any:
    total = terms[0]
    for term in terms[1:]:
        total = total + term
    return total


def dot(u: Sequence[Any], v: Sequence[Any]) -> Any:
    """The bilinear pairing ``uᵀv`` (incidence of a point and a line or plane).

    >>> dot((1, 2, 3), (4, 5, 6))
    32
    """
    return _sum([a * b for a, b in zip(u, v, strict=True)])


def cross(u: Sequence[Any], v: Sequence[Any]) -> Vector:
    """The cross product ``u × v`` of two 3-vectors: the join of two points, the meet of two lines.

    >>> cross((1, 2, 1), (3, 4, 1))
    (-2, 2, -2)
    """
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def det(rows: Sequence[Sequence[Any]]) -> Any:
    """The determinant by expansion along the first row (exact; meant for n ≤ 6).

    >>> det([[2, 0, 0], [0, 3, 0], [0, 0, 4]])
    24
    """
    n = len(rows)
    if n == 1:
        return rows[0][0]
    if n == 2:
        return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]
    terms = []
    rest = [tuple(r) for r in rows[1:]]
    for j in range(n):
        if not rows[0][j]:  # a zero entry contributes nothing: skip its minor (sparse matrices are common)
            continue
        term = rows[0][j] * det([row[:j] + row[j + 1 :] for row in rest])
        terms.append(term if j % 2 == 0 else -term)
    return _sum(terms) if terms else rows[0][0]  # a zero first row: its (zero) entry is the ring's zero


def transpose(m: Sequence[Sequence[Any]]) -> Matrix:
    """The transposed matrix.

    >>> transpose([[1, 2], [3, 4]])
    ((1, 3), (2, 4))
    """
    return tuple(zip(*m, strict=True))


def matvec(m: Sequence[Sequence[Any]], v: Sequence[Any]) -> Vector:
    """The product ``M v``.

    >>> matvec([[1, 1], [0, 1]], (2, 3))
    (5, 3)
    """
    return tuple(dot(row, v) for row in m)


def matmul(a: Sequence[Sequence[Any]], b: Sequence[Sequence[Any]]) -> Matrix:
    """The product ``A B``.

    >>> matmul([[1, 1], [0, 1]], [[1, 0], [2, 1]])
    ((3, 1), (2, 1))
    """
    cols = transpose(b)
    return tuple(tuple(dot(row, col) for col in cols) for row in a)


def adjugate(m: Sequence[Sequence[Any]]) -> Matrix:
    """The adjugate ``adj(M)`` with ``M adj(M) = det(M) I``: an inverse up to scale, without division.

    >>> adjugate([[1, 2], [3, 4]])
    ((4, -2), (-3, 1))
    """
    n = len(m)
    rows = [tuple(r) for r in m]
    if n == 1:
        return ((1,),)
    cof = []
    for i in range(n):
        row = []
        for j in range(n):
            sub = [r[:j] + r[j + 1 :] for k, r in enumerate(rows) if k != i]
            c = det(sub)
            row.append(c if (i + j) % 2 == 0 else -c)
        cof.append(tuple(row))
    return transpose(cof)


def plane_through(a: Sequence[Any], b: Sequence[Any], c: Sequence[Any]) -> Vector:
    """The plane through three points of P³: the signed 3×3 minors of the matrix with rows a, b, c.

    It satisfies ``πᵀx = det[x a b c]`` for every x (cofactor expansion along the first row).

    >>> plane_through((0, 0, 0, 1), (1, 0, 0, 1), (0, 1, 0, 1))
    (0, 0, 1, 0)
    """
    rows = (tuple(a), tuple(b), tuple(c))
    out = []
    for j in range(4):
        sub = [r[:j] + r[j + 1 :] for r in rows]
        d = det(sub)
        out.append(d if j % 2 == 0 else -d)
    return tuple(out)


def wedge(a: Sequence[Any], b: Sequence[Any]) -> Matrix:
    """The Plücker matrix ``A Bᵀ − B Aᵀ`` of the line through two points of P³ (4×4, skew).

    >>> wedge((1, 0, 0, 0), (0, 1, 0, 0))[0]
    (0, 1, 0, 0)
    """
    return tuple(tuple(a[i] * b[j] - b[i] * a[j] for j in range(4)) for i in range(4))


class Action:
    """A square matrix ``H`` acting on coordinates, in any ring: the four rules objects transform by.

    Points map by ``H x``; lines and planes by the cofactor matrix ``adj(H)ᵀ ∝ H⁻ᵀ`` (so that ``lᵀx = 0`` is kept);
    forms on points (conics, quadrics) by ``adj(H)ᵀ M adj(H) ∝ H⁻ᵀ M H⁻¹``; forms on lines or planes (dual conics,
    dual quadrics, Plücker matrices) by ``H M Hᵀ``. Each object class names its rule (its ``image`` classmethod);
    the cofactor matrix is computed once, on first use, unless the caller already has it.

    >>> H = Action([[1, 0, 5], [0, 1, 0], [0, 0, 1]])          # the translation by (5, 0)
    >>> H.point((0, 0, 1)), H.hyperplane((1, 0, 0))             # the origin, and the line x = 0 moves to x = 5
    ((5, 0, 1), (1, 0, -5))
    """

    __slots__ = ("_cofactor", "matrix")

    def __init__(self, matrix: Sequence[Sequence[Any]], cofactor: Sequence[Sequence[Any]] | None = None) -> None:
        self.matrix: Matrix = tuple(tuple(row) for row in matrix)
        self._cofactor = None if cofactor is None else tuple(tuple(row) for row in cofactor)

    @property
    def cofactor(self) -> Matrix:
        """``adj(H)ᵀ``, which is ``det(H) H⁻ᵀ``."""
        if self._cofactor is None:
            self._cofactor = transpose(adjugate(self.matrix))
        return self._cofactor

    def point(self, x: Sequence[Any]) -> Vector:
        """``H x``."""
        return matvec(self.matrix, x)

    def hyperplane(self, l: Sequence[Any]) -> Vector:
        """``adj(H)ᵀ l ∝ H⁻ᵀ l``."""
        return matvec(self.cofactor, l)

    def point_form(self, m: Sequence[Sequence[Any]]) -> Matrix:
        """``adj(H)ᵀ M adj(H) ∝ H⁻ᵀ M H⁻¹``."""
        c = self.cofactor
        return matmul(matmul(c, m), transpose(c))

    def hyperplane_form(self, m: Sequence[Sequence[Any]]) -> Matrix:
        """``H M Hᵀ``."""
        return matmul(matmul(self.matrix, m), transpose(self.matrix))


def squared_distance_fraction(p: Sequence[Any], q: Sequence[Any]) -> tuple[Any, Any]:
    """The squared distance of two finite points given homogeneously (last coordinate w), as the pair
    ``(Σ (p_i w_q − q_i w_p)², (w_p w_q)²)`` of numerator and denominator: no division, right for any
    representatives and any ring, in the plane and in space.

    >>> squared_distance_fraction((0, 0, 1), (6, 8, 2))         # (6/2)² + (8/2)² = 25 = 100 / 4
    (100, 4)
    """
    wp, wq = p[-1], q[-1]
    diffs = [pi * wq - qi * wp for pi, qi in zip(p[:-1], q[:-1], strict=True)]
    return _sum([d * d for d in diffs]), wp * wp * wq * wq


def minors(m: Sequence[Sequence[Any]], k: int) -> list[tuple[tuple[int, ...], tuple[int, ...], Any]]:
    """Every k×k minor of ``m`` as ``(rows, columns, value)``.

    >>> [value for _, _, value in minors([[1, 2], [2, 4]], 2)]
    [0]
    """
    rows = [tuple(r) for r in m]
    out = []
    for rs in combinations(range(len(rows)), k):
        for cs in combinations(range(len(rows[0])), k):
            out.append((rs, cs, det([[rows[i][j] for j in cs] for i in rs])))
    return out


# -- the integer fast path: one representative of a rational vector up to scale ----------------------------

def primitive_integers(values: Sequence[Any]) -> tuple[int, ...]:
    """The primitive integer representative of a nonzero rational vector up to scale, first nonzero entry positive.

    Entries are integers or :class:`fractions.Fraction` (or anything ``Fraction`` accepts). It never
    divides by the last entry, so ideal points keep their zero. Raises ``ValueError`` for the zero
    vector (a template that produced it has a bug; the stress check reports it).

    >>> primitive_integers([Fraction(1, 2), Fraction(-1, 3), 0])
    (3, -2, 0)
    >>> primitive_integers([0, -4, 6])
    (0, 2, -3)
    """
    if all(type(v) is int for v in values):  # fast paths: integers need no common denominator
        ints = list(values)
    elif all(type(v) is Fraction and v.denominator == 1 for v in values):
        ints = [v.numerator for v in values]
    else:
        fr = [Fraction(v) for v in values]
        den = math.lcm(*[v.denominator for v in fr])
        ints = [int(v * den) for v in fr]
    if not any(ints):
        # a plain ValueError with this text, as before the move: stress reports and the book show it
        raise ValueError("the zero vector has no canonical form")
    g = math.gcd(*ints)
    sign = -1 if next(i for i in ints if i != 0) < 0 else 1
    return tuple(sign * i // g for i in ints)


def primitive_integer_matrix(rows: Sequence[Sequence[Any]]) -> Matrix:
    """The primitive integer representative of a nonzero rational matrix up to scale (all entries together).

    >>> primitive_integer_matrix([[2, 0], [0, -4]])
    ((1, 0), (0, -2))
    """
    n = len(rows[0])
    flat = primitive_integers([x for row in rows for x in row])
    return tuple(tuple(flat[i:i + n]) for i in range(0, len(flat), n))


class Quotient:
    """``n / d`` of two ring elements, never reduced: a fraction of polynomials without gcd cancellation.

    Proofs that divide only by a few known denominators (``1 + t²`` of a rational rotation) clear them
    at the end instead of paying for a gcd at every step. Numbers mix in as ``x / 1``. It is zero exactly
    when its numerator is, and it lets the functions above skip zero terms as they do for numbers.

    >>> from sympy import ZZ, ring
    >>> R, t = ring("t", ZZ)
    >>> q = (1 - t**2) / Quotient(1 + t**2) + 1
    >>> q.n, q.d, bool(q - q)
    (2, t**2 + 1, False)
    >>> Quotient(t) / (t - t)
    Traceback (most recent call last):
    ...
    ZeroDivisionError: division by a zero quotient
    """

    __slots__ = ("d", "n")

    def __init__(self, n: Any, d: Any = 1) -> None:
        self.n, self.d = n, d

    @staticmethod
    def of(x: Any) -> Quotient:
        """``x`` itself when it is a quotient, else ``x / 1``."""
        return x if isinstance(x, Quotient) else Quotient(x)

    def __add__(self, o: Any) -> Quotient:
        o = Quotient.of(o)
        if o.d == self.d:
            return Quotient(self.n + o.n, self.d)
        return Quotient(self.n * o.d + o.n * self.d, self.d * o.d)

    __radd__ = __add__

    def __neg__(self) -> Quotient:
        return Quotient(-self.n, self.d)

    def __sub__(self, o: Any) -> Quotient:
        return self + -Quotient.of(o)

    def __rsub__(self, o: Any) -> Quotient:
        return Quotient.of(o) + -self

    def __mul__(self, o: Any) -> Quotient:
        o = Quotient.of(o)
        return Quotient(self.n * o.n, self.d * o.d)

    __rmul__ = __mul__

    def __truediv__(self, o: Any) -> Quotient:
        o = Quotient.of(o)
        if not o.n:
            raise ZeroDivisionError("division by a zero quotient")
        return Quotient(self.n * o.d, self.d * o.n)

    def __rtruediv__(self, o: Any) -> Quotient:
        return Quotient.of(o) / self

    def __pow__(self, k: int) -> Quotient:
        return Quotient(self.n**k, self.d**k)

    def is_zero(self) -> bool:
        """Whether the numerator is zero."""
        return not self.n

    def __bool__(self) -> bool:
        return bool(self.n)
