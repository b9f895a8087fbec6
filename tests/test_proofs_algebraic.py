"""Constructions with square roots: proofs for every choice of root, named branches, counterexamples on a branch.

Every counterexample is checked again here with SymPy's own exact arithmetic (square roots, cos and sin of
rational multiples of π), not with the engine's formulas.
"""

from __future__ import annotations

import json
import time

import pytest
import sympy
from hypothesis import given, settings
from strategies import homogeneous_vectors, integers

from pgsym.errors import ObjectTypeError
from pgsym.proofs import Claim, prove
from pgsym.proofs.algebraic import (
    _annihilator,
    _branches,
    _evaluate,
    _evidently_positive,
    _framed_values,
    _primitive,
    _Tower,
)
from pgsym.proofs.budget import Deadline
from pgsym.proofs.errors import StatementKindError, StatementSyntaxError
from pgsym.proofs.language import parse_statement
from pgsym.proofs.polynomials import available_backends
from pgsym.proofs.square_roots import _cyclotomic_combination, roots_of

x = sympy.Symbol("x")


# -- helpers: the centroid as a formula of the claim, and an independent exact zero test ----------------------

def centroid(a, b, c):
    return (a[0] * b[2] * c[2] + b[0] * a[2] * c[2] + c[0] * a[2] * b[2],
            a[1] * b[2] * c[2] + b[1] * a[2] * c[2] + c[1] * a[2] * b[2], 3 * a[2] * b[2] * c[2])


def nonzero(expr) -> bool:
    """An algebraic number is nonzero exactly when its minimal polynomial is not x."""
    return sympy.minimal_polynomial(sympy.nsimplify(expr) if expr.is_Float else expr, x) != x


def timed(claim):
    start = time.perf_counter()
    v = prove(claim)
    return v, time.perf_counter() - start


def triangle(c):
    return tuple(c.free_point(n) for n in "ABC")


def bisector_line(p, b, q, internal=True):
    """The bisector at B of the angle PBQ, exactly: the line through B with direction BP/|BP| ± BQ/|BQ|."""
    u, v = sympy.Matrix(p) - sympy.Matrix(b), sympy.Matrix(q) - sympy.Matrix(b)
    d = u / sympy.sqrt(u.dot(u)) + (1 if internal else -1) * v / sympy.sqrt(v.dot(v))
    return sympy.Matrix([d[1], -d[0], d[0] * b[1] - d[1] * b[0]])  # (d_y, −d_x, d_x b_y − d_y b_x) through B


def point_of(values, name):
    return sympy.Rational(values[f"{name}_x"]), sympy.Rational(values[f"{name}_y"])


# -- angle bisectors ---------------------------------------------------------------------------------------

def test_angle_bisector_theorem_in_squared_form_is_proved_for_every_root():
    # D = b ∩ AC with b the internal bisector at B: |AD|/|DC| = |BA|/|BC|, squared and cross-multiplied
    c = Claim("bisector-theorem", "the internal bisector divides the opposite side in the ratio of the sides")
    A, B, C = triangle(c)
    b = c.angle_bisector("b", A, B, C)
    D = c.meet("D", b, c.join("AC", A, C))
    lhs = c.mul("lhs", c.dist2("AD", A, D), c.dist2("BC", B, C))
    rhs = c.mul("rhs", c.dist2("DC", D, C), c.dist2("BA", B, A))
    c.conclude_equal_ratio(lhs, rhs)
    v, t = timed(c)
    assert v.proved and t < 10
    assert v.branches.startswith("proved for every choice of root")
    assert "internal and external bisectors alike" in v.branches
    assert [str(r.symbol) for r in roots_of(c)] == ["d_A_B", "d_B_C"]


def test_the_three_internal_bisectors_are_concurrent():
    c = Claim("incentre", "the internal bisectors of a triangle meet in the incentre")
    A, B, C = triangle(c)
    c.conclude_concurrent(c.angle_bisector("a", B, A, C), c.angle_bisector("b", A, B, C),
                          c.angle_bisector("c", A, C, B))
    v, t = timed(c)
    assert v.proved and t < 10
    assert v.core_check.startswith("3 algebraic objects agree")  # with metric.angle_bisectors
    # the lengths are shared: flipping |AB| swaps internal and external at A and B together (an excentre)
    assert "swapped in pairs" in v.branches


@pytest.mark.parametrize("backend", available_backends())
def test_both_polynomial_backends_prove_the_incentre(backend):
    from pgsym.proofs.engine import prove as prove_with

    c = Claim("incentre", "the internal bisectors of a triangle meet in the incentre")
    A, B, C = triangle(c)
    c.conclude_concurrent(c.angle_bisector("a", B, A, C), c.angle_bisector("b", A, B, C),
                          c.angle_bisector("c", A, C, B))
    v = prove_with(c, backend=backend)
    assert v.proved and v.certificate.backend == backend


def test_one_internal_and_two_external_bisectors_meet_in_an_excentre():
    c = Claim("excentre", "the internal bisector at A and the external ones at B and C are concurrent")
    A, B, C = triangle(c)
    c.conclude_concurrent(c.angle_bisector("a", B, A, C), c.external_bisector("b", A, B, C),
                          c.external_bisector("c", A, C, B))
    v, t = timed(c)
    assert v.proved and t < 10


