"""The grades of ``pgsym check`` as a CSV for Moodle's gradebook import (Grades → Import → CSV file).

Moodle's CSV grade import maps one column to a user field (``Email address``, ``ID number`` or
``Username``; the instructor chooses in the import's "Identify user" step) and other columns to a
grade item and to its feedback (see the Moodle documentation "Grade import",
https://docs.moodle.org/en/Grade_import). pgsym writes all the identity columns it knows, the points
earned (:func:`~pgsym.exercises.grading.score_summary`, the same sum as the report and the Canvas
gradebook) and a one-line feedback naming the parts not right.

>>> from fractions import Fraction
>>> from pgsym.exercises.grading import Result
>>> from pgsym.exercises.lms import Person
>>> report = {"ada@x.org": [Result("ada@x.org", "1", "2", True, "", points=Fraction(2)),
...                         Result("ada@x.org", "2", "(1, 2, 1)", False, "wrong", mistake="ideal-as-finite")]}
>>> print(moodle_grades_csv(report, {"ada@x.org": Person("ada@x.org", "Ada", email="ada@x.org")}, "Week 4"), end="")
Email address,ID number,Username,Full name,Week 4,Feedback
ada@x.org,,,Ada,2,2 of 3 points; not right: 2 (ideal-as-finite)
"""

from __future__ import annotations

from collections.abc import Mapping

from ..csv_cells import csv_text
from ..escaping import one_line
from .grading import Result, score_summary
from .lms import Person
from .points import points_text

__all__ = ["moodle_grades_csv"]


def moodle_grades_csv(report: Mapping[str, list[Result]], people: Mapping[str, Person], title: str) -> str:
    """One row per person with their identity columns, the points earned and the feedback."""
    title = one_line(title) or "pgsym"
    lines: list[list[object]] = [["Email address", "ID number", "Username", "Full name", title, "Feedback"]]
    for key, got, worth in score_summary({k: rs for k, rs in report.items() if k in people}):
        person = people[key]
        missed = [r.label + (f" ({r.mistake})" if r.mistake else "") for r in report[key]
                  if r.counted and not r.correct]
        feedback = f"{points_text(got)} of {points_text(worth)} points" + (
            "; not right: " + ", ".join(missed) if missed else "")
        lines.append([person.email, person.id_number, person.username, person.name, points_text(got),
                      one_line(feedback)[:1000]])
    return csv_text(lines)
