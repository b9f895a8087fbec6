"""The proof engine: random evaluation modulo a prime first, then an exact certificate.

1. **Random pass.** Every construction is evaluated at random integers modulo the
   prime p = 2⁶¹ − 1. If a conclusion polynomial is nonzero there while the
   constructions are defined, the claim is false, and an exact counterexample
   (small integers when possible) is returned. A zero value proves nothing.
2. **Certificate.** When the claim allows it, coordinates are first chosen without loss
   of generality (:mod:`pgsym.proofs.normalisation`: free points mapped to a projective
   frame). The constructions are then expanded in the polynomial ring ℤ[parameters] or
   ℚ[parameters] (:mod:`pgsym.proofs.polynomials`: python-flint, or SymPy's ring where
   flint is missing); the claim is proved when every conclusion polynomial is the zero
   polynomial. Before that, every constructed object is checked not to vanish
   identically and every non-degeneracy condition not to be identically violated:
   otherwise the verdict is *degenerate*, naming the object — never *proved*.
   With equation hypotheses, points of the hypothesis variety are searched first (solving
   the hypotheses for variables they contain linearly, exactly) and a point violating the
   conclusion refutes the claim; otherwise the conclusion must reduce to zero modulo a
   Gröbner basis of the hypotheses (ideal membership).
3. **Core check.** At one exact rational point the same configuration is built with
   pgsym's own objects (``join``, ``meet``, ``plane_through``, ``Line3.join``, …) and
   compared with the formulas, so the catalogue and the library cannot drift.

All three read each construction's formula, conditions and core builder from the one table
:data:`pgsym.proofs.operations.OPERATIONS`.

>>> from pgsym.proofs.claims import Claim
>>> c = Claim("demo", "the join of A and B contains A")
>>> A, B = c.free_point("A"), c.free_point("B")
>>> c.conclude_incident(A, c.join("l", A, B))
>>> v = prove(c)
>>> v.status, v.method, [k.text for k in v.conditions]
('proved', 'polynomial identity (exact expansion)', ['A ≠ B'])
"""

from __future__ import annotations

import itertools
import random
import time
from collections.abc import Callable
from enum import StrEnum
from fractions import Fraction
from functools import partial
from typing import Any

import sympy

from .. import ring as alg
from ..errors import ObjectTypeError, PgsymError
from ..exact import is_zero
from . import by_evaluation
from .algebraic import prove_algebraic, prove_ordered
from .budget import Deadline, Timeout, TooLarge, alarm
from .claims import Claim, Node
from .errors import UndefinedConstructionError
from .evaluation import claim_rng, conclusion_polys, evaluate, nonzero_requirements, objects_to_check
from .normalisation import Normalisation, normalise
from .operations import CoreDegenerate, flat
from .polynomials import PolynomialRing, default_backend
from .verdicts import Certificate, Condition, Counterexample, Status, Verdict

__all__ = ["PRIME", "prove", "recheck_counterexample"]

PRIME = 2**61 - 1
"""The prime of the random pass (a Mersenne prime)."""


class _Outcome(StrEnum):
    """What one pass (or one evaluated point) found, before it becomes a verdict's :class:`Status`."""

    PROVED = "proved"
    HOLDS = "holds"
    FAILS = "fails"
    LOW_RANK = "low-rank"
    DEGENERATE = "degenerate"
    NONZERO = "nonzero"
    NOT_IN_IDEAL = "not-in-ideal"
    NO_WITNESS = "no-witness"


# -- evaluation of a claim in one arithmetic -----------------------------------------------

def _rank_mod(rows: list[list[int]], p: int) -> tuple[int, tuple[int, ...], tuple[int, ...]]:
    """Rank of an integer matrix modulo p, with the rows and columns of a nonzero maximal minor."""
    m = [[x % p for x in r] for r in rows]
    n_rows, n_cols = len(m), len(m[0])
    rank, piv_rows, piv_cols = 0, [], []
    used = [False] * n_rows
    for j in range(n_cols):
        i = next((i for i in range(n_rows) if not used[i] and m[i][j]), None)
        if i is None:
            continue
        used[i] = True
        piv_rows.append(i)
        piv_cols.append(j)
        inv = pow(m[i][j], -1, p)
        for k in range(n_rows):
            if k != i and m[k][j]:
                f = m[k][j] * inv % p
                m[k] = [(a - f * b) % p for a, b in zip(m[k], m[i], strict=True)]
        rank += 1
    return rank, tuple(sorted(piv_rows)), tuple(sorted(piv_cols))


# -- the passes ---------------------------------------------------------------------------

