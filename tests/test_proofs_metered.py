"""Counted products and cancelled denominators (pgsym.proofs.budget.metered, pgsym.proofs.evaluation): an expansion
the term estimate refuses is still run when its real products fit, and two ratios lose their common denominator
factor before they are cross-multiplied. Expected counts and polynomials are derived by hand in the comments.
"""

from __future__ import annotations

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from pgsym.proofs import budget, evaluation
from pgsym.proofs.budget import Deadline, TooLarge, estimate, metered
from pgsym.proofs.claims import Claim
from pgsym.proofs.engine import prove
from pgsym.proofs.evaluation import cancel_common_denominator, conclusion_polys, evaluate
from pgsym.proofs.polynomials import PolynomialRing

X, Y = sympy.symbols("x y")


def fourth_power(v: list, wrap: object = None) -> object:
    s = v[0] * v[0]
    return s * s


def test_the_estimate_is_above_the_real_count_and_the_count_decides():
    # (x + y)²: 2·2 = 4 products, 3 terms (the estimate keeps 4); then its square: estimate 4·4 = 16 more (20),
    # real 3·3 = 9 more (13)
    R = PolynomialRing([X, Y])
    x, y = R.gens
    assert estimate(fourth_power, [x + y], R) == 20
    assert R.to_expr(metered(fourth_power, [x + y], 13)) == sympy.expand((X + Y) ** 4)
    with pytest.raises(TooLarge, match=r"more than 1\.2e"):
        metered(fourth_power, [x + y], 12)


def test_a_product_that_would_not_end_before_the_deadline_is_not_started(monkeypatch):
    # 4 + 9 = 13 products; at one product a second, the second product (9) cannot end within a deadline of 5 s
    R = PolynomialRing([X, Y])
    x, y = R.gens
    monkeypatch.setattr(budget, "PRODUCTS_PER_SECOND", 1)
    with pytest.raises(TooLarge, match="would not end within the time left"):
        metered(fourth_power, [x + y], 100, Deadline(5))
    assert R.to_expr(metered(fourth_power, [x + y], 100, Deadline(60))) == sympy.expand((X + Y) ** 4)


def midpoint_distance() -> Claim:
    c = Claim("half", "the midpoint M of AB: |MA|² = |AB|²/4")
    A, B = c.free_point("A"), c.free_point("B")
    M = c.midpoint("M", A, B)
    c.dist2("d", M, A)
    return c


def test_a_construction_the_estimate_refuses_is_expanded_when_its_real_products_fit():
    # M = (A_x + B_x, A_y + B_y, 2) (w_B·A + w_A·B with w = 1): 6 products of one term by one.
    # |MA|²: dₓ = Mₓ·w_A − Aₓ·w_M = (A_x + B_x) − 2A_x = B_x − A_x: products 2·1 + 1·1, then dₓ·dₓ: the estimate
    # gives dₓ 2 + 1 = 3 terms (9 products), really 2 terms (4 products); the same for y; denominator
    # w_M·w_M·w_A·w_A: 3 products of one term. Estimate 2·(3 + 9) + 3 = 27, real 2·(3 + 4) + 3 = 17.
    c = midpoint_distance()
    R = PolynomialRing(c.parameters)
    d = c.nodes["d"]
    with pytest.raises(TooLarge, match=r"would need about 2\.7e"):
        evaluate(c, R, ring=R, max_work=16)
    value = evaluate(c, R, ring=R, max_work=17)[d]
    ax, ay, bx, by = sympy.symbols("A_x A_y B_x B_y")
    assert sympy.expand(R.to_expr(value[0]) - ((bx - ax) ** 2 + (by - ay) ** 2)) == 0
    assert R.to_expr(value[1]) == 4  # (w_M w_A)² = (2·1)²


def three_distances() -> Claim:
    c = Claim("not isosceles", "|AB| = |AC| for three generic points", expected=False)
    A, B, C = (c.free_point(n, homogeneous=True) for n in "ABC")
    c.conclude_equal_length(A, B, A, C)
    return c


def three_distances_conclusion() -> tuple:
    """The conclusion |AB|² = |AC|² of three_distances as an expression, and the numerators nAB, nAC and the
    weights w_A, w_B, w_C written out by hand."""
    c = three_distances()
    R = PolynomialRing(c.parameters)
    [(label, poly)] = conclusion_polys(c, evaluate(c, R, ring=R), ring=R)
    ax, ay, aw, bx, by, bw, cx, cy, cw = sympy.symbols("A_x A_y A_w B_x B_y B_w C_x C_y C_w")
    n_ab = (ax * bw - bx * aw) ** 2 + (ay * bw - by * aw) ** 2
    n_ac = (ax * cw - cx * aw) ** 2 + (ay * cw - cy * aw) ** 2
    return label, R.to_expr(poly), n_ab, n_ac, (aw, bw, cw)


def test_two_squared_distances_from_one_point_lose_its_weight_before_cross_multiplying(monkeypatch):
    # |AB|² = nAB / (w_A w_B)², |AC|² = nAC / (w_A w_C)²: the gcd of the denominators is w_A², so the conclusion
    # polynomial is nAB·w_C² − nAC·w_B² (not nAB·w_A²w_C² − nAC·w_A²w_B², its multiple by w_A²)
    monkeypatch.setattr(evaluation, "CANCEL_FROM", 0)
    label, poly, n_ab, n_ac, (_, bw, cw) = three_distances_conclusion()
    expected = n_ab * cw ** 2 - n_ac * bw ** 2
    assert label.startswith("the numerator of")
    # the gcd is defined up to its sign: the polynomial is ± the expected one
    assert sympy.expand(poly - expected) == 0 or sympy.expand(poly + expected) == 0


