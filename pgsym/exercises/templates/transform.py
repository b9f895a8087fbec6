"""Templates on plane transformations: applying a homography, the hierarchy, four correspondences,
and the decomposition H = H_S H_A H_P."""

from __future__ import annotations

import functools
import random
from fractions import Fraction

import sympy

from ...conics import Conic
from ...decomposition import decompose
from ...errors import SingularTransformationError
from ...hierarchy import AFFINE_2D, EUCLIDEAN_2D, ISOMETRY_2D, PROJECTIVE_2D, SIMILARITY_2D, classify
from ...projective_plane import Line, Point, collinear, incident
from ...ring import adjugate, det, matmul, matvec, primitive_integer_matrix, primitive_integers, transpose
from ..errors import TemplateError
from ..mistakes import mistake
from ..model import Answer, Exercise, Mistake
from ..template_base import Draft, Template, check
from ._util import invertible, matrix_latex, nz, primitive_dir, tuple_latex


def _homography(rng: random.Random, level: int) -> list[list[Fraction]]:
    """Level 1: an affine map (last row 0 0 1); levels 2 and 3: a general projective map."""
    if level == 1:
        A = invertible(rng, 2, 1, 2)
        return [[A[0][0], A[0][1], Fraction(rng.randint(-3, 3))], [A[1][0], A[1][1], Fraction(rng.randint(-3, 3))],
                [Fraction(0), Fraction(0), Fraction(1)]]
    return invertible(rng, 3, 1, 2 if level == 2 else 3)


def _smatrix(rows: list[list[int]] | tuple) -> sympy.Matrix:
    return sympy.Matrix([[sympy.Rational(str(x)) for x in row] for row in rows])


def _proportional(a: sympy.Matrix, b: sympy.Matrix) -> bool:
    fa, fb = list(a), list(b)
    return any(x != 0 for x in fa) and all(
        sympy.expand(fa[i] * fb[j] - fa[j] * fb[i]) == 0 for i in range(len(fa)) for j in range(i + 1, len(fa)))


def _ints(rows: list[list[Fraction]]) -> list[list[int]]:
    return [[int(x) for x in row] for row in rows]


class ApplyPointTemplate(Template):
    """Apply a homography to a point: x' = H x.

    Level 1: an affine map; level 2: a projective map; level 3: larger entries, and the point is
    given with a scale factor.
    """

    name = "apply-point"
    title = "A homography applied to a point"
    max_entry = 10_000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        H, x = exercise.params["H"], exercise.params["x"]
        wrong = [mistake("transposed", Answer.projective(matvec(transpose(H), x)), "Hᵀx: H transposed"),
                 mistake("inverted", Answer.projective(matvec(adjugate(H), x)), "H⁻¹x: the map taken backwards")]
        return [*super().mistakes(exercise, index), *wrong]

    def build(self, rng: random.Random, level: int) -> Draft:
        H = _homography(rng, level)
        x = [rng.randint(-3, 3), rng.randint(-3, 3), 1]
        if level == 3:
            k = rng.choice([2, -1, 3])
            x = [k * c for c in x]
        image = matvec(H, x)
        while all(c == 0 for c in image):  # impossible (H invertible, x nonzero): kept as a guard
            x[0] += 1
            image = matvec(H, x)
        answer = primitive_integers(image)
        statement = (f"The homography $H = {matrix_latex(H)}$ acts on points of the plane. "
                     f"Let $\\mathbf{{x}} = {tuple_latex(x)}$.")
        prompt = "Give the image $\\mathbf{x}' = H\\mathbf{x}$ (homogeneous coordinates)."
        steps = [f"$H\\mathbf{{x}} = {tuple_latex(image)}$.",
                 f"Canonical form: $\\mathbf{{x}}' \\sim {tuple_latex(answer)}$"
                 + (" (an ideal point: $\\mathbf{x}$ lay on the line mapped to infinity)." if answer[2] == 0 else ".")]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"H": _ints(H), "x": x})

    def verify(self, exercise: Exercise) -> None:
        H = _smatrix(exercise.params["H"])
        check(H.det() != 0, "singular homography")
        image = H * sympy.Matrix(exercise.params["x"])
        check(Point(*image) == Point(*exercise.parts[0].answer.value), "wrong image point")


