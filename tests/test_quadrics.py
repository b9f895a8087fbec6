"""Quadrics of P³: worked values derived by hand, properties of spheres and tangent planes, named errors."""

from __future__ import annotations

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers, invertible_matrices
from strategies import planes as plane_strategy
from sympy import Rational, S, symbols

from pgsym.errors import (
    CoincidentPointsError,
    DegenerateConicError,
    DimensionError,
    InvalidCoordinatesError,
    LineOnQuadricError,
    NotASphereError,
    ObjectTypeError,
    ZeroVectorError,
)
from pgsym.plucker import Line3
from pgsym.quadrics import DualQuadric, NotOnQuadricError, Quadric
from pgsym.space import Plane, Point3
from pgsym.transformations import Transformation

small = integers(6)
FAST = settings(max_examples=40, deadline=None)
SIGNS = st.tuples(*[st.sampled_from([1, -1])] * 3)

# Pythagorean quadruples a² + b² + c² = d²: the point centre + (a, b, c) lies on the sphere of radius d.
QUADRUPLES = [(1, 2, 2, 3), (2, 3, 6, 7), (1, 4, 8, 9), (4, 4, 7, 9), (2, 6, 9, 11), (0, 3, 4, 5), (0, 0, 1, 1)]


def test_sphere_matrix_by_hand():
    # (x-1)² + (y+2)² + z² - 4 = x² + y² + z² - 2x + 4y + 1 = 0:
    # off-diagonal last column = half the linear coefficients (-1, 2, 0), constant 1 + 4 + 0 - 4 = 1
    Q = Quadric.sphere((1, -2, 0), 2)
    assert Q.matrix.tolist() == [[1, 0, 0, -1], [0, 1, 0, 2], [0, 0, 1, 0], [-1, 2, 0, 1]]
    x, y, z = symbols("x y z")
    assert Q.equation() == x**2 + y**2 + z**2 - 2 * x + 4 * y + 1
    assert Q.rank == 4 and not Q.is_degenerate


def test_unit_sphere_tangent_plane_and_polar():
    Q = Quadric.sphere((0, 0, 0), 1)
    # at (1, 0, 0): Q X = (1, 0, 0, -1), the plane x = 1
    assert Q.tangent_plane(Point3(1, 0, 0)) == Plane(1, 0, 0, -1)
    # the polar of (0, 0, 3) is (0, 0, 3, -1): the plane z = 1/3, which joins the tangency points
    assert Q.polar(Point3(0, 0, 3)) == Plane(0, 0, 3, -1)
    # the polar of the centre is (0, 0, 0, -1): the plane at infinity
    assert Q.polar(Point3(0, 0, 0)) == Plane(0, 0, 0, 1)


def test_cone_is_degenerate_and_its_vertex_has_no_polar():
    cone = Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 0]])  # x² + y² = z²
    assert cone.rank == 3 and cone.is_degenerate
    assert cone.contains(Point3(0, 0, 0)) and cone.contains(Point3(3, 4, 5)) and cone.contains(Point3(1, 0, 1, 0))
    # at (3, 4, 5): Q X = (3, 4, -5, 0), the plane 3x + 4y - 5z = 0 through the vertex
    assert cone.tangent_plane(Point3(3, 4, 5)) == Plane(3, 4, -5, 0)
    with pytest.raises(DegenerateConicError, match="vertex"):
        cone.tangent_plane(Point3(0, 0, 0))


def test_plane_pair_rank_two():
    # x² - 1 = 0: the planes x = 1 and x = -1
    pair = Quadric([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, -1]])
    assert pair.rank == 2 and pair.contains(Point3(1, 5, -7)) and pair.contains(Point3(-1, 0, 0))


def test_equality_up_to_scale_and_hash():
    Q = Quadric.sphere((0, 0, 0), 1)
    assert Q == Quadric([[-2, 0, 0, 0], [0, -2, 0, 0], [0, 0, -2, 0], [0, 0, 0, 2]])
    assert Q != Quadric.sphere((0, 0, 0), 2)
    assert hash(Q) == hash(Quadric(3 * Q.matrix))
    assert Q != "sphere"


