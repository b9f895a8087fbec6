"""Benchmark: every invariant proof (polynomial ring, exact) vs SymPy ``simplify`` on the same claim.

Prints one JSON line per case. ``ours_s`` for all proofs together is the best of three runs with the
proof cache cleared. The baseline builds the same residual (after − before) as SymPy expressions
for the generic element and calls ``simplify`` on it, in a child process with a time limit
(``timed_out`` true means the ratio is a lower bound).
"""

from __future__ import annotations

import json
import multiprocessing as mp
import time

TIMEOUT_S = 20.0


def _all_proofs() -> tuple[float, int]:
    import pgsym.invariants as inv

    best = float("inf")
    for _ in range(3):
        inv._prove.cache_clear()
        t0 = time.perf_counter()
        results = [i.prove().holds for i in inv.INVARIANTS]
        best = min(best, time.perf_counter() - t0)
    assert all(results)
    return best, len(results)


def _one_proof(key: str) -> float:
    import pgsym.invariants as inv

    inv._prove.cache_clear()
    t0 = time.perf_counter()
    assert inv.invariant(key).prove().holds
    return time.perf_counter() - t0


def _naive(key: str, out: mp.Queue) -> None:
    import sympy

    import pgsym.invariants as inv

    claim = inv.invariant(key)
    cls = claim.transformation_class
    t0 = time.perf_counter()
    counter = iter(range(1000))
    config = claim.configuration(lambda: sympy.Symbol(f"z{next(counter)}"))
    H = cls.generic(0).tolist()
    before, after = claim.value(config), claim.value(inv._act(H, config))
    ok = all(sympy.simplify(a - b) == 0 for a, b in zip(after, before, strict=True))
    out.put((time.perf_counter() - t0, ok))


def _baseline(key: str) -> tuple[float | None, bool | None]:
    ctx = mp.get_context("fork")
    q: mp.Queue = ctx.Queue()
    p = ctx.Process(target=_naive, args=(key, q))
    p.start()
    p.join(TIMEOUT_S)
    if p.is_alive():
        p.terminate()
        p.join()
        return None, None
    return q.get()


def main() -> None:
    total, n = _all_proofs()
    print(json.dumps({"bench": "invariants", "case": f"all {n} invariant proofs", "ours_s": round(total, 4),
                      "budget_s": 2.0, "within_budget": total <= 2.0}), flush=True)
    for key in ("angle", "cross-ratio", "angle-3d"):
        mine = _one_proof(key)
        base, ok = _baseline(key)
        row = {"bench": "invariants", "case": key, "ours_s": round(mine, 4),
               "baseline": "sympy.simplify(after - before) on the same generic claim",
               "baseline_s": None if base is None else round(base, 3), "timed_out": base is None,
               "timeout_s": TIMEOUT_S}
        if base is None:
            row["ratio_at_least"] = round(TIMEOUT_S / mine)
        else:
            row["ratio"] = round(base / mine, 1)
            row["baseline_proved"] = ok
        print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main()
