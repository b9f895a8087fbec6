"""Affine type, centre, axes and foci of conics, and conics from metric data: hand-derived values, named
errors, and properties (type invariant under affinities, centre equivariant, |PF₁| ± |PF₂| = 2a)."""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from sympy import I, Matrix, Rational, sqrt, symbols

import pgsym
from pgsym.conic_metric import (
    CONIC_TYPES,
    affine_type,
    axes,
    center,
    conic_from_foci,
    ellipse,
    foci,
    hyperbola,
    parabola,
    semi_axes,
)
from pgsym.conics import Conic, circular_points
from pgsym.errors import (
    DegenerateConfigurationError,
    DegenerateConicError,
    InvalidCoordinatesError,
    UndecidableError,
)
from pgsym.exact import is_zero
from pgsym.metric import distance
from pgsym.projective_plane import Line, Point, meet
from pgsym.transformations import Transformation
from tests.strategies import affine_matrices, integers, unit_directions

FAST = settings(max_examples=12, deadline=None)

# (a, b, c, d, e, f) of a x² + b xy + c y² + d x + e y + f, each type derived by hand
TYPES = [
    ((1, 0, 4, 0, 0, -4), "ellipse"),                  # x²/4 + y² = 1
    ((1, 0, 1, -2, 0, -3), "circle"),                  # (x − 1)² + y² = 4
    ((1, 0, -1, 0, 0, -1), "hyperbola"),               # b² − 4ac = 4 > 0
    ((0, 1, 0, 0, 0, -1), "hyperbola"),                # xy = 1
    ((1, 0, 0, 0, -1, 0), "parabola"),                 # y = x²: b² − 4ac = 0
    ((1, 2, 1, 1, 0, 0), "parabola"),                  # (x + y)² + x = 0, det = −1/4 ≠ 0
    ((1, 0, 2, 0, 0, 1), "imaginary ellipse"),         # x² + 2y² = −1: a·det = 2 > 0
    ((1, 0, 1, 0, 0, 1), "imaginary circle"),          # x² + y² = −1
    ((1, 0, -1, 0, 0, 0), "intersecting lines"),       # (x − y)(x + y)
    ((1, 0, 1, 0, 0, 0), "point ellipse"),             # x² + y² = 0: the lines x ± iy through the origin
    ((1, 0, 0, 0, 0, -1), "parallel lines"),           # x = ±1
    ((1, 0, 0, 0, 0, 1), "imaginary parallel lines"),  # x = ±i
    ((0, 0, 0, 1, 0, 0), "line and line at infinity"), # x w = 0
    ((1, 2, 1, -2, -2, 1), "double line"),             # (x + y − 1)²
    ((0, 0, 0, 0, 0, 1), "double line at infinity"),   # w² = 0
]


@pytest.mark.parametrize(("coefficients", "kind"), TYPES)
def test_affine_type_by_hand(coefficients, kind):
    C = Conic.from_coefficients(*coefficients)
    assert affine_type(C) == kind
    assert affine_type(Conic(-3 * Matrix(C.matrix))) == kind  # a negative scale changes no decision


def test_every_type_is_covered_and_exported():
    assert {kind for _, kind in TYPES} == set(CONIC_TYPES)
    assert pgsym.affine_type is affine_type and pgsym.conic_foci is foci and pgsym.conic_center is center


def test_affine_type_with_irrational_and_undecidable_coefficients():
    # x² + √2 xy + y² = 1: b² − 4ac = 2 − 4 < 0, an ellipse; with √5 instead: 5 − 4 > 0, a hyperbola
    assert affine_type(Conic.from_coefficients(1, sqrt(2), 1, 0, 0, -1)) == "ellipse"
    assert affine_type(Conic.from_coefficients(1, sqrt(5), 1, 0, 0, -1)) == "hyperbola"
    k = symbols("k")
    with pytest.raises(UndecidableError):
        affine_type(Conic.from_coefficients(1, k, 1, 0, 0, -1))
    with pytest.raises(InvalidCoordinatesError, match="not a real conic"):  # x² + i xy + y² = 1
        affine_type(Conic.from_coefficients(1, I, 1, 0, 0, -1))
    # i(x² + y² − 1) is the unit circle: real up to scale
    assert affine_type(Conic.from_coefficients(I, 0, I, 0, 0, -I)) == "circle"
    # a symbolic but decided case: the circle (x − k)² + y² = 1 (a = c, b = 0; b² − 4ac = −4)
    assert affine_type(Conic.circle(k, 0, 1)) == "circle"


