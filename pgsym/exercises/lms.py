"""Answers typed in Canvas or Moodle, brought back to ``pgsym check``: the quiz reports both platforms export.

**Canvas** (Classic Quizzes → Quiz Statistics → "Student Analysis" → download CSV). The columns this
reader relies on: ``name``, ``id`` (Canvas user id), ``sis_id`` (SIS User ID), then for every question
a column headed ``<question id>: <question text>`` with the student's answer, followed by a column of
the points earned; at the end ``n correct``, ``n incorrect``, ``score``. An item of a question group
that a student was not shown has an empty answer and an empty score. The variant id
(:func:`~pgsym.exercises.model.variant_id`) in the question text names the variant the student saw.

**Moodle** (Quiz → Results → "Responses", with "Question text" ticked, → download CSV). The columns:
the identity fields (``Last name`` or ``Surname``, ``First name``, ``Email address``, ``ID number``,
``Username``, as the site shows them), ``State``, then for every slot ``Question N`` (for a STACK
question its question note, which carries the variant id) and ``Response N`` (STACK's summary
``Seed: 1; ans1: [1,-2,0] [score]; prt1: # = 1 | prt1-1-T``), optionally ``Right answer N``.

The test data in ``tests/data/lms/`` cite the platforms' documentation of both files. Everything is
read within the limits (file size, columns, one answer's length), every failure is a named
:class:`~pgsym.exercises.errors.LmsReportError`, and a report none of whose questions carries a
variant id of the manifest is refused instead of being graded as zeros.

>>> detect_platform(["name", "id", "sis_id", "section", "123: Q", "1.0", "n correct", "n incorrect", "score"])
'canvas'
>>> detect_platform(["Surname", "First name", "Email address", "State", "Question 1", "Response 1"])
'moodle'
>>> detect_platform(["id", "1", "2"]) is None
True
"""

from __future__ import annotations

import html
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

from ..escaping import one_line
from .errors import LmsReportError
from .grading import Result, grade_rows
from .model import VARIANT_PATTERN, Answer, Mistake
from .reading import csv_rows, read_user_text

__all__ = ["LmsAnswers", "LmsGrading", "Person", "detect_platform", "grade_lms", "read_lms_report",
           "split_parts", "stack_inputs"]

#: Columns of a report read at most (a Canvas report has two per question, Moodle three per slot).
MAX_COLUMNS = 4000

_CANVAS_QUESTION = re.compile(r"^\s*(\d+):\s*(.*)$", re.S)
_MOODLE_QUESTION = re.compile(r"^Question (\d+)$")
_MOODLE_RESPONSE = re.compile(r"^Response (\d+)$")
_STACK_INPUT = re.compile(r"(?:^|; )ans(\d+): (.*?) \[(\w+)\](?=; |$)")


@dataclass(frozen=True)
class Person:
    """Who answered, as the platform names them: ``key`` is unique within the report."""

    key: str
    name: str
    canvas_id: str = ""
    sis_id: str = ""
    email: str = ""
    id_number: str = ""
    username: str = ""


@dataclass
class LmsAnswers:
    """What a report holds: the platform, the people, (person, variant id, label, text) rows and the
    problems met while reading (one line each)."""

    platform: str
    people: dict[str, Person] = field(default_factory=dict)
    rows: list[tuple[str, str, str, str]] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)


def detect_platform(header: Sequence[str]) -> str | None:
    """``"canvas"`` for a Student Analysis report, ``"moodle"`` for a Responses report, else None."""
    cells = [h.strip() for h in header]
    lower = [h.lower() for h in cells]
    if {"name", "id", "sis_id", "n correct", "n incorrect", "score"} <= set(lower):
        return "canvas"
    if any(_MOODLE_RESPONSE.match(h) for h in cells) and "state" in lower:
        return "moodle"
    return None


