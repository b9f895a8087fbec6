"""`pgsym prove`, run as the installed command; theorem files (``pgsym prove FILE``) in-process with CliRunner."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

from _installed import run_pgsym
from click.testing import CliRunner

from pgsym.cli import main
from pgsym.proofs import CATALOGUE, catalogue_names

THEOREMS = Path(__file__).parent / "theorems"


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return run_pgsym("prove", *args, timeout=120)


def test_list_names_every_claim():
    result = run("--list")
    assert result.returncode == 0
    names = [line.split()[0] for line in result.stdout.splitlines()]
    assert names == list(CATALOGUE)
    assert "FALSE" in result.stdout and "pappus" in names


def test_named_claims_are_proved_and_exit_zero():
    result = run("pappus", "desargues", "cross-product-sign-flipped")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0].startswith("proved") and "pappus" in lines[0]
    assert lines[2].startswith("false") and "counterexample" in lines[2] and "[false claim]" in lines[2]


def test_all_as_json_with_the_progress_bar_on_stderr():
    result = run("--all", "--json")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)  # stdout is pure JSON: the progress bar went to stderr
    assert [d["name"] for d in data] == catalogue_names()
    assert all(d["as_expected"] for d in data)
    assert "proving" in result.stderr


def test_a_true_claim_that_is_not_proved_exits_one():
    result = run("--timeout", "0.000001", "pappus")
    assert result.returncode == 1
    assert result.stdout.startswith("unknown") and "timed out" in result.stdout
    assert "not as expected: pappus" in result.stderr


def test_a_false_claim_that_stays_unknown_does_not_fail():
    result = run("--timeout", "0.000001", "cross-product-sign-flipped")
    assert result.returncode == 0 and result.stdout.startswith("unknown")


def test_usage_errors_exit_two():
    for args, message in ((("no-such-claim",), "no claim named 'no-such-claim'"), ((), "give claim names"),
                          (("--all", "pappus"), "not both")):
        result = run(*args)
        assert result.returncode == 2 and message in result.stderr


# -- theorem files ------------------------------------------------------------------------------------



def _invoke(*args: str):
    return CliRunner().invoke(main, ["prove", *args], catch_exceptions=False)


def test_a_true_theorem_file_is_proved():
    result = _invoke(str(THEOREMS / "pappus.thm"))
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("proved")
    assert "pappus" in result.stdout


def test_a_false_theorem_file_is_refuted_as_expected():
    result = _invoke(str(THEOREMS / "fano-false.thm"))
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith("false") and "counterexample" in result.stdout and "[false claim]" in result.stdout


def test_certificate_and_json(tmp_path):
    result = _invoke(str(THEOREMS / "desargues.thm"), "--certificate")
    assert result.exit_code == 0
    assert "Non-degeneracy conditions" in result.output and "O ≠ A" in result.output
    result = _invoke(str(THEOREMS / "desargues.thm"), "--json")
    (verdict,) = json.loads(result.stdout)
    assert verdict["status"] == "proved" and verdict["name"] == "desargues"


def test_catalogue_names_still_work():
    result = _invoke("pappus")
    assert result.exit_code == 0 and result.stdout.startswith("proved")


def test_a_file_stated_true_but_false_exits_1(tmp_path):
    f = tmp_path / "wrong.thm"
    f.write_text("points A B C\nprove collinear A B C\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["prove", str(f)])
    assert result.exit_code == 1
    assert "not as expected: wrong" in result.output


def test_bad_files_exit_2_with_file_line_and_column(tmp_path):
    f = tmp_path / "bad.thm"
    f.write_text("points A B\nline l = join A C\nprove on A l\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["prove", str(f)])
    assert result.exit_code == 2
    # line 2, column 17: the C of "line l = join A C"
    assert f"Error: {f}:2:17: C is not defined" in result.output
    missing = tmp_path / "missing.thm"
    result = CliRunner().invoke(main, ["prove", str(missing)])
    assert result.exit_code == 2 and "Error:" in result.output and "cannot read" in result.output
    binary = tmp_path / "binary.thm"
    binary.write_bytes(b"points A\x00\xff\n")
    result = CliRunner().invoke(main, ["prove", str(binary)])
    assert result.exit_code == 2 and f"Error: {binary}:1:" in result.output


def test_help_shows_an_example():
    result = _invoke("--help")
    assert result.exit_code == 0
    assert "points A B C D" in result.output and "prove collinear X Y Z" in result.output


def test_discover_finds_and_proves_the_pappus_line():
    result = CliRunner().invoke(main, ["discover", str(THEOREMS / "pappus.thm")])
    assert result.exit_code == 0, result.output
    assert "proved            X, Y, Z are collinear" in result.stdout
    assert "by construction" not in result.stdout
    result = CliRunner().invoke(main, ["discover", "--all", "--json", str(THEOREMS / "pappus.thm")])
    rows = json.loads(result.stdout)
    assert {"kind": "on", "objects": ["A", "join A D"], "text": "A lies on join A D",
            "status": "by construction"} in rows


def test_discover_bad_file_exits_2(tmp_path):
    f = tmp_path / "bad.thm"
    f.write_text("points A\npoint B = join A\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["discover", str(f)])
    assert result.exit_code == 2 and f"Error: {f}:2:" in result.output


def test_discover_help_shows_an_example():
    result = CliRunner().invoke(main, ["discover", "--help"])
    assert result.exit_code == 0 and "point P = meet (join A B) (join C D)" in result.output


def test_discover_says_when_conics_were_looked_for_among_some_points_only(tmp_path):
    # 13 points: the six-on-a-conic search covers the first 12 (C(12, 6) = 924 determinants) and says so
    f = tmp_path / "many.thm"
    f.write_text("points " + " ".join(f"P{i}" for i in range(13)) + "\nprove collinear P0 P1 P2\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["discover", str(f)])
    assert result.exit_code == 0, result.output
    assert "among the first 12 of the 13 points only" in result.stderr
    f.write_text("points " + " ".join(f"P{i}" for i in range(12)) + "\nprove collinear P0 P1 P2\n", encoding="utf-8")
    assert "only" not in CliRunner().invoke(main, ["discover", str(f)]).stderr


def test_help_shows_a_euclidean_example_that_is_proved(tmp_path):
    # the example printed by --help is a theorem (Simson's line) that the command proves
    text = _invoke("--help").output
    lines = text[text.index("    points A B C\n"):].splitlines()[:4]
    f = tmp_path / "simson.thm"
    f.write_text("\n".join(line.strip() for line in lines) + "\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["prove", str(f)])
    assert result.exit_code == 0 and "proved" in result.output, result.output
