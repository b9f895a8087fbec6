"""The ``pgsym harris`` and ``pgsym rectify`` commands (the lecture's two programs).

Heavy libraries (NumPy, OpenCV) are imported inside the commands, so that
``pgsym --version`` and the exact commands start quickly. Every command checks
its input and computes its result completely before it writes anything; files are
written under a temporary name inside the output folder and then renamed into place
(a symlink in the way is replaced, never written through), so a failed run leaves no
partial output and nothing is ever written outside the output folder. Images are read
with the limits of :func:`pgsym.vision.images.read_image`; points, lines and sizes with
the one grammar of :mod:`pgsym.cli._common`.
"""

from __future__ import annotations

from pathlib import Path

import click

from ..atomic import exists, replace_file, replace_files_in_folder
from ..csv_cells import csv_text
from ..errors import PgsymError
from ._common import LINES, POINTS, SIZE, DecimalRange, IntegerRange, fail, parse_lines, parse_points, parse_size

__all__ = ["harris_command", "parse_lines", "parse_points", "parse_size", "rectify_command"]

_IMAGE_SUFFIXES = {".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff"}
_CONTEXT = {"help_option_names": ["-h", "--help"]}



def _check_output_file(out: Path) -> None:
    if out.suffix.lower() not in _IMAGE_SUFFIXES:
        raise click.BadParameter(
            f"cannot tell the image format from {out.name!r}: use one of {', '.join(sorted(_IMAGE_SUFFIXES))}",
            param_hint="'--out'",
        )
    if exists(out) and out.is_dir():
        raise click.BadParameter(f"{str(out)!r} is a directory; give a file name", param_hint="'--out'")


@click.command(
    "harris",
    short_help="Harris corners with every intermediate image.",
    context_settings=_CONTEXT,
)
@click.argument("image", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--out", "out", required=True, type=click.Path(file_okay=False, path_type=Path),
              help="Directory for the results (created if missing; existing files of the same names are replaced).")
@click.option("--k", "k", default=0.05, show_default=True, type=DecimalRange(0, 0.25, max_open=True),
              help="Sensitivity k in R = det M - k (trace M)^2.")
@click.option("--sigma", default=1.0, show_default=True, type=DecimalRange(0, 50, min_open=True),
              help="Standard deviation of the Gaussian window, in pixels.")
@click.option("--threshold", default=0.01, show_default=True, type=DecimalRange(0, 1, max_open=True),
              help="Keep pixels with R > threshold * max R (relative to the strongest response).")
@click.option("--min-distance", default=5, show_default=True, type=IntegerRange(1, 500),
              help="Half-width of the non-maximum-suppression window, in pixels.")
def harris_command(image: Path, out: Path, k: float, sigma: float, threshold: float, min_distance: int) -> None:
    """Harris corners of IMAGE, with every intermediate result written to --out.

    \b
    Writes into DIR:
      image.png            the grey input
      Ix.png, Iy.png       Sobel gradients (grey 128 = 0)
      Ixx.png Iyy.png Ixy.png   gradient products
      Sxx.png Syy.png Sxy.png   Gaussian-weighted structure tensor entries
      det.png, trace.png   det M and trace M
      response.png         R = det M - k (trace M)^2 (grey 128 = 0)
      candidates.png       pixels with R above the threshold
      maxima.png           the candidates left by non-maximum suppression
      corners.png          the corners drawn on the image
      corners.csv          x,y,response of each corner (x = column, y = row), strongest first
    Each image is scaled to 0..255 for display; quantities quadratic in the
    gradient are shown through a square root, det and R through a fourth
    root (signs kept), so that weak structure stays visible.

    \b
    Example:
      pgsym harris photo.png --out harris-out --sigma 1.5 --threshold 0.05
    """
    out = Path(out)
    if exists(out) and not out.is_dir():
        raise click.BadParameter(f"{str(out)!r} exists and is not a directory", param_hint="'--out'")
    try:
        from ..vision.harris import harris  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
        from ..vision.images import read_image  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

        result = harris(read_image(image), k=k, sigma=sigma, threshold=threshold, min_distance=min_distance)
        files = _harris_files(result)
        replace_files_in_folder(out, files, lambda tmp: _write_harris(tmp, files))
    except PgsymError as err:
        raise fail(err) from None
    click.echo(
        f"{len(result.corners)} corners (k={k:g}, sigma={sigma:g}, threshold={threshold:g} * max R, "
        f"min distance {min_distance}) written to {out}/corners.csv; {len(files) - 1} images in {out}"
    )