class _Converter:
    """Parameter expressions to ring elements, memoised (one per ring), after an optional substitution."""

    def __init__(self, R: PolynomialRing, substitution: dict[sympy.Symbol, Any] | None = None) -> None:
        self.R = R
        self.sub = substitution or {}
        self.cache: dict[Any, Any] = {}

    def __call__(self, expr: Any) -> Any:
        out = self.cache.get(expr)
        if out is None:
            e = expr
            if self.sub and not isinstance(e, (int, Fraction)):
                e = sympy.sympify(e).xreplace(self.sub)
            out = self.cache[expr] = self.R(e)
        return out


_CONVERTERS: dict[tuple[int, str, bool, str | None], tuple[Claim, _Converter]] = {}


def _integral(claim: Claim) -> bool:
    """True when every coefficient in the claim's data is an integer (then ℤ[params] suffices)."""
    for node in claim.nodes.values():
        if node.operation.coefficients:
            for e in flat(node.data) if isinstance(node.data, tuple) else []:
                if any(not a.is_Integer for a in sympy.sympify(e).atoms(sympy.Rational)):
                    return False
    return not claim.hypotheses


def _converter(claim: Claim, order: str = "lex", field: bool = True, backend: str | None = None,
               substitution: dict[sympy.Symbol, Any] | None = None) -> _Converter:
    integral = not field and _integral(claim)
    if substitution is not None:
        sub = substitution
        integral = integral and all(sympy.Rational(v).q == 1 for v in sub.values() if sympy.sympify(v).is_Rational)
        gens = [s for s in claim.parameters if s not in sub]
        return _Converter(PolynomialRing(gens, integral=integral, order=order, backend=backend), sub)
    backend = backend or default_backend()  # the environment may change between calls
    key = (id(claim), order, field, backend)
    hit = _CONVERTERS.get(key)
    if hit is None or hit[0] is not claim:
        if len(_CONVERTERS) > 64:
            _CONVERTERS.clear()
        R = PolynomialRing(claim.parameters, integral=integral, order=order, backend=backend)
        hit = _CONVERTERS[key] = (claim, _Converter(R))
    return hit[1]


def _point_evaluator(claim: Claim, R: Any, point: dict[sympy.Symbol, Any]) -> Callable[[Any], Any]:
    """A converter from parameter expressions to exact Fractions at the given point."""
    conv = _converter(claim)
    cache: dict[Any, Fraction] = {}
    args = [Fraction(point[s]) for s in claim.parameters] or [Fraction(0)]

    def scalar(expr: Any) -> Fraction:
        out = cache.get(expr)
        if out is None:
            if expr in point:
                out = Fraction(point[expr])
            elif expr.is_Rational:
                out = Fraction(int(expr.p), int(expr.q))
            else:
                out = conv.R.evaluate(conv(expr), args)
            cache[expr] = out
        return out

    return scalar


def _modp(x: Fraction) -> int:
    return x.numerator % PRIME * pow(x.denominator % PRIME, -1, PRIME) % PRIME


def _check_point(claim: Claim, values: dict[Node, Any], modp: bool) -> tuple[str, Any]:
    """Classify one evaluated point: 'degenerate', 'fails' (with residuals), 'holds' (with rank data)."""
    red = (lambda x: x % PRIME) if modp else (lambda x: x)
    for _text, polys in nonzero_requirements(claim, values):
        if all(red(p) == 0 for p in polys):
            return _Outcome.DEGENERATE, _text
    for node in objects_to_check(claim):
        if all(red(p) == 0 for p in flat(values[node])):
            return _Outcome.DEGENERATE, f"{node.label} is the zero vector"
    residuals = [red(val) for _, val in conclusion_polys(claim, values)]
    rank_info = []
    for c in claim.conclusions:
        if c.kind == "rank":
            node, r = c.args
            rows = [list(row) for row in values[node]]
            if modp:
                rk, rs, cs = _rank_mod(rows, PRIME)
            else:
                rk = sympy.Matrix(rows).rank(iszerofunc=lambda v: is_zero(sympy.sympify(v)))
                rs = cs = ()
            if rk > r:
                residuals.append(Fraction(rk - r) if not modp else rk - r)
            rank_info.append((node, r, rk, rs, cs))
    if any(x != 0 for x in residuals):
        return _Outcome.FAILS, residuals
    if any(rk < r for _, r, rk, _, _ in rank_info):
        return _Outcome.LOW_RANK, rank_info
    return _Outcome.HOLDS, rank_info


