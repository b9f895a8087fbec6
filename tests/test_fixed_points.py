"""Fixed points, lines and planes as eigenvectors: worked examples by hand, and the defining property."""

from __future__ import annotations

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import integers, invertible_matrices
from sympy import I, Rational, sqrt

from pgsym.errors import DimensionError, UndecidableError
from pgsym.fixed_points import fixed_lines, fixed_planes, fixed_points
from pgsym.projective_line import Point1
from pgsym.projective_plane import Line, Point
from pgsym.space import Plane, Point3
from pgsym.transformations import Transformation


def _by_value(spaces):
    return {f.eigenvalue: f for f in spaces}


def test_a_rotation_fixes_the_circular_points():
    # R = 5·[[cos, −sin], [sin, cos]] with cos = 3/5, sin = 4/5. R (1, i, 0) = (3 − 4i, 4 + 3i, 0) = (3 − 4i)(1, i, 0)
    # since (3 − 4i) i = 4 + 3i; likewise (1, −i, 0) with 3 + 4i; the centre (0, 0, 1) with 5
    spaces = _by_value(fixed_points([[3, -4, 0], [4, 3, 0], [0, 0, 5]]))
    assert spaces[3 - 4 * I].basis == (Point(1, I, 0),) and spaces[3 + 4 * I].basis == (Point(1, -I, 0),)
    assert spaces[5].basis == (Point(0, 0, 1),) and all(f.dimension == 1 for f in spaces.values())


def test_a_rotation_by_30_degrees_with_algebraic_entries():
    # cos 30° = √3/2, sin 30° = 1/2: eigenvalues (√3 ± i)/2 on I and J, and 1 at the centre
    c, s = sqrt(3) / 2, Rational(1, 2)
    spaces = _by_value(fixed_points([[c, -s, 0], [s, c, 0], [0, 0, 1]]))
    assert set(spaces) == {1, c - s * I, c + s * I}
    assert spaces[c - s * I].basis[0] == Point(1, I, 0) and spaces[c + s * I].basis[0] == Point(1, -I, 0)


def test_homology_and_translation_give_lines_and_pencils():
    # diag(2, 2, 1): eigenvalue 2 on span(e1, e2) — every point of the line at infinity is fixed; 1 on the origin
    spaces = _by_value(fixed_points([[2, 0, 0], [0, 2, 0], [0, 0, 1]]))
    assert spaces[2].dimension == 2 and spaces[2].describe() == "a line of fixed points"
    assert spaces[1].basis == (Point(0, 0, 1),) and spaces[2].multiplicity == 2
    # translation by (3, 0): H − I = [[0, 0, 3], 0, 0] so the fixed points are x3 = 0 (the line at infinity);
    # Hᵀ − I has the single row (3, 0, 0) in the last place, so the fixed lines have l1 = 0: y = const, a pencil
    T = [[1, 0, 3], [0, 1, 0], [0, 0, 1]]
    (pts,) = fixed_points(T)
    assert pts.multiplicity == 3 and set(pts.basis) == {Point(1, 0, 0), Point(0, 1, 0)}
    (lns,) = fixed_lines(T)
    assert set(lns.basis) == {Line(0, 1, 0), Line(0, 0, 1)}
    assert lns.describe() == "a pencil of fixed lines (every line through one point)"
    (everything,) = fixed_points(Transformation.identity(2))
    assert everything.is_whole_space and everything.describe() == "every point is fixed"


def test_space_rotation_mirror_and_p1():
    # quarter turn about the z-axis: eigenvalue 1 on span(e3, e4) — the z-axis is a line of fixed points;
    # ±i on (1, ∓i, 0, 0), the circular points of the horizontal planes
    spaces = _by_value(fixed_points([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]))
    assert set(spaces[1].basis) == {Point3(0, 0, 1, 0), Point3(0, 0, 0, 1)}
    assert spaces[I].basis == (Point3(1, -I, 0, 0),) and spaces[-I].basis == (Point3(1, I, 0, 0),)
    # the mirror z = 0 fixes the plane z = 0 pointwise, and every plane perpendicular to it
    planes = _by_value(fixed_planes([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]]))
    assert planes[-1].basis == (Plane(0, 0, 1, 0),)
    assert planes[1].dimension == 3
    assert planes[1].describe() == "a bundle of fixed planes (every plane through one point)"
    # a parabolic map of P¹, x ↦ x + 1: one fixed point (∞) of multiplicity 2
    (par,) = fixed_points([[1, 1], [0, 1]])
    assert par.basis == (Point1(1, 0),) and par.multiplicity == 2 and par.dimension == 1


def test_cubic_eigenvalues_in_radicals():
    # the companion matrix of x³ − 2: the fixed points are (λ², λ, 1) for the three cube roots λ of 2
    H = Transformation([[0, 0, 2], [1, 0, 0], [0, 1, 0]])
    spaces = fixed_points(H)
    assert len(spaces) == 3
    for f in spaces:
        lam = f.eigenvalue
        assert sympy.expand(lam**3) == 2
        assert f.basis[0] == Point(lam**2, lam, 1) and H(f.basis[0]) == f.basis[0]


