"""The instructor commands of the ``pgsym`` command line: ``sheet``, ``check`` and ``templates``.

They live apart from :mod:`pgsym.cli` so that ``import pgsym`` never loads the exercise package.
"""

from __future__ import annotations

import keyword
import re
import sys
from pathlib import Path

import click

from ..errors import PgsymError
from ..limits import MAX_ANSWER_CHARS, MAX_FILE_BYTES
from ._common import fail

_EPILOG_SHEET = """\b
Examples:
  pgsym sheet --topics join,meet:2,cross-ratio --count 30 --seed 2026 --format md,pdf --out week4
  pgsym sheet --topics homography4:2,decompose --roster students.csv --seed 7 \\
              --format pdf,html,ipynb,qti,moodle --out quiz
  pgsym sheet --templates my_templates --topics midpoint --count 5 --seed 1 --solutions-in-sheets --out demo

\b
Topics are template names, optionally with a level (topic:level); 'pgsym templates list' shows them.
A variant is fixed by (seed, student id, topic and its occurrence), so reordering or adding topics
keeps the other exercises. The output folder must be new or empty; on any error (or Ctrl-C) nothing
is left behind. One run writes, for each format, the student sheets, the answer key (every
student's worked solutions) and the key table (student x question -> canonical answer):
  manifest.json                     the answer key read by 'pgsym check'
  md/ html/ ipynb/                  student sheets (no solutions unless --solutions-in-sheets)
  key/md/ key/html/ key/ipynb/      the answer key, one file per student
  key-table.md .html .ipynb         the key table of the class
  sheets.tex/.pdf key.tex/.pdf key-table.tex/.pdf
  moodle.xml                        Moodle XML (one category per topic)
  qti.zip                           Canvas QTI 1.2 (a question bank per topic, a quiz of question groups)
HTML pages carry their math as MathML: no script, no network, nothing to install.

\b
Names, ids and titles are printed as text in every format, never run as LaTeX, Markdown, HTML,
XML or Cloze; PDFs print every script (LuaLaTeX with the Noto fonts: 'make system-deps').
LuaLaTeX runs without shell escape, with openin_any=p and openout_any=p, in a temporary
folder, for at most 30 s + 2 s per sheet; a sheet that fails names its student."""

_EPILOG_CHECK = f"""\b
Examples:
  pgsym check --manifest week4/manifest.json --answers answers.csv
  pgsym check --manifest week4/manifest.json --answers answers.csv --out grades.csv
  pgsym check --manifest week4/manifest.json --answers answers.csv --report week4-report \\
              --canvas canvas.csv --canvas-title "Week 4" --canvas-id 1234

\b
answers.csv is either wide (header: id,1,2,3a,3b,...; one row per student) or long
(header: id,question,answer). Homogeneous answers are right up to a nonzero scale; fractions
such as -2/3, decimals and 0 are read exactly; nothing typed is ever evaluated as code.
The file may hold at most {MAX_FILE_BYTES // 1_000_000} MB, one answer at most {MAX_ANSWER_CHARS} characters.
An answer that cannot be read (too long, not a number, vector or matrix) or a question
answered twice costs only that answer: it counts as wrong, is listed on stderr and in
--out, and all others are graded.
A wrong answer that is a common mistake (a sign lost, the dual object, a matrix transposed
or inverted, H applied to a line, an ideal point given as finite, a wrong scale, ...) is
named in --out, --report and with --details; the manifest holds the candidates.
--report writes index.html (no script, no network), report.json and SVG plots into a new
folder; --canvas writes Canvas's gradebook import CSV (Student, ID, SIS User ID, SIS Login
ID, Section, "Title (id)") with the number of right answers as the score.
Cells of --out, --canvas (and of the summary) that a spreadsheet would run as a formula
(starting with = + - @, tab or carriage return) get a leading ' as OWASP recommends.

\b
Exit status:
  0  every answer was read and graded
  1  the manifest or the answers file could not be used (nothing graded)
  2  wrong usage (a missing or bad option)
  3  some answers could not be read or were given twice; every other answer was graded"""

#: Exit status of 'pgsym check' when some answers were unreadable (the others are graded).
EXIT_UNREADABLE = 3



def _load_folders(folders: tuple[str, ...]) -> None:
    from ..exercises.template import load_template_folder  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    for folder in folders:
        try:
            load_template_folder(folder)
        except PgsymError as err:
            raise fail(err) from None


