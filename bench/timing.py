"""Shared timing and reporting for the benchmark scripts (imported as a sibling module).

Every script prints one JSON line per case:
``{"bench": NAME, "ours_s": T, "baseline": NAME, "baseline_s": T, "ratio": baseline_s/ours_s, ...}``.
A baseline stopped at its time limit reports the limit as ``baseline_s`` with ``"timed_out": true``,
so its ratio is a lower bound.
"""

from __future__ import annotations

import json
import multiprocessing as mp
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any


def median_time(fn: Callable[[], object], repeat: int) -> float:
    """Median wall time of ``fn`` over ``repeat`` runs, after one warm-up run."""
    fn()
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def paired_medians(ours: Callable[[], object], baseline: Callable[[], object], repeat: int) -> tuple[float, float]:
    """Median times of two functions run alternately, so that both see the same machine load."""
    ours()
    baseline()
    a, b = [], []
    for _ in range(repeat):
        t = time.perf_counter()
        ours()
        a.append(time.perf_counter() - t)
        t = time.perf_counter()
        baseline()
        b.append(time.perf_counter() - t)
    return statistics.median(a), statistics.median(b)


def report(bench: str, ours_s: float, baseline: str, baseline_s: float, **extra: Any) -> None:
    """Print one JSON line in the common format; ``extra`` keys follow the required ones."""
    row = {"bench": bench, "ours_s": round(ours_s, 6), "baseline": baseline, "baseline_s": round(baseline_s, 6),
           "ratio": round(baseline_s / ours_s, 3), **extra}
    print(json.dumps(row), flush=True)


def _child(target: Callable[..., Any], args: tuple[Any, ...], queue: mp.Queue) -> None:
    t = time.perf_counter()
    result = target(*args)
    queue.put((time.perf_counter() - t, result))


def run_with_timeout(target: Callable[..., Any], args: tuple[Any, ...], timeout_s: float) -> tuple[float | None, Any]:
    """Time ``target(*args)`` in a child process; ``(None, None)`` when it exceeds ``timeout_s``."""
    ctx = mp.get_context("fork")
    queue: mp.Queue = ctx.Queue()
    process = ctx.Process(target=_child, args=(target, args, queue))
    process.start()
    process.join(timeout_s)
    if process.is_alive():
        process.terminate()
        process.join()
        return None, None
    return queue.get() if not queue.empty() else (None, None)


def report_against_timeout(bench: str, ours_s: float, baseline: str, timeout_s: float,
                           measured: float | None, **extra: Any) -> None:
    """Report a baseline run under a time limit: a timeout becomes a lower bound on the ratio."""
    if measured is None:
        report(bench, ours_s, baseline, timeout_s, timed_out=True, **extra)
    else:
        report(bench, ours_s, baseline, measured, timed_out=False, **extra)


def medians(functions: dict[str, Callable[[], object]], repeats: int) -> dict[str, float]:
    """Median wall time of each function, the calls interleaved so that machine load hits all alike."""
    for f in functions.values():
        f()  # warm up: first-touch page faults, caches
    times: dict[str, list[float]] = {name: [] for name in functions}
    for _ in range(repeats):
        for name, f in functions.items():
            t0 = time.perf_counter()
            f()
            times[name].append(time.perf_counter() - t0)
    return {name: statistics.median(ts) for name, ts in times.items()}


def import_geometer(script: str) -> Any:
    """The geometer package (the numeric benchmarks' second baseline), or a plain exit naming the set-up step."""
    try:
        import geometer
    except ImportError:  # a set-up problem, reported plainly
        sys.exit(f"{script} needs geometer, a benchmark-only dependency: .venv/bin/pip install geometer")
    return geometer
