"""Order conditions read off float figures: which condition selects the common points where a goal holds.

AlphaGeometry takes either common point of a line and a circle (or of two circles) at random and draws its
figure again until the goal holds, so a problem whose goal holds at one of the two points only means that
point without saying which. :func:`selecting_conditions` looks for order conditions of
:mod:`pgsym.proofs.order` on the figure's points that say it: in every random float figure, on every choice of
the random points, the choices the conditions keep are not empty and the goal holds at each of them. The
conditions are then hypotheses of the statement, which the engine proves on the branch they select
(:func:`pgsym.proofs.algebraic.prove_ordered`) — a condition that only happened to separate the sampled
figures gives no proof there, never a wrong one. :func:`restricting_conditions` does the same for a goal that
holds in some figures only (AlphaGeometry draws its figure until it holds): conditions that keep only figures
where it holds.

>>> figure = {(0,): ({"A": 0j, "B": 2 + 0j, "X": 1 + 0j}, True), (1,): ({"A": 0j, "B": 2 + 0j, "X": 3 + 0j}, False)}
>>> selecting_conditions([figure], ["X"], ["A", "B", "X"])
[('between', ('X', 'A', 'B'))]
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Sequence

__all__ = ["Condition", "Figure", "condition_holds", "restricting_conditions", "selecting_conditions"]

Condition = tuple[str, tuple[str, ...]]
"""An order condition as its word of the statement language and its point names."""

Figure = dict[tuple[int, ...], tuple[dict[str, complex], bool]]
"""One random figure: for each choice of the random points (a bit per point), the points' values and whether
the goal holds."""

MARGIN = 1e-6
"""A condition whose sine or cosine is nearer 0 than this in some figure decides nothing there."""

MAX_PAIRS = 400
"""The most candidates combined in pairs when no single condition selects the points."""

MAX_CANDIDATES = 40_000
"""The most conditions tried (those on the figure's points always; then midpoints while the budget lasts)."""

MAX_EVALUATIONS = 250_000
"""The most evaluations of a condition in a figure, for the whole search (about a second)."""

MAX_MIDPOINTS = 28
"""The most midpoints of two points tried as points of a condition (those of 8 points)."""


def _unit(z: complex) -> complex | None:
    return z / abs(z) if abs(z) > 1e-12 else None


def _sine(a: complex, b: complex, p: complex) -> float | None:
    """The sine of the angle from AB to AP (its sign: the side of the line AB that P is on)."""
    u, v = _unit(b - a), _unit(p - a)
    return None if u is None or v is None else (u.conjugate() * v).imag


def _cosine(v: complex, a: complex, b: complex) -> float | None:
    """The cosine of the angle at V between VA and VB."""
    u, w = _unit(a - v), _unit(b - v)
    return None if u is None or w is None else (u.conjugate() * w).real


def condition_holds(word: str, pts: Sequence[complex]) -> bool | None:
    """Whether an order condition holds at float points; None when it is too close to its boundary to say.

    >>> condition_holds("onray", [2 + 0j, 0j, 1 + 0j]), condition_holds("inside", [0.2 + 0.2j, 0j, 1 + 0j, 1j])
    (True, True)
    """
    if word in ("sameside", "oppositeside"):
        p, q, a, b = pts
        s, t = _sine(a, b, p), _sine(a, b, q)
        if s is None or t is None or min(abs(s), abs(t)) < MARGIN:
            return None
        return (s * t > 0) == (word == "sameside")
    if word in ("between", "onray"):
        x, a, b = pts
        c = _cosine(x, a, b) if word == "between" else _cosine(a, x, b)
        if c is None or abs(c) < MARGIN:
            return None
        return c < 0 if word == "between" else c > 0
    x, a, b, c = pts
    sides = [condition_holds("sameside", [x, p, q, r]) for p, q, r in ((a, b, c), (b, c, a), (c, a, b))]
    return None if None in sides else all(sides)


def _candidates(x: str, points: Sequence[str]) -> Iterator[Condition]:
    """Order conditions that name x, in the order they are preferred (simple words, early points first)."""
    others = [p for p in points if p != x]
    pairs = list(itertools.combinations(others, 2))
    for a, b in pairs:
        yield "between", (x, a, b)
    for v, p in itertools.permutations(others, 2):
        yield "onray", (x, v, p)
    for q, (a, b) in itertools.product(others, pairs):
        if q not in (a, b):
            yield "sameside", (x, q, a, b)
            yield "oppositeside", (x, q, a, b)
    for a, (p, q) in itertools.product(others, pairs):
        if a not in (p, q):
            yield "sameside", (p, q, x, a)
            yield "oppositeside", (p, q, x, a)
    for a, b in pairs:
        yield "onray", (a, x, b)
    for v, a in itertools.permutations(others, 2):
        yield "between", (v, x, a)
        yield "onray", (a, v, x)
    for a, b, c in itertools.combinations(others, 3):
        yield "inside", (x, a, b, c)


def selecting_conditions(figures: Sequence[Figure], either: Sequence[str], points: Sequence[str]
                         ) -> list[Condition] | None:
    """One or two order conditions that keep, in each figure, some choices and only choices where the goal holds;
    None when no such conditions are found.

    ``either`` names the points taken at random (the bits of a choice, in order), ``points`` every point
    the conditions may name (in definition order). A condition names a random point and points of ``points`` or
    the midpoint ``(midpoint P Q)`` of two that are not random; one naming a single random point and earlier
    points is preferred."""
    choices = sorted({c for f in figures for c in f})
    fixed = [p for p in points if p not in either]
    midpoints = [f"(midpoint {p} {q})" for p, q in itertools.combinations(fixed, 2)][:MAX_MIDPOINTS]
    # per figure, per choice: every point and midpoint by name (None where the choice fell degenerate); the figures
    # where the goal holds at fewest choices first, as they rule out most candidates
    tables = [[None if c not in f else {**f[c][0], **{m: (f[c][0][m[10:-1].split()[0]]
                                                          + f[c][0][m[10:-1].split()[1]]) / 2 for m in midpoints}}
               for c in choices] for f in figures]
    holds = [sum(1 << i for i, c in enumerate(choices) if c in f and f[c][1]) for f in figures]
    if not all(holds):
        return None  # a figure where the goal holds at no choice: no order condition of the points selects it
    order = sorted(range(len(figures)), key=lambda i: (holds[i].bit_count(), i))
    tables, holds = [tables[i] for i in order], [holds[i] for i in order]
    present = [sum(1 << i for i, v in enumerate(t) if v is not None) for t in tables]
    useful: list[tuple[Condition, list[int]]] = []
    # a condition naming one random point first (the engine selects the branch of one root at a time); then the
    # figure's points before one midpoint of two points that are not random; then earlier points first (a
    # condition on the points known when x is chosen reads as the figure's order). A single condition proves the
    # branch; two together only say which point is meant
    candidates = [c for x in either for c in _candidates(x, points)]
    ranked = [((len(set(c[1]) & set(either)), 0, max(points.index(a) for a in c[1])), c) for c in candidates]
    for m in midpoints:
        if len(ranked) > MAX_CANDIDATES:
            break  # a counted budget, not a clock: the translation must not depend on the machine
        names = [*points, m]
        ranked += [((len(set(c[1]) & set(either)), 1, max(names.index(a) for a in c[1])), c)
                   for x in either for c in _candidates(x, names) if m in c[1]]
    ranked.sort(key=lambda kc: kc[0])
    budget = [MAX_EVALUATIONS]
    for (_, midpoint, _), cond in ranked:
        budget[0] -= 1
        kept = _kept(tables, cond, budget, holds)
        if budget[0] < 0:
            break
        if kept is None:
            continue
        if all(k and not k & ~h for k, h in zip(kept, holds, strict=True)):
            return [cond]
        if kept != present and not midpoint:
            useful.append((cond, kept))
    for (one, a), (two, b) in itertools.combinations(useful[:MAX_PAIRS], 2):
        kept = [x & y for x, y in zip(a, b, strict=True)]
        if all(k and not k & ~h for k, h in zip(kept, holds, strict=True)):
            return [one, two]
    return None


def restricting_conditions(figures: Sequence[Figure], points: Sequence[str]) -> list[Condition] | None:
    """One or two order conditions that keep only figures (and choices) where the goal holds, and some in at least
    half of the figures where it holds somewhere: the figure AlphaGeometry means when its goal holds in some random
    figures only (a point on the other side of a vertex, say); the one that keeps most, and among those the one on
    the earliest points. None when none is found.

    >>> inside = {(): ({"A": 0j, "B": 2 + 0j, "F": 1 + 0j}, True)}
    >>> outside = {(): ({"A": 0j, "B": 2 + 0j, "F": 3 + 0j}, False)}
    >>> restricting_conditions([inside, outside, inside], ["A", "B", "F"])
    [('between', ('F', 'A', 'B'))]
    """
    choices = sorted({c for f in figures for c in f})
    tables = [[f[c][0] if c in f else None for c in choices] for f in figures]
    holds = [sum(1 << i for i, c in enumerate(choices) if c in f and f[c][1]) for f in figures]
    need = (sum(1 for h in holds if h) + 1) // 2
    if not need:
        return None
    seen: set[Condition] = set()
    ranked = []
    for x in reversed(points):  # conditions on later points first (the point the figure restricts is drawn late)
        if len(ranked) > MAX_CANDIDATES:
            break
        for c in _candidates(x, points):
            if c not in seen:
                seen.add(c)
                ranked.append(((max(points.index(a) for a in c[1]),), c))
            if len(ranked) > MAX_CANDIDATES:
                break
    ranked.sort(key=lambda kc: kc[0])
    budget = [MAX_EVALUATIONS]
    best: tuple[int, list[Condition]] | None = None
    useful: list[tuple[Condition, list[int]]] = []
    for _, cond in ranked:
        kept = _kept(tables, cond, budget)
        if budget[0] < 0:
            break
        if kept is None:
            continue
        count = sum(1 for k in kept if k)
        if count < need:
            continue
        if all(not k & ~h for k, h in zip(kept, holds, strict=True)):
            if best is None or count > best[0]:
                best = (count, [cond])
        elif len(useful) < MAX_PAIRS:
            useful.append((cond, kept))
    if best is not None:
        return best[1]
    for (one, a), (two, b) in itertools.combinations(useful, 2):
        kept = [x & y for x, y in zip(a, b, strict=True)]
        count = sum(1 for k in kept if k)
        if count >= need and all(not k & ~h for k, h in zip(kept, holds, strict=True)) and (
                best is None or count > best[0]):
            best = (count, [one, two])
    return None if best is None else best[1]


def _kept(tables: list[list[dict[str, complex] | None]], cond: Condition, budget: list[int],
          holds: list[int] | None = None) -> list[int] | None:
    """For each figure, the choices (bits of a mask) the condition keeps; None if it is undecided in one, or, with
    ``holds``, keeps no choice where the goal holds in one (then neither it nor a pair with it selects; most
    candidates stop at the first figure)."""
    word, args = cond
    out = []
    for k, table in enumerate(tables):
        mask = 0
        for i, values in enumerate(table):
            if values is not None:
                budget[0] -= 1
                verdict = condition_holds(word, [values[a] for a in args])
                if verdict is None:
                    return None
                mask |= verdict << i
        if (holds is not None and not mask & holds[k]) or budget[0] < 0:
            return None
        out.append(mask)
    return out
