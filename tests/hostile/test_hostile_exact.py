"""Exactness over algebraic numbers: identities the core must decide, and input it must refuse.

Every expected value is derived by hand in a comment; none is computed by the code under test.
"""

from __future__ import annotations

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import I, Rational, S, cos, exp, pi, sin, sqrt, tan

from pgsym import (
    CoincidentPointsError,
    Conic,
    DecompositionError,
    DegenerateConfigurationError,
    IdealPointError,
    Line,
    NonNumericError,
    Point,
    Transformation,
    UndecidableError,
    UndefinedCrossRatioError,
    ZeroVectorError,
    circular_points,
    classify,
    conic_through,
    decompose,
    invariants,
    is_zero,
    join,
    meet,
)
from pgsym.exact import algebraic_normal_form, sign

a, b = sympy.symbols("a b")
w = (-1 + I * sqrt(3)) / 2  # ω, a primitive cube root of unity
# ζ = e^{2πi/5} = cos 72° + i sin 72°, with cos 72° = (√5 − 1)/4 and sin 72° = √(10 + 2√5)/4
z5 = (sqrt(5) - 1) / 4 + I * sqrt(10 + 2 * sqrt(5)) / 4

# (lhs, rhs, wrong): lhs = rhs exactly (derivation in the comment); wrong ≠ lhs (usually a conjugate)
IDENTITIES = [
    # (1 + √2)² = 1 + 2√2 + 2 = 3 + 2√2, and 1 + √2 > 0
    (sqrt(3 + 2 * sqrt(2)), 1 + sqrt(2), sqrt(2) - 1),
    # (√2 + √3)² = 2 + 2√6 + 3 = 5 + 2√6
    (sqrt(5 + 2 * sqrt(6)), sqrt(2) + sqrt(3), sqrt(3) - sqrt(2)),
    # (√3 − √2)² = 5 − 2√6, and √3 > √2
    (sqrt(5 - 2 * sqrt(6)), sqrt(3) - sqrt(2), sqrt(2) - sqrt(3)),
    # (2 + √3)² = 4 + 4√3 + 3 = 7 + 4√3
    (sqrt(7 + 4 * sqrt(3)), 2 + sqrt(3), 2 - sqrt(3)),
    # (3 + √2)² = 9 + 6√2 + 2 = 11 + 6√2
    (sqrt(11 + 6 * sqrt(2)), 3 + sqrt(2), 3 - sqrt(2)),
    # (1 + √5)² = 1 + 2√5 + 5 = 6 + 2√5
    (sqrt(6 + 2 * sqrt(5)), 1 + sqrt(5), sqrt(5) - 1),
    # ((√6 + √2)/2)² = (6 + 2√12 + 2)/4 = (8 + 4√3)/4 = 2 + √3
    (sqrt(2 + sqrt(3)), (sqrt(6) + sqrt(2)) / 2, (sqrt(6) - sqrt(2)) / 2),
    # ((1 + √5)/2)³ = (1 + 3√5 + 15 + 5√5)/8 = (16 + 8√5)/8 = 2 + √5
    ((2 + sqrt(5)) ** Rational(1, 3), (1 + sqrt(5)) / 2, (1 - sqrt(5)) / 2),
    # 1/(√2 + 1) = (√2 − 1)/((√2 + 1)(√2 − 1)) = (√2 − 1)/1
    (1 / (sqrt(2) + 1), sqrt(2) - 1, sqrt(2) + 1),
    # (√2 + √3)² = 5 + 2√6 (expanded by hand)
    ((sqrt(2) + sqrt(3)) ** 2, 5 + 2 * sqrt(6), 5 - 2 * sqrt(6)),
    # (2^{1/4})² = 2^{1/2}
    (2 ** Rational(1, 4) * 2 ** Rational(1, 4), sqrt(2), -sqrt(2)),
    # cos 36° = (1 + √5)/4 (the golden ratio over 2)
    (cos(pi / 5), (1 + sqrt(5)) / 4, (1 - sqrt(5)) / 4),
    # cos 30° = √3/2
    (cos(pi / 6), sqrt(3) / 2, -sqrt(3) / 2),
    # cos 15° = cos(45° − 30°) = (√2/2)(√3/2) + (√2/2)(1/2) = (√6 + √2)/4
    (cos(pi / 12), (sqrt(6) + sqrt(2)) / 4, (sqrt(6) - sqrt(2)) / 4),
    # sin 18° = (√5 − 1)/4
    (sin(pi / 10), (sqrt(5) - 1) / 4, (-sqrt(5) - 1) / 4),
    # cos 72° = 2cos²36° − 1 = 2(6 + 2√5)/16 − 1 = (√5 − 1)/4
    (cos(2 * pi / 5), (sqrt(5) - 1) / 4, (sqrt(5) + 1) / 4),
    # tan 22.5° = sin 45°/(1 + cos 45°) = (√2/2)/(1 + √2/2) = √2/(2 + √2) = √2 − 1
    (tan(pi / 8), sqrt(2) - 1, -sqrt(2) - 1),
    # tan 15° = (1 − cos 30°)/sin 30° = (1 − √3/2)·2 = 2 − √3
    (tan(pi / 12), 2 - sqrt(3), 2 + sqrt(3)),
    # sin²36° + cos²36° = 1
    (sin(pi / 5) ** 2 + cos(pi / 5) ** 2, S(1), S(2)),
    # cos(π/7) cos(2π/7) cos(3π/7) = 1/8 (multiply by 8 sin(π/7) and use 2 sin x cos x = sin 2x thrice)
    (cos(pi / 7) * cos(2 * pi / 7) * cos(3 * pi / 7), Rational(1, 8), Rational(-1, 8)),
    # cos(2π/7) + cos(4π/7) + cos(6π/7) = (sum of the six primitive 7th roots of unity)/2 = −1/2
    (cos(2 * pi / 7) + cos(4 * pi / 7) + cos(6 * pi / 7), Rational(-1, 2), Rational(1, 2)),
    # ω³ = ((−1 + i√3)/2)³ = (−1 + 3i√3 + 9 − 3i√3)/8 = 8/8 = 1
    (w**3, S(1), w),
    # 1 + ω + ω² = 0 (ω is a root of x² + x + 1)
    (1 + w + w**2, S(0), S(1)),
    # ω² = (1 − 2i√3 − 3)/4 = (−1 − i√3)/2 = conj(ω)
    (w**2, (-1 - I * sqrt(3)) / 2, w),
    # e^{2πi/3} = cos 120° + i sin 120° = (−1 + i√3)/2 = ω
    (exp(2 * pi * I / 3), w, w**2),
    # e^{2πi/5} = cos 72° + i sin 72° = ζ (see z5 above)
    (exp(2 * pi * I / 5), z5, z5.conjugate()),
    # ζ⁵ = 1 for the primitive 5th root ζ
    (z5**5, S(1), z5),
    # 1 + ζ + ζ² + ζ³ + ζ⁴ = (ζ⁵ − 1)/(ζ − 1) = 0
    (1 + z5 + z5**2 + z5**3 + z5**4, S(0), S(1)),
    # ζ·ζ⁴ = ζ⁵ = 1, so ζ⁴ = 1/ζ = conj(ζ) (|ζ| = 1)
    (z5**4, (sqrt(5) - 1) / 4 - I * sqrt(10 + 2 * sqrt(5)) / 4, z5),
    # (1 + i)² = 1 + 2i − 1 = 2i
    ((1 + I) ** 2, 2 * I, -2 * I),
    # (1 + i)(1 − i) = 1 − i² = 2
    ((1 + I) * (1 - I), S(2), 2 * I),
    # (2 + i)² = 4 + 4i − 1 = 3 + 4i, and 2 + i has positive real part, so it is the principal root
    (sqrt(3 + 4 * I), 2 + I, -2 - I),
    # (1 − 2i)² = 1 − 4i − 4 = −3 − 4i, real part 1 > 0: the principal root
    (sqrt(-3 - 4 * I), 1 - 2 * I, -1 + 2 * I),
    # 1/(1 + i) = (1 − i)/((1 + i)(1 − i)) = (1 − i)/2
    (1 / (1 + I), (1 - I) / 2, (1 + I) / 2),
    # i⁴ = (i²)² = 1, written as a product of the Gaussian integers (1 + i)⁴ = (2i)² = −4
    ((1 + I) ** 4, S(-4), S(4)),
]
IDS = [f"{i:02d}" for i in range(len(IDENTITIES))]


