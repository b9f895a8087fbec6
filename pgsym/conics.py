"""Conics and dual conics of the projective plane, exactly.

A conic is the set of points with ``xᵀ C x = 0`` for a symmetric 3×3 matrix C,
defined up to a nonzero scale: 6 distinct entries minus the scale leaves 5
degrees of freedom, so five points in general position fix a conic. In
inhomogeneous coordinates ``xᵀ C x = 0`` is ``a x² + b xy + c y² + d x + e y + f = 0`` with

    C = [[a, b/2, d/2], [b/2, c, e/2], [d/2, e/2, f]].

The tangent line at a point x of the conic is ``l = C x``; for any point x the
line ``C x`` is its polar. The lines tangent to a non-degenerate conic C form the
dual conic ``C* = adj C``: ``l`` is tangent exactly when ``lᵀ C* l = 0``.

>>> from pgsym.conics import Conic
>>> from pgsym.projective_plane import Point
>>> unit = Conic.from_coefficients(1, 0, 1, 0, 0, -1)       # x² + y² - 1 = 0
>>> unit.contains(Point(0, 1)), unit.tangent_at(Point(0, 1))
(True, Line(0, 1, -1))
>>> unit.dual().contains_line(unit.tangent_at(Point(1, 0)))
True
"""

from __future__ import annotations

import itertools

import sympy
from sympy import Expr, I, Matrix

from .errors import (
    CoincidentPointsError,
    CollinearPointsError,
    DegenerateConfigurationError,
    DegenerateConicError,
    DimensionError,
    NotOnConicError,
    ObjectTypeError,
    UndecidableError,
)
from .exact import all_zero, latex
from .homogeneous import Scalar, _format_entry, is_zero, require, to_exact
from .matrices import adjugate
from .projective_plane import Line, Point, collinear, cross
from .symmetric_form import DualForm, SymmetricForm, roots_on_line

__all__ = [
    "Conic",
    "DualConic",
    "NotOnConicError",
    "circular_points",
    "conic_through",
    "dual_conic_at_infinity",
]


def _two_points_on(line: Line) -> tuple[Point, Point]:
    """Two distinct points of a line, chosen exactly among l × e1, l × e2, l × e3."""
    candidates = []
    for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
        coords = cross(line.coords, e)
        if not all_zero(coords):
            candidates.append(Point._from_exact(coords))
    p = candidates[0]
    q = next(c for c in candidates[1:] if not c == p)
    return p, q


