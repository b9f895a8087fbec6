"""The ``pgsym prove`` command: prove catalogue claims, or theorems written in the statement language.

    $ pgsym prove pappus
    proved    pappus    Pappus's hexagon theorem    (4 conditions)
    $ pgsym prove tests/theorems/pappus.thm

An argument ending in ``.thm``, or naming an existing file, is read as a theorem of the
statement language (:mod:`pgsym.proofs.language`). ``--from alphageometry FILE [NAME…]`` reads a problem
file of AlphaGeometry instead (:mod:`pgsym.proofs.alphageometry`; exit status 1 when a problem is refuted).
The exit status is 1 when a claim stated as true is not proved, or a claim stated as false is "proved";
2 for a file that cannot be read (``Error: FILE:LINE:COL: message``); 0 otherwise.
"""

from __future__ import annotations

import json
import os
import sys

import click

from ..limits import MAX_ARGUMENT_CHARS
from ..proofs.errors import StatementError, UnknownClaimError
from ..proofs.verdicts import Status  # no SymPy: the statuses only
from ._common import DecimalRange

__all__ = ["discover_command", "prove_command"]


def _line(verdict) -> str:  # type: ignore[no-untyped-def]
    expected = "" if verdict.expected else "  [false claim]"
    ok = "" if verdict.as_expected else "  <-- NOT AS EXPECTED"
    if verdict.status is Status.PROVED:
        extra = f"({len(verdict.conditions)} non-degeneracy conditions)"
    elif verdict.status is Status.FALSE:
        values = ", ".join(f"{k}={v}" for k, v in verdict.counterexample.values.items())
        extra = f"(counterexample: {values[:100]})"
    else:
        extra = f"({verdict.reason[:120]})"
    if verdict.branches:  # square roots: which choices of root the verdict covers
        extra += f" [{verdict.branches.split(':')[0].split(' (')[0][:60]}]"
    return f"{verdict.status:10s}  {verdict.name:40s}  {extra}  {1000 * verdict.elapsed:.0f} ms{expected}{ok}"


_SUFFIX = ".thm"  # pgsym.proofs.language.STATEMENT_SUFFIX (not imported here: it loads SymPy)


class _BadFile(click.ClickException):
    """A theorem file that cannot be read: ``Error: FILE:LINE:COL: message``, exit status 2."""

    exit_code = 2


def _is_file(name: str) -> bool:
    return name.endswith(_SUFFIX) or os.path.isfile(name)


_EXAMPLE = """\b
Example theorem file (pappus.thm):
    title Pappus's hexagon theorem
    points A B C D            # free points
    point E on line A B       # one parameter
    point F on line C D
    point X = meet (join A D) (join B C)
    point Y = meet (join A F) (join E C)
    point Z = meet (join E D) (join B F)
    prove collinear X Y Z

\b
Euclidean geometry (circles, perpendiculars, feet, squared distances; square
roots such as angle bisectors and line-circle intersections, with the roots
each verdict covers):
    points A B C
    conic K = circle A B C
    point P on circle K
    prove collinear (foot P (join B C)) (foot P (join C A)) (foot P (join A B))

\b
Order conditions pick the branch an olympiad statement means (strict; each
'where' line must hold; the verdict covers only what they select):
    points A B
    point X = intersection (join A B) (circle A B)   # B or its mirror in A
    where onray X A B            # also: sameside P Q A B, oppositeside P Q A B,
    prove equal X B              #   between X A B, inside X A B C
"""

_AG_EXAMPLE = """\b
AlphaGeometry's problems (a name line, then the problem line):
    pgsym prove --from alphageometry imo_ag_30.txt translated_imo_2000_p6
    pgsym prove --from alphageometry problems.txt --show    # the translations
Where AlphaGeometry takes a random common point and the goal holds at one of
the two only, the translation states the point by an order condition ('where')
that selects it in every random figure, and the verdict is about that point.
Where the goal holds in some random figures only, the translation adds order
conditions that keep only such figures; the verdict is about those they keep.
"""


@click.command("prove", epilog=_EXAMPLE + "\n" + _AG_EXAMPLE)
@click.argument("names", nargs=-1)
@click.option("--list", "list_", is_flag=True, help="List the catalogue's claims and exit.")
@click.option("--all", "all_", is_flag=True, help="Prove every claim of the catalogue.")
@click.option("--json", "as_json", is_flag=True, help="Print the verdicts as a JSON array.")
@click.option("--certificate", is_flag=True, help="Print each verdict in full (Markdown: constructions, "
              "certificate, non-degeneracy conditions, counterexample).")
