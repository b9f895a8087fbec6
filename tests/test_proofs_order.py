"""Order conditions (``where`` lines): the verdict is about the branches and figures they select, and only those.

Expected verdicts are derived by hand in the comments; the property test compares each verdict with its own exact
evaluation (rational arithmetic, both common points known in closed form) on the branches the conditions select.
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pgsym.proofs.engine import prove
from pgsym.proofs.errors import StatementKindError, StatementNameError, StatementSyntaxError
from pgsym.proofs.language import parse_statement

# (X = one common point of a line and a circle, the order condition, the conclusion, the verdict)
MINIMAL = {
    # the circle of centre A through B meets the line AB at B and at B' = 2A − B; (B − A)·(B − A) = |AB|² > 0 and
    # (B' − A)·(B − A) = −|AB|² < 0, so "X on the ray from A through B" selects B alone
    "ray": ("points A B\npoint X = intersection (join A B) (circle A B)\nwhere onray X A B\nprove equal X B",
            "proved"),
    # from B towards A: X = B gives (B − B)·(A − B) = 0, not > 0; X = B' gives (2A − 2B)·(A − B) = 2|AB|² > 0
    "ray-back": ("points A B\npoint X = intersection (join A B) (circle A B)\nwhere onray X B A\nprove equal X B",
                 "false"),
    "ray-back-mirror": ("points A B\npoint X = intersection (join A B) (circle A B)\nwhere onray X B A\n"
                        "prove equal X (reflect B A)", "proved"),
    # the circle of centre A through the midpoint M of AB meets AB at M and 2A − M; (M − A)·(B − M) = |AB|²/4 > 0,
    # (A − M)·(B − 2A + M) = −(1/2)(3/2)|AB|² < 0: "between A and B" selects M
    "between": ("points A B\npoint M = midpoint A B\npoint X = intersection (join A B) (circle A M)\n"
                "where between X A B\nprove equal X M", "proved"),
    "between-other": ("points A B\npoint M = midpoint A B\npoint X = intersection (join A B) (circle A M)\n"
                      "where between X A B\nprove equal X (reflect M A)", "false"),
    # the perpendicular bisector of AB meets the circle on the diameter AB at D = M + R(−90°)(A − M) and at 2M − D,
    # on opposite sides of AB (their signed areas with A, B are opposite)
    "side": ("points A B\npoint M = midpoint A B\npoint D = rotate A M 0 -1\n"
             "point X = intersection (bisector A B) (circle M A)\nwhere sameside X D A B\nprove equal X D", "proved"),
    "side-opposite": ("points A B\npoint M = midpoint A B\npoint D = rotate A M 0 -1\n"
                      "point X = intersection (bisector A B) (circle M A)\nwhere oppositeside X D A B\n"
                      "prove equal X D", "false"),
    # the centroid G of ABC is inside it, and lies on the median from A: true without the condition
    "inside-not-needed": ("points A B C\npoint G = meet (join A (midpoint B C)) (join B (midpoint C A))\n"
                          "where inside G A B C\nprove collinear A G (midpoint B C)", "proved"),
    # A is a vertex: area(B, C, A)·area(B, C, A) > 0 but area(C, A, A) = 0, so "A inside ABC" never holds; a claim
    # about no figure is not proved
    "inside-never": ("points A B C\nwhere inside A A B C\nprove collinear A B (midpoint A B)", "unknown"),
    # a free X with (X − A)·(B − X) > 0 (inside the circle on the diameter AB) is not on the line AB in general
    "rational-false": ("points A B X\nwhere between X A B\nprove collinear A B X", "false"),
}


@pytest.mark.parametrize("name", list(MINIMAL))
def test_minimal_statements_are_decided_on_the_selected_branch(name: str) -> None:
    text, expected = MINIMAL[name]
    verdict = prove(parse_statement(text, name=name))
    assert verdict.status == expected, (verdict.reason, verdict.branches)
    if expected == "false":
        assert verdict.counterexample is not None and verdict.counterexample.recheck()
        assert "selected branch" in verdict.branches
    if expected == "proved":
        assert "order condition" in verdict.branches
        assert any(h.startswith("order condition:") for h in verdict.hypotheses)
    if expected == "unknown":
        assert verdict.counterexample is None and verdict.certificate is None


def test_the_certificate_says_how_the_branch_is_selected() -> None:
    verdict = prove(parse_statement(MINIMAL["ray"][0], name="ray"))
    assert "norm over the conjugate branches is 0" in verdict.certificate.method
    assert any("the condition excludes that branch" in step for step in verdict.certificate.steps)


def test_a_wrong_branch_never_refutes_and_an_excluded_figure_never_counts() -> None:
    # without the condition the claim is refuted (X may be B' = 2A − B); with it, proved
    text = MINIMAL["ray"][0]
    assert prove(parse_statement(text.replace("where onray X A B\n", ""), name="ray")).status == "false"
    assert prove(parse_statement(text, name="ray")).status == "proved"


# -- hostile input ---------------------------------------------------------------------------------------------

BASE = "points A B C\npoint X = midpoint A B\n"


@pytest.mark.parametrize(("line", "error", "words"), [
    ("where", StatementSyntaxError, "where needs an order condition"),
    ("where above X A B", StatementSyntaxError, "unknown order condition 'above'"),
    ("where between X A", StatementKindError, "between takes 3 points (X A B), got 2"),
    ("where between X A B C", StatementKindError, "between takes 3 points"),
    ("where between X A A", StatementKindError, "A is given twice"),
    ("where inside X A B B", StatementKindError, "B is given twice"),
    ("where sameside X C A A", StatementKindError, "A is given twice"),
    ("where between X A (join A B)", StatementKindError, "takes points of the plane, got the line"),
    ("where onray X A 3", StatementKindError, "got the number 3"),
    ("where between X A Q", StatementNameError, "Q is not defined"),
    ("points where", StatementNameError, "'where' is a keyword"),
    ("point between = midpoint A C", StatementNameError, "'between' is a keyword"),
    ("where between X A B )", StatementSyntaxError, "expected a name or '('"),
    ("where (between X A B)", StatementSyntaxError, "unknown order condition '('"),
])
def test_misused_order_conditions_get_named_errors(line: str, error: type, words: str) -> None:
    with pytest.raises(error, match=None) as err:
        parse_statement(BASE + line + "\nprove collinear A B X")
    assert words in str(err.value) and str(err.value).startswith("3:")


def test_too_many_order_conditions_are_refused() -> None:
    text = BASE + "where between X A B\n" * 17 + "prove collinear A B X"
    with pytest.raises(StatementKindError, match="more than 16 order conditions"):
        parse_statement(text)


def test_points_of_space_are_refused() -> None:
    with pytest.raises(StatementKindError, match="takes points of the plane, got the point3"):
        parse_statement("points3 P Q R\nwhere between P Q R\nprove collinear P Q R")


# -- property: random statements against an exact evaluation on the selected branches -----------------------------

Q = Fraction
NAMES = "ABCM"


def _conditions(kind: str, pts: list[tuple[Fraction, Fraction]]) -> bool:
    """The order condition in affine coordinates, written from its definition (not from pgsym's formulas)."""
    def area(a, b, p):  # twice the signed area of abp
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    def dot(u0, u1, v0, v1):
        return (u1[0] - u0[0]) * (v1[0] - v0[0]) + (u1[1] - u0[1]) * (v1[1] - v0[1])

    if kind == "sameside":
        p, q, a, b = pts
        return area(a, b, p) * area(a, b, q) > 0
    if kind == "oppositeside":
        p, q, a, b = pts
        return area(a, b, p) * area(a, b, q) < 0
    if kind == "between":
        x, a, b = pts
        return dot(a, x, x, b) > 0
    if kind == "onray":
        x, v, p = pts
        return dot(v, x, v, p) > 0
    x, a, b, c = pts
    return all(area(u, v, x) * area(u, v, w) > 0 for u, v, w in ((b, c, a), (c, a, b), (a, b, c)))


def _figure(template: int, v: dict[str, tuple[Fraction, Fraction]], o: str, p: str, q: str):
    """Both common points of the template's line and circle, in closed form: (first, second) and their names."""
    if template == 0:  # line PQ, circle of centre O through P: P and P reflected in the foot F of O on PQ
        (px, py), (qx, qy), (ox, oy) = v[p], v[q], v[o]
        dx, dy = qx - px, qy - py
        t = ((ox - px) * dx + (oy - py) * dy) / (dx * dx + dy * dy)
        f = (px + t * dx, py + t * dy)
        return {"P0": (px, py), "S": (2 * f[0] - px, 2 * f[1] - py)}
    # the perpendicular bisector of AB and the circle on the diameter AB: M ± R(90°)(B − A)/2
    (ax, ay), (bx, by) = v["A"], v["B"]
    m = ((ax + bx) / 2, (ay + by) / 2)
    h = ((ay - by) / 2, (bx - ax) / 2)  # R(−90°)(x, y) = (y, −x) of A − M = (A − B)/2: D = M + h
    return {"P0": (m[0] + h[0], m[1] + h[1]), "S": (m[0] - h[0], m[1] - h[1])}


@st.composite
def statements(draw):
    template = draw(st.integers(0, 1))
    o, p, q = draw(st.permutations(NAMES))[:3]
    lines = ["points A B C", "point M = midpoint A B"]
    if template == 0:
        lines += [f"point S = reflect {p} (foot {o} (join {p} {q}))",
                  f"point X = intersection (join {p} {q}) (circle {o} {p})"]
        first = p
    else:
        lines += ["point P0 = rotate A M 0 -1", "point S = reflect P0 M",
                  "point X = intersection (bisector A B) (circle M A)"]
        first = "P0"
    kind = draw(st.sampled_from(["sameside", "oppositeside", "between", "onray", "inside"]))
    size = {"sameside": 4, "oppositeside": 4, "between": 3, "onray": 3, "inside": 4}[kind]
    pool = sorted({"A", "B", "C", "M", "S", first})
    args = ["X", *draw(st.permutations(pool))[:size - 1]]  # different points: every condition is defined
    if kind in ("sameside", "oppositeside") and draw(st.booleans()):
        args[0], args[1] = args[1], args[0]  # X as the second of the pair
    target = draw(st.sampled_from(["S", first]))
    lines += [f"where {kind} {' '.join(args)}", f"prove equal X {target}"]
    return "\n".join(lines), (template, o, p, q, kind, args, target, first)


def _exact(setup, values: dict[str, Fraction]) -> bool | None:
    """Whether the conclusion holds on every branch the condition selects at these values (None: no selected
    branch, or a degenerate figure)."""
    template, o, p, q, kind, args, target, _first = setup
    v = {n: (values[f"{n}_x"], values[f"{n}_y"]) for n in "ABC"}
    v["M"] = ((v["A"][0] + v["B"][0]) / 2, (v["A"][1] + v["B"][1]) / 2)
    if len({v[n] for n in NAMES}) < 4:
        return None
    two = _figure(template, v, o, p, q)
    if two["P0"] == two["S"]:
        return None
    v["S"] = two["S"]
    if template == 1:
        v["P0"] = two["P0"]
    selected = []
    for x in two.values():
        pts = [x if a == "X" else v[a] for a in args]
        if _conditions(kind, pts):
            selected.append(x)
    if not selected:
        return None
    return all(x == v[target] for x in selected)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True, database=None)
