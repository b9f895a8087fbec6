"""Images as NumPy arrays: checks, conversion to float32 grey values, reading and writing.

Convention: an image for the numeric routines is a ``float32`` array of shape
``(H, W)`` (rows, columns) with grey values, usually in ``[0, 1]``. Pixel
``(x, y)`` is column ``x``, row ``y``; pixel centres have integer coordinates.

>>> import numpy as np
>>> img = to_float_image(np.array([[0, 255]], dtype=np.uint8))
>>> img.dtype.name, img.tolist()
('float32', [[0.0, 1.0]])
"""

from __future__ import annotations

import io
import os
import stat
import warnings
from pathlib import Path

import numpy as np

from ..errors import InputLimitError
from ..limits import MAX_IMAGE_BYTES, MAX_IMAGE_PIXELS, read_bounded
from .errors import ImageError

__all__ = ["check_image", "display_uint8", "image_size", "read_image", "read_image_bytes", "to_float_image",
           "write_image"]


def check_image(image: object, name: str = "image") -> np.ndarray:
    """Return ``image`` unchanged if it is a non-empty finite ``float32`` array of shape ``(H, W)``.

    Raises :class:`~pgsym.vision.errors.ImageError` otherwise, saying how to convert it.

    >>> import numpy as np
    >>> check_image(np.zeros((2, 3), np.float32)).shape
    (2, 3)
    >>> check_image(np.zeros((2, 3)))
    Traceback (most recent call last):
    ...
    pgsym.vision.errors.ImageError: image must have dtype float32, got float64; convert it with to_float_image()
    """
    if not isinstance(image, np.ndarray):
        raise ImageError(f"{name} must be a NumPy array, got {type(image).__name__}; convert it with to_float_image()")
    if image.dtype != np.float32:
        raise ImageError(f"{name} must have dtype float32, got {image.dtype}; convert it with to_float_image()")
    if image.ndim != 2:
        raise ImageError(
            f"{name} must be a grey-value array of shape (H, W), got shape {image.shape}; "
            "convert colour images with to_float_image()"
        )
    if image.size == 0:
        raise ImageError(f"{name} is empty (shape {image.shape}); it needs at least one pixel")
    if not np.isfinite(image.sum(dtype=np.float64)):  # NaN and ±inf propagate through the sum
        raise ImageError(f"{name} contains NaN or infinite values; replace them before processing")
    return image


def to_float_image(array: object) -> np.ndarray:
    """Convert an integer, boolean or floating array (grey, RGB or RGBA) to a float32 ``(H, W)`` image.

    Integer images are scaled to ``[0, 1]`` by the maximum of their dtype; floating
    images keep their values; colour images are converted to grey with the
    ITU-R BT.601 weights ``0.299 R + 0.587 G + 0.114 B`` (alpha is dropped).

    >>> import numpy as np
    >>> rgb = np.zeros((1, 1, 3), np.uint8); rgb[..., 1] = 255
    >>> round(float(to_float_image(rgb)[0, 0]), 3)
    0.587
    """
    a = np.asarray(array)
    if a.size == 0:
        raise ImageError(f"the image is empty (shape {a.shape}); it needs at least one pixel")
    if a.dtype == bool:
        a = a.astype(np.float32)
    elif np.issubdtype(a.dtype, np.integer):
        a = a.astype(np.float32) / np.float32(np.iinfo(a.dtype).max)
    elif np.issubdtype(a.dtype, np.floating):
        a = a.astype(np.float32)
    else:
        raise ImageError(f"cannot read an image from an array of dtype {a.dtype}; use integers or floats")
    if a.ndim == 3 and a.shape[2] in (3, 4):
        a = a[..., 0] * np.float32(0.299) + a[..., 1] * np.float32(0.587) + a[..., 2] * np.float32(0.114)
    elif a.ndim == 3 and a.shape[2] == 1:
        a = a[..., 0]
    if a.ndim != 2:
        raise ImageError(f"expected a grey (H, W) or colour (H, W, 3|4) image, got shape {a.shape}")
    return check_image(np.ascontiguousarray(a, dtype=np.float32))


