"""Benchmark: exercise sheets for a class, the stress check of one template, and grading.

Prints one JSON line per case:

* ``sheets``: 200 students × 8 exercises in one ``pgsym sheet`` run with every format: student sheets,
  answer key and key table as Markdown, HTML (MathML), notebooks, LaTeX and PDF (three LuaLaTeX
  documents, side by side), plus Moodle XML and the Canvas QTI package (budget 20 s for everything);
* ``stress``: ``pgsym templates check join`` over 10⁴ seeds (one instance per seed, the levels in
  turn; budget 30 s);
* ``grading``: grading 200 × 8 typed answers with the hand-written parser and canonical forms
  (``ours_s``) against the naive route (``baseline_s``): ``sympy.sympify`` of the typed text and an
  up-to-scale test by the rank of the 2-row matrix [answer; key]. The baseline evaluates the
  student's text as a SymPy expression, which is exactly what the parser exists to avoid; it is
  here only to show the price of the naive route;
* ``report``: ``pgsym check --report --canvas --out`` for 200 students × 8 exercises (a third of the
  wrong answers recognised mistakes): read the manifest and the answers, grade, recognise, and write
  the HTML/JSON/SVG report, the Canvas CSV and the graded CSV (budget 2 s; ``cold_s`` includes
  importing Matplotlib).
"""

from __future__ import annotations

import os
import resource
import statistics
import tempfile
import time
from pathlib import Path

from timing import report

TOPICS = ["homogeneous", "join", "meet:2", "ideal:2", "apply-point:2", "cross-ratio", "plane3", "classify:2"]