def _progress(total: int, label: str, show: bool):  # type: ignore[no-untyped-def]
    if show:
        return click.progressbar(length=total, label=label, file=sys.stderr)
    return _NoBar()


class _NoBar:
    def __enter__(self) -> _NoBar:
        return self

    def __exit__(self, *args: object) -> None:
        return None

    def update(self, n: int) -> None:
        return None


@click.command("sheet", epilog=_EPILOG_SHEET)
@click.option("--topics", required=True, help="Comma-separated topics, each optionally topic:level.")
@click.option("--count", type=click.IntRange(1, 100_000), default=1, show_default=True,
              help="Number of anonymous forms (ignored with --roster).")
@click.option("--seed", type=int, default=0, show_default=True, help="Master seed of the whole set.")
@click.option("--roster", type=click.Path(dir_okay=False), help="CSV with an 'id' column (and optionally 'name').")
@click.option("--format", "formats", default="md", show_default=True,
              help="Comma-separated: md,tex,pdf,html,ipynb,moodle,qti.")
@click.option("--level", type=click.IntRange(1, 9), default=1, show_default=True,
              help="Level of topics given without one.")
@click.option("--solutions-in-sheets", "solutions_in_sheets", is_flag=True,
              help="Put the worked solutions into the student sheets too (practice sheets).")
@click.option("--solutions", "old_solutions", is_flag=True, hidden=True,
              help="Deprecated spelling of --solutions-in-sheets.")
@click.option("--key/--no-key", default=True, show_default=True,
              help="Also write the answer key and the key table.")
@click.option("--out", "out", required=True, type=click.Path(file_okay=False), help="New (or empty) output folder.")
@click.option("--templates", "template_dirs", multiple=True, type=click.Path(file_okay=False),
              help="Folder of instructor templates (*.py); may be repeated.")
@click.option("--mathjax", type=click.Path(file_okay=False), hidden=True,
              help="Deprecated and ignored: the HTML pages carry MathML and need no MathJax.")
@click.option("--progress/--no-progress", default=None, help="Show a progress bar (default: for 50 sheets or more).")
def sheet_command(topics: str, count: int, seed: int, roster: str | None, formats: str, level: int,
                  solutions_in_sheets: bool, old_solutions: bool, key: bool, out: str, template_dirs: tuple[str, ...],
                  mathjax: str | None, progress: bool | None) -> None:
    """Generate per-student exercise sheets, their answer key and key table, in every requested format."""
    from ..atomic import Terminated, write_new_folder  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.output import parse_formats, render_all  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.sheets import anonymous_students, build_sheets, parse_topics, read_roster  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    if old_solutions:
        click.echo("warning: --solutions is deprecated; use --solutions-in-sheets (the answer key is written "
                   "in any case, under key/)", err=True)
    if mathjax:
        click.echo("warning: --mathjax is deprecated and ignored; the HTML sheets carry their math as MathML "
                   "and need no MathJax", err=True)
    solutions = solutions_in_sheets or old_solutions
    _load_folders(template_dirs)
    try:
        fmt = parse_formats(formats)
    except ValueError as err:
        raise click.BadParameter(str(err), param_hint="--format") from None
    try:
        pairs = parse_topics(topics, level)
        students = read_roster(roster) if roster else anonymous_students(count)
        show = progress if progress is not None else len(students) >= 50
        with _progress(len(students), "building sheets", show) as bar:
            sheets = build_sheets(pairs, students, seed, progress=bar.update)
        with _progress(len(students), "rendering", show) as bar:
            target = write_new_folder(out, lambda tmp: render_all(sheets, pairs, fmt, tmp, solutions,
                                                                  progress=bar.update, key=key))
    except PgsymError as err:
        raise fail(err) from None
    except Terminated:
        click.echo("stopped by SIGTERM; nothing was written", err=True)
        sys.exit(143)
    what = "sheets, answer key and key table" if key else "sheets"
    click.echo(f"{len(sheets)} sheet(s) × {len(pairs)} exercise(s) → {target} ({what} as {', '.join(fmt)}; "
               "manifest.json)")


@click.command("check", epilog=_EPILOG_CHECK)
@click.option("--manifest", required=True, type=click.Path(dir_okay=False),
              help="manifest.json written by 'pgsym sheet'.")
@click.option("--answers", required=True, type=click.Path(dir_okay=False), help="CSV of typed answers.")
@click.option("--out", type=click.Path(dir_okay=False),
              help="Also write every graded answer, with the mistake recognised and its feedback, to this CSV.")
