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

Euclidean claims use smaller groups (``Operation.group``): the affine group (three free points to
(0, 0), (1, 0), (0, 1); midpoints, parallels, centres, signed areas), the orientation-preserving
similarities (two free points to (0, 0), (1, 0); perpendiculars, circles, inversions, rotations by a
fixed angle — no reflection is used, so oriented angles and signed areas keep their sign) and the
orientation-preserving isometries (one point to (0, 0), a second onto the x-axis; circles of a fixed
radius). The frame of the largest group that every construction commutes with and that keeps the
conclusion is used. A conclusion on ratios is kept when both sides change by the same factor: under a
similarity of ratio k a squared distance gains k², a signed area det M = k², a ratio of parallel
segments nothing, so ``|AB|² = |AC|² + |CB|²`` and ``area ABC = area DEF`` keep the similarity frame
while ``|AB|² = 1`` keeps only the isometry frame (on the frame A = (0, 0), B = (1, 0) it would be
"proved"); under an affine map a signed area gains det M, a squared distance no such factor.

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
from .operations import flat

__all__ = ["FRAMES", "GROUPS", "Normalisation", "normalise"]

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
        def shown(f: tuple[Any, ...]) -> str:
            # a metric frame in the chart w = 1 reads as inhomogeneous coordinates, e.g. A = (0, 0)
            if self.group != "projective" and len(f) == 3 and f[-1] == 1:
                return f"({f[0]}, {f[1]})"
            return str(tuple(f))

        where = ", ".join(f"{n} = {shown(f)}" for n, f in zip(self.objects, self.frame, strict=True))
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
        # every node with coefficient data (a free object, a combination, a constant, the parameter of a point on a
        # line or a conic, a squared radius, a rotation's cosine and sine): a parameter is "own" only when it
        # appears once, alone, in all of them
        if node.operation.coefficients and node.data is not None:
            for e in flat(node.data):
                for s in sympy.sympify(e).free_symbols:
                    counts[s] += 1 if isinstance(e, sympy.Symbol) else 2  # inside an expression: never "own"
    for h, _ in claim.hypotheses:
        for s in h.free_symbols:
            counts[s] += 2
    return counts


# -- the groups, largest first: a construction of group g commutes with the normalising group G when g ⊇ G --------
GROUPS = ("projective", "affine", "similarity", "euclidean")
_CONTAINS: dict[str, tuple[str, ...]] = {g: GROUPS[: i + 1] for i, g in enumerate(GROUPS)}
_INVARIANT_WORDS = {"projective": "projectively invariant", "affine": "invariant under affine maps",
                    "similarity": "invariant under similarities", "euclidean": "invariant under isometries"}


def _free(node: Node) -> bool:
    """A free object of the claim (given, not a constant)."""
    return node.operation.given and not node.operation.constant


def _own(e: Any, counts: Counter) -> bool:
    return isinstance(e, sympy.Symbol) and counts[e] == 1


def _node_group(node: Node, counts: Counter) -> str | None:
    """The group a construction commutes with, given its coefficient data.

    A point on a line or a conic with a parameter of its own (the family of its values is mapped onto the family);
    a circle with a squared radius of its own (similarities rescale it: the family again) or a fixed nonzero number
    (only isometries keep it); a rotation by a fixed angle (it commutes with every orientation-preserving
    similarity, the only ones the similarity frame uses). Anything else: ``None``.
    """
    op = node.operation
    if node.group:  # a construction with square roots says its group itself (pgsym.proofs.square_roots)
        return node.group
    if op.node_group is not None:
        return op.node_group(node.data, lambda e: _own(e, counts))
    return op.group


_ZERO = "zero"  # the character of the number 0: an equation "r = 0" is invariant whatever r's character


