"""AlphaGeometry's problems (its construction language) translated into pgsym's statement language.

AlphaGeometry (google-deepmind/alphageometry) writes a problem as one line of clauses, each defining new
points by one or two constructions of its ``defs.txt``, then a goal after ``?``::

    a b c = triangle a b c; o = circle o a b c; d = on_line d a b, on_circle d o a ? cong o d o a

:func:`translate` gives the same figure as text of :mod:`pgsym.proofs.language`, which
:func:`~pgsym.proofs.language.parse_statement` reads and the engine proves. A clause with one construction
of a one-dimensional locus is a free point on it (one parameter); two loci separated by a comma are
intersected. AlphaGeometry chooses between the two points of a line and a circle (or two circles)
numerically: a point already in the figure is avoided, otherwise either is taken at random. So:

* when a point defined earlier lies on both loci *by construction* (tracked here: the points known on each
  line and circle), the new point is the other one, which is rational: ``reflect P (foot O l)`` for a line
  l and a circle of centre O through P, ``reflect P (join O O')`` for two circles;
* two circles that touch in every figure meet in their double point, which ``intersection`` gives (the
  discriminant vanishes, so both roots are that point);
* a ray (``angle_mirror``, ``s_angle``, ``on_aline``) from the centre of a circle meets it at the ray's own
  point when that point is on the circle (an angle turned or copied from a radius); any other ray meets a
  circle at its point on the ray, not the ray's origin (AlphaGeometry's half-line): an order condition of the
  figure, written ``where onray X V P``; a ray that meets its circle twice in some random figure is refused
  (AlphaGeometry then takes one by the order of its own computation);
* otherwise either point is meant, which is pgsym's ``intersection`` (a conclusion must hold for both). When the
  goal holds for one of them only, AlphaGeometry (which takes either point at random and draws its figure again
  until the goal holds) means that one: the translator looks for order conditions on the figure's points that
  select it in every random figure (:mod:`pgsym.proofs.order_search`) and writes them as ``where`` lines, which
  the engine proves on the branch they select; when none is found but both points are rational (one is the
  fourth vertex P + Q − R of a parallelogram of earlier points, or P + (Q − R) turned by ±90°, the other its
  mirror image), the one where the goal holds in every random figure is written as it is, with a comment;
  otherwise the problem is refused with :class:`~pgsym.proofs.errors.UnsupportedConstructionError` ("needs a
  branch condition"), never guessed.

Two lines of a problem meet in the plane (AlphaGeometry's ``npara``), while pgsym's ``meet`` of parallel lines
is their point at infinity: once a square root with two signs is in the statement, each meet is followed by a
point that needs it finite (``# x is a finite point``), so a branch on which the lines are always parallel is
no counterexample. Angles are copied with ``similar`` (``on_aline``; ``eqangle3`` and ``on_aline2``: the
circle of an inscribed angle), ``eqangle2`` is a point of a conic through two pencils in correspondence, and
``trisegment``, ``3peq``, ``e5128`` are rational.

The tracked incidences are exact but incomplete, so the translator also draws the figure in floats (at
random, as AlphaGeometry does) while it writes the statement: an earlier point found on both loci gives the
other common point too. The goal is then evaluated in a few random figures, on every choice of the random
common points and with the shapes AlphaGeometry mirrors at random (``isquare``, ``risos``,
``ieq_triangle``) mirrored: a goal that holds on some choices only needs a branch condition (found as above, or
the problem is refused), one that holds in one orientation of a mirrored shape is written in that orientation
(a comment says so), one that holds in some figures only needs a condition on the figure: order conditions on
the figure's points that keep only figures where the goal holds, and at least half of those
(:func:`pgsym.proofs.order_search.restricting_conditions`; e.g. a free point of a line beyond a vertex), are
written as ``where`` lines (``# the figures where the goal holds``), or the problem is refused: never a statement
pgsym would refute. A goal that held in every random figure but that the engine refutes exactly holds in part
of the figures only (AlphaGeometry's figure is drawn until the goal holds): :func:`solve` reports it
unsupported with that reason, not refuted.

Goals: ``coll para perp cong cyclic eqangle eqratio midp simtri contri``. Constructions pgsym cannot
express are refused with the same error, naming the construction.

>>> print(translate("a b c = triangle a b c; d = midpoint d a b ? coll a b d"))
expect true
points a b c
point d = midpoint a b
prove collinear a b d
>>> translate("a b c = triangle a b c; x y = trisect x y a b c ? coll a b x")
Traceback (most recent call last):
...
pgsym.proofs.errors.UnsupportedConstructionError: unsupported: trisect (the trisectors of an angle need cube roots; ...
"""

from __future__ import annotations

import itertools
import math
import os
import random
import re
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import PgsymError
from ..limits import MAX_ARGUMENT_CHARS, MAX_STATEMENT_LINE_CHARS, MAX_STATEMENT_NAME_CHARS
from .engine import prove
from .errors import AlphaGeometryError, StatementError, UnsupportedConstructionError
from .language import KEYWORDS, parse_statement, read_statement_text
from .order_search import Figure, restricting_conditions, selecting_conditions

__all__ = ["MAX_AG_BYTES", "MAX_AG_LINE_CHARS", "MAX_AG_PROBLEMS", "OUTCOMES", "Outcome", "Problem",
           "read_alphageometry", "read_alphageometry_file", "solve", "translate"]

MAX_AG_BYTES = 2_000_000
"""The largest problem file read (the two public sets are about 60 kB)."""

MAX_AG_LINE_CHARS = 4 * MAX_STATEMENT_LINE_CHARS
"""The longest line of a problem file (the longest public problem has about 600 characters)."""

MAX_AG_PROBLEMS = 5000
"""The most problems in one file."""

MAX_AG_CLAUSES = 100
"""The most clauses (points defined) in one problem."""

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_NUMBER = re.compile(r"-?[0-9]{1,4}\Z")


@dataclass(frozen=True)
class Problem:
    """One problem of a file: its name, the line it is on, and the statement text or the error that refused it."""

    name: str
    line: int
    source: str
    statement: str | None = None
    error: StatementError | None = None
    held: bool = False  # the goal held in every random float figure of the translation


def read_alphageometry(text: str, source: str = "") -> list[Problem]:
    """Read a problem file of AlphaGeometry (a name line, then the problem line) into translated problems.

    Every problem is translated or carries its named error; only a file beyond the limits raises.

    >>> [(p.name, p.error is None) for p in read_alphageometry("demo\\na b = segment a b; m = midpoint m a b"
    ...                                                          " ? cong m a m b\\nbad\\na = foo a ? coll a a a")]
    [('demo', True), ('bad', False)]
    """
    if len(text) > MAX_AG_BYTES:
        raise AlphaGeometryError(f"the file has {len(text)} characters; at most {MAX_AG_BYTES} are read", source=source)
    problems: list[Problem] = []
    name, name_line = "", 0
    for lineno, raw in enumerate(text.splitlines(), start=1):
        if len(raw) > MAX_AG_LINE_CHARS:
            raise AlphaGeometryError(f"a line of {len(raw)} characters; lines have at most {MAX_AG_LINE_CHARS}",
                                     lineno, source=source)
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        bad = next((ch for ch in line if (ord(ch) < 32 and ch != "\t") or ch == "\x7f"), None)
        if "=" not in line:  # a name line
            if bad is not None or len(line) > MAX_ARGUMENT_CHARS:
                raise AlphaGeometryError("a problem name must be printable text of at most "
                                         f"{MAX_ARGUMENT_CHARS} characters", lineno, source=source)
            name, name_line = line, lineno
            continue
        if len(problems) >= MAX_AG_PROBLEMS:
            raise AlphaGeometryError(f"more than {MAX_AG_PROBLEMS} problems in one file", lineno, source=source)
        this = name if name_line == lineno - 1 and name else f"problem-{len(problems) + 1}"
        try:
            if bad is not None:
                raise AlphaGeometryError(f"a control character {bad!r}; a problem is plain text", lineno)
            statement, held = _translate(line, lineno, title=this)
            problems.append(Problem(this, lineno, source, statement=statement, held=held))
        except StatementError as err:
            err.line, err.source = err.line or lineno, source
            problems.append(Problem(this, lineno, source, error=err))
    return problems


def read_alphageometry_file(path: str | os.PathLike[str]) -> list[Problem]:
    """Read a problem file (UTF-8, at most :data:`MAX_AG_BYTES` bytes) with :func:`read_alphageometry`."""
    p = Path(path)
    text = read_statement_text(p, "problem file", MAX_AG_BYTES, AlphaGeometryError)
    return read_alphageometry(text, source=str(p))


OUTCOMES = ("proved", "refuted", "unknown", "unsupported", "error")
"""What :func:`solve` can say of a problem, in the order of the summaries."""


@dataclass(frozen=True)
class Outcome:
    """The result of one problem: ``status`` one of :data:`OUTCOMES`, the engine's verdict when it ran, the
    message of an unsupported construction or an error, and the seconds taken."""

    problem: Problem
    status: str
    verdict: Any = None
    message: str = ""
    elapsed: float = 0.0

    @property
    def either(self) -> bool:
        """Whether the translation lets either common point of a line and a circle (or two circles) be taken,
        as AlphaGeometry does at random: a refutation then may mean the problem needs a branch condition."""
        return bool(self.problem.statement and re.search(r"=\s*intersection\b", self.problem.statement))


