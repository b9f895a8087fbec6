"""The engine never proves what is not so: degenerate constructions, normalisation, equation hypotheses, backends."""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import incidence_programs

from pgsym import ring as alg
from pgsym.proofs import Claim, catalogue_names, get_claim, prove
from pgsym.proofs.engine import prove as prove_claim
from pgsym.proofs.normalisation import normalise
from pgsym.proofs.polynomials import available_backends

# -- constructions that vanish identically ---------------------------------------------------------------


def _line_meets_plane(v):
    # line AB meets the plane π at (π·B) A − (π·A) B; when π contains A and B both brackets are 0
    a, b, pi = v
    pa, pb = alg.dot(pi, a), alg.dot(pi, b)
    return tuple(pb * x - pa * y for x, y in zip(a, b, strict=True))


def test_line_meeting_a_plane_that_contains_it_is_degenerate_not_proved():
    # the unsound case of the issue: π = plane(A, B, C) contains AB, so X = (π·B)A − (π·A)B = 0·A − 0·B is
    # the zero vector for every A, B, C, and det[X P Q R] = 0 "proved" that X, P, Q, R are coplanar
    c = Claim("line-in-plane", "AB meets a plane through AB")
    A, B, C, P, Q, R = (c.free_point3(n) for n in ("A", "B", "C", "P", "Q", "R"))
    pi = c.plane_through("pi", A, B, C)
    X = c.formula("X", "point3", lambda *v: _line_meets_plane(v), A, B, pi)
    c.conclude_coplanar(X, P, Q, R)
    v = prove(c)
    assert v.status == "degenerate" and not v.proved
    assert v.reason.startswith("X = ") and "identically the zero vector" in v.reason


def test_three_planes_through_one_line_are_named():
    # plane(A, B, C), plane(A, B, D), plane(A, B, E) all contain AB: their "common point" is undefined
    c = Claim("pencil-of-planes", "three planes through a line")
    A, B, C, D, E, P = (c.free_point3(n) for n in "ABCDEP")
    X = c.point_on_planes("X", *(c.plane_through(f"p{n.name}", A, B, n) for n in (C, D, E)))
    c.conclude_coplanar(X, A, B, P)
    v = prove(c)
    assert v.status == "degenerate" and "pC, pD, pE do not share a line" in v.reason


def test_a_meet_of_a_line_with_itself_is_named():
    c = Claim("self-meet", "a line meets itself")
    A, B, C = (c.free_point(n) for n in "ABC")
    l = c.join("l", A, B)
    c.conclude_collinear(c.meet("X", l, l), A, C)
    v = prove(c)
    assert v.status == "degenerate" and "l ≠ l" in v.reason


# -- normalisation: only when it loses nothing -------------------------------------------------------------


def test_fixed_objects_prevent_normalisation():
    # on the frame A, B, C, D = (0,0), (1,0), (0,1), (1,1) the lines AB and CD are parallel, so AB ∧ CD lies on
    # the line at infinity; for four general points it does not. The fixed line l∞ must keep the claim as it is.
    c = Claim("frame-trap", "AB and CD meet at infinity", expected=False)
    A, B, C, D = (c.free_point(n) for n in "ABCD")
    X = c.meet("X", c.join("AB", A, B), c.join("CD", C, D))
    c.conclude_incident(X, c.line("linf", 0, 0, 1))
    n, why = normalise(c)
    assert n is None and "linf is a fixed object" in why
    v = prove(c)
    assert v.refuted and v.counterexample.recheck()


@pytest.mark.parametrize("case", ["midpoint", "raw-coordinates", "shared-parameter"])
def test_what_homographies_do_not_preserve_is_not_normalised(case):
    c = Claim("x", "x")
    A, B, C, D = (c.free_point(n) for n in "ABCD")
    if case == "midpoint":  # (A + B) depends on the representatives: an affine notion
        M = c.combine("M", A, B, 1, 1)
        c.conclude_collinear(M, C, D)
        expected = "depends on the representatives"
    elif case == "raw-coordinates":
        c.conclude_zero(c.join("AB", A, B))
        expected = "not projectively invariant"
    else:  # E shares its parameter with A: not a free point of its own
        E = c.point("E", sympy.Symbol("A_x"), 2)
        c.conclude_collinear(E, C, D)
        expected = "special coordinates"
    n, why = normalise(c)
    assert n is None and expected in why


