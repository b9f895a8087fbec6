"""Proofs of claims with square roots: which choices of root a proof covers, and the named branch.

An angle bisector, a line meeting a circle, the tangents from a point, a regular polygon or a rotation by 60°
cannot be written with ``+``, ``−``, ``×`` of the coordinates alone. Each is built (by the methods of
:class:`~pgsym.proofs.square_roots.SquareRootConstructions`, a base class of every claim) with a few new
quantities, the *roots*, each tied to the parameters by one defining equation; this module proves claims that
have them (:func:`pgsym.proofs.engine.prove` hands them here):

* a **length root** ``d_A_B`` with ``d² = (x_A w_B − x_B w_A)² + (y_A w_B − y_B w_A)²``, i.e. ``d = ±w_A w_B |AB|``:
  one per segment, shared by every construction that needs the length |AB|. The internal bisector of ∠ABC at
  B has the direction ``d_BC·(A − B) + d_BA·(C − B)`` (scaled unit vectors added), the external one
  ``d_BC·(A − B) − d_BA·(C − B)``. The statement names the *principal* root ``d = +w_A w_B |AB|`` (every
  length positive): then each ``anglebisector`` is internal and each ``exbisector`` external. Changing the
  sign of ``d_A_B`` swaps internal and external at A and at B together;
* an **intersection root** ``e_X`` with ``e² = β² − αγ``, the discriminant of a line meeting a conic
  (``line_conic_intersection``): the two common points are ``(−β ± e) P + α Q``. The statement names no root
  (``intersection`` is either point, ``intersections`` both in either order, ``tangentfrom`` either tangent),
  so a conclusion must hold for both;
* a **root of unity** ``zeta_M`` with ``Φ_M(zeta_M) = 0`` (the cyclotomic polynomial), for rotations by an
  angle and regular polygons: ``cos`` and ``sin`` of a multiple of 360°/M are polynomials in ζ = e^{2πi/M}
  with rational coefficients. The statement names ζ = e^{2πi/M} (counter-clockwise), and its conjugates
  ζ^u replace every angle a by u·a (the clockwise figure, the star polygons).

**Proof for every choice of root.** The defining equations form a triangular set (each root's leading term
is its own power, so they are a Gröbner basis for the lexicographic order with the roots first): a
conclusion polynomial whose remainder modulo them is zero vanishes on every point of the variety, i.e. for
every choice of the roots — this is Wu's method with unit initials. For roots of unity only this is also
necessary: a rational statement true for ζ is true for every conjugate (apply the Galois automorphism).

**Named branches.** When the remainder is not zero, named lengths are written through each other on the
named branch: lengths whose squares multiply to the square of a polynomial λ (one length: Wu's school, B = 0,
A = p²(1 − t², 2t) gives |BA| = p²(1 + t²); two: |AC| = λ|AB|; more: |CD|·|AB| = |CA|·|CB| in a right triangle)
have the product ±λ, with the sign the named roots give it (each has the sign of its w_A w_B) wherever the factors
of that product show a sign (factors of even power, sums of even powers, positive semidefinite quadratic forms);
if the conclusion, with one length of each such product replaced, then reduces to zero the verdict is "proved for
the named branch only", naming a sign change where it fails. Otherwise the claim is evaluated exactly at random
rational instances on every choice of signs of the square roots (exact algebraic numbers, decided by
:func:`pgsym.exact.is_zero`). A failure on the named branch (principal lengths, either intersection root) refutes
the claim, with the branch said; a claim that holds on the named branch at every instance but fails on another is
*unknown* ("holds on the named branch only … not proved"), never *proved*. When the defining equations generate a
field (generic lengths, a single root of unity) a rational statement true on one branch is true on all (the Galois
group permutes them), so one-branch statements need a reducible tower — squares whose product is a square — which
is exactly what the products of lengths detect.

>>> from pgsym.proofs.claims import Claim
>>> from pgsym.proofs.engine import prove
>>> c = Claim("incentre", "the three internal bisectors of a triangle are concurrent")
>>> A, B, C = (c.free_point(n) for n in "ABC")
>>> bs = [c.angle_bisector(n, *p) for n, p in (("a", (B, A, C)), ("b", (A, B, C)), ("c", (A, C, B)))]
>>> c.conclude_concurrent(*bs)
>>> v = prove(c)
>>> v.status, v.branches.split(":")[0]
('proved', 'proved for every choice of root')
"""

from __future__ import annotations

import copy
import itertools
import math
import random
import time
from collections.abc import Callable, Sequence
from contextlib import closing
from dataclasses import dataclass
from fractions import Fraction
from functools import partial
from typing import Any

import sympy

from ..errors import PgsymError
from ..exact import is_zero
from ..exact import sign as exact_sign
from ..projective_plane import Line, Point
from . import budget
from .budget import Deadline, Timeout, TooLarge, alarm
from .by_evaluation import identity_by_evaluation
from .claims import Claim, Node
from .evaluation import claim_rng, conclusion_polys, evaluate, nonzero_requirements, objects_to_check
from .normalisation import normalise
from .operations import flat
from .order import condition_values
from .polynomials import PolynomialRing, default_backend
from .real_signs import plane_sign
from .square_roots import MAX_POLYGON, MAX_ROOTS, Root, SquareRootConstructions, _data, roots_of
from .verdicts import Certificate, Condition, Counterexample, Status, Verdict

__all__ = [
    "MAX_POLYGON",
    "MAX_ROOTS",
    "Root",
    "angle_bisector",
    "circle_intersection",
    "circle_intersections",
    "external_bisector",
    "line_conic_intersection",
    "line_conic_intersections",
    "polygon_vertex",
    "prove_algebraic",
    "prove_ordered",
    "recheck_branch",
    "recheck_ordered",
    "roots_of",
    "rotate_degrees",
    "tangent_from",
    "tangents_from",
]

# -- the proof -------------------------------------------------------------------------------------------

class _Tower:
    """The defining equations as a triangular set (a lex Gröbner basis: leading terms root², or ζ^φ(M))."""

    def __init__(self, claim: Claim, gens: Sequence[sympy.Symbol], backend: str | None = None) -> None:
        roots = roots_of(claim)
        self.order = [r.symbol for r in reversed(roots)]
        self.R = PolynomialRing([*self.order, *gens], integral=False, order="lex",
                                backend=backend or default_backend())
        self.basis: list[Any] = []
        self.text: list[str] = []

    def add(self, root: Root, values: dict[Node, Any]) -> None:
        x = self.R(root.symbol)
        if root.kind == "unity":
            z = sympy.Symbol(str(root.symbol))
            poly = self.R(sympy.cyclotomic_poly(root.modulus, z).xreplace({z: root.symbol}))
        else:
            poly = x * x - self.reduce(root.square(values))
        self.basis.append(poly)
        self.text.append(root.text)

    def reduce(self, p: Any) -> Any:
        if not self.basis or isinstance(p, int):
            return p
        if self.R.backend == "sympy":
            return p.rem(self.basis)
        for g in reversed(self.basis):  # the latest root is the highest variable: its remainder first
            p = divmod(p, g)[1]
        return p


def _evaluate(claim: Claim, scalar: Callable[[Any], Any], tower: _Tower, deadline: Any,
              estimate: bool = False) -> dict[Node, Any]:
    """Every object's value, reduced modulo the roots' equations as they appear (each root's equation joins the
    tower once its value is known); with ``estimate`` the budget's MAX_WORK bounds each construction."""
    by_node = {r.node: r for r in roots_of(claim)}

    def after(node: Node, values: dict[Node, Any]) -> None:
        if node in by_node:
            tower.add(by_node[node], values)

    return evaluate(claim, scalar, tower.reduce, deadline, tower.R if estimate else None, after)


def _requirements(claim: Claim, values: dict[Node, Any]) -> list[tuple[str, list[Any]]]:
    out = list(nonzero_requirements(claim, values))
    out += [(f"{n.label} is not the zero vector", flat(values[n])) for n in objects_to_check(claim)]
    return out


def _sympy_value(R: PolynomialRing, p: Any, sub: dict[sympy.Symbol, Any]) -> sympy.Expr:
    if isinstance(p, (int, Fraction)):
        return sympy.Rational(p)
    return R.to_expr(p).xreplace(sub)


def _radical_zeta(modulus: int) -> bool:
    """SymPy writes cos and sin of 2π/M with radicals (M | 24 or M | 20, and a few more)."""
    angle = 2 * sympy.pi / modulus
    return not (sympy.cos(angle) + sympy.I * sympy.sin(angle)).has(sympy.cos, sympy.sin)


def _zeta_value(modulus: int) -> sympy.Expr:
    """e^{2πi/M} as an exact algebraic number (a root of Φ_M, chosen by its isolating interval)."""
    z = sympy.Symbol("z")
    target = complex(math.cos(2 * math.pi / modulus), math.sin(2 * math.pi / modulus))
    roots = sympy.Poly(sympy.cyclotomic_poly(modulus, z), z).all_roots()
    angle = 2 * sympy.pi / modulus
    radicals = sympy.cos(angle) + sympy.I * sympy.sin(angle)
    if not radicals.has(sympy.cos, sympy.sin):
        return radicals
    return min(roots, key=lambda r: abs(complex(r.evalf(30)) - target))  # selection only; roots differ by > 0.1


@dataclass
class _Branch:
    signs: dict[sympy.Symbol, int]
    values: dict[sympy.Symbol, sympy.Expr]
    named: bool
    text: str


