"""Projective transformations of P¹, P² and P³: exact non-singular matrices and their action on every object.

A projective transformation (collineation, homography) of P² is given by a
non-singular 3×3 matrix ``H``, of P³ by a non-singular 4×4 matrix (and of P¹ by a 2×2 one), all defined up
to a nonzero scale. Points map by ``x' = H x``. Every other object follows from the
requirement that incidence is preserved: lines and planes map by ``H⁻ᵀ``, conics
and quadrics by ``H⁻ᵀ C H⁻¹``, dual conics by ``H C* Hᵀ`` and Plücker matrices by
``H L Hᵀ``. Since all of these objects are themselves defined up to scale, pgsym
uses the adjugate ``adj(H) = det(H) H⁻¹`` in place of the inverse: no division
happens, and symbolic matrices stay polynomial.

>>> from pgsym.projective_plane import Point, Line, join
>>> H = Transformation([[1, 2, 0], [0, 1, 0], [0, 0, 1]])     # a shear
>>> p, q = Point(0, 0), Point(1, 1)
>>> H(p), H(q)
(Point(0, 0, 1), Point(3, 1, 1))
>>> H(join(p, q)) == join(H(p), H(q))                        # lines map by H^-T
True
"""

from __future__ import annotations

import numbers
import warnings
from itertools import combinations
from typing import Any, ClassVar

import sympy
from sympy import Expr, ImmutableMatrix, Matrix

from .errors import (
    CollinearPointsError,
    DimensionError,
    InputLimitError,
    ObjectTypeError,
    SingularTransformationError,
)
from .exact import latex
from .homogeneous import _format_entry, is_zero
from .kinds import Kind, object_classes
from .limits import MAX_EXPONENT
from .matrices import adjugate, exact_matrix, expanded, proportional
from .projective_plane import Point, collinear
from .ring import Action

__all__ = [
    "MAX_POWER",
    "Transformation",
    "adjugate",
    "as_exact_matrix",
    "homography_from_points",
]

MAX_POWER = 4096
"""The largest ``|n|`` that ``H ** n`` accepts for a numeric matrix: the entries grow about n-fold in
digits, so a larger power is a request for a number too long to write (symbolic matrices: ``MAX_EXPONENT``)."""


def as_exact_matrix(matrix: Any, what: str = "a transformation matrix") -> ImmutableMatrix:
    """A square exact ``ImmutableMatrix`` from nested sequences, a SymPy or NumPy matrix or a Transformation.

    The square case of :func:`pgsym.matrices.exact_matrix` (the one coercion); floats are read as
    the decimals they print as.

    >>> as_exact_matrix([[1, 0.5], [0, 2]])
    Matrix([
    [1, 1/2],
    [0,   2]])
    """
    return exact_matrix(matrix, square=True, what=what)


_SPACES = {1: "P¹", 2: "P²", 3: "P³"}