def _character(node: Node, group: str) -> Any:
    """How a ratio changes under the group: a tuple of exponents (equal tuples: the same factor for every element of
    the group), ``_ZERO`` for the constant 0, ``None`` when it changes by no such factor (or it is not known).

    The exponents (a, b) say: the factor det(M)^a · k^b, k the scale of a similarity. Under the affine group only
    det(M)^a exists (b must be 0); under orientation-preserving similarities det M = k², so the factor is
    k^(2a + b); under isometries it is 1; homographies keep only cross-ratios (a = b = 0).
    """
    op = node.operation
    if op.constant:
        value = node.data[0]
        if not sympy.sympify(value).is_Rational:
            return None  # a parameter as a ratio: its behaviour under the group is unknown
        return _ZERO if value == 0 else ((0,) if group in ("affine", "similarity") else ())  # the factor 1
    if op.ratio_scaling is not None:
        a, b = op.ratio_scaling
        if group == "projective":
            return () if (a, b) == (0, 0) else None
        if group == "affine":
            return (a,) if b == 0 else None
        if group == "similarity":
            return (2 * a + b,)
        return ()
    if op.ratio_arithmetic is not None:
        r, s = (_character(x, group) for x in node.args)
        if r is None or s is None:
            return None
        if op.ratio_arithmetic == "product":
            return _ZERO if _ZERO in (r, s) else tuple(x + y for x, y in zip(r, s, strict=True))
        if r == _ZERO or s == _ZERO:
            return s if r == _ZERO else r
        return r if r == s else None
    return None


def _obstacle(claim: Claim, counts: Counter, group: str = "projective") -> str | None:
    """Why the claim may not be normalised by the group (None when it may)."""
    if claim.hypotheses:
        return "the claim has equation hypotheses on coordinates"
    allowed = _CONTAINS[group]
    for c in claim.conclusions:
        if c.kind == "zero" and c.args[0].operation.conclusion and c.args[0].operation.group in allowed:
            continue  # a quantity of the table that the group multiplies by a nonzero factor
        if c.kind == "equal_ratio":
            r, s = (_character(a, group) for a in c.args)
            if r is not None and s is not None and (r == s or _ZERO in (r, s)):
                continue
            if group == "projective":
                return f"the conclusion '{c.text}' compares ratios that are not cross-ratios"
            return f"the conclusion '{c.text}' compares ratios that the group scales differently"
        if c.kind == "proportional" and any(a.kind in ("ratio", "scalar") for a in c.args):
            # two ratios "equal up to scale" are equal ratios: the group must scale both alike (|AB|⁴ ∝ |AB|² is
            # no invariant statement, though it holds on the frame A = (0, 0), B = (1, 0))
            r, s = (_character(a, group) if a.kind == "ratio" else None for a in c.args)
            if r is not None and s is not None and (r == s or _ZERO in (r, s)):
                continue
            return f"the conclusion '{c.text}' compares quantities that the group may scale differently"
        if c.kind not in _INVARIANT_CONCLUSIONS or c.kind == "zero":
            return f"the conclusion '{c.text}' is not {_INVARIANT_WORDS[group]}"
    for node in claim.nodes.values():
        if node.operation.constant:
            continue
        if node.operation.given:
            if node.root:  # a root of pgsym.proofs.algebraic: fixed by its defining equation
                continue
            if node.kind in FRAMES and _generic_vector(node, counts):
                continue
            if node.kind == "conic" and _generic_symmetric(node, counts):
                continue
            return f"{node.label} is a fixed object or has special coordinates {node.description}"
        if node.operation.fresh_coefficients:
            if _fresh_coefficients(node, counts):
                continue
            return f"{node.label} = {node.description} depends on the representatives of its points"
        if _node_group(node, counts) not in allowed:
            what = {"projective": "every homography", "affine": "every affine map",
                    "similarity": "every similarity", "euclidean": "every isometry"}[group]
            return f"{node.label} = {node.description} ({node.op}) does not commute with {what}"
    return None


METRIC_JUSTIFICATION = {
    "affine": (
        "the affine group acts transitively on ordered triples of non-collinear points; every construction of the "
        "claim commutes with affine maps; the conclusion is affinely invariant (a ratio of signed areas changes by "
        "det M on both sides); and configurations with these points not collinear are dense — so the conclusion "
        "polynomial vanishes identically once it vanishes on the normalised configurations"),
    "similarity": (
        "the orientation-preserving similarities z ↦ az + b act transitively on ordered pairs of distinct points (no "
        "reflection is needed, so rotations by a fixed angle and signed areas stay as they are); every construction "
        "of the claim commutes with them (a circle of free squared radius stays such a circle); the conclusion is "
        "invariant under them (both sides scale by the same power of the ratio k); and configurations with these "
        "points distinct are dense — so the conclusion polynomial vanishes identically once it vanishes on the "
        "normalised configurations"),
    "euclidean": (
        "a translation and a rotation move any first point to the origin and any second point onto the x-axis (at "
        "its own distance, so that coordinate stays free); every construction of the claim commutes with isometries "
        "and the conclusion is invariant under them — so the conclusion polynomial vanishes identically once it "
        "vanishes on the normalised configurations"),
}