def _apply(H: list[list[int]], C: Conic) -> Conic:
    return Transformation(H)(C)


@given(st.sampled_from([c for c, kind in TYPES]), affine_matrices())
@FAST
def test_type_invariant_under_affinities(coefficients, H):
    C = Conic.from_coefficients(*coefficients)
    before, after = affine_type(C), affine_type(_apply(H, C))
    # an affinity keeps l∞ and reality, so the type, except that a circle may become an ellipse
    merge = {"circle": "ellipse", "imaginary circle": "imaginary ellipse"}
    assert merge.get(after, after) == merge.get(before, before)


@given(st.sampled_from([c for c, kind in TYPES if kind in CONIC_TYPES[:6]]), affine_matrices())
@FAST
def test_center_is_equivariant(coefficients, H):
    C = Conic.from_coefficients(*coefficients)
    T = Transformation(H)
    assert center(T(C)) == T(center(C))


def test_center_axes_semi_axes_by_hand():
    # 5x² + 6xy + 5y² = 8: S = [[5, 3], [3, 5]] has eigenvalues 8 along (1, 1) and 2 along (1, −1),
    # so 8u² + 2v² = 8: a² = 4 along (1, −1) (the line x + y = 0), b² = 1 along (1, 1)
    C = Conic.from_coefficients(5, 6, 5, 0, 0, -8)
    assert center(C) == Point(0, 0)
    assert semi_axes(C) == (2, 1)
    assert axes(C) == (Line(1, 1, 0), Line(1, -1, 0))
    # c² = 4 − 1 = 3 along (1, −1)/√2: the foci ±(√6/2, −√6/2)
    assert set(foci(C)) == {Point(sqrt(6) / 2, -sqrt(6) / 2), Point(-sqrt(6) / 2, sqrt(6) / 2)}
    # (x − 1)²/9 − (y + 2)²/4 = 1: centre (1, −2), a = 3, b = 2, c² = 13, foci (1 ± √13, −2)
    H = Conic.from_coefficients(4, 0, -9, -8, -36, -68)
    assert affine_type(H) == "hyperbola" and center(H) == Point(1, -2)
    assert semi_axes(H) == (3, 2)
    assert axes(H) == (Line(0, 1, 2), Line(1, 0, -1))
    assert set(foci(H)) == {Point(1 + sqrt(13), -2), Point(1 - sqrt(13), -2)}


def test_parabola_centre_axis_focus_by_hand():
    # (y − 1)² = 8(x + 2): vertex (−2, 1), 4p = 8, focus (0, 1), axis y = 1, centre the ideal point (1, 0, 0)
    P = Conic.from_coefficients(0, 0, 1, -8, -2, -15)
    assert affine_type(P) == "parabola"
    assert center(P) == Point(1, 0, 0)
    assert foci(P) == (Point(0, 1),)
    assert axes(P) == (Line(0, 1, -1),)
    with pytest.raises(DegenerateConfigurationError, match="parabola has one axis"):
        semi_axes(P)


def test_circle_and_degenerate_cases():
    C = Conic.circle(2, 3, 5)
    assert foci(C) == (Point(2, 3),)
    with pytest.raises(DegenerateConfigurationError, match="circle"):
        axes(C)
    with pytest.raises(DegenerateConicError):
        center(Conic.from_coefficients(1, 0, -1, 0, 0, 0))
    with pytest.raises(DegenerateConfigurationError):
        foci(Conic.from_coefficients(1, 0, 2, 0, 0, 1))  # imaginary ellipse: no real focus here


