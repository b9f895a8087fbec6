"""The sign of a polynomial on the whole real plane, decided exactly (pgsym.proofs.real_signs)."""

from fractions import Fraction

import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from pgsym.proofs.real_signs import plane_sign

x, y = sympy.symbols("x y")


def test_definite_polynomials():
    assert plane_sign(x**2 + y**2 + 1, [x, y]) == 1
    assert plane_sign(-(x**2 + 1) * (y - 3)**2, [x, y]) == -1
    # 2x⁴ + 4x³ + 3x²y² + 2x² + 4xy² + y⁴ + y² = 2x²(x + 1)² + y²(3x + 1)(x + 1) + y⁴: as a quadratic in y²
    # its discriminant is (x + 1)²(x² + 6x + 1), negative exactly where (3x + 1)(x + 1) < 0, so it is ≥ 0
    assert plane_sign(2*x**4 + 4*x**3 + 3*x**2*y**2 + 2*x**2 + 4*x*y**2 + y**4 + y**2, [x, y]) == 1


def test_a_leading_coefficient_that_vanishes_somewhere():
    # x²y² + 1 ≥ 1; its leading coefficient in y, x², is 0 on the line x = 0, where it is the constant 1
    assert plane_sign(x**2 * y**2 + 1, [x, y]) == 1
    # x·y² + y + x is x at y = 0: it takes both signs
    assert plane_sign(x * y**2 + y + x, [x, y]) is None


def test_motzkin_polynomial_is_nonnegative_though_no_sum_of_squares():
    # x⁴y² + x²y⁴ − 3x²y² + 1 ≥ 0 by the AM-GM inequality on x⁴y², x²y⁴, 1; it is zero at (±1, ±1)
    assert plane_sign(x**4 * y**2 + x**2 * y**4 - 3 * x**2 * y**2 + 1, [x, y]) == 1


def test_polynomials_that_change_sign():
    assert plane_sign(x**2 + y**2 - 1, [x, y]) is None  # −1 at the origin, 3 at (2, 0)
    assert plane_sign(x * y, [x, y]) is None
    assert plane_sign(x**3 - x, [x]) is None
    # the Motzkin polynomial less 1/100 is negative at (1, 1): 1 + 1 − 3 + 1 − 1/100
    assert plane_sign(x**4 * y**2 + x**2 * y**4 - 3 * x**2 * y**2 + 1 - sympy.Rational(1, 100), [x, y]) is None


def test_roots_at_the_ends_of_isolating_intervals():
    # 2x² − 3x + 2y² + 1 is 2((x − 3/4)² + y² − 1/16): −1/8 at (3/4, 0), inside the small circle; the cut points
    # of the x-axis are the roots 1/2 and 1 of its discriminant, whose first isolating interval may end at 1
    assert plane_sign(2 * x**2 - 3 * x + 2 * y**2 + 1, [x, y]) is None
    assert plane_sign(-(2 * x - 1) * (x - 1), [x]) is None  # 1/8 at x = 3/4
    assert plane_sign((2 * x - 1)**2 * (x - 1)**2 + y**2, [x, y]) == 1


def test_more_than_two_variables_is_not_decided():
    z = sympy.Symbol("z")
    assert plane_sign(x**2 + y**2 + z**2 + 1, [x, y, z]) is None


small = st.integers(-3, 3)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(small, st.integers(0, 3), st.integers(0, 3)), min_size=1, max_size=5),
       st.lists(st.tuples(small, small), min_size=3, max_size=3))