def test_below_the_threshold_the_denominators_are_kept():
    # the same claim: a few hundred term products, below CANCEL_FROM: nAB·(w_A w_C)² − nAC·(w_A w_B)²
    _, poly, n_ab, n_ac, (aw, bw, cw) = three_distances_conclusion()
    assert sympy.expand(poly - (n_ab * (aw * cw) ** 2 - n_ac * (aw * bw) ** 2)) == 0


def test_a_claim_whose_cross_multiplication_is_too_large_is_expanded_after_the_cancellation(monkeypatch):
    # |MA| = |MB| for the midpoint M: both denominators are (w_M w_A)² = (w_M w_B)² = 4 (equal), so the conclusion
    # is nMA − nMB with no product at all; a budget of 17 products (those of one |MA|², as counted above) is
    # then enough for each construction, and the proof is the expansion's, not the grid's
    monkeypatch.setattr(evaluation, "CANCEL_FROM", 0)
    monkeypatch.setattr(budget, "MAX_WORK", 17)
    c = Claim("midpoint", "the midpoint is equidistant from the ends")
    A, B = c.free_point("A"), c.free_point("B")
    M = c.midpoint("M", A, B)
    c.conclude_equal_length(M, A, M, B)
    v = prove(c, normalise_coordinates=False)
    assert v.status == "proved" and "grid" not in v.method


poly = st.lists(st.tuples(st.integers(-3, 3), st.integers(0, 2), st.integers(0, 2)), min_size=1, max_size=4)


def build(R: PolynomialRing, terms: list) -> object:
    x, y = R.gens
    out = R(0)
    for c, i, j in terms:
        out = out + c * x ** i * y ** j
    return out


@settings(max_examples=60, deadline=None)
@given(poly, poly, poly, poly, poly)
def test_the_cancelled_cross_product_times_the_gcd_is_the_cross_product(n1, n2, a, b, g):
    # n₁d₂ − n₂d₁ = gcd(d₁, d₂)·(n₁q₂ − n₂q₁) with qᵢ = dᵢ / gcd: the cancelled polynomial is zero exactly when
    # the original is (a polynomial ring is an integral domain and the gcd of nonzero polynomials is nonzero)
    R = PolynomialRing([X, Y])
    n1, n2, a, b, g = (build(R, t) for t in (n1, n2, a, b, g))
    d1, d2 = g * a, g * b
    if d1 == 0 or d2 == 0:
        return
    old = evaluation.CANCEL_FROM
    evaluation.CANCEL_FROM = 0
    try:
        (m1, q1), (m2, q2) = cancel_common_denominator([(n1, d1), (n2, d2)])
    finally:
        evaluation.CANCEL_FROM = old
    e = R.to_expr
    common = sympy.cancel(e(d1) / e(q1))  # dᵢ = common·qᵢ with one polynomial common to both
    assert m1 == n1 and m2 == n2 and sympy.fraction(common)[1].is_number
    assert sympy.expand(common * e(q2) - e(d2)) == 0
    assert sympy.expand(e(n1 * d2 - n2 * d1) - common * e(n1 * q2 - n2 * q1)) == 0
    assert (n1 * d2 - n2 * d1 == 0) == (n1 * q2 - n2 * q1 == 0)


def test_a_formula_that_cannot_run_on_counted_values_runs_as_it_is_when_the_estimate_fits(monkeypatch):
    # a formula that refuses counted values (as one that inspects its values' type would); with every formula
    # counted (METER_FROM = 0): within a budget its estimate fits (A_x·A_x: 1·1 = 1 term product) it runs as it
    # is; beyond it (a budget of 0), it is refused as by the estimate alone
    monkeypatch.setattr(evaluation, "METER_FROM", 0)
    c = Claim("typed", "a formula that refuses counted values")
    A = c.free_point("A")
    R = PolynomialRing(c.parameters)

    def square_x(a: tuple) -> tuple:
        if isinstance(a[0], budget.Metered):
            raise TypeError("not a polynomial")
        return (a[0] * a[0],)

    c.formula("s", "scalar", square_x, A)
    assert R.to_expr(evaluate(c, R, ring=R)[c.nodes["s"]][0]) == sympy.Symbol("A_x") ** 2
    with pytest.raises(TooLarge, match="would need about 1"):
        evaluate(c, R, ring=R, max_work=0)


@settings(max_examples=60, deadline=None)
@given(poly, poly, poly)
def test_counted_values_compute_what_the_plain_ones_do_and_count_every_product(a, b, c):
    # (a·b − c)·a + 2·c: products a·b (|a|·|b|), then (a·b − c)·a (|a·b − c|·|a|), then 2·c (1·|c|)
    R = PolynomialRing([X, Y])
    a, b, c = (build(R, t) for t in (a, b, c))

    def f(v: list, wrap: object = None) -> object:
        return (v[0] * v[1] - v[2]) * v[0] + 2 * v[2]

    terms = R.nterms
    expected = terms(a) * terms(b) + terms(a * b - c) * terms(a) + terms(c)
    assert metered(f, [a, b, c], expected) == f([a, b, c])
    if expected:
        with pytest.raises(TooLarge):
            metered(f, [a, b, c], expected - 1)
