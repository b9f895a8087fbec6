"""Proof by evaluation: a polynomial identity decided at enough exact points, when expanding it is too large.

The exact pass of :mod:`pgsym.proofs.engine` proves a claim by expanding its conclusion into a polynomial in
the parameters and finding the zero polynomial. When that expansion is too large (the budget's estimate,
:mod:`pgsym.proofs.budget`), the same identity is decided here without expanding it, by the classical
argument of *proving by example* (Hong 1986; Zhang, Yang and Deng 1990):

1. **Degree bounds.** The constructions are run once on stand-ins that know only a bound on the degree in
   each parameter (deg(a·b) ≤ deg a + deg b, deg(a ± b) ≤ max): the conclusion polynomial P has degree at most
   dᵢ in the parameter xᵢ. Nothing is expanded; the cost is one pass over the constructions.
2. **Grid.** A nonzero polynomial with deg_{xᵢ} P ≤ dᵢ does not vanish at every point of a grid
   S₁ × … × Sₙ of integers with |Sᵢ| = dᵢ + 1 (induction on n: a nonzero polynomial of degree ≤ d in one
   variable, over an integral domain, has at most d roots). So P is the zero polynomial exactly when it
   vanishes at every grid point, and each grid point is one exact evaluation of the constructions.
3. **Variables kept.** A few parameters may be kept as variables (the ones of highest degree): at each grid
   point of the others, the conclusion is expanded in those few only (python-flint), which is cheap, and must
   be the zero polynomial. The grid then covers the other parameters only. The number of variables kept is
   chosen by timing one grid point of each choice.

This proves the same statement as the expansion (the numerator's polynomial identity), so the verdict keeps
the same non-degeneracy conditions; a condition counts as not identically violated once it is nonzero at one
evaluated point. Evaluation points need not satisfy the conditions: the identity is proved, not a value.

**Square roots.** With the defining equations of square roots (a triangular set, monic in each root, see
:mod:`pgsym.proofs.algebraic`) the conclusion's remainder modulo them is a polynomial in the roots whose
coefficients are polynomials in the parameters; it is zero exactly when every coefficient is. Division by a
monic polynomial commutes with substituting numbers for the parameters, so the remainder at a grid point is
the specialised remainder. A root r with r² = q counts, for the degree bounds, as a parameter monomial of
degree ⌈deg q / 2⌉ in each parameter (then replacing r² by q never raises the bound), and the coefficients'
degrees are at most the bound of the whole.

>>> from pgsym.proofs.claims import Claim
>>> c = Claim("demo", "the medians of a triangle are concurrent")
>>> A, B, C = (c.free_point(n) for n in "ABC")
>>> ma, mb, mc = (c.midpoint(f"M{i}", P, Q) for i, (P, Q) in enumerate(((B, C), (C, A), (A, B))))
>>> c.conclude_concurrent(c.join("a", A, ma), c.join("b", B, mb), c.join("c", C, mc))
>>> result = identity_by_evaluation(c, {}, Deadline(30), "a test")
>>> result.outcome, result.points > 0
('identity', True)
"""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import sympy

from . import budget
from .budget import Deadline, Timeout, TooLarge, metered
from .claims import Claim, Node
from .evaluation import cancel_common_denominator, conclusion_values, evaluate, nonzero_requirements, objects_to_check
from .operations import flat
from .polynomials import PolynomialRing
from .square_roots import roots_of
from .verdicts import Certificate, Condition

__all__ = ["MAX_POINTS", "Evaluation", "conclusion_polynomials", "degree_bounds", "exact_pass",
           "identity_by_evaluation"]

MAX_POINTS = 200_000
"""The most grid points one proof by evaluation may visit (beyond, the verdict stays *unknown*)."""

_KEEP_CHOICES = (0, 1, 2, 3)
"""How many parameters may be kept as variables at each grid point (the rest are numbers)."""

