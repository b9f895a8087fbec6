"""The grade report of ``pgsym check --report DIR``: one HTML page, its data as JSON, its plots as SVG.

The page is self-contained: no script, no network (a Content-Security-Policy forbids both), the
plots by Matplotlib inlined as SVG, every name, id and typed answer escaped as text (typed answers in
monospace, so no math engine is needed). It shows the score histogram, the success rate of every
question, the mistakes recognised, the most frequent wrong answers with their mistake class and one
row per student with the points earned (the same sum as the gradebooks: :mod:`pgsym.exercises.points`)
and the feedback on each wrong answer. ``report.json`` holds the same numbers.

>>> from pgsym.exercises.grading import Result
>>> results = {"s1": [Result("s1", "1", "(1, 2, 1)", False, "wrong", mistake="ideal-as-finite", feedback="…"),
...                   Result("s1", "2", "3", True, "")]}
>>> data = report_data(results, {"s1": "Ada"}, {"1": "ideal", "2": "meet"})
>>> data["summary"]["students"], data["histogram"], [q["right"] for q in data["questions"]]
(1, [0, 1, 0], [0, 1])
"""

from __future__ import annotations

import html
import io
import json
import statistics
from collections import Counter
from collections.abc import Iterable, Mapping
from fractions import Fraction
from pathlib import Path
from typing import Any

from ..escaping import html_escape, one_line
from .grading import Result
from .mistakes import MISTAKE_CLASSES
from .points import points_text

__all__ = ["REPORT_FILES", "report_data", "report_html", "write_report"]

#: The files of a report folder.
REPORT_FILES = ("index.html", "report.json", "scores.svg", "questions.svg")

_TOP_WRONG = 15  # most frequent wrong answers listed
_SHOWN = 80  # characters of a typed answer shown in the page


def _percent(part: int, whole: int) -> float:
    return round(100 * part / whole, 1) if whole else 0.0


def _normalised(text: str) -> str:
    return " ".join(text.split())[:_SHOWN]


def report_data(report: Mapping[str, list[Result]], names: Mapping[str, str], topics: Mapping[str, str],
                problems: Iterable[str] = ()) -> dict[str, Any]:
    """The numbers of the report (also written as ``report.json``).

    Students are those of the manifest (``names``); answers of ids not in the manifest are counted
    under ``unknown_students``. ``histogram[k]`` is the number of students with ``k`` right answers.
    """
    students = []
    for sid, results in report.items():
        if sid not in names:
            continue
        graded = [r for r in results if r.counted]
        right = sum(r.correct for r in graded)
        score = sum((r.score for r in graded), Fraction(0))
        worth = sum((Fraction(r.points) for r in graded), Fraction(0))
        students.append({
            "id": sid, "name": names[sid], "right": right, "questions": len(graded),
            "score": points_text(score), "points": points_text(worth),
            "percent": _percent(right, len(graded)),
            "answers": [{"question": r.label, "answer": r.given, "correct": r.correct, "reason": r.reason,
                         "mistake": r.mistake, "feedback": r.feedback, "points": points_text(r.points),
                         "score": points_text(r.score)} for r in results],
        })
    most = max((s["questions"] for s in students), default=0)
    histogram = [0] * (most + 1)
    for s in students:
        histogram[s["right"]] += 1
    questions = []
    for label, topic in topics.items():
        rows = [a for s in students for a in s["answers"] if a["question"] == label]
        answered = sum(a["reason"] != "no answer" for a in rows)
        right = sum(a["correct"] for a in rows)
        questions.append({"question": label, "topic": topic, "students": len(rows), "answered": answered,
                          "right": right, "percent": _percent(right, len(rows))})
    wrong = [(s, a) for s in students for a in s["answers"]
             if not a["correct"] and a["reason"] == "wrong"]
    classes = Counter(a["mistake"] for _, a in wrong if a["mistake"])
    mistakes = [{"mistake": code, "description": MISTAKE_CLASSES.get(code, code), "count": n,
                 "questions": sorted({a["question"] for _, a in wrong if a["mistake"] == code})}
                for code, n in sorted(classes.items(), key=lambda kv: (-kv[1], kv[0]))]
    groups: dict[tuple[str, str], list[dict[str, Any]]] = {}
    for _, a in wrong:
        groups.setdefault((a["question"], _normalised(a["answer"])), []).append(a)
    frequent = []
    for (label, text), answers in sorted(groups.items(), key=lambda kv: (-len(kv[1]), kv[0]))[:_TOP_WRONG]:
        codes = Counter(a["mistake"] for a in answers if a["mistake"])
        code = codes.most_common(1)[0][0] if codes else ""
        frequent.append({"question": label, "answer": text, "count": len(answers), "mistake": code,
                         "feedback": next((a["feedback"] for a in answers if a["mistake"] == code), "")})
    scores = [s["percent"] for s in students]
    unknown = sorted(s for s in report if s not in names)
    return {
        "format": "pgsym-grade-report",
        "version": 1,
        "summary": {"students": len(students), "questions": len(topics), "answers": sum(s["questions"]
                                                                                         for s in students),
                    "right": sum(s["right"] for s in students), "wrong": len(wrong),
                    "recognised": sum(classes.values()),
                    "mean_percent": round(statistics.fmean(scores), 1) if scores else 0.0,
                    "median_percent": round(statistics.median(scores), 1) if scores else 0.0},
        "histogram": histogram,
        "questions": questions,
        "mistakes": mistakes,
        "frequent_wrong": frequent,
        "students": students,
        "unknown_students": unknown,
        "problems": [one_line(p)[:300] for p in problems],
    }