def test_a_decided_sign_holds_at_rational_points(terms, points):
    f = sum(c * x**i * y**j for c, i, j in terms) + x * y - 1  # x·y − 1 makes f change sign often
    grid = [sympy.Rational(k, 4) for k in range(-12, 13)]  # a sign change of a small polynomial shows on it
    for g in (f, f**2 + 1, -(f**2) * (x**2 + 1)):
        poly = sympy.Poly(sympy.expand(g), x, y)
        s = plane_sign(poly.as_expr(), [x, y])
        for px, py in [*((sympy.Rational(px, 2), sympy.Rational(py, 3)) for px, py in points), *(
                (gx, gy) for gx in grid for gy in grid)]:
            assert s is None or s * poly.eval((px, py)) >= 0
    assert plane_sign(sympy.expand(f**2 + 1), [x, y]) == 1  # a square plus one is positive
    assert plane_sign(sympy.expand(-(f**2) * (x**2 + 1)), [x, y]) == -1


def test_a_shifted_variable_shows_the_sign():
    from pgsym.proofs.algebraic import _depressed, _signed_factors
    z = sympy.Symbol("z")
    # q²(z + 1)⁴ + 6q(z + 1)² + 1 with q = x² + y²: even in z + 1 and in x, y, positive; expanded in z, its odd
    # powers have positive coefficients and no factor shows the sign, three variables are too many for the plane
    q = x**2 + y**2
    b = sympy.expand(q**2 * (z + 1)**4 + 6 * q * (z + 1)**2 + 1)
    assert plane_sign(b, [x, y, z]) is None
    assert _depressed(b, [x, y, z]) == sympy.expand(q**2 * z**4 + 6 * q * z**2 + 1)
    assert _signed_factors(b, [x, y, z], {}) == 1
    assert _signed_factors(-b, [x, y, z], {}) == -1
    # ((z − 1)² − 1)(x² + 1) = z(z − 2)(x² + 1) changes sign: its factors z and z − 2 have no sign
    assert _signed_factors(sympy.expand(((z - 1)**2 - 1) * (x**2 + 1)), [x, z], {}) is None


def test_the_content_in_the_roots_is_set_apart():
    from pgsym.proofs.algebraic import _root_content
    r, s = sympy.symbols("r s")
    # T = −4y⁶(x² + 1)³·(r·(x² + 1) − 2x·s): the content in r, s is 4y⁶(x² + 1)³, the sign goes with the rest
    t = sympy.expand(-4 * y**6 * (x**2 + 1)**3 * (r * (x**2 + 1) - 2 * x * s))
    content, rest = _root_content(t, [r, s])
    assert sympy.factor(content) == 4 * y**6 * (x**2 + 1)**3
    assert sympy.expand(rest) == sympy.expand(-(r * (x**2 + 1) - 2 * x * s))
    assert _root_content(x**2 + 1, [r]) == (x**2 + 1, 1)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(small, st.integers(0, 2), st.integers(0, 2), st.integers(0, 2)), min_size=1, max_size=4),
       small, small, st.lists(st.tuples(small, small, small), min_size=3, max_size=3))
def test_a_sign_decided_through_a_shift_holds_at_rational_points(terms, sx, sz, points):
    from pgsym.proofs.algebraic import _signed_factors
    z = sympy.Symbol("z")
    # polynomials in (x − sx)², y², (z − sz)² (even: a shift shows their sign when the coefficients have one) and
    # the same less 1 (which may change sign)
    f = sum(c * (x - sx)**(2 * i) * y**(2 * j) * (z - sz)**(2 * k) for c, i, j, k in terms)
    grid = [Fraction(k, 2) for k in range(-8, 9)]
    for g in (f, f - 1, -f, f + 1):
        g = sympy.expand(g)
        s = _signed_factors(g, [x, y, z], {})
        value = sympy.lambdify((x, y, z), g, "math")  # integer coefficients: exact on fractions
        for q in [*((Fraction(a, 2), Fraction(b, 3), Fraction(c, 5)) for a, b, c in points),
                  *((gx, gy, gz) for gx in grid for gy in grid[::4] for gz in grid)]:
            assert s is None or s * value(*q) >= 0, (g, q)
    if all(c > 0 for c, *_ in terms):  # positive coefficients: the shift shows f + 1 > 0
        assert _signed_factors(sympy.expand(f + 1), [x, y, z], {}) == 1
