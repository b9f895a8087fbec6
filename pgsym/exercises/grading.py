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

With the mistakes stored in the manifest, a wrong answer that is a known mistake says which:

>>> from pgsym.exercises.mistakes import admissible, default_mistakes
>>> mistakes = {"s1": {"1": admissible(keys["s1"]["1"], default_mistakes(keys["s1"]["1"]))}}
>>> r = grade_rows(keys, [("s1", "1", "(1, -2, 1)")], mistakes)["s1"][0]
>>> r.correct, r.mistake, r.feedback
(False, 'ideal-as-finite', 'an ideal point given as a finite one (last coordinate 1 instead of 0)')
"""

from __future__ import annotations

import io
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, replace
from fractions import Fraction
from pathlib import Path

from ..csv_cells import write_csv
from ..limits import MAX_ANSWER_CHARS, MAX_FILE_BYTES
from .answers import matches, read_as
from .errors import AnswersFileError, UnparsableAnswerError
from .mistakes import recognise
from .model import Answer, Mistake
from .points import points_text
from .reading import read_table, separator_hint
from .roster import NOT_QUESTION_HEADERS, find_id_column, normal_header

MAX_CSV_BYTES = MAX_FILE_BYTES

__all__ = ["AnswersFileError", "Result", "grade_rows", "read_answer_file", "read_answers", "results_csv",
           "score_summary", "summary"]

_SHOWN = 200  # characters of a given answer kept in a report

NOT_ON_SHEET = "no such question on this student's sheet"
NOT_IN_MANIFEST = "student not in the manifest"


@dataclass(frozen=True)
class Result:
    """The grade of one answer: ``reason`` says why it is wrong or unreadable (empty if right).

    ``unreadable`` marks answers that were not graded as written: text that cannot be read as an
    answer (too long, not a number, vector or matrix) and questions answered more than once.
    ``mistake`` is the class of a recognised wrong answer (see :mod:`pgsym.exercises.mistakes`) and
    ``feedback`` says it in words; both are empty otherwise.
    """

    student: str
    label: str
    given: str
    correct: bool
    reason: str
    unreadable: bool = False
    mistake: str = ""
    feedback: str = ""
    points: Fraction = Fraction(1)

    @property
    def score(self) -> Fraction:
        """The points earned: all of the part's points if right, none otherwise (partial credit is per part)."""
        return Fraction(self.points) if self.correct else Fraction(0)

    @property
    def counted(self) -> bool:
        """Whether the answer belongs to the student's sheet (not an extra column or an unknown student)."""
        return self.reason not in (NOT_ON_SHEET, NOT_IN_MANIFEST)


