"""Fixed points, lines and planes of a projective transformation: its eigenvectors, exactly.

A point ``x`` is fixed by ``H`` when ``H x = λ x`` for some ``λ``: the fixed points are the
eigenvectors of ``H``. A line (in P²) or plane (in P³) is fixed when ``H⁻ᵀ l ∝ l``, i.e.
``Hᵀ l = λ l``: the eigenvectors of ``Hᵀ``, with the same eigenvalues. Each eigenvalue
gives a projective subspace of fixed elements: one point, or a whole line of fixed points
when the eigenspace has dimension 2 (then for lines: a pencil, every line through a point).

**Exactness.** The characteristic polynomial is factored over the field of the entries
(ℚ, or ℚ(√3), ℚ(i), …). A linear or quadratic factor gives rational or quadratic-surd
eigenvalues (complex ones included: a rotation fixes the circular points I and J); a
factor of degree 3 or 4 gives its roots as radicals (Cardano, Ferrari). An eigenvalue that
is a simple root gets its eigenvector as a column of ``adj(H − λI)`` computed modulo the
factor, so no row reduction ever divides by an unsimplified radical. When SymPy cannot
write a root in radicals, :class:`~pgsym.errors.UndecidableError` is raised; symbolic
matrices raise it too (the eigenvalues would be generic).

>>> from pgsym.transformations import Transformation
>>> R = Transformation([[3, -4, 0], [4, 3, 0], [0, 0, 5]])          # rotation by θ, cos θ = 3/5
>>> [(f.eigenvalue, f.basis) for f in fixed_points(R)]
[(5, (Point(0, 0, 1),)), (3 - 4*I, (Point(1, I, 0),)), (3 + 4*I, (Point(1, -I, 0),))]
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy
from sympy import Expr, Matrix

from .errors import DimensionError, UndecidableError
from .linalg import nullspace_exact
from .projective_line import Point1
from .projective_plane import Line, Point
from .space import Plane, Point3
from .transformations import Transformation

__all__ = ["FixedSpace", "fixed_lines", "fixed_planes", "fixed_points"]

_WHAT = {
    ("point", 1): "a fixed point",
    ("point", 2): "a line of fixed points",
    ("point", 3): "a plane of fixed points",
    ("line", 1): "a fixed line",
    ("line", 2): "a pencil of fixed lines (every line through one point)",
    ("plane", 1): "a fixed plane",
    ("plane", 2): "a pencil of fixed planes (every plane through one line)",
    ("plane", 3): "a bundle of fixed planes (every plane through one point)",
}


@dataclass(frozen=True)
class FixedSpace:
    """The fixed elements belonging to one eigenvalue.

    ``eigenvalue`` is exact (a rational, a surd, a complex or a radical number) and belongs to the
    matrix as given (scaling ``H`` scales it); ``multiplicity`` is its multiplicity as a root of
    the characteristic polynomial; ``basis`` spans the eigenspace (one point, line or plane per
    dimension) and every combination of it is fixed too; ``element`` is ``"point"``,
    ``"line"`` or ``"plane"``.
    """

    eigenvalue: Expr
    multiplicity: int
    basis: tuple[Any, ...]
    element: str

    @property
    def dimension(self) -> int:
        """The dimension of the eigenspace (1: an isolated fixed element)."""
        return len(self.basis)

    @property
    def is_whole_space(self) -> bool:
        """True when every element is fixed (``H`` is the identity up to scale)."""
        return self.dimension == len(self.basis[0].coords)

    def describe(self) -> str:
        """A phrase for what the eigenspace is, e.g. ``'a line of fixed points'``.

        >>> fixed_points(Transformation([[2, 0, 0], [0, 2, 0], [0, 0, 1]]))[1].describe()
        'a line of fixed points'
        """
        if self.is_whole_space:
            return f"every {self.element} is fixed"
        return _WHAT.get((self.element, self.dimension),
                         f"a {self.dimension}-dimensional family of fixed {self.element}s")


def _roots(factor: sympy.Poly) -> list[Expr]:
    """The roots of an irreducible factor, exactly (radicals up to degree 4), each once."""
    d = factor.degree()
    if d == 1:
        a, b = factor.all_coeffs()
        return [sympy.expand(-b / a)]
    if d == 2:
        a, b, c = factor.all_coeffs()
        root = sympy.sqrt(sympy.expand(b * b - 4 * a * c))
        return [sympy.expand((-b - root) / (2 * a)), sympy.expand((-b + root) / (2 * a))]
    found = sympy.roots(factor.as_expr(), factor.gen, cubics=True, quartics=True)
    if sum(found.values()) != d:
        raise UndecidableError(
            f"the eigenvalues are the roots of {factor.as_expr()}, which SymPy cannot write in radicals; "
            "the fixed points cannot be given exactly"
        )
    return list(found)


def _eigenspaces(M: Matrix) -> list[tuple[Expr, int, list[tuple[Expr, ...]], bool]]:
    """(eigenvalue, multiplicity, eigenspace basis, whether the eigenvalue is at most a quadratic surd)."""
    if M.free_symbols:
        raise UndecidableError(
            "fixed points of a symbolic transformation depend on the roots of its characteristic polynomial, "
            "which are not rational functions of the symbols; substitute values first"
        )
    n = M.rows
    x = sympy.Dummy("x")
    charpoly = sympy.Poly((M - x * sympy.eye(n)).det(method="berkowitz"), x, extension=True)
    _, factors = charpoly.factor_list()
    adj = None
    out = []
    for factor, mult in factors:
        if factor.degree() == 0:
            continue
        roots = _roots(factor)
        if mult == 1:  # simple roots: one eigenvector each, a column of adj(M − x I) that is nonzero modulo the factor
            if adj is None:
                adj = (M - x * sympy.eye(n)).adjugate(method="berkowitz")
            column = None
            for j in range(n):
                reduced = [sympy.Poly(adj[i, j], x, domain=factor.domain).rem(factor) for i in range(n)]
                if not all(r.is_zero for r in reduced):
                    column = reduced
                    break
            assert column is not None  # a simple root makes adj(M − λI) of rank 1
            for lam in roots:
                out.append((lam, 1, [tuple(sympy.expand(r.as_expr().subs(x, lam)) for r in column)],
                            factor.degree() <= 2))
        else:
            for lam in roots:
                out.append((lam, mult, nullspace_exact(M - lam * sympy.eye(n)), True))
    return out


def _spaces(H: Transformation, transpose: bool, element: str, cls: type) -> tuple[FixedSpace, ...]:
    M = Matrix(H.matrix.T if transpose else H.matrix)
    spaces = []
    for lam, mult, basis, quadratic in _eigenspaces(M):
        if quadratic:
            elements = tuple(cls(*v).canonical() for v in basis)
        else:
            # Cardano/Ferrari radicals: deciding that such coordinates are not all zero (or normalising them)
            # costs minutes, and is not needed — each coordinate is a polynomial of degree < deg f in λ, not
            # all zero modulo the irreducible f, and such a polynomial cannot vanish at a root of f
            elements = tuple(_trusted(cls, v) for v in basis)
        spaces.append(FixedSpace(lam, mult, elements, element))
    return tuple(spaces)


def _trusted(cls: type, coords: tuple[Expr, ...]) -> Any:
    obj = cls.__new__(cls)
    obj._coords = tuple(coords)
    return obj


def _transformation(H: Any) -> Transformation:
    return H if isinstance(H, Transformation) else Transformation(H)


def fixed_points(H: Any) -> tuple[FixedSpace, ...]:
    """The fixed points of a transformation of P¹, P² or P³, one :class:`FixedSpace` per eigenvalue.

    Points of P¹ are :class:`~pgsym.projective_line.Point1`, of P² :class:`~pgsym.projective_plane.Point`,
    of P³ :class:`~pgsym.space.Point3`. A homology fixes a line of points and one more point:

    >>> [(f.eigenvalue, f.describe()) for f in fixed_points([[2, 0, 0], [0, 2, 0], [0, 0, 1]])]
    [(1, 'a fixed point'), (2, 'a line of fixed points')]
    """
    T = _transformation(H)
    return _spaces(T, False, "point", _point_class(T.dim))


def fixed_lines(H: Any) -> tuple[FixedSpace, ...]:
    """The fixed lines of a transformation of P² (eigenvectors of ``Hᵀ``: ``H⁻ᵀ l ∝ l``).

    A translation fixes every line of its direction (a pencil through the ideal point) and the line at infinity:

    >>> [(f.eigenvalue, f.basis) for f in fixed_lines([[1, 0, 3], [0, 1, 0], [0, 0, 1]])]
    [(1, (Line(0, 1, 0), Line(0, 0, 1)))]
    """
    T = _transformation(H)
    if T.dim != 2:
        raise DimensionError(f"fixed_lines is for transformations of P²; for P³ use fixed_planes (got P^{T.dim})")

    return _spaces(T, True, "line", Line)


def fixed_planes(H: Any) -> tuple[FixedSpace, ...]:
    """The fixed planes of a transformation of P³ (eigenvectors of ``Hᵀ``: ``H⁻ᵀ π ∝ π``).

    >>> [f.basis for f in fixed_planes([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]])]  # mirror z = 0
    [(Plane(0, 0, 1, 0),), (Plane(1, 0, 0, 0), Plane(0, 1, 0, 0), Plane(0, 0, 0, 1))]
    """
    T = _transformation(H)
    if T.dim != 3:
        raise DimensionError(f"fixed_planes is for transformations of P³; for P² use fixed_lines (got P^{T.dim})")

    return _spaces(T, True, "plane", Plane)


def _point_class(dim: int) -> type:
    if dim == 1:
        return Point1
    if dim == 2:
        return Point

    return Point3