def solve(problem: Problem, timeout: float | None = 10.0) -> Outcome:
    """Parse a translated problem and prove it: proved, refuted (the engine found the goal false), unknown
    (timed out or undecided), unsupported (not translated), error (not read, or the statement refused).

    >>> [problem] = read_alphageometry("m\\na b = segment a b; m = midpoint m a b ? cong m a m b")
    >>> solve(problem).status
    'proved'
    """
    if problem.error is not None:
        status = "unsupported" if isinstance(problem.error, UnsupportedConstructionError) else "error"
        return Outcome(problem, status, message=str(problem.error))
    start = time.perf_counter()
    try:
        claim = parse_statement(problem.statement or "", name=problem.name, source=problem.source)
        verdict = prove(claim, timeout=timeout)
    except PgsymError as err:
        return Outcome(problem, "error", message=str(err), elapsed=time.perf_counter() - start)
    status = {"proved": "proved", "false": "refuted"}.get(str(verdict.status), "unknown")
    if status == "refuted" and problem.held:
        # AlphaGeometry draws its figure again until the goal holds: a goal that held in every random figure yet
        # fails at an exact counterexample holds in part of the figures only, selected by an order condition the
        # problem does not state (which arc, which side) — not a refutation of the problem as AlphaGeometry reads it
        return Outcome(problem, "unsupported", verdict=verdict, elapsed=time.perf_counter() - start,
                       message=f"unsupported: the goal held in {_FIGURES} random figures but fails at an exact "
                               "counterexample: it holds in part of the figures only (AlphaGeometry draws its figure "
                               "again until the goal holds), and the problem states no order condition that selects "
                               "them")
    return Outcome(problem, status, verdict=verdict, elapsed=time.perf_counter() - start)


def translate(problem: str, line: int = 0, title: str = "") -> str:
    """The statement text (pgsym's language) of one problem line of AlphaGeometry.

    Raises :class:`~pgsym.proofs.errors.AlphaGeometryError` for text that is not a problem, and
    :class:`~pgsym.proofs.errors.UnsupportedConstructionError` for what pgsym cannot express.

    >>> print(translate("a b = segment a b; c = on_circle c a b, on_line c a b ? cong a b a c"))
    expect true
    points a b
    point c = reflect b (foot a (join a b))
    prove equallength a b a c
    """
    return _translate(problem, line, title)[0]


class _OneOrientation(UnsupportedConstructionError):
    """The goal holds in one orientation of a shape AlphaGeometry mirrors at random (resolved if always the same)."""


def _drawn(problem: str, line: int, title: str, seed: int, orientation: bool | None = None,
           pick: dict[str, int] | None = None
           ) -> tuple[_Translator, str, dict[tuple[bool, tuple[int, ...]], bool], list[Figure]] | None:
    """One random figure of the problem on every choice of its random points (and mirrored, for the shapes
    AlphaGeometry mirrors at random, unless ``orientation`` fixes the mirrored one or not): the translator of the
    first choice, the statement, whether the goal holds on each choice, and the figure's points per choice; None
    when the figure has no real intersection."""
    start = bool(orientation)
    try:
        first = _Translator(line, seed, (), start, pick)
        out = first.run(problem, title)
        results = {(start, ()): first.goal_holds()}
        choices = list(itertools.product((0, 1), repeat=min(len(first.either), 3)))
        flips = (False, True) if first.flippable and orientation is None else (start,)
        drawings: dict[bool, Figure] = {start: {choices[0]: (first.points(), results[start, ()])}}
        texts = {start: out}  # the mirrored shape turns the other way in its text
        for flip, bits in list(itertools.product(flips, choices))[1:]:
            full, bits = bits, bits if any(bits) else ()
            t = _Translator(line, seed, bits, flip, pick)
            try:
                other = t.run(problem, title)
                holds = t.goal_holds()
            except _NoFigure:
                continue  # a degenerate choice (AlphaGeometry would draw again): the others decide
            if other != texts.setdefault(flip, other):
                raise first.branch(first.either, "the translation depends on the choice")
            results[flip, bits] = holds
            drawings.setdefault(flip, {})[full] = (t.points(), holds)
            first.ray_twice = first.ray_twice or t.ray_twice
            if flip and (False, bits) in results and holds != results[False, bits]:
                error = _OneOrientation if not first.either else UnsupportedConstructionError
                raise error(f"unsupported: {first.flippable} needs a branch condition (AlphaGeometry draws it "
                            "mirrored at random, and the goal holds in one orientation only, not always the same)",
                            line, construction=first.flippable)
    except _NoFigure:
        return None
    if first.ray_twice:
        raise first.unsupported(first.ray_twice.split("/")[0], "needs a branch condition: in some figures the ray "
                                f"({first.ray_twice}) meets the circle twice, and AlphaGeometry then takes one "
                                "by the order of its own computation")
    return first, out, results, list(drawings.values())


def _translate(problem: str, line: int = 0, title: str = "") -> tuple[str, bool]:
    """The statement text, and whether the goal held in every random figure (else it held in none)."""
    if len(problem) > MAX_AG_LINE_CHARS:
        raise AlphaGeometryError(f"a problem of {len(problem)} characters; at most {MAX_AG_LINE_CHARS}", line)
    try:
        return _translate_drawn(problem, line, title)
    except _OneOrientation as err:
        # AlphaGeometry draws the shape either way round until the goal holds: the orientation it means is the one
        # where the goal holds in every random figure, if one is; the statement's turns then say which it is
        for orientation in (False, True):
            try:
                text, held = _translate_drawn(problem, line, title, orientation)
            except UnsupportedConstructionError:
                continue
            if held:
                lines = text.split("\n")
                at = lines.index("expect true") + 1
                note = f"# AlphaGeometry draws {err.construction} either way round: the goal holds this way"
                return "\n".join([*lines[:at], note, *lines[at:]]), True
        raise UnsupportedConstructionError(err.message, line, construction=err.construction) from None


def _translate_drawn(problem: str, line: int, title: str, orientation: bool | None = None,
                     pick: dict[str, int] | None = None) -> tuple[str, bool]:
    """:func:`_translate` with the shapes AlphaGeometry mirrors at random drawn either way (None) or one way, and
    the random common points of ``pick`` taken as said there."""
    # Random float figures, on every choice of the points AlphaGeometry takes at random (at most 2³ choices):
    # a goal that holds on some choices only needs a branch condition, one that holds in some figures only a
    # condition on the figure: order conditions found on the figures' points, or the problem is refused.
    text, either, truths = None, [], []
    figures: list[Figure] = []  # each random figure: per choice, its points and whether the goal holds
    seed = 0
    for seed in range(_NUMERIC_TRIES):
        drawn = _drawn(problem, line, title, seed, orientation, pick)
        if drawn is None:
            continue  # the random figure had no real intersection: another one, as AlphaGeometry does
        first, out, results, drawings = drawn
        if text is None:
            text, either, named = out, first.either, (first.either_points, list(first.defined.values()))
            random_ag = first.either_ag
        elif out != text:
            raise first.branch(first.either, "the translation depends on the figure")
        truths += [(seed, holds) for holds in results.values()]
        figures += drawings
        if len({s for s, _ in truths}) >= _FIGURES:
            break
    if text is None:
        raise UnsupportedConstructionError(f"unsupported: two loci that did not meet in {_NUMERIC_TRIES} random "
                                           "figures (or a figure fell degenerate each time), so no figure of the "
                                           "problem could be drawn", line, construction="intersection")
    if len({h for _, h in truths}) == 2:
        by_seed: dict[int, set[bool]] = {}
        for seed, holds in truths:
            by_seed.setdefault(seed, set()).add(holds)
        # more figures than for the verdict above: a condition must hold in every one of them
        for extra in range(seed + 1, seed + 1 + _SELECTION_TRIES):
            drawn = _drawn(problem, line, title, extra, orientation, pick)
            if drawn is not None and drawn[1] == text:
                figures += drawn[3]
        if any(len(v) == 2 for v in by_seed.values()):
            # AlphaGeometry draws its figure until the goal holds: the point it means is the one an order condition
            # of every figure selects, if one does; the engine then proves the goal on the branch it selects
            found = selecting_conditions(figures, *named) if len(either) <= 3 else None
            if found is None and not pick:
                # both common points may be rational (a parallelogram's fourth vertex, a vector turned by 90° from
                # a point): then the one where the goal holds in every random figure is written as it is
                for ag, choice in itertools.product(random_ag, (0, 1)):
                    try:
                        picked, held = _translate_drawn(problem, line, title, orientation, {ag: choice})
                    except UnsupportedConstructionError:
                        continue
                    if held and "# the common point of" in picked:
                        return picked, True
            if found is None:
                raise _Translator(line).branch(either, "the goal holds for one of the two common points only, and "
                                                       "no order condition on the figure's points (one, or two "
                                                       "together) selects that point in every random figure")
            head, prove = text.split("\nprove ", 1)
            where = [f"where {word} {' '.join(args)}  # selects the common point where the goal holds"
                     for word, args in found]
            return "\n".join([head, *where, "prove " + prove]), True
        # the goal holds in some figures only: AlphaGeometry's figure is one where it holds, which an order condition
        # on the figure's points may say (a point beyond a vertex rather than before it)
        found = restricting_conditions(figures, named[1])
        if found is None:
            raise UnsupportedConstructionError("unsupported: the goal holds in some random figures only, and no order "
                                               "condition on the figure's points (one, or two together) keeps only "
                                               "figures where it holds (AlphaGeometry draws its figure until it does)",
                                               line, construction="figure")
        head, prove = text.split("\nprove ", 1)
        where = [f"where {word} {' '.join(args)}  # the figures where the goal holds" for word, args in found]
        return "\n".join([head, *where, "prove " + prove]), True
    return text, all(h for _, h in truths)


# -- the figure: which points are known on which lines and circles ------------------------------------------


@dataclass(eq=False)
class _Circle:
    centre: str | None  # an AG point, or None (then centre_expr is pgsym's centre (circle a b c))
    points: set[str] = field(default_factory=set)
    radius: frozenset[str] | None = None  # eqdistance: the centre's distance is |bc|


