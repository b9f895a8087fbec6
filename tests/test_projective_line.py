"""The projective line P¹, its maps and the cross-ratio: hand-derived values and properties on random exact data."""

from __future__ import annotations

from fractions import Fraction
from itertools import combinations

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers, invertible_matrices, rationals
from sympy import Rational, S, symbols

from pgsym.errors import (
    CoincidentPointsError,
    DegenerateConfigurationError,
    DimensionError,
    IdealPointError,
    ObjectTypeError,
    SingularTransformationError,
    UndefinedCrossRatioError,
    ZeroVectorError,
)
from pgsym.homogeneous import is_zero
from pgsym.projective_line import (
    Point1,
    ProjectiveMap1,
    bracket,
    cross_ratio,
    cross_ratio_lines,
    harmonic_conjugate,
)
from pgsym.projective_plane import Line, Point, join, meet

# -- strategies -----------------------------------------------------------------------------

small = integers(9)


@st.composite
def points1(draw, allow_ideal: bool = True) -> Point1:
    """Points of P¹ from small integer pairs; about one in five is the ideal point (when allowed)."""
    if allow_ideal and draw(st.integers(0, 4)) == 0:
        return Point1(draw(small.filter(lambda v: v != 0)), 0)
    return Point1(draw(small), draw(small.filter(lambda v: v != 0)))


@st.composite
def distinct_points1(draw, n: int, allow_ideal: bool = True) -> list[Point1]:
    pts = draw(st.lists(points1(allow_ideal), min_size=n, max_size=n))
    assume(all(not p == q for p, q in combinations(pts, 2)))
    return pts


def finite_ratio(a, b, c, d):
    """The textbook formula for finite points, computed independently of the brackets."""
    a, b, c, d = (Rational(x) for x in (a, b, c, d))
    return (a - c) * (b - d) / ((a - d) * (b - c))


FAST = settings(max_examples=60, deadline=None)

# -- Point1 ------------------------------------------------------------------------------------


def test_point1_stores_homogeneous_coordinates_and_compares_up_to_scale():
    assert Point1(3).coords == (3, 1)
    assert Point1(Fraction(1, 2)).coords == (Rational(1, 2), 1)
    assert Point1(6, 2) == Point1(3)
    assert Point1(-2, 0) == Point1(1, 0) and Point1(1, 0).is_ideal
    assert not Point1(0).is_ideal
    assert Point1(4, -6).canonical().coords == (2, -3)


def test_point1_dehomogenize_and_ideal_point_error():
    assert Point1(3, 6).dehomogenize() == Rational(1, 2)
    with pytest.raises(IdealPointError, match="ideal point"):
        Point1(7, 0).dehomogenize()


def test_point1_bad_input_errors():
    with pytest.raises(DimensionError, match="1 inhomogeneous coordinate"):
        Point1(1, 2, 3)
    with pytest.raises(ZeroVectorError):
        Point1(0, 0)


@given(points1())
def test_point1_repr_round_trips(p):
    assert eval(repr(p), {"Point1": Point1, "S": S}) == p


def test_bracket_of_finite_points_is_the_difference():
    # [(a, 1) (b, 1)] = a*1 - 1*b = a - b
    a, b = symbols("a b")
    assert bracket(Point1(a), Point1(b)) == a - b
    assert bracket(Point1(1, 0), Point1(b)) == 1


def test_bracket_scales_by_the_determinant_symbolically():
    h11, h12, h21, h22, p1, p2, q1, q2 = symbols("h11 h12 h21 h22 p1 p2 q1 q2")
    H = ProjectiveMap1([[h11, h12], [h21, h22]])
    p, q = Point1(p1, p2), Point1(q1, q2)
    assert sympy.expand(bracket(H(p), H(q)) - H.det * bracket(p, q)) == 0


# -- cross-ratio: worked values ----------------------------------------------------------------


def test_cross_ratio_worked_examples():
    # (0, 1; 2, 3) = (0-2)(1-3) / ((0-3)(1-2)) = (-2)(-2) / ((-3)(-1)) = 4/3
    assert cross_ratio(Point1(0), Point1(1), Point1(2), Point1(3)) == Rational(4, 3)
    # (-1, 1; 0, ∞): [A C] = -1*1 - 1*0 = -1, [B D] = 1*0 - 1*1 = -1, [A D] = -1*0 - 1*1 = -1,
    # [B C] = 1*1 - 1*0 = 1, so (-1)(-1) / ((-1)(1)) = -1: the midpoint and ∞ are harmonic
    assert cross_ratio(Point1(-1), Point1(1), Point1(0), Point1(1, 0)) == -1
    # homogeneous representatives do not matter: (0, 2; 1, 4) with 1 = (3, 3) and 4 = (-8, -2)
    # (0-1)(2-4) / ((0-4)(2-1)) = 2 / -4 = -1/2
    assert cross_ratio(Point1(0, 5), Point1(2), Point1(3, 3), Point1(-8, -2)) == Rational(-1, 2)