def _harris_files(result) -> dict[str, object]:  # type: ignore[no-untyped-def]
    import numpy as np  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    from ..vision.images import display_uint8  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    files: dict[str, object] = {}
    signed = ["Ix", "Iy", "Ixy", "Sxy", "det", "response"]
    degree = {"image": 1, "Ix": 1, "Iy": 1, "det": 4, "response": 4}  # the others are quadratic in the gradient
    for name in ["image", "Ix", "Iy", "Ixx", "Iyy", "Ixy", "Sxx", "Syy", "Sxy", "det", "trace", "response"]:
        raw = getattr(result, name).astype(np.float64)
        shown = np.sign(raw) * np.abs(raw) ** (1.0 / degree.get(name, 2))
        files[f"{name}.png"] = display_uint8(shown, signed=name in signed)
    files["candidates.png"] = np.where(result.candidates, 255, 0).astype(np.uint8)
    files["maxima.png"] = np.where(result.maxima, 255, 0).astype(np.uint8)
    files["corners.png"] = corner_overlay(result.image, result.corners)
    rows = [(int(x), int(y), f"{r:.6g}") for (x, y), r in zip(result.corners, result.strengths, strict=True)]
    files["corners.csv"] = csv_text([("x", "y", "response"), *rows])
    return files


def corner_overlay(image, corners):  # type: ignore[no-untyped-def]
    """An RGB ``uint8`` copy of a grey float image with each corner marked by a red circle and cross.

    >>> import numpy as np
    >>> corner_overlay(np.zeros((20, 20), np.float32), np.array([[10.0, 10.0]]))[10, 10].tolist()
    [255, 0, 0]
    """
    import cv2  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    import numpy as np  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    grey = np.clip(np.rint(image * 255.0), 0, 255).astype(np.uint8)
    rgb = np.ascontiguousarray(np.repeat(grey[..., None], 3, axis=2))
    radius = max(3, round(min(image.shape) / 100))
    for x, y in np.asarray(corners).reshape(-1, 2).astype(int).tolist():
        cv2.circle(rgb, (x, y), radius, (255, 0, 0), 1, lineType=cv2.LINE_AA)
        cv2.drawMarker(rgb, (x, y), (255, 0, 0), cv2.MARKER_CROSS, radius, 1)
    return rgb


def _write_harris(folder: Path, files: dict[str, object]) -> None:
    from ..vision.images import write_image  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    for name, content in files.items():
        if isinstance(content, str):
            (folder / name).write_text(content)
        else:
            write_image(folder / name, content)  # type: ignore[arg-type]


@click.command(
    "rectify",
    short_help="Rectify a photographed plane (points, affine, metric).",
    context_settings=_CONTEXT,
)
@click.argument("image", type=click.Path(dir_okay=False, path_type=Path))
@click.option("--out", "out", required=True, type=click.Path(path_type=Path),
              help="Output image file (.png recommended); replaced if it exists.")
@click.option("--method", type=click.Choice(["points", "affine", "metric", "orthogonal"]), default="points",
              show_default=True,
              help="points: four points to a rectangle; affine: two parallel pairs; metric: plus two right angles; "
                   "orthogonal: five or more right angles alone.")
@click.option("--points", "points", type=POINTS, default=None,
              help='Four image points "x1,y1 x2,y2 x3,y3 x4,y4": top-left, top-right, bottom-right, bottom-left '
                   "of a world rectangle (method points).")
@click.option("--lines", "lines", type=LINES, default=None,
              help='Image lines, two points each, separated by ";" (methods affine, metric, orthogonal; see below).')
@click.option("--size", "size", type=SIZE, default=None,
              help="Output size WIDTHxHEIGHT, e.g. 400x300 (required for points; default for the other "
                   "methods: the input size).")
