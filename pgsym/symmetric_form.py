"""Symmetric matrices up to scale: what conics, dual conics and quadrics share.

A conic (``xᵀ C x = 0``, 3×3), a dual conic (``lᵀ C* l = 0``, 3×3) and a quadric
(``Xᵀ Q X = 0``, 4×4) are each a nonzero symmetric matrix defined up to a nonzero scale.
:class:`SymmetricForm` holds the checks, equality up to scale, hashing, the canonical form,
substitution, rank and determinant, rendering and the action of a transformation
(``C' ∝ H⁻ᵀ C H⁻¹`` for the covariant forms, conics and quadrics; ``C*' = H C* Hᵀ`` for
dual conics); the subclasses add only their geometry.

>>> from pgsym.conics import Conic
>>> from pgsym.quadrics import Quadric
>>> Conic([[2, 0, 0], [0, 2, 0], [0, 0, -2]]) == Conic.circle(0, 0, 1)
True
>>> Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]).rank
3
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from typing import Any, ClassVar, TypeVar

import sympy
from sympy import Expr, ImmutableMatrix, Integer, Matrix, Rational

from .errors import DegenerateConicError, InvalidCoordinatesError, UndecidableError, ZeroVectorError
from .exact import all_zero, canonical_coords, format_entry, is_zero, latex, sign
from .kinds import Kind
from .matrices import exact_matrix, proportional, rank
from .ring import Action

__all__ = ["DualForm", "SymmetricForm", "roots_on_line"]

_F = TypeVar("_F", bound="SymmetricForm")


def _conjugate_normalised(u: Sequence[Expr], v: Sequence[Expr], disc: Expr) -> tuple[Expr, ...]:
    """The vector ``u + v √disc`` (rational u, v, disc not a rational square), scaled so that its last
    nonzero coordinate is 1: dividing by ``u_k + v_k √disc`` is multiplying by its conjugate over the
    nonzero rational ``u_k² − v_k² disc``."""
    root = sympy.sqrt(disc)
    k = max(i for i in range(len(u)) if u[i] != 0 or v[i] != 0)
    norm = u[k] ** 2 - v[k] ** 2 * disc
    return tuple(sympy.expand((u[i] * u[k] - v[i] * v[k] * disc + (v[i] * u[k] - u[i] * v[k]) * root) / norm)
                 for i in range(len(u)))


def roots_on_line(a: Expr, b: Expr, c: Expr, p: Sequence[Expr], q: Sequence[Expr]) -> tuple[tuple[Expr, ...], ...]:
    """The zeros ``s p + t q`` of the binary form ``a s² + 2b st + c t²`` (not identically zero), exactly.

    Two coordinate tuples when the discriminant ``b² − ac`` is nonzero (irrational or complex
    coordinates when it is not a rational square), one (the double zero) when it vanishes. The
    common kernel of conic ∩ line, quadric ∩ line and the splitting of a plane or line pair.

    >>> roots_on_line(1, 0, -2, (1, 0), (0, 1))          # s² − 2t² = 0: s/t = ±√2
    ((sqrt(2), 1), (-sqrt(2), 1))
    >>> roots_on_line(1, -1, 1, (1, 0), (0, 1))          # (s − t)²: the double zero s = t
    ((1, 1),)
    """
    a, b, c = (sympy.sympify(e) for e in (a, b, c))
    p, q = tuple(sympy.sympify(e) for e in p), tuple(sympy.sympify(e) for e in q)
    if is_zero(a):
        if is_zero(b):  # c t² = 0: the double zero t = 0
            return (tuple(p),)
        pairs = [(Integer(1), Integer(0)), (c, -2 * b)]
        return tuple(tuple(sympy.expand(s * pi + t * qi) for pi, qi in zip(p, q, strict=True)) for s, t in pairs)
    disc = sympy.expand(b**2 - a * c)
    u = [sympy.expand(-b * pi + a * qi) for pi, qi in zip(p, q, strict=True)]
    if is_zero(disc):
        return (tuple(u),)
    # the zeros (-b ± √disc) p + a q, i.e. coordinates u_i ± v_i √disc
    v = list(p)
    root = sympy.sqrt(disc)
    if not root.is_Rational and all(e.is_Rational for e in (*u, *v, disc)):
        return tuple(_conjugate_normalised(u, [sg * vi for vi in v], disc) for sg in (1, -1))
    return tuple(tuple(sympy.expand(ui + sg * root * vi) for ui, vi in zip(u, v, strict=True)) for sg in (1, -1))


class SymmetricForm(Kind):
    """A nonzero symmetric ``size``×``size`` matrix up to a nonzero scale (base of Conic, DualConic, Quadric).

    Subclasses set ``size`` (3 or 4), ``ambient_dim`` (the n of Pⁿ) and ``_kind`` (the name used in
    errors); a form on lines or planes (a dual form) overrides :meth:`image`.
    """

    __slots__ = ("_matrix",)
    size: ClassVar[int] = 3
    ambient_dim: ClassVar[int | None] = None
    _kind: ClassVar[str] = "symmetric form"

    def __init__(self, matrix: Any) -> None:
        self._matrix = self._check(matrix)

    @classmethod
    def _check(cls, matrix: Any) -> ImmutableMatrix:
        n = cls.size
        m = exact_matrix(matrix, shape=(n, n), what=f"the symmetric matrix of a {cls._kind}")
        for i in range(n):
            for j in range(i + 1, n):
                if not is_zero(m[i, j] - m[j, i]):
                    raise InvalidCoordinatesError(
                        f"the matrix of a {cls._kind} must be symmetric, but entry ({i}, {j}) is {m[i, j]} and entry "
                        f"({j}, {i}) is {m[j, i]}: got {m.tolist()}; use the symmetric part (M + M.T)/2, which "
                        "describes the same quadratic form"
                    )
        if all_zero(m):
            raise ZeroVectorError(
                f"the zero matrix is not a {cls._kind}: every element would satisfy 0 = 0; at least one entry "
                "must be nonzero"
            )
        return m

    @classmethod
    def _from_exact(cls: type[_F], m: Any) -> _F:
        obj = cls.__new__(cls)
        obj._matrix = cls._check(m)
        return obj

    # -- access -----------------------------------------------------------------------------------
    @property
    def matrix(self) -> ImmutableMatrix:
        """The symmetric matrix (one representative of the scale class, as stored)."""
        return self._matrix

    @property
    def determinant(self) -> Expr:
        """The determinant of the stored representative (its sign and size depend on the scale)."""
        return sympy.expand(Matrix(self._matrix).det(method="bareiss"))

    @property
    def is_degenerate(self) -> bool:
        """True when the matrix is singular (cones, line or plane pairs, double lines or planes)."""
        return is_zero(self.determinant)

    @property
    def rank(self) -> int:
        """The exact rank (``size`` when non-degenerate; the generic rank for symbolic entries)."""
        if not self.is_degenerate:
            return self.size
        return rank(self._matrix)

    def signature(self) -> tuple[int, int]:
        """The numbers ``(p, n)`` of positive and negative eigenvalues, ordered so that ``p ≥ n`` (scale-free).

        Decided exactly for real numeric entries (algebraic numbers included): the eigenvalues of
        a real symmetric matrix are real, so Descartes' rule of signs on the characteristic
        polynomial counts them exactly. Symbolic or non-real entries raise
        :class:`~pgsym.errors.UndecidableError`.

        >>> from pgsym.quadrics import Quadric
        >>> Quadric.sphere((0, 0, 0), 1).signature(), Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0],
        ...                                                     [0, 0, 0, -1]]).signature()
        ((3, 1), (2, 2))
        """
        coeffs = Matrix(self._matrix).charpoly().all_coeffs()
        try:
            signs = [sign(sympy.expand(c)) for c in coeffs]
        except UndecidableError as err:
            raise UndecidableError(f"the signature of {self!r} needs real numeric entries: {err}") from err

        def changes(seq: list[int]) -> int:
            nz = [x for x in seq if x != 0]
            return sum(1 for x, y in itertools.pairwise(nz) if x != y)

        deg = len(signs) - 1
        positive = changes(signs)
        negative = changes([sg * (-1) ** (deg - i) for i, sg in enumerate(signs)])
        return (max(positive, negative), min(positive, negative))

    def _split(self) -> tuple[tuple[Expr, ...], tuple[Expr, ...]]:
        """The two linear factors of a form of rank ≤ 2, ``xᵀ M x = (aᵀx)(bᵀx)`` up to scale (a = b for rank 1).

        A symmetric matrix of rank r has a non-singular r×r principal block ``B`` (rows and columns
        ``S``); then ``M = U B⁻¹ Uᵀ`` with ``U`` the columns ``S`` of ``M``, so the form is the binary
        form ``adj(B)`` in ``y = Uᵀ x``, which factors over ``ℚ(√disc)``.
        """
        m, n = self._matrix, self.size
        r = self.rank
        if r > 2:
            raise DegenerateConicError(
                f"{self!r} has rank {r}: only a form of rank 2 (two hyperplanes) or 1 (a double one) splits into "
                "linear factors"
            )
        if r == 1:
            i = next(k for k in range(n) if not is_zero(m[k, k]))
            col = tuple(m[:, i])
            return col, col
        i, j = next((i, j) for i in range(n) for j in range(i + 1, n)
                    if not is_zero(m[i, i] * m[j, j] - m[i, j] ** 2))
        u, v = tuple(m[:, i]), tuple(m[:, j])
        # the binary form adj(B) = [[m_jj, -m_ij], [-m_ij, m_ii]] in (s, t) = (uᵀx, vᵀx); its zeros (s, t) = (α, β)
        # give the factor β uᵀx − α vᵀx, i.e. the hyperplane β u − α v; the zeros are those of the form's dual
        zeros = roots_on_line(m[j, j], -m[i, j], m[i, i], (Integer(1), Integer(0)), (Integer(0), Integer(1)))
        planes = [tuple(sympy.expand(beta * ui - alpha * vi) for ui, vi in zip(u, v, strict=True))
                  for alpha, beta in zeros]
        return planes[0], planes[-1]

    def _form(self, u: Sequence[Expr], v: Sequence[Expr]) -> Expr:
        """The bilinear form ``uᵀ M v``, expanded."""
        n, m = self.size, self._matrix
        return sympy.expand(sum((u[i] * m[i, j] * v[j] for i in range(n) for j in range(n)), Integer(0)))

    def _image(self, x: Sequence[Expr]) -> tuple[Expr, ...]:
        """``M x``, expanded: the polar of a point (the pole of a line for a dual form)."""
        return tuple(sympy.expand(e) for e in self._matrix * Matrix(list(x)))

    # -- equality up to scale ------------------------------------------------------------------------
    def __eq__(self, other: object) -> bool:
        if type(self) is not type(other):
            return NotImplemented
        assert isinstance(other, SymmetricForm)
        return proportional(list(self._matrix), list(other._matrix))

    def __hash__(self) -> int:
        entries = list(self._matrix)
        if all(v.is_Rational for v in entries):
            pivot = next(v for v in entries if v != 0)
            return hash((type(self).__name__, tuple(v / pivot for v in entries)))
        return hash((type(self).__name__, self.size))

    def coefficients_of_form(self) -> tuple[Expr, ...]:
        """The coefficients of the quadratic form, monomials ``x_i x_j`` (i ≤ j) ordered by j, then i.

        For a conic these are ``(a, b, c, d, e, f)`` of ``a x² + b xy + c y² + d x + e y + f``.

        >>> from pgsym.conics import Conic
        >>> Conic([[1, 2, 3], [2, 4, 5], [3, 5, 6]]).coefficients_of_form()
        (1, 4, 4, 6, 10, 6)
        """
        m = self._matrix
        return tuple(m[i, j] if i == j else 2 * m[i, j] for j in range(self.size) for i in range(j + 1))

    @classmethod
    def _matrix_of_form(cls, coefficients: Sequence[Expr]) -> ImmutableMatrix:
        """The symmetric matrix of the coefficients in the order of :meth:`coefficients_of_form`."""
        n, it = cls.size, iter(coefficients)
        m = sympy.zeros(n, n)
        for j in range(n):
            for i in range(j + 1):
                c = next(it)
                m[i, j] = m[j, i] = c if i == j else c * Rational(1, 2)
        return ImmutableMatrix(m)

    def canonical(self: _F) -> _F:
        """The representative whose quadratic form has coprime integer (or polynomial) coefficients.

        The coefficients of :meth:`coefficients_of_form` are put in the canonical form of
        :func:`pgsym.exact.canonical_coords` (for rationals: primitive integers, first nonzero positive).

        >>> from pgsym.conics import Conic
        >>> Conic([[2, 1, 0], [1, 4, 0], [0, 0, -6]]).canonical()
        Conic.from_coefficients(1, 1, 2, 0, 0, -3)
        >>> Conic([[-1, 0, 0], [0, -1, 0], [0, 0, Rational(1, 2)]]).canonical()
        Conic.from_coefficients(2, 0, 2, 0, 0, -1)
        """
        return type(self)._from_exact(self._matrix_of_form(canonical_coords(self.coefficients_of_form())))

    def subs(self: _F, *args: Any, **kwargs: Any) -> _F:
        """Substitute values for symbols, as :meth:`sympy.Expr.subs` does."""
        return type(self)._from_exact(ImmutableMatrix(self._matrix.subs(*args, **kwargs)))

    # -- action of a transformation ------------------------------------------------------------------
    @classmethod
    def image(cls, matrix: Sequence[Sequence[Any]], H: Action) -> tuple[tuple[Any, ...], ...]:
        """The matrix of the image under the matrix action ``H``, in any ring: a form on points (a conic, a quadric)
        maps by ``adj(H)ᵀ M adj(H) ∝ H⁻ᵀ M H⁻¹``.

        >>> from pgsym import Conic
        >>> Conic.image([[1, 0, 0], [0, 1, 0], [0, 0, -1]], Action([[2, 0, 0], [0, 2, 0], [0, 0, 1]]))[2]
        (0, 0, -16)
        """
        return H.point_form(matrix)

    def _transformed_by(self: _F, H: Any) -> _F:
        """The image under the transformation ``H`` (checked by ``H.apply``), by the class's :meth:`image` rule."""
        rows = type(self).image(self._matrix.tolist(), H.action)
        return type(self)._from_exact(ImmutableMatrix([[sympy.expand(e) for e in row] for row in rows]))

    # -- rendering -----------------------------------------------------------------------------------
    def __repr__(self) -> str:
        rows = ", ".join("[" + ", ".join(format_entry(e) for e in row) + "]" for row in self._matrix.tolist())
        return f"{type(self).__name__}([{rows}])"

    def latex(self) -> str:
        """LaTeX of the matrix (without math delimiters)."""
        return latex(Matrix(self._matrix), mat_delim="[")

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"


class DualForm:
    """Mixin of the forms on lines or planes (dual conics, dual quadrics): they map by ``H M Hᵀ``."""

    __slots__ = ()

    @classmethod
    def image(cls, matrix: Sequence[Sequence[Any]], H: Action) -> tuple[tuple[Any, ...], ...]:
        """``H M Hᵀ``: the tangent lines (planes) ``l`` of the form, ``lᵀ M l = 0``, map by ``H⁻ᵀ``.

        >>> from pgsym import DualConic
        >>> DualConic.image([[1, 0, 0], [0, 1, 0], [0, 0, 0]], Action([[2, 0, 0], [0, 2, 0], [0, 0, 1]]))[0]
        (4, 0, 0)
        """
        return H.hyperplane_form(matrix)
