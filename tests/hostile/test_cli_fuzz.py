"""Property test: no argument list makes any `pgsym` command crash, hang or show a traceback.

The argument lists are generated from each command's own click parameters (found by walking
``main.commands``), so an option added later is fuzzed without touching this file. Values mix
hostile text (huge exponents, 5000 digits, unicode digits, NUL, nan, paths that escape) with cheap
valid ones (small files in a fresh working folder), so that examples also get past parsing.
Each example runs in-process with click's CliRunner in its own temporary working folder and must
exit with 0, 1 or 2, with no traceback, no "internal error", no exception other than SystemExit,
within PER_EXAMPLE seconds. Examples are derandomized: every run checks the same ones (no flaky tests).
"""

from __future__ import annotations

import os
import signal
import tempfile
import time
import zlib
from pathlib import Path

import click
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

# load the heavy modules once, so the first example of a command is not charged with imports
import pgsym.exercises.sheets
import pgsym.projective_plane
import pgsym.proofs.catalogue
import pgsym.vision.harris
import pgsym.vision.rectify  # noqa: F401
from pgsym.cli import main
from pgsym.limits import MAX_ARGUMENT_CHARS

PER_EXAMPLE = 10.0  # seconds; an example takes a few milliseconds to about a second
EXAMPLES = 85  # per command: 12 commands and groups (the root included), so 1020 per run

# Options whose valid use is slow by design and is tested elsewhere: proving the whole catalogue
# (tests/test_prove_cli.py). Everything else a command accepts is fuzzed.
EXPENSIVE = {("prove", "all_")}
# Options always given, because their default is slow by design: 10000 seeds per template.
ALWAYS = {("templates", "check", "seeds")}


def _commands(group: click.Group, prefix: tuple[str, ...] = ()):  # type: ignore[no-untyped-def]
    yield prefix, group
    for name, command in sorted(group.commands.items()):
        if isinstance(command, click.Group):
            yield from _commands(command, (*prefix, name))
        else:
            yield (*prefix, name), command


COMMANDS = list(_commands(main))

HOSTILE = [
    "", " ", ",", ";", "0", "-1", "1", "-0", "1e99999999", "1e5000", "-1e-99999", "9" * 5000, "1/" + "9" * 60,
    "x" * 10_000, "1," * 300, "nan", "inf", "-inf", "NaN", "1e309", "\u0663", "\uff11", "\u2212" + "1", "1/0",
    "\x00", "1\x00", "__import__('os').system('true')", "../escape", "/proc/pgsym-fuzz", "~", "-",
    "--", "--help", "0x0", "16384x16384", "\u00e9\u00e8", "\U0001f600",
]
# cheap valid words (coordinates, topics, formats, a claim), so that examples also get past parsing
VALID = ["1,2", "1,2,3", "1 -1 3", "0,0 9,0 9,9 0,9", "0,0 9,0; 0,5 9,6", "400x300", "join", "meet", "join:2", "md",
         "html", "md,html", "join-contains-both-points"]
# a few files in every example's working folder
PATHS = ["good.png", "text.png", "empty.png", "folder", "missing.png", "out", "out.png", "sub/out.png",
         "existing.txt", "existing.txt/out.png", "roster.csv", "manifest.json", "answers.csv", "templates",
         "/proc/pgsym-fuzz.png", "x" * 300]


def _fill(folder: Path) -> None:
    rows = b"".join(b"\x00" + bytes(255 if 6 <= x < 18 and 4 <= y < 12 else 0 for x in range(24)) for y in range(16))
    ihdr = (24).to_bytes(4, "big") + (16).to_bytes(4, "big") + bytes([8, 0, 0, 0, 0])

    def chunk(kind: bytes, data: bytes) -> bytes:
        return len(data).to_bytes(4, "big") + kind + data + zlib.crc32(kind + data).to_bytes(4, "big")

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")
    (folder / "good.png").write_bytes(png)
    (folder / "text.png").write_text("not an image\n")
    (folder / "empty.png").write_bytes(b"")
    (folder / "folder").mkdir()
    (folder / "templates").mkdir()
    (folder / "existing.txt").write_text("keep\n")
    (folder / "roster.csv").write_text("id,name\ns1,Ada\ns2,Alan\n")
    (folder / "manifest.json").write_text('{"format": "pgsym-exercises", "students": []}')
    (folder / "answers.csv").write_text("id,1\ns1,\"(1, 2, 3)\"\n")


def _texts() -> st.SearchStrategy[str]:
    numbers = st.one_of(st.integers().map(str), st.floats().map(repr), st.fractions().map(str),
                        st.decimals(allow_nan=True).map(str))
    return st.one_of(st.sampled_from(HOSTILE), st.sampled_from(VALID), st.text(max_size=40), numbers,
                     st.lists(numbers, min_size=1, max_size=9).map(",".join))


