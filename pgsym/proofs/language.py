"""The statement language: a theorem written as text, one construction a line, read into a :class:`Claim`.

.. code-block:: text

    # Pappus's theorem (Richter-Gebert, Perspectives on Projective Geometry, ch. 1)
    title Pappus's hexagon theorem
    points A B C D          # free points of P² (two parameters each)
    point E on line A B     # a point of the line AB (one parameter)
    point F on line C D
    point X = meet (join A D) (join B C)
    point Y = meet (join A F) (join E C)
    point Z = meet (join E D) (join B F)
    prove collinear X Y Z

The claim it gives is proved by :func:`pgsym.proofs.engine.prove` with the same verdicts and
certificates as one built with the Python API.

Grammar (one statement a line; ``#`` starts a comment; names are letters, digits, ``_`` and ``'``,
starting with a letter; keywords are not names):

.. code-block:: text

    statement  := "title" TEXT | "expect" ("true" | "false")
                | "params" NAME+                                parameters for coordinates
                | PLURAL NAME+                                  free objects
                | KIND NAME "=" expr                            a construction or given coordinates
                | "point" NAME "on" "line" arg [arg]            one parameter: on line l, or on line A B
                | "point3" NAME "on" "line" arg arg
                | "point" NAME "on" "conic" arg ["through" arg] one parameter; through a point of the conic
                | "point" NAME "on" "circle" arg ["through" arg] the same for a circle (its known point by default)
                | "prove" PREDICATE arg+
                | "where" CONDITION arg+                        an order condition (several must all hold)
    PLURAL     := points | lines | points3 | planes | points1 | conics | matrices | matrices4 | matrices2
    KIND       := point | line | point3 | plane | line3 | conic | point1 | ratio | matrix
    expr       := arg | OPERATION arg+
    arg        := NAME | "(" expr ")" | "(" coord ("," coord)+ ")" | ["-"] NUMBER
    coord      := ["-"] (NUMBER | NAME)                         NUMBER: digits ["/" digits]

Operations (chosen by the kinds of their arguments):

=================  =================================================================================
``join``           two points → line; two points of P³ → line3; three points of P³ → plane
``meet``           two lines → point; two planes → line3; line3 and plane → point3; three planes → point3
``plane``          three points of P³ → plane
``conic``          five points → the conic through them; five lines → the conic tangent to them
``tangent``        conic, point on it → the tangent there (``polar``: the polar of any point)
``second``         conic C, point P of C, point Q → the second point of C on the line PQ
``harmonic``       A B C → the harmonic conjugate of C with respect to A, B (collinear points,
                   concurrent lines, or points of P¹)
``crossratio``     A B C D → the ratio (A, B; C, D) (collinear points, concurrent lines, points of P¹)
``midpoint``       two finite points (of P² or P³) → their affine midpoint
``apply``          matrix, object → its image (point, line, plane or conic)
``dual``           conic → its dual conic (the matrix adj C)
=================  =================================================================================

Euclidean operations (relative to the absolute: l∞ and the circular points; every formula is right for
any homogeneous representative; each states its non-degeneracy condition in words):

=================  =================================================================================
``parallel``       line l, point P → the line through P parallel to l
``perpendicular``  line l, point P → the line through P perpendicular to l
``bisector``       A B → the perpendicular bisector of the segment AB (A ≠ B)
``foot``           point P, line l → the foot of the perpendicular from P to l
``reflect``        X P → X reflected in the point P; X l → X reflected in the line l
``rotate``         X O c s → X rotated about O by the angle with cos c, sin s (numbers with
                   c² + s² = 1, checked; or parameter names, then c² + s² = 1 is a hypothesis)
``translate``      X A B → X moved by the vector from A to B
``similar``        A B D E F → the point X with ABX directly similar to DEF (an angle copied:
                   ∠(AB, AX) = ∠(DE, DF); rational)
``circle``         O A → centre O through A; A B C → through three points; O r → centre O, squared
                   radius r (a number or a parameter name)
``centre``         circle (or conic) → its centre, the pole of l∞
``second``         circles K L, common point A → their second common point (on the radical axis)
``invert``         X K → the inverse of X in the circle K
``dist2``          A B → the squared distance (a ratio)
``area``           A B C → the signed area of the triangle (a ratio; positive counter-clockwise)
``segratio``       A B C D → the signed ratio AB / CD of parallel segments (a ratio)
``add sub mul``    two ratios (or a ratio and a number) → their sum, difference, product
=================  =================================================================================

Predicates of ``prove``: ``collinear`` (three points of P² or P³), ``concurrent`` (three lines),
``coplanar`` (four points of P³), ``on`` (point on line, plane, line3 or conic), ``tangent`` (line
touching a conic), ``meet`` (two lines of P³ meet), ``conconic`` (six points on a conic, or six lines
tangent to one), ``equal`` (two objects equal up to scale; two ratios, or a ratio and a number),
``harmonic`` (A B C D: the cross-ratio is −1); Euclidean: ``perpendicular`` and ``parallel`` (two lines),
``equallength`` (A B C D: AB and CD equally long), ``equalangle`` (A B C D E F: the oriented angle ∠ABC, from
line BA to line BC, equals ∠DEF modulo π), ``concyclic`` (four points on one circle, or on one line: the
line with l∞ is the degenerate member of the circles' family), ``equalarea`` (A B C D E F: equal signed
areas). Several ``prove`` lines must all hold. Parts of the Python
API with no statement form: ``formula`` (an arbitrary function), ``combine`` with given coefficients,
equation hypotheses (``assume_zero``), exact (not projective) equality, ranks and degrees of freedom.

Order conditions (``where`` lines; strict inequalities, see :mod:`pgsym.proofs.order`) say which of two
intersection points, which bisector or which part of the figure the theorem is about — as an olympiad
statement does: ``where sameside P Q A B`` (P and Q on the same side of the line AB), ``where oppositeside
P Q A B`` (opposite sides; for P on the circle QAB: P on the arc AB not containing Q), ``where between X A B``
(X strictly between A and B), ``where onray X V P`` (X on the ray from V through P, X ≠ V), ``where inside
X A B C`` (X inside the triangle ABC). The conclusion must then hold on every branch and at every figure the
conditions select, and only there; a figure they exclude never refutes the theorem:

>>> from pgsym.proofs.engine import prove
>>> v = prove(parse_statement('''
... points A B
... point X = intersection (join A B) (circle A B)   # B, or B reflected in A
... where onray X A B
... prove equal X B
... '''))
>>> v.status, v.branches.split(":")[0]
('proved', 'proved on the branch the order conditions select')

Reading is bounded (:mod:`pgsym.limits`): the text, a line, a name, the number of objects and the
nesting of parentheses. Every problem raises a :class:`~pgsym.proofs.errors.StatementError` subclass
naming the line and column.

>>> claim = parse_statement('''
... points A B C D
... point X = meet (join A B) (join C D)
... prove collinear A B X
... ''', name="demo")
>>> [n.name for n in claim.nodes.values() if not n.name.startswith("_")]
['A', 'B', 'C', 'D', 'join A B', 'join C D', 'X']
>>> from pgsym.proofs.engine import prove
>>> prove(claim).status
'proved'
>>> parse_statement("points A\\nprove collinear A A B")
Traceback (most recent call last):
...
pgsym.proofs.errors.StatementNameError: 2:21: B is not defined; define it on an earlier line
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

import sympy

from ..errors import InputLimitError, PgsymError
from ..limits import (
    MAX_DIGITS,
    MAX_NESTING,
    MAX_STATEMENT_BYTES,
    MAX_STATEMENT_LINE_CHARS,
    MAX_STATEMENT_NAME_CHARS,
    MAX_STATEMENT_OBJECTS,
    read_text_file,
)
from .claims import Claim, Node
from .errors import (
    StatementError,
    StatementKindError,
    StatementLimitError,
    StatementNameError,
    StatementSyntaxError,
)
from .order import CONDITIONS

__all__ = ["KEYWORDS", "STATEMENT_SUFFIX", "keywords", "parse_statement", "read_statement"]

STATEMENT_SUFFIX = ".thm"
"""The file suffix of theorems in the statement language."""

_PLURALS = {"points": "point", "lines": "line", "points3": "point3", "planes": "plane", "points1": "point1",
            "conics": "conic", "matrices": "matrix", "matrices4": "matrix4", "matrices2": "matrix2"}
_KINDS = ("point", "line", "point3", "plane", "line3", "conic", "point1", "ratio", "matrix")
_OPERATIONS = ("join", "meet", "plane", "conic", "tangent", "polar", "second", "harmonic", "crossratio",
               "midpoint", "apply", "dual")
_PREDICATES = ("collinear", "concurrent", "coplanar", "on", "tangent", "meet", "conconic", "equal", "harmonic")
# Euclidean constructions and predicates (relative to the absolute)
_OPERATIONS += ("parallel", "perpendicular", "bisector", "foot", "reflect", "rotate", "translate", "similar",
                "circle", "centre", "invert", "dist2", "area", "segratio", "add", "sub", "mul")
_PREDICATES += ("perpendicular", "parallel", "equallength", "equalangle", "concyclic", "equalarea")
KEYWORDS = frozenset({"title", "expect", "params", "prove", "on", "through", *_PLURALS, *_KINDS, *_OPERATIONS,
                      *_PREDICATES, "where", *CONDITIONS})

_TOKEN = re.compile(r"\s*(?:(?P<name>[A-Za-z][A-Za-z0-9_']*)|(?P<number>[0-9]+(?:/[0-9]+)?)|(?P<punct>[()=,-]))")


@dataclass(frozen=True)
class _Token:
    kind: str  # "name", "number", "punct", "end"
    text: str
    line: int
    col: int


@dataclass
class _Call:
    """A parsed expression: the keyword of an operation of the language and its arguments (names, tuples or
    calls)."""

    word: str
    args: list[Any]
    tok: _Token


@dataclass
class _Tuple:
    coords: list[tuple[int, _Token]]  # (sign, number-or-name token)
    tok: _Token


def _tokens(text: str, lineno: int) -> list[_Token]:
    out: list[_Token] = []
    pos = 0
    code = text.split("#", 1)[0]
    while True:
        while pos < len(code) and code[pos] in " \t\r":
            pos += 1
        if pos >= len(code):
            out.append(_Token("end", "", lineno, len(code) + 1))
            return out
        m = _TOKEN.match(code, pos)
        if m is None or m.end() == pos:
            ch = code[pos]
            raise StatementSyntaxError(f"unexpected character {ch!r}; names are letters, digits, _ and ', "
                                       "numbers are integers or fractions p/q", lineno, pos + 1)
        kind = m.lastgroup or "punct"
        start = m.start(kind)
        word = m.group(kind)
        if kind == "name" and len(word) > MAX_STATEMENT_NAME_CHARS:
            raise StatementLimitError(f"a name of {len(word)} characters; names have at most "
                                      f"{MAX_STATEMENT_NAME_CHARS}", lineno, start + 1)
        if kind == "number" and any(len(part) > MAX_DIGITS for part in word.split("/")):
            raise StatementLimitError(f"a number with more than {MAX_DIGITS} digits", lineno, start + 1)
        out.append(_Token(kind, word, lineno, start + 1))
        pos = m.end()


class _Line:
    """A cursor over the tokens of one line."""

    def __init__(self, tokens: list[_Token]) -> None:
        self.toks, self.i = tokens, 0

    def peek(self) -> _Token:
        return self.toks[self.i]

    def next(self) -> _Token:
        tok = self.toks[self.i]
        if tok.kind != "end":
            self.i += 1
        return tok

    def expect(self, text: str) -> _Token:
        tok = self.next()
        if tok.text != text:
            raise StatementSyntaxError(f"expected {text!r}, found {_show(tok)}", tok.line, tok.col)
        return tok

    def name(self, what: str = "a name") -> _Token:
        tok = self.next()
        if tok.kind != "name":
            raise StatementSyntaxError(f"expected {what}, found {_show(tok)}", tok.line, tok.col)
        return tok

    def end(self) -> None:
        tok = self.peek()
        if tok.kind != "end":
            raise StatementSyntaxError(f"unexpected {_show(tok)} after the end of the statement", tok.line, tok.col)


def _show(tok: _Token) -> str:
    return "the end of the line" if tok.kind == "end" else repr(tok.text)


def _parse_arg(cur: _Line, depth: int) -> Any:
    tok = cur.next()
    if tok.kind == "number" or (tok.text == "-" and cur.peek().kind == "number"):
        # a number argument (a cosine, a squared radius, a term of ratio arithmetic), kept as one token
        if tok.text == "-":
            num = cur.next()
            return _Token("number", "-" + num.text, tok.line, tok.col)
        return tok
    if tok.kind == "name":
        if tok.text in _OPERATIONS:
            raise StatementSyntaxError(f"the operation {tok.text!r} inside an argument needs parentheses: "
                                       f"({tok.text} …)", tok.line, tok.col)
        _not_inline(tok)
        return tok
    if tok.text != "(":
        raise StatementSyntaxError(f"expected a name or '(', found {_show(tok)}", tok.line, tok.col)
    if depth >= MAX_NESTING:
        raise StatementLimitError(f"parentheses nested more than {MAX_NESTING} deep", tok.line, tok.col)
    first = cur.peek()
    if first.text == "(":
        inner = _parse_arg(cur, depth + 1)
        cur.expect(")")
        return inner
    if first.kind == "name" and first.text in _OPERATIONS:
        call = _parse_expr(cur, depth + 1)
        cur.expect(")")
        return call
    _not_inline(first)
    if first.kind == "name" and cur.toks[cur.i + 1].text == ")":
        cur.next()
        cur.next()
        return first
    coords = []
    while True:
        sign = 1
        if cur.peek().text == "-":
            cur.next()
            sign = -1
        c = cur.next()
        if c.kind not in ("number", "name"):
            raise StatementSyntaxError(f"expected a number or a parameter in coordinates, found {_show(c)}",
                                       c.line, c.col)
        coords.append((sign, c))
        sep = cur.next()
        if sep.text == ")":
            break
        if sep.text != ",":
            raise StatementSyntaxError(f"expected ',' or ')' in coordinates, found {_show(sep)}", sep.line, sep.col)
    return _Tuple(coords, tok)


def _not_inline(tok: _Token) -> None:
    """A construction with square roots (``anglebisector``, ``intersection`` …) has a line of its own: named
    there, it names its branch in the verdict; inside another expression it would have no name."""
    if tok.kind == "name" and tok.text in _ALGEBRAIC_FORMS:
        kind, count = _ALGEBRAIC_FORMS[tok.text]
        names = "NAME" if count == 1 else "NAME1 NAME2"
        raise StatementSyntaxError(f"{tok.text!r} is a construction with square roots and cannot be an argument: "
                                   f"define it on a line of its own ({kind}{'s' if count > 1 else ''} {names} = "
                                   f"{tok.text} …) and use the name here", tok.line, tok.col)


def _parse_expr(cur: _Line, depth: int = 0) -> Any:
    tok = cur.peek()
    if tok.kind == "name" and tok.text in _OPERATIONS:
        cur.next()
        args = []
        while cur.peek().kind != "end" and cur.peek().text != ")":
            args.append(_parse_arg(cur, depth))
        if not args:
            raise StatementSyntaxError(f"{tok.text} needs arguments", tok.line, tok.col)
        return _Call(tok.text, args, tok)
    return _parse_arg(cur, depth)


def _canonical(e: Any) -> str:
    if isinstance(e, _Token):
        return e.text
    if isinstance(e, _Tuple):
        return "(" + ", ".join(("-" if s < 0 else "") + t.text for s, t in e.coords) + ")"
    return e.word + " " + " ".join(_canonical(a) if not isinstance(a, _Call) else f"({_canonical(a)})" for a in e.args)


# -- building the claim ---------------------------------------------------------------------------------------

_Builder = Callable[[Claim, str, list[Node]], Node]


def _kind_of(a: Any) -> str:
    """The kind of an argument: a node's kind, ``number`` for a number, ``param`` for a parameter name."""
    if isinstance(a, Node):
        return a.kind
    return "number" if isinstance(a, sympy.Rational) else "param"