def read_image(path: str | Path) -> np.ndarray:
    """Read an image file as a float32 grey image in ``[0, 1]``.

    The file is read with its limits checked while reading: it must be a regular file
    (not a folder, pipe or device) of at most :data:`~pgsym.limits.MAX_IMAGE_BYTES` bytes,
    and its header must announce at most :data:`~pgsym.limits.MAX_IMAGE_PIXELS` pixels,
    checked before anything is decoded (a small compressed file can decode to gigabytes).
    Raises :class:`~pgsym.vision.errors.ImageError` when the file is missing or is not an image
    OpenCV can decode, and :class:`~pgsym.errors.InputLimitError` past a limit.

    >>> read_image("no-such-file.png")
    Traceback (most recent call last):
    ...
    pgsym.vision.errors.ImageError: cannot read image 'no-such-file.png': the file does not exist
    """
    data = read_image_bytes(path)
    width, height = image_size(data, str(path))
    if width * height > MAX_IMAGE_PIXELS:
        raise InputLimitError(f"the image {str(path)!r} has {width}x{height} = {width * height} pixels; "
                              f"at most {MAX_IMAGE_PIXELS} are read (scale it down first)")
    import cv2  # noqa: PLC0415 — OpenCV loads on first use: vision modules load without it

    old = cv2.utils.logging.setLogLevel(cv2.utils.logging.LOG_LEVEL_SILENT)  # damage is reported below, once
    try:
        image = cv2.imdecode(np.frombuffer(data, dtype=np.uint8), cv2.IMREAD_UNCHANGED)
    finally:
        cv2.utils.logging.setLogLevel(old)
    if image is None or image.size == 0 or image.shape[0] * image.shape[1] > MAX_IMAGE_PIXELS:
        raise ImageError(f"cannot read image {str(path)!r}: OpenCV cannot decode it (truncated or damaged?); "
                         "use PNG or JPEG")
    if image.ndim == 3:  # OpenCV stores colour as BGR(A)
        image = image[..., [2, 1, 0]] if image.shape[2] >= 3 else image
    return to_float_image(image)


def read_image_bytes(path: str | Path) -> bytes:
    """The bytes of an image file, read with the limits of :func:`read_image` (no decoding).

    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     read_image_bytes(d)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.vision.errors.ImageError: cannot read image '...': it is a folder, not a file
    """
    name = str(path)
    try:
        # without blocking: a FIFO with no writer would block a plain open; the type is checked next
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except FileNotFoundError:
        raise ImageError(f"cannot read image {name!r}: the file does not exist") from None
    except IsADirectoryError:
        raise ImageError(f"cannot read image {name!r}: it is a folder, not a file") from None
    except (OSError, ValueError) as err:  # ValueError: a NUL byte in the name
        reason = err.strerror if isinstance(err, OSError) and err.strerror else str(err)
        raise ImageError(f"cannot read image {name!r}: {reason}") from None
    try:
        mode = os.fstat(fd).st_mode
        if stat.S_ISDIR(mode):
            raise ImageError(f"cannot read image {name!r}: it is a folder, not a file")
        if not stat.S_ISREG(mode):
            raise ImageError(f"cannot read image {name!r}: it is not a regular file (a pipe or a device)")
        with os.fdopen(fd, "rb", closefd=False) as stream:
            data = read_bounded(stream, MAX_IMAGE_BYTES, f"image {name!r}")
    except OSError as err:
        raise ImageError(f"cannot read image {name!r}: {err.strerror or err}") from None
    finally:
        os.close(fd)
    if not data:
        raise ImageError(f"cannot read image {name!r}: the file is empty")
    return data


