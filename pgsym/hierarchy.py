"""The hierarchy of transformations of P² and P³: generic elements, derived degrees of freedom, classify.

Each class of the hierarchy is given by a *parametrisation*: a rational map from a
parameter space onto (a dense part of) the class. Rotations use rational
parametrisations, so that every element and every derivative is exact:

- in 2D, the rotation with Cayley parameter ``t = tan(θ/2)`` is
  ``c = (1 − t²)/(1 + t²)``, ``s = 2t/(1 + t²)``;
- in 3D, the rotation of the unit quaternion proportional to ``(1, a, b, c)`` (the
  Cayley transform of the skew matrix ``[(a, b, c)]×``).

A 2D similarity needs no rotation parameter: ``sR = [[a, −b], [b, a]]`` with ``a = s cos θ``,
``b = s sin θ`` (``a² + b² ≠ 0``) has polynomial entries, so proofs built on it carry no denominator.

The number of degrees of freedom of a class is the dimension of its image in the
projective space of matrices, ``P^(n²−1)``. It is the generic rank of the Jacobian of the
parametrisation augmented by the column ``vec H`` (the direction of the overall scale,
which the projective quotient forgets), minus one. :meth:`TransformationClass.dof`
establishes it exactly, without a symbolic rank computation:

- **lower bound** — the exact rank at one random rational point (forward-mode
  derivatives in exact fractions). The set where the rank is at least ``r`` is
  Zariski-open, so a rank found at one point is at most the generic rank;
- **upper bound** — the augmented Jacobian has ``m + 1`` columns for ``m`` parameters,
  so the rank is at most ``m + 1`` and the DoF at most ``m``. When the
  parametrisation is homogeneous of degree one (the projective classes, whose
  parameters are the matrix entries), Euler's identity ``vec H = J p`` puts the
  scale column inside the span of ``J``, so the DoF is at most ``m − 1``. This
  homogeneity is checked as an exact identity ``H(k p) = k H(p)``.

When the two bounds agree, the DoF is proved.

>>> SIMILARITY_2D.dof().dof, PROJECTIVE_3D.dof().dof
(4, 15)
>>> classify([[0, -1, 5], [1, 0, 2], [0, 0, 1]]).name
'Euclidean (proper isometry)'
"""

from __future__ import annotations

import math
import random
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from functools import cached_property
from typing import Any

import sympy
from sympy import ImmutableMatrix, Rational

from .errors import (
    DegenerateConfigurationError,
    DimensionError,
    InvalidCoordinatesError,
    NonFiniteError,
    ObjectTypeError,
)
from .exact import sign
from .homogeneous import is_zero, to_exact
from .transformations import Transformation

__all__ = [
    "AFFINE_2D",
    "AFFINE_3D",
    "CLASSES_2D",
    "CLASSES_3D",
    "EUCLIDEAN_2D",
    "EUCLIDEAN_3D",
    "ISOMETRY_2D",
    "ISOMETRY_3D",
    "PROJECTIVE_2D",
    "PROJECTIVE_3D",
    "SIMILARITY_2D",
    "SIMILARITY_3D",
    "DofDerivation",
    "TransformationClass",
    "cayley_parameter",
    "class_by_key",
    "classify",
    "dof_table",
    "rotation_2d",
    "rotation_3d",
]


# -- rational rotations -------------------------------------------------------------------------
def rotation_2d(t: Any) -> list[list[Any]]:
    """The 2×2 rotation with Cayley parameter ``t = tan(θ/2)``: ``c = (1−t²)/(1+t²)``, ``s = 2t/(1+t²)``.

    Works for numbers, SymPy expressions and exact fractions alike. For a float ``t`` the
    result is finite and right to rounding for every finite ``t`` (beyond ``|t| = 1`` it is
    computed from ``1/t``, so ``t²`` never overflows: ``t = 1e200`` is the half turn less
    ``2e-200`` rad); a NaN or infinite ``t`` raises :class:`~pgsym.errors.NonFiniteError`.

    >>> rotation_2d(Rational(1, 2))      # cos θ = 3/5, sin θ = 4/5
    [[3/5, -4/5], [4/5, 3/5]]
    >>> rotation_2d(1e200)
    [[-1.0, -2e-200], [2e-200, -1.0]]
    """
    if isinstance(t, float) or type(t).__module__ == "numpy":
        return _rotation_2d_float(float(t))
    d = 1 + t * t
    c, s = (1 - t * t) / d, 2 * t / d
    return [[c, -s], [s, c]]


