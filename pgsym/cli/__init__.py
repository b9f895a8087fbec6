"""The ``pgsym`` command line.

Coordinates are given as one argument each, separated by commas or spaces;
every entry is an integer, a fraction ``p/q`` or a decimal, read exactly
(the grammar and its limits: :mod:`pgsym.cli._common`).

Every command reports bad input as one line ``Error: ...``: usage errors (a bad
argument or option) exit with status 2, a :class:`~pgsym.errors.PgsymError` raised
while the command runs with status 1. Anything else is a bug: it is reported as
one line ``Error: internal error (...)`` with status 1, never as a traceback.

    $ pgsym join "0,0" "1,1"
    line: (-1, 1, 0)   canonical: (1, -1, 0)   equation: x - y = 0
"""

from __future__ import annotations

import errno

import click

from .. import __version__
from ..errors import PgsymError
from .exercises import check_command, sheet_command, templates_group
from .geometry import join_command, meet_command
from .prove import discover_command, prove_command
from .vision import harris_command, rectify_command

__all__ = ["main"]


_MAX_MESSAGE = 300


def _shorten(err: click.ClickException) -> click.ClickException:
    """Cut the middle out of an error message that quotes a huge input (click quotes values whole)."""
    if len(err.message) > _MAX_MESSAGE:
        n = len(err.message)
        err.message = f"{err.message[:200]}[... {n - 260} characters left out ...]{err.message[-60:]}"
    return err


class _GuardedGroup(click.Group):
    """A click group whose commands never show a Python traceback, and whose errors are one short line."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        # a real command line cannot hold NUL (C strings), but a caller in Python can: refuse it
        # here once, before any command hands it to the operating system (which would raise ValueError)
        for i, arg in enumerate(args):
            if "\x00" in arg:
                raise click.UsageError(f"argument {i + 1} contains a NUL character", ctx=ctx)
        try:
            return super().parse_args(ctx, args)
        except click.ClickException as err:
            raise _shorten(err) from None

    def invoke(self, ctx: click.Context):  # type: ignore[no-untyped-def]
        try:
            return super().invoke(ctx)
        except click.ClickException as err:
            raise _shorten(err) from None
        except (click.exceptions.Exit, click.Abort):
            raise
        except PgsymError as err:
            raise _shorten(click.ClickException(f"{type(err).__name__}: {err}")) from None
        except MemoryError:
            raise click.ClickException("MemoryError: not enough memory for this input; make it smaller") from None
        except Exception as err:  # the last resort: a bug, reported in one line with the exception type
            if isinstance(err, OSError) and err.errno == errno.EPIPE:
                raise  # the reader of our output went away (| head): click ends quietly
            first = (str(err).splitlines() or [""])[0][:200]
            raise click.ClickException(f"internal error ({type(err).__name__}: {first}); "
                                       "please report it with the command that caused it") from None


@click.group(cls=_GuardedGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "-V", "--version", prog_name="pgsym")
def main() -> None:
    """pgsym: exact projective geometry on SymPy.

    Points take 2 inhomogeneous coordinates "x,y" or 3 homogeneous ones
    "x1,x2,x3"; lines take 3 coordinates "a,b,c" for ax + by + c = 0.
    """


# The vision, proof and instructor commands import their heavy modules only when they run.
for _command in (join_command, meet_command, harris_command, rectify_command, prove_command,
                 sheet_command, check_command, templates_group):
    main.add_command(_command)
main.add_command(discover_command)


if __name__ == "__main__":  # pragma: no cover
    main()
