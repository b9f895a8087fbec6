"""Discovery: every incidence relation that holds among a configuration's objects, found and then proved.

:func:`discover` evaluates the claim's constructions at a random exact rational instance and lists
every relation that holds there: a point on a line (or plane, or conic), three collinear points,
three concurrent lines, four coplanar points of P³, six points on a conic. A random instance only
suggests: each relation is then proved (or refuted) by the engine on its own claim, and relations
that hold by construction (a point on the line it was joined into, the meet of two lines on each
of them, a point of a conic it was built on) are marked as such and not sent to the engine.

>>> from pgsym.proofs.language import parse_statement
>>> claim = parse_statement('''
... points A B C D
... point P = meet (join A B) (join C D)
... point Q = meet (join A C) (join B D)
... prove collinear A B P
... ''')
>>> found = discover(claim)
>>> [r.text for r in found if r.kind == "collinear"]
['A, B, P are collinear', 'A, C, Q are collinear', 'B, D, Q are collinear', 'C, D, P are collinear']
>>> all(r.by_construction for r in found)
True
"""

from __future__ import annotations

import itertools
import random
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import sympy

from .. import ring as alg
from .claims import Claim, Node
from .engine import prove
from .operations import OPERATIONS, flat
from .verdicts import Verdict

__all__ = ["MAX_SIX", "Relation", "discover"]

MAX_SIX = 12
"""Six-on-a-conic relations are searched among at most this many points (C(12, 6) = 924 determinants)."""


@dataclass
class Relation:
    """A relation found on a random instance: its kind, objects, text, and how it is known to hold."""

    kind: str  # "on", "collinear", "concurrent", "coplanar", "conconic"
    objects: tuple[str, ...]
    text: str
    by_construction: bool
    verdict: Verdict | None = None

    @property
    def status(self) -> str:
        """``"by construction"``, or the engine's verdict on the relation (proved, false, unknown)."""
        return "by construction" if self.by_construction else str(self.verdict.status if self.verdict else "")


def _instance(claim: Claim, rng: random.Random) -> dict[str, Any]:
    point = {s: sympy.Rational(rng.randint(-97, 97), rng.randint(1, 13)) for s in claim.parameters}
    cache: dict[Any, Fraction] = {}

    def scalar(e: Any) -> Fraction:
        out = cache.get(e)
        if out is None:
            r = sympy.Rational(sympy.sympify(e).subs(point))
            out = cache[e] = Fraction(int(r.p), int(r.q))
        return out

    values: dict[str, Any] = {}
    for node in claim.nodes.values():
        values[node.name] = node.operation.formula(node, [values[a.name] for a in node.args], scalar)
    return values


def _zero(v: Any) -> bool:
    return all(x == 0 for x in v)


def _same(u: Any, v: Any) -> bool:
    return all(u[i] * v[j] == u[j] * v[i] for i in range(len(u)) for j in range(i + 1, len(u)))


def _on(p: Node) -> list[Node]:
    """The arguments p lies on by construction (the operation table's ``lies_on``)."""
    return [p.args[i] for i in p.operation.lies_on]


def _through(x: Node) -> list[Node]:
    """The arguments x passes through by construction (the operation table's ``through``)."""
    return [x.args[i] for i in x.operation.through]


def _lies_on(p: Node, x: Node) -> bool:
    """p lies on x by construction: x is one of p's own, or holds one of them (a point of a line of two planes)."""
    return any(a is x or any(b is x for b in _on(a)) for a in _on(p))


def _incident_by_construction(p: Node, x: Node) -> bool:
    """p lies on x (a line, plane or conic) because of how one of them was built."""
    if any(a is p for a in _through(x)) or _lies_on(p, x):
        return True
    if p.operation.on_span and x.kind in ("line", "plane") and all(any(a is b for b in _through(x)) for a in p.args):
        return True  # a point of the line AB lies on every line and plane through A and B (not on a conic)
    pole = x.operation.polar_of
    return pole is not None and x.args[pole[1]] is p and _lies_on(p, x.args[pole[0]])


def _on_line3_by_construction(c: Node, a: Node, b: Node) -> bool:
    """c lies on the line AB of P³ by construction (a point of AB, or where the line AB meets a plane)."""
    if c.operation.on_span and {id(x) for x in c.args} == {id(a), id(b)}:
        return True
    return any({id(x) for x in _through(line)} == {id(a), id(b)} for line in _on(c) if line.kind == "line3")


def _collinear_by_construction(pts: tuple[Node, ...], lines: list[Node]) -> bool:
    for a, b, c in itertools.permutations(pts):
        if c.operation.on_span and {id(x) for x in c.args} == {id(a), id(b)}:
            return True
    return any(all(_incident_by_construction(p, l) for p in pts) for l in lines)