@dataclass
class _Locus:
    kind: str  # "line", "circle" or "conic"
    expr: str  # pgsym text of the line or circle (names already pgsym's)
    on: set[str]  # AG points known on it
    name: str  # the construction (for messages)
    add: Callable[[str], None]  # records the new point on it
    centre: str = ""  # circle: pgsym text of its centre
    through: str = ""  # circle: pgsym text of a point on it (for a free point on the circle)
    ray: bool = False  # a half-line of AG: meeting a circle picks the point on the ray
    tail: str = ""  # the ray's origin (an AG point)
    head: str = ""  # a second point of the ray, as an argument (pgsym text): where onray X tail head
    ahead: str = ""  # the same point as a definition (pgsym text): a ray from a circle's centre meets the circle
    # there when that point is on the circle
    place: Callable[[str], None] | None = None  # writes a free point of a locus that is no line or circle


class _Translator:
    def __init__(self, line: int, seed: int = 0, bits: tuple[int, ...] = (), flip: bool = False,
                 pick: dict[str, int] | None = None) -> None:
        self.line = line
        self.flip, self.flippable = flip, ""  # the mirrored figure of a shape AG mirrors at random
        self.numeric = _Numeric(seed, bits)
        self.either: list[str] = []  # the constructions of the points AG takes at random (either common point)
        self.either_points: list[str] = []  # those points (pgsym names)
        self.either_ag: list[str] = []  # and AlphaGeometry's
        self.pick = dict(pick or {})  # AG point -> which rational common point to take (0 the vertex, 1 the other)
        self.ray_twice = ""  # a ray that met its circle twice in this figure (AG then takes one by its own order)
        self.goal_words: list[str] = []
        self.out: list[str] = []
        self.defined: dict[str, str] = {}  # AG name -> pgsym name (in definition order)
        self.collinear: list[set[str]] = []
        self.keyed: dict[tuple, set[str]] = {}  # non-join lines: ("perp", P, {B, C}) -> points on it
        self.circles: list[_Circle] = []
        self.aux = 0
        self.branches = False  # a square root with two signs is written (a bisector, a common point, a tangent)

    def emit(self, statement: str) -> None:
        """Write a statement, and evaluate it on the numeric figure."""
        self.out.append(statement)
        self.numeric.run(statement)
        self.branches = self.branches or bool(_BRANCHING.search(statement))

    # -- errors and names ---------------------------------------------------------------------------------
    def fail(self, message: str, construction: str = "") -> AlphaGeometryError:
        return AlphaGeometryError(message, self.line, construction=construction)

    def branch(self, either: list[str], why: str) -> UnsupportedConstructionError:
        name = either[0] if either else "intersection"
        return UnsupportedConstructionError(f"unsupported: {name} needs a branch condition ({why}; AlphaGeometry "
                                            "takes either point at random and draws its figure again until the goal "
                                            "holds)", self.line,
                                            construction=name.split()[0])

    def points(self) -> dict[str, complex]:
        """The float values of the problem's points in this figure (pgsym names)."""
        return {x: self.numeric.values[x] for x in self.defined.values()}

    def goal_holds(self) -> bool:
        """Whether the goal holds in the float figure."""
        name, *args = self.goal_words
        try:
            return _GOALS[name]([self.numeric.values[self.defined[a]] for a in args])
        except (ZeroDivisionError, OverflowError):
            raise _NoFigure from None

    def unsupported(self, construction: str, why: str) -> UnsupportedConstructionError:
        return UnsupportedConstructionError(f"unsupported: {construction} ({why})", self.line,
                                            construction=construction)

    def p(self, ag: str) -> str:
        """The pgsym name of a defined AG point."""
        if ag not in self.defined:
            raise self.fail(f"the point {ag!r} is used before it is defined")
        return self.defined[ag]

    def new_aux(self, prefix: str) -> str:
        self.aux += 1
        return f"{prefix}'{self.aux}"  # AG names never hold ', so no clash

    def define(self, ag: str) -> str:
        if not _NAME.match(ag) or len(ag) > MAX_STATEMENT_NAME_CHARS - 1:
            raise self.fail(f"{ag[:40]!r} is not a point name (letters, digits and _, starting with a letter, "
                            f"at most {MAX_STATEMENT_NAME_CHARS - 1} characters)")
        if ag in self.defined:
            raise self.fail(f"the point {ag} is defined twice")
        self.defined[ag] = ag + "'" if ag in KEYWORDS else ag
        return self.defined[ag]

    # -- incidences known by construction -----------------------------------------------------------------
    def on_join(self, a: str, b: str) -> set[str]:
        found = {a, b}
        for s in self.collinear:
            if a in s and b in s:
                found |= s
        return found

    def add_collinear(self, *pts: str) -> None:
        new = set(pts)
        if len(new) < 2:
            return
        keep = []
        for s in self.collinear:
            if len(s & new) >= 2:
                new |= s
            else:
                keep.append(s)
        self.collinear = [*keep, new]

    def key_line(self, key: tuple, *pts: str) -> set[str]:
        s = self.keyed.setdefault(key, set())
        s.update(pts)
        return s

    def circle_record(self, centre: str | None, points: set[str], radius: frozenset[str] | None = None) -> _Circle:
        """The record of the circle with that centre through those points (merged with what is known)."""
        for c in self.circles:
            same_centre = centre is not None and c.centre == centre
            if same_centre and (c.points & points or (radius is not None and c.radius == radius)):
                break
            if len(c.points & points) >= 3 or (len(points) >= 3 and points <= c.points):
                break
        else:
            c = _Circle(centre)
            self.circles.append(c)
        c.points |= points
        if c.centre is None:
            c.centre = centre
        if c.radius is None:
            c.radius = radius
        return c

    def circle_locus(self, rec: _Circle, name: str, expr: str = "", through: str = "") -> _Locus:
        pts = sorted(rec.points, key=list(self.defined).index)
        if rec.centre is not None and pts:
            centre = self.p(rec.centre)
            expr = expr or f"circle {centre} {self.p(pts[0])}"
            through = through or self.p(pts[0])
        elif rec.centre is not None:
            centre = self.p(rec.centre)
        else:
            expr = f"circle {self.p(pts[0])} {self.p(pts[1])} {self.p(pts[2])}"
            centre, through = f"(centre ({expr}))", self.p(pts[0])
        return _Locus("circle", expr, set(rec.points), name, rec.points.add, centre=centre, through=through)

    def join_locus(self, a: str, b: str, name: str) -> _Locus:
        if a == b:
            raise self.fail(f"{name}: the line through {a} and {b} needs two different points", name)
        return _Locus("line", f"join {self.p(a)} {self.p(b)}", self.on_join(a, b), name,
                      lambda x: self.add_collinear(a, b, x))

    def keyed_locus(self, key: tuple, expr: str, through: str, name: str, head: str = "", ahead: str = "") -> _Locus:
        """A line through ``through`` (shared by every construction with the same ``key``); with ``head`` (and
        ``ahead``, the same point written as a definition) the half-line from ``through`` towards that point."""
        pts = self.key_line(key, through)
        return _Locus("line", expr, set(pts), name, lambda x: (pts.add(x), self.add_collinear(*pts)), ray=bool(head),
                      tail=through, head=head, ahead=ahead)

    # -- a problem --------------------------------------------------------------------------------------------
    def run(self, problem: str, title: str) -> str:
        if problem.count("?") != 1:
            raise self.fail("a problem is 'CLAUSES ? GOAL' with one '?'")
        body, goal = problem.split("?")
        clauses = [c for c in body.split(";") if c.strip()]
        if not clauses:
            raise self.fail("the problem defines no points")
        if len(clauses) > MAX_AG_CLAUSES:
            raise self.fail(f"more than {MAX_AG_CLAUSES} clauses in one problem")
        head = [f"title {_printable(title)}"] if title else []
        for clause in clauses:
            self.clause(clause)
        self.goal(goal.split())
        return "\n".join([*head, "expect true", *self.out])

    def clause(self, text: str) -> None:
        if text.count("=") != 1:
            raise self.fail(f"a clause is 'POINTS = CONSTRUCTION, …', found {text.strip()[:60]!r}")
        lhs, rhs = text.split("=")
        news = [w.split("@", 1)[0] for w in lhs.split()]  # x@1.5_2 : a numeric hint of AG's, not used
        if not news:
            raise self.fail(f"the clause {text.strip()[:60]!r} names no new point")
        if len(set(news)) != len(news):
            raise self.fail(f"a point is named twice in {lhs.strip()!r}")
        parts = [c.split() for c in rhs.split(",")]
        if any(not c for c in parts):
            raise self.fail(f"an empty construction in {rhs.strip()[:60]!r}")
        if len(parts) > 2:
            raise self.unsupported(parts[0][0], "more than two constraints on one point")
        for c in parts:
            if c[0] not in _CONSTRUCTIONS:
                if c[0] in _UNSUPPORTED:
                    raise self.unsupported(c[0], _UNSUPPORTED[c[0]])
                raise self.fail(f"unknown construction {c[0][:40]!r}", c[0][:40])
            arity, count, _ = _CONSTRUCTIONS[c[0]]
            short = len(c) - 1 == arity - count and count == len(news)
            if short and sorted(c[1:1 + count]) != sorted(news):  # the short form: on_line b c for x
                c[1:1] = news
            if len(c) - 1 != arity:
                raise self.fail(f"{c[0]} takes {arity} arguments, got {len(c) - 1}", c[0])
            if c[0] in _NEW_AT:  # the new points first
                at = _NEW_AT[c[0]]
                c[1:] = [c[1 + i] for i in at] + [w for i, w in enumerate(c[1:]) if i not in at]
            if sorted(c[1:1 + count]) != sorted(news):  # in any order: AG defines them as the arguments say
                raise self.fail(f"{c[0]} defines {count} point(s), its first argument(s); the clause defines "
                                f"{' '.join(news)}", c[0])
            for a in c[1 + count:]:
                if not _NUMBER.match(a) and a not in self.defined:
                    raise self.fail(f"the point {a[:40]!r} is used before it is defined", c[0])
        if len(parts) == 1:
            name, *args = parts[0]
            result = _CONSTRUCTIONS[name][2](self, args)
            if isinstance(result, _Locus):
                self.free_on(self.define(args[0]), args[0], result)
            return
        loci = []
        for name, *args in parts:
            result = _CONSTRUCTIONS[name][2](self, args)
            if not isinstance(result, _Locus):
                raise self.fail(f"{name} defines its point alone; it cannot be met with another construction", name)
            loci.append(result)
        self.intersect(parts[0][1], *loci)

    def free_on(self, x: str, ag: str, locus: _Locus) -> None:
        if locus.kind == "line":
            two = locus.expr.split()
            where = (f"{two[1]} {two[2]}" if two[0] == "join" and len(two) == 3
                     else two[0] if len(two) == 1 else f"({locus.expr})")
            self.emit(f"point {x} on line {where}")
        elif locus.place is not None:
            locus.place(x)
        else:
            self.emit(f"point {x} on circle ({locus.expr}) through {locus.through}")
        locus.add(ag)

    def intersect(self, ag: str, one: _Locus, two: _Locus) -> None:
        if "conic" in (one.kind, two.kind):
            raise self.unsupported(one.name if one.kind == "conic" else two.name,
                                   "a conic met with another locus: its common points are not constructed")
        if one.kind == "circle" and two.kind == "line":
            one, two = two, one
        common = sorted((one.on & two.on) - {ag}, key=list(self.defined).index)
        if one.kind != "line" or two.kind != "line":
            common = self.numeric.common(one.expr, two.expr, common, self)
        if one.kind == "line" and two.kind == "line":
            x = self.define(ag)
            self.emit(f"point {x} = meet ({one.expr}) ({two.expr})")
            if self.branches:
                # AlphaGeometry's lines meet in the plane (npara), pgsym's meet of parallel lines is their point
                # at infinity: a construction that needs x finite carries that hypothesis, so a branch of the
                # square roots on which the lines are always parallel is no counterexample (rational lines are
                # parallel at no generic figure, so they need none)
                self.emit(f"point {self.new_aux('fin')} = reflect {x} {next(iter(self.defined.values()))}  "
                          f"# {x} is a finite point")
        elif (one.kind == "line" and one.ray and one.ahead and two.centre == self.p(one.tail)
              and self.numeric.on_circle(one.ahead, two.expr)):
            # a ray from the centre meets the circle once: at the point of the ray already on it
            x = self.define(ag)
            self.emit(f"point {x} = {one.ahead}")
        elif one.kind == "line" and one.ray and (not common or common[0] != one.tail):
            # AlphaGeometry's half-line meets the circle at its point on the ray (numericals.HalfLine.intersect):
            # an order condition of the figure, not a random choice
            x = self.define(ag)
            self.out.append(f"point {x} = intersection ({one.expr}) ({two.expr})")
            self.out.append(f"where onray {x} {self.p(one.tail)} {one.head}")
            if self.numeric.on_ray(x, one.expr, two.expr, self.p(one.tail), one.head):
                self.ray_twice = f"{one.name}/{two.name} of {ag}"
        elif one.kind == "line" and common:
            x = self.define(ag)
            self.emit(f"point {x} = reflect {self.p(common[0])} (foot {two.centre} ({one.expr}))")
        elif common:
            x = self.define(ag)
            self.emit(f"point {x} = reflect {self.p(common[0])} (join {one.centre} {two.centre})")
        else:
            x = self.define(ag)
            vertex = self.numeric.rational_common(one.expr, two.expr, self) if ag in self.pick else ""
            if vertex:  # both common points are rational: the one the goal holds at (see _translate)
                mirror = (f"(foot {two.centre} ({one.expr}))" if one.kind == "line"
                          else f"(join {one.centre} {two.centre})")
                self.emit(f"point {x} = {vertex if self.pick[ag] == 0 else f'reflect ({vertex}) {mirror}'}  # the "
                          f"common point of {one.name}/{two.name} where the goal holds")
            else:
                self.either.append(f"{one.name}/{two.name} of {ag}")
                self.either_points.append(x)
                self.either_ag.append(ag)
                self.emit(f"point {x} = intersection ({one.expr}) ({two.expr})")
        one.add(ag)
        two.add(ag)

    # -- goals ---------------------------------------------------------------------------------------------
    def goal(self, words: list[str]) -> None:
        if not words:
            raise self.fail("the goal after '?' is empty")
        name, args = words[0], words[1:]
        counts = {"coll": None, "cyclic": None, "para": 4, "perp": 4, "cong": 4, "eqangle": 8, "eqratio": 8,
                  "midp": 3, "simtri": 6, "contri": 6, "simtrir": 6, "contrir": 6}
        if name not in counts:
            raise self.unsupported(name[:40], "a goal pgsym's statement language cannot state")
        want = counts[name]
        if (want is not None and len(args) != want) or (want is None and len(args) < (3 if name == "coll" else 4)):
            raise self.fail(f"the goal {name} takes {want or 'at least 3'} points, got {len(args)}", name)
        p = [self.p(a) for a in args]
        self.goal_words = [name, *args]

        def d(i: int, j: int) -> str:
            return f"(dist2 {p[i]} {p[j]})"

        lines = []
        if name == "coll":
            lines = [f"collinear {p[0]} {p[1]} {q}" for q in p[2:]]
        elif name == "cyclic":
            lines = [f"concyclic {p[0]} {p[1]} {p[2]} {q}" for q in p[3:]]
        elif name in ("para", "perp"):
            word = "parallel" if name == "para" else "perpendicular"
            lines = [f"{word} (join {p[0]} {p[1]}) (join {p[2]} {p[3]})"]
        elif name == "cong":
            lines = [f"equallength {' '.join(p)}"]
        elif name == "eqangle":
            lines = [f"equalangle {self.angle(p[0:4])} {self.angle(p[4:8])}"]
        elif name == "eqratio":  # ab/cd = pq/rs, squared
            lines = [f"equal (mul {d(0, 1)} {d(6, 7)}) (mul {d(2, 3)} {d(4, 5)})"]
        elif name == "midp":
            lines = [f"equal {p[0]} (midpoint {p[1]} {p[2]})"]
        elif name in ("simtri", "simtrir"):  # ab·yz = bc·xy and bc·zx = ca·yz, squared (AG's check_simtri)
            lines = [f"equal (mul {d(0, 1)} {d(4, 5)}) (mul {d(1, 2)} {d(3, 4)})",
                     f"equal (mul {d(1, 2)} {d(5, 3)}) (mul {d(2, 0)} {d(4, 5)})"]
        else:  # contri: the three sides equally long
            lines = [f"equallength {p[0]} {p[1]} {p[3]} {p[4]}", f"equallength {p[1]} {p[2]} {p[4]} {p[5]}",
                     f"equallength {p[2]} {p[0]} {p[5]} {p[3]}"]
        self.out.extend(f"prove {text}" for text in lines)

    def angle(self, q: list[str]) -> str:
        """The angle from line q0 q1 to line q2 q3 as three arguments of equalangle (vertex in the middle)."""
        a, b, c, e = q
        for v in (a, b):
            if v in (c, e):
                u = b if v == a else a
                w = e if v == c else c
                return f"{u} {v} {w}"
        return f"{b} {a} (translate {a} {c} {e})"  # the line cd moved through a