class ApplyLineTemplate(Template):
    """Apply a homography to a line: l' = H^{-T} l (proportional to adj(H)^T l).

    Level 1: an affine map; level 2: a projective map; level 3: larger entries.
    """

    name = "apply-line"
    title = "A homography applied to a line"
    max_entry = 10_000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        H, l = exercise.params["H"], exercise.params["l"]
        # the answer is a line: "ideal point given as finite" does not apply to it
        generic = [m for m in super().mistakes(exercise, index) if m.code != "ideal-as-finite"]
        wrong = [mistake("line-as-point", Answer.projective(matvec(H, l)), "Hl: H applied to the line as to a "
                         "point; lines map by H⁻ᵀl"),
                 mistake("transposed", Answer.projective(matvec(adjugate(H), l)), "H⁻¹l: the transpose of "
                         "H⁻ᵀ is missing"),
                 mistake("inverted", Answer.projective(matvec(transpose(H), l)), "Hᵀl: the inverse of H⁻ᵀ "
                         "is missing")]
        return [*generic, *wrong]

    def build(self, rng: random.Random, level: int) -> Draft:
        H = _homography(rng, level)
        l = list(primitive_dir(rng, 3, 3))
        adjT = transpose(adjugate(H))
        image = matvec(adjT, l)
        answer = primitive_integers(image)
        statement = (f"The homography $H = {matrix_latex(H)}$ maps points by $\\mathbf{{x}}' = H\\mathbf{{x}}$. "
                     f"Let $\\mathbf{{l}} = {tuple_latex(l)}$ be a line.")
        prompt = "Give the image line $\\mathbf{l}'$ (homogeneous coordinates)."
        steps = ["Lines map by $\\mathbf{l}' = H^{-\\top}\\mathbf{l}$, and up to scale $H^{-\\top} \\sim "
                 "\\operatorname{adj}(H)^\\top$ (no division needed).",
                 f"$\\operatorname{{adj}}(H)^\\top = {matrix_latex(adjT)}$, $\\det H = {det(H)}$.",
                 f"$\\operatorname{{adj}}(H)^\\top\\mathbf{{l}} = {tuple_latex(image)} \\sim {tuple_latex(answer)}$."]
        return Draft(statement, [(prompt, Answer.projective(answer), ())], steps, {"H": _ints(H), "l": l})

    def verify(self, exercise: Exercise) -> None:
        # independent route: two points of l are mapped by H and must lie on the answer
        H = _smatrix(exercise.params["H"])
        check(H.det() != 0, "singular homography")
        l = Line(*exercise.params["l"])
        answer = Line(*exercise.parts[0].answer.value)
        points = []
        for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
            try:
                p = sympy.Matrix(l.coords).cross(sympy.Matrix(e))
            except Exception:  # pragma: no cover - defensive
                continue
            if any(c != 0 for c in p) and all(not _proportional(p, q) for q in points):
                points.append(p)
        check(len(points) >= 2, "could not find two points on the line")
        for p in points[:2]:
            check(incident(Point(*(H * p)), answer), "an image point is not on the answer line")


