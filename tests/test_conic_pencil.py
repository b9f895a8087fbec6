"""Line pairs, splitting degenerate conics, conic ∩ conic through the pencil, conics through four points
touching a line: hand-derived values, named errors, and properties on random exact configurations."""

from __future__ import annotations

import itertools

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from sympy import I, Matrix, Rational, sqrt, symbols

from pgsym.conic_pencil import conics_through_tangent, degenerate_members, intersect_conics
from pgsym.conics import Conic, conic_through
from pgsym.errors import (
    CollinearPointsError,
    DegenerateConfigurationError,
    DegenerateConicError,
    DimensionError,
    ObjectTypeError,
    UndecidableError,
)
from pgsym.exact import is_zero
from pgsym.projective_plane import Line, Point, collinear
from tests.strategies import integers

FAST = settings(max_examples=15, deadline=None)


def qf(C: Conic, p: Point) -> sympy.Expr:
    """xᵀ C x with SymPy directly (not the library's form)."""
    x = Matrix(list(p.coords))
    return sympy.expand((x.T * Matrix(C.matrix) * x)[0, 0])


def same_multiset(got, expected) -> bool:
    """Equal lists of points up to order (points compare up to scale, exactly)."""
    rest = list(expected)
    for p in got:
        k = next((i for i, q in enumerate(rest) if q == p), None)
        if k is None:
            return False
        rest.pop(k)
    return not rest


# -- line pairs and splitting ------------------------------------------------------------------------
def test_from_lines_is_the_symmetric_product():
    # (x − 1)(y + 2) = xy + 2x − y − 2; l mᵀ + m lᵀ is twice that form's matrix
    C = Conic.from_lines(Line(1, 0, -1), Line(0, 1, 2))
    assert C == Conic.from_coefficients(0, 1, 0, 2, -1, -2)
    assert C.rank == 2
    assert Conic.from_lines(Line(1, 1, 1), Line(2, 2, 2)).rank == 1  # the same line twice
    with pytest.raises(ObjectTypeError):
        Conic.from_lines(Point(1, 0), Line(1, 0, 0))


def test_split_rational_irrational_complex_and_double():
    # x² − y² = (x − y)(x + y)
    assert set(Conic.from_coefficients(1, 0, -1, 0, 0, 0).split()) == {Line(1, -1, 0), Line(1, 1, 0)}
    # x² − 2y² = (x − √2 y)(x + √2 y)
    assert set(Conic.from_coefficients(1, 0, -2, 0, 0, 0).split()) == {Line(1, -sqrt(2), 0), Line(1, sqrt(2), 0)}
    # x² + y² = (x + iy)(x − iy): the point ellipse at the origin
    assert set(Conic.from_coefficients(1, 0, 1, 0, 0, 0).split()) == {Line(1, I, 0), Line(1, -I, 0)}
    # (x + y − 1)² = x² + 2xy + y² − 2x − 2y + 1: a double line
    assert Conic.from_coefficients(1, 2, 1, -2, -2, 1).split() == (Line(1, 1, -1), Line(1, 1, -1))
    # x² − 1 = (x − 1)(x + 1): parallel lines, vertex at infinity
    assert set(Conic.from_coefficients(1, 0, 0, 0, 0, -1).split()) == {Line(1, 0, -1), Line(1, 0, 1)}
    with pytest.raises(DegenerateConfigurationError, match="non-degenerate"):
        Conic.circle(0, 0, 1).split()


def test_split_symbolic_square():
    # a²x² − y² = (ax − y)(ax + y): −B_ii is a polynomial square, so no branch of √ is chosen
    a = symbols("a")
    l, m = Conic.from_coefficients(a**2, 0, -1, 0, 0, 0).split()
    assert {l, m} == {Line(a, -1, 0), Line(a, 1, 0)}


@given(st.lists(integers(6), min_size=6, max_size=6))
@FAST
def test_split_inverts_from_lines(c):
    l, m = c[:3], c[3:]
    assume(any(l) and any(m))
    L, M = Line(*l), Line(*m)
    assert set(Conic.from_lines(L, M).split()) == {L, M}


