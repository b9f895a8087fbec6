"""The evaluation of a claim in one arithmetic, shared by both provers.

A claim is a list of constructions; :func:`evaluate` runs their formulas in any ring (integers modulo a
prime, exact polynomials, polynomials modulo the defining equations of square roots), and
:func:`conclusion_polys` turns the conclusions into polynomials that must vanish. The conditions a proof
must keep (:func:`nonzero_requirements`) and the objects that must not vanish (:func:`objects_to_check`)
are read from the same values.

>>> from pgsym.proofs.claims import Claim
>>> c = Claim("demo", "A lies on AB")
>>> A, B = c.point("A", 1, 2), c.point("B", 3, 5)
>>> c.conclude_incident(A, c.join("l", A, B))
>>> conclusion_polys(c, evaluate(c, lambda e: e))
[('lᵀA', 0)]
"""

from __future__ import annotations

import random
import zlib
from collections.abc import Callable, Sequence
from typing import Any

from .. import ring as alg
from . import budget
from .budget import Deadline, Timeout, TooLarge, estimate, metered
from .claims import Claim, Node
from .operations import flat, map_nested
from .polynomials import PolynomialRing

__all__ = ["CANCEL_FROM", "METER_FROM", "cancel_common_denominator", "claim_rng", "conclusion_polys",
           "conclusion_values", "evaluate", "nonzero_requirements", "objects_to_check"]


def evaluate(claim: Claim, scalar: Callable[[Any], Any], reduce: Callable[[Any], Any] | None = None,
             deadline: Deadline | None = None, ring: PolynomialRing | None = None,
             after: Callable[[Node, dict[Node, Any]], None] | None = None, max_work: int | None = None
             ) -> dict[Node, Any]:
    """Every object's value, in the order of construction, with the claim's parameters mapped by ``scalar``.

    ``reduce`` is applied to each entry as it is made (a remainder modulo equations, a residue modulo a prime);
    with ``ring`` each construction's term products are first estimated on stand-ins
    (:func:`~pgsym.proofs.budget.estimate`, an upper bound); beyond :data:`METER_FROM` they are counted as they are
    formed, and a construction that would need more than :data:`~pgsym.proofs.budget.MAX_WORK` of them, or a
    product that would not end before the deadline, raises :class:`~pgsym.proofs.budget.TooLarge` before that
    product starts; ``after(node, values)`` runs once each value is known (the square-root prover adds a root's
    defining equation there); ``max_work`` replaces MAX_WORK.

    >>> from pgsym.proofs.claims import Claim
    >>> c = Claim("x", "x")
    >>> l = c.join("l", c.point("A", 0, 0), c.point("B", 1, 0))
    >>> evaluate(c, lambda e: e)[l]
    (0, 1, 0)
    """
    values: dict[Node, Any] = {}
    for node in claim.nodes.values():
        if deadline is not None:
            deadline.check(f"constructing {node.name}")
        args = [values[a] for a in node.args if isinstance(a, Node)]
        value = None
        if ring is not None:
            limit = budget.MAX_WORK if max_work is None else max_work
            work = estimate(lambda v, node=node: node.operation.formula(node, v, scalar), args, ring)
            if work is not None and work > min(limit, METER_FROM):
                value = _counted(lambda v, wrap, node=node: node.operation.formula(node, v, lambda e: wrap(scalar(e))),
                                 args, limit, deadline, f"{node.name} would need about {work:.1e} term products",
                                 work <= limit)
        if value is None:
            value = node.operation.formula(node, args, scalar)
        if reduce is not None:
            value = map_nested(value, reduce)
        elif deadline is not None and any(hasattr(x, "__len__") and len(x) > budget.MAX_TERMS for x in flat(value)):
            raise TooLarge(f"{node.name} has more than {budget.MAX_TERMS} terms")
        values[node] = value
        if after is not None:
            after(node, values)
    return values


