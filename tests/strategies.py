"""Shared hypothesis strategies: exact random configurations, ideal elements included.

One home for the random data of the property tests, so that "a random point" means the same thing
in every test file.
"""

from __future__ import annotations

from fractions import Fraction

import sympy
from hypothesis import strategies as st

from pgsym import Line, Plane, Point, Point3, Transformation
from pgsym.plucker import Line3
from pgsym.projective_line import Point1
from pgsym.ring import det


def integers(bound: int) -> st.SearchStrategy[int]:
    """Integers from ``-bound`` to ``bound``: small entries keep exact examples fast."""
    return st.integers(min_value=-bound, max_value=bound)


def rationals(bound: int, max_denominator: int) -> st.SearchStrategy[Fraction]:
    """Fractions from ``-bound`` to ``bound`` with denominators up to ``max_denominator``."""
    return st.fractions(min_value=-bound, max_value=bound, max_denominator=max_denominator)


def nonzero_rationals(bound: int, max_denominator: int) -> st.SearchStrategy[Fraction]:
    """:func:`rationals` without zero (scale factors, parameters that must not vanish)."""
    return rationals(bound, max_denominator).filter(lambda f: f != 0)


small = integers(12)
nonzero_rational = nonzero_rationals(9, 7)


@st.composite
def homogeneous_vectors(draw, k: int = 3, allow_ideal: bool = True, entries: st.SearchStrategy[int] = small
                        ) -> tuple[int, ...]:
    """Integer k-vectors that are not the zero vector; a third of them ideal (last entry 0) when allowed."""
    if allow_ideal:
        last = 0 if draw(st.integers(0, 2)) == 0 else draw(entries)
    else:
        last = draw(entries.filter(lambda v: v != 0))
    head = [draw(entries) for _ in range(k - 1)]
    if not any(head) and last == 0:
        head[0] = 1
    return (*head, last)


def homogeneous_triples(allow_ideal: bool = True) -> st.SearchStrategy[tuple[int, ...]]:
    """Integer triples that are not the zero vector; a third of them ideal when allowed."""
    return homogeneous_vectors(3, allow_ideal)


def transformations(n: int = 3, bound: int = 6) -> st.SearchStrategy[Transformation]:
    """Invertible transformations of P^(n−1) with integer entries up to ``bound``."""
    return invertible_matrices(n, bound).map(Transformation)


def points3(allow_ideal: bool = True, bound: int = 9) -> st.SearchStrategy[Point3]:
    """Points of P³ with integer coordinates up to ``bound``; a third of them ideal when allowed."""
    return homogeneous_vectors(4, allow_ideal, integers(bound)).map(lambda t: Point3(*t))


def planes(bound: int = 9) -> st.SearchStrategy[Plane]:
    """Planes with integer coordinates up to ``bound``; a third of them through the origin (last coordinate 0)."""
    return homogeneous_vectors(4, True, integers(bound)).map(lambda t: Plane(*t))


def points(allow_ideal: bool = True, bound: int = 12) -> st.SearchStrategy[Point]:
    """Points of P² with integer coordinates up to ``bound``; a third of them ideal when allowed."""
    return homogeneous_vectors(3, allow_ideal, integers(bound)).map(lambda t: Point(*t))


def lines(bound: int = 12) -> st.SearchStrategy[Line]:
    """Lines of P² with integer coordinates up to ``bound``; a third of them through the origin."""
    return homogeneous_vectors(3, True, integers(bound)).map(lambda t: Line(*t))


def scaled(obj, factor: Fraction):
    """The same projective object with every coordinate multiplied by ``factor``."""
    return type(obj)(*(c * factor for c in obj.coords))


@st.composite
def incidence_programs(draw, max_points: int = 6, max_steps: int = 5) -> dict:
    """A random program of the proof engine's incidence grammar: free points, then joins and meets of
    earlier objects (by index), and three indices for a "collinear" conclusion (see test_proofs_soundness)."""
    n = draw(st.integers(4, max_points))
    steps = draw(st.lists(st.tuples(st.sampled_from(["meet", "copy"]), st.integers(0, 20), st.integers(0, 20)),
                          min_size=1, max_size=max_steps))
    conclusion = draw(st.tuples(st.integers(0, 30), st.integers(0, 30), st.integers(0, 30)))
    return {"points": n, "steps": steps, "conclusion": conclusion}


@st.composite
def unit_directions(draw) -> tuple[Fraction, Fraction]:
    """Rational points ``(cos θ, sin θ)`` of the unit circle: ``((1 − t²)/(1 + t²), 2t/(1 + t²))``, and ``(−1, 0)``."""
    if draw(st.integers(0, 9)) == 0:
        return Fraction(-1), Fraction(0)
    t = draw(st.fractions(min_value=-4, max_value=4, max_denominator=5))
    return (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)


