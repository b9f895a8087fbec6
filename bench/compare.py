"""Compare two runs of ``make bench``: the ratio of every case before and after a change.

    .venv/bin/python bench/compare.py before.jsonl after.jsonl [--tolerance 0.10]

Cases are matched by (bench, baseline). A case whose ratio fell by more than the tolerance is
marked ``SLOWER``; the exit status is 1 when any is. Lines that are not JSON are ignored, so the
raw output of ``make bench`` can be given as it is.
"""

from __future__ import annotations

import argparse
import json
import sys


def _cases(path: str) -> dict[tuple[str, str], float]:
    out = {}
    with open(path, encoding="utf-8") as stream:
        for line in stream:
            try:
                case = json.loads(line)
            except ValueError:
                continue
            if isinstance(case, dict) and isinstance(case.get("ratio"), (int, float)):
                out[(str(case.get("bench")), str(case.get("baseline")))] = float(case["ratio"])
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--tolerance", type=float, default=0.10, help="allowed relative drop of a ratio")
    args = parser.parse_args(argv)
    before, after = _cases(args.before), _cases(args.after)
    slower = 0
    for key in sorted(before.keys() | after.keys()):
        b, a = before.get(key), after.get(key)
        if b is None or a is None:
            print(f"{'new' if b is None else 'gone':8s} {key[0][:60]:60s} {key[1][:40]}")
            continue
        change = a / b - 1
        mark = "SLOWER" if change < -args.tolerance else ""
        slower += bool(mark)
        print(f"{change:+8.1%} {key[0][:60]:60s} {key[1][:40]:40s} {b:10.3f} -> {a:10.3f} {mark}")
    print(f"{slower} case(s) slower by more than {args.tolerance:.0%}")
    return 1 if slower else 0


if __name__ == "__main__":
    sys.exit(main())
