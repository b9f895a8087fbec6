"""Templates on projective 3-space: the plane through three points, the point on three planes,
Plücker coordinates of a line."""

from __future__ import annotations

import random
from fractions import Fraction

from ... import ring
from ...plucker import Line3
from ...ring import cross, primitive_integers
from ...space import Plane, Point3, plane_through, point_on_planes
from ..mistakes import mistake
from ..model import Answer, Exercise, Mistake
from ..template_base import Draft, Template, check
from ._util import nz, primitive_dir, tuple_latex


class PlaneThroughTemplate(Template):
    """The plane through three points of space.

    Level 1: three finite integer points; level 2: homogeneous coordinates with scale factors;
    level 3: one of the points is ideal (a direction in the plane).
    """

    name = "plane3"
    title = "The plane through three points"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        # the answer is a plane: "ideal point given as finite" does not apply to it
        generic = [m for m in super().mistakes(exercise, index) if m.code != "ideal-as-finite"]
        given = [mistake("dual", Answer.projective(p), "a given point, not the plane through the three points")
                 for p in exercise.params["points"]]
        return [*generic, *given]

    def build(self, rng: random.Random, level: int) -> Draft:
        while True:
            n = list(primitive_dir(rng, 3, 3))
            j = rng.randrange(3)
            n[j] = rng.choice((1, -1))
            dd = rng.randint(-5, 5)
            plane = [*n, dd]

            def point(plane: list[int] = plane, j: int = j) -> list[int]:
                p = [rng.randint(-3, 3) for _ in range(3)]
                p[j] = 0
                p[j] = -(sum(plane[i] * p[i] for i in range(3)) + plane[3]) * plane[j]
                return [*p, 1]

            pts = [point(), point(), point()]
            if level == 3:
                a, b = point(), point()
                pts[2] = [a[i] - b[i] for i in range(3)] + [0]
            if level >= 2:
                k = rng.choice((2, -1, 3))
                pts[0] = [k * c for c in pts[0]]
            raw = ring.plane_through(*pts)  # signed 3×3 minors: zero iff the points are dependent
            if any(raw):
                break
        answer = primitive_integers(raw)
        statement = "Let " + ", ".join(f"$\\mathbf{{X}}_{i + 1} = {tuple_latex(p)}$" for i, p in enumerate(pts)) + \
            " be points of projective 3-space (homogeneous coordinates)."
        if level == 3:
            statement += " The third one is an ideal point."
        prompt = ("Give the plane $\\boldsymbol{\\pi}$ through the three points (homogeneous coordinates "
                  "$(a, b, c, d)$ of $ax + by + cz + d = 0$).")
        steps = ["$\\boldsymbol{\\pi}$ spans the null space of the $3 \\times 4$ matrix with rows "
                 "$\\mathbf{X}_i^\\top$; its entries are the signed $3\\times3$ minors.",
                 f"Minors: $\\boldsymbol{{\\pi}} = {tuple_latex(raw)} \\sim {tuple_latex(answer)}$.",
                 "Check: $\\boldsymbol{\\pi}^\\top \\mathbf{X}_i = 0$ for $i = 1, 2, 3$."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"points": pts})

    def verify(self, exercise: Exercise) -> None:
        pts = [Point3(*p) for p in exercise.params["points"]]
        check(plane_through(*pts) == Plane(*exercise.parts[0].answer.value), "wrong plane")


