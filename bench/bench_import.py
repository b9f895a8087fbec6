"""Benchmark: how long ``import pgsym`` takes, against ``import sympy``, each in a fresh interpreter.

Cases (each the median over interleaved runs, timed inside the child around the statements only, so
interpreter start-up is excluded):

* ``import_pgsym``: ``import pgsym`` (the issue asks for at most 1.3× ``import sympy``, i.e. ratio ≥ 0.77);
* ``import_pgsym_numeric_call``: ``import pgsym.numeric`` and one ``meet`` on arrays; ``sympy_imported``
  says whether SymPy got loaded on the way (it must not);
* ``import_pgsym_exact_point``: ``from pgsym import Point`` and one exact join, which needs SymPy: the
  cost a user of the exact core pays, for reference.

``ratio`` = baseline_s / ours_s (> 1: ours is faster).
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys

RUNS = 11

TIMED = (
    "import time, sys\n"
    "t0 = time.perf_counter()\n"
    "{code}\n"
    "t1 = time.perf_counter()\n"
    "print(t1 - t0, 'sympy' in sys.modules)\n"
)

CASES = {
    "import sympy": "import sympy",
    "import_pgsym": "import pgsym",
    "import_pgsym_numeric_call": "import numpy as np\nimport pgsym.numeric as pn\npn.meet(np.eye(3), np.ones(3))",
    "import_pgsym_exact_point": "from pgsym import Point, join\njoin(Point(0, 0), Point(1, 1))",
}


def run(code: str) -> tuple[float, bool]:
    result = subprocess.run([sys.executable, "-c", TIMED.format(code=code)], capture_output=True, text=True, check=True)
    seconds, loaded = result.stdout.split()
    return float(seconds), loaded == "True"


def main() -> None:
    times: dict[str, list[float]] = {name: [] for name in CASES}
    loaded: dict[str, bool] = {}
    for code in CASES.values():  # warm the file-system cache once
        run(code)
    for _ in range(RUNS):
        for name, code in CASES.items():
            seconds, loaded[name] = run(code)
            times[name].append(seconds)
    base = statistics.median(times["import sympy"])
    for name in CASES:
        if name == "import sympy":
            continue
        ours = statistics.median(times[name])
        line = {
            "bench": name,
            "ours_s": round(ours, 4),
            "baseline": "import sympy",
            "baseline_s": round(base, 4),
            "ratio": round(base / ours, 2),
            "sympy_imported": loaded[name],
        }
        print(json.dumps(line), flush=True)


if __name__ == "__main__":
    main()