def _exact_sqrt(value: Expr) -> Expr:
    """A square root of ``value``: ``sympy.sqrt``, or the polynomial root when ``value`` is a polynomial square.

    Either root serves where it is used (both signs give the same lines), so a symbolic square such
    as ``a²`` gives ``a`` without assuming a sign.
    """
    if value.free_symbols:
        coeff, factors = sympy.factor_list(value)
        if all(e % 2 == 0 for _, e in factors):
            return sympy.sqrt(coeff) * sympy.Mul(*(f ** (e // 2) for f, e in factors))
    return sympy.sqrt(value)


class Conic(SymmetricForm, kind="conic"):
    """A conic ``xᵀ C x = 0`` of the projective plane, from a symmetric 3×3 matrix C.

    Equality is up to a nonzero scale; ``repr`` is the :meth:`from_coefficients`
    call that rebuilds the conic. In Jupyter a conic renders as its matrix and its
    equation in inhomogeneous coordinates.

    >>> C = Conic([[1, 0, 0], [0, 1, 0], [0, 0, -4]])     # the circle x² + y² = 4
    >>> C
    Conic.from_coefficients(1, 0, 1, 0, 0, -4)
    >>> C == Conic.from_coefficients(-2, 0, -2, 0, 0, 8), C.contains(Point(2, 0))
    (True, True)
    """

    __slots__ = ()
    _kind = "conic"
    ambient_dim = 2

    @classmethod
    def from_coefficients(cls, a: Scalar, b: Scalar, c: Scalar, d: Scalar, e: Scalar, f: Scalar) -> Conic:
        """The conic ``a x² + b xy + c y² + d x + e y + f = 0``.

        >>> Conic.from_coefficients(0, 2, 0, 0, 0, -2).matrix.tolist()     # xy = 1
        [[0, 1, 0], [1, 0, 0], [0, 0, -2]]
        """
        return cls(cls._matrix_of_form([to_exact(v) for v in (a, b, c, d, e, f)]))

    @classmethod
    def circle(cls, cx: Scalar, cy: Scalar, r: Scalar) -> Conic:
        """The circle with centre ``(cx, cy)`` and radius ``r``: ``(x - cx)² + (y - cy)² = r²``.

        >>> Conic.circle(1, 2, 3)
        Conic.from_coefficients(1, 0, 1, -2, -4, -4)
        """
        cx, cy, r = (to_exact(v) for v in (cx, cy, r))
        return cls.from_coefficients(1, 0, 1, -2 * cx, -2 * cy, sympy.expand(cx**2 + cy**2 - r**2))

    @classmethod
    def from_lines(cls, l: Line, m: Line) -> Conic:
        """The line pair ``l mᵀ + m lᵀ``: the degenerate conic of the points on l or on m (``l = m``: a double line).

        ``xᵀ (l mᵀ + m lᵀ) x = 2 (lᵀx)(mᵀx)``, which vanishes exactly on the two lines.

        >>> Conic.from_lines(Line(1, 0, 0), Line(0, 1, 0))        # x y = 0
        Conic.from_coefficients(0, 2, 0, 0, 0, 0)
        >>> Conic.from_lines(Line(1, 0, -1), Line(1, 0, -1)).rank     # the double line x = 1
        1
        """
        require(l, Line, "Conic.from_lines")
        require(m, Line, "Conic.from_lines")
        u, v = l.coords, m.coords
        return cls._from_exact(Matrix(3, 3, lambda i, j: sympy.expand(u[i] * v[j] + v[i] * u[j])))

    @property
    def coefficients(self) -> tuple[Expr, Expr, Expr, Expr, Expr, Expr]:
        """``(a, b, c, d, e, f)`` of ``a x² + b xy + c y² + d x + e y + f = 0``.

        >>> Conic([[1, 2, 3], [2, 4, 5], [3, 5, 6]]).coefficients
        (1, 4, 4, 6, 10, 6)
        """
        return self.coefficients_of_form()  # type: ignore[return-value]

    def equation(self, x: Expr | None = None, y: Expr | None = None) -> Expr:
        """The left-hand side ``a x² + b xy + c y² + d x + e y + f`` as a polynomial in x and y.

        >>> Conic.circle(0, 0, 1).equation()
        x**2 + y**2 - 1
        """
        x = sympy.Symbol("x") if x is None else x
        y = sympy.Symbol("y") if y is None else y
        a, b, c, d, e, f = self.coefficients
        return sympy.expand(a * x**2 + b * x * y + c * y**2 + d * x + e * y + f)

    def __repr__(self) -> str:
        return f"Conic.from_coefficients({', '.join(_format_entry(c) for c in self.coefficients)})"

    def _repr_latex_(self) -> str:
        eq = latex(sympy.Eq(self.equation(), 0))
        return f"$C = {self.latex()}, \\quad {eq}$"

    def value(self, point: Point) -> Expr:
        """The quadratic form ``xᵀ C x`` at a point, expanded (zero exactly on the conic).

        >>> Conic.circle(0, 0, 1).value(Point(2, 0))
        3
        """
        require(point, Point, "Conic.value")
        return self._form(point.coords, point.coords)

    def contains(self, point: Point) -> bool:
        """True when the point lies on the conic: ``xᵀ C x = 0`` identically.

        >>> Conic.circle(0, 0, 5).contains(Point(3, 4)), Conic.circle(0, 0, 5).contains(Point(3, 3))
        (True, False)
        """
        return is_zero(self.value(point))

    def polar(self, point: Point) -> Line:
        """The polar line ``l = C x`` of any point x.

        For a point on the conic it is the tangent there; for a point outside a
        real conic it is the line through the two points of contact of the tangents
        from x. Raises :class:`DegenerateConicError` when ``C x = 0``, i.e. x is a
        singular point of a degenerate conic (the vertex of a line pair, or any
        point of a double line), where no polar exists.

        >>> Conic.circle(0, 0, 1).polar(Point(2, 0))     # the line x = 1/2
        Line(2, 0, -1)
        """
        require(point, Point, "Conic.polar")
        return Line._from_nonzero(self._image(point.coords), DegenerateConicError, lambda: (
            f"{point!r} is a singular point of the degenerate conic {self!r} (C x = 0), so it has no polar line"))

    def tangent_at(self, point: Point) -> Line:
        """The tangent line ``l = C x`` at a point x of the conic.

        Raises :class:`NotOnConicError` when x is not on the conic (use
        :meth:`polar` for any point) and :class:`DegenerateConicError` at a singular
        point of a degenerate conic.

        >>> Conic.from_coefficients(1, 0, 0, 0, -1, 0).tangent_at(Point(2, 4))   # y = x² at x = 2
        Line(2, S(-1)/2, -2)
        """
        require(point, Point, "Conic.tangent_at")
        if not self.contains(point):
            raise NotOnConicError(
                f"{point!r} is not on the conic {self!r} (xᵀ C x = {self.value(point)}), so it has no tangent "
                "there; use polar() for the polar line of an arbitrary point"
            )
        return self.polar(point)

    def pole(self, line: Line) -> Point:
        """The pole of a line: the point x with polar l, ``x = adj(C) l`` (C non-degenerate).

        >>> Conic.circle(0, 0, 1).pole(Line(2, 0, -1)) == Point(2, 0)
        True
        """
        require(line, Line, "Conic.pole")
        self._require_nondegenerate("the pole of a line")
        return Point._from_exact(tuple(sympy.expand(e) for e in adjugate(self._matrix) * line.vector))

    def _require_nondegenerate(self, what: str) -> None:
        if self.is_degenerate:
            raise DegenerateConicError(
                f"{what} needs a non-degenerate conic, but {self!r} is degenerate (rank {self.rank}): "
                + ("a pair of lines" if self.rank == 2 else "a double line")
            )

    def tangents_from(self, point: Point) -> tuple[Line, Line]:
        """The two tangent lines from a point to a non-degenerate conic, exact (possibly irrational or complex).

        They form the line pair ``T = (xᵀCx) C − (Cx)(Cx)ᵀ``: a point y is on T exactly when
        ``(xᵀCx)(yᵀCy) = (xᵀCy)²``, the condition that the line xy touches C (Joachimsthal), so
        :meth:`split` gives the two lines. For a point on the conic T is the tangent there, doubled;
        from a point inside a real conic the tangents are complex conjugate.

        >>> sorted(Conic.circle(0, 0, 1).tangents_from(Point(0, 2)), key=str)   # slopes ±√3
        [Line(1, -sqrt(3)/3, 2*sqrt(3)/3), Line(1, sqrt(3)/3, -2*sqrt(3)/3)]
        >>> Conic.circle(0, 0, 1).tangents_from(Point(1, 0))
        (Line(1, 0, -1), Line(1, 0, -1))
        """
        require(point, Point, "Conic.tangents_from")
        self._require_nondegenerate("the tangents from a point")
        x = Matrix(list(point.coords))
        cx = Matrix(self._matrix) * x
        T = (sympy.expand((x.T * cx)[0, 0]) * Matrix(self._matrix) - cx * cx.T).applyfunc(sympy.expand)
        return Conic._from_exact(T).split()

    def split(self) -> tuple[Line, Line]:
        """The two lines of a degenerate conic: ``(l, m)`` with ``C ∝ l mᵀ + m lᵀ`` (a double line: ``l = m``).

        Rank 2 (Richter-Gebert, *Perspectives*, 11.3): for ``C = l mᵀ + m lᵀ`` the adjugate is
        ``B = adj C = −p pᵀ`` with ``p = l × m`` the vertex, so ``p = B e_i / √(−B_ii)`` for any
        ``B_ii ≠ 0``; ``C ± [p]ₓ`` is then ``2 l mᵀ`` or ``2 m lᵀ`` (``l mᵀ − m lᵀ = −[l × m]ₓ``), a rank-1
        matrix whose nonzero row and column are the lines. ``−B_ii`` is a square exactly when the
        lines are real and rational; otherwise the lines have coordinates with ``√(−B_ii)``, complex
        conjugate when ``B_ii > 0`` (a point ellipse such as ``x² + y² = 0``). Rank 1: every nonzero
        row is the double line. The result is checked exactly (``l mᵀ + m lᵀ ∝ C``).

        Raises :class:`DegenerateConfigurationError` for a non-degenerate conic, which contains no line.

        >>> Conic.from_coefficients(1, 0, -1, 0, 0, 0).split()           # x² − y² = (x − y)(x + y)
        (Line(1, -1, 0), Line(1, 1, 0))
        >>> Conic.from_coefficients(1, 0, 1, 0, 0, 0).split()            # x² + y²: complex conjugate lines
        (Line(1, -I, 0), Line(1, I, 0))
        >>> Conic.from_coefficients(1, 0, -2, 0, 0, 0).split()           # x² − 2y²: irrational lines
        (Line(1, -sqrt(2), 0), Line(1, sqrt(2), 0))
        """
        if not self.is_degenerate:
            raise DegenerateConfigurationError(
                f"{self!r} is non-degenerate (rank 3): it contains no line, so it does not split into lines"
            )
        A = self._matrix
        if self.rank == 1:
            row = next(r for r in A.tolist() if not all_zero(r))
            line = Line._from_exact(tuple(row)).canonical()
            return line, line
        B = adjugate(A)
        i = next(k for k in range(3) if not is_zero(B[k, k]))
        beta = _exact_sqrt(sympy.expand(-B[i, i]))
        p = [sympy.radsimp(B[k, i] / beta) for k in range(3)]
        skew = Matrix([[0, -p[2], p[1]], [p[2], 0, -p[0]], [-p[1], p[0], 0]])
        M = (Matrix(A) + skew).applyfunc(lambda e: sympy.expand(sympy.radsimp(e)))
        j, k = next((j, k) for j in range(3) for k in range(3) if not is_zero(M[j, k]))
        l = Line._from_exact(tuple(M.row(j))).canonical()
        m = Line._from_exact(tuple(M.col(k))).canonical()
        if not Conic.from_lines(l, m) == self:  # pragma: no cover - the identity above; a guard, not a branch
            raise UndecidableError(f"splitting {self!r} into lines could not be verified exactly")
        return tuple(sorted((l, m), key=lambda x: sympy.default_sort_key(x.coords)))  # type: ignore[return-value]

    def dual(self) -> DualConic:
        """The dual conic ``C* = adj C`` of the lines tangent to C (C non-degenerate).

        For a non-degenerate C, ``adj C = det(C) C⁻¹`` and a line is tangent exactly
        when ``lᵀ C* l = 0``. A degenerate conic raises :class:`DegenerateConicError`:
        for a line pair adj C has rank 1 (it is the vertex counted twice, which every
        line through the vertex "touches"), and for a double line adj C = 0, so the
        tangent lines no longer form a conic.

        >>> Conic.circle(0, 0, 1).dual()
        DualConic([[-1, 0, 0], [0, -1, 0], [0, 0, 1]])
        """
        self._require_nondegenerate("the dual conic of tangent lines")
        return DualConic._from_exact(adjugate(self._matrix))

    def restricted_form(self, line: Line) -> tuple[Expr, Expr, Expr]:
        """The quadratic form on a line: ``(A, B, C')`` with ``Q(s p + t q) = A s² + 2B st + C' t²``.

        Here p and q are the two points of the line that :meth:`intersections` uses
        (chosen exactly among ``l × e1, l × e2, l × e3``). The line is tangent
        exactly when the discriminant ``B² - A C'`` vanishes.

        >>> Conic.circle(0, 0, 1).restricted_form(Line(0, 1, -1))    # the tangent y = 1
        (0, 0, 1)
        """
        require(line, Line, "Conic.restricted_form")
        p, q = _two_points_on(line)
        return self._form(p.coords, p.coords), self._form(p.coords, q.coords), self._form(q.coords, q.coords)

    def discriminant(self, line: Line) -> Expr:
        """``B² - A C'`` of :meth:`restricted_form`: zero when the line meets the conic in a double point.

        Its sign (for real lines) tells how many real points the line shares with
        the conic: positive two, zero one double point, negative none. It is
        ``-(lᵀ adj(C) l)`` times a nonzero square, so it vanishes exactly when l is
        on the dual conic.

        >>> Conic.circle(0, 0, 1).discriminant(Line(0, 1, 0)) > 0   # y = 0 cuts the unit circle twice
        True
        """
        a, b, c = self.restricted_form(line)
        return sympy.expand(b**2 - a * c)

    def is_tangent(self, line: Line) -> bool:
        """True when the line meets the conic in a double point (discriminant zero).

        For a degenerate conic this includes every line through a singular point,
        and a line contained in the conic (where every point is a double point).

        >>> C = Conic.circle(0, 0, 1)
        >>> C.is_tangent(Line(1, 0, -1)), C.is_tangent(Line(1, 0, 0))
        (True, False)
        """
        return is_zero(self.discriminant(line))

    def intersections(self, line: Line) -> tuple[Point, ...]:
        """The two points (exact, possibly irrational or complex) where a line meets the conic.

        A tangent line gives the same point twice. Raises :class:`DegenerateConicError`
        when the line is contained in a degenerate conic (every point is common). Two conics
        meet through their pencil: :func:`pgsym.conic_pencil.intersect_conics` (a module above this one).

        >>> C = Conic.circle(0, 0, 1)
        >>> sorted(p.dehomogenize() for p in C.intersections(Line(0, 1, 0)))
        [(-1, 0), (1, 0)]
        """
        if isinstance(line, Conic):
            raise ObjectTypeError("Conic.intersections takes a Line; two conics meet through their pencil: "
                                  "use pgsym.intersect_conics(C, D) (pgsym.conic_pencil)")
        require(line, Line, "Conic.intersections")
        p, q = _two_points_on(line)
        a, b, c = self.restricted_form(line)
        if is_zero(a) and is_zero(b) and is_zero(c):
            raise DegenerateConicError(f"the line {line!r} lies entirely on the degenerate conic {self!r}")
        # the zeros of the binary form a s² + 2b st + c t² on the line, by the kernel quadrics share
        zeros = [Point._from_exact(z) for z in roots_on_line(a, b, c, p.coords, q.coords)]
        return (zeros[0], zeros[-1])  # a tangent: its one (double) point twice


class DualConic(DualForm, SymmetricForm, kind="dual_conic"):
    """A dual (line) conic: the lines l with ``lᵀ C* l = 0``, from a symmetric 3×3 matrix C*.

    Degenerate dual conics are allowed: the dual conic at infinity ``diag(1, 1, 0)``
    has rank 2. ``repr`` gives the matrix as nested lists.

    >>> Cs = DualConic([[1, 0, 0], [0, 1, 0], [0, 0, -1]])      # tangents of the unit circle
    >>> Cs.contains_line(Line(1, 0, -1)), Cs.contains_line(Line(1, 0, 0))
    (True, False)
    """

    __slots__ = ()
    _kind = "dual conic"
    ambient_dim = 2

    def _repr_latex_(self) -> str:
        return f"$C^{{*}} = {self.latex()}$"

    def value(self, line: Line) -> Expr:
        """``lᵀ C* l``, expanded.

        >>> dual_conic_at_infinity().value(Line(1, 2, 3))
        5
        """
        require(line, Line, "DualConic.value")
        return self._form(line.coords, line.coords)

    def contains_line(self, line: Line) -> bool:
        """True when ``lᵀ C* l = 0``: for the dual of a conic C, when l is tangent to C.

        >>> Conic.circle(0, 0, 2).dual().contains_line(Line(0, 1, -2))     # y = 2 touches
        True
        """
        return is_zero(self.value(line))

    def dual(self) -> Conic:
        """The point conic ``adj C*`` whose tangents are these lines (C* non-degenerate).

        Since ``adj(adj C) = det(C) C`` for 3×3 matrices, ``C.dual().dual() == C``.

        >>> Conic.circle(1, 1, 1).dual().dual() == Conic.circle(1, 1, 1)
        True
        """
        if self.is_degenerate:
            raise DegenerateConicError(
                f"{self!r} is degenerate (rank {self.rank}), so its lines are not the tangents of a point conic; "
                "e.g. the dual conic at infinity consists of the lines through the two circular points"
            )
        return Conic._from_exact(adjugate(self._matrix))






def _monomials(p: Point) -> list[Expr]:
    x1, x2, x3 = p.coords
    return [sympy.expand(v) for v in (x1 * x1, x1 * x2, x2 * x2, x1 * x3, x2 * x3, x3 * x3)]


def conic_through(*points: Point) -> Conic:
    """The unique conic through five points.

    Each point x gives one linear equation in ``(a, b, c, d, e, f)``:
    ``a x1² + b x1x2 + c x2² + d x1x3 + e x2x3 + f x3² = 0``. The 5×6 system has a
    one-dimensional null space exactly when it has rank 5, and then the null
    vector is given exactly by the signed 5×5 minors (a generalised cross
    product) — no pivoting, so it also works with symbolic coordinates.

    Decisions: if three of the points are collinear (but no four) the unique
    conic exists and is the degenerate line pair, which is returned. If the null
    space is two-dimensional or more, no unique conic exists and an error names
    the cause: :class:`CoincidentPointsError` when two points coincide,
    :class:`CollinearPointsError` when four of the five are collinear (these
    are the only ways it can happen for five points).

    >>> conic_through(Point(1, 0), Point(-1, 0), Point(0, 1), Point(0, -1), Point(3, 4, 5))
    Conic.from_coefficients(1, 0, 1, 0, 0, -1)
    """
    if len(points) == 1 and isinstance(points[0], (list, tuple)):
        points = tuple(points[0])
    if len(points) != 5:
        raise DimensionError(
            f"conic_through needs exactly five points (a conic has 5 degrees of freedom), got {len(points)}"
        )
    for p in points:
        require(p, Point, "conic_through")
    rows = Matrix([_monomials(p) for p in points])
    coeffs = []
    for j in range(6):
        minor = rows[:, [k for k in range(6) if k != j]].det(method="bareiss")
        coeffs.append(sympy.expand((-1) ** j * minor))
    if all_zero(coeffs):
        for i, j in itertools.combinations(range(5), 2):
            if points[i] == points[j]:
                raise CoincidentPointsError(
                    f"points {i + 1} and {j + 1} given to conic_through are the same point {points[i]!r}; "
                    "five distinct points are needed to fix a conic"
                )
        for quad in itertools.combinations(range(5), 4):
            if all(collinear(*(points[k] for k in trio)) for trio in itertools.combinations(quad, 3)):
                raise CollinearPointsError(
                    "points " + ", ".join(str(k + 1) for k in quad) + " given to conic_through are collinear: every "
                    "line pair made of that line and a line through the fifth point contains them, so no unique "
                    "conic passes through the five points"
                )
        raise DegenerateConfigurationError(  # pragma: no cover - unreachable for five points
            "the five points do not fix a unique conic"
        )
    a, b, c, d, e, f = coeffs
    return Conic.from_coefficients(a, b, c, d, e, f).canonical()


def circular_points() -> tuple[Point, Point]:
    """The circular points ``I = (1, i, 0)`` and ``J = (1, -i, 0)``, on every circle.

    They are ideal points with complex coordinates; a conic passes through both
    exactly when it is a circle (or a degenerate conic containing them).

    >>> I_, J_ = circular_points()
    >>> I_, Conic.circle(5, -2, 7).contains(I_) and Conic.circle(5, -2, 7).contains(J_)
    (Point(1, I, 0), True)
    """
    return Point(1, I, 0), Point(1, -I, 0)


def dual_conic_at_infinity() -> DualConic:
    """The dual conic ``C*∞ = I Jᵀ + J Iᵀ = diag(1, 1, 0)`` (up to the factor 2), of rank 2.

    Its lines are those through one of the circular points: ``l1² + l2² = 0``.

    >>> dual_conic_at_infinity()
    DualConic([[1, 0, 0], [0, 1, 0], [0, 0, 0]])
    >>> dual_conic_at_infinity().contains_line(Line(1, I, 7))     # a line through I
    True
    """
    return DualConic([[1, 0, 0], [0, 1, 0], [0, 0, 0]])