def _plain(text: str) -> str:
    """The text of an answer that may be HTML (Canvas's essay answers): tags dropped, line breaks kept."""
    text = re.sub(r"(?i)<br\s*/?>|</p\s*>|</div\s*>|</li\s*>", "\n", text)
    text = re.sub(r"<[^>]{0,2000}>", "", text)
    return html.unescape(text).replace("\xa0", " ")


def split_parts(text: str, labels: Sequence[str]) -> dict[str, str]:
    """One answer per part from a text answer: lines labelled ``4a: …`` (or ``[4a] …``) go to their
    part, unlabelled lines to the next part without an answer. A single part takes the whole text.

    >>> split_parts("<p>4b: 8</p><p>[4a] D</p>", ["4a", "4b"])
    {'4a': 'D', '4b': '8'}
    >>> split_parts("2a:C\\n2b = 6", ["2a", "2b"])
    {'2a': 'C', '2b': '6'}
    >>> split_parts("(1, -2, 0)", ["1"])
    {'1': '(1, -2, 0)'}
    """
    plain = _plain(text).strip()
    if len(labels) == 1:
        return {labels[0]: plain} if plain else {}
    out: dict[str, str] = {}
    loose: list[str] = []
    for line in (ln.strip() for ln in plain.splitlines()):
        if not line:
            continue
        match = re.match(r"^\[?\(?([0-9]{1,3}[a-z]?)\)?\]?(?:\s*[:=]\s*|\s+)(.+)$", line)
        if match and match.group(1) in labels and match.group(1) not in out:
            out[match.group(1)] = match.group(2).strip()
        else:
            loose.append(line)
    for label in labels:
        if label not in out and loose:
            out[label] = loose.pop(0)
    if loose:  # more lines than parts: keep them, so the grader reports the answer as unreadable
        last = labels[-1]
        out[last] = " | ".join([out.get(last, ""), *loose]).strip(" |")
    return {label: out[label] for label in labels if label in out}


def _maxima_matrix(text: str) -> str:
    """``matrix([1,0],[0,1])`` (how STACK writes a matrix) as ``[[1,0],[0,1]]``; other text unchanged."""
    text = text.strip()
    if text.startswith("matrix(") and text.endswith(")"):
        return "[" + text[len("matrix("):-1] + "]"
    return text


def stack_inputs(summary: str) -> dict[int, tuple[str, str]]:
    """The inputs of a STACK response summary: input number → (value, status).

    >>> stack_inputs("Seed: 7; ans1: [1,-2,0] [score]; ans2: matrix([1,0],[0,1]) [valid]; prt1: # = 1 | prt1-1-T")
    {1: ('[1,-2,0]', 'score'), 2: ('[[1,0],[0,1]]', 'valid')}
    """
    return {int(m.group(1)): (_maxima_matrix(m.group(2)), m.group(3)) for m in _STACK_INPUT.finditer(summary)}


def _column(lower: list[str], *names: str) -> int | None:
    return next((lower.index(n) for n in names if n in lower), None)


def _cell(row: list[str], index: int | None) -> str:
    return row[index].strip() if index is not None and index < len(row) else ""


def _variant(text: str) -> str | None:
    found = VARIANT_PATTERN.search(text)
    return found.group(0) if found else None