def read_answer_file(path: str | Path, keys: Mapping[str, Mapping[str, Answer]] | None = None,
                     ) -> tuple[list[tuple[str, str, str]], list[str]]:
    """Read an answers CSV (wide or long): the (student id, question label, answer text) triples, and
    the lines that are not valid CSV (one message each; the other lines are still read).

    The file is read like a roster (:func:`pgsym.exercises.reading.read_table`: any separator, UTF-8,
    UTF-16 or Windows-1252; the id column as :func:`pgsym.exercises.roster.find_id_column` finds it).
    With the ``keys`` of the manifest, the questions are checked: a file none of whose question
    columns (or, long, question cells) is a question of the manifest raises :class:`AnswersFileError`
    naming the expected labels (never a class of silent zeros); a column matching no question is
    reported in the messages. Columns platforms add (name, email, section, …) are not questions.

    The whole file is limited to :data:`pgsym.limits.MAX_FILE_BYTES`; single cells are not limited
    here (the grader refuses an overlong answer on its own, so it costs only that answer).
    """
    p = Path(path)
    table = read_table(p, "answers file", AnswersFileError)
    rows, problems = table.rows, table.problems
    messages = [f"line {line} of {p.name!r} is not valid CSV and was skipped: {reason}" for line, reason in problems]
    if not rows:
        raise AnswersFileError(f"the answers file {p.name!r} is empty")
    header = [h.strip() for h in rows[0][1]]
    lower = [normal_header(h) for h in header]
    id_col = find_id_column(header)
    if id_col is None:
        raise AnswersFileError(f"the answers file {p.name!r} needs a header with an 'id' column"
                               f"{separator_hint(header)}; e.g.\n  id,1,2,3a,3b\n  s001,\"(1, -2, 0)\",4/3,B,8")
    known = {label for answers in (keys or {}).values() for label in answers}
    out = []
    if "question" in lower and "answer" in lower:
        q, a = lower.index("question"), lower.index("answer")
        for line, row in rows[1:]:
            if len(row) > max(id_col, q, a):
                out.append((row[id_col].strip(), row[q].strip(), row[a]))
            elif any(cell.strip() for cell in row):
                messages.append(f"line {line} of {p.name!r} has fewer than {max(id_col, q, a) + 1} columns; skipped")
        if keys is not None and out and not any(label in known for _, label, _ in out):
            found = sorted({label for _, label, _ in out})
            raise AnswersFileError(_no_question(p.name, "question cells", found, known))
        return out, messages
    columns = [j for j, label in enumerate(header) if j != id_col and label and lower[j] not in NOT_QUESTION_HEADERS]
    if keys is not None:
        if not any(header[j] in known for j in columns):
            raise AnswersFileError(_no_question(p.name, "columns", [header[j] for j in columns], known))
        messages += [f"column {header[j]!r} of {p.name!r} is no question of the manifest and was not graded"
                     for j in columns if header[j] not in known]
        columns = [j for j in columns if header[j] in known]
    for _, row in rows[1:]:
        if len(row) <= id_col or not row[id_col].strip():
            continue
        for j in columns:
            if j < len(row):
                out.append((row[id_col].strip(), header[j], row[j]))
    return out, messages


def _no_question(name: str, what: str, found: Sequence[str], known: set[str]) -> str:
    def natural(label: str) -> tuple[int, str]:
        digits = "".join(c for c in label if c.isdigit())
        return (int(digits) if digits else 0, label)

    expected = sorted(known, key=natural)
    shown = ", ".join(repr(f[:20]) for f in list(found)[:12]) or "none"
    return (f"the answers file {name!r} answers no question of the manifest: its {what} are {shown}, the "
            f"questions are {', '.join(expected[:40])}{' …' if len(expected) > 40 else ''}; name the columns "
            f"after the questions (e.g. id,{','.join(expected[:3])})")


def read_answers(path: str | Path) -> list[tuple[str, str, str]]:
    """The (student id, question label, answer text) triples of an answers CSV (see :func:`read_answer_file`)."""
    return read_answer_file(path)[0]


def _shown(text: str) -> str:
    return text if len(text) <= _SHOWN else text[:_SHOWN] + "…"