def _rotation_2d_float(t: float) -> list[list[float]]:
    if not math.isfinite(t):
        raise NonFiniteError(f"rotation_2d: the Cayley parameter must be finite, got {t}; the half turn is t → ∞")
    if abs(t) <= 1:
        d = 1 + t * t
        c, s = (1 - t * t) / d, 2 * t / d
    else:  # divide numerator and denominator by t²: no overflow, and 1/t² → 0 gives the half turn
        u = 1 / t
        d = u * u + 1
        c, s = (u * u - 1) / d, 2 * u / d
    return [[c, -s], [s, c]]


def cayley_parameter(c: Any, s: Any) -> Any:
    """The parameter ``t = s / (1 + c)`` of the rotation with cosine ``c`` and sine ``s`` (``c ≠ −1``).

    Raises :class:`~pgsym.errors.DegenerateConfigurationError` for the half turn (``c = −1``), the one
    rotation the rational parametrisation reaches only as ``t → ∞``, and
    :class:`~pgsym.errors.InvalidCoordinatesError` unless ``c² + s² = 1``.

    >>> cayley_parameter(Rational(3, 5), Rational(4, 5))
    1/2
    """
    c, s = to_exact(c), to_exact(s)
    if not is_zero(c * c + s * s - 1):
        raise InvalidCoordinatesError(f"(c, s) = ({c}, {s}) is no rotation: c² + s² = {c * c + s * s}, not 1")
    if is_zero(c + 1):
        raise DegenerateConfigurationError(
            "the half turn (c = -1) has no finite Cayley parameter; compose two quarter turns (t = 1) instead"
        )
    return sympy.cancel(s / (1 + c))


def rotation_3d(a: Any, b: Any, c: Any) -> list[list[Any]]:
    """The 3×3 rotation of the quaternion ``(1, a, b, c)``: the Cayley transform of ``[(a, b, c)]×``.

    Its axis is ``(a, b, c)`` and its angle ``2 arctan |(a, b, c)|``; every entry is rational. For float
    arguments the result is finite and right to rounding for every finite ``(a, b, c)`` (the quaternion is
    scaled by its largest entry first, so no square overflows); a NaN or infinite one raises
    :class:`~pgsym.errors.NonFiniteError`, as :func:`rotation_2d` does.

    >>> rotation_3d(0, 0, 1)             # a quarter turn about the z-axis
    [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    >>> rotation_3d(0.0, 0.0, 1e200)[0]  # nearly the half turn about z
    [-1.0, -2e-200, 0.0]
    """
    if any(isinstance(x, float) or type(x).__module__ == "numpy" for x in (a, b, c)):
        return _rotation_3d_float(a, b, c)
    n = 1 + a * a + b * b + c * c
    rows = [
        [1 + a * a - b * b - c * c, 2 * (a * b - c), 2 * (a * c + b)],
        [2 * (a * b + c), 1 - a * a + b * b - c * c, 2 * (b * c - a)],
        [2 * (a * c - b), 2 * (b * c + a), 1 - a * a - b * b + c * c],
    ]
    if isinstance(n, int):
        n = Rational(n)
    return [[e / n for e in row] for row in rows]


def _rotation_3d_float(a: Any, b: Any, c: Any) -> list[list[float]]:
    a, b, c = float(a), float(b), float(c)
    bad = [(name, x) for name, x in zip("abc", (a, b, c), strict=True) if not math.isfinite(x)]
    if bad:
        name, x = bad[0]
        raise NonFiniteError(f"rotation_3d: the quaternion's entries must be finite, got {name} = {x}; "
                             "a half turn is the limit of (a, b, c) → ∞ along its axis")
    m = max(1.0, abs(a), abs(b), abs(c))
    w, a, b, c = 1 / m, a / m, b / m, c / m  # the same rotation: a quaternion is defined up to scale
    n = w * w + a * a + b * b + c * c
    rows = [
        [w * w + a * a - b * b - c * c, 2 * (a * b - w * c), 2 * (a * c + w * b)],
        [2 * (a * b + w * c), w * w - a * a + b * b - c * c, 2 * (b * c - w * a)],
        [2 * (a * c - w * b), 2 * (b * c + w * a), w * w - a * a - b * b + c * c],
    ]
    return [[e / n for e in row] for row in rows]


