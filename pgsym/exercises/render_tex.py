"""LaTeX renderer (one document with every sheet, one sheet per page group) and PDF through LuaLaTeX.

LuaLaTeX with the Noto fonts typesets every name as it is (Latin, Greek, Cyrillic, Chinese, Japanese,
Korean, Arabic, Hebrew, Devanagari, Bengali, Tamil, Ethiopic, Khmer, emoji, … whatever an installed
Noto font has): luaotfload falls back, glyph by glyph, to the fonts :mod:`~pgsym.exercises.tex_fonts`
finds for the document's characters, and right-to-left runs are set right to left, so ``pdftotext``
gives every name back exactly. A character no installed font has stops the PDF with
:class:`~pgsym.exercises.errors.MissingGlyphError` naming the student and the character (checked
before TeX runs, and in TeX's log for "Missing character"): never an empty box.

User text never reaches TeX as code: names, ids and titles go through
:func:`~pgsym.escaping.tex_escape`, exercise text through :func:`~pgsym.escaping.to_tex`
(math only from an allowed set of commands). TeX itself runs confined (:func:`compile_pdf`): shell
escape off (``-no-shell-escape``), kpathsea's paranoid ``openin_any=p`` and ``openout_any=p`` (no
absolute paths, no ``..``, no dot files), inside a fresh temporary folder, in its own process group
killed as a whole after :func:`tex_time_limit` seconds.

>>> from pgsym.exercises.sheets import build_sheet
>>> tex = render_document([build_sheet(["meet"], "s1", "", 1)], solutions=False)
>>> r"\\documentclass" in tex and "F-" in tex
True
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import tempfile
import threading
import time
from collections.abc import Sequence
from pathlib import Path

from ..escaping import one_line, tex_escape, to_tex
from .errors import MissingGlyphError, TeXFailedError, TeXMissingError
from .model import KIND_HINTS, Exercise, Sheet
from .tex_fonts import (
    MAIN_FONT,
    STATIC_FALLBACKS,
    describe,
    fallback_chain,
    missing_characters,
    needs_glyph,
    package_hint,
)

#: Fallback fonts when fontconfig is not available (the chain is otherwise built from the installed
#: Noto fonts, :mod:`pgsym.exercises.tex_fonts`).
FALLBACKS = STATIC_FALLBACKS
FALLBACK_FONTS = tuple(font for _, font in FALLBACKS)

_PREAMBLE_REST = r"""% (no TeX ligatures: a name's -- << ,, `` prints as typed)
% no creation date, producer or PTEX keys in the PDF: the same sheets give the same bytes
\pdfvariable suppressoptionalinfo 1023
\usepackage{amsmath,amssymb}
\usepackage[margin=2.2cm]{geometry}
\usepackage{enumitem}
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.5em}
% a line that cannot be filled well may stretch rather than run off the page (long paths, names, URLs)
\setlength{\emergencystretch}{3em}
\newif\ifsolutions
% headings as ordinary paragraphs: a very long name or title breaks across lines and pages
\newcommand{\sheettitle}[1]{\par{\raggedright\Large\bfseries #1\par}\nopagebreak\medskip}
\newcommand{\exercisetitle}[1]{\par\bigskip{\raggedright\large\bfseries #1\par}\nopagebreak\smallskip}
% each sheet on its own paper: it starts on an odd (right-hand) page of the class PDF (a blank page
% after a sheet of odd length), its pages are numbered from 1, and the log tells where it starts and
% ends (the per-student PDFs are cut there)
\newcommand{\sheetend}{\clearpage
  \ifnum\ReadonlyShipoutCounter>0 \typeout{pgsym-sheet-end=\the\ReadonlyShipoutCounter}\fi}
\newcommand{\sheetstart}{\sheetend\ifodd\value{page}\else\null\thispagestyle{empty}\newpage\fi
  \setcounter{page}{1}\typeout{pgsym-sheet-start=\the\numexpr\ReadonlyShipoutCounter+1\relax}}
\AtEndDocument{\sheetend}
"""


def fallback_fonts(text: str | None = None) -> list[str]:
    """The fallback fonts ``text`` needs, preferred first (the fixed table for ``None``): loading a font
    costs TeX time, so a document loads only those its characters use.

    >>> fallback_fonts("Ada"), [f.split(":")[0] for f in fallback_fonts("李雷 and محمد")]
    ([], ['Noto Serif CJK SC', 'Noto Naskh Arabic'])
    """
    if text is None:
        return list(FALLBACK_FONTS)
    return fallback_chain(text)[0]


def preamble(text: str | None = None) -> str:
    """The LaTeX preamble, with the fallback fonts for the characters of ``text`` (all for ``None``)."""
    fonts = fallback_fonts(text)
    lines = [r"\documentclass[11pt,a4paper]{article}",
             r"% LuaLaTeX: every Unicode name prints (fonts and fallbacks below); right-to-left runs use \textdir TRT",
             r"\usepackage{fontspec}"]
    if fonts:
        lines.append(r'\directlua{luaotfload.add_fallback("pgsym", {' + ", ".join(f'"{f}"' for f in fonts) + "})}")
        lines.append(rf"\setmainfont{{{MAIN_FONT}}}[Ligatures=TeXOff, RawFeature={{fallback=pgsym}}]")
    else:  # no fallback needed: TeX's own ligatures and kerning (base mode) take half the time of node mode
        lines.append(rf"\setmainfont{{{MAIN_FONT}}}[Ligatures=TeXOff, Renderer=Basic]")
    return "\n".join(lines) + "\n" + _PREAMBLE_REST


#: The preamble with every fallback font.
PREAMBLE = preamble()

#: Seconds TeX may take for a document: ``TEX_BASE_SECONDS + TEX_SECONDS_PER_SHEET × sheets``.
TEX_BASE_SECONDS = 30.0
TEX_SECONDS_PER_SHEET = 2.0


def tex_time_limit(sheets: int) -> float:
    """The time limit of TeX for a document of ``sheets`` sheets, in seconds.

    >>> tex_time_limit(1), tex_time_limit(100)
    (32.0, 230.0)
    """
    return TEX_BASE_SECONDS + TEX_SECONDS_PER_SHEET * max(1, sheets)


def _t(text: str) -> str:
    return tex_escape(text, unicode=True)


def _tx(text: str) -> str:
    return to_tex(text, unicode=True)


def _exercise(ex: Exercise) -> list[str]:
    lines = [rf"\exercisetitle{{Exercise {ex.slot}: {_t(ex.title)}}}", _tx(ex.statement), ""]
    for part in ex.parts:
        label = f"({part.label})" if len(ex.parts) > 1 else f"[{part.label}]"
        lines.append(rf"\textbf{{{_t(label)}}} {_tx(part.prompt)} \emph{{Answer format: "
                     rf"{_t(KIND_HINTS[part.answer.kind])}.}}")
        if part.choices:
            lines.append(r"\begin{enumerate}[label=\textbf{\Alph*.},itemsep=0pt]")
            lines += [rf"\item {_tx(c)}" for c in part.choices]
            lines.append(r"\end{enumerate}")
        lines.append("")
    return lines


def _solution(ex: Exercise) -> list[str]:
    lines = [r"\ifsolutions", r"\par\textbf{Solution.}", r"\begin{enumerate}[itemsep=0pt]"]
    lines += [rf"\item {_tx(step)}" for step in ex.solution]
    lines.append(r"\end{enumerate}")
    lines += [rf"\textbf{{Answer {_t('[' + p.label + ']')}:}} {_tx('$' + p.answer.latex() + '$')}\par"
              for p in ex.parts]
    lines.append(r"\fi")
    return lines


def render_sheet_body(sheet: Sheet, solutions: bool, heading: str = "Exercise sheet") -> str:
    """The LaTeX of one sheet (no preamble)."""
    who = _t(sheet.student_name or sheet.student_id)
    lines = [r"\sheetstart", rf"\sheettitle{{{_t(heading)}: {who}}}",
             rf"Student id: {_t(sheet.student_id)} \hfill Form id: \texttt{{{_t(sheet.form_id)}}}", "",
             "Give exact answers; homogeneous coordinates are accepted up to a nonzero scale.", ""]
    for ex in sheet.exercises:
        lines += _exercise(ex)
        if solutions:
            lines += _solution(ex)
    return "\n".join(lines) + "\n"


def render_document(sheets: Sequence[Sheet], solutions: bool = False, heading: str = "Exercise sheet") -> str:
    """A complete LaTeX document with every sheet; with solutions, ``\\solutionstrue`` switches them on
    (set ``\\solutionsfalse`` to hide them again). The answer key is ``render_document(sheets, True,
    "Answer key")``."""
    body = [render_sheet_body(s, solutions, heading) for s in sheets]
    parts = [preamble("".join(body)), r"\solutionstrue" if solutions else r"\solutionsfalse", r"\begin{document}",
             *body]
    parts.append(r"\end{document}")
    return "\n".join(parts) + "\n"


#: The TeX engine of the PDF sheets (Debian: texlive-luatex).
ENGINE = "lualatex"


def tex_available() -> bool:
    """True when LuaLaTeX is on the PATH."""
    return shutil.which(ENGINE) is not None


def _tex_environment() -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k not in ("TEXMFOUTPUT", "shell_escape", "shell_escape_commands")}
    # paranoid kpathsea: TeX opens no absolute path, nothing above its folder and no dot file
    env.update({"openin_any": "p", "openout_any": "p", "shell_escape": "f",
                # fixed dates make the PDF reproducible (pdfTeX honours SOURCE_DATE_EPOCH)
                "SOURCE_DATE_EPOCH": "0", "FORCE_SOURCE_DATE": "1",
                "max_print_line": "1000"})  # unwrapped log lines make readable error messages
    return env


# TeX runs started from worker threads (several documents at once): an error, Ctrl-C or SIGTERM in the
# main thread stops them all through stop_running(), and no new run starts until allow_running()
_RUNNING: set[subprocess.Popen[bytes]] = set()
_RUNNING_LOCK = threading.Lock()
_STOPPED = threading.Event()


def stop_running() -> None:
    """Kill every TeX run in progress (each with its process group) and refuse new ones."""
    with _RUNNING_LOCK:
        _STOPPED.set()
        for proc in list(_RUNNING):
            _kill_group(proc, wait=False)


def allow_running() -> None:
    """Allow TeX runs again (after :func:`stop_running`)."""
    _STOPPED.clear()


def _run_confined(cmd: list[str], cwd: str, timeout: float) -> tuple[int, str]:
    """Run ``cmd`` in its own process group; kill the whole group after ``timeout`` s (or on any error)."""
    with tempfile.TemporaryFile() as out:
        with _RUNNING_LOCK:
            if _STOPPED.is_set():
                raise TeXFailedError("stopped before TeX started (another part of the output failed)")
            proc = subprocess.Popen(cmd, cwd=cwd, stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT,
                                    env=_tex_environment(), start_new_session=True)
            _RUNNING.add(proc)
        try:
            code = proc.wait(timeout=timeout)
        finally:
            _kill_group(proc)  # on time-out, on interruption and after a normal end: nothing TeX started survives
            with _RUNNING_LOCK:
                _RUNNING.discard(proc)
        out.seek(0)
        return code, out.read()[-4000:].decode("utf-8", "replace")


def _kill_group(proc: subprocess.Popen[bytes], wait: bool = True) -> None:
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    if wait:
        proc.wait()


def compile_pdf(tex_source: str, timeout: float | None = None) -> bytes:
    """Compile LaTeX source with LuaLaTeX (see :func:`compile_pdf_and_log`); the PDF bytes."""
    return compile_pdf_and_log(tex_source, timeout)[0]


def compile_pdf_and_log(tex_source: str, timeout: float | None = None) -> tuple[bytes, str]:
    """Compile LaTeX source with LuaLaTeX in a temporary folder, confined as the module says; the PDF bytes
    and TeX's log.

    ``timeout`` defaults to :func:`tex_time_limit` of one sheet. Raises :class:`TeXMissingError` if TeX
    is not installed and :class:`TeXFailedError` if it fails or runs out of time.
    """
    if not tex_available():
        raise TeXMissingError("LuaLaTeX is not installed, so no PDF can be made. On Debian/Ubuntu run: "
                              "sudo apt-get install texlive-luatex texlive-latex-extra fonts-noto-core fonts-noto-cjk "
                              "(or 'make system-deps'); the other formats do not need TeX.")
    limit = tex_time_limit(1) if timeout is None else timeout
    with tempfile.TemporaryDirectory(prefix="pgsym-tex-") as tmp:
        src = Path(tmp) / "sheets.tex"
        src.write_text(tex_source, encoding="utf-8")
        # one run: the sheets have no cross-references; -no-shell-escape whatever texmf.cnf says
        cmd = [ENGINE, "-no-shell-escape", "-interaction=nonstopmode", "-halt-on-error", "sheets.tex"]
        started = time.monotonic()
        try:
            code, output = _run_confined(cmd, tmp, limit)
        except subprocess.TimeoutExpired:
            raise TeXFailedError(f"LuaLaTeX took longer than {limit:.0f} s (the limit) and was stopped") from None
        if code != 0 or not (Path(tmp) / "sheets.pdf").is_file():
            log = Path(tmp) / "sheets.log"
            text = log.read_text(errors="replace") if log.exists() else output
            start = text.find("\n! ")  # TeX's first error message, with the lines that locate it
            excerpt = text[start + 1:start + 800] if start >= 0 else text[-800:]
            raise TeXFailedError(f"LuaLaTeX failed (exit {code}, {time.monotonic() - started:.1f} s):\n{excerpt}")
        log = Path(tmp) / "sheets.log"
        missing = missing_in_log(log.read_text(errors="replace") if log.exists() else output)
        if missing:
            raise MissingGlyphError(_no_font(missing))
        return (Path(tmp) / "sheets.pdf").read_bytes(), log.read_text(errors="replace") if log.exists() else ""


_MISSING = re.compile(r"Missing character: There is no .*? \(U\+([0-9A-Fa-f]{4,6})\)")


def missing_in_log(log: str) -> list[str]:
    """The characters TeX's log says no font of the document has (those that print nothing are left out).

    >>> missing_in_log("Missing character: There is no \U00013000 (U+13000) in font NotoSerif:mode=node;")
    ['\U00013000']
    """
    found = dict.fromkeys(chr(int(m.group(1), 16)) for m in _MISSING.finditer(log))
    return [c for c in found if needs_glyph(c)]


def _no_font(missing: Sequence[str]) -> str:
    shown = ", ".join(describe(c) for c in missing[:5]) + (" …" if len(missing) > 5 else "")
    return (f"no installed font has {shown}, so it would print as an empty box; install a font with it "
            f"(Debian: {package_hint(missing[0])}) or write the text without it")


def compile_sheets(sheets: Sequence[Sheet], solutions: bool = False, heading: str = "Exercise sheet") -> bytes:
    """The PDF of every sheet (one LuaLaTeX run, limited to :func:`tex_time_limit` of the number of sheets).

    If TeX fails, the sheets are compiled again in halves, each under its own proportional limit,
    until the failing sheet is found: the :class:`TeXFailedError` then names its student.
    """
    return compile_class_and_each(sheets, solutions, heading, each=False)[0]


def compile_class_and_each(sheets: Sequence[Sheet], solutions: bool = False, heading: str = "Exercise sheet",
                           each: bool = True) -> tuple[bytes, list[bytes]]:
    """The PDF of the class (every sheet starting on an odd page, pages numbered per sheet) and, with
    ``each``, one PDF per sheet cut from it (:func:`split_pdf`), in the order of ``sheets``."""
    for sheet in sheets:  # before TeX: a character no installed font has names its student at once
        missing = missing_characters(render_sheet_body(sheet, solutions, heading))
        if missing:
            raise _named(sheet, MissingGlyphError(_no_font(missing)))
    try:
        pdf, log = compile_pdf_and_log(render_document(sheets, solutions, heading), tex_time_limit(len(sheets)))
    except TeXFailedError as err:
        if len(sheets) > 1:
            culprit = _failing_sheet(list(sheets), solutions)
            if culprit is not None:
                raise _named(culprit[0], culprit[1]) from None
        elif sheets:
            raise _named(sheets[0], err) from None
        raise
    if not each:
        return pdf, []
    ranges = sheet_pages(log)
    if len(ranges) != len(sheets):
        raise TeXFailedError(f"TeX's log names {len(ranges)} sheets, not {len(sheets)}: cannot cut the class PDF")
    return pdf, split_pdf(pdf, ranges)


_SHEET_MARK = re.compile(r"^pgsym-sheet-(start|end)=(\d+)$", re.MULTILINE)


def sheet_pages(log: str) -> list[tuple[int, int]]:
    """The (first, last) page of each sheet in the class PDF, from the marks ``\\sheetstart`` leaves in TeX's log.

    >>> sheet_pages("pgsym-sheet-start=1\\npgsym-sheet-end=3\\npgsym-sheet-start=5\\npgsym-sheet-end=5\\n")
    [(1, 3), (5, 5)]
    """
    starts = [int(n) for kind, n in _SHEET_MARK.findall(log) if kind == "start"]
    ends = [int(n) for kind, n in _SHEET_MARK.findall(log) if kind == "end"]
    return list(zip(starts, ends, strict=False))


def split_pdf(pdf: bytes, ranges: Sequence[tuple[int, int]]) -> list[bytes]:
    """Cut ``pdf`` into one PDF per page range with poppler's ``pdfseparate`` and ``pdfunite``."""
    tools = {name: shutil.which(name) for name in ("pdfseparate", "pdfunite")}
    if not all(tools.values()):
        raise TeXMissingError("pdfseparate and pdfunite are needed to cut the class PDF into one PDF per student; "
                              "on Debian/Ubuntu run: sudo apt-get install poppler-utils (or 'make system-deps')")
    out = []
    with tempfile.TemporaryDirectory(prefix="pgsym-split-") as tmp:
        source = Path(tmp) / "class.pdf"
        source.write_bytes(pdf)
        for i, (first, last) in enumerate(ranges):
            pattern = str(Path(tmp) / f"s{i}-%d.pdf")
            subprocess.run([str(tools["pdfseparate"]), "-f", str(first), "-l", str(last), str(source), pattern],
                           check=True, capture_output=True, timeout=120)
            pages = [str(Path(tmp) / f"s{i}-{n}.pdf") for n in range(first, last + 1)]
            target = Path(tmp) / f"sheet-{i}.pdf"
            if len(pages) == 1:
                target = Path(pages[0])
            else:
                subprocess.run([str(tools["pdfunite"]), *pages, str(target)], check=True, capture_output=True,
                               timeout=120)
            out.append(target.read_bytes())
    return out


def _named(sheet: Sheet, err: TeXFailedError) -> TeXFailedError:
    who = one_line(f"{sheet.student_id} ({sheet.student_name})" if sheet.student_name else sheet.student_id)
    return type(err)(f"the sheet of student {who[:120]} could not be typeset: {err}")


def _failing_sheet(sheets: list[Sheet], solutions: bool) -> tuple[Sheet, TeXFailedError] | None:
    """Bisect for one sheet that does not compile on its own (None if every half compiles)."""
    while len(sheets) > 1:
        half = len(sheets) // 2
        for group in (sheets[:half], sheets[half:]):
            try:
                compile_pdf(render_document(group, solutions), tex_time_limit(len(group)))
            except TeXFailedError as err:
                if len(group) == 1:
                    return group[0], err
                sheets = group
                break
        else:
            return None
    return None
