"""Benchmark: the proof catalogue (exact polynomial arithmetic) vs SymPy ``simplify`` on the same claims.

Prints one JSON line per case. The first line times the whole catalogue (every true and every false
claim, as ``pgsym prove --all`` runs it: random pass, exact certificate, core check), best of three runs;
the budget is 3 s. Then, for each true claim, ``ours_s`` is the time of ``prove(name)`` and the baseline
builds the same conclusion as SymPy expressions and calls ``simplify`` on each conclusion polynomial
(``Matrix.rank(simplify=True)`` for rank claims), in a child process with a time limit. ``timed_out``
true means the ratio is a lower bound (``ratio_at_least``). A global budget keeps the script near 90 s;
claims left when it runs out are reported with ``skipped`` true.
"""

from __future__ import annotations

import json
import multiprocessing as mp
import time

HEAVY = ("cross-ratio-invariance", "homography-preserves-incidence", "lines-transform-by-inverse-transpose",
         "plucker-matrix-rank-two")
HEAVY_TIMEOUT_S = 20.0
LIGHT_TIMEOUT_S = 3.0
NAIVE_BUDGET_S = 70.0


def _all_claims() -> tuple[float, int, int]:
    from pgsym.proofs import catalogue_names, prove

    names = catalogue_names()
    best = float("inf")
    for _ in range(3):
        t0 = time.perf_counter()
        verdicts = [prove(n) for n in names]
        best = min(best, time.perf_counter() - t0)
    assert all(v.as_expected for v in verdicts)
    return best, len(catalogue_names(True)), len(catalogue_names(False))


def _ours(name: str) -> float:
    from pgsym.proofs import prove

    best = float("inf")
    for _ in range(3):
        t0 = time.perf_counter()
        assert prove(name).proved
        best = min(best, time.perf_counter() - t0)
    return best


def _naive(name: str, out: mp.Queue) -> None:
    import sympy

    from pgsym.proofs import get_claim
    from pgsym.proofs.engine import _conclusion_polys, _evaluate

    claim = get_claim(name)
    t0 = time.perf_counter()
    values = _evaluate(claim, sympy.sympify)
    ok = all(sympy.simplify(expr) == 0 for _, expr in _conclusion_polys(claim, values))
    for c in claim.conclusions:
        if c.kind == "rank":
            node, r = c.args
            ok = ok and sympy.Matrix(values[node]).rank(simplify=True) == r
    out.put((time.perf_counter() - t0, ok))


def _baseline(name: str, timeout: float) -> tuple[float | None, bool | None]:
    ctx = mp.get_context("fork")
    q: mp.Queue = ctx.Queue()
    p = ctx.Process(target=_naive, args=(name, q))
    p.start()
    p.join(timeout)
    if p.is_alive():
        p.terminate()
        p.join()
        return None, None
    return q.get()


def main() -> None:
    from pgsym.proofs import catalogue_names

    total, n_true, n_false = _all_claims()
    print(json.dumps({"bench": "proofs", "case": f"whole catalogue ({n_true} true + {n_false} false claims)",
                      "ours_s": round(total, 4), "budget_s": 3.0, "within_budget": total <= 3.0}), flush=True)
    names = sorted(catalogue_names(True), key=lambda n: (n not in HEAVY, n))
    spent = 0.0
    for name in names:
        mine = _ours(name)
        timeout = HEAVY_TIMEOUT_S if name in HEAVY else LIGHT_TIMEOUT_S
        row: dict[str, object] = {"bench": "proofs", "case": name, "ours_s": round(mine, 5),
                                  "baseline": "sympy.simplify of each conclusion polynomial (same construction)",
                                  "timeout_s": timeout}
        if spent + timeout > NAIVE_BUDGET_S:
            row["skipped"] = True
            print(json.dumps(row), flush=True)
            continue
        t0 = time.perf_counter()
        base, ok = _baseline(name, timeout)
        spent += time.perf_counter() - t0
        row["timed_out"] = base is None
        if base is None:
            row["ratio_at_least"] = round(timeout / mine)
        else:
            row["baseline_s"] = round(base, 4)
            row["ratio"] = round(base / mine, 1)
            row["baseline_proved"] = ok
        print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main()
