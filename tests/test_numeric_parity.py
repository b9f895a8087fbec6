"""The numeric kernels of space, quadrics, harmonic conjugates and complex points against the exact core.

Random exact objects come from ``tests/strategies.py``; they are converted with
:func:`pgsym.numeric.to_array`, run through the kernel, and compared with the exact answer. Small integers
and their products are exact in float64, so the comparisons are exact where the kernel computes the same
polynomial as the core (``intersect_plane``, ``plane_through_point``, ``polar``, ``form_value``, the P¹
harmonic conjugate) and up to scale elsewhere (a rank test of the two vectors, exact for small integers).
Where the exact core raises a named error, the kernel raises it too (``degenerate="raise"``) or masks the row.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import pgsym.numeric as pn
from pgsym.conics import Conic, circular_points
from pgsym.errors import (
    CoincidentLinesError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DegenerateConicError,
    DependentPlanesError,
    NonNumericError,
    NotOnConicError,
    NotOnQuadricError,
    UndefinedCrossRatioError,
)
from pgsym.plucker import Line3
from pgsym.projective_line import Point1, cross_ratio, harmonic_conjugate
from pgsym.projective_plane import join
from pgsym.quadrics import Quadric
from pgsym.space import Point3, plane_through
from tests.strategies import forms_through_a_point, lines3, planes, point1s, points, points3, symmetric_forms

SETTINGS = settings(max_examples=40, deadline=None)


def floats(obj) -> np.ndarray:
    return pn.to_array(obj)


def proportional(u, v) -> bool:
    """u ∼ v: both nonzero and of rank one together (exact for the small integers of these tests)."""
    u, v = np.asarray(u, dtype=complex), np.asarray(v, dtype=complex)
    return bool(np.abs(u).max() > 0 and np.abs(v).max() > 0 and np.linalg.matrix_rank(np.stack([u, v])) == 1)


# -- lines of space ------------------------------------------------------------------------------------


@SETTINGS
@given(st.lists(st.tuples(lines3(), planes()), min_size=1, max_size=5))
def test_intersect_plane_is_the_exact_one(rows):
    L = np.array([floats(l) for l, _ in rows])
    P = np.array([floats(p) for _, p in rows])
    values, ok = pn.intersect_plane(L, P, degenerate="mask")
    for i, (l, p) in enumerate(rows):
        try:
            expected = floats(l.intersect_plane(p))
        except DependentPlanesError:  # the line lies in the plane
            assert not ok[i] and np.isnan(values[i]).all()
            with pytest.raises(DependentPlanesError):
                pn.intersect_plane(L[i], P[i])
            continue
        assert ok[i] and np.array_equal(values[i], expected)  # the same polynomial: the same numbers


@SETTINGS
@given(st.lists(st.tuples(lines3(), points3()), min_size=1, max_size=5))
def test_plane_through_point_is_the_exact_one(rows):
    L = np.array([floats(l) for l, _ in rows])
    X = np.array([floats(x) for _, x in rows])
    values, ok = pn.plane_through_point(L, X, degenerate="mask")
    for i, (l, x) in enumerate(rows):
        try:
            expected = floats(l.plane_through_point(x))
        except CollinearPointsError:  # the point lies on the line
            assert not ok[i]
            with pytest.raises(CollinearPointsError):
                pn.plane_through_point(L[i], X[i])
            continue
        assert ok[i] and np.array_equal(values[i], expected)


@st.composite
def meeting_lines(draw):
    """Two distinct lines through a common point X: X ∨ A and X ∨ B with X, A, B not collinear."""
    X, A, B = draw(points3()), draw(points3()), draw(points3())
    assume(len({X, A, B}) == 3)
    try:
        plane = plane_through(X, A, B)
    except CollinearPointsError:
        assume(False)
    return Line3.join(X, A), Line3.join(X, B), X, plane


@SETTINGS
@given(st.lists(meeting_lines(), min_size=1, max_size=4))
def test_meet_and_plane_of_meeting_lines_are_the_exact_ones(rows):
    L = np.array([floats(r[0]) for r in rows])
    M = np.array([floats(r[1]) for r in rows])
    points, planes_ = pn.meet_lines(L, M), pn.plane_through_lines(L, M)
    for i, (l, m, X, plane) in enumerate(rows):
        # the exact references: the common point X (by construction) and plane_through(X, A, B)
        assert proportional(points[i], floats(X))
        assert proportional(planes_[i], floats(plane))
        # and the exact core's own construction agrees: X = L π for a plane π through M not containing L
        through_m = next(p for p in m.planes() if not l.lies_in(p))
        assert l.intersect_plane(through_m) == X


@SETTINGS
@given(lines3(), lines3())
def test_skew_and_equal_lines_have_no_meet(l, m):
    reciprocal = sum(a * b for a, b in zip(l.coords, reversed(m.coords), strict=True))  # (L|M), exactly
    L, M = floats(l), floats(m)
    if reciprocal != 0:  # skew lines
        assert not pn.meet_lines(L, M).any() and not pn.plane_through_lines(L, M).any()
        with pytest.raises(DegenerateConfigurationError, match="skew"):
            pn.meet_lines(L, M, degenerate="raise")
    _, ok = pn.meet_lines(L, L, degenerate="mask")
    assert not ok
    with pytest.raises(CoincidentLinesError):
        pn.plane_through_lines(L, 3 * L, degenerate="raise")


def test_meet_of_lines_by_hand():
    # The x-axis O ∨ (1, 0, 0) and the line (2, 0, 0) ∨ (2, 1, 0) meet in (2, 0, 0) and span z = 0.
    x_axis = Line3.join(Point3(0, 0, 0), Point3(1, 0, 0))
    other = Line3.join(Point3(2, 0, 0), Point3(2, 1, 0))
    X = pn.meet_lines(floats(x_axis), floats(other), axis=-1)
    assert proportional(X, [2, 0, 0, 1])
    assert proportional(pn.plane_through_lines(floats(x_axis), floats(other)), [0, 0, 1, 0])
    # the component-major layout gives the same
    both = np.stack([floats(x_axis), floats(x_axis)]).T
    assert np.array_equal(pn.meet_lines(both, np.stack([floats(other)] * 2).T, axis=0)[:, 0], X)


# -- conics and quadrics -------------------------------------------------------------------------------


@SETTINGS
@given(symmetric_forms(3), st.lists(points(), min_size=1, max_size=5))
def test_conic_value_and_polar_are_the_exact_ones(M, pts):
    C = Conic(M)
    X = np.array([floats(p) for p in pts])
    Cf = np.array(M.tolist(), dtype=float)
    assert np.array_equal(pn.form_value(Cf, X), [float(C.value(p)) for p in pts])
    assert np.array_equal(pn.polar(Cf, X), [floats(C.polar(p)) for p in pts])  # non-degenerate: C x ≠ 0
    # one conic per point (a stack of forms) gives the same numbers
    assert np.array_equal(pn.polar(np.stack([Cf] * len(pts)), X), pn.polar(Cf, X))


@SETTINGS
@given(symmetric_forms(4), st.lists(points3(), min_size=1, max_size=5))
def test_quadric_value_and_polar_are_the_exact_ones(M, pts):
    Q = Quadric(M)
    X = np.array([floats(p) for p in pts])
    Qf = np.array(M.tolist(), dtype=float)
    values = [float((sympy.Matrix(p.coords).T * M * sympy.Matrix(p.coords))[0]) for p in pts]  # Xᵀ Q X by hand
    assert np.array_equal(pn.form_value(Qf, X), values)
    assert np.array_equal(pn.polar(Qf, X), [floats(Q.polar(p)) for p in pts])
    # the component-major layout: forms (4, 4, N), points (4, N)
    assert np.array_equal(pn.polar(np.moveaxis(np.stack([Qf] * len(pts)), 0, -1), X.T, axis=0).T, pn.polar(Qf, X))


@SETTINGS
@given(st.lists(forms_through_a_point(4), min_size=1, max_size=4))
def test_tangent_planes_of_a_batch_of_quadrics(rows):
    Q = np.array([np.array(M.tolist(), dtype=float) for M, _ in rows])
    X = np.array([x for _, x in rows], dtype=float)
    values, ok = pn.tangent_plane(Q, X, degenerate="mask")
    for i, (M, x) in enumerate(rows):
        quadric = Quadric(M)
        try:
            expected = floats(quadric.tangent_plane(Point3(*x)))
        except DegenerateConicError:  # x is a vertex (Q x = 0)
            assert not ok[i]
            continue
        assert ok[i] and np.array_equal(values[i], expected)


def test_tangent_planes_of_one_sphere_at_many_points():
    # the sphere x² + y² + z² = 25 at its Pythagorean points (3, 4, 0), (0, 3, 4), (5, 0, 0): π = (x, y, z, −25)
    pts = np.array([[3.0, 4, 0, 1], [0, 3, 4, 1], [5, 0, 0, 1]])
    sphere = np.array(Quadric.sphere((0, 0, 0), 5).matrix.tolist(), dtype=float)
    planes_ = pn.tangent_plane(sphere, pts)
    for plane, p in zip(planes_, pts, strict=True):
        assert proportional(plane, [p[0], p[1], p[2], -25])
    with pytest.raises(NotOnQuadricError):
        pn.tangent_plane(sphere, [[3.0, 3, 0, 1]])  # 9 + 9 ≠ 25
    cone = np.diag([1.0, 1, -1, 0])  # x² + y² = z²: its vertex is the origin
    with pytest.raises(DegenerateConicError):
        pn.tangent_plane(cone, [0.0, 0, 0, 1])
    with pytest.raises(NotOnConicError):
        pn.tangent_at(np.diag([1.0, 1, -25]), [4.0, 4, 1])
    # float data on the sphere, to rounding: cos and sin of many angles
    t = np.linspace(0, 6, 1001)
    on = np.c_[5 * np.cos(t), 5 * np.sin(t), np.zeros_like(t), np.ones_like(t)]
    assert np.allclose(pn.tangent_plane(sphere, on)[:, :2], on[:, :2])
    # in any units: the same points times 1e200 or 1e-200 (|x|² over- or underflows; the test is scale-free)
    for s in (1e200, 1e-200):
        assert np.allclose(pn.tangent_plane(sphere, on * s) / s, pn.tangent_plane(sphere, on))
        with pytest.raises(NotOnQuadricError):
            pn.tangent_plane(sphere, np.array([[3.0, 3, 0, 1]]) * s)


# -- harmonic conjugates -------------------------------------------------------------------------------


@SETTINGS
@given(st.lists(st.tuples(point1s(), point1s(), point1s()), min_size=1, max_size=6))
def test_harmonic_conjugate_on_the_line_is_the_exact_one(rows):
    A, B, C = (np.array([floats(r[i]) for r in rows]) for i in range(3))
    values, ok = pn.harmonic_conjugate(A, B, C, degenerate="mask")
    for i, (a, b, c) in enumerate(rows):
        try:
            expected = floats(harmonic_conjugate(a, b, c))
        except UndefinedCrossRatioError:  # two of the points coincide
            assert not ok[i]
            continue
        assert ok[i] and np.array_equal(values[i], expected)  # the same formula [A C] B + [B C] A


@SETTINGS
@given(points(), points(), st.integers(-5, 5), st.integers(-5, 5))
def test_harmonic_conjugate_of_collinear_points_of_the_plane(a, b, alpha, beta):
    assume(a != b and alpha != 0 and beta != 0)
    # C = α A + β B on the line A ∨ B; its conjugate is D = α A − β B: on the line, with the coordinates
    # (α : β) and (α : −β) of C and D relative to (A, B), the cross-ratio (∞, 0; α/β, −α/β) ... computed below
    av, bv = np.array(floats(a)), np.array(floats(b))
    c = alpha * av + beta * bv
    d = pn.harmonic_conjugate(av, bv, c)
    assert proportional(d, alpha * av - beta * bv)
    # (A, B; C, D) = −1 exactly, in the coordinates of the pencil: A = (1, 0), B = (0, 1), C = (α, β), D = (α, −β)
    assert cross_ratio(Point1(1, 0), Point1(0, 1), Point1(alpha, beta), Point1(alpha, -beta)) == -1
    # three points not on one line have none: n = A × B as a point has det[A B n] = n · n > 0
    n = np.cross(av, bv)
    with pytest.raises(UndefinedCrossRatioError):
        pn.harmonic_conjugate(av, bv, c + n)
    with pytest.raises(UndefinedCrossRatioError):
        pn.harmonic_conjugate(av, bv, 2 * av)  # C = A


# -- complex points ------------------------------------------------------------------------------------


def complex_array(obj) -> np.ndarray:
    return np.array([complex(sympy.N(c)) for c in obj.coords])


def test_the_circular_points_span_the_line_at_infinity():
    I_, J_ = circular_points()
    I, J = complex_array(I_), complex_array(J_)
    # I × J = (i·0 − 0·(−i), 0·1 − 1·0, 1·(−i) − i·1) = (0, 0, −2i): the line at infinity
    assert np.array_equal(pn.join(I, J), [0, 0, -2j])
    assert proportional(pn.join(I, J), complex_array(join(I_, J_)))
    assert pn.incident([I, J], [0.0, 0, 1]).all()


@SETTINGS
@given(points(allow_ideal=False))
def test_isotropic_lines_through_a_point_meet_there(p):
    # P ∨ I and P ∨ J are the isotropic lines through P; they meet in P again (exact: the same joins)
    I_, J_ = circular_points()
    P = floats(p)
    li, lj = pn.join(P, complex_array(I_)), pn.join(P, complex_array(J_))
    assert proportional(li, complex_array(join(p, I_))) and proportional(lj, complex_array(join(p, J_)))
    assert proportional(pn.meet(li, lj), P)
    assert pn.incident(complex_array(I_), li) and not pn.incident(complex_array(J_), li)


def test_complex_input_is_refused_by_name_where_it_makes_no_sense():
    I = np.array([1, 1j, 0])
    for f, args in [(pn.cos_angle, (I, I)), (pn.polar, (np.eye(3), I)), (pn.point_distance, (I, I)),
                    (pn.plucker_join, (np.r_[I, 1], np.r_[I, 1])), (pn.transform_points, (np.eye(3), I))]:
        with pytest.raises(NonNumericError, match="complex"):
            f(*args)
    assert pn.harmonic_conjugate([1, 1j], [1, -1j], [1, 0]).dtype == complex  # a complex kernel
    with pytest.raises(NonNumericError):
        pn.join(I, I, out=np.empty(3))  # a real out for a complex result
    with pytest.raises(NonNumericError):
        pn.join([[1, 2], [3]], I)  # ragged input is no array, complex kernel or not


def test_empty_batches_and_the_component_major_layout():
    lines, planes_, points_ = np.zeros((0, 6)), np.zeros((0, 4)), np.zeros((0, 4))
    for f, args in [(pn.intersect_plane, (lines, planes_)), (pn.plane_through_point, (lines, points_)),
                    (pn.meet_lines, (lines, lines)), (pn.plane_through_lines, (lines, lines)),
                    (pn.polar, (np.eye(4), points_)), (pn.tangent_plane, (np.eye(4), points_)),
                    (pn.form_value, (np.eye(4), points_)),
                    (pn.harmonic_conjugate, (np.zeros((0, 2)), np.zeros((0, 2)), np.zeros((0, 2))))]:
        assert np.asarray(f(*args)).shape[0] == 0
    # (k, N) in, (k, N) out, the same numbers as the (N, k) layout: the x-axis against x = 3 and the plane y = 1
    L = np.array([[0.0, 0, -1, 0, 0, 0]] * 2)
    P = np.array([[1.0, 0, 0, -3], [0, 1, 0, -1]])
    assert np.array_equal(pn.intersect_plane(L.T, P.T, axis=0).T, pn.intersect_plane(L, P))
    out = np.empty((4, 2))
    assert pn.plane_through_point(L.T, np.array([[0.0, 1, 0, 1]] * 2).T, axis=0, out=out) is out