# -- parametrisations (builders) ------------------------------------------------------------------
def _homogeneous(linear: list[list[Any]], translation: Sequence[Any]) -> list[list[Any]]:
    n = len(linear)
    rows = [[*linear[i], translation[i]] for i in range(n)]
    rows.append([0] * n + [1])
    return rows


def _isometry2(p: Sequence[Any], component: int) -> list[list[Any]]:
    t, tx, ty = p
    (c, _), (s, _) = rotation_2d(t)
    e = -1 if component else 1
    return _homogeneous([[c, -e * s], [s, e * c]], [tx, ty])


def _similarity2(p: Sequence[Any], component: int) -> list[list[Any]]:
    # a = s cos θ, b = s sin θ: polynomial entries, unlike a scale times a rational rotation
    a, b, tx, ty = p
    e = -1 if component else 1
    return _homogeneous([[a, -e * b], [b, e * a]], [tx, ty])


def _affine2(p: Sequence[Any], component: int) -> list[list[Any]]:
    a11, a12, a21, a22, tx, ty = p
    return _homogeneous([[a11, a12], [a21, a22]], [tx, ty])


def _projective(n: int) -> Callable[[Sequence[Any], int], list[list[Any]]]:
    def build(p: Sequence[Any], component: int) -> list[list[Any]]:
        return [list(p[i * n : (i + 1) * n]) for i in range(n)]

    return build


def _rotation3(a: Any, b: Any, c: Any, component: int) -> list[list[Any]]:
    """R, or R diag(1, 1, −1) (R after the mirror z = 0) for the reflected component."""
    R = rotation_3d(a, b, c)
    return [[-e if (component and j == 2) else e for j, e in enumerate(row)] for row in R]


def _euclidean3(p: Sequence[Any], component: int) -> list[list[Any]]:
    a, b, c, tx, ty, tz = p
    return _homogeneous(_rotation3(a, b, c, component), [tx, ty, tz])


def _similarity3(p: Sequence[Any], component: int) -> list[list[Any]]:
    k, a, b, c, tx, ty, tz = p
    return _homogeneous([[k * e for e in row] for row in _rotation3(a, b, c, component)], [tx, ty, tz])


def _affine3(p: Sequence[Any], component: int) -> list[list[Any]]:
    return _homogeneous([list(p[0:3]), list(p[3:6]), list(p[6:9])], p[9:12])


# -- exact forward-mode derivatives ---------------------------------------------------------------
class _Dual:
    """``v + d ε`` with ``ε² = 0`` over exact fractions: one directional derivative, exactly."""

    __slots__ = ("d", "v")

    def __init__(self, v: Any, d: Any = 0) -> None:
        self.v, self.d = v, d

    @staticmethod
    def lift(x: Any) -> _Dual:
        return x if isinstance(x, _Dual) else _Dual(x, 0)

    def __add__(self, o: Any) -> _Dual:
        o = _Dual.lift(o)
        return _Dual(self.v + o.v, self.d + o.d)

    __radd__ = __add__

    def __neg__(self) -> _Dual:
        return _Dual(-self.v, -self.d)

    def __sub__(self, o: Any) -> _Dual:
        return self + (-_Dual.lift(o))

    def __rsub__(self, o: Any) -> _Dual:
        return _Dual.lift(o) - self

    def __mul__(self, o: Any) -> _Dual:
        o = _Dual.lift(o)
        return _Dual(self.v * o.v, self.v * o.d + self.d * o.v)

    __rmul__ = __mul__

    def __truediv__(self, o: Any) -> _Dual:
        o = _Dual.lift(o)
        return _Dual(self.v / o.v, (self.d * o.v - self.v * o.d) / (o.v * o.v))

    def __rtruediv__(self, o: Any) -> _Dual:
        return _Dual.lift(o) / self