def _printable(text: str) -> str:
    return "".join(ch if ch.isprintable() else "?" for ch in text)[:200]


# -- the constructions of defs.txt ------------------------------------------------------------------------------
# name -> (number of arguments, how many of them are the new points, builder(translator, arguments)); a builder
# returns a locus for a one-parameter construction, or writes the definitions of fully determined points.

_BRANCHING = re.compile(r"= (anglebisector|exbisector|intersections?|tangentsfrom|tangentfrom) ")

_Build = Callable[[_Translator, list[str]], "_Locus | None"]
_CONSTRUCTIONS: dict[str, tuple[int, int, _Build]] = {}


_NEW_AT = {"s_angle": (2,), "parallelogram": (3,), "square": (2, 3)}  # where the new points are, if not first


def _construction(name: str, arity: int, count: int = 1) -> Callable[[_Build], _Build]:
    def register(f: _Build) -> _Build:
        _CONSTRUCTIONS[name] = (arity, count, f)
        return f
    return register


def _free(n: int, name: str) -> _Build:
    def build(t: _Translator, a: list[str]) -> None:
        t.emit("points " + " ".join(t.define(x) for x in a))
    _CONSTRUCTIONS[name] = (n, n, build)
    return build


for _n, _word in ((1, "free"), (2, "segment"), (3, "triangle"), (4, "quadrangle"), (5, "pentagon")):
    _free(_n, _word)


def _point(t: _Translator, ag: str, expr: str) -> str:
    x = t.define(ag)
    t.emit(f"point {x} = {expr}")
    return x


def _distinct(t: _Translator, name: str, *pts: str) -> None:
    if len(set(pts)) != len(pts):
        raise t.fail(f"{name} needs different points, got {' '.join(pts)}", name)


@_construction("on_line", 3)
def _on_line(t: _Translator, a: list[str]) -> _Locus:
    return t.join_locus(a[1], a[2], "on_line")


@_construction("on_circle", 3)
def _on_circle(t: _Translator, a: list[str]) -> _Locus:
    _distinct(t, "on_circle", a[1], a[2])
    return t.circle_locus(t.circle_record(a[1], {a[2]}), "on_circle")


@_construction("on_circum", 4)
def _on_circum(t: _Translator, a: list[str]) -> _Locus:
    _distinct(t, "on_circum", *a[1:])
    return t.circle_locus(t.circle_record(None, set(a[1:])), "on_circum")


@_construction("on_tline", 4)
def _on_tline(t: _Translator, a: list[str]) -> _Locus:
    _distinct(t, "on_tline", a[2], a[3])
    return t.keyed_locus(("perp", a[1], frozenset(a[2:])), f"perpendicular (join {t.p(a[2])} {t.p(a[3])}) "
                         f"{t.p(a[1])}", a[1], "on_tline")


