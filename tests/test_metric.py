"""Metric geometry through the absolute (pgsym.metric): exact values derived by hand, and properties."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from strategies import integers, nonzero_rational
from sympy import I, Rational, sqrt

from pgsym.errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    DegenerateConfigurationError,
    IdealPointError,
    InvalidCoordinatesError,
    ObjectTypeError,
    PgsymError,
    SingularTransformationError,
)
from pgsym.metric import (
    absolute_dual_quadric,
    angle_bisectors,
    common_perpendicular,
    cos_angle,
    cos_squared_angle,
    distance,
    is_concyclic,
    is_perpendicular,
    laguerre_cross_ratio,
    orthogonal_projection,
    perpendicular_line,
    perpendicular_plane,
    point_distance,
    point_line_distance,
    point_plane_distance,
    reflect,
    reflection,
    rotation,
    scaling,
    signed_angle,
    sin_angle,
    squared_distance,
    translation,
)
from pgsym.plucker import Line3
from pgsym.projective_plane import Line, Point, join, meet
from pgsym.space import Plane, Point3
from pgsym.transformations import Transformation

FAST = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])

ints = integers(6)


@st.composite
def lines(draw):
    a, b, c = draw(ints), draw(ints), draw(ints)
    assume((a, b) != (0, 0))
    return Line(a, b, c)


@st.composite
def points(draw):
    return Point(draw(ints), draw(ints), draw(st.integers(1, 4)))


@st.composite
def pythagorean(draw):
    """An exact (cos, sin) on the unit circle: ((a² − b²)/(a² + b²), 2ab/(a² + b²))."""
    a, b = draw(ints), draw(ints)
    assume((a, b) != (0, 0))
    n = a * a + b * b
    return Rational(a * a - b * b, n), Rational(2 * a * b, n)


@st.composite
def similarities(draw):
    c, s = draw(pythagorean())
    f = draw(st.sampled_from([Rational(1, 2), 1, 2, -3]))
    return translation(draw(ints), draw(ints)) @ rotation(c, s) @ scaling(f)


@st.composite
def isometries(draw):
    c, s = draw(pythagorean())
    m = translation(draw(ints), draw(ints)) @ rotation(c, s)
    return m @ reflection(Line(0, 1, 0)) if draw(st.booleans()) else m


# -- angles: values derived by hand ------------------------------------------------------------------
def test_angle_of_y0_and_y_eq_x():
    # l = (0, 1, 0), m = (1, −1, 0): lᵀC*∞m = 0·1 + 1·(−1) = −1, lᵀC*∞l = 1, mᵀC*∞m = 2
    # → cos θ = −1/√2, cos² θ = 1/2: the unsigned angle is π/4
    l, m = Line(0, 1, 0), Line(1, -1, 0)
    assert cos_angle(l, m) == -sqrt(2) / 2
    assert cos_squared_angle(l, m) == Rational(1, 2)
    # sin θ = (l1 m2 − l2 m1)/√2 = (0·(−1) − 1·1)/√2 = −1/√2
    assert sin_angle(l, m) == -sqrt(2) / 2
    assert cos_angle(Line(0, -3, 0), m) == sqrt(2) / 2  # the opposite orientation of the same line


def test_cos_squared_is_rational_and_scale_free():
    # l = (1, 2, 0), m = (3, 1, 9): lᵀC*∞m = 3 + 2 = 5, |l|² = 5, |m|² = 10 → cos² = 25/50 = 1/2
    assert cos_squared_angle(Line(1, 2, 0), Line(3, 1, 9)) == Rational(1, 2)
    assert cos_squared_angle(Line(-2, -4, 0), Line(6, 2, 18)) == Rational(1, 2)


def test_three_dimensional_angles():
    # planes x = 0 and x + y + z + 1 = 0: (1·1)² / (1·3) = 1/3 through Q*∞ = diag(1, 1, 1, 0)
    assert cos_squared_angle(Plane(1, 0, 0, 0), Plane(1, 1, 1, 1)) == Rational(1, 3)
    # directions (1, 0, 0) and (1, 1, 0): cos = 1/√2 on Ω∞ (identity on directions)
    a = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    b = Line3.join(Point3(5, 5, 5), Point3(6, 6, 5))
    assert cos_squared_angle(a, b) == Rational(1, 2)
    assert absolute_dual_quadric() == sympy.diag(1, 1, 1, 0)


@pytest.mark.parametrize(
    ("l", "m", "expected"),
    [
        # (l1 + i l2)(m1 − i m2) / ((l1 − i l2)(m1 + i m2)):
        (Line(1, 0, 0), Line(0, 1, 0), -1),  # (1)(−i)/((1)(i)) = −1: a right angle, e^{−iπ}
        (Line(0, 1, 0), Line(1, -1, 0), -I),  # (i)(1 + i)/((−i)(1 − i)) = (−1 + i)/(−1 − i) = −i
        (Line(1, 0, 0), Line(1, 0, -5), 1),  # parallel: angle 0
        # (3 + 4i)(−i)/((3 − 4i)(i)) = (4 − 3i)/(4 + 3i) = (4 − 3i)²/25 = (7 − 24i)/25
        (Line(3, 4, 1), Line(0, 1, 0), Rational(7, 25) - Rational(24, 25) * I),
    ],
)
def test_laguerre_cross_ratio_values(l, m, expected):
    assert sympy.expand(laguerre_cross_ratio(l, m) - expected) == 0


@given(lines(), lines())
@FAST
def test_laguerre_formula_is_the_angle(l, m):
    # cr(l, m; p∨I, p∨J) = e^{−2iθ} = (cos θ − i sin θ)², so θ = (1/2i) log cr up to orientation
    assume(l != m)
    cr = laguerre_cross_ratio(l, m)
    c, s = cos_angle(l, m), sin_angle(l, m)
    assert sympy.simplify(sympy.expand((c - I * s) ** 2) - cr) == 0


def test_signed_angle_at_a_vertex():
    # rays from (1, 1) to (3, 1) (direction (2, 0)) and to (1, 4) (direction (0, 3)): +90°
    assert signed_angle(Point(1, 1), Point(3, 1), Point(1, 4)) == (0, 1)
    assert signed_angle(Point(1, 1), Point(1, 4), Point(3, 1)) == (0, -1)
    # (3, 4) against (1, 0): cos = 3/5, sin = −4/5 from the first ray to the second
    assert signed_angle(Point(0, 0), Point(3, 4), Point(1, 0)) == (Rational(3, 5), Rational(-4, 5))
    with pytest.raises(CoincidentPointsError):
        signed_angle(Point(0, 0), Point(0, 0), Point(1, 0))
    with pytest.raises(IdealPointError):
        signed_angle(Point(0, 0), Point(1, 0, 0), Point(1, 0))


# -- perpendicularity ------------------------------------------------------------------------------
def test_perpendicularity_in_the_plane_and_in_space():
    assert is_perpendicular(Line(1, 2, 3), Line(2, -1, 7))  # 1·2 + 2·(−1) = 0
    assert not is_perpendicular(Line(1, 2, 3), Line(1, 2, 0))
    x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    skew = Line3.join(Point3(0, 0, 3), Point3(0, 1, 3))  # direction (0, 1, 0), skew to the x-axis
    assert is_perpendicular(x_axis, skew) and not x_axis.meets(skew)
    assert is_perpendicular(Plane(1, 0, 0, 4), Plane(0, 1, 0, -1))
    assert is_perpendicular(Plane(0, 0, 2, 5), Line3.join(Point3(1, 1, 0), Point3(1, 1, 1)))
    assert not is_perpendicular(Plane(0, 0, 2, 5), x_axis)


def test_perpendicular_constructions():
    # through (2, 0), perpendicular to y = x: x + y = 2
    assert perpendicular_line(Line(1, -1, 0), Point(2, 0)) == Line(1, 1, -2)
    # the normal to z = 3 through (1, 2, 5) is the vertical line x = 1, y = 2
    n = perpendicular_line(Plane(0, 0, 1, -3), Point3(1, 2, 5))
    assert n.contains(Point3(1, 2, -7)) and n.contains(
        Point3(
            1,
            2,
            0,
        )
    )
    # from (2, 0, 3) to the line through 0 with direction (1, 1, 0): the foot is (1, 1, 0)
    diagonal = Line3.join(Point3(0, 0, 0), Point3(1, 1, 0))
    p = perpendicular_line(diagonal, Point3(2, 0, 3))
    assert p == Line3.join(Point3(2, 0, 3), Point3(1, 1, 0)) and is_perpendicular(p, diagonal)
    with pytest.raises(CoincidentPointsError):
        perpendicular_line(diagonal, Point3(2, 2, 0))
    # through (1, 0, 7), normal (1, 1, 0): x + y − 1 = 0
    assert perpendicular_plane(Line3.join(Point3(0, 0, 0), Point3(1, 1, 0)), Point3(1, 0, 7)) == Plane(1, 1, 0, -1)


def test_common_perpendicular():
    # l: through 0 with direction (1, 0, 0); m: through (0, 0, 2) with direction (0, 1, 1).
    # n = d_l × d_m = (0, −1, 1); the feet are (0, 0, 0) and (0, −1, 1) ((0, 0, 2) + t(0, 1, 1) with t = −1)
    l = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    m = Line3.join(Point3(0, 0, 2), Point3(0, 1, 3))
    c = common_perpendicular(l, m)
    assert c == Line3.join(Point3(0, 0, 0), Point3(0, -1, 1))
    assert c.meets(l) and c.meets(m) and is_perpendicular(c, l) and is_perpendicular(c, m)
    with pytest.raises(DegenerateConfigurationError):
        common_perpendicular(l, Line3.join(Point3(0, 1, 0), Point3(1, 1, 0)))


def test_angle_bisectors_exact():
    # the axes x = 0, y = 0: bisectors y = ±x
    b1, b2 = angle_bisectors(Line(0, 1, 0), Line(1, 0, 0))
    assert {b1, b2} == {Line(1, 1, 0), Line(1, -1, 0)}
    # y = 0 and y = x: l/|l| ± m/|m| = (0, 1, 0) ± (1, −1, 0)/√2; both bisectors make 22.5° and 67.5°
    l, m = Line(0, 1, 0), Line(1, -1, 0)
    for b in angle_bisectors(l, m):
        assert sympy.simplify(cos_squared_angle(b, l) - cos_squared_angle(b, m)) == 0
    b1, b2 = angle_bisectors(l, m)
    assert is_perpendicular(b1, b2)
    # parallel lines y = 0 and y = 2: the midline y = 1 and the line at infinity
    mid, far = angle_bisectors(Line(0, 1, 0), Line(0, 1, -2))
    assert mid == Line(0, 1, -1) and far.is_at_infinity
    with pytest.raises(CoincidentLinesError):
        angle_bisectors(Line(1, 1, 1), Line(2, 2, 2))


# -- projections and distances ---------------------------------------------------------------------
def test_orthogonal_projection_values():
    # foot from (2, 0) on y = x: (1, 1); from (3, 4, 5) on z = 1: (3, 4, 1)
    assert orthogonal_projection(Point(2, 0), Line(1, -1, 0)) == Point(1, 1)
    assert orthogonal_projection(Point3(3, 4, 5), Plane(0, 0, 1, -1)) == Point3(3, 4, 1)
    # on the line through (0, 0, 0) and (1, 1, 0): (2, 0, 3) ↦ ((2·1 + 0·1)/2)(1, 1, 0) = (1, 1, 0)
    assert orthogonal_projection(Point3(2, 0, 3), Line3.join(Point3(0, 0, 0), Point3(1, 1, 0))) == Point3(1, 1, 0)
    with pytest.raises(IdealPointError):
        orthogonal_projection(Point(1, 1, 0), Line(1, 0, 0))


@pytest.mark.parametrize(
    ("a", "b", "squared"),
    [
        (Point(3, 4), Point(0, 0), 25),  # 3² + 4²
        (Point(1, 2), Line(3, 4, 0), Rational(121, 25)),  # (3 + 8)² / (9 + 16)
        (Line(3, 4, 0), Point(2, 4, 2), Rational(121, 25)),  # either order, any scale
        (Point3(1, 2, 3), Point3(1, 0, 3, 1), 4),
        (Point3(1, 2, 3), Plane(0, 0, 2, 0), 9),  # (2·3)² / 4
        (Point3(0, 3, 4), Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)), 25),  # from the x-axis
        # skew: x-axis and the line through (0, 0, 2) with direction (0, 1, 1): |(0,0,2)·(0,−1,1)|²/|n|² = 4/2
        (Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)), Line3.join(Point3(0, 0, 2), Point3(0, 1, 3)), 2),
        # parallel: the x-axis and the line through (0, 3, 4) with direction (2, 0, 0): 3² + 4²
        (Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)), Line3.join(Point3(0, 3, 4), Point3(2, 3, 4)), 25),
        # meeting lines are at distance 0
        (Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)), Line3.join(Point3(5, 0, 0), Point3(5, 1, 7)), 0),
    ],
)
def test_squared_distances(a, b, squared):
    assert squared_distance(a, b) == squared
    assert distance(a, b) == sqrt(squared)


def test_named_distances_match_the_numeric_names():
    assert point_distance(Point(0, 0), Point(3, 4)) == 5
    assert point_line_distance(Point(1, 2), Line(3, 4, 0)) == Rational(11, 5)  # (3 + 8) / 5
    assert point_line_distance(Point3(0, 3, 4), Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))) == 5
    assert point_plane_distance(Point3(1, 2, 3), Plane(0, 0, 2, 0)) == 3
    with pytest.raises(ObjectTypeError):
        point_distance(Point(0, 0), Point3(0, 0, 0))
    with pytest.raises(ObjectTypeError):
        point_line_distance(Point(0, 0), Line3.join(Point3(0, 0, 0), Point3(1, 0, 0)))
    with pytest.raises(ObjectTypeError):
        point_plane_distance(Point3(0, 0, 0), Line(1, 0, 0))


def test_distance_is_exact_algebraic():
    assert distance(Point(0, 0), Point(1, 1)) == sqrt(2)
    assert distance(Point3(0, 0, 0), Point3(1, 1, 1)) == sqrt(3)


@pytest.mark.parametrize(
    ("a", "b"),
    [
        (Point(1, 1, 0), Point(0, 0)),
        (Point(0, 0), Line(0, 0, 1)),
        (Point3(1, 0, 0, 0), Plane(1, 0, 0, 0)),
        (Point3(1, 0, 0), Plane(0, 0, 0, 1)),
        (Point3(1, 2, 3), Line3.join(Point3(1, 0, 0, 0), Point3(0, 1, 0, 0))),
        (Point3(1, 2, 3, 0), Line3.join(Point3(0, 0, 0), Point3(0, 1, 0))),
    ],
)
def test_ideal_elements_raise_a_named_error(a, b):
    with pytest.raises(IdealPointError) as err:
        squared_distance(a, b)
    assert isinstance(err.value, PgsymError)
    assert "ideal" in str(err.value) or "infinity" in str(err.value)
    with pytest.raises(IdealPointError):
        distance(a, b)


def test_angles_with_the_line_at_infinity_raise():
    for f in (cos_angle, cos_squared_angle, is_perpendicular):
        with pytest.raises(IdealPointError):
            f(Line(0, 0, 1), Line(1, 0, 0))
    with pytest.raises(IdealPointError):
        is_perpendicular(Plane(0, 0, 0, 1), Plane(1, 0, 0, 0))


def test_isotropic_lines_make_no_angle():
    # a line through I = (1, i, 0): lᵀC*∞l = 1 + i² = 0
    with pytest.raises(DegenerateConfigurationError):
        cos_angle(Line(1, I, 0), Line(1, 0, 0))


def test_wrong_types():
    with pytest.raises(ObjectTypeError):
        cos_angle(Line(1, 0, 0), Plane(1, 0, 0, 0))
    with pytest.raises(ObjectTypeError):
        squared_distance(Line(1, 0, 0), Line(0, 1, 0))
    with pytest.raises(ObjectTypeError):
        orthogonal_projection(Point(1, 1), Plane(1, 0, 0, 0))
    with pytest.raises(ObjectTypeError):
        reflection(Point(1, 1))


# -- similarities ----------------------------------------------------------------------------------
def test_rotations_quarter_and_half_turns_and_algebraic():
    assert rotation(0, 1)(Point(1, 0)) == Point(0, 1)
    assert rotation(-1, 0)(Point(2, 3)) == Point(-2, -3)
    assert rotation(0, -1, Point(1, 1))(Point(2, 1)) == Point(1, 0)  # −90° about (1, 1)
    r60 = rotation(Rational(1, 2), sqrt(3) / 2)
    assert r60 @ r60 @ r60 == rotation(-1, 0)  # three 60° turns make a half-turn
    with pytest.raises(InvalidCoordinatesError):
        rotation(3, 4)
    # the rational parametrisation: ((1 − t²)/(1 + t²))² + (2t/(1 + t²))² = 1 identically
    t = sympy.Symbol("t")
    r = rotation((1 - t**2) / (1 + t**2), 2 * t / (1 + t**2))
    assert r(Point(1, 0)) == Point(1 - t**2, 2 * t, 1 + t**2)
    with pytest.raises(InvalidCoordinatesError):
        rotation(t, 1 - t)
    with pytest.raises(InvalidCoordinatesError):
        rotation(Rational(1, 2), Rational(1, 2))


def test_translation_scaling_reflection_values():
    assert translation(1, -2)(Point(0, 0)) == Point(1, -2)
    assert translation((1, 2, 3))(Point3(1, 1, 1)) == Point3(2, 3, 4)
    assert scaling(2, Point(1, 1))(Point(2, 3)) == Point(3, 5)  # (1,1) + 2·(1, 2)
    assert scaling(2, Point3(0, 0, 1))(Point3(1, 1, 1)) == Point3(2, 2, 1)
    with pytest.raises(SingularTransformationError):
        scaling(0)
    # in y = 1: (x, y) ↦ (x, 2 − y)
    assert reflection(Line(0, 1, -1)) == Transformation([[1, 0, 0], [0, -1, 2], [0, 0, 1]])
    # in the plane x + y + z = 3, (0, 0, 0) ↦ 2·(1, 1, 1)
    assert reflect(Point3(0, 0, 0), Plane(1, 1, 1, -3)) == Point3(2, 2, 2)


def test_a_general_affinity_changes_angles():
    # the shear (x, y) ↦ (x + y, y) keeps y = 0 but sends x = 0 (points (0, t)) to y = x (points (t, t))
    shear = Transformation([[1, 1, 0], [0, 1, 0], [0, 0, 1]])
    l, m = Line(0, 1, 0), Line(1, 0, 0)
    assert is_perpendicular(l, m)
    assert shear(m) == Line(1, -1, 0)
    assert cos_squared_angle(shear(l), shear(m)) == Rational(1, 2) != cos_squared_angle(l, m)


# -- properties ------------------------------------------------------------------------------------
@given(lines(), lines(), similarities())
@FAST
def test_angles_and_perpendicularity_are_similarity_invariants(l, m, S):
    assert cos_squared_angle(S(l), S(m)) == cos_squared_angle(l, m)
    assert is_perpendicular(S(l), S(m)) == is_perpendicular(l, m)


@given(lines(), points(), points(), isometries())
@FAST
def test_distances_are_isometry_invariants(l, p, q, M):
    assert squared_distance(M(p), M(q)) == squared_distance(p, q)
    assert squared_distance(M(p), M(l)) == squared_distance(p, l)


@given(lines(), points(), ints)
@FAST
def test_reflection_is_an_involution_fixing_the_mirror(l, p, t):
    R = reflection(l)
    assert R @ R == Transformation.identity(2)
    assert R(p) != p or p.lies_on(l)
    other = Line(l[1], -l[0], t)  # a perpendicular line meets the mirror in a finite point
    on = meet(l, other)
    assert R(on) == on
    assert squared_distance(R(p), l) == squared_distance(p, l)


@given(lines(), points())
@FAST
def test_projection_is_idempotent_with_perpendicular_residual(l, p):
    f = orthogonal_projection(p, l)
    assert f.lies_on(l)
    assert orthogonal_projection(f, l) == f
    if not p.lies_on(l):
        assert is_perpendicular(join(p, f), l)
        assert squared_distance(p, f) == squared_distance(p, l)


@given(ints, ints, ints, ints, ints, ints, st.integers(1, 3))
@FAST
def test_space_projection_reflection_and_distance(a, b, c, x, y, z, w):
    assume((a, b, c) != (0, 0, 0))
    plane, p = Plane(a, b, c, x - y), Point3(x, y, z, w)
    f = orthogonal_projection(p, plane)
    assert plane.contains(f) and orthogonal_projection(f, plane) == f
    R = reflection(plane)
    assert R @ R == Transformation.identity(3)
    assert squared_distance(R(p), plane) == squared_distance(p, plane)
    assert squared_distance(p, f) == squared_distance(p, plane)
    q = Point3(1, 2, 3)
    for M in (translation(x, y, z), _turn_about_z(a, b)):
        assert squared_distance(M(p), M(q)) == squared_distance(p, q)
        assert squared_distance(M(p), M(plane)) == squared_distance(p, plane)


def _turn_about_z(a: int, b: int) -> Transformation:
    # the rotation about the z-axis by the angle with cos = (a² − b²)/n, sin = 2ab/n, n = a² + b²
    if a == b == 0:
        return Transformation.identity(3)
    n = a * a + b * b
    c, s = Rational(a * a - b * b, n), Rational(2 * a * b, n)
    return Transformation([[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])


@given(ints, ints, ints, ints, ints, ints, st.integers(1, 3))
@FAST
def test_space_angles_are_similarity_invariants(a, b, c, d, e, f, k):
    assume((a, b, c) != (0, 0, 0) and (d, e, f) != (0, 0, 0) and (a, b, c) != (d, e, f))
    S = translation(a, e, k) @ _turn_about_z(b, c) @ scaling(k, dim=3)
    p, q = Plane(a, b, c, d), Plane(d, e, f, a)
    assert cos_squared_angle(S(p), S(q)) == cos_squared_angle(p, q)
    assert is_perpendicular(S(p), S(q)) == is_perpendicular(p, q)
    l = Line3.join(Point3(a, b, c), Point3(d, e, f))
    m = Line3.join(Point3(0, 0, 0), Point3(f, d, e))
    assert cos_squared_angle(S(l), S(m)) == cos_squared_angle(l, m)
    assert squared_distance(S(l), S(m)) == k**2 * squared_distance(l, m)


# -- concyclic points -------------------------------------------------------------------------------

def _on_circle(cx: Fraction, cy: Fraction, r: Fraction, t: Fraction) -> Point:
    # the rational parametrisation of the unit circle ((1 − t²)/(1 + t²), 2t/(1 + t²)), scaled and moved
    q = 1 + t * t
    return Point(cx + r * (1 - t * t) / q, cy + r * 2 * t / q)


def test_is_concyclic_by_hand() -> None:
    # x² + y² = 25 holds for (5, 0), (3, 4), (−4, 3), (0, −5); (1, 1) gives 2 ≠ 25
    on = [Point(5, 0), Point(3, 4), Point(-4, 3), Point(0, -5)]
    assert is_concyclic(*on)
    assert not is_concyclic(*on[:3], Point(1, 1))
    # the same points with other representatives
    assert is_concyclic(Point(10, 0, 2), Point(-3, -4, -1), *on[2:])
    # collinear points: on the degenerate "circle" line ∪ l∞ only, so on no circle
    assert not is_concyclic(Point(0, 0), Point(1, 0), Point(2, 0), Point(3, 0))
    # a repeated point leaves three points in general position: a circle passes through them
    assert is_concyclic(Point(0, 0), Point(0, 0), Point(1, 0), Point(0, 1))
    with pytest.raises(IdealPointError):
        is_concyclic(Point(1, 0, 0), *on[1:])


@given(st.tuples(*[nonzero_rational] * 7))
@settings(max_examples=40, deadline=None)
def test_points_of_a_circle_are_concyclic_and_a_moved_one_is_not(v: tuple[Fraction, ...]) -> None:
    cx, cy, r, *ts = v
    pts = [_on_circle(cx, cy, r, t) for t in ts]
    assert is_concyclic(*pts)
    # the fourth point pushed away from the centre to twice the radius is on no circle with the others
    # (unless the first three coincide in fewer than three distinct points)
    x, y = (sympy.Rational(c.numerator, c.denominator) for c in (cx, cy))
    px, py = pts[3].dehomogenize()
    far = Point(x + 2 * (px - x), y + 2 * (py - y))
    if len({p.canonical().coords for p in pts[:3]}) == 3:
        assert not is_concyclic(*pts[:3], far)