def _by_kind(table: dict[tuple[str, ...], _Builder]) -> Callable[[Claim, str, list[Node], _Token], Node]:
    def build(claim: Claim, name: str, args: list[Node], tok: _Token) -> Node:
        kinds = tuple(_kind_of(a) for a in args)
        builder = table.get(kinds)
        if builder is None:
            accepted = "; ".join(" ".join(k) for k in table)
            got = " ".join(f"{_kind_of(a)} {getattr(a, 'name', a)}" for a in args) or "nothing"
            raise StatementKindError(f"{tok.text} takes ({accepted}), got {got}", tok.line, tok.col)
        return builder(claim, name, args)
    return build


_P, _L, _P3, _E, _L3, _C, _P1 = "point", "line", "point3", "plane", "line3", "conic", "point1"

_BUILD: dict[str, Callable[[Claim, str, list[Node], _Token], Node]] = {
    "join": _by_kind({(_P, _P): lambda c, n, a: c.join(n, *a), (_P3, _P3): lambda c, n, a: c.line3(n, *a),
                      (_P3, _P3, _P3): lambda c, n, a: c.plane_through(n, *a)}),
    "meet": _by_kind({(_L, _L): lambda c, n, a: c.meet(n, *a), (_E, _E): lambda c, n, a: c.line_of_planes(n, *a),
                      (_L3, _E): lambda c, n, a: c.line_meets_plane(n, *a),
                      (_E, _L3): lambda c, n, a: c.line_meets_plane(n, a[1], a[0]),
                      (_E, _E, _E): lambda c, n, a: c.point_on_planes(n, *a)}),
    "plane": _by_kind({(_P3, _P3, _P3): lambda c, n, a: c.plane_through(n, *a)}),
    "conic": _by_kind({(_P,) * 5: lambda c, n, a: c.conic_through(n, *a),
                       (_L,) * 5: lambda c, n, a: c.conic_tangent_to(n, *a)}),
    "tangent": _by_kind({(_C, _P): lambda c, n, a: c.tangent(n, *a)}),
    "polar": _by_kind({(_C, _P): lambda c, n, a: c.polar(n, *a)}),
    "second": _by_kind({(_C, _P, _P): lambda c, n, a: c.second_intersection(n, *a)}),
    "harmonic": _by_kind({(_P,) * 3: lambda c, n, a: c.harmonic_conjugate_collinear(n, *a),
                          (_L,) * 3: lambda c, n, a: c.harmonic_conjugate_collinear(n, *a),
                          (_P1,) * 3: lambda c, n, a: c.harmonic_conjugate(n, *a)}),
    "crossratio": _by_kind({(_P,) * 4: lambda c, n, a: c.cross_ratio_collinear(n, *a),
                            (_L,) * 4: lambda c, n, a: c.cross_ratio_collinear(n, *a),
                            (_P1,) * 4: lambda c, n, a: c.cross_ratio(n, *a)}),
    "midpoint": _by_kind({(_P, _P): lambda c, n, a: c.midpoint(n, *a), (_P3, _P3): lambda c, n, a: c.midpoint(n, *a)}),
    "apply": _by_kind({**{("matrix", k): (lambda c, n, a: c.apply(n, *a)) for k in (_P, _P3, _P1)},
                       **{("matrix", k): (lambda c, n, a: c.apply_line(n, *a)) for k in (_L, _E)},
                       ("matrix", _C): lambda c, n, a: c.apply_conic(n, *a)}),
    "dual": _by_kind({(_C,): lambda c, n, a: c.dual_conic(n, *a)}),
}