def test_normalised_and_plain_proofs_agree_on_the_catalogue():
    for name in catalogue_names():
        claim = get_claim(name)
        if normalise(claim)[0] is None:
            continue
        a, b = prove(claim), prove_claim(get_claim(name), normalise_coordinates=False)
        assert a.status == b.status, name
        assert a.certificate is None or a.certificate.normalisation


@settings(max_examples=25, deadline=None)
@given(incidence_programs())
def test_random_incidence_programs_normalised_agree_with_exact_evaluation(program):
    # a random program of joins and meets on free points, concluded "X, Y, Z collinear"; the verdict with the
    # frame chosen must be the verdict of the plain expansion, and a refutation must survive the core's recheck
    def build():
        c = Claim("random-program", "random incidence program")
        objs = [c.free_point(f"P{i}") for i in range(program["points"])]
        for k, (op, i, j) in enumerate(program["steps"]):
            a, b = objs[i % len(objs)], objs[j % len(objs)]
            if op == "meet":
                a, b = c.join(f"l{k}a", a, a if a is b else b), c.join(f"l{k}b", b, objs[(j + 1) % len(objs)])
            objs.append(c.meet(f"Q{k}", a, b) if op == "meet" else a)
        x, y, z = (objs[i % len(objs)] for i in program["conclusion"])
        c.conclude_collinear(x, y, z)
        return c

    fast, plain = prove(build(), timeout=20), prove_claim(build(), timeout=20, normalise_coordinates=False)
    assert fast.status == plain.status
    if fast.refuted:
        assert fast.counterexample.recheck()


# -- equation hypotheses -----------------------------------------------------------------------------------


def _parabola_hexagon(c: Claim, wrong: bool):
    pts = []
    for n in "ABCDEF":
        x, y = c.params(f"x{n} y{n}")
        c.assume_zero(y - x**2, f"{n} lies on y = x²")
        pts.append(c.point(n, x, y))
    A, B, C, D, E, F = pts
    X = c.meet("X", c.join("AB", A, B), c.join("DE", D, E))
    Y = c.meet("Y", c.join("BC", B, C), c.join("EF", E, F))
    # mis-stated: the third pair of opposite sides is CE, FA instead of CD, FA
    Z = c.meet("Z", c.join("CE" if wrong else "CD", C, E if wrong else D), c.join("FA", F, A))
    c.conclude_collinear(X, Y, Z)


def test_pascal_on_a_parabola_mis_stated_with_hypotheses_is_refuted():
    c = Claim("pascal-parabola-wrong", "Pascal on y = x², wrong pairing", expected=False)
    _parabola_hexagon(c, wrong=True)
    v = prove(c)
    assert v.refuted, (v.status, v.reason)
    vals = v.counterexample.values
    # independent check: every point lies on y = x², and det[X Y Z] ≠ 0 with Fractions
    assert all(vals[f"y{n}"] == vals[f"x{n}"] ** 2 for n in "ABCDEF")
    P = {n: (vals[f"x{n}"], vals[f"y{n}"], Fraction(1)) for n in "ABCDEF"}

    def meet(p, q, r, s):
        return alg.cross(alg.cross(P[p], P[q]), alg.cross(P[r], P[s]))

    assert alg.det([meet("A", "B", "D", "E"), meet("B", "C", "E", "F"), meet("C", "E", "F", "A")]) != 0
    assert v.counterexample.recheck()


def test_pascal_on_a_parabola_with_hypotheses_is_proved_by_reduction():
    # y_i − x_i² (i = A … F): distinct leading variables y_i, so the hypotheses are their own Gröbner basis
    # and reducing the conclusion substitutes y_i = x_i²
    c = Claim("pascal-parabola", "Pascal on y = x², stated with hypotheses")
    _parabola_hexagon(c, wrong=False)
    v = prove(c)
    assert v.proved and v.method == "Gröbner basis ideal membership" and v.elapsed < 2
    assert "reduction modulo it substitutes yA = xA**2" in v.certificate.steps[0]


def test_a_point_off_the_hypotheses_is_no_counterexample():
    c = Claim("pascal-parabola-wrong", "Pascal on y = x², wrong pairing", expected=False)
    _parabola_hexagon(c, wrong=True)
    v = prove(c)
    moved = dict(v.counterexample.values)
    moved["yA"] += 1  # A leaves the parabola: the recheck must refuse this point
    from pgsym.proofs.engine import recheck_counterexample

    assert not recheck_counterexample(c, moved)


