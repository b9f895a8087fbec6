"""Parallels, midpoints and real points: exact values derived by hand, and their affine properties."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import integers, lines, nonzero_rational, points, points3

from pgsym import Line, Line3, Plane, Point, Point3, Transformation, join
from pgsym.affine import is_parallel, midpoint, parallel_line
from pgsym.errors import CoincidentPointsError, IdealPointError, ObjectTypeError
from pgsym.projective_plane import line_at_infinity

# -- values derived by hand -------------------------------------------------------------------------


def test_parallel_line_in_the_plane() -> None:
    # 2x − y + 3 = 0 has normal (2, −1); through (1, 4): 2·1 − 4 + c = 0 ⇒ c = 2, i.e. (2, −1, 2)
    assert parallel_line(Line(2, -1, 3), Point(1, 4)) == Line(2, -1, 2)
    # through the homogeneous (2, 8, 2) — the same point — the same line
    assert parallel_line(Line(2, -1, 3), Point(2, 8, 2)) == Line(2, -1, 2)


def test_parallel_plane_and_line_of_space() -> None:
    # x + y + z = 0 through (1, 2, 3): c = −(1 + 2 + 3) = −6
    assert parallel_line(Plane(1, 1, 1, 0), Point3(1, 2, 3)) == Plane(1, 1, 1, -6)
    # the z-axis moved through (5, 0, 0): the points (5, 0, 0) and (5, 0, 1)
    z_axis = Line3.join(Point3(0, 0, 0), Point3(0, 0, 1))
    assert parallel_line(z_axis, Point3(5, 0, 0)) == Line3.join(Point3(5, 0, 0), Point3(5, 0, 1))


def test_is_parallel() -> None:
    assert is_parallel(Line(1, 2, 3), Line(-2, -4, 7))        # normals (1, 2) ∥ (−2, −4)
    assert not is_parallel(Line(1, 2, 3), Line(2, 1, 0))      # 1·1 − 2·2 = −3 ≠ 0
    assert is_parallel(Line(1, 2, 3), Line(1, 2, 3))          # a line is parallel to itself
    a = Line3.join(Point3(0, 0, 0), Point3(1, 2, 3))
    b = Line3.join(Point3(1, 1, 1), Point3(3, 5, 7))          # direction (2, 4, 6) ∥ (1, 2, 3)
    c = Line3.join(Point3(1, 1, 1), Point3(3, 5, 8))          # direction (2, 4, 7)
    assert is_parallel(a, b) and not is_parallel(a, c)
    assert is_parallel(Plane(0, 0, 1, 0), Plane(0, 0, 3, 9)) and not is_parallel(Plane(0, 0, 1, 0), Plane(0, 1, 1, 0))


def test_midpoint_of_any_representatives() -> None:
    # (1, 2) and (3, 0): ((1 + 3)/2, (2 + 0)/2) = (2, 1), whatever the scales
    assert midpoint(Point(1, 2), Point(3, 0)) == Point(2, 1)
    assert midpoint(Point(-3, -6, -3), Point(6, 0, 2)) == Point(2, 1)
    # space: (0, 0, 0) and (2, 4, 6)/2 = (1, 2, 3) → (1/2, 1, 3/2)
    assert midpoint(Point3(0, 0, 0, 5), Point3(2, 4, 6, 2)).dehomogenize() == (
        sympy.Rational(1, 2), 1, sympy.Rational(3, 2))


def test_ideal_and_wrong_input_give_named_errors() -> None:
    with pytest.raises(IdealPointError):
        midpoint(Point(1, 0, 0), Point(1, 1))
    with pytest.raises(IdealPointError):
        parallel_line(line_at_infinity(), Point(1, 1))
    with pytest.raises(IdealPointError):
        is_parallel(line_at_infinity(), Line(1, 0, 0))
    with pytest.raises(CoincidentPointsError):                # through the line's own direction: no unique line
        parallel_line(Line(0, 1, 0), Point(1, 0, 0))
    with pytest.raises(ObjectTypeError):
        is_parallel(Line(1, 0, 0), Plane(1, 0, 0, 0))
    with pytest.raises(ObjectTypeError):
        midpoint(Point(1, 1), Point3(1, 1, 1))


def test_real_points() -> None:
    i = sympy.I
    assert Point(i, 2 * i, 3 * i).is_real                   # i·(1, 2, 3)
    assert (1 + i) * 0 == 0 and Point(1 + i, 2 + 2 * i, 1 + i).is_real
    assert not Point(1, i, 0).is_real and not Point(1, -i, 0).is_real
    assert Point3(1, 2, 3).is_real and not Point3(1, i, 0, 0).is_real


# -- properties -------------------------------------------------------------------------------------

finite_points = points(allow_ideal=False)


@given(finite_points, finite_points, nonzero_rational, nonzero_rational)
@settings(max_examples=60, deadline=None)
def test_midpoint_is_the_average_for_any_scales(a: Point, b: Point, s: Fraction, t: Fraction) -> None:
    scaled_a = Point(*(sympy.Rational(s.numerator, s.denominator) * c for c in a.coords))
    scaled_b = Point(*(sympy.Rational(t.numerator, t.denominator) * c for c in b.coords))
    expected = tuple((x + y) / 2 for x, y in zip(a.dehomogenize(), b.dehomogenize(), strict=True))
    assert midpoint(scaled_a, scaled_b).dehomogenize() == expected


@given(lines(), finite_points)
@settings(max_examples=60, deadline=None)
def test_parallel_line_passes_through_the_point_and_is_parallel(l: Line, p: Point) -> None:
    if l.is_at_infinity:
        return
    m = parallel_line(l, p)
    assert m.contains(p) and is_parallel(l, m)


@given(lines(), lines(), st.tuples(*[integers(5)] * 6))
@settings(max_examples=60, deadline=None)
def test_affinities_keep_parallelism(l: Line, m: Line, entries: tuple[int, ...]) -> None:
    a11, a12, a21, a22, tx, ty = entries
    if a11 * a22 - a12 * a21 == 0 or l.is_at_infinity or m.is_at_infinity:
        return
    A = Transformation([[a11, a12, tx], [a21, a22, ty], [0, 0, 1]])
    assert is_parallel(A(l), A(m)) == is_parallel(l, m)


def test_a_projectivity_does_not_keep_parallelism() -> None:
    # x = 0 and x = 1 meet at the ideal point (0, 1, 0); H sends it to the finite point (0, 1, 1),
    # where the images meet, so they are no longer parallel
    H = Transformation([[1, 0, 0], [0, 1, 0], [0, 1, 1]])
    l, m = Line(1, 0, 0), Line(1, 0, -1)
    assert is_parallel(l, m) and not is_parallel(H(l), H(m))


@given(points3(allow_ideal=False), points3(allow_ideal=False))
@settings(max_examples=40, deadline=None)
def test_midpoint_in_space_lies_on_the_join(a: Point3, b: Point3) -> None:
    mid = midpoint(a, b)
    if a == b:
        assert mid == a
    else:
        assert Line3.join(a, b).contains(mid)


def test_midpoint_is_the_harmonic_conjugate_of_the_ideal_point() -> None:
    # on y = 0: A = (0, 0), B = (4, 0), ideal point (1, 0, 0); the midpoint (2, 0) is the harmonic
    # conjugate: cross-ratio (A, B; M, ∞) = (AM/BM) / (A∞/B∞) = (2/−2) / 1 = −1
    from pgsym.projective_line import Point1, cross_ratio
    A, B, M = Point(0, 0), Point(4, 0), midpoint(Point(0, 0), Point(4, 0))
    assert join(A, B) == Line(0, 1, 0)
    x = [p.coords[0] for p in (A, B, M)] + [1]
    w = [p.coords[2] for p in (A, B, M)] + [0]
    assert cross_ratio(*(Point1(xi, wi) for xi, wi in zip(x, w, strict=True))) == -1
