"""Templates on points and lines of the projective plane: coordinates, join, meet, ideal points, incidence."""

from __future__ import annotations

import random
from fractions import Fraction

from ...projective_plane import Line, Point, incident
from ...ring import cross, primitive_integers
from ..mistakes import mistake
from ..model import Answer, Exercise, Mistake
from ..template_base import Draft, Template, check
from ._util import equation_latex, integer_solution, nz, primitive_dir, tuple_latex


def _letter(i: int) -> str:
    return "ABCDE"[i]


class HomogeneousTemplate(Template):
    """Homogeneous ↔ inhomogeneous coordinates of a point of the plane.

    Level 1: homogeneous → inhomogeneous with integer result; level 2: the result has fractions;
    level 3: inhomogeneous with fractions → primitive homogeneous coordinates.
    """

    name = "homogeneous"
    title = "Homogeneous and inhomogeneous coordinates"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        extra = []
        p = exercise.params
        if p["direction"] == "to_inhomogeneous" and p["given"][2] != 1:
            # x1 and x2 copied without dividing by x3 (a multiple of the answer, stated concretely first)
            extra.append(mistake("scale", Answer.vector(p["given"][:2]), "the first two homogeneous coordinates, "
                                 "not divided by the last one"))
        return [*extra, *super().mistakes(exercise, index)]

    def build(self, rng: random.Random, level: int) -> Draft:
        if level in (1, 2):
            w = rng.randint(2, 6)
            if level == 1:
                x, y = rng.randint(-9, 9), rng.randint(-9, 9)
                given = (x * w, y * w, w)
            else:
                given = (rng.randint(-20, 20), rng.randint(-20, 20), w)
                while given[0] % w == 0 and given[1] % w == 0:
                    given = (given[0] + 1, given[1], w)
            if rng.random() < 0.5:
                given = tuple(-g for g in given)
            result = (Fraction(given[0], given[2]), Fraction(given[1], given[2]))
            statement = (f"The point $\\mathbf{{x}}$ of the projective plane has homogeneous coordinates "
                         f"$\\mathbf{{x}} = {tuple_latex(given)}$.")
            prompt = "Give its inhomogeneous coordinates $(x, y)$."
            steps = [f"The last coordinate is $x_3 = {given[2]} \\neq 0$, so the point is finite.",
                     f"Divide by it: $(x, y) = ({given[0]}/{given[2]},\\ {given[1]}/{given[2]}) = "
                     f"{tuple_latex(result)}$."]
            return Draft(statement, [(prompt, Answer.vector(result), ())], steps,
                         {"given": list(given), "direction": "to_inhomogeneous"})
        x = Fraction(rng.randint(-12, 12), rng.randint(1, 6))
        y = Fraction(rng.randint(-12, 12), rng.randint(1, 6))
        answer = primitive_integers([x, y, 1])
        statement = ("The point $\\mathbf{x}$ of the Euclidean plane has coordinates "
                     f"$(x, y) = {tuple_latex((x, y))}$.")
        prompt = "Give homogeneous coordinates of $\\mathbf{x}$ as primitive integers."
        steps = [f"Append $1$: $\\mathbf{{x}} = {tuple_latex((x, y, 1))}$.",
                 f"Multiply by the common denominator and divide by the common factor: "
                 f"$\\mathbf{{x}} \\sim {tuple_latex(answer)}$ (any nonzero multiple is the same point)."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps,
                     {"given": [str(x), str(y)], "direction": "to_homogeneous"})

    def verify(self, exercise: Exercise) -> None:
        p = exercise.params
        answer = exercise.parts[0].answer
        if p["direction"] == "to_inhomogeneous":
            point = Point(*p["given"])
            check(not point.is_ideal, "the given point is ideal")
            got = tuple(Fraction(str(c)) for c in point.dehomogenize())
            check(got == answer.value, "wrong inhomogeneous coordinates")
        else:
            x, y = (Fraction(v) for v in p["given"])
            check(Point(x, y) == Point(*answer.value), "wrong homogeneous coordinates")