@_construction("lc_tangent", 3)
def _lc_tangent(t: _Translator, a: list[str]) -> _Locus:
    _distinct(t, "lc_tangent", a[1], a[2])
    return t.keyed_locus(("perp", a[1], frozenset(a[1:])), f"perpendicular (join {t.p(a[1])} {t.p(a[2])}) "
                         f"{t.p(a[1])}", a[1], "lc_tangent")


@_construction("on_pline", 4)
def _on_pline(t: _Translator, a: list[str]) -> _Locus:
    _distinct(t, "on_pline", a[2], a[3])
    return t.keyed_locus(("para", a[1], frozenset(a[2:])), f"parallel (join {t.p(a[2])} {t.p(a[3])}) "
                         f"{t.p(a[1])}", a[1], "on_pline")


@_construction("on_bline", 3)
def _on_bline(t: _Translator, a: list[str]) -> _Locus:
    _distinct(t, "on_bline", a[1], a[2])
    pair = frozenset(a[1:])
    key = ("bline", pair)
    pts = t.key_line(key)
    pts.update(c.centre for c in t.circles if c.centre is not None and pair <= c.points)
    return _Locus("line", f"bisector {t.p(a[1])} {t.p(a[2])}", set(pts), "on_bline",
                  lambda x: (pts.add(x), t.add_collinear(*pts)))


@_construction("on_dia", 3)
def _on_dia(t: _Translator, a: list[str]) -> _Locus:
    _distinct(t, "on_dia", a[1], a[2])
    rec = t.circle_record(None, set(a[1:]))
    mid = f"(midpoint {t.p(a[1])} {t.p(a[2])})"
    return _Locus("circle", f"circle {mid} {t.p(a[1])}", set(rec.points), "on_dia", rec.points.add, centre=mid,
                  through=t.p(a[1]))


@_construction("eqdistance", 4)
def _eqdistance(t: _Translator, a: list[str]) -> _Locus:
    _, o, b, c = a
    _distinct(t, "eqdistance", b, c)
    if o in (b, c):  # |xo| = |oc|: the circle of centre o through the other point
        return t.circle_locus(t.circle_record(o, {c if o == b else b}), "eqdistance")
    rec = t.circle_record(o, set(), frozenset((b, c)))
    through = f"(translate {t.p(o)} {t.p(b)} {t.p(c)})"  # o moved by the vector bc: at distance |bc| from o
    return _Locus("circle", f"circle {t.p(o)} {through}", set(rec.points), "eqdistance", rec.points.add,
                  centre=t.p(o), through=through)


@_construction("angle_bisector", 4)
def _angle_bisector(t: _Translator, a: list[str]) -> _Locus:
    _, p, v, q = a
    _distinct(t, "angle_bisector", p, v, q)
    line = t.new_aux("bis")
    t.emit(f"line {line} = anglebisector {t.p(p)} {t.p(v)} {t.p(q)}")
    return t.keyed_locus(("bisect", p, v, q), line, v, "angle_bisector")


@_construction("angle_mirror", 4)
def _angle_mirror(t: _Translator, a: list[str]) -> _Locus:
    _, p, v, q = a  # the ray from v that line vq bisects with line vp
    _distinct(t, "angle_mirror", p, v, q)
    image = f"reflect {t.p(p)} (join {t.p(v)} {t.p(q)})"
    return t.keyed_locus(("amirror", p, v, q), f"join {t.p(v)} ({image})", v, "angle_mirror", head=f"({image})",
                         ahead=image)


@_construction("s_angle", 4)
def _s_angle(t: _Translator, a: list[str]) -> _Locus:
    _, p, v, deg = a  # the ray from v turned counter-clockwise by deg degrees from vp
    if not _NUMBER.match(deg) or _NUMBER.match(p) or _NUMBER.match(v):
        raise t.fail(f"s_angle takes two points, the new point and an angle in degrees, got {' '.join(a)}",
                     "s_angle")
    _distinct(t, "s_angle", p, v)
    r = t.new_aux("rot")
    t.emit(f"point {r} = rotate {t.p(p)} {t.p(v)} {int(deg)}")
    return t.keyed_locus(("sangle", p, v, deg), f"join {t.p(v)} {r}", v, "s_angle", head=r,
                         ahead=f"rotate {t.p(p)} {t.p(v)} {int(deg)}")


@_construction("midpoint", 3)
def _midpoint(t: _Translator, a: list[str]) -> None:
    _distinct(t, "midpoint", a[1], a[2])
    _point(t, a[0], f"midpoint {t.p(a[1])} {t.p(a[2])}")
    t.add_collinear(*a)
    t.key_line(("bline", frozenset(a[1:])), a[0])
    t.circle_record(a[0], {a[1], a[2]})


@_construction("mirror", 3)
def _mirror(t: _Translator, a: list[str]) -> None:
    _distinct(t, "mirror", a[1], a[2])
    _point(t, a[0], f"reflect {t.p(a[1])} {t.p(a[2])}")
    t.add_collinear(*a)
    t.circle_record(a[2], {a[0], a[1]})


@_construction("foot", 4)
def _foot(t: _Translator, a: list[str]) -> None:
    x, p, b, c = a
    _distinct(t, "foot", b, c)
    _point(t, x, f"foot {t.p(p)} (join {t.p(b)} {t.p(c)})")
    t.add_collinear(x, b, c)
    t.key_line(("perp", p, frozenset((b, c))), p, x)


@_construction("reflect", 4)
def _reflect(t: _Translator, a: list[str]) -> None:
    x, p, b, c = a
    _distinct(t, "reflect", b, c)
    _point(t, x, f"reflect {t.p(p)} (join {t.p(b)} {t.p(c)})")
    t.key_line(("perp", p, frozenset((b, c))), p, x)
    t.circle_record(b, {p, x})
    t.circle_record(c, {p, x})


@_construction("circle", 4)
def _circle(t: _Translator, a: list[str]) -> None:
    _distinct(t, "circle", *a[1:])
    _point(t, a[0], f"centre (circle {t.p(a[1])} {t.p(a[2])} {t.p(a[3])})")
    t.circle_record(a[0], set(a[1:]))


_CONSTRUCTIONS["circumcenter"] = (4, 1, _circle)


@_construction("orthocenter", 4)
def _orthocenter(t: _Translator, a: list[str]) -> None:
    x, p, q, r = a
    _distinct(t, "orthocenter", p, q, r)
    _point(t, x, f"meet (perpendicular (join {t.p(q)} {t.p(r)}) {t.p(p)}) "
                 f"(perpendicular (join {t.p(r)} {t.p(p)}) {t.p(q)})")
    for u, v, w in ((p, q, r), (q, r, p), (r, p, q)):
        t.key_line(("perp", u, frozenset((v, w))), u, x)


def _centre_of(t: _Translator, x: str, p: str, q: str, r: str, external: bool) -> None:
    """x: the incentre of pqr, or (external) the excentre opposite p (internal at p, external at q)."""
    _distinct(t, "incenter", p, q, r)
    one, two = t.new_aux("bis"), t.new_aux("bis")
    t.emit(f"line {one} = anglebisector {t.p(q)} {t.p(p)} {t.p(r)}")
    t.emit(f"line {two} = {'exbisector' if external else 'anglebisector'} {t.p(p)} {t.p(q)} {t.p(r)}")
    _point(t, x, f"meet {one} {two}")


@_construction("incenter", 4)
def _incenter(t: _Translator, a: list[str]) -> None:
    _centre_of(t, a[0], a[1], a[2], a[3], external=False)


@_construction("excenter", 4)
def _excenter(t: _Translator, a: list[str]) -> None:
    _centre_of(t, a[0], a[1], a[3], a[2], external=True)  # bisect b a c, exbisect b c a: external at c


def _feet(t: _Translator, x: str, y: str, z: str, i: str, p: str, q: str, r: str) -> None:
    for foot, (u, v) in ((x, (q, r)), (y, (r, p)), (z, (p, q))):
        _point(t, foot, f"foot {t.p(i)} (join {t.p(u)} {t.p(v)})")
        t.add_collinear(foot, u, v)
        t.key_line(("perp", i, frozenset((u, v))), i, foot)
    t.circle_record(i, {x, y, z})


@_construction("incenter2", 7, 4)
def _incenter2(t: _Translator, a: list[str]) -> None:
    x, y, z, i, p, q, r = a
    _centre_of(t, i, p, q, r, external=False)
    _feet(t, x, y, z, i, p, q, r)


@_construction("excenter2", 7, 4)
def _excenter2(t: _Translator, a: list[str]) -> None:
    x, y, z, i, p, q, r = a  # bisect b a c, exbisect a b c: external at b
    _centre_of(t, i, p, q, r, external=True)
    _feet(t, x, y, z, i, p, q, r)


def _midpoints(t: _Translator, x: str, y: str, z: str, p: str, q: str, r: str) -> None:
    _distinct(t, "centroid", p, q, r)
    for m, (u, v) in ((x, (q, r)), (y, (r, p)), (z, (p, q))):
        _midpoint(t, [m, u, v])


@_construction("centroid", 7, 4)
def _centroid(t: _Translator, a: list[str]) -> None:
    x, y, z, i, p, q, r = a
    _midpoints(t, x, y, z, p, q, r)
    _point(t, i, f"meet (join {t.p(p)} {t.p(x)}) (join {t.p(q)} {t.p(y)})")
    for u, v in ((p, x), (q, y), (r, z)):
        t.add_collinear(i, u, v)


@_construction("ninepoints", 7, 4)
def _ninepoints(t: _Translator, a: list[str]) -> None:
    x, y, z, i, p, q, r = a
    _midpoints(t, x, y, z, p, q, r)
    _circle(t, [i, x, y, z])


@_construction("intersection_ll", 5)
def _intersection_ll(t: _Translator, a: list[str]) -> None:
    x, p, q, r, s = a
    _distinct(t, "intersection_ll", p, q)
    _distinct(t, "intersection_ll", r, s)
    t.intersect(x, t.join_locus(p, q, "intersection_ll"), t.join_locus(r, s, "intersection_ll"))


