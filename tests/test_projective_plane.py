"""Points and lines of P²: worked values derived by hand, and properties on random exact configurations."""

from __future__ import annotations

from fractions import Fraction

import sympy
from hypothesis import assume, given
from hypothesis import strategies as st
from strategies import lines, nonzero_rational, points, scaled
from sympy import Rational, S, symbols

import pgsym
from pgsym import (
    Line,
    Point,
    collinear,
    concurrent,
    dual,
    ideal_point,
    incident,
    join,
    line_at_infinity,
    meet,
)

# -- worked examples (each value derived by hand from the cross-product formula) ------------


def test_meet_of_x_equals_1_and_y_equals_1():
    # (1,0,-1) x (0,1,-1) = (0*(-1) - (-1)*1, (-1)*0 - 1*(-1), 1*1 - 0*0) = (1, 1, 1)
    x = meet(Line(1, 0, -1), Line(0, 1, -1))
    assert x.coords == (1, 1, 1)
    assert x.dehomogenize() == (1, 1)


def test_join_of_origin_and_diagonal_point():
    # (0,0,1) x (1,1,1) = (0*1 - 1*1, 1*1 - 0*1, 0 - 0) = (-1, 1, 0): the line y = x
    l = join(Point(0, 0), Point(1, 1))
    assert l.coords == (-1, 1, 0)
    assert l.canonical().coords == (1, -1, 0)


def test_parallel_lines_meet_in_their_common_direction():
    # x + 2y = 3 and x + 2y = 5: (1,2,-3) x (1,2,-5) = (-10+6, -3+5, 2-2) = (-4, 2, 0) ~ (2, -1, 0)
    x = meet(Line(1, 2, -3), Line(1, 2, -5))
    assert x.coords == (-4, 2, 0)
    assert x == Point(2, -1, 0) and x.is_ideal
    assert incident(x, line_at_infinity())


def test_dehomogenize_rational_point():
    assert Point(3, -6, 4).dehomogenize() == (Rational(3, 4), Rational(-3, 2))


def test_canonical_form_is_primitive_with_positive_leading_entry():
    assert Point(-4, 6, 0).canonical().coords == (2, -3, 0)
    assert Line(0, Rational(-1, 2), Rational(1, 3)).canonical().coords == (0, 3, -2)
    assert Point(Fraction(1, 2), 0.25).canonical().coords == (2, 1, 4)


def test_symbolic_canonical_form_clears_denominators_and_content():
    a, b = symbols("a b")
    # common denominator 6 gives (3a, 2ab, 0); the content a is removed
    assert Point(a / 2, a * b / 3, 0).canonical().coords == (3, 2 * b, 0)
    assert Point(-a, 2 * a * b, 0).canonical().coords == (1, -2 * b, 0)


def test_symbolic_join_and_meet_give_the_textbook_formulas():
    x1, y1, x2, y2 = symbols("x1 y1 x2 y2")
    l = join(Point(x1, y1), Point(x2, y2))
    assert l.coords == (y1 - y2, x2 - x1, x1 * y2 - x2 * y1)
    a, b, c, d = symbols("a b c d")
    x = meet(Line(a, b, c), Line(a, b, d))
    assert x == Point(b, -a, 0)


def test_point_on_line_and_line_direction():
    l = Line(1, 2, -5)
    assert Point(1, 2).lies_on(l) and l.contains(Point(5, 0))
    assert not Point(0, 0).lies_on(l)
    assert l.direction == Point(2, -1, 0)
    assert l.normal == (1, 2)
    assert ideal_point(2, -1) == l.direction


def test_line_at_infinity_contains_ideal_points_only():
    l_inf = line_at_infinity()
    assert l_inf.is_at_infinity and l_inf.coords == (0, 0, 1)
    assert l_inf.contains(Point(7, -3, 0))
    assert not l_inf.contains(Point(7, -3))


def test_collinear_and_concurrent_by_determinants():
    assert collinear(Point(0, 0), Point(1, 2), Point(-2, -4))
    assert not collinear(Point(0, 0), Point(1, 2), Point(1, 3))
    assert collinear(Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0))  # three ideal points
    assert concurrent(Line(1, 0, -1), Line(0, 1, -1), Line(1, -1, 0))  # all pass through (1, 1)
    assert not concurrent(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, -1))


