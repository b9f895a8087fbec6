"""Points and planes of P³: worked values derived by hand, and properties on random exact configurations."""

from __future__ import annotations

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers, nonzero_rational, planes, points3, scaled
from sympy import Matrix, Rational, S, symbols

from pgsym.errors import (
    CollinearPointsError,
    DependentPlanesError,
    DimensionError,
    IdealPointError,
    ObjectTypeError,
    ZeroVectorError,
)
from pgsym.space import (
    Plane,
    Point3,
    coplanar,
    dual,
    incident,
    plane_at_infinity,
    plane_through,
    point_on_planes,
    triple_cross,
)

# -- strategies -------------------------------------------------------------------------------------

small = integers(9)



def rank(*objs) -> int:
    return Matrix([list(o.coords) for o in objs]).rank()


FAST = settings(max_examples=60, deadline=None)

# -- worked examples ------------------------------------------------------------------------------------


def test_inhomogeneous_point_gets_last_coordinate_one_and_dehomogenizes_back():
    p = Point3(1, Rational(1, 2), -3)
    assert p.coords == (1, Rational(1, 2), -3, 1)
    assert Point3(2, 1, -6, 2) == p
    assert Point3(4, 2, -12, 4).dehomogenize() == (1, Rational(1, 2), -3)
    assert not p.is_ideal


def test_ideal_point_has_no_inhomogeneous_coordinates():
    d = Point3(1, -2, 3, 0)
    assert d.is_ideal
    with pytest.raises(IdealPointError, match="direction is"):
        d.dehomogenize()


def test_plane_normal_and_incidence():
    # 2x - y + 2z = 4: (1, 0, 1) gives 2 - 0 + 2 = 4, (0, 0, 0) gives 0 ≠ 4
    pi = Plane(2, -1, 2, -4)
    assert pi.normal == (2, -1, 2)
    assert pi.contains(Point3(1, 0, 1)) and Point3(1, 0, 1).lies_on(pi)
    assert not pi.contains(Point3(0, 0, 0))
    # the direction (1, 2, 0) is parallel to the plane: 2*1 - 1*2 + 0 = 0
    assert pi.contains(Point3(1, 2, 0, 0))
    assert incident(pi, Point3(1, 0, 1))


def test_plane_at_infinity_contains_exactly_the_ideal_points():
    pinf = plane_at_infinity()
    assert pinf.coords == (0, 0, 0, 1) and pinf.is_at_infinity
    assert pinf.normal == (0, 0, 0)
    assert pinf.contains(Point3(5, -1, 7, 0))
    assert not pinf.contains(Point3(5, -1, 7))
    assert not Plane(0, 0, 1, 1).is_at_infinity


def test_plane_through_the_three_unit_points():
    # x + y + z = 1 contains (1,0,0), (0,1,0), (0,0,1); by the minors formula π·X = det[X; p; q; r]:
    # with X = (x, y, z, w) the determinant reduces to x + y + z - w, so π = (1, 1, 1, -1)
    pi = plane_through(Point3(1, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1))
    assert pi.coords == (1, 1, 1, -1)


def test_plane_through_points_with_fractions_and_an_ideal_point():
    # the plane through (0,0,2), (1,0,2) and the direction (0,1,0) is z = 2: (0, 0, 1, -2)
    pi = plane_through(Point3(0, 0, 2), Point3(1, 0, 2), Point3(0, 1, 0, 0))
    assert pi == Plane(0, 0, 1, -2)
    # the plane x/2 + y/3 + z/4 = 1 (intercepts 2, 3, 4) is 6x + 4y + 3z - 12 = 0
    pi = plane_through(Point3(2, 0, 0), Point3(0, 3, 0), Point3(0, 0, 4))
    assert pi.canonical().coords == (6, 4, 3, -12)


def test_three_ideal_points_span_the_plane_at_infinity():
    assert plane_through(Point3(1, 0, 0, 0), Point3(0, 1, 0, 0), Point3(1, 1, 1, 0)) == plane_at_infinity()