def test_two_internal_bisectors_and_one_external_are_not_concurrent():
    c = Claim("mixed", "internal bisectors at A and B, external at C, concurrent", expected=False)
    A, B, C = triangle(c)
    c.conclude_concurrent(c.angle_bisector("a", B, A, C), c.angle_bisector("b", A, B, C),
                          c.external_bisector("c", A, C, B))
    v = prove(c)
    assert v.refuted and v.as_expected
    assert "fails on the named branch" in v.branches and "c is the external bisector of ∠ACB" in v.branches
    ce = v.counterexample
    assert ce.recheck()
    # independently: the three bisectors at these rational vertices, with SymPy's square roots
    a, b, cc = (point_of(ce.values, n) for n in "ABC")
    lines = [bisector_line(b, a, cc), bisector_line(a, b, cc), bisector_line(a, cc, b, internal=False)]
    assert nonzero(sympy.Matrix.hstack(*lines).det())
    # the branch is the named one: every length root is the positive length (free points have w = 1)
    for key, value in ce.branch.items():
        p, q = (point_of(ce.values, n) for n in key.split("_")[1:])
        assert sympy.sympify(value) == sympy.sqrt((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2)


def test_a_statement_true_on_the_internal_branch_only_is_proved_for_that_branch_only():
    # A = (0, 0), B = (t², 0), C = (0, 1): |AB| = t², |AC| = 1 are polynomials, so the named branch is rational:
    # d_A_B = t², d_A_C = 1. The internal bisector at A has the direction (1, 0) + (0, 1) and passes through
    # (1, 1); with d_A_B = −t² it is the external one, direction d_A_C·(B − A) + d_A_B·(C − A) = (t², 0) − t²·(0, 1)
    # = t²·(1, −1), which does not.
    c = Claim("one-branch", "the internal bisector of ∠BAC passes through (1, 1)")
    (t,) = c.params("t")
    A, B, C = c.point("A", 0, 0), c.point("B", t * t, 0), c.point("C", 0, 1)
    c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))
    v = prove(c)
    assert v.proved
    assert v.branches.startswith("proved for the named branch only (d_A_B = t**2, d_A_C = 1")
    assert "with the sign of d_A_B changed, aᵀP does not vanish" in v.branches


def test_equal_lengths_make_the_named_branch_rational():
    # B = (t, 0), C = (0, t): |AB| = |AC| = |t|, so d_A_C = d_A_B on the named branch (whatever the sign of t):
    # the internal bisector has the direction d_A_B·(t, 0) + d_A_B·(0, t), through (1, 1)
    c = Claim("isosceles", "the internal bisector of a right isosceles angle at the origin is y = x")
    (t,) = c.params("t")
    A, B, C = c.point("A", 0, 0), c.point("B", t, 0), c.point("C", 0, t)
    c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))
    v = prove(c)
    assert v.proved and v.branches.startswith("proved for the named branch only (d_A_C = d_A_B")


def test_a_named_branch_without_an_evident_sign_stays_unknown():
    # B = (t, 0), C = (0, t(t⁴ − t + 1)): |AC|² = λ²|AB|² with λ = t⁴ − t + 1, positive (its minimum, at 4t³ = 1, is
    # 1 − (3/4)·4^(−1/3) > 0) but neither a sum of even powers nor of degree 2, so the engine cannot see that
    # d_A_C = λ d_A_B on the named branch: the internal bisector passes through (1, 1) at every instance it tries, the
    # external one does not, and the verdict is unknown
    c = Claim("not-evident", "the internal bisector of ∠BAC passes through (1, 1)")
    (t,) = c.params("t")
    A, B, C = c.point("A", 0, 0), c.point("B", t, 0), c.point("C", 0, t * (t**4 - t + 1))
    c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))
    v = prove(c)
    assert v.status == "unknown" and not v.proved
    assert v.branches.startswith("holds on the named branch only (a is the internal bisector of ∠BAC)")
    assert "not proved" in v.branches and "a is the external bisector of ∠BAC" in v.branches


def test_a_quadratic_multiplier_positive_by_its_form_is_proved_on_the_named_branch():
    # B = (t, 0), C = (0, t(t² − t + 1)): λ = t² − t + 1 = (t − 1/2)² + 3/4 has the positive definite form
    # [[1, −1/2], [−1/2, 1]] in (t, 1) (minors 1, 1 and 3/4), so d_A_C = λ d_A_B on the named branch, and the internal
    # bisector, direction d_A_C·(B − A) + d_A_B·(C − A) = λ d_A_B·(t, 0) + d_A_B·(0, tλ) = tλ d_A_B·(1, 1), passes
    # through (1, 1)
    c = Claim("quadratic", "the internal bisector of ∠BAC passes through (1, 1)")
    (t,) = c.params("t")
    A, B, C = c.point("A", 0, 0), c.point("B", t, 0), c.point("C", 0, t * (t * t - t + 1))
    c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))
    v = prove(c)
    assert v.proved and v.branches.startswith("proved for the named branch only (d_A_C = d_A_B*(t**2 - t + 1)")


def test_a_polynomial_ratio_of_lengths_with_an_evident_sign_is_proved_on_the_named_branch():
    # B = (t, 0), C = (0, t³): |AC| = t²|AB|, so d_A_C = t² d_A_B on the named branch
    c = Claim("evident", "the internal bisector of ∠BAC passes through (1, 1)")
    (t,) = c.params("t")
    A, B, C = c.point("A", 0, 0), c.point("B", t, 0), c.point("C", 0, t**3)
    c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))
    v = prove(c)
    assert v.proved and v.branches.startswith("proved for the named branch only (d_A_C = d_A_B*t**2")


RIGHT_TRIANGLE = "points c a\npoint b on line (perpendicular (join c a) c)\npoint d = foot c (join a b)\n"


