"""Invariants: each proved for its class, each refuted in the next larger class; the summary table."""

from __future__ import annotations

import pytest
import strategies
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pgsym.errors import DegenerateConfigurationError, ObjectTypeError
from pgsym.hierarchy import AFFINE_2D, EUCLIDEAN_2D, SIMILARITY_2D, class_by_key, classify
from pgsym.invariants import collinear_cross_ratio, cos2_angle, distance_squared, signed_area, signed_volume
from pgsym.proofs.invariance import (
    INVARIANTS,
    Invariant,
    invariance_claim,
    invariant,
    invariants_of,
    summary_markdown,
    summary_table,
)

R = sympy.Rational
rationals = strategies.rationals(5, 5)


@pytest.mark.parametrize("inv", INVARIANTS, ids=lambda i: i.key)
def test_each_invariant_is_proved_for_its_class(inv):
    proof = inv.prove()
    assert proof.holds
    assert proof.components == len(inv.transformation_class.components)


@pytest.mark.parametrize("inv", [i for i in INVARIANTS if i.counter is not None], ids=lambda i: i.key)
def test_each_counterexample_lies_in_the_next_class_and_breaks_the_invariant(inv):
    ce = inv.counterexample()
    larger = class_by_key(inv.transformation_class.larger)
    assert classify(ce.matrix) is larger
    assert ce.fails


def test_invariants_of_the_largest_classes_have_no_counterexample():
    tops = [i for i in INVARIANTS if i.transformation_class.larger is None]
    assert {i.key for i in tops} >= {"cross-ratio", "collinearity", "concurrency", "incidence", "tangency"}
    assert all(i.counterexample() is None for i in tops)


def test_the_engine_rejects_false_claims():
    # length is NOT invariant under similarities, nor the angle under affinities, nor parallelism under
    # projectivities: the claim engine refutes each with a counterexample it rechecks exactly
    wrong = [Invariant(f"x-{key}", invariant(key).name, cls, "", invariant(key).configuration, invariant(key).value)
             for key, cls in (("length", "similarity2"), ("angle", "affine2"), ("parallelism", "projective2"))]
    for w in wrong:
        proof = w.prove()
        assert not proof.holds
        assert all(v.status == "false" and v.counterexample.recheck() for v in proof.verdicts)


def test_an_invariance_proof_is_a_claim_proved_by_the_engine():
    # one claim per component of the class: the improper isometries are a component of their own
    proof = invariant("length").prove()
    assert [v.status for v in proof.verdicts] == ["proved", "proved"]
    assert proof.verdicts[1].title == "length is invariant under the class Isometry (reflection)"
    claim = invariance_claim(invariant("length"), 1)
    # the objects X1, X2, their images X1', X2' under the generic improper isometry H, and |X1X2|² before and after
    assert [n.name for n in claim.nodes.values() if not n.name.startswith("_")] == [
        "H", "X1", "X1'", "X2", "X2'", "q1", "q1'"]
    assert "H is non-singular (det H ≠ 0)" in claim.conditions_text()


def test_the_old_home_of_the_invariants_forwards_with_a_warning():
    import pgsym.invariants as old
    import pgsym.proofs.invariance as new

    for name in ("INVARIANTS", "Invariant", "invariant", "invariants_of", "summary_table", "summary_markdown"):
        with pytest.warns(DeprecationWarning, match=f"pgsym.invariants.{name} is now pgsym.proofs.invariance"):
            assert getattr(old, name) is getattr(new, name)
    import pgsym

    assert pgsym.invariant is new.invariant and pgsym.summary_markdown is new.summary_markdown


# -- counterexamples, values derived by hand -------------------------------------------------------


