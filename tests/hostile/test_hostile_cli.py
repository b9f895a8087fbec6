"""Every `pgsym` command against hostile arguments and files, run as the installed command.

Each case runs in a fresh process under a 2 GiB address-space limit and a time limit, in a
temporary working folder (also its TMPDIR). It must end with the expected non-zero status (0 where
the project's rule is to carry on, e.g. one unreadable answer while grading), one clean line
``Error: ...`` naming the problem, no traceback, and no file created, changed or removed anywhere in
the temporary folder.
"""

from __future__ import annotations

import os
import re
import resource
import struct
import subprocess
import zlib
from pathlib import Path

import pytest
from _installed import run_pgsym

MEMORY_LIMIT = 2 * 1024**3  # bytes of address space; NumPy, OpenCV and SymPy load in a few hundred MB
TIME_LIMIT = 30  # seconds per run; a good run takes one to three
WORDS = "x" * 10_000
DIGITS = "9" * 5000


def _limit_memory() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def _png(width: int, height: int, rows: bytes) -> bytes:
    """A grey 8-bit PNG whose zlib stream is ``rows`` (filter byte + pixels per row), written by hand."""

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", rows) + chunk(b"IEND", b"")


def _bomb() -> bytes:
    # 20000 x 20000 black pixels: 400 MB once decoded (4 GB as the float images of harris), a few hundred KB here
    side, block = 20_000, 500
    z = zlib.compressobj(9)
    rows = bytes(side + 1) * block  # each row: filter byte 0 and `side` zero pixels
    data = b"".join(z.compress(rows) for _ in range(side // block)) + z.flush()
    return _png(side, side, data)


@pytest.fixture(scope="module")
def bomb_bytes() -> bytes:
    data = _bomb()
    assert len(data) < 1_000_000
    return data


@pytest.fixture(scope="module")
def manifest_bytes(tmp_path_factory: pytest.TempPathFactory) -> bytes:
    """A real answer key: one sheet with one 'join' exercise for student s1, written by `pgsym sheet`."""
    from click.testing import CliRunner

    from pgsym.cli import main

    folder = tmp_path_factory.mktemp("key")
    (folder / "roster.csv").write_text("id\ns1\n")
    result = CliRunner().invoke(main, ["sheet", "--topics", "join", "--roster", str(folder / "roster.csv"),
                                       "--seed", "1", "--out", str(folder / "sheet")])
    assert result.exit_code == 0, result.output
    return (folder / "sheet" / "manifest.json").read_bytes()


@pytest.fixture
def work(tmp_path: Path, bomb_bytes: bytes, manifest_bytes: bytes) -> Path:
    """The working folder of one run, with every hostile file the cases name."""
    w = tmp_path / "work"
    (w / "tmp").mkdir(parents=True)
    # 32 x 24: a bright square on black, so harris finds corners (a good run would succeed)
    good = _png(32, 24, zlib.compress(b"".join(b"\x00" + bytes(255 if 8 <= x < 24 and 6 <= y < 18 else 0
                                                                for x in range(32)) for y in range(24))))
    (w / "good.png").write_bytes(good)
    (w / "truncated.png").write_bytes(good[: len(good) - 20])  # header intact, pixel data cut
    (w / "text.png").write_text("this is a text file with a .png name\n")
    (w / "empty.png").write_bytes(b"")
    (w / "nul.png").write_bytes(b"\x00" * 4096)
    (w / "bomb.png").write_bytes(bomb_bytes)
    (w / "folder.png").mkdir()
    os.mkfifo(w / "fifo.png")
    (w / "existing.txt").write_text("keep me\n")
    (w / "nul.csv").write_bytes(b"id,name\ns1\x00,Ada\x00\x00\n")
    (w / "templates_bad").mkdir()
    (w / "templates_bad" / "broken.py").write_text("this is not python (\n")
    (w / "manifest.json").write_bytes(manifest_bytes)
    (w / "huge_answers.csv").write_text(f"id,1\ns1,\"({DIGITS[:100]}, 1, 1)\"\n")
    (w / "long_answers.csv").write_text(f"id,1\ns1,\"({DIGITS}, 1, 1)\"\n")
    (w / "nul_answers.csv").write_bytes(b"id,1\ns1,(1\x00, 2, 3)\n")
    # theorem files: parentheses 100 deep, bytes that are not UTF-8, a fifo
    (w / "deep.thm").write_text("points A B C D\npoint X = meet " + "(" * 100 + "join A B" + ")" * 100
                                + " (join C D)\nprove collinear A B X\n")
    (w / "binary.thm").write_bytes(b"points A\xff\xfe B\n\x00\x01")
    os.mkfifo(w / "fifo.thm")
    return w


def snapshot(folder: Path) -> dict[str, tuple[bool, int, int]]:
    """Every entry under ``folder`` (symlinks not followed): is it a folder, and for files their size and
    modification time (a folder's own time changes when an entry is added, so it is not compared)."""
    entries = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs:
            entries[os.path.relpath(os.path.join(root, name), folder)] = (True, 0, 0)
        for name in files:
            st = os.lstat(os.path.join(root, name))
            entries[os.path.relpath(os.path.join(root, name), folder)] = (False, st.st_size, st.st_mtime_ns)
    return entries


def run(work: Path, *args: str) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "TMPDIR": str(work / "tmp"), "COLUMNS": "200"}
    return run_pgsym(*args, cwd=work, env=env, timeout=TIME_LIMIT, preexec_fn=_limit_memory)


def check(result: subprocess.CompletedProcess[str], code: int, message: str) -> None:
    output = result.stdout + result.stderr
    assert "Traceback" not in output, output
    assert "internal error" not in output, output
    assert result.returncode == code, output
    errors = [line for line in result.stderr.splitlines() if line.startswith("Error:")]
    if code in (1, 2):
        assert len(errors) == 1, result.stderr
        assert re.search(message, errors[0]), errors[0]
    else:  # carried on (`check` exits 3 when some answers were unreadable): named on stderr, no error line
        assert not errors and re.search(message, result.stderr), result.stderr


POINTS = "0,0 3,0 3,2 0,2"
# (id, arguments, exit status, regular expression the error line must match)
CASES = [
    # numbers: the grammar and its limits, checked on the text before any arithmetic
    ("join-huge-exponent", ("join", "1e99999999,0", "0,1"), 2, r"InputLimitError: the exponent of '1e99999999'"),
    ("join-exponent-5000", ("join", "1e5000,0", "0,1"), 2, r"InputLimitError: the exponent of '1e5000'"),
    ("meet-tiny-exponent", ("meet", "--", "-1e-99999,1,0", "0,1,0"), 2, r"InputLimitError: the exponent"),
    ("join-5000-digits", ("join", f"{DIGITS},1", "0,1"), 2, r"InputLimitError: the coordinate list is 5002 characters"),
    ("join-100-digits", ("join", f"{DIGITS[:100]},1", "0,1"), 2,
     r"InputLimitError: the number '9{30}\.\.\.' has 100 digits"),
    ("meet-100-digit-denominator", ("meet", f"1/{DIGITS[:100]},1,0", "0,1,0"), 2, r"InputLimitError: .* 100 digits"),
    ("join-10kB-argument", ("join", WORDS, "0,1"), 2, r"InputLimitError: the coordinate list is 10000 characters"),
    ("meet-arabic-digit", ("meet", "\u0663,1,0", "0,1,0"), 2, r"NonNumericError: .*U\+0663 is not an ASCII digit"),
    ("join-fullwidth-digit", ("join", "\uff11,2", "0,1"), 2, r"NonNumericError: .*U\+FF11"),
    ("join-nan", ("join", "nan,1", "0,1"), 2, r"NonNumericError: 'nan' is not a number"),
    ("meet-inf", ("meet", "inf,1,0", "0,1,0"), 2, r"NonNumericError: 'inf' is not a number"),
    ("join-empty", ("join", "", "0,1"), 2, r"InvalidCoordinatesError: the coordinate list is empty"),
    ("join-blank", ("join", " , ", "0,1"), 2, r"InvalidCoordinatesError: empty entry"),
    ("join-too-many", ("join", "1,2,3,4", "0,1"), 1, r"DimensionError"),
    ("join-too-few", ("join", "1", "0,1"), 1, r"DimensionError"),
    ("meet-two-coordinates", ("meet", "1,2", "0,1,0"), 1, r"DimensionError"),
    ("join-zero-denominator", ("join", "1/0,2", "0,1"), 2, r"denominator is zero"),
    ("join-python-code", ("join", "__import__('os').system('true')", "0,1"), 2, r"NonNumericError: .* not a number"),
    ("join-missing-argument", ("join", "0,1"), 2, r"Missing argument 'Q'"),
    # prove FILE and discover FILE: the statement language's readers
    ("prove-deep-file", ("prove", "deep.thm"), 2, r"deep\.thm:2:\d+: parentheses nested more than 32 deep"),
    ("discover-deep-file", ("discover", "deep.thm"), 2, r"deep\.thm:2:\d+: parentheses nested more than 32 deep"),
    ("discover-binary-file", ("discover", "binary.thm"), 2, r"binary\.thm:1:\d+: the file is not UTF-8 text"),
    ("discover-missing-file", ("discover", "missing.thm"), 2, r"missing\.thm.*No such file"),
    ("discover-fifo", ("discover", "fifo.thm"), 2, r"fifo\.thm"),
    # prove
    ("prove-unknown-claim", ("prove", "no-such-claim"), 2, r"no claim named 'no-such-claim'"),
    ("prove-10kB-name", ("prove", WORDS), 2, r"claim name of 10000 characters"),
    ("prove-empty-name", ("prove", ""), 2, r"no claim named ''"),
    ("prove-timeout-nan", ("prove", "--timeout", "nan", "pappus"), 2, r"'--timeout'.*'nan' is not a number"),
    ("prove-timeout-inf", ("prove", "--timeout", "inf", "pappus"), 2, r"'--timeout'.*'inf' is not a number"),
    ("prove-timeout-negative", ("prove", "--timeout", "-1", "pappus"), 2, r"'--timeout'.*range"),
    ("prove-timeout-huge-exponent", ("prove", "--timeout", "1e99999999", "pappus"), 2, r"InputLimitError"),
    ("prove-timeout-year", ("prove", "--timeout", "31536000", "pappus"), 2, r"'--timeout'.*range"),
    # harris: hostile images, options and output folders
    ("harris-decompression-bomb", ("harris", "bomb.png", "--out", "out"), 1,
     r"InputLimitError: the image 'bomb.png' has more than 40000000 pixels"),
    ("harris-truncated-png", ("harris", "truncated.png", "--out", "out"), 1, r"ImageError: .*truncated or damaged"),
    ("harris-text-named-png", ("harris", "text.png", "--out", "out"), 1, r"ImageError: .*not an image format"),
    ("harris-empty-file", ("harris", "empty.png", "--out", "out"), 1, r"ImageError: .*the file is empty"),
    ("harris-nul-bytes", ("harris", "nul.png", "--out", "out"), 1, r"ImageError: .*not an image format"),
    ("harris-directory", ("harris", "folder.png", "--out", "out"), 2, r"'folder.png' is a directory"),
    ("harris-dev-zero", ("harris", "/dev/zero", "--out", "out"), 1, r"ImageError: .*not a regular file"),
    ("harris-fifo", ("harris", "fifo.png", "--out", "out"), 1, r"ImageError: .*not a regular file"),
    ("harris-missing", ("harris", "missing.png", "--out", "out"), 1, r"ImageError: .*does not exist"),
    ("harris-negative-sigma", ("harris", "good.png", "--out", "out", "--sigma", "-1"), 2, r"'--sigma'.*range"),
    ("harris-k-nan", ("harris", "good.png", "--out", "out", "--k", "nan"), 2, r"'--k'.*'nan' is not a number"),
    ("harris-k-inf", ("harris", "good.png", "--out", "out", "--k", "inf"), 2, r"'--k'.*'inf' is not a number"),
    ("harris-min-distance-huge", ("harris", "good.png", "--out", "out", "--min-distance", "1000000000"), 2,
     r"'--min-distance'.*range"),
    ("harris-min-distance-fraction", ("harris", "good.png", "--out", "out", "--min-distance", "1/2"), 2,
     r"not an integer"),
    ("harris-out-existing-file", ("harris", "good.png", "--out", "existing.txt"), 2, r"'existing.txt' is a file"),
    ("harris-out-below-a-file", ("harris", "good.png", "--out", "existing.txt/out"), 1,
     r"OutputError: cannot write into 'existing.txt': it is a file, not a folder"),
    ("harris-out-unwritable", ("harris", "good.png", "--out", "/proc/pgsym-hostile-out"), 1,
     r"OutputError: cannot write '/proc/pgsym-hostile-out'"),
    ("harris-out-name-too-long", ("harris", "good.png", "--out", "o" * 300), 1, r"OutputError: .*name too long"),
    # rectify
    ("rectify-huge-exponent", ("rectify", "good.png", "--points", "1e99999999,0 3,0 3,2 0,2", "--size", "4x4",
                               "--out", "r.png"), 2, r"'--points'.*InputLimitError: the exponent"),
    ("rectify-five-points", ("rectify", "good.png", "--points", POINTS + " 1,1", "--size", "4x4", "--out", "r.png"),
     2, r"exactly four points"),
    ("rectify-nan-point", ("rectify", "good.png", "--points", "nan,0 3,0 3,2 0,2", "--size", "4x4", "--out", "r.png"),
     2, r"'nan' is not a number"),
    ("rectify-10kB-lines", ("rectify", "good.png", "--method", "affine", "--lines", WORDS, "--out", "r.png"), 2,
     r"'--lines'.*InputLimitError: the line list is 10000 characters"),
    ("rectify-size-too-large", ("rectify", "good.png", "--points", POINTS, "--size", "16384x16384", "--out", "r.png"),
     2, r"InputLimitError: the size 16384x16384 has 268435456 pixels"),
    ("rectify-size-absurd", ("rectify", "good.png", "--points", POINTS, "--size", f"{DIGITS}x2", "--out", "r.png"), 2,
     r"is not a size"),
    ("rectify-bomb", ("rectify", "bomb.png", "--points", POINTS, "--size", "4x4", "--out", "r.png"), 1,
     r"InputLimitError: the image 'bomb.png'"),
    ("rectify-out-unwritable", ("rectify", "good.png", "--points", POINTS, "--size", "4x4", "--out",
                                "/proc/pgsym-hostile.png"), 1, r"OutputError: cannot write"),
    ("rectify-out-below-a-file", ("rectify", "good.png", "--points", POINTS, "--size", "4x4", "--out",
                                  "existing.txt/r.png"), 1,
     r"OutputError: cannot write into 'existing.txt': it is a file"),
    ("rectify-out-folder", ("rectify", "good.png", "--points", POINTS, "--size", "4x4", "--out", "folder.png"), 2,
     r"'folder.png' is a directory"),
    ("rectify-fifo", ("rectify", "fifo.png", "--points", POINTS, "--size", "4x4", "--out", "r.png"), 1,
     r"not a regular file"),
    # sheet (the exercise commands)
    ("sheet-count-billion", ("sheet", "--topics", "join", "--count", "1000000000", "--out", "s"), 2, r"'--count'"),
    ("sheet-count-nan", ("sheet", "--topics", "join", "--count", "nan", "--out", "s"), 2, r"'--count'"),
    ("sheet-seed-5000-digits", ("sheet", "--topics", "join", "--seed", DIGITS, "--out", "s"), 2, r"'--seed'"),
    ("sheet-level-negative", ("sheet", "--topics", "join", "--level", "-1", "--out", "s"), 2, r"'--level'"),
    ("sheet-unknown-topic", ("sheet", "--topics", "no-such-topic", "--out", "s"), 1, r"no-such-topic"),
    ("sheet-10kB-topics", ("sheet", "--topics", WORDS, "--out", "s"), 1, r"InputLimitError|too long|characters"),
    ("sheet-topic-level-huge", ("sheet", "--topics", f"join:{DIGITS}", "--out", "s"), 1, r"level"),
    ("sheet-bad-format", ("sheet", "--topics", "join", "--format", "md,exe", "--out", "s"), 2, r"exe"),
    ("sheet-roster-dev-zero", ("sheet", "--topics", "join", "--roster", "/dev/zero", "--out", "s"), 1,
     r"(RosterError|InputLimitError): .*(regular file|device|larger than)"),
    ("sheet-roster-fifo", ("sheet", "--topics", "join", "--roster", "fifo.png", "--out", "s"), 1,
     r"(RosterError|InputLimitError): .*(regular file|pipe)"),
    ("sheet-roster-nul-bytes", ("sheet", "--topics", "join", "--roster", "nul.csv", "--out", "s"), 1,
     r"RosterError: .*(NUL|control)"),
    ("sheet-out-unwritable", ("sheet", "--topics", "join", "--out", "/proc/pgsym-hostile-sheet"), 1,
     r"OutputError: cannot write"),
    ("sheet-out-existing-file", ("sheet", "--topics", "join", "--out", "existing.txt"), 2, r"is a file"),
    ("sheet-templates-dev-zero", ("sheet", "--topics", "join", "--templates", "/dev/zero", "--out", "s"), 1,
     r"TemplateError: .*not a folder"),
    # check
    ("check-manifest-dev-zero", ("check", "--manifest", "/dev/zero", "--answers", "huge_answers.csv"), 1,
     r"(ManifestError|InputLimitError): .*(regular file|device|larger than)"),
    ("check-manifest-fifo", ("check", "--manifest", "fifo.png", "--answers", "huge_answers.csv"), 1,
     r"(ManifestError|InputLimitError): .*(regular file|pipe)"),
    ("check-manifest-not-json", ("check", "--manifest", "text.png", "--answers", "huge_answers.csv"), 1,
     r"ManifestError"),
    ("check-answers-dev-zero", ("check", "--manifest", "manifest.json", "--answers", "/dev/zero"), 1,
     r"(AnswersFileError|InputLimitError): .*(regular file|device|larger than)"),
    ("check-answers-100-digits", ("check", "--manifest", "manifest.json", "--answers", "huge_answers.csv"), 3,
     r"s1 \[1\]: cannot read the answer: .*more than 40 digits"),
    ("check-answers-5000-digits", ("check", "--manifest", "manifest.json", "--answers", "long_answers.csv"), 3,
     r"s1 \[1\]: cannot read the answer: it is 5008 characters long"),
    ("check-answers-nul-bytes", ("check", "--manifest", "manifest.json", "--answers", "nul_answers.csv"), 3,
     r"s1 \[1\]: cannot read the answer"),
    ("check-out-unwritable", ("check", "--manifest", "manifest.json", "--answers", "huge_answers.csv", "--out",
                              "/proc/pgsym-hostile.csv"), 1, r"cannot write"),
    # templates new / check / list
    ("templates-new-path-name", ("templates", "new", "../evil"), 2, r"lower-case letters"),
    ("templates-new-10kB-name", ("templates", "new", WORDS), 2, r"lower-case letters"),
    ("templates-new-keyword", ("templates", "new", "class"), 2, r"lower-case letters"),
    ("templates-new-dir-unwritable", ("templates", "new", "mine", "--dir", "/proc/pgsym-hostile"), 1,
     r"cannot write"),
    ("templates-new-dir-is-file", ("templates", "new", "mine", "--dir", "existing.txt"), 2, r"is a file"),
    ("templates-check-seeds-billion", ("templates", "check", "join", "--seeds", "1000000000"), 2, r"'--seeds'"),
    ("templates-check-seeds-nan", ("templates", "check", "join", "--seeds", "nan"), 2, r"'--seeds'"),
    ("templates-check-unknown", ("templates", "check", "no-such-topic"), 1, r"no-such-topic"),
    ("templates-list-dev-zero", ("templates", "list", "--templates", "/dev/zero"), 1, r"TemplateError: .*not a folder"),
    ("templates-list-name-too-long", ("templates", "list", "--templates", "t" * 300), 1,
     r"TemplateError: .*(name too long|does not exist|not a folder)"),
    ("templates-list-broken-file", ("templates", "list", "--templates", "templates_bad"), 1,
     r"TemplateError: could not load template file broken.py"),
]


@pytest.mark.parametrize(("args", "code", "message"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_hostile_input_gets_one_clean_line(work, args, code, message):
    before = snapshot(work.parent)
    result = run(work, *args)
    check(result, code, message)
    assert snapshot(work.parent) == before, "a file was created, changed or removed"


def test_every_command_has_hostile_cases():
    from pgsym.cli import main

    def paths(group, prefix=()):  # type: ignore[no-untyped-def]
        for name, command in group.commands.items():
            if hasattr(command, "commands"):
                yield from paths(command, (*prefix, name))
            else:
                yield (*prefix, name)

    covered = {args[: len(path)] for _, args, _, _ in CASES for path in paths(main)}
    missing = [path for path in paths(main) if path not in covered]
    assert not missing, missing
    assert len(CASES) >= 40


def test_a_nul_byte_in_an_argument_is_refused_before_any_command_runs():
    # a real command line cannot carry NUL (C strings end there), but a Python caller can
    from click.testing import CliRunner

    from pgsym.cli import main

    for args in (["join", "1\x00,2", "0,1"], ["harris", "good\x00.png", "--out", "o"], ["templates", "new", "a\x00"]):
        result = CliRunner().invoke(main, args)
        assert result.exit_code == 2
        assert result.exception is None or isinstance(result.exception, SystemExit)
        assert "argument" in result.stderr and "NUL character" in result.stderr


def test_a_good_run_after_the_hostile_ones_writes_only_its_output(work):
    # the control: the same harness accepts a good run, and the run writes exactly its output
    before = snapshot(work.parent)
    result = run(work, "rectify", "good.png", "--points", POINTS, "--size", "4x4", "--out", "r.png")
    assert result.returncode == 0, result.stderr
    after = snapshot(work.parent)
    assert set(after) - set(before) == {"work/r.png"} and all(after[k] == v for k, v in before.items())
