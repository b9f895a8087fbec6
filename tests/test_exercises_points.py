"""Points: one definition per part (command line, else the template's attribute, else 1), stored in the
manifest and read back by the grader; bad specifications are named errors."""

from __future__ import annotations

from fractions import Fraction

import pytest
from click.testing import CliRunner

from pgsym.cli import main
from pgsym.exercises.errors import TemplateError
from pgsym.exercises.grading import grade_rows, score_summary
from pgsym.exercises.points import parse_points
from pgsym.exercises.sheets import build_sheets, load_manifest_data, manifest_json, parse_topics
from pgsym.exercises.template import load_template_folder


@pytest.mark.parametrize(("spec", "message"), [
    ("join", "should be TOPIC=POINTS"),
    ("join=", "should be TOPIC=POINTS"),
    ("join=x", "'x' is not a number of points"),
    ("join=0", "points must be positive"),
    ("join=-1", "points must be positive"),
    ("join=101", "at most 100"),
    ("join=1/0", "is not a number of points"),
])
def test_bad_specifications_are_named(spec, message):
    with pytest.raises(TemplateError, match=message):
        parse_points(spec)


def test_a_wrong_number_of_part_points_is_named():
    with pytest.raises(TemplateError, match="2 numbers given for 1 parts"):
        build_sheets(["join"], [("s1", "")], 1, points=parse_points("join=1+2"))
    result = CliRunner().invoke(main, ["sheet", "--topics", "join", "--points", "join=1+2", "--out", "never"])
    assert result.exit_code == 1 and "2 numbers given for 1 parts" in result.output


def test_template_attribute_then_command_line(tmp_path):
    (tmp_path / "weighted.py").write_text(
        "from pgsym.exercises.model import Answer\n"
        "from pgsym.exercises.template import Draft, Template\n\n\n"
        "class Weighted(Template):\n"
        "    name = 'weighted-pair'\n"
        "    levels = (1,)\n"
        "    points = (1, 3)\n\n"
        "    def build(self, rng, level):\n"
        "        return Draft('S', [('a', Answer.scalar(1), ()), ('b', Answer.scalar(2), ())], ['s'])\n\n"
        "    def verify(self, ex):\n"
        "        pass\n")
    load_template_folder(tmp_path)
    declared = build_sheets(["weighted-pair", "join"], [("s1", "")], 1)[0]
    assert [p.points for ex in declared.exercises for p in ex.parts] == [1, 3, 1]
    overridden = build_sheets(["weighted-pair", "join"], [("s1", "")], 1,
                              points=parse_points("weighted-pair=1/2,default=2"))[0]
    assert [p.points for ex in overridden.exercises for p in ex.parts] == [Fraction(1, 2), Fraction(1, 2), 2]
    # the manifest keeps them, and the grader sums them: 1/2 (1a right) + 0 (1b wrong) + 2 (2 right) of 3
    path = tmp_path / "m.json"
    path.write_text(manifest_json([overridden], parse_topics("weighted-pair,join")))
    data = load_manifest_data(path)
    line = overridden.exercises[1].parts[0].answer.display()
    report = grade_rows(data.keys, [("s1", "1a", "1"), ("s1", "1b", "5"), ("s1", "2", line)], data.mistakes,
                        data.points)
    assert score_summary(report) == [("s1", Fraction(5, 2), Fraction(3))]