def test_point_on_three_coordinate_planes_shifted():
    # x = 1, y = 2, z = 3 meet at (1, 2, 3)
    X = point_on_planes(Plane(1, 0, 0, -1), Plane(0, 1, 0, -2), Plane(0, 0, 1, -3))
    assert X == Point3(1, 2, 3)
    assert X.dehomogenize() == (1, 2, 3)


def test_two_parallel_distinct_planes_and_a_third_meet_in_an_ideal_point():
    # z = 0 and z = 1 are parallel; with x + y = 0 they meet in the direction common to all
    # three: orthogonal to (0,0,1) and to (1,1,0), i.e. (1, -1, 0), at infinity
    X = point_on_planes(Plane(0, 0, 1, 0), Plane(0, 0, 1, -1), Plane(1, 1, 0, 0))
    assert X.is_ideal
    assert X == Point3(1, -1, 0, 0)


def test_coplanar_by_determinant():
    o, ex, ey = Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)
    assert coplanar(o, ex, ey, Point3(7, -3, 0))
    assert coplanar(o, ex, ey, Point3(1, 1, 0, 0))  # a direction in the plane z = 0
    assert not coplanar(o, ex, ey, Point3(0, 0, 1))
    assert not coplanar(o, ex, ey, Point3(0, 0, 1, 0))


def test_duality_of_point_and_plane():
    assert dual(Point3(1, 2, 3)) == Plane(1, 2, 3, 1)
    assert dual(Plane(0, 0, 0, 1)) == Point3(0, 0, 0, 1)
    assert Point3(1, 2, 3, 4).dual().dual() == Point3(1, 2, 3, 4)


def test_triple_cross_is_the_signed_minor_vector():
    # n·x = det[x; u; v; w]; for u, v, w = e2, e3, e4 it is det[x; e2; e3; e4] = x1
    assert triple_cross((0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1)) == (1, 0, 0, 0)
    with pytest.raises(DimensionError):
        triple_cross((1, 0, 0), (0, 1, 0), (0, 0, 1))


def test_symbolic_plane_through_three_points_holds_identically():
    c = symbols("p1:4 q1:4 r1:4")
    p, q, r = Point3(*c[0:3]), Point3(*c[3:6]), Point3(*c[6:9])
    pi = plane_through(p, q, r)
    assert pi.contains(p) and pi.contains(q) and pi.contains(r)


def test_repr_round_trips_and_latex():
    a = symbols("a")
    for obj in (Point3(1, Rational(-1, 2), 3), Plane(a, 0, 1, -(a**2))):
        again = eval(repr(obj), {"Point3": Point3, "Plane": Plane, "S": S, "a": a})
        assert again.coords == obj.coords
    assert Point3(1, 2, 3)._repr_latex_() == r"$\begin{bmatrix}1 \\ 2 \\ 3 \\ 1\end{bmatrix}$"
    assert Plane(1, 0, 0, -1)._repr_latex_() == r"$\begin{bmatrix}1 & 0 & 0 & -1\end{bmatrix}$"


# -- named errors -----------------------------------------------------------------------------------------


def test_wrong_number_of_coordinates():
    with pytest.raises(DimensionError, match="3 inhomogeneous"):
        Point3(1, 2)
    with pytest.raises(DimensionError):
        Plane(1, 2, 3)
    with pytest.raises(ZeroVectorError):
        Plane(0, 0, 0, 0)
    with pytest.raises(ZeroVectorError):
        Point3(0, 0, 0, 0)


def test_collinear_points_raise():
    with pytest.raises(CollinearPointsError, match="one line"):
        plane_through(Point3(0, 0, 0), Point3(1, 2, 3), Point3(-2, -4, -6))
    # a point, another point and the direction of their line
    with pytest.raises(CollinearPointsError):
        plane_through(Point3(1, 1, 1), Point3(2, 3, 4), Point3(1, 2, 3, 0))


def test_coincident_points_raise_collinear_points_error_naming_the_pair():
    with pytest.raises(CollinearPointsError, match="points 1 and 3 coincide"):
        plane_through(Point3(1, 2, 3), Point3(0, 0, 1), Point3(2, 4, 6, 2))


