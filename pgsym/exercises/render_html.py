"""HTML renderer: one self-contained page per sheet, math as MathML made at generation time.

Names, ids and titles go through :func:`~pgsym.escaping.html_escape` and exercise text through
:func:`~pgsym.escaping.to_html` with :func:`~pgsym.exercises.html_math.mathml`: no user text
becomes a tag or an entity, and the pages hold no script at all, so they open offline right after
``pip install pgsym`` (browsers render MathML themselves).

:func:`copy_mathjax` and :func:`find_mathjax` remain for callers that still copy MathJax (the
``--mathjax`` option of ``pgsym sheet`` is deprecated and ignored); the pages do not need it.

>>> from pgsym.exercises.sheets import build_sheet
>>> page = render_sheet(build_sheet(["ideal"], "s1", "", 1), solutions=True)
>>> "<math " in page and "<script" not in page and "<details>" in page
True
"""

from __future__ import annotations

import html
import os
import shutil
from functools import lru_cache
from pathlib import Path

from ..escaping import html_escape, one_line, to_html
from .errors import MathJaxMissingError
from .html_math import mathml
from .model import KIND_HINTS, Sheet

MATHJAX_DIR = "mathjax"

STYLE = """body{font-family:system-ui,sans-serif;max-width:48em;margin:2em auto;padding:0 1em;line-height:1.5}
.form{color:#555}.part{margin:.6em 0}details{background:#f4f6f8;padding:.4em .8em;border-radius:4px}
ol.choices{list-style-type:upper-alpha}math[display=block]{margin:.5em 0}"""


@lru_cache(maxsize=16384)  # the answer key repeats every text of the sheets
def _html(text: str) -> str:
    return to_html(text, mathml)


def render_sheet(sheet: Sheet, solutions: bool = False, heading: str = "Exercise sheet", *,
                 mathjax: str | None = None) -> str:
    """The HTML page of one sheet (with ``solutions``: the worked solutions in ``<details>``, open on
    the pages of the answer key). ``mathjax`` is accepted for old callers and ignored: the page needs none."""
    del mathjax
    who = html_escape(sheet.student_name or sheet.student_id)
    title = html.escape(one_line(sheet.student_name or sheet.student_id))  # <title> shows text only, never math
    out = ["<!DOCTYPE html>", '<html lang="en">', "<head>", '<meta charset="utf-8">',
           f"<title>{html.escape(heading)}: {title}</title>", f"<style>{STYLE}</style>", "</head>",
           "<body>", f"<h1>{html.escape(heading)}: {who}</h1>",
           f'<p class="form">Student id: <code>{html_escape(sheet.student_id)}</code> · Form id: '
           f"<code>{html_escape(sheet.form_id)}</code></p>",
           "<p>Give exact answers; homogeneous coordinates are accepted up to a nonzero scale.</p>"]
    for ex in sheet.exercises:
        out.append(f"<h2>Exercise {ex.slot}: {html_escape(ex.title)}</h2>")
        out.append(f"<p>{_html(ex.statement)}</p>")
        for part in ex.parts:
            out.append(f'<div class="part"><b>[{part.label}]</b> {_html(part.prompt)} '
                       f"<i>Answer format: {html.escape(KIND_HINTS[part.answer.kind])}.</i>")
            if part.choices:
                out.append('<ol class="choices">' + "".join(f"<li>{_html(c)}</li>" for c in part.choices) + "</ol>")
            out.append("</div>")
        if solutions:
            out.append("<details open><summary>Solution</summary><ol>" if heading != "Exercise sheet"
                       else "<details><summary>Solution</summary><ol>")
            out += [f"<li>{_html(step)}</li>" for step in ex.solution]
            out.append("</ol>")
            out += [f"<p><b>Answer [{p.label}]:</b> {_html('$' + p.answer.latex() + '$')}</p>"
                    for p in ex.parts]
            out.append("</details>")
    out += ["</body>", "</html>"]
    return "\n".join(out) + "\n"


def find_mathjax(explicit: str | Path | None = None) -> Path:
    """The folder holding ``tex-chtml.js`` (MathJax 3's ``es5`` folder)."""
    candidates: list[Path] = []
    if explicit:
        candidates.append(Path(explicit))
    if os.environ.get("PGSYM_MATHJAX"):
        candidates.append(Path(os.environ["PGSYM_MATHJAX"]))
    for base in (Path.cwd(), Path(__file__).resolve().parents[2]):
        candidates += [base / "node_modules" / "mathjax" / "es5", base / "_mathjax" / "_static" / "mathjax"]
    for c in candidates:
        if (c / "tex-chtml.js").is_file():
            return c
        if explicit and c == Path(explicit):
            raise MathJaxMissingError(f"{str(c)!r} has no tex-chtml.js; give MathJax 3's es5 folder "
                                      "(node_modules/mathjax/es5 after 'npm install mathjax@3')")
    raise MathJaxMissingError("no local MathJax found for the HTML sheets: install it with 'npm install mathjax@3' "
                              "and pass --mathjax node_modules/mathjax/es5 (or set PGSYM_MATHJAX)")


def copy_mathjax(target: Path, source: str | Path | None = None) -> None:
    """Copy the MathJax files the sheets need (the es5 folder) to ``target/mathjax``.

    Only regular files and folders inside the MathJax folder are copied: a link leading out of it
    is skipped, and a pipe or device there is refused instead of being read.
    """
    src = find_mathjax(source).resolve()

    def ignore(folder: str, names: list[str]) -> list[str]:
        skipped = []
        for name in names:
            path = Path(folder) / name
            if path.is_symlink() and not path.resolve().is_relative_to(src):
                skipped.append(name)
            elif not (path.is_file() or path.is_dir()):
                raise MathJaxMissingError(f"{str(path)!r} in the MathJax folder is not a regular file")
        return skipped

    shutil.copytree(src, target / MATHJAX_DIR, dirs_exist_ok=True, ignore=ignore)
