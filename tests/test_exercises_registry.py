"""Instructor templates named like built-in ones, and the variation check of `pgsym templates check`."""

from __future__ import annotations

from fractions import Fraction

import pytest
from click.testing import CliRunner

from pgsym.cli import main
from pgsym.exercises.errors import TemplateNameError
from pgsym.exercises.model import Answer
from pgsym.exercises.registry import get_template, load_template_folder
from pgsym.exercises.sheets import build_sheets
from pgsym.exercises.stress import MAX_TOP_SHARE, stress
from pgsym.exercises.template_base import Draft, Template

_JOIN_AGAIN = '''
from pgsym.exercises.model import Answer
from pgsym.exercises.template import Draft, Template


class MyJoin(Template):
    name = "join"
    title = "Not the built-in join"
    levels = (1,)

    def build(self, rng, level):
        return Draft("Say 1.", [("Give 1.", Answer.integer(1), ())], ["1."])

    def verify(self, exercise):
        pass
'''


def test_a_template_named_like_a_builtin_is_refused(tmp_path):
    (tmp_path / "mine.py").write_text(_JOIN_AGAIN)
    with pytest.raises(TemplateNameError, match=r"defines .join., the name of a built-in template.*--replace"):
        load_template_folder(tmp_path)
    assert get_template("join").title == "The line through two points"  # still the built-in


def test_the_cli_refuses_and_replaces_only_on_request(tmp_path):
    (tmp_path / "t").mkdir()
    (tmp_path / "t" / "mine.py").write_text(_JOIN_AGAIN)
    args = ["sheet", "--templates", str(tmp_path / "t"), "--topics", "join", "--format", "md"]
    refused = CliRunner().invoke(main, [*args, "--out", str(tmp_path / "a")])
    assert refused.exit_code == 1 and "TemplateNameError" in refused.output and not (tmp_path / "a").exists()
    try:
        replaced = CliRunner().invoke(main, [*args, "--replace-templates", "--out", str(tmp_path / "b")])
        assert replaced.exit_code == 0, replaced.output
        assert "Not the built-in join" in next((tmp_path / "b" / "md").iterdir()).read_text()
    finally:
        from pgsym.exercises import registry

        registry._EXTRA.pop("join", None)
        registry._ORIGIN.pop("join", None)


class _Constant(Template):
    name = "constant-test"
    title = "Always two"
    levels = (1,)

    def build(self, rng, level):  # type: ignore[no-untyped-def]
        x = rng.randint(1, 9)  # the statement varies, the answer does not
        return Draft(f"Let x = {x}.", [("Give 2.", Answer.integer(2), ())], ["2."])

    def verify(self, exercise):  # type: ignore[no-untyped-def]
        pass


class _Coin(_Constant):
    name = "coin-test"

    def build(self, rng, level):  # type: ignore[no-untyped-def]
        value = rng.choice((1, 2))
        return Draft("Toss.", [("Give it.", Answer.scalar(Fraction(value)), ())], ["."])


def test_a_template_whose_answer_never_varies_fails_the_check():
    report = stress(_Constant(), seeds=40)
    assert not report.ok and report.top_shares["-@level1"] == (1.0, 1)
    assert "barely varies: 1 distinct answer(s), the most common (2) in 100% of 40 instances" in report.failures[0]


def test_a_two_valued_answer_passes_and_the_threshold_is_a_share():
    report = stress(_Coin(), seeds=200)
    top, distinct = report.top_shares["-@level1"]
    assert report.ok and distinct == 2 and 0.5 <= top < MAX_TOP_SHARE


def test_angle_at_level_1_gives_a_class_different_answers():
    sheets = build_sheets([("angle", 1)], [(f"s{i}", "") for i in range(30)], master_seed=2026)
    answers = {s.exercises[0].parts[0].answer.display() for s in sheets}
    assert len(sheets[0].exercises[0].parts) == 1 and len(answers) >= 3
    assert stress(get_template("angle"), seeds=300).ok