@click.option("--timeout", type=DecimalRange(min=0, max=86400, min_open=True), default=10.0, show_default=True,
              help="Seconds per claim (at most a day); a claim that takes longer is reported as unknown.")
@click.option("--from", "source", type=click.Choice(["alphageometry"]), default=None,
              help="Read FILE as problems of another prover's language (AlphaGeometry: NAMES are FILE and the "
              "problems to prove, all when none is given).")
@click.option("--show", is_flag=True, help="With --from: print each problem's translation into the statement "
              "language instead of proving it.")
def prove_command(names: tuple[str, ...], list_: bool, all_: bool, as_json: bool, certificate: bool,
                  timeout: float, source: str | None, show: bool) -> None:
    """Prove claims of the catalogue, or theorem files (FILE.thm), by exact polynomial arithmetic.

    Examples: pgsym prove --list; pgsym prove pappus desargues; pgsym prove --all --json;
    pgsym prove tests/theorems/pappus.thm --certificate;
    pgsym prove --from alphageometry imo_ag_30.txt translated_imo_2000_p6
    """
    if source is not None:
        _prove_foreign(names, timeout, show, as_json)
        return
    if show:
        raise click.UsageError("--show goes with --from")
    from ..proofs.catalogue import CATALOGUE, catalogue_names, prove  # noqa: PLC0415 — SymPy loads only when a command runs

    if list_:
        if as_json:
            rows = [{"name": e.name, "title": e.title, "chapter": e.chapter, "expected": e.expected}
                    for e in CATALOGUE.values()]
            click.echo(json.dumps(rows, ensure_ascii=False, indent=1))
        else:
            for e in CATALOGUE.values():
                mark = "true " if e.expected else "FALSE"
                click.echo(f"{e.name:40s}  {mark}  {e.chapter:28s}  {e.title}")
        return
    if all_ and names:
        raise click.UsageError("give claim names or --all, not both")
    if not all_ and not names:
        raise click.UsageError("give claim names, --all or --list (see pgsym prove --help)")
    long = [n for n in names if len(n) > MAX_ARGUMENT_CHARS]
    if long:
        raise click.BadParameter(f"a claim name of {len(long[0])} characters; names have at most "
                                 f"{MAX_ARGUMENT_CHARS} (see pgsym prove --list)", param_hint="NAMES")
    files = [n for n in names if _is_file(n)]
    claims = {}
    if files:
        from ..proofs.language import read_statement  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

        for f in files:
            try:
                claims[f] = read_statement(f)
            except StatementError as err:
                raise _BadFile(str(err)) from None
    selected = catalogue_names() if all_ else list(names)
    unknown = [n for n in selected if n not in CATALOGUE and n not in claims]
    if unknown:
        try:
            prove(unknown[0])
        except UnknownClaimError as err:
            raise click.BadParameter(str(err), param_hint="NAMES") from None
    verdicts = []
    with click.progressbar(selected, label="proving", file=sys.stderr, show_pos=True,
                           item_show_func=lambda n: n or "") as bar:
        for name in bar:
            verdicts.append(prove(claims.get(name, name), timeout=timeout))
    if as_json:
        click.echo(json.dumps([v.to_dict() for v in verdicts], ensure_ascii=False, indent=1))
    elif certificate:
        for v in verdicts:
            click.echo(v.markdown())
    else:
        for v in verdicts:
            click.echo(_line(v))
    bad = [v.name for v in verdicts if not v.as_expected and (v.expected or v.status is Status.PROVED)]
    if bad:
        click.echo(f"not as expected: {', '.join(bad)}", err=True)
        sys.exit(1)