def _cpu_seconds() -> float:
    """CPU time of this process and of its finished children (the TeX runs)."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def _sheets_once() -> tuple[float, int, float]:
    from pgsym.exercises.output import render_all
    from pgsym.exercises.sheets import anonymous_students, build_sheets, parse_topics

    t0, c0 = time.perf_counter(), _cpu_seconds()
    pairs = parse_topics(TOPICS)
    sheets = build_sheets(pairs, anonymous_students(200), master_seed=2026)
    with tempfile.TemporaryDirectory() as tmp:
        files = render_all(sheets, pairs, ["md", "tex", "pdf", "html", "ipynb", "moodle", "qti"], Path(tmp))
    return time.perf_counter() - t0, len(files), _cpu_seconds() - c0


def _sheets() -> tuple[float, float, int, float]:
    """(first run, which also imports the templates and SymPy; median of three warm runs; files; median CPU
    seconds of the warm runs, Python and TeX together: the wall time on an idle machine is about this over
    the number of cores, since TeX runs beside the Python rendering)."""
    cold, files, _ = _sheets_once()
    warm = [_sheets_once() for _ in range(3)]
    return (cold, statistics.median(w[0] for w in warm), files, statistics.median(w[2] for w in warm))


def _stress() -> tuple[float, int, bool]:
    from pgsym.exercises.stress import stress
    from pgsym.exercises.template import get_template

    t0 = time.perf_counter()
    report = stress(get_template("join"), seeds=10_000)
    return time.perf_counter() - t0, report.instances, report.ok


def _answers() -> list[tuple[object, str]]:
    from pgsym.exercises.sheets import anonymous_students, build_sheets

    sheets = build_sheets(TOPICS, anonymous_students(200), master_seed=7)
    out = []
    for i, sheet in enumerate(sheets):
        for ex in sheet.exercises:
            for part in ex.parts:
                if part.answer.kind in ("projective", "vector", "scalar", "integer"):
                    text = part.answer.display()
                    if part.answer.kind == "projective" and i % 2:
                        text = "(" + ", ".join(str(-3 * v) for v in part.answer.value) + ")"
                    out.append((part.answer, text))
    return out


def _grade_ours(items: list) -> tuple[float, int]:
    from pgsym.exercises.answers import grade

    t0 = time.perf_counter()
    right = sum(grade(answer, text) for answer, text in items)
    return time.perf_counter() - t0, right


def _grade_naive(items: list) -> tuple[float, int]:
    import sympy

    t0 = time.perf_counter()
    right = 0
    for answer, text in items:
        value = sympy.sympify(text)  # the naive route: evaluates the typed text
        got = list(value) if isinstance(value, (tuple, sympy.Tuple)) else [value]
        key = [sympy.Rational(str(v)) for v in answer.flat()]
        if answer.kind == "projective":
            ok = len(got) == len(key) and sympy.Matrix([got, key]).rank() == 1
        else:
            ok = len(got) == len(key) and all(sympy.Rational(g) == k for g, k in zip(got, key, strict=True))
        right += bool(ok)
    return time.perf_counter() - t0, right


def _class_files(folder: Path) -> tuple[Path, Path]:
    """The manifest of 200 students and their typed answers: right, a stored mistake, other wrong, blank."""
    import csv
    import random

    from pgsym.exercises.model import Answer
    from pgsym.exercises.sheets import anonymous_students, build_sheets, manifest_json, parse_topics

    pairs = parse_topics(TOPICS)
    sheets = build_sheets(pairs, anonymous_students(200), master_seed=11)
    rng = random.Random(5)
    rows = [["id", "question", "answer"]]
    for sheet in sheets:
        for ex in sheet.exercises:
            for part in ex.parts:
                key, r = part.answer, rng.random()
                same = [m for m in part.mistakes if m.answer.kind == key.kind]
                if r < 0.6:
                    text = key.display()
                elif r < 0.8 and same:
                    text = rng.choice(same).answer.display()
                elif r < 0.95:  # some other wrong answer (all ones: rarely right)
                    if key.kind == "choice" or key.kind in ("scalar", "integer"):
                        text = "B" if key.kind == "choice" else "7"
                    elif key.kind.startswith("matrix"):
                        text = Answer.matrix_exact([[1] * len(row) for row in key.value]).display()
                    else:
                        text = Answer.vector([1] * len(key.value)).display()
                else:
                    continue
                rows.append([sheet.student_id, part.label, text])
    (folder / "manifest.json").write_text(manifest_json(sheets, pairs))
    with (folder / "answers.csv").open("w", newline="") as f:
        csv.writer(f).writerows(rows)
    return folder / "manifest.json", folder / "answers.csv"


def _report_once(manifest: Path, answers: Path, out: Path) -> dict:
    from pgsym.atomic import write_new_folder
    from pgsym.exercises.canvas import canvas_csv
    from pgsym.exercises.grading import grade_rows, read_answer_file, results_csv
    from pgsym.exercises.report import report_data, write_report
    from pgsym.exercises.sheets import load_manifest_data

    data = load_manifest_data(manifest)
    rows, problems = read_answer_file(answers)
    graded = grade_rows(data.keys, rows, data.mistakes)
    numbers = report_data(graded, data.names, data.topics, problems)
    write_new_folder(out / "report", lambda tmp: write_report(tmp, numbers))
    (out / "canvas.csv").write_text(canvas_csv(graded, data.names, "Week 4"))
    (out / "grades.csv").write_text(results_csv(graded, problems))
    return numbers["summary"]


def _report() -> tuple[float, float, dict]:
    """(first run, with Matplotlib's import; median of three warm runs; the summary of the report)."""
    with tempfile.TemporaryDirectory() as tmp:
        manifest, answers = _class_files(Path(tmp))
        times = []
        for i in range(4):
            out = Path(tmp) / f"run{i}"
            out.mkdir()
            t0 = time.perf_counter()
            summary = _report_once(manifest, answers, out)
            times.append(time.perf_counter() - t0)
    return times[0], statistics.median(times[1:]), summary


def main() -> None:
    # the rendering and the stress check have no naive counterpart: they are reported against the budgets
    cold, seconds, files, cpu = _sheets()
    report("exercises_200_students_x8_all_formats_sheets_key_table_pdf_qti", seconds, "budget 20 s", 20.0,
           cold_s=round(cold, 3), files=files, cpu_s=round(cpu, 2), cores=os.cpu_count(),
           load_average=round(os.getloadavg()[0], 2))
    seconds, instances, ok = _stress()
    report("exercises_stress_join_10000_seeds", seconds, "budget 30 s", 30.0, instances=instances, all_ok=ok)
    items = _answers()
    ours, right = _grade_ours(items)
    base, base_right = _grade_naive(items)
    report(f"exercises_grading_{len(items)}_answers", ours, "sympy.sympify of the typed text + Matrix.rank up to scale",
           base, right=right, baseline_right=base_right)
    cold, seconds, summary = _report()
    report("exercises_check_report_200_students", seconds, "budget 2 s", 2.0, cold_s=round(cold, 3),
           answers=summary["answers"], wrong=summary["wrong"], recognised=summary["recognised"])

if __name__ == "__main__":
    main()
