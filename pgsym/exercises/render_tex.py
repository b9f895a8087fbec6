"""LaTeX renderer (one document with every sheet, one sheet per page group) and PDF through latexmk/pdflatex.

>>> from pgsym.exercises.sheets import build_sheet
>>> tex = render_document([build_sheet(["meet"], "s1", "", 1)], solutions=False)
>>> r"\\documentclass" in tex and "F-" in tex
True
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from collections.abc import Sequence
from pathlib import Path

from ..errors import TeXFailedError, TeXMissingError
from ._text import to_tex
from .model import KIND_HINTS, Exercise, Sheet

PREAMBLE = r"""\documentclass[11pt,a4paper]{article}
\usepackage[utf8]{inputenc}
\usepackage[T1]{fontenc}
\usepackage{lmodern}
\usepackage{amsmath,amssymb}
\usepackage[margin=2.2cm]{geometry}
\usepackage{enumitem}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5em}
\newif\ifsolutions
"""




def _exercise(ex: Exercise) -> list[str]:
    lines = [rf"\subsection*{{Exercise {ex.slot}: {to_tex(ex.title)}}}", to_tex(ex.statement), ""]
    for part in ex.parts:
        label = f"({part.label})" if len(ex.parts) > 1 else f"[{part.label}]"
        lines.append(rf"\textbf{{{label}}} {to_tex(part.prompt)} \emph{{Answer format: "
                     rf"{to_tex(KIND_HINTS[part.answer.kind])}.}}")
        if part.choices:
            lines.append(r"\begin{enumerate}[label=\textbf{\Alph*.},itemsep=0pt]")
            lines += [rf"\item {to_tex(c)}" for c in part.choices]
            lines.append(r"\end{enumerate}")
        lines.append("")
    return lines


def _solution(ex: Exercise) -> list[str]:
    lines = [r"\ifsolutions", r"\par\textbf{Solution.}", r"\begin{enumerate}[itemsep=0pt]"]
    lines += [rf"\item {to_tex(step)}" for step in ex.solution]
    lines.append(r"\end{enumerate}")
    lines += [rf"\textbf{{Answer [{p.label}]:}} ${p.answer.latex()}$\par" for p in ex.parts]
    lines.append(r"\fi")
    return lines


def render_sheet_body(sheet: Sheet, solutions: bool) -> str:
    """The LaTeX of one sheet (no preamble)."""
    who = to_tex(sheet.student_name or sheet.student_id)
    lines = [r"\clearpage", rf"\section*{{Exercise sheet: {who}}}",
             rf"Student id: \texttt{{{to_tex(sheet.student_id)}}} \hfill Form id: \texttt{{{sheet.form_id}}}", "",
             "Give exact answers; homogeneous coordinates are accepted up to a nonzero scale.", ""]
    for ex in sheet.exercises:
        lines += _exercise(ex)
        if solutions:
            lines += _solution(ex)
    return "\n".join(lines) + "\n"


def render_document(sheets: Sequence[Sheet], solutions: bool = False) -> str:
    """A complete LaTeX document with every sheet; with solutions, ``\\solutionstrue`` switches them on
    (set ``\\solutionsfalse`` to hide them again)."""
    parts = [PREAMBLE, r"\solutionstrue" if solutions else r"\solutionsfalse", r"\begin{document}"]
    parts += [render_sheet_body(s, solutions) for s in sheets]
    parts.append(r"\end{document}")
    return "\n".join(parts) + "\n"


def tex_available() -> bool:
    """True when pdflatex is on the PATH."""
    return shutil.which("pdflatex") is not None


def compile_pdf(tex_source: str, timeout: float = 600) -> bytes:
    """Compile LaTeX source in a temporary folder (latexmk when present, else pdflatex twice); the PDF bytes.

    Raises :class:`TeXMissingError` if TeX is not installed and :class:`TeXFailedError` if it fails.
    """
    if not tex_available():
        raise TeXMissingError("pdflatex is not installed, so no PDF can be made. On Debian/Ubuntu run: "
                              "sudo apt-get install texlive-latex-extra texlive-fonts-recommended lmodern latexmk "
                              "(or 'make system-deps'); the other formats do not need TeX.")
    # fixed dates make the PDF reproducible (pdfTeX honours SOURCE_DATE_EPOCH)
    env = {**os.environ, "SOURCE_DATE_EPOCH": "0", "FORCE_SOURCE_DATE": "1"}
    with tempfile.TemporaryDirectory(prefix="pgsym-tex-") as tmp:
        src = Path(tmp) / "sheets.tex"
        src.write_text(tex_source, encoding="utf-8")
        if shutil.which("latexmk"):
            commands = [["latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "-quiet", "sheets.tex"]]
        else:
            commands = [["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "sheets.tex"]] * 2
        for cmd in commands:
            try:
                result = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, timeout=timeout,
                                        stdin=subprocess.DEVNULL, errors="replace", env=env)
            except subprocess.TimeoutExpired:
                raise TeXFailedError(f"{cmd[0]} took longer than {timeout:.0f} s") from None
            if result.returncode != 0:
                log = Path(tmp) / "sheets.log"
                tail = log.read_text(errors="replace")[-1500:] if log.exists() else result.stdout[-1500:]
                raise TeXFailedError(f"{cmd[0]} failed (exit {result.returncode}); end of the log:\n{tail}")
        return (Path(tmp) / "sheets.pdf").read_bytes()