def test_repr_round_trips_and_latex():
    a = symbols("a")
    for Q in (Quadric.sphere((Rational(1, 2), 0, -1), 3), Quadric.sphere((a, 0, 0), 1)):
        again = eval(repr(Q), {"Quadric": Quadric, "S": S, "a": a})
        assert again.matrix == Q.matrix
    latex = Quadric.sphere((0, 0, 0), 1)._repr_latex_()
    assert latex.startswith("$") and r"\begin{matrix}" in latex


def test_symbolic_sphere_contains_its_parametrised_points():
    r, u = symbols("r u")
    # (r(1-u²)/(1+u²), 2ru/(1+u²), 0) lies on the sphere of radius r about the origin
    X = Point3(r * (1 - u**2), 2 * r * u, 0, 1 + u**2)
    assert Quadric.sphere((0, 0, 0), r).contains(X)


# -- named errors -----------------------------------------------------------------------------------------


def test_asymmetric_matrix_raises():
    M = [[1, 2, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]
    with pytest.raises(InvalidCoordinatesError, match="symmetric"):
        Quadric(M)


def test_wrong_sizes_and_zero_matrix_raise():
    with pytest.raises(DimensionError):
        Quadric([[1, 0, 0], [0, 1, 0], [0, 0, -1]])
    with pytest.raises(DimensionError):
        Quadric(7)
    with pytest.raises(ZeroVectorError):
        Quadric([[0] * 4 for _ in range(4)])
    with pytest.raises(DimensionError):
        Quadric.sphere((0, 0), 1)
    with pytest.raises(InvalidCoordinatesError, match="radius"):
        Quadric.sphere((0, 0, 0), 0)


def test_tangent_plane_off_the_quadric_raises():
    with pytest.raises(NotOnQuadricError, match="polar"):
        Quadric.sphere((0, 0, 0), 1).tangent_plane(Point3(1, 1, 1))
    with pytest.raises(ObjectTypeError):
        Quadric.sphere((0, 0, 0), 1).contains(Plane(1, 0, 0, 0))


# -- properties -------------------------------------------------------------------------------------------


@FAST
@given(small, small, small, st.sampled_from(QUADRUPLES), st.permutations([0, 1, 2]), SIGNS)
def test_tangent_plane_of_a_sphere_is_orthogonal_to_the_radius(cx, cy, cz, quad, perm, signs):
    a, b, c, d = quad
    offset = [signs[k] * (a, b, c)[perm[k]] for k in range(3)]
    centre = (cx, cy, cz)
    X = Point3(*(centre[k] + offset[k] for k in range(3)))
    Q = Quadric.sphere(centre, d)
    assert Q.contains(X)
    pi = Q.tangent_plane(X)
    assert pi.contains(X)
    # the normal is parallel to the radius vector: their cross product vanishes
    n = pi.normal
    cross = (
        n[1] * offset[2] - n[2] * offset[1],
        n[2] * offset[0] - n[0] * offset[2],
        n[0] * offset[1] - n[1] * offset[0],
    )
    assert cross == (0, 0, 0)
    # and the centre is at distance d from it: |π·C| = d |n|
    value = sum(n[k] * centre[k] for k in range(3)) + pi.coords[3]
    assert value**2 == d**2 * sum(v**2 for v in n)


@FAST
@given(st.lists(small, min_size=10, max_size=10), st.lists(small, min_size=4, max_size=4), st.integers(1, 5))
def test_polar_is_linear_and_tangent_planes_touch(entries, x, k):
    i = iter(entries)
    M = [[0] * 4 for _ in range(4)]
    for r in range(4):
        for c in range(r, 4):
            M[r][c] = M[c][r] = next(i)
    assume(any(entries))
    assume(any(x))
    Q = Quadric(M)
    X = Point3(*x)
    if all(sum(M[r][c] * x[c] for c in range(4)) == 0 for r in range(4)):
        with pytest.raises(DegenerateConicError):
            Q.polar(X)
        return
    pi = Q.polar(X)
    assert Q.polar(Point3(*(k * v for v in x))) == pi
    # X lies on its own polar exactly when it lies on the quadric
    assert pi.contains(X) == Q.contains(X)
    assert Quadric([[k * v for v in row] for row in M]) == Q


# -- the shared symmetric-form base --------------------------------------------------------------------

entries = integers(4)


@st.composite
def symmetric4(draw):
    upper = {(i, j): draw(entries) for i in range(4) for j in range(i, 4)}
    assume(any(upper.values()))
    return [[upper[min(i, j), max(i, j)] for j in range(4)] for i in range(4)]


@settings(max_examples=40, deadline=None)
@given(symmetric4(), st.integers(-5, 5).filter(bool), st.fractions(min_value=-3, max_value=3).filter(bool))
def test_equal_quadrics_hash_alike_and_share_the_canonical_form(M, k, q):
    a, b = Quadric(M), Quadric([[k * q * e for e in row] for row in M])
    assert a == b and hash(a) == hash(b)
    assert a.canonical().matrix == b.canonical().matrix
    # the canonical form is a rescaling: the same quadric
    assert a.canonical() == a


def test_canonical_quadric_by_hand():
    # 2x² + 2y² + 2z² - 8w² (the sphere of radius 2, times 2): the coefficients (x², xy, y², xz, yz, z², xw, yw,
    # zw, w²) = (2, 0, 2, 0, 0, 2, 0, 0, 0, -8) have content 2, so the canonical form is x² + y² + z² - 4
    Q = Quadric([[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, -8]])
    assert Q.canonical().matrix.tolist() == Quadric.sphere((0, 0, 0), 2).matrix.tolist()
    assert Q.coefficients_of_form() == (2, 0, 2, 0, 0, 2, 0, 0, 0, -8)


def test_symbolic_quadric_substitutes_and_renders():
    a = symbols("a")
    Q = Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -a]])
    assert Q.subs(a, 4) == Quadric.sphere((0, 0, 0), 2)
    assert repr(Quadric.sphere((0, 0, 0), 1)) == "Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]])"
    assert Q.latex().startswith(r"\left[\begin{matrix}")
    with pytest.raises(DimensionError, match="4×4"):
        Quadric([[1, 0], [0, 1]])