def test_a_product_of_lengths_proves_the_named_branch_in_a_right_triangle():
    # C = (0, 0), A = (1, 0), B = (0, b), b > 0 (every right triangle up to similarity); s = |AB| = √(1 + b²); the foot
    # of C on AB is D = (b², b)/s². Internal bisector of ∠CAB: direction (C − A)/1 + (B − A)/s ∝ (−s − 1, b); of
    # ∠DCB: D/|D| + B/b = (b, 1)/s + (0, 1) ∝ (b, 1 + s). Dot product: −b(s + 1) + b(1 + s) = 0: perpendicular. No
    # length is a polynomial multiple of another (|AB|² = b² + 1, |CD|² ∝ b²(b² + 1)): only a product of three
    # lengths is a polynomial on the named branch, |CD|·|AB| = |CA|·|CB|
    c = parse_statement(RIGHT_TRIANGLE + "line u = anglebisector c a b\nline v = anglebisector d c b\n"
                        "prove perpendicular u v")
    v, t = timed(c)
    assert v.proved and t < 10
    assert v.branches.startswith("proved for the named branch only (") and "·" in v.branches.split(":")[0]
    assert "does not vanish" in v.branches
    assert any("|" in cond.text and "≠ 0 (divided by on the named branch)" in cond.text for cond in v.conditions)


@pytest.mark.parametrize("changed", ["line u = exbisector c a b\nline v = anglebisector d c b",
                                     "line u = anglebisector c a b\nline v = exbisector d c b"])
def test_the_same_right_triangle_with_an_external_bisector_is_not_proved(changed):
    # as above with s = |AB|: the external bisector at A has the direction (−1, 0) − (−1, b)/s ∝ (1 − s, −b), and
    # (1 − s, −b)·(b, 1 + s) = −2bs ≠ 0; the external one at C is perpendicular to the internal one there, hence
    # parallel to the internal bisector at A (not perpendicular). The other branch holds, the named one fails.
    c = parse_statement(RIGHT_TRIANGLE + changed + "\nprove perpendicular u v", name="wrong-branch")
    v = prove(c)
    assert not v.proved and v.refuted
    assert v.branches.startswith("fails on the named branch") and v.counterexample.recheck()


def test_a_product_over_earlier_lengths_with_a_squared_distance_as_sign():
    # the tangent at A of the circle ABC meets BC at E, and the internal bisector of ∠BAC meets BC at H. The
    # tangent-chord angle gives ∠EAC = ∠B (E beyond C), so ∠EAH = ∠B + ∠A/2 = ∠EHA (exterior angle of triangle ABH):
    # triangle EAH is isosceles, EA = EH, and the bisector at E of ∠AEH = ∠BEA is perpendicular to AH. In the frame
    # A = (0, 0), B = (1, 0) the proof uses |AC|·|BE|·|AE| = λ, whose sign needs the factor (c_x − 1)² + c_y²
    # (|BC|²) positive: its form in (c_x, c_y, 1), [[1, 0, −1], [0, 1, 0], [−1, 0, 1]], has the principal minors
    # 1, 1, 1, 1, 0, 1 and 0, all ≥ 0 (without that the verdict is unknown)
    c = parse_statement("points a b c\npoint d = centre (circle b a c)\n"
                        "point e = meet (perpendicular (join a d) a) (join b c)\nline u = anglebisector b e a\n"
                        "line v = anglebisector b a c\nprove perpendicular u v")
    v, t = timed(c)
    assert v.proved and t < 10 and v.branches.startswith("proved for the named branch only (")


CYCLIC = ("points a b\npoint c on circle (circle a b) through b\npoint d on circle (circle a b) through b\n"
          "point e on circle (circle a b) through b\npoint f = meet (join b c) (join d e)\n"
          "point g = meet (join c d) (join b e)\nline u = anglebisector d f b\nline v = anglebisector c g b\n")


def test_bisectors_at_the_meets_of_opposite_sides_of_a_cyclic_quadrilateral_are_perpendicular_where_they_meet():
    # B, C, D, E on a circle, F = BC ∩ DE, G = CD ∩ BE; lines BC, DE, CD, BE at the angles β₁, β₂, γ₁, γ₂ (mod π).
    # Inscribed angles (directed, mod π): ∠(CD, CB) = ∠(ED, EB), i.e. β₁ − γ₁ = γ₂ − β₂, so β₁ + β₂ = γ₁ + γ₂ and the
    # bisectors at F, at the angles (β₁ + β₂)/2 mod π/2, are each parallel or perpendicular to those at G: wherever u
    # and v meet in a finite point they are perpendicular (whichever sign each length root takes)
    v = prove(parse_statement(CYCLIC + "point j = meet u v\npoint k = reflect j a  # j is a finite point\n"
                              "prove perpendicular u v"))
    assert v.proved and v.branches.startswith("proved for every choice of root")
    assert v.certificate.steps[-1].endswith("it vanishes wherever j is a finite point")
    # without the finite meet the internal bisectors are parallel in some figures (the order of the points on the
    # circle decides), so the claim is not proved
    assert not prove(parse_statement(CYCLIC + "prove perpendicular u v")).proved


def test_a_conclusion_scaled_by_free_points_is_tested_against_a_condition_without_its_scale():
    # as above, with the lines through F and G given by free points H on u and I on v: the conclusion is the one above
    # times factors of h_t, i_t without roots (hundreds of thousands of terms), and multiplying it by the finite-meet
    # condition took minutes; its primitive part (the factors without roots divided out) has a few hundred terms
    statement = CYCLIC.replace("line v", "point h on line u\nline v") + (
        "point i on line v\npoint j = meet (join f h) (join g i)\npoint k = reflect j a  # j is a finite point\n"
        "prove perpendicular (join g i) (join f h)")
    start = time.perf_counter()
    v = prove(parse_statement(statement), timeout=60)
    assert v.proved and time.perf_counter() - start < 30
    assert v.certificate.steps[-1].endswith("it vanishes wherever j is a finite point")


