"""Invariants of the transformation classes: proofs by the claim engine, explicit counterexamples, the summary table.

An :class:`Invariant` is a quantity (or a relation, whose quantity is zero) attached to a configuration of
objects. It is *invariant* under a class when its value on the transformed configuration equals its value on
the original one for every member of the class. :meth:`Invariant.prove` states this as a
:class:`~pgsym.proofs.claims.Claim` for each component of the class — the class's generic element ``H`` (the
hierarchy's own parametrisation, denominators cleared), a generic configuration whose objects map by their own
``image`` rules, and the conclusion that every value after equals the value before — and hands it to the proof
engine (:func:`pgsym.proofs.engine.prove`): the random pass, then the exact expansion. Each invariant that is
new in its class also carries an explicit exact member of the next larger class and an exact configuration on
which the quantity changes: :meth:`Invariant.counterexample`.

The summary table of the hierarchy (:func:`summary_table`) is assembled from these results and from the
derived DoF; nothing in it is typed in.

>>> inv = invariant("angle")
>>> inv.prove().holds
True
>>> ce = inv.counterexample()
>>> ce.before, ce.after, ce.transformation_class
([0], [1/2], 'Affine')
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy
from sympy.polys.rings import ring

from .. import ring as alg
from ..conics import Conic, DualConic
from ..errors import DegenerateConfigurationError, ObjectTypeError
from ..exact import is_zero
from ..hierarchy import CLASSES_2D, CLASSES_3D, TransformationClass, class_by_key, classify
from ..invariants import (
    collinear_cross_ratio_fraction,
    cos2_angle_fraction,
    signed_area_fraction,
    signed_volume_fraction,
)
from ..projective_plane import Line, Point
from ..quadrics import DualQuadric
from ..space import Plane, Point3
from .claims import Claim, Node
from .engine import prove as prove_claim
from .operations import KINDS, affine_vector
from .verdicts import Verdict

__all__ = [
    "INVARIANTS",
    "InvarianceCounterexample",
    "Invariant",
    "Proof",
    "class_matrix",
    "invariance_claim",
    "invariant",
    "invariants_of",
    "summary_markdown",
    "summary_table",
    "transformed",
]

Pair = tuple[Any, Any]  # a value as numerator and denominator
Config = list[tuple[type, Any]]  # (class of the object, its coordinates or matrix)
New = Callable[[], Any]


def transformed(H: Sequence[Sequence[Any]], config: Config) -> Config:
    """The configuration's image under the matrix ``H``: each object by its class's ``image`` rule, in any ring.

    >>> transformed([[2, 0, 0], [0, 2, 0], [0, 0, 1]], [(Point, (1, 1, 1)), (Line, (1, 0, -1))])
    [(<class 'pgsym.projective_plane.Point'>, (2, 2, 1)), (<class 'pgsym.projective_plane.Line'>, (2, 0, -4))]
    """
    action = alg.Action(H)
    return [(cls, cls.image(data, action)) for cls, data in config]


# -- configurations (generic when ``new`` yields symbols; concrete when it yields numbers) ---------------------
def _point(dim: int) -> type:
    return Point if dim == 2 else Point3


def _hyperplane(dim: int) -> type:
    return Line if dim == 2 else Plane


def _c_points(k: int, dim: int) -> Callable[[New], Config]:
    return lambda new: [(_point(dim), (*(new() for _ in range(dim)), 1)) for _ in range(k)]


def _c_lines(k: int, dim: int) -> Callable[[New], Config]:
    return lambda new: [(_hyperplane(dim), tuple(new() for _ in range(dim + 1))) for _ in range(k)]


def _c_parallel_lines(new: New) -> Config:
    a, b, c, d = new(), new(), new(), new()
    return [(Line, (a, b, c)), (Line, (a, b, d))]


def _c_parallel_planes(new: New) -> Config:
    a, b, c, d, e = new(), new(), new(), new(), new()
    return [(Plane, (a, b, c, d)), (Plane, (a, b, c, e))]


def _c_parallel_segments(new: New) -> Config:
    p, q, r = ((new(), new(), 1) for _ in range(3))
    mu = new()
    s = (r[0] + mu * (q[0] - p[0]), r[1] + mu * (q[1] - p[1]), 1)
    return [(Point, p), (Point, q), (Point, r), (Point, s)]


def _span(cls: type, new: New) -> Config:
    x, y = tuple(new() for _ in range(3)), tuple(new() for _ in range(3))
    s, t = new(), new()
    return [(cls, x), (cls, y), (cls, tuple(s * a + t * b for a, b in zip(x, y, strict=True)))]


def _c_four_on_a_line(new: New) -> Config:
    a = [new(), new(), new()]
    b = [new(), new(), new()]
    lams = [new() for _ in range(4)]
    return [(Point, tuple(x + lam * y for x, y in zip(a, b, strict=True))) for lam in lams]


def _c_incident(new: New) -> Config:
    l = (new(), new(), new())
    v = (new(), new(), new())
    return [(Point, alg.cross(l, v)), (Line, l)]


def _c_tangent(new: New) -> Config:
    # a point x and a conic C through x (c22 solved from xᵀCx = 0, the conic scaled by x₃² to stay polynomial),
    # with the tangent line C x
    x = (new(), new(), new())
    c00, c01, c02, c11, c12 = (new() for _ in range(5))
    w2 = x[2] * x[2]
    rest = c00 * x[0] * x[0] + 2 * c01 * x[0] * x[1] + c11 * x[1] * x[1] + 2 * c02 * x[0] * x[2] + 2 * c12 * x[1] * x[2]
    C = ((c00 * w2, c01 * w2, c02 * w2), (c01 * w2, c11 * w2, c12 * w2), (c02 * w2, c12 * w2, -rest))
    return [(Point, x), (Conic, C), (Line, alg.matvec(C, x))]


def _c_coplanar(new: New) -> Config:
    p, q, r = (tuple(new() for _ in range(4)) for _ in range(3))
    s, t, u = new(), new(), new()
    return [(Point3, p), (Point3, q), (Point3, r),
            (Point3, tuple(s * a + t * b + u * c for a, b, c in zip(p, q, r, strict=True)))]


def _c_point_in_plane(new: New) -> Config:
    # the plane (a, b, c, d) through x with d solved from πᵀx = 0, scaled by x₄ to stay polynomial
    x = tuple(new() for _ in range(4))
    a, b, c = new(), new(), new()
    return [(Point3, x), (Plane, (a * x[3], b * x[3], c * x[3], -(a * x[0] + b * x[1] + c * x[2])))]


def _c_fixed(cls: type, data: Any) -> Callable[[New], Config]:
    exact = (tuple(tuple(sympy.Integer(e) for e in row) for row in data) if isinstance(data[0], list)
             else tuple(sympy.Integer(e) for e in data))
    return lambda new: [(cls, exact)]


# -- quantities: numerator and denominator, any ring, no division --------------------------------------------
def _data(config: Config) -> list[Any]:
    return [d for _, d in config]


def _over(r: Pair, s: Pair) -> Pair:
    return r[0] * s[1], r[1] * s[0]


def _v_dist(c: Config) -> list[Pair]:
    return [alg.squared_distance_fraction(*_data(c))]


def _v_area2(c: Config) -> list[Pair]:
    n, d = signed_area_fraction(*_data(c))
    return [(n * n, d * d)]


def _v_area(c: Config) -> list[Pair]:
    return [signed_area_fraction(*_data(c))]


def _v_volume(c: Config) -> list[Pair]:
    return [signed_volume_fraction(*_data(c))]


def _v_cos2(c: Config) -> list[Pair]:
    return [cos2_angle_fraction(*_data(c))]


def _v_length_ratio(c: Config) -> list[Pair]:
    p, q, r, s = _data(c)
    return [_over(alg.squared_distance_fraction(p, q), alg.squared_distance_fraction(r, s))]


def _v_area_ratio(c: Config) -> list[Pair]:
    d = _data(c)
    return [_over(signed_area_fraction(*d[:3]), signed_area_fraction(*d[3:]))]


def _v_volume_ratio(c: Config) -> list[Pair]:
    d = _data(c)
    return [_over(signed_volume_fraction(*d[:4]), signed_volume_fraction(*d[4:]))]


def _v_parallel_ratio(c: Config) -> list[Pair]:
    # u = q − p = U / (p₃q₃) and w = s − r = W / (r₃s₃) in affine coordinates: (w·u)/(u·u) and the 2×2 bracket
    p, q, r, s = _data(c)
    U, W = affine_vector(p, q), affine_vector(r, s)
    return [(alg.dot(W, U) * p[2] * q[2], alg.dot(U, U) * r[2] * s[2]),
            (U[0] * W[1] - U[1] * W[0], p[2] * q[2] * r[2] * s[2])]


def _v_meet_at_infinity(c: Config) -> list[Pair]:
    l, m = _data(c)
    return [(alg.cross(l, m)[2], 1)]


def _v_normals_parallel(c: Config) -> list[Pair]:
    l, m = _data(c)
    return [(x, 1) for x in alg.cross(l[:3], m[:3])]


def _v_at_infinity(c: Config) -> list[Pair]:
    (l,) = _data(c)
    return [(x, l[-1]) for x in l[:-1]]


def _v_absolute(c: Config) -> list[Pair]:
    (D,) = _data(c)
    n = len(D)
    return [(D[i][j], D[0][0]) for i in range(n) for j in range(i, n) if (i, j) != (0, 0)]


def _v_det(c: Config) -> list[Pair]:
    return [(alg.det(alg.transpose(_data(c))), 1)]


def _v_cross_ratio(c: Config) -> list[Pair]:
    return [collinear_cross_ratio_fraction(*_data(c))]


def _v_incidence(c: Config) -> list[Pair]:
    x, l = _data(c)
    return [(alg.dot(l, x), 1)]


def _v_tangency(c: Config) -> list[Pair]:
    x, C, l = _data(c)
    cx = alg.matvec(C, x)
    return [(alg.dot(x, cx), 1), *((e, 1) for e in alg.cross(cx, l))]


# -- the generic element of a class as a claim's matrix --------------------------------------------------------
def class_matrix(c: Claim, group: TransformationClass, names: str = "",
                 component: int = 0) -> tuple[sympy.Matrix, tuple[sympy.Symbol, ...]]:
    """The generic element of a class of the hierarchy with denominators cleared, and its parameters.

    The parametrisation is the hierarchy's own (:attr:`~pgsym.hierarchy.TransformationClass.builder`:
    rotations by ``rotation_2d`` / ``rotation_3d``; ``component`` picks e.g. the improper isometries); its
    parameters are declared on the claim, under ``names`` (space-separated, in the order of
    ``group.parameter_names``; default those names). The rotations have rational entries, so the element is
    multiplied by their common denominator: the same projective transformation, with polynomial entries as a
    claim needs.

    >>> from pgsym.hierarchy import EUCLIDEAN_2D
    >>> M, ps = class_matrix(Claim("x", "x"), EUCLIDEAN_2D)
    >>> M.row(2), ps
    (Matrix([[0, 0, t**2 + 1]]), (t, t_x, t_y))
    """
    params = c.params(names or " ".join(group.parameter_names))
    if len(params) != group.n_parameters:
        raise ObjectTypeError(f"{group.name} has {group.n_parameters} parameters, got the names {names!r}")
    R, *gens = ring(params, sympy.ZZ)
    built = group.builder([alg.Quotient(g) for g in gens], component)
    entries = [[alg.Quotient.of(e) for e in row] for row in built]
    dens: list[Any] = []
    for e in (e for row in entries for e in row):
        if e.d != 1 and all(e.d != d for d in dens):
            dens.append(e.d)
    den = functools.reduce(lambda x, y: x * y, dens, R.one)
    # entries without a denominator are taken as they are (most classes have none: no division at all)
    rows = [[(R(e.n) * (den if e.d == 1 else den.exquo(R(e.d)))).as_expr() for e in row] for row in entries]
    return sympy.Matrix(rows), params


# -- invariants ----------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Proof:
    """The outcome of :meth:`Invariant.prove`: ``holds`` when the engine proved the claim of every component.

    ``terms`` is the size (number of terms) of the largest polynomial the proofs expanded; ``verdicts`` are the
    engine's verdicts, one for each component of the class.
    """

    key: str
    transformation_class: str
    holds: bool
    components: int
    terms: int = 0
    verdicts: tuple[Verdict, ...] = field(default=(), repr=False, compare=False)


@dataclass(frozen=True)
class InvarianceCounterexample:
    """A member ``matrix`` of the next larger class and a configuration on which the quantity changes."""

    key: str
    transformation_class: str
    matrix: sympy.ImmutableMatrix
    before: list[Any]
    after: list[Any]

    @property
    def fails(self) -> bool:
        """True when some value changed, i.e. the counterexample is genuine."""
        return any(not is_zero(sympy.sympify(a - b)) for a, b in zip(self.after, self.before, strict=True))


@dataclass(frozen=True)
class Invariant:
    """A quantity preserved by every member of the class ``cls`` (a class key).

    ``configuration(new)`` builds the objects, as ``(class, coordinates)`` pairs, from scalars supplied by
    ``new()`` (symbols for the proof, numbers for examples); ``value`` maps a configuration to a list of
    values, each a pair (numerator, denominator) of ring elements. ``counter`` is ``(matrix, values)``: a
    member of the next larger class and the numbers that ``new()`` yields for the counterexample
    configuration (``None`` for invariants of the largest class).
    """

    key: str
    name: str
    cls: str
    statement: str
    configuration: Callable[[New], Config] = field(repr=False)
    value: Callable[[Config], list[Pair]] = field(repr=False)
    counter: tuple[list[list[int]], list[Any]] | None = field(default=None, repr=False, compare=False)

    @property
    def transformation_class(self) -> TransformationClass:
        """The class for which the invariant is proved."""
        return class_by_key(self.cls)

    @property
    def dim(self) -> int:
        """2 or 3."""
        return self.transformation_class.dim

    def evaluate(self, H: Any, values: Sequence[Any]) -> tuple[list[Any], list[Any]]:
        """The quantity before and after applying the matrix ``H`` to the configuration built from ``values``.

        A value whose denominator vanishes (an ideal point where a distance is asked, a line at infinity where
        an angle is) raises :class:`~pgsym.errors.DegenerateConfigurationError`.

        >>> invariant("length").evaluate([[2, 0, 0], [0, 2, 0], [0, 0, 1]], [0, 0, 3, 4])
        ([25], [100])
        """
        rows = [[sympy.sympify(e) for e in r] for r in (H.tolist() if hasattr(H, "tolist") else H)]
        it = iter([sympy.sympify(v) for v in values])
        config = self.configuration(lambda: next(it))
        return self._values(config), self._values(transformed(rows, config))

    def _values(self, config: Config) -> list[Any]:
        out = []
        for n, d in self.value(config):
            if is_zero(sympy.sympify(d)):
                raise DegenerateConfigurationError(
                    f"{self.name} is undefined for this configuration (a denominator vanishes: an ideal point, a "
                    "line or plane at infinity, or coincident objects); choose objects in general position")
            out.append(sympy.sympify(n) / d)
        return out

    def claim(self, component: int = 0) -> Claim:
        """The claim that the quantity is invariant under the class (one component of it): :func:`invariance_claim`."""
        return invariance_claim(self, component)

    def prove(self) -> Proof:
        """Prove the invariance exactly for the generic element (every component) of the class, by the engine."""
        return _prove(self)

    def counterexample(self) -> InvarianceCounterexample | None:
        """The explicit member of the next larger class that changes the quantity (None at the top)."""
        if self.counter is None:
            return None
        H, values = self.counter
        before, after = self.evaluate(H, values)
        return InvarianceCounterexample(self.key, classify(H).name, sympy.ImmutableMatrix(H), before, after)


def _free(claim: Claim, cls: type, name: str, data: Any) -> Node:
    """A free object of the claim with the configuration's coordinates (a form the claims have no kind for is a
    matrix)."""
    if isinstance(data[0], (list, tuple)):
        return claim.conic(name, data) if cls.kind in KINDS else claim.matrix(name, data)
    return getattr(claim, cls.kind)(name, *data)  # the claim's constructor is named after the kind


def _image(cls: type, h: Any, x: Any) -> Any:
    return cls.image(x, alg.Action(h))


def _zero(value: Any) -> Any:
    while isinstance(value, (tuple, list)):
        value = value[0]
    return value * 0


def _value(value: Callable[[Config], list[Pair]], classes: Sequence[type], i: int, *data: Any) -> Pair:
    n, d = value(list(zip(classes, data, strict=True)))[i]
    zero = _zero(data)  # numbers such as the 1 of a denominator become elements of the claim's ring
    return n + zero, d + zero


def invariance_claim(inv: Invariant, component: int = 0) -> Claim:
    """The claim that ``inv`` is unchanged by the generic element ``H`` of its class (the given component).

    The configuration's scalars are the parameters ``z0, z1, …``; each object ``Xi`` has the image ``Xi'`` by its
    class's ``image`` rule, and the conclusion says that each value of the quantity on the images equals its
    value on the objects.

    >>> c = invariance_claim(invariant("length"), 1)
    >>> c.title, [k.text for k in c.conclusions]
    ('length is invariant under the class Isometry (reflection)', ["q1' = q1"])
    """
    group = inv.transformation_class
    part = group.components[component]
    title = f"{inv.name} is invariant under the class {group.name}" + (f" ({part})" if part else "")
    claim = Claim(f"{inv.key}-under-{group.key}" + (f"-{component}" if component else ""), title, inv.statement)
    H = claim.matrix("H", class_matrix(claim, group, component=component)[0], invertible=True)
    made: list[sympy.Symbol] = []

    def new() -> sympy.Symbol:
        (z,) = claim.params(f"z{len(made)}")
        made.append(z)
        return z

    config = inv.configuration(new)
    classes = [cls for cls, _ in config]
    before, after = [], []
    for i, (cls, data) in enumerate(config, start=1):
        node = _free(claim, cls, f"X{i}", data)
        before.append(node)
        after.append(claim.formula(f"X{i}'", node.kind, functools.partial(_image, cls), H, node,
                                   description=f"the image of X{i} under H"))
    names = ", ".join(n.name for n in before)
    for i in range(len(inv.value(config))):
        compute = functools.partial(_value, inv.value, classes, i)
        q = claim.formula(f"q{i + 1}", "ratio", compute, *before, description=f"{inv.name} of {names}")
        q2 = claim.formula(f"q{i + 1}'", "ratio", compute, *after, description=f"{inv.name} of their images")
        claim.conclude_equal_ratio(q2, q)
    return claim


@functools.cache
def _prove(inv: Invariant) -> Proof:
    group = inv.transformation_class
    verdicts = tuple(prove_claim(invariance_claim(inv, k), timeout=60.0) for k in range(len(group.components)))
    terms = max((v.certificate.largest_terms for v in verdicts if v.certificate is not None), default=0)
    return Proof(inv.key, group.name, all(v.proved for v in verdicts), len(group.components), terms, verdicts)


_SCALE2 = [[2, 0, 0], [0, 2, 0], [0, 0, 1]]
_REFLECT2 = [[1, 0, 0], [0, -1, 0], [0, 0, 1]]
_SHEAR2 = [[1, 1, 0], [0, 1, 0], [0, 0, 1]]
_PERSP2 = [[1, 0, 0], [0, 1, 0], [0, 1, 1]]
_SCALE3 = [[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 1]]
_REFLECT3 = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]]
_SHEAR3 = [[1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
_PERSP3 = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 1, 0, 1]]

INVARIANTS: tuple[Invariant, ...] = (
    # 2D
    Invariant("orientation", "orientation (signed area)", "euclidean2",
              "the signed area of a triangle, hence its orientation", _c_points(3, 2), _v_area,
              (_REFLECT2, [0, 0, 1, 0, 0, 1])),
    Invariant("length", "length", "isometry2", "the distance between two points", _c_points(2, 2), _v_dist,
              (_SCALE2, [0, 0, 3, 4])),
    Invariant("area", "area", "isometry2", "the area of a triangle", _c_points(3, 2), _v_area2,
              (_SCALE2, [0, 0, 1, 0, 0, 1])),
    Invariant("angle", "angle", "similarity2", "the angle between two lines", _c_lines(2, 2), _v_cos2,
              (_SHEAR2, [1, 0, 0, 0, 1, 0])),
    Invariant("length-ratio", "ratio of lengths", "similarity2", "the ratio of two distances",
              _c_points(4, 2), _v_length_ratio, (_SHEAR2, [0, 0, 1, 0, 0, 0, 0, 1])),
    Invariant("circular-points", "circular points", "similarity2",
              "the dual conic C*∞ = diag(1, 1, 0) of the circular points, up to scale",
              _c_fixed(DualConic, [[1, 0, 0], [0, 1, 0], [0, 0, 0]]), _v_absolute, (_SHEAR2, [])),
    Invariant("parallelism", "parallelism", "affine2", "parallel lines stay parallel",
              _c_parallel_lines, _v_meet_at_infinity, (_PERSP2, [1, 0, 0, -1])),
    Invariant("area-ratio", "ratio of areas", "affine2", "the ratio of the areas of two triangles",
              _c_points(6, 2), _v_area_ratio, (_PERSP2, [0, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2])),
    Invariant("parallel-length-ratio", "ratio of lengths on parallel lines", "affine2",
              "the ratio of the lengths of two parallel segments", _c_parallel_segments, _v_parallel_ratio,
              (_PERSP2, [0, 0, 1, 0, 0, 1, 1])),
    Invariant("line-at-infinity", "the line at infinity", "affine2", "the line at infinity l∞ = (0, 0, 1)",
              _c_fixed(Line, [0, 0, 1]), _v_at_infinity, (_PERSP2, [])),
    Invariant("cross-ratio", "cross-ratio", "projective2", "the cross-ratio of four collinear points",
              _c_four_on_a_line, _v_cross_ratio),
    Invariant("collinearity", "collinearity", "projective2", "three collinear points stay collinear",
              functools.partial(_span, Point), _v_det),
    Invariant("concurrency", "concurrency", "projective2", "three concurrent lines stay concurrent",
              functools.partial(_span, Line), _v_det),
    Invariant("incidence", "incidence", "projective2", "a point on a line maps to a point on the image line",
              _c_incident, _v_incidence),
    Invariant("tangency", "tangency", "projective2",
              "a point of a conic and the tangent there map to a point of the image conic and its tangent",
              _c_tangent, _v_tangency),
    # 3D
    Invariant("length-3d", "length", "isometry3", "the distance between two points", _c_points(2, 3), _v_dist,
              (_SCALE3, [0, 0, 0, 1, 2, 2])),
    Invariant("volume", "volume", "euclidean3", "the signed volume of a tetrahedron", _c_points(4, 3), _v_volume,
              (_REFLECT3, [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1])),
    Invariant("angle-3d", "angle", "similarity3", "the angle between two planes", _c_lines(2, 3), _v_cos2,
              (_SHEAR3, [1, 0, 0, 0, 0, 1, 0, 0])),
    Invariant("length-ratio-3d", "ratio of lengths", "similarity3", "the ratio of two distances",
              _c_points(4, 3), _v_length_ratio, (_SHEAR3, [0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0])),
    Invariant("absolute-conic", "the absolute conic Ω∞", "similarity3",
              "the dual absolute quadric Q*∞ = diag(1, 1, 1, 0), up to scale",
              _c_fixed(DualQuadric, [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]), _v_absolute,
              (_SHEAR3, [])),
    Invariant("parallelism-3d", "parallelism of planes", "affine3", "parallel planes stay parallel",
              _c_parallel_planes, _v_normals_parallel, (_PERSP3, [1, 0, 0, 0, -1])),
    Invariant("volume-ratio", "ratio of volumes", "affine3", "the ratio of the volumes of two tetrahedra",
              _c_points(8, 3), _v_volume_ratio,
              (_PERSP3, [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 1])),
    Invariant("plane-at-infinity", "the plane at infinity π∞", "affine3", "the plane at infinity (0, 0, 0, 1)",
              _c_fixed(Plane, [0, 0, 0, 1]), _v_at_infinity, (_PERSP3, [])),
    Invariant("coplanarity", "coplanarity", "projective3", "four coplanar points stay coplanar",
              _c_coplanar, _v_det),
    Invariant("incidence-3d", "incidence", "projective3", "a point on a plane maps to a point on the image plane",
              _c_point_in_plane, _v_incidence),
)


def invariant(key: str) -> Invariant:
    """The invariant with the given key.

    >>> invariant("cross-ratio").cls
    'projective2'
    """
    for inv in INVARIANTS:
        if inv.key == key:
            return inv
    raise ObjectTypeError(f"no invariant {key!r}; known: {[i.key for i in INVARIANTS]}")


def invariants_of(cls: TransformationClass | str, inherited: bool = True) -> list[Invariant]:
    """The invariants of a class: its own and (``inherited``) those of every larger class.

    >>> [i.key for i in invariants_of("affine2", inherited=False)]
    ['parallelism', 'area-ratio', 'parallel-length-ratio', 'line-at-infinity']
    """
    key = cls if isinstance(cls, str) else cls.key
    chain = [key]
    while inherited and class_by_key(chain[-1]).larger is not None:
        chain.append(class_by_key(chain[-1]).larger)  # type: ignore[arg-type]
    return [inv for k in chain for inv in INVARIANTS if inv.cls == k]


def summary_table(dim: int = 2) -> list[dict[str, Any]]:
    """The rows of the hierarchy table (largest class first), generated from the DoF derivations and the proofs.

    Each row: class name, matrix form (LaTeX), the derived DoF, the invariants *new* in the
    class (each proved, and refuted in the next larger class by its counterexample), and the
    number of invariants it has in all (with those of the larger classes).

    >>> [(row["class"], row["dof"]) for row in summary_table(2)]
    [('Projective', 8), ('Affine', 6), ('Similarity', 4), ('Isometry', 3), ('Euclidean (proper isometry)', 3)]
    """
    classes = CLASSES_2D if dim == 2 else CLASSES_3D
    rows = []
    for cls in reversed(classes):
        own = []
        for inv in invariants_of(cls, inherited=False):
            proof = inv.prove()
            ce = inv.counterexample()
            if proof.holds and (ce is None or ce.fails):
                own.append(inv.name)
        rows.append({
            "class": cls.name,
            "matrix": cls.matrix_form,
            "dof": cls.dof().dof,
            "invariants": own,
            "all": len([i for i in invariants_of(cls) if i.prove().holds]),
        })
    return rows


def summary_markdown(dim: int = 2) -> str:
    """The summary table as Markdown with LaTeX matrices (for a notebook's ``Markdown`` display).

    >>> summary_markdown(3).splitlines()[0]
    '| Class | Matrix | DoF | Invariants (plus those of the rows above) |'
    """
    lines = ["| Class | Matrix | DoF | Invariants (plus those of the rows above) |", "|---|---|---|---|"]
    for row in summary_table(dim):
        lines.append(f"| {row['class']} | ${row['matrix']}$ | {row['dof']} | {', '.join(row['invariants'])} |")
    return "\n".join(lines)