@given(statements())
def test_random_statements_agree_with_exact_evaluation_on_the_selected_branch(drawn) -> None:
    text, setup = drawn
    verdict = prove(parse_statement(text, name="random"), timeout=6)
    rng = random.Random(text)
    found = []
    for _ in range(40):
        values = {f"{n}_{c}": Q(rng.randint(-9, 9), rng.randint(1, 3)) for n in "ABC" for c in "xy"}
        holds = _exact(setup, values)
        if holds is not None:
            found.append(holds)
    if verdict.status == "proved":
        assert all(found), (text, verdict.branches)
    elif verdict.status == "false":
        ce = verdict.counterexample
        assert ce is not None and ce.recheck(), text
        assert _exact(setup, dict(ce.values)) is False, (text, ce.values)  # a selected branch fails there
    else:  # unknown: no figure satisfies the condition, or neither a proof nor a counterexample was found
        assert verdict.status == "unknown" and verdict.certificate is None and verdict.counterexample is None, text


BISECTOR = """points a b c
point e = intersection (join a b) (circle a c)
line bis = anglebisector b a c
point d = meet bis (join b c)
{where}
prove perpendicular (join a d) (join c e)
"""


def selected_and_refuted(good: str, bad: str, words: str) -> object:
    """The verdict on ``good``: proved, its branch words naming ``words``; ``bad`` (the other branch or figures) is
    refuted with a counterexample that re-checks."""
    proved = prove(parse_statement(good), timeout=30)
    assert str(proved.status) == "proved" and words in proved.branches
    wrong = prove(parse_statement(bad), timeout=30)
    assert str(wrong.status) == "false" and wrong.counterexample.recheck()
    return proved


