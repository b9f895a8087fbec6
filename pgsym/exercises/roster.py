"""Class lists the way spreadsheets and learning platforms export them.

A roster is a table with a header row (any encoding and separator :func:`~pgsym.exercises.reading.read_table`
understands). The student id is taken from the first column whose header names an institutional
student number, else a plain ``id``; the name from a ``name``-like column or from first and last name:

- a plain list: ``id,name`` (also ``Student ID``, ``student_id``, ``Matriculation number`` …);
- Canvas's gradebook export (``Student, ID, SIS User ID, SIS Login ID, Section, …`` then a
  ``Points Possible`` row): the id is ``SIS User ID`` (the column ``pgsym check --canvas`` writes back),
  never Canvas's internal ``ID``; the name is ``Student``; the ``Points Possible`` and
  ``Manual Posting`` rows and Canvas's ``Test Student`` are skipped;
- Moodle's grade and user exports (``First name, Last name, ID number, …, Email address``): the id is
  ``ID number``, the name first and last name joined;
- R/exams' register (``registration;name;id``, semicolons): the id is the registration number.

>>> import tempfile, os
>>> with tempfile.TemporaryDirectory() as d:
...     p = os.path.join(d, "grades.csv")
...     _ = open(p, "w").write('Student,ID,SIS User ID,SIS Login ID,Section\\n'
...                            '    Points Possible,,,,\\n"Lovelace, Ada",4711,s001,ada,A\\n')
...     read_roster(p)
[('s001', 'Lovelace, Ada')]
"""

from __future__ import annotations

import re
import unicodedata
from pathlib import Path

from ..escaping import one_line
from ..limits import MAX_NAME_CHARS
from .errors import RosterError
from .reading import Table, read_table, separator_hint

__all__ = ["ID_HEADERS", "NAME_HEADERS", "NOT_QUESTION_HEADERS", "find_id_column", "normal_header", "read_roster"]

#: Headers of a student id, most specific first (normalised by :func:`normal_header`): an institution's
#: student number wins over a platform's internal id.
ID_HEADERS = ("sis user id", "id number", "idnumber", "student id", "student number", "student no",
              "matriculation number", "matrikelnummer", "matrikelnr", "registration", "registration number",
              "id", "student")

#: Headers of a whole name.
NAME_HEADERS = ("name", "full name", "student name", "student")

_FIRST = ("first name", "given name", "firstname", "vorname")
_LAST = ("last name", "surname", "family name", "lastname", "nachname")

#: Headers of platform exports that are never questions (an answers file may carry them beside the answers).
NOT_QUESTION_HEADERS = frozenset((*ID_HEADERS, *NAME_HEADERS, *_FIRST, *_LAST, "sis login id", "section",
                                  "email", "email address", "e-mail", "username", "login", "institution",
                                  "department", "integration id", "group", "groups"))

#: First cells of Canvas export rows that are not students.
_CANVAS_META_ROWS = ("points possible", "manual posting")
_CANVAS_TEST_STUDENT = ("student, test", "test student")

_MAX_ID_CHARS = 100


def normal_header(cell: str) -> str:
    """A header cell compared case-, space- and punctuation-blind: ``" Student_ID "`` → ``"student id"``.

    >>> normal_header(" Student_ID "), normal_header("E-Mail-Adresse"), normal_header("ID-Nummer")
    ('student id', 'e-mail-adresse', 'id-nummer')
    """
    return re.sub(r"[\s_.]+", " ", unicodedata.normalize("NFKC", cell)).strip().lower()


def find_id_column(header: list[str], wanted: str | None = None) -> int | None:
    """The column of the student id: ``wanted`` (a header, compared as :func:`normal_header`) or the
    first of :data:`ID_HEADERS` present.

    >>> find_id_column(["Student", "ID", "SIS User ID"]), find_id_column(["Student", "ID"], "student")
    (2, 0)
    """
    fields = [normal_header(h) for h in header]
    for name in ((normal_header(wanted),) if wanted else ID_HEADERS):
        if name in fields:
            return fields.index(name)
    return None


def _name_getter(fields: list[str], id_col: int):  # type: ignore[no-untyped-def]
    for name in NAME_HEADERS:
        if name in fields and fields.index(name) != id_col:
            col = fields.index(name)
            return lambda row: row[col].strip() if col < len(row) else ""
    first = next((fields.index(f) for f in _FIRST if f in fields), None)
    last = next((fields.index(f) for f in _LAST if f in fields), None)
    if first is None and last is None:
        return lambda row: ""
    cols = [c for c in (first, last) if c is not None]
    return lambda row: " ".join(row[c].strip() for c in cols if c < len(row) and row[c].strip())


def _is_canvas(fields: list[str]) -> bool:
    return "sis user id" in fields and "student" in fields


