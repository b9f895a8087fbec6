"""The sign of a polynomial in one or two real variables, decided exactly: is f ≥ 0 (or ≤ 0) on all of ℝ²?

A cylindrical decomposition of the plane for one polynomial f(x, y) of positive degree in y: the real roots
of P(x) = lc_y(f)·disc_y(f) (f squarefree, so P ≠ 0) cut the x-axis into open intervals; over each of them
the real roots of f(x, ·) are distinct and move continuously (no two meet, none goes to infinity), so f has one
sign between two consecutive roots for every x of the interval. One rational x per interval and one rational
y per sector between roots reach every open cell; f is nonzero there, and those cells are dense in the plane,
so f ≥ 0 everywhere as soon as f > 0 at every sample (by continuity). Every step is exact: real roots are
isolated in rational intervals (SymPy's ``Poly.intervals``) and f is evaluated at rational points.

>>> x, y = sympy.symbols("x y")
>>> plane_sign(2*x**4 + 4*x**3 + 3*x**2*y**2 + 2*x**2 + 4*x*y**2 + y**4 + y**2, [x, y])
1
>>> plane_sign(x**2 + y**2 - 1, [x, y]) is None, plane_sign(-(x - y)**2 * (x**2 + 1), [x, y])
(True, -1)
"""

from __future__ import annotations

from collections.abc import Sequence
from fractions import Fraction

import sympy

__all__ = ["MAX_DEGREE", "plane_sign"]

MAX_DEGREE = 16
"""The largest total degree decided (the discriminant of a larger polynomial costs too much)."""

MAX_REFINEMENTS = 24
"""The most rounds of narrower isolating intervals (width 4⁻ᵏ) until consecutive ones are apart."""


def _samples(poly: sympy.Poly) -> list[Fraction] | None:
    """A rational number in each open interval of ℝ cut by the real roots of a univariate polynomial; None when
    the roots could not be separated."""
    if poly.degree() <= 0:
        return [Fraction(0)]
    # isolating intervals may touch, and an end may be another interval's root (1/2 in (0, 1) beside 1 in [1, 1]):
    # narrower ones until each lies strictly left of the next, so a point between two is no root
    for k in range(MAX_REFINEMENTS):
        eps = sympy.Rational(1, 4 ** k) if k else None
        cuts = [(sympy.Rational(a), sympy.Rational(b)) for (a, b), _m in poly.intervals(eps=eps)]  # increasing
        if not cuts:
            return [Fraction(0)]
        if all(cuts[i][1] < cuts[i + 1][0] for i in range(len(cuts) - 1)):
            break
    else:
        return None
    ends = [cuts[0][0] - 1, *((cuts[i][1] + cuts[i + 1][0]) / 2 for i in range(len(cuts) - 1)), cuts[-1][1] + 1]
    return [Fraction(int(e.p), int(e.q)) for e in ends]


def _sign_at(expr: sympy.Poly, point: Sequence[Fraction]) -> int:
    value = expr.eval(tuple(sympy.Rational(p.numerator, p.denominator) for p in point))
    return int(sympy.sign(value))


def plane_sign(f: sympy.Expr, gens: Sequence[sympy.Symbol]) -> int | None:
    """1 when f ≥ 0 on the whole real plane (or line) of its one or two variables, −1 when f ≤ 0, else None
    (f changes sign, has more variables, or is too large to decide)."""
    free = [g for g in gens if f.has(g)]
    if not free:
        return int(sympy.sign(f)) or None
    if len(free) > 2:
        return None
    if sympy.Poly(f, *free).total_degree() > MAX_DEGREE:
        return None
    coeff, factors = sympy.factor_list(f, *free)
    # f = c·∏ fᵢ^kᵢ has the sign of c·∏ fᵢ (kᵢ odd) wherever it is not 0: that product is squarefree
    poly = sympy.Poly(coeff * sympy.Mul(*(g for g, k in factors if k % 2)), *free)
    if poly.total_degree() <= 0:
        return int(sympy.sign(poly.as_expr())) or None
    if len(free) == 1:
        samples = _samples(poly)
        if samples is None:
            return None
        signs = {_sign_at(poly, [s]) for s in samples}
    else:
        x, y = free
        if poly.degree(y) == 0:
            return plane_sign(poly.as_expr(), [x])
        lead = sympy.Poly(poly.as_poly(y).LC(), x)
        disc = sympy.Poly(sympy.discriminant(poly.as_expr(), y), x) if poly.degree(y) > 1 else sympy.Poly(1, x)
        cuts = lead * disc
        if cuts.is_zero:
            return None  # not squarefree after all: refuse rather than miss a strip
        signs = set()
        for sx in _samples(cuts) or [None]:
            if sx is None:
                return None
            fibre = sympy.Poly(poly.as_expr().subs(x, sympy.Rational(sx.numerator, sx.denominator)), y)
            for sy in _samples(fibre) or [None]:
                if sy is None:
                    return None
                signs.add(_sign_at(poly, [sx, sy]))
                if len(signs) > 1:
                    return None
    if 0 in signs or len(signs) != 1:
        return None  # a sample on the zero set (an end shared by two isolating intervals): refuse, not guess
    return signs.pop()
