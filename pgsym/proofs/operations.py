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
>>> sorted(n for n, op in OPERATIONS.items() if not op.constructible)
['const', 'free']
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


# -- non-degeneracy ---------------------------------------------------------------------------------------

def _det_of_first(node: Any, value: Any, args: list[Any]) -> list[list[Any]]:
    """The matrix (first argument) is non-singular: its determinant is not zero."""
    return [[alg.det(args[0])]]


def _free_conditions(node: Any, value: Any, args: list[Any]) -> list[list[Any]]:
    # a free matrix declared invertible needs det ≠ 0; nothing else of a free object carries a condition
    return [[alg.det(value)]] if node.kind == "matrix" else [flat(value)] * len(node.conditions)


def _nonsingular(names: list[str], name: str, data: Any) -> list[str]:
    return [f"{names[0]} is non-singular (det {names[0]} ≠ 0)"]


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
              core=lambda node, a, exact: conics.Conic(a[0]).polar(a[1])),
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
