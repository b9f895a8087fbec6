"""Templates on the metric plane read off the absolute: the angle of two lines, the perpendicular through a
point, and the type of a conic from its points at infinity.

An angle's cosine is usually a surd; it is asked as ``p√q`` (``p`` rational, ``q`` square-free), two parts
that grade exactly.

>>> from pgsym.exercises.registry import get_template
>>> ex = get_template("angle").generate(seed=1, level=2, slot=2)
>>> [(p.label, p.answer.kind) for p in ex.parts]
[('2a', 'scalar'), ('2b', 'integer')]
>>> _surd(Fraction(1, 12))       # √(1/12) = 1/(2√3) = √3/6
(Fraction(1, 6), 3)
"""

from __future__ import annotations

import random
from fractions import Fraction

import sympy

from ...conic_metric import affine_type
from ...conics import Conic
from ...exact import is_zero
from ...metric import cos_angle, cos_squared_angle, is_perpendicular, orthogonal_projection, perpendicular_line
from ...projective_plane import Line, Point, incident
from ...ring import cross, primitive_integers
from ..mistakes import mistake
from ..model import Answer, Exercise, Mistake
from ..template_base import Draft, Template, check
from ._util import equation_latex, integer_solution, matrix_latex, nz, primitive_dir, tuple_latex

# rotations by an angle with rational cosine and sine, (cos, sin, hypotenuse): Pythagorean triples
_PYTHAGOREAN = ((3, 4, 5), (4, 3, 5), (5, 12, 13), (12, 5, 13), (8, 15, 17), (15, 8, 17))


def _tex(value: Fraction) -> str:
    if value.denominator == 1:
        return str(value.numerator)
    return ("-" if value < 0 else "") + f"\\tfrac{{{abs(value.numerator)}}}{{{value.denominator}}}"


