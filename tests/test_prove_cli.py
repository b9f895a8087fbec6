"""`pgsym prove`, run as the installed command."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

from pgsym.proofs import CATALOGUE, catalogue_names

PGSYM = shutil.which("pgsym", path=str(Path(sys.executable).parent))


def run(*args: str) -> subprocess.CompletedProcess[str]:
    assert PGSYM is not None, "the pgsym console script is not installed next to this Python"
    return subprocess.run([PGSYM, "prove", *args], capture_output=True, text=True, timeout=120,
                          stdin=subprocess.DEVNULL)


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