class Transformation(Kind, kind="transformation"):
    """A projective transformation of P¹ (2×2 matrix), P² (3×3) or P³ (4×4), defined up to scale.

    The matrix is exact and must be non-singular; ``det H = 0`` raises
    :class:`~pgsym.errors.SingularTransformationError`. Apply it by calling it
    (``H(x)``) or with ``@`` (``H @ x``); ``H @ G`` is the composition "first
    ``G``, then ``H``". ``==`` compares up to a nonzero scale. Each object class knows
    how it transforms (its ``image`` rule, in any ring); the transformation only supplies the
    products with ``H``, its adjugate and their transposes.

    >>> H = Transformation([[2, 0, 1], [0, 2, 0], [0, 0, 1]])
    >>> H @ Point(1, 1)
    Point(3, 2, 1)
    >>> H.inverse() @ H == Transformation.identity(2)
    True
    >>> Transformation([[1, 2, 3], [2, 4, 6], [0, 0, 1]])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.SingularTransformationError: ...
    """

    __slots__ = ("_adj", "_det", "_matrix")
    # the shape a subclass insists on (None: 2×2, 3×3 or 4×4), and how its errors name the matrix
    _shape: ClassVar[tuple[int, int] | None] = None
    _what: ClassVar[str] = "a transformation matrix"
    _default_dim: ClassVar[int] = 2

    def __init__(self, matrix: Any) -> None:
        m = exact_matrix(matrix, shape=self._shape, square=True, what=self._what)
        if m.shape[0] - 1 not in _SPACES:
            raise DimensionError(
                "a projective transformation of P¹ is a 2×2 matrix, of P² a 3×3 matrix and of P³ a 4×4 matrix, "
                f"got shape {m.shape}"
            )
        det = sympy.expand(m.det(method="bareiss"))
        if is_zero(det):
            raise SingularTransformationError(
                f"the matrix {m.tolist()} is singular (determinant 0), so it "
                + ("maps P¹ onto a single point and is no projective map; use an invertible 2×2 matrix"
                   if m.shape[0] == 2 else
                   "is no projective transformation: it collapses the plane (or space) onto a line or point; "
                   "use a matrix of full rank")
            )
        self._matrix = m
        self._det = det
        self._adj: ImmutableMatrix | None = None

    # -- construction --------------------------------------------------------------------------
    @classmethod
    def identity(cls, dim: int | None = None) -> Transformation:
        """The identity of P^dim (``dim`` 1, 2 or 3; by default 2, and 1 for :class:`ProjectiveMap1`).

        >>> Transformation.identity(3).matrix.shape
        (4, 4)
        """
        dim = cls._default_dim if dim is None else dim
        if dim not in _SPACES:
            raise DimensionError(f"pgsym has transformations of P¹, P² and P³ only (dim 1, 2 or 3), got dim={dim!r}")
        return cls(sympy.eye(dim + 1))

    # -- access --------------------------------------------------------------------------------
    @property
    def matrix(self) -> ImmutableMatrix:
        """The exact matrix as given (one representative of the scale class)."""
        return self._matrix

    @property
    def dim(self) -> int:
        """1 for a transformation of P¹, 2 for P², 3 for P³."""
        return self._matrix.shape[0] - 1

    @property
    def det(self) -> Expr:
        """The determinant of the matrix (nonzero)."""
        return self._det

    @property
    def adjugate(self) -> ImmutableMatrix:
        """``adj(H) = det(H) H⁻¹``: the inverse up to the scale ``det H``, without division."""
        if self._adj is None:
            self._adj = adjugate(self._matrix)
        return self._adj

    @property
    def cofactor(self) -> ImmutableMatrix:
        """``adj(H)ᵀ = det(H) H⁻ᵀ``: the matrix that maps lines (in P²) and planes (in P³).

        >>> Transformation([[1, 0, 5], [0, 1, 0], [0, 0, 1]]).cofactor     # a translation by (5, 0)
        Matrix([
        [ 1, 0, 0],
        [ 0, 1, 0],
        [-5, 0, 1]])
        """
        return ImmutableMatrix(self.adjugate.T)

    def free_symbols(self) -> set[sympy.Symbol]:
        """The symbols the matrix depends on."""
        return set(self._matrix.free_symbols)

    def subs(self, *args: Any, **kwargs: Any) -> Transformation:
        """Substitute values for symbols (raises if the result is singular).

        >>> t = sympy.Symbol("t")
        >>> Transformation([[1, t, 0], [0, 1, 0], [0, 0, 1]]).subs(t, 3).matrix[0, 1]
        3
        """
        return type(self)(self._matrix.subs(*args, **kwargs))

    # -- group structure -----------------------------------------------------------------------
    def inverse(self) -> Transformation:
        """The inverse transformation, represented by the adjugate (equal to ``H⁻¹`` up to scale).

        >>> Transformation([[2, 0, 0], [0, 1, 0], [0, 0, 1]]).inverse().matrix
        Matrix([
        [1, 0, 0],
        [0, 2, 0],
        [0, 0, 2]])
        """
        return type(self)(self.adjugate)

    def compose(self, other: Transformation) -> Transformation:
        """``self ∘ other``: first ``other``, then ``self`` (matrix product ``H G``).

        >>> T = Transformation([[1, 0, 1], [0, 1, 0], [0, 0, 1]])
        >>> T.compose(T).matrix[0, 2]
        2
        """
        if not isinstance(other, Transformation):
            raise ObjectTypeError(f"compose expects a Transformation, got {type(other).__name__} {other!r}")
        if other.dim != self.dim:
            raise DimensionError(f"cannot compose a transformation of P^{self.dim} with one of P^{other.dim}")
        return type(self)(expanded(self._matrix * other._matrix))

    def __pow__(self, n: int) -> Transformation:
        """``H ** n``: the n-fold composition; ``H ** 0`` the identity, ``H ** -n`` the inverse's power.

        Computed by repeated squaring (the inverse by the adjugate). ``n`` must be an integer
        (a float or fraction raises :class:`~pgsym.errors.ObjectTypeError`); ``|n|`` is at most
        :data:`MAX_POWER` (:data:`pgsym.limits.MAX_EXPONENT` for symbolic matrices), else
        :class:`~pgsym.errors.InputLimitError`.

        >>> R = Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])       # a quarter turn
        >>> R ** 4 == Transformation.identity(), R ** -1 == R ** 3, (R ** 2).matrix[0, 0]
        (True, True, -1)
        """
        if isinstance(n, bool) or not isinstance(n, (numbers.Integral, sympy.Integer)):
            raise ObjectTypeError(f"a transformation is raised to integer powers only, got {type(n).__name__} {n!r}")
        n = int(n)
        limit = MAX_EXPONENT if self._matrix.free_symbols else MAX_POWER
        if abs(n) > limit:
            raise InputLimitError(f"H ** {n}: the power is limited to |n| ≤ {limit} (the entries grow with n)")
        base = Matrix(self.adjugate if n < 0 else self._matrix)
        result = Matrix.eye(self._matrix.rows)
        n = abs(n)
        while n:
            if n & 1:
                result = Matrix(expanded(result * base))
            n >>= 1
            if n:
                base = Matrix(expanded(base * base))
        return type(self)(result)

    def __matmul__(self, other: Any) -> Any:
        if isinstance(other, Transformation):
            return self.compose(other)
        return self.apply(other)

    def __call__(self, obj: Any) -> Any:
        return self.apply(obj)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Transformation):
            return NotImplemented
        return other.dim == self.dim and proportional(list(self._matrix), list(other._matrix))

    def __hash__(self) -> int:
        return hash(("Transformation", self.dim))

    def is_proportional_to(self, matrix: Any) -> bool:
        """True when ``matrix`` is a nonzero multiple of this transformation's matrix."""
        try:
            return self == Transformation(matrix)
        except SingularTransformationError:
            return False

    # -- action --------------------------------------------------------------------------------
    def apply(self, obj: Any) -> Any:
        """The image of a point, line, conic, dual conic, 3D point, plane, quadric, 3D line or point of P¹.

        Rules (``H`` the matrix, ``adj`` its adjugate, ``∝`` equality up to scale):
        points ``x' = H x``; lines and planes ``l' = adj(H)ᵀ l ∝ H⁻ᵀ l``; conics and quadrics
        ``C' = adj(H)ᵀ C adj(H) ∝ H⁻ᵀ C H⁻¹``; dual conics ``C*' = H C* Hᵀ``; lines of P³
        by their Plücker matrix ``L' = H L Hᵀ`` (equivalently ``L*' ∝ H⁻ᵀ L* H⁻¹``). Each class
        states its rule in its ``image`` classmethod and the space it lives in as ``ambient_dim``.

        >>> from pgsym.projective_plane import Line
        >>> H = Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])     # rotation by 90°
        >>> H.apply(Point(1, 0)), H.apply(Line(1, 0, -1))             # the line x = 1 becomes y = 1
        (Point(0, 1, 1), Line(0, 1, -1))
        """
        if isinstance(obj, (numbers.Number, Expr)) or obj is None or isinstance(obj, str):
            raise ObjectTypeError(f"a transformation acts on geometric objects, got {type(obj).__name__} {obj!r}")
        dim = getattr(obj, "ambient_dim", None)
        name = type(obj).__name__
        if dim is None:
            acted = [c.__name__ for c in object_classes().values() if getattr(c, "ambient_dim", None) == self.dim]
            raise ObjectTypeError(
                f"a transformation of P^{self.dim} acts on {', '.join(acted)}; got {name} {obj!r}"
            )
        if dim != self.dim:
            n = dim + 1
            raise DimensionError(
                f"a transformation of P^{self.dim} cannot act on a {name}, which lives in P^{dim}; "
                f"use a {n}×{n} matrix"
            )
        return obj._transformed_by(self)

    @property
    def action(self) -> Action:
        """The matrix and its cofactor matrix as an :class:`~pgsym.ring.Action`: the products the objects' ``image``
        rules are written with.

        >>> Transformation([[1, 0, 5], [0, 1, 0], [0, 0, 1]]).action.point((0, 0, 1))
        (5, 0, 1)
        """
        return Action(self._matrix.tolist(), self.cofactor.tolist())

    def map_vector(self, coords: Any, covariant: bool = False) -> tuple[Expr, ...]:
        """Deprecated: ``H x`` (``covariant``: ``adj(H)ᵀ l``) of bare coordinates. Transform the object itself
        (``H(Point(...))``, ``H(Line(...))``), or use :attr:`action` (``H.action.point``, ``.hyperplane``)."""
        warnings.warn("Transformation.map_vector is deprecated: transform the object (H(obj)) or use "
                      "H.action.point / H.action.hyperplane", DeprecationWarning, stacklevel=2)
        act = self.action
        return tuple(expanded(Matrix(act.hyperplane(coords) if covariant else act.point(coords))))

    def map_form(self, m: Any, covariant: bool = False) -> ImmutableMatrix:
        """Deprecated: ``H M Hᵀ`` (``covariant``: ``adj(H)ᵀ M adj(H)``) of a bare matrix. Transform the object
        itself (``H(DualQuadric(M))``, ``H(Conic(M))``), or use :attr:`action` (``.hyperplane_form``,
        ``.point_form``)."""
        warnings.warn("Transformation.map_form is deprecated: transform the object (H(DualConic(M)), H(Quadric(M)), "
                      "...) or use H.action.hyperplane_form / H.action.point_form", DeprecationWarning, stacklevel=2)
        rows = Matrix(m).tolist()
        act = self.action
        return ImmutableMatrix(expanded(Matrix(act.point_form(rows) if covariant else act.hyperplane_form(rows))))

    # -- rendering -----------------------------------------------------------------------------
    def __repr__(self) -> str:
        rows = ", ".join("[" + ", ".join(_format_entry(e) for e in self._matrix.row(i)) + "]"
                         for i in range(self._matrix.rows))
        return f"{type(self).__name__}([{rows}])"

    def latex(self) -> str:
        """LaTeX of the matrix (without math delimiters)."""
        return latex(self._matrix)

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"