def _squarefree_split(n: int) -> tuple[int, int]:
    """``(k, b)`` with ``n = k² b`` and ``b`` square-free (``n > 0``)."""
    k, b = 1, 1
    for prime, exponent in sympy.factorint(n).items():
        p, e = int(prime), int(exponent)  # large factors may come back as python-flint integers
        k *= p ** (e // 2)
        b *= p ** (e % 2)
    return k, b


def _surd(square: Fraction) -> tuple[Fraction, int]:
    """``(a, b)`` with ``√square = a√b``, ``a ≥ 0`` rational and ``b`` a square-free positive integer.

    ``√(p/q) = √(pq)/q``; ``pq = k² b`` gives ``a = k/q``. Zero is written ``0·√1``.
    """
    if square == 0:
        return Fraction(0), 1
    k, b = _squarefree_split(square.numerator * square.denominator)
    return Fraction(k, square.denominator), b


def _surd_tex(a: Fraction, b: int) -> str:
    if b == 1:
        return _tex(a)
    if a.denominator == 1:
        return ("" if a == 1 else str(a.numerator)) + f"\\sqrt{{{b}}}"
    return f"\\tfrac{{{'' if a.numerator == 1 else a.numerator}\\sqrt{{{b}}}}}{{{a.denominator}}}"


def _forms(l: list[int], m: list[int], size: int = 2) -> tuple[int, int, int]:
    """``(lᵀAm, lᵀAl, mᵀAm)`` for ``A = C*∞ = diag(1, 1, 0)`` (``size=2``) or the identity (``size=3``)."""
    def dot(u: list[int], v: list[int]) -> int:
        return sum(x * y for x, y in zip(u[:size], v[:size], strict=True))
    return dot(l, m), dot(l, l), dot(m, m)


def _line_through(p: tuple[int, int], q: tuple[int, int]) -> list[int]:
    return list(primitive_integers(cross([p[0], p[1], 1], [q[0], q[1], 1])))


def _two_points_on(line: list[int], rng: random.Random) -> tuple[tuple[int, int], tuple[int, int]]:
    """Two distinct integer points of an integer line ``a x + b y + c = 0`` with ``gcd(a, b) = 1``."""
    a, b, c = line
    x0, y0 = integer_solution(a, b, -c)
    s, t = rng.sample(range(-2, 3), 2)
    return (x0 + s * b, y0 - s * a), (x0 + t * b, y0 - t * a)


class AngleTemplate(Template):
    """The angle of two lines from the dual conic at infinity, cos θ = |lᵀC*∞m| / √((lᵀC*∞l)(mᵀC*∞m)).

    The answer is written ``p√q`` (``p`` rational, ``q`` square-free), so that a surd is graded exactly.
    Level 1: the cosine is rational (the lines differ by a Pythagorean rotation) and is the only answer;
    level 2: the cosine is a surd; level 3: each line is given by two of its points.
    """

    name = "angle"
    title = "The angle between two lines"
    max_entry = 2_000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        l, m = exercise.params["l"], exercise.params["m"]
        lm, ll, mm = _forms(l, m)
        cos2 = Fraction(lm * lm, ll * mm)
        wrong3 = _surd(Fraction(_forms(l, m, 3)[0] ** 2, _forms(l, m, 3)[1] * _forms(l, m, 3)[2]))
        sine = _surd(1 - cos2)
        if index == 0:
            one = len(exercise.parts) == 1  # level 1: the rational cosine itself; a surd is no candidate then
            out = [mistake("squared", Answer.scalar(cos2), "cos²θ: the square root was not taken")]
            out += [mistake("absolute", Answer.scalar(wrong3[0]), "the third coordinates were used: the angle "
                            "comes from C*∞ = diag(1, 1, 0), which ignores them")] if not one or wrong3[1] == 1 else []
            out += [mistake("sine", Answer.scalar(sine[0]), "sin θ computed instead of cos θ")
                    ] if not one or sine[1] == 1 else []
        else:
            unreduced = cos2.numerator * cos2.denominator  # √(p/q) = √(pq)/q with pq not reduced
            out = [mistake("unsimplified", Answer.integer(unreduced), "the square factor was not taken out of the "
                           "root: q must be square-free"),
                   mistake("absolute", Answer.integer(wrong3[1]), "the third coordinates were used: the angle "
                           "comes from C*∞ = diag(1, 1, 0), which ignores them"),
                   mistake("sine", Answer.integer(sine[1]), "sin θ computed instead of cos θ")]
        return [*super().mistakes(exercise, index), *out]

    def build(self, rng: random.Random, level: int) -> Draft:
        x0, y0 = rng.randint(-4, 4), rng.randint(-4, 4)
        n1 = primitive_dir(rng, 4)
        if level == 1:
            c, s, _ = rng.choice(_PYTHAGOREAN)
            s = s if rng.random() < 0.5 else -s
            n2 = primitive_integers([c * n1[0] - s * n1[1], s * n1[0] + c * n1[1]])
        else:
            n2 = primitive_dir(rng, 4)
            while n1[0] * n2[1] - n1[1] * n2[0] == 0 or n1[0] * n2[0] + n1[1] * n2[1] == 0:
                n2 = primitive_dir(rng, 4)  # neither parallel nor perpendicular
        l = [n1[0], n1[1], -(n1[0] * x0 + n1[1] * y0)]
        m = [n2[0], n2[1], -(n2[0] * x0 + n2[1] * y0)]
        if rng.random() < 0.5:
            m = [-v for v in m]
        m[2] += rng.choice((0, 0, 1, -2)) * (abs(n2[0]) + abs(n2[1]))  # the lines need not meet at an integer point
        lm, ll, mm = _forms(l, m)
        a, b = _surd(Fraction(lm * lm, ll * mm))
        names = "(the line $(a, b, c)$ is $ax + by + c = 0$)"
        if level == 3:
            pl, ql = _two_points_on(l, rng)
            pm, qm = _two_points_on(m, rng)
            l, m = _line_through(pl, ql), _line_through(pm, qm)
            lm, ll, mm = _forms(l, m)
            statement = (f"The line $\\mathbf{{l}}$ passes through ${tuple_latex(pl)}$ and ${tuple_latex(ql)}$, the "
                         f"line $\\mathbf{{m}}$ through ${tuple_latex(pm)}$ and ${tuple_latex(qm)}$.")
            steps = [f"$\\mathbf{{l}} \\sim {tuple_latex(l)}$ and $\\mathbf{{m}} \\sim {tuple_latex(m)}$ "
                     "(cross products of the homogeneous points)."]
        else:
            statement = (f"Let $\\mathbf{{l}} = {tuple_latex(l)}$ and $\\mathbf{{m}} = {tuple_latex(m)}$ be two "
                         f"lines {names}.")
            steps = []
        statement += " Let $\\theta$ be the angle between them, with $0 \\le \\theta \\le 90^\\circ$"
        # at level 1 the cosine is rational: asking for q as well would give every student q = 1
        statement += (", a rational number here." if level == 1 else
                      ", and write $\\cos\\theta = p\\sqrt{q}$ with $p$ rational and $q$ a square-free positive "
                      "integer ($q = 1$ when the cosine is rational).")
        steps += [f"With $C^*_\\infty = \\operatorname{{diag}}(1, 1, 0)$: "
                  f"$\\mathbf{{l}}^\\top C^*_\\infty \\mathbf{{m}} = {lm}$, "
                  f"$\\mathbf{{l}}^\\top C^*_\\infty \\mathbf{{l}} = {ll}$, "
                  f"$\\mathbf{{m}}^\\top C^*_\\infty \\mathbf{{m}} = {mm}$.",
                  f"$\\cos\\theta = \\frac{{|{lm}|}}{{\\sqrt{{{ll} \\cdot {mm}}}}}$, so "
                  f"$\\cos^2\\theta = {_tex(Fraction(lm * lm, ll * mm))}$ and $\\cos\\theta = {_surd_tex(a, b)}$"
                  + (f": $p = {_tex(a)}$, $q = {b}$." if level > 1 else ".")]
        parts = ([("Give $\\cos\\theta$.", Answer.scalar(a), ())] if level == 1 else
                 [("Give $p$.", Answer.scalar(a), ()), ("Give $q$.", Answer.integer(b), ())])
        return Draft(statement, parts, steps, {"l": list(l), "m": list(m)})

    def verify(self, exercise: Exercise) -> None:
        l, m = Line(*exercise.params["l"]), Line(*exercise.params["m"])
        a = exercise.parts[0].answer.value
        b = exercise.parts[1].answer.value if len(exercise.parts) > 1 else 1  # level 1: one rational cosine
        check(l != m and not is_zero(cos_squared_angle(l, m) - 1), "the lines are parallel")
        check(a >= 0 and b >= 1 and _squarefree_split(b)[0] == 1, "a√b is not in the normal form")
        cos = sympy.Abs(cos_angle(l, m))
        check(is_zero(sympy.radsimp(cos - sympy.Rational(a.numerator, a.denominator) * sympy.sqrt(b))),
              "wrong cosine")


class PerpendicularTemplate(Template):
    """The perpendicular to a line through a point: x × C*∞l = x × (l1, l2, 0).

    Level 1: integer point and line; level 2: the point in homogeneous coordinates with a fraction; level 3:
    the line is given by two of its points.
    """

    name = "perpendicular"
    title = "The perpendicular through a point"
    max_entry = 10_000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        (a, b, c), x = exercise.params["l"], exercise.params["x"]
        generic = [m for m in super().mistakes(exercise, index) if m.code != "ideal-as-finite"]
        foot = orthogonal_projection(Point(*x), Line(a, b, c))
        wrong = [mistake("parallel", Answer.projective(cross(x, [b, -a, 0])), "the parallel to l through the point, "
                         "not the perpendicular"),
                 mistake("wrong-point", Answer.projective([b, -a, c]), "a perpendicular to l, but not through the "
                         "given point (the constant term was copied from l)"),
                 mistake("dual", Answer.projective([int(v) for v in foot]), "the foot of the perpendicular (a point), "
                         "not the perpendicular line")]
        return [*generic, *wrong]

    def build(self, rng: random.Random, level: int) -> Draft:
        p0 = (rng.randint(-5, 5), rng.randint(-5, 5))
        n = primitive_dir(rng, 4)
        line = [n[0], n[1], -(n[0] * p0[0] + n[1] * p0[1])]
        # a point off the line: a foot on it plus a nonzero multiple of the normal, plus a step along it
        e, t = nz(rng, 2), rng.randint(-2, 2)
        w = 1 if level == 1 else rng.choice((2, 3, -2))
        xw = [w * (p0[0] + t * n[1]) + e * n[0], w * (p0[1] - t * n[0]) + e * n[1], w]
        x = list(primitive_integers(xw))
        if x[2] < 0:
            x = [-v for v in x]
        raw = cross(x, [line[0], line[1], 0])
        answer = primitive_integers(raw)
        if level == 3:
            p, q = _two_points_on(line, rng)
            statement = (f"The line $\\mathbf{{l}}$ passes through ${tuple_latex(p)}$ and ${tuple_latex(q)}$. "
                         f"Let $\\mathbf{{x}} = {tuple_latex(x)}$ (homogeneous coordinates).")
            steps = [f"$\\mathbf{{l}} \\sim {tuple_latex(line)}$, the line ${equation_latex(line)}$."]
        else:
            statement = (f"Let $\\mathbf{{l}} = {tuple_latex(line)}$ be a line (that is, ${equation_latex(line)}$) and "
                         f"$\\mathbf{{x}} = {tuple_latex(x)}$ a point (homogeneous coordinates).")
            steps = []
        prompt = "Give the line through $\\mathbf{x}$ perpendicular to $\\mathbf{l}$ (homogeneous coordinates)."
        steps += [f"The pole of $\\mathbf{{l}}$ with respect to $C^*_\\infty$ is $C^*_\\infty\\mathbf{{l}} = "
                  f"{tuple_latex([line[0], line[1], 0])}$, the ideal point in the direction of the normal.",
                  f"The perpendicular joins it to $\\mathbf{{x}}$: $\\mathbf{{x}} \\times C^*_\\infty\\mathbf{{l}} = "
                  f"{tuple_latex(raw)} \\sim {tuple_latex(answer)}$, the line ${equation_latex(answer)}$."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"l": line, "x": x})

    def verify(self, exercise: Exercise) -> None:
        l, x = Line(*exercise.params["l"]), Point(*exercise.params["x"])
        check(not incident(x, l) and not x.is_ideal, "the point lies on the line or is ideal")
        answer = Line(*exercise.parts[0].answer.value)
        check(incident(x, answer) and is_perpendicular(l, answer), "the answer is not the perpendicular")
        check(answer == perpendicular_line(l, x), "the answer differs from pgsym.metric.perpendicular_line")


