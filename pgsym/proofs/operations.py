"""The operations of the proof engine, one table: every construction a claim can use, in one entry each.

An :class:`Operation` says everything the engine and the claim builder need to know about
one construction: the kinds of its arguments and of its result, its polynomial formula
(written with :mod:`pgsym.ring`, so it runs on integers modulo p, on fractions and on
polynomials alike), its non-degeneracy conditions in geometric words together with the
polynomials that must not all vanish, and the builder of the same object with pgsym's own
classes (the core cross-check). Adding an operation means adding one entry here and, for
a readable claim vocabulary, one small :class:`~pgsym.proofs.claims.Claim` method that
calls it.

>>> OPERATIONS["join"].conditions(["A", "B"], "l", None)
['A ≠ B']
>>> OPERATIONS["apply"].result_kind(["matrix", "point3"])
'point3'
>>> sorted(n for n, op in OPERATIONS.items() if not op.constructible and not op.conclusion)
['const', 'free']
>>> OPERATIONS["lines_meet"].conclusion     # a conclusion's quantity, built by Claim.conclude_lines_meet
True
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy
from sympy import Matrix

from .. import (
    affine,
    conic_metric,
    conic_pencil,
    conics,
    invariants,
    metric,
    plucker,
    projective_line,
    projective_plane,
    space,
)
from .. import ring as alg
from ..exact import is_zero
from ..homogeneous import HomogeneousVector
from ..kinds import object_classes

__all__ = [
    "EUCLIDEAN_OPERATIONS", "KINDS", "OPERATIONS", "CoreDegenerate", "Operation", "affine_vector", "constructions",
    "flat", "map_nested", "operation",
]

# Proofs carry a line of P³ as its 4×4 Plücker matrix (the wedge of two points), not as the six
# Plücker coordinates of the Line3 class, so its size here is that of a matrix.
#: kind of object -> number of homogeneous coordinates (None for matrices, scalars and ratios): the kinds of
#: pgsym's classes, plus the kinds that exist only in proofs (matrix, scalar, ratio)
KINDS: dict[str, int | None] = {
    # vectors (points, lines, planes, Plücker lines) have ``size`` coordinates; forms and maps are matrices
    **{kind: (cls.size if issubclass(cls, HomogeneousVector) else None) for kind, cls in object_classes().items()},
    "matrix": None,
    "scalar": None,
    "ratio": None,
}

_VECTOR_KINDS = tuple(k for k, size in KINDS.items() if size is not None)


class CoreDegenerate(Exception):
    """The core cannot build an object at this point (e.g. a singular matrix): try another point."""


def map_nested(value: Any, f: Callable[[Any], Any]) -> Any:
    """``f`` applied to every entry of a nested tuple value, keeping its shape.

    >>> map_nested(((1, 2), 3), lambda x: 10 * x)
    ((10, 20), 30)
    """
    if isinstance(value, tuple):
        return tuple(map_nested(v, f) for v in value)
    return f(value)


def flat(value: Any) -> list[Any]:
    """The entries of a nested tuple value, in order.

    >>> flat(((1, 2), (3, 4)))
    [1, 2, 3, 4]
    """
    if isinstance(value, tuple):
        out: list[Any] = []
        for v in value:
            out.extend(flat(v))
        return out
    return [value]


Scalar = Callable[[Any], Any]


@dataclass(frozen=True)
class Operation:
    """One construction: its name, argument and result kinds, formula, conditions and core builder.

    * ``arg_kinds``: the kinds accepted for each argument (``None``: any number of arguments of any kind);
      with ``same_kind`` every argument after the first must have the first one's kind;
    * ``result``: the kind of the result, or the index of the argument whose kind it has;
    * ``formula(node, args, scalar)``: the value from the arguments' values (``scalar`` maps the node's
      coefficient data into the arithmetic in use);
    * ``conditions(names, name, data)``: the non-degeneracy conditions in words, and
      ``condition_values(node, value, args)`` one list of polynomials per condition, not all zero when it
      holds (default: the entries of the value itself, i.e. the result is not the zero vector);
    * ``core(node, args, exact)``: the same object built with pgsym's classes (``None`` when the core has no
      counterpart), ``exact`` mapping coefficient data to SymPy rationals;
    * ``description(names, data)``: how the construction reads, e.g. ``A × B``;
    * ``group``: the group whose action the construction commutes with (``"projective"``: mapping the
      arguments by any homography maps the result by it; ``"affine"`` for constructions that use l∞ (midpoint,
      parallel, centre, signed area), ``"similarity"`` for those that use the circular points (perpendicular,
      circles, inversion, squared distance, angles; they commute with every orientation-preserving
      similarity), ``"euclidean"`` for fixed lengths), or ``None`` when its value depends on the representatives or on
      data the group does not act on (``combine`` with coefficients, a matrix applied, a formula). Choosing
      coordinates without loss of generality is allowed only under a group every construction commutes with.
      A construction with a free parameter (a point on a line or on a conic) counts as commuting when the
      homography maps the family of its values onto the family for the mapped arguments (the parameter changes
      by an invertible substitution), since a generic statement then holds for one family exactly when for the
      other;
    * ``on_span``: the value is a combination ``s·P + t·Q`` of the arguments' representatives, so which point of
      their span it is depends on the representatives: the core check takes the formula's point once it lies in
      the span of the core's own arguments;
    * ``conclusion``: the value is a quantity of a conclusion (zero exactly when the statement holds, e.g. the
      reciprocal product of two lines that meet), so it vanishes identically on a true claim and is never a
      degenerate construction;
    * ``given``: the value is given (a free object or a constant), not constructed: it is never checked for
      vanishing identically, and a constant's denominator is not a condition;
    * ``lies_on``: the indices of the arguments the result lies on by construction (the meet of two lines lies on
      both, the second point of a conic on the conic), ``through``: those the result passes through (the join of
      two points, the conic through five), ``polar_of``: ``(conic, point)`` when the result passes through the
      point exactly when the point lies on the conic (a polar) — what discovery marks as true by construction;
    * for the choice of a frame (:mod:`pgsym.proofs.normalisation`): ``constant`` (a number given as a ratio),
      ``fresh_coefficients`` (the value depends on the representatives unless its coefficients are parameters of
      its own: ``combine``), ``node_group(data, own)`` the group when it depends on the node's data (``own(e)``:
      ``e`` is a parameter used nowhere else), ``ratio_scaling`` ``(a, b)`` when a ratio changes by
      det(M)^a · k^b under an affine map or a similarity of scale k, ``ratio_arithmetic`` ``"sum"`` or
      ``"product"`` for the arithmetic of ratios; ``circle``: the value is a circle's matrix
      ((a, 0, b), (0, a, c), (b, c, f)) for every value of the arguments (its centre is then (−b, −c, a)).
    """

    name: str
    arg_kinds: tuple[tuple[str, ...], ...] | None
    result: str | int
    formula: Callable[[Any, list[Any], Scalar], Any]
    description: Callable[[list[str], Any], str]
    conditions: Callable[[list[str], str, Any], list[str]] = lambda names, name, data: []
    condition_values: Callable[[Any, Any, list[Any]], list[list[Any]]] | None = None
    core: Callable[[Any, list[Any], Scalar], Any] | None = None
    same_kind: bool = False
    coefficients: bool = False
    constructible: bool = True
    aliases: tuple[str, ...] = field(default=())
    group: str | None = "projective"
    conclusion: bool = False
    on_span: bool = False
    given: bool = False
    constant: bool = False
    fresh_coefficients: bool = False
    node_group: Callable[[Any, Callable[[Any], bool]], str | None] | None = None
    ratio_scaling: tuple[int, int] | None = None
    ratio_arithmetic: str | None = None
    lies_on: tuple[int, ...] = ()
    through: tuple[int, ...] = ()
    polar_of: tuple[int, int] | None = None
    circle: bool = False

    def result_kind(self, arg_kinds: Sequence[str]) -> str:
        """The kind of the result for arguments of the given kinds."""
        return self.result if isinstance(self.result, str) else arg_kinds[self.result]

    def nonzero(self, node: Any, value: Any, args: list[Any]) -> list[list[Any]]:
        """One list per condition of the node: the condition holds when not all entries vanish."""
        if not node.conditions:
            return []
        if self.condition_values is not None:
            return self.condition_values(node, value, args)
        return [flat(value)] * len(node.conditions)


# -- formulas -------------------------------------------------------------------------------------------

def _free_value(node: Any, args: list[Any], scalar: Scalar) -> Any:
    if node.kind == "scalar":
        return scalar(node.data[0])
    if KINDS.get(node.kind) is not None:
        return tuple(scalar(e) for e in node.data)
    return tuple(tuple(scalar(e) for e in row) for row in node.data)


def _conic_from_points(points: list[tuple[Any, ...]]) -> tuple[tuple[Any, ...], ...]:
    """The symmetric matrix of the conic through five points: its coefficients are signed 5×5 minors."""
    rows = [(x * x, x * y, y * y, x * w, y * w, w * w) for x, y, w in points]
    coeffs = []
    for j in range(6):
        d = alg.det([r[:j] + r[j + 1:] for r in rows])
        coeffs.append(d if j % 2 == 0 else -d)
    a, b, c, d, e, f = coeffs
    return ((a + a, b, d), (b, c + c, e), (d, e, f + f))


def _bracket(p: Sequence[Any], q: Sequence[Any]) -> Any:
    return p[0] * q[1] - p[1] * q[0]


def _cross_ratio(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, Any]:
    a, b, c, d = v
    return (_bracket(a, c) * _bracket(b, d), _bracket(a, d) * _bracket(b, c))


def _harmonic_conjugate(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    a, b, c = v
    ac, bc = _bracket(a, c), _bracket(b, c)
    return tuple(ac * bi + bc * ai for ai, bi in zip(a, b, strict=True))


def _combine(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    s, t = scalar(node.data[0]), scalar(node.data[1])
    return tuple(s * a + t * b for a, b in zip(v[0], v[1], strict=True))


def _apply_conic(node: Any, v: list[Any], scalar: Scalar) -> Any:
    a = alg.adjugate(v[0])
    return alg.matmul(alg.transpose(a), alg.matmul(v[1], a))


def _second_intersection(p: Sequence[Any], q: Sequence[Any], c: Any) -> tuple[Any, ...]:
    """The second point where the line PQ meets the conic C, when P lies on C: ``(QᵀCQ) P − 2 (PᵀCQ) Q``.

    On the line, X(s, t) = s P + t Q meets C where ``2 s t PᵀCQ + t² QᵀCQ = 0`` (as ``PᵀCP = 0``): t = 0 is P,
    and (s, t) = (QᵀCQ, −2 PᵀCQ) the other point; a tangent at P gives P again, a Q on C gives Q.
    """
    cq = alg.matvec(c, q)
    qcq, pcq = alg.dot(q, cq), alg.dot(p, cq)
    return tuple(qcq * pi - 2 * pcq * qi for pi, qi in zip(p, q, strict=True))


def _conic_point(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # the pencil of lines through P is cut out by the points (1, t, t²) of the conic y² = xw: never one line,
    # wherever P is (projecting a conic from a point is non-constant), so the family is the whole conic for any C, P
    t = scalar(node.data[0])
    return _second_intersection(v[1], _moment(t), v[0])


def _pairs(a: Sequence[Any], b: Sequence[Any]) -> list[Any]:
    """The 2×2 minors ``a_i b_j − a_j b_i`` (i < j): all zero exactly when a and b are proportional."""
    return [a[i] * b[j] - a[j] * b[i] for i in range(len(a)) for j in range(i + 1, len(a))]


def _moment(t: Any) -> tuple[Any, Any, Any]:
    """(1, t, t²): a point of the conic y² = xw (or a tangent of its dual), used to sweep a pencil or a line."""
    one = t ** 0 if t else t + 1  # SymPy's ring has no 0**0
    return (one, t, t * t)


def _conic_tangent_to(node: Any, v: list[Any], scalar: Scalar) -> Any:
    # the dual conic through five lines, then back to points: adj(adj C) = det(C)·C
    return alg.adjugate(_conic_from_points(v))


def _plucker_coords(m: Any) -> tuple[Any, ...]:
    """(l12, l13, l14, l23, l42, l34) of a 4×4 Plücker matrix (pgsym.plucker's order)."""
    return (m[0][1], m[0][2], m[0][3], m[1][2], m[3][1], m[2][3])


def _plucker_matrix(c: Sequence[Any]) -> tuple[tuple[Any, ...], ...]:
    l12, l13, l14, l23, l42, l34 = c
    z = l12 - l12
    return ((z, l12, l13, l14), (-l12, z, l23, -l42), (-l13, -l23, z, l34), (-l14, l42, -l34, z))


def _dual_plucker(m: Any) -> tuple[tuple[Any, ...], ...]:
    """L* from L by the rewrite rule (the six coordinates reversed); the other way round as well."""
    return _plucker_matrix(tuple(reversed(_plucker_coords(m))))


def _reciprocal(l: Any, m: Any) -> Any:
    """The reciprocal product of two lines of P³ (zero exactly when they meet): pgsym.plucker.reciprocal_product."""
    a, b = _plucker_coords(l), _plucker_coords(m)
    return alg.dot(a, tuple(reversed(b)))


def _veronese(p: Sequence[Any]) -> tuple[Any, ...]:
    x, y, w = p
    return (x * x, x * y, y * y, x * w, y * w, w * w)


def _bracket_on(a: Sequence[Any], c: Sequence[Any], base: Sequence[Any]) -> Any:
    """λ with A × C = λ·l for collinear A, C on the line l = A × B, times |l|²: (A × C)·(A × B)."""
    return alg.dot(alg.cross(a, c), base)


def _cross_ratio2(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, Any]:
    # four collinear points (concurrent lines): A × C = λ_AC l with one l, and (A, B; C, D) = λ_AC λ_BD / (λ_AD λ_BC);
    # λ is read off by a dot product with l = A × B, whose factor |l|² cancels
    a, b, c, d = v
    base = alg.cross(a, b)
    return (_bracket_on(a, c, base) * _bracket_on(b, d, base), _bracket_on(a, d, base) * _bracket_on(b, c, base))


def _harmonic2(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # the P¹ formula [A C] B + [B C] A with the brackets read on the common line (see _cross_ratio2)
    a, b, c = v
    base = alg.cross(a, b)
    ac, bc = _bracket_on(a, c, base), _bracket_on(b, c, base)
    return tuple(ac * bi + bc * ai for ai, bi in zip(a, b, strict=True))


def _midpoint(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # w_B·A + w_A·B: the inhomogeneous coordinates are (A/w_A + B/w_B)/2 for any representatives of A and B
    a, b = v
    return tuple(b[-1] * ai + a[-1] * bi for ai, bi in zip(a, b, strict=True))


# -- non-degeneracy ---------------------------------------------------------------------------------------

def _det_of_first(node: Any, value: Any, args: list[Any]) -> list[list[Any]]:
    """The matrix (first argument) is non-singular: its determinant is not zero."""
    return [[alg.det(args[0])]]


def _free_conditions(node: Any, value: Any, args: list[Any]) -> list[list[Any]]:
    # a free matrix declared invertible needs det ≠ 0; nothing else of a free object carries a condition
    return [[alg.det(value)]] if node.kind == "matrix" else [flat(value)] * len(node.conditions)


def _nonsingular(names: list[str], name: str, data: Any) -> list[str]:
    return [f"{names[0]} is non-singular (det {names[0]} ≠ 0)"]


def _finite_points(node: Any, value: Any, args: list[Any]) -> list[list[Any]]:
    return [[args[0][-1]], [args[1][-1]]]


# -- the core's objects ------------------------------------------------------------------------------------

def _vector(kind: str, coords: Any) -> Any:
    return object_classes()[kind](*coords)


def _free_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    if node.kind in _VECTOR_KINDS:
        return _vector(node.kind, (exact(e) for e in node.data))
    if node.kind in ("matrix", "conic"):
        return Matrix([[exact(e) for e in row] for row in node.data])
    return None


def _combine_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    s, t = exact(node.data[0]), exact(node.data[1])
    return _vector(node.kind, (s * x + t * y for x, y in zip(a[0].coords, a[1].coords, strict=True)))


def _apply_line_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    if is_zero(a[0].det()):
        raise CoreDegenerate(f"{node.args[0].name} is singular")
    return _vector(node.kind, a[0].adjugate().T * a[1].vector)


def _apply_conic_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    adj = a[0].adjugate()
    return conics.Conic(adj.T * (a[1].matrix if hasattr(a[1], "matrix") else a[1]) * adj)


def _second_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    """The other point of ``Conic.intersections`` with the line PQ (the core finds both with its own formula)."""
    conic = conics.Conic(a[0].matrix if hasattr(a[0], "matrix") else a[0])
    p, q = a[1], a[2]
    if not is_zero(conic.value(p)):
        raise CoreDegenerate(f"{node.args[1].name} is not on {node.args[0].name} at this point")
    if p == q:
        raise CoreDegenerate(f"{node.args[1].name} = {node.args[2].name} at this point")
    first, second = conic.intersections(projective_plane.join(p, q))
    return second if first == p else first


def _conic_point_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    t = exact(node.data[0])
    q = projective_plane.Point(1, t, t * t)
    return _second_core(node, [a[0], a[1], q], exact)


def _tangent_to_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    dual = conics.conic_through(*(projective_plane.Point(*l.coords) for l in a))
    return conics.DualConic(dual.matrix).dual()


def _cross_ratio2_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    if node.args[0].kind == "line":
        return projective_line.cross_ratio_lines(*a)
    pts = _on_common_line(node, a)
    return projective_line.cross_ratio(*pts)


def _on_common_line(node: Any, a: list[Any]) -> list[Any]:
    """Points of P² on one line, as points of P¹ (coordinates on a basis A, B of the line)."""
    basis = Matrix.hstack(a[0].vector, a[1].vector)
    out = []
    for p in a:
        sol = basis.solve_least_squares(p.vector)
        if (basis * sol - p.vector).applyfunc(lambda e: 0 if is_zero(e) else 1) != Matrix([0, 0, 0]):
            raise CoreDegenerate("the points are not collinear at this point")
        out.append(projective_line.Point1(*sol))
    return out


def _harmonic2_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    kind = node.args[0].kind
    objs = a if kind == "point" else [projective_plane.Point(*x.coords) for x in a]
    a1 = _on_common_line(node, objs)
    h = projective_line.harmonic_conjugate(*a1)
    vec = Matrix.hstack(objs[0].vector, objs[1].vector) * h.vector
    return _vector(kind, vec)


def _midpoint_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    p, q = (x.dehomogenize() for x in a)
    return _vector(node.kind, (*((s + t) / 2 for s, t in zip(p, q, strict=True)), 1))


def _line_of_planes_formula(node: Any, v: list[Any], scalar: Scalar) -> Any:
    return _dual_plucker(alg.wedge(v[0], v[1]))


# -- the group of a construction that depends on its data ------------------------------------------------------

def _family(data: Any, own: Callable[[Any], bool]) -> str | None:
    """A point with a parameter of its own: a homography maps the family of its values onto the family."""
    return "projective" if own(data[0]) else None


def _radius_group(data: Any, own: Callable[[Any], bool]) -> str | None:
    """A squared radius of its own is rescaled by a similarity (the family again); a fixed nonzero number is kept
    only by isometries."""
    r = data[0]
    if own(r):
        return "similarity"
    return "euclidean" if r.is_Rational and r != 0 else None


def _rotation_group(data: Any, own: Callable[[Any], bool]) -> str | None:
    """A rotation by a fixed angle commutes with every orientation-preserving similarity."""
    return "similarity" if all(sympy.sympify(e).is_Rational for e in data) else None


# -- the table -------------------------------------------------------------------------------------------

_POINT, _LINE, _POINT1, _POINT3, _PLANE = ("point",), ("line",), ("point1",), ("point3",), ("plane",)

_TABLE = (
    Operation("free", (), "free", _free_value, lambda n, d: "", condition_values=_free_conditions, core=_free_core,
              coefficients=True, constructible=False, given=True),
    Operation("const", (), "ratio", lambda node, v, scalar: (scalar(node.data[0]), scalar(node.data[1])),
              lambda n, d: "", coefficients=True, constructible=False, given=True, constant=True),
    Operation("join", (_POINT, _POINT), "line", lambda node, v, scalar: alg.cross(v[0], v[1]),
              lambda n, d: f"{n[0]} × {n[1]}", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: projective_plane.join(*a), through=(0, 1)),
    Operation("meet", (_LINE, _LINE), "point", lambda node, v, scalar: alg.cross(v[0], v[1]),
              lambda n, d: f"{n[0]} × {n[1]}", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: projective_plane.meet(*a), lies_on=(0, 1)),
    Operation("combine", (_VECTOR_KINDS, _VECTOR_KINDS), 0, _combine,
              lambda n, d: f"{d[0]}·{n[0]} + {d[1]}·{n[1]}",
              lambda n, name, d: [f"{name} is not the zero vector ({n[0]} ≠ {n[1]})"],
              core=_combine_core, same_kind=True, coefficients=True, group=None, on_span=True,
              fresh_coefficients=True),
    Operation("plane_through", (_POINT3,) * 3, "plane", lambda node, v, scalar: alg.plane_through(*v),
              lambda n, d: f"plane({', '.join(n)})", lambda n, name, d: [f"{', '.join(n)} are not collinear"],
              core=lambda node, a, exact: space.plane_through(*a), through=(0, 1, 2)),
    Operation("point_on_planes", (_PLANE,) * 3, "point3", lambda node, v, scalar: alg.plane_through(*v),
              lambda n, d: f"point({', '.join(n)})", lambda n, name, d: [f"{', '.join(n)} do not share a line"],
              core=lambda node, a, exact: space.point_on_planes(*a), lies_on=(0, 1, 2)),
    Operation("line3", (_POINT3, _POINT3), "line3", lambda node, v, scalar: alg.wedge(v[0], v[1]),
              lambda n, d: f"{n[0]} {n[1]}ᵀ − {n[1]} {n[0]}ᵀ", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: plucker.Line3.join(*a), through=(0, 1)),
    Operation("apply", (("matrix",), ("point1", "point", "point3")), 1,
              lambda node, v, scalar: alg.matvec(v[0], v[1]), lambda n, d: f"{n[0]} {n[1]}",
              core=lambda node, a, exact: _vector(node.kind, a[0] * a[1].vector), group=None),
    Operation("apply_line", (("matrix",), ("line", "plane")), 1,
              lambda node, v, scalar: alg.matvec(alg.transpose(alg.adjugate(v[0])), v[1]),
              lambda n, d: f"adj({n[0]})ᵀ {n[1]}", _nonsingular, _det_of_first, core=_apply_line_core,
              aliases=("apply_plane",), group=None),
    Operation("apply_conic", (("matrix",), ("conic",)), "conic", _apply_conic,
              lambda n, d: f"adj({n[0]})ᵀ {n[1]} adj({n[0]})", _nonsingular, _det_of_first,
              core=_apply_conic_core, group=None),
    Operation("polar", (("conic",), _POINT), "line", lambda node, v, scalar: alg.matvec(v[0], v[1]),
              lambda n, d: f"{n[0]} {n[1]}",
              lambda n, name, d: [f"{n[1]} is not a singular point of {n[0]} ({n[0]} {n[1]} ≠ 0)"],
              core=lambda node, a, exact: conics.Conic(a[0].matrix if hasattr(a[0], "matrix") else a[0]).polar(a[1]),
              aliases=("tangent",), polar_of=(0, 1)),
    Operation("conic_through", (_POINT,) * 5, "conic", lambda node, v, scalar: _conic_from_points(v),
              lambda n, d: f"conic({', '.join(n)})",
              lambda n, name, d: [f"{', '.join(n)} determine a unique conic (no two equal, no four collinear)"],
              core=lambda node, a, exact: conics.conic_through(*a), through=(0, 1, 2, 3, 4)),
    Operation("dual_conic", (("conic",),), "matrix", lambda node, v, scalar: alg.adjugate(v[0]),
              lambda n, d: f"adj({n[0]})", lambda n, name, d: [f"{n[0]} is non-degenerate (det {n[0]} ≠ 0)"],
              _det_of_first, core=lambda node, a, exact: conics.Conic(a[0]).dual()),
    Operation("cross_ratio", (_POINT1,) * 4, "ratio", _cross_ratio, lambda n, d: f"({n[0]}, {n[1]}; {n[2]}, {n[3]})",
              lambda n, name, d: [f"[{n[0]} {n[3]}][{n[1]} {n[2]}] ≠ 0 ({n[0]} ≠ {n[3]} and {n[1]} ≠ {n[2]})"],
              lambda node, value, args: [[value[1]]],
              core=lambda node, a, exact: projective_line.cross_ratio(*a), ratio_scaling=(0, 0)),
    Operation("harmonic_conjugate", (_POINT1,) * 3, "point1", _harmonic_conjugate,
              lambda n, d: f"[{n[0]} {n[2]}] {n[1]} + [{n[1]} {n[2]}] {n[0]}",
              lambda n, name, d: [f"{', '.join(n)} are distinct"],
              core=lambda node, a, exact: projective_line.harmonic_conjugate(*a)),
    Operation("second_intersection", (("conic",), _POINT, _POINT), "point",
              lambda node, v, scalar: _second_intersection(v[1], v[2], v[0]),
              lambda n, d: f"({n[2]}ᵀ{n[0]}{n[2]}) {n[1]} − 2 ({n[1]}ᵀ{n[0]}{n[2]}) {n[2]}",
              lambda n, name, d: [f"{n[1]} ≠ {n[2]} ({name} is the second point of {n[0]} on the line {n[1]}{n[2]}; "
                                  f"{n[1]} must lie on {n[0]})"],
              core=_second_core, lies_on=(0,)),
    Operation("point_on_conic", (("conic",), _POINT), "point", _conic_point,
              lambda n, d: f"second point of {n[0]} on the line through {n[1]} and (1, {d[0]}, {d[0]}²)",
              lambda n, name, d: [f"{name} is defined ({n[1]} lies on {n[0]}, the line through it is no tangent)"],
              core=_conic_point_core, coefficients=True, lies_on=(0,), node_group=_family),
    Operation("point_on_line", (("point", "point3"), ("point", "point3")), 0,
              lambda node, v, scalar: tuple(a + scalar(node.data[0]) * b for a, b in zip(v[0], v[1], strict=True)),
              lambda n, d: f"{n[0]} + {d[0]}·{n[1]}", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              lambda node, value, args: [_pairs(args[0], args[1])],
              core=lambda node, a, exact: _vector(node.kind, (x + exact(node.data[0]) * y
                                                              for x, y in zip(a[0].coords, a[1].coords, strict=True))),
              same_kind=True, coefficients=True, on_span=True, node_group=_family),
    Operation("point_of_line", (_LINE,), "point",
              lambda node, v, scalar: alg.cross(v[0], _moment(scalar(node.data[0]))),
              lambda n, d: f"{n[0]} × (1, {d[0]}, {d[0]}²)", lambda n, name, d: [f"{name} is a point of {n[0]}"],
              core=lambda node, a, exact: projective_plane.meet(
                  a[0], projective_plane.Line(*_moment(exact(node.data[0])))),
              coefficients=True, lies_on=(0,), node_group=_family),
    Operation("conic_tangent_to", (_LINE,) * 5, "conic", _conic_tangent_to,
              lambda n, d: f"adj(dual conic({', '.join(n)}))",
              lambda n, name, d: [f"{', '.join(n)} are tangent to a unique non-degenerate conic "
                                  "(no two equal, no three concurrent)"],
              core=_tangent_to_core),
    Operation("line_meets_plane", (("line3",), _PLANE), "point3", lambda node, v, scalar: alg.matvec(v[0], v[1]),
              lambda n, d: f"{n[0]} {n[1]}", lambda n, name, d: [f"{n[0]} does not lie in {n[1]}"],
              core=lambda node, a, exact: a[0].intersect_plane(a[1]), lies_on=(0, 1)),
    Operation("line_of_planes", (_PLANE, _PLANE), "line3", _line_of_planes_formula,
              lambda n, d: f"({n[0]} {n[1]}ᵀ − {n[1]} {n[0]}ᵀ)*", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: plucker.Line3.meet(*a), lies_on=(0, 1)),
    Operation("cross_ratio_collinear", (("point", "line"),) * 4, "ratio", _cross_ratio2,
              lambda n, d: f"({n[0]}, {n[1]}; {n[2]}, {n[3]})",
              lambda n, name, d: [f"{n[0]} ≠ {n[3]}, {n[1]} ≠ {n[2]} and {n[0]} ≠ {n[1]} "
                                  f"({', '.join(n)} collinear or concurrent)"],
              lambda node, value, args: [[value[1]]], core=_cross_ratio2_core, same_kind=True, ratio_scaling=(0, 0)),
    Operation("harmonic_conjugate_collinear", (("point", "line"),) * 3, 0, _harmonic2,
              lambda n, d: f"harmonic conjugate of {n[2]} with respect to {n[0]}, {n[1]}",
              lambda n, name, d: [f"{', '.join(n)} are distinct ({', '.join(n)} collinear or concurrent)"],
              core=_harmonic2_core, same_kind=True),
    Operation("midpoint", (("point", "point3"),) * 2, 0, _midpoint,
              lambda n, d: f"w({n[1]}) {n[0]} + w({n[0]}) {n[1]}",
              lambda n, name, d: [f"{n[0]} is a finite point", f"{n[1]} is a finite point"], _finite_points,
              core=_midpoint_core, same_kind=True, group="affine"),
    # conclusion quantities: zero exactly when the statement holds
    Operation("collinear3", (_POINT3,) * 3, "scalar",
              lambda node, v, scalar: tuple(m for _r, _c, m in alg.minors(alg.transpose(v), 3)),
              lambda n, d: f"3×3 minors of [{' '.join(n)}]", constructible=False, conclusion=True),
    Operation("on_line3", (_POINT3, ("line3",)), "scalar",
              lambda node, v, scalar: alg.matvec(_dual_plucker(v[1]), v[0]),
              lambda n, d: f"{n[1]}* {n[0]}", constructible=False, conclusion=True),
    Operation("lines_meet", (("line3",), ("line3",)), "scalar",
              lambda node, v, scalar: (_reciprocal(v[0], v[1]),),
              lambda n, d: f"reciprocal product of {n[0]} and {n[1]}", constructible=False, conclusion=True),
    Operation("on_conic", (_POINT, ("conic",)), "scalar",
              lambda node, v, scalar: (alg.dot(v[0], alg.matvec(v[1], v[0])),),
              lambda n, d: f"{n[0]}ᵀ {n[1]} {n[0]}", constructible=False, conclusion=True),
    Operation("tangent_to", (_LINE, ("conic",)), "scalar",
              lambda node, v, scalar: (alg.dot(v[0], alg.matvec(alg.adjugate(v[1]), v[0])),),
              lambda n, d: f"{n[0]}ᵀ adj({n[1]}) {n[0]}", constructible=False, conclusion=True),
    Operation("six_on_conic", (("point", "line"),) * 6, "scalar",
              lambda node, v, scalar: (alg.det([_veronese(p) for p in v]),),
              lambda n, d: f"det of the 6×6 matrix of the quadratic monomials of {', '.join(n)}",
              same_kind=True, constructible=False, conclusion=True),
    Operation("formula", None, "formula", lambda node, v, scalar: node.data(*v),
              lambda n, d: f"{getattr(d, '__name__', 'f')}({', '.join(n)})", group=None),
)

# -- Euclidean constructions: the absolute (l∞ = (0, 0, 1), C*∞ = diag(1, 1, 0)) in real form ---------------
#
# Points are homogeneous (x, y, w): every formula below is right for any representative (any w ≠ 0), lines
# (a, b, c) for any scale, circles for any scale of their matrix. A ratio is a pair (numerator, denominator).

def affine_vector(a: Sequence[Any], b: Sequence[Any]) -> tuple[Any, Any]:
    """w_A w_B (B − A) in affine coordinates: ``w_A B − w_B A`` (first two coordinates); right for any
    representatives, with no division.

    >>> affine_vector((1, 1, 1), (6, 4, 2))       # (3, 2) − (1, 1) = (2, 1), times w_A w_B = 2
    (4, 2)
    """
    return b[0] * a[2] - a[0] * b[2], b[1] * a[2] - a[1] * b[2]


def _parallel(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # P × (b, −a, 0), the join of P with the ideal point of l
    (a, b, _c), (x, y, w) = v
    return (a * w, b * w, -(a * x + b * y))


def _perpendicular(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # P × (a, b, 0) = P × C*∞ l, the join of P with the pole of l for the absolute (the normal's ideal point)
    (a, b, _c), (x, y, w) = v
    return (-b * w, a * w, b * x - a * y)


def _bisector(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # |X − A|² = |X − B|² ⇔ 2 (B − A)·X + |A|² − |B|² = 0 with A = a/w_a, B = b/w_b, times w_a² w_b²
    (x1, y1, w1), (x2, y2, w2) = v
    return (2 * (x2 * w1 - x1 * w2) * w1 * w2, 2 * (y2 * w1 - y1 * w2) * w1 * w2,
            (x1 * x1 + y1 * y1) * w2 * w2 - (x2 * x2 + y2 * y2) * w1 * w1)


def _foot(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # s P − (lᵀP)(a, b, 0) with s = a² + b² (pgsym.metric.orthogonal_projection)
    (x, y, w), (a, b, c) = v
    s, lp = a * a + b * b, a * x + b * y + c * w
    return (s * x - lp * a, s * y - lp * b, s * w)


def _reflect_point(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # 2P − X: (2 w_X P − w_P X) over w_P w_X
    (x, y, w), (px, py, pw) = v
    return (2 * w * px - pw * x, 2 * w * py - pw * y, pw * w)


def _reflect_line(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # s X − 2 (lᵀX)(a, b, 0) with s = a² + b² (pgsym.metric.reflection)
    (x, y, w), (a, b, c) = v
    s, lx = a * a + b * b, a * x + b * y + c * w
    return (s * x - 2 * lx * a, s * y - 2 * lx * b, s * w)


def _rotate(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # O + R(X − O): with (u, v) = w_O w_X (X − O), the point (w_X O + R(u, v), w_O w_X)
    (x, y, w), (ox, oy, ow) = v
    c, s = scalar(node.data[0]), scalar(node.data[1])
    u, t = affine_vector((ox, oy, ow), (x, y, w))
    return (w * ox + c * u - s * t, w * oy + s * u + c * t, ow * w)


def _translate(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # X + (B − A) over the common denominator w_X w_A w_B
    (x, y, w), a, b = v
    u, t = affine_vector(a, b)
    return (x * a[2] * b[2] + w * u, y * a[2] * b[2] + w * t, w * a[2] * b[2])


def _similar(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # X = A + (B − A)(F − D)/(E − D) in complex numbers (ABX directly similar to DEF). With U = w_A w_B (B − A),
    # T = w_D w_F (F − D), S = w_D w_E (E − D): (F − D)/(E − D) = T S̄ w_E / (|S|² w_F), so
    # X = (w_B w_F |S|² (x_A, y_A) + w_E U T S̄, w_A w_B w_F |S|²), right for any representatives
    a, b, d, e, f = v
    (u0, u1), (t0, t1), (s0, s1) = affine_vector(a, b), affine_vector(d, f), affine_vector(d, e)
    ut0, ut1 = u0 * t0 - u1 * t1, u0 * t1 + u1 * t0
    p0, p1 = (ut0 * s0 + ut1 * s1) * e[2], (ut1 * s0 - ut0 * s1) * e[2]
    k = b[2] * f[2] * (s0 * s0 + s1 * s1)
    return (k * a[0] + p0, k * a[1] + p1, k * a[2])


def _similar_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    # the same point with complex numbers: A + (B − A)(F − D)/(E − D)
    za, zb, zd, ze, zf = (x + sympy.I * y for x, y in (p.dehomogenize() for p in a))
    if is_zero(sympy.expand(ze - zd)):
        raise CoreDegenerate("D = E at this point: the triangle DEF has no shape")
    z = sympy.expand(za + (zb - za) * sympy.radsimp((zf - zd) / (ze - zd)))
    return projective_plane.Point(*z.as_real_imag())


def _circle_centre_point(node: Any, v: list[Any], scalar: Scalar) -> Any:
    # x² + y² − 2 (O·X) w + (2 A·O − |A|²) w² with O = o/w_o, A = a/w_a, times w_o w_a²
    (ox, oy, ow), (ax, ay, aw) = v
    q = aw * aw
    f = 2 * (ax * ox + ay * oy) * aw - (ax * ax + ay * ay) * ow
    return ((ow * q, ow - ow, -ox * q), (ow - ow, ow * q, -oy * q), (-ox * q, -oy * q, f))


def _circle_centre_radius(node: Any, v: list[Any], scalar: Scalar) -> Any:
    # w_o² (x² + y²) − 2 w_o (o·X) w + (|o|² − r w_o²) w²
    (ox, oy, ow) = v[0]
    r = scalar(node.data[0])
    z = ow - ow
    return ((ow * ow, z, -ox * ow), (z, ow * ow, -oy * ow), (-ox * ow, -oy * ow, ox * ox + oy * oy - r * ow * ow))


def _circle_three(node: Any, v: list[Any], scalar: Scalar) -> Any:
    # the 4×4 determinant of the rows (x² + y², xw, yw, w²) of X, A, B, C, expanded along the row of X
    rows = [(x * x + y * y, x * w, y * w, w * w) for x, y, w in v]
    d, ex, ey, f = (alg.det([r[:j] + r[j + 1:] for r in rows]) * (1 if j % 2 == 0 else -1) for j in range(4))
    z = d - d
    return ((d + d, z, ex), (z, d + d, ey), (ex, ey, f + f))


def _centre(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # the pole of l∞: adj(K) (0, 0, 1)ᵀ (pgsym.conic_metric.center), the last column of the adjugate only; for a
    # circle ((a, 0, b), (0, a, c), (b, c, f)) that column is a·(−b, −c, a), and the point is (−b, −c, a): the same
    # point wherever a ≠ 0 (the circle's own condition), with a polynomial of lower degree for what is built on it
    k = v[0]
    if getattr(getattr(node.args[0], "operation", None), "circle", False):  # (a bare node: the general formula)
        return (-k[0][2], -k[1][2], k[0][0])
    return (k[0][1] * k[1][2] - k[0][2] * k[1][1], k[0][2] * k[1][0] - k[0][0] * k[1][2],
            k[0][0] * k[1][1] - k[0][1] * k[1][0])


def _circles_second(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # the radical axis: L₀₀ K − K₀₀ L has no x², y² terms, so it is w·(2d x + 2e y + f w); its ideal point Q
    # (direction) and A span it, and the second point of K on the line AQ is (QᵀKQ) A − 2 (AᵀKQ) Q
    k, l, a = v
    m = [[l[0][0] * k[i][j] - k[0][0] * l[i][j] for j in range(3)] for i in range(3)]
    q = (m[1][2], -m[0][2], m[0][2] - m[0][2])
    return _second_intersection(a, q, k)


def _invert(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, ...]:
    # K = a(x² + y²) + 2dxw + 2eyw + fw²: centre −(d, e)/a, r² = N/a² with N = d² + e² − af; with
    # U = (a x + d w, a y + e w) = a w (X − O), the inverse O + r² (X − O)/|X − O|² is (−(d, e)|U|² + N w U, a|U|²)
    (x, y, w), k = v
    a, d, e, f = k[0][0], k[0][2], k[1][2], k[2][2]
    ux, uy = a * x + d * w, a * y + e * w
    uu, n = ux * ux + uy * uy, d * d + e * e - a * f
    return (-d * uu + n * w * ux, -e * uu + n * w * uy, a * uu)


def _dist2(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, Any]:
    return alg.squared_distance_fraction(v[0], v[1])


def _area(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, Any]:
    # det[A B C] / (2 w_A w_B w_C) (pgsym.invariants.signed_area)
    return (alg.det(v), 2 * v[0][2] * v[1][2] * v[2][2])


def _segratio(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, Any]:
    # AB / CD for parallel segments: with u = B − A, t = D − C (u = k t), k = u·t / t·t; the vectors are
    # U/(w_A w_B) and T/(w_C w_D), so k = (U·T) w_C w_D / ((T·T) w_A w_B)
    a, b, c, d = v
    uu, tt = affine_vector(a, b), affine_vector(c, d)
    return ((uu[0] * tt[0] + uu[1] * tt[1]) * c[2] * d[2], (tt[0] * tt[0] + tt[1] * tt[1]) * a[2] * b[2])


def _ratio_arith(op: str) -> Callable[[Any, list[Any], Scalar], tuple[Any, Any]]:
    def formula(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any, Any]:
        (n1, d1), (n2, d2) = v
        if op == "mul":
            return (n1 * n2, d1 * d2)
        return (n1 * d2 + n2 * d1 if op == "add" else n1 * d2 - n2 * d1, d1 * d2)
    return formula


def _perpendicular_q(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any]:
    return (v[0][0] * v[1][0] + v[0][1] * v[1][1],)


def _parallel_q(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any]:
    return (v[0][0] * v[1][1] - v[0][1] * v[1][0],)


def _concyclic_q(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any]:
    return (alg.det([(x * x + y * y, x * w, y * w, w * w) for x, y, w in v]),)


def _equalangle_q(node: Any, v: list[Any], scalar: Scalar) -> tuple[Any]:
    # tan ∠ABC = (u × t)/(u · t) with u = A − B, t = C − B; the representatives scale u × t and u · t alike
    def cross_dot(p: Any, vertex: Any, q: Any) -> tuple[Any, Any]:
        u, t = affine_vector(vertex, p), affine_vector(vertex, q)
        return u[0] * t[1] - u[1] * t[0], u[0] * t[0] + u[1] * t[1]
    (c1, d1), (c2, d2) = cross_dot(*v[:3]), cross_dot(*v[3:])
    return (c1 * d2 - c2 * d1,)


# non-degeneracy values: each a list of polynomials, the condition holds when not all vanish
def _direction(l: Sequence[Any]) -> list[Any]:
    return [l[0] * l[0] + l[1] * l[1]]


def _finite(*points: Sequence[Any]) -> list[list[Any]]:
    return [[p[2]] for p in points]


def _distinct(p: Sequence[Any], q: Sequence[Any]) -> list[Any]:
    # P ≠ Q: the affine vector is not (0, 0); for real points the same as u² + t² ≠ 0, without its products
    # (two squares of 10⁵-term coordinates took seconds)
    u, t = affine_vector(p, q)
    return [u, t]


# the core's objects
def _conic_core(x: Any) -> conics.Conic:
    return x if isinstance(x, conics.Conic) else conics.Conic(x.matrix if hasattr(x, "matrix") else x)


def _circle_core(o: Any, r2: Any) -> conics.Conic:
    ox, oy = o.dehomogenize()
    return conics.Conic.circle(ox, oy, sympy.sqrt(r2))


def _circumcentre_core(a: Any, b: Any, c: Any) -> Any:
    def bisector(p: Any, q: Any) -> Any:
        return metric.perpendicular_line(projective_plane.join(p, q), affine.midpoint(p, q))
    return projective_plane.meet(bisector(a, b), bisector(b, c))


def _segratio_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = (p.dehomogenize() for p in a)
    u, t = (bx - ax, by - ay), (dx - cx, dy - cy)
    if is_zero(t[0]) and is_zero(t[1]):
        raise CoreDegenerate("C = D at this point: the ratio AB / CD is undefined")
    if not is_zero(sympy.expand(u[0] * t[1] - u[1] * t[0])):
        raise CoreDegenerate("the segments are not parallel at this point")
    i = 0 if not is_zero(t[0]) else 1
    return u[i] / t[i]


def _circles_second_core(node: Any, a: list[Any], exact: Scalar) -> Any:
    k, l, p = (_conic_core(a[0]), _conic_core(a[1]), a[2])
    common = conic_pencil.intersect_conics(k, l)
    points = [x for x in common if x != p and all(is_zero(e.as_real_imag()[1]) for e in x.coords)]
    if len(points) != 1:
        raise CoreDegenerate("the circles do not meet in one second real point at this point")
    return points[0]


def _sim(name: str, arg_kinds: Any, result: str, formula: Any, describe: Any, conditions: Any,
         values: Any, core: Any, group: str = "similarity", **kw: Any) -> Operation:
    return Operation(name, arg_kinds, result, formula, describe, conditions, values, core, group=group, **kw)


_C2 = ("conic",)
_EUCLIDEAN = (
    _sim("parallel", (_LINE, _POINT), "line", _parallel, lambda n, d: f"line through {n[1]} parallel to {n[0]}",
         lambda n, name, d: [f"{n[0]} is not the line at infinity", f"{n[1]} is a finite point"],
         lambda node, value, a: [_direction(a[0]), *_finite(a[1])],
         lambda node, a, exact: affine.parallel_line(*a), group="affine"),
    _sim("perpendicular", (_LINE, _POINT), "line", _perpendicular,
         lambda n, d: f"line through {n[1]} perpendicular to {n[0]}",
         lambda n, name, d: [f"{n[0]} is not the line at infinity", f"{n[1]} is a finite point"],
         lambda node, value, a: [_direction(a[0]), *_finite(a[1])],
         lambda node, a, exact: metric.perpendicular_line(*a)),
    _sim("bisector", (_POINT, _POINT), "line", _bisector, lambda n, d: f"perpendicular bisector of {n[0]}{n[1]}",
         lambda n, name, d: [f"{n[0]} ≠ {n[1]}", f"{n[0]} is a finite point", f"{n[1]} is a finite point"],
         lambda node, value, a: [_distinct(a[0], a[1]), *_finite(a[0], a[1])],
         lambda node, a, exact: metric.perpendicular_line(projective_plane.join(*a), affine.midpoint(*a))),
    _sim("foot", (_POINT, _LINE), "point", _foot, lambda n, d: f"foot of the perpendicular from {n[0]} to {n[1]}",
         lambda n, name, d: [f"{n[1]} is not the line at infinity", f"{n[0]} is a finite point"],
         lambda node, value, a: [_direction(a[1]), *_finite(a[0])],
         lambda node, a, exact: metric.orthogonal_projection(*a)),
    _sim("reflect_point", (_POINT, _POINT), "point", _reflect_point, lambda n, d: f"{n[0]} reflected in {n[1]}",
         lambda n, name, d: [f"{n[0]} is a finite point", f"{n[1]} is a finite point"],
         lambda node, value, a: _finite(a[0], a[1]),
         lambda node, a, exact: metric.scaling(-1, a[1])(a[0]), group="affine"),
    _sim("reflect_line", (_POINT, _LINE), "point", _reflect_line, lambda n, d: f"{n[0]} reflected in {n[1]}",
         lambda n, name, d: [f"{n[1]} is not the line at infinity"], lambda node, value, a: [_direction(a[1])],
         lambda node, a, exact: metric.reflect(*a)),
    _sim("rotate", (_POINT, _POINT), "point", _rotate,
         lambda n, d: f"{n[0]} rotated about {n[1]} by the angle with cos = {d[0]}, sin = {d[1]}",
         lambda n, name, d: [f"{n[0]} is a finite point", f"{n[1]} is a finite point"],
         lambda node, value, a: _finite(a[0], a[1]),
         lambda node, a, exact: metric.rotation(exact(node.data[0]), exact(node.data[1]), a[1])(a[0]),
         coefficients=True, node_group=_rotation_group),
    _sim("translate", (_POINT, _POINT, _POINT), "point", _translate,
         lambda n, d: f"{n[0]} translated by the vector {n[1]}{n[2]}",
         lambda n, name, d: [f"{x} is a finite point" for x in n], lambda node, value, a: _finite(*a),
         lambda node, a, exact: metric.translation(*(q - p for p, q in zip(a[1].dehomogenize(),
                                                                            a[2].dehomogenize(), strict=True)))(a[0]),
         group="affine"),
    _sim("similar", (_POINT,) * 5, "point", _similar,
         lambda n, d: f"the point X with {n[0]}{n[1]}X directly similar to {n[2]}{n[3]}{n[4]}",
         lambda n, name, d: [f"{n[2]} ≠ {n[3]}", *(f"{x} is a finite point" for x in n)],
         lambda node, value, a: [_distinct(a[2], a[3]), *_finite(*a)], _similar_core),
    _sim("circle", (_POINT, _POINT), "conic", _circle_centre_point,
         lambda n, d: f"circle with centre {n[0]} through {n[1]}",
         lambda n, name, d: [f"{name} has nonzero radius ({n[0]} ≠ {n[1]})", f"{n[0]} is a finite point",
                             f"{n[1]} is a finite point"],
         lambda node, value, a: [_distinct(a[0], a[1]), *_finite(a[0], a[1])],
         lambda node, a, exact: _circle_core(a[0], metric.squared_distance(a[0], a[1])), through=(1,), circle=True),
    _sim("circle_radius", (_POINT,), "conic", _circle_centre_radius,
         lambda n, d: f"circle with centre {n[0]} and squared radius {d[0]}",
         lambda n, name, d: [f"{name} has nonzero radius ({d[0]} ≠ 0)", f"{n[0]} is a finite point"],
         lambda node, value, a: [[value[2][2] * value[0][0] - value[0][2] * value[0][2] - value[1][2] * value[1][2]],
                                 *_finite(a[0])],
         lambda node, a, exact: _circle_core(a[0], exact(node.data[0])), coefficients=True,
         node_group=_radius_group, circle=True),
    _sim("circle3", (_POINT,) * 3, "conic", _circle_three, lambda n, d: f"circle through {', '.join(n)}",
         lambda n, name, d: [f"{', '.join(n)} are finite and not collinear"],
         lambda node, value, a: [[value[0][0]]],
         lambda node, a, exact: _circle_core(_circumcentre_core(*a),
                                             metric.squared_distance(_circumcentre_core(*a), a[0])),
         through=(0, 1, 2), circle=True),
    _sim("centre", (_C2,), "point", _centre, lambda n, d: f"centre of {n[0]} (the pole of l∞)",
         lambda n, name, d: [f"{n[0]} has a finite centre (it is no parabola)"],
         lambda node, value, a: [[value[2]]],
         lambda node, a, exact: conic_metric.center(_conic_core(a[0])), group="affine"),
    _sim("circles_second", (_C2, _C2, _POINT), "point", _circles_second,
         lambda n, d: f"second common point of {n[0]} and {n[1]} through {n[2]}",
         lambda n, name, d: [f"{n[0]} and {n[1]} are not concentric ({n[2]} must lie on both)"],
         lambda node, value, a: [[a[1][0][0] * a[0][i][2] - a[0][0][0] * a[1][i][2] for i in range(2)]],
         _circles_second_core),
    _sim("invert", (_POINT, _C2), "point", _invert, lambda n, d: f"inverse of {n[0]} in {n[1]}",
         lambda n, name, d: [f"{n[0]} is not the centre of {n[1]}", f"{n[1]} has nonzero radius"],
         lambda node, value, a: [[value[2]], [a[1][0][2] ** 2 + a[1][1][2] ** 2 - a[1][0][0] * a[1][2][2]]],
         lambda node, a, exact: conic_metric.inversion(a[0], _conic_core(a[1]))),
    _sim("dist2", (_POINT, _POINT), "ratio", _dist2, lambda n, d: f"|{n[0]}{n[1]}|²",
         lambda n, name, d: [f"{n[0]} and {n[1]} are finite points"], lambda node, value, a: [[value[1]]],
         lambda node, a, exact: metric.squared_distance(*a), ratio_scaling=(0, 2)),
    _sim("area", (_POINT,) * 3, "ratio", _area, lambda n, d: f"signed area of {''.join(n)}",
         lambda n, name, d: [f"{', '.join(n)} are finite points"], lambda node, value, a: [[value[1]]],
         lambda node, a, exact: invariants.signed_area(*(p.coords for p in a)), group="affine",
         ratio_scaling=(1, 0)),
    _sim("segratio", (_POINT,) * 4, "ratio", _segratio, lambda n, d: f"{n[0]}{n[1]} / {n[2]}{n[3]}",
         lambda n, name, d: [f"{n[2]} ≠ {n[3]} and {n[0]}, {n[1]} are finite points"],
         lambda node, value, a: [[value[1]]], _segratio_core, ratio_scaling=(0, 0)),
    *(_sim(op, (("ratio",), ("ratio",)), "ratio", _ratio_arith(op), lambda n, d, s=sign: f"{n[0]} {s} {n[1]}",
           lambda n, name, d: [], None, lambda node, a, exact, op=op: (a[0] + a[1] if op == "add" else
                                                                      a[0] - a[1] if op == "sub" else a[0] * a[1]),
           group="projective", ratio_arithmetic="product" if op == "mul" else "sum")
      for op, sign in (("add", "+"), ("sub", "−"), ("mul", "·"))),
    # conclusion quantities
    _sim("perpendicular_to", (_LINE, _LINE), "scalar", _perpendicular_q, lambda n, d: f"{n[0]}ᵀ C*∞ {n[1]}",
         lambda n, name, d: [], None, None, constructible=False, conclusion=True),
    _sim("parallel_to", (_LINE, _LINE), "scalar", _parallel_q, lambda n, d: f"[{n[0]}, {n[1]}, l∞]",
         lambda n, name, d: [], None, None, group="affine", constructible=False, conclusion=True),
    _sim("concyclic", (_POINT,) * 4, "scalar", _concyclic_q,
         lambda n, d: f"det of the rows (x² + y², xw, yw, w²) of {', '.join(n)}",
         # four points of one line make the determinant vanish too: "concyclic" is then no statement about a circle
         lambda n, name, d: [f"{', '.join(n)} do not all lie on one line"],
         lambda node, value, a: [[alg.det(list(t)) for t in itertools.combinations(a, 3)]], None,
         constructible=False, conclusion=True),
    _sim("equal_angle", (_POINT,) * 6, "scalar", _equalangle_q,
         lambda n, d: f"tan ∠{''.join(n[:3])} − tan ∠{''.join(n[3:])} (numerators)",
         lambda n, name, d: [f"{n[1]} ≠ {n[0]}", f"{n[1]} ≠ {n[2]}", f"{n[4]} ≠ {n[3]}", f"{n[4]} ≠ {n[5]}"],
         lambda node, value, a: [_distinct(a[1], a[0]), _distinct(a[1], a[2]), _distinct(a[4], a[3]),
                                 _distinct(a[4], a[5])],
         None, constructible=False, conclusion=True),
)
_TABLE += _EUCLIDEAN

#: the names of the Euclidean operations (constructions and conclusion quantities relative to the absolute)
EUCLIDEAN_OPERATIONS = tuple(op.name for op in _EUCLIDEAN)

#: every operation by name, in the order of the table
OPERATIONS: dict[str, Operation] = {op.name: op for op in _TABLE}


def operation(name: str) -> Operation | None:
    """The operation of that name or alias (``None`` when there is none).

    >>> operation("apply_plane").name
    'apply_line'
    """
    op = OPERATIONS.get(name)
    if op is None:
        op = next((o for o in _TABLE if name in o.aliases), None)
    return op


def constructions() -> list[str]:
    """The names (and aliases) a claim can build with :meth:`~pgsym.proofs.claims.Claim.construct`.

    >>> "join" in constructions(), "free" in constructions()
    (True, False)
    """
    return [n for op in _TABLE if op.constructible for n in (op.name, *op.aliases)]
