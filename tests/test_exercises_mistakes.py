"""Common wrong answers: each mistake class is recognised on a wrong answer built independently (by
hand or with SymPy), the right answer never is, and every stored candidate is really wrong.

The property test runs ``PGSYM_MISTAKE_SEEDS`` seeds per template: 10⁴ by default (about three
minutes for the nineteen templates on two cores); a smaller number gives a quick local run.
"""

from __future__ import annotations

import json
import os
from collections import Counter
from fractions import Fraction

import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from pgsym.exercises.answers import grade, matches, read_as
from pgsym.exercises.errors import ManifestError
from pgsym.exercises.grading import grade_rows
from pgsym.exercises.mistakes import admissible, default_mistakes, mistake, recognise
from pgsym.exercises.model import Answer, Exercise
from pgsym.exercises.sheets import build_sheets, load_manifest_data, manifest_json, parse_topics
from pgsym.exercises.template import all_templates, get_template
from pgsym.projective_line import Point1, cross_ratio

F = Fraction
SEEDS = int(os.environ.get("PGSYM_MISTAKE_SEEDS", "10000"))


def found(key: Answer, candidates, text: str) -> str | None:
    """The class recognised for a typed text (None for a right answer or an unknown wrong one)."""
    m = recognise(key, candidates, read_as(key, text))
    return m.code if m else None


def typed(values) -> str:
    return "(" + ", ".join(str(v) for v in values) + ")"


def typed_matrix(m: sympy.Matrix) -> str:
    return "[" + ", ".join("[" + ", ".join(str(m[i, j]) for j in range(m.cols)) + "]" for i in range(m.rows)) + "]"


# --- the generic classes, on hand-made keys ------------------------------------------------------------
def test_projective_sign_and_ideal_as_finite():
    key = Answer.projective([1, -2, 0])  # the ideal point of direction (1, -2)
    cands = admissible(key, default_mistakes(key))
    assert found(key, cands, "(1, -2, 1)") == "ideal-as-finite"  # the direction read as a finite point
    assert found(key, cands, "(-1, 2, 1)") == "ideal-as-finite"  # the opposite direction, likewise
    assert found(key, cands, "(2, 4, 0)") == "sign"  # (1, 2, 0) up to scale: the sign of x2 lost
    assert found(key, cands, "(-1, -2, 0)") == "sign"  # (1, 2, 0) again: x1's sign lost
    assert found(key, cands, "(-3, 6, 0)") is None  # right (−3 times the key)
    assert found(key, cands, "(1, 1, 1)") is None  # wrong, but no known mistake


def test_a_sign_lost_in_a_zero_or_only_coordinate_is_never_stored():
    # (0, 1, 0) with its one nonzero entry negated is (0, -1, 0) ~ (0, 1, 0): the right point
    key = Answer.projective([0, 1, 0])
    assert [m.code for m in admissible(key, default_mistakes(key))] == ["ideal-as-finite"] * 2
    assert [m.answer.value for m in admissible(key, default_mistakes(key))] == [(0, 1, 1), (0, 1, -1)]


def test_matrix_transposed_and_inverted():
    key = Answer.matrix([[1, 2], [0, 1]])
    cands = admissible(key, default_mistakes(key))
    assert found(key, cands, "[[2, 0], [4, 2]]") == "transposed"  # 2·[[1, 0], [2, 1]]
    assert found(key, cands, "[[-1, 2], [0, -1]]") == "inverted"  # −[[1, −2], [0, 1]], the inverse (det 1)
    assert found(key, cands, "[[3, 6], [0, 3]]") is None  # right up to scale
    symmetric = Answer.matrix([[1, 0], [0, 2]])  # its transpose is itself: no such candidate
    assert [m.code for m in admissible(symmetric, default_mistakes(symmetric))] == ["inverted"]
    # diag(1, 2)⁻¹ = diag(1, 1/2) ~ diag(2, 1)
    assert found(symmetric, admissible(symmetric, default_mistakes(symmetric)), "[[2, 0], [0, 1]]") == "inverted"