def test_named_errors():
    t = sympy.Symbol("t")
    with pytest.raises(UndecidableError):
        fixed_points([[1, t, 0], [0, 2, 0], [0, 0, 1]])
    with pytest.raises(DimensionError):
        fixed_lines(Transformation.identity(3))
    with pytest.raises(DimensionError):
        fixed_planes(Transformation.identity(2))


def _conjugated(S, B):
    S, B = sympy.Matrix(S), sympy.Matrix(B)
    return Transformation(S * B * S.adjugate())


# char polys with a rational root and a quadratic factor: conjugate a block matrix by a random S
@settings(max_examples=12, deadline=None)
@given(invertible_matrices(3, 2), integers(4).filter(bool), st.lists(integers(4), min_size=4, max_size=4))
def test_fixed_points_and_lines_are_fixed(S, a, block):
    b, c, d, e = block
    if b * e - c * d == 0:  # keep the example: det [[1, c], [d, 1 + cd]] = 1
        b, e = 1, 1 + c * d
    H = _conjugated(S, [[a, 0, 0], [0, b, c], [0, d, e]])
    pts, lns = fixed_points(H), fixed_lines(H)
    assert sum(f.multiplicity for f in pts) == 3 and sum(f.multiplicity for f in lns) == 3
    assert all(H(p) == p for f in pts for p in f.basis)
    assert all(H(l) == l for f in lns for l in f.basis)
    # the eigenvalues of H and Hᵀ agree, and each eigenspace has at most the dimension of its multiplicity
    assert {f.eigenvalue for f in pts} == {f.eigenvalue for f in lns}
    assert all(1 <= f.dimension <= f.multiplicity for f in pts)


@settings(max_examples=5, deadline=None)
@given(invertible_matrices(4, 1), st.lists(integers(3), min_size=8, max_size=8))
def test_fixed_points_and_planes_in_space(S, e):
    B = sympy.diag(sympy.Matrix([[e[0], e[1]], [e[2], e[3]]]), sympy.Matrix([[e[4], e[5]], [e[6], e[7]]]))
    if B.det() == 0:
        B = sympy.diag(1, 2, sympy.Matrix([[0, -1], [1, 0]]))
    H = _conjugated(S, B)
    assert all(H(p) == p for f in fixed_points(H) for p in f.basis)
    assert all(H(p) == p for f in fixed_planes(H) for p in f.basis)


@pytest.mark.parametrize("m", [
    [[1, 2, 0, 1], [0, 1, 3, 1], [1, 0, 1, 2], [2, 1, 0, 1]],   # char poly x⁴ − 4x³ + 3x² − 14x − 13, irreducible
    [[2, 1, 3], [1, -1, 2], [0, 4, 1]],                           # an irreducible cubic
])
def test_generic_matrices_get_radical_fixed_points_quickly(m):
    # exact by construction (a column of adj(H − xI) modulo the irreducible factor); checked here to 40 digits,
    # since comparing Ferrari radicals exactly costs minutes
    import time

    start = time.perf_counter()
    spaces = fixed_points(m)
    assert time.perf_counter() - start < 20
    M = sympy.Matrix(m)
    assert len(spaces) == M.rows and all(f.dimension == 1 and f.multiplicity == 1 for f in spaces)
    for f in spaces:
        v = sympy.Matrix(f.basis[0].coords).evalf(60)
        lam = sympy.N(f.eigenvalue, 60)
        assert max(abs(e) for e in (M * v - lam * v)) < 1e-40 * max(abs(e) for e in v)


def test_glide_reflection_by_hand():
    # (x, y) ↦ (x + 2, −y). H − I = [[0, 0, 2], [0, −2, 0], 0]: y = w = 0, the ideal point (1, 0, 0);
    # H + I = [[2, 0, 2], 0, [0, 0, 2]]: x = w = 0, the ideal point (0, 1, 0). No finite point is fixed.
    # Hᵀ − I = [0, [0, −2, 0], [2, 0, 0]]: the line at infinity (0, 0, 1); Hᵀ + I = [[2, 0, 0], 0, [2, 0, 2]]:
    # the line (0, 1, 0), y = 0 — the glide axis
    G = Transformation([[1, 0, 2], [0, -1, 0], [0, 0, 1]])
    assert {f.eigenvalue: f.basis for f in fixed_points(G)} == {1: (Point(1, 0, 0),), -1: (Point(0, 1, 0),)}
    assert {f.eigenvalue: f.basis for f in fixed_lines(G)} == {1: (Line(0, 0, 1),), -1: (Line(0, 1, 0),)}
    mirror = Transformation(sympy.diag(1, 1, -1, 1))
    assert [f.element for f in fixed_planes(mirror)] == ["plane", "plane"]