@_construction("intersection_lc", 4)
def _intersection_lc(t: _Translator, a: list[str]) -> None:
    x, p, o, b = a  # line b p, circle of centre o through b: the point other than b
    _distinct(t, "intersection_lc", p, b)
    _distinct(t, "intersection_lc", o, b)
    _point(t, x, f"reflect {t.p(b)} (foot {t.p(o)} (join {t.p(b)} {t.p(p)}))")
    t.add_collinear(x, p, b)
    t.circle_record(o, {b, x})


@_construction("intersection_cc", 4)
def _intersection_cc(t: _Translator, a: list[str]) -> None:
    x, o, w, p = a  # the circles of centres o and w through p: the point other than p
    _distinct(t, "intersection_cc", o, w, p)
    _point(t, x, f"reflect {t.p(p)} (join {t.p(o)} {t.p(w)})")
    t.circle_record(o, {p, x})
    t.circle_record(w, {p, x})


@_construction("intersection_lp", 6)
def _intersection_lp(t: _Translator, a: list[str]) -> None:
    x, p, q, c, m, n = a
    _distinct(t, "intersection_lp", m, n)
    t.intersect(x, t.join_locus(p, q, "intersection_lp"), _on_pline(t, [x, c, m, n]))


@_construction("intersection_lt", 6)
def _intersection_lt(t: _Translator, a: list[str]) -> None:
    x, p, q, c, d, e = a
    t.intersect(x, t.join_locus(p, q, "intersection_lt"), _on_tline(t, [x, c, d, e]))


@_construction("intersection_pp", 7)
def _intersection_pp(t: _Translator, a: list[str]) -> None:
    x, p, b, c, q, e, f = a
    t.intersect(x, _on_pline(t, [x, p, b, c]), _on_pline(t, [x, q, e, f]))


@_construction("intersection_tt", 7)
def _intersection_tt(t: _Translator, a: list[str]) -> None:
    x, p, b, c, q, e, f = a
    t.intersect(x, _on_tline(t, [x, p, b, c]), _on_tline(t, [x, q, e, f]))


@_construction("parallelogram", 4)
def _parallelogram(t: _Translator, a: list[str]) -> None:
    x, p, q, r = a  # parallelogram a b c x: x = a + c − b
    _distinct(t, "parallelogram", p, q, r)
    x_ = t.define(x)
    t.emit(f"point {x_} = translate {t.p(r)} {t.p(q)} {t.p(p)}")
    t.key_line(("para", r, frozenset((p, q))), r, x)
    t.key_line(("para", p, frozenset((q, r))), p, x)


@_construction("shift", 4)
def _shift(t: _Translator, a: list[str]) -> None:
    x, b, c, d = a  # x = b + (c − d)
    _distinct(t, "shift", b, d)
    _point(t, x, f"translate {t.p(b)} {t.p(d)} {t.p(c)}")


def _rotate(t: _Translator, ag: str, x: str, o: str, sign: int) -> None:
    """ag = x turned about o by +90° (sign 1) or −90°: an exact rotation (cos 0, sin ±1)."""
    _point(t, ag, f"rotate {t.p(x)} {t.p(o)} 0 {'-' if sign < 0 else ''}1")


def _mirrored(t: _Translator, shape: str) -> int:
    """AlphaGeometry draws this shape mirrored at random: the sense of its turns, −1 in the mirrored figure."""
    t.flippable = t.flippable or shape
    return -1 if t.flip else 1


@_construction("psquare", 3)
def _psquare(t: _Translator, a: list[str]) -> None:
    _distinct(t, "psquare", a[1], a[2])
    _rotate(t, a[0], a[2], a[1], 1)  # a + (b − a) turned by +90°
    t.circle_record(a[1], {a[0], a[2]})


@_construction("nsquare", 3)
def _nsquare(t: _Translator, a: list[str]) -> None:
    _distinct(t, "nsquare", a[1], a[2])
    _rotate(t, a[0], a[2], a[1], -1)
    t.circle_record(a[1], {a[0], a[2]})


@_construction("square", 4, 2)
def _square(t: _Translator, a: list[str]) -> None:
    x, y, p, q = a  # square a b x y: x = b + (a − b) turned by −90°, y = a + (b − a) turned by +90°
    _distinct(t, "square", p, q)
    _rotate(t, x, p, q, -1)
    _rotate(t, y, q, p, 1)


@_construction("isquare", 4, 4)
def _isquare(t: _Translator, a: list[str]) -> None:
    p, q, r, s = a
    t.emit(f"points {t.define(p)} {t.define(q)}")
    turn = _mirrored(t, "isquare")
    _rotate(t, r, p, q, -turn)
    _rotate(t, s, q, p, turn)


@_construction("eq_triangle", 3)
def _eq_triangle(t: _Translator, a: list[str]) -> None:
    x, b, c = a  # either apex: the rotation by 60° names one, its conjugate root the other
    _distinct(t, "eq_triangle", b, c)
    _point(t, x, f"rotate {t.p(c)} {t.p(b)} 60")
    t.circle_record(b, {c, x})
    t.circle_record(c, {b, x})


@_construction("ieq_triangle", 3, 3)
def _ieq_triangle(t: _Translator, a: list[str]) -> None:
    p, q, r = a
    t.emit(f"points {t.define(p)} {t.define(q)}")
    _point(t, r, f"rotate {t.p(q)} {t.p(p)} {60 * _mirrored(t, 'ieq_triangle')}")


@_construction("iso_triangle", 3, 3)
def _iso_triangle(t: _Translator, a: list[str]) -> None:
    p, q, r = a  # |pq| = |pr|
    t.emit(f"points {t.define(p)} {t.define(q)}")
    t.free_on(t.define(r), r, t.circle_locus(t.circle_record(p, {q}), "iso_triangle"))


@_construction("r_triangle", 3, 3)
def _r_triangle(t: _Translator, a: list[str]) -> None:
    p, q, r = a  # the right angle at p
    t.emit(f"points {t.define(p)} {t.define(q)}")
    t.free_on(t.define(r), r, _on_tline(t, [r, p, p, q]))


@_construction("risos", 3, 3)
def _risos(t: _Translator, a: list[str]) -> None:
    p, q, r = a  # the right angle at p, |pq| = |pr|; AG flips the figure at random, so one turn is general
    t.emit(f"points {t.define(p)} {t.define(q)}")
    _rotate(t, r, q, p, _mirrored(t, "risos"))


@_construction("triangle12", 3, 3)
def _triangle12(t: _Translator, a: list[str]) -> None:
    p, q, r = a  # |pr| = 2 |pq|
    t.emit(f"points {t.define(p)} {t.define(q)}")
    far = f"(reflect {t.p(p)} {t.p(q)})"
    t.emit(f"point {t.define(r)} on circle (circle {t.p(p)} {far}) through {far}")


@_construction("trapezoid", 4, 4)
def _trapezoid(t: _Translator, a: list[str]) -> None:
    p, q, r, s = a  # ab ∥ cd
    t.emit(f"points {t.define(p)} {t.define(q)} {t.define(r)}")
    t.free_on(t.define(s), s, _on_pline(t, [s, r, p, q]))


@_construction("r_trapezoid", 4, 4)
def _r_trapezoid(t: _Translator, a: list[str]) -> None:
    p, q, r, s = a  # ab ∥ cd, ab ⟂ ad
    t.emit(f"points {t.define(p)} {t.define(q)}")
    t.free_on(t.define(s), s, _on_tline(t, [s, p, p, q]))
    t.free_on(t.define(r), r, _on_pline(t, [r, s, p, q]))


@_construction("eq_trapezoid", 4, 4)
def _eq_trapezoid(t: _Translator, a: list[str]) -> None:
    p, q, r, s = a  # dc ∥ ab, |da| = |bc|: d is c mirrored in the perpendicular bisector of ab
    t.emit(f"points {t.define(p)} {t.define(q)} {t.define(r)}")
    _point(t, s, f"reflect {t.p(r)} (bisector {t.p(p)} {t.p(q)})")


@_construction("rectangle", 4, 4)
def _rectangle(t: _Translator, a: list[str]) -> None:
    p, q, r, s = a
    t.emit(f"points {t.define(p)} {t.define(q)}")
    t.free_on(t.define(r), r, _on_tline(t, [r, q, q, p]))
    _point(t, s, f"translate {t.p(r)} {t.p(q)} {t.p(p)}")


@_construction("eq_quadrangle", 4, 4)
def _eq_quadrangle(t: _Translator, a: list[str]) -> None:
    p, q, r, s = a  # |da| = |bc|
    t.emit(f"points {t.define(p)} {t.define(q)} {t.define(r)}")
    t.free_on(t.define(s), s, _eqdistance(t, [s, p, q, r]))


@_construction("eqdia_quadrangle", 4, 4)
def _eqdia_quadrangle(t: _Translator, a: list[str]) -> None:
    p, q, r, s = a  # |db| = |ac|
    t.emit(f"points {t.define(p)} {t.define(q)} {t.define(r)}")
    t.free_on(t.define(s), s, _eqdistance(t, [s, q, p, r]))


def _copy(t: _Translator, a: str, b: str, d: str, e: str, f: str) -> str:
    """An auxiliary point X with abX directly similar to def (so ∠(ab, aX) = ∠(de, df)): its pgsym name."""
    _distinct(t, "the angle", d, e)
    _distinct(t, "the angle", d, f)
    x = t.new_aux("sim")
    t.emit(f"point {x} = similar {t.p(a)} {t.p(b)} {t.p(d)} {t.p(e)} {t.p(f)}")
    return x