class JoinTemplate(Template):
    """The line through two points.

    Level 1: two finite points; level 2: homogeneous coordinates with scale factors; level 3: one of
    the points is ideal.
    """

    name = "join"
    title = "The line through two points"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        # the answer is a line: "ideal point given as finite" does not apply to it
        generic = [m for m in super().mistakes(exercise, index) if m.code != "ideal-as-finite"]
        given = [mistake("dual", Answer.projective(exercise.params[k]), "a given point, not the line through "
                         "both points") for k in ("p", "q")]
        return [*generic, *given]

    def build(self, rng: random.Random, level: int) -> Draft:
        x0, y0 = rng.randint(-5, 5), rng.randint(-5, 5)
        d = primitive_dir(rng, 3)
        s, t = rng.sample(range(-3, 4), 2)
        p = [x0 + s * d[0], y0 + s * d[1], 1]
        if level == 3:
            k = nz(rng, 3)
            q = [k * d[0], k * d[1], 0]
        else:
            q = [x0 + t * d[0], y0 + t * d[1], 1]
        if level >= 2:
            k = rng.choice([2, 3, -1, -2])
            p = [k * c for c in p]
        line = cross(p, q)
        answer = primitive_integers(line)
        statement = (f"Let $\\mathbf{{p}} = {tuple_latex(p)}$ and $\\mathbf{{q}} = {tuple_latex(q)}$ "
                     "(homogeneous coordinates).")
        if level == 3:
            statement += " Note that $\\mathbf{q}$ is an ideal point."
        prompt = "Give the line $\\mathbf{l}$ through $\\mathbf{p}$ and $\\mathbf{q}$ (homogeneous coordinates)."
        steps = [f"$\\mathbf{{l}} = \\mathbf{{p}} \\times \\mathbf{{q}} = {tuple_latex(line)}$.",
                 f"Canonical form (primitive integers, first nonzero entry positive): $\\mathbf{{l}} \\sim "
                 f"{tuple_latex(answer)}$.",
                 f"Check: $\\mathbf{{l}}^\\top \\mathbf{{p}} = 0$ and $\\mathbf{{l}}^\\top \\mathbf{{q}} = 0$; "
                 f"the line is ${equation_latex(answer)}$."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"p": p, "q": q})

    def verify(self, exercise: Exercise) -> None:
        p, q = Point(*exercise.params["p"]), Point(*exercise.params["q"])
        check(p != q, "the two points coincide")
        line = Line(*exercise.parts[0].answer.value)
        check(incident(p, line) and incident(q, line), "the answer does not pass through both points")


class MeetTemplate(Template):
    """The intersection point of two lines.

    Level 1: the point is an integer point; level 2: the point has fractional coordinates; level 3:
    fractional point and lines given with common factors.
    """

    name = "meet"
    title = "The intersection of two lines"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        given = [mistake("dual", Answer.projective(exercise.params[k]), "a given line, not the point on both "
                         "lines") for k in ("l", "m")]
        return [*super().mistakes(exercise, index), *given]

    def build(self, rng: random.Random, level: int) -> Draft:
        w = 1 if level == 1 else rng.randint(2, 4)
        x = [rng.randint(-6, 6), rng.randint(-6, 6), w]
        d1 = primitive_dir(rng, 3)
        d2 = primitive_dir(rng, 3)
        while d1[0] * d2[1] - d1[1] * d2[0] == 0:
            d2 = primitive_dir(rng, 3)
        l1 = list(primitive_integers(cross(x, [d1[0], d1[1], 0])))
        l2 = list(primitive_integers(cross(x, [d2[0], d2[1], 0])))
        if level == 3:
            k1, k2 = rng.choice([2, -3]), rng.choice([-1, 2])
            l1 = [k1 * c for c in l1]
            l2 = [k2 * c for c in l2]
        raw = cross(l1, l2)
        answer = primitive_integers(raw)
        statement = (f"Let $\\mathbf{{l}} = {tuple_latex(l1)}$ and $\\mathbf{{m}} = {tuple_latex(l2)}$ be two lines "
                     "(the line $(a, b, c)$ is $ax + by + c = 0$).")
        prompt = "Give their intersection point $\\mathbf{x}$ (homogeneous coordinates)."
        xs = [Fraction(answer[0], answer[2]), Fraction(answer[1], answer[2])]
        steps = [f"$\\mathbf{{x}} = \\mathbf{{l}} \\times \\mathbf{{m}} = {tuple_latex(raw)}$.",
                 f"Canonical form: $\\mathbf{{x}} \\sim {tuple_latex(answer)}$, i.e. the finite point "
                 f"${tuple_latex(xs)}$."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"l": l1, "m": l2})

    def verify(self, exercise: Exercise) -> None:
        l, m = Line(*exercise.params["l"]), Line(*exercise.params["m"])
        check(l != m, "the two lines coincide")
        x = Point(*exercise.parts[0].answer.value)
        check(incident(x, l) and incident(x, m), "the answer does not lie on both lines")