def _branches(claim: Claim, tower: _Tower, values: dict[Node, Any], point: dict[sympy.Symbol, Any]):
    """Every real choice of the square roots at a rational point: their exact values and which branch it is
    (none where a length has no principal sign: a point at infinity, w = 0)."""
    roots = roots_of(claim)
    quadratic = [r for r in roots if r.kind != "unity"]
    base = {r.symbol: _zeta_value(r.modulus) for r in roots if r.kind == "unity"}
    R = tower.R
    for signs in itertools.product((1, -1), repeat=len(quadratic)):
        sgn = dict(zip((r.symbol for r in quadratic), signs, strict=True))
        sub = dict(base)
        real = True
        for r in quadratic:
            q = _sympy_value(R, tower.reduce(r.square(values)), sub)
            s = exact_sign(q)
            if s < 0:
                real = False
                break
            principal = 1
            if r.orient is not None:
                o = _sympy_value(R, tower.reduce(r.orient(values)), sub)
                principal = exact_sign(o)
                if principal == 0:  # a point at infinity (w = 0): no principal root, so no named branch here
                    return
            sub[r.symbol] = sgn[r.symbol] * principal * sympy.sqrt(q)
        if not real:
            continue
        named = all(sgn[r.symbol] > 0 for r in quadratic if r.named)
        words = [f"{r.symbol} = {r.words[0] if sgn[r.symbol] > 0 else r.words[1]}" for r in quadratic]
        readings = [f(sgn) for f in _data(claim).readings]
        text = "; ".join(x for x in (", ".join(words), "; ".join(readings)) if x)
        yield _Branch(sgn, sub, named, text or "the principal root of unity")


def _vanishes(R: PolynomialRing, p: Any, sub: dict[sympy.Symbol, Any], tower: _Tower | None = None) -> bool:
    if tower is not None:  # one root of unity and nothing else: Q[ζ]/Φ_M is the field Q(ζ), zero iff remainder zero
        return tower.reduce(p) == 0
    e = _sympy_value(R, p, sub)
    return bool(e == 0) if e.is_Rational else is_zero(e)


def _check_branch(claim: Claim, R: PolynomialRing, values: dict[Node, Any], reqs: list[tuple[str, list[Any]]],
                  branch: _Branch, deadline: Any, tower: _Tower | None = None) -> tuple[str, list[Any]]:
    roots = roots_of(claim)
    if tower is not None and not (len(roots) == 1 and roots[0].kind == "unity"):
        tower = None

    def vanishes(p: Any, sub: dict[sympy.Symbol, Any]) -> bool:
        return _vanishes(R, p, sub, tower)

    for text, polys in reqs:
        deadline.check("checking a branch")
        if all(vanishes(p, branch.values) for p in polys):
            return "degenerate", [text]
    residuals = []
    for _label, poly in conclusion_polys(claim, values):
        deadline.check("evaluating the conclusion on a branch")
        if not vanishes(poly, branch.values):
            residuals.append(_sympy_value(R, poly, branch.values))
    return ("fails", residuals) if residuals else ("holds", [])


def _instance(claim: Claim, rng: random.Random, bound: int, deadline: Any, denominators: Sequence[int] = (1,)):
    """Random parameters (integers up to ``bound``, or fractions with one of ``denominators``), and the claim's
    values there."""
    params = [p for p in claim.parameters if p not in {r.symbol for r in roots_of(claim)}]

    def draw() -> sympy.Rational:
        d = rng.choice(denominators) if len(denominators) > 1 else 1
        return sympy.Rational(rng.randint(-bound * d, bound * d), d)

    point = {p: draw() for p in params}
    tower = _Tower(claim, [])
    R = tower.R
    values = _evaluate(claim, lambda e: R(sympy.sympify(e).xreplace(point)), tower, deadline)
    return point, tower, values


def recheck_branch(claim: Claim, values: dict[str, Any], branch: dict[str, str]) -> bool:
    """True when, at these rational parameters and these exact values of the roots, the roots satisfy their
    defining equations, the constructions are defined and the conclusion fails (exact arithmetic throughout).

    >>> c = Claim("x", "x")
    >>> A, B, C = (c.point(n, *xy) for n, xy in zip("ABC", ((0, 0), (4, 0), (0, 3))))
    >>> c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))   # the internal one: true
    >>> recheck_branch(c, {}, {"d_A_B": "4", "d_A_C": "3"}), recheck_branch(c, {}, {"d_A_B": "4", "d_A_C": "-3"})
    (False, True)
    """
    roots = {str(r.symbol): r for r in roots_of(claim)}
    point = {p: sympy.Rational(values[str(p)]) for p in claim.parameters if str(p) not in roots}
    tower = _Tower(claim, [])
    R = tower.R
    vals = _evaluate(claim, lambda e: R(sympy.sympify(e).xreplace(point)), tower, Deadline(None))
    sub = {roots[k].symbol: sympy.sympify(v) for k, v in branch.items()}
    for r in roots.values():
        if r.kind == "unity":
            if not is_zero(sympy.cyclotomic_poly(r.modulus, sub[r.symbol])):
                return False
        elif not is_zero(sub[r.symbol] ** 2 - _sympy_value(R, tower.reduce(r.square(vals)), sub)):
            return False
    b = _Branch({}, sub, True, "")
    kind, _ = _check_branch(claim, R, vals, _requirements(claim, vals), b, Deadline(None))
    return kind == "fails"


def _proportional(u: Sequence[Any], v: Sequence[Any]) -> bool:
    return all(is_zero(sympy.expand(u[i] * v[j] - u[j] * v[i])) for i in range(len(u)) for j in range(i + 1, len(u)))


def _core_object(node: Node, value: Any, tower: _Tower, branch: _Branch) -> Any:
    """A point, line or conic matrix of pgsym's core with the exact coordinates of ``value`` on the branch."""
    if node.kind == "conic":
        return sympy.Matrix([[_sympy_value(tower.R, x, branch.values) for x in row] for row in value])
    coords = [_sympy_value(tower.R, x, branch.values) for x in flat(value)]
    return (Point if node.kind == "point" else Line)(*coords)


def _core_check(claim: Claim, rng: random.Random, deadline: Any) -> str:
    """At a rational instance, on the named branch, every algebraic object must be one of the objects pgsym's
    core builds from the same exact arguments (``metric.angle_bisectors``, ``Conic.intersections``,
    ``Conic.tangents_from``, ``metric.rotation``), so the proof's formulas and the library cannot drift."""
    records = _data(claim).core
    if not records:
        return "not needed"
    slow = [r.modulus for r in roots_of(claim) if r.kind == "unity" and not _radical_zeta(r.modulus)]
    if slow:  # exact decisions about roots of unity without radicals (cos 2π/7, …) take too long
        return f"skipped: e^(2πi/{slow[0]}) has no expression in radicals here"
    for _ in range(8):
        deadline.check("comparing with pgsym's core objects")
        point, tower, values = _instance(claim, rng, 6, deadline)
        branch = next((b for b in _branches(claim, tower, values, point) if b.named), None)
        if branch is None:
            continue

        try:
            for node, args, build in records:
                mine = [_sympy_value(tower.R, x, branch.values) for x in flat(values[node])]
                candidates = build(*(_core_object(a, values[a], tower, branch) for a in args))
                if not any(_proportional(mine, list(c.coords)) for c in candidates):
                    return f"MISMATCH at {node.label}"
        except PgsymError as err:  # a degenerate instance or an undecidable cos(2π/7): try another
            last = str(err)
            continue
        return f"{len(records)} algebraic objects agree with pgsym's core at a rational instance (named branch)"
    return "skipped: no rational instance where the core could build every object" + (
        f" ({last[:80]})" if "last" in locals() else "")


def _undecided(err: Exception, timeout: float | None) -> str:
    """Why a prover stopped without a verdict: the expansion's size, the time limit, or an exact evaluation that
    could not be carried out."""
    if isinstance(err, TooLarge):
        return f"the expansion is too large: {err.args[0]}"
    if isinstance(err, Timeout):
        return f"timed out after {timeout} s while {err.args[0] if err.args else 'working'}"
    return f"the exact evaluation could not decide: {err}"


