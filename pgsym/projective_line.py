"""The projective line P¹, its projective maps, and the cross-ratio, exactly.

A point of P¹ is a nonzero 2-vector ``(x1, x2)`` up to scale. ``Point1(x)`` is the
finite point with inhomogeneous coordinate ``x``, stored as ``(x, 1)``; the one
point with ``x2 = 0``, ``(1, 0)``, is the ideal point (the point at infinity).

Everything here is built on the *bracket* of two points,

    [P Q] = p1 q2 - p2 q1,

the 2×2 determinant of their coordinate columns. It vanishes exactly when P = Q,
and a linear map H multiplies it by det(H): ``[HP HQ] = det(H) [P Q]``.

Convention. The cross-ratio of four points is

    (A, B; C, D) = [A C][B D] / ([A D][B C]),

which for finite points is ``(a - c)(b - d) / ((a - d)(b - c))``; four points are
harmonic when the value is -1.

>>> from pgsym.projective_line import Point1, cross_ratio, harmonic_conjugate
>>> cross_ratio(Point1(0), Point1(1), Point1(2), Point1(3))
4/3
>>> harmonic_conjugate(Point1(0), Point1(1, 0), Point1(1))   # 0, ∞, 1 -> -1
Point1(-1, 1)
"""

from __future__ import annotations

import numbers
from collections.abc import Iterable, Sequence
from typing import Any

import sympy
from sympy import Expr, Integer, Matrix

from . import ring
from .errors import (
    CoincidentPointsError,
    DegenerateConfigurationError,
    DimensionError,
    IdealPointError,
    ObjectTypeError,
    UndefinedCrossRatioError,
)
from .homogeneous import HomogeneousPoint, is_zero
from .matrices import adjugate, expanded
from .projective_plane import Line, Point
from .transformations import Transformation

__all__ = [
    "Point1",
    "ProjectiveMap1",
    "bracket",
    "cross_ratio",
    "cross_ratio_lines",
    "harmonic_conjugate",
]


class Point1(HomogeneousPoint, kind="point1"):
    """A point of the projective line P¹.

    ``Point1(x)`` is the finite point with coordinate ``x``, stored as ``(x, 1)``;
    ``Point1(x1, x2)`` gives homogeneous coordinates, and ``Point1(1, 0)`` is the
    ideal point. Equality is up to a nonzero scale.

    >>> Point1(3)
    Point1(3, 1)
    >>> Point1(6, 2) == Point1(3), Point1(5, 0) == Point1(1, 0)
    (True, True)
    >>> Point1(1, 0).is_ideal
    True
    """

    size = 2
    _kind = "point of P¹"
    _inhomogeneous = "x"
    ambient_dim = 1
    __slots__ = ()

    def dehomogenize(self) -> Expr:
        """The inhomogeneous coordinate ``x1 / x2``.

        >>> Point1(3, 6).dehomogenize()
        1/2
        >>> Point1(1, 0).dehomogenize()  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        pgsym.errors.IdealPointError: Point1(1, 0) is the ideal point of P¹ ...
        """
        if self.is_ideal:
            raise IdealPointError(
                f"{self!r} is the ideal point of P¹ (x2 = 0) and has no inhomogeneous coordinate; "
                "test .is_ideal first, or work with the homogeneous coordinates"
            )
        return sympy.cancel(self._coords[0] / self._coords[1])


def _as_point1(obj: Any, operation: str) -> Point1:
    """Accept a Point1, or a plain number / SymPy expression as the finite point it names."""
    if isinstance(obj, Point1):
        return obj
    if isinstance(obj, (numbers.Number, Expr)) and not isinstance(obj, bool):
        return Point1(obj)
    raise ObjectTypeError(
        f"{operation} expects points of P¹ (Point1, or a number x for Point1(x)), got {type(obj).__name__} {obj!r}"
    )


def bracket(p: Point1, q: Point1) -> Expr:
    """The bracket ``[P Q] = p1 q2 - p2 q1``: zero exactly when P and Q are the same point.

    For finite points ``[Point1(a) Point1(b)] = a - b``.

    >>> bracket(Point1(5), Point1(2)), bracket(Point1(1, 0), Point1(7))
    (3, 1)
    """
    p = _as_point1(p, "bracket")
    q = _as_point1(q, "bracket")
    return sympy.expand(p[0] * q[1] - p[1] * q[0])


_NAMES = ("A", "B", "C", "D")