class ApplyConicTemplate(Template):
    """Apply a homography to a conic: C' = H^{-T} C H^{-1} (proportional to adj(H)^T C adj(H)).

    Level 1: a circle and an affine map; level 2: a circle and a projective map; level 3: a general
    non-degenerate conic and a projective map.
    """

    name = "apply-conic"
    title = "A homography applied to a conic"
    max_entry = 100_000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        H, C = exercise.params["H"], exercise.params["C"]
        A = adjugate(H)
        generic = [m if m.code != "inverted" else mistake("dual", m.answer, "C'⁻¹: the dual conic (its tangent "
                                                            "lines), not the conic of points")
                   for m in super().mistakes(exercise, index)]
        wrong = [mistake("inverted", Answer.matrix(matmul(matmul(transpose(H), C), H)), "HᵀCH: the map taken in "
                         "the wrong direction (H instead of H⁻¹)"),
                 mistake("transposed", Answer.matrix(matmul(matmul(A, C), transpose(A))), "H⁻¹CH⁻ᵀ: the "
                         "transposes on the wrong side")]
        return [*wrong, *generic]

    def build(self, rng: random.Random, level: int) -> Draft:
        H = _homography(rng, min(level, 2))
        if level < 3:
            r = rng.randint(1, 3)
            C = [[Fraction(1), 0, 0], [0, Fraction(1), 0], [0, 0, Fraction(-r * r)]]
            what = f"the circle $x^2 + y^2 = {r * r}$, with matrix $C = {matrix_latex(C)}$"
        else:
            L = invertible(rng, 3, 1, 1)
            D = [[Fraction(nz(rng, 2)) if i == j else Fraction(0) for j in range(3)] for i in range(3)]
            C = matmul(matmul(transpose(L), D), L)
            what = f"the conic with matrix $C = {matrix_latex(C)}$ (non-degenerate: $\\det C = {det(C)}$)"
        A = adjugate(H)
        image = matmul(matmul(transpose(A), C), A)
        answer = primitive_integer_matrix(image)
        statement = (f"The homography $H = {matrix_latex(H)}$ maps points by $\\mathbf{{x}}' = H\\mathbf{{x}}$. "
                     f"Consider {what}.")
        prompt = "Give the matrix $C'$ of the image conic (any nonzero multiple is accepted)."
        steps = ["Points on $C$ satisfy $\\mathbf{x}^\\top C \\mathbf{x} = 0$; substituting $\\mathbf{x} = "
                 "H^{-1}\\mathbf{x}'$ gives $C' = H^{-\\top} C H^{-1} \\sim \\operatorname{adj}(H)^\\top C\\, "
                 "\\operatorname{adj}(H)$.",
                 f"$\\operatorname{{adj}}(H) = {matrix_latex(A)}$.",
                 f"$C' \\sim {matrix_latex(image)} \\sim {matrix_latex(answer)}$."]
        return Draft(statement, [(prompt, Answer.matrix(answer), ())], steps,
                     {"H": _ints(H), "C": _ints(C)})

    def verify(self, exercise: Exercise) -> None:
        H = _smatrix(exercise.params["H"])
        C = _smatrix(exercise.params["C"])
        check(H.det() != 0 and C.det() != 0, "singular homography or degenerate conic")
        Cp = _smatrix(exercise.parts[0].answer.value)
        Conic(Cp)  # symmetric 3x3
        # H^T C' H must be proportional to C (no adjugate on this route)
        check(_proportional(H.T * Cp * H, C), "H^T C' H is not proportional to C")


# --- the hierarchy ---------------------------------------------------------------------------------
CLASSES = ("isometry", "similarity", "affinity", "projectivity")
# the exercise's words for the classes of pgsym.hierarchy (an isometry may contain a reflection)
HIERARCHY = {"isometry": ISOMETRY_2D, "similarity": SIMILARITY_2D, "affinity": AFFINE_2D, "projectivity": PROJECTIVE_2D}
_WORD = {cls.key: word for word, cls in HIERARCHY.items()} | {EUCLIDEAN_2D.key: "isometry"}


@functools.cache
def dof(word: str) -> int:
    """The degrees of freedom of a class of the exercise, as :mod:`pgsym.hierarchy` derives them.

    >>> [dof(word) for word in CLASSES]
    [3, 4, 6, 8]
    """
    return HIERARCHY[word].dof().dof
TRIPLES = ((3, 4, 5), (5, 12, 13), (8, 15, 17), (4, 3, 5))


def _rotation(rng: random.Random, level: int) -> tuple[int, int, int]:
    if level == 1:
        a, b = rng.choice(((1, 0), (0, 1), (-1, 0), (0, -1)))
        return a, b, 1
    a, b, c = rng.choice(TRIPLES)
    return a * rng.choice((1, -1)), b * rng.choice((1, -1)), c