def right_angle_tower():
    # A = (0, 0), B = (t, 0), C = (0, 1): the length root d = d_A_B has d² = t², a square: d − t and d + t are zero
    # divisors modulo d² − t², since (d − t)(d + t) = d² − t²
    c = Claim("tower", "x")
    (t,) = c.params("t")
    A, B, C = c.point("A", 0, 0), c.point("B", t, 0), c.point("C", 0, 1)
    c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))
    _norm, tower, _values = _framed_values(c, None, Deadline(None), None)
    R = tower.R
    return tower, R(sympy.Symbol("d_A_B")), R(t)


def test_a_primitive_part_divides_out_the_factors_without_roots():
    tower, d, t = right_angle_tower()
    p = (d + t) * (t * t + 1) * 6
    q = _primitive(tower, p)
    # p = 6(t² + 1)·(d + t): the gcd of p at d = 2 and d = −5 is a multiple of (t² + 1) times a constant, and the
    # quotient is (d + t) up to a rational factor
    assert divmod(p, q)[1] == 0
    ratio = [c for _, c in tower.R.terms(q)]
    assert tower.R.nterms(q) == 2 and ratio[0] == ratio[1]
    assert _primitive(tower, t * t + 1) == t * t + 1  # no roots: unchanged


def test_a_condition_kills_the_conclusion_only_as_a_zero_divisor():
    tower, d, t = right_angle_tower()
    kills = _annihilator(tower, (d + t) * (t + 3), Deadline(None))
    assert kills(d - t)           # (d − t)(d + t)(t + 3) = (d² − t²)(t + 3) ≡ 0
    assert not kills(d + 2 * t)   # (d + 2t)(d + t) = d² + 3td + 2t² ≡ 3td + 3t² ≠ 0
    assert not kills(t + 1)       # no roots: (t + 1)(d + t)(t + 3) is a nonzero normal form
    assert kills(tower.R.constant(0))


@settings(max_examples=60, deadline=None)
@given(integers(5), integers(5), integers(5), integers(5), integers(5), integers(5), integers(3), integers(3),
       integers(4), integers(4))
def test_evidently_positive_forms_are_never_negative(a, b, c, e, f, g, u, w, x0, y0):
    # f = u²·(a x + b y + c)² + w²·(e x² + f y + g)², a sum of squares of polynomials; the claim "positive wherever
    # not 0" must hold at every point tried, and the form itself (or its negative minus 1) at (x0, y0) decides it
    x, y = sympy.symbols("x y")
    poly = sympy.expand(u**2 * (a * x + b * y + c) ** 2 + w**2 * (e * x**2 + f * y + g) ** 2)
    for candidate in (poly, -poly - 1, poly - (x0**2 + 1)):
        if candidate != 0 and _evidently_positive(candidate, [x, y]):
            for px, py in ((x0, y0), (y0, x0), (0, 0), (x0, 0), (1, -1)):
                assert candidate.subs({x: px, y: py}) >= 0
    if u and (a or b) and not (e or f or g or w):  # a nonzero square of a linear form: recognised by its form
        assert _evidently_positive(poly, [x, y])


def test_wu_half_angle_parametrisation_proves_the_internal_bisector():
    # B = 0, A = p²(1 − t², 2t), C = q²(1 − u², 2u): |BA| = p²(1 + t²), |BC| = q²(1 + u²) (every configuration
    # has this form); the internal bisector passes through B + (1 − t², 2t)/(1 + t²) + (1 − u², 2u)/(1 + u²)
    c = Claim("wu", "the internal bisector through the sum of the unit vectors")
    p, q, t, u = c.params("p q t u")
    B = c.point("B", 0, 0)
    A = c.point("A", p * p * (1 - t * t), 2 * p * p * t)
    C = c.point("C", q * q * (1 - u * u), 2 * q * q * u)
    E = c.point("E", (1 - t * t) * (1 + u * u) + (1 - u * u) * (1 + t * t), 2 * t * (1 + u * u) + 2 * u * (1 + t * t),
                (1 + t * t) * (1 + u * u))
    c.conclude_incident(E, c.angle_bisector("b", A, B, C))
    v, elapsed = timed(c)
    assert v.proved and elapsed < 10
    assert "d_A_B = p**2*(t**2 + 1)" in v.branches and "does not vanish" in v.branches


def test_the_same_statement_for_the_external_bisector_fails_on_the_named_branch():
    c = Claim("one-branch-false", "the external bisector of ∠BAC passes through (1, 1)", expected=False)
    (t,) = c.params("t")
    A, B, C = c.point("A", 0, 0), c.point("B", t * t, 0), c.point("C", 0, 1)
    c.conclude_incident(c.point("P", 1, 1), c.external_bisector("e", B, A, C))
    v = prove(c)
    assert v.refuted and v.counterexample.recheck()
    t0 = sympy.Rational(v.counterexample.values["t"])
    # independently: the external bisector at A = (0, 0) of B = (t0², 0), C = (0, 1) misses (1, 1)
    line = bisector_line((t0**2, 0), (0, 0), (0, 1), internal=False)
    assert nonzero(line.dot(sympy.Matrix([1, 1, 1])))


# -- a line and a circle, two circles, tangents ----------------------------------------------------------------

