"""Polynomial arithmetic of the proof engine: python-flint where it imports, SymPy's ``PolyRing`` otherwise.

The engine expands constructions in ℤ[parameters] or ℚ[parameters]. python-flint's
``fmpz_mpoly`` / ``fmpq_mpoly`` do this about ten times faster than SymPy's sparse
polynomial ring; where flint cannot be imported (the book's live cells run in the browser)
the same code runs on SymPy's ring. Both element types support ``+``, ``-``, ``*``,
comparison with 0 and ``len`` (number of terms), so the formulas of :mod:`pgsym.ring` run
on either; the few other things the engine needs (conversion from SymPy expressions,
exact division, evaluation at a rational point, text) are methods of
:class:`PolynomialRing`. Setting the environment variable ``PGSYM_POLY_BACKEND=sympy``
forces the fallback (the tests do, to check both give the same verdicts).

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> R = PolynomialRing([x, y], backend="sympy")
>>> p = R(x + y) * R(x - y)
>>> R.to_expr(p), R.nterms(p), R.degree(p)
(x**2 - y**2, 2, 2)
>>> R.evaluate(p, [Fraction(1, 2), Fraction(1)])
Fraction(-3, 4)
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from fractions import Fraction
from typing import Any

import sympy
from sympy.polys.rings import ring

from .errors import PolynomialBackendError

try:  # optional: the extra "fast" of the package
    import flint as _flint
except ImportError:  # pragma: no cover - exercised by forcing the fallback
    _flint = None

__all__ = ["BACKEND_VARIABLE", "PolynomialRing", "available_backends", "default_backend"]

BACKEND_VARIABLE = "PGSYM_POLY_BACKEND"
"""The environment variable that chooses the backend (``flint`` or ``sympy``; default: flint when installed)."""


def available_backends() -> tuple[str, ...]:
    """The backends that can be used here.

    >>> "sympy" in available_backends()
    True
    """
    return ("flint", "sympy") if _flint is not None else ("sympy",)


def default_backend() -> str:
    """``"flint"`` when python-flint imports and the environment does not ask for ``sympy``.

    >>> default_backend() in available_backends()
    True
    """
    wanted = os.environ.get(BACKEND_VARIABLE, "").strip().lower()
    if wanted == "sympy" or _flint is None:
        return "sympy"
    return "flint"


class PolynomialRing:
    """ℤ[symbols] (``integral=True``) or ℚ[symbols] on the chosen backend, with the engine's few helpers.

    >>> import sympy
    >>> a = sympy.Symbol("a")
    >>> R = PolynomialRing([a], integral=True)
    >>> R.exact_quotient(R(a**2 - 1), R(a + 1)) == R(a - 1)
    True
    """

    def __init__(self, symbols: Sequence[sympy.Symbol], *, integral: bool = False, order: str = "lex",
                 backend: str | None = None) -> None:
        self.symbols = list(symbols) or [sympy.Symbol("_t")]
        self.backend = backend or default_backend()
        if self.backend not in available_backends():
            raise PolynomialBackendError(f"polynomial backend {self.backend!r} is not available here "
                             f"(available: {', '.join(available_backends())})")
        self.integral = integral
        self.order = order
        self._index = {s: i for i, s in enumerate(self.symbols)}
        self._sympy_ring: Any = None
        if self.backend == "flint":
            ctx_type = _flint.fmpz_mpoly_ctx if integral else _flint.fmpq_mpoly_ctx
            names = tuple(str(sym) for sym in self.symbols)
            self._ctx = ctx_type.get(names, {"lex": "lex", "grevlex": "degrevlex", "grlex": "deglex"}[order])
            self.gens = list(self._ctx.gens())
        else:
            self._ring, *self.gens = ring(self.symbols, sympy.ZZ if integral else sympy.QQ, order)

    @property
    def field(self) -> str:
        """``ℤ`` or ``ℚ``."""
        return "ℤ" if self.integral else "ℚ"

    def __call__(self, expr: Any) -> Any:
        """The polynomial of a SymPy expression (or number) in the ring's symbols."""
        i = self._index.get(expr)
        if i is not None:
            return self.gens[i]
        if self.backend == "sympy":
            return self._ring(expr)
        e = sympy.sympify(expr)
        if e.is_Rational:
            return self._ctx.constant(self._coefficient(e))
        if self._sympy_ring is None:  # SymPy's ring reads expressions fastest; flint then takes its terms
            self._sympy_ring = ring(self.symbols, sympy.QQ, "lex")[0]
        terms = self._sympy_ring(e).items()
        return self._ctx.from_dict({m: self._coefficient(c) for m, c in terms})

    def _coefficient(self, c: Any) -> Any:
        p, q = (int(c.numerator), int(c.denominator)) if hasattr(c, "numerator") else (int(c.p), int(c.q))
        if self.integral:
            if q != 1:
                raise PolynomialBackendError(f"the coefficient {p}/{q} is not an integer, but the ring is ℤ[…]")
            return p
        return _flint.fmpq(p, q)

    def constant(self, value: int) -> Any:
        """The constant polynomial ``value``."""
        return self._ctx.constant(value) if self.backend == "flint" else self._ring(value)

    # -- facts about one element ------------------------------------------------------------------
    def terms(self, p: Any) -> list[tuple[tuple[int, ...], Fraction]]:
        """The (exponents, coefficient) pairs of p, coefficients as Fractions."""
        if isinstance(p, int):
            return [((0,) * len(self.symbols), Fraction(p))] if p else []
        if self.backend == "flint":
            return [(tuple(int(e) for e in m), Fraction(int(c.p), int(c.q)) if hasattr(c, "q") else Fraction(int(c)))
                    for m, c in zip(p.monoms(), p.coeffs(), strict=True)]
        return [(m, Fraction(int(c.numerator), int(c.denominator))) for m, c in p.terms()]

    @staticmethod
    def nterms(p: Any) -> int:
        """The number of terms of p (0 for the zero polynomial)."""
        return len(p) if hasattr(p, "__len__") else int(p != 0)

    def degree(self, p: Any) -> int:
        """The total degree of p (−1 for the zero polynomial)."""
        if p == 0:
            return -1
        if self.backend == "flint":
            return int(p.total_degree())
        return max(sum(m) for m in p.monoms())

    def to_expr(self, p: Any) -> sympy.Expr:
        """p as a SymPy expression in the ring's symbols."""
        if self.backend == "sympy" and hasattr(p, "as_expr"):
            return p.as_expr()
        terms = []  # one Add at the end: adding term by term re-sorts the sum each time (quadratic)
        for m, c in self.terms(p):
            terms.append(sympy.Mul(sympy.Rational(c.numerator, c.denominator),
                                   *(s**e for s, e in zip(self.symbols, m, strict=True) if e)))
        return sympy.Add(*terms)

    def text(self, p: Any, max_terms: int = 40) -> str:
        """p as text; long polynomials are summarised by degree and number of terms."""
        n = self.nterms(p)
        if n > max_terms:
            return f"<a polynomial of degree {self.degree(p)} with {n} terms>"
        return str(self.to_expr(p))

    def evaluate(self, p: Any, values: Sequence[Fraction]) -> Fraction:
        """The exact value of p at a rational point (values in the order of the ring's symbols)."""
        total = Fraction(0)
        for m, c in self.terms(p):
            term = c
            for x, e in zip(values, m, strict=False):
                if e:
                    term *= x**e
            total += term
        return total

    def exact_quotient(self, x: Any, y: Any) -> Any | None:
        """q with x = q·y exactly, or None when y does not divide x (or y is zero)."""
        if y == 0:
            return None
        q, r = divmod(x, y)
        return q if r == 0 and q * y == x else None