# -- conic ∩ conic ----------------------------------------------------------------------------------
def test_circles_meeting_in_rational_points():
    # x² + y² = 25 minus (x − 4)² + y² = 9 gives 8x − 16 = 16, x = 4, y = ±3; and I, J on both circles
    got = intersect_conics(Conic.circle(0, 0, 5), Conic.circle(4, 0, 3))
    assert same_multiset(got, [Point(4, 3), Point(4, -3), Point(1, I, 0), Point(1, -I, 0)])


def test_circles_meeting_in_irrational_points():
    # x² + y² = 4 minus (x − 1)² + (y − 1)² = 4: 2x + 2y − 2 = 0, y = 1 − x; then 2x² − 2x − 3 = 0,
    # x = (1 ± √7)/2, y = (1 ∓ √7)/2
    got = intersect_conics(Conic.circle(0, 0, 2), Conic.circle(1, 1, 2))
    r = sqrt(7)
    expected = [Point((1 + r) / 2, (1 - r) / 2), Point((1 - r) / 2, (1 + r) / 2), Point(1, I, 0), Point(1, -I, 0)]
    assert same_multiset(got, expected)


def test_disjoint_circles_meet_in_complex_points():
    # x² + y² = 1 and (x − 5)² + y² = 1: radical axis x = 5/2, y² = 1 − 25/4 = −21/4, y = ±i√21/2
    got = intersect_conics(Conic.circle(0, 0, 1), Conic.circle(5, 0, 1))
    y = I * sqrt(21) / 2
    assert same_multiset(got, [Point(Rational(5, 2), y), Point(Rational(5, 2), -y), Point(1, I, 0), Point(1, -I, 0)])


def test_ellipse_and_hyperbola():
    # x² + 4y² = 4 and x² − y² = 1: 5y² = 3, x² = 8/5: (±√(8/5), ±√(3/5))
    got = intersect_conics(Conic.from_coefficients(1, 0, 4, 0, 0, -4), Conic.from_coefficients(1, 0, -1, 0, 0, -1))
    xs, ys = sqrt(Rational(8, 5)), sqrt(Rational(3, 5))
    assert same_multiset(got, [Point(sx * xs, sy * ys) for sx in (1, -1) for sy in (1, -1)])


def test_tangency_counts_twice_and_bitangency_four_times():
    # y = x² and x² + (y − 1)² = 1: y(y − 1) = 0, the origin (touching) twice and (±1, 1)
    got = intersect_conics(Conic.from_coefficients(1, 0, 0, 0, -1, 0), Conic.circle(0, 1, 1))
    assert same_multiset(got, [Point(0, 0), Point(0, 0), Point(1, 1), Point(-1, 1)])
    # x² + y² = 1 and x² + 4y² = 1: 3y² = 0, so (±1, 0), each a point of tangency
    got = intersect_conics(Conic.circle(0, 0, 1), Conic.from_coefficients(1, 0, 4, 0, 0, -1))
    assert same_multiset(got, [Point(1, 0), Point(1, 0), Point(-1, 0), Point(-1, 0)])
    # two line pairs with one vertex and no common line: xy = 0 and x² − y² = 0 meet only at the origin, 2·2 times
    got = intersect_conics(Conic.from_coefficients(0, 1, 0, 0, 0, 0), Conic.from_coefficients(1, 0, -1, 0, 0, 0))
    assert same_multiset(got, [Point(0, 0)] * 4)


def test_hyperosculating_circle():
    # y = x² and x² + (y − 1/2)² = 1/4, the circle of curvature at the vertex: y² = 0, contact of order 4
    got = intersect_conics(Conic.from_coefficients(1, 0, 0, 0, -1, 0), Conic.circle(0, Rational(1, 2), Rational(1, 2)))
    assert same_multiset(got, [Point(0, 0)] * 4)


