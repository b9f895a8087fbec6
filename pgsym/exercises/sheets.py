"""Building the sheets of a class: topics × students → :class:`~pgsym.exercises.model.Sheet` objects,
and the JSON manifest (the roster reader lives in :mod:`pgsym.exercises.roster`; ``read_roster`` is
still importable from here).

>>> sheets = build_sheets(["join", "meet:2"], [("s1", "Ada"), ("s2", "Alan")], master_seed=7)
>>> [len(s.exercises) for s in sheets], sheets[0].exercises[1].level
([2, 2], 2)
>>> sheets[0].form_id != sheets[1].form_id
True
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..errors import PgsymError
from ..escaping import one_line
from ..limits import MAX_NAME_CHARS
from .errors import ManifestError, TemplateError, UnknownTopicError
from .mistakes import MAX_MISTAKES
from .model import Answer, Mistake, Sheet, variant_id
from .points import MAX_POINTS, apply_points
from .reading import load_json
from .registry import get_template
from .roster import read_roster
from .seeds import form_id, slot_keys, variant_seed

__all__ = ["ManifestData", "anonymous_students", "build_sheet", "build_sheets", "load_manifest",
           "load_manifest_data", "manifest", "manifest_json", "parse_topics", "read_roster"]

MANIFEST_VERSION = 1

#: Characters of a mistake's feedback kept from a manifest.
MAX_MESSAGE_CHARS = 300

#: Characters of a statement, prompt, title or solution step kept from a manifest.
MAX_TEXT_CHARS = 20_000


def parse_topics(spec: str | Sequence[str], default_level: int = 1) -> list[tuple[str, int]]:
    """Read ``"join,meet:2"`` (or a list of such items) into (topic, level) pairs; unknown topics raise.

    >>> parse_topics("join, meet:2")
    [('join', 1), ('meet', 2)]
    """
    items = spec.split(",") if isinstance(spec, str) else list(spec)
    out = []
    for item in (i.strip() for i in items):
        if not item:
            continue
        name, _, level = item.partition(":")
        template = get_template(name.strip())
        try:
            lvl = int(level) if level else default_level
        except ValueError:
            raise TemplateError(f"level {level!r} of topic {name!r} is not an integer") from None
        if lvl not in template.levels:
            raise TemplateError(f"topic {name!r} has levels {list(template.levels)}, not {lvl}")
        out.append((template.name, lvl))
    if not out:
        raise TemplateError("no topics given; e.g. --topics join,meet:2")
    return out


def build_sheet(topics: Sequence[tuple[str, int]] | Sequence[str], student_id: str, student_name: str,
                master_seed: int, points: Mapping[str, Sequence[Fraction]] | None = None) -> Sheet:
    """The sheet of one student; ``points`` as :func:`pgsym.exercises.points.parse_points` reads them.

    >>> build_sheet(["join"], "s1", "Ada", 1).exercises[0].topic
    'join'
    """
    pairs = [parse_topics([t])[0] if isinstance(t, str) else t for t in topics]
    keys = slot_keys([t for t, _ in pairs])
    exercises = []
    for slot, ((topic, level), key) in enumerate(zip(pairs, keys, strict=True), start=1):
        seed = variant_seed(master_seed, student_id, f"{key}@{level}")
        exercises.append(get_template(topic).generate(seed, level, slot))
    sheet = Sheet(student_id, student_name, form_id(master_seed, student_id, [f"{k}@{lv}" for k, (_, lv) in
                                                                               zip(keys, pairs, strict=True)]),
                  master_seed, tuple(exercises))
    return apply_points([sheet], points)[0]


def build_sheets(topics: Sequence[tuple[str, int]] | Sequence[str], students: Iterable[tuple[str, str]],
                 master_seed: int, progress: Callable[[int], None] | None = None,
                 points: Mapping[str, Sequence[Fraction]] | None = None) -> list[Sheet]:
    """The sheets of every student (``progress(1)`` is called after each one).

    >>> [s.student_id for s in build_sheets(["meet"], [("a", ""), ("b", "")], 3)]
    ['a', 'b']
    """
    sheets = []
    for sid, name in students:
        try:
            sheets.append(build_sheet(topics, sid, name, master_seed, points))
        except (UnknownTopicError, OSError):
            raise
        except PgsymError as err:  # say whose sheet failed (a template may fail for one variant only)
            raise TemplateError(f"the sheet of student {one_line(sid)[:120]}: {err}") from None
        except Exception as err:  # an instructor template's own bug
            raise TemplateError(f"the sheet of student {one_line(sid)[:120]}: a template failed with "
                                f"{type(err).__name__}: {str(err)[:300]}") from None
        if progress is not None:
            progress(1)
    return sheets


def anonymous_students(count: int) -> list[tuple[str, str]]:
    """Ids ``form-001`` … for sheets without a roster.

    >>> anonymous_students(2)
    [('form-001', ''), ('form-002', '')]
    """
    width = max(3, len(str(count)))
    return [(f"form-{i:0{width}d}", "") for i in range(1, count + 1)]


def manifest(sheets: Sequence[Sheet], topics: Sequence[tuple[str, int]]) -> dict[str, Any]:
    """The JSON manifest: parameters and answers of every variant of every student."""
    return {
        "format": "pgsym-exercises",
        "version": MANIFEST_VERSION,
        "master_seed": sheets[0].master_seed if sheets else None,
        "topics": [{"topic": t, "level": lv} for t, lv in topics],
        "students": [
            {"id": s.student_id, "name": s.student_name, "form_id": s.form_id,
             "exercises": [e.to_json() for e in s.exercises]}
            for s in sheets
        ],
    }


def manifest_json(sheets: Sequence[Sheet], topics: Sequence[tuple[str, int]]) -> str:
    """The manifest as deterministic JSON text."""
    return json.dumps(manifest(sheets, topics), indent=1, sort_keys=True, ensure_ascii=False) + "\n"


@dataclass
class ManifestData:
    """What ``pgsym check`` needs from a manifest: the keys, the recognised mistakes (empty for a
    manifest written before they were stored), the students' names and each question's topic."""

    keys: dict[str, dict[str, Answer]] = field(default_factory=dict)
    mistakes: dict[str, dict[str, tuple[Mistake, ...]]] = field(default_factory=dict)
    names: dict[str, str] = field(default_factory=dict)
    topics: dict[str, str] = field(default_factory=dict)
    #: student → label → points of the part (1 for a manifest written before points were stored)
    points: dict[str, dict[str, Fraction]] = field(default_factory=dict)
    #: variant id (:func:`~pgsym.exercises.model.variant_id`) → (student, the labels of its parts)
    variants: dict[str, tuple[str, tuple[str, ...]]] = field(default_factory=dict)
    #: variant id → what a feedback document shows: title, statement, prompts by label, solution steps
    texts: dict[str, VariantText] = field(default_factory=dict)


@dataclass(frozen=True)
class VariantText:
    """The text of one variant as stored in the manifest (empty for a manifest of an older version)."""

    title: str = ""
    statement: str = ""
    prompts: dict[str, str] = field(default_factory=dict)
    solution: tuple[str, ...] = ()


def _read_mistake(data: Any, lines: dict[str, str]) -> Mistake:
    m = Mistake.from_json(data)
    # the message is shown to instructors in every output: one line, bounded (cleaned once per distinct text)
    for text in (m.code, m.message):
        if text not in lines:
            lines[text] = one_line(text)[:MAX_MESSAGE_CHARS]
    return Mistake(lines[m.code][:40], lines[m.message], m.answer)


def load_manifest_data(path: str | Path) -> ManifestData:
    """Read a manifest with everything ``pgsym check`` reports (see :class:`ManifestData`)."""
    p = Path(path)
    data = load_json(p, "manifest", ManifestError)
    if not isinstance(data, dict) or data.get("format") != "pgsym-exercises":
        raise ManifestError(f"{str(p)!r} is not a pgsym exercise manifest (written by 'pgsym sheet')")
    out = ManifestData()
    lines: dict[str, str] = {}
    try:
        for student in data["students"]:
            sid = str(student["id"])
            out.keys[sid] = {str(part["label"]): Answer.from_json(part)
                             for ex in student["exercises"] for part in ex["parts"]}
            out.mistakes[sid] = {str(part["label"]): tuple(_read_mistake(m, lines)
                                                           for m in part.get("mistakes", ())[:MAX_MISTAKES])
                                 for ex in student["exercises"] for part in ex["parts"]}
            out.names[sid] = one_line(str(student.get("name", "")))[:MAX_NAME_CHARS]
            out.points[sid] = {str(part["label"]): _points(part.get("points", "1"))
                               for ex in student["exercises"] for part in ex["parts"]}
            form = str(student.get("form_id", ""))
            for ex in student["exercises"]:
                labels = tuple(str(part["label"]) for part in ex["parts"])
                for label in labels:
                    out.topics.setdefault(label, one_line(str(ex.get("topic", ""))))
                vid = variant_id(form, int(ex["slot"]))
                out.variants[vid] = (sid, labels)
                out.texts[vid] = VariantText(
                    str(ex.get("title", ""))[:MAX_TEXT_CHARS], str(ex.get("statement", ""))[:MAX_TEXT_CHARS],
                    {str(p["label"]): str(p.get("prompt", ""))[:MAX_TEXT_CHARS] for p in ex["parts"]},
                    tuple(str(step)[:MAX_TEXT_CHARS] for step in ex.get("solution", ())[:100]))
    except (KeyError, TypeError, ValueError, ArithmeticError, AttributeError, IndexError) as err:
        raise ManifestError(f"the manifest {str(p)!r} is damaged: {type(err).__name__}: {err}") from None
    return out


def _points(value: Any) -> Fraction:
    points = Fraction(str(value))
    if not 0 < points <= MAX_POINTS:
        raise ValueError(f"points {points} out of range (0, {MAX_POINTS}]")
    return points


def load_manifest(path: str | Path) -> dict[str, dict[str, Answer]]:
    """Read a manifest: student id → {question label → expected answer}."""
    return load_manifest_data(path).keys