def test_a_line_through_the_centre_meets_the_circle_in_points_symmetric_about_it():
    c = Claim("diameter", "a line through the centre meets the circle in two points with midpoint the centre")
    O, A, P = (c.free_point(n) for n in "OAP")
    K = c.circle("K", O, A)
    X, Y = c.line_conic_intersections(("X", "Y"), c.join("l", O, P), K)
    c.conclude_proportional(c.midpoint("M", X, Y), O)
    c.conclude_on_conic(X, K)
    v, t = timed(c)
    assert v.proved and t < 10
    assert "both common points of every intersection" in v.branches


def test_one_unnamed_intersection_must_work_for_both_roots():
    # X is either point of the line OA on the circle: one of them is A itself, whose midpoint with A is A ≠ O
    c = Claim("antipode", "the line OA meets the circle again in the reflection of A in O", expected=False)
    O, A = c.free_point("O"), c.free_point("A")
    K = c.circle("K", O, A)
    X = c.line_conic_intersection("X", c.join("l", O, A), K)
    c.conclude_proportional(c.midpoint("M", X, A), O)
    v = prove(c)
    assert v.refuted and v.counterexample.recheck()
    o, a = (point_of(v.counterexample.values, n) for n in "OA")
    # independently: the two points of the line OA on the circle are A and 2O − A; one of them is A
    s = sympy.Symbol("s")
    pts = [tuple(o[i] + r * (a[i] - o[i]) for i in range(2)) for r in sympy.solve(s**2 - 1, s)]
    assert a in pts and tuple(2 * o[i] - a[i] for i in range(2)) in pts
    assert f"X = ({a[0]}, {a[1]})" in v.branches  # the failing root is A itself


def test_tangents_from_an_external_point_have_equal_length():
    c = Claim("tangent-lengths", "the two tangents from a point have equal length")
    O, A, P = (c.free_point(n) for n in "OAP")
    K = c.circle("K", O, A)
    S, T = c.line_conic_intersections(("S", "T"), c.polar("p", K, P), K)
    c.conclude_equal_ratio(c.dist2("PS", P, S), c.dist2("PT", P, T))
    v, t = timed(c)
    assert v.proved and t < 10
    assert "similarity frame" in v.certificate.normalisation  # O = (0, 0), A = (1, 0) without loss of generality


def test_the_tangents_from_a_point_touch_the_circle():
    c = Claim("tangents", "the lines tangentsfrom P K touch K")
    O, A, P = (c.free_point(n) for n in "OAP")
    K = c.circle("K", O, A)
    s, t_ = c.tangents_from(("s", "t"), P, K)
    c.conclude_tangent(s, K)
    c.conclude_tangent(t_, K)
    v, t = timed(c)
    assert v.proved and t < 10


def test_the_common_points_of_two_circles_lie_on_both():
    c = Claim("two-circles", "the common points of two circles lie on both")
    O, A, Q, B = (c.free_point(n) for n in "OAQB")
    K, L = c.circle("K", O, A), c.circle("L", Q, B)
    X, Y = c.circle_intersections(("X", "Y"), K, L)
    c.conclude_on_conic(X, L)
    c.conclude_on_conic(Y, K)
    v, t = timed(c)
    assert v.proved and t < 10
    assert v.core_check.startswith("2 algebraic objects agree with pgsym's core")


# -- rotations and regular polygons -------------------------------------------------------------------------

def _napoleon(angles):
    c = Claim("napoleon", "Napoleon's theorem", expected=len(set(angles)) == 1)
    A, B, C = triangle(c)
    tips = [c.rotate_degrees(n, p, q, a) for n, p, q, a in zip("XYZ", (C, A, B), (B, C, A), angles, strict=True)]
    n1 = c.formula("N1", "point", centroid, B, C, tips[0])
    n2 = c.formula("N2", "point", centroid, C, A, tips[1])
    n3 = c.formula("N3", "point", centroid, A, B, tips[2])
    r1, r2, r3 = (c.dist2(f"r{i}", p, q) for i, (p, q) in
                  enumerate(((n1, n2), (n2, n3), (n3, n1)), start=1))
    c.conclude_equal_ratio(r1, r2)
    c.conclude_equal_ratio(r2, r3)
    return c


def test_napoleon_theorem_holds_for_every_conjugate_of_the_sixth_root_of_unity():
    v, t = timed(_napoleon((-60, -60, -60)))
    assert v.proved and t < 10
    assert v.core_check.startswith("3 algebraic objects agree with pgsym's core")  # metric.rotation(1/2, −√3/2)
    assert "ζ = e^(2πi/12)" in v.branches  # cos 60° = (ζ + ζ⁻¹)/2, sin 60° with i = ζ³


def test_napoleon_with_one_triangle_turned_the_other_way_fails():
    v = prove(_napoleon((-60, -60, 60)))
    assert v.refuted and v.counterexample.recheck()
    a, b, cc = (sympy.Matrix(point_of(v.counterexample.values, n)) for n in "ABC")

    def rot(p, o, deg):
        th = sympy.pi * deg / 180
        return o + sympy.Matrix([[sympy.cos(th), -sympy.sin(th)], [sympy.sin(th), sympy.cos(th)]]) * (p - o)

    n1 = (b + cc + rot(cc, b, -60)) / 3
    n2 = (cc + a + rot(a, cc, -60)) / 3
    n3 = (a + b + rot(b, a, 60)) / 3
    sides = [(p - q).dot(p - q) for p, q in ((n1, n2), (n2, n3), (n3, n1))]
    assert nonzero(sympy.expand(sides[0] - sides[1])) or nonzero(sympy.expand(sides[1] - sides[2]))