def conclusion_polys(claim: Claim, values: dict[Node, Any], skip: Any = (), ring: PolynomialRing | None = None
                      ) -> list[tuple[str, Any]]:
    """(label, polynomial) pairs that must all vanish; rank conclusions are handled separately.

    With ``ring`` (exact polynomials of that ring) each conclusion is first formed on
    :class:`~pgsym.proofs.budget.Cost` stand-ins; beyond :data:`METER_FROM` term products they are counted as they
    are formed, and one that would need more than :data:`~pgsym.proofs.budget.MAX_WORK` of them raises
    :class:`~pgsym.proofs.budget.TooLarge` before the product that would pass it. Two ratios have the gcd of
    their denominators divided out first (:func:`cancel_common_denominator`).
    """
    out: list[tuple[str, Any]] = []
    for c in claim.conclusions:
        if any(c is x for x in skip):
            continue
        vals = [values[a] for a in c.args if isinstance(a, Node)]
        names = [a.label for a in c.args if isinstance(a, Node)]
        if c.kind == "equal_ratio":  # before the estimate, which cannot see a common factor
            vals = list(cancel_common_denominator(vals))
        if ring is not None:
            work = estimate(lambda v, kind=c.kind, names=names: conclusion_values(kind, v, names), vals, ring)
            if work is not None and work > min(budget.MAX_WORK, METER_FROM):
                why = f"the conclusion {c.text or c.kind} would need about {work:.1e} term products"
                found = _counted(lambda v, wrap, kind=c.kind, names=names: tuple(conclusion_values(kind, v, names)),
                                 vals, budget.MAX_WORK, None, why, work <= budget.MAX_WORK)
                if found is not None:
                    out.extend(found)
                    continue
        out.extend(conclusion_values(c.kind, vals, names))
    return out


def conclusion_values(kind: str, vals: list[Any], names: list[str]) -> list[tuple[str, Any]]:
    """The (label, polynomial) pairs of one conclusion of that kind, from its arguments' values."""
    out: list[tuple[str, Any]] = []
    if kind == "incident":
        out.append((f"{names[1]}ᵀ{names[0]}", alg.dot(vals[0], vals[1])))
    elif kind == "det":
        out.append((f"det[{' '.join(names)}]", alg.det(vals)))
    elif kind == "proportional":
        u, v = flat(vals[0]), flat(vals[1])
        k = next((i for i, x in enumerate(v) if x != 0), 0)
        for i in range(len(u)):
            if i != k:
                out.append((f"{names[0]}[{i}]·{names[1]}[{k}] − {names[0]}[{k}]·{names[1]}[{i}]",
                            u[i] * v[k] - u[k] * v[i]))
    elif kind == "equal":
        u, v = flat(vals[0]), flat(vals[1])
        for i, (a, b) in enumerate(zip(u, v, strict=True)):
            out.append((f"{names[0]}[{i}] − {names[1]}[{i}]", a - b))
    elif kind == "zero":
        for i, a in enumerate(flat(vals[0])):
            out.append((f"{names[0]}[{i}]" if len(flat(vals[0])) > 1 else names[0], a))
    elif kind == "equal_ratio":
        (n1, d1), (n2, d2) = cancel_common_denominator(vals)
        out.append((f"the numerator of {names[0]} − {names[1]}", n1 * d2 - n2 * d1))
    return out


def _counted(compute: Callable[[list[Any], Callable[[Any], Any]], Any], args: list[Any], limit: int,
             deadline: Deadline | None, why: str, fits: bool) -> Any:
    """A large computation run with its term products counted (:func:`~pgsym.proofs.budget.metered`): the estimate
    bounds the number of terms of each product by the product of its factors' numbers of terms, far above the truth
    for polynomials dense in a few variables; the count stops before the product that would pass the limit or not
    end in the time left, and then ``why`` (the estimate) is the reason. A formula that cannot run on counted
    values gives None when the estimate ``fits`` (the caller runs it as it is), else the estimate's refusal."""
    try:
        return metered(compute, args, limit, deadline)
    except TooLarge as err:
        raise TooLarge(f"{why} (counted: {err.args[0]})") from err
    except Timeout:
        raise
    except Exception as err:  # a formula that compares or converts its values
        if fits:
            return None
        raise TooLarge(why) from err


