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
                                    (each sheet on its own pages: it starts on an odd page, its
                                    pages are numbered from 1)
  pdf/ key/pdf/                     one PDF per student (with --format pdf)
  stack.xml                         Moodle STACK questions: graded up to scale in Moodle, with
                                    pgsym's mistake feedback and the worked solution
  moodle.xml                        Moodle Cloze questions (each box compared with the canonical
                                    form; the questions say so: prefer stack.xml)
  qti.zip                           Canvas QTI 1.2: a question bank per exercise, a quiz whose
                                    question groups draw one variant from each bank
HTML pages carry their math as MathML: no script, no network, nothing to install.
Student notebooks check each typed answer against salted digests of the key: a practice aid,
not a secret (answers with few possible values are found from the digests by trying them in
under a second). For a graded sheet use --no-self-check: the notebooks only collect answers.

\b
--roster reads class lists as spreadsheets and platforms save them: separated by ',', ';', tab
or '|' (or Excel's 'sep=' line), in UTF-8, UTF-16 (Excel "Unicode text") or Windows-1252. The id
is the first of: SIS User ID (Canvas gradebook export; 'Student' is the name, the Points
Possible row is skipped), ID number (Moodle; first and last name joined), Student ID /
student number / registration (R/exams), id; --roster-id-column chooses another column.

\b
Moodle and Canvas round trip:
  pgsym sheet --topics join,classify:2 --roster students.csv --seed 7 --format stack,qti --out week4
  (import stack.xml or qti.zip, give the quiz, download its report, then 'pgsym check')
Every question carries its variant id (F-0123456789#1: form id and slot) in its title and text
(STACK: in its question note), so a quiz may draw variants at random and 'pgsym check' still
grades each answer against the variant the student saw. Canvas compares answers as strings and
never up to scale, so Canvas does not grade these questions: they are essays, and pgsym grades
the answers from Canvas's Student Analysis report. STACK grades them in Moodle itself.
--points TOPIC=P sets the points of each part (join=2, classify=1+3 per part; default=1): the
manifest stores them and every output uses them (QTI points, STACK marks, gradebooks, report).

\b
Names, ids and titles are printed as text in every format, never run as LaTeX, Markdown, HTML,
XML or Cloze; PDFs print every character an installed Noto font has (LuaLaTeX; 'make system-deps'
installs the Noto fonts and colour emoji), and a character no installed font has stops the run
naming the student and the character, never an empty box.
LuaLaTeX runs without shell escape, with openin_any=p and openout_any=p, in a temporary
folder, for at most 30 s + 2 s per sheet; a sheet that fails names its student."""

_EPILOG_CHECK = f"""\b
Examples:
  pgsym check --manifest week4/manifest.json --answers answers.csv
  pgsym check --manifest week4/manifest.json --answers answers.csv --out grades.csv
  pgsym check --manifest week4/manifest.json --answers answers.csv --report week4-report \\
              --canvas canvas.csv --canvas-title "Week 4" --canvas-id 1234
  pgsym check --manifest week4/manifest.json --answers student-analysis.csv \\
              --canvas gradebook.csv --feedback week4-feedback
  pgsym check --manifest week4/manifest.json --answers responses.csv \\
              --moodle-grades grades-import.csv --feedback week4-feedback

\b
--answers is one of (detected from its header):
  a pgsym answers CSV, wide (header: id,1,2,3a,3b,...; one row per student) or long
    (header: id,question,answer);
  Canvas's quiz "Student Analysis" report (Quiz Statistics > Student Analysis): columns
    name, id, sis_id, then "<question id>: <question text>" per question (the text holds the
    variant id), n correct, n incorrect, score; a multi-part answer has one line per part;
  Moodle's quiz "Responses" report of the STACK questions, downloaded with "Question text"
    ticked: identity columns, State, "Question N" (the variant id) and "Response N".
A report whose questions carry no variant id of the manifest is an error, never zeros.
Homogeneous answers are right up to a nonzero scale; fractions
such as -2/3, decimals and 0 are read exactly; nothing typed is ever evaluated as code.
The file may hold at most {MAX_FILE_BYTES // 1_000_000} MB, one answer at most {MAX_ANSWER_CHARS} characters.
An answer that cannot be read (too long, not a number, vector or matrix) or a question
answered twice costs only that answer: it counts as wrong, is listed on stderr and in
--out, and all others are graded.
A wrong answer that is a common mistake (a sign lost, the dual object, a matrix transposed
or inverted, H applied to a line, an ideal point given as finite, a wrong scale, ...) is
named in --out, --report and with --details; the manifest holds the candidates.
--report writes index.html (no script, no network), report.json and SVG plots into a new
folder; --feedback writes one HTML page per student (their answers, the verdicts, the mistakes
explained, the worked solutions) and an index into a new folder; --canvas writes Canvas's
gradebook import CSV (Student, ID, SIS User ID, SIS Login ID, Section, "Title (id)");
--moodle-grades writes a CSV for Moodle's grade import (Email address, ID number, Username,
Full name, the grade, Feedback). Scores are points: each part earns its points when right
(set by 'pgsym sheet --points'; 1 per part by default), the same in every output.
Cells of --out, --canvas, --moodle-grades (and of the summary) that a spreadsheet would run as a formula
(starting with = + - @, tab or carriage return) get a leading ' as OWASP recommends.

\b
Exit status:
  0  every answer was read and graded
  1  the manifest or the answers file could not be used (nothing graded)
  2  wrong usage (a missing or bad option)
  3  some answers could not be read or were given twice; every other answer was graded"""

#: Exit status of 'pgsym check' when some answers were unreadable (the others are graded).
EXIT_UNREADABLE = 3



_REPLACE_HELP = "Let a template of --templates replace a built-in one of the same name (refused otherwise)."


def _load_folders(folders: tuple[str, ...], replace: bool = False) -> None:
    from ..exercises.registry import load_template_folder  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    for folder in folders:
        try:
            load_template_folder(folder, replace)
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
@click.option("--roster", type=click.Path(dir_okay=False),
              help="Class list: CSV (',' ';' tab), UTF-8/UTF-16/Windows-1252, or a Canvas/Moodle export.")
@click.option("--roster-id-column", "roster_id_column", metavar="HEADER",
              help="Take the student id from this column (default: SIS User ID, ID number, Student ID, id, ...).")
@click.option("--format", "formats", default="md", show_default=True,
              help="Comma-separated: md,tex,pdf,html,ipynb,moodle,stack,qti.")
@click.option("--points", "points_spec", default="", metavar="TOPIC=P[+P...],...",
              help="Points of each part, e.g. 'join=2,classify=1+3,default=1' (default: a template's own "
                   "points, else 1 per part); every output and gradebook uses them.")
@click.option("--level", type=click.IntRange(1, 9), default=1, show_default=True,
              help="Level of topics given without one.")
@click.option("--solutions-in-sheets", "solutions_in_sheets", is_flag=True,
              help="Put the worked solutions into the student sheets too (practice sheets).")
@click.option("--solutions", "old_solutions", is_flag=True, hidden=True,
              help="Deprecated spelling of --solutions-in-sheets.")
@click.option("--key/--no-key", default=True, show_default=True,
              help="Also write the answer key and the key table.")
@click.option("--self-check/--no-self-check", "self_check", default=True, show_default=True,
              help="Student notebooks check each answer (practice: the digests can be brute-forced; "
                   "use --no-self-check for a graded sheet).")
@click.option("--out", "out", required=True, type=click.Path(file_okay=False), help="New (or empty) output folder.")
@click.option("--templates", "template_dirs", multiple=True, type=click.Path(file_okay=False),
              help="Folder of instructor templates (*.py); may be repeated.")
@click.option("--replace-templates", "replace_templates", is_flag=True, help=_REPLACE_HELP)
@click.option("--mathjax", type=click.Path(file_okay=False), hidden=True,
              help="Deprecated and ignored: the HTML pages carry MathML and need no MathJax.")
@click.option("--progress/--no-progress", default=None, help="Show a progress bar (default: for 50 sheets or more).")
def sheet_command(topics: str, count: int, seed: int, roster: str | None, roster_id_column: str | None,
                  formats: str, points_spec: str, level: int,
                  solutions_in_sheets: bool, old_solutions: bool, key: bool, self_check: bool, out: str,
                  template_dirs: tuple[str, ...], replace_templates: bool, mathjax: str | None,
                  progress: bool | None) -> None:
    """Generate per-student exercise sheets, their answer key and key table, in every requested format."""
    from ..atomic import Terminated, write_new_folder  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.output import parse_formats, render_all  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.points import parse_points  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.sheets import anonymous_students, build_sheets, parse_topics, read_roster  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    if old_solutions:
        click.echo("warning: --solutions is deprecated; use --solutions-in-sheets (the answer key is written "
                   "in any case, under key/)", err=True)
    if mathjax:
        click.echo("warning: --mathjax is deprecated and ignored; the HTML sheets carry their math as MathML "
                   "and need no MathJax", err=True)
    solutions = solutions_in_sheets or old_solutions
    _load_folders(template_dirs, replace_templates)
    try:
        fmt = parse_formats(formats)
    except ValueError as err:
        raise click.BadParameter(str(err), param_hint="--format") from None
    try:
        pairs = parse_topics(topics, level)
        points = parse_points(points_spec)
        notes: list[str] = []
        students = read_roster(roster, roster_id_column, notes) if roster else anonymous_students(count)
        for note in notes:
            click.echo(f"note: {note}", err=True)
        show = progress if progress is not None else len(students) >= 50
        with _progress(len(students), "building sheets", show) as bar:
            sheets = build_sheets(pairs, students, seed, progress=bar.update, points=points)
        with _progress(len(students), "rendering", show) as bar:
            target = write_new_folder(out, lambda tmp: render_all(sheets, pairs, fmt, tmp, solutions,
                                                                  progress=bar.update, key=key,
                                                                  self_check=self_check))
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
@click.option("--answers", required=True, type=click.Path(dir_okay=False),
              help="A pgsym answers CSV, Canvas's Student Analysis CSV or Moodle's Responses CSV (detected).")
@click.option("--out", type=click.Path(dir_okay=False),
              help="Also write every graded answer, with the mistake recognised and its feedback, to this CSV.")
@click.option("--report", "report_dir", type=click.Path(file_okay=False),
              help="Write a grade report (index.html, report.json, SVG plots) into this new or empty folder.")
@click.option("--feedback", "feedback_dir", type=click.Path(file_okay=False),
              help="Write one feedback page per student (answers, verdicts, mistakes, worked solutions) into "
                   "this new or empty folder.")
@click.option("--canvas", type=click.Path(dir_okay=False), help="Write a Canvas gradebook CSV to import.")
@click.option("--canvas-title", default="pgsym exercises", show_default=True,
              help="Assignment title of the Canvas (and Moodle) grade column.")
@click.option("--canvas-id", type=click.IntRange(1), help="Canvas id of an existing assignment (column 'Title (id)').")
@click.option("--moodle-grades", type=click.Path(dir_okay=False),
              help="Write a CSV for Moodle's gradebook import (Grades > Import > CSV file).")
@click.option("--details", is_flag=True, help="Print every wrong or unreadable answer.")
@click.pass_context
def check_command(ctx: click.Context, manifest: str, answers: str, out: str | None, report_dir: str | None,
                  feedback_dir: str | None, canvas: str | None, canvas_title: str, canvas_id: int | None,
                  moodle_grades: str | None, details: bool) -> None:
    """Grade the answers of every student against the manifest, naming the common mistakes."""
    from ..atomic import Terminated, write_new_folder  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..csv_cells import csv_text  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..escaping import clean  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.grading import grade_rows, read_answer_file, results_csv, score_summary  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.lms import grade_lms, read_lms_report  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.points import points_text  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.roundtrip import Graded, own_variants, people_of_manifest  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.sheets import load_manifest_data  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    try:
        data = load_manifest_data(manifest)
        lms = read_lms_report(answers, {v: labels for v, (_, labels) in data.variants.items()})
        if lms is None:
            rows, problems = read_answer_file(answers, data.keys)
            report = grade_rows(data.keys, rows, data.mistakes, data.points)
            graded = Graded(report, people_of_manifest(data), own_variants(data), list(problems), "pgsym")
        else:
            result = grade_lms(lms, data.keys, data.variants, data.mistakes, data.points)
            graded = Graded(result.report, result.people, result.variants, result.problems, lms.platform)
    except PgsymError as err:
        raise fail(err) from None
    report, problems = graded.report, graded.problems
    right = {s: (r, n) for s, r, n in ((s, sum(x.correct for x in rs), sum(x.counted for x in rs))
                                       for s, rs in report.items())}
    click.echo(csv_text([["student", "right", "questions", "score", "points"],
                         *[[s, *right[s], points_text(got), points_text(worth)]
                           for s, got, worth in score_summary(report)]]), nl=False)
    unreadable = [r for rs in report.values() for r in rs if r.unreadable]
    for rs in report.values():
        for r in rs:
            if r.reason and (details or r.unreadable or "manifest" in r.reason):
                text = f"  {r.student} [{r.label}]: {r.reason}" + (f" ({r.feedback})" if r.feedback else "")
                click.echo(clean(text)[:1000], err=True)
    for message in problems:
        click.echo(clean(f"  {message}")[:1000], err=True)
    if unreadable or problems:
        click.echo(f"{len(unreadable)} answer(s) could not be read or were given twice, and {len(problems)} "
                   "problem(s) with the answers file (see above); every other answer was graded.", err=True)
    try:
        if report_dir:
            from ..exercises.report import report_data, write_report  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

            numbers = report_data(report, graded.names, data.topics, problems)
            title = f"Grade report: {Path(manifest).resolve().parent.name or 'exercises'}"
            write_new_folder(report_dir, lambda tmp: write_report(tmp, numbers, title))
        if feedback_dir:
            from ..exercises.feedback import write_feedback  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

            write_new_folder(feedback_dir, lambda tmp: write_feedback(tmp, graded, data, canvas_title))
        if canvas:
            from ..exercises.canvas import canvas_csv  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

            _write_text(Path(canvas), canvas_csv(report, graded.names, canvas_title, canvas_id, graded.people))
        if moodle_grades:
            from ..exercises.moodle_grades import moodle_grades_csv  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

            _write_text(Path(moodle_grades), moodle_grades_csv(report, graded.people, canvas_title))
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
@click.option("--replace-templates", "replace_templates", is_flag=True, help=_REPLACE_HELP)
def templates_list(template_dirs: tuple[str, ...], replace_templates: bool) -> None:
    """List the known topics with their levels."""
    from ..exercises.registry import all_templates  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    _load_folders(template_dirs, replace_templates)
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
@click.option("--replace-templates", "replace_templates", is_flag=True, help=_REPLACE_HELP)
@click.option("--progress/--no-progress", default=None, help="Show a progress bar (default: on a terminal).")
def templates_check(name: str | None, seeds: int, template_dirs: tuple[str, ...], replace_templates: bool,
                    progress: bool | None) -> None:
    """Stress-test one template (or all): degenerate instances, independent re-verification, answer sizes,
    multiple-choice key spread.

    Example: pgsym templates check join --seeds 10000
    """
    from ..exercises.registry import all_templates, get_template  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..exercises.stress import stress  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    _load_folders(template_dirs, replace_templates)
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
