"""Template on the projective line: the cross-ratio of four points."""

from __future__ import annotations

import random
from fractions import Fraction

from ...projective_line import Point1, cross_ratio
from ..mistakes import mistake
from ..model import Answer, Exercise, Mistake
from ..template_base import Draft, Template, check
from ._util import primitive_dir, tuple_latex


class CrossRatioTemplate(Template):
    """The cross-ratio (A, B; C, D) = [AC][BD] / ([AD][BC]) of four distinct points of a line.

    Level 1: four numbers on the real line; level 2: four collinear points of the plane; level 3:
    homogeneous coordinates on the projective line, one of the points ideal.
    """

    name = "cross-ratio"
    title = "The cross-ratio of four points"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        lam = exercise.parts[0].answer.value  # neither 0 nor 1 for four distinct points
        others = [("(A, B; D, C)", 1 / lam), ("(A, C; B, D)", 1 - lam), ("(A, C; D, B)", 1 / (1 - lam)),
                  ("(A, D; B, C)", (lam - 1) / lam), ("(A, D; C, B)", lam / (lam - 1))]
        order = [mistake("order", Answer.scalar(v), f"the cross-ratio {name}: the points taken in another order")
                 for name, v in others]
        return [*super().mistakes(exercise, index), *order]

    def build(self, rng: random.Random, level: int) -> Draft:
        values = rng.sample(range(-6, 7), 4)
        a, b, c, d = values
        if level == 3:
            ideal = rng.randrange(4)
            homog = [[v * k, k] for v, k in zip(values, [rng.choice((1, 2, -1)) for _ in range(4)], strict=True)]
            homog[ideal] = [rng.choice((1, -1, 2)), 0]
            brackets = {}
            for (i, p), (j, q) in ((("A", homog[0]), ("C", homog[2])), (("B", homog[1]), ("D", homog[3])),
                                   (("A", homog[0]), ("D", homog[3])), (("B", homog[1]), ("C", homog[2]))):
                brackets[i + j] = p[0] * q[1] - p[1] * q[0]
            value = Fraction(brackets["AC"] * brackets["BD"], brackets["AD"] * brackets["BC"])
            names = "ABCD"
            statement = ("On the projective line, let " + ", ".join(
                f"${n} = {tuple_latex(h)}$" for n, h in zip(names, homog, strict=True))
                + f" (homogeneous coordinates; ${names[ideal]}$ is the ideal point).")
            steps = ["With $[PQ] = p_1 q_2 - p_2 q_1$: " + ", ".join(f"$[{k}] = {v}$" for k, v in brackets.items())
                     + ".", f"$(A, B; C, D) = \\frac{{[AC][BD]}}{{[AD][BC]}} = {_tex(value)}$."]
            params = {"points": homog}
        else:
            value = Fraction((a - c) * (b - d), (a - d) * (b - c))
            if level == 1:
                statement = f"On the real line, let $A = {a}$, $B = {b}$, $C = {c}$, $D = {d}$."
            else:
                x0, y0 = rng.randint(-3, 3), rng.randint(-3, 3)
                u = primitive_dir(rng, 2)
                pts2 = [(x0 + v * u[0], y0 + v * u[1]) for v in values]
                statement = ("The points " + ", ".join(f"${n} = {tuple_latex(p)}$" for n, p in zip("ABCD", pts2,
                             strict=True)) + " of the plane are collinear.")
            steps = ([] if level == 1 else
                     [f"Parametrise the line as $(x_0, y_0) + \\lambda\\,{tuple_latex(u)}$ with $(x_0, y_0) = "
                      f"{tuple_latex((x0, y0))}$: the parameters are $\\lambda = {a}, {b}, {c}, {d}$ "
                      "(the cross-ratio does not depend on the parametrisation)."])
            steps.append(f"$(A, B; C, D) = \\frac{{(a - c)(b - d)}}{{(a - d)(b - c)}} = "
                         f"\\frac{{({a - c})({b - d})}}{{({a - d})({b - c})}} = {_tex(value)}$.")
            params = {"points": [[v, 1] for v in values]}
        prompt = "Give the cross-ratio $(A, B; C, D) = \\frac{[AC][BD]}{[AD][BC]}$ as an exact number."
        return Draft(statement, [(prompt, Answer.scalar(value), ())], steps, params)

    def verify(self, exercise: Exercise) -> None:
        pts = [Point1(*p) for p in exercise.params["points"]]
        check(len(set(pts)) == 4, "two of the points coincide")
        check(Fraction(str(cross_ratio(*pts))) == exercise.parts[0].answer.value, "wrong cross-ratio")


def _tex(value: Fraction) -> str:
    if value.denominator == 1:
        return str(value.numerator)
    return ("-" if value < 0 else "") + f"\\tfrac{{{abs(value.numerator)}}}{{{value.denominator}}}"