# -- quadric ∩ line ----------------------------------------------------------------------------------


def _finite_set(points):
    return {p.dehomogenize() for p in points}


def test_sphere_meets_a_line_through_its_centre_by_hand():
    # centre (1, 2, 3), radius 3; the direction (1, 2, 2) has length √(1 + 4 + 4) = 3,
    # so the line meets the sphere at centre ± (1, 2, 2) = (2, 4, 5) and (0, 0, 1)
    S = Quadric.sphere((1, 2, 3), 3)
    assert _finite_set(S.intersections(Point3(1, 2, 3), Point3(2, 4, 5))) == {(2, 4, 5), (0, 0, 1)}
    line = Line3.join(Point3(1, 2, 3), Point3(1, 2, 2, 0))   # through the centre, direction (1, 2, 2)
    assert _finite_set(S.intersections(line)) == {(2, 4, 5), (0, 0, 1)}
    assert not S.is_tangent(line) and len(S.real_intersections(line)) == 2


def test_irrational_and_complex_intersections_by_hand():
    S = Quadric.sphere((0, 0, 0), 1)
    # t (1, 1, 0): 2t² = 1, t = ±1/√2 = ±√2/2
    r = sympy.sqrt(2) / 2
    assert _finite_set(S.intersections(Point3(0, 0, 0), Point3(1, 1, 0))) == {(r, r, 0), (-r, -r, 0)}
    # x = 2, z = 0: 4 + y² = 1, y = ±i√3 — two complex points, no real one
    pts = S.intersections(Point3(2, 0, 0), Point3(2, 1, 0))
    assert _finite_set(pts) == {(2, sympy.I * sympy.sqrt(3), 0), (2, -sympy.I * sympy.sqrt(3), 0)}
    assert all(S.contains(p) for p in pts)
    assert S.real_intersections(Point3(2, 0, 0), Point3(2, 1, 0)) == ()