def _read_canvas(rows: list[tuple[int, list[str]]], labels_of: Mapping[str, tuple[str, ...]],
                 out: LmsAnswers, name: str) -> None:
    header = [h.strip() for h in rows[0][1]]
    lower = [h.lower() for h in header]
    name_col, id_col, sis_col = _column(lower, "name"), _column(lower, "id"), _column(lower, "sis_id")
    questions: list[tuple[int, str]] = []
    strangers = []
    for j, h in enumerate(header):
        match = _CANVAS_QUESTION.match(h)
        if not match:
            continue
        vid = _variant(match.group(2))
        if vid is None or vid not in labels_of:
            strangers.append(one_line(h)[:80])
        else:
            questions.append((j, vid))
    _check_questions(questions, strangers, name, "Canvas", "the question text")
    for line, row in rows[1:]:
        if not any(c.strip() for c in row):
            continue
        person = Person(_person_key(_cell(row, sis_col), _cell(row, id_col), _cell(row, name_col), line),
                        _cell(row, name_col), canvas_id=_cell(row, id_col), sis_id=_cell(row, sis_col))
        _add_person(out, person, line, name)
        for j, vid in questions:
            answer = row[j] if j < len(row) else ""
            score = row[j + 1].strip() if j + 1 < len(row) else ""
            if not answer.strip() and not score:
                continue  # an item of a question group this student was not shown
            for label, text in split_parts(answer, labels_of[vid]).items():
                out.rows.append((person.key, vid, label, text))
            if not answer.strip():
                out.rows.append((person.key, vid, labels_of[vid][0], ""))


def _read_moodle(rows: list[tuple[int, list[str]]], labels_of: Mapping[str, tuple[str, ...]],
                 out: LmsAnswers, name: str) -> None:
    header = [h.strip() for h in rows[0][1]]
    lower = [h.lower() for h in header]
    cols = {k: _column(lower, *names) for k, names in {
        "last": ("last name", "surname"), "first": ("first name",), "email": ("email address",),
        "idnumber": ("id number",), "username": ("username",), "state": ("state",)}.items()}
    question_cols = {int(m.group(1)): j for j, h in enumerate(header) if (m := _MOODLE_QUESTION.match(h))}
    response_cols = {int(m.group(1)): j for j, h in enumerate(header) if (m := _MOODLE_RESPONSE.match(h))}
    if not question_cols:
        raise LmsReportError(f"the Moodle report {name!r} has no 'Question N' columns; download the Responses "
                             "report with 'Question text' ticked, so each slot names the variant the student saw")
    slots = sorted(set(question_cols) & set(response_cols))
    seen_variants: set[str] = set()
    strangers: set[str] = set()
    kept: dict[str, tuple[int, list[str]]] = {}
    for line, row in rows[1:]:
        if not any(c.strip() for c in row):
            continue
        state = _cell(row, cols["state"])
        full = " ".join(x for x in (_cell(row, cols["first"]), _cell(row, cols["last"])) if x)
        person = Person(_person_key(_cell(row, cols["idnumber"]), _cell(row, cols["email"]),
                                    _cell(row, cols["username"]) or full, line), full,
                        email=_cell(row, cols["email"]), id_number=_cell(row, cols["idnumber"]),
                        username=_cell(row, cols["username"]))
        if state and state.lower() not in ("finished", "beendet", "terminé"):
            out.problems.append(f"line {line} of {name!r}: an attempt in state {one_line(state)[:30]!r} "
                                "was not graded")
            continue
        if person.key in kept:
            out.problems.append(f"line {line} of {name!r}: another attempt of {one_line(person.key)[:60]!r}; "
                                "the last one listed is graded")
        kept[person.key] = (line, row)
        out.people[person.key] = person
    for key, (_line, row) in kept.items():
        for slot in slots:
            vid = _variant(_cell(row, question_cols[slot]))
            if vid is None or vid not in labels_of:
                strangers.add(one_line(_cell(row, question_cols[slot]))[:80] or f"Question {slot} (empty)")
                continue
            seen_variants.add(vid)
            labels = labels_of[vid]
            inputs = stack_inputs(_cell(row, response_cols[slot]))
            if not inputs:
                out.rows.append((key, vid, labels[0], ""))
            for number, (value, _status) in sorted(inputs.items()):
                if 1 <= number <= len(labels):
                    out.rows.append((key, vid, labels[number - 1], value))
    _check_questions([(0, v) for v in seen_variants], sorted(strangers), name, "Moodle", "the question note")


def _person_key(*candidates: str | int) -> str:
    for c in candidates[:-1]:
        if str(c).strip():
            return str(c).strip()[:200]
    return f"line {candidates[-1]}"


