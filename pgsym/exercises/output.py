"""Writing a set of sheets to disk in the requested formats, atomically.

Everything is written into a temporary folder next to the target and moved into place only when
every format succeeded, so an error (for example TeX failing), Ctrl-C or SIGTERM leaves no partial
output: the target is either complete or untouched.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from . import render_html, render_ipynb, render_md, render_moodle, render_tex
from .model import Sheet
from .sheets import manifest_json

__all__ = ["FORMATS", "parse_formats", "render_all"]

FORMATS = ("md", "tex", "pdf", "html", "ipynb", "moodle")



def parse_formats(spec: str) -> list[str]:
    """``"md,tex"`` → ``["md", "tex"]``; unknown formats raise ValueError.

    >>> parse_formats("md, pdf")
    ['md', 'pdf']
    """
    items = [f.strip().lower() for f in spec.split(",") if f.strip()]
    bad = [f for f in items if f not in FORMATS]
    if bad or not items:
        raise ValueError(f"unknown format(s) {', '.join(bad) or '(none)'}; choose from {', '.join(FORMATS)}")
    return list(dict.fromkeys(items))


def render_all(sheets: Sequence[Sheet], topics: Sequence[tuple[str, int]], formats: Sequence[str], folder: Path,
               solutions: bool = False, mathjax: str | Path | None = None,
               progress: Callable[[int], None] | None = None) -> list[Path]:
    """Write the manifest and every format into ``folder`` (which must exist); the files written."""
    written = []

    def write(name: str, text: str | bytes) -> None:
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(text, bytes):
            path.write_bytes(text)
        else:
            path.write_text(text, encoding="utf-8", newline="\n")
        written.append(path)

    if "html" in formats:
        render_html.copy_mathjax(folder / "html", mathjax)
    write("manifest.json", manifest_json(sheets, topics))
    for sheet in sheets:
        if "md" in formats:
            write(f"md/{sheet.file_stem}.md", render_md.render_sheet(sheet, solutions))
        if "html" in formats:
            write(f"html/{sheet.file_stem}.html", render_html.render_sheet(sheet, solutions))
        if "ipynb" in formats:
            write(f"ipynb/{sheet.file_stem}.ipynb", render_ipynb.render_sheet(sheet, solutions))
        if progress is not None:
            progress(1)
    if "tex" in formats or "pdf" in formats:
        tex = render_tex.render_document(sheets, solutions)
        if "tex" in formats:
            write("sheets.tex", tex)
        if "pdf" in formats:
            write("sheets.pdf", render_tex.compile_sheets(sheets, solutions))
    if "moodle" in formats:
        write("moodle.xml", render_moodle.render_quiz(sheets, solutions))
    return written