def _basis_map(pts: list[Point], name: str) -> Matrix:
    """The matrix sending e1, e2, e3 and (1, 1, 1) to the four points (columns scaled by adj(P) p4)."""
    for (i, a), (j, b), (k, c) in combinations(enumerate(pts), 3):
        if collinear(a, b, c):
            raise CollinearPointsError(
                f"{name} points {i + 1}, {j + 1} and {k + 1} ({a!r}, {b!r}, {c!r}) are collinear; four "
                "correspondences determine a homography only when no three of the points lie on one line"
            )
    P = Matrix([list(p.coords) for p in pts[:3]]).T
    lam = adjugate(P) * Matrix(pts[3].coords)  # ∝ P⁻¹ p4
    return P * sympy.diag(*lam)


def homography_from_points(src: list[Point], dst: list[Point]) -> Transformation:
    """The unique homography with ``H src[i] ∝ dst[i]`` for four points in general position, exactly.

    Each quadruple is first mapped from the standard frame ``e1, e2, e3, (1, 1, 1)``; then
    ``H = B adj(A)``. No three of the four points (on either side) may be collinear, else
    :class:`~pgsym.errors.CollinearPointsError`.

    >>> H = homography_from_points([Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)],
    ...                            [Point(0, 0), Point(2, 0), Point(2, 2), Point(0, 2)])
    >>> H == Transformation([[2, 0, 0], [0, 2, 0], [0, 0, 1]])
    True
    """
    for pts in (src, dst):
        if len(pts) != 4 or not all(isinstance(p, Point) for p in pts):
            raise DimensionError(f"a homography of P² is fixed by exactly four Point correspondences, got {pts!r}")
    A, B = _basis_map(list(src), "source"), _basis_map(list(dst), "destination")
    return Transformation(expanded(B * adjugate(A)))