def _relations(claim: Claim, values: dict[str, Any]) -> list[Relation]:
    nodes = [n for n in claim.nodes.values() if not n.name.startswith("_")]
    by_kind: dict[str, list[Node]] = {}
    for n in nodes:
        if n.kind in ("point", "line", "point3", "plane", "conic") and (n.kind == "conic" or not _zero(values[n.name])):
            by_kind.setdefault(n.kind, []).append(n)
    pts, lines = by_kind.get("point", []), by_kind.get("line", [])
    pts3, planes, conics = by_kind.get("point3", []), by_kind.get("plane", []), by_kind.get("conic", [])
    v = values
    names3 = {p.name for p in pts3}
    found: list[Relation] = []

    def distinct(objs: tuple[Node, ...]) -> bool:
        return not any(_same(v[a.name], v[b.name]) for a, b in itertools.combinations(objs, 2))

    for p, x in itertools.chain(itertools.product(pts, lines), itertools.product(pts3, planes)):
        if alg.dot(v[p.name], v[x.name]) == 0:
            found.append(Relation("on", (p.name, x.name), f"{p.name} lies on {x.name}",
                                  _incident_by_construction(p, x)))
    for p, k in itertools.product(pts, conics):
        if alg.dot(v[p.name], alg.matvec(v[k.name], v[p.name])) == 0:
            found.append(Relation("on", (p.name, k.name), f"{p.name} lies on {k.name}",
                                  _incident_by_construction(p, k)))
    for trio in itertools.combinations(pts, 3):
        if distinct(trio) and alg.det([v[p.name] for p in trio]) == 0:
            found.append(Relation("collinear", tuple(p.name for p in trio),
                                  f"{', '.join(p.name for p in trio)} are collinear",
                                  _collinear_by_construction(trio, lines)))
    for trio in itertools.combinations(lines, 3):
        if distinct(trio) and alg.det([v[l.name] for l in trio]) == 0:
            by = any(all(_incident_by_construction(p, l) for l in trio) for p in pts)
            found.append(Relation("concurrent", tuple(l.name for l in trio),
                                  f"{', '.join(l.name for l in trio)} are concurrent", by))
    for trio in itertools.combinations(pts3, 3):
        if distinct(trio) and all(m == 0 for _r, _c, m in alg.minors(alg.transpose([v[p.name] for p in trio]), 3)):
            by = any(_on_line3_by_construction(c, a, b) for a, b, c in itertools.permutations(trio))
            found.append(Relation("collinear", tuple(p.name for p in trio),
                                  f"{', '.join(p.name for p in trio)} are collinear", by))
    collinear3 = {frozenset(r.objects) for r in found if r.kind == "collinear" and r.objects[0] in names3}
    for quad in itertools.combinations(pts3, 4):
        if any(frozenset(t.name for t in trio) in collinear3 for trio in itertools.combinations(quad, 3)):
            continue  # three collinear points are coplanar with any fourth
        if distinct(quad) and alg.det([v[p.name] for p in quad]) == 0:
            by = any(all(_incident_by_construction(p, e) for p in quad) for e in planes)
            found.append(Relation("coplanar", tuple(p.name for p in quad),
                                  f"{', '.join(p.name for p in quad)} are coplanar", by))
    collinear = {frozenset(r.objects) for r in found if r.kind == "collinear"}
    for six in itertools.combinations(pts[:MAX_SIX], 6):
        names = tuple(p.name for p in six)
        if any(frozenset(t) in collinear for t in itertools.combinations(names, 3)) or not distinct(six):
            continue  # three collinear points lie on a conic with any three others (a line pair)
        rows = [(x * x, x * y, y * y, x * w, y * w, w * w) for x, y, w in (v[n] for n in names)]
        if alg.det(rows) == 0:
            by = any(all(_incident_by_construction(p, k) for p in six) for k in conics)
            found.append(Relation("conconic", names, f"{', '.join(names)} lie on a conic", by))
    return found


def _claim_for(claim: Claim, rel: Relation) -> Claim:
    c = Claim(f"{claim.name}: {rel.text}", rel.text)
    c.parameters = list(claim.parameters)
    c.nodes = {k: n for k, n in claim.nodes.items() if n.op in OPERATIONS and not n.operation.conclusion}
    c.hypotheses = list(claim.hypotheses)
    objs = [claim.nodes[n] for n in rel.objects]
    if rel.kind == "on":
        x = objs[1]
        (c.conclude_on_conic if x.kind == "conic" else c.conclude_incident)(*objs)
    elif rel.kind == "collinear":
        (c.conclude_collinear3 if objs[0].kind == "point3" else c.conclude_collinear)(*objs)
    elif rel.kind == "concurrent":
        c.conclude_concurrent(*objs)
    elif rel.kind == "coplanar":
        c.conclude_coplanar(*objs)
    else:
        c.conclude_conconic(*objs)
    return c


def discover(claim: Claim, *, timeout: float | None = 2.0, seed: int = 0, prove_them: bool = True) -> list[Relation]:
    """Every relation among the claim's objects that holds on a random exact instance, each then proved.

    Relations that hold by construction are marked and not proved again; the others carry the engine's
    verdict (``proved``, ``false`` when the instance was special, or ``unknown`` after ``timeout`` seconds
    each). Relations implied by a collinear triple (four coplanar points, six points on a line pair) are
    left out.
    The claim's own conclusions are not needed (and not used).
    """
    rng = random.Random(seed)
    values = None
    for _ in range(8):  # an instance where every construction is defined
        candidate = _instance(claim, rng)
        if all(not _zero(flat(candidate[n.name])) for n in claim.nodes.values()
               if n.kind in ("point", "line", "point3", "plane") and not n.name.startswith("_")):
            values = candidate
            break
    if values is None:
        return []
    found = _relations(claim, values)
    if prove_them:
        for rel in found:
            if not rel.by_construction:
                rel.verdict = prove(_claim_for(claim, rel), timeout=timeout, core_check=False)
    return found