def _canvas_without_sis(fields: list[str], table: Table) -> bool:
    """A Canvas export without the SIS User ID column (exports by a role that may not see it)."""
    rows = table.rows[1:3]
    return ("student" in fields and "id" in fields and "sis user id" not in fields
            and any(row and row[0].strip().lower() in _CANVAS_META_ROWS for _, row in rows))


def roster_from_table(table: Table, name: str, id_column: str | None = None) -> list[tuple[str, str]]:
    """The (id, name) pairs of a decoded roster table (see the module); ``name`` names the file in errors."""
    if table.problems:
        line, reason = table.problems[0]
        raise RosterError(f"line {line} of the roster {name!r} is not valid CSV: {reason}")
    if not table.rows:
        raise RosterError(f"the roster {name!r} is empty; it needs a header row such as\n"
                          "  id,name\n  s001,Ada Lovelace")
    header = table.rows[0][1]
    fields = [normal_header(f) for f in header]
    id_col = find_id_column(header, id_column)
    if id_col is None:
        shown = ", ".join(repr(one_line(f)[:40]) for f in header[:10]) or "none"
        wanted = (f"a column {id_column!r}" if id_column else
                  "an 'id' column (or 'Student ID', Moodle's 'ID number', Canvas's 'SIS User ID')")
        how = "" if id_column else "; or name the id column with --roster-id-column HEADER"
        raise RosterError(f"the roster {name!r} needs a header row with {wanted} (found: {shown})"
                          f"{separator_hint(header)}{how}; e.g.\n  id,name\n  s001,Ada Lovelace")
    if id_column is None and _canvas_without_sis(fields, table):
        raise RosterError(f"the roster {name!r} is a Canvas gradebook export without the 'SIS User ID' column, "
                          "which 'pgsym check --canvas' writes back; export the gradebook with SIS ids (a role "
                          "that may see them), or pass --roster-id-column ID to use Canvas's own id")
    name_of = _name_getter(fields, id_col)
    canvas = _is_canvas(fields) or (id_column is not None and _canvas_without_sis(fields, table))
    students, seen = [], set()
    for line, row in table.rows[1:]:
        if not any(cell.strip() for cell in row):
            continue  # a blank line
        sid = row[id_col].strip() if id_col < len(row) else ""
        if canvas:
            first = row[0].strip().lower() if row else ""
            if first in _CANVAS_META_ROWS or name_of(row).lower() in _CANVAS_TEST_STUDENT:
                # Canvas's points-possible / posting-policy rows, and its test student, which has a Canvas
                # id (read with --roster-id-column ID) but no SIS id
                continue
        if not sid:
            column = one_line(header[id_col])[:40]
            raise RosterError(f"line {line} of {name!r} has no student id (column {column!r})"
                              + ("; Canvas fills 'SIS User ID' only for students enrolled through the "
                                 "institution's SIS: fill it in, or pass --roster-id-column ID to use Canvas's "
                                 "own id instead" if canvas else "")
                              + ("; Moodle fills 'ID number' only where the site sets it: pass --roster-id-column "
                                 "'Email address' (or another column that is never empty)"
                                 if fields[id_col] in ("id number", "idnumber") else ""))
        if len(sid) > _MAX_ID_CHARS:
            raise RosterError(f"line {line} of {name!r}: the id is longer than {_MAX_ID_CHARS} characters")
        if any(unicodedata.category(c) == "Cc" for c in sid):
            # an id names files and matches answers: a control character there is a broken roster
            raise RosterError(f"line {line} of {name!r}: the id {one_line(sid)!r} contains a control character")
        if sid in seen:
            raise RosterError(f"line {line} of {name!r}: the id {one_line(sid)!r} appears twice")
        seen.add(sid)
        student_name = name_of(row)
        if len(student_name) > MAX_NAME_CHARS:
            raise RosterError(f"line {line} of {name!r}: the name is longer than {MAX_NAME_CHARS} characters "
                              "(the limit)")
        students.append((sid, student_name))
    if not students:
        raise RosterError(f"the roster {name!r} lists no students")
    return students


def read_roster(path: str | Path, id_column: str | None = None,
                notes: list[str] | None = None) -> list[tuple[str, str]]:
    """Read a roster file (see the module): the (student id, name) pairs in file order.

    ``id_column`` names the id column when the usual choice is not wanted (e.g. ``"ID"`` for Canvas's
    internal id); ``notes`` receives what the reader guessed (e.g. the encoding) to show the instructor.
    Every refusal is a :class:`RosterError` that says what to change.

    >>> import tempfile, os
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = os.path.join(d, "r.csv")
    ...     _ = open(p, "w").write("id,name\\ns1,Ada\\ns2,Alan\\n")
    ...     read_roster(p)
    [('s1', 'Ada'), ('s2', 'Alan')]
    """
    p = Path(path)
    table = read_table(p, "roster", RosterError)
    if notes is not None:
        notes += table.notes
    return roster_from_table(table, p.name, id_column)
