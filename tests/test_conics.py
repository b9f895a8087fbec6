"""Conics, dual conics and the circular points: hand-derived values and properties on random exact conics."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers, invertible_matrices, lines, points, rationals
from sympy import I, Matrix, Rational, S, sqrt, symbols

from pgsym.conics import (
    Conic,
    DualConic,
    NotOnConicError,
    circular_points,
    conic_through,
    dual_conic_at_infinity,
)
from pgsym.errors import (
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DegenerateConicError,
    DimensionError,
    InvalidCoordinatesError,
    ObjectTypeError,
    ZeroVectorError,
)
from pgsym.homogeneous import is_zero
from pgsym.projective_plane import Line, Point, join

params = rationals(5, 4)
FAST = settings(max_examples=30, deadline=None)

D0 = Matrix([[1, 0, 0], [0, 1, 0], [0, 0, -1]])  # the unit circle x² + y² = w²


def qf(m: Matrix, v) -> sympy.Expr:
    """xᵀ M x computed directly, independent of the library."""
    x = Matrix(list(v))
    return sympy.expand((x.T * m * x)[0, 0])


def circle_point(t) -> list:
    """The rational parametrisation of the unit circle: (1 - t², 2t, 1 + t²); t = None gives (-1, 0, 1)."""
    if t is None:
        return [-1, 0, 1]
    t = Rational(t)
    return [1 - t**2, 2 * t, 1 + t**2]


@st.composite
def conics_with_points(draw, n: int = 5):
    """A random non-degenerate conic H(unit circle) and n distinct points on it.

    If y lies on the unit circle then x = H y satisfies xᵀ adj(H)ᵀ D adj(H) x = det(H)² yᵀ D y = 0,
    so the matrix adj(H)ᵀ D adj(H) is the image conic (computed here with SymPy, not pgsym).
    """
    H = Matrix(draw(invertible_matrices()))
    ts = draw(st.lists(st.one_of(st.none(), params), min_size=n, max_size=n, unique=True))
    pts = [Point(*(H * Matrix(circle_point(t)))) for t in ts]
    A = H.adjugate()
    return A.T * D0 * A, pts


def points_of(l: Line) -> list[Point]:
    """The points l × e_i (i = 1, 2, 3) that are not zero: at least two distinct points of l."""
    out = []
    for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
        y = Matrix(l.coords).cross(Matrix(e))
        if any(y):
            out.append(Point(*y))
    return out


# -- construction, equality, display ----------------------------------------------------------


def test_matrix_from_coefficients():
    # a x² + b xy + c y² + d x + e y + f  <->  [[a, b/2, d/2], [b/2, c, e/2], [d/2, e/2, f]]
    C = Conic.from_coefficients(1, 2, 3, 4, 5, 6)
    assert C.matrix == Matrix([[1, 1, 2], [1, 3, Rational(5, 2)], [2, Rational(5, 2), 6]])
    assert C.coefficients == (1, 2, 3, 4, 5, 6)
    x, y = symbols("x y")
    assert C.equation() == x**2 + 2 * x * y + 3 * y**2 + 4 * x + 5 * y + 6


def test_equality_up_to_scale_and_canonical_form():
    C = Conic.from_coefficients(1, 0, 1, 0, 0, -1)
    assert C == Conic([[-3, 0, 0], [0, -3, 0], [0, 0, 3]])
    assert C != Conic.from_coefficients(1, 0, 2, 0, 0, -1)
    assert Conic([[Fraction(1, 2), 0, 0], [0, Fraction(1, 2), 0], [0, 0, Fraction(-1, 2)]]).canonical().matrix == D0
    assert DualConic(-2 * D0).canonical() == DualConic(D0)


@given(st.lists(integers(6), min_size=6, max_size=6).filter(any))
def test_repr_round_trips(coeffs):
    C = Conic.from_coefficients(*coeffs)
    assert eval(repr(C), {"Conic": Conic, "S": S}) == C
    Cs = DualConic(C.matrix)
    assert eval(repr(Cs), {"DualConic": DualConic, "S": S}) == Cs


def test_latex_shows_matrix_and_equation():
    text = Conic.circle(0, 0, 1)._repr_latex_()
    assert text.startswith("$C = ") and "x^{2} + y^{2} - 1 = 0" in text
    assert r"C^{*}" in dual_conic_at_infinity()._repr_latex_()


def test_construction_errors():
    with pytest.raises(InvalidCoordinatesError, match="symmetric"):
        Conic([[1, 2, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ZeroVectorError):
        Conic.from_coefficients(0, 0, 0, 0, 0, 0)
    with pytest.raises(DimensionError, match="3×3"):
        Conic([[1, 0], [0, 1]])
    with pytest.raises(DimensionError):
        DualConic(7)


# -- the conic through five points ---------------------------------------------------------------


def test_conic_through_five_points_worked_examples():
    # (±1, 0), (0, ±1) and (3/5, 4/5): 9/25 + 16/25 = 1, the unit circle
    C = conic_through(Point(1, 0), Point(-1, 0), Point(0, 1), Point(0, -1), Point(3, 4, 5))
    assert C == Conic.circle(0, 0, 1)
    # (0,0), (±1,1), (±2,4) lie on y = x², i.e. x² - y = 0: coefficients (1, 0, 0, 0, -1, 0)
    P = conic_through(*(Point(x, x * x) for x in (0, 1, -1, 2, -2)))
    assert P.coefficients == (1, 0, 0, 0, -1, 0)


def test_three_collinear_points_give_the_line_pair():
    # (0,0), (1,0), (2,0) on y = 0 and (0,1), (1,1) on y = 1: the pair y (y - 1) = y² - y = 0
    C = conic_through(Point(0, 0), Point(1, 0), Point(2, 0), Point(0, 1), Point(1, 1))
    assert C == Conic.from_coefficients(0, 0, 1, 0, -1, 0)
    assert C.rank == 2 and C.is_degenerate


def test_conic_through_errors():
    with pytest.raises(CollinearPointsError, match="points 1, 2, 3, 4"):
        conic_through(Point(0, 0), Point(1, 0), Point(2, 0), Point(1, 0, 0), Point(0, 1))
    with pytest.raises(CoincidentPointsError, match="points 2 and 5"):
        conic_through(Point(0, 0), Point(1, 0), Point(0, 1), Point(1, 1), Point(2, 0, 2))
    with pytest.raises(DimensionError, match="five"):
        conic_through(Point(0, 0), Point(1, 0), Point(0, 1), Point(1, 1))
    with pytest.raises(ObjectTypeError):
        conic_through(Point(0, 0), Point(1, 0), Point(0, 1), Point(1, 1), Line(1, 1, 1))


@FAST
@given(conics_with_points())
def test_conic_through_five_points_on_a_random_conic(data):
    M, pts = data
    C = conic_through(*pts)
    assert all(C.contains(p) for p in pts)
    assert C == Conic(M)
    assert not C.is_degenerate and C.rank == 3


def test_conic_through_symbolic_fifth_point():
    # a fifth point (s, t) with the four points (±1, 0), (0, ±1): the conic family is
    # x² + y² - 1 + k xy = 0 (symmetric under x -> -x, y -> -y); through (s, t): k = (1 - s² - t²)/(s t)
    s, t = symbols("s t")
    C = conic_through(Point(1, 0), Point(-1, 0), Point(0, 1), Point(0, -1), Point(s, t))
    assert C == Conic.from_coefficients(s * t, 1 - s**2 - t**2, s * t, 0, 0, -s * t)


# -- tangents, polars, duality ------------------------------------------------------------------


def test_tangent_and_polar_worked_examples():
    # y = x², i.e. x² - y = 0, at (2, 4): C x = (2, -1/2, -2), the line 4x - y - 4 = 0 (slope 4 = 2·2)
    P = Conic.from_coefficients(1, 0, 0, 0, -1, 0)
    assert P.tangent_at(Point(2, 4)) == Line(4, -1, -4)
    # polar of (2, 0) for the unit circle: diag(1, 1, -1)(2, 0, 1) = (2, 0, -1), the line x = 1/2;
    # it meets the circle in (1/2, ±√3/2), whose tangents x/2 ± (√3/2) y = 1 both pass through (2, 0)
    C = Conic.circle(0, 0, 1)
    polar = C.polar(Point(2, 0))
    assert polar == Line(2, 0, -1)
    contact = C.intersections(polar)
    assert {tuple(p.dehomogenize()) for p in contact} == {(S(1) / 2, sqrt(3) / 2), (S(1) / 2, -sqrt(3) / 2)}
    assert all(C.tangent_at(p).contains(Point(2, 0)) for p in contact)
    assert C.pole(polar) == Point(2, 0)


def test_tangent_errors():
    C = Conic.circle(0, 0, 1)
    with pytest.raises(NotOnConicError, match="not on the conic"):
        C.tangent_at(Point(1, 1))
    assert issubclass(NotOnConicError, DegenerateConfigurationError)
    with pytest.raises(ObjectTypeError):
        C.tangent_at(Line(1, 0, 0))
    with pytest.raises(ObjectTypeError):
        C.pole(Point(1, 0))


@FAST
@given(conics_with_points(n=2))
def test_tangent_meets_the_conic_in_a_double_root(data):
    M, (p, other) = data
    C = Conic(M)
    l = C.tangent_at(p)
    assert l.contains(p)
    # parametrise the tangent as p + s q with a second point q of it; xᵀ M x must be c·s²:
    # the constant term vanishes (p on C) and so does the linear one (the root s = 0 is double)
    q = next(y for y in points_of(l) if not y == p)
    s = symbols("s")
    poly = sympy.Poly(qf(M, [pi + s * qi for pi, qi in zip(p, q, strict=True)]), s)
    assert poly.coeff_monomial(1) == 0 and poly.coeff_monomial(s) == 0
    assert C.is_tangent(l) and C.discriminant(l) == 0
    # the other point on a secant is not a double root
    secant = join(p, other)
    assert not C.is_tangent(secant)
    assert set(C.intersections(secant)) == {p, other} or all(C.contains(x) for x in C.intersections(secant))


@FAST
@given(conics_with_points(n=1), points(bound=6), lines(6))
def test_pole_polar_and_dual_conic(data, x, l):
    M, (p,) = data
    C = Conic(M)
    Cs = C.dual()
    # the tangent at a point of C is on the dual conic
    assert Cs.contains_line(C.tangent_at(p))
    # polar and pole are inverse to each other
    assert C.pole(C.polar(x)) == x
    # l is tangent (a double intersection point) exactly when lᵀ C* l = 0, and then its pole is on C
    assert Cs.contains_line(l) == C.is_tangent(l)
    assert C.contains(C.pole(l)) == Cs.contains_line(l)
    # lᵀ adj(M) l computed directly
    assert is_zero(Cs.value(l) - qf(M.adjugate(), l))
    assert Cs.dual() == C


@FAST
@given(conics_with_points(n=1), lines(6))
def test_intersections_lie_on_line_and_conic(data, l):
    M, _ = data
    C = Conic(M)
    for x in C.intersections(l):
        assert l.contains(x)
        assert is_zero(qf(M, x))


# -- degenerate conics ----------------------------------------------------------------------------


def pair(l: Line, m: Line) -> Conic:
    """The line pair l ∪ m: (lᵀx)(mᵀx) = 0 has the symmetric matrix (l mᵀ + m lᵀ)/2."""
    L, N = l.vector, m.vector
    return Conic((L * N.T + N * L.T) / 2)


def test_degenerate_conics_by_rank():
    # x y = 0: the two axes, meeting in the origin (0, 0, 1)
    axes = pair(Line(1, 0, 0), Line(0, 1, 0))
    assert axes.rank == 2 and axes.is_degenerate
    assert axes == Conic.from_coefficients(0, 1, 0, 0, 0, 0)
    # x² = 0: the y-axis counted twice
    double = pair(Line(1, 0, 0), Line(1, 0, 0))
    assert double.rank == 1 and double.is_degenerate
    assert Conic.circle(0, 0, 1).rank == 3
    # every line through the vertex of a line pair meets it in a double point
    assert axes.is_tangent(Line(1, 1, 0)) and not axes.is_tangent(Line(1, 1, -1))


@FAST
@given(lines(6), lines(6), points(bound=6))
def test_random_line_pairs(l, m, x):
    C = pair(l, m)
    assert C.rank == (1 if l == m else 2)
    # every point of l and of m is on C, and a point off both lines is not
    for line in (l, m):
        for y in points_of(line):
            assert C.contains(y)
    assert C.contains(x) == (l.contains(x) or m.contains(x))


def test_degenerate_conic_errors():
    axes = Conic.from_coefficients(0, 1, 0, 0, 0, 0)
    with pytest.raises(DegenerateConicError, match="singular point"):
        axes.polar(Point(0, 0))
    with pytest.raises(DegenerateConicError, match="pair of lines"):
        axes.dual()
    with pytest.raises(DegenerateConicError, match="double line"):
        Conic.from_coefficients(1, 0, 0, 0, 0, 0).pole(Line(1, 1, 1))
    with pytest.raises(DegenerateConicError, match="lies entirely"):
        axes.intersections(Line(1, 0, 0))
    with pytest.raises(DegenerateConicError, match="degenerate"):
        dual_conic_at_infinity().dual()


# -- circular points ---------------------------------------------------------------------------------


def test_circular_points_and_dual_conic_at_infinity():
    I_, J_ = circular_points()
    assert I_ == Point(1, I, 0) and J_ == Point(1, -I, 0) and I_.is_ideal
    # C*∞ = I Jᵀ + J Iᵀ = [[2, 0, 0], [0, 2, 0], [0, 0, 0]] ~ diag(1, 1, 0)
    assert DualConic(I_.vector * J_.vector.T + J_.vector * I_.vector.T) == dual_conic_at_infinity()
    assert dual_conic_at_infinity().rank == 2
    # an ellipse that is not a circle, x²/4 + y² = 1, misses them: 1/4 + i² = -3/4
    ellipse = Conic.from_coefficients(Rational(1, 4), 0, 1, 0, 0, -1)
    assert not ellipse.contains(I_)


@FAST
@given(params, params, params.filter(lambda r: r != 0), lines(6))
def test_every_circle_passes_through_the_circular_points(cx, cy, r, l):
    C = Conic.circle(cx, cy, r)
    assert all(C.contains(p) for p in circular_points())
    # a real line is on C*∞ only when l1² + l2² = 0, i.e. it is the line at infinity
    assert dual_conic_at_infinity().contains_line(l) == l.is_at_infinity


@FAST
@given(points(bound=6))
def test_lines_through_a_circular_point_are_on_the_dual_conic_at_infinity(x):
    I_, J_ = circular_points()
    assume(not x.is_ideal)
    for c in (I_, J_):
        assert dual_conic_at_infinity().contains_line(join(c, x))


def test_asymptote_is_the_tangent_at_an_ideal_point():
    # the hyperbola xy = 1 is x1 x2 - x3² = 0; on the line y = 0 (x2 = 0) the form is -x3², with the
    # double root x3 = 0: the asymptote touches the hyperbola at its ideal point (1, 0, 0)
    H = Conic.from_coefficients(0, 1, 0, 0, 0, -1)
    assert H.is_tangent(Line(0, 1, 0))
    assert H.intersections(Line(0, 1, 0)) == (Point(1, 0, 0), Point(1, 0, 0))
    assert H.tangent_at(Point(1, 0, 0)) == Line(0, 1, 0)
    # the line y = -x gives -x² = 1, so x = ±i: the complex points (i, -i, 1) and (-i, i, 1)
    assert set(H.intersections(Line(1, 1, 0))) == {Point(I, -I, 1), Point(-I, I, 1)}
