"""Benchmark: the Euclidean corpus (tests/euclid/*.thm) against its time budgets.

One JSON line per statement: ``ours_s`` is the time of ``prove`` on the statement as read from its file
(limit 10 s; the median of three runs when the first takes under a second), against a budget of 1 s for a
statement that needs no square root (``"baseline": "budget 1 s"``) and 10 s for one with algebraic points
(``"budget 10 s"``), so the ratio is below 1 when a statement is over budget; with its verdict
(``status``), the expected truth (``expected``) and ``wrong`` when the verdict contradicts it (a false
statement proved, a true one refuted, a statement that holds on one branch proved for every root).

Then one summary line: the counts proved / refuted / unknown / wrong, the share of statements decided
within budget in each class (the targets: 95 % of the rational ones in 1 s, 70 % of those with algebraic
points in 10 s) and the five slowest statements.
"""

from __future__ import annotations

import re
import statistics
import time
from pathlib import Path

from timing import report

CORPUS = sorted((Path(__file__).resolve().parent.parent / "tests" / "euclid").glob("*.thm"))
RATIONAL_BUDGET_S = 1.0
ROOTS_BUDGET_S = 10.0
LIMIT_S = 10.0
# the section B words: a statement using one has algebraic points
SECTION_B = re.compile(r"\b(anglebisector|exbisector|intersections?|tangentsfrom|tangentfrom|polygon)\b"
                       r"|\brotate\s+\S+\s+\S+\s+-?\d+\s*(?:\)|$)", re.M)


def needs_roots(text: str) -> bool:
    """Whether the statement has algebraic points (section B of the statement language)."""
    return bool(SECTION_B.search("\n".join(line.split("#", 1)[0] for line in text.splitlines())))


def classify(verdict, expected: bool) -> tuple[str, bool]:
    """The verdict's word (proved / refuted / unknown) and whether it is wrong for the expected truth.

    A verdict that holds for a named branch only is ``proved`` when the statement is expected true and
    not wrong when it is expected false (the false one-branch statements say "for every choice of root").
    """
    status = str(verdict.status)
    named_only = "named branch" in " ".join(str(getattr(verdict, a, "")) for a in ("reason", "branches", "scope"))
    if verdict.proved:
        return "proved", (not expected and not named_only)
    if status == "false":
        return "refuted", expected
    return "unknown", False


def main() -> None:
    from pgsym.proofs.engine import prove
    from pgsym.proofs.language import read_statement

    times: dict[str, float] = {}
    counts = {"proved": 0, "refuted": 0, "unknown": 0, "wrong": 0}
    within = {"rational": [0, 0], "roots": [0, 0]}  # decided within budget, total
    for path in CORPUS:
        roots = needs_roots(path.read_text(encoding="utf-8"))
        budget = ROOTS_BUDGET_S if roots else RATIONAL_BUDGET_S
        try:
            claim = read_statement(path)
        except Exception as err:  # a statement the language cannot read yet counts as unknown
            times[path.stem] = 0.0
            counts["unknown"] += 1
            within["roots" if roots else "rational"][1] += 1
            report(f"euclid_{path.stem}", 1e-6, f"budget {budget:g} s", budget, status="unreadable",
                   expected=None, error=type(err).__name__)
            continue
        runs = []
        for _ in range(3):
            t = time.perf_counter()
            verdict = prove(claim, timeout=LIMIT_S)
            runs.append(time.perf_counter() - t)
            if runs[0] >= RATIONAL_BUDGET_S:
                break
        times[path.stem] = statistics.median(runs)
        word, wrong = classify(verdict, claim.expected)
        counts[word] += 1
        counts["wrong"] += wrong
        decided = word != "unknown" and not wrong
        cls = within["roots" if roots else "rational"]
        cls[0] += decided and times[path.stem] <= budget
        cls[1] += 1
        report(f"euclid_{path.stem}", times[path.stem], f"budget {budget:g} s", budget, status=word,
               expected=claim.expected, **({"wrong": True} if wrong else {}))
    slowest = sorted(times, key=times.get, reverse=True)[:5]
    total = sum(times.values())
    report("euclid_summary", total, "budget per statement (sum)",
           within["rational"][1] * RATIONAL_BUDGET_S + within["roots"][1] * ROOTS_BUDGET_S,
           statements=len(times), **counts,
           rational_within_1s=f"{within['rational'][0]}/{within['rational'][1]}",
           roots_within_10s=f"{within['roots'][0]}/{within['roots'][1]}",
           slowest={name: round(times[name], 3) for name in slowest})


if __name__ == "__main__":
    main()
