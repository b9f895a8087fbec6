"""The installed `pgsym` command, run as a user would."""

from __future__ import annotations

import subprocess
import sys
from fractions import Fraction

import pytest
from _installed import run_pgsym
from hypothesis import given
from hypothesis import strategies as st

import pgsym
from pgsym.cli._common import parse_coordinates, parse_number, parse_points
from pgsym.errors import InputLimitError, PgsymError
from pgsym.limits import MAX_DIGITS, MAX_EXPONENT


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return run_pgsym(*args, timeout=60)


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


def test_an_unexpected_exception_is_one_line_not_a_traceback(monkeypatch):
    # the last resort for bugs: no hostile input reaches it (tests/hostile), so provoke it by hand
    from click.testing import CliRunner

    import pgsym.cli.geometry

    def broken(obj):  # type: ignore[no-untyped-def]
        raise RuntimeError("a bug\nsecond line")

    monkeypatch.setattr(pgsym.cli.geometry, "_describe", broken)
    result = CliRunner().invoke(pgsym.cli.main, ["join", "0,0", "1,1"])
    assert result.exit_code == 1 and isinstance(result.exception, SystemExit)
    assert result.stderr == ("Error: internal error (RuntimeError: a bug); "
                             "please report it with the command that caused it\n")


def test_a_pgsym_error_anywhere_in_a_command_is_one_clean_line(monkeypatch):
    from click.testing import CliRunner

    import pgsym.cli.geometry
    from pgsym.errors import UndecidableError

    def undecidable(obj):  # type: ignore[no-untyped-def]
        raise UndecidableError("cannot decide")

    monkeypatch.setattr(pgsym.cli.geometry, "_describe", undecidable)
    result = CliRunner().invoke(pgsym.cli.main, ["meet", "1,0,0", "0,1,0"])
    assert (result.exit_code, result.stderr) == (1, "Error: UndecidableError: cannot decide\n")


def test_the_exact_commands_read_the_one_number_grammar():
    # 1.5e-3 = 3/2000 and -2/3 exactly: the line through (3/2000, -2/3) and (0, 1) is
    # (-2/3 - 1, 0 - 3/2000, 3/2000 * 1 - 0 * (-2/3)) = (-5/3, -3/2000, 3/2000) ~ (10000, 9, -9)
    result = run("join", "1.5e-3, -2/3", "0 1")
    assert result.returncode == 0, result.stderr
    assert "canonical: (10000, 9, -9)" in result.stdout


# The one grammar of numbers (pgsym.cli._common), as properties: exact values, limits on the text.
MANTISSAS = st.integers(-(10**MAX_DIGITS) + 1, 10**MAX_DIGITS - 1)
EXPONENTS = st.integers(-MAX_EXPONENT, MAX_EXPONENT)


@given(MANTISSAS, EXPONENTS)
def test_scientific_notation_is_read_exactly(m, e):
    # m e e means m * 10**e, computed here with integers only
    expected = Fraction(m * 10**e) if e >= 0 else Fraction(m, 10**-e)
    assert parse_number(f"{m}e{e}") == expected
    assert parse_number(f"{m}E+{e}" if e >= 0 else f"{m}E{e}") == expected


@given(MANTISSAS, st.integers(1, 10**MAX_DIGITS - 1))
def test_fractions_are_read_exactly(p, q):
    assert parse_number(f"{p}/{q}") == Fraction(p, q)


@given(st.integers(0, 10**20), st.integers(0, 20))
def test_decimals_are_read_exactly(n, places):
    # the digits of n with a point `places` from the right: n / 10**places
    text = str(n).rjust(places + 1, "0")
    decimal = f"{text[:len(text) - places]}.{text[len(text) - places:]}"
    assert parse_number(decimal) == Fraction(n, 10**places)


@given(st.integers(MAX_EXPONENT + 1, 10**12), st.sampled_from(["", "-", "+"]))
def test_an_exponent_beyond_the_limit_is_refused_on_the_text(e, sign):
    with pytest.raises(InputLimitError, match="exponent"):
        parse_number(f"1e{sign}{e}")


@given(st.integers(10**MAX_DIGITS, 10**(3 * MAX_DIGITS)))
def test_too_many_digits_are_refused(n):
    for text in (str(n), f"1/{n}", f"{str(n)[:1]}.{str(n)[1:]}"):
        with pytest.raises(InputLimitError, match="digits"):
            parse_number(text)


@given(st.text(max_size=30))
def test_any_text_is_a_number_list_or_a_named_error(text):
    try:
        values = parse_coordinates(text)
    except PgsymError:
        return
    assert values and all(isinstance(v, Fraction) for v in values)


@given(st.lists(st.tuples(st.integers(-999, 999), st.integers(-999, 999)), min_size=1, max_size=8))
def test_points_and_coordinates_share_the_grammar(pairs):
    text = " ".join(f"{x},{y}" for x, y in pairs)
    assert parse_points(text) == [(float(x), float(y)) for x, y in pairs]
    assert parse_coordinates(text) == tuple(Fraction(v) for pair in pairs for v in pair)