def test_pencil_of_three_planes_through_one_line_raises():
    # x = 0, y = 0 and x + y = 0 all contain the z-axis
    with pytest.raises(DependentPlanesError, match="share a line"):
        point_on_planes(Plane(1, 0, 0, 0), Plane(0, 1, 0, 0), Plane(1, 1, 0, 0))
    # three parallel planes share a line at infinity
    with pytest.raises(DependentPlanesError):
        point_on_planes(Plane(0, 0, 1, 0), Plane(0, 0, 1, -1), Plane(0, 0, 1, -2))


def test_repeated_plane_raises():
    with pytest.raises(DependentPlanesError, match="planes 1 and 2 are the same plane"):
        point_on_planes(Plane(1, 2, 3, 4), Plane(2, 4, 6, 8), Plane(0, 0, 1, 0))


def test_wrong_object_types_raise():
    with pytest.raises(ObjectTypeError, match="point_on_planes"):
        plane_through(Plane(1, 0, 0, 0), Point3(0, 1, 0), Point3(0, 0, 1))
    with pytest.raises(ObjectTypeError):
        point_on_planes(Point3(1, 0, 0), Plane(0, 1, 0, 0), Plane(0, 0, 1, 0))
    with pytest.raises(ObjectTypeError):
        incident(Point3(1, 0, 0), Point3(1, 0, 0))
    with pytest.raises(ObjectTypeError):
        dual("plane")


# -- properties -------------------------------------------------------------------------------------------


@FAST
@given(points3(), points3(), points3(), nonzero_rational, nonzero_rational, nonzero_rational)
def test_plane_through_contains_the_points_and_ignores_their_scale(p, q, r, a, b, c):
    assume(rank(p, q, r) == 3)
    pi = plane_through(p, q, r)
    assert pi.contains(p) and pi.contains(q) and pi.contains(r)
    assert plane_through(scaled(p, a), scaled(q, b), scaled(r, c)) == pi
    assert plane_through(q, r, p) == pi


@FAST
@given(points3(), points3(), points3())
def test_plane_through_raises_exactly_when_rank_below_three(p, q, r):
    if rank(p, q, r) == 3:
        plane_through(p, q, r)
    else:
        with pytest.raises(CollinearPointsError):
            plane_through(p, q, r)


@FAST
@given(planes(), planes(), planes())
def test_point_on_planes_lies_on_all_three(a, b, c):
    if rank(a, b, c) < 3:
        with pytest.raises(DependentPlanesError):
            point_on_planes(a, b, c)
        return
    X = point_on_planes(a, b, c)
    assert X.lies_on(a) and X.lies_on(b) and X.lies_on(c)


@FAST
@given(points3(), points3(), points3())
def test_plane_through_points_is_point_on_dual_planes(p, q, r):
    assume(rank(p, q, r) == 3)
    assert plane_through(p, q, r).dual() == point_on_planes(p.dual(), q.dual(), r.dual())


@FAST
@given(points3(), points3(), points3(), points3())
def test_coplanar_iff_fourth_point_on_plane(p, q, r, s):
    assume(rank(p, q, r) == 3)
    assert coplanar(p, q, r, s) == plane_through(p, q, r).contains(s)


@FAST
@given(st.tuples(small, small, small).filter(lambda n: n != (0, 0, 0)), small, small, points3())
def test_parallel_distinct_planes_meet_a_third_plane_at_infinity(n, d1, d2, third):
    assume(d1 != d2)
    a, b = Plane(*n, d1), Plane(*n, d2)
    c = third.dual()
    assume(rank(a, b, c) == 3)
    X = point_on_planes(a, b, c)
    assert X.is_ideal and plane_at_infinity().contains(X)
    # the direction is orthogonal to the common normal n
    assert sum(x * k for x, k in zip(X.coords[:3], n, strict=True)) == 0


@FAST
@given(points3(), planes())
def test_duality_preserves_incidence(X, pi):
    assert X.lies_on(pi) == pi.dual().lies_on(X.dual())