def rectify_command(image: Path, out: Path, method: str, points, lines, size) -> None:  # type: ignore[no-untyped-def]
    """Rectify a photographed plane in IMAGE and write the result to --out.

    \b
    --method points (default): the four --points go to the corners of the
      output rectangle of --size, so a world rectangle fills the output.
    --method affine: --lines holds four lines "A; A'; B; B'" where A is parallel
      to A' and B to B' in the world (two different directions). Their vanishing
      points span the vanishing line, which is sent back to infinity: parallel
      lines come out parallel (an affine view of the plane).
    --method metric: --lines holds eight lines, the four of the affine method
      followed by "C; C'; D; D'" with C perpendicular to C' and D to D' in the
      world (e.g. two sides and the two diagonals of a square). Right angles and
      length ratios come out right (the plane up to a similarity).
    --method orthogonal: --lines holds ten or more lines, "C1; C1'; ...; C5; C5'",
      each line perpendicular to the next in the world (five or more pairs, in
      several directions and places). They fix the image of the dual conic C*∞
      and rectify in one step, up to a similarity (Hartley & Zisserman 2.7.5).
    For affine, metric and orthogonal the whole input image is scaled to fit --size.
    Coordinates are pixels: x = column, y = row, origin at the top-left pixel.

    \b
    Examples:
      pgsym rectify photo.png --points "12,30 410,18 430,300 5,280" --size 400x300 --out flat.png
      pgsym rectify photo.png --method affine --out affine.png \\
          --lines "10,10 400,30; 10,200 400,260; 10,10 10,200; 400,30 400,260"
    """
    out = Path(out)
    _check_output_file(out)
    try:
        from ..vision.images import read_image  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

        img = read_image(image)
        H, out_size = _rectifying_homography(img.shape, method, points, lines, size)
        from ..vision.warp import warp  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

        rectified = warp(img, H, out_size)
        _write_file(out, rectified)
    except PgsymError as err:
        raise fail(err) from None
    click.echo(f"rectified ({method}) {out_size[0]}x{out_size[1]} image written to {out}")


def _write_file(out: Path, image) -> None:  # type: ignore[no-untyped-def]
    from ..vision.images import write_image  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    replace_file(out, lambda tmp: write_image(tmp, image))


def _rectifying_homography(shape, method, points, lines, size):  # type: ignore[no-untyped-def]
    import numpy as np  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    from ..vision.rectify import (  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
        affine_rectification,
        fit_to_size,
        line_through,
        metric_rectification,
        metric_rectification_from_orthogonal_pairs,
        rectangle_homography,
        vanishing_line,
    )

    if method == "points":
        if points is None:
            raise click.UsageError("--method points needs --points \"x1,y1 x2,y2 x3,y3 x4,y4\"")
        if len(points) != 4:
            raise click.BadParameter(f"exactly four points are needed, got {len(points)}", param_hint="'--points'")
        if size is None:
            raise click.UsageError("--method points needs --size WIDTHxHEIGHT for the output rectangle")
        if lines is not None:
            raise click.UsageError("--lines belongs to the methods affine and metric, not to points")
        return rectangle_homography(np.array(points), size), size
    if lines is None:
        raise click.UsageError(f"--method {method} needs --lines")
    if points is not None:
        raise click.UsageError(f"--points belongs to the method points, not to {method}")
    if method == "orthogonal":
        if len(lines) < 10 or len(lines) % 2:
            raise click.BadParameter(f"--method orthogonal takes an even number of lines, at least ten (five "
                                     f"perpendicular pairs), got {len(lines)}", param_hint="'--lines'")
    else:
        wanted = 4 if method == "affine" else 8
        if len(lines) != wanted:
            raise click.BadParameter(f"--method {method} takes {wanted} lines, got {len(lines)}",
                                     param_hint="'--lines'")
    h, w = shape
    centre = ((w - 1) / 2, (h - 1) / 2)
    ls = [line_through(p, q) for p, q in lines]
    parallel = [(ls[0], ls[1]), (ls[2], ls[3])]
    if method == "orthogonal":
        pairs = list(zip(ls[0::2], ls[1::2], strict=True))
        H = metric_rectification_from_orthogonal_pairs(pairs, reference=centre, scale=max(w, h) / 2)
    elif method == "affine":
        H = affine_rectification(vanishing_line(*parallel), reference=centre)
    else:
        H = metric_rectification(parallel, [(ls[4], ls[5]), (ls[6], ls[7])], reference=centre)
    out_size = size if size is not None else (w, h)
    corners = [[0, 0], [w - 1, 0], [w - 1, h - 1], [0, h - 1]]
    return fit_to_size(H, corners, out_size), out_size
