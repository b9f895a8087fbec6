"""Random building blocks shared by the built-in templates (all exact integers or fractions)."""

from __future__ import annotations

import math
import random
from fractions import Fraction

from ...ring import det, matmul
from ..model import matrix_latex, tuple_latex, vector_latex

__all__ = ["det", "equation_latex", "homog_latex", "integer_solution", "invertible", "matrix_latex", "nz",
           "primitive_dir", "tuple_latex", "vector_latex"]


def integer_solution(a: int, b: int, c: int) -> tuple[int, int]:
    """A small integer solution (x, y) of a x + b y = c when gcd(a, b) = 1 (x is the least in [0, |b|]).

    >>> integer_solution(3, 5, 1)  # 3·2 + 5·(-1) = 1
    (2, -1)
    >>> integer_solution(-1, 0, 4)  # b = 0 needs a = ±1: x = c·a = -4
    (-4, 0)
    """
    if b == 0:
        return c * a, 0  # a = ±1
    x = next(x for x in range(abs(b) + 1) if (c - a * x) % b == 0)
    return x, (c - a * x) // b


def nz(rng: random.Random, bound: int) -> int:
    """A nonzero integer in [-bound, bound]."""
    value = rng.randint(1, bound)
    return value if rng.random() < 0.5 else -value


def primitive_dir(rng: random.Random, bound: int, size: int = 2) -> tuple[int, ...]:
    """A nonzero integer vector with coprime entries, first nonzero entry positive."""
    while True:
        v = [rng.randint(-bound, bound) for _ in range(size)]
        if any(v) and math.gcd(*v) == 1:
            sign = -1 if next(x for x in v if x) < 0 else 1
            return tuple(sign * x for x in v)


def invertible(rng: random.Random, n: int, bound: int = 1, diag: int = 2) -> list[list[Fraction]]:
    """An integer n×n matrix L·U·P with det ≠ 0 by construction (unit lower L, upper U with nonzero diagonal,
    a random permutation P)."""
    L = [[Fraction(1 if i == j else (rng.randint(-bound, bound) if i > j else 0)) for j in range(n)] for i in range(n)]
    U = [[Fraction(nz(rng, diag) if i == j else (rng.randint(-bound, bound) if j > i else 0)) for j in range(n)]
         for i in range(n)]
    perm = list(range(n))
    rng.shuffle(perm)
    P = [[Fraction(1 if perm[i] == j else 0) for j in range(n)] for i in range(n)]
    M = [list(row) for row in matmul(matmul(L, U), P)]
    assert det(M) != 0
    return M


def equation_latex(coeffs: tuple[int, ...] | list[int], names: str = "xyz") -> str:
    """``a x + b y + c = 0`` written neatly: ``(3, -1, 0)`` gives ``3x - y = 0``."""
    terms = []
    for c, name in zip(coeffs, [*names[: len(coeffs) - 1], ""], strict=True):
        c = int(c)
        if c == 0:
            continue
        mag = "" if abs(c) == 1 and name else str(abs(c))
        sign = "-" if c < 0 else "+"
        terms.append((sign, f"{mag}{name}"))
    if not terms:
        return "0 = 0"
    first_sign, first = terms[0]
    text = ("-" if first_sign == "-" else "") + first
    text += "".join(f" {s} {t}" for s, t in terms[1:])
    return text + " = 0"


def homog_latex(values: tuple[int | Fraction, ...] | list[int | Fraction]) -> str:
    """Homogeneous coordinates written as a row ``(x_1 : x_2 : x_3)``-style tuple."""
    return tuple_latex(values)
