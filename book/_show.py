"""Small printing helpers shared by the chapters: how an error or a value is shown to the reader.

Pure Python on pgsym and SymPy (no NumPy), so the live cells of the online book can import it too.

>>> from pgsym import Point, CoincidentPointsError, join
>>> expect(CoincidentPointsError, lambda: join(Point(1, 2), Point(2, 4, 2)))  # doctest: +ELLIPSIS
CoincidentPointsError:
    ...
>>> dot((1, 2, 3), (4, 5, 6))
32
>>> say("a long verdict:", "x " * 40)
a long verdict: x x x x x x x x x x x x x x x x x x x x x x x x x x x x
    x x x x x x x x x x x x
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Iterable
from typing import Any

import sympy as sp

WIDTH = 72  # characters of a printed line: what the page shows without scrolling


def report(err: BaseException, width: int = WIDTH) -> None:
    """Print an error's class and its message, wrapped to the page."""
    print(type(err).__name__ + ":")
    print(textwrap.fill(str(err), width, initial_indent="    ", subsequent_indent="    "))


def expect(error: type[BaseException], build: Callable[[], Any]) -> None:
    """Run ``build()``, which must raise ``error``, and print the error; fail if it does not raise."""
    try:
        build()
    except error as err:
        report(err)
        return
    raise AssertionError(f"expected {error.__name__}")


def say(*parts: Any, sep: str = " ", indent: str = "    ", width: int = WIDTH) -> None:
    """Print like ``print``, wrapped to the page, continuation lines indented (for verdicts, reasons,
    lists of conditions)."""
    text = sep.join(str(p) for p in parts)
    for line in text.split("\n"):
        print(textwrap.fill(line, width, subsequent_indent=indent, break_on_hyphens=False))


def dot(u: Iterable[Any], v: Iterable[Any]) -> sp.Expr:
    """The expanded dot product of two coordinate vectors (points, lines, planes or tuples)."""
    return sp.expand(sum(a * b for a, b in zip(u, v, strict=True)))


def xy(P: Any) -> tuple[Any, ...]:
    """The exact Euclidean coordinates of a finite point of the plane."""
    return tuple(P.dehomogenize())