def test_cross_ratio_accepts_numbers_as_finite_points():
    assert cross_ratio(0, 1, 2, 3) == Rational(4, 3)
    with pytest.raises(ObjectTypeError, match="Point1"):
        cross_ratio("0", 1, 2, 3)
    with pytest.raises(ObjectTypeError):
        cross_ratio(Point(0, 0), 1, 2, 3)


def test_cross_ratio_coincidences_that_are_defined():
    # A = C or B = D makes a bracket of the numerator vanish: value 0
    assert cross_ratio(2, 5, 2, 7) == 0
    assert cross_ratio(2, 5, 3, 5) == 0
    # A = B: [A C][A D] / ([A D][A C]) = 1; C = D likewise
    assert cross_ratio(2, 2, 3, 7) == 1
    assert cross_ratio(2, 5, 3, 3) == 1
    # with the ideal point involved
    assert cross_ratio(Point1(1, 0), 5, Point1(1, 0), 7) == 0


def test_cross_ratio_infinite_value_is_refused():
    with pytest.raises(UndefinedCrossRatioError, match=r"zero denominator \(A = D\)"):
        cross_ratio(1, 2, 3, 1)
    with pytest.raises(UndefinedCrossRatioError, match=r"zero denominator \(B = C\)"):
        cross_ratio(1, 2, 2, 4)
    with pytest.raises(UndefinedCrossRatioError, match=r"A = D, B = C"):
        cross_ratio(1, 2, 2, 1)


def test_cross_ratio_of_three_coincident_points_is_0_over_0():
    for args, names in [((1, 1, 1, 4), "A = B = C"), ((1, 4, 4, 4), "B = C = D"), ((3, 3, 3, 3), "A = B = C = D")]:
        with pytest.raises(UndefinedCrossRatioError, match="0/0") as info:
            cross_ratio(*args)
        assert names in str(info.value)
    with pytest.raises(UndefinedCrossRatioError, match="0/0"):
        cross_ratio(Point1(1, 0), 2, Point1(3, 0), Point1(-1, 0))


def test_cross_ratio_is_a_rational_function_of_symbols():
    a, b, c, d = symbols("a b c d")
    value = cross_ratio(Point1(a), Point1(b), Point1(c), Point1(d))
    assert is_zero(value - (a - c) * (b - d) / ((a - d) * (b - c)))


def test_cross_ratio_is_invariant_under_a_general_map_symbolically():
    a, b, c, d, h11, h12, h21, h22 = symbols("a b c d h11 h12 h21 h22")
    H = ProjectiveMap1([[h11, h12], [h21, h22]])
    pts = [Point1(x) for x in (a, b, c, d)]
    assert is_zero(cross_ratio(*(H(p) for p in pts)) - cross_ratio(*pts))


# -- cross-ratio: properties -------------------------------------------------------------------


@FAST
@given(st.lists(rationals(9, 6), min_size=4, max_size=4, unique=True))
def test_cross_ratio_equals_the_finite_formula(xs):
    assert cross_ratio(*(Point1(x) for x in xs)) == finite_ratio(*xs)


@FAST
@given(distinct_points1(4), invertible_matrices(2, 9).map(ProjectiveMap1))
def test_cross_ratio_is_invariant_under_projective_maps(pts, H):
    assert cross_ratio(*(H(p) for p in pts)) == cross_ratio(*pts)


@FAST
@given(distinct_points1(4))
def test_cross_ratio_pair_swaps(pts):
    A, B, C, D = pts
    value = cross_ratio(A, B, C, D)
    assert cross_ratio(B, A, D, C) == value
    assert cross_ratio(C, D, A, B) == value
    assert cross_ratio(D, C, B, A) == value
    # and the classical companions: swapping C, D inverts; swapping B, C gives 1 - value
    assert cross_ratio(A, B, D, C) == 1 / value
    assert cross_ratio(A, C, B, D) == 1 - value


@FAST
@given(st.lists(rationals(9, 6), min_size=3, max_size=3, unique=True), st.integers(0, 3))
def test_cross_ratio_with_one_ideal_point_is_the_limit_formula(xs, position):
    # with ∞ = (1, 0): [P ∞] = -1 and [∞ P] = 1 for a finite P, so the two factors containing ∞
    # cancel and the others remain; e.g. (a, b; c, ∞) = (a - c)/(b - c), (∞, b; c, d) = (b - d)/(b - c)
    x, y, z = (Rational(v) for v in xs)
    args = [Point1(v) for v in (x, y, z)]
    args.insert(position, Point1(1, 0))
    expected = {
        0: (x - z) / (x - y),  # (∞, b; c, d) with b, c, d = x, y, z
        1: (x - y) / (x - z),  # (a, ∞; c, d)
        2: (y - z) / (x - z),  # (a, b; ∞, d)
        3: (x - z) / (y - z),  # (a, b; c, ∞)
    }[position]
    assert cross_ratio(*args) == expected