_TYPES = ("ellipse", "hyperbola", "parabola")


class ConicTypeTemplate(Template):
    """Ellipse, hyperbola or parabola: how a real non-degenerate conic meets the line at infinity.

    Level 1: no ``xy`` term; level 2: an ``xy`` term; level 3: the conic is given by its symmetric matrix.
    """

    name = "conic-type"
    title = "The type of a conic"
    max_entry = 10

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        a, b, c = exercise.params["coefficients"][:3]
        key = exercise.params["type"]
        out = []
        if key != "parabola":  # the rule read backwards: b² − 4ac > 0 taken for an ellipse
            other = "hyperbola" if key == "ellipse" else "ellipse"
            out.append(mistake("reversed", Answer.choice("ABC"[_TYPES.index(other)]), "the sign rule read "
                               "backwards: b² − 4ac > 0 means two real points at infinity, a hyperbola"))
        slip = _type_of(b * b - a * c)  # b is the coefficient of xy; the matrix entry is b/2
        if slip != key:
            out.append(mistake("matrix-entry", Answer.choice("ABC"[_TYPES.index(slip)]), "b² − ac used with b the "
                               "coefficient of xy: the matrix entry is b/2, so the test is b² − 4ac"))
        return [*super().mistakes(exercise, index), *out]

    def build(self, rng: random.Random, level: int) -> Draft:
        kind = _TYPES[rng.randrange(3)]
        while True:
            if kind == "parabola":
                p, q = (nz(rng, 2), 0) if level == 1 and rng.random() < 0.5 else (0, nz(rng, 2))
                if level > 1:
                    p, q = nz(rng, 2), nz(rng, 2)
                a, b, c = p * p, 2 * p * q, q * q
            else:
                a, c = nz(rng, 3), nz(rng, 3)
                b = 0 if level == 1 else 2 * rng.randint(-3, 3) if level == 3 else rng.randint(-4, 4)
            if _type_of(b * b - 4 * a * c) != kind:
                continue
            d, e = rng.randint(-3, 3), rng.randint(-3, 3)
            if level == 3:
                d, e = 2 * d, 2 * e  # even, so that the matrix has integer entries
            x0, y0 = rng.randint(-2, 2), rng.randint(-2, 2)  # a real point of the conic
            f = -(a * x0 * x0 + b * x0 * y0 + c * y0 * y0 + d * x0 + e * y0)
            conic = Conic.from_coefficients(a, b, c, d, e, f)
            if not conic.is_degenerate:
                break
        coefficients = [a, b, c, d, e, f]
        if level == 3:
            M = [[a, b // 2, d // 2], [b // 2, c, e // 2], [d // 2, e // 2, f]]
            statement = f"The conic $\\mathbf{{x}}^\\top C \\mathbf{{x}} = 0$ has the matrix $C = {matrix_latex(M)}$."
        else:
            statement = f"Consider the conic ${_conic_latex(coefficients)}$."
        statement += f" It passes through the real point ${tuple_latex((x0, y0))}$ and is not degenerate."
        disc = b * b - 4 * a * c
        count = {"hyperbola": "two real points", "parabola": "one double real point", "ellipse": "no real point"}
        steps = [] if level < 3 else [f"From $C$: $a = C_{{11}} = {a}$, $b = 2C_{{12}} = {b}$, $c = C_{{22}} = {c}$."]
        steps += ["Its points at infinity have $x_3 = 0$: $a x_1^2 + b x_1 x_2 + c x_2^2 = "
                 f"{_conic_latex([a, b, c, 0, 0, 0], 'x_1', 'x_2').removesuffix(' = 0')} = 0$.",
                 f"Its discriminant is $b^2 - 4ac = ({b})^2 - 4 \\cdot ({a}) \\cdot ({c}) = {disc}$: {count[kind]} "
                 f"at infinity, so the conic is a **{kind}**."]
        choices = ("an ellipse", "a hyperbola", "a parabola")
        prompt = "Which type of conic is it?"
        key = "ABC"[_TYPES.index(kind)]
        return Draft(statement, [(prompt, Answer.choice(key), choices)], steps,
                     {"coefficients": coefficients, "point": [x0, y0], "type": kind})

    def verify(self, exercise: Exercise) -> None:
        conic = Conic.from_coefficients(*exercise.params["coefficients"])
        check(not conic.is_degenerate, "the conic is degenerate")
        check(conic.contains(Point(*exercise.params["point"])), "the conic has no real point where it should")
        # the library's classification by how the conic meets l∞ (a circle is the ellipse through I and J)
        kind = affine_type(conic)
        kind = "ellipse" if kind == "circle" else kind
        check(exercise.parts[0].answer.value == "ABC"[_TYPES.index(kind)], f"the conic is a {kind}")


def _type_of(disc: int) -> str:
    return "hyperbola" if disc > 0 else "parabola" if disc == 0 else "ellipse"


def _conic_latex(coefficients: list[int], x: str = "x", y: str = "y") -> str:
    """``a x² + b xy + c y² + d x + e y + f = 0`` written neatly."""
    monomials = [f"{x}^2", f"{x}{y}", f"{y}^2", x, y, ""]
    terms = []
    for value, mono in zip(coefficients, monomials, strict=True):
        if value == 0:
            continue
        mag = "" if abs(value) == 1 and mono else str(abs(value))
        terms.append(("-" if value < 0 else "+", f"{mag}{mono}"))
    if not terms:
        return "0 = 0"
    text = ("-" if terms[0][0] == "-" else "") + terms[0][1]
    text += "".join(f" {s} {t}" for s, t in terms[1:])
    return text + " = 0"
