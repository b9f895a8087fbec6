"""Writing a set of sheets to disk in the requested formats, atomically.

One run serves both audiences: for every requested format the student sheets (without solutions,
unless ``solutions`` asks for practice sheets), the answer key (every student's sheet with worked
solutions) and the key table of the class (student × question → canonical answer)::

    manifest.json                      the answer key for 'pgsym check'
    md/ html/ ipynb/                   student sheets, one file each
    key/md/ key/html/ key/ipynb/       the answer key, one file per student
    key-table.md .html .ipynb          the key table of the class
    sheets.tex key.tex key-table.tex   LaTeX (all students in one document each)
    sheets.pdf key.pdf key-table.pdf   the same through LuaLaTeX (compiled side by side); each sheet starts
                                       on an odd page and numbers its pages from 1
    pdf/ key/pdf/                      one PDF per student, cut from sheets.pdf and key.pdf
    stack.xml                          Moodle STACK questions (graded up to scale, pgsym's mistake feedback)
    moodle.xml  qti.zip                Moodle Cloze questions and the Canvas QTI 1.2 package

Everything is written into a temporary folder next to the target and moved into place only when
every format succeeded, so an error (for example TeX failing), Ctrl-C or SIGTERM leaves no partial
output: the target is either complete or untouched.

>>> parse_formats("qti,pdf")
['qti', 'pdf']
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path

from . import key_table, render_html, render_ipynb, render_md, render_moodle, render_qti, render_stack, render_tex
from .model import Sheet
from .sheets import manifest_json

__all__ = ["FORMATS", "KEY_HEADING", "parse_formats", "render_all"]

FORMATS = ("md", "tex", "pdf", "html", "ipynb", "moodle", "stack", "qti")

#: The heading of the answer key's pages.
KEY_HEADING = "Answer key"


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
               progress: Callable[[int], None] | None = None, key: bool = True,
               self_check: bool = True) -> list[Path]:
    """Write the manifest and every format into ``folder`` (which must exist); the files written.

    ``solutions`` puts the worked solutions into the student sheets too (practice sheets); ``key``
    writes the answer key and the key table next to them. ``mathjax`` is ignored: the HTML pages
    carry their math as MathML and need no script (kept so that old callers still work).
    ``self_check=False`` writes the student notebooks without the practice self-check
    (:mod:`pgsym.exercises.render_ipynb`).
    """
    del mathjax  # the pages need no MathJax any more
    written = []

    def write(name: str, text: str | bytes) -> None:
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(text, bytes):
            path.write_bytes(text)
        else:
            path.write_text(text, encoding="utf-8", newline="\n")
        written.append(path)

    # TeX runs in separate processes: start it first, so it works while Python renders the other formats
    pool = ThreadPoolExecutor(max_workers=max(1, min(3, os.cpu_count() or 1)))
    pdfs = _start_pdfs(pool, sheets, solutions, key) if "pdf" in formats else {}
    try:
        write("manifest.json", manifest_json(sheets, topics))
        per_sheet = [(f, r) for f, r in (("md", render_md), ("html", render_html), ("ipynb", render_ipynb))
                     if f in formats]
        for sheet in sheets:
            for fmt, renderer in per_sheet:
                page = (render_ipynb.render_sheet(sheet, solutions, self_check) if fmt == "ipynb"
                        else renderer.render_sheet(sheet, solutions))
                write(f"{fmt}/{sheet.file_stem}.{fmt}", page)
                if key:
                    keyed = (render_html.render_sheet(sheet, True, KEY_HEADING) if fmt == "html"
                             else renderer.render_sheet(sheet, True))
                    write(f"key/{fmt}/{sheet.file_stem}.{fmt}", keyed)
            if progress is not None:
                progress(1)
        if key:
            for fmt, renderer in (("md", key_table.render_md), ("html", key_table.render_html),
                                  ("ipynb", key_table.render_ipynb)):
                if fmt in formats:
                    write(f"key-table.{fmt}", renderer(sheets))
        if "tex" in formats:
            write("sheets.tex", render_tex.render_document(sheets, solutions))
            if key:
                write("key.tex", render_tex.render_document(sheets, True, KEY_HEADING))
                write("key-table.tex", key_table.render_tex(sheets, render_tex.preamble))
        if "moodle" in formats:
            write("moodle.xml", render_moodle.render_quiz(sheets, solutions))
        if "stack" in formats:
            write("stack.xml", render_stack.render_stack_quiz(sheets))
        if "qti" in formats:
            write("qti.zip", render_qti.render_package(sheets, topics))
        for name, future in pdfs.items():
            pdf, each = future.result()
            write(f"{name}.pdf", pdf)
            folder_of = {"sheets": "pdf", "key": "key/pdf"}.get(name)
            for sheet, one in zip(sheets, each, strict=False):
                write(f"{folder_of}/{sheet.file_stem}.pdf", one)
    except BaseException:
        if pdfs:  # an error, Ctrl-C or SIGTERM: stop the TeX runs instead of waiting for them
            for future in pdfs.values():
                future.cancel()
            render_tex.stop_running()
        raise
    finally:
        pool.shutdown(wait=True)
        render_tex.allow_running()
    return written


def _start_pdfs(pool: ThreadPoolExecutor, sheets: Sequence[Sheet], solutions: bool,
                key: bool) -> dict[str, Future[tuple[bytes, list[bytes]]]]:
    """Submit the TeX runs (each a separate LuaLaTeX process, at most one per core at a time): the class
    PDFs and, for sheets and key, one PDF per student cut from them."""
    jobs: dict[str, Callable[[], tuple[bytes, list[bytes]]]] = {
        "sheets": lambda: render_tex.compile_class_and_each(sheets, solutions)}
    if key:
        jobs["key"] = lambda: render_tex.compile_class_and_each(sheets, True, KEY_HEADING)
        jobs["key-table"] = lambda: (render_tex.compile_pdf(key_table.render_tex(sheets, render_tex.preamble),
                                                            render_tex.tex_time_limit(len(sheets))), [])
    return {name: pool.submit(job) for name, job in jobs.items()}
