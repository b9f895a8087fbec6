"""The exact counterparts of numeric constructions: the meet and the common plane of two lines of space, the
harmonic conjugate of collinear points of P²; values derived by hand, agreement with the float kernels on
random integer input, and the convention of ``distance`` between complex points."""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from hypothesis import assume, given, settings
from strategies import homogeneous_vectors, integers, points3

from pgsym import numeric
from pgsym.errors import CoincidentLinesError, ObjectTypeError, SkewLinesError, UndefinedCrossRatioError
from pgsym.invariants import collinear_cross_ratio
from pgsym.metric import distance, squared_distance
from pgsym.plucker import Line3, meet_lines, plane_through_lines
from pgsym.projective_line import Point1, harmonic_conjugate
from pgsym.projective_plane import Point, collinear
from pgsym.space import Plane, Point3, coplanar, plane_through


def _proportional(exact, floats) -> bool:
    u = np.array([float(x) for x in exact])
    v = np.asarray(floats, dtype=float)
    return np.linalg.matrix_rank(np.stack([u, v]), tol=1e-9 * max(np.abs(u).max(), np.abs(v).max())) == 1


# -- the meet of two lines of space and their common plane, by hand ------------------------------------------

X_AXIS = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))


def test_meet_and_plane_of_two_lines_by_hand():
    # x = 2 in the plane z = 0 crosses the x-axis at (2, 0, 0); both lie in z = 0
    line = Line3.join(Point3(2, 0, 0), Point3(2, 1, 0))
    assert meet_lines(X_AXIS, line) == Point3(2, 0, 0)
    assert plane_through_lines(X_AXIS, line) == Plane(0, 0, 1, 0)
    # the line through (0, 3, 0) and (1, 5, 1): at (x, 3 + 2x, x) it meets y = 0 only where x = −3/2, z = −3/2,
    # off the x-axis (z ≠ 0): skew
    with pytest.raises(SkewLinesError, match="skew"):
        meet_lines(X_AXIS, Line3.join(Point3(0, 3, 0), Point3(1, 5, 1)))
    # y = 5 in z = 0 is parallel to the x-axis: they meet at the ideal point (1, 0, 0, 0), in the plane z = 0
    parallel = Line3.join(Point3(0, 5, 0), Point3(1, 5, 0))
    assert meet_lines(X_AXIS, parallel) == Point3(1, 0, 0, 0)
    assert plane_through_lines(parallel, X_AXIS) == Plane(0, 0, 1, 0)
    with pytest.raises(CoincidentLinesError, match="same line"):
        plane_through_lines(X_AXIS, Line3.join(Point3(5, 0, 0), Point3(-1, 0, 0)))
    with pytest.raises(ObjectTypeError, match="Line3"):
        meet_lines(X_AXIS, Plane(0, 0, 1, 0))


@settings(max_examples=40, deadline=None)
@given(points3(), points3(), points3())
def test_two_lines_through_a_point_meet_there_and_agree_with_the_float_kernels(a, b, c):
    # the lines AB and AC meet at A and span the plane ABC (when A, B, C are not collinear)
    assume(a != b and a != c and b != c)
    l, m = Line3.join(a, b), Line3.join(a, c)
    assume(l != m)
    x, pi = meet_lines(l, m), plane_through_lines(l, m)
    assert x == a and pi == plane_through(a, b, c)
    floats = [np.array([float(v) for v in line.coords]) for line in (l, m)]
    assert _proportional(x.coords, numeric.meet_lines(*floats))
    assert _proportional(pi.coords, numeric.plane_through_lines(*floats))


@settings(max_examples=40, deadline=None)
@given(points3(), points3(), points3(), points3())
def test_skew_lines_have_no_meet_in_either_arithmetic(a, b, c, d):
    # four points not in one plane span two skew lines AB and CD
    assume(not coplanar(a, b, c, d))
    l, m = Line3.join(a, b), Line3.join(c, d)
    for build in (meet_lines, plane_through_lines):
        with pytest.raises(SkewLinesError):
            build(l, m)
    floats = [np.array([float(v) for v in line.coords]) for line in (l, m)]
    assert not numeric.meet_lines(*floats).any()      # the numeric default for degenerate pairs: zeros


# -- the harmonic conjugate of collinear points of P² -----------------------------------------------------------

def test_harmonic_conjugate_of_collinear_points_by_hand():
    # on y = x: A = 0, B = 4, C = 1 in the coordinate x; (0, 4; 1, d) = (0 − 1)(4 − d)/((0 − d)(4 − 1)) = −1
    # gives 4 − d = −3d, d = −2
    assert harmonic_conjugate(Point(0, 0), Point(4, 4), Point(1, 1)) == Point(-2, -2)
    # the midpoint of A = (−1, 0), B = (1, 0) pairs with the ideal point of their line
    assert harmonic_conjugate(Point(-1, 0), Point(1, 0), Point(0, 0)) == Point(1, 0, 0)
    # C ideal: the conjugate of ∞ is the midpoint (3, 3) of (2, 1) and (4, 5)
    assert harmonic_conjugate(Point(2, 1), Point(4, 5), Point(1, 2, 0)) == Point(3, 3)
    with pytest.raises(UndefinedCrossRatioError, match="not collinear"):
        harmonic_conjugate(Point(0, 0), Point(1, 0), Point(0, 1))
    with pytest.raises(UndefinedCrossRatioError, match="A = C"):
        harmonic_conjugate(Point(0, 0), Point(1, 0), Point(0, 0))
    with pytest.raises(ObjectTypeError, match="collinear points of P²"):
        harmonic_conjugate(Point(0, 0), Point1(1), Point(2, 0))


@settings(max_examples=60, deadline=None)
@given(homogeneous_vectors(3), homogeneous_vectors(3), integers(6), integers(6))
def test_harmonic_conjugate_of_collinear_points_is_harmonic_and_agrees_with_the_float_kernel(a, b, s, t):
    A, B = Point(*a), Point(*b)
    assume(A != B and s != 0 and t != 0)
    C = Point(*(s * x + t * y for x, y in zip(a, b, strict=True)))
    D = harmonic_conjugate(A, B, C)
    assert collinear(A, B, D)
    assert collinear_cross_ratio(A.coords, B.coords, C.coords, D.coords) == -1
    assert harmonic_conjugate(A, B, D) == C     # an involution
    # in the coordinates of the line, C = s A + t B has the conjugate s A − t B
    assert D == Point(*(s * x - t * y for x, y in zip(a, b, strict=True)))
    assert _proportional(D.coords, numeric.harmonic_conjugate(np.array(a, float), np.array(b, float),
                                                               np.array(C.coords, float)))


# -- the distance between complex points ------------------------------------------------------------------------

def test_distance_of_complex_points_is_the_root_of_the_bilinear_squared_distance():
    i = sympy.I
    # (0, 0) and (3i, 0): (3i)² = −9, and the principal root of −9 is 3i (a Hermitian norm would give 3)
    assert squared_distance(Point(0, 0), Point(3 * i, 0)) == -9
    assert distance(Point(0, 0), Point(3 * i, 0)) == 3 * i
    # a point on an isotropic line through the origin, (1, i): 1 + i² = 0, at distance 0 (the absolute's lines of
    # zero length); a Hermitian norm would give √2
    assert distance(Point(0, 0), Point(1, i)) == 0
    # real points: the usual distance, 3-4-5
    assert distance(Point(0, 0), Point(3, 4)) == 5
