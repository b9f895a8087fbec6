"""Lines of P³ (Plücker matrices and coordinates): worked values derived by hand, and properties on
random exact configurations, ideal points included."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from strategies import integers, nonzero_rational, points3, scaled
from strategies import planes as planes_strategy
from sympy import Matrix, Rational, S, symbols

from pgsym.errors import (
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
    NotOnKleinQuadricError,
    ObjectTypeError,
    PgsymError,
    UndefinedCrossRatioError,
    ZeroVectorError,
)
from pgsym.homogeneous import is_zero
from pgsym.plucker import (
    COORDINATE_ORDER,
    Line3,
    NotAPencilError,
    NotSkewSymmetricError,
    cross_ratio_planes,
    klein_form,
    reciprocal_product,
)
from pgsym.projective_line import Point1, cross_ratio
from pgsym.space import Plane, Point3, coplanar, plane_through

# -- strategies: exact random configurations of P³ --------------------------------------------

small = integers(6)
points = points3(bound=6)
planes = planes_strategy(bound=6)


@st.composite
def lines(draw) -> tuple[Line3, Point3, Point3]:
    """A line with the two distinct points it was joined from."""
    a = draw(points)
    b = draw(points.filter(lambda p: p != a))
    return Line3.join(a, b), a, b


def outer_minus(u, v) -> Matrix:
    """u vᵀ − v uᵀ, written out independently of pgsym."""
    return Matrix(4, 4, lambda i, j: u[i] * v[j] - v[i] * u[j])


FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])


# -- worked examples (values derived by hand in the comments) -----------------------------------


def test_x_axis_as_join_of_origin_and_1_0_0():
    # A = (0,0,0,1), B = (1,0,0,1); l_ij = A_i B_j - B_i A_j. Only l14 = A1 B4 - B1 A4 = 0 - 1 = -1 is nonzero.
    L = Line3.join(Point3(0, 0, 0, 1), Point3(1, 0, 0, 1))
    assert L.coordinates == (0, 0, -1, 0, 0, 0)
    assert L.matrix == Matrix([[0, 0, 0, -1], [0, 0, 0, 0], [0, 0, 0, 0], [1, 0, 0, 0]])
    # rewrite rule: l*23 = l14 = -1, so L* has -1 at (2,3) and +1 at (3,2)
    assert L.dual_matrix == Matrix([[0, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 0]])
    # the same line as the meet of y = 0, P = (0,1,0,0), and z = 0, Q = (0,0,1,0):
    # l*23 = P2 Q3 - Q2 P3 = 1, all other l*ij = 0, so the coordinates are (0, 0, 1, 0, 0, 0) = -1 * the join's
    M = Line3.meet(Plane(0, 1, 0, 0), Plane(0, 0, 1, 0))
    assert M.coordinates == (0, 0, 1, 0, 0, 0)
    assert M.dual_matrix == Matrix([[0, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 0]])
    assert M == L and hash(M) == hash(L)
    # direction b - a = (1, 0, 0), moment a x b = 0
    assert L.direction_moment() == ((1, 0, 0), (0, 0, 0))
    assert L.direction == Point3(1, 0, 0, 0)


def test_x_axis_meets_the_plane_x_equals_3():
    # X = (B.pi) A - (A.pi) B with pi = (1,0,0,-3): B.pi = 1 - 3 = -2, A.pi = -3, X = -2 A + 3 B = (3, 0, 0, 1)
    L = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    X = L.intersect_plane(Plane(1, 0, 0, -3))
    assert X.coords == (3, 0, 0, 1)


def test_plane_through_the_x_axis_and_0_1_0():
    # L* has l*23 = -1: rows (0,0,0,0), (0,0,-1,0), (0,1,0,0), (0,0,0,0); L* (0,1,0,1) = (0, 0, 1, 0): z = 0
    L = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    assert L.plane_through_point(Point3(0, 1, 0)).coords == (0, 0, 1, 0)


def test_x_axis_and_a_skew_line():
    # C = (0,1,0,1), D = (0,1,1,1): l23 = C2 D3 - D2 C3 = 1, l34 = C3 D4 - D3 C4 = -1, the rest 0.
    # (L|M) = l14 m23 + ... = (-1)(1) = -1. det[A B C D]: subtract A from B and C, C from D ->
    # rows e4, e1, e2, e3, a cyclic permutation of odd sign, so det = -1 as well.
    L = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    M = Line3.join(Point3(0, 1, 0), Point3(0, 1, 1))
    assert M.coordinates == (0, 0, 0, 1, 0, -1)
    assert reciprocal_product(L, M) == -1
    assert not L.meets(M) and not M.meets(L)
    # the y-axis meets the x-axis at the origin; the line y = 1, z = 0 is parallel: it meets at infinity
    assert L.meets(Line3.join(Point3(0, 0, 0), Point3(0, 1, 0)))
    assert L.meets(Line3.join(Point3(0, 1, 0), Point3(1, 1, 0)))
    assert L.meets(L)


def test_direction_and_moment_of_a_line_parallel_to_x():
    # a = (0,1,0), b = (1,1,0): d = b - a = (1,0,0), m = a x b = (1*0 - 0*1, 0*1 - 0*0, 0*1 - 1*1) = (0, 0, -1)
    L = Line3.join(Point3(0, 1, 0), Point3(1, 1, 0))
    assert L.direction_moment() == ((1, 0, 0), (0, 0, -1))
    assert Line3.from_direction_moment((2, 0, 0), (0, 0, -2)) == L


def test_a_line_at_infinity_has_no_direction():
    # z = 0 and z = 1 are parallel: they meet in the line at infinity of horizontal planes,
    # P = (0,0,1,0), Q = (0,0,1,-1): l*34 = P3 Q4 - Q3 P4 = -1, the only nonzero dual coordinate -> l12 = -1
    L = Line3.meet(Plane(0, 0, 1, 0), Plane(0, 0, 1, -1))
    assert L.coordinates == (-1, 0, 0, 0, 0, 0)
    assert L.is_at_infinity
    assert L == Line3.join(Point3(1, 0, 0, 0), Point3(0, 1, 0, 0))
    with pytest.raises(DegenerateConfigurationError):
        _ = L.direction


def test_cross_ratio_of_four_planes_through_the_z_axis_is_harmonic():
    # The line (1, t, 0) cuts x = 0 at t = oo, y = 0 at t = 0, x - y = 0 at t = 1, x + y = 0 at t = -1.
    # (oo, 0; 1, -1) = (0 - (-1)) / (0 - 1) = -1 (the factors with oo cancel).
    value = cross_ratio_planes(Plane(1, 0, 0, 0), Plane(0, 1, 0, 0), Plane(1, -1, 0, 0), Plane(1, 1, 0, 0))
    assert value == -1


def test_cross_ratio_of_four_parallel_planes():
    # z = 0, 1, 2, 3 share the line at infinity; the z-axis cuts them at 0, 1, 2, 3:
    # (0, 1; 2, 3) = (0-2)(1-3) / ((0-3)(1-2)) = 4/3
    value = cross_ratio_planes(*(Plane(0, 0, 1, -k) for k in range(4)))
    assert value == Rational(4, 3)


def test_coordinate_order_is_documented():
    assert COORDINATE_ORDER == ("l12", "l13", "l14", "l23", "l42", "l34")
    # l42 = -l24: the line through e4 and e2 has l42 = 1
    assert Line3.join(Point3(0, 0, 0, 1), Point3(0, 1, 0, 0)).coordinates == (0, 0, 0, 0, 1, 0)


def test_repr_round_trips_and_latex_shows_the_matrix():
    a = symbols("a")
    for L in (
        Line3.join(Point3(1, 2, 3), Point3(Rational(1, 2), 0, 1, 0)),
        Line3.join(Point3(a, 1, 0), Point3(0, a / 3, 1)),
    ):
        again = eval(repr(L), {"Line3": Line3, "S": S, "a": a})
        assert again.coordinates == L.coordinates
    tex = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))._repr_latex_()
    assert tex.startswith("$") and tex.endswith("$") and r"\begin{matrix}" in tex


def test_symbolic_join_has_the_textbook_entries_and_two_parameter_changes_scale_it():
    A, B = Point3(*symbols("a1:5")), Point3(*symbols("b1:5"))
    L = Line3.join(A, B)
    assert L.matrix == outer_minus(A.coords, B.coords).applyfunc(sympy.expand)
    assert klein_form(L.coordinates) == 0
    al, be, ga, de = symbols("alpha beta gamma delta")
    A2 = Point3(*(al * x + be * y for x, y in zip(A.coords, B.coords, strict=True)))
    B2 = Point3(*(ga * x + de * y for x, y in zip(A.coords, B.coords, strict=True)))
    factor = al * de - be * ga
    L2 = Line3.join(A2, B2)
    assert all(is_zero(u - factor * v) for u, v in zip(L2.coordinates, L.coordinates, strict=True))


def test_four_degrees_of_freedom():
    # lines through (a1, a2, 0) and (b1, b2, 1): four parameters, and the map to the five ratios
    # l_ij / l34 has a Jacobian of rank 4 (6 coordinates - 1 scale - 1 Klein constraint = 4)
    a1, a2, b1, b2 = params = symbols("a1 a2 b1 b2")
    L = Line3.join(Point3(a1, a2, 0), Point3(b1, b2, 1))
    c = L.coordinates
    ratios = Matrix([sympy.cancel(x / c[5]) for x in c[:5]])
    assert ratios.jacobian(Matrix(params)).rank() == 4


# -- named errors ---------------------------------------------------------------------------------


def test_six_numbers_off_the_klein_quadric_are_rejected():
    with pytest.raises(NotOnKleinQuadricError, match="Klein"):
        Line3.from_coordinates([1, 0, 0, 0, 0, 1])  # l12 l34 = 1
    with pytest.raises(NotOnKleinQuadricError):
        Line3(1, 1, 1, 1, 1, 1)  # 1 + 1 + 1 = 3
    with pytest.raises(ZeroVectorError):
        Line3.from_coordinates([0] * 6)
    with pytest.raises(DimensionError):
        Line3.from_coordinates([1, 0, 0, 0, 0])
    with pytest.raises(DimensionError):
        Line3.from_coordinates(3)
    with pytest.raises(DimensionError):
        klein_form([1, 2, 3])
    with pytest.raises(NotOnKleinQuadricError):
        Line3.from_direction_moment((1, 0, 0), (1, 0, 0))  # d.m = 1
    with pytest.raises(DimensionError):
        Line3.from_direction_moment((1, 0), (0, 0, 1))
    with pytest.raises(DimensionError):
        Line3.from_direction_moment(1, (0, 0, 1))
    with pytest.raises(ZeroVectorError):
        Line3.from_direction_moment((0, 0, 0), (0, 0, 0))


def test_matrices_that_are_no_plucker_matrices_are_rejected():
    with pytest.raises(NotSkewSymmetricError, match="skew"):
        Line3.from_matrix(sympy.eye(4))
    rank4 = Matrix([[0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 0, 1], [0, 0, -1, 0]])  # l12 = l34 = 1: Pfaffian 1
    with pytest.raises(NotOnKleinQuadricError):
        Line3.from_matrix(rank4)
    with pytest.raises(NotOnKleinQuadricError):
        Line3.from_dual_matrix(rank4)
    with pytest.raises(ZeroVectorError):
        Line3.from_matrix(sympy.zeros(4, 4))
    with pytest.raises(DimensionError):
        Line3.from_matrix(sympy.zeros(3, 3))
    with pytest.raises(DimensionError):
        Line3.from_matrix("not a matrix")
    assert issubclass(NotSkewSymmetricError, PgsymError) and issubclass(NotSkewSymmetricError, ValueError)


def test_degenerate_constructions_raise_named_errors():
    with pytest.raises(CoincidentPointsError):
        Line3.join(Point3(1, 2, 3), Point3(2, 4, 6, 2))
    with pytest.raises(DependentPlanesError):
        Line3.meet(Plane(1, 1, 0, 2), Plane(-2, -2, 0, -4))
    x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    with pytest.raises(DependentPlanesError, match="lies in the plane"):
        x_axis.intersect_plane(Plane(0, 1, 0, 0))
    with pytest.raises(CollinearPointsError, match="lies on the line"):
        x_axis.plane_through_point(Point3(7, 0, 0))
    with pytest.raises(CollinearPointsError):
        x_axis.plane_through_point(Point3(1, 0, 0, 0))  # the ideal point of the x-axis
    with pytest.raises(ObjectTypeError):
        Line3.join(Plane(1, 0, 0, 0), Point3(1, 0, 0))
    with pytest.raises(ObjectTypeError):
        Line3.meet(Point3(1, 0, 0), Plane(1, 0, 0, 0))
    with pytest.raises(ObjectTypeError):
        x_axis.contains(Plane(1, 0, 0, 0))
    with pytest.raises(ObjectTypeError):
        x_axis.meets(Point3(1, 0, 0))


def test_cross_ratio_of_planes_errors():
    z_pencil = [Plane(1, 0, 0, 0), Plane(0, 1, 0, 0), Plane(1, 1, 0, 0), Plane(1, -1, 0, 0)]
    with pytest.raises(NotAPencilError, match="plane 4"):
        cross_ratio_planes(*z_pencil[:3], Plane(0, 0, 1, 0))
    with pytest.raises(UndefinedCrossRatioError):
        cross_ratio_planes(*[Plane(1, 2, 3, 4)] * 4)
    with pytest.raises(UndefinedCrossRatioError):  # p1 = p4: infinite value
        cross_ratio_planes(z_pencil[0], z_pencil[1], z_pencil[2], scaled(z_pencil[0], 3))
    with pytest.raises(ObjectTypeError):
        cross_ratio_planes(*z_pencil[:3], Point3(1, 0, 0))
    assert issubclass(NotAPencilError, DegenerateConfigurationError)


# -- properties on random exact configurations ----------------------------------------------------


@FAST
@given(lines())
def test_every_join_is_skew_of_rank_2_and_on_the_klein_quadric(lab):
    L, a, b = lab
    assert klein_form(L.coordinates) == 0
    M = L.matrix
    assert M.T == -M
    assert M.rank() == 2
    assert M == outer_minus(a.coords, b.coords)
    assert L.contains(a) and L.contains(b)


@FAST
@given(lines())
def test_rewrite_rule_is_consistent(lab):
    L, _, _ = lab
    assert (L.matrix * L.dual_matrix).is_zero_matrix
    assert (L.dual_matrix * L.matrix).is_zero_matrix
    assert L.dual_matrix.rank() == 2
    assert Line3.from_dual_matrix(L.dual_matrix) == L
    assert Line3.from_matrix(L.matrix) == L
    assert Line3.from_coordinates(L.coordinates) == L
    d, m = L.direction_moment()
    assert Line3.from_direction_moment(d, m) == L


@FAST
@given(lines(), points, points)
def test_join_of_points_equals_meet_of_two_planes_through_them(lab, c, d):
    L, a, b = lab
    assume(not coplanar(a, b, c, d))  # then abc and abd are two distinct planes through the line
    p, q = plane_through(a, b, c), plane_through(a, b, d)
    M = Line3.meet(p, q)
    assert M == L
    assert M.dual_matrix == outer_minus(p.coords, q.coords)
    assert L.lies_in(p) and L.lies_in(q)


@FAST
@given(lines(), planes)
def test_line_meets_plane_in_a_point_on_both(lab, pi):
    L, a, b = lab
    if L.lies_in(pi):
        assert a.lies_on(pi) and b.lies_on(pi)
        with pytest.raises(DependentPlanesError):
            L.intersect_plane(pi)
        return
    X = L.intersect_plane(pi)
    assert X.lies_on(pi) and L.contains(X)
    if not L.is_at_infinity and not pi.is_at_infinity:
        # the line is not in the plane, so it meets it at infinity exactly when its ideal point is on it
        assert X.is_ideal == L.direction.lies_on(pi)


@FAST
@given(lines(), points)
def test_plane_through_line_and_point_contains_both(lab, x):
    L, a, b = lab
    if L.contains(x):
        with pytest.raises(CollinearPointsError):
            L.plane_through_point(x)
        return
    pi = L.plane_through_point(x)
    assert pi.contains(x) and L.lies_in(pi)
    assert pi == plane_through(a, b, x)


@FAST
@given(lines(), lines())
def test_meets_agrees_with_coplanarity_of_the_four_points(lab, mcd):
    (L, a, b), (M, c, d) = lab, mcd
    assert L.meets(M) == coplanar(a, b, c, d) == M.meets(L)
    assert reciprocal_product(L, M) == Matrix([a.coords, b.coords, c.coords, d.coords]).det()
    if L.meets(M) and L != M:
        # coplanar distinct lines share a point: cut L with a plane through M that does not contain L
        rho = next(r for r in M.planes() if not L.lies_in(r))
        X = L.intersect_plane(rho)
        assert M.contains(X) and L.contains(X)


@FAST
@given(lines(), nonzero_rational, nonzero_rational, st.integers(-3, 3), st.integers(-3, 3))
def test_invariant_under_rescaling_and_under_a_change_of_points(lab, k, j, s, t):
    L, a, b = lab
    assert Line3.join(scaled(a, k), scaled(b, j)) == L
    assert Line3.join(b, a) == L
    # a + s b and t a + b are distinct points of the same line when 1 - s t != 0
    assume(1 - s * t != 0)
    a2 = Point3(*(x + s * y for x, y in zip(a.coords, b.coords, strict=True)))
    b2 = Point3(*(t * x + y for x, y in zip(a.coords, b.coords, strict=True)))
    L2 = Line3.join(a2, b2)
    assert L2.coordinates == tuple((1 - s * t) * c for c in L.coordinates)


@FAST
@given(lines(), st.lists(st.tuples(small, small).filter(lambda v: v != (0, 0)), min_size=4, max_size=4), lines())
def test_cross_ratio_of_planes_equals_pencil_parameters_and_any_transversal(lab, params, transversal):
    L, _, _ = lab
    p, q = L.planes()
    pencil = [Plane(*(s * u + t * v for u, v in zip(p.coords, q.coords, strict=True))) for s, t in params]
    ps = [Point1(s, t) for s, t in params]
    try:
        expected = cross_ratio(*ps)
    except UndefinedCrossRatioError:
        with pytest.raises(UndefinedCrossRatioError):
            cross_ratio_planes(*pencil)
        return
    assert cross_ratio_planes(*pencil) == expected
    # an arbitrary transversal E F that does not meet the axis cuts the planes in X = (F.pi) E - (E.pi) F
    T, e, f = transversal
    assume(not T.meets(L))
    along = [
        Point1(
            sum(x * y for x, y in zip(f.coords, pi.coords, strict=True)),
            -sum(x * y for x, y in zip(e.coords, pi.coords, strict=True)),
        )
        for pi in pencil
    ]
    assert cross_ratio(*along) == expected


@FAST
@given(lines())
def test_points_and_planes_of_a_line_recover_it(lab):
    L, _, _ = lab
    a, b = L.points()
    p, q = L.planes()
    assert Line3.join(a, b) == L and Line3.meet(p, q) == L
    assert L.contains(a) and L.contains(b) and L.lies_in(p) and L.lies_in(q)


@FAST
@given(lines(), nonzero_rational)
def test_equality_is_up_to_scale_and_hash_agrees(lab, k):
    L, _, _ = lab
    M = Line3(*(k * c for c in L.coordinates))
    assert M == L and hash(M) == hash(L)
    assert M.canonical().coordinates == L.canonical().coordinates


def test_symbolic_intersection_and_plane_lie_where_they_should():
    A, B = Point3(*symbols("a1:5")), Point3(*symbols("b1:5"))
    L = Line3.join(A, B)
    pi = Plane(*symbols("p1:5"))
    X = L.intersect_plane(pi)
    assert X.lies_on(pi) and L.contains(X)
    Y = Point3(*symbols("y1:5"))
    P = L.plane_through_point(Y)
    assert P.contains(Y) and P.contains(A) and P.contains(B)


def test_fraction_and_float_inputs_are_exact():
    L = Line3(Fraction(1, 2), 0, 0, 0, 0, 0)
    assert L == Line3(1, 0, 0, 0, 0, 0) and L.coordinates[0] == Rational(1, 2)
    assert Line3(0.5, 0, 0, 0, 0, 0).coordinates[0] == Rational(1, 2)