@pytest.mark.parametrize(("lhs", "rhs", "wrong"), IDENTITIES, ids=IDS)
def test_identity_is_decided_everywhere(lhs, rhs, wrong):
    assert is_zero(lhs - rhs)
    assert not is_zero(lhs - wrong)
    assert Point(lhs, 1) == Point(rhs, 1)
    assert Point(lhs, 1) != Point(wrong, 1)
    # equal objects have identical canonical forms (structurally, not only up to scale)
    assert Point(lhs, 1).canonical().coords == Point(rhs, 1).canonical().coords
    assert Point(lhs, 1, 0).canonical().coords == Point(rhs, 1, 0).canonical().coords
    # join with the origin: (x, 1, 1) × (0, 0, 1) = (1·1 − 1·0, 1·0 − x·1, x·0 − 1·0) = (1, −x, 0)
    assert join(Point(lhs, 1), Point(0, 0)) == Line(1, -rhs, 0)
    # meet of x = lhs and y = 1: (1, 0, −lhs) × (0, 1, −1) = (0·(−1) + lhs, −lhs·0 + 1, 1) = (lhs, 1, 1)
    assert meet(Line(1, 0, -lhs), Line(0, 1, -1)) == Point(rhs, 1)


@pytest.mark.parametrize(("lhs", "rhs", "wrong"), IDENTITIES[:8], ids=IDS[:8])
def test_identity_in_conics(lhs, rhs, wrong):
    # circle (x − c)² + y² = 1 for the same centre c, written two ways
    assert Conic.circle(lhs, 0, 1) == Conic.circle(rhs, 0, 1)
    assert Conic.circle(lhs, 0, 1) != Conic.circle(wrong, 0, 1)
    assert Conic.circle(lhs, 0, 1).contains(Point(rhs + 1, 0))


