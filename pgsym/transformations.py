"""Projective transformations of P² and P³: exact non-singular matrices and their action on every object.

A projective transformation (collineation, homography) of P² is given by a
non-singular 3×3 matrix ``H``, of P³ by a non-singular 4×4 matrix, both defined up
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
from itertools import combinations
from typing import Any

import sympy
from sympy import Expr, ImmutableMatrix, Matrix

from .errors import CollinearPointsError, DimensionError, ObjectTypeError, SingularTransformationError
from .exact import latex
from .homogeneous import _format_entry, is_zero, to_exact
from .kinds import Kind
from .projective_plane import Line, Point, collinear

__all__ = ["Transformation", "adjugate", "as_exact_matrix", "homography_from_points"]


def as_exact_matrix(matrix: Any, what: str = "transformation matrix") -> ImmutableMatrix:
    """Coerce a nested sequence, SymPy or NumPy matrix to a square exact ``ImmutableMatrix``.

    Floats are read as the decimals they print as (see :func:`~pgsym.homogeneous.to_exact`).

    >>> as_exact_matrix([[1, 0.5], [0, 2]])
    Matrix([
    [1, 1/2],
    [0,   2]])
    """
    if isinstance(matrix, Transformation):
        return matrix.matrix
    try:
        rows = matrix.tolist() if hasattr(matrix, "tolist") else [list(r) for r in matrix]
    except TypeError as err:
        raise DimensionError(f"a {what} must be a square matrix (a list of rows), got {matrix!r}") from err
    n = len(rows)
    if n == 0 or any(not hasattr(r, "__len__") or len(r) != n for r in rows):
        raise DimensionError(f"a {what} must be square (n rows of n entries), got {matrix!r}")
    return ImmutableMatrix([[to_exact(e) for e in r] for r in rows])


def adjugate(matrix: Any) -> ImmutableMatrix:
    """The adjugate ``adj(M)`` (transposed cofactor matrix), expanded: ``M adj(M) = det(M) I``.

    >>> adjugate([[2, 0], [0, 3]])
    Matrix([
    [3, 0],
    [0, 2]])
    """
    m = as_exact_matrix(matrix, "matrix")
    return ImmutableMatrix(m.adjugate(method="bareiss").applyfunc(sympy.expand))


def _expand(m: Matrix) -> ImmutableMatrix:
    return ImmutableMatrix(m.applyfunc(sympy.expand))


class Transformation(Kind, kind="transformation"):
    """A projective transformation of P² (3×3 matrix) or P³ (4×4 matrix), defined up to scale.

    The matrix is exact and must be non-singular; ``det H = 0`` raises
    :class:`~pgsym.errors.SingularTransformationError`. Apply it by calling it
    (``H(x)``) or with ``@`` (``H @ x``); ``H @ G`` is the composition "first
    ``G``, then ``H``". ``==`` compares up to a nonzero scale.

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

    def __init__(self, matrix: Any) -> None:
        m = as_exact_matrix(matrix)
        if m.shape not in ((3, 3), (4, 4)):
            raise DimensionError(
                f"a projective transformation of P² is a 3×3 matrix and of P³ a 4×4 matrix, got shape {m.shape}"
            )
        det = sympy.expand(m.det(method="bareiss"))
        if is_zero(det):
            raise SingularTransformationError(
                f"the matrix {m.tolist()} is singular (determinant 0), so it is no projective transformation: "
                "it collapses the plane (or space) onto a line or point; use a matrix of full rank"
            )
        self._matrix = m
        self._det = det
        self._adj: ImmutableMatrix | None = None

    # -- construction --------------------------------------------------------------------------
    @classmethod
    def identity(cls, dim: int = 2) -> Transformation:
        """The identity of P^dim (``dim`` 2 or 3).

        >>> Transformation.identity(3).matrix.shape
        (4, 4)
        """
        if dim not in (2, 3):
            raise DimensionError(f"pgsym has transformations of P² and P³ only (dim 2 or 3), got dim={dim!r}")
        return cls(sympy.eye(dim + 1))

    # -- access --------------------------------------------------------------------------------
    @property
    def matrix(self) -> ImmutableMatrix:
        """The exact matrix as given (one representative of the scale class)."""
        return self._matrix

    @property
    def dim(self) -> int:
        """2 for a transformation of P², 3 for P³."""
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
        return Transformation(self._matrix.subs(*args, **kwargs))

    # -- group structure -----------------------------------------------------------------------
    def inverse(self) -> Transformation:
        """The inverse transformation, represented by the adjugate (equal to ``H⁻¹`` up to scale).

        >>> Transformation([[2, 0, 0], [0, 1, 0], [0, 0, 1]]).inverse().matrix
        Matrix([
        [1, 0, 0],
        [0, 2, 0],
        [0, 0, 2]])
        """
        return Transformation(self.adjugate)

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
        return Transformation(_expand(self._matrix * other._matrix))

    def __matmul__(self, other: Any) -> Any:
        if isinstance(other, Transformation):
            return self.compose(other)
        return self.apply(other)

    def __call__(self, obj: Any) -> Any:
        return self.apply(obj)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Transformation):
            return NotImplemented
        if other.dim != self.dim:
            return False
        a, b = list(self._matrix), list(other._matrix)
        k = next(i for i, e in enumerate(a) if not is_zero(e))
        return all(is_zero(a[k] * b[i] - a[i] * b[k]) for i in range(len(a)))

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
        """The image of a point, line, conic, dual conic, 3D point, plane, quadric or 3D line.

        Rules (``H`` the matrix, ``adj`` its adjugate, ``∝`` equality up to scale):
        points ``x' = H x``; lines and planes ``l' = adj(H)ᵀ l ∝ H⁻ᵀ l``; conics and quadrics
        ``C' = adj(H)ᵀ C adj(H) ∝ H⁻ᵀ C H⁻¹``; dual conics ``C*' = H C* Hᵀ``; lines of P³
        by their Plücker matrix ``L' = H L Hᵀ`` (equivalently ``L*' ∝ H⁻ᵀ L* H⁻¹``).

        >>> H = Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])     # rotation by 90°
        >>> H.apply(Point(1, 0)), H.apply(Line(1, 0, -1))             # the line x = 1 becomes y = 1
        (Point(0, 1, 1), Line(0, 1, -1))
        """
        if isinstance(obj, (numbers.Number, Expr)) or obj is None or isinstance(obj, str):
            raise ObjectTypeError(f"a transformation acts on geometric objects, got {type(obj).__name__} {obj!r}")
        name = type(obj).__name__
        rule = _RULES.get((self.dim, name))
        if rule is None:
            other = [k[1] for k in _RULES if k[0] == self.dim]
            wrong_dim = any(k[1] == name for k in _RULES)
            if wrong_dim:
                raise DimensionError(
                    f"a transformation of P^{self.dim} cannot act on a {name}, which lives in the other space; "
                    f"use a {'4×4' if self.dim == 2 else '3×3'} matrix"
                )
            raise ObjectTypeError(
                f"a transformation of P^{self.dim} acts on {', '.join(other)}; got {name} {obj!r}"
            )
        return rule(self, obj)

    def _vector(self, coords: tuple[Expr, ...]) -> tuple[Expr, ...]:
        return tuple(_expand(self._matrix * Matrix(coords)))

    def _covector(self, coords: tuple[Expr, ...]) -> tuple[Expr, ...]:
        return tuple(_expand(self.cofactor * Matrix(coords)))

    def _congruence_dual(self, m: Any) -> ImmutableMatrix:
        # C' = adj(H)^T C adj(H)  ∝  H^-T C H^-1
        return _expand(self.cofactor * Matrix(m) * self.adjugate)

    def _congruence(self, m: Any) -> ImmutableMatrix:
        # C*' = H C* H^T
        return _expand(self._matrix * Matrix(m) * self._matrix.T)

    # -- rendering -----------------------------------------------------------------------------
    def __repr__(self) -> str:
        rows = ", ".join("[" + ", ".join(_format_entry(e) for e in self._matrix.row(i)) + "]"
                         for i in range(self._matrix.rows))
        return f"Transformation([{rows}])"

    def latex(self) -> str:
        """LaTeX of the matrix (without math delimiters)."""
        return latex(self._matrix)

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"


