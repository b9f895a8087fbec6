"""Benchmark: the eight DoF derivations (exact rank at a rational point) vs symbolic ``Matrix.rank()``.

Prints one JSON line per case: ``ours_s`` is the median of several runs of all eight derivations
(reported against the 50 ms budget), and per class the time of SymPy's symbolic rank of the same
augmented Jacobian, run in a child process with a time limit (``timed_out`` true: the ratio is a
lower bound).
"""

from __future__ import annotations

import time

from timing import median_time, report, report_against_timeout, run_with_timeout

TIMEOUT_S = 20.0


def _ours() -> float:
    from pgsym.hierarchy import dof_table

    assert [r["dof"] for r in dof_table()] == [3, 4, 6, 8, 6, 7, 12, 15]
    return median_time(dof_table, 7)


def _naive(key: str) -> int:
    import sympy

    from pgsym.hierarchy import class_by_key

    cls = class_by_key(key)
    vec = sympy.Matrix(list(cls.generic()))
    J = vec.jacobian(sympy.Matrix(cls.parameters)).row_join(vec)
    return J.rank(simplify=True) - 1




def main() -> None:
    from pgsym.hierarchy import class_by_key

    # the first (cold) call includes building the symbols of the parametrisations
    t0 = time.perf_counter()
    for key in ("isometry2", "similarity2", "affine2", "projective2",
                "euclidean3", "similarity3", "affine3", "projective3"):
        class_by_key(key).dof()
    cold = time.perf_counter() - t0
    ours = _ours()
    # the aggregate has no single naive counterpart: it is reported against the 50 ms budget
    report("dof_all_eight", ours, "budget 50 ms", 0.05, cold_s=round(cold, 5))
    for key in ("similarity2", "euclidean3"):
        cls = class_by_key(key)
        t0 = time.perf_counter()
        d = cls.dof()
        mine = time.perf_counter() - t0
        base, rank = run_with_timeout(_naive, (key,), TIMEOUT_S)
        report_against_timeout(f"dof_{key}", mine, "sympy Matrix.rank(simplify=True) of the symbolic Jacobian",
                               TIMEOUT_S, base, dof=d.dof, baseline_dof=rank)

if __name__ == "__main__":
    main()
