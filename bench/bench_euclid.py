"""Benchmark: the Euclidean corpus (tests/euclid/*.thm) against its time budgets.

One JSON line per statement: ``ours_s`` is the time of ``prove`` on the statement as read from its file
(limit 10 s; the median of three runs when the first takes under a second), against a budget of 1 s for a
statement that needs no square root (``"baseline": "budget 1 s"``) and 10 s for one with algebraic points
(``"budget 10 s"``), so the ratio is below 1 when a statement is over budget; with its verdict
(``status``), the expected truth (``expected``) and ``wrong`` when the verdict contradicts it (a false
statement proved, a true one refuted, a statement that holds on one branch proved for every root).

Then one summary line: the counts proved / refuted / named (holds on the named branch only: decided, not
proved for every root) / unknown / wrong, the share of statements decided
within budget in each class (the targets: 95 % of the rational ones in 1 s, 70 % of those with algebraic
points in 10 s) and the five slowest statements.
"""

from __future__ import annotations

import re
import statistics
from pathlib import Path

from timing import report, run_with_timeout

CORPUS = sorted((Path(__file__).resolve().parent.parent / "tests" / "euclid").glob("*.thm"))
RATIONAL_BUDGET_S = 1.0
ROOTS_BUDGET_S = 10.0
LIMIT_S = 10.0
HARD_LIMIT_S = 30.0  # a run that overstays the engine's limit this long is stopped and counts as unknown
# the section B words: a statement using one has algebraic points
SECTION_B = re.compile(r"\b(anglebisector|exbisector|intersections?|tangentsfrom|tangentfrom|polygon)\b"
                       r"|\brotate\s+\S+\s+\S+\s+-?\d+\s*(?:\)|$)", re.M)


def needs_roots(text: str) -> bool:
    """Whether the statement has algebraic points (section B of the statement language)."""
    return bool(SECTION_B.search("\n".join(line.split("#", 1)[0] for line in text.splitlines())))


def _summary(path: Path) -> dict:
    """``prove`` on the statement file, as plain words (run in a child process)."""
    from pgsym.proofs.engine import prove
    from pgsym.proofs.language import read_statement

    claim = read_statement(path)
    v = prove(claim, timeout=LIMIT_S)
    return {"status": str(v.status), "proved": bool(v.proved), "branches": str(getattr(v, "branches", "") or ""),
            "expected": claim.expected}


def classify(verdict: dict, expected: bool) -> tuple[str, bool]:
    """The verdict's word and whether it is wrong for the expected truth.

    ``proved`` (for every choice of root), ``refuted``, ``named`` (status unknown, but the verdict says the
    statement holds on the named branch only: decided, and right for a true statement whose other
    branches fail) or ``unknown``.
    """
    if verdict["proved"]:
        return "proved", not expected
    if verdict["status"] == "false":
        return "refuted", expected
    if verdict["branches"].startswith("holds on the named branch only"):
        return "named", not expected
    return "unknown", False


def main() -> None:
    from pgsym.proofs.language import read_statement

    times: dict[str, float] = {}
    counts = {"proved": 0, "refuted": 0, "named": 0, "unknown": 0, "wrong": 0}
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
            elapsed, verdict = run_with_timeout(_summary, (path,), HARD_LIMIT_S)
            if elapsed is None:  # stopped: an unknown verdict at the hard limit
                elapsed, verdict = HARD_LIMIT_S, {"status": "unknown", "proved": False, "branches": ""}
            runs.append(elapsed)
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