class ClassifyTemplate(Template):
    """Classify a plane transformation (isometry, similarity, affinity, projectivity) and give its DoF.

    Level 1: quarter-turn rotations; level 2: Pythagorean rotations; level 3: the matrix is also
    multiplied by a scale factor and may contain a reflection.
    """

    name = "classify"
    title = "Classify a transformation"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        if index == 1 and exercise.params["class"] == "projectivity":
            return [mistake("scale", Answer.integer(9), "9 entries counted; H is defined only up to scale, so a "
                            "projectivity has 8 degrees of freedom")]
        return super().mistakes(exercise, index)

    def build(self, rng: random.Random, level: int) -> Draft:
        cls = rng.choice(CLASSES)
        a, b, c = _rotation(rng, level)
        reflect = level == 3 and rng.random() < 0.5
        R = [[a, b], [b, -a]] if reflect else [[a, -b], [b, a]]
        t = [rng.randint(-4, 4), rng.randint(-4, 4)]
        if cls == "isometry":
            A, last = R, [0, 0, c]
            t = [c * t[0], c * t[1]]
        elif cls == "similarity":
            s = rng.randint(2, 3)
            A, last = [[s * x for x in row] for row in R], [0, 0, c]
        else:
            p, r, q = nz(rng, 3), nz(rng, 3), nz(rng, 2)
            K = [[p, q], [0, r]]
            A = [[int(x) for x in row] for row in matmul(R, K)]
            last = [0, 0, c]
            if cls == "projectivity":
                v = [0, 0]
                while v == [0, 0]:
                    v = [rng.randint(-2, 2), rng.randint(-2, 2)]
                last = [v[0], v[1], c]
        H = [[A[0][0], A[0][1], t[0]], [A[1][0], A[1][1], t[1]], last]
        while det(H) == 0:  # only possible for the projectivity: move the last entry
            H[2][2] += 1
        k = rng.choice((2, -1, 3)) if level == 3 else 1
        H = [[k * x for x in row] for row in H]
        choices = ("an isometry (Euclidean transformation)", "a similarity, but not an isometry",
                   "an affinity, but not a similarity", "a projectivity, but not an affinity")
        key = "ABCD"[CLASSES.index(cls)]
        statement = f"Consider the plane transformation with matrix $H = {matrix_latex(H)}$."
        parts = [("Which is the most specific class $H$ belongs to?", Answer.choice(key), choices),
                 ("How many degrees of freedom does that class of transformations have?", Answer.integer(dof(cls)),
                  ())]
        last_row = H[2]
        steps = [f"The last row is ${tuple_latex(last_row)}$: "
                 + ("not of the form $(0, 0, w)$, so $H$ is a projectivity and no affinity."
                    if cls == "projectivity" else "of the form $(0, 0, w)$, so $H$ is affine. Divide by "
                    f"$w = {last_row[2]}$ and look at the upper-left block $A$."),
                 ]
        if cls != "projectivity":
            Aw = [[Fraction(H[i][j], last_row[2]) for j in range(2)] for i in range(2)]
            AtA = matmul(transpose(Aw), Aw)
            steps.append(f"$A^\\top A = {matrix_latex(AtA)}$"
                         + (": not a multiple of the identity, so no similarity." if cls == "affinity" else
                            (": the identity, so $A$ is orthogonal: an isometry." if cls == "isometry" else
                             f": ${AtA[0][0]}\\,I$ with ${AtA[0][0]} \\neq 1$, so a similarity with scale "
                             f"$\\sqrt{{{AtA[0][0]}}}$.")))
        steps.append(f"The class has {dof(cls)} degrees of freedom.")
        return Draft(statement, parts, steps, {"H": H, "class": cls})

    def verify(self, exercise: Exercise) -> None:
        try:  # exact classification; a singular matrix is no transformation at all
            found = _WORD[classify(exercise.params["H"]).key]
        except SingularTransformationError:
            raise TemplateError("singular transformation") from None
        key = exercise.parts[0].answer.value
        check(key == "ABCD"[CLASSES.index(found)], f"key {key} but the matrix is an {found}")
        check(exercise.parts[1].answer.value == dof(found), "wrong DoF")


# quantity -> the most general class of plane transformations that preserves it
MOST_GENERAL = {
    "the length of a segment": "isometry",
    "the area of a triangle": "isometry",
    "the angle between two lines": "similarity",
    "the ratio of the lengths of two segments": "similarity",
    "the circular points $I, J$ (as a pair)": "similarity",
    "parallelism of lines": "affinity",
    "the ratio of the areas of two triangles": "affinity",
    "the ratio of lengths of two parallel segments": "affinity",
    "the line at infinity $\\mathbf{l}_\\infty$ (as a set)": "affinity",
    "the cross-ratio of four collinear points": "projectivity",
    "collinearity of three points": "projectivity",
    "incidence of a point and a line": "projectivity",
    "tangency of a line to a conic": "projectivity",
}


def _why(quantity: str, cls: str) -> str:
    general = MOST_GENERAL[quantity]
    if CLASSES.index(general) < CLASSES.index(cls):
        return f"changed by some {cls}"
    return f"preserved by every {general} too"