def test_tangent_line_gives_one_point():
    S = Quadric.sphere((0, 0, 0), 1)
    # (1, t, 0): 1 + t² = 1 only at t = 0, a double root
    assert S.is_tangent(Point3(1, 0, 0), Point3(1, 5, 0))
    assert S.intersections(Point3(1, 0, 0), Point3(1, 5, 0)) == (Point3(1, 0, 0),)
    assert S.real_intersections(Point3(1, 0, 0), Point3(1, 5, 0)) == (Point3(1, 0, 0),)
    # a tangent line through two points that are not on the sphere: (1, 1, t) ... (x = 1, y = 0 line direction z)
    assert S.intersections(Line3.join(Point3(1, 0, 7), Point3(1, 0, -3))) == (Point3(1, 0, 0),)


def test_ruling_of_a_hyperboloid_lies_on_it():
    H = Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, -1]])  # x² + y² = z² + 1
    # (1, t, t): 1 + t² = t² + 1 for every t
    assert H.contains_line(Point3(1, 0, 0), Point3(1, 1, 1)) and H.is_tangent(Point3(1, 0, 0), Point3(1, 1, 1))
    with pytest.raises(LineOnQuadricError):
        H.intersections(Point3(1, 0, 0), Point3(1, 1, 1))
    with pytest.raises(CoincidentPointsError):
        H.intersections(Point3(1, 0, 0), Point3(2, 0, 0, 2))
    with pytest.raises(ObjectTypeError):
        H.intersections(Plane(1, 0, 0, 0))


@FAST
@given(st.sampled_from(QUADRUPLES), st.permutations([0, 1, 2]), SIGNS, SIGNS, small, small, small)
def test_line_through_two_sphere_points_meets_it_there(quad, perm, s1, s2, cx, cy, cz):
    # two points of the sphere: the centre plus (a, b, c), and plus a signed permutation of it
    a, b, c, r = quad
    e, f, g = (quad[i] for i in perm)
    P = Point3(cx + s1[0] * a, cy + s1[1] * b, cz + s1[2] * c)
    R = Point3(cx + s2[0] * e, cy + s2[1] * f, cz + s2[2] * g)
    assume(P != R)
    S = Quadric.sphere((cx, cy, cz), r)
    assert set(S.intersections(P, R)) == {P, R}
    assert set(S.intersections(Line3.join(P, R))) == {P, R}


# -- spheres, cones, cylinders, types -------------------------------------------------------------------
def test_sphere_centre_and_radius_by_hand():
    # 2x² + 2y² + 2z² − 4x + 8z + 2 = 0  ⇔  x² + y² + z² − 2x + 4z + 1 = 0  ⇔  (x − 1)² + y² + (z + 2)² = 1 + 4 − 1 = 4
    Q = Quadric([[2, 0, 0, -2], [0, 2, 0, 0], [0, 0, 2, 4], [-2, 0, 4, 2]])
    assert Q.sphere_center() == Point3(1, 0, -2) and Q.sphere_radius() == 2
    # x² + y² + z² = 3: radius √3
    assert Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -3]]).sphere_radius() == sympy.sqrt(3)


@pytest.mark.parametrize("matrix", [
    [[1, 0, 0, 0], [0, 2, 0, 0], [0, 0, 3, 0], [0, 0, 0, -1]],   # an ellipsoid
    [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],    # x² + y² + z² + 1 = 0: r² = −1, no real point
    [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]],    # r² = 0: a point-cone
    [[1, 1, 0, 0], [1, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]],   # an xy term
], ids=["ellipsoid", "imaginary", "point", "xy-term"])
def test_not_a_sphere_is_a_named_error(matrix):
    with pytest.raises(NotASphereError):
        Quadric(matrix).sphere_radius()


