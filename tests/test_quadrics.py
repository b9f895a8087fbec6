"""Quadrics of P³: worked values derived by hand, properties of spheres and tangent planes, named errors."""

from __future__ import annotations

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers
from sympy import Rational, S, symbols

from pgsym.errors import (
    DegenerateConicError,
    DimensionError,
    InvalidCoordinatesError,
    ObjectTypeError,
    ZeroVectorError,
)
from pgsym.quadrics import NotOnQuadricError, Quadric
from pgsym.space import Plane, Point3

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
