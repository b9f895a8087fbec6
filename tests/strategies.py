"""Shared hypothesis strategies: exact random configurations, ideal elements included.

One home for the random data of the property tests, so that "a random point" means the same thing
in every test file.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

from pgsym import Line, Plane, Point, Point3

small = st.integers(min_value=-12, max_value=12)
nonzero_rational = st.fractions(min_value=-9, max_value=9, max_denominator=7).filter(lambda f: f != 0)


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


def integers(bound: int) -> st.SearchStrategy[int]:
    """Integers from ``-bound`` to ``bound``: small entries keep exact examples fast."""
    return st.integers(min_value=-bound, max_value=bound)


def points3(allow_ideal: bool = True, bound: int = 9) -> st.SearchStrategy[Point3]:
    """Points of P³ with integer coordinates up to ``bound``; a third of them ideal when allowed."""
    return homogeneous_vectors(4, allow_ideal, integers(bound)).map(lambda t: Point3(*t))


def planes(bound: int = 9) -> st.SearchStrategy[Plane]:
    """Planes with integer coordinates up to ``bound``; a third of them through the origin (last coordinate 0)."""
    return homogeneous_vectors(4, True, integers(bound)).map(lambda t: Plane(*t))


def points(allow_ideal: bool = True) -> st.SearchStrategy[Point]:
    return homogeneous_triples(allow_ideal).map(lambda t: Point(*t))


def lines() -> st.SearchStrategy[Line]:
    return homogeneous_triples(True).map(lambda t: Line(*t))


def scaled(obj, factor: Fraction):
    """The same projective object with every coordinate multiplied by ``factor``."""
    return type(obj)(*(c * factor for c in obj.coords))


@st.composite
def incidence_programs(draw) -> tuple[str, int]:
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
