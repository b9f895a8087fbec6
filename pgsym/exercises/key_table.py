"""The key table of a class: one row per student, one column per question, each cell the canonical
answer (the text :meth:`~pgsym.exercises.model.Answer.display` gives, which ``pgsym check`` reads).

One table per class in every format: Markdown, HTML, LaTeX (landscape, repeating its header on every
page) and a notebook with the Markdown table. Names and ids are escaped as everywhere else; the answers
are pgsym's own text (digits, signs, brackets, commas and letters).

>>> from pgsym.exercises.sheets import build_sheets
>>> sheets = build_sheets(["join", "meet"], [("s1", "Ada"), ("s2", "李雷")], 3)
>>> labels, rows = key_rows(sheets)
>>> labels, [r[1] for r in rows]
(['1', '2'], ['s1', 's2'])
>>> print(render_md(sheets).splitlines()[4].startswith("| Ada | s1 | `("))
True
"""

from __future__ import annotations

import html
import json
from collections.abc import Callable, Sequence

from ..escaping import html_escape, md_escape, tex_escape
from .model import Sheet

TITLE = "Answer key table"


def key_rows(sheets: Sequence[Sheet]) -> tuple[list[str], list[tuple[str, str, dict[str, str]]]]:
    """The question labels (in order of first appearance) and one ``(name, id, {label: answer})`` per student."""
    labels: dict[str, None] = {}
    rows = []
    for sheet in sheets:
        answers = {p.label: p.answer.display() for ex in sheet.exercises for p in ex.parts}
        labels.update(dict.fromkeys(answers))
        rows.append((sheet.student_name, sheet.student_id, answers))
    return list(labels), rows


def _md_code(text: str) -> str:
    # answers never hold a backtick or a pipe; a table cell cannot hold a line break
    return f"`{text}`" if text else ""


def render_md(sheets: Sequence[Sheet]) -> str:
    """The key table as a MyST/CommonMark pipe table."""
    labels, rows = key_rows(sheets)
    lines = [f"# {TITLE}", "", "| Name | Id | " + " | ".join(labels) + " |",
             "|---|---|" + "---|" * len(labels)]
    for name, sid, answers in rows:
        cells = [md_escape(name).replace("|", "\\|"), md_escape(sid).replace("|", "\\|")]
        cells += [_md_code(answers.get(label, "")) for label in labels]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


STYLE = """body{font-family:system-ui,sans-serif;margin:2em}table{border-collapse:collapse}
th,td{border:1px solid #bbb;padding:.2em .5em;text-align:left;vertical-align:top}td code{white-space:nowrap}"""


def render_html(sheets: Sequence[Sheet]) -> str:
    """The key table as one HTML page (no script)."""
    labels, rows = key_rows(sheets)
    out = ["<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">', f"<title>{TITLE}</title>",
           f"<style>{STYLE}</style>", "</head>", "<body>", f"<h1>{TITLE}</h1>", "<table>",
           "<thead><tr><th>Name</th><th>Id</th>" + "".join(f"<th>{html.escape(lb)}</th>" for lb in labels)
           + "</tr></thead>", "<tbody>"]
    for name, sid, answers in rows:
        out.append(f"<tr><td>{html_escape(name)}</td><td>{html_escape(sid)}</td>"
                   + "".join(f"<td><code>{html.escape(answers.get(lb, ''))}</code></td>" for lb in labels)
                   + "</tr>")
    out += ["</tbody>", "</table>", "</body>", "</html>"]
    return "\n".join(out) + "\n"


def render_tex(sheets: Sequence[Sheet], preamble: Callable[[str], str]) -> str:
    """The key table as a LaTeX document, landscape; ``preamble(body)`` gives the preamble for the
    characters of the body (:func:`pgsym.exercises.render_tex.preamble`)."""
    labels, rows = key_rows(sheets)
    t = lambda s: tex_escape(s, unicode=True)  # noqa: E731
    # landscape A4 less margins is 27.3 cm: name and id take 5.4 cm, each column 0.42 cm of separation
    width = f"{max(1.0, 21.0 / max(1, len(labels)) - 0.45):.2f}cm"
    cell = r">{\raggedright\arraybackslash\footnotesize}p{" + width + "}"
    spec = r"@{}p{3.2cm}p{2.2cm}*{" + str(len(labels)) + "}{" + cell + "}@{}"
    head = "Name & Id & " + " & ".join(t(lb) for lb in labels) + r" \\ \hline"
    lines = [rf"\sheettitle{{{t(TITLE)}}}", r"{\small", rf"\begin{{longtable}}{{{spec}}}", head, r"\endhead"]
    for name, sid, answers in rows:
        lines.append(" & ".join([t(name), t(sid)] + [r"\texttt{" + t(answers.get(lb, "")) + "}" for lb in labels])
                     + r" \\ \hline")
    lines += [r"\end{longtable}}", r"\end{document}"]
    body = "\n".join(lines) + "\n"
    return (preamble(body) + "\\usepackage{longtable,array}\n\\geometry{landscape,margin=1.2cm}\n\\begin{document}\n"
            + body)


def render_ipynb(sheets: Sequence[Sheet]) -> str:
    """The key table as a notebook (one Markdown cell)."""
    nb = {"cells": [{"cell_type": "markdown", "id": "key-table", "metadata": {},
                     "source": render_md(sheets).splitlines(keepends=True)}],
          "metadata": {"language_info": {"name": "python"}}, "nbformat": 4, "nbformat_minor": 5}
    return json.dumps(nb, indent=1, sort_keys=True, ensure_ascii=False) + "\n"