# the frames of the metric groups: targets for the first free points (None: the coordinate stays free)
_METRIC_FRAMES: dict[str, tuple[tuple[Any, ...], ...]] = {
    "affine": ((0, 0, 1), (1, 0, 1), (0, 1, 1)),
    "similarity": ((0, 0, 1), (1, 0, 1)),
    "euclidean": ((0, 0, 1), (None, 0, 1)),
}


def _metric_frame(claim: Claim, group: str) -> Normalisation | None:
    """The first free points of the claim sent to the group's frame (None when there are too few of them)."""
    targets = _METRIC_FRAMES[group]
    # points in the chart w = 1 (or with their own w), which the frame's points fit
    free = [n for n in claim.nodes.values() if _free(n) and n.kind == "point"]
    if len(free) < len(targets):
        return None
    chosen = free[: len(targets)]
    sub: dict[sympy.Symbol, Any] = {}
    frame = []
    for node, target in zip(chosen, targets, strict=True):
        last = node.data[-1]
        scale = 1 if isinstance(last, sympy.Symbol) else sympy.Rational(last)
        shown = []
        for e, v in zip(node.data, target, strict=True):
            if v is None:
                shown.append(e)
                continue
            if isinstance(e, sympy.Symbol):
                sub[e] = v * scale
            shown.append(v * scale)
        frame.append(tuple(shown))
    names = [n.name for n in chosen]
    condition = {"affine": f"{', '.join(names)} are not collinear", "similarity": " ≠ ".join(names),
                 "euclidean": ""}[group]
    return Normalisation(group, names, "point", sub, condition, justification=METRIC_JUSTIFICATION[group],
                         frame=frame)


def normalise(claim: Claim) -> tuple[Normalisation | None, str]:
    """The normalisation the claim allows (or None) and a sentence saying what was done or why not.

    The largest group that every construction commutes with and that leaves the conclusion invariant is used:
    projective (four points to a frame), affine (three points to (0, 0), (1, 0), (0, 1)), similarity (two points to
    (0, 0), (1, 0)) or euclidean (a first point to (0, 0), a second onto the x-axis).

    >>> from pgsym.proofs.claims import Claim
    >>> c = Claim("demo", "the perpendicular bisectors of a triangle are concurrent")
    >>> A, B, C = (c.free_point(n) for n in "ABC")
    >>> c.conclude_concurrent(c.bisector("a", B, C), c.bisector("b", C, A), c.bisector("c", A, B))
    >>> n, why = normalise(c)
    >>> n.group, n.frame, n.condition
    ('similarity', [(0, 0, 1), (1, 0, 1)], 'A ≠ B')
    >>> c = Claim("unit", "a distance equal to a number: not scale-invariant")
    >>> A, B = c.free_point("A"), c.free_point("B")
    >>> c.conclude_equal_ratio(c.dist2("d", A, B), 1)
    >>> normalise(c)[0].describe()[:57]
    'without loss of generality A = (0, 0), B = (B_x, 0) (eucl'
    """
    counts = _parameter_counts(claim)
    why = _obstacle(claim, counts)
    if why is not None:
        metric = any(not (n.operation.given or n.operation.fresh_coefficients)
                     and _node_group(n, counts) not in (None, "projective")
                     for n in claim.nodes.values())
        if not metric:
            return None, f"no normalisation: {why}"
        for group in GROUPS[1:]:
            why = _obstacle(claim, counts, group)
            if why is None:
                found = _metric_frame(claim, group)
                if found is not None:
                    return found, "normalised"
                why = f"fewer than {len(_METRIC_FRAMES[group])} free points for the {group} frame"
        return None, f"no normalisation: {why}"
    return _projective(claim)


def _projective(claim: Claim) -> tuple[Normalisation | None, str]:
    free = [n for n in claim.nodes.values() if _free(n) and n.kind in FRAMES]
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