def prove_algebraic(claim: Claim, timeout: float | None = 10.0, seed: int = 0, instances: int = 4,
                    backend: str | None = None) -> Any:
    """Decide a claim with square roots (called by :func:`pgsym.proofs.engine.prove` when the claim has roots).

    Proved for every choice of root when the conclusion is in the ideal of the defining equations (possibly
    after a non-degeneracy condition); otherwise evaluated exactly at ``instances`` random rational instances on
    every choice of signs of the roots: false (with the branch) when the named branch fails, unknown when only
    another branch fails. ``backend`` chooses the polynomial arithmetic as in :func:`~pgsym.proofs.engine.prove`.

    >>> c = Claim("x", "x")
    >>> A, B, C = (c.free_point(n) for n in "ABC")
    >>> c.conclude_perpendicular(c.angle_bisector("b", A, B, C), c.external_bisector("e", A, B, C))
    >>> prove_algebraic(c).branches[:33]
    'proved for every choice of root: '
    """
    start = time.perf_counter()
    deadline = Deadline(timeout)
    roots = roots_of(claim)
    base = dict(name=claim.name, title=claim.title, statement=claim.statement, expected=claim.expected,
                constructions=[(n.name, n.kind, n.description) for k, n in claim.nodes.items()
                               if not k.startswith("_")],
                hypotheses=[t for _, t in claim.hypotheses] + [r.text for r in roots],
                conclusion=[c.text for c in claim.conclusions])

    def done(status: Any, **kw: Any) -> Any:
        return Verdict(status=status, elapsed=time.perf_counter() - start, **base, **kw)

    def proved(certificate: Certificate, branches: str) -> Any:
        # the core rebuilds the objects at a rational instance first: a disagreement withholds the proof
        core = _core_check(claim, claim_rng(claim, seed), deadline)
        if core.startswith("MISMATCH"):
            return done(Status.UNKNOWN, core_check=core, branches="no decision",
                        reason=f"pgsym's core and the proof formulas disagree ({core})")
        return done(Status.PROVED, method=certificate.method, certificate=certificate, conditions=conditions,
                    branches=branches, core_check=core)

    if claim.hypotheses:
        return done(Status.UNKNOWN, reason="equation hypotheses together with square-root constructions are not "
                                           "supported", branches="no decision")
    try:
        with alarm(timeout):
            norm, _why = normalise(claim)
            try:
                norm, tower, values = _framed_values(claim, norm, deadline, backend)
            except TooLarge as err:  # too large to expand: the same membership decided by exact evaluation on a grid
                if norm is not None and any(r.kind == "intersection" for r in roots) and \
                        _frame_breaks_somewhere(claim, norm, deadline, backend, claim_rng(claim, seed)):
                    norm = None
                sub = norm.substitution if norm is not None else {}
                found = identity_by_evaluation(claim, sub, deadline, err.args[0], partial(_Tower, claim,
                                               backend=backend), backend)
                if found.outcome == "nonzero":
                    return _sample(claim, (found.label, found.value), found.ring, rng=claim_rng(claim, seed),
                                   instances=instances, deadline=deadline, done=done, counterexample=Counterexample)
                if found.outcome == "degenerate":
                    return done(Status.DEGENERATE, reason=f"the condition {found.label} fails identically (zero on a "
                                "grid its degree bound makes conclusive)", branches="no decision")
                conditions = [Condition(t) for t in found.conditions] + (
                    [Condition(f"{norm.condition} (frame)")] if norm is not None and norm.condition else [])
                return proved(found.certificate(found.where, "" if norm is None else norm.describe(),
                                                backend or default_backend()), _every_root(roots))
            R = tower.R
            reqs = _requirements(claim, values)
            conditions = []
            for text, polys in reqs:
                deadline.check("checking the non-degeneracy conditions")
                if all(p == 0 for p in polys):
                    return done(Status.DEGENERATE, reason=f"the condition {text} fails identically (for every "
                                "value of the parameters and every choice of root)", branches="no decision")
                if not text.endswith("is not the zero vector"):
                    conditions.append(Condition(text, raw=[p for p in polys if p != 0][:3]))
            if norm is not None and norm.condition:
                conditions.append(Condition(f"{norm.condition} (frame)"))
            steps = ["triangular set (lex, roots first; a Gröbner basis): " + "; ".join(tower.text)]
            failing = None
            for label, poly in conclusion_polys(claim, values, ring=R):
                deadline.check("reducing the conclusion")
                poly = tower.reduce(poly)  # the normal form: 0 exactly when the conclusion is in the ideal
                if poly == 0:
                    steps.append(f"{label} reduces to 0 modulo the defining equations")
                    continue
                kills = _annihilator(tower, poly, deadline)
                needed = next((text for text, polys in reqs if polys and all(kills(c) for c in polys)), None)
                if needed is None:
                    failing = (label, poly)
                    break
                steps.append(f"{label} is not in the ideal, but c·({label}) is for every polynomial c of the "
                             f"condition {needed}: it vanishes wherever {needed}")
            if failing is None:
                entries = [p for v in values.values() for p in flat(v) if not isinstance(p, int)]
                certificate = Certificate("ideal membership modulo the defining equations (Wu's method: a "
                                          "triangular set with unit initials)", R.field + f"[{len(R.symbols)} "
                                          "variables, lex, roots first]", steps,
                                          max((R.nterms(p) for p in entries), default=0), backend=R.backend,
                                          largest_degree=max((R.degree(p) for p in entries), default=0),
                                          normalisation="" if norm is None else norm.describe())
                return proved(certificate, _every_root(roots))
            named = _named_branch_proof(claim, values, tower, deadline)
            if named is not None:
                text, lines, extra = named
                conditions += extra
                certificate = Certificate("ideal membership on the named branch: named roots written through the other "
                                          "named roots there (their squares multiply to a square, and the named "
                                          "signs fix the sign), then reduction modulo the remaining equations",
                                          R.field + f"[{len(R.symbols)} variables, lex, roots first]",
                                          [*steps, *lines], 0, backend=R.backend,
                                          normalisation="" if norm is None else norm.describe())
                return proved(certificate, text)
            return _sample(claim, failing, R, rng=claim_rng(claim, seed), instances=instances, deadline=deadline,
                           done=done, counterexample=Counterexample)
    except (TooLarge, Timeout, PgsymError) as err:
        return done(Status.UNKNOWN, reason=_undecided(err, timeout), branches="no decision")


def _primitive(tower: _Tower, p: Any) -> Any:
    """p divided by a common factor h of its coefficients as a polynomial in the roots (h has no roots; h is the gcd
    of p at two integer values of the roots, kept when it divides p exactly). Multiplying by a nonzero h without
    roots maps normal forms to normal forms, so p·c reduces to 0 exactly when (p/h)·c does, and p vanishes wherever
    p/h does: a conclusion's factor that only scales it (a free point's position on its line) is dropped."""
    R = tower.R
    if not _has_roots(tower, p) or R.nterms(p) < 2:
        return p
    roots = [x for x in R.symbols if x in set(tower.order)]
    values = ((2, -3, 5, -7, 11, -13, 17, -19, 23, -29), (-5, 7, 3, 13, -2, 19, -11, 29, -17, 31))
    a, b = (_compose(R, p, {r: R.constant(v) for r, v in zip(roots, vs, strict=False)}) for vs in values)
    if a == 0 or b == 0:
        return p
    h = a.gcd(b)
    if R.degree(h) < 1:
        return p
    q, r = divmod(p, h)
    return q if r == 0 else p


def _annihilator(tower: _Tower, p: Any, deadline: Any) -> Callable[[Any], bool]:
    """For p ≠ 0 in normal form (degree < the leading degree in every root), the test whether c·p reduces to 0.

    Never when c reduces to a nonzero polynomial without roots (c·p is then in normal form and nonzero: the ring has
    no zero divisors). Otherwise the parameters are first specialised at two points, a ring map that keeps the
    basis's leading terms: a product whose image does not reduce to 0 does not reduce to 0 itself (exact, and cheap,
    as only the roots remain; p's images are formed once for all c). Only then is c·p formed (which for a large
    conclusion and condition takes minutes), and only when its terms times p's stay within the budget's work. Both
    are first divided by their factors without roots (:func:`_primitive`), which changes none of these answers."""
    R = tower.R
    roots = set(tower.order)
    params = [x for x in R.symbols if x not in roots]
    rng = random.Random(len(params))
    points = [{x: R.constant(rng.randint(-97, 97)) for x in params} for _ in range(2)]
    images: list[tuple[dict, list[Any], Any]] = []
    primitive: list[Any] = []  # p's primitive part, formed for the first condition with roots

    def image(i: int) -> tuple[dict, list[Any], Any]:
        while len(images) <= i:
            point = points[len(images)]
            images.append((point, [_compose(R, g, point) for g in tower.basis], _compose(R, primitive[0], point)))
        return images[i]

    def kills(c: Any) -> bool:
        c = tower.reduce(c) if c != 0 else c
        if c == 0:
            return True
        if not _has_roots(tower, c):
            return False
        if not primitive:
            primitive.append(_primitive(tower, p))
        c = _primitive(tower, c)
        for i in range(len(points)):
            deadline.check("multiplying the conclusion by a condition at a point")
            point, basis, p_at = image(i)
            q = _compose(R, c, point) * p_at
            if R.backend == "sympy":
                q = q.rem(basis) if basis else q
            else:
                for g in reversed(basis):
                    q = divmod(q, g)[1]
            if q != 0:
                return False
        if R.nterms(c) * R.nterms(primitive[0]) > budget.MAX_WORK:
            return False  # not shown: the caller then looks for another proof or samples
        deadline.check("multiplying the conclusion by a condition")
        return tower.reduce(c * primitive[0]) == 0

    return kills


def _framed_values(claim: Claim, norm: Any, deadline: Any, backend: str | None) -> tuple[Any, _Tower, dict]:
    """The tower and the values of every object in the frame ``norm`` (None: the claim's own coordinates) — or in
    the claim's own coordinates when the frame breaks a formula (:func:`_frame_breaks`)."""
    rootsyms = {r.symbol for r in roots_of(claim)}
    while True:
        sub = norm.substitution if norm is not None else {}
        params = [p for p in claim.parameters if p not in rootsyms and p not in sub]
        tower = _Tower(claim, params, backend)
        R = tower.R
        cache: dict[Any, Any] = {}

        def conv(e: Any, R: Any = R, sub: Any = sub, cache: Any = cache) -> Any:
            if e not in cache:
                cache[e] = R(sympy.sympify(e).xreplace(sub) if sub else e)
            return cache[e]

        values = _evaluate(claim, conv, tower, deadline, estimate=True)
        if norm is None or not _frame_breaks(claim, values, tower):
            return norm, tower, values
        norm = None


def _frame_breaks_somewhere(claim: Claim, norm: Any, deadline: Any, backend: str | None, rng: random.Random) -> bool:
    """:func:`_frame_breaks` at one random instance of the parameters the frame leaves free, for a claim too large to
    expand: a collapse that holds identically shows at every instance, and one that holds here by coincidence only
    makes the caller drop the frame (always sound). An instance where a construction is undefined drops it too."""
    rootsyms = {r.symbol for r in roots_of(claim)}
    sub = dict(norm.substitution)
    for p in claim.parameters:
        if p not in rootsyms and p not in sub:
            sub[p] = sympy.Integer(rng.randint(-97, 97))
    tower = _Tower(claim, [], backend)
    try:
        values = _evaluate(claim, lambda e: tower.R(sympy.sympify(e).xreplace(sub)), tower, deadline)
        return _frame_breaks(claim, values, tower)
    except PgsymError:
        return True


def _frame_breaks(claim: Claim, values: dict[Node, Any], tower: _Tower) -> bool:
    """Whether a common point of a line and a conic is the zero vector on one branch in these coordinates.

    Its formula ``(−β ± e)·P + α·Q`` starts from the foot P of the origin on the line; when P lies on the conic (the
    frame put a point of both at the origin, e.g. A = (0, 0) on the line AB and the circle through A), α = 0 and one
    branch collapses to 0 while the other is P: the second common point would be lost, and a claim about it
    'proved' of P. Detected as the discriminant being a square s² with the point's coordinates 0 at e = ±s."""
    R = tower.R
    for r in roots_of(claim):
        if r.kind != "intersection":
            continue
        s = _rational_root(R, tower.reduce(r.square(values)))
        if s is None:
            continue
        for node in claim.nodes.values():
            if node.kind != "point" or r.node not in node.args:
                continue
            coords = [R.to_expr(tower.reduce(c)) if not isinstance(c, int) else sympy.Integer(c)
                      for c in flat(values[node])]
            if any(all(sympy.expand(c.xreplace({r.symbol: sign * s})) == 0 for c in coords) for sign in (1, -1)):
                return True
    return False