def image_size(data: bytes, name: str = "image") -> tuple[int, int]:
    """``(width, height)`` announced by the header of an encoded image, without decoding its pixels.

    >>> import cv2, numpy as np
    >>> image_size(cv2.imencode(".png", np.zeros((3, 5), np.uint8))[1].tobytes())
    (5, 3)
    >>> image_size(b"not an image")
    Traceback (most recent call last):
    ...
    pgsym.vision.errors.ImageError: cannot read image 'image': not an image format pgsym reads (use PNG or JPEG)
    """
    from PIL import Image  # noqa: PLC0415 — Pillow (a Matplotlib dependency) reads only the header here

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", Image.DecompressionBombWarning)
            with Image.open(io.BytesIO(data)) as header:
                width, height = header.size
    except Image.DecompressionBombError:
        raise InputLimitError(f"the image {name!r} has more than {MAX_IMAGE_PIXELS} pixels; "
                              "at most that many are read (scale it down first)") from None
    except Exception:  # Pillow raises many types for broken headers (OSError, SyntaxError, struct.error, ...)
        raise ImageError(f"cannot read image {name!r}: not an image format pgsym reads (use PNG or JPEG)") from None
    return int(width), int(height)


def display_uint8(array: np.ndarray, signed: bool = False) -> np.ndarray:
    """Scale an array to ``uint8`` for display.

    By default the range ``[min, max]`` is mapped to ``[0, 255]``; with
    ``signed=True`` zero maps to 128 and ``±max|a|`` to 0 and 255, so the sign
    stays visible (for gradients and the Harris response). A constant array maps to 0
    (or 128 when ``signed``).

    >>> import numpy as np
    >>> display_uint8(np.array([[-1.0, 0.0, 3.0]])).tolist()
    [[0, 64, 255]]
    >>> display_uint8(np.array([[-2.0, 0.0, 1.0]]), signed=True).tolist()
    [[0, 128, 191]]
    """
    a = np.asarray(array, dtype=np.float64)
    if signed:
        m = float(np.abs(a).max()) if a.size else 0.0
        if m == 0.0:
            return np.full(a.shape, 128, np.uint8)
        return np.clip(np.rint(127.5 + 127.5 * a / m), 0, 255).astype(np.uint8)
    lo, hi = (float(a.min()), float(a.max())) if a.size else (0.0, 0.0)
    if hi == lo:
        return np.zeros(a.shape, np.uint8)
    return np.clip(np.rint(255.0 * (a - lo) / (hi - lo)), 0, 255).astype(np.uint8)


def write_image(path: str | Path, image: np.ndarray) -> None:
    """Write an image file; float images are taken to be in ``[0, 1]`` and clipped.

    ``uint8`` arrays (grey ``(H, W)`` or RGB ``(H, W, 3)``) are written as they are.
    The format follows the file extension (``.png`` recommended).

    >>> import numpy as np, tempfile, os
    >>> with tempfile.TemporaryDirectory() as d:
    ...     write_image(os.path.join(d, "a.png"), np.ones((2, 2), np.float32))
    ...     read_image(os.path.join(d, "a.png")).tolist()
    [[1.0, 1.0], [1.0, 1.0]]
    """
    import cv2  # noqa: PLC0415 — OpenCV loads on first use: vision modules load without it

    a = np.asarray(image)
    if a.dtype != np.uint8:
        a = np.clip(np.rint(np.asarray(a, dtype=np.float64) * 255.0), 0, 255).astype(np.uint8)
    if a.ndim == 3 and a.shape[2] == 3:
        a = a[..., ::-1]  # RGB -> BGR for OpenCV
    ok, buf = cv2.imencode(Path(path).suffix or ".png", np.ascontiguousarray(a))
    if not ok:
        raise ImageError(f"cannot encode an image for {str(path)!r}; use a .png or .jpg file name")
    Path(path).write_bytes(buf.tobytes())
