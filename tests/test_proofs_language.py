"""The constructions of published theorems (operations table) and the statement language that reads them.

Each construction is checked twice: its table formula at an exact rational point against the same object
built with pgsym's core classes here (values derived in the comments), and a small claim with it proved
while a false variant is refuted with a counterexample that the core confirms.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy
from hypothesis import assume, given
from hypothesis import strategies as st
from strategies import nonzero_rationals, rationals

from pgsym import conics, plucker, projective_line, projective_plane, space
from pgsym.errors import InputLimitError, ObjectTypeError, PgsymError
from pgsym.escaping import md_escape
from pgsym.limits import MAX_NESTING, MAX_STATEMENT_NAME_CHARS, MAX_STATEMENT_OBJECTS
from pgsym.proofs.claims import Claim
from pgsym.proofs.engine import prove
from pgsym.proofs.errors import (
    StatementError,
    StatementKindError,
    StatementLimitError,
    StatementNameError,
    StatementSyntaxError,
)
from pgsym.proofs.language import parse_statement, read_statement
from pgsym.proofs.operations import OPERATIONS

CIRCLE = [[1, 0, 0], [0, 1, 0], [0, 0, -1]]  # x² + y² = w²
# the unit circle as the conic through five of its points, in the statement language
_CIRCLE = ("point U1 = (1, 0)\npoint U2 = (0, 1)\npoint U3 = (-1, 0)\npoint U4 = (0, -1)\npoint U5 = (3, 4, 5)\n"
           "conic K = conic U1 U2 U3 U4 U5\n")


def _values(claim: Claim) -> dict[str, object]:
    """The table formulas of every node, in exact rationals (no parameters: all coordinates are numbers)."""
    vals: dict[str, object] = {}
    for node in claim.nodes.values():
        vals[node.name] = node.operation.formula(node, [vals[a.name] for a in node.args], lambda e: Fraction(str(e)))
    return vals


class ComplexFraction:
    """x + iy with exact fractions (complex numbers of Python are floats)."""

    def __init__(self, x: Fraction, y: Fraction) -> None:
        self.x, self.y = Fraction(x), Fraction(y)

    def __add__(self, o: ComplexFraction) -> ComplexFraction:
        return ComplexFraction(self.x + o.x, self.y + o.y)

    def __sub__(self, o: ComplexFraction) -> ComplexFraction:
        return ComplexFraction(self.x - o.x, self.y - o.y)

    def __mul__(self, o: ComplexFraction) -> ComplexFraction:
        return ComplexFraction(self.x * o.x - self.y * o.y, self.x * o.y + self.y * o.x)

    def __truediv__(self, o: ComplexFraction) -> ComplexFraction:
        n = o.x * o.x + o.y * o.y
        return self * ComplexFraction(o.x / n, -o.y / n)

    def __eq__(self, o: object) -> bool:
        return isinstance(o, ComplexFraction) and (self.x, self.y) == (o.x, o.y)

    __hash__ = None  # type: ignore[assignment]


def _proportional(u, v) -> bool:
    u, v = [Fraction(str(x)) for x in u], [Fraction(str(x)) for x in v]
    return any(u) and all(u[i] * v[j] == u[j] * v[i] for i in range(len(u)) for j in range(len(u)))


# -- each construction against the core -----------------------------------------------------------------------

def test_second_intersection_matches_the_core():
    c = Claim("x", "x")
    K = c.conic("K", CIRCLE)
    X = c.second_intersection("X", K, c.point("P", 1, 0), c.point("Q", 0, 2))
    # the line through (1, 0) and (0, 2) is y = 2 − 2x; with x² + y² = 1: 5x² − 8x + 3 = 0, x = 1 or 3/5, y = 4/5
    assert _proportional(_values(c)["X"], (3, 4, 5))
    first, second = conics.Conic(sympy.Matrix(CIRCLE)).intersections(projective_plane.Line(2, 1, -2))
    assert {first, second} == {projective_plane.Point(1, 0), projective_plane.Point(3, 4, 5)}
    assert X.conditions[0].startswith("P ≠ Q")


def test_similar_copies_a_triangle_for_any_representatives():
    c = Claim("x", "x")
    # A = (1, 2), B = (3, 3) (written with w = 2), D = (0, 0), E = (1, 1), F = (0, 2) (w = 3): in complex numbers
    # (F − D)/(E − D) = 2i/(1 + i) = 1 + i, and X = A + (B − A)(1 + i) = (1 + 2i) + (2 + i)(1 + i) = 2 + 5i
    pts = [c.point("A", 1, 2), c.point("B", 6, 6, 2), c.point("D", 0, 0), c.point("E", 1, 1), c.point("F", 0, 6, 3)]
    X = c.similar("X", *pts)
    assert _proportional(_values(c)["X"], (2, 5, 1))
    core = OPERATIONS["similar"].core(X, [projective_plane.Point(*n.data) for n in pts], sympy.Rational)
    assert core == projective_plane.Point(2, 5)
    assert X.conditions[0] == "D ≠ E" and OPERATIONS["similar"].group == "similarity"


@given(st.lists(st.tuples(rationals(9, 5), rationals(9, 5), nonzero_rationals(4, 3)), min_size=5, max_size=5))
def test_similar_is_the_complex_formula_for_any_representatives(points):
    # X = A + (B − A)(F − D)/(E − D) with complex fractions, whatever the scale w of each point's representative
    za, zb, zd, ze, zf = (ComplexFraction(x, y) for x, y, _ in points)
    assume(ze != zd)
    want = za + (zb - za) * (zf - zd) / (ze - zd)
    x, y, w = OPERATIONS["similar"].formula(None, [(x * w, y * w, w) for x, y, w in points], Fraction)
    assert w != 0 and ComplexFraction(x / w, y / w) == want


def test_point_on_conic_matches_the_core():
    c = Claim("x", "x")
    c.point_on_conic("X", c.conic("K", CIRCLE), c.point("P", -1, 0), 1)
    # t = 1: the line through (−1, 0) and (1, 1, 1) is y = (x + 1)/2; x² + (x+1)²/4 = 1: 5x² + 2x − 3 = 0, x = 3/5
    assert _proportional(_values(c)["X"], (3, 4, 5))


def test_conic_tangent_to_five_lines_matches_the_core():
    # the tangents of the unit circle at (1,0), (0,1), (−1,0), (0,−1), (3/5, 4/5):
    # x = 1, y = 1, x = −1, y = −1, 3x + 4y = 5
    c = Claim("x", "x")
    lines = [c.line(f"l{i}", *v) for i, v in enumerate([(1, 0, -1), (0, 1, -1), (1, 0, 1), (0, 1, 1), (3, 4, -5)])]
    c.conic_tangent_to("K", *lines)
    got = _values(c)["K"]
    assert _proportional([e for row in got for e in row], [e for row in CIRCLE for e in row])


def test_tangent_is_the_polar_at_a_point_of_the_conic():
    c = Claim("x", "x")
    c.tangent("t", c.conic("K", CIRCLE), c.point("P", 3, 4, 5))
    assert _proportional(_values(c)["t"], conics.Conic(sympy.Matrix(CIRCLE)).tangent_at(
        projective_plane.Point(3, 4, 5)).coords)  # 3x + 4y − 5w = 0


def test_line_meets_plane_and_line_of_planes_match_the_core():
    c = Claim("x", "x")
    A, B = c.point3("A", 0, 0, 0), c.point3("B", 1, 1, 1)
    L = c.line3("L", A, B)
    c.line_meets_plane("X", L, c.plane("E", 0, 0, 1, -2))  # the diagonal x = y = z meets z = 2 at (2, 2, 2)
    E, F = c.plane("F", 1, 0, 0, 0), c.plane("G", 0, 1, 0, 0)
    c.line_of_planes("M", E, F)  # x = 0 and y = 0: the z-axis
    vals = _values(c)
    assert _proportional(vals["X"], (2, 2, 2, 1))
    zaxis = plucker.Line3.join(space.Point3(0, 0, 0), space.Point3(0, 0, 1))
    assert _proportional([e for row in vals["M"] for e in row], list(zaxis.matrix))


def test_cross_ratio_and_harmonic_conjugate_of_collinear_points_and_concurrent_lines():
    c = Claim("x", "x")
    # on the line y = 1: x = 0, 1, 2, 4, i.e. P¹ points 0, 1, 2, 4: (0, 1; 2, 4) = (2·3)/(4·1) = 3/2
    pts = [c.point(n, x, 1) for n, x in zip("ABCD", (0, 1, 2, 4), strict=True)]
    c.cross_ratio_collinear("r", *pts)
    c.harmonic_conjugate_collinear("H", *pts[:3])
    # lines through the origin with slopes 0, 1, 2, 4 (the lines y = m x: (m, −1, 0)): the same cross-ratio
    lines = [c.line(f"l{m}", m, -1, 0) for m in (0, 1, 2, 4)]
    c.cross_ratio_collinear("s", *lines)
    vals = _values(c)
    assert Fraction(vals["r"][0]) / Fraction(vals["r"][1]) == Fraction(3, 2)
    assert projective_line.cross_ratio(*(projective_line.Point1(x) for x in (0, 1, 2, 4))) == sympy.Rational(3, 2)
    assert Fraction(vals["s"][0]) / Fraction(vals["s"][1]) == Fraction(3, 2)
    # the harmonic conjugate of x = 2 with respect to 0 and 1: (0, 1; 2, h) = −1 gives h = 2/3
    assert _proportional(vals["H"], (2, 3, 3))


def test_midpoint_is_right_for_any_representatives():
    c = Claim("x", "x")
    c.midpoint("M", c.point("A", 4, 0, 2), c.point("B", -3, 3, 3))  # (2, 0) and (−1, 1): midpoint (1/2, 1/2)
    assert _proportional(_values(c)["M"], (1, 1, 2))
    assert OPERATIONS["midpoint"].group == "affine"


def test_every_new_operation_says_its_group():
    for name in ("second_intersection", "point_on_conic", "conic_tangent_to", "line_meets_plane", "line_of_planes",
                 "cross_ratio_collinear", "harmonic_conjugate_collinear", "point_on_line", "point_of_line",
                 "collinear3", "on_line3", "lines_meet",
                 "on_conic", "tangent_to", "six_on_conic"):
        assert OPERATIONS[name].group == "projective"
    assert all(OPERATIONS[n].conclusion for n in ("collinear3", "on_line3", "lines_meet", "six_on_conic"))


# -- each construction in a claim: a true statement proved, a false one refuted ------------------------------

def _proved_and_refuted(true_text: str, false_text: str) -> None:
    v = prove(parse_statement(true_text, "t"), timeout=20)
    assert v.proved, v.reason
    w = prove(parse_statement(false_text, "f"), timeout=20)
    assert w.refuted and w.counterexample.recheck()


@pytest.mark.parametrize("true_text, false_text", [
    ("params s t\n" + _CIRCLE + "point P = (1, 0)\npoint Q = (s, t)\n"
     "point X = second K P Q\nprove on X K\nprove collinear P Q X\n",
     "params s t\n" + _CIRCLE + "point P = (1, 0)\npoint Q = (s, t)\n"
     "prove on Q K\n"),
    ("" + _CIRCLE + "point P = (1, 0)\npoint X on conic K through P\n"
     "prove on X K\n",
     "" + _CIRCLE + "point P = (1, 0)\npoint X on conic K through P\n"
     "prove on X (tangent K P)\n"),
    ("lines e\nline a = (1, 0, -1)\nline b = (0, 1, -1)\nline c = (1, 0, 1)\nline d = (0, 1, 1)\n"
     "conic K = conic a b c d e\nprove tangent e K\n",
     "lines e f\nline a = (1, 0, -1)\nline b = (0, 1, -1)\nline c = (1, 0, 1)\nline d = (0, 1, 1)\n"
     "conic K = conic a b c d e\nprove tangent f K\n"),
    ("points3 A B C\nplanes E\npoint3 X = meet (join A B) E\nprove collinear A B X\nprove on X (join A B)\n",
     "points3 A B C\nplanes E\npoint3 X = meet (join A B) E\nprove collinear A C X\n"),
    ("planes E F G\npoint3 X = meet (meet E F) G\nprove on X E\nprove equal X (meet E F G)\n",
     "planes E F G H\npoint3 X = meet (meet E F) G\nprove on X H\n"),
    ("points3 A B C\npoint3 D on line A C\nprove meet (join A B) (join C D)\n",
     "points3 A B C D\nprove meet (join A B) (join C D)\n"),
    ("points A B\npoint C on line A B\npoint D = harmonic A B C\nprove harmonic A B C D\n",
     "points A B\npoint C on line A B\npoint D on line A B\nprove harmonic A B C D\n"),
    ("point O = (0, 0)\nline m = (1, 2, -3)\npoint A on line m\npoint B on line m\npoint C on line m\n"
     "prove equal (crossratio (join O A) (join O B) (join O C) (join O (harmonic A B C))) -1\n",
     "point O = (0, 0)\nline m = (1, 2, -3)\npoint A on line m\npoint B on line m\npoint C on line m\n"
     "prove equal (crossratio (join O A) (join O B) (join O C) (join O (harmonic A B C))) 2\n"),
    ("points A B C\nprove collinear A B (midpoint A B)\n", "points A B C\nprove collinear A C (midpoint A B)\n"),
    # ∠(AB, AX) = ∠(DE, DF) and |AX|·|DE| = |AB|·|DF|; the angle the other way round is false
    ("points A B D E F\npoint X = similar A B D E F\nprove equalangle B A X E D F\n"
     "prove equal (mul (dist2 A X) (dist2 D E)) (mul (dist2 A B) (dist2 D F))\n",
     "points A B D E F\npoint X = similar A B D E F\nprove equalangle X A B E D F\n"),
    ("points F\n" + _CIRCLE + "prove conconic U1 U2 U3 U4 U5 (second K U1 F)\n",
     "points F\n" + _CIRCLE + "prove conconic U1 U2 U3 U4 F (second K U1 F)\n"),
])
def test_constructions_prove_and_refute(true_text, false_text):
    _proved_and_refuted(true_text, false_text)


def test_the_midpoint_conclusion_at_infinity():
    # the harmonic conjugate of the midpoint of AB with respect to A, B is the point at infinity of AB
    text = "points A B\nline inf = (0, 0, 1)\nprove on (harmonic A B (midpoint A B)) inf\n"
    assert prove(parse_statement(text), timeout=20).proved


# -- the language -------------------------------------------------------------------------------------------

def test_the_same_claim_as_the_python_api():
    text = "points A B C D\npoint X = meet (join A B) (join C D)\nprove collinear A B X\n"
    c = parse_statement(text, "demo")
    d = Claim("demo", "demo")
    A, B, C, D = (d.free_point(n) for n in "ABCD")
    X = d.meet("X", d.join("join A B", A, B), d.join("join C D", C, D))
    d.conclude_collinear(A, B, X)
    assert [(n.name, n.op, n.kind) for n in c.nodes.values()] == [(n.name, n.op, n.kind) for n in d.nodes.values()]
    assert c.parameters == d.parameters and c.conditions_text() == d.conditions_text()
    assert prove(c).to_dict(timing=False) == prove(d).to_dict(timing=False)


def test_shared_subexpressions_are_built_once():
    c = parse_statement("points A B C\nprove concurrent (join A B) (join A B) (join B C)\n")
    assert sum(1 for n in c.nodes.values() if n.name == "join A B") == 1


def test_title_expect_comments_and_blank_lines():
    c = parse_statement("# a comment\n\ntitle Three points  # not a comment in a title\nexpect false\n"
                        "points A B C   # free\nprove collinear A B C\n", "n")
    assert c.title == "Three points  # not a comment in a title" and c.expected is False


@pytest.mark.parametrize("text, error, line, col", [
    ("points A B\nline l = join A C\nprove on A l\n", StatementNameError, 2, 17),       # C undefined
    ("points A A\nprove collinear A A A\n", StatementNameError, 1, 10),                 # redefinition
    ("points join\nprove on join join\n", StatementNameError, 1, 8),                    # a keyword as a name
    ("points A B\nline l = meet A B\nprove on A l\n", StatementKindError, 2, 10),       # meet of two points
    ("points A B\npoint X = join A B\nprove on X X\n", StatementKindError, 2, 11),      # declared point, is a line
    ("points A B C\nprove concurrent A B C\n", StatementKindError, 2, 7),              # points are not lines
    ("points A B\nfrobnicate A\n", StatementSyntaxError, 2, 1),
    ("points A B\nline l = join A B extra\n", StatementNameError, 2, 19),
    ("points A B C\nline l = join A B C\nprove on A l\n", StatementKindError, 2, 10),       # three points of P²
    ("points A B\nline l = join A (B\n", StatementSyntaxError, 2, 19),
    ("points A B\nline l = join A B\n", StatementSyntaxError, 2, 1),                    # no prove line
    ("points A €\n", StatementSyntaxError, 1, 10),
    ("points A\x07\n", StatementSyntaxError, 1, 9),
    ("expect maybe\n", StatementSyntaxError, 1, 8),
    ("points A B\nprove equal A 3\n", StatementKindError, 2, 7),
    ("points A B\npoint X on ellipse A\n", StatementSyntaxError, 2, 12),
    ("conics K\npoints A\npoint X on conic K\nprove on X K\n", StatementSyntaxError, 3, 12),
    ("point P = (0, 0, 0)\nprove on P P\n", StatementKindError, 1, 11),                 # the zero vector
    ("point P = (s, 1)\nprove on P P\n", StatementNameError, 1, 12),                    # s is no parameter
    # a construction with square roots inside an expression: it has a line of its own
    ("points A B C\npoint H = meet (anglebisector B A C) (join A B)\nprove on H H\n", StatementSyntaxError, 2, 17),
    ("points A B C\npoint H = meet intersection (join A B)\nprove on H H\n", StatementSyntaxError, 2, 16),
])
def test_errors_name_line_and_column(text, error, line, col):
    with pytest.raises(error) as info:
        parse_statement(text)
    assert (info.value.line, info.value.column) == (line, col), str(info.value)
    assert isinstance(info.value, PgsymError) and str(info.value).startswith(f"{line}:{col}: ")


def test_a_square_root_construction_inside_an_expression_says_how_to_write_it():
    with pytest.raises(StatementSyntaxError, match=r"define it on a line of its own \(line NAME = anglebisector …\)"):
        parse_statement("points A B C\npoint H = meet (anglebisector B A C) (join A B)\nprove on H H\n")
    with pytest.raises(StatementSyntaxError, match=r"\(points NAME1 NAME2 = intersections …\)"):
        parse_statement("points A B\npoint H = meet (intersections (join A B) (circle A B)) (join A B)\n"
                        "prove on H H\n")


def test_hostile_inputs_get_named_errors(tmp_path):
    deep = "(" * (MAX_NESTING + 5) + "join A B" + ")" * (MAX_NESTING + 5)
    with pytest.raises(StatementLimitError):
        parse_statement(f"points A B\nline l = join A {deep}\nprove on A l\n")
    with pytest.raises(StatementLimitError) as info:
        parse_statement("points " + "A" * (MAX_STATEMENT_NAME_CHARS + 1) + "\nprove on A A\n")
    assert isinstance(info.value, InputLimitError)
    with pytest.raises(StatementLimitError):
        parse_statement("points " + " ".join(f"P{i}" for i in range(MAX_STATEMENT_OBJECTS + 1)))
    with pytest.raises(StatementLimitError):
        parse_statement("points A" + " " * 5000 + "\n")
    huge = tmp_path / "huge.thm"
    huge.write_text("# " + "x" * 300_000 + "\n", encoding="utf-8")
    with pytest.raises(StatementLimitError):
        read_statement(huge)
    binary = tmp_path / "binary.thm"
    binary.write_bytes(b"points A\nprove \xff\xfe\n")
    with pytest.raises(StatementSyntaxError) as info:
        read_statement(binary)
    assert (info.value.line, info.value.column) == (2, 7) and str(binary) in str(info.value)
    nul = tmp_path / "nul.thm"
    nul.write_bytes(b"points A\x00\n")
    with pytest.raises(StatementSyntaxError):
        read_statement(nul)
    with pytest.raises(StatementError):
        read_statement(tmp_path / "absent.thm")
    with pytest.raises(StatementLimitError):
        read_statement(tmp_path)  # a folder is not a regular file
    with pytest.raises(StatementLimitError):
        parse_statement("points A\nprove on A " + "9" * 50 + "\n")


def test_claim_api_errors_stay_named():
    c = Claim("x", "x")
    with pytest.raises(ObjectTypeError):
        c.conclude_conconic(*(c.free_point(n) for n in "ABCDE"))
    with pytest.raises(ObjectTypeError):
        c.line_meets_plane("X", c.free_point("P"), c.free_plane("E"))


def test_a_verdict_names_only_the_statement_s_objects_in_every_output():
    # the conclusion |DG| = |GE| needs two squared distances the prover adds itself; the certificate, the
    # conditions and the Markdown, LaTeX and plain text must call them |DG|² and |GE|², not by internal names
    claim = parse_statement("""
points B A C
point D = foot C (join B A)
point E = foot B (join A C)
point F = midpoint C B
point G = foot F (join D E)
prove equallength D G G E
""", name="feet")
    v = prove(claim)
    assert v.proved
    texts = [v.to_markdown(), v.to_latex(), v.summary(), " ".join(v.certificate.steps)]
    for text in texts:
        assert "_dist2" not in text and "#" not in text and "flint" not in text
    assert v.certificate.steps == ["the numerator of |DG|² − |GE|² expands to 0"]
    assert "the denominator of |DG|² is not zero" in v.condition_texts()
    # more than three conditions: one per line, in Markdown as a list and in the terminal as an indented list
    markdown = v.to_markdown().splitlines()
    first = markdown.index("*Non-degeneracy conditions:*")
    assert markdown[first + 1:first + 1 + len(v.condition_texts())] == [
        f"- {md_escape(t)}" for t in v.condition_texts()]
    assert "  provided that:" in v.summary().splitlines()
