"""Benchmark: every invariant proof (a claim run by the proof engine) vs SymPy ``simplify`` on the same claim.

Prints one JSON line per case. ``ours_s`` for all proofs together is the median of three runs with the
proof cache cleared. The baseline builds the same residual (after − before) as SymPy expressions
for the generic element and calls ``simplify`` on it, in a child process with a time limit
(``timed_out`` true means the ratio is a lower bound).
"""

from __future__ import annotations

import time

from timing import median_time, report, report_against_timeout, run_with_timeout

TIMEOUT_S = 20.0


def _all_proofs() -> tuple[float, int]:
    import pgsym.proofs.invariance as inv

    def run() -> None:
        inv._prove.cache_clear()
        assert all(i.prove().holds for i in inv.INVARIANTS)

    return median_time(run, 3), len(inv.INVARIANTS)


def _one_proof(key: str) -> float:
    import pgsym.proofs.invariance as inv

    inv._prove.cache_clear()
    t0 = time.perf_counter()
    assert inv.invariant(key).prove().holds
    return time.perf_counter() - t0


def _naive(key: str) -> bool:
    import sympy

    import pgsym.proofs.invariance as inv

    claim = inv.invariant(key)
    cls = claim.transformation_class
    counter = iter(range(1000))
    config = claim.configuration(lambda: sympy.Symbol(f"z{next(counter)}"))
    H = cls.generic(0).tolist()
    before, after = claim.value(config), claim.value(inv.transformed(H, config))
    ok = all(sympy.simplify(a[0] / a[1] - b[0] / b[1]) == 0 for a, b in zip(after, before, strict=True))
    return ok


def main() -> None:
    total, n = _all_proofs()
    # the aggregate has no single naive counterpart: it is reported against the 2 s budget
    report(f"invariants_all_{n}", total, "budget 2 s", 2.0)
    for key in ("angle", "cross-ratio", "angle-3d"):
        mine = _one_proof(key)
        base, ok = run_with_timeout(_naive, (key,), TIMEOUT_S)
        report_against_timeout(f"invariant_{key}", mine, "sympy.simplify(after - before) on the same generic claim",
                               TIMEOUT_S, base, baseline_proved=ok)

if __name__ == "__main__":
    main()