def test_same_conic_common_line_and_irreducible_cubic_raise():
    C = Conic.circle(1, 2, 3)
    with pytest.raises(DegenerateConfigurationError, match="same conic"):
        intersect_conics(C, Conic(2 * Matrix(C.matrix)))
    l = Line(1, -1, 0)
    with pytest.raises(DegenerateConicError, match="share the line"):
        intersect_conics(Conic.from_lines(l, Line(1, 0, 0)), Conic.from_lines(l, Line(0, 1, 3)))
    # det(C1 + t C2) for these two conics is irreducible over ℚ (no rational root by the rational-root test)
    C1, C2 = Conic.from_coefficients(1, 2, 3, 4, 5, -7), Conic.from_coefficients(2, -1, 1, 3, -2, -5)
    t = sympy.Symbol("t")
    assert sympy.Poly(sympy.expand((Matrix(C1.matrix) + t * Matrix(C2.matrix)).det()), t).is_irreducible
    assert degenerate_members(C1, C2) == []
    with pytest.raises(UndecidableError, match="irreducible cubic"):
        intersect_conics(C1, C2)
    with pytest.raises(ObjectTypeError):
        intersect_conics(C1, Line(1, 0, 0))


def test_two_circles_meet_in_two_points_and_the_circular_points():
    # x² + y² = 25 minus x² − 8x + 16 + y² = 9 is 8x − 16 = 16: x = 4, y² = 9; I and J lie on every circle
    assert same_multiset(intersect_conics(Conic.circle(0, 0, 5), Conic.circle(4, 0, 3)),
                         [Point(4, 3), Point(4, -3), Point(1, I, 0), Point(1, -I, 0)])
    # the conic's own method takes lines only (the pencil is a module above the conic) and says where to go
    with pytest.raises(ObjectTypeError, match="intersect_conics"):
        Conic.circle(0, 0, 5).intersections(Conic.circle(4, 0, 3))


def _general_position(pts) -> bool:
    return not any(collinear(*trio) for trio in itertools.combinations(pts, 3))


@given(st.lists(st.tuples(integers(6), integers(6)), min_size=6, max_size=6, unique=True))
@FAST
def test_two_conics_through_four_points_meet_in_them(coords):
    pts = [Point(x, y) for x, y in coords]
    assume(_general_position(pts))
    base = pts[:4]
    C1, C2 = conic_through(*base, pts[4]), conic_through(*base, pts[5])
    assume(C1 != C2)
    got = intersect_conics(C1, C2)
    assert len(got) == 4
    assert same_multiset(got, base)
    for p in got:
        assert is_zero(qf(C1, p)) and is_zero(qf(C2, p))


@given(st.tuples(integers(5), integers(5), st.integers(1, 6)), st.tuples(integers(5), integers(5), st.integers(1, 6)))
@FAST
def test_random_circles_meet_in_points_on_both(c1, c2):
    C1, C2 = Conic.circle(*c1), Conic.circle(*c2)
    assume(C1 != C2)
    got = intersect_conics(C1, C2)
    assert len(got) == 4
    assert Point(1, I, 0) in got and Point(1, -I, 0) in got     # every circle passes through I and J
    for p in got:
        assert is_zero(qf(C1, p)) and is_zero(qf(C2, p))
    assert _resultant_matches(C1, C2, got)     # (0, 1, 0) is on no circle