# Euclidean constructions (numbers and parameter names allowed where a cosine, sine or squared radius goes)
_N, _R = ("number", "param"), "ratio"
_BUILD.update({
    "parallel": _by_kind({(_L, _P): lambda c, n, a: c.parallel(n, *a)}),
    "perpendicular": _by_kind({(_L, _P): lambda c, n, a: c.perpendicular(n, *a)}),
    "bisector": _by_kind({(_P, _P): lambda c, n, a: c.bisector(n, *a)}),
    "foot": _by_kind({(_P, _L): lambda c, n, a: c.foot(n, *a)}),
    "reflect": _by_kind({(_P, _P): lambda c, n, a: c.reflect_point(n, *a),
                         (_P, _L): lambda c, n, a: c.reflect_line(n, *a)}),
    "rotate": _by_kind({(_P, _P, x, y): (lambda c, n, a: c.rotate(n, *a)) for x in _N for y in _N}),
    "translate": _by_kind({(_P, _P, _P): lambda c, n, a: c.translate(n, *a)}),
    "similar": _by_kind({(_P,) * 5: lambda c, n, a: c.similar(n, *a)}),
    "circle": _by_kind({(_P, _P): lambda c, n, a: c.circle(n, *a), (_P, _P, _P): lambda c, n, a: c.circle3(n, *a),
                        **{(_P, x): (lambda c, n, a: c.circle_radius(n, *a)) for x in _N}}),
    "centre": _by_kind({(_C,): lambda c, n, a: c.centre(n, *a)}),
    "invert": _by_kind({(_P, _C): lambda c, n, a: c.invert(n, *a)}),
    "dist2": _by_kind({(_P, _P): lambda c, n, a: c.dist2(n, *a)}),
    "area": _by_kind({(_P, _P, _P): lambda c, n, a: c.area(n, *a)}),
    "segratio": _by_kind({(_P,) * 4: lambda c, n, a: c.segratio(n, *a)}),
    **{op: _by_kind({(x, y): (lambda c, n, a, op=op: getattr(c, op)(n, *a))
                     for x in (_R, "number") for y in (_R, "number") if (x, y) != ("number", "number")})
       for op in ("add", "sub", "mul")},
})
_BUILD["second"] = _by_kind({(_C, _P, _P): lambda c, n, a: c.second_intersection(n, *a),
                             (_C, _C, _P): lambda c, n, a: c.circles_second(n, *a)})