def test_equality_is_up_to_scale_and_between_same_kinds_only():
    assert Point(1, 2) == Point(-3, -6, -3)
    assert Point(1, 2) != Point(1, 2, 2)
    assert Point(1, 2, 3) != Line(1, 2, 3)
    assert len({Point(1, 2), Point(2, 4, 2), Point(Rational(1, 2), 1, Rational(1, 2))}) == 1


def test_repr_round_trips_exactly():
    a = symbols("a")
    for obj in (Point(1, 2), Point(Rational(-3, 2), a / 3 + Rational(1, 2), 1), Line(a, 0, -(a**2))):
        again = eval(repr(obj), {"Point": Point, "Line": Line, "S": S, "a": a})
        assert again.coords == obj.coords


def test_latex_rendering_points_as_columns_lines_as_rows():
    assert Point(1, 2)._repr_latex_() == r"$\begin{bmatrix}1 \\ 2 \\ 1\end{bmatrix}$"
    assert Line(Rational(1, 2), 0, -1)._repr_latex_() == r"$\begin{bmatrix}\frac{1}{2} & 0 & -1\end{bmatrix}$"


def test_coordinates_accept_sequences_and_numpy_scalars():
    import numpy as np

    assert Point([1, 2, 1]) == Point(np.int64(1), np.int64(2))
    assert Point(np.array([2, 4, 2])) == Point(1, 2)
    assert Point(sympy.Matrix([1, 2, 1])) == Point(1, 2)


def test_subs_specialises_a_symbolic_point():
    t = symbols("t")
    assert Point(t, t**2).subs(t, 3) == Point(3, 9)


def test_public_api_is_exported():
    for name in pgsym.__all__:
        assert hasattr(pgsym, name), name


# -- properties on random exact configurations -------------------------------------------------


@given(points(), points(), points(), points())
def test_meet_of_two_joins_lies_on_both_lines(p, q, r, s):
    assume(p != q and r != s)
    l, m = join(p, q), join(r, s)
    assume(l != m)
    x = meet(l, m)
    assert incident(x, l) and incident(x, m)


@given(points(), points())
def test_join_contains_both_points(p, q):
    assume(p != q)
    l = join(p, q)
    assert p.lies_on(l) and q.lies_on(l)


@given(points(), points(), nonzero_rational, nonzero_rational)
def test_join_is_invariant_under_rescaling(p, q, k, j):
    assume(p != q)
    assert join(scaled(p, k), scaled(q, j)) == join(p, q)


@given(lines(), lines(), nonzero_rational, nonzero_rational)
def test_meet_is_invariant_under_rescaling(l, m, k, j):
    assume(l != m)
    assert meet(scaled(l, k), scaled(m, j)) == meet(l, m)


@given(points(), points())
def test_dual_of_a_true_incidence_is_a_true_incidence(p, q):
    assume(p != q)
    l = join(p, q)  # p lies on l by construction
    assert incident(p, l)
    assert incident(dual(l), dual(p))  # the point dual(l) lies on the line dual(p)
    assert dual(dual(p)) == p


@given(points(), points(), points())
def test_collinear_iff_third_point_on_join(p, q, r):
    assume(p != q)
    assert collinear(p, q, r) == incident(r, join(p, q))


@given(st.integers(-9, 9), st.integers(-9, 9), st.integers(-9, 9), st.integers(-9, 9), nonzero_rational)
def test_parallel_lines_meet_in_an_ideal_point_on_the_line_at_infinity(a, b, c, c2, k):
    assume((a, b) != (0, 0) and c != c2)
    x = meet(Line(a, b, c), Line(k * a, k * b, k * c2))
    assert x.is_ideal
    assert incident(x, line_at_infinity())
    assert x == Point(b, -a, 0)


@given(points())
def test_canonical_form_is_equal_primitive_and_idempotent(p):
    c = p.canonical()
    ints = [int(v) for v in c.coords]
    assert c == p and c.canonical().coords == c.coords
    assert sympy.igcd(*ints) == 1
    assert next(v for v in ints if v != 0) > 0


@given(points(allow_ideal=False), nonzero_rational)
def test_dehomogenize_ignores_scale(p, k):
    assert scaled(p, k).dehomogenize() == p.dehomogenize()
    x, y = p.dehomogenize()
    assert Point(x, y) == p


def test_meet_of_joins_holds_identically_for_symbolic_points():
    coords = symbols("p1 p2 q1 q2 r1 r2 s1 s2")
    p, q, r, s = (Point(coords[i], coords[i + 1]) for i in range(0, 8, 2))
    l, m = join(p, q), join(r, s)
    x = meet(l, m)
    assert incident(x, l) and incident(x, m)