def _is_positive(value: sympy.Expr) -> bool:
    """True when a number is positive (decided exactly) or a symbolic expression is positive by assumptions."""
    if value.free_symbols:
        return value.is_positive is True
    return sign(value) > 0


def _rank(rows: list[list[Fraction]]) -> int:
    """The exact rank of a matrix of fractions (Gaussian elimination)."""
    m = [list(r) for r in rows]
    rank, ncols = 0, len(m[0]) if m else 0
    for col in range(ncols):
        pivot = next((i for i in range(rank, len(m)) if m[i][col] != 0), None)
        if pivot is None:
            continue
        m[rank], m[pivot] = m[pivot], m[rank]
        p = m[rank][col]
        for i in range(rank + 1, len(m)):
            f = m[i][col]
            if f:
                f /= p
                m[i] = [a - f * b for a, b in zip(m[i], m[rank], strict=True)]
        rank += 1
    return rank


@dataclass(frozen=True)
class DofDerivation:
    """The result of :meth:`TransformationClass.dof`: a proved number of degrees of freedom.

    ``lower`` is the rank (minus one) found at the rational ``point``; ``upper`` the bound from
    the number of parameters (minus one more when ``homogeneous``). ``dof`` is set only when
    they agree.
    """

    key: str
    dof: int
    lower: int
    upper: int
    n_parameters: int
    homogeneous: bool
    point: tuple[Fraction, ...]

    @property
    def proved(self) -> bool:
        """True when the lower and upper bounds agree."""
        return self.lower == self.upper

    def explanation(self) -> str:
        """One sentence that states both bounds."""
        up = (
            f"{self.n_parameters} parameters, homogeneous of degree 1 (Euler: vec H = J p), so DoF ≤ "
            f"{self.n_parameters} − 1 = {self.upper}"
            if self.homogeneous
            else f"{self.n_parameters} parameters, so DoF ≤ {self.upper}"
        )
        return f"rank [J | vec H] = {self.lower + 1} at a rational point, so DoF ≥ {self.lower}; {up}"