# ---------------------------------------------------------------- plots

def _svg(figure: Any, salt: str) -> str:
    import matplotlib  # noqa: PLC0415 — Matplotlib loads only when a report draws its figures

    buf = io.StringIO()
    # a fixed salt and no date: the same grades give the same bytes
    with matplotlib.rc_context({"svg.hashsalt": salt, "svg.fonttype": "none"}):
        figure.savefig(buf, format="svg", metadata={"Date": None}, bbox_inches="tight")
    return buf.getvalue()


def _figures(data: dict[str, Any]) -> tuple[str, str]:
    import matplotlib  # noqa: PLC0415 — Matplotlib loads only when a report draws its figures
    from matplotlib.figure import Figure  # noqa: PLC0415 — no pyplot: no GUI backend, no global state

    with matplotlib.rc_context({"text.parse_math": False, "font.size": 9}):
        hist = Figure(figsize=(5.2, 2.6))
        ax = hist.add_subplot()
        counts = data["histogram"]
        ax.bar(range(len(counts)), counts, color="#3465a4", width=0.8)
        ax.set_xticks(range(len(counts)))
        ax.set_xlabel("right answers")
        ax.set_ylabel("students")
        ax.set_title("Score histogram")
        ax.yaxis.get_major_locator().set_params(integer=True)
        ax.spines[["top", "right"]].set_visible(False)
        questions = data["questions"]
        bars = Figure(figsize=(5.2, 2.6))
        bx = bars.add_subplot()
        bx.bar(range(len(questions)), [q["percent"] for q in questions], color="#4e9a06", width=0.8)
        bx.set_xticks(range(len(questions)), [one_line(q["question"])[:12] for q in questions],
                      rotation=90 if len(questions) > 12 else 0)
        bx.set_ylim(0, 100)
        bx.set_xlabel("question")
        bx.set_ylabel("% right")
        bx.set_title("Success rate per question")
        bx.spines[["top", "right"]].set_visible(False)
        return _svg(hist, "pgsym-scores"), _svg(bars, "pgsym-questions")


def _inline(svg: str) -> str:
    """An SVG document as an element of the page (without its XML prolog and doctype)."""
    return svg[svg.index("<svg"):]


# ---------------------------------------------------------------- HTML

_CSS = """
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 70em; padding: 0 1em; color: #222; }
h1 { font-size: 1.6em; } h2 { font-size: 1.2em; margin-top: 2em; }
table { border-collapse: collapse; margin: 0.5em 0; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f2f2f2; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
code { font-family: ui-monospace, monospace; background: #f6f6f6; padding: 0 0.2em; }
.plots { display: flex; flex-wrap: wrap; gap: 1em; } .plots svg { max-width: 100%; height: auto; }
td.who { max-width: 18em; overflow-wrap: anywhere; }
.wrong { color: #a40000; } .mistake { color: #5c3566; } details summary { cursor: pointer; }
"""

_CSP = "default-src 'none'; style-src 'unsafe-inline'; img-src data:"


def _e(value: object) -> str:
    return html_escape(str(value))


def _code(text: str) -> str:
    shown = text if len(text) <= _SHOWN else text[:_SHOWN] + "…"
    return f"<code>{_e(shown)}</code>" if shown else ""


#: Characters of a name or id shown in the students' table; the whole text is in the cell's title.
_SHOWN_NAME = 80


def _who(text: str) -> str:
    """A table cell for a name or id: at most :data:`_SHOWN_NAME` characters, wrapping anywhere (a name
    without spaces must not widen the table), the full text in the title (shown on hover)."""
    if len(text) <= _SHOWN_NAME:
        return f'<td class="who">{_e(text)}</td>'
    return f'<td class="who" title="{html.escape(one_line(text), quote=True)}">{_e(text[:_SHOWN_NAME])}…</td>'