def _add_person(out: LmsAnswers, person: Person, line: int, name: str) -> None:
    if person.key in out.people:
        out.problems.append(f"line {line} of {name!r}: {one_line(person.key)[:60]!r} appears again; "
                            "both rows are graded together (a question answered twice is reported)")
    out.people[person.key] = person


def _check_questions(found: Sequence[tuple[int, str]], strangers: Sequence[str], name: str, platform: str,
                     where: str) -> None:
    if not found:
        shown = "; ".join(strangers[:3]) or "none"
        raise LmsReportError(f"no question of the {platform} report {name!r} carries a variant id of this manifest "
                             f"(such as F-0123456789#1 in {where}); questions found: {shown}. Export the quiz with "
                             "'pgsym sheet --format qti,stack' from the same manifest")


def read_lms_report(path: str | Path, labels_of: Mapping[str, tuple[str, ...]]) -> LmsAnswers | None:
    """Read a Canvas or Moodle quiz report; None if the file is neither (a pgsym answers CSV).

    ``labels_of`` maps every variant id of the manifest to the labels of its parts
    (:attr:`pgsym.exercises.sheets.ManifestData.variants`).
    """
    p = Path(path)
    rows, problems = csv_rows(read_user_text(p, "answers file", LmsReportError))
    if not rows:
        return None
    header = rows[0][1]
    platform = detect_platform(header)
    if platform is None:
        return None
    if len(header) > MAX_COLUMNS:
        raise LmsReportError(f"the {platform} report {p.name!r} has {len(header)} columns; at most {MAX_COLUMNS} "
                             "are read")
    out = LmsAnswers(platform, problems=[f"line {line} of {p.name!r} is not valid CSV and was skipped: {reason}"
                                         for line, reason in problems])
    (_read_canvas if platform == "canvas" else _read_moodle)(rows, labels_of, out, p.name)
    return out


@dataclass
class LmsGrading:
    """The grades of a report: results per person, the people, which variant each answered part
    belongs to (person → label → variant id) and the problems (one line each)."""

    report: dict[str, list[Result]]
    people: dict[str, Person]
    variants: dict[str, dict[str, str]]
    problems: list[str]


def grade_lms(answers: LmsAnswers, keys: Mapping[str, Mapping[str, Answer]],
              variants: Mapping[str, tuple[str, tuple[str, ...]]],
              mistakes: Mapping[str, Mapping[str, Sequence[Mistake]]] | None = None,
              points: Mapping[str, Mapping[str, Fraction]] | None = None) -> LmsGrading:
    """Grade every answer against the key of the variant the person saw (``variants``: variant id →
    (owner in the manifest, labels)), with the owner's mistakes and points."""
    person_keys: dict[str, dict[str, Answer]] = {k: {} for k in answers.people}
    person_mistakes: dict[str, dict[str, Sequence[Mistake]]] = {k: {} for k in answers.people}
    person_points: dict[str, dict[str, Fraction]] = {k: {} for k in answers.people}
    seen: dict[str, dict[str, str]] = {k: {} for k in answers.people}
    problems = list(answers.problems)
    rows = []
    for person, vid, label, text in answers.rows:
        owner, labels = variants[vid]
        for lab in labels:
            earlier = seen[person].get(lab)
            if earlier not in (None, vid):
                problems.append(f"{one_line(person)[:60]!r} saw two variants of question {lab} ({earlier}, {vid}); "
                                "only the first is graded")
                break
            seen[person][lab] = vid
            person_keys[person][lab] = keys[owner][lab]
            person_mistakes[person][lab] = (mistakes or {}).get(owner, {}).get(lab, ())
            person_points[person][lab] = (points or {}).get(owner, {}).get(lab, Fraction(1))
        else:
            rows.append((person, label, text))
    report = grade_rows(person_keys, rows, person_mistakes, person_points)
    return LmsGrading(report, dict(answers.people), seen, problems)