@click.option("--report", "report_dir", type=click.Path(file_okay=False),
              help="Write a grade report (index.html, report.json, SVG plots) into this new or empty folder.")
@click.option("--canvas", type=click.Path(dir_okay=False), help="Write a Canvas gradebook CSV to import.")
@click.option("--canvas-title", default="pgsym exercises", show_default=True,
              help="Assignment title of the Canvas column.")
@click.option("--canvas-id", type=click.IntRange(1), help="Canvas id of an existing assignment (column 'Title (id)').")
@click.option("--details", is_flag=True, help="Print every wrong or unreadable answer.")
@click.pass_context
def check_command(ctx: click.Context, manifest: str, answers: str, out: str | None, report_dir: str | None,
                  canvas: str | None, canvas_title: str, canvas_id: int | None, details: bool) -> None:
    """Grade the answers of every student against the manifest, naming the common mistakes."""
    from ..atomic import Terminated, write_new_folder  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..csv_cells import csv_text  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..escaping import clean  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.grading import grade_rows, read_answer_file, results_csv, summary  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.sheets import load_manifest_data  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    try:
        data = load_manifest_data(manifest)
        rows, problems = read_answer_file(answers)
        report = grade_rows(data.keys, rows, data.mistakes)
    except PgsymError as err:
        raise fail(err) from None
    click.echo(csv_text([["student", "right", "questions"], *summary(report)]), nl=False)
    unreadable = [r for rs in report.values() for r in rs if r.unreadable]
    for rs in report.values():
        for r in rs:
            if r.reason and (details or r.unreadable or "manifest" in r.reason):
                text = f"  {r.student} [{r.label}]: {r.reason}" + (f" ({r.feedback})" if r.feedback else "")
                click.echo(clean(text)[:1000], err=True)
    for message in problems:
        click.echo(clean(f"  {message}")[:1000], err=True)
    if unreadable or problems:
        click.echo(f"{len(unreadable)} answer(s) could not be read or were given twice, and {len(problems)} line(s) "
                   "of the answers file were skipped (see above); every other answer was graded.", err=True)
    try:
        if report_dir:
            from ..exercises.report import report_data, write_report  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

            numbers = report_data(report, data.names, data.topics, problems)
            title = f"Grade report: {Path(manifest).resolve().parent.name or 'exercises'}"
            write_new_folder(report_dir, lambda tmp: write_report(tmp, numbers, title))
        if canvas:
            from ..exercises.canvas import canvas_csv  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

            _write_text(Path(canvas), canvas_csv(report, data.names, canvas_title, canvas_id))
        if out:
            _write_text(Path(out), results_csv(report, problems))
    except PgsymError as err:
        raise fail(err) from None
    except Terminated:
        click.echo("stopped by SIGTERM; the file being written was left out", err=True)
        sys.exit(143)
    if unreadable or problems:
        ctx.exit(EXIT_UNREADABLE)


def _write_text(path: Path, text: str) -> None:
    """Write ``path`` complete or not at all (:func:`pgsym.atomic.replace_file`), readable as the umask allows."""
    import os  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    from ..atomic import replace_file  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    def fill(tmp: Path) -> None:
        tmp.write_text(text, encoding="utf-8", newline="")
        mask = os.umask(0)
        os.umask(mask)
        tmp.chmod(0o666 & ~mask)  # the temporary file is private; the result should not be

    replace_file(path, fill)


@click.group("templates")
def templates_group() -> None:
    """List, create and stress-test exercise templates."""


@templates_group.command("list")
@click.option("--templates", "template_dirs", multiple=True, type=click.Path(file_okay=False))
def templates_list(template_dirs: tuple[str, ...]) -> None:
    """List the known topics with their levels."""
    from ..exercises.template import all_templates  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    _load_folders(template_dirs)
    for name, t in sorted(all_templates().items()):
        click.echo(f"{name:14s} levels {','.join(map(str, t.levels))}  {t.title}")