# -- harmonic conjugates -------------------------------------------------------------------------


def test_harmonic_conjugate_worked_examples():
    # (0, 4; 1, d) = (0-1)(4-d)/((0-d)(4-1)) = (4-d)/(3d) = -1  =>  d = -2
    assert harmonic_conjugate(Point1(0), Point1(4), Point1(1)) == Point1(-2)
    # with B = ∞: (a, ∞; c, d) = (a - c)/(a - d) = -1  =>  d = 2a - c, the mirror image of c in a
    assert harmonic_conjugate(Point1(3), Point1(1, 0), Point1(5)) == Point1(1)
    # the midpoint of A, B pairs with ∞
    assert harmonic_conjugate(Point1(-1), Point1(1), Point1(0)).is_ideal


@FAST
@given(distinct_points1(3))
def test_harmonic_conjugate_gives_minus_one_and_is_an_involution(pts):
    a, b, c = pts
    d = harmonic_conjugate(a, b, c)
    assert cross_ratio(a, b, c, d) == -1
    assert harmonic_conjugate(a, b, d) == c
    assert harmonic_conjugate(b, a, c) == d


def test_harmonic_conjugate_undefined_for_coincident_points():
    for args, names in [((1, 1, 2), "A = B"), ((1, 2, 1), "A = C"), ((1, 2, 2), "B = C")]:
        with pytest.raises(UndefinedCrossRatioError, match=names):
            harmonic_conjugate(*args)


# -- maps of P¹ ------------------------------------------------------------------------------------


def test_map_applies_the_moebius_formula():
    # [[2, 1], [1, 1]] sends x to (2x + 1)/(x + 1): 0 -> 1, 1 -> 3/2, ∞ -> 2, -1 -> ∞
    H = ProjectiveMap1([[2, 1], [1, 1]])
    assert H(Point1(0)) == Point1(1)
    assert H.apply(Point1(1)).dehomogenize() == Rational(3, 2)
    assert H(Point1(1, 0)) == Point1(2)
    assert H @ Point1(-1) == Point1(1, 0)


def test_map_errors():
    with pytest.raises(SingularTransformationError, match="singular"):
        ProjectiveMap1([[1, 2], [2, 4]])
    with pytest.raises(DimensionError, match="2×2"):
        ProjectiveMap1([[1, 0, 0], [0, 1, 0]])
    with pytest.raises(DimensionError, match="2×2"):
        ProjectiveMap1(5)


@FAST
@given(invertible_matrices(2, 9).map(ProjectiveMap1), invertible_matrices(2, 9).map(ProjectiveMap1), points1())
def test_composition_inverse_equality_and_repr(F, G, p):
    assert (F @ G)(p) == F(G(p))
    assert F.inverse()(F(p)) == p
    assert F @ F.inverse() == ProjectiveMap1([[1, 0], [0, 1]])
    assert ProjectiveMap1(3 * F.matrix) == F
    assert eval(repr(F), {"ProjectiveMap1": ProjectiveMap1, "S": S}) == F


def test_map_with_fraction_entries_round_trips():
    H = ProjectiveMap1([[Fraction(1, 2), 0], [0, 3]])
    assert repr(H) == "ProjectiveMap1([[S(1)/2, 0], [0, 3]])"
    assert eval(repr(H), {"ProjectiveMap1": ProjectiveMap1, "S": S}) == H


def test_from_pairs_worked_example():
    # 0 -> ∞, ∞ -> 0, 1 -> 1 is x -> 1/x, the matrix [[0, 1], [1, 0]]
    H = ProjectiveMap1.from_pairs([(Point1(0), Point1(1, 0)), (Point1(1, 0), Point1(0)), (Point1(1), Point1(1))])
    assert H == ProjectiveMap1([[0, 1], [1, 0]])
    assert H(Point1(4)) == Point1(Rational(1, 4))


@FAST
@given(distinct_points1(3), distinct_points1(3), points1())
def test_from_pairs_maps_the_three_points_and_preserves_cross_ratios(src, dst, p):
    H = ProjectiveMap1.from_pairs(list(zip(src, dst, strict=True)))
    assert all(H(a) == b for a, b in zip(src, dst, strict=True))
    assume(all(not p == q for q in src))
    # the image of a fourth point is fixed by the cross-ratio
    assert cross_ratio(*dst, H(p)) == cross_ratio(*src, p)