# -- constructors ------------------------------------------------------------------------------------
def test_constructors_by_hand():
    # 4(x − 1)² + 9(y − 2)² = 36: 4x² + 9y² − 8x − 36y + 4 = 0
    assert ellipse((1, 2), 3, 2) == Conic.from_coefficients(4, 0, 9, -8, -36, 4)
    assert ellipse(Point(1, 2), 3, 2) == ellipse((1, 2), 3, 2)  # the centre as a Point or a pair
    # rotated by 90°: the a-axis vertical, x²/b² + y²/a² = 1 → 9x² + 4y² = 36
    assert ellipse((0, 0), 3, 2, direction=(0, 1)) == Conic.from_coefficients(9, 0, 4, 0, 0, -36)
    # rotated by 45°, a = 2, b = 1: the conic 5x² + 6xy + 5y² = 8 above has its major axis along (1, −1)
    assert ellipse((0, 0), 2, 1, direction=(sqrt(2) / 2, -sqrt(2) / 2)) == Conic.from_coefficients(5, 6, 5, 0, 0, -8)
    # x²/9 − y²/4 = 1 moved to (1, −2): 4(x − 1)² − 9(y + 2)² = 36
    assert hyperbola((1, -2), 3, 2) == Conic.from_coefficients(4, 0, -9, -8, -36, -68)
    # y² = 8x moved to (−2, 1): (y − 1)² = 8(x + 2)
    assert parabola((-2, 1), 2) == Conic.from_coefficients(0, 0, 1, -8, -2, -15)
    # foci (±3, 0), a = 5: b² = 16; a = 2 < 3: the hyperbola x²/4 − y²/5 = 1
    assert conic_from_foci(Point(-3, 0), Point(3, 0), 5) == Conic.from_coefficients(16, 0, 25, 0, 0, -400)
    assert conic_from_foci(Point(-3, 0), Point(3, 0), 2) == Conic.from_coefficients(5, 0, -4, 0, 0, -20)
    assert conic_from_foci(Point(1, 1), Point(1, 1), 3) == Conic.circle(1, 1, 3)


def test_constructor_errors():
    with pytest.raises(DegenerateConicError, match="distance of the foci"):
        conic_from_foci(Point(-3, 0), Point(3, 0), 3)
    with pytest.raises(InvalidCoordinatesError):
        conic_from_foci(Point(1, 0, 0), Point(3, 0), 3)
    with pytest.raises(DegenerateConfigurationError):
        ellipse((0, 0), 0, 1)
    with pytest.raises(InvalidCoordinatesError, match="unit circle"):
        ellipse((0, 0), 2, 1, direction=(1, 1))
    with pytest.raises(InvalidCoordinatesError):
        ellipse(Point(1, 1, 0), 2, 1)


def _on_frame(center, direction, u, v):
    """The point centre + u·d + v·d⊥ for the unit direction d = (cos, sin)."""
    (cx, cy), (c, s) = center, direction
    return Point(cx + u * c - v * s, cy + u * s + v * c)


positive = st.fractions(min_value=Fraction(1, 3), max_value=6, max_denominator=4)


@given(st.tuples(integers(4), integers(4)), positive, positive, unit_directions(), unit_directions())
@FAST
def test_ellipse_foci_sum_of_distances(centre, a, b, direction, param):
    assume(a != b)
    a, b = max(a, b), min(a, b)
    E = ellipse(centre, a, b, direction)
    assert affine_type(E) == "ellipse"
    assert set(semi_axes(E)) == {Rational(a), Rational(b)}
    f1, f2 = foci(E)
    # the foci lie at distance c = √(a² − b²) from the centre
    assert is_zero(distance(f1, Point(*centre)) ** 2 - (Rational(a) ** 2 - Rational(b) ** 2))
    # a rational point of the ellipse: centre + a cos t · d + b sin t · d⊥
    P = _on_frame(centre, direction, a * param[0], b * param[1])
    assert E.contains(P)
    assert is_zero(distance(P, f1) + distance(P, f2) - 2 * Rational(a))
    # and the foci give back the ellipse
    assert conic_from_foci(f1, f2, a) == E