_SKELETON = '''"""Instructor template {name!r}: the midpoint of two points (a working skeleton to edit).

Use it with:  pgsym sheet --templates {folder} --topics {name} --count 3 --seed 1 --out demo
Check it with: pgsym templates check {name} --templates {folder}
"""

from fractions import Fraction

from pgsym.exercises.model import Answer
from pgsym.exercises.template import Draft, Template, check
from pgsym.exercises.model import tuple_latex
from pgsym.projective_plane import Point


class {cls}(Template):
    """The midpoint of two points. Level 1: integer midpoint; level 2: fractions allowed."""

    name = "{name}"
    title = "The midpoint of two points"
    levels = (1, 2)
    max_entry = 100

    def build(self, rng, level):
        # build backwards from the answer: choose the midpoint m and an offset d, then p = m - d, q = m + d
        step = Fraction(1) if level == 1 else Fraction(1, 2)
        m = (rng.randint(-5, 5) * step, rng.randint(-5, 5) * step)
        d = (rng.randint(1, 4), rng.randint(-4, 4))  # d != 0, so p != q
        p = (m[0] - d[0], m[1] - d[1])
        q = (m[0] + d[0], m[1] + d[1])
        statement = f"Let $p = {{tuple_latex(p)}}$ and $q = {{tuple_latex(q)}}$."
        prompt = "Give the midpoint of $p$ and $q$."
        steps = [f"$\\\\tfrac{{1}}{{2}}(p + q) = {{tuple_latex(m)}}$."]
        return Draft(statement, [(prompt, Answer.vector(m), ())], steps,
                     {{"p": [str(x) for x in p], "q": [str(x) for x in q]}})

    def verify(self, exercise):
        # re-check with pgsym, independently of build(): the midpoint lies on the line pq, half-way
        p = Point(*(Fraction(x) for x in exercise.params["p"]))
        q = Point(*(Fraction(x) for x in exercise.params["q"]))
        check(p != q, "the two points coincide")
        m = exercise.parts[0].answer.value
        (px, py), (qx, qy) = p.dehomogenize(), q.dehomogenize()
        check(2 * m[0] == px + qx and 2 * m[1] == py + qy, "wrong midpoint")
'''


@templates_group.command("new")
@click.argument("name")
@click.option("--dir", "folder", default="templates", show_default=True, type=click.Path(file_okay=False),
              help="Folder to write NAME.py into (created if missing).")
def templates_new(name: str, folder: str) -> None:
    """Write a working template skeleton NAME.py (the midpoint of two points) to edit.

    Example: pgsym templates new midpoint --dir my_templates
    """
    if not re.fullmatch(r"[a-z][a-z0-9_]{0,40}", name) or keyword.iskeyword(name):
        raise click.BadParameter("use lower-case letters, digits and '_', starting with a letter", param_hint="NAME")
    path = Path(folder) / f"{name}.py"
    if path.exists():
        raise click.ClickException(f"{path} exists already; choose another name or delete it")
    cls = "".join(part.capitalize() for part in name.split("_")) + "Template"
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        with path.open("x", encoding="utf-8") as stream:  # "x": never through a dangling link or over a file
            stream.write(_SKELETON.format(name=name, cls=cls, folder=folder))
    except FileExistsError:
        raise click.ClickException(f"{path} exists already; choose another name or delete it") from None
    except OSError as err:
        raise click.ClickException(f"cannot write {path}: {err.strerror or err}") from None
    click.echo(f"wrote {path}; try: pgsym templates check {name} --templates {folder}")


@templates_group.command("check")
@click.argument("name", required=False)
@click.option("--seeds", type=click.IntRange(1, 1_000_000), default=10_000, show_default=True,
              help="Number of seeds (one instance each, cycling through the levels).")
@click.option("--templates", "template_dirs", multiple=True, type=click.Path(file_okay=False))
@click.option("--progress/--no-progress", default=None, help="Show a progress bar (default: on a terminal).")
def templates_check(name: str | None, seeds: int, template_dirs: tuple[str, ...], progress: bool | None) -> None:
    """Stress-test one template (or all): degenerate instances, independent re-verification, answer sizes,
    multiple-choice key spread.

    Example: pgsym templates check join --seeds 10000
    """
    from ..exercises.stress import stress  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.template import all_templates, get_template  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    _load_folders(template_dirs)
    try:
        templates = [get_template(name)] if name else list(all_templates().values())
    except PgsymError as err:
        raise fail(err) from None
    failed = False
    for t in templates:
        show = progress if progress is not None else sys.stderr.isatty()
        with _progress(seeds, f"{t.name}", show) as bar:
            report = stress(t, seeds, progress=bar.update)
        for line in report.lines():
            click.echo(line)
        failed = failed or not report.ok
    if failed:
        raise click.ClickException("some template checks failed (see above)")