# -- four points and a tangent ----------------------------------------------------------------------
def test_four_points_and_a_tangent_by_hand():
    square = (Point(1, 1), Point(-1, 1), Point(-1, -1), Point(1, -1))
    # the pencil is α(x² − 1) + β(y² − 1); on y = 2: αx² + 3β − α, a double root iff α(3β − α) = 0:
    # α = 0 (y² = 1, its vertex at infinity on y = 2) and α = 3β (3x² + y² = 4)
    got = conics_through_tangent(square, Line(0, 1, -2))
    assert set(got) == {Conic.from_coefficients(0, 0, 1, 0, 0, -1), Conic.from_coefficients(3, 0, 1, 0, 0, -4)}
    # on x + y = 2 (through (1, 1)) the second point is x = (3β − α)/(α + β): tangent iff α = β, the circle
    assert conics_through_tangent(square, Line(1, 1, -2)) == (Conic.circle(0, 0, sqrt(2)),)
    # on y = x/2 + 3: the pencil restricted is (α + β/4)x² + 3βx + 8β − α; its discriminant
    # 9β² − 4(α + β/4)(8β − α) = 9β² − 32αβ + 4α² − 8β² + αβ = 4α² − 31αβ + β², zero at
    # α/β = (31 ± √(961 − 16))/8 = (31 ± 3√105)/8: two irrational conics
    got = conics_through_tangent(square, Line(1, -2, 6))
    assert len(got) == 2
    for C in got:
        a, c = C.matrix[0, 0], C.matrix[1, 1]     # C = α x² + β y² − (α + β)
        assert is_zero(C.matrix[0, 1]) and is_zero(C.matrix[0, 2]) and is_zero(C.matrix[1, 2])
        assert is_zero(4 * a**2 - 31 * a * c + c**2)


def test_four_points_errors():
    with pytest.raises(CollinearPointsError):
        conics_through_tangent((Point(0, 0), Point(1, 1), Point(2, 2), Point(0, 1)), Line(1, 0, 5))
    with pytest.raises(DimensionError):
        conics_through_tangent((Point(0, 0), Point(1, 1), Point(2, 2)), Line(1, 0, 5))


@given(st.lists(st.tuples(integers(5), integers(5)), min_size=4, max_size=4, unique=True),
       st.tuples(integers(5), integers(5), integers(5)))
