"""The numeric kernels against the exact core ("derive once"): same integer data, same numbers.

Small integers and their products are exact in float64, so every kernel is compared with the
exact pgsym result *exactly* (cross ratios, which divide, to 1e-12 relative). Degenerate inputs
are included: where the exact core raises a named error, the kernel returns the zero vector
(or flags the row).
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import homogeneous_vectors, integers, invertible_matrices

import pgsym.numeric as pn
from pgsym.errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DependentPlanesError,
    DimensionError,
    IdealPointError,
    NonNumericError,
    SingularTransformationError,
    UndefinedCrossRatioError,
)
from pgsym.numeric import OptionError

# -- strategies: batches of small integer vectors, about a third of them ideal ------------------------


def batches(k: int, n_arrays: int, allow_ideal: bool = True) -> st.SearchStrategy:
    """``n_arrays`` lists of the same length of nonzero integer k-vectors; rows may repeat (degenerate)."""
    row = st.tuples(*[homogeneous_vectors(k, allow_ideal, integers(9)) for _ in range(n_arrays)])
    repeated = row.map(lambda r: (r[0], *([r[0]] * (len(r) - 1))))  # a fully degenerate row
    return st.lists(st.one_of(row, row, row, repeated), min_size=1, max_size=6).map(
        lambda rows: [np.array([r[i] for r in rows], dtype=float) for i in range(n_arrays)]
    )


def exact_or_zero(make, args: tuple, k: int, errors: tuple[type[Exception], ...]) -> np.ndarray:
    """The coordinates of ``make(*args)`` as floats, or zeros where the exact core refuses the input."""
    try:
        return np.array([float(c) for c in make(*args).coords])
    except errors:
        return np.zeros(k)


# -- P²: join and meet are cross products --------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@given(batches(3, 2))
def test_join_and_meet_equal_the_exact_cross_products(data):
    from pgsym.projective_plane import Line, Point, join, meet

    p, q = data
    lines, points = pn.join(p, q), pn.meet(p, q)
    for i in range(len(p)):
        a, b = p[i].astype(int).tolist(), q[i].astype(int).tolist()
        assert np.array_equal(lines[i], exact_or_zero(join, (Point(*a), Point(*b)), 3, (CoincidentPointsError,)))
        assert np.array_equal(points[i], exact_or_zero(meet, (Line(*a), Line(*b)), 3, (CoincidentLinesError,)))
        assert pn.is_zero_vector(lines[i]) == (Point(*a) == Point(*b))


@settings(max_examples=30, deadline=None)
@given(batches(3, 2))
def test_incidence_with_zero_tolerance_is_the_exact_incidence(data):
    from pgsym.projective_plane import Line, Point, incident

    x, l = data
    got = pn.incident(x, l, rtol=0)
    assert got.tolist() == [incident(Point(*a), Line(*b)) for a, b in zip(x.tolist(), l.tolist(), strict=True)]
    assert np.array_equal(pn.incident(x, l), got)  # integer data: the default tolerance decides the same
    # the join of two points is incident with both
    assert pn.incident(x, pn.join(x, l)).all()


def test_worked_examples_in_the_plane():
    # y = x is (1, -1, 0) up to scale: (0,0,1) × (1,1,1) = (0·1 − 1·1, 1·1 − 0·1, 0·1 − 0·1) = (−1, 1, 0)
    assert pn.join([0.0, 0, 1], [1.0, 1, 1]).tolist() == [-1, 1, 0]
    # the parallel lines x − y = 0 and x − y + 3 = 0: (1,−1,0) × (1,−1,3) = (−3 − 0, 0 − 3, −1 + 1) = (−3, −3, 0)
    assert pn.meet([1.0, -1, 0], [1.0, -1, 3]).tolist() == [-3, -3, 0]


# -- layouts, broadcasting, out= and block boundaries ----------------------------------------------------


def test_layouts_broadcasting_and_out_give_the_same_numbers():
    rng = np.random.default_rng(1)
    n = 2 * pn.CHUNK + 7  # several blocks and a short last one
    a, b = rng.integers(-50, 50, (n, 3)).astype(float), rng.integers(-50, 50, (n, 3)).astype(float)
    ref = np.cross(a, b)
    assert np.array_equal(pn.meet(a, b), ref)
    assert np.array_equal(pn.meet(a.T.copy(), b.T.copy(), axis=0), ref.T)  # component-major (3, N)
    out = np.empty((3, n))
    assert pn.meet(a.T, b.T, axis=0, out=out) is out and np.array_equal(out, ref.T)
    assert np.array_equal(pn.meet(a, b[0]), np.cross(a, b[0]))  # one line against many
    batch = pn.meet(a[:12].reshape(3, 4, 3), b[:4])  # (3, 4, 3) with (4, 3)
    assert np.array_equal(batch, np.cross(a[:12].reshape(3, 4, 3), b[:4]))
    strided = a[:24].reshape(4, 6, 3)[:, ::2]  # a view that cannot be flattened without a copy
    assert np.array_equal(pn.meet(strided, b[0]), np.cross(strided, b[0]))
    inplace = a[:100].copy()
    pn.meet(inplace, b[:100], out=inplace)  # the output may overwrite an input
    assert np.array_equal(inplace, ref[:100])


def test_bad_arrays_raise_named_errors():
    with pytest.raises(DimensionError, match="3 homogeneous coordinates"):
        pn.join([1.0, 2], [3.0, 4])
    with pytest.raises(DimensionError, match="out has shape"):
        pn.join([[1.0, 2, 1]], [[3.0, 4, 1]], out=np.empty((2, 3)))
    with pytest.raises(NonNumericError):
        pn.join(["a", "b", "c"], [1.0, 2, 3])
    with pytest.raises(NonNumericError):
        pn.join([1.0, 2, 3], [1.0, 2, 4], out=np.empty(3, dtype=np.float32))
    with pytest.raises(DimensionError):
        pn.incident([1.0, 2, 3], [1.0, 2, 3, 4])


# -- homogenise and dehomogenise -------------------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(batches(3, 1))
def test_dehomogenize_agrees_with_the_exact_points_and_flags_ideal_ones(data):
    from pgsym.projective_plane import Point

    (x,) = data
    coords, finite = pn.dehomogenize(x, ideal="mask")
    for row, c, ok in zip(x.astype(int).tolist(), coords, finite, strict=True):
        point = Point(*row)
        assert ok == (not point.is_ideal)
        if ok:
            assert np.allclose(c, [float(v) for v in point.dehomogenize()], rtol=1e-15, atol=0)
        else:
            assert np.isnan(c).all()
            with pytest.raises(IdealPointError):
                point.dehomogenize()
    if finite.all():
        assert np.array_equal(pn.dehomogenize(x), coords)
    else:
        with pytest.raises(IdealPointError, match="ideal"):
            pn.dehomogenize(x)


def test_homogenize_round_trip_tolerance_and_overflow():
    pts = np.array([[1.5, -2.0], [0.0, 7.0]])
    h = pn.homogenize(pts)
    assert h.tolist() == [[1.5, -2.0, 1.0], [0.0, 7.0, 1.0]]
    assert np.array_equal(pn.dehomogenize(3 * h), pts)
    assert pn.homogenize(pts.T, axis=0).shape == (3, 2)
    assert np.array_equal(pn.dehomogenize(pn.homogenize(pts.T, axis=0), axis=0), pts.T)
    # tolerance: w = 1e-17 is ideal only when asked; a quotient that overflows is flagged, never inf
    near = np.array([[1.0, 1.0, 1e-17], [1e300, 1.0, 1e-300]])
    coords, finite = pn.dehomogenize(near, ideal="mask")
    assert finite.tolist() == [True, False] and np.isfinite(coords[0]).all() and np.isnan(coords[1]).all()
    assert pn.dehomogenize(near, ideal="mask", rtol=1e-12)[1].tolist() == [False, False]
    assert pn.dehomogenize(near[:1], ideal="mask", fill=0.0, rtol=1e-12)[0].tolist() == [[0.0, 0.0]]
    with pytest.raises(OptionError, match="ideal='skip'"):
        pn.dehomogenize(near, ideal="skip")
    with pytest.raises(DimensionError):
        pn.is_ideal([1.0])


# -- P³: planes through three points, points on three planes ------------------------------------------------


@settings(max_examples=25, deadline=None)
@given(batches(4, 3))
def test_plane_through_and_point_on_planes_equal_the_exact_minors(data):
    from pgsym.space import Plane, Point3, plane_through, point_on_planes

    p, q, r = data
    planes, plane_ok = pn.plane_through(p, q, r, degenerate="mask")
    points, point_ok = pn.point_on_planes(p, q, r, degenerate="mask")
    minors = pn.triple_cross(p, q, r)
    # the policy: a row is masked exactly where every minor is zero, and is the minors elsewhere
    assert np.array_equal(plane_ok, minors.any(axis=-1)) and np.array_equal(point_ok, plane_ok)
    assert np.array_equal(planes[plane_ok], minors[plane_ok]) and np.isnan(planes[~plane_ok]).all()
    for i in range(len(p)):
        rows = [v[i].astype(int).tolist() for v in (p, q, r)]
        want = exact_or_zero(plane_through, tuple(Point3(*x) for x in rows), 4, (CollinearPointsError,))
        assert plane_ok[i] == want.any()  # masked exactly where the exact core raises
        assert not plane_ok[i] or np.array_equal(planes[i], want)
        want = exact_or_zero(point_on_planes, tuple(Plane(*x) for x in rows), 4, (DependentPlanesError,))
        assert point_ok[i] == want.any()
        assert not point_ok[i] or np.array_equal(points[i], want)
    # the plane contains the three points: det[X; p; q; r] = 0 for X = p, q, r
    assert pn.incident(p, minors, rtol=0).all() and pn.incident(r, minors, rtol=0).all()
    if not plane_ok.all():  # the default raises the named errors instead
        with pytest.raises(CollinearPointsError, match="collinear"):
            pn.plane_through(p, q, r)
        with pytest.raises(DependentPlanesError, match="one line"):
            pn.point_on_planes(p, q, r)


def test_worked_example_in_space():
    # the plane through e1, e2, e3 (finite points (1,0,0), (0,1,0), (0,0,1)) is x + y + z − 1 = 0:
    # n0 = det[[0,0,1],[1,0,1],[0,1,1]] = 1, n1 = −det[[1,0,1],[0,0,1],[0,1,1]] = 1,
    # n2 = det[[1,0,1],[0,1,1],[0,0,1]] = 1, n3 = −det(I) = −1
    assert pn.plane_through([1.0, 0, 0, 1], [0.0, 1, 0, 1], [0.0, 0, 1, 1]).tolist() == [1, 1, 1, -1]


# -- Plücker coordinates --------------------------------------------------------------------------------------


@settings(max_examples=25, deadline=None)
@given(batches(4, 2))
def test_plucker_coordinates_equal_line3(data):
    from pgsym.plucker import Line3
    from pgsym.space import Plane, Point3

    a, b = data
    joins, meets = pn.plucker_join(a, b), pn.plucker_meet(a, b)
    assert np.array_equal(pn.klein_form(joins), np.zeros(len(a)))
    for i in range(len(a)):
        x, y = a[i].astype(int).tolist(), b[i].astype(int).tolist()
        want = exact_or_zero(Line3.join, (Point3(*x), Point3(*y)), 6, (CoincidentPointsError,))
        assert np.array_equal(joins[i], want)
        want = exact_or_zero(Line3.meet, (Plane(*x), Plane(*y)), 6, (DependentPlanesError,))
        assert np.array_equal(meets[i], want)


def test_worked_plucker_example():
    # A = (0,0,0,1), B = (1,2,3,0): l_ij = A_i B_j − B_i A_j, so l14 = 0·0 − 1·1 = −1, l42 = 1·2 − 0 = 2,
    # l34 = 0·0 − 3·1 = −3 and the rest vanish; direction (−l14, l42, −l34) = (1, 2, 3)
    assert pn.plucker_join([0.0, 0, 0, 1], [1.0, 2, 3, 0]).tolist() == [0, 0, -1, 0, 2, -3]
    with pytest.raises(DimensionError):
        pn.klein_form([1.0, 2, 3])


# -- P¹: brackets and cross-ratios ------------------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@given(batches(2, 4))
def test_cross_ratio_equals_the_exact_cross_ratio(data):
    from pgsym.projective_line import Point1, cross_ratio

    values, defined = pn.cross_ratio(*data, undefined="mask")
    for i in range(len(data[0])):
        pts = [Point1(*v[i].astype(int).tolist()) for v in data]
        try:
            exact = Fraction(str(cross_ratio(*pts)))
        except UndefinedCrossRatioError:
            assert not defined[i] and np.isnan(values[i])
            continue
        assert defined[i] and values[i] == pytest.approx(float(exact), rel=1e-12, abs=1e-300)


def test_cross_ratio_by_hand_and_its_errors():
    # (0, 1; 2, 3) = (0 − 2)(1 − 3) / ((0 − 3)(1 − 2)) = 4/3; with D = ∞: (−1, 1; 0, ∞) = [AC]/[BC] = −1/1
    assert pn.cross_ratio([0.0, 1], [1.0, 1], [2.0, 1], [3.0, 1]) == pytest.approx(4 / 3, rel=1e-15)
    assert pn.cross_ratio([-1.0, 1], [1.0, 1], [0.0, 1], [1.0, 0]) == -1
    assert pn.bracket([5.0, 1], [2.0, 1]) == 3  # 5·1 − 1·2
    with pytest.raises(UndefinedCrossRatioError, match="zero denominator"):
        pn.cross_ratio([0.0, 1], [1.0, 1], [1.0, 1], [2.0, 1])  # B = C
    with pytest.raises(OptionError):
        pn.cross_ratio([0.0, 1], [1.0, 1], [2.0, 1], [3.0, 1], undefined="inf")
    # a tolerance flags nearly coincident B and C
    near = pn.cross_ratio([0.0, 1], [1.0, 1], [1.0 + 1e-14, 1], [2.0, 1], undefined="mask", rtol=1e-12)
    assert not near[1]
    # component-major layout
    cols = np.array([[0.0, 0.0], [1.0, 1.0]])  # two copies of the point 0, one per column
    assert pn.cross_ratio(cols, [[1.0], [1.0]], [[2.0], [1.0]], [[3.0], [1.0]], axis=0) == pytest.approx(
        [4 / 3, 4 / 3], rel=1e-15
    )


# -- transformations ----------------------------------------------------------------------------------------------


@settings(max_examples=20, deadline=None)
@given(invertible_matrices(3, 4), batches(3, 1), st.lists(st.integers(-5, 5), min_size=6, max_size=6))
def test_plane_transformations_equal_the_exact_action(H, data, conic):
    from pgsym.conics import Conic, DualConic
    from pgsym.projective_plane import Line, Point
    from pgsym.transformations import Transformation

    T = Transformation(H)
    (x,) = data
    points, lines = pn.transform_points(H, x), pn.transform_lines(H, x)
    for i, row in enumerate(x.astype(int).tolist()):
        assert np.array_equal(points[i], [float(c) for c in T(Point(*row)).coords])
        assert np.array_equal(lines[i], [float(c) for c in T(Line(*row)).coords])
    a, b, c, d, e, f = conic
    C = np.array([[2 * a, b, d], [b, 2 * c, e], [d, e, 2 * f]], dtype=float)
    if np.any(C):
        want = np.array(T(Conic(C.astype(int).tolist())).matrix.tolist(), dtype=float)
        assert np.array_equal(pn.transform_conics(H, C), want)
        want = np.array(T(DualConic(C.astype(int).tolist())).matrix.tolist(), dtype=float)
        assert np.array_equal(pn.transform_dual_conics(H, C), want)
    # incidence is preserved: image points lie on image lines
    lines0 = pn.join(x, x[::-1])
    assert np.array_equal(
        pn.incident(pn.transform_points(H, x), pn.transform_lines(H, lines0), rtol=0), pn.incident(x, lines0, rtol=0)
    )


@settings(max_examples=10, deadline=None)
@given(invertible_matrices(4, 4), batches(4, 1))
def test_space_transformations_equal_the_exact_action(H, data):
    from pgsym.quadrics import Quadric
    from pgsym.space import Plane, Point3
    from pgsym.transformations import Transformation

    T = Transformation(H)
    (x,) = data
    points, planes = pn.transform_points(H, x), pn.transform_planes(H, x)
    for i, row in enumerate(x.astype(int).tolist()):
        assert np.array_equal(points[i], [float(c) for c in T(Point3(*row)).coords])
        assert np.array_equal(planes[i], [float(c) for c in T(Plane(*row)).coords])
    Q = np.diag([1.0, 2.0, -1.0, -3.0])
    want = np.array(T(Quadric(Q.astype(int).tolist())).matrix.tolist(), dtype=float)
    assert np.array_equal(pn.transform_quadrics(H, Q), want)


@pytest.mark.parametrize("k", [2, 3, 4])
def test_adjugate_equals_the_exact_adjugate(k):
    from pgsym.transformations import adjugate

    rng = np.random.default_rng(k)
    H = rng.integers(-6, 7, (5, k, k)).astype(float)
    got = pn.adjugate(H)
    for i in range(5):
        assert np.array_equal(got[i], np.array(adjugate(H[i].astype(int).tolist()).tolist(), dtype=float))


def test_transformation_layouts_stacks_and_errors():
    rng = np.random.default_rng(3)
    H = rng.integers(-5, 6, (3, 3)).astype(float) + 10 * np.eye(3)
    x = rng.integers(-9, 10, (pn.CHUNK + 5, 3)).astype(float)
    ref = x @ H.T
    assert np.array_equal(pn.transform_points(H, x), ref)
    assert np.array_equal(pn.transform_points(H, x.T.copy(), axis=0), ref.T)
    out = np.empty_like(x)
    assert pn.transform_points(H, x, out=out) is out and np.array_equal(out, ref)
    stack = np.stack([H, 2 * H])
    assert np.array_equal(pn.transform_points(stack, x[:2]), np.stack([H @ x[0], 2 * H @ x[1]]))
    # worked example: the shear (x, y) ↦ (x + 2y, y) maps y = x, i.e. (−1, 1, 0), to the line through
    # (0, 0) and (3, 1): adj(H)ᵀ (−1, 1, 0) with adj(H) = [[1, −2, 0], [0, 1, 0], [0, 0, 1]] gives (−1, 3, 0)
    assert pn.transform_lines([[1.0, 2, 0], [0, 1, 0], [0, 0, 1]], [-1.0, 1, 0]).tolist() == [-1, 3, 0]
    singular = [[1.0, 2, 3], [2, 4, 6], [0, 0, 1]]
    for f in (pn.transform_points, pn.transform_lines, pn.transform_conics, pn.transform_dual_conics):
        with pytest.raises(SingularTransformationError, match="singular"):
            f(singular, np.eye(3))
    with pytest.raises(DimensionError):
        pn.transform_points(np.eye(3), [1.0, 2])
    with pytest.raises(DimensionError):
        pn.transform_planes(np.eye(3), [1.0, 2, 3])
    with pytest.raises(DimensionError):
        pn.transform_conics(np.eye(3), np.eye(4))
    with pytest.raises(DimensionError):
        pn.adjugate(np.eye(5))
    assert issubclass(SingularTransformationError, DegenerateConfigurationError)