_PRODUCTS_PER_SECOND = 10**9
"""Term products a second at python-flint's best (see :data:`~pgsym.proofs.budget.MAX_WORK`)."""



class _Degree:
    """A stand-in for a polynomial that knows only an upper bound on its degree in each parameter."""

    __slots__ = ("d",)

    def __init__(self, d: tuple[int, ...]) -> None:
        self.d = d

    def __add__(self, other: Any) -> _Degree:
        if not isinstance(other, _Degree):
            return self
        return _Degree(tuple(max(a, b) for a, b in zip(self.d, other.d, strict=True)))

    __radd__ = __sub__ = __rsub__ = __add__

    def __neg__(self) -> _Degree:
        return self

    def __mul__(self, other: Any) -> _Degree:
        if not isinstance(other, _Degree):
            return self
        return _Degree(tuple(a + b for a, b in zip(self.d, other.d, strict=True)))

    __rmul__ = __mul__

    def __pow__(self, e: int) -> _Degree:
        return _Degree(tuple(a * int(e) for a in self.d))


def _bound(x: Any, n: int) -> tuple[int, ...]:
    return x.d if isinstance(x, _Degree) else (0,) * n


def conclusion_polynomials(claim: Claim, values: dict[Node, Any], limit: int | None = None,
                           deadline: Deadline | None = None) -> list[tuple[str, Any]]:
    """(label, polynomial) pairs that vanish identically exactly when the claim holds (rank conclusions aside).

    The same polynomials as :func:`~pgsym.proofs.evaluation.conclusion_polys`, except that two proportional
    vectors give every 2×2 minor: the engine picks the minors through one nonzero entry, and which entry is
    nonzero may change from point to point, while the identity must be the same polynomial at every point.
    With ``limit`` the term products are counted (:func:`~pgsym.proofs.budget.metered`): a product in C cannot be
    interrupted, so none starts that would pass the limit.
    """
    out: list[tuple[str, Any]] = []
    for c in claim.conclusions:
        nodes = [a for a in c.args if isinstance(a, Node)]
        vals, names = [values[a] for a in nodes], [a.label for a in nodes]
        if c.kind == "equal_ratio":  # on the values themselves: a metered value has no gcd
            vals = list(cancel_common_denominator(vals))

        def compute(vals: list[Any], _wrap: Any, kind: str = c.kind, names: list[str] = names) -> tuple[Any, ...]:
            if kind == "proportional":
                u, v = flat(vals[0]), flat(vals[1])
                return tuple((f"{names[0]}[{i}]·{names[1]}[{j}] − {names[0]}[{j}]·{names[1]}[{i}]",
                              u[i] * v[j] - u[j] * v[i]) for i, j in itertools.combinations(range(len(u)), 2))
            return () if kind == "rank" else tuple(conclusion_values(kind, vals, names))

        out += compute(vals, None) if limit is None else metered(compute, vals, limit, deadline)
    return out


def _requirements(claim: Claim, values: dict[Node, Any], limit: int | None = None,
                  deadline: Deadline | None = None) -> list[tuple[str, list[Any]]]:
    def compute(vals: list[Any], _wrap: Any) -> tuple[Any, ...]:
        at = dict(zip(values, vals, strict=True))
        out = [(text, tuple(ps)) for text, ps in nonzero_requirements(claim, at)]
        return tuple(out + [(f"{n.label} is not the zero vector", tuple(flat(at[n]))) for n in objects_to_check(claim)])

    found = compute(list(values.values()), None) if limit is None else metered(compute, list(values.values()), limit,
                                                                                deadline)
    return [(text, list(ps)) for text, ps in found]


