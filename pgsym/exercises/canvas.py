"""The grades of ``pgsym check`` as a Canvas gradebook CSV, ready for Canvas's "Import" of the Gradebook.

The columns follow the gradebook Canvas exports and imports: ``Student, ID, SIS User ID,
SIS Login ID, Section``, then one column per assignment headed ``Title (id)`` (an existing
assignment is matched by its id; a column without an id creates a new assignment), and an optional
second row ``Points Possible``. See Canvas's guide "How do I import grades in the Gradebook?"
(https://community.canvaslms.com/t5/Instructor-Guide/How-do-I-import-grades-in-the-Gradebook/ta-p/807).
Graded from an answers CSV, pgsym knows no Canvas user ids, so ``ID`` stays empty and the roster id
goes to ``SIS User ID``, one of the columns Canvas matches students by; graded from Canvas's Student
Analysis report, both come from the report. The score is the points earned (:mod:`pgsym.exercises.points`).

>>> from pgsym.exercises.grading import Result
>>> report = {"s1": [Result("s1", "1", "2", True, ""), Result("s1", "2", "", False, "no answer")]}
>>> print(canvas_csv(report, {"s1": "Ada Lovelace"}, "Week 4", 1234), end="")
Student,ID,SIS User ID,SIS Login ID,Section,Week 4 (1234)
Points Possible,,,,,2
Ada Lovelace,,s1,,,1
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction

from ..csv_cells import csv_text
from ..escaping import one_line
from .grading import Result, score_summary
from .lms import Person
from .points import points_text

__all__ = ["CANVAS_COLUMNS", "canvas_csv"]

#: The fixed leading columns of a Canvas gradebook CSV.
CANVAS_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")


def canvas_csv(report: Mapping[str, list[Result]], names: Mapping[str, str], title: str,
               assignment_id: int | None = None, people: Mapping[str, Person] | None = None) -> str:
    """One row per student with the points earned as the score (:func:`~pgsym.exercises.grading.score_summary`,
    the same sum as the report and the Moodle gradebook) and the points possible in the second row.

    ``people`` (from a Canvas quiz report) supplies the Canvas user id and the SIS User ID of each
    person; without it the key (the roster id) is the SIS User ID. Students who are not in ``names``
    (an unknown id in the answers file) are left out; cells a spreadsheet would run as a formula are
    neutralised like every CSV pgsym writes.
    """
    title = one_line(title) or "pgsym"
    column = f"{title} ({assignment_id})" if assignment_id is not None else title
    rows = score_summary({s: rs for s, rs in report.items() if s in names})
    possible = max((worth for _, _, worth in rows), default=Fraction(0))
    lines: list[list[object]] = [[*CANVAS_COLUMNS, column], ["Points Possible", "", "", "", "", points_text(possible)]]
    for s, got, _ in rows:
        person = (people or {}).get(s)
        canvas_id, sis = (person.canvas_id, person.sis_id) if person else ("", s)
        lines.append([names[s] or s, canvas_id, sis, "", "", points_text(got)])
    return csv_text(lines)
