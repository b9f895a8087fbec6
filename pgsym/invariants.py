"""Invariants of the transformation classes: exact proofs, explicit counterexamples, the summary table.

An :class:`Invariant` is a quantity (or a relation, whose quantity is zero) attached to
a configuration of objects. It is *invariant* under a class when its value on the
transformed configuration equals its value on the original one for every member of
the class. :meth:`Invariant.prove` decides this for the class's symbolic generic
element acting on a generic symbolic configuration: every quantity is a rational
function, computed as a numerator/denominator pair of polynomials in a SymPy
polynomial ring over ℚ (no ``simplify``), and the claim is that the numerator of
``after − before`` is the zero polynomial. Each invariant that is new in its class
also carries an explicit exact member of the next larger class and an exact
configuration on which the quantity changes: :meth:`Invariant.counterexample`.

The summary table of the hierarchy (:func:`summary_table`) is assembled from these
results and from the derived DoF; nothing in it is typed in.

>>> inv = invariant("angle")
>>> inv.prove().holds
True
>>> ce = inv.counterexample()
>>> ce.before, ce.after, ce.transformation_class
([0], [1/2], 'Affine')
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import cache
from typing import Any

import sympy
from sympy import ZZ
from sympy.polys.rings import PolyElement, ring

from .errors import DegenerateConfigurationError, IdealPointError, ObjectTypeError, UndefinedCrossRatioError
from .exact import is_zero, primitive_part
from .hierarchy import CLASSES_2D, CLASSES_3D, TransformationClass, class_by_key, classify
from .ring import Quotient, adjugate, cross, det, dot, matmul, matvec, squared_distance_fraction, transpose

__all__ = [
    "INVARIANTS",
    "InvarianceCounterexample",
    "Invariant",
    "Proof",
    "invariant",
    "invariants_of",
    "summary_markdown",
    "summary_table",
]


def _nonzero(x: Any) -> bool:
    return not x.is_zero() if isinstance(x, Quotient) else not is_zero(sympy.sympify(x))


def _ex(v: Sequence[Any]) -> list[Any]:
    return [x if isinstance(x, Quotient) else sympy.sympify(x) for x in v]


def _finite_w(x: Sequence[Any]) -> Any:
    """The last coordinate of a finite point; an ideal point raises (a division would give zoo/nan)."""
    w = x[-1]
    if (w.n == 0) if isinstance(w, Quotient) else is_zero(w):
        raise IdealPointError(f"the point {list(x)} is ideal (last coordinate zero): it has no Euclidean position")
    return w


def _euclid(x: Sequence[Any]) -> list[Any]:
    w = _finite_w(x)
    return [c / w for c in x[:-1]]


# -- Euclidean quantities of finite points (homogeneous input) ---------------------------------------
def distance_squared(p: Sequence[Any], q: Sequence[Any]) -> Any:
    """The squared Euclidean distance of two finite points given homogeneously (2D or 3D).

    >>> distance_squared([0, 0, 1], [6, 8, 2])
    25
    """
    p, q = _ex(p), _ex(q)
    _finite_w(p), _finite_w(q)
    n, d = squared_distance_fraction(p, q)
    return n / d


def signed_area(p: Sequence[Any], q: Sequence[Any], r: Sequence[Any]) -> Any:
    """The signed area of the triangle of three finite points: ``det[p q r] / (2 p₃ q₃ r₃)``.

    >>> signed_area([0, 0, 1], [1, 0, 1], [0, 1, 1])
    1/2
    """
    p, q, r = _ex(p), _ex(q), _ex(r)
    return det(transpose([p, q, r])) / (2 * _finite_w(p) * _finite_w(q) * _finite_w(r))


def signed_volume(p: Sequence[Any], q: Sequence[Any], r: Sequence[Any], s: Sequence[Any]) -> Any:
    """The signed volume ``det[q − p, r − p, s − p] / 6`` of a tetrahedron of finite points (homogeneous input).

    >>> signed_volume([0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1])
    1/6
    """
    p, q, r, s = _ex(p), _ex(q), _ex(r), _ex(s)
    return -det(transpose([p, q, r, s])) / (6 * _finite_w(p) * _finite_w(q) * _finite_w(r) * _finite_w(s))


def cos2_angle(l: Sequence[Any], m: Sequence[Any]) -> Any:
    """``cos²`` of the angle between two lines (2D) or planes (3D) from their normals; it fixes the angle in [0, π/2].

    >>> cos2_angle([1, 0, 0], [1, -1, 0])
    1/2
    """
    u, v = _ex(l[:-1]), _ex(m[:-1])
    uu, vv = dot(u, u), dot(v, v)
    if not (_nonzero(uu) and _nonzero(vv)):
        raise DegenerateConfigurationError(
            "an angle needs two ordinary lines (planes) with real directions: the line (plane) at infinity "
            "and isotropic lines have a normal of zero length")
    return dot(u, v) * dot(u, v) / (uu * vv)


def collinear_cross_ratio(a: Sequence[Any], b: Sequence[Any], c: Sequence[Any], d: Sequence[Any]) -> Any:
    """The cross-ratio ``(A, B; C, D) = [AC][BD] / ([AD][BC])`` of four collinear points of P².

    For collinear points every ``X × Y`` is a multiple ``[XY]`` of the same line vector, so
    one coordinate ``k`` of the cross products (where ``A × B`` is nonzero) gives the brackets.

    >>> collinear_cross_ratio([0, 0, 1], [1, 0, 1], [2, 0, 1], [3, 0, 1])     # (0−2)(1−3)/((0−3)(1−2))
    4/3
    """
    a, b, c, d = _ex(a), _ex(b), _ex(c), _ex(d)
    base = cross(a, b)
    k = next((i for i in range(3) if _nonzero(base[i])), None)
    if k is None:
        raise UndefinedCrossRatioError("the cross-ratio needs A ≠ B: the first two points coincide")

    def br(x: Sequence[Any], y: Sequence[Any]) -> Any:
        return cross(x, y)[k]

    denominator = br(a, d) * br(b, c)
    if not _nonzero(denominator):
        raise UndefinedCrossRatioError("the cross-ratio is undefined: A = D or B = C makes its denominator zero")
    return br(a, c) * br(b, d) / denominator


# -- configurations and their images ------------------------------------------------------------------
# A configuration is a tuple of (tag, data): "P" point (vector), "L" line / plane (covector),
# "D" dual conic/quadric (matrix, H D Hᵀ), "C" conic/quadric (matrix, cof C cofᵀ).
def _primitive(entries: Sequence[Any]) -> list[Any]:
    """A homogeneous object with polynomial entries in its primitive form (:func:`pgsym.exact.primitive_part`).

    Projective objects are defined up to scale, so the common polynomial factor carries no
    information; removing it keeps the proof polynomials small. Non-polynomial data is returned unchanged.
    """
    if not entries or not all(isinstance(e, Quotient) for e in entries):
        return list(entries)
    one = entries[0].n.ring.one
    return [Quotient(x, one) for x in primitive_part([e.n for e in entries], [e.d for e in entries])]


def _act(H: Sequence[Sequence[Any]], config: Sequence[tuple[str, Any]]) -> list[tuple[str, Any]]:
    cof: Any = None
    out: list[tuple[str, Any]] = []
    for tag, data in config:
        if tag in "LC" and cof is None:
            cof = transpose(adjugate(H))  # adj(H)ᵀ ∝ H⁻ᵀ maps lines and planes
        if tag == "P":
            out.append((tag, matvec(H, data)))
        elif tag == "L":
            out.append((tag, _primitive(matvec(cof, data))))  # type: ignore[arg-type]
        else:
            m = matmul(matmul(H, data), transpose(H)) if tag == "D" else matmul(matmul(cof, data), transpose(cof))  # type: ignore[arg-type]
            flat = _primitive([e for row in m for e in row])
            n = len(m)
            out.append((tag, [flat[i * n : (i + 1) * n] for i in range(n)]))
    return out


def _data(config: Sequence[tuple[str, Any]]) -> list[Any]:
    return [d for _, d in config]


New = Callable[[], Any]


def _pt(new: New, dim: int) -> tuple[str, list[Any]]:
    return ("P", [new() for _ in range(dim)] + [1])


def _ln(new: New, dim: int) -> tuple[str, list[Any]]:
    return ("L", [new() for _ in range(dim + 1)])


# -- configurations (generic when ``new`` yields symbols; concrete when it yields numbers) ---------
def _c_points(k: int, dim: int) -> Callable[[New], list]:
    return lambda new: [_pt(new, dim) for _ in range(k)]


def _c_lines(k: int, dim: int) -> Callable[[New], list]:
    return lambda new: [_ln(new, dim) for _ in range(k)]


def _c_parallel_lines(new: New) -> list:
    a, b, c, d = new(), new(), new(), new()
    return [("L", [a, b, c]), ("L", [a, b, d])]


def _c_parallel_planes(new: New) -> list:
    a, b, c, d, e = new(), new(), new(), new(), new()
    return [("L", [a, b, c, d]), ("L", [a, b, c, e])]


def _c_parallel_segments(new: New) -> list:
    p, q, r = (_pt(new, 2) for _ in range(3))
    mu = new()
    s = ("P", [r[1][0] + mu * (q[1][0] - p[1][0]), r[1][1] + mu * (q[1][1] - p[1][1]), 1])
    return [p, q, r, s]


def _c_collinear(new: New) -> list:
    p = ("P", [new(), new(), new()])
    q = ("P", [new(), new(), new()])
    s, t = new(), new()
    return [p, q, ("P", [s * a + t * b for a, b in zip(p[1], q[1], strict=True)])]


def _c_concurrent(new: New) -> list:
    l = ("L", [new(), new(), new()])
    m = ("L", [new(), new(), new()])
    s, t = new(), new()
    return [l, m, ("L", [s * a + t * b for a, b in zip(l[1], m[1], strict=True)])]


def _c_four_on_a_line(new: New) -> list:
    a = [new(), new(), new()]
    b = [new(), new(), new()]
    lams = [new() for _ in range(4)]
    return [("P", [x + lam * y for x, y in zip(a, b, strict=True)]) for lam in lams]


def _c_incident(new: New) -> list:
    l = [new(), new(), new()]
    v = [new(), new(), new()]
    return [("P", cross(l, v)), ("L", l)]


def _c_tangent(new: New) -> list:
    # a point x and a conic C through x (c22 solved from xᵀCx = 0), with the tangent line C x
    x = [new(), new(), new()]
    c00, c01, c02, c11, c12 = (new() for _ in range(5))
    rest = c00 * x[0] * x[0] + 2 * c01 * x[0] * x[1] + c11 * x[1] * x[1] + 2 * c02 * x[0] * x[2] + 2 * c12 * x[1] * x[2]
    c22 = -rest / (x[2] * x[2])
    C = [[c00, c01, c02], [c01, c11, c12], [c02, c12, c22]]
    return [("P", x), ("C", C), ("L", matvec(C, x))]


def _c_coplanar(new: New) -> list:
    p, q, r = ([new() for _ in range(4)] for _ in range(3))
    s, t, u = new(), new(), new()
    return [("P", p), ("P", q), ("P", r), ("P", [s * a + t * b + u * c for a, b, c in zip(p, q, r, strict=True)])]


def _c_point_in_plane(new: New) -> list:
    x = [new() for _ in range(4)]
    a, b, c = new(), new(), new()
    d = -(a * x[0] + b * x[1] + c * x[2]) / x[3]
    return [("P", x), ("L", [a, b, c, d])]


def _c_fixed(tag: str, data: list) -> Callable[[New], list]:
    exact = [[sympy.Integer(e) for e in row] for row in data] if isinstance(data[0], list) else _ex(data)
    return lambda new: [(tag, exact)]


# -- quantities ----------------------------------------------------------------------------------------
def _v_dist(c: list) -> list:
    p, q = _data(c)
    return [distance_squared(p, q)]


def _v_area2(c: list) -> list:
    a = signed_area(*_data(c))
    return [a * a]


def _v_area(c: list) -> list:
    return [signed_area(*_data(c))]


def _v_volume(c: list) -> list:
    return [signed_volume(*_data(c))]


def _v_cos2(c: list) -> list:
    return [cos2_angle(*_data(c))]


def _v_length_ratio(c: list) -> list:
    p, q, r, s = _data(c)
    return [distance_squared(p, q) / distance_squared(r, s)]


def _v_area_ratio(c: list) -> list:
    d = _data(c)
    return [signed_area(*d[:3]) / signed_area(*d[3:])]


def _v_volume_ratio(c: list) -> list:
    d = _data(c)
    return [signed_volume(*d[:4]) / signed_volume(*d[4:])]


def _v_parallel_ratio(c: list) -> list:
    p, q, r, s = (_euclid(x) for x in _data(c))
    u = [b - a for a, b in zip(p, q, strict=True)]
    w = [b - a for a, b in zip(r, s, strict=True)]
    return [dot(w, u) / dot(u, u), u[0] * w[1] - u[1] * w[0]]


def _v_meet_at_infinity(c: list) -> list:
    l, m = _data(c)
    return [cross(l, m)[2]]


def _v_normals_parallel(c: list) -> list:
    l, m = _data(c)
    return list(cross(l[:3], m[:3]))


def _v_at_infinity(c: list) -> list:
    (l,) = _data(c)
    return [x / l[-1] for x in l[:-1]]


def _v_absolute(c: list) -> list:
    (D,) = _data(c)
    n = len(D)
    return [D[i][j] / D[0][0] for i in range(n) for j in range(i, n) if (i, j) != (0, 0)]


def _v_det(c: list) -> list:
    return [det(transpose(_data(c)))]


def _v_cross_ratio(c: list) -> list:
    return [collinear_cross_ratio(*_data(c))]


def _v_incidence(c: list) -> list:
    x, l = _data(c)
    return [dot(l, x)]


def _v_tangency(c: list) -> list:
    x, C, l = _data(c)
    return [dot(x, matvec(C, x)), *cross(matvec(C, x), l)]


# -- invariants -----------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Proof:
    """The outcome of :meth:`Invariant.prove`: ``holds`` when every residual numerator is the zero polynomial."""

    key: str
    transformation_class: str
    holds: bool
    components: int
    terms: int = 0


@dataclass(frozen=True)
class InvarianceCounterexample:
    """A member ``matrix`` of the next larger class and a configuration on which the quantity changes.

    (Called ``Counterexample`` before; that name is the proofs' :class:`pgsym.proofs.verdicts.Counterexample`.)
    """

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

    ``configuration(new)`` builds the objects from scalars supplied by ``new()`` (symbols
    for the proof, numbers for examples); ``value`` maps a configuration to a list of
    scalars. ``counter`` is ``(matrix, values)``: a member of the next larger class and
    the numbers that ``new()`` yields for the counterexample configuration (``None`` for
    invariants of the largest class).
    """

    key: str
    name: str
    cls: str
    statement: str
    configuration: Callable[[New], list] = field(repr=False)
    value: Callable[[list], list] = field(repr=False)
    counter: tuple[list[list[int]], list[Any]] | None = field(default=None, repr=False)

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

        >>> invariant("length").evaluate([[2, 0, 0], [0, 2, 0], [0, 0, 1]], [0, 0, 3, 4])
        ([25], [100])
        """
        rows = [[sympy.sympify(e) for e in r] for r in (H.tolist() if hasattr(H, "tolist") else H)]
        it = iter([sympy.sympify(v) for v in values])
        config = self.configuration(lambda: next(it))
        return self.value(config), self.value(_act(rows, config))

    def prove(self) -> Proof:
        """Prove the invariance exactly for the generic element (every component) of the class."""
        return _prove(self.key)

    def counterexample(self) -> InvarianceCounterexample | None:
        """The explicit member of the next larger class that changes the quantity (None at the top)."""
        if self.counter is None:
            return None
        H, values = self.counter
        before, after = self.evaluate(H, values)
        return InvarianceCounterexample(self.key, classify(H).name, sympy.ImmutableMatrix(H), before, after)


def _symbol_factory() -> tuple[New, list[sympy.Symbol]]:
    made: list[sympy.Symbol] = []

    def new() -> sympy.Symbol:
        s = sympy.Symbol(f"z{len(made)}")
        made.append(s)
        return s

    return new, made


def _matrix_rows(flat: list[Quotient], n: int) -> list[list[PolyElement]]:
    return [[e.n for e in flat[i * n : (i + 1) * n]] for i in range(n)]


@cache
def _prove(key: str) -> Proof:
    inv = invariant(key)
    cls = inv.transformation_class
    new, made = _symbol_factory()
    inv.configuration(new)
    n_config = len(made)
    R, *gens = ring([*map(str, cls.parameters), *(f"z{i}" for i in range(n_config))], ZZ)
    one = R.one
    zs = iter(gens[cls.n_parameters :])
    params = [Quotient(g, one) for g in gens[: cls.n_parameters]]
    config = inv.configuration(lambda: Quotient(next(zs), one))
    holds, terms = True, 0
    for comp in range(len(cls.components)):
        # the generic element, built in the ring; every quantity is independent of the
        # representative of H (a projective map is defined up to scale), so the polynomial
        # multiple with the denominators cleared is used
        G = [[e if isinstance(e, Quotient) else Quotient(R(e), one) for e in row] for row in cls.builder(params, comp)]
        H = [[Quotient(e, one) for e in row] for row in _matrix_rows(_primitive([e for row in G for e in row]), len(G))]
        before, after = inv.value(config), inv.value(_act(H, config))
        for a, b in zip(after, before, strict=True):
            r = a - b
            terms = max(terms, len(r.n))
            holds = holds and r.is_zero()
    return Proof(key, cls.name, holds, len(cls.components), terms)


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
              _c_fixed("D", [[1, 0, 0], [0, 1, 0], [0, 0, 0]]), _v_absolute, (_SHEAR2, [])),
    Invariant("parallelism", "parallelism", "affine2", "parallel lines stay parallel",
              _c_parallel_lines, _v_meet_at_infinity, (_PERSP2, [1, 0, 0, -1])),
    Invariant("area-ratio", "ratio of areas", "affine2", "the ratio of the areas of two triangles",
              _c_points(6, 2), _v_area_ratio, (_PERSP2, [0, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2])),
    Invariant("parallel-length-ratio", "ratio of lengths on parallel lines", "affine2",
              "the ratio of the lengths of two parallel segments", _c_parallel_segments, _v_parallel_ratio,
              (_PERSP2, [0, 0, 1, 0, 0, 1, 1])),
    Invariant("line-at-infinity", "the line at infinity", "affine2", "the line at infinity l∞ = (0, 0, 1)",
              _c_fixed("L", [0, 0, 1]), _v_at_infinity, (_PERSP2, [])),
    Invariant("cross-ratio", "cross-ratio", "projective2", "the cross-ratio of four collinear points",
              _c_four_on_a_line, _v_cross_ratio),
    Invariant("collinearity", "collinearity", "projective2", "three collinear points stay collinear",
              _c_collinear, _v_det),
    Invariant("concurrency", "concurrency", "projective2", "three concurrent lines stay concurrent",
              _c_concurrent, _v_det),
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
              _c_fixed("D", [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]), _v_absolute, (_SHEAR3, [])),
    Invariant("parallelism-3d", "parallelism of planes", "affine3", "parallel planes stay parallel",
              _c_parallel_planes, _v_normals_parallel, (_PERSP3, [1, 0, 0, 0, -1])),
    Invariant("volume-ratio", "ratio of volumes", "affine3", "the ratio of the volumes of two tetrahedra",
              _c_points(8, 3), _v_volume_ratio,
              (_PERSP3, [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 1])),
    Invariant("plane-at-infinity", "the plane at infinity π∞", "affine3", "the plane at infinity (0, 0, 0, 1)",
              _c_fixed("L", [0, 0, 0, 1]), _v_at_infinity, (_PERSP3, [])),
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


def __getattr__(name: str) -> Any:
    """``Counterexample``, the old name of :class:`InvarianceCounterexample`, with a DeprecationWarning."""
    if name == "Counterexample":
        warnings.warn("pgsym.invariants.Counterexample is now InvarianceCounterexample (the proofs' verdicts have "
                      "their own Counterexample)", DeprecationWarning, stacklevel=2)
        return InvarianceCounterexample
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