@dataclass(frozen=True, eq=False)
class TransformationClass:
    """One class of the hierarchy: its parametrisation, matrix form and place in the hierarchy.

    ``components`` names the connected pieces the parametrisation covers (e.g. proper
    isometries and isometries with a reflection); ``larger`` is the key of the next
    larger class.

    >>> SIMILARITY_2D.element(3, 4, 1, 1).matrix      # a = s cos θ, b = s sin θ: scale 5
    Matrix([
    [3, -4, 1],
    [4,  3, 1],
    [0,  0, 1]])
    """

    key: str
    name: str
    dim: int
    parameter_names: tuple[str, ...]
    builder: Callable[[Sequence[Any], int], list[list[Any]]]
    matrix_form: str
    larger: str | None
    components: tuple[str, ...] = ("",)
    homogeneous: bool = False

    @cached_property
    def parameters(self) -> tuple[sympy.Symbol, ...]:
        """The SymPy symbols of the parametrisation."""
        return tuple(sympy.symbols(" ".join(self.parameter_names), seq=True))

    @property
    def n_parameters(self) -> int:
        """The number of parameters."""
        return len(self.parameter_names)

    def generic(self, component: int = 0) -> ImmutableMatrix:
        """The symbolic generic element (``component`` 1 is the reflected piece where there is one).

        >>> EUCLIDEAN_2D.generic()[0, 0]
        (1 - t**2)/(t**2 + 1)
        """
        self._check_component(component)
        return ImmutableMatrix(self.builder(self.parameters, component))

    def _check_component(self, component: int) -> None:
        if component not in range(len(self.components)):
            raise DimensionError(
                f"the class {self.name} has {len(self.components)} component(s) {self.components}, "
                f"got component={component!r}"
            )

    def element(self, *values: Any, component: int = 0) -> Transformation:
        """The member with the given parameter values (in the order of ``parameter_names``).

        >>> EUCLIDEAN_2D.element(1, 0, 0).matrix      # t = 1: a quarter turn
        Matrix([
        [0, -1, 0],
        [1,  0, 0],
        [0,  0, 1]])
        """
        self._check_component(component)
        if len(values) == 1 and isinstance(values[0], (list, tuple)):
            values = tuple(values[0])
        if len(values) != self.n_parameters:
            raise DimensionError(
                f"{self.name} takes {self.n_parameters} parameters {self.parameter_names}, got {len(values)}"
            )
        exact = [to_exact(v) for v in values]
        return Transformation(self.builder(exact, component))

    def jacobian(self, component: int = 0) -> ImmutableMatrix:
        """The symbolic Jacobian of ``vec H`` (rows) with respect to the parameters (columns), for display."""
        vec = sympy.Matrix(list(self.generic(component)))
        return ImmutableMatrix(vec.jacobian(sympy.Matrix(self.parameters)).applyfunc(sympy.cancel))

    def jacobian_at(self, point: Sequence[Any], component: int = 0) -> list[list[Fraction]]:
        """The exact augmented Jacobian ``[J | vec H]`` at a rational point, by forward-mode derivatives.

        >>> [row[-1] for row in AFFINE_2D.jacobian_at([1, 2, 3, 4, 5, 6])][-1]     # vec H ends with h33 = 1
        Fraction(1, 1)
        """
        p = [Fraction(x) if not isinstance(x, Fraction) else x for x in point]
        columns = []
        for i in range(len(p)):
            dual = [_Dual(v, 1 if j == i else 0) for j, v in enumerate(p)]
            m = self.builder(dual, component)
            columns.append([_Dual.lift(e).d for row in m for e in row])
        vec = [Fraction(_Dual.lift(e).v) for row in self.builder(p, component) for e in row]
        return [[Fraction(c[r]) for c in columns] + [vec[r]] for r in range(len(vec))]

    def is_homogeneous(self) -> bool:
        """Exact check that ``H(k p) = k H(p)`` identically (Euler's identity then gives ``vec H = J p``)."""
        k = sympy.Symbol("k")
        scaled = self.builder([k * q for q in self.parameters], 0)
        plain = self.builder(self.parameters, 0)
        return all(is_zero(sympy.sympify(a) - k * b) for ra, rb in zip(scaled, plain, strict=True)
                   for a, b in zip(ra, rb, strict=True))

    def dof(self, seed: int = 0, tries: int = 5) -> DofDerivation:
        """Derive the degrees of freedom: exact rank at random rational points vs the parameter bound.

        >>> d = AFFINE_2D.dof()
        >>> d.dof, d.lower, d.upper, d.proved
        (6, 6, 6, True)
        """
        homogeneous = self.homogeneous and self.is_homogeneous()
        upper = self.n_parameters - (1 if homogeneous else 0)
        rng = random.Random(seed)
        best, best_point = -1, ()
        for _ in range(tries):
            point = tuple(Fraction(rng.randint(-9, 9), rng.randint(1, 9)) for _ in self.parameter_names)
            lower = min(_rank(self.jacobian_at(point, c)) for c in range(len(self.components))) - 1
            if lower > best:
                best, best_point = lower, point
            if best >= upper:
                break
        return DofDerivation(self.key, best if best == upper else -1, best, upper, self.n_parameters,
                             homogeneous, best_point)

    def contains(self, H: Any) -> bool:
        """True when the transformation (or matrix) belongs to this class, up to scale.

        >>> H = [[1, 2, 3], [4, 5, 6], [0, 0, 2]]
        >>> AFFINE_2D.contains(H), SIMILARITY_2D.contains(H)
        (True, False)
        """
        return _rank_of_key(classify(H).key) <= _rank_of_key(self.key)

    def __repr__(self) -> str:
        return f"<{self.name}, {self.dim}D, {self.n_parameters} parameters>"


