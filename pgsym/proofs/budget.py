"""The budget of a proof: its time limit and the size of the expansions it may start.

Both provers (:mod:`pgsym.proofs.engine`, :mod:`pgsym.proofs.algebraic`) read the same limits: a
:class:`Deadline` checked between steps, an :func:`alarm` that interrupts one long computation, and an
:func:`estimate` of the term products a formula would form, taken on :class:`Cost` stand-ins before the
real polynomials are multiplied (a product in C cannot be interrupted by the time limit).

>>> import sympy
>>> R = PolynomialRing(sympy.symbols("x y"))
>>> x, y = R.gens
>>> estimate(lambda v: v[0] * v[1], [x + y, x - y], R)       # 2 terms times 2 terms
4
"""

from __future__ import annotations

import math
import signal
import threading
import time
from collections.abc import Callable
from contextlib import contextmanager
from typing import Any

from .operations import map_nested
from .polynomials import PolynomialRing

__all__ = ["MAX_TERMS", "MAX_WORK", "Cost", "Deadline", "Timeout", "TooLarge", "alarm", "estimate"]


class Timeout(Exception):
    """The time limit of a proof ran out; ``args[0]`` says at which stage."""


class TooLarge(Exception):
    """A computation would exceed MAX_TERMS or MAX_WORK; ``args[0]`` says which."""


MAX_TERMS = 400_000
"""The most terms one coordinate may have in the exact pass: beyond, the verdict is *unknown* rather than a
computation that a time limit cannot interrupt (python-flint's products run in C)."""

MAX_WORK = 1_500_000_000
"""The most term products one construction may need in the exact pass (estimated before it runs, see
:class:`Cost`; python-flint forms 10⁸ to 10⁹ a second): beyond, the verdict is *unknown* at once, since one
product in C cannot be interrupted by a time limit."""


class Cost:
    """A stand-in for a polynomial that knows only bounds on its number of terms and its degree.

    The table's formulas are written for any ring, so running one on stand-ins bounds the term products
    it would form (``n₁·n₂`` for each product) before the real polynomials are multiplied; ``tally[0]`` adds
    them up. A product has at most ``n₁·n₂`` terms and at most as many as there are monomials of its degree
    in the ring's ``k`` variables, ``C(k + d, k)``.
    """

    __slots__ = ("d", "k", "n", "tally")

    def __init__(self, n: int, d: int, k: int, tally: list[int]) -> None:
        self.n, self.d, self.k, self.tally = n, d, k, tally

    def _parts(self, other: Any) -> tuple[int, int]:
        return (other.n, other.d) if isinstance(other, Cost) else (1, 0)

    def _monomials(self, d: int) -> int:
        return math.comb(self.k + d, self.k)

    def __add__(self, other: Any) -> Cost:
        n, d = self._parts(other)
        d = max(self.d, d)
        return Cost(min(self.n + n, self._monomials(d)), d, self.k, self.tally)

    __radd__ = __sub__ = __rsub__ = __add__

    def __mul__(self, other: Any) -> Cost:
        n, d = self._parts(other)
        self.tally[0] += self.n * n
        d += self.d
        return Cost(min(self.n * n, self._monomials(d)), d, self.k, self.tally)

    __rmul__ = __mul__

    def __neg__(self) -> Cost:
        return self

    def __pow__(self, e: int) -> Cost:
        out = Cost(1, 0, self.k, self.tally)
        for _ in range(int(e)):
            out = out * self
        return out


def estimate(compute: Callable[[list[Any]], Any], args: list[Any], R: PolynomialRing) -> int | None:
    """The term products ``compute`` would form on these arguments' values (None when it cannot be told)."""
    tally = [0]
    k = len(R.symbols)
    stand_ins = [map_nested(a, lambda x: Cost(R.nterms(x), max(R.degree(x), 0), k, tally)) for a in args]
    try:
        compute(stand_ins)
    except Exception:  # a computation that compares or converts its values: no estimate, MAX_TERMS still holds
        return None
    return tally[0]


class Deadline:
    """The end of a proof's time budget; :meth:`check` raises :class:`Timeout` once it has passed.

    >>> d = Deadline(None)
    >>> d.check("expanding"); d.stage
    'expanding'
    """

    def __init__(self, seconds: float | None) -> None:
        self.end = None if seconds is None else time.perf_counter() + seconds
        self.stage = "start"

    def check(self, stage: str | None = None) -> None:
        if stage:
            self.stage = stage
        if self.end is not None and time.perf_counter() > self.end:
            raise Timeout(self.stage)


@contextmanager
def alarm(seconds: float | None):  # type: ignore[no-untyped-def]
    """Interrupt long single computations with SIGALRM (main thread on Unix only)."""
    usable = (seconds is not None and seconds > 0 and hasattr(signal, "setitimer")
              and threading.current_thread() is threading.main_thread())
    if not usable:
        yield
        return

    def handler(signum, frame):  # type: ignore[no-untyped-def]
        raise Timeout("interrupted")

    old = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, seconds + 0.05)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