def test_cone_by_hand():
    # apex (1, 1, 1), base circle of radius 2 about (1, 1, 3): axis d = (0, 0, 2), h² = 4, cos² = 4/(4 + 4) = 1/2,
    # a half-angle of 45°: (z − 1)² = (x − 1)² + (y − 1)²
    K = Quadric.cone(Point3(1, 1, 1), (1, 1, 3), 2)
    x, y, z = symbols("x y z")
    expected = (x - 1) ** 2 + (y - 1) ** 2 - (z - 1) ** 2
    assert sympy.cancel(K.equation() / expected).is_number
    assert K.apex == Point3(1, 1, 1) and K.is_cone and not K.is_cylinder and K.rank == 3
    assert K.contains(Point3(3, 1, 3)) and K.kind_of_quadric() == "cone"


def test_cylinder_by_hand():
    # axis through (1, 0, 0) with direction u = (1, 1, 0), radius 1: |y|²·2 − (y·u)² = 2 for y = X − (1, 0, 0);
    # (1, 0, 1): y = (0, 0, 1), 2 − 0 = 2, on it; (2, 1, 0) is on the axis, not on it
    Z = Quadric.cylinder(Point3(1, 0, 0), (1, 1, 0), 1)
    assert Z.contains(Point3(1, 0, 1)) and not Z.contains(Point3(2, 1, 0))
    assert Z.apex == Point3(1, 1, 0, 0) and Z.is_cylinder and Z.kind_of_quadric() == "cylinder"
    with pytest.raises(InvalidCoordinatesError):
        Quadric.cylinder((0, 0, 0), (0, 0, 0), 1)
    with pytest.raises(InvalidCoordinatesError):
        Quadric.cone((0, 0, 0), (0, 0, 0), 1)


@FAST
@given(st.tuples(small, small, small), st.tuples(small, small, small), st.integers(1, 5))
def test_cone_and_cylinder_apex_is_the_null_vector(a, c, r):
    assume(a != c)
    K = Quadric.cone(a, c, r)
    assert K.apex == Point3(*a) and K.contains(Point3(*a)) and K.is_cone
    d = tuple(ci - ai for ai, ci in zip(a, c, strict=True))
    Z = Quadric.cylinder(a, d, r)
    assert Z.apex == Point3(*d, 0) and Z.is_cylinder


@pytest.mark.parametrize("matrix, kind", [
    ([[1, 0, 0, 0], [0, 2, 0, 0], [0, 0, 3, 0], [0, 0, 0, -1]], "oval quadric"),           # ellipsoid: (+ + + −)
    # the paraboloid z = x² + y², i.e. x² + y² − zw: eigenvalues 1, 1, ±1/2
    ([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, Rational(-1, 2)], [0, 0, Rational(-1, 2), 0]], "oval quadric"),
    ([[0, 1, 0, 0], [1, 0, 0, 0], [0, 0, 0, -1], [0, 0, -1, 0]], "ruled quadric"),        # zw = xy: eigenvalues ±1, ±1
    ([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], "imaginary quadric"),
    ([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]], "imaginary cone"),
    ([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 0, 0], [0, 0, 0, -1]], "cylinder"),             # x² − y² = 1
    ([[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], "plane pair"),
    ([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], "complex plane pair"),
    ([[1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]], "double plane"),
    ([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -sympy.sqrt(2)]], "oval quadric"),  # algebraic entry
])
def test_kind_of_quadric_by_signature(matrix, kind):
    assert Quadric(matrix).kind_of_quadric() == kind