def _prove_foreign(names: tuple[str, ...], timeout: float, show: bool, as_json: bool) -> None:
    """``--from alphageometry FILE [NAME…]``: one verdict line a problem, then the summary."""
    if not names:
        raise click.UsageError("give the problem file: pgsym prove --from alphageometry FILE [NAME…]")
    long = [n for n in names if len(n) > MAX_ARGUMENT_CHARS]
    if long:
        raise click.BadParameter(f"an argument of {len(long[0])} characters; at most {MAX_ARGUMENT_CHARS}",
                                 param_hint="NAMES")
    from ..proofs.alphageometry import OUTCOMES, read_alphageometry_file, solve  # noqa: PLC0415 — SymPy loads only when a command runs

    try:
        problems = read_alphageometry_file(names[0])
    except StatementError as err:
        raise _BadFile(str(err)) from None
    wanted = list(dict.fromkeys(names[1:]))
    known = {p.name for p in problems}
    missing = [n for n in wanted if n not in known]
    if missing:
        raise click.BadParameter(f"no problem named {missing[0]!r} in {names[0]} (it has {len(problems)})",
                                 param_hint="NAMES")
    chosen = [p for p in problems if not wanted or p.name in wanted]
    if show:
        for p in chosen:
            click.echo(p.statement if p.statement is not None else f"# {p.name}\n# {p.error}")
            click.echo()
        return
    counts = dict.fromkeys(OUTCOMES, 0)
    rows = []
    with click.progressbar(chosen, label="proving", file=sys.stderr, show_pos=True) as bar:
        for p in bar:
            outcome = solve(p, timeout=timeout)
            counts[outcome.status] += 1
            rows.append(outcome)
    for o in rows:
        if as_json:
            continue
        if o.verdict is not None:
            note = ("  [either common point, as AlphaGeometry takes one at random: the problem may need a branch "
                    "condition]" if o.status == "refuted" and o.either else "")
            click.echo(_line(o.verdict).replace(f"{o.verdict.status:10s}", f"{o.status:11s}", 1) + note)
        else:
            click.echo(f"{o.status:11s}  {o.problem.name:40s}  ({o.message})")
    if as_json:
        click.echo(json.dumps([{"name": o.problem.name, "line": o.problem.line, "status": o.status,
                                "message": o.message or str(getattr(o.verdict, "reason", "") or ""),
                                "elapsed_ms": round(1000 * o.elapsed, 2)} for o in rows], ensure_ascii=False,
                              indent=1))
    summary = ", ".join(f"{counts[k]} {k if k != 'error' else 'errors'}" for k in OUTCOMES)
    click.echo(f"{len(rows)} problems: {summary}", err=as_json)
    if counts["refuted"]:
        sys.exit(1)


_DISCOVER_EXAMPLE = """\b
Example (quadrangle.thm):
    points A B C D
    point P = meet (join A B) (join C D)
    point Q = meet (join A C) (join B D)
    point R = meet (join A D) (join B C)
    prove collinear A B P
"""


@click.command("discover", epilog=_DISCOVER_EXAMPLE)
@click.argument("file")
@click.option("--json", "as_json", is_flag=True, help="Print the relations as a JSON array.")
@click.option("--timeout", type=DecimalRange(min=0, max=86400, min_open=True), default=2.0, show_default=True,
              help="Seconds to prove each relation that does not hold by construction.")
@click.option("--all", "all_", is_flag=True, help="Also list the relations that hold by construction.")
def discover_command(file: str, as_json: bool, timeout: float, all_: bool) -> None:
    """Find every incidence among the objects of a theorem file (FILE.thm), then prove each.

    Relations (a point on a line, plane or conic; three collinear points; three concurrent lines; four
    coplanar points; six points on a conic) are found on a random exact instance; those that do not hold
    by construction are proved by the engine. Exit status 2 for a file that cannot be read.
    """
    from ..proofs.discovery import MAX_SIX, discover  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it
    from ..proofs.language import read_statement  # noqa: PLC0415 — CLI start-up: loaded by the command that needs it

    try:
        claim = read_statement(file)
    except StatementError as err:
        raise _BadFile(str(err)) from None
    found = discover(claim, timeout=timeout)
    shown = [r for r in found if all_ or not r.by_construction]
    if as_json:
        click.echo(json.dumps([{"kind": r.kind, "objects": list(r.objects), "text": r.text,
                                "status": r.status} for r in shown], ensure_ascii=False, indent=1))
        return
    for r in shown:
        click.echo(f"{r.status:16s}  {r.text}")
    trivial = sum(r.by_construction for r in found)
    click.echo(f"{len(found)} relations on a random instance: {trivial} by construction, "
               f"{sum(r.status == 'proved' for r in found)} proved, "
               f"{sum(r.status == 'false' for r in found)} false at a generic point, "
               f"{sum(r.status == 'unknown' for r in found)} unknown", err=True)
    n_points = sum(n.kind == "point" and not n.name.startswith("_") for n in claim.nodes.values())
    if n_points > MAX_SIX:
        click.echo(f"six points on a conic were looked for among the first {MAX_SIX} of the {n_points} points only "
                   "(the other relations among all of them)", err=True)