EUCLIDEAN_2D = TransformationClass(
    "euclidean2", "Euclidean (proper isometry)", 2, ("t", "t_x", "t_y"), _isometry2,
    r"\begin{bmatrix} \cos\theta & -\sin\theta & t_x \\ \sin\theta & \cos\theta & t_y \\ 0 & 0 & 1\end{bmatrix}",
    "isometry2",
)
ISOMETRY_2D = TransformationClass(
    "isometry2", "Isometry", 2, ("t", "t_x", "t_y"), _isometry2,
    r"\begin{bmatrix} \epsilon\cos\theta & -\sin\theta & t_x \\ \epsilon\sin\theta & \cos\theta & t_y \\ "
    r"0 & 0 & 1\end{bmatrix}",
    "similarity2", ("proper", "reflection"),
)
SIMILARITY_2D = TransformationClass(
    "similarity2", "Similarity", 2, ("a", "b", "t_x", "t_y"), _similarity2,
    r"\begin{bmatrix} s\,r_{11} & s\,r_{12} & t_x \\ s\,r_{21} & s\,r_{22} & t_y \\ 0 & 0 & 1\end{bmatrix}",
    "affine2", ("proper", "reflection"),
)
AFFINE_2D = TransformationClass(
    "affine2", "Affine", 2, ("a_11", "a_12", "a_21", "a_22", "t_x", "t_y"), _affine2,
    r"\begin{bmatrix} a_{11} & a_{12} & t_x \\ a_{21} & a_{22} & t_y \\ 0 & 0 & 1\end{bmatrix}",
    "projective2",
)
PROJECTIVE_2D = TransformationClass(
    "projective2", "Projective", 2, tuple(f"h_{i}{j}" for i in range(1, 4) for j in range(1, 4)), _projective(3),
    r"\begin{bmatrix} h_{11} & h_{12} & h_{13} \\ h_{21} & h_{22} & h_{23} \\ h_{31} & h_{32} & h_{33}\end{bmatrix}",
    None, homogeneous=True,
)
EUCLIDEAN_3D = TransformationClass(
    "euclidean3", "Euclidean (rigid motion)", 3, ("a", "b", "c", "t_x", "t_y", "t_z"), _euclidean3,
    r"\begin{bmatrix} R & \mathbf{t} \\ \mathbf{0}^\top & 1\end{bmatrix}", "isometry3",
)
ISOMETRY_3D = TransformationClass(
    "isometry3", "Isometry", 3, ("a", "b", "c", "t_x", "t_y", "t_z"), _euclidean3,
    r"\begin{bmatrix} R & \mathbf{t} \\ \mathbf{0}^\top & 1\end{bmatrix},\ R^\top R = I",
    "similarity3", ("proper", "reflection"),
)
SIMILARITY_3D = TransformationClass(
    "similarity3", "Similarity", 3, ("k", "a", "b", "c", "t_x", "t_y", "t_z"), _similarity3,
    r"\begin{bmatrix} s R & \mathbf{t} \\ \mathbf{0}^\top & 1\end{bmatrix}", "affine3", ("proper", "reflection"),
)
AFFINE_3D = TransformationClass(
    "affine3", "Affine", 3, (*(f"a_{i}{j}" for i in range(1, 4) for j in range(1, 4)), "t_x", "t_y", "t_z"),
    _affine3, r"\begin{bmatrix} A & \mathbf{t} \\ \mathbf{0}^\top & 1\end{bmatrix}", "projective3",
)
PROJECTIVE_3D = TransformationClass(
    "projective3", "Projective", 3, tuple(f"h_{i}{j}" for i in range(1, 5) for j in range(1, 5)), _projective(4),
    r"\begin{bmatrix} A & \mathbf{t} \\ \mathbf{v}^\top & v\end{bmatrix}", None, homogeneous=True,
)

CLASSES_2D: tuple[TransformationClass, ...] = (EUCLIDEAN_2D, ISOMETRY_2D, SIMILARITY_2D, AFFINE_2D, PROJECTIVE_2D)
"""The 2D hierarchy, smallest class first."""
CLASSES_3D: tuple[TransformationClass, ...] = (EUCLIDEAN_3D, ISOMETRY_3D, SIMILARITY_3D, AFFINE_3D, PROJECTIVE_3D)
"""The 3D hierarchy, smallest class first."""

_ORDER = {c.key: i for i, c in enumerate(CLASSES_2D)} | {c.key: i for i, c in enumerate(CLASSES_3D)}


def _rank_of_key(key: str) -> int:
    return _ORDER[key]


