"""Claims: free parameters, constructions, hypotheses and a conclusion.

A :class:`Claim` is a small geometric program. Free objects have coordinates that
are polynomials in the claim's parameters (SymPy symbols); every further object is
built from earlier ones by one of pgsym's operations (join, meet, plane through
three points, Plücker matrix, a transformation acting on a point or a line, …).
Each construction records the non-degeneracy condition it needs, e.g. ``A ≠ B``
for a join, because the cross product vanishes exactly when the points coincide.
The conclusion is a list of polynomials that must vanish (an incidence, a
collinearity, an equality up to scale, a matrix identity, a rank condition, …).

>>> c = Claim("demo", "the join of A and B contains A")
>>> A, B = c.free_point("A"), c.free_point("B")
>>> l = c.join("l", A, B)
>>> c.conclude_incident(A, l)
>>> [n.name for n in c.nodes.values()], c.conditions_text()
(['A', 'B', 'l'], ['A ≠ B'])
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy

from .. import ring as alg
from ..errors import InvalidCoordinatesError, ObjectTypeError
from .errors import NonPolynomialClaimError, UndefinedConstructionError
from .operations import KINDS, OPERATIONS, Operation, constructions, operation
from .order import OrderCondition, OrderConditions
from .square_roots import RootData, SquareRootConstructions

__all__ = [
    "KINDS",
    "Claim",
    "Conclusion",
    "Node",
    "NonPolynomialClaimError",
    "UndefinedConstructionError",
]

_VECTOR_KINDS = tuple(k for k, size in KINDS.items() if size is not None)


@dataclass(eq=False)
class Node:
    """One object of a claim: its name, kind, the operation that built it and its arguments."""

    name: str
    kind: str
    op: str
    args: tuple[Any, ...]
    description: str = ""
    data: Any = None
    conditions: list[str] = field(default_factory=list)
    #: the group a formula commutes with when its builder knows it (a square-root construction), else None
    group: str | None = None
    #: a root adjoined by its defining equation (pgsym.proofs.square_roots): no free object, so no frame moves it
    root: bool = False

    @property
    def operation(self) -> Operation:
        """The entry of :data:`~pgsym.proofs.operations.OPERATIONS` that built this object."""
        try:
            return OPERATIONS[self.op]
        except KeyError:
            raise UndefinedConstructionError(
                f"{self.name} was built by {self.op!r}, which is no operation of the table "
                f"(known: {', '.join(OPERATIONS)})"
            ) from None

    @property
    def label(self) -> str:
        """How a verdict names the object: the statement's own name, or for an object the prover added (its name
        starts with ``_``) what it is, e.g. ``|AB|²`` for a squared distance a conclusion needed.

        >>> c = Claim("x", "x")
        >>> A, B = c.free_point("A"), c.free_point("B")
        >>> c.conclude_equal_length(A, B, B, A)
        >>> A.label, [n.label for n in c.nodes.values() if n.name.startswith("_")]
        ('A', ['|AB|²', '|BA|²'])
        """
        if not self.name.startswith("_"):
            return self.name
        if self.root or not self.description:
            return self.name[1:]
        return self.description

    def __repr__(self) -> str:
        return f"<{self.kind} {self.name} = {self.description}>"


@dataclass
class Conclusion:
    """What must hold: ``kind`` (incident, collinear, …), its nodes and a readable statement."""

    kind: str
    args: tuple[Any, ...]
    text: str


def _polynomial(expr: Any, params: Sequence[sympy.Symbol], what: str) -> sympy.Expr:
    """Check that ``expr`` is a polynomial over ℚ in ``params``; return it as a SymPy expression."""
    try:
        e = sympy.sympify(expr)
    except (sympy.SympifyError, TypeError) as err:
        raise NonPolynomialClaimError(f"{what}: {expr!r} is not an expression ({err})") from None
    if not isinstance(e, sympy.Expr):
        raise NonPolynomialClaimError(f"{what}: {expr!r} is not a number or an expression in the parameters")
    extra = e.free_symbols - set(params)
    if extra:
        names = ", ".join(sorted(map(str, extra)))
        raise NonPolynomialClaimError(
            f"{what}: {e} uses {names}, which are not parameters of the claim; declare them with claim.params()"
        )
    if e.is_Rational or e in params:
        return e
    bad_numbers = any(not a.is_Rational for a in e.atoms(sympy.Number)) or e.atoms(sympy.NumberSymbol, sympy.I)
    bad_powers = any(not (p.exp.is_Integer and p.exp >= 0) for p in e.atoms(sympy.Pow))
    if bad_numbers or bad_powers or not e.is_polynomial(*params):
        raise NonPolynomialClaimError(
            f"{what}: {e} is not a polynomial with rational coefficients in the parameters; "
            "multiply out denominators (compare a/b = c/d as a*d - b*c = 0, or use conclude_equal_ratio) "
            "and avoid roots and transcendental functions"
        )
    return e


_NUMBER_WORDS = ("no", "one", "two", "three", "four", "five", "six")


def _count(n: int) -> str:
    return _NUMBER_WORDS[n] if n < len(_NUMBER_WORDS) else str(n)


class Claim(SquareRootConstructions, OrderConditions):
    """A statement of projective geometry to be proved for generic values of its parameters.

    Build it with the ``free_*`` methods (free objects), the construction methods
    (``join``, ``meet``, ``apply``, …), optional equation hypotheses
    (:meth:`assume_zero`) and one or more ``conclude_*`` calls; then pass it to
    :func:`pgsym.proofs.engine.prove`. ``expected`` records whether the catalogue
    states the claim as true (``True``) or as a deliberate false statement.

    >>> c = Claim("parallel", "parallel lines meet at infinity")
    >>> a, b, p, q = c.params("a b p q")
    >>> l, m = c.line("l", a, b, p), c.line("m", a, b, q)
    >>> x = c.meet("x", l, m)
    >>> c.conclude_incident(x, c.line("linf", 0, 0, 1))
    >>> len(c.conclusions), c.conditions_text()
    (1, ['l ≠ m'])
    """

    def __init__(
        self,
        name: str,
        title: str,
        statement: str = "",
        *,
        expected: bool = True,
        chapter: str = "",
        method_note: str = "",
    ) -> None:
        self.name = name
        self.title = title
        self.statement = statement or title
        self.expected = expected
        self.chapter = chapter
        self.method_note = method_note
        self.parameters: list[sympy.Symbol] = []
        self.nodes: dict[str, Node] = {}
        self.hypotheses: list[tuple[sympy.Expr, str]] = []
        self.conclusions: list[Conclusion] = []
        #: the roots of the square-root constructions (:mod:`pgsym.proofs.square_roots`), None without any
        self.square_roots: RootData | None = None
        #: the order conditions (:mod:`pgsym.proofs.order`): strict inequalities selecting branches or regions
        self.order_conditions: list[OrderCondition] = []

    def __repr__(self) -> str:
        return f"Claim({self.name!r}, {self.title!r})"

    # -- parameters and free objects -----------------------------------------------
    def params(self, names: str) -> tuple[sympy.Symbol, ...]:
        """Declare free parameters (space-separated names); returns the symbols.

        >>> Claim("x", "x").params("s t")
        (s, t)
        """
        syms = sympy.symbols(names, seq=True)
        for s in syms:
            if s not in self.parameters:
                self.parameters.append(s)
        return tuple(syms)

    def _node(self, name: str, kind: str, op: str, args: tuple[Any, ...], description: str,
              data: Any = None, conditions: Sequence[str] = ()) -> Node:
        if not isinstance(name, str) or not name:
            raise ObjectTypeError(f"every object of a claim needs a nonempty name, got {name!r}")
        if name in self.nodes:
            raise ObjectTypeError(f"claim {self.name!r} already has an object named {name!r}; choose another name")
        node = Node(name, kind, op, args, description, data, list(conditions))
        self.nodes[name] = node
        return node

    def _free(self, name: str, kind: str, coords: Sequence[Any]) -> Node:
        size = KINDS[kind]
        if size is not None and len(coords) != size:
            raise ObjectTypeError(f"a {kind} needs {size} coordinates, got {len(coords)} for {name!r}")
        exprs = tuple(_polynomial(c, self.parameters, f"coordinate of {name}") for c in coords)
        if all(e == 0 for e in exprs):
            raise ObjectTypeError(f"{name!r} has only zero coordinates, which is no {kind}")
        text = "(" + ", ".join(map(str, exprs)) + ")"
        return self._node(name, kind, "free", (), text, exprs)

    def point(self, name: str, *coords: Any) -> Node:
        """A point of P² with given coordinates (2 inhomogeneous or 3 homogeneous).

        >>> Claim("x", "x").point("P", 1, 2).data
        (1, 2, 1)
        """
        return self._free(name, "point", coords if len(coords) != 2 else (*coords, 1))

    def line(self, name: str, *coords: Any) -> Node:
        """A line ``ax + by + c = 0`` of P² with given coefficients.

        >>> Claim("x", "x").line("l", 0, 0, 1).description
        '(0, 0, 1)'
        """
        return self._free(name, "line", coords)

    def point1(self, name: str, *coords: Any) -> Node:
        """A point of P¹ (one inhomogeneous or two homogeneous coordinates)."""
        return self._free(name, "point1", coords if len(coords) != 1 else (*coords, 1))

    def point3(self, name: str, *coords: Any) -> Node:
        """A point of P³ (3 inhomogeneous or 4 homogeneous coordinates)."""
        return self._free(name, "point3", coords if len(coords) != 3 else (*coords, 1))

    def plane(self, name: str, *coords: Any) -> Node:
        """A plane ``ax + by + cz + d = 0`` of P³."""
        return self._free(name, "plane", coords)

    def matrix(self, name: str, rows: Any, *, invertible: bool = False) -> Node:
        """A matrix with given entries; ``invertible`` records ``det ≠ 0`` as a condition."""
        m = sympy.Matrix(rows)
        exprs = tuple(tuple(_polynomial(e, self.parameters, f"entry of {name}") for e in m.row(i))
                      for i in range(m.rows))
        node = self._node(name, "matrix", "free", (), f"{m.rows}×{m.cols} matrix", exprs)
        if invertible:
            node.conditions.append(f"{name} is non-singular (det {name} ≠ 0)")
        return node

    def conic(self, name: str, rows: Any) -> Node:
        """A conic given by its symmetric 3×3 matrix."""
        node = self.matrix(name, rows)
        node.kind = "conic"
        node.description = "conic"
        return node

    def free_point(self, name: str, homogeneous: bool = False) -> Node:
        """A generic point of P² whose coordinates are new parameters (``A_x``, ``A_y`` [, ``A_w``]).

        >>> Claim("x", "x").free_point("A").data
        (A_x, A_y, 1)
        """
        names = ("x", "y", "w") if homogeneous else ("x", "y")
        syms = self.params(" ".join(f"{name}_{n}" for n in names))
        return self.point(name, *syms)

    def free_line(self, name: str) -> Node:
        """A generic line of P² with new parameters ``l_a, l_b, l_c``."""
        return self.line(name, *self.params(f"{name}_a {name}_b {name}_c"))

    def free_point1(self, name: str) -> Node:
        """A generic finite point of P¹ with one new parameter (its name in lower case)."""
        return self.point1(name, *self.params(name.lower()))

    def free_point3(self, name: str) -> Node:
        """A generic finite point of P³ with new parameters ``A_x, A_y, A_z``."""
        return self.point3(name, *self.params(f"{name}_x {name}_y {name}_z"))

    def free_plane(self, name: str) -> Node:
        """A generic plane of P³ with new parameters."""
        return self.plane(name, *self.params(f"{name}_a {name}_b {name}_c {name}_d"))

    def free_matrix(self, name: str, n: int, m: int | None = None, *, invertible: bool = True) -> Node:
        """A generic n×m matrix with new parameters ``h11 … hnm`` (prefix: the name in lower case)."""
        m = n if m is None else m
        prefix = name.lower()
        syms = self.params(" ".join(f"{prefix}{i}{j}" for i in range(1, n + 1) for j in range(1, m + 1)))
        rows = [syms[i * m:(i + 1) * m] for i in range(n)]
        return self.matrix(name, rows, invertible=invertible and n == m)

    # -- constructions ----------------------------------------------------------------
    def _get(self, obj: Any, kinds: Sequence[str], operation: str) -> Node:
        if isinstance(obj, str):
            if obj not in self.nodes:
                raise UndefinedConstructionError(
                    f"{operation}: claim {self.name!r} has no object named {obj!r}; "
                    f"define it first (known: {', '.join(self.nodes) or 'none'})"
                )
            obj = self.nodes[obj]
        if not isinstance(obj, Node) or self.nodes.get(obj.name) is not obj:
            raise UndefinedConstructionError(
                f"{operation}: {obj!r} is not an object of claim {self.name!r}; build it with this claim's methods"
            )
        if kinds and obj.kind not in kinds:
            raise ObjectTypeError(f"{operation} expects {' or '.join(kinds)}, got the {obj.kind} {obj.name}")
        return obj

    def construct(self, op: str, name: str, *args: Any) -> Node:
        """Build an object by the name of its operation, e.g. ``construct("join", "l", A, B)``.

        >>> c = Claim("x", "x")
        >>> c.construct("frobnicate", "z")
        Traceback (most recent call last):
        ...
        pgsym.proofs.errors.UndefinedConstructionError: unknown construction 'frobnicate'; ...
        """
        found = operation(op)
        if found is None or not found.constructible:
            raise UndefinedConstructionError(
                f"unknown construction {op!r}; the operations are: {', '.join(sorted(constructions()))}"
            )
        return getattr(self, found.name)(name, *args)

    def _construct(self, op: str, name: str, args: Sequence[Any], data: Any = None, *, kind: str | None = None,
                   description: str = "", conditions: Sequence[str] | None = None) -> Node:
        """Check the arguments against the operation's table entry and record the new object."""
        entry = OPERATIONS[op]
        kinds = entry.arg_kinds
        if kinds is None:
            nodes = tuple(self._get(a, (), op) for a in args)
        else:
            if len(args) != len(kinds):
                raise ObjectTypeError(f"{op} needs {_count(len(kinds))} {kinds[0][0]}s, got {len(args)}")
            nodes = []
            for i, (a, allowed) in enumerate(zip(args, kinds, strict=True)):
                nodes.append(self._get(a, (nodes[0].kind,) if entry.same_kind and i else allowed, op))
            nodes = tuple(nodes)
        names = [n.label for n in nodes]
        return self._node(name, kind or entry.result_kind([n.kind for n in nodes]), op, nodes,
                          description or entry.description(names, data), data,
                          entry.conditions(names, name, data) if conditions is None else conditions)

    def join(self, name: str, p: Any, q: Any) -> Node:
        """The line through two points of P² (their cross product); needs ``P ≠ Q``.

        >>> c = Claim("x", "x")
        >>> c.join("l", c.free_point("P"), c.free_point("Q")).conditions
        ['P ≠ Q']
        """
        return self._construct("join", name, (p, q))

    def meet(self, name: str, l: Any, m: Any) -> Node:
        """The point common to two lines of P² (their cross product); needs ``l ≠ m``.

        >>> c = Claim("x", "x")
        >>> c.meet("X", c.free_line("l"), c.free_line("m")).kind
        'point'
        """
        return self._construct("meet", name, (l, m))

    def combine(self, name: str, p: Any, q: Any, s: Any, t: Any = 1) -> Node:
        """The point (or line, plane) ``s·P + t·Q``: a generic point on the line PQ for a parameter s."""
        s = _polynomial(s, self.parameters, f"coefficient of {name}")
        t = _polynomial(t, self.parameters, f"coefficient of {name}")
        return self._construct("combine", name, (p, q), (s, t))

    def plane_through(self, name: str, a: Any, b: Any, c: Any) -> Node:
        """The plane through three points of P³; needs them not collinear."""
        return self._construct("plane_through", name, (a, b, c))

    def point_on_planes(self, name: str, a: Any, b: Any, c: Any) -> Node:
        """The point common to three planes of P³; needs them independent."""
        return self._construct("point_on_planes", name, (a, b, c))

    def line3(self, name: str, a: Any, b: Any) -> Node:
        """The Plücker matrix ``A Bᵀ − B Aᵀ`` of the line through two points of P³; needs ``A ≠ B``."""
        return self._construct("line3", name, (a, b))

    def apply(self, name: str, h: Any, x: Any) -> Node:
        """The image ``H x`` of a point (of P¹, P² or P³) under a matrix."""
        return self._construct("apply", name, (h, x))

    def apply_line(self, name: str, h: Any, l: Any) -> Node:
        """The image of a line (or plane) under H: ``adj(H)ᵀ l``, i.e. ``H⁻ᵀ l`` up to the scale det H."""
        return self._construct("apply_line", name, (h, l))

    apply_plane = apply_line

    def apply_conic(self, name: str, h: Any, c: Any) -> Node:
        """The image of a conic under H: ``adj(H)ᵀ C adj(H)``, i.e. ``H⁻ᵀ C H⁻¹`` up to scale."""
        return self._construct("apply_conic", name, (h, c))

    def polar(self, name: str, c: Any, p: Any) -> Node:
        """The polar line ``C p`` of a point with respect to a conic (the tangent when p is on C)."""
        return self._construct("polar", name, (c, p))

    def conic_through(self, name: str, *points: Any) -> Node:
        """The conic through five points (its six coefficients are signed 5×5 minors).

        >>> Claim("x", "x").conic_through("C")
        Traceback (most recent call last):
        ...
        pgsym.errors.ObjectTypeError: conic_through needs five points, got 0
        """
        return self._construct("conic_through", name, points)

    def dual_conic(self, name: str, c: Any) -> Node:
        """The dual conic ``adj(C)``: the tangent lines of C satisfy ``lᵀ adj(C) l = 0``."""
        return self._construct("dual_conic", name, (c,))

    def cross_ratio(self, name: str, a: Any, b: Any, c: Any, d: Any) -> Node:
        """The cross-ratio ``(A, B; C, D) = [A C][B D] / ([A D][B C])`` of four points of P¹."""
        return self._construct("cross_ratio", name, (a, b, c, d))

    def harmonic_conjugate(self, name: str, a: Any, b: Any, c: Any) -> Node:
        """The harmonic conjugate ``[A C] B + [B C] A`` of C with respect to A and B (points of P¹)."""
        return self._construct("harmonic_conjugate", name, (a, b, c))

    def tangent(self, name: str, c: Any, p: Any) -> Node:
        """The tangent ``C p`` of a conic at a point p on it (the polar of p).

        >>> c = Claim("x", "x")
        >>> c.tangent("t", c.conic("C", [[1, 0, 0], [0, 1, 0], [0, 0, -1]]), c.point("P", 1, 0)).kind
        'line'
        """
        return self._construct("polar", name, (c, p))

    def second_intersection(self, name: str, c: Any, p: Any, q: Any) -> Node:
        """The second point where the line PQ meets the conic C through P: ``(QᵀCQ) P − 2 (PᵀCQ) Q``.

        P must lie on C (as a point of it built by :meth:`conic_through`, :meth:`point_on_conic`, …);
        the point is then P itself only when the line is the tangent at P.

        >>> c = Claim("x", "x")
        >>> C = c.conic("C", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])     # the unit circle
        >>> c.second_intersection("X", C, c.point("P", 1, 0), c.point("Q", 0, 1)).conditions[0][:6]
        'P ≠ Q '
        """
        return self._construct("second_intersection", name, (c, p, q))

    def point_on_conic(self, name: str, c: Any, p: Any, t: Any = None) -> Node:
        """A point of the conic C with one parameter t: the second point of C on the line through P and (1, t, t²).

        P must lie on C. As t runs through the numbers the line runs through the pencil at P, so the point runs
        through the whole conic: a generic point of C. ``t`` defaults to a new parameter named after the point
        (``X_t``).

        >>> c = Claim("x", "x")
        >>> C = c.conic("C", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
        >>> c.point_on_conic("X", C, c.point("P", 1, 0)).data
        (X_t,)
        """
        if t is None:
            (t,) = self.params(f"{name}_t")
        t = _polynomial(t, self.parameters, f"parameter of {name}")
        return self._construct("point_on_conic", name, (c, p), (t,))

    def point_on_line(self, name: str, p: Any, q: Any = None, t: Any = None) -> Node:
        """A point of the line PQ (points of P² or P³) with one parameter t: ``P + t Q``.

        ``t`` defaults to a new parameter ``X_t``. Given a line l of P² instead of two points, this is
        :meth:`point_of_line`.

        >>> c = Claim("x", "x")
        >>> c.point_on_line("X", c.free_point("P"), c.free_point("Q")).description
        'P + X_t·Q'
        """
        if q is None:
            return self.point_of_line(name, p, t)
        if t is None:
            (t,) = self.params(f"{name}_t")
        t = _polynomial(t, self.parameters, f"parameter of {name}")
        return self._construct("point_on_line", name, (p, q), (t,))

    def point_of_line(self, name: str, l: Any, t: Any = None) -> Node:
        """A point of a line l of P² with one parameter t: ``l × (1, t, t²)``, its meet with the tangents of a
        fixed conic, which sweep every point of l (``t`` defaults to a new parameter ``X_t``).

        >>> c = Claim("x", "x")
        >>> c.point_of_line("Y", c.free_line("l")).conditions
        ['Y is a point of l']
        """
        if t is None:
            (t,) = self.params(f"{name}_t")
        t = _polynomial(t, self.parameters, f"parameter of {name}")
        return self._construct("point_of_line", name, (l,), (t,))

    def conic_tangent_to(self, name: str, *lines: Any) -> Node:
        """The conic tangent to five lines (the dual conic through them, turned back into a point conic).

        >>> c = Claim("x", "x")
        >>> c.conic_tangent_to("C", *(c.free_line(n) for n in "abcde")).kind
        'conic'
        """
        return self._construct("conic_tangent_to", name, lines)

    def line_meets_plane(self, name: str, l: Any, e: Any) -> Node:
        """The point where a line of P³ (a :meth:`line3`) meets a plane: ``L E``; needs the line not in the plane.

        >>> c = Claim("x", "x")
        >>> L = c.line3("L", c.free_point3("A"), c.free_point3("B"))
        >>> c.line_meets_plane("X", L, c.free_plane("E")).kind
        'point3'
        """
        return self._construct("line_meets_plane", name, (l, e))

    def line_of_planes(self, name: str, e: Any, f: Any) -> Node:
        """The line where two planes of P³ meet (its Plücker matrix, from ``E Fᵀ − F Eᵀ`` by the rewrite rule)."""
        return self._construct("line_of_planes", name, (e, f))

    def cross_ratio_collinear(self, name: str, a: Any, b: Any, c: Any, d: Any) -> Node:
        """The cross-ratio ``(A, B; C, D)`` of four collinear points, or four concurrent lines, of P².

        With ``A × C = λ_AC l`` on the common line l: ``λ_AC λ_BD / (λ_AD λ_BC)``, the P¹ cross-ratio of the
        points on that line (the same for every choice of coordinates on it).
        """
        return self._construct("cross_ratio_collinear", name, (a, b, c, d))

    def harmonic_conjugate_collinear(self, name: str, a: Any, b: Any, c: Any) -> Node:
        """The harmonic conjugate of C with respect to A and B: collinear points (or concurrent lines) of P²."""
        return self._construct("harmonic_conjugate_collinear", name, (a, b, c))

    def midpoint(self, name: str, a: Any, b: Any) -> Node:
        """The affine midpoint ``w_B A + w_A B`` of two finite points of P² (or P³), right for any representatives.

        >>> c = Claim("x", "x")
        >>> c.midpoint("M", c.point("A", 2, 0, 2), c.point("B", 3, 3)).conditions
        ['A is a finite point', 'B is a finite point']
        """
        return self._construct("midpoint", name, (a, b))

    # -- Euclidean constructions (the absolute: l∞ and the circular points, in real form) ----------------------
    def parallel(self, name: str, l: Any, p: Any) -> Node:
        """The line through P parallel to l: ``P × (b, −a, 0)``; needs l not the line at infinity.

        >>> c = Claim("x", "x")
        >>> c.parallel("m", c.free_line("l"), c.free_point("P")).conditions
        ['l is not the line at infinity', 'P is a finite point']
        """
        return self._construct("parallel", name, (l, p))

    def perpendicular(self, name: str, l: Any, p: Any) -> Node:
        """The line through P perpendicular to l: ``P × C*∞ l = P × (a, b, 0)``.

        >>> c = Claim("x", "x")
        >>> c.perpendicular("m", c.line("l", 1, 2, 3), c.point("P", 0, 0)).kind
        'line'
        """
        return self._construct("perpendicular", name, (l, p))

    def bisector(self, name: str, a: Any, b: Any) -> Node:
        """The perpendicular bisector of the segment AB; needs ``A ≠ B``.

        >>> c = Claim("x", "x")
        >>> c.bisector("m", c.free_point("A"), c.free_point("B")).conditions[0]
        'A ≠ B'
        """
        return self._construct("bisector", name, (a, b))

    def foot(self, name: str, p: Any, l: Any) -> Node:
        """The foot of the perpendicular from P to l (:func:`pgsym.metric.orthogonal_projection`).

        >>> c = Claim("x", "x")
        >>> c.foot("F", c.free_point("P"), c.free_line("l")).description
        'foot of the perpendicular from P to l'
        """
        return self._construct("foot", name, (p, l))

    def reflect(self, name: str, x: Any, mirror: Any) -> Node:
        """X reflected in a point (the half-turn about it) or in a line, as the mirror's kind says.

        >>> c = Claim("x", "x")
        >>> X = c.free_point("X")
        >>> c.reflect("Y", X, c.free_point("P")).op, c.reflect("Z", X, c.free_line("l")).op
        ('reflect_point', 'reflect_line')
        """
        kind = self._get(mirror, ("point", "line"), "reflect").kind
        return self.reflect_point(name, x, mirror) if kind == "point" else self.reflect_line(name, x, mirror)

    def reflect_point(self, name: str, x: Any, p: Any) -> Node:
        """X reflected in the point P: ``2P − X``."""
        return self._construct("reflect_point", name, (x, p))

    def reflect_line(self, name: str, x: Any, l: Any) -> Node:
        """X reflected in the line l (:func:`pgsym.metric.reflection`)."""
        return self._construct("reflect_line", name, (x, l))

    def rotate(self, name: str, x: Any, o: Any, cos: Any, sin: Any) -> Node:
        """X rotated about O by the angle with the given cosine and sine.

        Numbers must satisfy ``cos² + sin² = 1`` exactly; parameters (or expressions in them) add that
        equation as a hypothesis.

        >>> c = Claim("x", "x")
        >>> c.rotate("Y", c.free_point("X"), c.free_point("O"), sympy.Rational(3, 5), sympy.Rational(4, 5)).kind
        'point'
        >>> c.rotate("Z", "X", "O", 1, 1)
        Traceback (most recent call last):
        ...
        pgsym.errors.InvalidCoordinatesError: rotate: cos² + sin² = 2, not 1
        """
        c = _polynomial(cos, self.parameters, f"cosine of {name}")
        s = _polynomial(sin, self.parameters, f"sine of {name}")
        norm = sympy.expand(c * c + s * s - 1)
        if norm.is_Rational and norm != 0:
            raise InvalidCoordinatesError(f"rotate: cos² + sin² = {norm + 1}, not 1")
        node = self._construct("rotate", name, (x, o), (c, s))
        if not norm.is_Rational:
            self.assume_zero(norm, f"({c})² + ({s})² = 1 (the angle of {name})")
        return node

    def translate(self, name: str, x: Any, a: Any, b: Any) -> Node:
        """X moved by the vector from A to B.

        >>> c = Claim("x", "x")
        >>> c.translate("Y", *(c.free_point(n) for n in "XAB")).description
        'X translated by the vector AB'
        """
        return self._construct("translate", name, (x, a, b))

    def similar(self, name: str, a: Any, b: Any, d: Any, e: Any, f: Any) -> Node:
        """The point X that makes the triangle ABX directly similar to DEF: ``A + (B − A)(F − D)/(E − D)`` in
        complex numbers, rational (a spiral similarity). It copies an angle: ∠(AB, AX) = ∠(DE, DF); needs D ≠ E.

        >>> c = Claim("x", "x")
        >>> c.similar("X", *(c.free_point(n) for n in "ABDEF")).description
        'the point X with ABX directly similar to DEF'
        """
        return self._construct("similar", name, (a, b, d, e, f))

    def circle(self, name: str, o: Any, a: Any) -> Node:
        """The circle with centre O through A; needs ``O ≠ A`` (a nonzero radius).

        >>> c = Claim("x", "x")
        >>> c.circle("K", c.point("O", 0, 0), c.point("A", 3, 4)).conditions[0]
        'K has nonzero radius (O ≠ A)'
        """
        return self._construct("circle", name, (o, a))

    circle_centre_point = circle_center_point = circle

    def circle_radius(self, name: str, o: Any, r2: Any = None) -> Node:
        """The circle with centre O and squared radius ``r2`` (a number or a parameter; default a new
        parameter ``K_r2``).

        >>> c = Claim("x", "x")
        >>> c.circle_radius("K", c.free_point("O")).data
        (K_r2,)
        """
        if r2 is None:
            (r2,) = self.params(f"{name}_r2")
        r2 = _polynomial(r2, self.parameters, f"squared radius of {name}")
        return self._construct("circle_radius", name, (o,), (r2,))

    def circle3(self, name: str, a: Any, b: Any, c: Any) -> Node:
        """The circle through three points; needs them finite and not collinear.

        >>> cl = Claim("x", "x")
        >>> cl.circle3("K", *(cl.free_point(n) for n in "ABC")).conditions
        ['A, B, C are finite and not collinear']
        """
        return self._construct("circle3", name, (a, b, c))

    circle_through = circle3

    def centre(self, name: str, k: Any) -> Node:
        """The centre of a circle (or conic): the pole of the line at infinity, ``adj(K) (0, 0, 1)ᵀ``."""
        return self._construct("centre", name, (k,))

    center = centre

    def point_on_circle(self, name: str, k: Any, p: Any, t: Any = None) -> Node:
        """A point of the circle K with one parameter (through its known point P): :meth:`point_on_conic`."""
        return self.point_on_conic(name, k, p, t)

    def circles_second(self, name: str, k: Any, l: Any, a: Any) -> Node:
        """The second common point of two circles K, L through the common point A (on their radical axis).

        >>> c = Claim("x", "x")
        >>> A, B, C, D = (c.free_point(n) for n in "ABCD")
        >>> c.circles_second("X", c.circle3("K", A, B, C), c.circle3("L", A, B, D), A).conditions[0]
        'K and L are not concentric (A must lie on both)'
        """
        return self._construct("circles_second", name, (k, l, a))

    def invert(self, name: str, x: Any, k: Any) -> Node:
        """The inverse of X in the circle K (:func:`pgsym.conic_metric.inversion`); needs X not the centre."""
        return self._construct("invert", name, (x, k))

    def dist2(self, name: str, a: Any, b: Any) -> Node:
        """The squared distance ``|AB|²``, a ratio (numerator, denominator).

        >>> c = Claim("x", "x")
        >>> c.dist2("d", c.free_point("A"), c.free_point("B")).kind
        'ratio'
        """
        return self._construct("dist2", name, (a, b))

    def area(self, name: str, a: Any, b: Any, c: Any) -> Node:
        """The signed area of the triangle ABC (positive counter-clockwise): ``det[A B C] / (2 w_A w_B w_C)``."""
        return self._construct("area", name, (a, b, c))

    def segratio(self, name: str, a: Any, b: Any, c: Any, d: Any) -> Node:
        """The signed ratio AB / CD of two parallel (or collinear) segments, ``(B − A)·(D − C) / |D − C|²``.

        For segments that are not parallel this is the ratio of the projection of AB on CD to CD.
        """
        return self._construct("segratio", name, (a, b, c, d))

    def add(self, name: str, r: Any, s: Any) -> Node:
        """The sum of two ratios (or numbers)."""
        return self._construct("add", name, (self._ratio_arg(r), self._ratio_arg(s)))

    def sub(self, name: str, r: Any, s: Any) -> Node:
        """The difference of two ratios (or numbers)."""
        return self._construct("sub", name, (self._ratio_arg(r), self._ratio_arg(s)))

    def mul(self, name: str, r: Any, s: Any) -> Node:
        """The product of two ratios (or numbers).

        >>> c = Claim("x", "x")
        >>> A, B = c.free_point("A"), c.free_point("B")
        >>> c.mul("m", c.dist2("d", A, B), 2).description
        'd · 2'
        """
        return self._construct("mul", name, (self._ratio_arg(r), self._ratio_arg(s)))

    def _ratio_arg(self, x: Any) -> Node:
        """A ratio object, or a number as a constant ratio registered under its own text (names start with a
        letter, so it clashes with none)."""
        if isinstance(x, (Node, str)):
            return self._get(x, ("ratio",), "ratio arithmetic")
        node = self._ratio(x)
        del self.nodes[next(k for k, v in self.nodes.items() if v is node)]
        return self.nodes.setdefault(node.name, node)

    # Euclidean conclusions
    def conclude_perpendicular(self, l: Any, m: Any) -> None:
        """Two lines are perpendicular: ``lᵀ C*∞ m = a a' + b b' = 0``."""
        self._conclude_quantity("perpendicular_to", (l, m), f"{' ⟂ '.join(self._names(l, m))}")

    def conclude_parallel(self, l: Any, m: Any) -> None:
        """Two lines are parallel (they meet on l∞): ``a b' − a' b = 0``."""
        self._conclude_quantity("parallel_to", (l, m), f"{' ∥ '.join(self._names(l, m))}")

    def conclude_equal_length(self, a: Any, b: Any, c: Any, d: Any) -> None:
        """``|AB| = |CD|``: the squared distances are equal.

        >>> c = Claim("x", "x")
        >>> c.conclude_equal_length(*(c.free_point(n) for n in "ABCD"))
        >>> c.conclusions[0].text
        '|AB| = |CD|'
        """
        na, nb, nc, nd = self._names(a, b, c, d)
        r = self.dist2(f"_dist2 {na} {nb}#{len(self.nodes)}", a, b)
        s = self.dist2(f"_dist2 {nc} {nd}#{len(self.nodes)}", c, d)
        self._conclude("equal_ratio", (r, s), f"|{na}{nb}| = |{nc}{nd}|")

    def conclude_equal_angle(self, a: Any, b: Any, c: Any, d: Any, e: Any, f: Any) -> None:
        """The oriented angle ∠ABC (from line BA to line BC) equals ∠DEF modulo π: equal tangents."""
        n = self._names(a, b, c, d, e, f)
        self._conclude_quantity("equal_angle", (a, b, c, d, e, f), f"∠{''.join(n[:3])} = ∠{''.join(n[3:])} (mod π)")

    def conclude_concyclic(self, a: Any, b: Any, c: Any, d: Any) -> None:
        """Four points lie on one circle or one line: ``det[(x² + y², xw, yw, w²)] = 0`` (a circle is a conic through
        the circular points; the line ∪ l∞ is the degenerate member of that family)."""
        self._conclude_quantity("concyclic", (a, b, c, d), f"{', '.join(self._names(a, b, c, d))} are concyclic")

    def conclude_equal_area(self, a: Any, b: Any, c: Any, d: Any, e: Any, f: Any) -> None:
        """The signed areas of ABC and DEF are equal."""
        n = self._names(a, b, c, d, e, f)
        r = self.area(f"_area {' '.join(n[:3])}#{len(self.nodes)}", a, b, c)
        s = self.area(f"_area {' '.join(n[3:])}#{len(self.nodes)}", d, e, f)
        self._conclude("equal_ratio", (r, s), f"area {''.join(n[:3])} = area {''.join(n[3:])}")

    def formula(self, name: str, kind: str, fn: Callable[..., Any], *args: Any, description: str = "",
                conditions: Sequence[str] = ()) -> Node:
        """An object computed by ``fn`` from earlier objects with ``+``, ``-``, ``*`` only.

        ``fn`` receives the values of ``args`` (tuples for vectors and matrices,
        a ``(numerator, denominator)`` pair for ratios) and must return a value
        of ``kind``. The helpers of :mod:`pgsym.ring` are written this way.
        """
        if kind not in KINDS:
            raise ObjectTypeError(f"unknown kind {kind!r}; use one of {', '.join(KINDS)}")
        return self._construct("formula", name, args, fn, kind=kind, description=description,
                               conditions=conditions)

    # -- hypotheses ----------------------------------------------------------------
    def assume_zero(self, expr: Any, text: str) -> None:
        """An equation hypothesis ``expr = 0`` (a polynomial in the parameters); proofs then use Gröbner bases."""
        self.hypotheses.append((_polynomial(expr, self.parameters, "hypothesis"), text))

    # -- conclusions -----------------------------------------------------------------
    def _conclude(self, kind: str, args: tuple[Any, ...], text: str) -> None:
        self.conclusions.append(Conclusion(kind, args, text))

    def conclude_incident(self, x: Any, l: Any) -> None:
        """The point x lies on the line (or plane) l: ``lᵀx = 0``."""
        x = self._get(x, ("point", "point3"), "conclude_incident")
        l = self._get(l, ("line",) if x.kind == "point" else ("plane",), "conclude_incident")
        self._conclude("incident", (x, l), f"{x.name} lies on {l.name}")

    def conclude_collinear(self, p: Any, q: Any, r: Any) -> None:
        """Three points of P² are collinear: ``det[P Q R] = 0``.

        >>> c = Claim("x", "x")
        >>> c.conclude_collinear(*(c.free_point(n) for n in "PQR"))
        >>> c.conclusions[0].text
        'P, Q, R are collinear'
        """
        pts = tuple(self._get(x, ("point",), "conclude_collinear") for x in (p, q, r))
        self._conclude("det", pts, f"{', '.join(x.name for x in pts)} are collinear")

    def conclude_concurrent(self, l: Any, m: Any, n: Any) -> None:
        """Three lines of P² pass through one point: ``det[l m n] = 0``."""
        lines = tuple(self._get(x, ("line",), "conclude_concurrent") for x in (l, m, n))
        self._conclude("det", lines, f"{', '.join(x.name for x in lines)} are concurrent")

    def conclude_coplanar(self, a: Any, b: Any, c: Any, d: Any) -> None:
        """Four points of P³ lie in one plane: ``det[A B C D] = 0``."""
        pts = tuple(self._get(x, ("point3",), "conclude_coplanar") for x in (a, b, c, d))
        self._conclude("det", pts, f"{', '.join(x.name for x in pts)} are coplanar")

    def conclude_proportional(self, u: Any, v: Any) -> None:
        """Equality up to a nonzero scale of two vectors or matrices of the same shape.

        >>> c = Claim("x", "x")
        >>> c.conclude_proportional(c.point("P", 1, 2, 3), c.point("Q", 2, 4, 6))
        >>> c.conclusions[0].kind
        'proportional'
        """
        u, v = self._get(u, (), "conclude_proportional"), self._get(v, (), "conclude_proportional")
        self._conclude("proportional", (u, v), f"{u.name} = λ {v.name} for a nonzero λ")

    def conclude_equal(self, u: Any, v: Any) -> None:
        """Exact equality of two vectors, matrices or scalars (e.g. a matrix identity)."""
        u, v = self._get(u, (), "conclude_equal"), self._get(v, (), "conclude_equal")
        self._conclude("equal", (u, v), f"{u.name} = {v.name}")

    def conclude_zero(self, x: Any, text: str = "") -> None:
        """A polynomial identity: a scalar or matrix object, or an expression in the parameters, vanishes.

        >>> c = Claim("x", "x"); (a,) = c.params("a")
        >>> c.conclude_zero(sympy.sin(a))
        Traceback (most recent call last):
        ...
        pgsym.proofs.errors.NonPolynomialClaimError: conclusion: sin(a) is not a polynomial ...
        """
        if isinstance(x, (Node, str)):
            node = self._get(x, (), "conclude_zero")
            self._conclude("zero", (node,), text or f"{node.name} = 0")
        else:
            e = _polynomial(x, self.parameters, "conclusion")
            node = self._free(f"_expr{len(self.conclusions)}", "scalar", (e,))
            node.name = f"({e})"
            self._conclude("zero", (node,), text or f"{e} = 0")

    def conclude_equal_ratio(self, r: Any, s: Any) -> None:
        """Two ratios are equal: ``r = n₁/d₁``, ``s = n₂/d₂`` (ratio objects or numbers), ``n₁d₂ − n₂d₁ = 0``."""
        r = self._ratio(r)
        s = self._ratio(s)
        self._conclude("equal_ratio", (r, s), f"{r.name} = {s.name}")

    def _ratio(self, x: Any) -> Node:
        if isinstance(x, (Node, str)):
            return self._get(x, ("ratio",), "conclude_equal_ratio")
        if isinstance(x, sympy.Symbol) and x in self.parameters:  # a parameter as a ratio x / 1
            node = Node(str(x), "ratio", "const", (), str(x), (x, sympy.Integer(1)))
            self.nodes[f"_const{len(self.nodes)}"] = node
            return node
        try:
            value = sympy.Rational(x)
        except (TypeError, ValueError, sympy.SympifyError):
            raise NonPolynomialClaimError(
                f"conclude_equal_ratio: {x!r} is neither a ratio object nor a rational number"
            ) from None
        node = Node(str(value), "ratio", "const", (), str(value), (sympy.Integer(value.p), sympy.Integer(value.q)))
        self.nodes[f"_const{len(self.nodes)}"] = node
        return node

    def conclude_rank(self, m: Any, r: int) -> None:
        """The generic rank of a matrix object is exactly r (its (r+1)-minors vanish, some r-minor does not)."""
        m = self._get(m, ("matrix", "line3", "conic"), "conclude_rank")
        self._conclude("rank", (m, r), f"rank {m.name} = {r}")

    def conclude_dof(self, name: str, entries: Any, params: Sequence[sympy.Symbol], dof: int) -> None:
        """A family of matrices, polynomial in ``params``, up to scale, has ``dof`` degrees of freedom.

        The number of degrees of freedom is the dimension of the family in projective
        space: the generic rank of the Jacobian of the entries with the entry vector
        itself as an extra column (the scale direction), minus one.
        """
        m = sympy.Matrix(entries)
        v = sympy.Matrix(list(m))
        jac = v.jacobian(list(params)).row_join(v)
        node = self.matrix(name, jac)
        node.description = f"[∂{name}/∂params | vec {name}]"
        self._conclude("rank", (node, dof + 1), f"{name} has {dof} degrees of freedom (rank of [J | v] = {dof + 1})")

    def _conclude_quantity(self, op: str, args: Sequence[Any], text: str) -> None:
        """A conclusion through a quantity of the table that vanishes exactly when the statement holds."""
        node = self._construct(op, f"_{op}{len(self.nodes)}", args)
        self._conclude("zero", (node,), text)

    def conclude_collinear3(self, a: Any, b: Any, c: Any) -> None:
        """Three points of P³ are collinear: the 3×3 minors of the 4×3 matrix [A B C] vanish.

        >>> c = Claim("x", "x")
        >>> c.conclude_collinear3(*(c.free_point3(n) for n in "ABC"))
        >>> c.conclusions[0].text
        'A, B, C are collinear'
        """
        self._conclude_quantity("collinear3", (a, b, c), f"{', '.join(self._names(a, b, c))} are collinear")

    def conclude_on_line3(self, x: Any, l: Any) -> None:
        """A point of P³ lies on a line of P³: ``L* X = 0`` with L* the dual Plücker matrix."""
        self._conclude_quantity("on_line3", (x, l), f"{' lies on '.join(self._names(x, l))}")

    def conclude_lines_meet(self, l: Any, m: Any) -> None:
        """Two lines of P³ meet (are coplanar): their reciprocal product vanishes."""
        self._conclude_quantity("lines_meet", (l, m), f"{' and '.join(self._names(l, m))} meet")

    def conclude_on_conic(self, x: Any, c: Any) -> None:
        """A point lies on a conic: ``XᵀCX = 0``."""
        self._conclude_quantity("on_conic", (x, c), f"{' lies on '.join(self._names(x, c))}")

    def conclude_tangent(self, l: Any, c: Any) -> None:
        """A line touches a conic: ``lᵀ adj(C) l = 0``."""
        self._conclude_quantity("tangent_to", (l, c), f"{' touches '.join(self._names(l, c))}")

    def conclude_conconic(self, *points: Any) -> None:
        """Six points lie on one conic: the 6×6 determinant of their quadratic monomials vanishes.

        >>> c = Claim("x", "x")
        >>> c.conclude_conconic(*(c.free_point(n) for n in "ABCDEF"))
        >>> c.conclusions[0].text
        'A, B, C, D, E, F lie on a conic'
        """
        self._conclude_six(points, "point", "lie on a conic")

    def conclude_six_tangent(self, *lines: Any) -> None:
        """Six lines touch one conic (the dual statement of :meth:`conclude_conconic`)."""
        self._conclude_six(lines, "line", "touch a conic")

    def _conclude_six(self, objs: Sequence[Any], kind: str, what: str) -> None:
        nodes = [self._get(x, (kind,), f"six {kind}s {what}") for x in objs]
        if len(nodes) != 6:
            raise ObjectTypeError(f"six {kind}s {what}: needs six {kind}s, got {len(nodes)}")
        self._conclude_quantity("six_on_conic", nodes, f"{', '.join(n.name for n in nodes)} {what}")

    def _names(self, *objs: Any) -> list[str]:
        return [o if isinstance(o, str) else getattr(o, "name", repr(o)) for o in objs]

    def conditions_text(self) -> list[str]:
        """The non-degeneracy conditions the constructions need, as readable text."""
        return [c for n in self.nodes.values() for c in n.conditions]


_ = alg  # the formulas module is part of the claim vocabulary (see Claim.formula)