class PointOnPlanesTemplate(Template):
    """The point on three planes.

    Level 1: a finite integer point; level 2: a finite point with fractional coordinates; level 3:
    an ideal point (three planes parallel to one direction).
    """

    name = "point3"
    title = "The point on three planes"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        given = [mistake("dual", Answer.projective(p), "a given plane, not the point on the three planes")
                 for p in exercise.params["planes"]]
        return [*super().mistakes(exercise, index), *given]

    def build(self, rng: random.Random, level: int) -> Draft:
        if level == 3:
            X = [*primitive_dir(rng, 2, 3), 0]
        else:
            X = [rng.randint(-3, 3) for _ in range(3)] + [1 if level == 1 else rng.randint(2, 3)]
        while True:
            planes = []
            for _ in range(3):
                if level == 3:
                    n = cross(X[:3], [rng.randint(-2, 2) for _ in range(3)])
                    planes.append([int(x) for x in n] + [nz(rng, 4)])
                else:
                    n = [rng.randint(-2, 2) for _ in range(3)]
                    w = X[3]
                    planes.append([w * x for x in n] + [-sum(a * b for a, b in zip(n, X[:3], strict=True))])
            if all(any(p[:3]) for p in planes):
                raw = ring.plane_through(*planes)  # the same minors give the point of three planes
                if any(raw):
                    break
        answer = primitive_integers(raw)
        assert answer == primitive_integers(X)
        statement = "Let " + ", ".join(f"$\\boldsymbol{{\\pi}}_{i + 1} = {tuple_latex(p)}$"
                                       for i, p in enumerate(planes)) + \
            " be planes of projective 3-space ($(a, b, c, d)$ is the plane $ax + by + cz + d = 0$)."
        prompt = "Give the point $\\mathbf{X}$ on all three planes (homogeneous coordinates)."
        steps = ["$\\mathbf{X}$ spans the null space of the matrix with rows $\\boldsymbol{\\pi}_i^\\top$; its "
                 "entries are the signed $3\\times3$ minors.",
                 f"$\\mathbf{{X}} = {tuple_latex(raw)} \\sim {tuple_latex(answer)}$"
                 + (" (an ideal point)." if answer[3] == 0 else
                    f", the finite point ${tuple_latex([Fraction(answer[i], answer[3]) for i in range(3)])}$.")]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"planes": planes})

    def verify(self, exercise: Exercise) -> None:
        planes = [Plane(*p) for p in exercise.params["planes"]]
        check(point_on_planes(*planes) == Point3(*exercise.parts[0].answer.value), "wrong point")


class PluckerTemplate(Template):
    """Plücker coordinates (l12, l13, l14, l23, l42, l34) of the line through two points, l_ij = a_i b_j − a_j b_i.

    Level 1: two finite points; level 2: homogeneous coordinates with scale factors; level 3: one of
    the points is ideal.
    """

    name = "plucker"
    title = "Plücker coordinates of a line"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        l12, l13, l14, l23, l42, l34 = exercise.parts[0].answer.value
        dual = mistake("dual", Answer.projective([l34, l42, l23, l14, l13, l12]),
                       "the dual Plücker coordinates (l34, l42, l23, l14, l13, l12) of the same line")
        return [*super().mistakes(exercise, index), dual]

    def build(self, rng: random.Random, level: int) -> Draft:
        while True:
            A = [rng.randint(-3, 3) for _ in range(3)] + [1]
            B = [rng.randint(-3, 3) for _ in range(3)] + [0 if level == 3 else 1]
            if level == 2:
                k = rng.choice((2, -1, 3))
                A = [k * x for x in A]
            raw = [A[i] * B[j] - A[j] * B[i] for i, j in ((0, 1), (0, 2), (0, 3), (1, 2), (3, 1), (2, 3))]
            if any(raw):
                break
        answer = primitive_integers(raw)
        statement = (f"Let $\\mathbf{{A}} = {tuple_latex(A)}$ and $\\mathbf{{B}} = {tuple_latex(B)}$ be points "
                     "of projective 3-space. Use $l_{ij} = a_i b_j - a_j b_i$, the entries of $L = \\mathbf{A}"
                     "\\mathbf{B}^\\top - \\mathbf{B}\\mathbf{A}^\\top$.")
        prompt = ("Give the Plücker coordinates $(l_{12}, l_{13}, l_{14}, l_{23}, l_{42}, l_{34})$ of the line "
                  "through $\\mathbf{A}$ and $\\mathbf{B}$.")
        steps = [f"$(l_{{12}}, l_{{13}}, l_{{14}}, l_{{23}}, l_{{42}}, l_{{34}}) = {tuple_latex(raw)} \\sim "
                 f"{tuple_latex(answer)}$.",
                 "Check the Klein relation $l_{12}l_{34} + l_{13}l_{42} + l_{14}l_{23} = "
                 f"{answer[0] * answer[5] + answer[1] * answer[4] + answer[2] * answer[3]}$."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"A": A, "B": B})

    def verify(self, exercise: Exercise) -> None:
        A, B = Point3(*exercise.params["A"]), Point3(*exercise.params["B"])
        check(A != B, "coincident points")
        check(Line3.join(A, B) == Line3(*exercise.parts[0].answer.value), "wrong Plücker coordinates")