def _stand_in_values(claim: Claim, gens: Sequence[sympy.Symbol], substitution: dict[sympy.Symbol, Any]
                     ) -> dict[Node, Any]:
    """The constructions run on degree stand-ins; a root r with r² = q weighs ⌈deg q / 2⌉ in each parameter."""
    n = len(gens)
    roots = {r.node: r for r in roots_of(claim)}
    weight: dict[sympy.Symbol, tuple[int, ...]] = {}
    cache: dict[Any, Any] = {}

    def scalar(expr: Any) -> Any:
        out = cache.get(expr)
        if out is None:
            e = sympy.sympify(expr).xreplace(substitution)
            symbols = sorted(e.free_symbols, key=str)
            if not symbols:
                out = 1
            else:
                bound = [0] * n
                for monomial in sympy.Poly(e, *symbols).monoms():
                    term = [0] * n
                    for s, k in zip(symbols, monomial, strict=True):
                        w = weight[s] if s in weight else tuple(int(s == g) for g in gens)
                        term = [t + k * x for t, x in zip(term, w, strict=True)]
                    bound = [max(b, t) for b, t in zip(bound, term, strict=True)]
                out = _Degree(tuple(bound))
            cache[expr] = out
        return out

    def before(node: Node, values: dict[Node, Any]) -> None:
        root = roots.get(node)
        if root is not None:
            q = (0,) * n if root.square is None else _bound(root.square(values), n)
            weight[root.symbol] = tuple(-(-x // 2) for x in q)

    values: dict[Node, Any] = {}
    for node in claim.nodes.values():
        before(node, values)
        args = [values[a] for a in node.args if isinstance(a, Node)]
        values[node] = node.operation.formula(node, args, scalar)
    return values


def degree_bounds(claim: Claim, substitution: dict[sympy.Symbol, Any] | None = None
                  ) -> dict[str, dict[sympy.Symbol, int]]:
    """For each conclusion polynomial, an upper bound on its degree in each parameter (roots excluded), found by
    running the constructions on stand-ins, without expanding anything.

    >>> from pgsym.proofs.claims import Claim
    >>> c = Claim("demo", "demo")
    >>> A, B = c.free_point("A"), c.free_point("B")
    >>> c.conclude_incident(A, c.join("l", A, B))
    >>> degree_bounds(c)      # A = (A_x, A_y, 1): l = A × B has degree 1 in each, and so has each lᵢ·Aᵢ
    {'lᵀA': {A_x: 1, A_y: 1, B_x: 1, B_y: 1}}
    """
    substitution = substitution or {}
    gens = _parameters(claim, substitution)
    values = _stand_in_values(claim, gens, substitution)
    return {label: dict(zip(gens, _bound(p, len(gens)), strict=True))
            for label, p in conclusion_polynomials(claim, values)}


def _parameters(claim: Claim, substitution: dict[sympy.Symbol, Any]) -> list[sympy.Symbol]:
    rootsyms = {r.symbol for r in roots_of(claim)}
    return [p for p in claim.parameters if p not in substitution and p not in rootsyms]


@dataclass
class Evaluation:
    """What the evaluation found: ``identity`` (every conclusion polynomial is zero), ``nonzero`` (one is not:
    ``label`` and ``point``) or ``degenerate`` (``label`` names a condition that vanishes identically)."""

    outcome: str
    steps: list[str] = field(default_factory=list)
    label: str = ""
    point: dict[sympy.Symbol, Fraction] = field(default_factory=dict)
    value: Any = None
    ring: PolynomialRing | None = None
    points: int = 0
    conditions: list[str] = field(default_factory=list)
    where: str = ""
    largest_terms: int = 0
    largest_degree: int = 0
    method: str = ("polynomial identity by exact evaluation on a grid (degree bounds from the constructions, "
                   "then one exact evaluation per grid point: proving by example, Hong 1986, Zhang, Yang and "
                   "Deng 1990)")

    def certificate(self, ring: str, normalisation: str = "", backend: str = "") -> Certificate:
        """The certificate of an identity: the method, the ring, and why the grid decides."""
        return Certificate(self.method, ring, self.steps, self.largest_terms, normalisation=normalisation,
                           backend=backend, largest_degree=self.largest_degree)


class _PointEvaluator:
    """The constructions at one point: some parameters numbers, the kept ones variables of a small ring."""

    def __init__(self, claim: Claim, gens: Sequence[sympy.Symbol], substitution: dict[sympy.Symbol, Any],
                 kept: Sequence[sympy.Symbol], tower: Callable[[list[sympy.Symbol]], Any] | None,
                 backend: str | None, terms: dict[Any, Any]) -> None:
        self.claim, self.gens, self.kept, self.tower = claim, list(gens), list(kept), tower
        self.rootsyms = [r.symbol for r in roots_of(claim)]
        symbols = [*self.gens, *self.rootsyms]
        self.terms: dict[Any, list[tuple[Fraction, tuple[int, ...]]]] = terms  # shared by the choices
        self.symbols = symbols
        self.substitution = substitution
        self.backend = backend
        self.ring = None if tower is not None or not kept else PolynomialRing(kept, backend=backend)

    def _terms(self, expr: Any) -> list[tuple[Fraction, tuple[int, ...]]]:
        out = self.terms.get(expr)
        if out is None:
            e = sympy.sympify(expr).xreplace(self.substitution)
            poly = sympy.Poly(e, *self.symbols)
            out = self.terms[expr] = [(Fraction(int(c.p), int(c.q)), m) for m, c in poly.terms()]
        return out

    def run(self, point: dict[sympy.Symbol, int], deadline: Deadline, max_work: int | None = None
            ) -> tuple[dict[Node, Any], Callable[[Any], bool], PolynomialRing | None]:
        """The values at the point, a zero test for them, and the ring they live in (None: exact rationals)."""
        tower = self.tower(self.kept) if self.tower is not None else None
        R = tower.R if tower is not None else self.ring
        gen = {} if R is None else {s: R(s) for s in [*self.kept, *(self.rootsyms if tower is not None else [])]}
        numbers = [point.get(s) for s in self.symbols]
        cache: dict[Any, Any] = {}

        def scalar(expr: Any) -> Any:
            out = cache.get(expr)
            if out is None:
                out = 0
                for c, m in self._terms(expr):
                    coefficient, variable = c, 1
                    for s, x, k in zip(self.symbols, numbers, m, strict=True):
                        if k:
                            if x is None:
                                variable = variable * gen[s] ** k
                            else:
                                coefficient *= Fraction(x) ** k
                    if R is None:
                        out += coefficient
                    else:
                        out = out + R(sympy.Rational(coefficient.numerator, coefficient.denominator)) * variable
                cache[expr] = out
            return out

        if tower is None:
            values = evaluate(self.claim, scalar, deadline=deadline, ring=R, max_work=max_work)
        else:
            by_node = {r.node: r for r in roots_of(self.claim)}

            def after(node: Node, values: dict[Node, Any]) -> None:
                if node in by_node:
                    tower.add(by_node[node], values)

            # with no parameter kept, the values are polynomials in the roots alone, each of degree < 2 (a root of
            # unity: < φ(M)): small, so the budget's estimate is for the kept variables only
            values = evaluate(self.claim, scalar, tower.reduce, deadline, R if self.kept else None, after, max_work)
        if tower is None:
            return values, (lambda p: p == 0), R
        # a conclusion is a product of reduced values: its remainder decides (zero unreduced is zero reduced)
        return values, (lambda p: tower.reduce(p) == 0), R


def _limit(deadline: Deadline, evaluator: _PointEvaluator) -> int | None:
    """The most term products one grid point may form: what the time left allows at flint's best speed (None: every
    parameter is a number, nothing to count)."""
    if not evaluator.kept:
        return None
    if deadline.end is None:
        return budget.MAX_WORK
    left = deadline.end - time.perf_counter()
    return max(1, min(budget.MAX_WORK, int(left * _PRODUCTS_PER_SECOND)))


def _grid(bounds: Sequence[int]) -> list[list[int]]:
    """dᵢ + 1 consecutive integers around 0 for each bound dᵢ."""
    return [list(range(-(d // 2), d - d // 2 + 1)) for d in bounds]


def identity_by_evaluation(claim: Claim, substitution: dict[sympy.Symbol, Any], deadline: Deadline, why: str,
                           tower: Callable[[list[sympy.Symbol]], Any] | None = None,
                           backend: str | None = None) -> Evaluation:
    """Decide whether every conclusion polynomial is identically zero by exact evaluation on a grid.

    ``substitution`` is the frame's (parameters fixed without loss of generality); ``why`` says why the expansion
    was not done (it heads the certificate); ``tower(kept)`` builds the triangular set of the claim's square
    roots over the kept parameters (see :mod:`pgsym.proofs.algebraic`), None for a claim without roots.
    Raises :class:`~pgsym.proofs.budget.TooLarge` when the grid would not fit in the time left (or in
    :data:`MAX_POINTS`), with the numbers, so that the verdict stays *unknown* and says why.
    """
    if claim.hypotheses or any(c.kind == "rank" for c in claim.conclusions):
        raise TooLarge(f"{why}; proof by evaluation covers neither equation hypotheses nor rank conclusions")
    gens = _parameters(claim, substitution)
    n = len(gens)
    try:
        stand_ins = _stand_in_values(claim, gens, substitution)
        polys = conclusion_polynomials(claim, stand_ins)
        requirements = _requirements(claim, stand_ins)
    except Timeout:
        raise
    except Exception as err:  # a formula that compares or converts its values: no degree bound, no proof here
        raise TooLarge(f"{why}; no degree bound for proof by evaluation ({type(err).__name__})") from err
    degree = [max((_bound(p, n)[i] for _, p in polys), default=0) for i in range(n)]
    requirement_bounds = [[max((_bound(p, n)[i] for p in ps), default=0) for i in range(n)] for _, ps in requirements]
    order = sorted(range(n), key=lambda i: -degree[i])
    plan = _choose(claim, gens, substitution, degree, order, tower, backend, deadline, why)
    kept_count, evaluator = plan
    kept = [gens[i] for i in order[:kept_count]]
    varying = [i for i in range(n) if gens[i] not in kept]
    axes = _grid([degree[i] for i in varying])
    witnessed: set[int] = set()
    count = 0
    failing: Evaluation | None = None
    largest = (1, 0)  # (terms, total degree) of the largest value at a grid point: a number when nothing is kept
    for numbers in itertools.product(*axes):
        deadline.check(f"evaluating the constructions at grid point {count + 1}")
        point = {gens[i]: x for i, x in zip(varying, numbers, strict=True)}
        limit = _limit(deadline, evaluator)
        values, is_zero, R = evaluator.run(point, deadline, limit)
        count += 1
        if R is not None:  # the size of what was expanded at a grid point, for the certificate
            entries = [x for v in values.values() for x in flat(v) if not isinstance(x, (int, Fraction))]
            largest = max([largest, *((R.nterms(x), R.degree(x)) for x in entries)])
        if failing is None:
            for label, p in conclusion_polynomials(claim, values, limit, deadline):
                if not is_zero(p):
                    failing = Evaluation("nonzero", label=label, point={s: Fraction(x) for s, x in point.items()},
                                         value=p, ring=R)
                    break
        if len(witnessed) < len(requirement_bounds):
            for k, (_text, ps) in enumerate(_requirements(claim, values, limit, deadline)):
                if k not in witnessed and any(not is_zero(p) for p in ps):
                    witnessed.add(k)
        if failing is not None and len(witnessed) == len(requirement_bounds):
            break  # not an identity, and no condition fails identically (those come first, as in the expansion)
    total = grid_points = count
    for k, (text, _ps) in enumerate(requirements):
        if k in witnessed:
            continue
        # zero at every point so far: its own grid (its own degree bounds) decides whether it is identically zero
        if math.prod(requirement_bounds[k][i] + 1 for i in varying) > MAX_POINTS:
            raise TooLarge(f"{why}; by evaluation, the condition {text} was zero at all {total} grid points, and its "
                           "own grid is too large")
        for numbers in itertools.product(*_grid([requirement_bounds[k][i] for i in varying])):
            deadline.check(f"evaluating the condition {text}")
            limit = _limit(deadline, evaluator)
            values, is_zero, _ = evaluator.run({gens[i]: x for i, x in zip(varying, numbers, strict=True)}, deadline,
                                               limit)
            total += 1
            if any(not is_zero(p) for p in _requirements(claim, values, limit, deadline)[k][1]):
                break
        else:
            return Evaluation("degenerate", label=text, points=total)
    if failing is not None:
        failing.points = total
        return failing
    shown = ", ".join(f"{gens[i]}: {degree[i]}" for i in order)
    steps = [f"the expansion was not carried out ({why})",
             f"degree bounds propagated through the {len(claim.nodes)} constructions without expanding "
             "(the degree of a product is at most the sum of the degrees, that of a sum at most the larger"
             + ("; a root r with r² = q counts as half the degree of q, rounded up" if tower is not None else "")
             + f"): every conclusion polynomial has degree at most {shown or 'zero'} in these parameters"]
    if kept:
        where = (f"ℚ[{', '.join(str(s) for s in kept)}]" if tower is None else
                 f"ℚ[{', '.join(str(s) for s in kept)}][roots] modulo the defining equations")
        steps.append(f"{', '.join(str(s) for s in kept)} kept as variables: at each grid point of the others the "
                     f"conclusion is expanded in {where} and is the zero polynomial")
    sizes = " × ".join(str(len(a)) for a in axes) or "1"
    steps.append(f"grid of {sizes} = {grid_points} points (degree bound + 1 consecutive integers per parameter): "
                 "every conclusion polynomial vanishes at each of them, exactly")
    steps.append("a nonzero polynomial of degree at most d in each parameter cannot vanish on a grid with d + 1 values "
                 "of each parameter (a nonzero polynomial of degree at most d in one variable, over an integral "
                 "domain, has at most d roots; induction on the number of variables): so each conclusion polynomial "
                 "is the zero polynomial"
                 + ("; specialising the parameters commutes with division by the monic defining equations, so the "
                    "remainder modulo them is zero" if tower is not None else ""))
    if any(c.kind == "equal_ratio" for c in claim.conclusions):
        steps.append("two ratios n₁/d₁ = n₂/d₂ are compared at a grid point as n₁·(d₂/g) − n₂·(d₁/g) with g the gcd "
                     "of the nonzero denominators there, when cross-multiplying would be large: g ≠ 0 and "
                     "n₁d₂ − n₂d₁ = g·(n₁·(d₂/g) − n₂·(d₁/g)), so one vanishes exactly when the other does, and the "
                     "degree bound above (of n₁d₂ − n₂d₁) still decides")
    steps.append(f"every one of the {len(requirement_bounds)} non-degeneracy conditions is nonzero at some evaluated "
                 "point, so none is violated identically")
    conditions = [text for text, _ in nonzero_requirements(claim, stand_ins)]
    where = (f"{'ℚ' if tower is None else 'ℚ[roots]'}{'[' + ', '.join(map(str, kept)) + ']' if kept else ''} at "
             f"{total} grid points of {', '.join(str(gens[i]) for i in varying) or 'no parameter'}")
    return Evaluation("identity", steps=steps, points=total, conditions=conditions, largest_terms=largest[0],
                      largest_degree=largest[1],
                      where=where)


def _choose(claim: Claim, gens: Sequence[sympy.Symbol], substitution: dict[sympy.Symbol, Any], degree: list[int],
            order: list[int], tower: Callable[[list[sympy.Symbol]], Any] | None, backend: str | None,
            deadline: Deadline, why: str) -> tuple[int, _PointEvaluator]:
    """How many parameters to keep as variables: the choice whose grid takes the least time, timed on one point."""
    best: tuple[float, int, _PointEvaluator] | None = None
    notes = []
    terms: dict[Any, Any] = {}
    numbers = _PointEvaluator(claim, gens, substitution, [], tower, backend, terms)
    numbers.run(dict.fromkeys(gens, 0), deadline)  # parses every datum once, so that the timings below compare
    started = time.perf_counter()
    numbers.run({g: d - d // 2 for g, d in zip(gens, degree, strict=True)}, deadline)
    fastest = time.perf_counter() - started  # a point with every parameter a number: the cheapest kind of point
    left = math.inf if deadline.end is None else deadline.end - time.perf_counter()
    started_all = time.perf_counter()
    for keep in _KEEP_CHOICES:
        if keep > len(gens):
            break
        points = math.prod(degree[i] + 1 for i in order[keep:])
        if points > MAX_POINTS or points * fastest > left:  # hopeless without timing it
            notes.append(f"{keep} kept: {points} points")
            continue
        kept = [gens[i] for i in order[:keep]]
        evaluator = _PointEvaluator(claim, gens, substitution, kept, tower, backend, terms) if keep else numbers
        first = {gens[i]: degree[i] - degree[i] // 2 for i in order[keep:]}  # a grid corner: not a special point
        cap = (left - (time.perf_counter() - started_all)) / points  # the most one point may take for the grid to fit
        started = time.perf_counter()
        try:
            # one product in C cannot be stopped: none may need more than the cap allows at flint's best speed; the
            # conclusions and the conditions are timed too (the first grid point forms both)
            trial, limit = Deadline(cap), max(1, min(budget.MAX_WORK, int(cap * _PRODUCTS_PER_SECOND)))
            values, _, _ = evaluator.run(first, trial, max_work=limit)
            limit = limit if keep else None  # numbers: no product to count
            conclusion_polynomials(claim, values, limit, trial)
            _requirements(claim, values, limit, trial)
        except TooLarge:
            notes.append(f"{keep} kept: too large")
            continue
        except Timeout:
            deadline.check()
            notes.append(f"{keep} kept: {points} points × more than {cap:.2g} s")
            continue
        seconds = time.perf_counter() - started
        estimate = seconds * points
        notes.append(f"{keep} kept: {points} points × {seconds:.2g} s")
        if best is None or estimate < best[0]:
            best = (estimate, keep, evaluator)
        if points == 1:
            break
    left = math.inf if deadline.end is None else deadline.end - time.perf_counter()
    if best is None or best[0] > left:
        raise TooLarge(f"{why}; proof by evaluation on a grid would take too long ({'; '.join(notes)})")
    return best[1], best[2]



def exact_pass(claim: Claim, deadline: Deadline, normalisation: Any, why: str,
               frame_conditions: Callable[[], list[Condition]], backend: str | None = None) -> tuple[str, Any]:
    """The engine's exact pass by evaluation (called by :mod:`pgsym.proofs.engine` when expanding is too large):
    ``("proved", (certificate, conditions))``, ``("nonzero", (label, text))`` or ``("degenerate", reason)``."""
    substitution = normalisation.substitution if normalisation is not None else {}
    found = identity_by_evaluation(claim, substitution, deadline, why, backend=backend)
    if found.outcome == "nonzero":
        at = ", ".join(f"{s} = {x}" for s, x in found.point.items())
        return "nonzero", (f"{found.label} (nonzero at the grid point {at or 'of the kept variables'})",
                           str(found.value)[:200])
    if found.outcome == "degenerate":
        return "degenerate", (f"the condition {found.label} fails identically (zero at every point of a grid its "
                              "degree bound makes conclusive: the construction is undefined for every value of the "
                              "parameters)")
    conditions = [Condition(text) for text in found.conditions]
    if normalisation is not None:
        conditions += frame_conditions()
    certificate = found.certificate(found.where, "" if normalisation is None else normalisation.describe(),
                                    backend or "")
    return "proved", (certificate, conditions)