def _table(head: list[str], rows: list[str], cls: str) -> str:
    header = "".join(f"<th>{h}</th>" for h in head)
    return f'<table class="{cls}"><thead><tr>{header}</tr></thead><tbody>{"".join(rows)}</tbody></table>'


def report_html(data: dict[str, Any], scores_svg: str, questions_svg: str, title: str = "Grade report") -> str:
    """The page of the report (see the module docstring)."""
    s = data["summary"]
    parts = [f"<h1>{_e(title)}</h1>",
             f'<p id="summary">{s["students"]} students, {s["questions"]} questions; mean score '
             f'{s["mean_percent"]} %, median {s["median_percent"]} %; {s["wrong"]} wrong answers, '
             f'{s["recognised"]} of them a recognised mistake.</p>',
             f'<div class="plots">{_inline(scores_svg)}{_inline(questions_svg)}</div>']
    parts.append("<h2>Mistakes recognised</h2>")
    parts.append(_table(["mistake", "what it means", "count", "questions"],
                        [f'<tr><td class="mistake">{_e(m["mistake"])}</td><td>{_e(m["description"])}</td>'
                         f'<td class="num">{m["count"]}</td><td>{_e(", ".join(m["questions"]))}</td></tr>'
                         for m in data["mistakes"]], "mistakes")
                 if data["mistakes"] else "<p>None.</p>")
    parts.append("<h2>Most frequent wrong answers</h2>")
    parts.append(_table(["question", "answer", "count", "mistake", "feedback"],
                        [f'<tr><td>{_e(w["question"])}</td><td>{_code(w["answer"])}</td>'
                         f'<td class="num">{w["count"]}</td><td class="mistake">{_e(w["mistake"])}</td>'
                         f'<td>{_e(w["feedback"])}</td></tr>' for w in data["frequent_wrong"]], "frequent")
                 if data["frequent_wrong"] else "<p>None.</p>")
    parts.append("<h2>Questions</h2>")
    parts.append(_table(["question", "topic", "students", "answered", "right", "% right"],
                        [f'<tr><td>{_e(q["question"])}</td><td>{_e(q["topic"])}</td>'
                         f'<td class="num">{q["students"]}</td><td class="num">{q["answered"]}</td>'
                         f'<td class="num">{q["right"]}</td><td class="num">{q["percent"]}</td></tr>'
                         for q in data["questions"]], "questions"))
    parts.append("<h2>Students</h2>")
    rows = []
    for st in data["students"]:
        wrong = [a for a in st["answers"] if not a["correct"]]
        items = "".join(
            f'<li>[{_e(a["question"])}] {_code(a["answer"])} <span class="wrong">{_e(a["reason"])}</span>'
            + (f' — <span class="mistake">{_e(a["feedback"])}</span>' if a["feedback"] else "") + "</li>"
            for a in wrong)
        codes = ", ".join(dict.fromkeys(a["mistake"] for a in wrong if a["mistake"]))
        head = f"{len(wrong)} not right" + (f' — <span class="mistake">{_e(codes)}</span>' if codes else "")
        detail = f"<details><summary>{head}</summary><ul>{items}</ul></details>" if wrong else ""
        rows.append(f'<tr>{_who(st["id"])}{_who(st["name"])}<td class="num">{st["right"]}</td>'
                    f'<td class="num">{st["questions"]}</td><td class="num">{st["percent"]}</td>'
                    f'<td class="num">{st["score"]} / {st["points"]}</td><td>{detail}</td></tr>')
    parts.append(_table(["id", "name", "right", "questions", "%", "score", "feedback"], rows, "students"))
    if data["unknown_students"]:
        parts.append("<p>Answers of ids not in the manifest (not graded): "
                     + ", ".join(_e(u) for u in data["unknown_students"][:200]) + "</p>")
    if data["problems"]:
        parts.append("<h2>Lines of the answers file skipped</h2><ul>"
                     + "".join(f"<li>{_e(p)}</li>" for p in data["problems"][:200]) + "</ul>")
    body = "\n".join(parts)
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            f'<meta http-equiv="Content-Security-Policy" content="{_CSP}">'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">'
            f'<link rel="icon" href="data:,"><title>{_e(title)}</title><style>{_CSS}</style></head>'
            f"<body>\n{body}\n</body></html>\n")


def write_report(folder: Path, data: dict[str, Any], title: str = "Grade report") -> None:
    """Write :data:`REPORT_FILES` into ``folder`` (an existing, empty folder; see
    :func:`pgsym.atomic.write_new_folder`)."""
    scores, questions = _figures(data)
    (folder / "scores.svg").write_text(scores, encoding="utf-8")
    (folder / "questions.svg").write_text(questions, encoding="utf-8")
    (folder / "report.json").write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    (folder / "index.html").write_text(report_html(data, scores, questions, title), encoding="utf-8")