def test_counterexample_values_by_hand():
    # scaling by 2 maps (0,0), (3,4) to (0,0), (6,8): squared length 25 -> 100
    assert invariant("length").counterexample().before == [25]
    assert invariant("length").counterexample().after == [100]
    # the shear (x, y) -> (x + y, y) maps the lines x = 0, y = 0 (perpendicular, cos² = 0) to x - y = 0
    # and y = 0, at 45°: cos² = 1/2
    ce = invariant("angle").counterexample()
    assert (ce.before, ce.after) == ([0], [R(1, 2)])
    # the same shear maps (0,0),(1,0),(0,0),(0,1) to (0,0),(1,0),(0,0),(1,1): |..|² ratio 1 -> 1/2
    ce = invariant("length-ratio").counterexample()
    assert (ce.before, ce.after) == ([1], [R(1, 2)])
    # H = [[1,0,0],[0,1,0],[0,1,1]] maps x = 0, x = 1 to x = 0 and x + y = 1 (H^-T (1,0,-1) = (1,1,-1)):
    # the image lines meet at (0,1), a finite point: 3rd coordinate of l×m is 1·1 - 0·1 = 1
    ce = invariant("parallelism").counterexample()
    assert (ce.before, ce.after) == ([0], [1])
    # the line at infinity (0,0,1) goes to H^-T (0,0,1) = (0,-1,1), the line y = 1
    ce = invariant("line-at-infinity").counterexample()
    assert ce.after == [0, -1]
    # reflection y -> -y flips the orientation of (0,0),(1,0),(0,1): signed area 1/2 -> -1/2
    ce = invariant("orientation").counterexample()
    assert (ce.before, ce.after) == ([R(1, 2)], [R(-1, 2)])


def test_evaluate_rejects_unknown_keys():
    with pytest.raises(ObjectTypeError):
        invariant("curvature")


# -- the quantities themselves ---------------------------------------------------------------------


def test_quantities_by_hand():
    assert distance_squared([0, 0, 1], [3, 4, 1]) == 25
    assert signed_area([0, 0, 1], [2, 0, 1], [0, 3, 1]) == 3
    assert signed_area([0, 0, 2], [4, 0, 2], [0, 6, 2]) == 3  # other representatives, same triangle
    assert signed_volume([0, 0, 0, 1], [2, 0, 0, 1], [0, 3, 0, 1], [0, 0, 1, 1]) == 1
    assert cos2_angle([1, 0, 0], [1, 1, 5]) == R(1, 2)
    # points 0, 1, 2, 3 on the x-axis: (0-2)(1-3)/((0-3)(1-2)) = 4/3
    assert collinear_cross_ratio([0, 0, 1], [1, 0, 1], [2, 0, 1], [3, 0, 1]) == R(4, 3)
    # on a vertical line the other bracket coordinate is used; harmonic: 0, 2; 1, infinity
    assert collinear_cross_ratio([5, 0, 1], [5, 2, 1], [5, 1, 1], [0, 1, 0]) == -1


# -- random concrete members preserve the invariants (exact arithmetic) ----------------------------


@settings(max_examples=15, deadline=None)
@given(st.lists(rationals, min_size=4, max_size=4), st.lists(rationals, min_size=8, max_size=8))
def test_random_similarity_preserves_ratio_of_lengths(p, pts):
    assume(p[0] != 0 or p[1] != 0)  # a = b = 0 is singular
    H = SIMILARITY_2D.element(*p).matrix
    values = list(pts)
    assume(values[4:6] != values[6:8] and values[0:2] != values[2:4])
    before, after = invariant("length-ratio").evaluate(H, values)
    assert before == after


@settings(max_examples=15, deadline=None)
@given(st.lists(rationals, min_size=6, max_size=6), st.lists(rationals, min_size=12, max_size=12))
def test_random_affinity_preserves_ratio_of_areas(p, pts):
    H = AFFINE_2D.element(*p) if p[0] * p[3] - p[1] * p[2] != 0 else None
    assume(H is not None)
    inv = invariant("area-ratio")
    assume(signed_area([*pts[6:8], 1], [*pts[8:10], 1], [*pts[10:12], 1]) != 0)
    before, after = inv.evaluate(H.matrix, pts)
    assert before == after


@settings(max_examples=15, deadline=None)
@given(rationals, rationals, rationals, st.lists(rationals, min_size=4, max_size=4))
def test_random_euclidean_preserves_length(t, tx, ty, pts):
    H = EUCLIDEAN_2D.element(t, tx, ty).matrix
    before, after = invariant("length").evaluate(H, pts)
    assert before == after


# -- the summary table -------------------------------------------------------------------------------