def grade_rows(keys: dict[str, dict[str, Answer]], rows: Iterable[tuple[str, str, str]],
               mistakes: Mapping[str, Mapping[str, Sequence[Mistake]]] | None = None,
               points: Mapping[str, Mapping[str, Fraction]] | None = None) -> dict[str, list[Result]]:
    """Grade (student, label, text) triples against the keys; students without a row get 'no answer'.

    ``mistakes`` (student → label → candidates, as stored in the manifest) names the class of a
    wrong answer that is a known mistake; a right answer is never one. ``points`` (student → label →
    points, as stored in the manifest) says what each part is worth (1 when not given).

    Every answer is graded on its own: an answer that cannot be read (or is longer than
    :data:`pgsym.limits.MAX_ANSWER_CHARS`) is marked ``unreadable`` and the others are still graded;
    a question answered twice with different text is reported and not graded (the same text twice is
    one answer).
    """
    given: dict[str, dict[str, list[str]]] = {}
    unknown: dict[str, list[Result]] = {}
    for student, label, text in rows:
        if student not in keys:
            unknown.setdefault(student, []).append(Result(student, label, _shown(text), False,
                                                          NOT_IN_MANIFEST))
            continue
        given.setdefault(student, {}).setdefault(label, []).append(text)
    report: dict[str, list[Result]] = {}
    for student, answers in keys.items():
        results = []
        typed = given.get(student, {})
        for label, expected in answers.items():
            # the same row twice (a copy pasted again) is one answer; different answers stay a conflict
            texts = list(dict.fromkeys(t.strip() for t in typed.get(label, []) if t.strip()))
            if not texts:
                results.append(Result(student, label, "", False, "no answer"))
            elif len(texts) > 1:
                results.append(Result(student, label, _shown(" | ".join(texts)), False,
                                      f"answered {len(texts)} times; not graded (keep one answer per question)",
                                      unreadable=True))
            elif len(texts[0]) > MAX_ANSWER_CHARS:
                results.append(Result(student, label, _shown(texts[0]), False,
                                      f"cannot read the answer: it is {len(texts[0])} characters long; "
                                      f"at most {MAX_ANSWER_CHARS} are read", unreadable=True))
            else:
                try:
                    value = read_as(expected, texts[0])
                    ok = matches(expected, value)
                    found = None if ok or not mistakes else recognise(
                        expected, mistakes.get(student, {}).get(label, ()), value)
                    results.append(Result(student, label, texts[0], ok, "" if ok else "wrong",
                                          mistake=found.code if found else "",
                                          feedback=found.message if found else ""))
                except UnparsableAnswerError as err:
                    results.append(Result(student, label, texts[0], False, str(err), unreadable=True))
        for label in sorted(set(typed) - set(answers)):
            results.append(Result(student, label, _shown(" | ".join(typed[label])), False,
                                  NOT_ON_SHEET))
        worth = (points or {}).get(student, {})
        report[student] = [replace(r, points=worth[r.label]) if r.label in worth else r for r in results]
    report.update(unknown)
    return report


def summary(report: dict[str, list[Result]]) -> list[tuple[str, int, int]]:
    """(student, right, questions) per student, in manifest order.

    >>> summary({"s1": [Result("s1", "1", "x", True, ""), Result("s1", "2", "", False, "no answer")]})
    [('s1', 1, 2)]
    """
    return [(s, sum(r.correct for r in rs), sum(r.counted for r in rs)) for s, rs in report.items()]


def score_summary(report: Mapping[str, list[Result]]) -> list[tuple[str, Fraction, Fraction]]:
    """(student, points earned, points possible) per student: the one sum every gradebook and report uses.

    >>> score_summary({"s1": [Result("s1", "1", "x", True, "", points=Fraction(2)),
    ...                       Result("s1", "2", "", False, "no answer", points=Fraction(1, 2))]})
    [('s1', Fraction(2, 1), Fraction(5, 2))]
    """
    return [(s, sum((r.score for r in rs if r.counted), Fraction(0)),
             sum((Fraction(r.points) for r in rs if r.counted), Fraction(0))) for s, rs in report.items()]


def results_csv(report: dict[str, list[Result]], problems: Iterable[str] = ()) -> str:
    """Every graded answer as CSV: student, question, answer, correct, reason, mistake (its class) and
    feedback, the part's points and the score earned (then one row per line of the answers file that could
    not be read). Cells a spreadsheet
    would run as a formula are neutralised (:func:`pgsym.csv_cells.safe_cell`).

    >>> print(results_csv({"=1+1": [Result("=1+1", "1", "-2+3", False, "wrong", False, "sign", "the sign is wrong")]}),
    ...       end="")
    student,question,answer,correct,reason,mistake,feedback,points,score
    '=1+1,1,'-2+3,0,wrong,sign,the sign is wrong,1,0
    """
    rows: list[list[object]] = [["student", "question", "answer", "correct", "reason", "mistake", "feedback",
                                 "points", "score"]]
    for results in report.values():
        rows += [[r.student, r.label, _shown(r.given), int(r.correct), r.reason, r.mistake, r.feedback,
                  points_text(r.points), points_text(r.score)] for r in results]
    rows += [["", "", "", 0, message, "", "", "", ""] for message in problems]
    buf = io.StringIO()
    write_csv(buf, rows)
    return buf.getvalue()