def test_rational_functions_over_algebraic_numbers():
    # (√(5 + 2√6) − √2 − √3)·a = 0·a, divided by a + √2 (nonzero as a rational function)
    assert is_zero((sqrt(5 + 2 * sqrt(6)) * a - (sqrt(2) + sqrt(3)) * a) / (a + sqrt(2)))
    # (a + √2)(a − √2) = a² − 2
    assert is_zero((a + sqrt(2)) * (a - sqrt(2)) - (a**2 - 2))
    assert not is_zero(a * sqrt(2) - a)
    # Point(√2 a, √2 b, √2) is (a, b, 1) scaled by √2; (1 + √2)(√2 − 1) = 1 makes the second a rescaling too
    assert Point(sqrt(2) * a, sqrt(2) * b, sqrt(2)) == Point(a, b)
    assert Point(sqrt(2) * a, sqrt(2) * b, sqrt(2)).canonical().coords == Point(a, b).canonical().coords
    p = Point((1 + sqrt(2)) * a, sqrt(3 + 2 * sqrt(2)) * b, 1 + sqrt(2))
    assert p == Point(a, b) and p.canonical().coords == (a, b, 1)
    # over ℚ(√2): (√2 a, b, 1) scaled to make the leading coefficient of the first entry 1: (a, b/√2, 1/√2)
    assert Point(sqrt(2) * a, b, 1).canonical().coords == (a, sqrt(2) * b / 2, sqrt(2) / 2)
    # the same point written with √(3 + 2√2) − 1 in place of √2 has the same canonical form
    q = Point((sqrt(3 + 2 * sqrt(2)) - 1) * a, b, 1)
    assert q.canonical().coords == (a, sqrt(2) * b / 2, sqrt(2) / 2)


