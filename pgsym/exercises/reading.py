"""Reading the files an instructor gives the exercise tools: rosters, answers, manifests, templates.

Every reader goes through :func:`pgsym.limits.read_text_file` (bytes actually read, at most
:data:`~pgsym.limits.MAX_FILE_BYTES`; FIFOs and devices refused), checks the bracket nesting of
JSON before parsing it (:data:`~pgsym.limits.MAX_NESTING`) and turns every failure into the named
error of the file's kind.

>>> check_nesting('{"a": [[1], "[[[["]}', "manifest", ValueError)
>>> check_nesting("[" * 40 + "]" * 40, "manifest", ValueError)
Traceback (most recent call last):
...
ValueError: the manifest nests brackets more than 32 deep (the limit)
"""

from __future__ import annotations

import csv
import io
import json
import os
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from ..errors import InputLimitError, PgsymError
from ..limits import MAX_FILE_BYTES, MAX_NESTING, read_text_file


def read_user_text(path: str | os.PathLike[str], what: str, error: type[PgsymError]) -> str:
    """The text of a user's file: :class:`InputLimitError` past the limits or for a pipe/device,
    ``error`` when it is missing, unreadable or not UTF-8."""
    p = Path(path)
    try:
        return read_text_file(p, what)
    except InputLimitError:
        raise
    except FileNotFoundError:
        raise error(f"the {what} {str(p)!r} does not exist") from None
    except UnicodeDecodeError as err:
        raise error(f"the {what} {str(p)!r} is not UTF-8 text (byte {err.start + 1})") from None
    except OSError as err:
        raise error(f"cannot read the {what} {str(p)!r}: {err.strerror or err}") from None


def check_nesting(text: str, what: str, error: type[Exception], limit: int = MAX_NESTING) -> None:
    """Raise ``error`` if JSON ``text`` nests ``[``/``{`` more than ``limit`` deep (strings skipped).

    A single loop over the characters, so hostile nesting costs no recursion before ``json.loads``.
    """
    depth = 0
    in_string = escaped = False
    for c in text:
        if in_string:
            if escaped:
                escaped = False
            elif c == "\\":
                escaped = True
            elif c == '"':
                in_string = False
        elif c == '"':
            in_string = True
        elif c in "[{":
            depth += 1
            if depth > limit:
                raise error(f"the {what} nests brackets more than {limit} deep (the limit)")
        elif c in "]}":
            depth -= 1


def load_json(path: str | os.PathLike[str], what: str, error: type[PgsymError]) -> Any:
    """Parse a user's JSON file within the limits; ``error`` names what is wrong."""
    text = read_user_text(path, what, error)
    check_nesting(text, what, error)
    try:
        return json.loads(text)
    except (ValueError, RecursionError) as err:  # ValueError: bad JSON, or an integer of too many digits
        raise error(f"the {what} {str(path)!r} is not readable JSON: {err}") from None


@contextmanager
def _csv_fields_up_to(limit: int) -> Iterator[None]:
    # the csv module refuses fields over 128 KiB for the whole file; the file size is bounded
    # already, and each caller limits its own cells (so one long cell never stops the others)
    old = csv.field_size_limit(limit)
    try:
        yield
    finally:
        csv.field_size_limit(old)


def csv_rows(text: str) -> tuple[list[tuple[int, list[str]]], list[tuple[int, str]]]:
    """Parse CSV text: the rows with their line numbers, and the rows that are not valid CSV (line, reason).

    >>> csv_rows('id,name\\ns1,"Ada, A."\\n')
    ([(1, ['id', 'name']), (2, ['s1', 'Ada, A.'])], [])
    """
    rows: list[tuple[int, list[str]]] = []
    problems: list[tuple[int, str]] = []
    with _csv_fields_up_to(MAX_FILE_BYTES):
        reader = csv.reader(io.StringIO(text, newline=""))
        while True:
            start = reader.line_num + 1
            try:
                row = next(reader)
            except StopIteration:
                break
            except csv.Error as err:
                problems.append((start, str(err)))
                continue
            rows.append((start, row))
    return rows, problems