class PreservedTemplate(Template):
    """Which quantity a class of plane transformations preserves (and its more general class does not).

    Level 1: three options; level 2: four; level 3: five.
    """

    name = "preserved"
    title = "What a class of transformations preserves"
    max_entry = 10

    def build(self, rng: random.Random, level: int) -> Draft:
        cls = rng.choice(CLASSES)
        correct = rng.choice(sorted(q for q, c in MOST_GENERAL.items() if c == cls))
        wrong = rng.sample(sorted(q for q, c in MOST_GENERAL.items() if c != cls), level + 1)
        index = rng.randrange(level + 2)
        options = [*wrong[:index], correct, *wrong[index:]]
        parent = CLASSES[CLASSES.index(cls) + 1] if cls != "projectivity" else None
        question = f"Which of the following is preserved by every {cls} of the plane" + (
            f" but not by every {parent}?" if parent else "?")
        steps = [f"{correct[0].upper() + correct[1:]} is preserved by every {cls}"
                 + (f" but changed by some {parent}." if parent else "."),
                 "The other options: " + "; ".join(f"{q} ({_why(q, cls)})" for q in wrong) + "."]
        return Draft("Recall the hierarchy isometry ⊂ similarity ⊂ affinity ⊂ projectivity.",
                     [(question, Answer.choice("ABCDE"[index]), tuple(options))], steps,
                     {"class": cls, "options": options})

    def verify(self, exercise: Exercise) -> None:
        cls, options = exercise.params["class"], exercise.params["options"]
        key = "ABCDE".index(exercise.parts[0].answer.value)
        right = [i for i, q in enumerate(options) if MOST_GENERAL[q] == cls]
        check(right == [key], f"options {options} for {cls}: key {key}")


class FourPointsTemplate(Template):
    """The homography mapping four points in general position to four given points.

    Level 1: an affine map (integer images); level 2: a projective map, images in homogeneous
    coordinates; level 3: images as (possibly fractional) inhomogeneous coordinates.
    """

    name = "homography4"
    title = "A homography from four correspondences"
    max_entry = 10_000

    def build(self, rng: random.Random, level: int) -> Draft:
        while True:
            src = [[rng.randint(-2, 2), rng.randint(-2, 2), 1] for _ in range(4)]
            if all(det([src[i], src[j], src[k]]) != 0 for i, j, k in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))):
                break
        while True:
            H = _homography(rng, level)
            dst = [matvec(H, x) for x in src]
            if all(d[2] != 0 for d in dst):
                break
        answer = primitive_integer_matrix(H)
        if level == 3:
            shown = [tuple_latex((d[0] / d[2], d[1] / d[2])) for d in dst]
            dst_params = [[str(d[0] / d[2]), str(d[1] / d[2]), "1"] for d in dst]
        else:
            shown = [tuple_latex(primitive_integers(d)) for d in dst]
            dst_params = [[str(x) for x in primitive_integers(d)] for d in dst]
        pairs = ", ".join(f"${tuple_latex(s)} \\mapsto {t}$" for s, t in zip(src, shown, strict=True))
        statement = ("A homography $H$ of the plane maps four points (homogeneous coordinates; no three of "
                     f"them collinear) as follows: {pairs}.")
        prompt = "Give the matrix $H$ (any nonzero multiple is accepted)."
        # solution by the four-point basis method
        dsts = [[Fraction(x) for x in row] for row in dst_params]

        def basis(points: list) -> list[list[Fraction]]:
            M = transpose(points[:3])
            lam = matvec(adjugate(M), points[3])
            return [[M[i][j] * lam[j] for j in range(3)] for i in range(3)]

        B1, B2 = basis(src), basis(dsts)
        solved = matmul(B2, adjugate(B1))
        assert primitive_integer_matrix(solved) == answer
        steps = ["Map the standard frame $\\mathbf{e}_1, \\mathbf{e}_2, \\mathbf{e}_3, (1,1,1)^\\top$ to each "
                 "quadruple: if $M = [\\mathbf{x}_1\\ \\mathbf{x}_2\\ \\mathbf{x}_3]$ and $\\boldsymbol{\\lambda} = "
                 "\\operatorname{adj}(M)\\,\\mathbf{x}_4$, then $B = M \\operatorname{diag}(\\boldsymbol{\\lambda})$.",
                 f"Source: $B_1 = {matrix_latex(B1)}$; images: $B_2 = {matrix_latex(B2)}$.",
                 f"$H \\sim B_2 \\operatorname{{adj}}(B_1) = {matrix_latex(solved)} \\sim {matrix_latex(answer)}$."]
        return Draft(statement, [(prompt, Answer.matrix(answer), ())], steps, {"src": src, "dst": dst_params})

    def verify(self, exercise: Exercise) -> None:
        src = [Point(*p) for p in exercise.params["src"]]
        dst = [Point(*(Fraction(x) for x in p)) for p in exercise.params["dst"]]
        for pts in (src, dst):
            for i, j, k in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
                check(not collinear(pts[i], pts[j], pts[k]), "three collinear points")
        H = _smatrix(exercise.parts[0].answer.value)
        check(H.det() != 0, "singular answer")
        for s, d in zip(src, dst, strict=True):
            check(Point(*(H * s.vector)) == d, "a correspondence is not satisfied")