@settings(max_examples=8, deadline=None)
def test_four_points_and_tangent_property(coords, l):
    pts = tuple(Point(x, y) for x, y in coords)
    assume(_general_position(pts) and any(l[:2]))
    line = Line(*l)
    try:
        got = conics_through_tangent(pts, line)
    except DegenerateConfigurationError:
        return
    assert 1 <= len(got) <= 2
    for C in got:
        for p in pts:
            assert is_zero(qf(C, p))
        # tangency checked independently: restrict to the line through two of its points, discriminant 0
        on_line = [tuple(Matrix(line.coords).cross(Matrix(e))) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
        on_line = [Point(*v) for v in on_line if any(v)]
        p, q = on_line[0], next(P for P in on_line[1:] if P != on_line[0])
        s, u = sympy.symbols("s u")
        x = [s * a + u * b for a, b in zip(p.coords, q.coords, strict=True)]
        form = sympy.Poly(sympy.expand((Matrix(x).T * Matrix(C.matrix) * Matrix(x))[0, 0]), s, u)
        A, B2, Cc = (form.coeff_monomial(m) for m in (s**2, s * u, u**2))
        assert is_zero(B2**2 - 4 * A * Cc)


def test_symbolic_conics():
    # y = a x² and x² = 1: the points (±1, a); the lines x = ±1 both pass through (0, 1, 0), where the
    # parabola touches l∞, so that ideal point counts twice
    a, r, d = symbols("a r d")
    got = intersect_conics(Conic.from_coefficients(a, 0, 0, 0, -1, 0), Conic.from_coefficients(1, 0, 0, 0, 0, -1))
    assert same_multiset(got, [Point(1, a), Point(-1, a), Point(0, 1, 0), Point(0, 1, 0)])
    # circles of radius r at distance d: y = ±√(r² − d²/4), a symbol under a radical, so no decision
    with pytest.raises(UndecidableError):
        intersect_conics(Conic.circle(0, 0, r), Conic.circle(d, 0, r))


def test_conics_through_four_points_touching_special_lines():
    # touching l∞ means a parabola (or a parallel pair). Through (0, 0), (1, 1), (−1, 1), (2, 4): y = x², and
    # the pair y = x (through the first two) and y = x + 2 (through the other two): (x − y)(x − y + 2)
    got = conics_through_tangent((Point(0, 0), Point(1, 1), Point(-1, 1), Point(2, 4)), Line(0, 0, 1))
    assert set(got) == {Conic.from_coefficients(1, 0, 0, 0, -1, 0), Conic.from_coefficients(1, -2, 1, 2, -2, 0)}
    square = (Point(1, 1), Point(-1, 1), Point(-1, -1), Point(1, -1))
    # α(x² − 1) + β(y² − 1) on w = 0 is αx² + βy², a double root iff αβ = 0: the pairs y = ±1 and x = ±1
    assert set(conics_through_tangent(square, Line(0, 0, 1))) == {Conic.from_coefficients(1, 0, 0, 0, 0, -1),
                                                                   Conic.from_coefficients(0, 0, 1, 0, 0, -1)}
    # x = 1 holds two of the points, met by every conic of the pencil twice: only the pair x = ±1 contains it
    assert conics_through_tangent(square, Line(1, 0, -1)) == (Conic.from_coefficients(1, 0, 0, 0, 0, -1),)


def test_tangents_from_a_point():
    # from (0, 2) to x² + y² = 1: y = kx + 2 touches when k² + 1 = 4 (distance 2/√(1 + k²) = 1), k = ±√3
    got = Conic.circle(0, 0, 1).tangents_from(Point(0, 2))
    assert set(got) == {Line(sqrt(3), -1, 2), Line(-sqrt(3), -1, 2)}
    # from a point of the conic: its tangent, twice
    assert Conic.circle(0, 0, 1).tangents_from(Point(0, 1)) == (Line(0, 1, -1), Line(0, 1, -1))
    # from the origin, inside: y = kx touches when 1 + k² = 0, k = ±i
    assert set(Conic.circle(0, 0, 1).tangents_from(Point(0, 0))) == {Line(I, -1, 0), Line(-I, -1, 0)}
    with pytest.raises(DegenerateConicError):
        Conic.from_coefficients(1, 0, -1, 0, 0, 0).tangents_from(Point(1, 2))


@given(st.lists(integers(5), min_size=6, max_size=6), st.lists(integers(5), min_size=3, max_size=3))
@FAST
def test_pencil_with_a_line_pair_through_the_origin(e, d):
    # C2 = C1 + D with D = d0 x² + d1 xy + d2 y² (two lines through the origin: rational, irrational or
    # complex): every common point of C1 and C2 is on D, and the four points (with multiplicity) are exact
    assume(any(e) and any(d))
    C1 = Conic.from_coefficients(*e)
    D = Conic.from_coefficients(d[0], d[1], d[2], 0, 0, 0)
    C2 = Conic(Matrix(C1.matrix) + Matrix(D.matrix))
    assume(C1 != C2 and not C1.is_degenerate)
    got = intersect_conics(C1, C2)
    assert len(got) == 4
    for p in got:
        assert is_zero(qf(C1, p)) and is_zero(qf(C2, p)) and is_zero(qf(D, p))
    if not (is_zero(qf(C1, Point(0, 1, 0))) and is_zero(qf(C2, Point(0, 1, 0)))):
        assert _resultant_matches(C1, C2, got)


def _resultant_matches(C1: Conic, C2: Conic, points) -> bool:
    """Multiplicities checked independently: if (0, 1, 0) is on at most one of the conics, the resultant
    Res_y(C1, C2) is a binary quartic in (x, w) equal, up to a constant, to ∏ (w_p x − x_p w) over the
    common points p counted with multiplicity (Poisson's product formula). It sees only (x : w); with the
    points checked on both conics separately, it pins the multiplicities."""
    x, y, w = symbols("x y w")
    v = Matrix([x, y, w])
    f1, f2 = ((v.T * Matrix(C.matrix) * v)[0, 0] for C in (C1, C2))
    res = sympy.Poly(sympy.resultant(sympy.expand(f1), sympy.expand(f2), y), x, w)
    prod = sympy.Poly(sympy.expand(sympy.Mul(*(p.coords[2] * x - p.coords[0] * w for p in points))), x, w)
    monomials = [(4 - k, k) for k in range(5)]
    a = [res.coeff_monomial(m) for m in monomials]
    b = [prod.coeff_monomial(m) for m in monomials]
    k = next(i for i in range(5) if a[i] != 0)
    return all(is_zero(a[k] * b[i] - a[i] * b[k]) for i in range(5)) and not is_zero(b[k])


@pytest.mark.parametrize(("C1", "C2"), [
    (Conic.from_coefficients(1, 0, 0, 0, -1, 0), Conic.circle(0, 1, 1)),                          # tangent once
    (Conic.circle(0, 0, 1), Conic.from_coefficients(1, 0, 4, 0, 0, -1)),                          # bitangent
    (Conic.from_coefficients(1, 0, 0, 0, -1, 0), Conic.circle(0, Rational(1, 2), Rational(1, 2))),  # order 4
    (Conic.from_coefficients(1, 0, 4, 0, 0, -4), Conic.from_coefficients(1, 0, -1, 0, 0, -1)),    # four simple
    (Conic.circle(0, 0, 2), Conic.circle(1, 1, 2)),                                               # with I and J
])
def test_multiplicities_agree_with_the_resultant(C1, C2):
    assert _resultant_matches(C1, C2, intersect_conics(C1, C2))


# -- Steiner's conic: a constant cross-ratio seen from the conic ------------------------------------

def test_conic_from_cross_ratio_by_hand() -> None:
    from pgsym.conic_pencil import conic_from_cross_ratio

    a, b, c, d = Point(0, 1), Point(0, -1), Point(1, 0), Point(-1, 0)
    # seen from e = (3/5, 4/5) on the unit circle: [eac] = det[[3,4,5],[0,1,1],[1,0,1]] = 3·1 − 4·(−1) + 5·(−1) = 2,
    # [ebd] = det[[3,4,5],[0,−1,1],[−1,0,1]] = 3·(−1) − 4·1 + 5·(−1) = −12,
    # [ead] = det[[3,4,5],[0,1,1],[−1,0,1]] = 3·1 − 4·1 + 5·1 = 4,
    # [ebc] = det[[3,4,5],[0,−1,1],[1,0,1]] = 3·(−1) − 4·(−1) + 5·1 = 6
    # cross-ratio 2·(−12)/(4·6) = −1: the four points are harmonic on the circle
    assert conic_from_cross_ratio(-1, a, b, c, d) == Conic.circle(0, 0, 1)
    # cr = 0 and cr = 1 are the line pairs ac ∪ bd and ab ∪ cd
    assert conic_from_cross_ratio(0, a, b, c, d) == Conic.from_lines(Line(1, 1, -1), Line(1, 1, 1))
    assert conic_from_cross_ratio(1, a, b, c, d) == Conic.from_lines(Line(1, 0, 0), Line(0, 1, 0))
    with pytest.raises(CollinearPointsError):
        conic_from_cross_ratio(2, a, b, Point(0, 5), d)


@given(st.lists(st.tuples(integers(6), integers(6)), min_size=5, max_size=5, unique=True))
@settings(max_examples=40, deadline=None)
def test_steiner_the_cross_ratio_seen_from_the_conic_gives_it_back(coords) -> None:
    from pgsym.conic_pencil import conic_from_cross_ratio
    from pgsym.projective_line import cross_ratio_lines
    from pgsym.projective_plane import join

    a, b, c, d, e = (Point(*xy) for xy in coords)
    assume(not any(collinear(*trio) for trio in itertools.combinations((a, b, c, d, e), 3)))
    cr = cross_ratio_lines(join(e, a), join(e, b), join(e, c), join(e, d))
    assert conic_from_cross_ratio(cr, a, b, c, d) == conic_through(a, b, c, d, e)