_Conclude = Callable[[Claim, list[Any]], None]


_PROVE: dict[str, dict[tuple[str, ...], _Conclude]] = {
    "collinear": {(_P,) * 3: lambda c, a: c.conclude_collinear(*a), (_P3,) * 3: lambda c, a: c.conclude_collinear3(*a)},
    "concurrent": {(_L,) * 3: lambda c, a: c.conclude_concurrent(*a)},
    "coplanar": {(_P3,) * 4: lambda c, a: c.conclude_coplanar(*a)},
    "on": {(_P, _L): lambda c, a: c.conclude_incident(*a), (_P3, _E): lambda c, a: c.conclude_incident(*a),
           (_P3, _L3): lambda c, a: c.conclude_on_line3(*a), (_P, _C): lambda c, a: c.conclude_on_conic(*a)},
    "tangent": {(_L, _C): lambda c, a: c.conclude_tangent(*a)},
    "meet": {(_L3, _L3): lambda c, a: c.conclude_lines_meet(*a)},
    "conconic": {(_P,) * 6: lambda c, a: c.conclude_conconic(*a), (_L,) * 6: lambda c, a: c.conclude_six_tangent(*a)},
    "equal": {**{(k, k): (lambda c, a: c.conclude_proportional(*a)) for k in (_P, _L, _P3, _E, _L3, _C, _P1)},
              ("ratio", "ratio"): lambda c, a: c.conclude_equal_ratio(*a),
              ("ratio", "number"): lambda c, a: c.conclude_equal_ratio(*a)},
}
# Euclidean predicates
_PROVE.update({
    "perpendicular": {(_L, _L): lambda c, a: c.conclude_perpendicular(*a)},
    "parallel": {(_L, _L): lambda c, a: c.conclude_parallel(*a)},
    "equallength": {(_P,) * 4: lambda c, a: c.conclude_equal_length(*a)},
    "equalangle": {(_P,) * 6: lambda c, a: c.conclude_equal_angle(*a)},
    "concyclic": {(_P,) * 4: lambda c, a: c.conclude_concyclic(*a)},
    "equalarea": {(_P,) * 6: lambda c, a: c.conclude_equal_area(*a)},
})
_PROVE["equal"][("ratio", "param")] = lambda c, a: c.conclude_equal_ratio(*a)

# the points of each order condition, as the error messages name them
_WHERE_ARGS = {"sameside": "P Q A B", "oppositeside": "P Q A B", "between": "X A B", "onray": "X V P",
               "inside": "X A B C"}