class DecomposeTemplate(Template):
    """Decompose H = H_S H_A H_P (similarity, affinity with K upper triangular, det K = 1, projective part).

    Level 1: quarter-turn rotations and K = [[1, m], [0, 1]]; level 2: Pythagorean rotations;
    level 3: also K = [[k, m], [0, 1/k]] with k = 2.
    """

    name = "decompose"
    title = "Decompose a homography"
    max_entry = 1000

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        generic = super().mistakes(exercise, index)
        if index == 0:
            s = exercise.parts[0].answer.value
            return [*generic, mistake("scale", Answer.scalar(s * s), "s² = det(sRK): the square root is missing")]
        if index == 1:  # Rᵀ = R⁻¹: one candidate, the rotation the other way
            return [mistake(m.code, m.answer, "Rᵀ = R⁻¹: the rotation in the other direction")
                    if m.code == "transposed" else m for m in generic]
        return generic

    def build(self, rng: random.Random, level: int) -> Draft:
        a, b, c = _rotation(rng, level)
        j = rng.randint(1, 2)
        s = c * j  # s R = j [[a, -b], [b, a]] is an integer matrix
        R = [[Fraction(a, c), Fraction(-b, c)], [Fraction(b, c), Fraction(a, c)]]
        k = Fraction(2) if level == 3 else Fraction(1)
        K = [[k, Fraction(nz(rng, 2))], [Fraction(0), 1 / k]]
        t = [Fraction(rng.randint(-3, 3)), Fraction(rng.randint(-3, 3))]
        v = [Fraction(rng.randint(-1, 1)), Fraction(nz(rng, 1))]
        w = Fraction(rng.choice((1, 2)))
        sRK = matmul([[s * x for x in row] for row in R], K)
        A = [[sRK[i][jj] + t[i] * v[jj] for jj in range(2)] for i in range(2)]
        H = [[A[0][0], A[0][1], w * t[0]], [A[1][0], A[1][1], w * t[1]], [v[0], v[1], w]]
        statement = (f"Let $H = {matrix_latex(H)}$ (exactly this matrix, not up to scale). Write "
                     "$H = H_S H_A H_P$ with $H_S = \\begin{bmatrix} sR & \\mathbf{t} \\\\ \\mathbf{0}^\\top & 1 "
                     "\\end{bmatrix}$ ($s > 0$, $R$ a rotation), $H_A = \\begin{bmatrix} K & \\mathbf{0} \\\\ "
                     "\\mathbf{0}^\\top & 1 \\end{bmatrix}$ ($K$ upper triangular, $\\det K = 1$, $K_{11} > 0$) and "
                     "$H_P = \\begin{bmatrix} I & \\mathbf{0} \\\\ \\mathbf{v}^\\top & v \\end{bmatrix}$.")
        parts = [("Give the scale $s$.", Answer.scalar(s), ()),
                 ("Give the rotation $R$.", Answer.matrix_exact(R), ()),
                 ("Give $K$.", Answer.matrix_exact(K), ())]
        steps = [f"The last row of $H$ is $(\\mathbf{{v}}^\\top, v) = {tuple_latex(H[2])}$, and the last column "
                 f"is $v\\,(\\mathbf{{t}}, 1)$, so $\\mathbf{{t}} = {tuple_latex(t)}$.",
                 f"$sRK = A - \\mathbf{{t}}\\mathbf{{v}}^\\top = {matrix_latex(sRK)}$.",
                 f"Its first column is $sK_{{11}}$ times the first column of $R$; with $\\det(sRK) = s^2 = {s * s}$ "
                 f"we get $s = {s}$, $K_{{11}} = {k}$, $R = {matrix_latex(R)}$.",
                 f"$K = (sR)^{{-1}}(sRK) = {matrix_latex(K)}$."]
        return Draft(statement, parts, steps, {"H": [[str(x) for x in row] for row in H]})

    def verify(self, exercise: Exercise) -> None:
        # the library's decomposition is unique (s > 0, K upper triangular with K11 > 0, det K = 1)
        d = decompose(_smatrix(exercise.params["H"]))
        s = sympy.Rational(str(exercise.parts[0].answer.value))
        R = _smatrix(exercise.parts[1].answer.value)
        K = _smatrix(exercise.parts[2].answer.value)
        check(d.s == s, f"the scale is {d.s}, not {s}")
        check(d.R == R and d.K == K, "R or K differs from the decomposition of H")
