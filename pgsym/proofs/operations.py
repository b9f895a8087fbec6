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

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

from sympy import Matrix

from .. import conics, plucker, projective_line, projective_plane, space
from .. import ring as alg
from ..exact import is_zero
from ..homogeneous import HomogeneousVector
from ..kinds import object_classes

__all__ = ["KINDS", "OPERATIONS", "CoreDegenerate", "Operation", "constructions", "flat", "operation"]

# Proofs carry a line of P³ as its 4×4 Plücker matrix (the wedge of two points), not as the six
# Plücker coordinates of the Line3 class, so its size here is that of a matrix.
_MATRIX_FORM = ("line3",)

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
      arguments by any homography maps the result by it; ``"affine"``, ``"similarity"`` for constructions
      that use l∞ or the circular points), or ``None`` when its value depends on the representatives or on
      data the group does not act on (``combine`` with coefficients, a matrix applied, a formula). Choosing
      coordinates without loss of generality is allowed only under a group every construction commutes with.
      A construction with a free parameter (a point on a line or on a conic) counts as commuting when the
      homography maps the family of its values onto the family for the mapped arguments (the parameter changes
      by an invertible substitution), since a generic statement then holds for one family exactly when for the
      other;
    * ``conclusion``: the value is a quantity of a conclusion (zero exactly when the statement holds, e.g. the
      reciprocal product of two lines that meet), so it vanishes identically on a true claim and is never a
      degenerate construction.
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
    return (t ** 0, t, t * t)


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


# -- the table -------------------------------------------------------------------------------------------

_POINT, _LINE, _POINT1, _POINT3, _PLANE = ("point",), ("line",), ("point1",), ("point3",), ("plane",)

