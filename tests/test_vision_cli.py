"""`pgsym harris` and `pgsym rectify`, run as the installed command on small synthetic PNG files."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import cv2
import numpy as np
import pytest
from _installed import run_pgsym

HARRIS_FILES = {"image.png", "Ix.png", "Iy.png", "Ixx.png", "Iyy.png", "Ixy.png", "Sxx.png", "Syy.png", "Sxy.png",
                "det.png", "trace.png", "response.png", "candidates.png", "maxima.png", "corners.png",
                "corners.csv"}


def run(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return run_pgsym(*args, cwd=cwd, timeout=60)


@pytest.fixture
def square_png(tmp_path: Path) -> Path:
    # a white rectangle on black: rows 20..59, columns 30..79
    img = np.zeros((80, 100), np.uint8)
    img[20:60, 30:80] = 255
    path = tmp_path / "square.png"
    cv2.imwrite(str(path), img)
    return path


@pytest.fixture
def keystone_png(tmp_path: Path) -> tuple[Path, np.ndarray]:
    # a 40 x 40 world checkerboard (4 squares of 20 px) seen through a homography
    y, x = np.mgrid[0:40, 0:40]
    world = ((((x // 20) + (y // 20)) % 2) * 255).astype(np.uint8)
    H = np.array([[2.0, 0.3, 20.0], [0.1, 1.8, 15.0], [0.004, 0.002, 1.0]])
    photo = cv2.warpPerspective(world, H, (160, 120), flags=cv2.INTER_LINEAR)
    path = tmp_path / "keystone.png"
    cv2.imwrite(str(path), photo)
    q = np.c_[np.array([[0, 0], [39, 0], [39, 39], [0, 39]], float), np.ones(4)] @ H.T
    return path, q[:, :2] / q[:, 2:]


def listing(folder: Path) -> set[str]:
    return {p.name for p in folder.iterdir()}


def test_harris_writes_every_intermediate_and_the_corners(square_png, tmp_path):
    out = tmp_path / "result"
    result = run("harris", str(square_png), "--out", str(out), "--sigma", "1.5", "--threshold", "0.1")
    assert result.returncode == 0, result.stderr
    assert "4 corners" in result.stdout
    assert listing(out) == HARRIS_FILES
    rows = list(csv.DictReader((out / "corners.csv").open()))
    found = sorted((int(r["x"]), int(r["y"])) for r in rows)
    # the true corners lie at x in {29.5, 79.5}, y in {19.5, 59.5}: the nearest pixels are within 1 px
    for (x, y), (tx, ty) in zip(found, [(29.5, 19.5), (29.5, 59.5), (79.5, 19.5), (79.5, 59.5)], strict=True):
        assert abs(x - tx) <= 1 and abs(y - ty) <= 1
    overlay = cv2.imread(str(out / "corners.png"))
    assert overlay.shape == (80, 100, 3)
    gx = cv2.imread(str(out / "Ix.png"), cv2.IMREAD_UNCHANGED)
    assert gx.shape == (80, 100) and gx.dtype == np.uint8 and gx.min() < 128 < gx.max()


def test_harris_into_an_existing_folder_keeps_other_files(square_png, tmp_path):
    from click.testing import CliRunner

    from pgsym.cli import main

    out = tmp_path / "existing"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    result = CliRunner().invoke(main, ["harris", str(square_png), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert listing(out) == HARRIS_FILES | {"notes.txt"}
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".pgsym")]


def test_rectify_with_four_points_restores_the_board(keystone_png, tmp_path):
    path, corners = keystone_png
    points = " ".join(f"{x:.6f},{y:.6f}" for x, y in corners)
    out = tmp_path / "flat.png"
    result = run("rectify", str(path), "--points", points, "--size", "40x40", "--out", str(out))
    assert result.returncode == 0, result.stderr
    flat = cv2.imread(str(out), cv2.IMREAD_GRAYSCALE)
    assert flat.shape == (40, 40)
    # the four 20 x 20 squares: dark, bright / bright, dark (judged 4 px inside each square)
    means = [flat[r:r + 12, c:c + 12].mean() for r in (4, 24) for c in (4, 24)]
    assert means[0] < 40 and means[3] < 40 and means[1] > 215 and means[2] > 215


def test_rectify_affine_and_metric(keystone_png, tmp_path):
    path, c = keystone_png
    a, b, cc, d = c  # top-left, top-right, bottom-right, bottom-left of the world square
    fmt = lambda p, q: f"{p[0]:.6f},{p[1]:.6f} {q[0]:.6f},{q[1]:.6f}"  # noqa: E731
    affine = "; ".join([fmt(a, b), fmt(d, cc), fmt(a, d), fmt(b, cc)])
    out = tmp_path / "affine.png"
    result = run("rectify", str(path), "--method", "affine", "--lines", affine, "--out", str(out))
    assert result.returncode == 0, result.stderr
    assert cv2.imread(str(out), cv2.IMREAD_GRAYSCALE).shape == (120, 160)
    metric = affine + "; " + "; ".join([fmt(a, b), fmt(a, d), fmt(a, cc), fmt(b, d)])
    out2 = tmp_path / "metric.png"
    result = run("rectify", str(path), "--method", "metric", "--lines", metric, "--size", "100x80", "--out", str(out2))
    assert result.returncode == 0, result.stderr
    assert cv2.imread(str(out2), cv2.IMREAD_GRAYSCALE).shape == (80, 100)


def test_rectify_from_five_orthogonal_pairs(keystone_png, tmp_path):
    path, _ = keystone_png
    H = np.array([[2.0, 0.3, 20.0], [0.1, 1.8, 15.0], [0.004, 0.002, 1.0]])  # the fixture's world → image map

    def image(*world):
        q = np.c_[np.array(world, float), np.ones(len(world))] @ H.T
        return q[:, :2] / q[:, 2:]

    # five right angles of the 40 × 40 board: two corners, the diagonals, and two mid-lines against sides
    world_pairs = [(((0, 0), (39, 0)), ((0, 0), (0, 39))), (((39, 39), (0, 39)), ((39, 39), (39, 0))),
                   (((0, 0), (39, 39)), ((39, 0), (0, 39))), (((0, 0), (39, 0)), ((19.5, 0), (19.5, 39))),
                   (((0, 19.5), (39, 19.5)), ((0, 0), (0, 39)))]
    text = "; ".join(" ".join(f"{x:.2f},{y:.2f}" for x, y in image(*segment))  # argument lists: 500 characters
                     for pair in world_pairs for segment in pair)
    out = tmp_path / "orthogonal.png"
    result = run("rectify", str(path), "--method", "orthogonal", "--lines", text, "--size", "100x80", "--out", str(out))
    assert result.returncode == 0, result.stderr
    assert "orthogonal" in result.stdout
    assert cv2.imread(str(out), cv2.IMREAD_GRAYSCALE).shape == (80, 100)
    eight = "; ".join(text.split("; ")[:8])
    result = run("rectify", str(path), "--method", "orthogonal", "--lines", eight, "--out", str(out))
    assert result.returncode == 2 and "at least ten" in result.stderr


def test_help_texts_document_the_commands():
    from click.testing import CliRunner

    from pgsym.cli import main

    for command, words in (("harris", ["--k", "--sigma", "--threshold", "--min-distance", "corners.csv", "Example"]),
                           ("rectify", ["--points", "--size", "--method", "--lines", "affine", "metric", "orthogonal",
                                        "Example"])):
        result = CliRunner().invoke(main, [command, "--help"])
        assert result.exit_code == 0
        for word in words:
            assert word in result.stdout, (command, word)


ERROR_CASES = [
    (("harris", "missing.png", "--out", "OUT"), 1, "ImageError: cannot read image 'missing.png'"),
    (("harris", "junk.png", "--out", "OUT"), 1, "not an image format"),
    (("harris", "square.png", "--out", "OUT", "--k", "0.5"), 2, "--k"),
    (("harris", "square.png", "--out", "OUT", "--sigma", "abc"), 2, "--sigma"),
    (("harris", "square.png", "--out", "junk.png"), 2, "is a file"),
    (("rectify", "square.png", "--points", "30,20 79,20 79,59", "--size", "50x40", "--out", "OUT.png"), 2,
     "exactly four points"),
    (("rectify", "square.png", "--points", "30,20 79,20 79,59 1,2 3,4", "--size", "50x40", "--out", "OUT.png"),
     2, "exactly four points"),
    (("rectify", "square.png", "--points", "0,0 1,1 2,2 9,1", "--size", "50x40", "--out", "OUT.png"), 1,
     "CollinearPointsError"),
    (("rectify", "square.png", "--points", "0,0 1,x 2,2 9,1", "--size", "50x40", "--out", "OUT.png"), 2,
     "'x' is not a number"),
    (("rectify", "square.png", "--points", "__import__('os'),1 1,1 2,2 9,1", "--size", "5x4", "--out", "OUT.png"),
     2, "not a number"),
    (("rectify", "square.png", "--points", "1e999,1 1,1 2,2 9,1", "--size", "5x4", "--out", "OUT.png"), 2,
     "InputLimitError: the exponent of '1e999' is out of range"),
    (("rectify", "square.png", "--points", "0,0 10,0 10,10 0,10", "--size", "50by40", "--out", "OUT.png"), 2,
     "WIDTHxHEIGHT"),
    (("rectify", "square.png", "--points", "0,0 10,0 10,10 0,10", "--out", "OUT.png"), 2, "--size"),
    (("rectify", "square.png", "--points", "0,0 10,0 10,10 0,10", "--size", "5x5", "--out", "OUT.txt"), 2,
     "image format"),
    (("rectify", "square.png", "--method", "affine", "--lines", "0,0 10,0; 0,5 10,5", "--out", "OUT.png"), 2,
     "takes 4 lines"),
    (("rectify", "square.png", "--method", "affine", "--lines", "0,0 10,0; 0,5 10 5; 0,0 0,9; 5,0 5,9",
      "--out", "OUT.png"), 2, "line 2"),
    # both vanishing points on the row y = 39.5 through the image centre
    (("rectify", "square.png", "--method", "affine", "--lines",
      "0,39.5 10,30; 0,39.5 10,50; 99,39.5 89,30; 99,39.5 89,50", "--out", "OUT.png"), 1, "reference point"),
    # both vanishing points on the row y = 10, which crosses the image
    (("rectify", "square.png", "--method", "affine", "--lines",
      "0,10 10,0; 0,10 10,20; 99,10 89,0; 99,10 89,20", "--out", "OUT.png"), 1, "crosses"),
    # all four lines horizontal: a single vanishing point
    (("rectify", "square.png", "--method", "affine", "--lines", "0,0 10,0; 0,5 10,5; 0,10 10,10; 0,20 10,20",
      "--out", "OUT.png"), 1, "same vanishing point"),
    (("rectify", "square.png", "--method", "metric", "--out", "OUT.png"), 2, "needs --lines"),
    (("rectify", "square.png", "--method", "points", "--lines", "0,0 1,1", "--points", "0,0 10,0 10,10 0,10",
      "--size", "5x5", "--out", "OUT.png"), 2, "--lines belongs"),
    (("rectify", "missing.png", "--points", "0,0 10,0 10,10 0,10", "--size", "5x5", "--out", "OUT.png"), 1,
     "does not exist"),
]


def check_failure(code, stderr, before, tmp_path, expected_code, message):
    assert code == expected_code, stderr
    assert message in stderr
    assert "Traceback" not in stderr
    assert len([line for line in stderr.splitlines() if line.startswith("Error:")]) == 1
    assert listing(tmp_path) == before  # nothing written, no temporary files left behind


@pytest.fixture
def workdir(square_png, tmp_path, monkeypatch):
    (tmp_path / "junk.png").write_bytes(b"this is not a PNG")
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.parametrize(("args", "code", "message"), ERROR_CASES)
def test_errors_give_one_message_a_nonzero_exit_and_no_output(args, code, message, workdir):
    # in-process (the same click command the console script runs), so the whole table stays fast
    from click.testing import CliRunner

    from pgsym.cli import main

    before = listing(workdir)
    result = CliRunner().invoke(main, list(args))
    check_failure(result.exit_code, result.stderr, before, workdir, code, message)


@pytest.mark.parametrize(("args", "code", "message"), [ERROR_CASES[i] for i in (0, 5, 7, 9)])
def test_errors_from_the_installed_command(args, code, message, workdir):
    before = listing(workdir)
    result = run(*args, cwd=workdir)
    check_failure(result.returncode, result.stderr, before, workdir, code, message)


def test_the_command_line_does_not_import_opencv_until_a_vision_command_runs():
    code = "import sys\nfrom pgsym.cli import main\nprint('cv2' in sys.modules, 'pgsym.vision.harris' in sys.modules)"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert result.stdout.split() == ["False", "False"]


def test_outputs_replace_symlinks_and_never_write_through_them(square_png, tmp_path):
    # a symlink in the output place pointing outside the output folder: the link is replaced,
    # the file it pointed to is left exactly as it was
    from click.testing import CliRunner

    from pgsym.cli import main

    outside = tmp_path / "outside.txt"
    outside.write_text("precious")
    out = tmp_path / "results"
    out.mkdir()
    (out / "corners.csv").symlink_to(outside)
    (tmp_path / "flat.png").symlink_to(outside)
    result = CliRunner().invoke(main, ["harris", str(square_png), "--out", str(out)])
    assert result.exit_code == 0, result.output
    result = CliRunner().invoke(main, ["rectify", str(square_png), "--points", "30,20 79,20 79,59 30,59",
                                       "--size", "50x40", "--out", str(tmp_path / "flat.png")])
    assert result.exit_code == 0, result.output
    assert outside.read_text() == "precious"
    assert not (out / "corners.csv").is_symlink() and (out / "corners.csv").read_text().startswith("x,y,response")
    assert not (tmp_path / "flat.png").is_symlink() and cv2.imread(str(tmp_path / "flat.png")).shape == (40, 50, 3)


def test_a_failed_write_leaves_the_folder_as_it_was(square_png, tmp_path):
    from click.testing import CliRunner

    from pgsym.cli import main

    out = tmp_path / "results"
    out.mkdir()
    (out / "image.png").write_bytes(b"old")
    (out / "corners.csv").mkdir()  # a folder where a file must go
    result = CliRunner().invoke(main, ["harris", str(square_png), "--out", str(out)])
    assert result.exit_code == 1
    assert result.stderr.startswith("Error: OutputError: cannot write") and "folder of that name" in result.stderr
    assert listing(out) == {"image.png", "corners.csv"} and (out / "image.png").read_bytes() == b"old"
    # below a file: named, nothing created
    (tmp_path / "blocked").write_text("a file")
    result = CliRunner().invoke(main, ["harris", str(square_png), "--out", str(tmp_path / "blocked" / "x" / "y")])
    assert result.exit_code == 1 and "it is a file, not a folder" in result.stderr
    assert listing(tmp_path) == {"square.png", "results", "blocked"}


def test_a_full_disk_leaves_no_folder_and_no_temporary_file(square_png, tmp_path, monkeypatch):
    import errno

    from click.testing import CliRunner

    import pgsym.vision.images
    from pgsym.cli import main

    def full(path, image):  # type: ignore[no-untyped-def]
        raise OSError(errno.ENOSPC, "No space left on device", str(path))

    monkeypatch.setattr(pgsym.vision.images, "write_image", full)
    for args in (["harris", str(square_png), "--out", str(tmp_path / "new" / "deeper")],
                 ["rectify", str(square_png), "--points", "30,20 79,20 79,59 30,59", "--size", "50x40",
                  "--out", str(tmp_path / "new" / "flat.png")]):
        result = CliRunner().invoke(main, args)
        assert result.exit_code == 1 and "OutputError: cannot write" in result.stderr, result.output
        assert "No space left on device" in result.stderr
        assert listing(tmp_path) == {"square.png"}  # the folders made for the run are gone again


def test_the_image_reader_checks_the_header_before_decoding(tmp_path):
    from pgsym.errors import InputLimitError
    from pgsym.limits import MAX_IMAGE_PIXELS
    from pgsym.vision.errors import ImageError
    from pgsym.vision.images import image_size, read_image

    # a header announcing 8000 x 6000 = 48e6 > 40e6 pixels, with a pixel stream far too short for it:
    # refused from the size alone, so the decoder never sees it
    side = struct_png_header(8000, 6000)
    (tmp_path / "big.png").write_bytes(side)
    assert image_size(side) == (8000, 6000) and 8000 * 6000 > MAX_IMAGE_PIXELS
    with pytest.raises(InputLimitError, match="8000x6000 = 48000000 pixels"):
        read_image(tmp_path / "big.png")
    (tmp_path / "small.png").write_bytes(struct_png_header(10, 10))
    with pytest.raises(ImageError, match="truncated or damaged"):
        read_image(tmp_path / "small.png")


def struct_png_header(width: int, height: int) -> bytes:
    """The signature and IHDR chunk of a grey 8-bit PNG, an empty IDAT and IEND (no pixels)."""
    import struct
    import zlib

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    ihdr = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(b"")) + chunk(b"IEND", b"")
