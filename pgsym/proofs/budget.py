"""The budget of a proof: its time limit and the size of the expansions it may start.

Both provers (:mod:`pgsym.proofs.engine`, :mod:`pgsym.proofs.algebraic`) read the same limits: a
:class:`Deadline` checked between steps, an :func:`alarm` that interrupts one long computation, and an
:func:`estimate` of the term products a formula would form, taken on :class:`Cost` stand-ins before the
real polynomials are multiplied (a product in C cannot be interrupted by the time limit). The estimate is an
upper bound, often far above the truth (a product of polynomials dense in a few variables has far fewer
terms than the product of the numbers of terms); a formula it refuses may still be run by :func:`metered`,
which counts the real products one by one and stops before the one that would pass the limit.

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

__all__ = ["ALARM_REPEAT", "MAX_TERMS", "MAX_WORK", "PRODUCTS_PER_SECOND", "Cost", "Deadline", "Metered", "Timeout",
           "TooLarge", "alarm", "estimate", "metered"]


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


PRODUCTS_PER_SECOND = 4 * 10**7
"""Term products a second that python-flint keeps up on the large products of an expansion (measured 4·10⁷ to
9·10⁷ a second for polynomials of 10⁴ terms with coefficients of 30 to 120 bits, on a shared machine; dense
small-coefficient products run faster): a product that would not end within the time left at this speed is not
started (:class:`Metered`)."""


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
    stand_ins = [map_nested(a, lambda x: x if isinstance(x, int) else Cost(R.nterms(x), max(R.degree(x), 0), k, tally))
                 for a in args]
    try:
        compute(stand_ins)
    except Timeout:
        raise
    except Exception:  # a computation that compares or converts its values: no estimate, MAX_TERMS still holds
        return None
    return tally[0]


class Metered:
    """A polynomial that counts the term products formed with it: each product of ``n₁`` by ``n₂`` terms adds
    ``n₁·n₂`` to ``meter[0]`` and raises :class:`TooLarge` *before* it starts when the count would pass
    ``meter[1]`` or when the product would not end before the deadline ``meter[2]`` at
    :data:`PRODUCTS_PER_SECOND` (the deadline is checked there too): a product in C cannot be interrupted, while
    the time limit stops the computation between two products. Sums are not counted (linear in the terms)."""

    __slots__ = ("meter", "p")

    def __init__(self, p: Any, meter: list[Any]) -> None:
        self.p, self.meter = p, meter

    @staticmethod
    def _raw(x: Any) -> Any:
        return x.p if isinstance(x, Metered) else x

    def __add__(self, other: Any) -> Metered:
        return Metered(self.p + self._raw(other), self.meter)

    def __radd__(self, other: Any) -> Metered:
        return Metered(self._raw(other) + self.p, self.meter)

    def __sub__(self, other: Any) -> Metered:
        return Metered(self.p - self._raw(other), self.meter)

    def __rsub__(self, other: Any) -> Metered:
        return Metered(self._raw(other) - self.p, self.meter)

    def __neg__(self) -> Metered:
        return Metered(-self.p, self.meter)

    def __mul__(self, other: Any) -> Metered:
        q = self._raw(other)
        meter = self.meter
        work = _terms(self.p) * _terms(q)
        meter[0] += work
        if meter[0] > meter[1]:
            raise TooLarge(f"more than {meter[1]:.1e} term products")
        deadline = meter[2]
        if deadline is not None:
            deadline.check()
            if deadline.end is not None and work > (deadline.end - time.perf_counter()) * PRODUCTS_PER_SECOND:
                raise TooLarge(f"a product of {work:.1e} term products would not end within the time left")
        return Metered(self.p * q, meter)

    __rmul__ = __mul__

    def __pow__(self, e: int) -> Metered:
        out = self
        for _ in range(int(e) - 1):
            out = out * self
        return out if int(e) > 0 else Metered(1, self.meter)

    def __eq__(self, other: object) -> bool:
        return bool(self.p == self._raw(other))

    def __ne__(self, other: object) -> bool:
        return bool(self.p != self._raw(other))

    def __hash__(self) -> int:
        return hash(self.p)


def _terms(p: Any) -> int:
    return len(p) if hasattr(p, "__len__") else int(p != 0)


def metered(compute: Callable[[list[Any], Callable[[Any], Any]], Any], args: list[Any], limit: int,
            deadline: Deadline | None = None) -> Any:
    """``compute(args, wrap)`` run on :class:`Metered` values (``wrap`` makes one of a new ring element): its
    result, or :class:`TooLarge` before the product that would pass ``limit`` term products in all.

    >>> import sympy
    >>> R = PolynomialRing(sympy.symbols("x y"))
    >>> x, y = R.gens
    >>> p = metered(lambda v, wrap: v[0] * v[0], [(x + y) ** 3], 16)      # 4 terms times 4 terms
    >>> R.nterms(p)
    7
    >>> metered(lambda v, wrap: v[0] * v[0] * v[0], [(x + y) ** 3], 40)  # 16, then 7 × 4 = 28 more
    Traceback (most recent call last):
    ...
    pgsym.proofs.budget.TooLarge: more than 4.0e+01 term products
    """
    meter: list[Any] = [0, limit, deadline]

    def wrap(x: Any) -> Metered:
        return Metered(x, meter)

    out = compute([map_nested(a, wrap) for a in args], wrap)
    return map_nested(out, Metered._raw)


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


ALARM_REPEAT = 0.25
"""Seconds between the repeats of a proof's alarm once its time is up (see :func:`alarm`)."""


@contextmanager
def alarm(seconds: float | None):  # type: ignore[no-untyped-def]
    """Interrupt long single computations with SIGALRM (main thread on Unix only).

    The alarm then fires again every :data:`ALARM_REPEAT` seconds until the block is left: Python drops an
    exception raised in a finaliser or a garbage-collector callback ("Exception ignored in ..."), and a single
    alarm that lands there would let the computation run on past its limit."""
    usable = (seconds is not None and seconds > 0 and hasattr(signal, "setitimer")
              and threading.current_thread() is threading.main_thread())
    if not usable:
        yield
        return

    def handler(signum, frame):  # type: ignore[no-untyped-def]
        raise Timeout("computing")  # read as "timed out after N s while computing"

    old = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, seconds + 0.05, ALARM_REPEAT)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