@st.composite
def affine_matrices(draw, bound: int = 5) -> list[list[int]]:
    """Invertible affine 3×3 integer matrices ``[[A, t], [0, 0, 1]]`` (entries up to ``bound``)."""
    a, b, c, d = (draw(integers(bound)) for _ in range(4))
    if a * d - b * c == 0:
        a, b, c, d = a + 1, b, c, d + (1 if d >= 0 else -1)
        if a * d - b * c == 0:
            a, b, c, d = 1, 0, 0, 1
    return [[a, b, draw(integers(bound))], [c, d, draw(integers(bound))], [0, 0, 1]]


@st.composite
def invertible_matrices(draw, n: int = 3, bound: int = 6) -> list[list[int]]:
    """Non-singular integer n×n matrices with entries up to ``bound`` (a homography of P^(n-1)), as lists of rows."""
    m = [[draw(integers(bound)) for _ in range(n)] for _ in range(n)]
    if det(m) == 0:  # a shifted diagonal keeps the example instead of rejecting it
        for i in range(n):
            m[i][i] += 2 * bound + 1
    if det(m) == 0:
        m = [[int(i == j) for j in range(n)] for i in range(n)]
    return m


# -- lines of space, points of P¹, symmetric forms (the numeric parity tests) --


def lines3() -> st.SearchStrategy:
    """Lines of P³ (Plücker) joining two distinct points, ideal ones included."""
    return st.tuples(points3(), points3()).filter(lambda ab: ab[0] != ab[1]).map(lambda ab: Line3.join(*ab))