METER_FROM = 10**6
"""Estimated term products from which a construction's products are counted one by one as they are formed
(:func:`~pgsym.proofs.budget.metered`: the estimate is an upper bound, often far above the truth, and each counted
product checks the time limit before it starts); below, the formula runs as it is."""

CANCEL_FROM = 10**6
"""Term products from which two ratios' denominators are divided by their gcd before cross-multiplying (below,
the gcd costs more than it saves)."""


def cancel_common_denominator(vals: Sequence[Any]) -> tuple[tuple[Any, Any], tuple[Any, Any]]:
    """Two ratios n₁/d₁, n₂/d₂ as n₁/(d₁/g), n₂/(d₂/g) with g = gcd(d₁, d₂), when their values have a gcd (exact
    polynomials) and cross-multiplying would be large: n₁d₂ − n₂d₁ = g·(n₁(d₂/g) − n₂(d₁/g)) exactly, so over an
    integral domain one is the zero polynomial exactly when the other is (g ≠ 0). The squared distances of two
    segments with a common end have the common factor w² of its homogeneous coordinate in their denominators.

    >>> import sympy
    >>> from pgsym.proofs.polynomials import PolynomialRing
    >>> R = PolynomialRing(sympy.symbols("x y"))
    >>> x, y = R.gens
    >>> w = (x + y + 1) ** 40       # 861 terms; w² has 3321: cross-multiplying, about 3.6e6 term products
    >>> (n1, d1), (n2, d2) = cancel_common_denominator([(x * w, w * w), (y * w, w * (x + 2))])
    >>> R.to_expr(d1) == R.to_expr(w), R.to_expr(d2)
    (True, x + 2)
    """
    (n1, d1), (n2, d2) = vals
    if type(d1) is not type(d2) or not hasattr(d1, "gcd") or not hasattr(d1, "__len__") or d1 == 0 or d2 == 0:
        return (n1, d1), (n2, d2)
    if _size(n1) * len(d2) + _size(n2) * len(d1) < CANCEL_FROM:
        return (n1, d1), (n2, d2)
    if d1 == d2:
        return (n1, 1), (n2, 1)
    try:
        g = d1.gcd(d2)
        (q1, r1), (q2, r2) = divmod(d1, g), divmod(d2, g)
    except (ArithmeticError, TypeError):  # a ring whose division fails on constants: keep the denominators
        return (n1, d1), (n2, d2)
    if r1 != 0 or r2 != 0 or q1 * g != d1 or q2 * g != d2:  # a gcd divides both: not reached
        return (n1, d1), (n2, d2)
    return (n1, q1), (n2, q2)


def _size(p: Any) -> int:
    return len(p) if hasattr(p, "__len__") else 1


def nonzero_requirements(claim: Claim, values: dict[Node, Any]) -> list[tuple[str, list[Any]]]:
    out = []
    for node in claim.nodes.values():
        args = [values[a] for a in node.args if isinstance(a, Node)]
        for text, polys in zip(node.conditions, node.operation.nonzero(node, values[node], args), strict=True):
            out.append((text, polys))
    for c in claim.conclusions:
        if c.kind == "proportional":
            for a in c.args:
                out.append((f"{a.label} is not zero", flat(values[a])))
        if c.kind == "equal_ratio":
            for a in c.args:
                if not a.operation.given:
                    out.append((f"the denominator of {a.label} is not zero", [values[a][1]]))
    return out


def objects_to_check(claim: Claim) -> list[Node]:
    """The constructed objects that must not be the zero vector: every point, line, plane, line of P³ and
    conic built by an operation (a matrix or scalar may be zero on purpose, e.g. a residual concluded zero)."""
    protected = {id(a) for c in claim.conclusions if c.kind in ("zero", "equal") for a in c.args}
    return [n for n in claim.nodes.values()
            if not n.operation.given and n.kind not in ("matrix", "scalar", "ratio")
            and id(n) not in protected]


def claim_rng(claim: Claim, seed: int) -> random.Random:
    """The random numbers of one proof: fixed by the claim's name and the seed, so runs are reproducible."""
    return random.Random(zlib.crc32(claim.name.encode()) + 7919 * seed)