class _Reader:
    def __init__(self, name: str, source: str) -> None:
        self.claim = Claim(name, name)
        self.source = source
        self.first_point: dict[str, Node] = {}  # conic name -> the first point it was built through
        self.title_set = False
        self.count = 0

    # -- objects ------------------------------------------------------------------------------------
    def _new_name(self, tok: _Token) -> str:
        if tok.text in KEYWORDS:
            raise StatementNameError(f"{tok.text!r} is a keyword of the statement language, not a name",
                                     tok.line, tok.col)
        if tok.text in self.claim.nodes or any(str(p) == tok.text for p in self.claim.parameters):
            raise StatementNameError(f"{tok.text} is already defined; every name is defined once", tok.line, tok.col)
        self.count += 1
        if self.count > MAX_STATEMENT_OBJECTS:
            raise StatementLimitError(f"more than {MAX_STATEMENT_OBJECTS} objects in one theorem", tok.line, tok.col)
        return tok.text

    def _lookup(self, tok: _Token) -> Node:
        node = self.claim.nodes.get(tok.text)
        if node is None:
            raise StatementNameError(f"{tok.text} is not defined; define it on an earlier line", tok.line, tok.col)
        return node

    def _value(self, e: Any, name: str | None = None, kind: str | None = None) -> Node:
        """The node of an expression; named when ``name`` is given, else named by its text (and shared)."""
        if isinstance(e, _Token) and name is None and e.kind == "number":
            return sympy.Rational(Fraction(e.text))  # type: ignore[return-value]
        if isinstance(e, _Token) and name is None and e.text not in self.claim.nodes:
            param = next((p for p in self.claim.parameters if str(p) == e.text), None)
            if param is not None:
                return param  # type: ignore[return-value]
        if isinstance(e, _Token):
            node = self._lookup(e)
            if name is None:
                return node
            raise StatementSyntaxError(f"{name} = {e.text} only renames an object; use {e.text} itself",
                                       e.line, e.col)
        if isinstance(e, _Tuple):
            if name is None or kind is None:
                raise StatementSyntaxError("coordinates name an object only in a definition such as "
                                           "'point P = (1, 2, 1)'", e.tok.line, e.tok.col)
            return self._coordinates(name, kind, e)
        key = name or _canonical(e)
        if name is None and key in self.claim.nodes:
            return self.claim.nodes[key]
        args = [self._value(a) for a in e.args]
        if name is None:
            self.count += 1
            if self.count > MAX_STATEMENT_OBJECTS:
                raise StatementLimitError(f"more than {MAX_STATEMENT_OBJECTS} objects in one theorem",
                                          e.tok.line, e.tok.col)
        node = _BUILD[e.word](self.claim, key, args, e.tok)
        if e.word == "conic" and args and args[0].kind == _P:
            self.first_point[key] = args[0]
        if e.word == "circle" and node.operation.through:  # a known point: A of circle O A, circle A B C
            self.first_point[key] = args[node.operation.through[0]]
        return node

    def _coordinates(self, name: str, kind: str, e: _Tuple) -> Node:
        params = {str(p): p for p in self.claim.parameters}
        values = []
        for sign, t in e.coords:
            if t.kind == "number":
                values.append(sign * sympy.Rational(Fraction(t.text)))
            elif t.text in params:
                values.append(sign * params[t.text])
            else:
                raise StatementNameError(f"{t.text} is not a parameter; declare it with 'params {t.text}'",
                                         t.line, t.col)
        method = {"point": self.claim.point, "line": self.claim.line, "point3": self.claim.point3,
                  "plane": self.claim.plane, "point1": self.claim.point1}.get(kind)
        if method is None:
            raise StatementKindError(f"a {kind} cannot be given by coordinates (only points, lines, planes)",
                                     e.tok.line, e.tok.col)
        try:
            return method(name, *values)
        except PgsymError as err:
            raise StatementKindError(str(err), e.tok.line, e.tok.col) from None

    # -- statements ---------------------------------------------------------------------------------
    def statement(self, cur: _Line) -> None:
        head = cur.next()
        if head.kind == "end":
            return
        if head.kind != "name":
            raise StatementSyntaxError(f"a statement starts with a keyword, found {_show(head)}", head.line, head.col)
        word = head.text
        if word in ("title", "expect"):
            raise StatementSyntaxError(f"{word} must be the first word of its line", head.line, head.col)
        if word == "params":
            self._names(cur, lambda n: self.claim.params(n))
        elif word in _PLURALS and _algebraic_line(cur):
            _algebraic_definition(self, word, cur)
        elif word in _PLURALS:
            self._names(cur, lambda n: self._free(_PLURALS[word], n))
        elif word in _KINDS:
            self._definition(word, cur)
        elif word == "prove":
            self._prove(cur)
        elif word == "where":
            self._where(cur, head)
        else:
            raise StatementSyntaxError(
                f"unknown statement {word!r}; a line starts with one of: title, expect, params, "
                f"{', '.join(_PLURALS)}, {', '.join(_KINDS)}, prove, where", head.line, head.col)
        cur.end()

    def _names(self, cur: _Line, make: Callable[[str], Any]) -> None:
        if cur.peek().kind == "end":
            tok = cur.peek()
            raise StatementSyntaxError("expected at least one name", tok.line, tok.col)
        while cur.peek().kind != "end":
            make(self._new_name(cur.name()))

    def _free(self, kind: str, name: str) -> Node:
        c = self.claim
        if kind == "point":
            return c.free_point(name)
        if kind == "line":
            return c.free_line(name)
        if kind == "point3":
            return c.free_point3(name)
        if kind == "plane":
            return c.free_plane(name)
        if kind == "point1":
            return c.free_point1(name)
        if kind.startswith("matrix"):
            return c.free_matrix(name, {"matrix": 3, "matrix4": 4, "matrix2": 2}[kind])
        # a free conic: a symmetric matrix of six parameters
        a, b, cc, d, e, f = c.params(" ".join(f"{name}_{k}" for k in ("a", "b", "c", "d", "e", "f")))
        return c.conic(name, [[a, b, d], [b, cc, e], [d, e, f]])

    def _definition(self, kind: str, cur: _Line) -> None:
        tok = cur.name("the name of the new object")
        name = self._new_name(tok)
        nxt = cur.next()
        if nxt.text == "on" and kind in ("point", "point3"):
            self._on(kind, name, cur, nxt)
            return
        if nxt.text != "=":
            raise StatementSyntaxError(f"expected '=' after {name}, found {_show(nxt)}", nxt.line, nxt.col)
        if _algebraic_line(cur):
            _algebraic_definition(self, kind, cur, [name])
            return
        expr = _parse_expr(cur)
        node = self._value(expr, name, kind)
        if node.kind != kind:
            where = expr.tok if not isinstance(expr, _Token) else expr
            raise StatementKindError(f"{name} is declared a {kind} but its construction gives a {node.kind}",
                                     where.line, where.col)

    def _on(self, kind: str, name: str, cur: _Line, on: _Token) -> None:
        what = cur.name("'line' or 'conic'")
        if what.text == "line":
            first = self._value(_parse_arg(cur, 0))
            if cur.peek().kind == "end":
                if kind != "point" or first.kind != _L:
                    raise StatementKindError(f"'{kind} {name} on line' takes a line of P² or two {kind}s",
                                             what.line, what.col)
                self.claim.point_on_line(name, first)
                return
            second = self._value(_parse_arg(cur, 0))
            if first.kind != kind or second.kind != kind:
                raise StatementKindError(f"'{kind} {name} on line' takes two {kind}s, got the {first.kind} "
                                         f"{first.name} and the {second.kind} {second.name}", what.line, what.col)
            self.claim.point_on_line(name, first, second)
            return
        if what.text in ("conic", "circle") and kind == "point":
            conic = self._value(_parse_arg(cur, 0))
            if conic.kind != _C:
                raise StatementKindError(f"'on conic' takes a conic, got the {conic.kind} {conic.name}",
                                         what.line, what.col)
            if cur.peek().text == "through":
                cur.next()
                through = self._value(_parse_arg(cur, 0))
            elif conic.name in self.first_point:
                through = self.first_point[conic.name]
            else:
                raise StatementSyntaxError(f"say through which point of {conic.name} the parameter runs: "
                                           f"'point {name} on conic {conic.name} through P'", what.line, what.col)
            if through.kind != _P:
                raise StatementKindError(f"'through' takes a point, got the {through.kind} {through.name}",
                                         what.line, what.col)
            self.claim.point_on_conic(name, conic, through)
            return
        raise StatementSyntaxError(f"expected 'line' or 'conic' after 'on', found {_show(what)}", what.line, what.col)

    def _prove(self, cur: _Line) -> None:
        pred = cur.name("a predicate")
        if pred.text not in _PREDICATES:
            raise StatementSyntaxError(f"unknown predicate {pred.text!r}; prove one of: {', '.join(_PREDICATES)}",
                                       pred.line, pred.col)
        args: list[Any] = []
        while cur.peek().kind != "end":
            tok = cur.peek()
            if pred.text == "equal" and (tok.kind == "number" or tok.text == "-"):
                args.append(self._number(cur))
            else:
                args.append(self._value(_parse_arg(cur, 0)))
        if pred.text == "harmonic":
            if len(args) != 4 or len({a.kind for a in args}) != 1 or args[0].kind not in (_P, _L, _P1):
                raise StatementKindError("harmonic takes four collinear points, four concurrent lines or four "
                                         "points of P¹", pred.line, pred.col)
            ratio = self._value(_Call("crossratio", [_Token("name", a.name, 0, 0) for a in args], pred))
            self.claim.conclude_equal_ratio(ratio, -1)
            return
        kinds = tuple(_kind_of(a) for a in args)
        table = _PROVE[pred.text]
        conclude = table.get(kinds)
        if conclude is None:
            accepted = "; ".join(" ".join(k) for k in table)
            got = " ".join(k for k in kinds) or "nothing"
            raise StatementKindError(f"prove {pred.text} takes ({accepted}), got {got}", pred.line, pred.col)
        conclude(self.claim, args)

    def _where(self, cur: _Line, head: _Token) -> None:
        """``where CONDITION POINTS``: an order condition of :mod:`pgsym.proofs.order`."""
        usage = "; ".join(f"where {w} {_WHERE_ARGS[w]}" for w in CONDITIONS)
        cond = cur.next()
        if cond.kind == "end":
            raise StatementSyntaxError(f"where needs an order condition: {usage}", cond.line, cond.col)
        if cond.text not in CONDITIONS:
            raise StatementSyntaxError(f"unknown order condition {_show(cond)}; write one of: {usage}",
                                       cond.line, cond.col)
        args = []
        while cur.peek().kind != "end":
            args.append(self._value(_parse_arg(cur, 0)))
        want = CONDITIONS[cond.text]
        if len(args) != want:
            raise StatementKindError(f"where {cond.text} takes {want} points ({_WHERE_ARGS[cond.text]}), got "
                                     f"{len(args)}", cond.line, cond.col)
        bad = next((a for a in args if _kind_of(a) != _P), None)
        if bad is not None:
            raise StatementKindError(f"where {cond.text} takes points of the plane, got the {_kind_of(bad)} "
                                     f"{getattr(bad, 'name', bad)}", cond.line, cond.col)
        method = {"sameside": self.claim.where_same_side, "oppositeside": self.claim.where_opposite_sides,
                  "between": self.claim.where_between, "onray": self.claim.where_on_ray,
                  "inside": self.claim.where_inside}[cond.text]
        try:
            method(*args)
        except PgsymError as err:  # a point given twice, too many conditions
            raise StatementKindError(f"where {err}", cond.line, cond.col) from None

    def _number(self, cur: _Line) -> sympy.Rational:
        sign = -1 if cur.peek().text == "-" and cur.next() else 1
        tok = cur.next()
        if tok.kind != "number":
            raise StatementSyntaxError(f"expected a number, found {_show(tok)}", tok.line, tok.col)
        return sign * sympy.Rational(Fraction(tok.text))