def _coincidences(equal: dict[tuple[int, int], bool]) -> list[str]:
    """Group indices 0..3 that are equal into classes, named like 'A = C = D'."""
    classes: list[set[int]] = []
    for i in range(4):
        for cls in classes:
            if any(equal[(min(i, j), max(i, j))] for j in cls):
                cls.add(i)
                break
        else:
            classes.append({i})
    return [" = ".join(_NAMES[i] for i in sorted(c)) for c in classes if len(c) > 1]


def _ratio(
    ac: Expr, bd: Expr, ad: Expr, bc: Expr, equal: dict[tuple[int, int], bool], what: str, inputs: str
) -> Expr:
    """The cross-ratio from the four brackets, or UndefinedCrossRatioError."""
    numerator, denominator = sympy.expand(ac * bd), sympy.expand(ad * bc)
    if is_zero(denominator):
        together = ", ".join(_coincidences(equal))
        if is_zero(numerator):
            raise UndefinedCrossRatioError(
                f"the cross-ratio of {inputs} is 0/0 and undefined: three of the {what} coincide ({together}); "
                f"the cross-ratio needs at least three distinct {what}"
            )
        raise UndefinedCrossRatioError(
            f"the cross-ratio of {inputs} has a zero denominator ({together}): its value would be infinite, "
            f"which pgsym does not return as a number; reorder the {what} (swapping C and D gives the "
            "reciprocal, which is 0 here)"
        )
    return sympy.cancel(numerator / denominator)


def cross_ratio(a: Point1, b: Point1, c: Point1, d: Point1) -> Expr:
    """The cross-ratio ``(A, B; C, D) = [A C][B D] / ([A D][B C])`` of four points of P¹.

    For finite points this is ``(a - c)(b - d) / ((a - d)(b - c))``. Because it is
    computed from brackets it is defined when one point is ideal, and for the
    coincidences that give 0 (``A = C`` or ``B = D``) or 1 (``A = B`` or ``C = D``).

    Undefined cases (both raise :class:`UndefinedCrossRatioError`, naming the
    coincident points):

    * 0/0, when three (or four) of the points coincide;
    * x/0 with x nonzero, when ``A = D`` or ``B = C`` and no three coincide. The
      extended value ∞ is deliberately *not* returned: an exact number is always
      a finite value, so a caller never receives SymPy's ``zoo`` by surprise.

    Numbers are accepted as finite points: ``cross_ratio(0, 1, 2, 3)`` means
    ``cross_ratio(Point1(0), Point1(1), Point1(2), Point1(3))``.

    >>> cross_ratio(Point1(-1), Point1(1), Point1(0), Point1(1, 0))   # harmonic
    -1
    >>> cross_ratio(0, 1, 0, 3), cross_ratio(2, 2, 0, 5)
    (0, 1)
    >>> cross_ratio(0, 1, 1, 2)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.UndefinedCrossRatioError: ... has a zero denominator (B = C): ...
    """
    pts = [_as_point1(p, "cross_ratio") for p in (a, b, c, d)]
    brackets = {(i, j): bracket(pts[i], pts[j]) for i in range(4) for j in range(i + 1, 4)}
    equal = {key: is_zero(value) for key, value in brackets.items()}
    inputs = "(" + ", ".join(repr(p) for p in pts[:2]) + "; " + ", ".join(repr(p) for p in pts[2:]) + ")"
    return _ratio(brackets[(0, 2)], brackets[(1, 3)], brackets[(0, 3)], brackets[(1, 2)], equal, "points", inputs)


def harmonic_conjugate(a: Point1 | Point, b: Point1 | Point, c: Point1 | Point) -> Point1 | Point:
    """The harmonic conjugate of C with respect to A and B: the point D with ``(A, B; C, D) = -1``.

    Solving ``[A C][B D] + [A D][B C] = 0`` (linear in D) gives
    ``D = [A C] B + [B C] A``. The three points must be distinct; otherwise no
    such D exists and :class:`UndefinedCrossRatioError` is raised. Note that the
    map C ↦ D is an involution, and D is C's mirror image when B is ideal.

    Three collinear points of P² (:class:`~pgsym.projective_plane.Point`) have their conjugate on the same
    line: with ``C = αA + βB``, read off ``C × B = α (A × B)`` and ``A × C = β (A × B)`` in a coordinate where
    ``A × B`` is nonzero, ``D = αA − βB`` (the P¹ formula in the coordinates (α, β) of the line; no division,
    so ideal points are fine). Points that are not collinear have no conjugate:
    :class:`UndefinedCrossRatioError`. The float kernel is :func:`pgsym.numeric.harmonic_conjugate`.

    >>> harmonic_conjugate(Point1(0), Point1(4), Point1(1)).dehomogenize()
    -2
    >>> harmonic_conjugate(Point1(-1), Point1(1), Point1(0)).is_ideal   # the midpoint pairs with ∞
    True
    >>> harmonic_conjugate(Point(0, 0), Point(4, 4), Point(1, 1)).dehomogenize()     # the same on the line y = x
    (-2, -2)
    """
    if any(isinstance(p, Point) for p in (a, b, c)):
        return _harmonic_conjugate_collinear(a, b, c)
    a, b, c = (_as_point1(p, "harmonic_conjugate") for p in (a, b, c))
    ac, bc, ab = bracket(a, c), bracket(b, c), bracket(a, b)
    _require_distinct(a, b, c, {"A = B": ab, "A = C": ac, "B = C": bc})
    coords = tuple(sympy.expand(ac * bi + bc * ai) for ai, bi in zip(a, b, strict=True))
    return Point1._from_exact(coords)