@_construction("on_aline", 6)
def _on_aline(t: _Translator, a: list[str]) -> _Locus:
    _, p, q, c, d, e = a  # ∠(px, pq) = ∠(dc, de): x on the ray from p towards p + (q − p)(c − d)/(e − d)
    _distinct(t, "on_aline", p, q)
    x = _copy(t, p, q, d, e, c)
    return t.keyed_locus(("aline", p, q, c, d, e), f"join {t.p(p)} {x}", p, "on_aline", head=x,
                         ahead=f"similar {t.p(p)} {t.p(q)} {t.p(d)} {t.p(e)} {t.p(c)}")


def _angle_circle(t: _Translator, p: str, q: str, d: str, e: str, f: str, name: str) -> _Locus:
    """The circle of the points x with ∠(xp, xq) = ∠(de, df): through p, q and the X with Xpq directly similar
    to def (an inscribed angle; the angles are of lines, modulo π, so the whole circle)."""
    _distinct(t, name, p, q)
    _distinct(t, name, d, e, f)
    x = _copy(t, p, q, e, f, d)
    rec = t.circle_record(None, {p, q})
    expr = f"circle {t.p(p)} {t.p(q)} {x}"
    return _Locus("circle", expr, set(rec.points), name, rec.points.add, centre=f"(centre ({expr}))", through=t.p(p))


@_construction("eqangle3", 6)
def _eqangle3(t: _Translator, a: list[str]) -> _Locus:
    _, p, q, d, e, f = a  # ∠(xp, xq) = ∠(de, df)
    return _angle_circle(t, p, q, d, e, f, "eqangle3")


@_construction("on_aline2", 6)
def _on_aline2(t: _Translator, a: list[str]) -> _Locus:
    _, p, q, c, d, e = a  # ∠(xp, xq) = ∠(dc, de)
    return _angle_circle(t, p, q, d, c, e, "on_aline2")


@_construction("eqangle2", 4)
def _eqangle2(t: _Translator, a: list[str]) -> _Locus:
    _, p, q, r = a  # ∠(pq, px) = ∠(rx, rq): the directions of px and rx add up to those of pq and rq, so x runs on
    # a conic through p and r (Steiner: two pencils in projective correspondence). A point of it: px through a
    # point u of the line qr, and rx with the direction (q − r)(q − p)/(u − p) (complex numbers), which is
    # similar r q p u q − r
    _distinct(t, "eqangle2", p, q, r)
    P, Q, R = t.p(p), t.p(q), t.p(r)

    def place(x: str) -> None:
        u = t.new_aux("dir")
        t.emit(f"point {u} on line {Q} {R}")
        t.emit(f"point {x} = meet (join {P} {u}) (join {R} (similar {R} {Q} {P} {u} {Q}))")

    return _Locus("conic", "", {p, q, r}, "eqangle2", lambda x: None, place=place)


@_construction("trisegment", 4, 2)
def _trisegment(t: _Translator, a: list[str]) -> None:
    x, y, p, q = a  # x, y divide pq in three equal parts, x next to p: x = p + (q − p)/3, the foot on pq of the
    # centroid of p, q and q turned by 90° about p (its offset from pq is perpendicular); y = p + q − x
    _distinct(t, "trisegment", p, q)
    P, Q = t.p(p), t.p(q)
    r = t.new_aux("rot")
    t.emit(f"point {r} = rotate {Q} {P} 0 1")
    _point(t, x, f"foot (meet (join {P} (midpoint {Q} {r})) (join {Q} (midpoint {P} {r}))) (join {P} {Q})")
    _point(t, y, f"reflect {t.p(x)} (midpoint {P} {Q})")
    t.add_collinear(x, y, p, q)


@_construction("3peq", 6, 3)
def _3peq(t: _Translator, a: list[str]) -> None:
    x, y, z, p, q, r = a  # z on qr; x on pq and y on pr with z the midpoint of xy: y is x turned about z, so x is
    # on pq and on the line pr turned about z
    _distinct(t, "3peq", p, q, r)
    t.free_on(t.define(z), z, t.join_locus(q, r, "3peq"))
    Z = t.p(z)
    _point(t, x, f"meet (join {t.p(p)} {t.p(q)}) (join (reflect {t.p(p)} {Z}) (reflect {t.p(r)} {Z}))")
    _point(t, y, f"reflect {t.p(x)} {Z}")
    t.add_collinear(x, p, q)
    t.add_collinear(y, p, r)
    t.add_collinear(x, y, z)


@_construction("e5128", 6, 2)
def _e5128(t: _Translator, a: list[str]) -> None:
    x, y, p, q, c, d = a  # |cq| = |cd|, qc ⟂ qp; x on the circle c through q, y on pq, x y d collinear,
    # ∠(pq, pd) = ∠(xp, xy): as pq touches at p the circle through p and d that is tangent to pq, that angle is
    # the one this circle's points x see pd under, so x is its second common point with circle c (besides d)
    _distinct(t, "e5128", p, q, c, d)
    P, Q, C, D = t.p(p), t.p(q), t.p(c), t.p(d)
    v = t.numeric.values
    if not (_close(abs(v[C] - v[Q]), abs(v[C] - v[D])) and _close(_perp_dot((v[C] - v[Q]) * 1j, v[P] - v[Q]), 0.0)):
        raise t.fail(f"e5128 needs |{c}{q}| = |{c}{d}| and {q}{c} ⟂ {q}{p} (its preconditions)", "e5128")
    touching = f"(circle (meet (perpendicular (join {P} {Q}) {P}) (bisector {P} {D})) {P})"
    _point(t, x, f"second (circle {C} {Q}) {touching} {D}")
    _point(t, y, f"meet (join {t.p(x)} {D}) (join {P} {Q})")
    t.circle_record(c, {q, d, x})
    t.add_collinear(x, y, d)
    t.add_collinear(y, p, q)


_UNSUPPORTED: dict[str, str] = {
    "trisect": "the trisectors of an angle need cube roots; pgsym's constructions take square roots only",
    "2l1c": "a circle touching two lines and a circle: its centre needs square roots, and AlphaGeometry picks one "
            "of the circles that touch all three numerically, a choice pgsym cannot name",
    "cc_tangent": "common tangents of two circles: AlphaGeometry takes the two external ones, through the homothety "
                  "centre o + (w − o)·r₁/(r₁ − r₂) with the radii as square roots, a choice among four tangents that "
                  "pgsym cannot name",
    "cc_tangent0": "a common tangent of two circles: AlphaGeometry takes an external one, a choice among four "
                   "tangents that pgsym cannot name",
    "tangent": "needs a branch condition: the two tangent points from a point, told apart by AG numerically",
    "on_opline": "a ray: no construction of pgsym's statement language",
    "acircle": "no construction of pgsym's statement language",
}


# -- a numeric figure: which earlier point an intersection meets, told as AlphaGeometry tells it ----------------
# AlphaGeometry takes, of the two common points of a line and a circle (or two circles), the one that is not
# already in the figure. The incidences tracked above are exact but incomplete; this float figure of the
# statement written so far finds every earlier point that lies on both loci (at a random instance, as
# AlphaGeometry's own figure does).

_NUMERIC_TRIES = 16
_FIGURES = 8  # random figures the goal is evaluated in
_SELECTION_TRIES = 24  # more random figures an order condition that selects a random point must hold in
_TOKENS = re.compile(r"\(|\)|[^\s()]+")


class _NoFigure(Exception):  # a signal to draw another random figure, never shown
    """The random figure is degenerate here (a line and a circle that do not meet)."""


@dataclass(frozen=True)
class _NLine:
    p: complex
    d: complex


@dataclass(frozen=True)
class _NCircle:
    c: complex
    r2: float


