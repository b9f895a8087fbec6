"""Reading the files an instructor gives the exercise tools: rosters, answers, manifests, templates.

Every reader goes through :func:`pgsym.limits.read_file_bytes` (bytes actually read, at most
:data:`~pgsym.limits.MAX_FILE_BYTES`; FIFOs and devices refused), checks the bracket nesting of
JSON before parsing it (:data:`~pgsym.limits.MAX_NESTING`) and turns every failure into the named
error of the file's kind.

>>> check_nesting('{"a": [[1], "[[[["]}', "manifest", ValueError)
>>> check_nesting("[" * 40 + "]" * 40, "manifest", ValueError)
Traceback (most recent call last):
...
ValueError: the manifest nests brackets more than 32 deep (the limit)

Tables (rosters, answers files) come the way spreadsheets and learning platforms save them: the
encoding is found from the byte-order mark (UTF-8, UTF-16 as Excel's "Unicode text", UTF-32), else
strict UTF-8, else Windows-1252 (Excel's "CSV" on Western Windows); the separator (``,`` ``;`` tab
``|``, or Excel's ``sep=`` first line) from the header row:

>>> t = decode_table("id;name\\r\\ns1;D\\u2019Angelo\\r\\n".encode("cp1252"), "roster", "r.csv", ValueError)
>>> t.encoding, t.separator, t.rows
('windows-1252', ';', [(1, ['id', 'name']), (2, ['s1', 'D’Angelo'])])
"""

from __future__ import annotations

import csv
import io
import json
import os
import re
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import InputLimitError, PgsymError
from ..limits import MAX_FILE_BYTES, MAX_NESTING, read_file_bytes, read_text_file


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


def csv_rows(text: str, separator: str = ",") -> tuple[list[tuple[int, list[str]]], list[tuple[int, str]]]:
    """Parse CSV text: the rows with their line numbers, and the rows that are not valid CSV (line, reason).

    >>> csv_rows('id,name\\ns1,"Ada, A."\\n')
    ([(1, ['id', 'name']), (2, ['s1', 'Ada, A.'])], [])
    """
    rows: list[tuple[int, list[str]]] = []
    problems: list[tuple[int, str]] = []
    with _csv_fields_up_to(MAX_FILE_BYTES):
        reader = csv.reader(io.StringIO(text, newline=""), delimiter=separator)
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


#: Separators a table may use, in the order they are preferred when the header does not decide.
SEPARATORS = (",", ";", "\t", "|")

#: Byte-order marks, longest first (UTF-32 LE starts with the UTF-16 LE mark).
_BOMS = ((b"\x00\x00\xfe\xff", "utf-32-be"), (b"\xff\xfe\x00\x00", "utf-32-le"), (b"\xef\xbb\xbf", "utf-8"),
         (b"\xff\xfe", "utf-16-le"), (b"\xfe\xff", "utf-16-be"))

_RESAVE = "re-save it as \"CSV UTF-8\" (Excel: File → Save As → CSV UTF-8; LibreOffice: Character set UTF-8)"


@dataclass
class Table:
    """A decoded table: rows with their line numbers, lines that are not valid CSV, how it was read."""

    rows: list[tuple[int, list[str]]]
    problems: list[tuple[int, str]]
    encoding: str
    separator: str
    notes: list[str] = field(default_factory=list)