def test_signature_of_symbolic_quadric_is_undecidable():
    from pgsym.errors import UndecidableError

    a = symbols("a")
    with pytest.raises(UndecidableError):
        Quadric([[a, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]).kind_of_quadric()


# -- splitting into planes ---------------------------------------------------------------------------------
def test_plane_pair_by_hand():
    # (x − y)(x + 2z − 1) = x² + 2xz − x − xy − 2yz + y: halves of the mixed coefficients off the diagonal
    h = Rational(1, 2)
    Q = Quadric([[1, -h, 1, -h], [-h, 0, -1, h], [1, -1, 0, 0], [-h, h, 0, 0]])
    assert set(Q.planes()) == {Plane(1, -1, 0, 0), Plane(1, 0, 2, -1)}
    # x² − 2y² = (x − √2 y)(x + √2 y)
    r = sympy.sqrt(2)
    assert set(Quadric([[1, 0, 0, 0], [0, -2, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]]).planes()) == {
        Plane(1, r, 0, 0), Plane(1, -r, 0, 0)}
    # (x + y + 1)²: the double plane, twice
    assert Quadric([[1, 1, 0, 1], [1, 1, 0, 1], [0, 0, 0, 0], [1, 1, 0, 1]]).planes() == (Plane(1, 1, 0, 1),) * 2
    with pytest.raises(DegenerateConicError):
        Quadric.cone((0, 0, 0), (0, 0, 1), 1).planes()


@FAST
@given(plane_strategy(5), plane_strategy(5))
def test_splitting_recovers_the_two_planes(p, q):
    P, Qv = sympy.Matrix(p.coords), sympy.Matrix(q.coords)
    Q = Quadric(P * Qv.T + Qv * P.T)
    assert set(Q.planes()) == {p, q}


# -- dual quadrics and the transformation rules ------------------------------------------------------------
def test_dual_of_a_sphere_by_hand():
    # Q = diag(1, 1, 1, −4): adj Q = det Q · Q⁻¹ = −4 · diag(1, 1, 1, −1/4) = diag(−4, −4, −4, 1)
    D = Quadric.sphere((0, 0, 0), 2).dual()
    assert isinstance(D, DualQuadric) and D.matrix == sympy.diag(-4, -4, -4, 1)
    # the tangent plane z = 2 is (0, 0, 1, −2): −4 + 4 = 0
    assert D.contains_plane(Plane(0, 0, 1, -2)) and not D.contains_plane(Plane(0, 0, 1, -1))
    assert D.dual() == Quadric.sphere((0, 0, 0), 2)
    with pytest.raises(DegenerateConicError):
        Quadric.cone((0, 0, 0), (0, 0, 1), 1).dual()
    with pytest.raises(DegenerateConicError):
        DualQuadric.absolute().dual()


def test_absolute_dual_quadric_agrees_with_metric():
    from pgsym.metric import absolute_dual_quadric

    assert DualQuadric.absolute().matrix == absolute_dual_quadric() and DualQuadric.absolute().rank == 3
    # a similarity (scale 2, translation) fixes Q*∞ up to scale; a shear does not
    sim = Transformation([[2, 0, 0, 1], [0, 2, 0, 5], [0, 0, 2, 0], [0, 0, 0, 1]])
    shear = Transformation([[1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
    assert sim(DualQuadric.absolute()) == DualQuadric.absolute()
    assert shear(DualQuadric.absolute()) != DualQuadric.absolute()


@FAST
@given(invertible_matrices(4, 3), st.sampled_from(QUADRUPLES), SIGNS, small, small, small)
def test_quadric_rules_point_and_dual_agree(m, quad, sgn, cx, cy, cz):
    H = Transformation(m)
    a, b, c, r = quad
    S = Quadric.sphere((cx, cy, cz), r)
    X = Point3(cx + sgn[0] * a, cy + sgn[1] * b, cz + sgn[2] * c)
    # Q' = H⁻ᵀ Q H⁻¹ contains H X when Q contains X
    Hi = sympy.Matrix(m).inv()
    image = H(S)
    assert image == Quadric(Hi.T * S.matrix * Hi) and image.contains(H(X))
    # the dual rule Q*' = H Q* Hᵀ gives the dual of the image
    assert H(S.dual()) == DualQuadric(sympy.Matrix(m) * S.dual().matrix * sympy.Matrix(m).T) == image.dual()
    # and the tangent plane at X maps to the tangent plane at H X
    assert H(S.tangent_plane(X)) == image.tangent_plane(H(X))