def test_exact_vectors_scalars_and_matrices_up_to_a_scale_that_is_not_allowed():
    key = Answer.vector([F(1, 2), 3])
    cands = admissible(key, default_mistakes(key))
    assert found(key, cands, "(1, 6)") == "scale"  # 2·(1/2, 3)
    assert found(key, cands, "(-1/2, 3)") == "sign"
    assert found(key, cands, "(0.5, 3)") is None  # right
    scalar = Answer.scalar(F(-3, 2))
    assert found(scalar, admissible(scalar, default_mistakes(scalar)), "3/2") == "sign"
    R = Answer.matrix_exact([[F(3, 5), F(-4, 5)], [F(4, 5), F(3, 5)]])
    cands = admissible(R, default_mistakes(R))
    assert found(R, cands, "[[3, -4], [4, 3]]") == "scale"  # 5R
    assert found(R, cands, "[[3/5, 4/5], [-4/5, 3/5]]") == "transposed"  # Rᵀ (= R⁻¹, stored once)
    assert [m.code for m in cands] == ["transposed", "scale"]


def test_admissible_drops_wrong_kinds_shapes_repeats_and_the_key():
    key = Answer.projective([1, 2, 3])
    cands = admissible(key, [mistake("dual", Answer.projective([2, 4, 6])),  # the key itself: dropped
                             mistake("dual", Answer.projective([1, 0, 0])),
                             mistake("sign", Answer.projective([-2, 0, 0])),  # a repeat up to scale
                             mistake("dual", Answer.projective([1, 0])),  # wrong shape
                             mistake("dual", Answer.scalar(1))])  # wrong kind
    assert [(m.code, m.answer.value) for m in cands] == [("dual", (1, 0, 0))]


@settings(max_examples=300)
@given(st.lists(st.integers(-9, 9), min_size=2, max_size=6).filter(any), st.integers(-5, 5).filter(bool))
def test_projective_defaults_never_flag_a_right_answer(values, k):
    key = Answer.projective(values)
    cands = admissible(key, default_mistakes(key))
    for m in cands:
        assert not matches(key, m.answer.value)
    assert recognise(key, cands, tuple(F(k * v) for v in values)) is None


@settings(max_examples=200)
@given(st.lists(st.integers(-4, 4), min_size=9, max_size=9).filter(any), st.integers(-5, 5).filter(bool),
       st.booleans())
def test_matrix_defaults_never_flag_a_right_answer(entries, k, exact):
    rows = [entries[0:3], entries[3:6], entries[6:9]]
    key = Answer.matrix_exact(rows) if exact else Answer.matrix(rows)
    cands = admissible(key, default_mistakes(key))
    for m in cands:
        if m.answer.kind == key.kind:
            assert not matches(key, m.answer.value)
    scale = 1 if exact else k
    assert recognise(key, cands, tuple(tuple(F(scale * x) for x in row) for row in rows)) is None


# --- the template-specific classes, on wrong answers computed independently --------------------------------
def _instance(topic: str, level: int, want: str, seed0: int = 0) -> Exercise:
    """The first instance (from seed0) whose part 0 stores a mistake of class ``want``."""
    t = get_template(topic)
    for seed in range(seed0, seed0 + 200):
        ex = t.generate(seed, level, 1)
        if any(m.code == want for p in ex.parts for m in p.mistakes):
            return ex
    raise AssertionError(f"no {topic} instance with a {want} candidate")


def _check(ex: Exercise, index: int, text: str) -> str | None:
    part = ex.parts[index]
    return found(part.answer, part.mistakes, text)


def test_apply_line_h_on_the_line_instead_of_the_inverse_transpose():
    ex = _instance("apply-line", 2, "line-as-point")
    H, l = sympy.Matrix(ex.params["H"]), sympy.Matrix(ex.params["l"])
    assert _check(ex, 0, typed(H * l)) == "line-as-point"
    assert _check(ex, 0, typed(H.inv().T * l)) is None  # the right rule H⁻ᵀl
    assert _check(ex, 0, typed(H.inv() * l)) == "transposed"


def test_apply_point_and_conic_transposed_or_inverted():
    ex = _instance("apply-point", 2, "transposed")
    H, x = sympy.Matrix(ex.params["H"]), sympy.Matrix(ex.params["x"])
    assert _check(ex, 0, typed(H.T * x)) == "transposed"
    assert _check(ex, 0, typed(H * x)) is None
    ex = _instance("apply-conic", 2, "inverted")
    H, C = sympy.Matrix(ex.params["H"]), sympy.Matrix(ex.params["C"])
    assert _check(ex, 0, typed_matrix(H.T * C * H)) == "inverted"  # H used instead of H⁻¹
    assert _check(ex, 0, typed_matrix(H.inv().T * C * H.inv())) is None
    assert _check(ex, 0, typed_matrix((H.inv().T * C * H.inv()).inv())) == "dual"  # the dual conic