def _require_distinct(a: Any, b: Any, c: Any, named: dict[str, Any]) -> None:
    same = [name for name, value in named.items() if all(is_zero(x) for x in (value if isinstance(value, tuple)
                                                                                else (value,)))]
    if same:
        raise UndefinedCrossRatioError(
            f"no harmonic conjugate of C = {c!r} with respect to A = {a!r} and B = {b!r}: "
            f"{', '.join(same)}; the three points must be distinct"
        )


def _harmonic_conjugate_collinear(a: Point, b: Point, c: Point) -> Point:
    for name, p in zip("ABC", (a, b, c), strict=True):
        if not isinstance(p, Point):
            raise ObjectTypeError(
                f"harmonic_conjugate takes three points of P¹ or three collinear points of P², got {name} = "
                f"{type(p).__name__} {p!r} beside a Point")
    n, cb, ac = ring.cross(a.coords, b.coords), ring.cross(c.coords, b.coords), ring.cross(a.coords, c.coords)
    _require_distinct(a, b, c, {"A = B": n, "A = C": ac, "B = C": cb})
    if not is_zero(ring.dot(c.coords, n)):
        raise UndefinedCrossRatioError(
            f"no harmonic conjugate of C = {c!r} with respect to A = {a!r} and B = {b!r}: the three points are not "
            "collinear (det[A B C] ≠ 0), and a harmonic conjugate lies on the line of the other three")
    k = next(i for i in range(3) if not is_zero(n[i]))
    alpha, beta = cb[k], ac[k]
    return Point._from_exact(tuple(sympy.expand(alpha * x - beta * y) for x, y in zip(a.coords, b.coords, strict=True)))


class ProjectiveMap1(Transformation):
    """A projective transformation of P¹: an invertible 2×2 matrix H up to scale, acting by ``x ↦ H x``.

    It is a :class:`~pgsym.transformations.Transformation` of dimension 1 (inverse, ``@``,
    ``==`` up to scale, hashing and ``repr`` are those of every transformation) that also takes
    numbers as the finite points they name and is fixed by three point pairs (:meth:`from_pairs`).
    On finite points it is the Möbius map ``x ↦ (h11 x + h12) / (h21 x + h22)``, with
    4 - 1 = 3 degrees of freedom. ``F @ G`` is the composition "first G, then F";
    ``F @ point`` applies F.

    >>> H = ProjectiveMap1([[1, 1], [0, 1]])     # x -> x + 1
    >>> H.apply(Point1(2)), H(Point1(1, 0)), H(5)
    (Point1(3, 1), Point1(1, 0), Point1(6, 1))
    >>> H == Transformation([[2, 2], [0, 2]])
    True
    >>> ProjectiveMap1([[1, 2], [2, 4]])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.SingularTransformationError: the matrix [[1, 2], [2, 4]] is singular ...
    """

    __slots__ = ()
    _shape = (2, 2)
    _what = "the matrix of a map of P¹"
    _default_dim = 1

    def apply(self, point: Any) -> Any:
        """The image ``H x`` of a point (numbers are read as finite points).

        >>> ProjectiveMap1([[0, 1], [1, 0]]).apply(Point1(4))   # x -> 1/x
        Point1(1, 4)
        >>> ProjectiveMap1([[2, 1], [1, 1]]).inverse().matrix.tolist()   # the adjugate: no division
        [[1, -1], [-1, 2]]
        """
        if isinstance(point, (numbers.Number, Expr)) and not isinstance(point, bool):
            point = _as_point1(point, "ProjectiveMap1.apply")
        return super().apply(point)

    @classmethod
    def from_pairs(cls, pairs: Iterable[tuple[Point1, Point1]]) -> ProjectiveMap1:
        """The unique projective map sending three distinct points to three distinct points.

        With ``M_abc = [[B C] A | [C A] B]`` (columns), which sends ``(1, 0), (0, 1), (1, 1)``
        to A, B, C (up to one common scale), the map is ``M_a'b'c' · adj(M_abc)``.
        Raises :class:`CoincidentPointsError` when the three source points or the three
        target points are not distinct.

        >>> H = ProjectiveMap1.from_pairs([(0, 1), (1, 2), (Point1(1, 0), Point1(1, 0))])
        >>> H == ProjectiveMap1([[1, 1], [0, 1]])      # x -> x + 1
        True
        """
        pairs = list(pairs)
        if len(pairs) != 3 or any(not isinstance(p, Sequence) or len(p) != 2 for p in pairs):
            raise DimensionError(
                f"from_pairs needs exactly three (point, image) pairs, got {pairs!r}; a map of P¹ has 3 degrees "
                "of freedom"
            )
        sources = [_as_point1(p, "from_pairs") for p, _ in pairs]
        targets = [_as_point1(q, "from_pairs") for _, q in pairs]
        return cls(expanded(_frame(targets, "target") * adjugate(_frame(sources, "source"))))


