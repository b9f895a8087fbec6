"""Every limit pgsym puts on user input, and the readers that enforce them while reading.

A reader of user input (a CLI argument, a roster, an answers file, a manifest, a template,
an image) never trusts ``stat()``: a FIFO or ``/dev/zero`` reports size 0. It reads at most
``limit + 1`` bytes and raises :class:`InputLimitError` when the extra byte arrives. The
limits are plain constants here, so the README, the errors and the tests quote one value.

>>> import io
>>> read_bounded(io.BytesIO(b"abc"), 10, "roster")
b'abc'
>>> read_bounded(io.BytesIO(b"x" * 11), 10, "roster")
Traceback (most recent call last):
...
pgsym.errors.InputLimitError: the roster is larger than 10 bytes (the limit); split it or shorten it
"""

from __future__ import annotations

import os
import stat
from pathlib import Path
from typing import BinaryIO

from .errors import InputLimitError

__all__ = [
    "MAX_ANSWER_CHARS",
    "MAX_ARGUMENT_CHARS",
    "MAX_DIGITS",
    "MAX_EXPONENT",
    "MAX_FILE_BYTES",
    "MAX_IMAGE_BYTES",
    "MAX_IMAGE_PIXELS",
    "MAX_NAME_CHARS",
    "MAX_NESTING",
    "MAX_STATEMENT_BYTES",
    "MAX_STATEMENT_LINE_CHARS",
    "MAX_STATEMENT_NAME_CHARS",
    "MAX_STATEMENT_OBJECTS",
    "read_bounded",
    "read_file_bytes",
    "read_text_file",
]

MAX_FILE_BYTES = 20_000_000
"""Rosters, answers files, manifests and templates: bytes actually read."""

MAX_ARGUMENT_CHARS = 500
"""One command-line argument (a coordinate list, a point list)."""

MAX_ANSWER_CHARS = 2000
"""One typed answer cell."""

MAX_DIGITS = 40
"""Digits of one number typed by a user (numerator and denominator each)."""

MAX_EXPONENT = 40
"""Largest absolute decimal exponent in ``1e…`` notation typed by a user."""

MAX_NESTING = 32
"""Bracket / JSON nesting depth of any structured input."""

MAX_IMAGE_PIXELS = 40_000_000
"""Pixels of a decoded image (checked from the header, before decoding)."""

MAX_IMAGE_BYTES = 200_000_000
"""Bytes of one image file read (an uncompressed 8-bit RGBA image of MAX_IMAGE_PIXELS pixels is 160 MB)."""

MAX_NAME_CHARS = 20_000
"""One roster field other than the id (a student's name), in characters."""

MAX_STATEMENT_BYTES = 200_000
"""A theorem in the statement language (``pgsym prove FILE``): bytes read."""

MAX_STATEMENT_LINE_CHARS = 1000
"""One line of a theorem in the statement language, in characters."""

MAX_STATEMENT_NAME_CHARS = 40
"""One name (of an object or parameter) in the statement language, in characters."""

MAX_STATEMENT_OBJECTS = 400
"""Objects (named or nested constructions) of one theorem in the statement language."""

_CHUNK = 1 << 16


def read_bounded(stream: BinaryIO, limit: int, what: str) -> bytes:
    """Read a binary stream to its end, raising :class:`InputLimitError` past ``limit`` bytes.

    Reads in chunks and stops as soon as the limit is exceeded, so an endless stream
    (``/dev/zero``) costs at most ``limit`` bytes of memory.
    """
    chunks: list[bytes] = []
    total = 0
    while True:
        chunk = stream.read(min(_CHUNK, limit + 1 - total))
        if not chunk:
            return b"".join(chunks)
        chunks.append(chunk)
        total += len(chunk)
        if total > limit:
            raise InputLimitError(f"the {what} is larger than {limit} bytes (the limit); split it or shorten it")


def read_file_bytes(path: str | os.PathLike[str], what: str, limit: int = MAX_FILE_BYTES) -> bytes:
    """The bytes of a regular file of at most ``limit`` bytes (counted while reading).

    Only regular files are read: a FIFO, a device or a folder raises :class:`InputLimitError`
    at once instead of blocking. Missing or unreadable files raise ``FileNotFoundError`` /
    ``OSError`` for the caller to name.
    """
    p = Path(path)
    # open without blocking (a FIFO with no writer would block a plain open), then check the type
    fd = os.open(p, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    try:
        if not _is_regular(fd):
            raise InputLimitError(f"the {what} {p.name!r} is not a regular file (a pipe, device or folder)")
        with os.fdopen(fd, "rb", closefd=False) as stream:
            return read_bounded(stream, limit, what)
    finally:
        os.close(fd)


def read_text_file(path: str | os.PathLike[str], what: str, limit: int = MAX_FILE_BYTES) -> str:
    """Read a UTF-8 text file of at most ``limit`` bytes (BOM dropped) with :func:`read_file_bytes`;
    undecodable bytes raise ``UnicodeDecodeError``."""
    return read_file_bytes(path, what, limit).decode("utf-8-sig")


def _is_regular(fd: int) -> bool:
    return stat.S_ISREG(os.fstat(fd).st_mode)
