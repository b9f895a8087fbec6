"""Choosing coordinates without loss of generality: map free points (or lines, planes) to a projective frame.

Every geometry prover does this first. When a claim is built only from constructions that
commute with every homography (``Operation.group == "projective"``), its free objects are
generic (each coordinate a parameter of its own), and its conclusions are projectively
invariant (an incidence, a collinearity, a concurrency, a coplanarity, an equality up to
scale, an equality of cross-ratios of collinear points or concurrent lines, a point on a conic, a tangent,
six points on a conic, lines of P³ that meet), then the conclusion polynomial vanishes identically as
soon as it vanishes for the configurations whose first four free points of P² (five of P³,
three of P¹; or free lines / planes, dually) are a fixed frame:

* PGL acts transitively on ordered frames, so a homography H maps any configuration whose
  chosen points are in general position to one whose chosen points are the frame;
* every construction commutes with H (up to a nonzero scale), and a point ``s·P + t·Q`` on
  a line with a parameter of its own stays such a point (with another value of the
  parameter), so the image is again a configuration of the claim;
* the conclusion's polynomial changes by a nonzero factor under H, so it vanishes on the
  original exactly when it vanishes on the image;
* the configurations with the chosen points in general position are Zariski-dense, so a
  polynomial that vanishes on them vanishes identically.

Anything else — a fixed object (the line at infinity, the circular points), a matrix, a
formula, a combination with fixed coefficients, an equation hypothesis, a conclusion on raw
coordinates — keeps the claim as it is: :func:`normalise` then says why.

>>> from pgsym.proofs.claims import Claim
>>> c = Claim("demo", "four points")
>>> A, B, C, D = (c.free_point(n) for n in "ABCD")
>>> c.conclude_collinear(c.meet("E", c.join("AB", A, B), c.join("CD", C, D)), A, B)
>>> n, why = normalise(c)
>>> n.substitution == {s: v for s, v in zip(c.parameters, (0, 0, 1, 0, 0, 1, 1, 1))}, n.condition
(True, 'A, B, C, D are in general position (no three collinear)')
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Any

import sympy

from .claims import Claim, Node

__all__ = ["FRAMES", "Normalisation", "normalise"]

#: affine frames (last coordinate 1, so they fit free points in the chart w = 1), by kind: no three of the
#: four points of P² collinear, no four of the five points of P³ coplanar, the three points of P¹ distinct
FRAMES: dict[str, tuple[tuple[int, ...], ...]] = {
    "point": ((0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)),
    "point3": ((0, 0, 0, 1), (1, 0, 0, 1), (0, 1, 0, 1), (0, 0, 1, 1), (1, 1, 1, 1)),
    "point1": ((0, 1), (1, 1), (-1, 1)),
    "line": ((1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)),
    "plane": ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1), (1, 1, 1, 1)),
}

_GENERAL_POSITION = {
    "point": "no three collinear",
    "point3": "no four coplanar",
    "point1": "distinct",
    "line": "no three concurrent",
    "plane": "no four through one point",
}

# conclusions whose polynomial changes by a nonzero factor under a homography (given projective arguments)
_INVARIANT_CONCLUSIONS = ("incident", "det", "proportional", "equal_ratio")

JUSTIFICATION = (
    "PGL acts transitively on ordered frames; every construction of the claim commutes with homographies "
    "(a point on a line with a parameter of its own stays such a point); the conclusion is projectively "
    "invariant; and configurations with these objects in general position are dense — so the conclusion "
    "polynomial vanishes identically once it vanishes on the normalised configurations"
)


@dataclass
class Normalisation:
    """The objects mapped to a frame, the substitution of their parameters, and the condition it needs."""

    group: str
    objects: list[str]
    kind: str
    substitution: dict[sympy.Symbol, int]
    condition: str
    justification: str = JUSTIFICATION
    frame: list[tuple[int, ...]] = field(default_factory=list)

    def describe(self) -> str:
        """One sentence: which objects went where, and why that loses nothing.

        >>> Normalisation("projective", ["A"], "point", {}, "", frame=[(0, 0, 1)]).describe()[:31]
        'without loss of generality A = '
        """
        where = ", ".join(f"{n} = {tuple(f)}" for n, f in zip(self.objects, self.frame, strict=True))
        return f"without loss of generality {where} ({self.group} frame): {self.justification}"


def _generic_vector(node: Node, counts: Counter) -> bool:
    """Each coordinate its own parameter (the last may be a nonzero constant: the dense chart w ≠ 0)."""
    data = node.data
    if not isinstance(data, tuple) or any(isinstance(e, tuple) for e in data):
        return False
    head, last = data[:-1], data[-1]
    if not all(isinstance(e, sympy.Symbol) and counts[e] == 1 for e in head):
        return False
    return (isinstance(last, sympy.Symbol) and counts[last] == 1) or (last.is_Rational and last != 0)


def _generic_symmetric(node: Node, counts: Counter) -> bool:
    """A symmetric matrix (a conic) with its own parameter in each upper entry."""
    m = node.data
    n = len(m)
    upper = [m[i][j] for i in range(n) for j in range(i, n)]
    symmetric = all(m[i][j] == m[j][i] for i in range(n) for j in range(n))
    expected = {e: (1 if (i == j) else 2) for i in range(n) for j in range(i, n) for e in [m[i][j]]}
    return symmetric and all(isinstance(e, sympy.Symbol) and counts[e] == expected[e] for e in upper) \
        and len(set(upper)) == len(upper)


def _fresh_coefficients(node: Node, counts: Counter) -> bool:
    """``s·P + t·Q`` with a parameter of its own among s, t and the other a parameter or a nonzero constant."""
    s, t = node.data

    def own(e: Any) -> bool:
        return isinstance(e, sympy.Symbol) and counts[e] == 1

    def nonzero_constant(e: Any) -> bool:
        return e.is_Rational and e != 0

    return (own(s) or own(t)) and all(own(e) or nonzero_constant(e) for e in (s, t))


def _parameter_counts(claim: Claim) -> Counter:
    counts: Counter = Counter()
    for node in claim.nodes.values():
        if node.op in ("free", "combine", "const") and node.data is not None:
            from .operations import flat

            for e in flat(node.data):
                for s in sympy.sympify(e).free_symbols:
                    counts[s] += 1 if isinstance(e, sympy.Symbol) else 2  # inside an expression: never "own"
    for h, _ in claim.hypotheses:
        for s in h.free_symbols:
            counts[s] += 2
    return counts


def _obstacle(claim: Claim, counts: Counter) -> str | None:
    """Why the claim may not be normalised (None when it may)."""
    if claim.hypotheses:
        return "the claim has equation hypotheses on coordinates"
    for c in claim.conclusions:
        if c.kind == "zero" and c.args[0].operation.conclusion and c.args[0].operation.group == "projective":
            continue  # a quantity of the table that a homography maps by an invertible linear map
        if c.kind not in _INVARIANT_CONCLUSIONS:
            return f"the conclusion '{c.text}' is not projectively invariant"
        if c.kind == "equal_ratio" and any(a.op != "const" and a.operation.group != "projective" for a in c.args):
            return f"the conclusion '{c.text}' compares ratios that are not cross-ratios"
    for node in claim.nodes.values():
        if node.op == "const":
            continue
        if node.op == "free":
            if node.kind in FRAMES and _generic_vector(node, counts):
                continue
            if node.kind == "conic" and _generic_symmetric(node, counts):
                continue
            return f"{node.name} is a fixed object or has special coordinates {node.description}"
        if node.op == "combine":
            if _fresh_coefficients(node, counts):
                continue
            return f"{node.name} = {node.description} depends on the representatives of its points"
        if node.operation.group != "projective":
            return f"{node.name} = {node.description} ({node.op}) does not commute with every homography"
    return None


def normalise(claim: Claim) -> tuple[Normalisation | None, str]:
    """The normalisation the claim allows (or None) and a sentence saying what was done or why not."""
    counts = _parameter_counts(claim)
    why = _obstacle(claim, counts)
    if why is not None:
        return None, f"no normalisation: {why}"
    free = [n for n in claim.nodes.values() if n.op == "free" and n.kind in FRAMES]
    by_kind: dict[str, list[Node]] = {}
    for n in free:
        by_kind.setdefault(n.kind, []).append(n)
    # the kind with the most free objects, points first: it removes the most parameters
    order = ("point", "point3", "point1", "line", "plane")
    kind = max(by_kind, key=lambda k: (min(len(by_kind[k]), len(FRAMES[k])), -order.index(k)), default=None)
    if kind is None:
        return None, "no normalisation: the claim has no free point, line or plane"
    chosen: list[Node] = []
    sub: dict[sympy.Symbol, Any] = {}
    frame = []
    targets = iter(FRAMES[kind])
    target = next(targets)
    for node in by_kind[kind]:
        last = node.data[-1]
        if not isinstance(last, sympy.Symbol) and target[-1] == 0:
            continue  # a fixed last coordinate cannot be sent to 0; leave this object free
        scale = 1 if isinstance(last, sympy.Symbol) else sympy.Rational(last) / target[-1]
        sub.update({e: v * scale for e, v in zip(node.data, target, strict=True) if isinstance(e, sympy.Symbol)})
        chosen.append(node)
        frame.append(tuple(v * scale for v in target))
        target = next(targets, None)
        if target is None:
            break
    if len(chosen) < len(FRAMES[kind]) - 1:
        # fewer than a simplex (n + 1 objects in general position in Pⁿ) saves little, and the conditions
        # read better in the claim's own coordinates
        return None, f"no normalisation: fewer than {len(FRAMES[kind]) - 1} free objects of one kind fit a frame"
    names = [n.name for n in chosen]
    words = _GENERAL_POSITION[kind]
    if len(names) > 2:
        condition = f"{', '.join(names)} are in general position ({words})"
    else:
        condition = " ≠ ".join(names) if len(names) == 2 else ""
    return Normalisation("projective", names, kind, sub, condition, frame=frame), "normalised"