def parse_statement(text: str, name: str = "statement", source: str = "") -> Claim:
    """Read a theorem of the statement language into a :class:`Claim` (``source`` names it in errors).

    >>> c = parse_statement("title A demo\\nexpect false\\npoints A B C\\nprove collinear A B C")
    >>> c.title, c.expected, c.conclusions[0].text
    ('A demo', False, 'A, B, C are collinear')
    """
    try:
        return _parse(text, name, source)
    except StatementError as err:
        err.source = source
        raise


def _parse(text: str, name: str, source: str) -> Claim:
    if len(text) > MAX_STATEMENT_BYTES:
        raise StatementLimitError(f"the theorem has {len(text)} characters; at most {MAX_STATEMENT_BYTES} are read")
    reader = _Reader(name, source)
    lines = text.splitlines()
    for lineno, raw in enumerate(lines, start=1):
        if len(raw) > MAX_STATEMENT_LINE_CHARS:
            raise StatementLimitError(f"a line of {len(raw)} characters; lines have at most "
                                      f"{MAX_STATEMENT_LINE_CHARS}", lineno, MAX_STATEMENT_LINE_CHARS + 1)
        bad = next((i for i, ch in enumerate(raw) if (ord(ch) < 32 and ch not in "\t\r") or ch == "\x7f"), None)
        if bad is not None:
            raise StatementSyntaxError(f"a control character {raw[bad]!r}; the theorem must be plain text",
                                       lineno, bad + 1)
        stripped = raw.strip()
        for word in ("title", "expect"):
            if stripped.startswith(word + " ") or stripped == word:
                rest = stripped[len(word):].strip()
                if word == "title":
                    if not rest:
                        raise StatementSyntaxError("title needs a text", lineno, 1)
                    reader.claim.title = reader.claim.statement = rest
                else:
                    value = rest.split("#", 1)[0].strip()
                    if value not in ("true", "false"):
                        raise StatementSyntaxError(f"expect takes true or false, found {value!r}", lineno,
                                                   raw.index(word) + len(word) + 2)
                    reader.claim.expected = value == "true"
                break
        else:
            try:
                reader.statement(_Line(_tokens(raw, lineno)))
            except StatementError:
                raise
            except PgsymError as err:  # a claim method refused (e.g. a degenerate coordinate tuple)
                raise StatementKindError(str(err), lineno, 1) from None
    if not reader.claim.conclusions:
        raise StatementSyntaxError("the theorem has no 'prove' line", len(lines) or 1, 1)
    return reader.claim