def _point2(H: Transformation, x: Point) -> Point:
    return Point._from_exact(H._vector(x.coords))


def _line2(H: Transformation, l: Line) -> Line:
    return Line._from_exact(H._covector(l.coords))


def _conic(H: Transformation, c: Any) -> Any:
    return type(c)._from_exact(H._congruence_dual(c.matrix))


def _dual_conic(H: Transformation, c: Any) -> Any:
    return type(c)._from_exact(H._congruence(c.matrix))


def _point3(H: Transformation, X: Any) -> Any:
    return type(X)._from_exact(H._vector(X.coords))


def _plane(H: Transformation, p: Any) -> Any:
    return type(p)._from_exact(H._covector(p.coords))


def _quadric(H: Transformation, q: Any) -> Any:
    return type(q)(H._congruence_dual(q.matrix))


def _line3(H: Transformation, L: Any) -> Any:
    return type(L).from_matrix(H._congruence(L.matrix))


_RULES = {
    (2, "Point"): _point2,
    (2, "Line"): _line2,
    (2, "Conic"): _conic,
    (2, "DualConic"): _dual_conic,
    (3, "Point3"): _point3,
    (3, "Plane"): _plane,
    (3, "Quadric"): _quadric,
    (3, "Line3"): _line3,
}


def _basis_map(pts: list[Point], name: str) -> Matrix:
    """The matrix sending e1, e2, e3 and (1, 1, 1) to the four points (columns scaled by adj(P) p4)."""
    for (i, a), (j, b), (k, c) in combinations(enumerate(pts), 3):
        if collinear(a, b, c):
            raise CollinearPointsError(
                f"{name} points {i + 1}, {j + 1} and {k + 1} ({a!r}, {b!r}, {c!r}) are collinear; four "
                "correspondences determine a homography only when no three of the points lie on one line"
            )
    P = Matrix([list(p.coords) for p in pts[:3]]).T
    lam = (P.adjugate() * Matrix(pts[3].coords)).applyfunc(sympy.expand)  # ∝ P⁻¹ p4
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
    return Transformation(_expand(B * A.adjugate()))
