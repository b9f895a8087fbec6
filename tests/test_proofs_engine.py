"""The proof engine: verdicts, certificates, conditions, mutations, bad input, display and JSON."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import homogeneous_vectors, integers

from pgsym import ring as alg
from pgsym.errors import ObjectTypeError, PgsymError
from pgsym.projective_plane import Point, cross, join
from pgsym.proofs import Claim, NonPolynomialClaimError, UndefinedConstructionError, UnknownClaimError, prove
from pgsym.proofs.catalogue import _cross_ratio_p2

small = integers(6)
vec3 = homogeneous_vectors(3, entries=small)


# -- worked examples -------------------------------------------------------------------------------

def test_worked_example_false_claim_has_the_hand_derived_residual():
    # "P = (x, y, 1) lies on y = 0": the residual is lᵀP = 0·x + 1·y + 0·1 = y, so any
    # counterexample must have P_y ≠ 0 and the residual equals P_y.
    c = Claim("on-x-axis", "every point lies on the x-axis", expected=False)
    P = c.free_point("P")
    c.conclude_incident(P, c.line("l", 0, 1, 0))
    v = prove(c)
    assert v.refuted
    assert v.counterexample.residuals == [v.counterexample.values["P_y"]] != [0]
    assert v.counterexample.recheck()


def test_proved_claim_lists_its_conditions_as_text_and_polynomials():
    # join(A, B) = A × B with A = (A_x, A_y, 1), B = (B_x, B_y, 1): the first two coordinates are
    # A_y − B_y and B_x − A_x (by hand), so "A ≠ B" is reported with those polynomials.
    c = Claim("demo", "the join contains A")
    A, B = c.free_point("A"), c.free_point("B")
    c.conclude_incident(A, c.join("l", A, B))
    v = prove(c)
    assert v.proved and [k.text for k in v.conditions] == ["A ≠ B"]
    polys = {sympy.sympify(p) for p in v.conditions[0].polynomials}
    A_x, A_y, B_x, B_y = sympy.symbols("A_x A_y B_x B_y")
    assert sympy.expand(A_y - B_y) in polys and sympy.expand(B_x - A_x) in polys


def test_random_pass_never_proves_alone():
    v = prove("pappus")
    assert "proves nothing" in v.random_pass and v.certificate.steps


def test_rank_claims_true_false_and_too_high():
    def claim(r):
        c = Claim(f"rank{r}", "rank of a Plücker matrix", expected=(r == 2))
        A, B = c.free_point3("A"), c.free_point3("B")
        c.conclude_rank(c.line3("L", A, B), r)
        return c

    assert prove(claim(2)).proved
    low = prove(claim(1))  # a 2×2 minor is nonzero: rank > 1 at the counterexample
    assert low.refuted and low.counterexample.recheck()
    high = prove(claim(3))  # every 3×3 minor vanishes identically: no witness, never "proved"
    assert high.status == "unknown"


def test_groebner_membership_and_non_membership():
    c = Claim("sq", "x² = 0 implies x = 0")
    (x,) = c.params("x")
    c.assume_zero(x**2, "x² = 0")
    c.conclude_zero(x)
    v = prove(c)
    # x is not in the ideal (x²) (it is in its radical): the engine must not claim a proof
    assert v.status == "unknown" and "not in" in v.reason
    c2 = Claim("sq2", "x² = 0 implies x³ = 0")
    (x,) = c2.params("x")
    c2.assume_zero(x**2, "x² = 0")
    c2.conclude_zero(x**3)
    v2 = prove(c2)
    assert v2.proved and v2.method == "Gröbner basis ideal membership"
    assert any("remainder 0" in s for s in v2.certificate.steps)


# -- mutations: perturb a construction and the proof must turn into a refutation --------------------

def _desargues(perturb: bool) -> Claim:
    c = Claim("desargues-mutant", "Desargues with A' moved off OA", expected=not perturb)
    a, b, cc = c.params("a b c")
    O, A, B, C = (c.free_point(n) for n in "OABC")
    A2 = c.combine("A'", A, O, 1, a)
    if perturb:
        A2 = c.combine("A''", A2, c.point("U", 1, 0, 0), 1, 1)  # shift A' by a fixed direction
    B2, C2 = c.combine("B'", B, O, 1, b), c.combine("C'", C, O, 1, cc)
    X = c.meet("X", c.join("AB", A, B), c.join("A'B'", A2, B2))
    Y = c.meet("Y", c.join("BC", B, C), c.join("B'C'", B2, C2))
    Z = c.meet("Z", c.join("CA", C, A), c.join("C'A'", C2, A2))
    c.conclude_collinear(X, Y, Z)
    return c


def test_mutating_desargues_turns_proved_into_false():
    assert prove(_desargues(False)).proved
    v = prove(_desargues(True))
    assert v.refuted and v.counterexample.recheck()


@pytest.mark.parametrize("swap", ["meet->join", "sign"])
def test_mutating_pascal(swap):
    c = Claim("pascal-mutant", "Pascal, mutated", expected=False)
    ts = c.params("a b c d e f")
    P = [c.point(n, t, t**2 + (1 if (swap == "sign" and n == "F") else 0)) for n, t in zip("ABCDEF", ts, strict=True)]
    A, B, C, D, E, F = P
    X = c.meet("X", c.join("AB", A, B), c.join("DE", D, E))
    Y = c.meet("Y", c.join("BC", B, C), c.join("EF", E, F))
    Z = c.meet("Z", c.join("CD", C, D), c.join("FA", F, A)) if swap == "sign" else \
        c.meet("Z", c.join("CE", C, E), c.join("FA", F, A))
    c.conclude_collinear(X, Y, Z)
    v = prove(c)
    assert v.refuted and v.counterexample.recheck()


def test_mutating_the_harmonic_value():
    c = Claim("harmonic-mutant", "the harmonic conjugate gives −2", expected=False)
    A, B, C = (c.free_point1(n) for n in "ABC")
    D = c.harmonic_conjugate("D", A, B, C)
    c.conclude_equal_ratio(c.cross_ratio("cr", A, B, C, D), -2)
    assert prove(c).refuted


# -- bad input -------------------------------------------------------------------------------------

@pytest.mark.parametrize("expr", ["sin", "inverse", "root", "float", "undeclared"])
def test_non_polynomial_conclusions_are_named_errors(expr):
    c = Claim("bad", "bad")
    (a,) = c.params("a")
    value = {"sin": sympy.sin(a), "inverse": 1 / a, "root": sympy.sqrt(2) * a, "float": sympy.Float(0.5) * a,
             "undeclared": sympy.Symbol("zz")}[expr]
    with pytest.raises(NonPolynomialClaimError):
        c.conclude_zero(value)


def test_non_polynomial_coordinates_are_named_errors():
    c = Claim("bad", "bad")
    (a,) = c.params("a")
    with pytest.raises(NonPolynomialClaimError, match="not a polynomial"):
        c.point("P", 1 / a, 1)
    assert issubclass(NonPolynomialClaimError, PgsymError)


def test_undefined_constructions_are_named_errors():
    c = Claim("bad", "bad")
    A = c.free_point("A")
    with pytest.raises(UndefinedConstructionError, match="no object named 'B'"):
        c.join("l", A, "B")
    other = Claim("other", "other").free_point("Q")
    with pytest.raises(UndefinedConstructionError, match="not an object of claim"):
        c.join("l", A, other)
    with pytest.raises(UndefinedConstructionError, match="unknown construction"):
        c.construct("frobnicate", "z", A)
    with pytest.raises(ObjectTypeError, match="join expects point"):
        c.join("l", A, c.free_line("m"))
    with pytest.raises(UnknownClaimError, match="no claim named"):
        prove("no-such-claim")
    with pytest.raises(UndefinedConstructionError, match="no conclusion"):
        prove(Claim("empty", "nothing to prove"))


def test_timeout_is_unknown_never_proved():
    v = prove("pappus", timeout=1e-6)
    assert v.status == "unknown" and "timed out" in v.reason and v.certificate is None


def test_identically_degenerate_construction_is_named_never_proved():
    # l = A × A = 0 for every A, so "A lies on l" holds vacuously: the verdict must say which condition fails
    c = Claim("self-join", "the join of A with itself contains A")
    A = c.free_point("A")
    c.conclude_incident(A, c.join("l", A, A))
    v = prove(c)
    assert v.status == "degenerate" and "A ≠ A" in v.reason and not v.proved


# -- display and JSON ------------------------------------------------------------------------------

def test_markdown_latex_and_json():
    v = prove("desargues")
    md = v._repr_markdown_()
    assert "✔ proved" in md and "Non-degeneracy conditions" in md and "*Time:*" in md
    assert "*Time:*" not in v.markdown(timing=False)
    assert v._repr_latex_().startswith("$") and "proved" in v._repr_latex_()
    data = json.loads(v.to_json())
    assert data["status"] == "proved" and data["conditions"] and data["certificate"]["steps"]
    assert "elapsed_ms" in data and "elapsed_ms" not in v.to_dict(timing=False)
    f = prove("cross-product-sign-flipped")
    fd = json.loads(f.to_json())
    assert fd["status"] == "false" and fd["counterexample"]["values"]
    assert all(Fraction(x) is not None for x in fd["counterexample"]["values"].values())
    assert "Counterexample" in f.markdown()


# -- the shared formulas agree with pgsym and SymPy on random exact inputs -----------------------------

@settings(max_examples=40, deadline=None)
@given(vec3, vec3)
def test_cross_matches_the_core(u, v):
    assert alg.cross(u, v) == tuple(cross(u, v))
    if alg.cross(u, v) != (0, 0, 0):
        assert join(Point(*u), Point(*v)) == Point(*u).join(Point(*v))


@settings(max_examples=25, deadline=None)
@given(st.lists(small, min_size=9, max_size=9))
def test_det_and_adjugate_match_sympy(entries):
    M = sympy.Matrix(3, 3, entries)
    rows = tuple(tuple(r) for r in M.tolist())
    assert alg.det(rows) == M.det()
    assert sympy.Matrix(alg.adjugate(rows)) == M.adjugate()


@settings(max_examples=25, deadline=None)
@given(st.lists(small, min_size=16, max_size=16))
def test_plane_through_satisfies_the_determinant_identity(entries):
    x, a, b, c = (tuple(entries[i:i + 4]) for i in range(0, 16, 4))
    assert alg.dot(alg.plane_through(a, b, c), x) == sympy.Matrix([x, a, b, c]).det()


@settings(max_examples=25, deadline=None)
@given(st.lists(st.integers(-5, 5), min_size=4, max_size=4, unique=True), st.sampled_from([(0, 1), (1, 0)]))
def test_cross_ratio_from_a_point_matches_the_line_formula(xs, o):
    # four points (x, 0) on the x-axis seen from O = (0, 1) or from the ideal point (1, 0, 0)… only O off the
    # line works; (1, 0) is the x-axis direction, so use (0, 1, 1) and (1, 1, 0) as the two viewpoints
    a, b, c, d = ((x, 0, 1) for x in xs)
    view = (0, 1, 1) if o == (0, 1) else (1, 1, 0)
    num, den = _cross_ratio_p2(a, b, c, d, view)
    x1, x2, x3, x4 = xs
    assert sympy.Rational(num, den) == sympy.Rational((x1 - x3) * (x2 - x4), (x1 - x4) * (x2 - x3))


# -- the table of operations ---------------------------------------------------------------------------------

def test_every_operation_of_the_table_has_formula_conditions_and_core_builder():
    from pgsym.proofs.operations import KINDS, OPERATIONS

    for op in OPERATIONS.values():
        assert callable(op.formula) and callable(op.conditions) and callable(op.description), op.name
        # a user formula has no counterpart in the core, and a constant ratio is just a number
        # (nor has a conclusion's quantity, e.g. the reciprocal product of two lines)
        assert (op.core is None) == (op.name in ("formula", "const") or op.conclusion), op.name
        for kinds in op.arg_kinds or ():
            assert set(kinds) <= set(KINDS), op.name
        assert isinstance(op.result, int) or op.result in KINDS or op.name in ("free", "formula"), op.name
    # every construction states its non-degeneracy in words, e.g. "A and B distinct" for a join
    assert OPERATIONS["join"].conditions(["A", "B"], "l", None) == ["A ≠ B"]
    assert OPERATIONS["plane_through"].conditions(["A", "B", "C"], "p", None) == ["A, B, C are not collinear"]


def test_the_builder_accepts_exactly_the_table_operations():
    from pgsym.proofs.operations import OPERATIONS, constructions

    accepted = set(constructions())
    assert accepted == {n for n, op in OPERATIONS.items() if op.constructible} | {"apply_plane", "tangent"}
    for name in accepted:
        assert callable(getattr(Claim, name)), name
    for name in ("free", "const", "frobnicate", "cross"):
        with pytest.raises(UndefinedConstructionError, match="unknown construction"):
            Claim("x", "x").construct(name, "z")
    # construct dispatches through the table: the same node as the method
    c = Claim("x", "x")
    A, B = c.free_point("A"), c.free_point("B")
    via_table, via_method = c.construct("join", "l", A, B), c.join("m", A, B)
    assert (via_table.op, via_table.args, via_table.conditions) == (via_method.op, via_method.args, ["A ≠ B"])
    assert c.construct("apply_plane", "q", c.free_matrix("H", 4), c.free_plane("p")).op == "apply_line"
    with pytest.raises(ObjectTypeError, match="conic_through needs five points, got 2"):
        c.conic_through("C", A, B)


def test_the_engine_evaluates_exactly_the_table_operations():
    c = Claim("x", "x")
    A = c.free_point("A")
    c.conclude_incident(A, c.join("l", A, c.point("B", 1, 2)))
    c.nodes["l"].op = "wedge-of-three"  # an operation no entry of the table defines
    with pytest.raises(UndefinedConstructionError, match="no operation of the table"):
        prove(c)


def test_one_claim_with_every_operation_agrees_with_the_core():
    # each operation's formula is compared with its core builder at a rational point (the core check)
    from pgsym.proofs.operations import EUCLIDEAN_OPERATIONS, OPERATIONS

    c = Claim("all-operations", "every operation of the table once")
    (s,) = c.params("s")
    A, B = c.free_point("A"), c.point("B", 1, 2)
    l = c.join("l", A, B)
    c.meet("X", l, c.line("m", 1, s, 3))
    c.combine("Y", A, B, s, 1)
    Q = c.free_point3("Q")
    P1, P2 = c.point3("P1", 1, 0, 0), c.point3("P2", 0, 1, 2)
    pi = c.plane_through("pi", Q, P1, P2)
    c.point_on_planes("Z", pi, c.plane("q1", 1, 0, 0, s), c.plane("q2", 0, 1, 0, 2))
    c.line3("L", Q, P1)
    H = c.matrix("H", [[1, s, 0], [0, 1, 2], [1, 0, 1]], invertible=True)
    c.apply("HA", H, A)
    c.apply_line("Hl", H, l)
    C0 = c.conic("C0", [[1, 0, 0], [0, 2, 0], [0, 0, -1]])
    c.apply_conic("HC", H, C0)
    c.polar("p", C0, A)
    c.dual_conic("D", C0)
    c.conic_through("C", *(c.point(f"K{i}", x, y) for i, (x, y) in enumerate(((1, 0), (0, 1), (-1, 0), (0, -1),
                                                                                 (2, 3)))))
    a, b, d = c.free_point1("a"), c.free_point1("b"), c.free_point1("d")
    h = c.harmonic_conjugate("h", a, b, d)
    c.conclude_equal_ratio(c.cross_ratio("cr", a, b, d, h), -1)  # -1 is a constant ratio node
    c.formula("f", "scalar", alg.dot, l, A)
    # the constructions and conclusions of the published theorems, on the circle x² + y² = w² through U
    K0, U = c.conic("Kc", [[1, 0, 0], [0, 1, 0], [0, 0, -1]]), c.point("U", 1, 0)
    S2, S3 = c.second_intersection("S2", K0, U, A), c.point_on_conic("S3", K0, U, s)
    tangents = [c.line(f"t{i}", *v) for i, v in enumerate([(1, 0, -1), (0, 1, -1), (1, 0, 1), (0, 1, 1), (3, 4, -5)])]
    c.conic_tangent_to("CT", *tangents)
    c.point_on_line("PL", A, B)
    c.point_of_line("PG", l)
    LM = c.line_meets_plane("LM", c.nodes["L"], c.plane("q3", 0, 0, 1, s))
    c.line_of_planes("LP", pi, c.plane("q4", 1, 1, 0, s))
    c.cross_ratio_collinear("cr2", A, B, c.nodes["X"], c.nodes["Y"])
    c.harmonic_conjugate_collinear("hc2", A, B, c.nodes["X"])
    c.midpoint("M", A, B)
    c.conclude_collinear3(Q, P1, LM)
    c.conclude_on_line3(LM, c.nodes["L"])
    c.conclude_lines_meet(c.nodes["L"], c.line3("L2", Q, P2))
    c.conclude_on_conic(S2, K0)
    c.conclude_tangent(tangents[0], K0)
    c.conclude_conconic(U, S2, S3, *(c.point(f"V{i}", *v) for i, v in enumerate([(0, 1), (-1, 0), (0, -1)])))
    c.conclude_incident(A, l)
    # the Euclidean operations have their own such claim in test_proofs_euclidean.py
    assert {n.op for n in c.nodes.values()} == set(OPERATIONS) - set(EUCLIDEAN_OPERATIONS)
    v = prove(c)
    assert v.proved, v.reason
    rebuilt = sum(1 for n in c.nodes.values() if n.op not in ("formula", "const") and not n.operation.conclusion)
    assert v.core_check == f"{rebuilt} objects rebuilt with pgsym's core at a rational point agree with the formulas"


def test_statuses_are_an_enum_that_reads_as_before():
    from pgsym.proofs import Status

    v = prove("pappus")
    assert v.status is Status.PROVED and v.status == "proved" and f"{v.status:8s}|" == "proved  |"
    assert repr(v.status) == "'proved'" and v.to_dict()["status"] == "proved"
    assert json.loads(v.to_json())["status"] == "proved"
    assert [str(s) for s in Status] == ["proved", "false", "unknown", "degenerate"]


# -- readable certificates -----------------------------------------------------------------------------

def test_a_proved_verdict_prints_its_normalisation_method_size_and_conditions():
    v = prove("desargues")
    text = str(v)
    # Desargues: O, A, B, C free, A' = A + aO, …: the four free points become the frame
    assert "normalisation: without loss of generality O = (0, 0, 1), A = (1, 0, 1), B = (0, 1, 1), C = (1, 1, 1)" \
        in text
    assert "by polynomial identity (exact expansion)" in text and "terms of degree" in text
    assert "O, A, B are not collinear (frame)" in text and "AB ≠ A'B'" in text
    md = v.to_markdown(timing=False)
    assert "*Normalisation:* without loss of generality" in md and "terms of degree" in md


def test_markdown_and_latex_escape_the_claims_text():
    c = Claim("x_y", "50% of *A* & {B}_1 $\\input{x}$", "a `code` # heading")
    A, B = c.free_point("A"), c.free_point("B")
    c.conclude_incident(A, c.join("l", A, B))
    v = prove(c)
    md = v.to_markdown(timing=False)
    # a title with a backslash or a dollar is shown as code, where no math or markup scanner looks
    assert md.startswith(r"**`50% of *A* & {B}_1 $\input{x}$`** (`x_y`)")
    assert r"*Claim.* a \`code\` \# heading" in md
    tex = v.to_latex()
    assert tex.startswith(r"\paragraph{50\% of *A* \& \{B\}\_1 \$\textbackslash{}input\{x\}\$} \textbf{proved}.")
    assert r"A $\neq$ B" in tex and "\\input{" not in tex


def test_degenerate_verdict_reads_in_every_format():
    c = Claim("self-join", "the join of A with itself")
    A = c.free_point("A")
    c.conclude_incident(A, c.join("l", A, A))
    v = prove(c)
    assert "⚠ degenerate construction" in v.to_markdown() and r"\textbf{degenerate}" in v.to_latex()
    assert str(v).startswith("the join of A with itself: degenerate") and v.to_dict()["status"] == "degenerate"