def read_statement_text(path: str | os.PathLike[str], what: str = "theorem file", limit: int = MAX_STATEMENT_BYTES,
                        error: type[StatementError] | None = None) -> str:
    """The text of a statement file (UTF-8, at most ``limit`` bytes read), or a statement error naming the file,
    line and column: of class ``error`` when given (a reader of another format), else the language's own.
    """
    p, source = Path(path), str(path)
    try:
        text = read_text_file(p, what, limit)
    except InputLimitError as err:
        raise (error or StatementLimitError)(str(err), source=source) from None
    except UnicodeDecodeError as err:
        line = err.object[: err.start].count(b"\n") + 1
        col = err.start - (err.object.rfind(b"\n", 0, err.start) + 1) + 1
        raise (error or StatementSyntaxError)("the file is not UTF-8 text", line, col, source) from None
    except OSError as err:
        raise (error or StatementError)(f"cannot read the {what}: {err.strerror or err}", source=source) from None
    if "\x00" in text:
        line = text[: text.index("\x00")].count("\n") + 1
        raise (error or StatementSyntaxError)(f"the file holds binary data (a NUL byte); a {what} is plain text",
                                              line, 1, source)
    return text


def read_statement(path: str | os.PathLike[str]) -> Claim:
    """Read a theorem file (UTF-8, at most :data:`~pgsym.limits.MAX_STATEMENT_BYTES` bytes) into a claim.

    The claim is named after the file (without its suffix). Errors name the file, line and column.
    """
    p = Path(path)
    text = read_statement_text(p)
    return parse_statement(text, name=p.stem if p.suffix == STATEMENT_SUFFIX else p.name, source=str(p))


# -- constructions with square roots (pgsym.proofs.algebraic): section B of the Euclidean syntax ------------------
#   line b = anglebisector A B C          line b = exbisector A B C
#   point X = intersection l K            points X Y = intersections l K     (l a line or a circle, K a circle)
#   line t = tangentfrom P K              lines s t = tangentsfrom P K
#   point X = polygon A B n k             point Y = rotate X O DEGREES       (integers; DEGREES may be negative)

_ALGEBRAIC_FORMS: dict[str, tuple[str, int]] = {  # keyword -> (kind of each result, number of results)
    "anglebisector": ("line", 1), "exbisector": ("line", 1), "intersection": ("point", 1),
    "intersections": ("point", 2), "tangentfrom": ("line", 1), "tangentsfrom": ("line", 2),
    "polygon": ("point", 1), "rotate": ("point", 1),
}
KEYWORDS = KEYWORDS | frozenset(_ALGEBRAIC_FORMS)


def _algebraic_line(cur: _Line) -> bool:
    """The rest of the line (after ``=``, or after a plural keyword) is a construction with square roots:
    one of the keywords above; ``rotate`` only with an angle in degrees (three arguments, the last a number)."""
    toks = cur.toks[cur.i:]
    if toks and toks[0].kind == "name" and any(t.text == "=" for t in toks):  # plural: skip the names
        toks = toks[next(i for i, t in enumerate(toks) if t.text == "=") + 1:]
    if not toks or toks[0].text not in _ALGEBRAIC_FORMS:
        return False
    if toks[0].text != "rotate":
        return True
    # the arguments as the parser reads them (an inline object such as (midpoint A B) is one argument): the
    # degree form has three, the last a number
    args, rest = [], _Line(toks[1:])
    try:
        while rest.peek().kind != "end":
            args.append(_parse_arg(rest, 0))
    except StatementError:
        return False  # not the degree form; the cosine-sine form reports the error
    return len(args) == 3 and isinstance(args[2], _Token) and args[2].kind == "number"


def _integer(cur: _Line, what: str) -> int:
    sign = -1 if cur.peek().text == "-" and cur.next() else 1
    tok = cur.next()
    if tok.kind != "number" or "/" in tok.text:
        raise StatementSyntaxError(f"{what} is an integer, found {_show(tok)}", tok.line, tok.col)
    return sign * int(tok.text)


def _algebraic_definition(reader: _Reader, word: str, cur: _Line, names: list[str] | None = None) -> None:
    """Read ``KIND NAME = FORM args`` or ``PLURAL NAME NAME = FORM args`` (the forms of _ALGEBRAIC_FORMS)."""
    if names is None:
        names = []
        while cur.peek().text != "=":
            names.append(reader._new_name(cur.name("a name")))
        cur.expect("=")
    kind = _PLURALS.get(word, word)
    form = cur.next()
    result, count = _ALGEBRAIC_FORMS[form.text]
    if kind != result or len(names) != count:
        wanted = f"{result} NAME" if count == 1 else f"{result}s NAME NAME"
        raise StatementKindError(f"{form.text} gives {'one' if count == 1 else 'two'} {result}"
                                 f"{'' if count == 1 else 's'}: write '{wanted} = {form.text} …'", form.line, form.col)
    c = reader.claim
    if form.text in ("polygon", "rotate"):
        a, b = (reader._value(_parse_arg(cur, 0)) for _ in range(2))
        if form.text == "polygon":
            n, k = _integer(cur, "the number of vertices"), _integer(cur, "the vertex index")
            c.polygon_vertex(names[0], a, b, n, k)
        else:
            c.rotate_degrees(names[0], a, b, _integer(cur, "the angle in degrees"))
        return
    args = []
    while cur.peek().kind != "end":
        args.append(reader._value(_parse_arg(cur, 0)))
    kinds = tuple(a.kind for a in args)
    table: dict[tuple[str, ...], Callable[[], Any]] = {}
    if form.text in ("anglebisector", "exbisector"):
        method = c.angle_bisector if form.text == "anglebisector" else c.external_bisector
        table[(_P, _P, _P)] = lambda: method(names[0], *args)
    elif form.text.startswith("intersection"):
        one = form.text == "intersection"
        table[(_L, _C)] = lambda: (c.line_conic_intersection(names[0], *args) if one
                                   else c.line_conic_intersections(names, *args))
        table[(_C, _C)] = lambda: (c.circle_intersection(names[0], *args) if one
                                   else c.circle_intersections(names, *args))
    else:
        table[(_P, _C)] = lambda: (c.tangent_from(names[0], *args) if form.text == "tangentfrom"
                                   else c.tangents_from(names, *args))
    build = table.get(kinds)
    if build is None:
        accepted = "; ".join(" ".join(k) for k in table)
        got = " ".join(f"{a.kind} {a.name}" for a in args) or "nothing"
        raise StatementKindError(f"{form.text} takes ({accepted}), got {got}", form.line, form.col)
    build()


# -- the keywords and what each means (for references and error messages) -------------------------------------------