def test_homography_from_four_points_transposed_or_inverted():
    ex = _instance("homography4", 2, "inverted")
    H = sympy.Matrix(ex.parts[0].answer.value)
    assert _check(ex, 0, typed_matrix(H.inv())) == "inverted"
    assert _check(ex, 0, typed_matrix(-2 * H)) is None
    ex = _instance("homography4", 2, "transposed")
    assert _check(ex, 0, typed_matrix(sympy.Matrix(ex.parts[0].answer.value).T)) == "transposed"


def test_points_lines_and_planes_given_for_each_other():
    ex = _instance("join", 1, "dual")
    assert _check(ex, 0, typed(ex.params["p"])) == "dual"  # a given point where the line was asked
    ex = _instance("meet", 2, "dual")
    assert _check(ex, 0, typed(ex.params["m"])) == "dual"
    ex = _instance("ideal", 2, "dual")
    a, b, _ = ex.params["l"]
    assert _check(ex, 0, typed([a, b, 0])) == "dual"  # the normal of the lines
    assert _check(ex, 0, typed([b, -a, 1])) == "ideal-as-finite"  # the direction with a 1 appended
    assert _check(ex, 0, typed([-b, a, 0])) is None  # right: the direction (b, −a) up to sign
    ex = _instance("plane3", 1, "dual")
    assert _check(ex, 0, typed(ex.params["points"][1])) == "dual"
    ex = _instance("point3", 3, "ideal-as-finite")
    X = ex.parts[0].answer.value
    assert _check(ex, 0, typed([*X[:3], 1])) == "ideal-as-finite"
    ex = _instance("plucker", 1, "dual")
    A, B = ex.params["A"], ex.params["B"]
    l = {(i, j): A[i] * B[j] - A[j] * B[i] for i in range(4) for j in range(4)}
    # the dual coordinates (l34, l42, l23, l14, l13, l12) of the line AB
    assert _check(ex, 0, typed([l[2, 3], l[3, 1], l[1, 2], l[0, 3], l[0, 2], l[0, 1]])) == "dual"


def test_cross_ratio_in_another_order_and_with_a_lost_sign():
    ex = _instance("cross-ratio", 1, "order")
    a, b, c, d = (Point1(*p) for p in ex.params["points"])
    swapped = F(str(cross_ratio(a, b, d, c)))  # (A, B; D, C) = 1/λ
    assert _check(ex, 0, str(swapped)) == "order"
    assert _check(ex, 0, str(-ex.parts[0].answer.value)) == "sign"
    assert _check(ex, 0, str(F(str(cross_ratio(a, b, c, d))))) is None


def test_exact_answers_right_only_up_to_scale():
    ex = _instance("homogeneous", 2, "scale")
    assert _check(ex, 0, typed(ex.params["given"][:2])) == "scale"  # not divided by x3
    ex = _instance("decompose", 2, "scale")
    s, R = ex.parts[0].answer.value, sympy.Matrix(ex.parts[1].answer.value)
    assert _check(ex, 0, str(s * s)) == "scale"  # det(sRK) = s², no square root
    assert _check(ex, 1, typed_matrix(s * R)) == "scale"  # sR for R
    if R != R.T:
        assert _check(ex, 1, typed_matrix(R.T)) == "transposed"
    classify = next(get_template("classify").generate(seed, 3, 1) for seed in range(200)
                    if get_template("classify").generate(seed, 3, 1).params["class"] == "projectivity")
    assert _check(classify, 1, "9") == "scale"  # nine entries, but H is up to scale: 8
    assert _check(classify, 1, "8") is None