@given(st.tuples(integers(4), integers(4)), positive, positive, unit_directions(), unit_directions())
@FAST
def test_hyperbola_foci_difference_of_distances(centre, a, b, direction, param):
    assume(param[0] != 0)
    Hc = hyperbola(centre, a, b, direction)
    assert affine_type(Hc) == "hyperbola" and semi_axes(Hc) == (Rational(a), Rational(b))
    f1, f2 = foci(Hc)
    # (1/cos t, tan t) lies on x² − y² = 1
    P = _on_frame(centre, direction, a / param[0], b * param[1] / param[0])
    assert Hc.contains(P)
    assert is_zero((distance(P, f1) - distance(P, f2)) ** 2 - 4 * Rational(a) ** 2)   # |d₁ − d₂| = 2a


@given(st.tuples(integers(4), integers(4)), positive, unit_directions(), st.fractions(min_value=-3, max_value=3,
                                                                                      max_denominator=3))
@FAST
def test_parabola_focus_and_directrix(vertex, p, direction, s):
    P_ = parabola(vertex, p, direction)
    (F,) = foci(P_)
    assert F == _on_frame(vertex, direction, p, 0)
    # (p s², 2 p s) lies on y² = 4px; its distance to the focus equals that to the directrix x = −p: p s² + p
    Q = _on_frame(vertex, direction, p * s * s, 2 * p * s)
    assert P_.contains(Q)
    assert is_zero(distance(Q, F) - (p * s * s + p))
    assert center(P_) == Point(direction[0], direction[1], 0)


@pytest.mark.parametrize("coefficients", [(1, 0, 4, 0, 0, -4), (5, 6, 5, 0, 0, -8), (4, 0, -9, -8, -36, -68)])
def test_foci_are_where_tangents_from_I_and_J_meet(coefficients):
    # Plücker's definition (H&Z, Richter-Gebert): the tangents from I and from J meet in four points, the
    # two real foci and two imaginary ones; computed here with the tangents, independently of foci()
    C = Conic.from_coefficients(*coefficients)
    I_, J_ = circular_points()
    meets = [meet(s, t) for s in C.tangents_from(I_) for t in C.tangents_from(J_)]
    for f in foci(C):
        assert any(f == m for m in meets)


def test_radius_and_intersection_angle_of_circles() -> None:
    from pgsym.conic_metric import cos_intersection_angle, radius, squared_radius

    # (x − 1)² + (y − 2)² = 9 → x² + y² − 2x − 4y − 4 = 0: d = −1, e = −2, f = −4, r² = 1 + 4 + 4 = 9
    assert squared_radius(Conic.from_coefficients(1, 0, 1, -2, -4, -4)) == 9
    # 2x² + 2y² − 1 = 0: r² = (0 + 0 + 2)/4 = 1/2
    assert radius(Conic.from_coefficients(2, 0, 2, 0, 0, -1)) == sqrt(2) / 2
    assert semi_axes(Conic.circle(0, 0, 3)) == (3, 3)
    # unit circles with centres 1 apart: (1 + 1 − 1)/(2·1·1) = 1/2, they cross at 60°
    assert cos_intersection_angle(Conic.circle(0, 0, 1), Conic.circle(1, 0, 1)) == Rational(1, 2)
    # r = 3 and r = 4 with centres 5 apart: (9 + 16 − 25)/24 = 0, orthogonal
    assert cos_intersection_angle(Conic.circle(0, 0, 3), Conic.circle(5, 0, 4)) == 0
    with pytest.raises(DegenerateConfigurationError):
        radius(Conic.from_coefficients(1, 0, 4, 0, 0, -4))      # an ellipse
    with pytest.raises(DegenerateConfigurationError):
        radius(Conic.from_coefficients(1, 0, 1, 0, 0, 1))       # x² + y² + 1 = 0 has no real point