def test_regular_pentagon_diagonal_ratio_satisfies_the_golden_equation():
    # d/s = φ, so r = d²/s² = φ² = (3 + √5)/2 satisfies r² − 3r + 1 = 0 (and so does the pentagram's 1/φ²)
    c = Claim("pentagon", "diagonal and side of a regular pentagon: d⁴ − 3d²s² + s⁴ = 0")
    A, B = c.free_point("A"), c.free_point("B")
    C = c.polygon_vertex("C", A, B, 5, 2)
    s, d = c.dist2("s", A, B), c.dist2("d", A, C)
    c.conclude_equal_ratio(c.add("d2 + s2", c.mul("d2", d, d), c.mul("s2", s, s)), c.mul("3ds", c.mul("ds", d, s), 3))
    v, t = timed(c)
    assert v.proved and t < 10
    assert "star polygons" in v.branches


def test_a_wrong_pentagon_ratio_is_refuted_at_the_principal_root():
    c = Claim("pentagon-wrong", "d² = 3/2 s² in a regular pentagon", expected=False)
    A, B = c.free_point("A"), c.free_point("B")
    C = c.polygon_vertex("C", A, B, 5, 2)
    c.conclude_equal_ratio(c.dist2("d", A, C), c.mul("s", c.dist2("AB", A, B), sympy.Rational(3, 2)))
    v = prove(c)
    assert v.refuted and v.counterexample.recheck()
    a, b = (point_of(v.counterexample.values, n) for n in "AB")
    # independently: |AC|² = φ²|AB|² with φ = (1 + √5)/2, which is not 3/2 |AB|²
    s2 = (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2
    assert nonzero(((1 + sympy.sqrt(5)) / 2) ** 2 * s2 - sympy.Rational(3, 2) * s2)


@pytest.mark.parametrize("internal", [True, False])
def test_the_bisector_of_an_equilateral_triangle_mixes_a_root_of_unity_and_lengths(internal):
    # C = B rotated about A by 60°: |AC| = |AB|; with C's representative w_C = 2 the roots are d_A_C = 2 d_A_B on
    # the named branch. The internal bisector at A is the median to BC; the external one is not.
    c = Claim("equilateral", "the bisector at A passes through the midpoint of BC", expected=internal)
    A, B = c.free_point("A"), c.free_point("B")
    C = c.rotate_degrees("C", B, A, 60)
    b = (c.angle_bisector if internal else c.external_bisector)("b", B, A, C)
    c.conclude_incident(c.midpoint("M", B, C), b)
    v = prove(c)
    if internal:
        # without loss of generality A = (0, 0), B = (1, 0): then |AB| = 1 and d_A_C = w_A w_C |AC| = 2·1
        assert v.proved and v.branches.startswith("proved for the named branch only (d_A_B = 1, d_A_C = 2")
        assert "similarity frame" in v.certificate.normalisation
        return
    assert v.refuted and v.counterexample.recheck()
    a, b_ = (sympy.Matrix(point_of(v.counterexample.values, n)) for n in "AB")
    cc = a + sympy.Matrix([[sympy.Rational(1, 2), -sympy.sqrt(3) / 2], [sympy.sqrt(3) / 2, sympy.Rational(1, 2)]]) * (
        b_ - a)
    m = (b_ + cc) / 2
    assert nonzero(sympy.expand(bisector_line(b_, a, cc, internal=False).dot(sympy.Matrix([m[0], m[1], 1]))))


@pytest.mark.parametrize("n", range(3, 14))
def test_every_regular_polygon_closes_and_has_equal_sides(n):
    c = Claim(f"polygon-{n}", f"the regular {n}-gon: vertex n is A, and |V1 V2| = |AB|")
    A, B = c.free_point("A"), c.free_point("B")
    V2 = c.polygon_vertex("V2", A, B, n, 2)
    c.conclude_equal_ratio(c.dist2("s", A, B), c.dist2("t", B, V2))
    v, t = timed(c)
    assert v.proved and t < 10


@pytest.mark.parametrize("n", [7, 13])
def test_six_vertices_of_a_regular_polygon_lie_on_a_conic(n):
    # they lie on the circumcircle; ζ_28 and ζ_52 have degree φ(28) = 12 and φ(52) = 24
    c = Claim(f"polygon-{n}-conic", "six vertices of a regular polygon lie on a conic")
    A, B = c.free_point("A"), c.free_point("B")
    c.conclude_conconic(A, B, *(c.polygon_vertex(f"V{k}", A, B, n, k) for k in range(2, 6)))
    v, t = timed(c)
    assert v.proved and t < 10 and f"e^(2πi/{4 * n})" in v.branches


@settings(max_examples=25, deadline=None)
@given(integers(40), integers(6))
def test_cosine_and_sine_of_a_rational_angle_as_polynomials_in_a_root_of_unity(k, n):
    # 2 cos(2πk/M) and 2 sin(2πk/M) as integer polynomials in ζ = e^{2πi/M}, checked against SymPy's cos, sin
    m = 4 * (abs(n) + 1)
    zeta = sympy.exp(2 * sympy.pi * sympy.I / m)
    angle = 2 * sympy.pi * k / m
    for imaginary, expected in ((False, 2 * sympy.cos(angle)), (True, 2 * sympy.sin(angle))):
        terms = _cyclotomic_combination(m, [k], imaginary)
        value = sum(c * zeta**e for e, c in terms)
        assert abs(complex(sympy.N(value - expected, 30))) < 1e-20


@settings(max_examples=30, deadline=None)
@given(homogeneous_vectors(3, allow_ideal=False), homogeneous_vectors(3, allow_ideal=False),
       homogeneous_vectors(3, allow_ideal=False))
def test_the_named_branch_is_the_internal_bisector_for_any_representatives(a, b, cc):
    # points with any nonzero w (negative ones too): on the named branch the engine's line is the internal
    # bisector computed here from the inhomogeneous points with SymPy's square roots (and the external one
    # on the branch with one length negated)
    pa, pb, pc = ([sympy.Rational(v[0], v[2]), sympy.Rational(v[1], v[2])] for v in (a, b, cc))
    if pa == pb or pc == pb:
        return
    c = Claim("bisector", "x")
    A, B, C = (c.point(n, *v) for n, v in zip("ABC", (a, b, cc), strict=True))
    c.angle_bisector("b", A, B, C)
    tower = _Tower(c, [])
    values = _evaluate(c, lambda e: tower.R(e), tower, Deadline(None))
    line = values[c.nodes["b"]]
    for branch in _branches(c, tower, values, {}):
        mine = sympy.Matrix([tower.R.to_expr(v).xreplace(branch.values) if not isinstance(v, int) else v
                             for v in line])
        internal = all(s > 0 for s in branch.signs.values()) or all(s < 0 for s in branch.signs.values())
        exact = bisector_line(pa, pb, pc, internal=internal)
        if all(not nonzero(sympy.expand(e)) for e in exact):
            continue  # A, B, C on a line with A, C on opposite sides: the bisector is undefined
        assert all(not nonzero(sympy.expand(e)) for e in mine.cross(exact)), (branch.text, mine, exact)
        assert ("internal" in branch.text) == internal


@settings(max_examples=20, deadline=None)
@given(homogeneous_vectors(3, allow_ideal=False), homogeneous_vectors(3, allow_ideal=False),
       integers(12))
def test_a_rotation_by_degrees_agrees_with_sympy_cos_and_sin(x_, o_, k):
    # rotate X about O by 15k degrees, any representatives: on ζ = e^{2πi/M} the engine's point is
    # O + R(X − O) with R built here from SymPy's exact cos and sin of 15k°
    degrees = 15 * k
    c = Claim("rotation", "x")
    c.rotate_degrees("Y", c.point("X", *x_), c.point("O", *o_), degrees)
    tower = _Tower(c, [])
    values = _evaluate(c, lambda e: tower.R(e), tower, Deadline(None))
    (branch,) = _branches(c, tower, values, {})
    y = [tower.R.to_expr(v).xreplace(branch.values) if not isinstance(v, int) else sympy.Integer(v)
         for v in values[c.nodes["Y"]]]
    px, po = (sympy.Matrix([sympy.Rational(v[0], v[2]), sympy.Rational(v[1], v[2])]) for v in (x_, o_))
    th = sympy.pi * degrees / 180
    expected = po + sympy.Matrix([[sympy.cos(th), -sympy.sin(th)], [sympy.sin(th), sympy.cos(th)]]) * (px - po)
    for i in range(2):
        assert not nonzero(sympy.expand(y[i] - expected[i] * y[2]))


# -- the statement language -----------------------------------------------------------------------------------

def test_statements_with_square_roots_are_read_and_decided():
    cases = {
        "points A B C\nline a = anglebisector B A C\nline b = anglebisector A B C\nline c = anglebisector A C B\n"
        "prove concurrent a b c": "proved",
        "points A B C\nline a = anglebisector B A C\nline b = anglebisector A B C\nline c = exbisector A C B\n"
        "prove concurrent a b c": "false",
        "conics K\nlines l\npoints X Y = intersections l K\nprove on X K\nprove on Y l": "proved",
        "points P\nconics K\nlines s t = tangentsfrom P K\nprove tangent s K\nprove tangent t K": "proved",
        "points P\nconics K\nline t = tangentfrom P K\nprove tangent t K": "proved",
        "points A B\npoint C = polygon A B 6 2\npoint E = rotate B A -120\npoint D = polygon A B 6 0\n"
        "prove equal D A\nprove collinear A B (midpoint A B)": "proved",
        "points A B\npoint C = polygon A B 4 2\npoint D = rotate A B -90\nprove equal C D": "proved",
        "points A B\npoint C = polygon A B 4 2\npoint D = rotate A B 90\nprove equal C D": "false",
    }
    for text, status in cases.items():
        assert prove(parse_statement(text)).status == status, text


EUCLIDEAN = {  # with the rational Euclidean constructions of the language (circle, dist2, equallength, …)
    "diameter": ("points O A P\nconic K = circle O A\nline l = join O P\npoints X Y = intersections l K\n"
                 "point M = midpoint X Y\nprove equal M O", "proved"),
    "tangents": ("points O A P\nconic K = circle O A\nlines s t = tangentsfrom P K\n"
                 "points S T = intersections (polar K P) K\nprove equallength P S P T\nprove tangent s K", "proved"),
    "radical axis": ("points O A Q B\nconic K = circle O A\nconic L = circle Q B\npoints X Y = intersections K L\n"
                     "prove on X L\nprove perpendicular (join X Y) (join O Q)", "proved"),
    "bisector theorem": ("points A B C\nline b = anglebisector A B C\npoint D = meet b (join A C)\n"
                         "prove equal (mul (dist2 A D) (dist2 B C)) (mul (dist2 D C) (dist2 B A))", "proved"),
    "bisectors perpendicular": ("points A B C\nline b = anglebisector A B C\nline e = exbisector A B C\n"
                                "prove perpendicular b e", "proved"),
    "pentagon": ("points A B\npoint C = polygon A B 5 2\npoint D = polygon A B 5 3\nprove concyclic A B C D\n"
                 "prove equallength A C B D", "proved"),
    "napoleon": ("points A B C\npoint X = rotate C B -60\npoint Y = rotate A C -60\npoint Z = rotate B A -60\n"
                 "point N1 = centre (circle B C X)\npoint N2 = centre (circle C A Y)\n"
                 "point N3 = centre (circle A B Z)\nprove equallength N1 N2 N2 N3\nprove equallength N2 N3 N3 N1",
                 "proved"),
    "napoleon mixed": ("expect false\npoints A B C\npoint X = rotate C B -60\npoint Y = rotate A C -60\n"
                       "point Z = rotate B A 60\npoint N1 = centre (circle B C X)\npoint N2 = centre (circle C A Y)\n"
                       "point N3 = centre (circle A B Z)\nprove equallength N1 N2 N2 N3\n"
                       "prove equallength N2 N3 N3 N1", "false"),
    "antipode": ("expect false\npoints O A\nconic K = circle O A\npoint X = intersection (join O A) K\n"
                 "prove equal (midpoint X A) O", "false"),
}


@pytest.mark.parametrize("name", EUCLIDEAN)
def test_square_roots_with_the_euclidean_constructions(name):
    text, status = EUCLIDEAN[name]
    v, t = timed(parse_statement(text, name=name))
    assert v.status == status and t < 10, v.summary()
    if status == "false":
        assert v.counterexample.recheck()
    if name == "antipode":  # X = A on the failing branch: its coordinates are those of A
        a = point_of(v.counterexample.values, "A")
        assert f"X = ({a[0]}, {a[1]})" in v.branches


def test_rotate_with_an_angle_in_degrees_is_a_root_of_unity_and_rotate_by_90_is_rational():
    c = parse_statement("points X O\npoint Y = rotate X O 60\npoint Z = rotate X O 90\nprove equal Y Y")
    assert [str(r.symbol) for r in roots_of(c)] == ["zeta_12"]


@pytest.mark.parametrize(("text", "error"), [
    ("points A B C\npoint b = anglebisector A B C\nprove on A b", StatementKindError),
    ("points A B\nlines l\npoint X = intersections l A\nprove on X l", StatementKindError),
    ("points A B\npoints X Y = intersection A B\nprove collinear A B X", StatementKindError),
    ("points A B\npoint C = polygon A B 5/2 1\nprove collinear A B C", StatementSyntaxError),
    ("points A B\npoint polygon = polygon A B 5 1\nprove collinear A B A", Exception),
    ("points A B\nline l = anglebisector A B\nprove on A l", StatementKindError),
])
def test_malformed_square_root_statements_raise_named_errors(text, error):
    with pytest.raises(error):
        parse_statement(text)


def test_more_than_eight_square_roots_are_refused():
    # every choice of signs is visited: 2⁸ branches at most; five points give ten lengths
    c = Claim("many", "x")
    P = [c.free_point(f"P{i}") for i in range(5)]
    for i, (a, b, d) in enumerate(((1, 0, 2), (3, 0, 4), (2, 1, 3), (4, 1, 2))):  # lengths 01 02 03 04 12 13 14
        c.angle_bisector(f"b{i}", P[a], P[b], P[d])
    with pytest.raises(ObjectTypeError, match="more than 8 square roots"):
        c.angle_bisector("b4", P[3], P[2], P[4])  # 23 and 24: the ninth length is refused
    assert len(roots_of(c)) == 8


def test_polygon_and_rotation_arguments_are_checked():
    c = Claim("x", "x")
    A, B = c.free_point("A"), c.free_point("B")
    with pytest.raises(ObjectTypeError):
        c.polygon_vertex("P", A, B, 2, 1)
    with pytest.raises(ObjectTypeError):
        c.rotate_degrees("R", A, B, 1.5)


# -- the verdict says which roots it covers ---------------------------------------------------------------------

def test_the_branch_semantics_are_in_every_output():
    c = Claim("mixed", "internal bisectors at A and B, external at C, concurrent", expected=False)
    A, B, C = triangle(c)
    c.conclude_concurrent(c.angle_bisector("a", B, A, C), c.angle_bisector("b", A, B, C),
                          c.external_bisector("c", A, C, B))
    v = prove(c)
    data = json.loads(v.to_json())
    assert data["branches"].startswith("fails on the named branch")
    assert set(data["counterexample"]["branch"]) == {"d_A_B", "d_A_C", "d_B_C"}
    assert "on the roots:" in v.summary() and "*Roots:*" in v.to_markdown() and "Roots:" in v.to_latex()


def test_the_command_line_says_which_roots_a_verdict_covers(tmp_path):
    from click.testing import CliRunner

    from pgsym.cli import main

    (tmp_path / "incentre.thm").write_text("points A B C\nline a = anglebisector B A C\nline b = anglebisector A B C\n"
                                           "line c = anglebisector A C B\nprove concurrent a b c\n")
    (tmp_path / "mixed.thm").write_text("expect false\npoints A B C\nline a = anglebisector B A C\n"
                                        "line b = anglebisector A B C\nline c = exbisector A C B\n"
                                        "prove concurrent a b c\n")
    result = CliRunner().invoke(main, ["prove", str(tmp_path / "incentre.thm"), str(tmp_path / "mixed.thm")])
    assert result.exit_code == 0, result.output
    assert "[proved for every choice of root]" in result.output
    assert "[fails on the named branch]" in result.output
    result = CliRunner().invoke(main, ["prove", "--json", str(tmp_path / "mixed.thm")])
    (data,) = json.loads(result.output[result.output.index("["):])  # after the progress line on stderr
    assert data["status"] == "false" and set(data["counterexample"]["branch"]) == {"d_A_B", "d_A_C", "d_B_C"}