def test_a_branch_selected_through_a_named_root_is_proved_and_the_other_refuted() -> None:
    # |ae| = |ac| with e on the ray ab: the triangle ace is isosceles with apex a, so ce is perpendicular to the
    # internal bisector of ∠bac; on the opposite ray it is perpendicular to the external bisector instead
    selected_and_refuted(BISECTOR.format(where="where onray e a b"),
                         BISECTOR.format(where="where onray e a (reflect b a)"), "order conditions select")


def test_a_root_the_conditions_do_not_name_may_take_either_branch() -> None:
    # g, a common point of the line ac and the circle about b through c, is either of the two: the conclusion does
    # not involve it, so the branch of e the condition selects decides alone
    text = BISECTOR.format(where="point g = intersection (join a c) (circle b c)\nwhere onray e a b")
    verdict = prove(parse_statement(text), timeout=30)
    assert str(verdict.status) == "proved" and "order conditions select" in verdict.branches


TWO_ROOTS = """points c a e
point b = rotate a c 0 1
point d = intersection (join c a) (circle c e)
point f = intersection (join c b) (circle c e)
where {side} d f c (midpoint a b)
prove parallel (join d f) (join a b)
"""


def test_two_roots_whose_product_is_rational_are_selected_by_one_condition() -> None:
    # |ca| = |cb| (b is a turned about c by 90°) and d, f are the points at distance |ce| from c on the lines ca,
    # cb: d = ±r·u_a, f = ±r·u_b (unit vectors). With equal signs d − f = ±r(u_a − u_b) is parallel to a − b,
    # and d, f are mirror images in the bisector c(midpoint a b): on opposite sides of it. With different signs
    # d − f = ±r(u_a + u_b) is perpendicular to a − b, and d, f are on the same side
    selected_and_refuted(TWO_ROOTS.format(side="oppositeside"), TWO_ROOTS.format(side="sameside"), "component")


