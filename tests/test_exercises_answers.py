"""The answer parser (no evaluation, bounded) and grading up to scale, incl. ideal points and zero."""

from __future__ import annotations

import time
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from pgsym.exercises.answers import MAX_DEPTH, grade, parse_answer, read_as, self_check
from pgsym.exercises.errors import UnparsableAnswerError
from pgsym.exercises.grading import grade_rows
from pgsym.exercises.model import Answer

F = Fraction


# --- the parser --------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("3", F(3)),
        ("-3/4", F(-3, 4)),
        ("+0.25", F(1, 4)),
        ("3/-6", F(-1, 2)),
        ("0", F(0)),
        ("(1, -2/3, 0)", (F(1), F(-2, 3), F(0))),
        ("1, 2; 3", (F(1), F(2), F(3))),
        ("[1 ,2]", (F(1), F(2))),
        ("((5))", F(5)),
        ("[[1, 0], [0, 1/2]]", ((F(1), F(0)), (F(0), F(1, 2)))),
        ("\u22122", F(-2)),  # the unicode minus sign is read as a minus
    ],
)
def test_parser_reads_numbers_vectors_matrices(text, value):
    assert parse_answer(text) == value


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("__import__('os')", "unexpected character '_'"),
        ("exec('1')", "unexpected character 'e'"),
        ("1e9999", "unexpected character 'e'"),
        ("2**1000", "unexpected character '*'"),
        ("1/0", "division by zero"),
        ("(" * 50 + "1" + ")" * 50, "nested more than"),
        ("9" * 41, "more than 40 digits"),
        ("1," * 2000, "characters long"),
        (", ".join(["1"] * 65), "more than 64 numbers"),
        ("", "empty"),
        ("   ", "empty"),
        ("(1, 2", "ends too early"),
        ("(1, 2]", "closed by"),
        ("1 2", "unexpected '2'"),
        ("1..2", "is not a number"),
        ("\uff11", "U+FF11"),  # fullwidth digit one: not read as 1
        ("1\u200b", "U+200B"),  # zero-width space
        ("--1", "expected a number"),
    ],
)
def test_parser_rejects_hostile_or_malformed_text_with_a_reason(text, message):
    with pytest.raises(UnparsableAnswerError, match="cannot read the answer") as info:
        parse_answer(text)
    assert message in str(info.value)


def test_depth_limit_is_exactly_max_depth():
    assert parse_answer("[" * MAX_DEPTH + "1" + "]" * MAX_DEPTH) == F(1)
    with pytest.raises(UnparsableAnswerError):
        parse_answer("[" * (MAX_DEPTH + 1) + "1" + "]" * (MAX_DEPTH + 1))


def test_long_hostile_input_is_rejected_quickly():
    t0 = time.perf_counter()
    for text in ("(" * 1999, "1/" * 999 + "1", "9" * 1999, "-" * 1999):
        with pytest.raises(UnparsableAnswerError):
            parse_answer(text)
    assert time.perf_counter() - t0 < 2.0  # milliseconds when idle; generous for a loaded CI machine


# --- fuzzing ---------------------------------------------------------------------------------------------
# the characters of numbers, brackets and separators mixed with letters, quotes, operators and unicode
_ALPHABET = "0123456789+-/.,;()[] _eEx*'\"\\\u2212\uff11\u200b"


# generation only (no shrinking or database): 10^4 inputs per run is the point of this test
@settings(max_examples=10_000, deadline=None, database=None, phases=[Phase.generate],
          suppress_health_check=list(HealthCheck))
@given(st.one_of(st.text(alphabet=_ALPHABET, max_size=40), st.text(max_size=40)))
def test_fuzz_parser_returns_a_value_or_a_named_error(text):
    # any input: either an exact value or UnparsableAnswerError, never another exception, never evaluation
    try:
        value = parse_answer(text)
    except UnparsableAnswerError as err:
        assert str(err).startswith("cannot read the answer")
        return
    assert isinstance(value, (Fraction, tuple))


_num = st.fractions(max_denominator=50).filter(lambda f: abs(f.numerator) < 10**6)


@settings(max_examples=60, deadline=None)
# the scale stays small enough that every typed entry is within the parser's 40-digit limit
@given(st.lists(_num, min_size=2, max_size=6),
       st.fractions(max_denominator=9).filter(lambda f: f != 0 and abs(f.numerator) < 10**12))
def test_any_nonzero_multiple_of_a_projective_answer_grades_right(values, scale):
    if all(v == 0 for v in values):
        return
    key = Answer.projective(values)
    typed = "(" + ", ".join(str(v * scale) for v in values) + ")"
    assert grade(key, typed)