UNDECIDABLE = [
    (sympy.pi - 3, "pi"),
    (sympy.E - 2, "E"),
    (exp(1) - 2, "E"),
    (sympy.log(2) - 1, "log(2)"),
    (sympy.Function("f")(a), "f(a)"),
    (sqrt(a) - sqrt(a**2), "under a radical"),
    (sympy.Float("1.5") * sqrt(2) - a, "float"),
    (2 ** sqrt(2) - 3, "exponent"),
    (cos(1) - Rational(1, 2), "cos(1)"),
]


@pytest.mark.parametrize(("expr", "culprit"), UNDECIDABLE, ids=[c for _, c in UNDECIDABLE])
def test_undecidable_input_raises_a_named_error(expr, culprit):
    with pytest.raises(UndecidableError, match="cannot decide") as info:
        is_zero(expr)
    assert culprit in str(info.value)
    assert isinstance(info.value, ValueError)


def test_undecidable_equality_names_both_objects():
    with pytest.raises(UndecidableError, match=r"Point\(pi, 1, 1\).*Point\(3, 1, 1\)"):
        _ = Point(sympy.pi, 1) == Point(3, 1)
    # pi times itself cancels before anything is decided: equal whatever pi is
    assert Point(sympy.pi, 1) == Point(2 * sympy.pi, 2, 2)
    with pytest.raises(UndecidableError):
        Point(sympy.pi, 1).canonical()


def test_identity_that_expands_to_zero_is_zero_whatever_the_atoms():
    # √a·√a = a for every a (SymPy writes it as a), and pi − pi = 0
    assert is_zero(sqrt(a) ** 2 - a)
    assert is_zero((sympy.pi + 1) ** 2 - sympy.pi**2 - 2 * sympy.pi - 1)


def test_complex_canonical():
    # (i, −2, 0)/i = (1, −2/i, 0) = (1, 2i, 0) since 1/i = −i
    assert Point(1j, -2, 0).canonical().coords == (1, 2 * I, 0)
    assert Point(1j, -2, 0) == Point(1, 2 * I, 0)
    # (1 + i)·(1, 2, 3) is the rational point (1, 2, 3): same canonical form as before
    assert Point(1 + I, 2 + 2 * I, 3 + 3 * I).canonical().coords == (1, 2, 3)
    # (ω, ω², 1) = ω·(1, ω, ω²) because ω³ = 1
    assert Point(w, w**2, 1) == Point(1, w, w**2)
    # first entry 1; ω = −1/2 + (√3/2)i and ω² = −1/2 − (√3/2)i in the normal form a + b√d
    expected = (1, Rational(-1, 2) + sqrt(3) * I / 2, Rational(-1, 2) - sqrt(3) * I / 2)
    assert Point(w, w**2, 1).canonical().coords == Point(1, w, w**2).canonical().coords == expected


def test_rational_canonical_form_is_unchanged():
    assert repr(Point(2, 4, 6).canonical()) == "Point(1, 2, 3)"
    assert repr(Line(Rational(-1, 2), Rational(1, 3), 0).canonical()) == "Line(3, -2, 0)"
    assert repr(Point(-2 * a, 4 * a**2, 0).canonical()) == "Point(1, -2*a, 0)"


def test_circle_through_the_circular_points():
    i_, j_ = circular_points()
    # x² + y² + Dx + Ey + F through (1, 0), (0, 1), (2, 3): 1 + D + F = 0, 1 + E + F = 0,
    # 13 + 2D + 3E + F = 0, so D = E = −1 − F and 13 − 5 − 5F + F = 0: F = 2, D = E = −3
    conic = conic_through(i_, j_, Point(1, 0), Point(0, 1), Point(2, 3))
    x, y = sympy.symbols("x y")
    assert sympy.expand(conic.canonical().equation() - (x**2 + y**2 - 3 * x - 3 * y + 2)) == 0
    assert conic == Conic.from_coefficients(1, 0, 1, -3, -3, 2)