def test_metric_templates_name_the_usual_slips():
    ex = _instance("angle", 2, "squared")
    (l1, l2, _), (m1, m2, _) = ex.params["l"], ex.params["m"]
    cos2 = F((l1 * m1 + l2 * m2) ** 2, (l1**2 + l2**2) * (m1**2 + m2**2))
    assert _check(ex, 0, str(cos2)) == "squared"  # cos²θ, no square root
    sin2 = 1 - cos2
    assert _check(ex, 0, str(-ex.parts[0].answer.value)) == "sign"
    assert _check(ex, 0, str(ex.parts[0].answer.value)) is None
    # the sine: p² q = 1 − cos²θ; found among the candidates of part 0 by value
    sine = next(m for m in ex.parts[0].mistakes if m.code == "sine").answer.value
    q_sine = next((m.answer.value for m in ex.parts[1].mistakes if m.code == "sine"), ex.parts[1].answer.value)
    assert sine * sine * q_sine == sin2
    ex = _instance("angle", 2, "unsimplified")
    (l1, l2, _), (m1, m2, _) = ex.params["l"], ex.params["m"]
    cos2 = F((l1 * m1 + l2 * m2) ** 2, (l1**2 + l2**2) * (m1**2 + m2**2))
    assert _check(ex, 1, str(cos2.numerator * cos2.denominator)) == "unsimplified"  # √(n/d) = √(nd)/d, not reduced
    ex = _instance("perpendicular", 1, "parallel")
    (a, b, c), x = ex.params["l"], ex.params["x"]
    # the parallel through x: (a, b, −(a x1 + b x2)/x3), here with x3 = 1
    assert _check(ex, 0, typed([a, b, -(a * x[0] + b * x[1])])) == "parallel"
    assert _check(ex, 0, typed([b, -a, c])) == "wrong-point"
    ex = _instance("conic-type", 2, "reversed")
    wrong = "A" if ex.parts[0].answer.value == "B" else "B"  # ellipse for a hyperbola, or the other way round
    assert _check(ex, 0, wrong) == "reversed"


# --- the property over many seeds ------------------------------------------------------------------------
# the classes each built-in template must produce somewhere in its seeds
EXPECTED = {
    "homogeneous": {"sign", "scale"}, "join": {"sign", "dual"}, "meet": {"sign", "dual"},
    "ideal": {"sign", "dual", "ideal-as-finite"}, "apply-point": {"transposed", "inverted"},
    "apply-line": {"line-as-point", "transposed", "inverted"}, "apply-conic": {"transposed", "inverted", "dual"},
    "classify": {"scale"}, "cross-ratio": {"sign", "order"}, "homography4": {"transposed", "inverted"},
    "plane3": {"dual"}, "point3": {"dual", "ideal-as-finite"}, "plucker": {"dual", "sign"},
    "decompose": {"sign", "scale", "transposed", "inverted"}, "incidence": set(), "preserved": set(),
    "angle": {"sign", "squared", "absolute", "sine", "unsimplified"},
    "perpendicular": {"sign", "parallel", "wrong-point", "dual"}, "conic-type": {"reversed", "matrix-entry"},
}


def _scaled_text(key: Answer, k: int) -> str:
    if key.kind in ("projective", "vector"):
        return typed([k * F(v) for v in key.value])
    return "[" + ", ".join("[" + ", ".join(str(k * F(x)) for x in row) + "]" for row in key.value) + "]"


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_the_right_answer_is_never_a_mistake_and_every_candidate_is_recognised(name):
    template = all_templates()[name]
    codes: Counter = Counter()
    for seed in range(SEEDS):
        ex = template.generate(seed, template.levels[seed % len(template.levels)], 1)  # the fast path
        for part in ex.parts:
            key, cands = part.answer, part.mistakes
            assert found(key, cands, part.answer.display()) is None
            if key.kind in ("projective", "matrix"):
                assert found(key, cands, _scaled_text(key, -3)) is None  # right up to scale
            for m in cands:
                codes[m.code] += 1
                if m.answer.kind == key.kind:
                    assert not matches(key, m.answer.value), (seed, m)
                    text = m.answer.display()
                else:  # a multiple of an exact key: twice the key is such a wrong answer
                    text = _scaled_text(key, 2)
                assert not grade(key, text), (seed, m)
                hit = recognise(key, cands, read_as(key, text))
                assert hit is not None and matches(hit.answer, read_as(key, text)), (seed, m)
    assert EXPECTED[name] <= set(codes), (name, codes)


# --- the manifest -----------------------------------------------------------------------------------------
def test_the_manifest_stores_the_mistakes_and_an_old_one_still_grades(tmp_path):
    topics = parse_topics(["ideal:2", "apply-line"])
    sheets = build_sheets(topics, [("s1", "Ada")], 5)
    (tmp_path / "new.json").write_text(manifest_json(sheets, topics))
    data = load_manifest_data(tmp_path / "new.json")
    key = data.keys["s1"]["1"]
    assert data.mistakes["s1"]["1"] == sheets[0].exercises[0].parts[0].mistakes
    assert data.names == {"s1": "Ada"} and data.topics == {"1": "ideal", "2": "apply-line"}
    finite = typed([*key.value[:2], 1])
    report = grade_rows(data.keys, [("s1", "1", finite)], data.mistakes)
    assert report["s1"][0].mistake == "ideal-as-finite" and not report["s1"][0].correct
    # a manifest written before mistakes were stored: the same answer is wrong, without feedback
    old = json.loads((tmp_path / "new.json").read_text())
    for ex in old["students"][0]["exercises"]:
        for part in ex["parts"]:
            part.pop("mistakes", None)
    (tmp_path / "old.json").write_text(json.dumps(old))
    data = load_manifest_data(tmp_path / "old.json")
    report = grade_rows(data.keys, [("s1", "1", finite), ("s1", "2", data.keys["s1"]["2"].display())], data.mistakes)
    assert [(r.correct, r.mistake) for r in report["s1"]] == [(False, ""), (True, "")]


