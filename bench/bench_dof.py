"""Benchmark: the eight DoF derivations (exact rank at a rational point) vs symbolic ``Matrix.rank()``.

Prints one JSON line per case: ``ours_s`` is the best of several runs of all eight derivations,
``baseline_s`` the time of SymPy's symbolic rank of the same augmented Jacobian, run in a child
process with a time limit (``timed_out`` true means the ratio is a lower bound).
"""

from __future__ import annotations

import json
import multiprocessing as mp
import time

TIMEOUT_S = 20.0


def _ours() -> float:
    from pgsym.hierarchy import dof_table

    best = float("inf")
    for _ in range(5):
        t0 = time.perf_counter()
        rows = dof_table()
        best = min(best, time.perf_counter() - t0)
    assert [r["dof"] for r in rows] == [3, 4, 6, 8, 6, 7, 12, 15]
    return best


def _naive(key: str, out: mp.Queue) -> None:
    import sympy

    from pgsym.hierarchy import class_by_key

    cls = class_by_key(key)
    t0 = time.perf_counter()
    vec = sympy.Matrix(list(cls.generic()))
    J = vec.jacobian(sympy.Matrix(cls.parameters)).row_join(vec)
    rank = J.rank(simplify=True)
    out.put((time.perf_counter() - t0, rank - 1))


def _baseline(key: str) -> tuple[float | None, int | None]:
    ctx = mp.get_context("fork")
    q: mp.Queue = ctx.Queue()
    p = ctx.Process(target=_naive, args=(key, q))
    t0 = time.perf_counter()
    p.start()
    p.join(TIMEOUT_S)
    if p.is_alive():
        p.terminate()
        p.join()
        return None, None
    return q.get() if not q.empty() else (time.perf_counter() - t0, None)


def main() -> None:
    from pgsym.hierarchy import class_by_key

    # the first (cold) call includes building the symbols of the parametrisations
    t0 = time.perf_counter()
    for key in ("isometry2", "similarity2", "affine2", "projective2",
                "euclidean3", "similarity3", "affine3", "projective3"):
        class_by_key(key).dof()
    cold = time.perf_counter() - t0
    ours = _ours()
    print(json.dumps({"bench": "dof", "case": "all eight DoF derivations", "ours_s": round(ours, 5),
                      "cold_s": round(cold, 5), "budget_s": 0.05, "within_budget": ours <= 0.05}))
    for key in ("similarity2", "euclidean3"):
        cls = class_by_key(key)
        t0 = time.perf_counter()
        d = cls.dof()
        mine = time.perf_counter() - t0
        base, rank = _baseline(key)
        row = {"bench": "dof", "case": f"{key}: DoF {d.dof}", "ours_s": round(mine, 6),
               "baseline": "sympy Matrix.rank(simplify=True) of the symbolic Jacobian",
               "baseline_s": None if base is None else round(base, 3), "timed_out": base is None,
               "timeout_s": TIMEOUT_S}
        if base is None:
            row["ratio_at_least"] = round(TIMEOUT_S / mine)
        else:
            row["ratio"] = round(base / mine)
            row["baseline_dof"] = rank
        print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main()
