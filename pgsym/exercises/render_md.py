"""Markdown/MyST renderer: one page per sheet, solutions in dropdown admonitions on request.

Names, ids and titles go through :func:`~pgsym.escaping.md_escape`, exercise text through
:func:`~pgsym.escaping.to_md`: no user text becomes a role, directive, link, HTML or math.

>>> from pgsym.exercises.sheets import build_sheet
>>> page = render_sheet(build_sheet(["join"], "s1", "Ada", 1), solutions=True)
>>> page.startswith("# Exercise sheet") and ":class: dropdown" in page
True
"""

from __future__ import annotations

from functools import lru_cache

from ..escaping import md_escape
from ..escaping import to_md as _to_md
from .model import KIND_HINTS, Exercise, Sheet

# the answer key repeats every text of the sheets: convert each text once
to_md = lru_cache(maxsize=16384)(_to_md)


def _exercise(ex: Exercise, solutions: bool) -> list[str]:
    lines = [f"## Exercise {ex.slot}: {md_escape(ex.title)}", "", to_md(ex.statement), ""]
    for part in ex.parts:
        label = f"**({part.label})** " if len(ex.parts) > 1 else f"**[{part.label}]** "  # labels are ours
        lines.append(f"{label}{to_md(part.prompt)} *Answer format: {KIND_HINTS[part.answer.kind]}.*")
        lines.append("")
        for letter, choice in zip("ABCDEFGH", part.choices, strict=False):
            lines.append(f"- **{letter}.** {to_md(choice)}")
        if part.choices:
            lines.append("")
    if solutions:
        lines += ["````{admonition} Solution", ":class: dropdown", ""]
        lines += [f"{i}. {to_md(step)}" for i, step in enumerate(ex.solution, start=1)]
        lines.append("")
        for part in ex.parts:
            lines.append(f"**Answer [{part.label}]:** {to_md('$' + part.answer.latex() + '$')}  "
                         f"(typed: `{part.answer.display()}`)")
            lines.append("")
        lines += ["````", ""]
    return lines


def render_sheet(sheet: Sheet, solutions: bool = False) -> str:
    """The MyST Markdown page of one sheet."""
    who = f"{sheet.student_name} ({sheet.student_id})" if sheet.student_name else sheet.student_id
    lines = [f"# Exercise sheet: {md_escape(who)}", "", f"Form id: **{md_escape(sheet.form_id)}**", "",
             "Give exact answers: integers and fractions such as `-2/3`; homogeneous coordinates are accepted up "
             "to a nonzero scale.", ""]
    for ex in sheet.exercises:
        lines += _exercise(ex, solutions)
    return "\n".join(lines).rstrip() + "\n"