def _random_point(claim: Claim, rng: random.Random, bound: int) -> dict[sympy.Symbol, int]:
    if bound >= PRIME:
        return {s: rng.randrange(PRIME) for s in claim.parameters}
    return {s: rng.randint(-bound, bound) for s in claim.parameters}


def _find_small_counterexample(claim: Claim, R: Any, rng: random.Random, fallback: dict[sympy.Symbol, int],
                               deadline: Deadline) -> Counterexample:
    for attempt in range(120):
        deadline.check("searching a small counterexample")
        point = _random_point(claim, rng, 2 + attempt // 10)
        values = evaluate(claim, _point_evaluator(claim, R, point))
        kind, data = _check_point(claim, values, modp=False)
        if kind == _Outcome.FAILS:
            at = {str(s): Fraction(v) for s, v in point.items()}
            return Counterexample(at, data, claim, check=partial(recheck_counterexample, claim, at))
    values = evaluate(claim, _point_evaluator(claim, R, fallback))
    kind, data = _check_point(claim, values, modp=False)
    at = {str(s): Fraction(v) for s, v in fallback.items()}
    return Counterexample(at, data, claim, check=partial(recheck_counterexample, claim, at))


def _describe_ring(R: PolynomialRing) -> str:
    names = [str(s) for s in R.symbols]
    shown = ", ".join(names) if len(names) <= 6 else ", ".join(names[:4]) + ", …"
    return f"{R.field}[{shown}] ({len(names)} variables, {R.order} order)"


def _random_pass(claim: Claim, R: Any, rng: random.Random, deadline: Deadline) -> tuple[str, Any, str]:
    """Returns (outcome, data, summary) with outcome in 'fails', 'holds', 'degenerate', 'low-rank'."""
    last = (_Outcome.DEGENERATE, "", "")
    for trial in range(4):
        deadline.check("random evaluation")
        point = _random_point(claim, rng, PRIME)
        frac = _point_evaluator(claim, R, point)
        values = evaluate(claim, lambda e, frac=frac: _modp(frac(e)), reduce=lambda x: x % PRIME, deadline=deadline)
        kind, data = _check_point(claim, values, modp=True)
        if kind == _Outcome.FAILS:
            return (_Outcome.FAILS, point,
                    f"conclusion nonzero modulo p = 2^61 − 1 at a random point (trial {trial + 1})")
        if kind == _Outcome.HOLDS:
            return _Outcome.HOLDS, (point, data), (
                f"conclusion zero modulo p = 2^61 − 1 at a random point (trial {trial + 1}); "
                "this finds counterexamples but proves nothing"
            )
        last = (kind, data, "")
    kind, data, _ = last
    if kind == _Outcome.LOW_RANK:
        return _Outcome.LOW_RANK, data, "the rank stayed below the claim at four random points"
    return _Outcome.DEGENERATE, data, f"a construction was undefined at four random points: {data}"


def _proportional_by_division(c: Any, values: dict[Node, Any], R: PolynomialRing) -> str | None:
    """Prove u = q·v (or v = q·u) with one exact polynomial division; None when that does not work."""
    u, v = (flat(values[a]) for a in c.args)
    names = [a.label for a in c.args]
    for (x, y), (nx, ny) in (((u, v), names), ((v, u), names[::-1])):
        k = next((i for i, t in enumerate(y) if t != 0), None)
        if k is None or x[k] == 0:
            continue
        q = R.exact_quotient(x[k], y[k])
        if q is not None and q != 0 and all(a == q * b for a, b in zip(x, y, strict=True)):
            scale = R.text(q, 12)
            scale = scale if len(scale) <= 120 else f"a polynomial with {R.nterms(q)} terms"
            return f"{nx} = q·{ny} exactly, with q = {scale} (one exact division, then {len(x)} products compared)"
    return None


def _size(R: PolynomialRing, polys: list[Any]) -> tuple[int, int]:
    """The largest number of terms and the largest total degree among the polynomials."""
    return (max((R.nterms(p) for p in polys), default=0), max((R.degree(p) for p in polys), default=0))


_NOT_DEPENDENT = {"point": "are not collinear", "point3": "are not coplanar", "point1": "are distinct",
                  "line": "are not concurrent", "plane": "do not pass through one point"}


def _general_position(claim: Claim, normalisation: Normalisation, backend: str | None) -> list[Condition]:
    """The frame's general position as conditions in the claim's own coordinates: every n + 1 of its objects
    in Pⁿ independent (one determinant each), e.g. "A, B, C are not collinear"."""
    conv = _converter(claim, backend=backend)
    nodes = [claim.nodes[n] for n in normalisation.objects]  # their coordinates are plain parameters
    if normalisation.group in ("similarity", "euclidean"):  # two points: distinct (similarity), nothing (isometry)
        if normalisation.group == "euclidean":
            return []
        p, q = ([conv(e) for e in n.data] for n in nodes)
        return [Condition(f"{nodes[0].name} ≠ {nodes[1].name} (frame)",
                          raw=[p[i] * q[j] - p[j] * q[i] for i in range(3) for j in range(i + 1, 3)])]
    out = []
    for subset in itertools.combinations(nodes, len(nodes[0].data)):
        minor = alg.det([tuple(conv(e) for e in n.data) for n in subset])
        words = _NOT_DEPENDENT[normalisation.kind]
        out.append(Condition(f"{', '.join(n.name for n in subset)} {words} (frame)", raw=[minor]))
    return out


def _membership_given(poly: Any, basis: list[Any], requirements: list[tuple[str, list[Any]]],
                      deadline: Deadline) -> str | None:
    """A non-degeneracy condition under which the conclusion follows from the hypotheses, or None.

    The condition "c₁, …, cₖ not all zero" suffices when every cᵢ·g lies in the ideal: wherever some cᵢ ≠ 0
    on the hypothesis variety, g = 0 there (a first step of saturating the ideal by the conditions)."""
    for text, polys in requirements:
        deadline.check("reducing the conclusion under a non-degeneracy condition")
        if polys and all((c * poly).div(basis)[1] == 0 for c in polys):
            return text
    return None


def _solved_hypotheses(claim: Claim) -> dict[sympy.Symbol, sympy.Expr] | None:
    """Each hypothesis as ``v = f`` (None when that is not possible): v of degree one with a constant coefficient
    in its hypothesis and in no other. The variety is then the graph of v = f over the other parameters, so a
    polynomial vanishes on it exactly when it vanishes identically once v is replaced by f."""
    hyps = [sympy.expand(h) for h, _ in claim.hypotheses]
    sub: dict[sympy.Symbol, sympy.Expr] = {}
    for i, h in enumerate(hyps):
        others = set().union(*(g.free_symbols for j, g in enumerate(hyps) if j != i))
        for v in sorted(h.free_symbols - others, key=str):
            c = h.coeff(v, 1)
            if c.is_Rational and c != 0 and sympy.degree(h, v) == 1:
                sub[v] = sympy.expand(-(h - c * v) / c)
                break
        else:
            return None
    return sub


def _exact_pass(claim: Claim, deadline: Deadline, rank_witness: list[Any], backend: str | None = None,
                normalisation: Normalisation | None = None) -> tuple[str, Any]:
    solved = _solved_hypotheses(claim) if claim.hypotheses else None
    hyps = claim.hypotheses if solved is None else []
    order = "grevlex" if hyps else "lex"
    # Gröbner reduction runs in SymPy's ring (hypotheses are small); expansion on the fastest backend
    substitution = normalisation.substitution if normalisation is not None else solved
    conv = _converter(claim, order, field=bool(claim.hypotheses), backend="sympy" if hyps else backend,
                      substitution=substitution)
    R = conv.R
    values = evaluate(claim, conv, deadline=deadline, ring=R)
    entries = [p for v in values.values() for p in flat(v) if not isinstance(p, int)]
    largest = max((R.nterms(p) for p in entries), default=0)
    conditions = []
    requirements: list[tuple[str, list[Any]]] = []
    for text, polys in nonzero_requirements(claim, values):
        deadline.check("checking the non-degeneracy conditions")
        if all(p == 0 for p in polys):
            return _Outcome.DEGENERATE, (f"the condition {text} fails identically "
                                         "(the construction is undefined for every value of the parameters)")
        conditions.append(Condition(text, raw=[p for p in polys if p != 0][:3]))
        requirements.append((text, [p for p in polys if p != 0]))
    for node in objects_to_check(claim):
        deadline.check("checking that no construction vanishes identically")
        if all(p == 0 for p in flat(values[node])):
            return _Outcome.DEGENERATE, (f"{node.label} = {node.description} is identically the zero vector "
                                         "(the construction is undefined for every value of the parameters)")
    if normalisation is not None:  # last, so that the claim's own conditions read first
        conditions += _general_position(claim, normalisation, backend)
    deadline.check("reducing the conclusion")
    steps = []
    identity: list[Any] = []
    if hyps:
        G = sympy.groebner([h for h, _ in hyps], *R.symbols, order="grevlex", domain="QQ")
        basis = [R(g.as_expr()) for g in G.exprs]
        method = "Gröbner basis ideal membership"
        steps.append("Gröbner basis (grevlex) of the hypotheses: " + "; ".join(R.text(g) for g in basis))
        for label, poly in conclusion_polys(claim, values, ring=R):
            deadline.check("reducing the conclusion")
            quotients, rem = poly.div(basis)
            if rem != 0:
                needed = _membership_given(poly, basis, requirements, deadline)
                if needed is None:
                    return _Outcome.NOT_IN_IDEAL, (label, R.text(rem))
                steps.append(f"{label} is not in the ideal of the hypotheses, but c·({label}) is for every "
                             f"polynomial c of the condition {needed}: the conclusion holds wherever {needed}")
                continue
            identity.append(poly)
            combo = " + ".join(f"({R.text(q)})·g{i + 1}" for i, q in enumerate(quotients) if q != 0) or "0"
            steps.append(f"{label} = {combo}; remainder 0")
    else:
        method = "polynomial identity (exact expansion)"
        if solved:
            # v − f with pairwise distinct leading variables v absent from every f: a Gröbner basis for a lex
            # order with the v first (coprime leading terms), and reducing modulo it is substituting v = f
            method = "Gröbner basis ideal membership"
            steps.append("the hypotheses " + ", ".join(f"{v} − ({f})" for v, f in solved.items())
                         + " are a Gröbner basis (lex, solved variables first: coprime leading terms); "
                         "reduction modulo it substitutes " + ", ".join(f"{v} = {f}" for v, f in solved.items()))
        done = []
        for c in claim.conclusions:
            if c.kind == "proportional":
                deadline.check("dividing for the scale factor")
                line = _proportional_by_division(c, values, R)
                if line is not None:
                    steps.append(line)
                    done.append(c)
        for label, poly in conclusion_polys(claim, values, done, ring=R):
            deadline.check("expanding the conclusion")
            if poly != 0:
                if solved:
                    return _Outcome.NOT_IN_IDEAL, (label, R.text(poly))
                return _Outcome.NONZERO, (label, R.text(poly))
            steps.append(f"{label} reduces to 0" if solved else f"{label} expands to 0")
    for c in claim.conclusions:
        if c.kind != "rank":
            continue
        node, r = c.args
        rows = values[node]
        n_cols = len(rows[0])
        if r < min(len(rows), n_cols):
            for rs, cs, minor in alg.minors(rows, r + 1):
                deadline.check("expanding the minors")
                if minor != 0:
                    return _Outcome.NONZERO, (f"minor rows {rs} columns {cs} of {node.label}", R.text(minor))
            steps.append(f"all {r + 1}×{r + 1} minors of {node.label} expand to 0")
        witness = next((w for w in rank_witness if w[0] is node), None)
        if witness is None:
            return _Outcome.NO_WITNESS, node.label
        _, _, _rank, rs, cs = witness
        steps.append(f"the {r}×{r} minor of {node.label} on rows {rs}, columns {cs} is nonzero at a random point "
                     "modulo p, hence not the zero polynomial")
    _, degree = _size(R, entries)
    certificate = Certificate(method, _describe_ring(R), steps, largest,
                              normalisation="" if normalisation is None else normalisation.describe(),
                              backend=R.backend, largest_degree=degree)
    return _Outcome.PROVED, (certificate, conditions)


# -- the core check -------------------------------------------------------------------------

def _core_objects(claim: Claim, point: dict[Any, Any], quantities_may_fail: bool = False,
                  values: dict[Node, Any] | None = None) -> dict[Node, Any]:
    """Build the configuration with pgsym's own objects at an exact rational point.

    With the formulas' ``values``, a point ``P + t·Q`` (``Operation.on_span``) is the formula's point when it lies
    on the core's line PQ: which point of the line it is depends on the representatives of P and Q, which the
    core chooses its own way, and the parameter t is free anyway.

    With ``quantities_may_fail``, a ratio the core cannot build here (a ratio of segments that a counterexample
    has made non-parallel) is left out, as a quantity without a core counterpart is: it is no object of the
    configuration, and the conclusion's own polynomial still decides.
    """
    R = _converter(claim).R
    frac = _point_evaluator(claim, R, point)

    def exact(e: Any) -> sympy.Rational:
        x = frac(e)
        return sympy.Rational(x.numerator, x.denominator)

    objs: dict[Node, Any] = {}
    for node in claim.nodes.values():
        build = node.operation.core
        a = [objs.get(x) for x in node.args if isinstance(x, Node)]
        if build is None or any(x is None for x in a):
            continue
        try:
            obj = build(node, a, exact)
        except (PgsymError, CoreDegenerate):
            if quantities_may_fail and node.kind == "ratio":
                continue
            raise
        if values is not None and node.operation.on_span and obj is not None:
            obj = _on_core_span(node, a, values[node], obj)
        if obj is not None:
            objs[node] = obj
    return objs


def _on_core_span(node: Node, args: list[Any], value: Any, own: Any) -> Any:
    """The formula's point as a core object when it lies in the span of the core's arguments, else the core's own."""
    vec = [sympy.Rational(x.numerator, x.denominator) for x in flat(value)]
    if sympy.Matrix([list(x.coords) for x in args] + [vec]).rank() > len(args):
        return own  # not on the core's line: _agree reports the mismatch
    return type(own)(*vec)


def _core_value(obj: Any) -> list[Fraction]:
    if hasattr(obj, "matrix"):
        entries = list(obj.matrix)
    elif hasattr(obj, "coords"):
        entries = list(obj.coords)
    elif hasattr(obj, "shape"):
        entries = list(obj)
    else:
        entries = [obj]
    return [Fraction(int(sympy.Rational(e).p), int(sympy.Rational(e).q)) for e in entries]


def _agree(claim: Claim, objs: dict[Node, Any], values: dict[Node, Any]) -> str | None:
    """None when every core object is proportional to the formula's value, else the first mismatch."""
    for node, obj in objs.items():
        mine = values[node]
        if node.kind == "ratio":
            n, d = mine
            if d == 0 or Fraction(n) / Fraction(d) != _core_value(obj)[0]:
                return node.label
            continue
        u, v = flat(mine), _core_value(obj)
        k = next((i for i, x in enumerate(v) if x != 0), None)
        if len(u) != len(v) or k is None or u[k] == 0 or any(u[i] * v[k] != u[k] * v[i] for i in range(len(u))):
            return node.label
    return None


def _core_check(claim: Claim, rng: random.Random, deadline: Deadline) -> str:
    R = _converter(claim).R
    for _ in range(8):
        deadline.check("comparing with pgsym's core objects")
        point = _random_point(claim, rng, 9)
        values = evaluate(claim, _point_evaluator(claim, R, point))
        try:
            objs = _core_objects(claim, point, values=values)
        except (PgsymError, CoreDegenerate):
            continue
        bad = _agree(claim, objs, values)
        if bad is not None:
            return f"MISMATCH at {bad}"
        return f"{len(objs)} objects rebuilt with pgsym's core at a rational point agree with the formulas"
    return "skipped: the core rejected eight random rational instances as degenerate"


def _on_hypotheses(claim: Claim, point: dict[Any, Fraction]) -> bool:
    """Every equation hypothesis vanishes exactly at the point."""
    sub = {s: sympy.Rational(x.numerator, x.denominator) for s, x in point.items()}
    return all(h.xreplace(sub) == 0 for h, _ in claim.hypotheses)


def _variety_points(claim: Claim, rng: random.Random, deadline: Deadline, tries: int = 60):
    """Exact points of the hypothesis variety: random small values for some parameters, the others solved for.

    Each hypothesis is solved for a parameter it contains to the first degree (or, failing that, for the
    rational roots of what remains once everything else is known), in an order found as it goes.
    """
    hyps = [sympy.expand(h) for h, _ in claim.hypotheses]
    solved: dict[int, sympy.Symbol] = {}
    taken: set[sympy.Symbol] = set()
    for i, h in enumerate(hyps):  # a parameter of degree one, each used for one hypothesis only
        cands = [s for s in claim.parameters if s in h.free_symbols and s not in taken]
        linear = [s for s in cands if sympy.degree(h, s) == 1]
        pick = (linear or cands or [None])[0]
        if pick is not None:
            solved[i] = pick
            taken.add(pick)
    for attempt in range(tries):
        deadline.check("searching points of the hypothesis variety")
        bound = 2 + attempt // 6
        point: dict[sympy.Symbol, sympy.Rational] = {s: sympy.Integer(rng.randint(-bound, bound))
                                                      for s in claim.parameters if s not in taken}
        pending = dict(enumerate(hyps))
        progress = True
        while pending and progress:
            progress = False
            for i, h in list(pending.items()):
                rest = h.xreplace(point)
                unknown = rest.free_symbols
                if not unknown:
                    if rest != 0:
                        pending = {}
                        point = {}
                        break
                    del pending[i]
                    progress = True
                elif unknown == {solved.get(i)}:
                    v = solved[i]
                    roots = [r for r in sympy.Poly(rest, v).ground_roots() if r.is_Rational]
                    if not roots:
                        pending, point = {}, {}
                        break
                    point[v] = rng.choice(roots)
                    del pending[i]
                    progress = True
            if not point:
                break
        if point and not pending and len(point) == len(claim.parameters):
            yield {s: Fraction(int(x.p), int(x.q)) for s, x in point.items()}


def _variety_refutation(ce: Counterexample, summary: str, start: float, base: dict[str, Any]) -> Verdict:
    return Verdict(status=Status.FALSE, counterexample=ce, random_pass=summary,
                   method="a point of the hypothesis variety (hypotheses solved exactly), then exact evaluation",
                   reason="the hypotheses hold and the conclusion fails at the counterexample",
                   elapsed=time.perf_counter() - start, **base)


def _variety_counterexample(claim: Claim, deadline: Deadline, rng: random.Random, tries: int = 60,
                            enough: int = 8) -> Counterexample | None:
    """A point of the hypothesis variety where the constructions are defined and the conclusion fails.

    The search stops after ``tries`` candidate points or ``enough`` points where the conclusion holds.
    """
    R = _converter(claim).R
    holds = 0
    for point in _variety_points(claim, rng, deadline, tries):
        values = evaluate(claim, _point_evaluator(claim, R, point))
        kind, data = _check_point(claim, values, modp=False)
        if kind == _Outcome.FAILS and _on_hypotheses(claim, point):
            at = {str(s): v for s, v in point.items()}
            return Counterexample(at, data, claim, check=partial(recheck_counterexample, claim, at))
        holds += kind == _Outcome.HOLDS
        if holds >= enough:  # a false claim fails almost everywhere on the variety: enough searching
            break
    return None


def recheck_counterexample(claim: Claim, values: dict[str, Any]) -> bool:
    """True when, at these exact values, pgsym's core builds the configuration and the conclusion fails.

    The core objects must be defined (no degenerate construction raised) and agree
    with the formulas, the equation hypotheses must hold exactly; then the conclusion
    polynomials are evaluated exactly.
    """
    point = {s: Fraction(values[str(s)]) for s in claim.parameters}
    vals = evaluate(claim, _point_evaluator(claim, _converter(claim).R, point))
    try:
        objs = _core_objects(claim, point, quantities_may_fail=True, values=vals)
    except (PgsymError, CoreDegenerate):
        return False
    if _agree(claim, objs, vals) is not None:
        return False
    if not _on_hypotheses(claim, point):
        return False
    kind, _ = _check_point(claim, vals, modp=False)
    return kind == _Outcome.FAILS


# -- the entry point --------------------------------------------------------------------------

def _constructions(claim: Claim) -> list[tuple[str, str, str]]:
    return [(n.name, n.kind, n.description) for k, n in claim.nodes.items() if not k.startswith("_")]


def prove(claim: Claim, *, timeout: float | None = 10.0, seed: int = 0, core_check: bool = True,
          backend: str | None = None, normalise_coordinates: bool = True) -> Verdict:
    """Decide a claim: proved (with certificate and conditions), false (with a counterexample), or unknown.

    ``timeout`` (seconds, ``None`` for none) bounds the whole run; when it is
    exceeded the verdict is *unknown*, never *proved*. ``seed`` changes the random
    points (the default makes runs reproducible). ``backend`` chooses the polynomial
    arithmetic (``"flint"`` or ``"sympy"``; default: flint when installed, see
    :mod:`pgsym.proofs.polynomials`); ``normalise_coordinates=False`` keeps the claim's
    coordinates even when a frame could be chosen without loss of generality.

    >>> from pgsym.proofs.claims import Claim
    >>> c = Claim("wrong", "every point lies on the line y = 0", expected=False)
    >>> P = c.free_point("P")
    >>> c.conclude_incident(P, c.line("l", 0, 1, 0))
    >>> v = prove(c)
    >>> v.status, v.counterexample.recheck()
    ('false', True)
    """
    if not isinstance(claim, Claim):
        raise ObjectTypeError(f"prove expects a Claim (or use pgsym.proofs.prove with a catalogue name), got {claim!r}")
    if not claim.conclusions:
        raise UndefinedConstructionError(f"claim {claim.name!r} has no conclusion; add one with a conclude_* method")
    if claim.order_conditions:  # proved on the branches and the region they select (pgsym.proofs.algebraic)
        return prove_ordered(claim, lambda c: prove(c, timeout=timeout, seed=seed, core_check=core_check,
                                                    backend=backend, normalise_coordinates=normalise_coordinates),
                             timeout=timeout, seed=seed, backend=backend)
    if claim.square_roots is not None:  # square roots: branch semantics (pgsym.proofs.algebraic)
        return prove_algebraic(claim, timeout=timeout, seed=seed, backend=backend)
    start = time.perf_counter()
    deadline = Deadline(timeout)
    base = dict(name=claim.name, title=claim.title, statement=claim.statement, expected=claim.expected,
                constructions=_constructions(claim), hypotheses=[t for _, t in claim.hypotheses],
                conclusion=[c.text for c in claim.conclusions])
    rng = claim_rng(claim, seed)
    summary = ""
    try:
        with alarm(timeout):
            R = _converter(claim).R
            rank_witness: list[Any] = []
            if claim.hypotheses:
                summary = "skipped: random points do not satisfy the equation hypotheses"
                # a short search first (a false claim fails almost everywhere on the variety); the full one
                # only when the exact pass does not prove the claim, so true claims do not pay for it
                ce = _variety_counterexample(claim, deadline, rng, tries=12, enough=2)
                if ce is not None:
                    return _variety_refutation(ce, summary, start, base)
            else:
                outcome, data, summary = _random_pass(claim, R, rng, deadline)
                if outcome == _Outcome.FAILS:
                    ce = _find_small_counterexample(claim, R, rng, data, deadline)
                    return Verdict(status=Status.FALSE, method="random evaluation modulo a prime, then exact recheck",
                                   counterexample=ce, random_pass=summary,
                                   reason="the conclusion does not vanish at the counterexample",
                                   elapsed=time.perf_counter() - start, **base)
                if outcome == _Outcome.LOW_RANK:
                    return Verdict(status=Status.UNKNOWN, random_pass=summary,
                                   reason="the matrix had lower rank than claimed at every random point tried",
                                   elapsed=time.perf_counter() - start, **base)
                rank_witness = data[1] if outcome == _Outcome.HOLDS else []
            norm, _why = normalise(claim) if normalise_coordinates else (None, "")
            try:
                status, data = _exact_pass(claim, deadline, rank_witness, backend, norm)
            except TooLarge as err:  # too large to expand: the same identity decided by exact evaluation on a grid
                status, data = by_evaluation.exact_pass(claim, deadline, norm, err.args[0], partial(
                    _general_position, claim, norm, backend), backend)
                status = _Outcome(status)
            if status is _Outcome.PROVED:
                certificate, conditions = data
                core = _core_check(claim, rng, deadline) if core_check else "not requested"
                if core.startswith("MISMATCH"):
                    return Verdict(status=Status.UNKNOWN, random_pass=summary, core_check=core,
                                   reason=f"pgsym's core and the proof formulas disagree ({core})",
                                   elapsed=time.perf_counter() - start, **base)
                method = certificate.method
                if claim.method_note:
                    method = f"rational parametrisation ({claim.method_note}), then {method}"
                return Verdict(status=Status.PROVED, method=method, certificate=certificate, conditions=conditions,
                               random_pass=summary, core_check=core, elapsed=time.perf_counter() - start, **base)
            if status == _Outcome.DEGENERATE:
                return Verdict(status=Status.DEGENERATE, random_pass=summary, reason=data,
                               elapsed=time.perf_counter() - start, **base)
            if claim.hypotheses:
                ce = _variety_counterexample(claim, deadline, rng)
                if ce is not None:
                    return _variety_refutation(ce, summary, start, base)
            if status == _Outcome.NOT_IN_IDEAL:
                reason = (f"{data[0]} has the nonzero remainder {data[1][:200]} modulo the hypotheses: it is not in "
                          "their ideal (it may still hold on a component, or after saturating by the conditions)")
            elif status == _Outcome.NO_WITNESS:
                reason = f"no nonzero minor of {data} of the claimed size was found"
            else:
                ce = _find_small_counterexample(claim, R, rng, _random_point(claim, rng, PRIME), deadline)
                return Verdict(status=Status.FALSE, method="exact expansion, then exact recheck", counterexample=ce,
                               random_pass=summary, reason=f"{data[0]} expands to a nonzero polynomial",
                               elapsed=time.perf_counter() - start, **base)
            return Verdict(status=Status.UNKNOWN, random_pass=summary, reason=reason,
                           elapsed=time.perf_counter() - start, **base)
    except TooLarge as err:
        return Verdict(status=Status.UNKNOWN, random_pass=summary,
                       reason=f"the expansion is too large: {err.args[0]} (no frame could be chosen, or it did not "
                              "suffice)", elapsed=time.perf_counter() - start, **base)
    except Timeout as err:
        return Verdict(status=Status.UNKNOWN, random_pass=summary,
                       reason=f"timed out after {timeout} s while {err.args[0] if err.args else 'working'}",
                       elapsed=time.perf_counter() - start, **base)