def test_ideal_membership_under_a_stated_condition():
    # hypothesis a·b = 0, conclusion b = 0: b is not in the ideal (a·b), but the join of A = (a, 0, 1) and
    # B = (0, 0, 1) needs A ≠ B, i.e. A × B = (0·1 − 1·0, 1·0 − a·1, a·0 − 0·0) = (0, −a, 0) ≠ 0, and
    # (−a)·b = −(a·b) lies in the ideal: b = 0 wherever that condition holds
    c = Claim("membership-given", "a·b = 0 and A ≠ B give b = 0")
    a, b = c.params("a b")
    A, B = c.point("A", a, 0, 1), c.point("B", 0, 0, 1)
    c.join("l", A, B)
    c.assume_zero(a * b, "a·b = 0")
    c.conclude_zero(b)
    v = prove(c)
    assert v.proved and v.method == "Gröbner basis ideal membership"
    assert any("wherever A ≠ B" in s for s in v.certificate.steps)


# -- the two polynomial backends give the same verdicts --------------------------------------------------


@pytest.mark.skipif("flint" not in available_backends(), reason="python-flint is not installed")
def test_sympy_fallback_gives_the_same_verdicts_as_flint(monkeypatch):
    names = catalogue_names()
    with_flint = {n: prove(n) for n in names}
    monkeypatch.setenv("PGSYM_POLY_BACKEND", "sympy")
    for n in names:
        v = prove(n)
        w = with_flint[n]
        assert (v.status, v.method, [c.text for c in v.conditions]) == (w.status, w.method,
                                                                          [c.text for c in w.conditions]), n
        if v.certificate is not None:
            assert v.certificate.steps == w.certificate.steps, n
            assert v.certificate.backend == "sympy" and w.certificate.backend in ("flint", "sympy"), n


def test_without_flint_the_engine_runs_on_sympys_ring(monkeypatch):
    # as in the browser, where python-flint cannot be imported
    from pgsym.proofs import polynomials
    from pgsym.proofs.errors import PolynomialBackendError

    monkeypatch.setattr(polynomials, "_flint", None)
    assert polynomials.available_backends() == ("sympy",) and polynomials.default_backend() == "sympy"
    with pytest.raises(PolynomialBackendError, match="not available"):
        polynomials.PolynomialRing([sympy.Symbol("a")], backend="flint")
    v = prove("desargues")
    assert v.proved and v.certificate.backend == "sympy"


@pytest.mark.skipif("flint" not in available_backends(), reason="python-flint is not installed")
@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(-5, 5), st.integers(0, 3), st.integers(0, 3)), min_size=1, max_size=6),
       st.lists(st.tuples(st.integers(-5, 5), st.integers(0, 3), st.integers(0, 3)), min_size=1, max_size=6))
def test_both_backends_multiply_alike(f_terms, g_terms):
    # (Σ c xⁱ yʲ)(Σ d xᵏ yˡ) expanded by each backend is the product SymPy's expand gives
    from pgsym.proofs.polynomials import PolynomialRing

    x, y = sympy.symbols("x y")
    f = sum(c * x**i * y**j for c, i, j in f_terms)
    g = sum(d * x**k * y**m for d, k, m in g_terms)
    for backend in ("flint", "sympy"):
        R = PolynomialRing([x, y], integral=True, backend=backend)
        product = R(f) * R(g)
        assert sympy.expand(R.to_expr(product) - f * g) == 0
        at = (f * g).subs({x: 2, y: sympy.Rational(-1, 3)})
        assert R.evaluate(product, [Fraction(2), Fraction(-1, 3)]) == Fraction(str(at))


def test_an_expansion_beyond_the_term_limit_is_unknown(monkeypatch):
    from pgsym.proofs import budget, by_evaluation

    monkeypatch.setattr(budget, "MAX_TERMS", 3)
    monkeypatch.setattr(by_evaluation, "MAX_POINTS", 0)  # and no grid either
    v = prove("pappus")  # its meets have more than three terms per coordinate
    assert v.status == "unknown" and "too large" in v.reason


def test_beyond_the_term_limit_the_identity_is_decided_by_evaluation(monkeypatch):
    from pgsym.proofs import budget

    monkeypatch.setattr(budget, "MAX_TERMS", 3)
    v = prove("pappus")  # its method: "rational parametrisation (…), then polynomial identity by exact evaluation …"
    assert v.proved and "then polynomial identity by exact evaluation on a grid" in v.method
    assert [c.text for c in v.conditions] == [c.text for c in prove("pappus").conditions]