_TABLE = (
    Operation("free", (), "free", _free_value, lambda n, d: "", condition_values=_free_conditions, core=_free_core,
              coefficients=True, constructible=False),
    Operation("const", (), "ratio", lambda node, v, scalar: (scalar(node.data[0]), scalar(node.data[1])),
              lambda n, d: "", coefficients=True, constructible=False),
    Operation("join", (_POINT, _POINT), "line", lambda node, v, scalar: alg.cross(v[0], v[1]),
              lambda n, d: f"{n[0]} × {n[1]}", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: projective_plane.join(*a)),
    Operation("meet", (_LINE, _LINE), "point", lambda node, v, scalar: alg.cross(v[0], v[1]),
              lambda n, d: f"{n[0]} × {n[1]}", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: projective_plane.meet(*a)),
    Operation("combine", (_VECTOR_KINDS, _VECTOR_KINDS), 0, _combine,
              lambda n, d: f"{d[0]}·{n[0]} + {d[1]}·{n[1]}",
              lambda n, name, d: [f"{name} is not the zero vector ({n[0]} ≠ {n[1]})"],
              core=_combine_core, same_kind=True, coefficients=True, group=None),
    Operation("plane_through", (_POINT3,) * 3, "plane", lambda node, v, scalar: alg.plane_through(*v),
              lambda n, d: f"plane({', '.join(n)})", lambda n, name, d: [f"{', '.join(n)} are not collinear"],
              core=lambda node, a, exact: space.plane_through(*a)),
    Operation("point_on_planes", (_PLANE,) * 3, "point3", lambda node, v, scalar: alg.plane_through(*v),
              lambda n, d: f"point({', '.join(n)})", lambda n, name, d: [f"{', '.join(n)} do not share a line"],
              core=lambda node, a, exact: space.point_on_planes(*a)),
    Operation("line3", (_POINT3, _POINT3), "line3", lambda node, v, scalar: alg.wedge(v[0], v[1]),
              lambda n, d: f"{n[0]} {n[1]}ᵀ − {n[1]} {n[0]}ᵀ", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: plucker.Line3.join(*a)),
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
              aliases=("tangent",)),
    Operation("conic_through", (_POINT,) * 5, "conic", lambda node, v, scalar: _conic_from_points(v),
              lambda n, d: f"conic({', '.join(n)})",
              lambda n, name, d: [f"{', '.join(n)} determine a unique conic (no two equal, no four collinear)"],
              core=lambda node, a, exact: conics.conic_through(*a)),
    Operation("dual_conic", (("conic",),), "matrix", lambda node, v, scalar: alg.adjugate(v[0]),
              lambda n, d: f"adj({n[0]})", lambda n, name, d: [f"{n[0]} is non-degenerate (det {n[0]} ≠ 0)"],
              _det_of_first, core=lambda node, a, exact: conics.Conic(a[0]).dual()),
    Operation("cross_ratio", (_POINT1,) * 4, "ratio", _cross_ratio, lambda n, d: f"({n[0]}, {n[1]}; {n[2]}, {n[3]})",
              lambda n, name, d: [f"[{n[0]} {n[3]}][{n[1]} {n[2]}] ≠ 0 ({n[0]} ≠ {n[3]} and {n[1]} ≠ {n[2]})"],
              lambda node, value, args: [[value[1]]],
              core=lambda node, a, exact: projective_line.cross_ratio(*a)),
    Operation("harmonic_conjugate", (_POINT1,) * 3, "point1", _harmonic_conjugate,
              lambda n, d: f"[{n[0]} {n[2]}] {n[1]} + [{n[1]} {n[2]}] {n[0]}",
              lambda n, name, d: [f"{', '.join(n)} are distinct"],
              core=lambda node, a, exact: projective_line.harmonic_conjugate(*a)),
    Operation("second_intersection", (("conic",), _POINT, _POINT), "point",
              lambda node, v, scalar: _second_intersection(v[1], v[2], v[0]),
              lambda n, d: f"({n[2]}ᵀ{n[0]}{n[2]}) {n[1]} − 2 ({n[1]}ᵀ{n[0]}{n[2]}) {n[2]}",
              lambda n, name, d: [f"{n[1]} ≠ {n[2]} ({name} is the second point of {n[0]} on the line {n[1]}{n[2]}; "
                                  f"{n[1]} must lie on {n[0]})"],
              core=_second_core),
    Operation("point_on_conic", (("conic",), _POINT), "point", _conic_point,
              lambda n, d: f"second point of {n[0]} on the line through {n[1]} and (1, {d[0]}, {d[0]}²)",
              lambda n, name, d: [f"{name} is defined ({n[1]} lies on {n[0]}, the line through it is no tangent)"],
              core=_conic_point_core, coefficients=True),
    Operation("point_on_line", (("point", "point3"), ("point", "point3")), 0,
              lambda node, v, scalar: tuple(a + scalar(node.data[0]) * b for a, b in zip(v[0], v[1], strict=True)),
              lambda n, d: f"{n[0]} + {d[0]}·{n[1]}", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              lambda node, value, args: [_pairs(args[0], args[1])],
              core=lambda node, a, exact: _vector(node.kind, (x + exact(node.data[0]) * y
                                                              for x, y in zip(a[0].coords, a[1].coords, strict=True))),
              same_kind=True, coefficients=True),
    Operation("point_of_line", (_LINE,), "point",
              lambda node, v, scalar: alg.cross(v[0], _moment(scalar(node.data[0]))),
              lambda n, d: f"{n[0]} × (1, {d[0]}, {d[0]}²)", lambda n, name, d: [f"{name} is a point of {n[0]}"],
              core=lambda node, a, exact: projective_plane.meet(
                  a[0], projective_plane.Line(*_moment(exact(node.data[0])))),
              coefficients=True),
    Operation("conic_tangent_to", (_LINE,) * 5, "conic", _conic_tangent_to,
              lambda n, d: f"adj(dual conic({', '.join(n)}))",
              lambda n, name, d: [f"{', '.join(n)} are tangent to a unique non-degenerate conic "
                                  "(no two equal, no three concurrent)"],
              core=_tangent_to_core),
    Operation("line_meets_plane", (("line3",), _PLANE), "point3", lambda node, v, scalar: alg.matvec(v[0], v[1]),
              lambda n, d: f"{n[0]} {n[1]}", lambda n, name, d: [f"{n[0]} does not lie in {n[1]}"],
              core=lambda node, a, exact: a[0].intersect_plane(a[1])),
    Operation("line_of_planes", (_PLANE, _PLANE), "line3", _line_of_planes_formula,
              lambda n, d: f"({n[0]} {n[1]}ᵀ − {n[1]} {n[0]}ᵀ)*", lambda n, name, d: [f"{n[0]} ≠ {n[1]}"],
              core=lambda node, a, exact: plucker.Line3.meet(*a)),
    Operation("cross_ratio_collinear", (("point", "line"),) * 4, "ratio", _cross_ratio2,
              lambda n, d: f"({n[0]}, {n[1]}; {n[2]}, {n[3]})",
              lambda n, name, d: [f"{n[0]} ≠ {n[3]}, {n[1]} ≠ {n[2]} and {n[0]} ≠ {n[1]} "
                                  f"({', '.join(n)} collinear or concurrent)"],
              lambda node, value, args: [[value[1]]], core=_cross_ratio2_core, same_kind=True),
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
