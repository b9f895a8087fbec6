"""Benchmark: AlphaGeometry's problem sets (tests/data/alphageometry) translated and proved.

Every problem is translated (:mod:`pgsym.proofs.alphageometry`) and proved with the engine's timeout of
10 s, each in a child process stopped at 30 s (then it counts as unknown); its time is the translation's and
the proof's. One JSON line per set: the
counts proved / unknown / wrong / unsupported / errors; the median time of the translated problems
(``median_s``, seconds, a timeout counting as its time) and of the proved ones (``median_proved_s``);
``wrong_either``, the wrong ones whose translation lets either common point of a line and a circle (or
two circles) be taken, as AlphaGeometry takes one at random (such a problem may hold on one branch
only); and how often each unsupported construction refused a problem. Every problem of the files is a
true theorem, so a refutation is wrong. ``--verbose`` adds one JSON line per problem; ``--only N`` runs
the first N problems of each set.

    python bench/bench_alphageometry.py [--verbose] [--only N]
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
from collections import Counter
from pathlib import Path

from timing import run_with_timeout

DATA = Path(__file__).resolve().parent.parent / "tests" / "data" / "alphageometry"
SETS = ("imo_ag_30.txt", "jgex_ag_231.txt")
LIMIT_S = 10.0
HARD_LIMIT_S = 30.0
EITHER = re.compile(r"=\s*intersection\b")


def _solve(name: str, text: str) -> dict:
    """The outcome of one problem, translated and proved in a child process, as plain words."""
    from pgsym.proofs.alphageometry import read_alphageometry, solve

    [problem] = read_alphageometry(f"{name}\n{text}")
    outcome = solve(problem, timeout=LIMIT_S)
    return {"status": outcome.status, "message": outcome.message[:200],
            "reason": str(getattr(outcome.verdict, "reason", "") or "")[:200]}


def main() -> None:
    from pgsym.proofs.alphageometry import read_alphageometry_file

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--verbose", action="store_true")
    parser.add_argument("--only", type=int, default=0)
    options = parser.parse_args()
    for name in SETS:
        path = DATA / name
        problems = read_alphageometry_file(path)
        lines = path.read_text(encoding="utf-8").splitlines()
        if options.only:
            problems = problems[:options.only]
        counts: Counter[str] = Counter()
        unsupported: Counter[str] = Counter()
        times, proved_times = [], []
        for problem in problems:
            elapsed, result = run_with_timeout(_solve, (problem.name, lines[problem.line - 1]), HARD_LIMIT_S)
            if elapsed is None:
                elapsed, result = HARD_LIMIT_S, {"status": "unknown", "message": "", "reason": "stopped at 30 s"}
            status = result["status"]
            wrong = status == "refuted"
            either = bool(problem.statement and EITHER.search(problem.statement))
            counts["wrong" if wrong else status] += 1
            counts["wrong_either"] += wrong and either
            if problem.error is None:
                times.append(elapsed)
            if status == "proved":
                proved_times.append(elapsed)
            if problem.error is not None:
                unsupported[getattr(problem.error, "construction", "") or "?"] += 1
            if options.verbose:
                print(json.dumps({"set": name, "problem": problem.name, "status": "wrong" if wrong else status,
                                  "seconds": round(elapsed, 3), "either_branch": either,
                                  "message": result["message"] or result["reason"]}, ensure_ascii=False),
                      flush=True)
        print(json.dumps({"set": name, "problems": len(problems), "proved": counts["proved"],
                          "unknown": counts["unknown"], "wrong": counts["wrong"],
                          "wrong_either": counts["wrong_either"], "unsupported": counts["unsupported"],
                          "errors": counts["error"],
                          "median_s": round(statistics.median(times), 3) if times else None,
                          "median_proved_s": round(statistics.median(proved_times), 3) if proved_times else None,
                          "unsupported_constructions": dict(unsupported.most_common())}), flush=True)


if __name__ == "__main__":
    main()