def test_summary_table_2d():
    rows = summary_table(2)
    assert [r["dof"] for r in rows] == [8, 6, 4, 3, 3]
    by = {r["class"]: r for r in rows}
    assert set(by["Projective"]["invariants"]) == {"cross-ratio", "collinearity", "concurrency", "incidence",
                                                   "tangency"}
    assert "the line at infinity" in by["Affine"]["invariants"]
    assert set(by["Similarity"]["invariants"]) == {"angle", "ratio of lengths", "circular points"}
    assert set(by["Isometry"]["invariants"]) == {"length", "area"}
    # each row inherits everything above it
    assert [r["all"] for r in rows] == [5, 9, 12, 14, 15]
    md = summary_markdown(2)
    assert md.count("\n") == len(rows) + 1 and "| Affine |" in md


def test_summary_table_3d():
    rows = summary_table(3)
    assert [(r["class"], r["dof"]) for r in rows] == [("Projective", 15), ("Affine", 12), ("Similarity", 7),
                                                     ("Isometry", 6), ("Euclidean (rigid motion)", 6)]
    # improper isometries keep lengths; only the rigid motions keep the signed volume
    assert rows[3]["invariants"] == ["length"] and rows[4]["invariants"] == ["volume"]
    assert "the plane at infinity π∞" in rows[1]["invariants"]


def test_invariants_of_includes_inherited_ones():
    own = {i.key for i in invariants_of(EUCLIDEAN_2D, inherited=False)}
    every = {i.key for i in invariants_of(EUCLIDEAN_2D)}
    assert own == {"orientation"} and {"length", "angle", "parallelism", "cross-ratio"} <= every


# -- the one primitive form of polynomial vectors ------------------------------------------------------

polys = st.lists(st.tuples(st.integers(-3, 3), st.integers(0, 2), st.integers(0, 2)), min_size=1, max_size=3)


@settings(max_examples=40, deadline=None)
@given(st.lists(polys, min_size=2, max_size=4), polys)
def test_primitive_part_removes_any_common_factor(vector, factor):
    from sympy.polys.rings import ring

    from pgsym.exact import primitive_part

    R, a, b = ring("a, b", sympy.ZZ)

    def poly(terms):
        return sum((c * a**i * b**j for c, i, j in terms), R.zero)

    v, f = [poly(t) for t in vector], poly(factor)
    assume(any(v) and f)
    p, q = primitive_part(v), primitive_part([f * x for x in v])
    # a primitive vector is determined up to a unit of ℤ[a, b], i.e. ±1
    assert q == p or q == [-x for x in p]
    # and with denominators: (v_i / f) has the same primitive form as v
    assert primitive_part(v, [f] * len(v)) in (p, [-x for x in p])


@pytest.mark.parametrize("inv", [i for i in INVARIANTS if i.counter is not None], ids=lambda i: i.key)
def test_counterexample_values_are_lists(inv):
    # the values are printed in the book as lists, whatever sequence type the kit returns
    ce = inv.counterexample()
    assert type(ce.before) is list and type(ce.after) is list


def test_the_old_name_of_the_invariance_counterexample_still_works_with_a_warning():
    import pgsym.invariants as invariants
    from pgsym.proofs.invariance import InvarianceCounterexample

    with pytest.warns(DeprecationWarning, match="InvarianceCounterexample"):
        old = invariants.Counterexample
    assert old is InvarianceCounterexample
    with pytest.raises(AttributeError):
        invariants.NoSuchName  # noqa: B018


def test_a_value_with_a_zero_denominator_is_a_named_error():
    # (0, 0) and (1, −1): squared distance 1 + 1 = 2; the perspectivity (x, y, w) ↦ (x, y, y + w) sends
    # (1, −1, 1) to the ideal point (1, −1, 0), where the squared distance has the denominator (w_p w_q)² = 0
    persp = [[1, 0, 0], [0, 1, 0], [0, 1, 1]]
    assert invariant("length").evaluate([[1, 0, 0], [0, 1, 0], [0, 0, 1]], [0, 0, 1, -1]) == ([2], [2])
    with pytest.raises(DegenerateConfigurationError, match="length is undefined"):
        invariant("length").evaluate(persp, [0, 0, 1, -1])