def _values(param: click.Parameter) -> st.SearchStrategy[str]:
    kind = param.type
    if isinstance(kind, click.Path | click.File):
        return st.one_of(st.sampled_from(PATHS), st.sampled_from(HOSTILE))
    if isinstance(kind, click.Choice):
        return st.one_of(st.sampled_from([str(c) for c in kind.choices]), _texts())
    if isinstance(kind, click.IntRange | click.FloatRange):
        # valid and cheap: the lower end (a large valid count is slow by design); just beyond the ends: hostile
        cheap = [str(kind.min if kind.min is not None else 0)]
        beyond = [str(kind.min - 1) if kind.min is not None else "-1", str(kind.max + 1) if kind.max is not None
                  else "1" + "0" * 30]
        return st.one_of(st.sampled_from(cheap), st.sampled_from(beyond), _texts())
    return _texts()


@st.composite
def _argument_lists(draw, path: tuple[str, ...], command: click.Command) -> list[str]:  # type: ignore[no-untyped-def]
    args: list[str] = []
    positional: list[str] = []
    for param in command.params:
        if (*path, param.name) in EXPENSIVE:
            continue
        if isinstance(param, click.Option):
            if param.hidden or param.name in ("help", "version"):
                continue
            given = (*path, param.name) in ALWAYS or draw(st.booleans())
            if not given and not (param.required and draw(st.integers(0, 9)) > 0):
                continue
            name = draw(st.sampled_from(param.opts + param.secondary_opts))
            if param.is_flag:
                args.append(name)
                continue
            for _ in range(draw(st.integers(1, 2)) if param.multiple else 1):
                args += [name, draw(_values(param))]
        elif isinstance(param, click.Argument):
            count = param.nargs if param.nargs >= 0 else draw(st.integers(0, 3))
            if draw(st.integers(0, 9)) == 0:  # sometimes one too few or too many
                count = max(0, count + draw(st.sampled_from([-1, 1])))
            positional += [draw(_values(param)) for _ in range(count)]
    if isinstance(command, click.Group):
        # a group: the name of one of its commands (or something else) and a few hostile words; the
        # commands' own parameters are fuzzed by their own examples
        positional = [draw(st.one_of(st.sampled_from(sorted(command.commands)), _texts()))]
        positional += draw(st.lists(st.sampled_from(HOSTILE), max_size=3))
    if draw(st.booleans()):
        positional = ["--", *positional]
    elif draw(st.integers(0, 9)) == 0:
        args.append(draw(st.sampled_from(["--no-such-option", "-x", "--out"])))
    return [*path, *args, *positional]


class ExampleTimeout(BaseException):
    """One example ran longer than PER_EXAMPLE seconds (not an Exception: no handler in pgsym may swallow it)."""


def _time_out(signum, frame):  # type: ignore[no-untyped-def]
    raise ExampleTimeout(f"an example ran longer than {PER_EXAMPLE} s")


def run_example(args: list[str]) -> None:
    """Run one argument list in a fresh working folder and check the rules of the module docstring."""
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as d:
        folder = Path(d) / "cwd"  # one level down, so that "../escape" still lands in the temporary folder
        folder.mkdir()
        _fill(folder)
        os.chdir(folder)
        old = signal.signal(signal.SIGALRM, _time_out)
        # hard stop for a hang; `pgsym prove` sets its own (shorter) alarm and cancels ours: the time is checked below
        signal.setitimer(signal.ITIMER_REAL, 3 * PER_EXAMPLE)
        start = time.perf_counter()
        try:
            result = CliRunner().invoke(main, args, catch_exceptions=True)
        finally:
            elapsed = time.perf_counter() - start
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
            os.chdir(here)
    shown = [a if len(a) <= 60 else a[:60] + f"...({len(a)} chars)" for a in args]
    output = result.stdout + result.stderr
    assert result.exception is None or isinstance(result.exception, SystemExit), (shown, repr(result.exception))
    # 0 done, 1 named error, 2 usage error; `check` alone has 3: some answers unreadable, the rest graded
    allowed = (0, 1, 2, 3) if args[:1] == ["check"] else (0, 1, 2)
    assert result.exit_code in allowed, (shown, result.exit_code, output[-500:])
    assert "Traceback" not in output, (shown, output[-2000:])
    assert "internal error" not in output, (shown, output[-500:])
    assert elapsed < PER_EXAMPLE, (shown, elapsed)
    for line in result.stderr.splitlines():
        if line.startswith("Error:"):  # one readable line, not a dump of the input
            assert len(line) < 3 * MAX_ARGUMENT_CHARS, (shown, line[:300])


@pytest.mark.parametrize(("path", "command"), COMMANDS, ids=[" ".join(p) or "pgsym" for p, _ in COMMANDS])
def test_no_argument_list_crashes_a_command(path, command):
    @settings(max_examples=EXAMPLES, deadline=None, derandomize=True, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(_argument_lists(path, command))
    def check(args: list[str]) -> None:
        run_example(args)

    check()


def test_every_command_is_fuzzed_and_enough_examples_run():
    names = {" ".join(p) for p, _ in COMMANDS}
    assert {"join", "meet", "prove", "harris", "rectify", "sheet", "check", "templates new", "templates check",
            "templates list"} <= names
    assert EXAMPLES * len(COMMANDS) >= 1000