_MEANINGS: dict[str, tuple[str, str]] = {  # keyword -> (group, meaning)
    "title": ("statement", "the theorem's title (the rest of the line)"),
    "expect": ("statement", "expect true or expect false: whether the statement is meant to hold"),
    "params": ("statement", "names of parameters that coordinates may use"),
    "prove": ("statement", "a conclusion: a predicate and its arguments; several prove lines must all hold"),
    "on": ("statement", "point NAME on line, conic or circle: a point with one parameter of its own"),
    "through": ("statement", "point NAME on conic K through P: the point of K seen from P"),
    "points": ("free objects", "free points of P² (two parameters each)"),
    "lines": ("free objects", "free lines of P²"),
    "points3": ("free objects", "free points of P³"),
    "planes": ("free objects", "free planes of P³"),
    "points1": ("free objects", "free points of P¹"),
    "conics": ("free objects", "free conics (six parameters each)"),
    "matrices": ("free objects", "free invertible 3×3 matrices"),
    "matrices4": ("free objects", "free invertible 4×4 matrices"),
    "matrices2": ("free objects", "free invertible 2×2 matrices"),
    "point": ("kinds", "a point of P²: point NAME = expression, or given coordinates"),
    "line": ("kinds", "a line of P²"),
    "point3": ("kinds", "a point of P³"),
    "plane": ("kinds", "a plane of P³; as an operation: the plane through three points of P³"),
    "line3": ("kinds", "a line of P³"),
    "conic": ("kinds", "a conic; as an operation: the conic through five points or tangent to five lines"),
    "point1": ("kinds", "a point of P¹"),
    "ratio": ("kinds", "a number built from the figure (a quotient of two polynomials)"),
    "matrix": ("kinds", "a matrix (given entries)"),
    "join": ("operations", "two points → their line; two points of P³ → line3; three points of P³ → plane"),
    "meet": ("operations", "two lines → their point; two planes → line3; line3 and plane, three planes → point3; "
                           "as a predicate: two lines of P³ meet"),
    "tangent": ("operations", "conic, point on it → the tangent there; as a predicate: a line touches a conic"),
    "polar": ("operations", "conic, point → the polar of the point"),
    "second": ("operations", "conic C, point P of C, point Q → the second point of C on PQ; circles K L, common "
                             "point A → their second common point"),
    "harmonic": ("operations", "A B C → the harmonic conjugate of C with respect to A, B; as a predicate: "
                               "A B C D is harmonic (cross-ratio −1)"),
    "crossratio": ("operations", "A B C D → the cross-ratio (A, B; C, D)"),
    "midpoint": ("operations", "two finite points → their affine midpoint"),
    "apply": ("operations", "matrix, object → its image (point, line, plane or conic)"),
    "dual": ("operations", "conic → its dual conic (the matrix adj C)"),
    "parallel": ("Euclidean operations", "line l, point P → the line through P parallel to l; as a predicate: "
                                         "two lines are parallel"),
    "perpendicular": ("Euclidean operations", "line l, point P → the line through P perpendicular to l; as a "
                                              "predicate: two lines are perpendicular"),
    "bisector": ("Euclidean operations", "A B → the perpendicular bisector of the segment AB"),
    "foot": ("Euclidean operations", "point P, line l → the foot of the perpendicular from P to l"),
    "reflect": ("Euclidean operations", "X P → X reflected in the point P; X l → X reflected in the line l"),
    "rotate": ("Euclidean operations", "X O c s → X rotated about O by the angle with cosine c and sine s; "
                                       "X O DEGREES → by a whole number of degrees (square roots)"),
    "translate": ("Euclidean operations", "X A B → X moved by the vector from A to B"),
    "similar": ("Euclidean operations", "A B D E F → the point X with ABX directly similar to DEF (copies the "
                                        "angle EDF to AB)"),
    "circle": ("Euclidean operations", "O A → centre O through A; A B C → through three points; O r → centre O, "
                                       "squared radius r"),
    "centre": ("Euclidean operations", "circle (or conic) → its centre"),
    "invert": ("Euclidean operations", "X K → the inverse of X in the circle K"),
    "dist2": ("Euclidean operations", "A B → the squared distance (a ratio)"),
    "area": ("Euclidean operations", "A B C → the signed area of the triangle (a ratio)"),
    "segratio": ("Euclidean operations", "A B C D → the signed ratio AB / CD of parallel segments"),
    "add": ("Euclidean operations", "two ratios (or a ratio and a number) → their sum"),
    "sub": ("Euclidean operations", "two ratios (or a ratio and a number) → their difference"),
    "mul": ("Euclidean operations", "two ratios (or a ratio and a number) → their product"),
    "collinear": ("predicates", "three points of P² or P³ on one line"),
    "concurrent": ("predicates", "three lines through one point"),
    "coplanar": ("predicates", "four points of P³ on one plane"),
    "conconic": ("predicates", "six points on one conic, or six lines tangent to one"),
    "equal": ("predicates", "two objects equal up to scale; two ratios, or a ratio and a number, equal"),
    "equallength": ("predicates", "A B C D: AB and CD are equally long"),
    "equalangle": ("predicates", "A B C D E F: the oriented angle ∠ABC equals ∠DEF modulo π"),
    "concyclic": ("predicates", "four points on one circle (or one line)"),
    "equalarea": ("predicates", "A B C D E F: the triangles have equal signed areas"),
    "anglebisector": ("square roots", "A B C → the internal bisector of the angle ABC"),
    "exbisector": ("square roots", "A B C → the external bisector of the angle ABC"),
    "intersection": ("square roots", "l K or K M → a common point of a line (or circle) and a circle"),
    "intersections": ("square roots", "points X Y = intersections l K: both common points, in either order"),
    "tangentfrom": ("square roots", "P K → a tangent from P to the circle K"),
    "tangentsfrom": ("square roots", "lines s t = tangentsfrom P K: both tangents, in either order"),
    "polygon": ("square roots", "A B n k → vertex k of the regular n-gon with consecutive vertices A, B"),
    "where": ("order conditions", "where CONDITION POINTS: an order condition (strict); the theorem is about the "
                                  "figures and branches the conditions select"),
    "sameside": ("order conditions", "P Q A B: P and Q on the same side of the line AB"),
    "oppositeside": ("order conditions", "P Q A B: P and Q on opposite sides of the line AB (for P on the circle "
                                         "QAB: P on the arc AB not containing Q)"),
    "between": ("order conditions", "X A B: X strictly between A and B ((X − A)·(B − X) > 0)"),
    "onray": ("order conditions", "X V P: X on the ray from V through P, X ≠ V ((X − V)·(P − V) > 0)"),
    "inside": ("order conditions", "X A B C: X strictly inside the triangle ABC"),
}


def keywords() -> list[tuple[str, str, str]]:
    """Every keyword of the statement language with its group and meaning, in the order of the grammar.

    >>> [k for k in keywords() if k[0] == "midpoint"]
    [('midpoint', 'operations', 'two finite points → their affine midpoint')]
    >>> {word for word, _, _ in keywords()} == KEYWORDS
    True
    """
    return [(word, group, meaning) for word, (group, meaning) in _MEANINGS.items()]
