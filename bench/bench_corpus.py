"""Benchmark: the theorem corpus (tests/theorems/*.thm) against its time budgets.

One JSON line per theorem: ``ours_s`` is the median of three runs of ``prove`` on the theorem as read
from its file (limit 10 s), against a budget of 1 s per theorem (``"baseline": "budget 1 s"``, so the
ratio is below 1 when a theorem is over budget), with its verdict. Then one line for the whole corpus
against a budget of 30 s, naming the five slowest theorems.
"""

from __future__ import annotations

import statistics
import time
from pathlib import Path

from timing import report

CORPUS = sorted((Path(__file__).resolve().parent.parent / "tests" / "theorems").glob("*.thm"))
THEOREM_BUDGET_S = 1.0
CORPUS_BUDGET_S = 30.0
LIMIT_S = 10.0


def main() -> None:
    from pgsym.proofs.engine import prove
    from pgsym.proofs.language import read_statement

    times = {}
    for path in CORPUS:
        claim = read_statement(path)
        runs = []
        for _ in range(3):
            t = time.perf_counter()
            verdict = prove(claim, timeout=LIMIT_S)
            runs.append(time.perf_counter() - t)
        times[path.stem] = statistics.median(runs)
        report(f"corpus_{path.stem}", times[path.stem], f"budget {THEOREM_BUDGET_S:g} s", THEOREM_BUDGET_S,
               status=str(verdict.status), expected=claim.expected)
    slowest = sorted(times, key=times.get, reverse=True)[:5]
    report("corpus_whole", sum(times.values()), f"budget {CORPUS_BUDGET_S:g} s", CORPUS_BUDGET_S,
           theorems=len(times), slowest={name: round(times[name], 3) for name in slowest})


if __name__ == "__main__":
    main()