def test_from_pairs_errors():
    with pytest.raises(CoincidentPointsError, match="source points 1 and 3"):
        ProjectiveMap1.from_pairs([(0, 0), (1, 1), (Point1(0, 3), 2)])
    with pytest.raises(CoincidentPointsError, match="target points 2 and 3"):
        ProjectiveMap1.from_pairs([(0, 0), (1, 5), (2, 5)])
    with pytest.raises(DimensionError, match="three"):
        ProjectiveMap1.from_pairs([(0, 0), (1, 1)])


# -- four concurrent lines -------------------------------------------------------------------------


def test_cross_ratio_of_lines_through_the_origin_is_that_of_their_slopes():
    # y = m x is the line (m, -1, 0); it meets x = 1 in (1, m), so the cross-ratio is that of the slopes
    # m = 0, 2, 1, 3: (0-1)(2-3) / ((0-3)(2-1)) = 1 / (-3) = -1/3
    lines = [Line(m, -1, 0) for m in (0, 2, 1, 3)]
    assert cross_ratio_lines(*lines) == Rational(-1, 3)
    # the vertical line x = 0 has slope ∞: (0, 1; 2, ∞) = (0 - 2)/(1 - 2) = 2
    assert cross_ratio_lines(Line(0, -1, 0), Line(1, -1, 0), Line(2, -1, 0), Line(1, 0, 0)) == 2


def test_cross_ratio_of_parallel_lines_is_that_of_their_intercepts():
    # x = -1, x = 1, x = 0, and the line at infinity all pass through (0, 1, 0): harmonic
    assert cross_ratio_lines(Line(1, 0, 1), Line(1, 0, -1), Line(1, 0, 0), Line(0, 0, 1)) == -1


def drop_coordinate(x: Point, k: int) -> Point1:
    """Project a point of P² from the vertex e_k onto P¹ by deleting coordinate k."""
    coords = [c for i, c in enumerate(x.coords) if i != k]
    return Point1(*coords)


@st.composite
def pencils(draw):
    """A centre P (possibly ideal), four distinct lines through it, and a transversal t missing P."""
    x1, x2, x3 = draw(small), draw(small), draw(st.sampled_from([0, 1, 2, -3]))
    assume((x1, x2, x3) != (0, 0, 0))
    centre = Point(x1, x2, x3)
    others = [Point(draw(small), draw(small), draw(small.filter(lambda v: v != 0))) for _ in range(4)]
    assume(all(not q == centre for q in others))
    lines = [join(centre, q) for q in others]
    assume(all(not l == m for l, m in combinations(lines, 2)))
    t1, t2, t3 = draw(small), draw(small), draw(small)
    assume((t1, t2, t3) != (0, 0, 0))
    t = Line(t1, t2, t3)
    assume(not t.contains(centre))
    return lines, t


@FAST
@given(pencils())
def test_cross_ratio_of_lines_equals_that_of_their_points_on_any_transversal(data):
    lines, t = data
    points = [meet(l, t) for l in lines]
    # deleting coordinate k is a projection from e_k; it is one-to-one on t when e_k is not on t (t_k != 0)
    k = next(i for i in range(3) if t[i] != 0)
    assert cross_ratio_lines(*lines) == cross_ratio(*(drop_coordinate(x, k) for x in points))


def test_cross_ratio_lines_errors():
    with pytest.raises(DegenerateConfigurationError, match="not concurrent") as info:
        cross_ratio_lines(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, -1), Line(1, -1, 0))
    assert not isinstance(info.value, UndefinedCrossRatioError)
    with pytest.raises(UndefinedCrossRatioError, match="same line"):
        cross_ratio_lines(Line(1, 1, 0), Line(2, 2, 0), Line(-1, -1, 0), Line(3, 3, 0))
    with pytest.raises(UndefinedCrossRatioError, match="A = D"):
        cross_ratio_lines(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, 0), Line(2, 0, 0))
    with pytest.raises(UndefinedCrossRatioError, match="0/0"):
        cross_ratio_lines(Line(1, 0, 0), Line(1, 0, 0), Line(1, 0, 0), Line(0, 1, 0))
    with pytest.raises(ObjectTypeError, match="Lines"):
        cross_ratio_lines(Point(1, 0), Line(0, 1, 0), Line(1, 1, 0), Line(2, 0, 0))


def test_cross_ratio_lines_symbolic_pencil_through_a_general_point():
    # lines through (p, q) with slopes m1..m4: y - q = m (x - p), i.e. (m, -1, q - m p)
    p, q = symbols("p q")
    ms = symbols("m1:5")
    lines = [Line(m, -1, q - m * p) for m in ms]
    m1, m2, m3, m4 = ms
    assert is_zero(cross_ratio_lines(*lines) - (m1 - m3) * (m2 - m4) / ((m1 - m4) * (m2 - m3)))