def _evidently_positive(e: sympy.Expr, gens: Sequence[sympy.Symbol]) -> bool:
    """Positive wherever it is not zero, as its form shows: every term has even exponents and a positive coefficient,
    or it is a quadratic form in (x₁^g₁, …, xₙ^gₙ, 1) that is positive semidefinite (a squared distance such as
    (x − 1)² + y², or x⁴ − x² + 1: :func:`_semidefinite`).

    >>> x, y = sympy.symbols("x y")
    >>> [_evidently_positive(f, [x, y]) for f in (x**2 + y**4, x**2 - 2*x + y**2 + 1, x**2 - 2*x + y**2, x*y)]
    [True, True, False, False]
    >>> [_evidently_positive(f, [x, y]) for f in (x**4 - x**2 + 1, x**4 - x + 1, x**6 - 2*x**3*y + y**2, x**3 + 1)]
    [True, False, True, False]
    """
    poly = sympy.Poly(e, *gens) if gens else None
    if poly is None:
        return bool(e > 0)
    if poly.is_zero:
        return False
    if all(c > 0 and all(k % 2 == 0 for k in m) for m, c in poly.terms()):
        return True
    return _semidefinite(poly)


def _semidefinite(poly: sympy.Poly) -> bool:
    """Whether the polynomial is F(x₁^g₁, …, xₙ^gₙ) with F of degree 2 and F = uᵀMu ≥ 0 for u = (u₁, …, uₙ, 1), M
    positive semidefinite (Sylvester: all principal minors ≥ 0), with every gᵢ = 1 or every gᵢ the gcd of xᵢ's
    exponents (e.g. x⁴ − x² + 1 is F(x²) with F = u² − u + 1). F ≥ 0 everywhere gives f ≥ 0 everywhere."""
    used = [i for i in range(len(poly.gens)) if any(m[i] for m in poly.monoms())]
    n = len(used) + 1
    if n > 8:
        return False
    gcds = [math.gcd(*(m[i] for m in poly.monoms())) if i in used else 1 for i in range(len(poly.gens))]
    for g in ([1] * len(poly.gens), gcds) if any(x > 1 for x in gcds) else ([1] * len(poly.gens),):
        terms = [(tuple(k // gi for k, gi in zip(mon, g, strict=True)), c) for mon, c in poly.terms()]
        if max(sum(mon) for mon, _ in terms) != 2:
            continue
        m = sympy.zeros(n, n)
        for mon, c in terms:
            a, b = [used.index(i) for i in used for _ in range(mon[i])] + [n - 1] * (2 - sum(mon))
            if a == b:
                m[a, a] += c
            else:
                m[a, b] += sympy.Rational(c, 2)
                m[b, a] += sympy.Rational(c, 2)
        subsets = (list(s) for k in range(1, n + 1) for s in itertools.combinations(range(n), k))
        minors = (m.extract(s, s).det() for s in subsets)
        if all(x >= 0 for x in minors):
            return True
    return False


def _rational_root(R: PolynomialRing, q: Any) -> sympy.Expr | None:
    """s with s² = q (a polynomial of the ring) when q is the square of a polynomial with rational coefficients, as
    an expression (else None): :func:`_square_root` of its factors."""
    s = _square_root(_Factored.of(R, q))
    return None if s is None else sympy.expand(R.to_expr(s.value(R)))


@dataclass
class _Factored:
    """A polynomial of the proof's ring as c·∏ fᵏ over ℚ (factored by the ring's backend, whose factors are normalised,
    so the same factor of two polynomials has the same text, the key): the coefficient and key ↦ (factor, k)."""

    coeff: Fraction
    factors: dict[str, tuple[Any, int]]

    @classmethod
    def of(cls, R: PolynomialRing, p: Any) -> _Factored:
        if isinstance(p, int):
            return cls(Fraction(p), {})
        coeff, factors = p.factor() if R.backend == "flint" else p.factor_list()
        coeff = Fraction(int(coeff.p), int(coeff.q)) if hasattr(coeff, "q") else Fraction(coeff.numerator,
                                                                                           coeff.denominator)
        out: dict[str, tuple[Any, int]] = {}
        for f, k in factors:
            key = str(f)
            out[key] = (f, out[key][1] + int(k) if key in out else int(k))
        return cls(coeff, out)

    def times(self, *others: _Factored) -> _Factored:
        """The product with others, factored."""
        coeff, out = self.coeff, dict(self.factors)
        for o in others:
            coeff *= o.coeff
            for key, (f, k) in o.factors.items():
                out[key] = (f, out[key][1] + k if key in out else k)
        return _Factored(coeff, {key: v for key, v in out.items() if v[1]})

    def value(self, R: PolynomialRing) -> Any:
        out = R(sympy.Rational(self.coeff.numerator, self.coeff.denominator))
        for f, k in self.factors.values():
            out = out * f**k
        return out

    def text(self, R: PolynomialRing, *extra: sympy.Symbol) -> str:
        """The product as SymPy writes it (factors kept, times ``extra``)."""
        return str(sympy.Mul(sympy.Rational(self.coeff.numerator, self.coeff.denominator),
                             *(R.to_expr(f) ** k for f, k in self.factors.values()), *extra))

    def sign(self, R: PolynomialRing, gens: Sequence[sympy.Symbol], known: dict[sympy.Expr, int] | None = None
             ) -> int | None:
        """The sign wherever the polynomial is not 0, when the factors of odd power all have an evident one or one
        that a root-free order condition fixes (``known``, see :func:`_known_signs`)."""
        total = 1 if self.coeff > 0 else -1 if self.coeff < 0 else 0
        for f, k in self.factors.values():
            if k % 2:
                s = _form_or_known_sign(sympy.expand(R.to_expr(f)), gens, known)
                if s is None:
                    return None
                total *= s
        return total


def _square_root(f: _Factored) -> _Factored | None:
    """λ with λ² = f (λ with rational coefficients), from the factorisation; else None."""
    if f.coeff <= 0 or any(k % 2 for _, k in f.factors.values()):
        return None
    num, den = (math.isqrt(x) for x in (f.coeff.numerator, f.coeff.denominator))
    if num * num != f.coeff.numerator or den * den != f.coeff.denominator:
        return None
    return _Factored(Fraction(num, den), {key: (p, k // 2) for key, (p, k) in f.factors.items()})


def _named_value(R: PolynomialRing, square: _Factored, orient: _Factored, gens: Sequence[sympy.Symbol],
                 known: dict[sympy.Expr, int] | None = None) -> tuple[_Factored, _Factored, int] | None:
    """The value on the named branch of a named root (or a product of named roots) whose square is a square λ²:
    ±λ, with the sign σ of λ·o, o the product of the orientations (each named root has the sign of its own),
    when the factors of λ·o show it (some may be fixed by root-free order conditions, ``known``). Returns λ, λ·o
    and σ, or None.

    >>> R = PolynomialRing([sympy.Symbol("t")])
    >>> (t,) = R.gens
    >>> lam, _, sign = _named_value(R, _Factored.of(R, (t - 1)**2), _Factored.of(R, 1 - t), [R.symbols[0]])
    >>> lam.text(R), sign
    ('t - 1', -1)
    """
    lam = _square_root(square)
    if lam is None:
        return None
    signed = lam.times(orient)
    sign = signed.sign(R, gens, known)
    return (lam, signed, sign) if sign in (1, -1) else None


def _compose(R: PolynomialRing, p: Any, sub: dict[sympy.Symbol, Any]) -> Any:
    """p with some of the ring's variables replaced by elements of the ring (in the ring: the conclusion can have
    many thousands of terms, which a SymPy expression would take minutes to hold)."""
    if isinstance(p, int) or not sub:
        return p
    if R.backend == "flint":
        return p.compose(*(sub.get(s, g) for s, g in zip(R.symbols, R.gens, strict=True)))
    # SymPy's ring: numbers by subs (its compose fails on 0 for a variable's power 0), polynomials by compose
    pairs = [(g, sub[s]) for s, g in zip(R.symbols, R.gens, strict=True) if s in sub]
    numbers = [(g, v.LC if v else 0) for g, v in pairs if not v or v.is_ground]
    if numbers:
        p = p.subs(numbers)
    rest = [(g, v) for g, v in pairs if v and not v.is_ground]
    return p.compose(rest) if rest else p


def _has_roots(tower: _Tower, p: Any) -> bool:
    if isinstance(p, int) or p == 0:
        return False
    degrees = p.degrees()
    return any(degrees[i] for i, x in enumerate(tower.R.symbols) if x in set(tower.order))


_MAX_NAMED_TERMS = 2000
"""The largest square or orientation of a named root that is factored to relate it to the others."""


@dataclass
class _Step:
    """On the named branch d·d₁⋯dₖ = value (``whole``: d = value·d₁⋯dₖ, no division)."""

    root: sympy.Symbol
    value: _Factored
    others: tuple[sympy.Symbol, ...]
    whole: bool

    def words(self, R: PolynomialRing) -> str:
        if self.whole:
            return f"{self.root} = {self.value.text(R, *self.others)}"
        return f"{'·'.join(str(x) for x in (self.root, *self.others))} = {self.value.text(R)}"


def _named_branch_proof(claim: Claim, values: dict[Node, Any], tower: _Tower, deadline: Any,
                        known: dict[sympy.Expr, int] | None = None) -> tuple[str, list[str], list[Condition]] | None:
    """Prove the conclusion on the named branch by writing named roots through the others there.

    Named roots d, d₁ … dₖ (d² = q, named sign d·o > 0 with o = w_A w_B; root-free squares) whose squares multiply to
    the square of a polynomial, q·q₁⋯qₖ = λ², satisfy d·d₁⋯dₖ = ±λ. On the named branch every dⱼ·oⱼ > 0, so
    d·d₁⋯dₖ has the sign of o·o₁⋯oₖ, and ±λ has the sign of S = λ·o·o₁⋯oₖ times the chosen sign; when the factors
    of S show its sign σ wherever it is not zero (factors of odd power with an evident sign, :func:`_evident_sign`),
    d·d₁⋯dₖ = σλ on the named branch (where S = 0, either λ = 0 and both sides are 0, or some o = 0 and there is no
    named branch). With k = 0 the root is a polynomial (|AB| for B = A + p²(1 − t², 2t), the tangent half-angle of
    Wu's school), with k = 1 a multiple of another length, with k ≥ 2 e.g. |CD|·|AB| = |CA|·|CB| in a right
    triangle. Then d = σλ·d₁⋯dₖ/(q₁⋯qₖ) where no dⱼ is 0: the conclusion, of degree ≤ 1 in d once reduced, is
    multiplied by q₁⋯qₖ and d replaced; each root so replaced is removed from the others, and the result must
    reduce to zero modulo the remaining defining equations. Returns the branch's words, the certificate's lines
    and the conditions qⱼ ≠ 0, or None. With ``known`` (the signs root-free order conditions give to factors), the
    sign of S may come from them: the proof then covers the figures those conditions select."""
    R = tower.R
    roots = roots_of(claim)
    rootsyms = {r.symbol for r in roots}
    gens = [g for g in R.symbols if g not in rootsyms]
    named: dict[sympy.Symbol, tuple[Any, _Factored, _Factored, Root]] = {}  # d: (q, q and o factored, the root)
    for r in roots:
        deadline.check("looking for the named branch in terms of other roots")
        if r.kind == "unity" or not r.named:
            continue
        q = tower.reduce(r.square(values))
        o = tower.reduce(r.orient(values)) if r.orient is not None else 1
        if q == 0 or _has_roots(tower, q) or _has_roots(tower, o) or max(R.nterms(q), R.nterms(o)) > _MAX_NAMED_TERMS:
            continue
        named[r.symbol] = (q, _Factored.of(R, q), _Factored.of(R, o), r)
    order = list(named)
    kept = list(order)
    steps: list[_Step] = []
    lines = []
    for anywhere in (False, True):  # first through earlier roots only, then through any root not yet replaced
        for d in order:
            if d not in kept:
                continue
            _q, fq, fo, _r = named[d]
            pool = [x for x in kept if x != d and (anywhere or order.index(x) < order.index(d))]
            for subset in (s for k in range(len(pool) + 1) for s in itertools.combinations(pool, k)):
                deadline.check("looking for the named branch in terms of other roots")
                if anywhere and all(order.index(x) < order.index(d) for x in subset):
                    continue  # tried in the first sweep
                found = _named_value(R, fq.times(*(named[x][1] for x in subset)),
                                     fo.times(*(named[x][2] for x in subset)), gens, known)
                if found is None:
                    continue
                lam, signed, sign = found
                # λ/(q₁⋯qₖ) is a polynomial when no factor's power goes below 0: then d = σ·λ/(q₁⋯qₖ)·d₁⋯dₖ
                den = _Factored(Fraction(1), {}).times(*(named[x][1] for x in subset))
                whole = all(k <= lam.factors.get(key, (None, 0))[1] for key, (_f, k) in den.factors.items())
                if whole:
                    value = _Factored(sign * lam.coeff / den.coeff, {
                        key: (f, k - den.factors.get(key, (None, 0))[1]) for key, (f, k) in lam.factors.items()
                        if k - den.factors.get(key, (None, 0))[1]})
                else:
                    value = _Factored(sign * lam.coeff, lam.factors)
                steps.append(_Step(d, value, subset, whole))
                kept.remove(d)
                product = "·".join(str(x) for x in (d, *subset))
                squares = "·".join(f"({named[x][1].text(R)})" for x in (d, *subset))
                lines.append(f"on the named branch {steps[-1].words(R)}: the squares multiply to {squares} = "
                             f"({lam.text(R)})², so {product} = ±{lam.text(R)}; every named root has the sign of its "
                             f"w_A w_B, so the sign is that of {signed.text(R)} "
                             f"({'positive' if sign > 0 else 'negative'} wherever it is not 0: its factors show it"
                             f"{', some by the order conditions' if signed.sign(R, gens) is None else ''})")
                break
    if not steps:
        return None
    numerators = {id(s): s.value.value(R) for s in steps}

    def on_branch(p: Any, flip: sympy.Symbol | None = None) -> Any:
        for s in steps:  # d = value·∏dⱼ (/∏qⱼ): times ∏qⱼ, d replaced (p has degree ≤ 1 in d once reduced)
            deadline.check("reducing the conclusion on the named branch")
            p = tower.reduce(p)
            if isinstance(p, int):
                return p
            zero = _compose(R, p, {s.root: R.constant(0)})
            slope = _compose(R, p, {s.root: R.constant(1)}) - zero
            den = R.constant(1)
            for x in s.others if not s.whole else ():
                den = den * named[x][0]
            num = -numerators[id(s)] if s.root == flip else numerators[id(s)]
            for x in s.others:
                num = num * R(x)
            p = den * zero + slope * num
        return tower.reduce(p)

    others = []
    for label, poly in conclusion_polys(claim, values):
        if on_branch(poly) != 0:
            return None
        lines.append(f"{label} reduces to 0 on the named branch")
        for s in steps if not others else ():
            if on_branch(poly, s.root) != 0:
                others.append((label, s.root))
                break
    divided = dict.fromkeys(x for s in steps if not s.whole for x in s.others)
    conditions = [Condition(f"{named[x][3].words[0].lstrip('+')} ≠ 0 (divided by on the named branch)",
                            raw=[named[x][0]]) for x in divided]
    words = ", ".join(s.words(R) for s in steps)
    if others:
        label, d = others[0]
        other = f"with the sign of {d} changed, {label} does not vanish"
    else:
        other = "it holds with every sign of these roots as well"
    return (f"proved for the named branch only ({words}: {_named_words(claim, {})}); {other}", lines, conditions)


def _named_words(claim: Claim, sub: dict[sympy.Symbol, sympy.Expr]) -> str:
    signs = {r.symbol: 1 for r in roots_of(claim)}
    readings = [f(signs) for f in _data(claim).readings]
    return "; ".join(readings) or "the named roots"


def _every_root(roots: list[Root]) -> str:
    parts = []
    if any(r.kind == "length" for r in roots):
        parts.append("both signs of every length root (so internal and external bisectors alike, swapped in pairs)")
    if any(r.kind == "intersection" for r in roots):
        parts.append("both common points of every intersection")
    for m in sorted({r.modulus for r in roots if r.kind == "unity"}):
        parts.append(f"every conjugate ζ ↦ ζ^u of ζ = e^(2πi/{m}) (u prime to {m}: each angle a becomes u·a, "
                     "e.g. the clockwise figure and the star polygons)")
    return "proved for every choice of root: " + "; ".join(parts)


def _coordinates(claim: Claim, tower: _Tower, values: dict[Node, Any], branch: _Branch) -> str:
    """The exact coordinates of the claim's algebraic points on a branch, as text ("; X = (1, 2 + √3)")."""
    out = []
    for node, _args, _build in _data(claim).core:
        if node.kind != "point" or node.name.startswith("_"):
            continue
        x, y, w = (_sympy_value(tower.R, v, branch.values) for v in flat(values[node]))
        if w == 0 or is_zero(w):
            continue
        out.append(f"{node.name} = ({sympy.radsimp(x / w)}, {sympy.radsimp(y / w)})")
    return "; " + "; ".join(out) if out else ""


def _sample(claim: Claim, failing: tuple[str, Any], R0: PolynomialRing, rng: random.Random, instances: int,
            deadline: Any, done: Callable[..., Any], counterexample: Any) -> Any:
    seen = 0
    other_failure = None
    for attempt in range(12 * instances):
        deadline.check("evaluating random instances")
        point, tower, values = _instance(claim, rng, 3 + attempt // 4, deadline)
        reqs = _requirements(claim, values)
        branches = list(_branches(claim, tower, values, point))
        if not branches:
            continue
        results = [(b, _check_branch(claim, tower.R, values, reqs, b, deadline, tower)) for b in branches]
        if any(kind == "degenerate" for b, (kind, _) in results if b.named):
            continue
        for b, (kind, residuals) in results:
            if kind == "fails" and b.named:
                b.text += _coordinates(claim, tower, values, b)
                at = {str(s): Fraction(int(v.p), int(v.q)) for s, v in point.items()}
                roots = {str(s): str(v) for s, v in b.values.items()}
                ce = counterexample(at, residuals, claim, branch=roots,
                                    check=partial(recheck_branch, claim, at, roots))
                return done(Status.FALSE, counterexample=ce,
                            method="exact evaluation at a rational instance on each choice of root",
                            reason=f"the conclusion fails on the named branch ({b.text})",
                            branches=f"fails on the named branch: {b.text}")
            if kind == "fails" and other_failure is None:
                b.text += _coordinates(claim, tower, values, b)
                other_failure = (point, b, residuals)
        seen += 1
        if seen >= instances:
            break
    label, poly = failing
    if other_failure is not None:
        point, b, _ = other_failure
        at = ", ".join(f"{s} = {v}" for s, v in point.items())
        return done(Status.UNKNOWN,
                    reason=f"{label} is not in the ideal of the defining equations; the conclusion holds on the "
                           f"named branch at {seen} random instances, but fails on another branch, e.g. at {at} "
                           f"with {b.text}: not proved",
                    branches=f"holds on the named branch only ({_named_words(claim, {})}) at {seen} random instances; "
                             "not proved; "
                             f"fails on the branch {b.text}")
    return done(Status.UNKNOWN,
                reason=f"{label} has the nonzero remainder {R0.text(poly)[:200]} modulo the defining equations, "
                       f"yet the conclusion held on every branch at {seen} random instances (a degenerate component?)",
                branches=f"held on every branch at {seen} random instances; not proved")


# the constructions as plain functions of a claim, as they were spelled before they became methods of Claim
angle_bisector = SquareRootConstructions.angle_bisector
external_bisector = SquareRootConstructions.external_bisector
line_conic_intersection = SquareRootConstructions.line_conic_intersection
line_conic_intersections = SquareRootConstructions.line_conic_intersections
circle_intersection = SquareRootConstructions.circle_intersection
circle_intersections = SquareRootConstructions.circle_intersections
tangent_from = SquareRootConstructions.tangent_from
tangents_from = SquareRootConstructions.tangents_from
rotate_degrees = SquareRootConstructions.rotate_degrees
polygon_vertex = SquareRootConstructions.polygon_vertex


# -- order conditions: the branch (or region) they select ------------------------------------------------------

def _selected(claim: Claim, tower: _Tower, values: dict[Node, Any], branch: _Branch) -> bool:
    """Whether the order conditions hold (each polynomial > 0, decided exactly) on this branch of an instance."""
    for _text, poly in condition_values(claim, values):
        if exact_sign(_sympy_value(tower.R, tower.reduce(poly), branch.values)) <= 0:
            return False
    return True


def recheck_ordered(claim: Claim, values: dict[str, Any], branch: dict[str, str]) -> bool:
    """:func:`recheck_branch`, and the order conditions hold there (exact arithmetic throughout).

    >>> c = Claim("x", "x")
    >>> A, B, X = c.point("A", 0, 0), c.point("B", 4, 0), c.point("X", 1, 0)
    >>> _ = c.where_between(X, A, B)
    >>> c.conclude_proportional(X, A)
    >>> recheck_ordered(c, {}, {})        # X = (1, 0) lies between A and B, and X ≠ A
    True
    """
    if not recheck_branch(claim, values, branch):
        return False
    roots = {str(r.symbol): r for r in roots_of(claim)}
    point = {p: sympy.Rational(values[str(p)]) for p in claim.parameters if str(p) not in roots}
    tower = _Tower(claim, [])
    vals = _evaluate(claim, lambda e: tower.R(sympy.sympify(e).xreplace(point)), tower, Deadline(None))
    sub = {roots[k].symbol: sympy.sympify(v) for k, v in branch.items()}
    return _selected(claim, tower, vals, _Branch({}, sub, True, ""))


_MAX_FACTOR_TERMS = 2000
_MAX_SIGN_TERMS = 300  # T with named roots, their squares and orientations: factored to find the sign of T
"""The largest polynomial whose sign is looked for by factoring (a larger one is left undecided)."""


def _signed_factors(expr: sympy.Expr, gens: Sequence[sympy.Symbol], known: dict[sympy.Expr, int]) -> int | None:
    """The sign that ``expr`` has wherever it is not zero, when its factors show it: even powers, factors with
    even exponents and coefficients of one sign, factors whose sign an order condition fixes (``known``); else
    None."""
    if expr == 0:
        return 0
    s = _evident_sign(expr, gens)
    if s is not None:
        return s
    if len(sympy.Add.make_args(expr)) > _MAX_FACTOR_TERMS:
        return None
    coeff, factors = sympy.factor_list(expr, *gens) if gens else (expr, [])
    total = 1 if coeff > 0 else -1
    for f, k in factors:
        if k % 2 == 0:
            continue
        s = _form_or_known_sign(f, gens, known)
        if s is None:
            s = plane_sign(f, gens)  # one or two variables: decided by a cylindrical decomposition
        if s is None and (moved := _depressed(f, gens)) is not None:
            s = _evident_sign(moved, gens)
        if s is None:
            return None
        total *= s
    return total


def _form_or_known_sign(f: sympy.Expr, gens: Sequence[sympy.Symbol], known: dict[sympy.Expr, int] | None
                        ) -> int | None:
    """A factor's sign as its form shows it (:func:`_evident_sign`), else as a root-free order condition fixes it."""
    s = _evident_sign(f, gens)
    return _known_sign(sympy.expand(f), known, gens) if s is None and known else s


def _known_sign(f: sympy.Expr, known: dict[sympy.Expr, int], gens: Sequence[sympy.Symbol]) -> int | None:
    """The sign an order condition fixes for the expanded factor f (see :func:`_known_signs`), or None: f or −f is a
    known factor, or f = c·k + r with k of known sign, c a number and r evidently of the sign of c·k (t + 1 > 0
    once t > 0).

    >>> t = sympy.Symbol("t")
    >>> _known_sign(t + 1, {t: 1}, [t]), _known_sign(-t - 1, {t: 1}, [t]), _known_sign(t - 1, {t: 1}, [t])
    (1, -1, None)
    """
    s = known.get(f, -known[-f] if -f in known else None)
    if s is not None or not gens:
        return s
    lead = sympy.Poly(f, *gens).LC()
    for k, sk in known.items():
        c = lead / sympy.Poly(k, *gens).LC()
        if not c.is_Rational:
            continue
        sign = sk if c > 0 else -sk  # the sign of c·k
        rest = sympy.expand(f - c * k)
        if rest == 0 or _evident_sign(rest, gens) == sign:
            return sign
    return None


def _evident_sign(f: sympy.Expr, gens: Sequence[sympy.Symbol]) -> int | None:
    if _evidently_positive(f, gens):
        return 1
    if _evidently_positive(-f, gens):
        return -1
    return None


def _known_signs(conditions: list[tuple[str, sympy.Expr]], gens: Sequence[sympy.Symbol]) -> dict[sympy.Expr, int]:
    """The signs that the root-free order conditions give to single factors: p > 0 with one factor f of odd
    multiplicity whose sign is not evident fixes the sign of f; with two, f and g, it fixes their product's sign,
    and both signs when one of the two ways to have it contradicts itself (−t(t + 1) > 0: t > 0 would make t + 1
    positive too, so t < 0 < t + 1).

    >>> t = sympy.Symbol("t")
    >>> _known_signs([("t > 0", t), ("−t(t + 1) > 0", -t**2 - t)], [t]) == {t: -1, t + 1: 1}
    True
    """
    known: dict[sympy.Expr, int] = {}
    for _text, p in conditions:
        if p == 0 or not gens:
            continue
        coeff, factors = sympy.factor_list(p, *gens)
        odd = [sympy.expand(f) for f, k in factors if k % 2 and _evident_sign(f, gens) is None]
        if len(odd) not in (1, 2):
            continue
        rest = 1 if coeff > 0 else -1  # the sign of the product of the odd factors, where p > 0
        for f, k in factors:
            if k % 2 and sympy.expand(f) not in odd:
                rest *= _evident_sign(f, gens) or 1
        if len(odd) == 1:
            known[odd[0]] = rest
            continue
        f, g = odd
        ways = [(sf, rest * sf) for sf in (1, -1)
                if _known_sign(g, {f: sf}, gens) != -rest * sf and _known_sign(f, {g: rest * sf}, gens) != -sf]
        if len(ways) == 1:
            known[f], known[g] = ways[0]
    return known


def _root_content(t: sympy.Expr, roots: Sequence[sympy.Symbol]) -> tuple[sympy.Expr, sympy.Expr]:
    """T = content × rest, the content the gcd of T's coefficients as a polynomial in the roots (free of them):
    the content's sign is read from its factors alone, and the rest is smaller to split by the roots.

    >>> x, r = sympy.symbols("x r")
    >>> _root_content(sympy.expand(x**2 * (x + 1) * (r - x)), [r])
    (x**3 + x**2, r - x)
    """
    present = [r for r in roots if t.has(r)]
    if not present:
        return t, sympy.Integer(1)
    poly = sympy.Poly(t, *present)
    if not poly.domain.is_PolynomialRing:
        return sympy.Integer(1), t
    content, rest = poly.primitive()
    return poly.domain.to_sympy(content), rest.as_expr()


def _depressed(f: sympy.Expr, gens: Sequence[sympy.Symbol]) -> sympy.Expr | None:
    """f with each variable x moved to x − c, where the shift c = a₁/(d·a₀) that removes the second highest power
    of x (a₀, a₁ its two highest coefficients, d its degree) is a number: a polynomial in (x + 1)² + y² or in
    (x − 2)² shows its sign then. A shift of the variables is a bijection of the space, so the sign everywhere
    is kept. None when no variable has such a shift.

    >>> x, y = sympy.symbols("x y")
    >>> _depressed(sympy.expand(((x + 1)**2 + y**2)**2 + 1), [x, y])
    x**4 + 2*x**2*y**2 + y**4 + 1
    """
    shift = {}
    for x in gens:
        p = sympy.Poly(f, x)
        if p.degree() < 2:
            continue
        a0, a1 = p.all_coeffs()[:2]
        c = sympy.cancel(a1 / (p.degree() * a0))
        if c.is_Rational and c != 0:
            shift[x] = x - c
    return sympy.expand(f.xreplace(shift)) if shift else None


def _sign_over_named_root(t: sympy.Expr, params: Sequence[sympy.Symbol], known: dict[sympy.Expr, int],
                          roots: Sequence[Any], values: dict[Any, Any], tower: _Tower) -> int | None:
    """The sign of T (wherever it is not 0) when T involves named length roots, whose principal sign is that of
    their orientation: a root r whose square is a square λ² is ±λ (:func:`_named_value`); for T = A + r·B with one
    root r left (r² = q), A and r·B of one sign, or |A| ≤ |r·B| (A² − q·B² ≤ 0) and the sign of r·B known, or
    |A| ≥ |r·B| and the sign of A known. Else None (also when a square or an orientation has more than
    _MAX_SIGN_TERMS terms)."""
    R = tower.R
    present = [r for r in roots if r.named and r.kind == "length" and t.has(r.symbol) and r.orient is not None]
    signs = {}
    for root in present:
        q, orient = tower.reduce(root.square(values)), tower.reduce(root.orient(values))
        if any(_has_roots(tower, x) or (not isinstance(x, int) and R.nterms(x) > _MAX_SIGN_TERMS) for x in (q, orient)):
            return None
        signs[root] = sympy.expand(R.to_expr(q)), _signed_factors(sympy.expand(R.to_expr(orient)), params, known)
        found = _named_value(R, _Factored.of(R, q), _Factored.of(R, orient), params, known)
        if found is not None:
            lam, _, sign = found
            t = sympy.expand(t.xreplace({root.symbol: sign * R.to_expr(lam.value(R))}))  # r = σλ
    left = [r for r in present if t.has(r.symbol)]
    if any(t.has(r.symbol) for r in roots if r not in left):
        return None  # a root whose branch the statement leaves open
    if not left:
        return _signed_factors(t, params, known)
    if len(left) > 1:
        return None
    [root] = left
    q, sr = signs[root]
    if not sr:
        return None
    poly = sympy.Poly(t, root.symbol)
    if poly.degree() > 1:
        return None
    b, a = (sympy.expand(c) for c in poly.all_coeffs()) if poly.degree() == 1 else (sympy.Integer(0), t)
    sa, sb = _signed_factors(a, params, known), _signed_factors(b, params, known)
    srb = None if sb is None else sb * sr
    if sa is not None and srb is not None and (sa == srb or 0 in (sa, srb)):
        return sa or srb
    norm = _signed_factors(sympy.expand(a * a - q * b * b), params, known)
    if norm is not None and norm <= 0 and srb is not None:
        return srb  # |A| ≤ |r·B|
    if norm is not None and norm >= 0 and sa is not None:
        return sa  # |A| ≥ |r·B|
    return None


def _component_proof(claim: Claim, tower: _Tower, values: dict[Node, Any], pair: list[Root],
                     params: list[sympy.Symbol], deadline: Any) -> tuple[list[str], str] | str:
    """Prove the conclusion where the order conditions select, for two intersection roots e₁, e₂ (eᵢ² = Δᵢ) whose
    squares multiply to a square, Δ₁Δ₂ = λ²: then e₁e₂ = ±λ, and the figure has two components. On the
    component e₁e₂ = σλ, e₂ = σλe₁/Δ₁, so a polynomial a + b·e₁ + c·e₂ + d·e₁e₂ times Δ₁ > 0 is
    (a + dσλ)Δ₁ + (bΔ₁ + cσλ)·e₁. The conclusion must vanish identically there for one σ; on the other component
    an order condition p₀ + p₁e₁ must be ≤ 0 at both e₁ = ±√Δ₁, i.e. p₀ ≤ 0 and p₀² − p₁²Δ₁ ≥ 0 (their factors
    show it): the condition then excludes every branch of that component. Returns the certificate's lines and the
    branch words, or why it does not apply."""
    R = tower.R
    one, two = sorted(pair, key=lambda r: tower.order.index(r.symbol) if r.symbol in tower.order else 0)
    e1, e2 = one.symbol, two.symbol
    if [r for r in roots_of(claim) if r not in pair]:
        return "the exact selection over two roots handles claims with no other square roots"

    def reduced(x: Any) -> sympy.Expr:
        return sympy.expand(R.to_expr(tower.reduce(x)))

    q1, q2 = tower.reduce(one.square(values)), tower.reduce(two.square(values))
    d1, d2 = reduced(q1), reduced(q2)
    lam = None if d1.has(e1, e2) or d2.has(e1, e2) else _rational_root(R, q1 * q2)
    if lam is None:
        return "the two roots' squares do not multiply to a square: no component to select"

    def on(x: Any, sigma: int) -> tuple[sympy.Expr, sympy.Expr] | None:
        p = sympy.Poly(reduced(x), e1, e2)
        if p.degree(e1) > 1 or p.degree(e2) > 1:
            return None
        a, b, c, d = (p.coeff_monomial(m) for m in (1, e1, e2, e1 * e2))
        return sympy.expand((a + d * sigma * lam) * d1), sympy.expand(b * d1 + c * sigma * lam)

    goals = list(conclusion_polys(claim, values))
    good = [sigma for sigma in (1, -1) if all(on(p, sigma) == (0, 0) for _label, p in goals)]
    if len(good) != 1:
        return "the conclusion does not vanish on exactly one of the components e₁e₂ = ±λ"
    sigma = good[0]
    for text, poly in condition_values(claim, values):
        deadline.check("the order conditions on the other component")
        split = on(poly, -sigma)
        if split is None:
            continue
        p0, p1 = split
        s0 = _signed_factors(p0, params, {})
        sn = _signed_factors(sympy.expand(p0 * p0 - p1 * p1 * d1), params, {})
        if s0 is not None and s0 <= 0 and sn is not None and sn >= 0:
            sign = "+" if sigma > 0 else "−"
            return ([f"{e1}² = Δ₁ and {e2}² = Δ₂ with Δ₁Δ₂ = λ², λ = {lam}: {e1}{e2} = ±λ, two components",
                     f"on the component {e1}{e2} = {sign}λ every conclusion polynomial, times Δ₁ and with "
                     f"{e2} = {sign}λ{e1}/Δ₁, reduces to 0 modulo {e1}² = Δ₁",
                     f"on the other, '{text}' times Δ₁ is p₀ + p₁{e1} with p₀ ≤ 0 and p₀² − p₁²Δ₁ ≥ 0 (their "
                     f"factors show it): ≤ 0 at both {e1} = ±√Δ₁, so the condition excludes that component"],
                    f"the component {e1}{e2} = {sign}λ")
    return "no order condition's sign on the other component is fixed by its factors"


_NORM_METHOD = ("the norm over the conjugate branches is 0, and the order conditions select the branch where the "
                "conclusion vanishes")
_COMPONENT_METHOD = ("the conclusion vanishes on one component of two roots, and the order conditions exclude the "
                     "other")
_NAMED_METHOD = ("ideal membership on the named branch, the named roots written through each other with the signs "
                 "the order conditions fix")


def _selected_branch_proof(claim: Claim, deadline: Any, backend: str | None
                           ) -> tuple[list[str], list[Condition], str, str] | str:
    """Prove the conclusion on the branch the order conditions select, for one intersection root e (e² = Δ).

    Each conclusion polynomial reduces to g = g₀ + g₁e. (1) Its norm over the two branches, g₀² − g₁²Δ, is 0
    modulo the defining equations: at every point one of the two common points satisfies the conclusion. (2) For
    an order condition c = c₀ + c₁e > 0, T = g₁e·(c₀·g₁e + c₁e·g₀) = Δ·g₁(c₀g₁ + c₁g₀) is root-free; where the
    conclusion fails on a branch, it holds on the other, so g₁e = g₀ there and c = (c₀g₁ + c₁g₀)/g₁ has the sign
    of T. When T ≤ 0 wherever it is defined (its factors show it), the condition excludes every branch where
    the conclusion fails. Two roots: :func:`_component_proof`. Named roots only (bisectors, whose branch the
    statement names): :func:`_named_branch_proof` with the signs the root-free conditions fix. Returns the
    certificate's lines, the non-degeneracy conditions, the branch words and the method, or why it does not
    apply."""
    roots = roots_of(claim)
    free = [r for r in roots if not r.named]
    if not roots or any(r.kind == "unity" for r in free):
        return "the exact selection handles the branches of an intersection root; the claim has none"
    norm, _why = normalise(claim)
    if norm is not None and norm.group not in ("similarity", "euclidean"):
        norm = None  # the order conditions are kept by similarities, not by affine maps or homographies
    norm, tower, values = _framed_values(claim, norm, deadline, backend)
    R = tower.R
    # the root the conditions select: the conclusion must then hold on its selected branch for every branch of
    # the other roots (the norm below is 0 modulo all their equations, and T must not involve them)
    # (read off the monomials: a large condition as an expression took minutes)
    polys = [p for _t, c in condition_values(claim, values) if not isinstance(p := tower.reduce(c), int)]
    named = [r for r in free if any(m[i] for p in polys for m, _ in R.terms(p) for i in [R.symbols.index(r.symbol)])]
    if free and len(named) not in (1, 2):
        return (f"the exact selection handles one or two intersection roots named by the order conditions; they name "
                f"{len(named)} of the {len(free)} roots whose branch the statement leaves open")
    params = [g for g in R.symbols if g not in {r.symbol for r in roots}]
    conditions = []
    for text, polys in _requirements(claim, values):
        if all(p == 0 for p in polys):
            return f"the condition {text} fails identically"
        if not text.endswith("is not the zero vector"):
            conditions.append(Condition(text, raw=[p for p in polys if p != 0][:3]))
    if norm is not None and norm.condition:
        conditions.append(Condition(f"{norm.condition} (frame)"))
    frame = [norm.describe() + " (similarities keep every order condition)"] if norm is not None else []
    if not free:  # named roots only (bisectors): their branch, with the signs the root-free conditions fix
        known = _known_signs([(text, sympy.expand(R.to_expr(c))) for text, poly in condition_values(claim, values)
                              if not _has_roots(tower, c := tower.reduce(poly))], params)
        on_named = _named_branch_proof(claim, values, tower, deadline, known) if known else None
        if on_named is None:
            return "the signs the order conditions fix do not decide the named roots' branch"
        text, lines, extra = on_named
        return (frame + lines, conditions + extra, text.replace("proved for the named branch only", "the named branch"),
                _NAMED_METHOD)
    if len(named) == 2:
        found = _component_proof(claim, tower, values, named, params, deadline)
        return found if isinstance(found, str) else (frame + found[0], conditions, found[1], _COMPONENT_METHOD)
    root = named[0]
    e = root.symbol
    others = {r.symbol for r in roots} - {e}

    def split(p: Any) -> tuple[Any, Any]:  # p = p₀ + p₁·e modulo the defining equations, in the ring
        x = R.to_expr(tower.reduce(p))
        return R(x.coeff(e, 0)), R(x.coeff(e, 1))

    def reduced(x: Any) -> sympy.Expr:  # modulo the defining equations (the other roots' too), as an expression
        return sympy.expand(R.to_expr(tower.reduce(x)))

    delta = tower.reduce(root.square(values))
    at = [i for i, x in enumerate(R.symbols) if x in others]

    def involves_others(p: Any) -> bool:
        return not isinstance(p, int) and any(m[i] for m, _ in R.terms(p) for i in at)
    conds = []
    for text, poly in condition_values(claim, values):
        deadline.check("splitting the order conditions by branch")
        conds.append((text, *split(poly)))
    known = _known_signs([(t, x) for t, c0, c1 in conds if c1 == 0
                          for x in [reduced(c0)] if not x.free_symbols & others], params)
    lines = [f"{e}² = Δ (the branches ±{e}); the order conditions, each > 0: "
             + "; ".join(t for t, _, _ in conds), *frame]
    for label, poly in conclusion_polys(claim, values):
        deadline.check("the conclusion on the selected branch")
        g0, g1 = split(poly)
        if g1 == 0 and g0 == 0:
            lines.append(f"{label} reduces to 0 modulo the defining equations (on both branches)")
            continue
        if g1 == 0:
            return f"{label} does not depend on the branch of {e}, and it is not in the ideal"
        if tower.reduce(g0 * g0 - g1 * g1 * delta) != 0:
            return f"the norm of {label} over the two branches of {e} is not 0: it fails on both somewhere"
        for text, c0, c1 in conds:
            if c1 == 0:
                continue
            t = tower.reduce(g1 * (c0 * g1 + c1 * g0))
            if involves_others(t):  # times Δ ≥ 0 (a real branch), the other roots may cancel
                t = tower.reduce(t * delta)
            if R.nterms(t) > _MAX_FACTOR_TERMS:
                continue  # too large to factor
            if involves_others(t):
                content, rest = _root_content(reduced(t), [r.symbol for r in roots])
                if len(sympy.Add.make_args(rest)) > _MAX_SIGN_TERMS:
                    continue  # its sign involves the named roots, and it is too large to split by them
                sc = _signed_factors(content, params, known)
                s = sc and _sign_over_named_root(rest, params, known, roots, values, tower)
                s = None if s is None else sc * s
            else:
                s = _signed_factors(reduced(t), params, known)
            if s is not None and s <= 0:
                why = ("it is 0" if s == 0 else "its factors are squares and factors of one sign"
                       + (" (some fixed by the order conditions without roots)" if known else ""))
                lines.append(f"{label} = g₀ + g₁·{e}: the norm g₀² − g₁²·Δ reduces to 0 (one branch satisfies it at "
                             f"every point); on a branch where it fails, '{text}' has the sign of "
                             f"T = g₁·(c₀g₁ + c₁g₀) (or Δ·T, Δ ≥ 0), and it is ≤ 0 everywhere ({why}): the condition "
                             "excludes that branch")
                break
        else:
            return (f"no order condition's sign on the failing branch of {label} is fixed by its factors (a "
                    "condition selects the branch only where a polynomial keeps its sign)")
    return lines, conditions, f"the sign of {e} at which they hold", _NORM_METHOD


def prove_ordered(claim: Claim, plain: Callable[[Claim], Any], timeout: float | None = 10.0, seed: int = 0,
                  instances: int = 4, backend: str | None = None) -> Any:
    """Decide a claim with order conditions (called by :func:`pgsym.proofs.engine.prove`): the conclusion must hold
    on every branch and at every real point the conditions select.

    ``plain`` proves the claim without its conditions. Proved without them: proved (the conditions only narrow the
    claim), once a random instance shows they can hold together. Otherwise: the exact selection of
    :func:`_selected_branch_proof` (one or two intersection roots, or named roots whose branch root-free conditions
    fix), else exact evaluation at random rational instances on every branch the conditions select — false with a
    counterexample there, unknown when it holds at every instance tried. A branch the conditions exclude never
    refutes the claim.

    >>> c = Claim("ray", "the point of the line AB at distance |AB| from A on the ray AB is B")
    >>> A, B = c.free_point("A"), c.free_point("B")
    >>> X = c.line_conic_intersection("X", c.join("l", A, B), c.circle("K", A, B))
    >>> _ = c.where_on_ray(X, A, B)
    >>> c.conclude_proportional(X, B)
    >>> from pgsym.proofs.engine import prove
    >>> v = prove(c)
    >>> v.status, v.branches.split(":")[0]
    ('proved', 'proved on the branch the order conditions select')
    """
    start = time.perf_counter()
    deadline = Deadline(timeout)
    unordered = copy.copy(claim)
    unordered.order_conditions = []
    verdict = plain(unordered)
    words = "; ".join(w.text for w in claim.order_conditions)
    verdict.hypotheses = [*verdict.hypotheses, *(f"order condition: {w.text}" for w in claim.order_conditions)]

    def done(status: Any, **kw: Any) -> Any:
        if status != Status.FALSE:
            kw.setdefault("counterexample", None)
        if status != Status.PROVED:
            kw.setdefault("certificate", None)
        for k, v in kw.items():
            setattr(verdict, k, v)
        verdict.status = Status(status)
        verdict.elapsed = time.perf_counter() - start
        return verdict

    if verdict.status == Status.DEGENERATE:
        return done(Status.DEGENERATE)
    if claim.hypotheses:
        return done(Status.UNKNOWN, reason="order conditions together with equation hypotheses are not supported",
                    certificate=None, counterexample=None, branches="no decision")
    rng = claim_rng(claim, seed)
    try:
        with alarm(None if timeout is None else max(timeout - (time.perf_counter() - start), 0.5)):
            if verdict.status == Status.PROVED:
                witness = _ordered_witness(claim, rng, deadline)
                if witness is None:
                    return done(Status.UNKNOWN, certificate=None, branches="no decision",
                                reason=f"proved without the order conditions, but no random instance satisfies them "
                                       f"({words}): they may contradict each other, and a claim about no figure is "
                                       "not proved")
                return done(Status.PROVED, branches=(verdict.branches + "; " if verdict.branches else "")
                            + f"the order conditions ({words}) are not needed; they hold e.g. at {witness}")
            if verdict.status == Status.UNKNOWN and verdict.reason.startswith(("timed out", "the expansion is too")):
                return done(Status.UNKNOWN)
            why = "the claim has no square roots"
            if roots_of(claim):
                found = _selected_branch_proof(claim, deadline, backend)
                if not isinstance(found, str):
                    lines, conditions, branch, method = found
                    witness = _ordered_witness(claim, rng, deadline)
                    if witness is not None:
                        certificate = Certificate(method, "ℚ[parameters, roots] modulo the defining equations", lines)
                        core = _core_check(claim, rng, deadline)
                        if not core.startswith("MISMATCH"):
                            return done(Status.PROVED, certificate=certificate, method=certificate.method,
                                        counterexample=None, reason="", core_check=core, conditions=conditions,
                                        branches=f"proved on the branch the order conditions select: {branch} "
                                                 f"({words}); they hold e.g. at {witness}")
                    why = "no random instance satisfies the order conditions"
                else:
                    why = found
            return _sample_ordered(claim, rng, instances, deadline, done, why, words)
    except (TooLarge, Timeout, PgsymError) as err:
        return done(Status.UNKNOWN, reason=_undecided(err, timeout), branches="no decision")


def _ordered_instances(claim: Claim, rng: random.Random, deadline: Any, tries: int):
    """Random rational instances and, on each, the real branches the order conditions (and the named roots)
    select."""
    for attempt in range(tries):
        deadline.check("looking for instances where the order conditions hold")
        # integers first; then fractions too, since a condition may need a parameter strictly between two integers
        # (F = (A + tB)/(1 + t) lies beyond A only for −1 < t < 0), every other time between −1 and 1
        bound, fractions = 3 + attempt // 4, (1,)
        if attempt >= tries // 2:
            bound, fractions = (1, (2, 3, 4)) if attempt % 2 else (bound, (1, 2, 3))
        point, tower, values = _instance(claim, rng, bound, deadline, fractions)
        try:
            chosen = [b for b in _branches(claim, tower, values, point)
                      if b.named and _selected(claim, tower, values, b)]
        except PgsymError:
            continue
        yield point, tower, values, chosen


def _ordered_witness(claim: Claim, rng: random.Random, deadline: Any) -> str | None:
    with closing(_ordered_instances(claim, rng, deadline, 48)) as instances:  # closed now, not when collected
        for point, _tower, _values, chosen in instances:
            if chosen:
                return ", ".join(f"{s} = {v}" for s, v in point.items()) or "every instance"
    return None


def _sample_ordered(claim: Claim, rng: random.Random, instances: int, deadline: Any, done: Callable[..., Any],
                    why: str, words: str) -> Any:
    with closing(_ordered_instances(claim, rng, deadline, 24 * instances)) as found:
        return _first_failure(claim, found, instances, deadline, done, why, words)


def _first_failure(claim: Claim, found: Any, instances: int, deadline: Any, done: Callable[..., Any], why: str,
                   words: str) -> Any:
    seen = 0
    for point, tower, values, chosen in found:
        if not chosen:
            continue
        reqs = _requirements(claim, values)
        results = [(b, _check_branch(claim, tower.R, values, reqs, b, deadline)) for b in chosen]
        if any(kind == "degenerate" for _, (kind, _) in results):
            continue
        for b, (kind, residuals) in results:
            if kind == "fails":
                b.text = (b.text + _coordinates(claim, tower, values, b)) if roots_of(claim) else "no square roots"
                at = {str(s): Fraction(int(v.p), int(v.q)) for s, v in point.items()}
                roots = {str(s): str(v) for s, v in b.values.items()}
                ce = Counterexample(at, residuals, claim, branch=roots,
                                    check=partial(recheck_ordered, claim, at, roots))
                return done(Status.FALSE, counterexample=ce, certificate=None,
                            method="exact evaluation at a rational instance on each branch the order conditions "
                                   "select",
                            reason=f"the conclusion fails on a branch the order conditions select ({words}): "
                                   f"{b.text}",
                            branches=f"fails on the selected branch: {b.text}")
        seen += 1
        if seen >= instances:
            break
    if not seen:
        return done(Status.UNKNOWN, certificate=None, counterexample=None, branches="no decision",
                    reason=f"no random instance satisfies the order conditions ({words}); they may contradict "
                           "each other")
    return done(Status.UNKNOWN, certificate=None, counterexample=None,
                reason=f"the conclusion holds on the branches the order conditions select ({words}) at {seen} random "
                       f"instances, but it is not proved: {why}",
                branches=f"holds on the selected branch at {seen} random instances; not proved")