def test_rotation_by_thirty_degrees():
    c, s = cos(pi / 6), sin(pi / 6)  # √3/2 and 1/2
    R = Transformation([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    assert R.det == 1  # cos² + sin² = 3/4 + 1/4
    # three turns by 30° are the quarter turn (x, y) ↦ (−y, x)
    assert R @ R @ R == Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    # R (1, i, 0) = (c − i s, s + i c, 0) = (c − i s)(1, i, 0): the circular points are fixed
    i_, j_ = circular_points()
    assert R @ i_ == i_ and R @ j_ == j_
    assert R @ Conic.circle(0, 0, 1) == Conic.circle(0, 0, 1)
    # (1, 0) goes to (cos 30°, sin 30°) = (√3/2, 1/2)
    assert R @ Point(1, 0) == Point(sqrt(3), 1, 2)
    assert classify(R).name == "Euclidean (proper isometry)"
    assert decompose(R).verify()


def test_singular_transformation_in_disguise():
    from pgsym import SingularTransformationError

    # rows (1, √2, 0) and (1 + √2, √(3 + 2√2)·√2, 0) are proportional: (1 + √2)√2 = √2 + 2 = √(3+2√2)·√2
    with pytest.raises(SingularTransformationError):
        Transformation([[1, sqrt(2), 0], [1 + sqrt(2), sqrt(3 + 2 * sqrt(2)) * sqrt(2), 0], [0, 0, 1]])


def test_sign_of_non_real_numbers_is_a_named_error():
    assert sign(sqrt(3) - Rational(17, 10)) == 1  # 3 > 2.89 = 1.7²
    assert sign(sqrt(3 + 2 * sqrt(2)) - 1 - sqrt(2)) == 0
    with pytest.raises(UndecidableError, match="not a real number"):
        sign(1 + I)
    with pytest.raises(DecompositionError):
        decompose([[I, 0, 0], [0, I, 0], [0, 0, 1]])


def test_normal_form_of_algebraic_numbers():
    assert algebraic_normal_form(sqrt(3 + 2 * sqrt(2))) == 1 + sqrt(2)
    # ω = (−1 + i√3)/2, and √(−3) is written i√3
    assert algebraic_normal_form(exp(2 * pi * I / 3)) == Rational(-1, 2) + sqrt(3) * I / 2
    # cos(2π/7) has degree 3 (minimal polynomial 8x³ + 4x² − 4x − 1) and no real radical form
    x = sympy.Symbol("x")
    assert algebraic_normal_form(cos(2 * pi / 7)) == sympy.CRootOf(8 * x**3 + 4 * x**2 - 4 * x - 1, 2)


def test_zero_vector_in_disguise_is_rejected():
    zero = sqrt(3 + 2 * sqrt(2)) - 1 - sqrt(2)
    with pytest.raises(ZeroVectorError):
        Point(zero, 0, 0)
    with pytest.raises(ZeroVectorError):
        Line(zero, zero * I, 0)
    with pytest.raises(CoincidentPointsError):
        join(Point(sqrt(3 + 2 * sqrt(2)), 1), Point(1 + sqrt(2), 1))
    # a division by zero in disguise: (a + 1)² − a² − 2a − 1 = 0 and (1 + √2)² − 3 − 2√2 = 0
    with pytest.raises(NonNumericError, match="divides by"):
        Point(1 / ((a + 1) ** 2 - a**2 - 2 * a - 1), 1)
    with pytest.raises(NonNumericError, match="divides by"):
        Point(1, 1 / ((1 + sqrt(2)) ** 2 - 3 - 2 * sqrt(2)))


def test_huge_integer_repr_round_trips():
    n = 10**5000 + 7  # 5001 digits, past Python's 4300-digit int-to-str limit
    p = Point(n, -n, 3)
    again = eval(repr(p), {"Point": Point, "S": S})
    assert again.coords == (n, -n, 3)
    assert str(p) == repr(p)
    tex = p.latex()
    assert tex.count("1" + "0" * 4999 + "7") == 2 and "-1000" in tex
    q = Point(Rational(n, 3), 1)
    assert eval(repr(q), {"Point": Point, "S": S}).coords == (Rational(n, 3), 1, 1)


# each scalar written in three ways that are equal but look different
SPELLINGS = [
    [sqrt(2), 2 / sqrt(2), sqrt(3 + 2 * sqrt(2)) - 1],
    [I, -1 / I, (1 + I) ** 2 / 2],
    [w, exp(2 * pi * I / 3), -1 - w**2],
    [cos(pi / 5), (1 + sqrt(5)) / 4, sqrt(6 + 2 * sqrt(5)) / 4],
    [1 + sqrt(2), sqrt(3 + 2 * sqrt(2)), 1 / (sqrt(2) - 1)],
]


@settings(max_examples=25)
@given(
    v=st.tuples(*(st.integers(-9, 9) for _ in range(3))).filter(any),
    k=st.integers(0, len(SPELLINGS) - 1),
    choice=st.tuples(*(st.integers(0, 2) for _ in range(3))),
)
def test_algebraic_rescaling_is_the_same_point(v, k, choice):
    scaled = Point(*(SPELLINGS[k][c] * x for c, x in zip(choice, v, strict=True)))
    assert scaled == Point(*v)
    assert scaled.canonical().coords == Point(*v).canonical().coords


@pytest.mark.parametrize(
    ("call", "error"),
    [
        # an ideal point has no position: 1/0 would have given SymPy's zoo and a nan distance
        (lambda: invariants.distance_squared([0, 0, 1], [1, 2, 0]), IdealPointError),
        (lambda: invariants.signed_area([0, 0, 1], [1, 0, 0], [0, 1, 1]), IdealPointError),
        (lambda: invariants.signed_volume([0, 0, 0, 1], [1, 0, 0, 0], [0, 1, 0, 1], [0, 0, 1, 1]), IdealPointError),
        # l∞ = (0, 0, 1) has normal (0, 0); the isotropic line (1, i, 0) has normal·normal = 1 + i² = 0
        (lambda: invariants.cos2_angle([0, 0, 1], [1, 0, 0]), DegenerateConfigurationError),
        (lambda: invariants.cos2_angle([1, sympy.I, 0], [1, 0, 0]), DegenerateConfigurationError),
        # A = B, and A = D (denominator [AD][BC] = 0)
        (lambda: invariants.collinear_cross_ratio([0, 0, 1], [0, 0, 2], [1, 0, 1], [2, 0, 1]),
         UndefinedCrossRatioError),
        (lambda: invariants.collinear_cross_ratio([0, 0, 1], [1, 0, 1], [2, 0, 1], [0, 0, 3]),
         UndefinedCrossRatioError),
    ],
)
def test_euclidean_quantities_of_degenerate_input_are_named_errors(call, error):
    with pytest.raises(error):
        call()


def test_expressions_in_a_complex_indexed_root_are_decided_quickly() -> None:
    # r is a non-real root of x⁴ − 3x³ + x − 5 (irreducible over ℚ); SymPy's minimal polynomial of an
    # expression in it takes minutes, reduction modulo the root's polynomial takes milliseconds
    x = sympy.Symbol("x")
    r = sympy.CRootOf(x**4 - 3 * x**3 + x - 5, 2)
    assert not r.is_real
    assert is_zero(r**4 - 3 * r**3 + r - 5)
    assert not is_zero(r**2 + 1 - r)
    # 1/(r + 1) written two ways: (r³ − 4r² + 4r − 3)(r + 1) = r⁴ − 3r³ + r − 3 = (r⁴ − 3r³ + r − 5) + 2 = 2
    assert is_zero(1 / (r + 1) - (r**3 - 4 * r**2 + 4 * r - 3) / 2)
