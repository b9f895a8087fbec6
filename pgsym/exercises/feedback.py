"""Per-student feedback pages of ``pgsym check --feedback DIR``: one HTML page per student.

Each page shows, for every exercise the student answered (the variant they saw, also when a Canvas or
Moodle quiz drew it at random), the statement, each part with the answer as typed, the verdict and the
points, the explanation of a recognised mistake, the expected answer and the worked solution; in the
spirit of the individual result pages of R/exams' ``nops_eval``. The pages are self-contained: math
as MathML made at generation time, no script (a Content-Security-Policy forbids it), every typed answer,
name and id escaped as text (:func:`~pgsym.escaping.html_escape`). ``index.html`` lists the pages.
They are written into a new folder, complete or not at all (:func:`pgsym.atomic.write_new_folder`).

>>> from fractions import Fraction
>>> from pgsym.exercises.grading import Result
>>> from pgsym.exercises.lms import Person
>>> from pgsym.exercises.roundtrip import Graded
>>> from pgsym.exercises.sheets import ManifestData, VariantText
>>> from pgsym.exercises.model import Answer
>>> data = ManifestData(keys={"s1": {"1": Answer.projective([1, -2, 0])}}, variants={"F-0123456789#1": ("s1", ("1",))},
...                     texts={"F-0123456789#1": VariantText("Meet", "Let $l = (1, 2, 3)$.", {"1": "Give x."},
...                                                          ("$x = l \\\\times m$.",))})
>>> graded = Graded({"<b>": [Result("<b>", "1", "(1, 2, 1)", False, "wrong", mistake="ideal-as-finite",
...                                 feedback="an ideal point given as a finite one")]},
...                 {"<b>": Person("<b>", "Ada <i>")}, {"<b>": {"1": "F-0123456789#1"}}, [], "canvas")
>>> page = feedback_page("<b>", graded, data, "Week 4")
>>> "Ada &lt;i&gt;" in page and "<code>(1, 2, 1)</code>" in page and "(1, -2, 0)" in page and "<math" in page
True
"""

from __future__ import annotations

import html
from pathlib import Path

from ..escaping import html_escape, one_line, to_html
from .grading import Result, score_summary
from .html_math import mathml
from .model import Sheet
from .points import points_text
from .roundtrip import Graded
from .sheets import ManifestData, VariantText

__all__ = ["feedback_name", "feedback_page", "write_feedback"]

_CSP = "default-src 'none'; style-src 'unsafe-inline'"
_STYLE = """body{font-family:system-ui,sans-serif;max-width:48em;margin:2em auto;padding:0 1em;line-height:1.5}
.right{color:#2e7d32}.wrong{color:#a40000}.mistake{color:#5c3566}code{background:#f6f6f6;padding:0 .2em}
.part{margin:.6em 0;padding:.3em .6em;border-left:3px solid #ccc}details{background:#f4f6f8;padding:.4em .8em}"""


def _math_html(text: str) -> str:
    return to_html(text, mathml)


def feedback_name(key: str) -> str:
    """The file name of a person's page: file-name-safe, distinct for distinct keys.

    >>> feedback_name("s-01"), feedback_name("ada@x.org")
    ('feedback-s-01.html', 'feedback-ada_x_org-56e3ad.html')
    """
    return "feedback-" + Sheet(key, "", "", 0, ()).file_stem.removeprefix("sheet-") + ".html"


def _verdict(r: Result) -> str:
    if r.correct:
        return f'<span class="right">right</span> ({points_text(r.score)} of {points_text(r.points)} points)'
    text = f'<span class="wrong">{html_escape(r.reason or "wrong")}</span> (0 of {points_text(r.points)} points)'
    if r.feedback:
        text += f'<br><span class="mistake">Mistake: {html_escape(r.feedback)}</span>'
    return text


def feedback_page(key: str, graded: Graded, data: ManifestData, title: str = "Feedback") -> str:
    """The page of the person ``key`` (see the module docstring)."""
    person = graded.people.get(key)
    name = (person.name if person else "") or key
    results = graded.report.get(key, [])
    got, worth = next(((g, w) for k, g, w in score_summary({key: results})), (0, 0))
    variants = graded.variants.get(key, {})
    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           f'<meta http-equiv="Content-Security-Policy" content="{_CSP}">',
           f"<title>{html.escape(one_line(title))}: {html.escape(one_line(name))}</title>",
           f"<style>{_STYLE}</style></head><body>",
           f"<h1>{html_escape(title)}: {html_escape(name)}</h1>",
           f'<p id="score">Score: <b>{points_text(got)}</b> of {points_text(worth)} points.</p>']
    by_variant: dict[str, list[Result]] = {}
    for r in results:
        by_variant.setdefault(variants.get(r.label, ""), []).append(r)
    for vid, rs in by_variant.items():
        text = data.texts.get(vid, VariantText())
        owner = data.variants.get(vid, ("", ()))[0]
        heading = html_escape(text.title) if text.title else "Questions"
        out.append(f"<h2>{heading}</h2>" + (f'<p class="form">Variant <code>{html_escape(vid)}</code></p>'
                                            if vid else ""))
        if text.statement:
            out.append(f"<p>{_math_html(text.statement)}</p>")
        for r in rs:
            prompt = text.prompts.get(r.label, "")
            key_answer = data.keys.get(owner, {}).get(r.label)
            out.append(f'<div class="part"><b>[{html_escape(r.label)}]</b> {_math_html(prompt)}<br>'
                       f"Your answer: {f'<code>{html_escape(r.given)}</code>' if r.given else '(none)'}<br>"
                       f"{_verdict(r)}"
                       + (f"<br>Expected: <code>{html_escape(key_answer.display())}</code>" if key_answer else "")
                       + "</div>")
        if text.solution:
            out.append("<details open><summary>Worked solution</summary><ol>"
                       + "".join(f"<li>{_math_html(step)}</li>" for step in text.solution) + "</ol></details>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"


def write_feedback(folder: Path, graded: Graded, data: ManifestData, title: str = "Feedback") -> list[Path]:
    """Write one page per person with results, and ``index.html`` linking them, into ``folder``."""
    written = []
    rows = []
    for key, got, worth in score_summary({k: rs for k, rs in graded.report.items() if k in graded.people}):
        name = feedback_name(key)
        (folder / name).write_text(feedback_page(key, graded, data, title), encoding="utf-8")
        written.append(folder / name)
        person = graded.people[key]
        rows.append(f'<tr><td><a href="{html.escape(name)}">{html_escape(person.name or key)}</a></td>'
                    f"<td>{html_escape(key)}</td><td>{points_text(got)}</td><td>{points_text(worth)}</td></tr>")
    index = ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
             f'<meta http-equiv="Content-Security-Policy" content="{_CSP}">'
             f"<title>{html.escape(one_line(title))}</title><style>{_STYLE}</style></head><body>"
             f"<h1>{html_escape(title)}</h1><table><thead><tr><th>name</th><th>id</th><th>score</th>"
             f"<th>points</th></tr></thead><tbody>{''.join(rows)}</tbody></table></body></html>\n")
    (folder / "index.html").write_text(index, encoding="utf-8")
    return [*written, folder / "index.html"]