EQUAL_STEPS = """points a b c
line bis = anglebisector b a c
point d = meet bis (join b c)
point e on line a b
point f = intersection (join a c) (circle c (translate c b e))
where {side} f e b c
prove parallel (join (midpoint e f) (midpoint b c)) (join a d)
"""


def test_equal_steps_from_two_vertices_meet_the_bisector_parallel_on_the_branch_selected() -> None:
    # |cf| = |be| (f on ac, e on ab): the midpoint line of ef and bc is parallel to the internal bisector of ∠bac
    # when e, f are both moved towards a or both away from it, i.e. e and f on the same side of bc: with u, v the
    # unit vectors along ab, ac, e = b + s·u and f = c + s·v (the same s), so (e + f)/2 − (b + c)/2 = s(u + v)/2,
    # along u + v. With a = 0, b = 1, the sign on the failing branch is that of A + |ac|·B once T's content free
    # of the roots is set apart, with B = q²(t + 1)⁴ + 6q(t + 1)² + 1 (q = |ac|², t the parameter of e), whose
    # sign the shift t ↦ t − 1 shows
    selected_and_refuted(EQUAL_STEPS.format(side="sameside"), EQUAL_STEPS.format(side="oppositeside"),
                         "order conditions select")


BISECTOR_SIDE = """points a b c
point f on line a b
line bis = anglebisector c b f
point g = meet bis (join a c)
line at_a = anglebisector b a c
line at_b = anglebisector a b c
point h = meet at_a at_b
where {where}
prove collinear b g h
"""


def test_a_named_bisector_is_proved_on_the_figures_a_condition_without_roots_selects() -> None:
    # the internal bisector of ∠cbf is that of ∠cba, through the incentre h, when f is on the ray from b through a,
    # and the external bisector at b when b is between a and f: the named branch's sign is fixed by the condition
    proved = selected_and_refuted(BISECTOR_SIDE.format(where="onray f b a"),
                                  BISECTOR_SIDE.format(where="between b a f"), "named branch")
    assert "order conditions fix" in proved.certificate.method
    assert any("some by the order conditions" in line for line in proved.certificate.steps)


# f on the line ab: the internal bisector of ∠cbf is that of ∠cba (through the incentre h: b, g, h collinear) when
# f is on the ray from b through a, and the external one at b (bg ⟂ bh) when b is between a and f. Each condition
# below keeps f on one of the two rays from b, or on both (onray f a b: between a and b, and beyond b)
SIDES = [  # (condition, the ray from b it keeps f on: "a" towards a, "beyond" past b, "both")
    ("onray f b a", "a"), ("sameside f a c b", "a"), ("onray f b (midpoint a b)", "a"), ("between f a b", "a"),
    ("between a f b", "a"), ("between b a f", "beyond"), ("oppositeside f a c b", "beyond"), ("onray f a b", "both"),
]


@pytest.mark.parametrize(("condition", "ray"), SIDES)
@pytest.mark.parametrize("internal", [True, False])
def test_a_named_bisector_under_conditions_on_a_free_point_agrees_with_its_side(condition, ray, internal) -> None:
    goal = "collinear b g h" if internal else "perpendicular (join b g) (join b h)"
    text = BISECTOR_SIDE.format(where=condition).replace("prove collinear b g h", f"prove {goal}")
    verdict = prove(parse_statement(text), timeout=30)
    # (between a f b: with f = (a + t·b)/(1 + t) the condition is −t(t + 1) > 0, so −1 < t < 0: it fixes the sign
    # of both factors, and only fractions satisfy it)
    if ray != ("a" if internal else "beyond"):  # false on the figures the condition keeps (some of them)
        assert str(verdict.status) == "false" and verdict.counterexample.recheck(), (condition, goal)
    else:
        assert str(verdict.status) == "proved", (condition, goal)