def test_a_damaged_or_hostile_mistake_list_costs_only_its_feedback(tmp_path):
    topics = parse_topics(["meet", "homography4"])
    sheets = build_sheets(topics, [("s1", "")], 2)
    data = json.loads(manifest_json(sheets, topics))
    point, matrix = (ex["parts"][0] for ex in data["students"][0]["exercises"])
    hostile = "<b>\x1b[31m" + "x" * 1000
    point["mistakes"] = [{"code": "dual", "message": hostile, "kind": "projective", "value": ["1", "0"]},  # 2 ≠ 3
                         {"code": "x", "message": "m", "kind": "scalar", "value": "1"},  # wrong kind
                         {"code": "sign", "message": hostile, "kind": "projective", "value": ["0", "0", "1"]}]
    matrix["mistakes"] = [{"code": "ragged", "message": "m", "kind": "matrix", "value": [["1"], ["1", "2"], []]}]
    (tmp_path / "m.json").write_text(json.dumps(data))
    loaded = load_manifest_data(tmp_path / "m.json")
    report = grade_rows(loaded.keys, [("s1", "1", "(0, 0, 5)"), ("s1", "2", "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]")],
                        loaded.mistakes)
    first, second = report["s1"]
    assert (first.mistake, len(first.feedback)) == ("sign", 300) and "\x1b" not in first.feedback
    assert not second.correct and second.mistake == ""
    (tmp_path / "bad.json").write_text(json.dumps(data).replace('"kind": "scalar", "value": "1"',
                                                                 '"kind": "scalar", "value": "1/0"'))
    with pytest.raises(ManifestError, match="damaged"):
        load_manifest_data(tmp_path / "bad.json")


def test_an_instructor_template_adds_its_own_mistake_class(tmp_path):
    from pgsym.exercises.template import load_template_folder

    (tmp_path / "t").mkdir()
    (tmp_path / "t" / "midsum.py").write_text(
        "from fractions import Fraction\n"
        "from pgsym.exercises.mistakes import mistake\n"
        "from pgsym.exercises.model import Answer\n"
        "from pgsym.exercises.template import Draft, Template\n\n\n"
        "class MidSum(Template):\n"
        "    name = 'midsum-test'\n"
        "    levels = (1,)\n\n"
        "    def mistakes(self, exercise, index):\n"
        "        p, q = exercise.params['p'], exercise.params['q']\n"
        "        return [*super().mistakes(exercise, index),\n"
        "                mistake('no-half', Answer.vector([p[0] + q[0], p[1] + q[1]]), 'p + q, not halved')]\n\n"
        "    def build(self, rng, level):\n"
        "        p, q = [rng.randint(1, 5), 2], [rng.randint(1, 5), 4]\n"
        "        m = [Fraction(p[0] + q[0], 2), Fraction(3)]\n"
        "        return Draft('p, q', [('midpoint?', Answer.vector(m), ())], [], {'p': p, 'q': q})\n\n"
        "    def verify(self, exercise):\n"
        "        pass\n")
    assert load_template_folder(tmp_path / "t") == ["midsum-test"]
    sheets = build_sheets(["midsum-test"], [("s1", "")], 4)
    (tmp_path / "m.json").write_text(manifest_json(sheets, [("midsum-test", 1)]))
    data = load_manifest_data(tmp_path / "m.json")  # no template needed from here on
    p, q = sheets[0].exercises[0].params["p"], sheets[0].exercises[0].params["q"]
    report = grade_rows(data.keys, [("s1", "1", typed([p[0] + q[0], 6]))], data.mistakes)
    assert (report["s1"][0].mistake, report["s1"][0].feedback) == ("no-half", "p + q, not halved")
    # p + q = 2 · (p + q)/2 is also a multiple of the answer: the concrete candidate is preferred
    assert [m.code for m in data.mistakes["s1"]["1"]][-2:] == ["scale", "no-half"]