class IdealPointTemplate(Template):
    """The ideal point shared by two parallel lines.

    Level 1: the lines have the same (a, b); level 2: the second line is scaled; level 3: the second
    line is given by two of its points.
    """

    name = "ideal"
    title = "The ideal point of two parallel lines"
    max_entry = 100

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        a, b = exercise.params["l"][:2]
        # (a, b) is the normal of the lines; their common point at infinity is the direction (b, -a)
        normal = mistake("dual", Answer.projective([a, b, 0]), "the normal (a, b) of the lines, read from their "
                         "coefficients, instead of their direction")
        return [*super().mistakes(exercise, index), normal]

    def build(self, rng: random.Random, level: int) -> Draft:
        d = primitive_dir(rng, 4)
        a, b = d[1], -d[0]
        c1, c2 = rng.sample(range(-9, 10), 2)
        l1 = [a, b, c1]
        k = 1 if level == 1 else rng.choice([2, 3, -2])
        l2 = [k * a, k * b, k * c2]
        answer = primitive_integers([b, -a, 0])
        statement = f"Let $\\mathbf{{l}} = {tuple_latex(l1)}$ be a line (that is, ${equation_latex(l1)}$)."
        if level == 3:
            # two integer points on a x + b y + c2 = 0: a particular one needs gcd(a, b) = 1, true here
            x0, y0 = integer_solution(a, b, -c2)
            p = [x0, y0]
            r = rng.randint(1, 2)
            q = [x0 + d[0] * r, y0 + d[1] * r]
            statement += (f" The line $\\mathbf{{m}}$ passes through ${tuple_latex(p)}$ and ${tuple_latex(q)}$; "
                          "it is parallel to $\\mathbf{l}$.")
            l2 = primitive_integers(cross([*p, 1], [*q, 1]))
        else:
            statement += f" Let $\\mathbf{{m}} = {tuple_latex(l2)}$ be a second line; the two are parallel."
        prompt = "Give the point $\\mathbf{x}$ where $\\mathbf{l}$ and $\\mathbf{m}$ meet (homogeneous coordinates)."
        raw = cross(l1, l2)
        steps = [f"$\\mathbf{{x}} = \\mathbf{{l}} \\times \\mathbf{{m}} = {tuple_latex(raw)}$.",
                 f"Canonical form: $\\mathbf{{x}} \\sim {tuple_latex(answer)}$. The last coordinate is $0$: "
                 "an ideal point, the common direction of the two lines. Never divide by it."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"l": l1, "m": list(l2)})

    def verify(self, exercise: Exercise) -> None:
        l, m = Line(*exercise.params["l"]), Line(*exercise.params["m"])
        check(l != m, "the two lines coincide")
        x = Point(*exercise.parts[0].answer.value)
        check(x.is_ideal and incident(x, l) and incident(x, m), "the answer is not the common ideal point")


class IncidenceTemplate(Template):
    """Incidence of points and lines.

    Level 1: does a given point lie on a given line (yes/no); level 2: which of four points lies on
    the line; level 3: the same with homogeneous coordinates, scale factors and ideal points.
    """

    name = "incidence"
    title = "Incidence of a point and a line"
    max_entry = 10

    def build(self, rng: random.Random, level: int) -> Draft:
        x0, y0 = rng.randint(-4, 4), rng.randint(-4, 4)
        d = primitive_dir(rng, 3)
        line = list(primitive_integers(cross([x0, y0, 1], [d[0], d[1], 0])))
        a, b = line[0], line[1]

        def on(k: int) -> list[int]:
            if level == 3 and k == 0:
                s = nz(rng, 2)
                return [s * d[0], s * d[1], 0]
            t = rng.randint(-3, 3)
            w = rng.choice([1, 2, -1]) if level == 3 else 1
            return [w * (x0 + t * d[0]), w * (y0 + t * d[1]), w]

        def off() -> list[int]:
            t, e = rng.randint(-3, 3), nz(rng, 2)
            w = rng.choice([1, 2, -1]) if level == 3 else 1
            return [w * (x0 + t * d[0] + e * a), w * (y0 + t * d[1] + e * b), w]

        statement = f"Let $\\mathbf{{l}} = {tuple_latex(line)}$ be a line."
        if level == 1:
            yes = rng.random() < 0.5
            p = on(1) if yes else off()
            statement += f" Let $\\mathbf{{p}} = {tuple_latex(p)}$."
            choices = ("yes", "no")
            key = "A" if yes else "B"
            prompt = "Does $\\mathbf{p}$ lie on $\\mathbf{l}$?"
            value = p[0] * line[0] + p[1] * line[1] + p[2] * line[2]
            steps = [f"$\\mathbf{{l}}^\\top \\mathbf{{p}} = {value}$, so the answer is **{choices['AB'.index(key)]}**."]
            return Draft(statement, [(prompt, Answer.choice(key), choices)], steps,
                         {"line": line, "points": [p], "key": key})
        index = rng.randrange(4)
        points = [on(rng.randrange(2)) if i == index else off() for i in range(4)]
        choices = tuple(f"${tuple_latex(p)}$" for p in points)
        prompt = "Which of these points lies on $\\mathbf{l}$?"
        values = [sum(pi * li for pi, li in zip(p, line, strict=True)) for p in points]
        steps = ["Compute $\\mathbf{l}^\\top \\mathbf{p}$ for each point: "
                 + ", ".join(f"{_letter(i)}: ${v}$" for i, v in enumerate(values)) + ".",
                 f"Only {_letter(index)} gives $0$."]
        return Draft(statement, [(prompt, Answer.choice(_letter(index)), choices)], steps,
                     {"line": line, "points": points, "key": _letter(index)})

    def verify(self, exercise: Exercise) -> None:
        line = Line(*exercise.params["line"])
        points = [Point(*p) for p in exercise.params["points"]]
        key = exercise.parts[0].answer.value
        if len(points) == 1:
            check((key == "A") == incident(points[0], line), "wrong yes/no key")
        else:
            on = [i for i, p in enumerate(points) if incident(p, line)]
            check(on == ["ABCD".index(key)], f"points on the line: {on}, key {key}")