def decode_text(data: bytes, what: str, name: str, error: type[Exception]) -> tuple[str, str]:
    """The text of a table's bytes and the encoding read: BOM, else strict UTF-8, else Windows-1252.

    UTF-16 without a BOM (every other byte NUL) is recognised too; bytes that fit none of these raise
    ``error`` saying how to re-save the file.

    >>> decode_text("id\\tname\\n".encode("utf-16"), "roster", "r.txt", ValueError)
    ('id\\tname\\n', 'utf-16-le')
    >>> decode_text(b"id\\x81", "roster", "r.csv", ValueError)
    Traceback (most recent call last):
    ...
    ValueError: the roster 'r.csv' is neither UTF-8, UTF-16 nor Windows-1252 text (byte 3 is 0x81); re-save it ...
    """
    for bom, encoding in _BOMS:
        if data.startswith(bom):
            try:
                return data[len(bom):].decode(encoding), encoding
            except UnicodeDecodeError as err:
                raise error(f"the {what} {name!r} starts with a {encoding.upper()} byte-order mark but byte "
                            f"{err.start + len(bom) + 1} is not {encoding.upper()}; {_RESAVE}") from None
    head = data[:4000]
    if len(head) >= 4 and head.count(0) * 3 >= len(head):  # UTF-16 without a mark: ASCII with NUL bytes between
        encoding = "utf-16-le" if head[1] == 0 else "utf-16-be"
        try:
            return data.decode(encoding), encoding
        except UnicodeDecodeError:
            pass
    try:
        return data.decode("utf-8"), "utf-8"
    except UnicodeDecodeError:
        pass
    try:
        text = data.decode("cp1252")
    except UnicodeDecodeError as err:
        raise error(f"the {what} {name!r} is neither UTF-8, UTF-16 nor Windows-1252 text (byte {err.start + 1} is "
                    f"0x{data[err.start]:02x}); {_RESAVE}") from None
    if "\x00" in text:
        raise error(f"the {what} {name!r} contains NUL bytes: it is not a text table; {_RESAVE}")
    return text, "windows-1252"


def _width(line: str, sep: str) -> int:
    try:
        return len(next(csv.reader([line], delimiter=sep)))
    except (csv.Error, StopIteration):
        return 0


def sniff_separator(text: str) -> tuple[str, str]:
    """The separator of a table and the text without Excel's ``sep=X`` first line (which decides).

    Otherwise the separator is the one that splits the header row into more than one column and gives
    the most of the next lines the header's width; ties go to the wider header, then to ``,``.

    >>> sniff_separator("id;name\\ns1;Lovelace, Ada\\n")[0], sniff_separator("sep=|\\nid|name\\n")
    (';', ('|', 'id|name\\n'))
    >>> sniff_separator("Name, first\\tID\\nLovelace, Ada\\ts1\\nTuring\\ts2\\n")[0]
    '\\t'
    """
    first, _, rest = text.partition("\n")
    hint = re.fullmatch(r"\s*sep=(.)\s*", first)
    if hint and hint.group(1) in SEPARATORS:
        return hint.group(1), rest
    lines = [line.rstrip("\r") for line in text.split("\n", 20)[:20] if line.strip()]
    scores = {}
    for sep in SEPARATORS:
        width = _width(lines[0], sep) if lines else 0
        if width > 1:
            scores[sep] = (sum(_width(line, sep) == width for line in lines[1:20]), width, -SEPARATORS.index(sep))
    return (max(scores, key=lambda sep: scores[sep]) if scores else ","), text


def separator_hint(cells: list[str]) -> str:
    """A hint when a header row was not understood: which character looks like its separator.

    >>> separator_hint(["id:name:email"])
    " (the separator looks like ':'; save the file as CSV with ',' or ';' between the columns)"
    """
    line = "".join(cells)
    counts = {c: line.count(c) for c in ":/ "}
    sep = max(counts, key=lambda c: counts[c]) if len(cells) == 1 else ""
    if sep and counts[sep] and sep != " ":
        return f" (the separator looks like {sep!r}; save the file as CSV with ',' or ';' between the columns)"
    return ""


def read_table(path: str | os.PathLike[str], what: str, error: type[PgsymError]) -> Table:
    """Read a table file within the limits: decoded (:func:`decode_text`), separator found
    (:func:`sniff_separator`), parsed (:func:`csv_rows`); a note says when the encoding was a guess."""
    p = Path(path)
    try:
        data = read_file_bytes(p, what)
    except InputLimitError:
        raise
    except FileNotFoundError:
        raise error(f"the {what} {str(p)!r} does not exist") from None
    except OSError as err:
        raise error(f"cannot read the {what} {str(p)!r}: {err.strerror or err}") from None
    return decode_table(data, what, p.name, error)


def decode_table(data: bytes, what: str, name: str, error: type[Exception]) -> Table:
    """The :class:`Table` of a table file's bytes (see :func:`read_table`)."""
    text, encoding = decode_text(data, what, name, error)
    sep, text = sniff_separator(text)
    rows, problems = csv_rows(text, sep)
    notes = []
    if encoding == "windows-1252":
        notes.append(f"the {what} {name!r} is not UTF-8; it was read as Windows-1252 (Excel's \"CSV\" on Western "
                     f"Windows). If a name looks wrong, {_RESAVE}")
    return Table(rows, problems, encoding, sep, notes)