class _Numeric:
    def __init__(self, seed: int, bits: tuple[int, ...] = ()) -> None:
        self.rng = random.Random(seed)
        self.bits, self.choices = bits, 0
        self.values: dict[str, Any] = {}

    def random_point(self) -> complex:
        return complex(self.rng.uniform(-1, 1), self.rng.uniform(-1, 1))

    # -- statements --------------------------------------------------------------------------------------
    def run(self, statement: str) -> None:
        try:
            self._run(statement.split("#", 1)[0].strip())
        except (ZeroDivisionError, OverflowError):
            raise _NoFigure from None  # two points fell together in the random figure

    def _run(self, statement: str) -> None:
        words = statement.split()
        if words[0] == "points":
            for w in words[1:]:
                self.values[w] = self.random_point()
            return
        name = words[1]
        if words[2] == "on":  # point x on line …, point x on circle (…) through T
            tokens = _TOKENS.findall(statement.split(" on ", 1)[1].split(" through ")[0])
            what, tokens = tokens[0], tokens[1:]
            if what == "line":
                args = self._args(tokens)
                line = args[0] if len(args) == 1 else self._op("join", args)
                self.values[name] = line.p + self.rng.uniform(-1.5, 1.5) * line.d / max(abs(line.d), 1e-300)
            else:
                circle = self._args(tokens)[0]
                angle = self.rng.uniform(0, 2 * math.pi)
                self.values[name] = circle.c + (circle.r2 ** 0.5) * complex(math.cos(angle), math.sin(angle))
            return
        tokens = _TOKENS.findall(statement.split("=", 1)[1])
        if tokens[0] in ("anglebisector", "exbisector"):
            a, b, c = (self.values[w] for w in tokens[1:4])
            u, v = (a - b) / abs(a - b), (c - b) / abs(c - b)
            self.values[name] = _NLine(b, u + v if tokens[0] == "anglebisector" else u - v)
            return
        if tokens[0] == "intersection":
            one, two = self._args(tokens[1:])
            two_points = _meet(one, two)
            bit = self.bits[self.choices] if self.choices < len(self.bits) else 0
            self.choices += 1
            self.values[name] = two_points[bit]
            return
        if tokens[0] == "rotate" and len(tokens) == 4:  # by degrees
            x, o = self.values[tokens[1]], self.values[tokens[2]]
            angle = int(tokens[3]) * math.pi / 180
            self.values[name] = o + (x - o) * complex(math.cos(angle), math.sin(angle))
            return
        self.values[name] = self._expr(tokens, 0)[0]

    def _args(self, tokens: list[str]) -> list[Any]:
        out, i = [], 0
        while i < len(tokens):
            value, i = self._arg(tokens, i)
            out.append(value)
        return out

    def _arg(self, tokens: list[str], i: int) -> tuple[Any, int]:
        if tokens[i] == "(":
            value, i = self._expr(tokens, i + 1)
            return value, i + 1  # past ")"
        word = tokens[i]
        if re.fullmatch(r"-?[0-9]+", word):
            return float(word), i + 1
        return self.values[word], i + 1

    def _expr(self, tokens: list[str], i: int) -> tuple[Any, int]:
        if tokens[i] not in _NUMERIC_OPS:
            return self._arg(tokens, i)
        op, args, i = tokens[i], [], i + 1
        while i < len(tokens) and tokens[i] != ")":
            value, i = self._arg(tokens, i)
            args.append(value)
        return self._op(op, args), i

    def _op(self, op: str, a: list[Any]) -> Any:
        return _NUMERIC_OPS[op](*a)

    def on_ray(self, name: str, line: str, circle: str, tail: str, head: str) -> bool:
        """The common point of the ray from ``tail`` through ``head`` (on ``line``) and the circle, as AlphaGeometry
        takes it (not the tail itself); True when both common points lie on the ray (then AlphaGeometry takes one
        by the order of its own computation)."""
        one, two = (self._expr(_TOKENS.findall(e), 0)[0] for e in (line, circle))
        t, h = self.values[tail], self._arg(_TOKENS.findall(head), 0)[0]
        scale = 1 + abs(h - t)
        on = [p for p in _meet(one, two) if abs(p - t) > 1e-9 * scale and ((p - t) * (h - t).conjugate()).real > 0]
        if not on:
            raise _NoFigure  # the ray misses the circle: AlphaGeometry draws again
        self.values[name] = on[0]
        return len(on) == 2

    # -- the check ----------------------------------------------------------------------------------------
    def on_circle(self, point: str, circle: str) -> bool:
        """Whether a point (pgsym text) lies on a circle (pgsym text) in the float figure."""
        z, k = (self._expr(_TOKENS.findall(e), 0)[0] for e in (point, circle))
        return _close(abs(z - k.c) ** 2, k.r2)

    def common(self, one: str, two: str, known: list[str], t: _Translator) -> list[str]:
        """The earlier points on both loci: those known by construction, then those the figure shows."""
        first, second = (self._expr(_TOKENS.findall(e), 0)[0] for e in (one, two))
        points = _meet(first, second)
        scale = 1 + max(abs(v) for v in self.values.values() if isinstance(v, complex))
        near = [ag for ag, name in t.defined.items()
                if isinstance(self.values.get(name), complex)
                and min(abs(self.values[name] - p) for p in points) < 1e-7 * scale]
        return [*known, *(ag for ag in near if ag not in known)]


    def rational_common(self, one: str, two: str, t: _Translator) -> str:
        """A common point of the loci that is rational in earlier points, as pgsym text, or "": the fourth vertex
        P + Q − R of a parallelogram (e.g. the point of the parallel to DC through B at distance |CB| from D), else
        P + (Q − R) turned by ±90° (e.g. the point of the perpendicular to BC through A at distance |BC| from A)."""
        first, second = (self._expr(_TOKENS.findall(e), 0)[0] for e in (one, two))
        points = _meet(first, second)
        scale = 1 + max(abs(v) for v in self.values.values() if isinstance(v, complex))
        names = [n for n in t.defined.values() if isinstance(self.values.get(n), complex)]

        def common(x: complex) -> bool:
            return min(abs(x - c) for c in points) < 1e-7 * scale

        for p, q in itertools.combinations(names, 2):
            for r in names:
                if r not in (p, q) and common(self.values[p] + self.values[q] - self.values[r]):
                    return f"translate {p} {r} {q}"
        for p, q, r in itertools.product(names, repeat=3):
            for turn in (1, -1):
                if q != r and common(self.values[p] + turn * 1j * (self.values[q] - self.values[r])):
                    return f"translate (rotate {q} {r} 0 {'-' if turn < 0 else ''}1) {r} {p}"
        return ""


def _foot(p: complex, line: _NLine) -> complex:
    d = line.d
    t = ((p - line.p) * d.conjugate()).real / abs(d) ** 2
    return line.p + t * d


def _line_meet(l: _NLine, m: _NLine) -> complex:
    cross = (l.d.conjugate() * m.d).imag
    if abs(cross) < 1e-12 * abs(l.d) * abs(m.d):
        raise _NoFigure
    t = ((m.p - l.p).conjugate() * m.d).imag / cross
    return l.p + t * l.d


def _meet(one: Any, two: Any) -> list[complex]:
    """The common points of two loci (lines and circles) of the numeric figure."""
    if isinstance(one, _NLine) and isinstance(two, _NLine):
        return [_line_meet(one, two)]
    if isinstance(one, _NCircle) and isinstance(two, _NLine):
        one, two = two, one
    if isinstance(one, _NLine):
        f = _foot(two.c, one)
        h2 = two.r2 - abs(f - two.c) ** 2
        if abs(h2) < 1e-9 * two.r2:  # touching (in every figure when a theorem says so): one double point, which
            return [f, f]  # pgsym's intersection gives too (the discriminant is zero)
        if h2 < 0:
            raise _NoFigure
        step = h2 ** 0.5 * one.d / abs(one.d)
        return [f + step, f - step]
    d = two.c - one.c  # two circles: the radical line, then a line and a circle
    if abs(d) < 1e-12:
        raise _NoFigure
    along = (one.r2 - two.r2 + abs(d) ** 2) / (2 * abs(d))
    return _meet(_NLine(one.c + along * d / abs(d), d * 1j), one)


def _circumcentre(a: complex, b: complex, c: complex) -> complex:
    return _line_meet(_NLine((a + b) / 2, (b - a) * 1j), _NLine((a + c) / 2, (c - a) * 1j))


def _reflect(x: complex, what: Any) -> complex:
    return 2 * (what if isinstance(what, complex) else _foot(x, what)) - x


_NUMERIC_OPS: dict[str, Callable[..., Any]] = {
    "join": lambda p, q: _NLine(p, q - p),
    "meet": _line_meet,
    "perpendicular": lambda line, p: _NLine(p, line.d * 1j),
    "parallel": lambda line, p: _NLine(p, line.d),
    "bisector": lambda a, b: _NLine((a + b) / 2, (b - a) * 1j),
    "foot": _foot,
    "reflect": _reflect,
    "midpoint": lambda a, b: (a + b) / 2,
    "circle": lambda *a: (_NCircle(a[0], abs(a[1] - a[0]) ** 2) if len(a) == 2
                          else _NCircle(_circumcentre(*a), abs(a[0] - _circumcentre(*a)) ** 2)),
    "centre": lambda k: k.c,
    "translate": lambda x, a, b: x + b - a,
    "similar": lambda a, b, d, e, f: a + (b - a) * (f - d) / (e - d),
    "second": lambda k, m, a: _reflect(a, _NLine(k.c, m.c - k.c)),  # two circles through a
    "rotate": lambda x, o, c, s=None: o + (x - o) * (complex(c, s) if s is not None else _degrees(c)),
}


def _degrees(angle: float) -> complex:
    """The turn by a whole number of degrees (rotate X O DEGREES)."""
    return complex(math.cos(math.radians(angle)), math.sin(math.radians(angle)))


def _close(x: float, y: float) -> bool:
    return abs(x - y) < 1e-7 * (1 + abs(x) + abs(y))


def _perp_dot(u: complex, v: complex) -> float:  # of two plane vectors as complex numbers (floats)
    return (u.conjugate() * v).imag


def _line_angle(p: complex, q: complex, r: complex, s: complex) -> float:
    """The angle from line pq to line rs, modulo π."""
    return math.atan2(_perp_dot(q - p, s - r), ((q - p).conjugate() * (s - r)).real) % math.pi


def _same_angle(x: float, y: float) -> bool:
    d = (x - y) % math.pi
    return min(d, math.pi - d) < 1e-7


def _concyclic(v: list[complex]) -> bool:
    o = _circumcentre(v[0], v[1], v[2])
    return all(_close(abs(z - o), abs(v[0] - o)) for z in v[3:])


def _dist(v: list[complex], i: int, j: int) -> float:
    return abs(v[i] - v[j])


_GOALS: dict[str, Callable[[list[complex]], bool]] = {  # AlphaGeometry's goals in the float figure
    "coll": lambda v: all(abs(_perp_dot(v[1] - v[0], z - v[0])) < 1e-9 * (1 + abs(v[1] - v[0]) * abs(z - v[0]))
                          for z in v[2:]),
    "para": lambda v: _same_angle(_line_angle(*v[:4]), 0.0),
    "perp": lambda v: _same_angle(_line_angle(*v[:4]), math.pi / 2),
    "cong": lambda v: _close(_dist(v, 0, 1), _dist(v, 2, 3)),
    "cyclic": _concyclic,
    "eqangle": lambda v: _same_angle(_line_angle(*v[0:4]), _line_angle(*v[4:8])),
    "eqratio": lambda v: _close(_dist(v, 0, 1) * _dist(v, 6, 7), _dist(v, 2, 3) * _dist(v, 4, 5)),
    "midp": lambda v: _close(abs(v[0] - (v[1] + v[2]) / 2), 0.0),
    "simtri": lambda v: (_close(_dist(v, 0, 1) * _dist(v, 4, 5), _dist(v, 1, 2) * _dist(v, 3, 4))
                         and _close(_dist(v, 1, 2) * _dist(v, 5, 3), _dist(v, 2, 0) * _dist(v, 4, 5))),
    "contri": lambda v: all(_close(_dist(v, i, j), _dist(v, i + 3, j + 3)) for i, j in ((0, 1), (1, 2), (2, 0))),
}
_GOALS["simtrir"], _GOALS["contrir"] = _GOALS["simtri"], _GOALS["contri"]
