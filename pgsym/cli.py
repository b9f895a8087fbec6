"""The ``pgsym`` command line.

Coordinates are given as one argument each, separated by commas or spaces;
every entry is an integer, a fraction ``p/q`` or a decimal, read exactly.

    $ pgsym join "0,0" "1,1"
    line: (-1, 1, 0)   canonical: (1, -1, 0)   equation: x - y = 0
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import TYPE_CHECKING

import click

from . import __version__
from .errors import PgsymError

if TYPE_CHECKING:
    from .projective_plane import Line, Point

_MAX_ARGUMENT = 500


def _parse_coordinates(text: str) -> tuple[Fraction, ...]:
    """Read ``"1, -2/3, 0.5"`` exactly; never evaluates code."""
    if len(text) > _MAX_ARGUMENT:
        raise click.BadParameter(f"coordinate list longer than {_MAX_ARGUMENT} characters")
    parts = [p for p in re.split(r"[,\s]+", text.strip()) if p]
    if not parts:
        raise click.BadParameter("no coordinates given; write them like '1,2' or '1,2,1'")
    values = []
    for part in parts:
        try:
            values.append(Fraction(part))
        except (ValueError, ZeroDivisionError):
            raise click.BadParameter(f"{part!r} is not a number (use integers, p/q fractions or decimals)") from None
    return tuple(values)


class _Coordinates(click.ParamType):
    name = "COORDS"

    def convert(self, value, param, ctx):  # type: ignore[no-untyped-def]
        if isinstance(value, tuple):
            return value
        try:
            return _parse_coordinates(value)
        except click.BadParameter as err:
            self.fail(err.message, param, ctx)


COORDS = _Coordinates()


def _describe(obj: Point | Line) -> str:
    import sympy

    from .projective_plane import Line

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
        raise click.ClickException(f"{type(err).__name__}: {err}") from None


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "-V", "--version", prog_name="pgsym")
def main() -> None:
    """pgsym: exact projective geometry on SymPy.

    Points take 2 inhomogeneous coordinates "x,y" or 3 homogeneous ones
    "x1,x2,x3"; lines take 3 coordinates "a,b,c" for ax + by + c = 0.
    """


@main.command("join")
@click.argument("p", type=COORDS)
@click.argument("q", type=COORDS)
def join_command(p: tuple[Fraction, ...], q: tuple[Fraction, ...]) -> None:
    """The line through the points P and Q (their cross product).

    Example: pgsym join "0,0" "1,1"
    """
    from .projective_plane import Point, join  # SymPy loads only when a command runs

    _run(lambda: join(Point(*p), Point(*q)))


@main.command("meet")
@click.argument("l", type=COORDS)
@click.argument("m", type=COORDS)
def meet_command(l: tuple[Fraction, ...], m: tuple[Fraction, ...]) -> None:
    """The point where the lines L and M meet (their cross product).

    Example: pgsym meet "1,-1,0" "1,-1,3"   (parallel lines: an ideal point)
    """
    from .projective_plane import Line, meet

    _run(lambda: meet(Line(*l), Line(*m)))


# The vision, proof and instructor commands import their heavy modules only when they run.
from .prove_cli import prove_command  # noqa: E402
from .vision_cli import harris_command, rectify_command  # noqa: E402

main.add_command(harris_command)
main.add_command(rectify_command)
main.add_command(prove_command)
from .exercises_cli import check_command, sheet_command, templates_group  # noqa: E402

main.add_command(sheet_command)
main.add_command(check_command)
main.add_command(templates_group)


if __name__ == "__main__":  # pragma: no cover
    main()