# --- grading up to scale -----------------------------------------------------------------------------------
def test_projective_answers_are_equal_up_to_a_nonzero_scale():
    key = Answer.projective([1, -2, 0])  # an ideal point: the direction (1, -2)
    assert grade(key, "(1, -2, 0)")
    assert grade(key, "(-3, 6, 0)")
    assert grade(key, "1/2, -1, 0")
    assert grade(key, "(0.5, -1.0, 0)")
    assert not grade(key, "(1, 2, 0)")
    assert not grade(key, "(1, -2, 1)")
    assert not grade(key, "(0, 0, 0)")  # the zero vector is no point


def test_zero_entries_and_fractions_are_accepted():
    # a line through the origin: (3, -2, 0) ~ (1/2, -1/3, 0) (multiply by 6)
    key = Answer.projective([F(1, 2), F(-1, 3), 0])
    assert key.value == (3, -2, 0)
    assert grade(key, "(1/2, -1/3, 0)")
    assert grade(Answer.scalar(0), "0")
    assert grade(Answer.scalar(F(4, 3)), "4/3") and grade(Answer.scalar(F(4, 3)), "8/6")
    assert not grade(Answer.scalar(F(4, 3)), "1.333")


def test_matrices_and_conics_up_to_scale():
    # the unit circle x^2 + y^2 - 1 = 0: diag(1, 1, -1) ~ diag(-2, -2, 2)
    key = Answer.matrix([[1, 0, 0], [0, 1, 0], [0, 0, -1]])
    assert grade(key, "[[-2, 0, 0], [0, -2, 0], [0, 0, 2]]")
    assert not grade(key, "[[1, 0, 0], [0, 1, 0], [0, 0, 1]]")
    assert not grade(key, "[[0, 0, 0], [0, 0, 0], [0, 0, 0]]")
    with pytest.raises(UnparsableAnswerError, match="expected 3 rows"):
        grade(key, "[[1, 0, 0], [0, 1, 0]]")


def test_exact_kinds_are_not_up_to_scale():
    assert grade(Answer.vector([F(1, 2), 3]), "(0.5, 3)")
    assert not grade(Answer.vector([F(1, 2), 3]), "(1, 6)")
    assert grade(Answer.matrix_exact([[2, 1], [0, F(1, 2)]]), "[[2, 1], [0, 1/2]]")
    assert not grade(Answer.matrix_exact([[2, 1], [0, F(1, 2)]]), "[[4, 2], [0, 1]]")
    assert grade(Answer.integer(8), "8") and not grade(Answer.integer(8), "7")
    with pytest.raises(UnparsableAnswerError, match="expected an integer"):
        read_as(Answer.integer(8), "15/2")


def test_choices_and_wrong_shapes():
    assert grade(Answer.choice("C"), " c ")
    with pytest.raises(UnparsableAnswerError):
        grade(Answer.choice("C"), "C or D")
    with pytest.raises(UnparsableAnswerError, match="expected 3 numbers"):
        grade(Answer.projective([1, 0, 0]), "(1, 0)")
    with pytest.raises(UnparsableAnswerError, match="expected one number"):
        grade(Answer.scalar(1), "(1, 2)")


def test_grade_rows_reports_missing_unreadable_and_unknown():
    keys = {"s1": {"1": Answer.projective([1, 1, 0]), "2": Answer.scalar(-1)}, "s2": {"1": Answer.choice("A")}}
    report = grade_rows(keys, [("s1", "1", "(2, 2, 0)"), ("s1", "2", "__import__('os')"), ("s9", "1", "A"),
                               ("s1", "7", "1")])
    reasons = {(r.student, r.label): (r.correct, r.reason) for rs in report.values() for r in rs}
    assert reasons[("s1", "1")] == (True, "")
    assert not reasons[("s1", "2")][0] and reasons[("s1", "2")][1].startswith("cannot read")
    assert reasons[("s2", "1")] == (False, "no answer")
    assert reasons[("s9", "1")] == (False, "student not in the manifest")
    assert "no such question" in reasons[("s1", "7")][1]


def test_self_check_digest():
    from pgsym.exercises.answers import answer_digest

    key = Answer.projective([0, 1, 0])
    digest = answer_digest("F-0:1", key)
    assert self_check("F-0:1", "projective", digest, "(0, -5, 0)")
    assert not self_check("F-0:1", "projective", digest, "(0, 0, 0)")
    assert not self_check("F-0:2", "projective", digest, "(0, 1, 0)")  # the salt is part of the digest


def test_parser_never_calls_eval_or_sympify(monkeypatch):
    import builtins

    import sympy

    def forbidden(*args, **kwargs):
        raise AssertionError("the parser must not evaluate text")

    monkeypatch.setattr(builtins, "eval", forbidden)
    monkeypatch.setattr(builtins, "exec", forbidden)
    monkeypatch.setattr(sympy, "sympify", forbidden)
    monkeypatch.setattr(sympy, "parse_expr", forbidden, raising=False)
    assert grade(Answer.projective([2, 0, -1]), "(-4, 0, 2)")
    with pytest.raises(UnparsableAnswerError):
        parse_answer("__import__('os').system('true')")
