"""Grading typed answers against a manifest.

The answers CSV is either *wide* (a header ``id`` followed by question labels ``1, 2, 3a, 3b, …``; one
row per student) or *long* (columns ``id, question, answer``; one row per answer). Every answer is
read by :mod:`pgsym.exercises.answers` (no code is evaluated); answers that cannot be read count as
wrong and are reported with the reason.

>>> from fractions import Fraction
>>> from pgsym.exercises.model import Answer
>>> keys = {"s1": {"1": Answer.projective([1, -2, 0]), "2": Answer.scalar(Fraction(4, 3))}}
>>> report = grade_rows(keys, [("s1", "1", "(-2, 4, 0)"), ("s1", "2", "1.5")])
>>> [(r.label, r.correct) for r in report["s1"]]
[('1', True), ('2', False)]
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from ..errors import AnswersFileError, UnparsableAnswerError
from .answers import grade
from .model import Answer

MAX_CSV_BYTES = 20_000_000

__all__ = ["AnswersFileError", "Result", "grade_rows", "read_answers", "results_csv", "summary"]



@dataclass(frozen=True)
class Result:
    """The grade of one answer: ``reason`` says why it is wrong or unreadable (empty if right)."""

    student: str
    label: str
    given: str
    correct: bool
    reason: str


def read_answers(path: str | Path) -> list[tuple[str, str, str]]:
    """Read an answers CSV (wide or long) into (student id, question label, answer text) triples."""
    p = Path(path)
    try:
        if p.stat().st_size > MAX_CSV_BYTES:
            raise AnswersFileError(f"the answers file {p.name!r} is larger than {MAX_CSV_BYTES // 1_000_000} MB")
        text = p.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        raise AnswersFileError(f"the answers file {str(p)!r} does not exist") from None
    except (OSError, UnicodeDecodeError) as err:
        raise AnswersFileError(f"cannot read the answers file {str(p)!r}: {err}") from None
    try:
        rows = list(csv.reader(io.StringIO(text)))
    except csv.Error as err:
        raise AnswersFileError(f"the answers file {p.name!r} is not valid CSV: {err}") from None
    if not rows:
        raise AnswersFileError(f"the answers file {p.name!r} is empty")
    header = [h.strip() for h in rows[0]]
    lower = [h.lower() for h in header]
    id_col = next((lower.index(n) for n in ("id", "student_id", "student") if n in lower), None)
    if id_col is None:
        raise AnswersFileError(f"the answers file {p.name!r} needs a header with an 'id' column; e.g.\n"
                               "  id,1,2,3a,3b\n  s001,\"(1, -2, 0)\",4/3,B,8")
    out = []
    if "question" in lower and "answer" in lower:
        q, a = lower.index("question"), lower.index("answer")
        for row in rows[1:]:
            if len(row) > max(id_col, q, a):
                out.append((row[id_col].strip(), row[q].strip(), row[a]))
        return out
    for row in rows[1:]:
        if len(row) <= id_col or not row[id_col].strip():
            continue
        for j, label in enumerate(header):
            if j != id_col and label and j < len(row):
                out.append((row[id_col].strip(), label, row[j]))
    return out


def grade_rows(keys: dict[str, dict[str, Answer]], rows: Iterable[tuple[str, str, str]]) -> dict[str, list[Result]]:
    """Grade (student, label, text) triples against the keys; students without a row get 'no answer'."""
    given: dict[str, dict[str, str]] = {}
    unknown: dict[str, list[Result]] = {}
    for student, label, text in rows:
        if student not in keys:
            unknown.setdefault(student, []).append(Result(student, label, text, False, "student not in the manifest"))
            continue
        given.setdefault(student, {})[label] = text
    report: dict[str, list[Result]] = {}
    for student, answers in keys.items():
        results = []
        typed = given.get(student, {})
        for label, expected in answers.items():
            text = typed.get(label, "")
            if not text.strip():
                results.append(Result(student, label, text, False, "no answer"))
                continue
            try:
                ok = grade(expected, text)
                results.append(Result(student, label, text, ok, "" if ok else "wrong"))
            except UnparsableAnswerError as err:
                results.append(Result(student, label, text, False, str(err)))
        for label in sorted(set(typed) - set(answers)):
            results.append(Result(student, label, typed[label], False, "no such question on this student's sheet"))
        report[student] = results
    report.update(unknown)
    return report


def summary(report: dict[str, list[Result]]) -> list[tuple[str, int, int]]:
    """(student, right, questions) per student, in manifest order.

    >>> summary({"s1": [Result("s1", "1", "x", True, ""), Result("s1", "2", "", False, "no answer")]})
    [('s1', 1, 2)]
    """
    return [(s, sum(r.correct for r in rs), sum(r.reason != "no such question on this student's sheet"
                                                 and r.reason != "student not in the manifest" for r in rs))
            for s, rs in report.items()]


def results_csv(report: dict[str, list[Result]]) -> str:
    """Every graded answer as CSV: student, question, answer, correct, reason."""
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(["student", "question", "answer", "correct", "reason"])
    for results in report.values():
        for r in results:
            writer.writerow([r.student, r.label, r.given[:200], int(r.correct), r.reason])
    return buf.getvalue()
