"""The ``pgsym join`` and ``pgsym meet`` commands: incidence in the plane from the shell.

    $ pgsym meet "1,-1,0" "1,-1,3"
    point: (-3, -3, 0)   canonical: (1, 1, 0)   ideal point (at infinity)
"""

from __future__ import annotations

from fractions import Fraction
from typing import TYPE_CHECKING

import click

from ..errors import PgsymError
from ._common import COORDS, fail

if TYPE_CHECKING:
    from ..projective_plane import Line, Point

__all__ = ["join_command", "meet_command"]


def _describe(obj: Point | Line) -> str:
    import sympy  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    from ..projective_plane import Line  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    raw = ", ".join(str(c) for c in obj.coords)
    canonical = ", ".join(str(c) for c in obj.canonical().coords)
    if isinstance(obj, Line):
        x, y = sympy.symbols("x y")
        a, b, c = obj.canonical().coords
        extra = f"equation: {sympy.sstr(a * x + b * y + c)} = 0"
        kind = "line"
    else:
        kind = "point"
        extra = "ideal point (at infinity)" if obj.is_ideal else "inhomogeneous: ({}, {})".format(*obj.dehomogenize())
    return f"{kind}: ({raw})   canonical: ({canonical})   {extra}"


def _run(build):  # type: ignore[no-untyped-def]
    try:
        click.echo(_describe(build()))
    except PgsymError as err:
        raise fail(err) from None


@click.command("join")
@click.argument("p", type=COORDS)
@click.argument("q", type=COORDS)
def join_command(p: tuple[Fraction, ...], q: tuple[Fraction, ...]) -> None:
    """The line through the points P and Q (their cross product).

    Example: pgsym join "0,0" "1,1"
    """
    from ..projective_plane import Point, join  # noqa: PLC0415 — SymPy loads only when a command runs

    _run(lambda: join(Point(*p), Point(*q)))


@click.command("meet")
@click.argument("l", type=COORDS)
@click.argument("m", type=COORDS)
def meet_command(l: tuple[Fraction, ...], m: tuple[Fraction, ...]) -> None:
    """The point where the lines L and M meet (their cross product).

    Example: pgsym meet "1,-1,0" "1,-1,3"   (parallel lines: an ideal point)
    """
    from ..projective_plane import Line, meet  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    _run(lambda: meet(Line(*l), Line(*m)))