def class_by_key(key: str) -> TransformationClass:
    """The class with the given key (``'euclidean2'``, ``'isometry2'``, …, ``'projective3'``).

    >>> class_by_key("affine3").name
    'Affine'
    """
    for c in CLASSES_2D + CLASSES_3D:
        if c.key == key:
            return c
    raise ObjectTypeError(f"no transformation class {key!r}; known: {[c.key for c in CLASSES_2D + CLASSES_3D]}")


def dof_table(seed: int = 0) -> list[dict[str, Any]]:
    """The derived DoF of the eight classes of the issue (isometry, similarity, affine, projective; 2D and 3D).

    >>> [row["dof"] for row in dof_table()]
    [3, 4, 6, 8, 6, 7, 12, 15]
    """
    rows = []
    for c in (ISOMETRY_2D, SIMILARITY_2D, AFFINE_2D, PROJECTIVE_2D,
              EUCLIDEAN_3D, SIMILARITY_3D, AFFINE_3D, PROJECTIVE_3D):
        d = c.dof(seed)
        rows.append({"class": c.name, "dim": c.dim, "dof": d.dof, "parameters": c.n_parameters,
                     "proof": d.explanation()})
    return rows


# -- classify -------------------------------------------------------------------------------------
def _is_float_input(H: Any) -> bool:
    # NumPy values exist only once NumPy is loaded: asking sys.modules keeps exact classification NumPy-free
    np = sys.modules.get("numpy")
    if np is not None and isinstance(H, np.ndarray):
        return H.dtype.kind in "fc"
    try:
        return any(isinstance(e, float) or type(e).__module__ == "numpy" for row in H for e in row)
    except TypeError:
        return False


def classify(H: Any, tol: float | None = None) -> TransformationClass:
    """The smallest class of the hierarchy that contains ``H`` (a Transformation or a matrix).

    Exact matrices are classified exactly (symbolic entries: a property must hold
    identically). Float matrices (NumPy arrays or lists of floats), or any matrix when
    ``tol`` is given, are classified numerically with relative tolerance ``tol``
    (default ``1e-9``). Membership is up to scale: ``2H`` is in the class of ``H``.

    >>> classify([[2, 0, 0], [0, 2, 0], [0, 0, 1]]).name
    'Similarity'
    >>> classify([[1.0, 1e-12, 0.0], [0.0, 1.0, 3.0], [0.0, 0.0, 1.0]]).name
    'Euclidean (proper isometry)'
    >>> classify([[1, 0, 0], [0, -1, 0], [0, 0, 1]]).name    # a reflection
    'Isometry'
    >>> classify(sympy.diag(1, 1, -1, 1)).key, classify(sympy.diag(2, 2, -2, 1)).key   # in space too
    ('isometry3', 'similarity3')
    """
    if tol is not None or _is_float_input(H):
        return _classify_numeric(H, tol)
    T = H if isinstance(H, Transformation) else Transformation(H)
    M, n = T.matrix, T.matrix.rows
    classes = CLASSES_2D if n == 3 else CLASSES_3D
    if not all(is_zero(M[n - 1, j]) for j in range(n - 1)):
        return classes[-1]
    A = M[: n - 1, : n - 1] / M[n - 1, n - 1]
    G = (A.T * A).applyfunc(sympy.cancel)
    off = all(is_zero(G[i, j]) for i in range(n - 1) for j in range(n - 1) if i != j)
    if not (off and all(is_zero(G[i, i] - G[0, 0]) for i in range(n - 1))):
        return classes[-2]
    proper = _is_positive(sympy.cancel(A.det()))
    if n == 3:
        if not is_zero(G[0, 0] - 1):
            return SIMILARITY_2D
        return EUCLIDEAN_2D if proper else ISOMETRY_2D
    if not is_zero(G[0, 0] - 1):
        return SIMILARITY_3D
    return EUCLIDEAN_3D if proper else ISOMETRY_3D


def _classify_numeric(H: Any, tol: float | None) -> TransformationClass:
    """Float classification by :func:`pgsym.numeric.classify.classify_matrix` (default ``tol``: ``CLASS_RTOL``).

    NumPy is loaded here, on the first float input, not with this module.
    """
    from .numeric.classify import classify_matrix  # noqa: PLC0415 — core → numeric by design: classify hands floats to the numeric classifier

    return class_by_key(classify_matrix(H.matrix if isinstance(H, Transformation) else H, tol))