def symmetric_forms(k: int) -> st.SearchStrategy:
    """Non-singular symmetric k×k SymPy matrices with integer entries up to 5."""
    entries = st.lists(integers(5), min_size=k * (k + 1) // 2, max_size=k * (k + 1) // 2)

    def build(values):
        M = sympy.zeros(k, k)
        it = iter(values)
        for i in range(k):
            for j in range(i, k):
                M[i, j] = M[j, i] = next(it)
        return M

    return entries.map(build).filter(lambda M: M.det() != 0)


@st.composite
def forms_through_a_point(draw, k: int):
    """A symmetric integer form with a given integer point X on it: Q' = X_j² Q − (XᵀQX) e_j e_jᵀ."""
    M = draw(symmetric_forms(k))
    X = draw(homogeneous_vectors(k, True, integers(6)))
    j = max(range(k), key=lambda i: abs(X[i]))
    v = sympy.Matrix(X)
    value = (v.T * M * v)[0]
    Q = X[j] ** 2 * M
    Q[j, j] -= value  # Xᵀ Q' X = X_j² XᵀQX − XᵀQX X_j² = 0
    return Q, X


def point1s() -> st.SearchStrategy:
    """Points of P¹ with integer coordinates up to 9, a third of them ideal."""
    return homogeneous_vectors(2, True, integers(9)).map(lambda t: Point1(*t))


@st.composite
def statement_programs(draw) -> tuple[str, int]:
    """A random theorem of the statement language (free points and lines, joins, meets, points on lines, and
    one incidence, collinearity or concurrency conclusion), with a seed for evaluating it: (text, seed)."""
    points = [f"P{i}" for i in range(draw(st.integers(3, 5)))]
    lines = [f"l{i}" for i in range(draw(st.integers(0, 2)))]
    text = [f"points {' '.join(points)}"] + ([f"lines {' '.join(lines)}"] if lines else [])
    for i in range(draw(st.integers(1, 5))):
        step = draw(st.sampled_from(["join", "meet", "on"] if len(lines) >= 2 else ["join", "on"]))
        if step == "meet":
            a, b = draw(st.lists(st.sampled_from(lines), min_size=2, max_size=2, unique=True))
            name = f"X{i}"
            text.append(f"point {name} = meet {a} {b}")
            points.append(name)
        else:
            a, b = draw(st.lists(st.sampled_from(points), min_size=2, max_size=2, unique=True))
            name = f"X{i}" if step == "on" else f"m{i}"
            text.append(f"point {name} on line {a} {b}" if step == "on" else f"line {name} = join {a} {b}")
            (points if step == "on" else lines).append(name)
    kinds = ["collinear"] + (["concurrent"] if len(lines) >= 3 else []) + (["on"] if lines else [])
    kind = draw(st.sampled_from(kinds))
    if kind == "collinear":
        args = draw(st.lists(st.sampled_from(points), min_size=3, max_size=3, unique=True))
    elif kind == "concurrent":
        args = draw(st.lists(st.sampled_from(lines), min_size=3, max_size=3, unique=True))
    else:
        args = [draw(st.sampled_from(points)), draw(st.sampled_from(lines))]
    text.append(f"prove {kind} {' '.join(args)}")
    return "\n".join(text) + "\n", draw(st.integers(0, 2**16))


@st.composite
def conic_statement_programs(draw) -> tuple[str, int]:
    """A random theorem on a conic through five free points: second intersections, points on the conic,
    tangents, polars, joins and meets, concluded by an incidence with the conic, a tangency, six points on
    a conic, a collinearity, or an equality of the cross-ratios of four points seen from two points — true
    by construction often enough (Steiner, Chasles) to test proofs as well as refutations: (text, seed)."""
    free = [f"P{i}" for i in range(6)]  # P5 is off the conic
    text = [f"points {' '.join(free)}", f"conic K = conic {' '.join(free[:5])}"]
    points, on_conic, lines = list(free), list(free[:5]), []
    for i in range(draw(st.integers(1, 4))):
        step = draw(st.sampled_from(["second", "onconic", "tangent", "polar", "join"]
                                    + (["meet"] if len(lines) >= 2 else [])))
        a = draw(st.sampled_from(on_conic))
        if step == "second":
            q = draw(st.sampled_from([p for p in points if p != a]))
            text.append(f"point X{i} = second K {a} {q}")
            points.append(f"X{i}")
            on_conic.append(f"X{i}")
        elif step == "onconic":
            text.append(f"point X{i} on conic K through {a}")
            points.append(f"X{i}")
            on_conic.append(f"X{i}")
        elif step == "tangent":
            text.append(f"line t{i} = tangent K {a}")
            lines.append(f"t{i}")
        elif step == "polar":
            text.append(f"line t{i} = polar K {draw(st.sampled_from(points))}")
            lines.append(f"t{i}")
        elif step == "join":
            p, q = draw(st.lists(st.sampled_from(points), min_size=2, max_size=2, unique=True))
            text.append(f"line t{i} = join {p} {q}")
            lines.append(f"t{i}")
        else:
            l, m = draw(st.lists(st.sampled_from(lines), min_size=2, max_size=2, unique=True))
            text.append(f"point X{i} = meet {l} {m}")
            points.append(f"X{i}")
    kind = draw(st.sampled_from(["on", "collinear", "crossratio", "conconic"] + (["tangent"] if lines else [])))
    if kind == "on":
        text.append(f"prove on {draw(st.sampled_from(points))} K")
    elif kind == "tangent":
        text.append(f"prove tangent {draw(st.sampled_from(lines))} K")
    elif kind == "collinear":
        text.append("prove collinear " + " ".join(draw(st.lists(st.sampled_from(points), min_size=3, max_size=3,
                                                                   unique=True))))
    elif kind == "conconic":
        pool = draw(st.sampled_from([on_conic, points]))
        pool = pool if len(pool) >= 6 else points
        text.append("prove conconic " + " ".join(draw(st.lists(st.sampled_from(pool), min_size=6, max_size=6,
                                                                  unique=True))))
    else:
        pool = draw(st.sampled_from([on_conic, points]))
        pool = pool if len(pool) >= 6 else points
        p, q, *abcd = draw(st.lists(st.sampled_from(pool), min_size=6, max_size=6, unique=True))
        seen = [" ".join(f"(join {o} {x})" for x in abcd) for o in (p, q)]
        text.append(f"prove equal (crossratio {seen[0]}) (crossratio {seen[1]})")
    return "\n".join(text) + "\n", draw(st.integers(0, 2**16))


@st.composite
def euclidean_programs(draw, max_steps: int = 3) -> dict:
    """A random program of Euclidean constructions on four free points (see test_proofs_euclidean): steps
    ``(operation, i, j, k)`` on earlier points by index, and a conclusion ``(predicate, indices)``."""
    ops = ["midpoint", "foot", "reflect_line", "reflect_point", "circumcentre", "orthocentre", "translate", "rotate",
           "invert"]
    steps = draw(st.lists(st.tuples(st.sampled_from(ops), st.integers(0, 20), st.integers(0, 20),
                                    st.integers(0, 20)), min_size=1, max_size=max_steps))
    predicates = ["collinear", "perpendicular", "parallel", "equallength", "concyclic", "equalangle", "unit",
                  "equalarea", "area",
                  # true statements on the program's points, so that proofs are compared too
                  "foot-perpendicular", "mirror-length", "circumcentre-length", "inverse-on-ray", "rotation-angle"]
    conclusion = (draw(st.sampled_from(predicates)), draw(st.lists(st.integers(0, 30), min_size=6, max_size=6)))
    return {"steps": steps, "conclusion": conclusion}


@st.composite
def euclidean_arguments(draw, kinds: tuple[str, ...]) -> list:
    """Random rational data of the given kinds ("point": finite (x, y, w), "line": (a, b, c) not at infinity,
    "circle": a real circle's matrix), with a random nonzero scale for each (to test representatives)."""
    out = []
    for kind in kinds:
        if kind == "point":
            w = draw(st.integers(1, 5)) * draw(st.sampled_from([1, -1]))
            out.append((draw(integers(9)), draw(integers(9)), w))
        elif kind == "line":
            a, b = draw(integers(9)), draw(integers(9))
            out.append((a or 1, b, draw(integers(9))))
        else:
            cx, cy, r = draw(integers(5)), draw(integers(5)), draw(st.integers(1, 6))
            out.append(((1, 0, -cx), (0, 1, -cy), (-cx, -cy, cx * cx + cy * cy - r * r)))
    scales = [draw(nonzero_rationals(5, 4)) for _ in kinds]
    return [out, scales]