def _frame(points: list[Point1], role: str) -> Matrix:
    a, b, c = points
    for (p, q), names in (((a, b), "1 and 2"), ((a, c), "1 and 3"), ((b, c), "2 and 3")):
        if is_zero(bracket(p, q)):
            raise CoincidentPointsError(
                f"the {role} points {names} of from_pairs are the same point {p!r}; a map of P¹ is fixed by "
                "three pairs of distinct points"
            )
    la, lb = bracket(b, c), bracket(c, a)
    return Matrix([[la * a[0], lb * b[0]], [la * a[1], lb * b[1]]])


def _det3(u: Sequence[Expr], v: Sequence[Expr], w: Sequence[Expr]) -> Expr:
    return sympy.expand(ring.det([tuple(u), tuple(v), tuple(w)]))


def cross_ratio_lines(l1: Line, l2: Line, l3: Line, l4: Line) -> Expr:
    """The cross-ratio of four concurrent lines of P², with the same convention as :func:`cross_ratio`.

    It equals the cross-ratio of the four points where the lines meet any line t
    not through their common point P. It is computed from brackets of lines,
    ``[L M] = det[L, M, t]``, with t the first coordinate line (``x = 0``, ``y = 0``,
    or the line at infinity) that misses P: writing each line as ``α m + β n`` in a
    basis of the pencil gives ``det[L_i, L_j, t] = (α_i β_j − α_j β_i) det[m, n, t]``,
    so the common factor cancels and the choice of t does not matter.

    Raises :class:`DegenerateConfigurationError` when the lines are not concurrent and
    :class:`UndefinedCrossRatioError` in the cases listed for :func:`cross_ratio`.

    >>> from pgsym.projective_plane import Line
    >>> # x = -1, x = 1, x = 0, and the line at infinity: all through the ideal point (0, 1, 0)
    >>> cross_ratio_lines(Line(1, 0, 1), Line(1, 0, -1), Line(1, 0, 0), Line(0, 0, 1))
    -1
    """
    lines = (l1, l2, l3, l4)
    for obj in lines:
        if not isinstance(obj, Line):
            raise ObjectTypeError(
                f"cross_ratio_lines expects four Lines of P², got {type(obj).__name__} {obj!r}; "
                "use cross_ratio for points of P¹"
            )
    for i, j, k in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3)):
        if not is_zero(_det3(lines[i], lines[j], lines[k])):
            raise DegenerateConfigurationError(
                f"the lines {lines[i]!r}, {lines[j]!r}, {lines[k]!r} are not concurrent (det ≠ 0): the cross-ratio "
                "is defined only for four lines through one point"
            )
    common = None
    for i in range(4):
        for j in range(i + 1, 4):
            candidate = lines[i].meet(lines[j]) if not lines[i] == lines[j] else None
            if candidate is not None:
                common = candidate
                break
        if common is not None:
            break
    inputs = "(" + ", ".join(repr(x) for x in lines[:2]) + "; " + ", ".join(repr(x) for x in lines[2:]) + ")"
    if common is None:
        raise UndefinedCrossRatioError(
            f"the cross-ratio of {inputs} is 0/0 and undefined: all four lines are the same line"
        )
    basis = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
    t = next(e for e in basis if not is_zero(sum((ei * pi for ei, pi in zip(e, common, strict=True)), Integer(0))))
    br = {(i, j): _det3(lines[i], lines[j], t) for i in range(4) for j in range(i + 1, 4)}
    equal = {key: is_zero(value) for key, value in br.items()}
    return _ratio(br[(0, 2)], br[(1, 3)], br[(0, 3)], br[(1, 2)], equal, "lines", inputs)
