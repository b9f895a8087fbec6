"""The grades of ``pgsym check`` as a Canvas gradebook CSV, ready for Canvas's "Import" of the Gradebook.

The columns follow the gradebook Canvas exports and imports: ``Student, ID, SIS User ID,
SIS Login ID, Section``, then one column per assignment headed ``Title (id)`` (an existing
assignment is matched by its id; a column without an id creates a new assignment), and an optional
second row ``Points Possible``. See Canvas's guide "How do I import grades in the Gradebook?"
(https://community.canvaslms.com/t5/Instructor-Guide/How-do-I-import-grades-in-the-Gradebook/ta-p/807).
pgsym knows no Canvas user ids, so ``ID`` stays empty and the roster id goes to ``SIS User ID``,
one of the columns Canvas matches students by.

>>> from pgsym.exercises.grading import Result
>>> report = {"s1": [Result("s1", "1", "2", True, ""), Result("s1", "2", "", False, "no answer")]}
>>> print(canvas_csv(report, {"s1": "Ada Lovelace"}, "Week 4", 1234), end="")
Student,ID,SIS User ID,SIS Login ID,Section,Week 4 (1234)
Points Possible,,,,,2
Ada Lovelace,,s1,,,1
"""

from __future__ import annotations

from collections.abc import Mapping

from ..csv_cells import csv_text
from ..escaping import one_line
from .grading import Result, summary

__all__ = ["CANVAS_COLUMNS", "canvas_csv"]

#: The fixed leading columns of a Canvas gradebook CSV.
CANVAS_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")


def canvas_csv(report: Mapping[str, list[Result]], names: Mapping[str, str], title: str,
               assignment_id: int | None = None) -> str:
    """One row per student of the manifest with the number of right answers as the score.

    Students who are not in the manifest (an unknown id in the answers file) are left out; cells a
    spreadsheet would run as a formula are neutralised like every CSV pgsym writes.
    """
    title = one_line(title) or "pgsym"
    column = f"{title} ({assignment_id})" if assignment_id is not None else title
    rows = summary({s: rs for s, rs in report.items() if s in names})
    possible = max((questions for _, _, questions in rows), default=0)
    lines: list[list[object]] = [[*CANVAS_COLUMNS, column], ["Points Possible", "", "", "", "", possible]]
    lines += [[names[s] or s, "", s, "", "", right] for s, right, _ in rows]
    return csv_text(lines)
