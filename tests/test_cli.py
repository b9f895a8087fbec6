"""The installed `pgsym` command, run as a user would."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import pgsym

PGSYM = shutil.which("pgsym", path=str(Path(sys.executable).parent))


def run(*args: str) -> subprocess.CompletedProcess[str]:
    assert PGSYM is not None, "the pgsym console script is not installed next to this Python"
    return subprocess.run([PGSYM, *args], capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL)


def test_version():
    result = run("--version")
    assert result.returncode == 0
    assert result.stdout.strip() == f"pgsym, version {pgsym.__version__}"


def test_help_lists_the_commands():
    result = run("--help")
    assert result.returncode == 0
    assert "join" in result.stdout and "meet" in result.stdout and "Usage: pgsym" in result.stdout


def test_join_prints_the_cross_product_and_the_equation():
    result = run("join", "0,0", "1,1")
    assert result.returncode == 0
    assert result.stdout.strip() == "line: (-1, 1, 0)   canonical: (1, -1, 0)   equation: x - y = 0"


def test_meet_of_parallel_lines_is_ideal():
    result = run("meet", "1,-1,0", "1 -1 3")
    assert result.returncode == 0
    assert "canonical: (1, 1, 0)" in result.stdout and "ideal point" in result.stdout


def test_meet_with_fractions_is_exact():
    result = run("meet", "1,0,-1/2", "0,1,-2/3")
    assert result.returncode == 0
    assert "inhomogeneous: (1/2, 2/3)" in result.stdout


@pytest.mark.parametrize(
    ("args", "code", "message"),
    [
        (("join", "1,2", "2,4,2"), 1, "CoincidentPointsError"),
        (("meet", "1,2,3", "2,4,6"), 1, "CoincidentLinesError"),
        (("join", "1,x", "2,3"), 2, "'x' is not a number"),
        (("join", "1,2,3,4", "2,3"), 1, "DimensionError"),
        (("meet", "0,0,0", "1,2,3"), 1, "ZeroVectorError"),
        (("join", "1/0,2", "2,3"), 2, "not a number"),
        (("join", "__import__('os')", "2,3"), 2, "not a number"),
        (("join", "1,2"), 2, "Missing argument"),
    ],
)
def test_bad_input_gives_a_message_and_nonzero_exit(args, code, message):
    result = run(*args)
    assert result.returncode == code
    assert message in result.stderr
    assert "Traceback" not in result.stderr


def test_version_and_help_do_not_load_sympy_or_opencv():
    code = (
        "import sys\n"
        "from click.testing import CliRunner\n"
        "from pgsym.cli import main\n"
        "assert CliRunner().invoke(main, ['--help']).exit_code == 0\n"
        "print(sorted(m for m in ('sympy', 'cv2', 'skimage', 'matplotlib') if m in sys.modules))\n"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "[]"
