"""Constructions that need square roots, as methods of every claim: angle bisectors, a line or a circle meeting a
circle, tangents from a point, rotations by whole degrees and regular polygons.

Each adds *roots* to its claim (new quantities with a defining equation, :class:`Root`): a length root
``d_A_B`` with ``d² = (w_A w_B)²|AB|²``, an intersection root ``e_X`` with ``e² = β² − αγ``, a root of unity
``zeta_M`` with ``Φ_M(zeta_M) = 0``. :class:`SquareRootConstructions` is a base class of
:class:`~pgsym.proofs.claims.Claim`; the roots it adds live in ``claim.square_roots`` (:class:`RootData`), and
:mod:`pgsym.proofs.algebraic` proves claims that have them (for every choice of root, or for the branch the
statement names).

>>> from pgsym.proofs.claims import Claim
>>> c = Claim("x", "x")
>>> A, B, C = (c.free_point(n) for n in "ABC")
>>> c.angle_bisector("b", A, B, C).description, [str(r.symbol) for r in roots_of(c)]
('internal bisector of ∠ABC', ['d_A_B', 'd_B_C'])
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import TYPE_CHECKING, Any

import sympy

from .. import metric, projective_plane
from .. import ring as alg
from ..conic_pencil import intersect_conics
from ..conics import Conic
from ..errors import ObjectTypeError
from ..projective_plane import Point
from .operations import affine_vector

if TYPE_CHECKING:
    from .claims import Claim, Node

__all__ = ["MAX_POLYGON", "MAX_ROOTS", "Root", "RootData", "SquareRootConstructions", "roots_of"]

MAX_POLYGON = 24
"""The largest n of a regular n-gon (and denominator of a rotation angle in turns): Φ_M stays of degree ≤ 48."""

MAX_ROOTS = 8
"""The most square roots one claim may use: the exact evaluation visits every choice of their signs (2⁸)."""


@dataclass(eq=False)
class Root:
    """A new quantity of a claim and its defining equation.

    ``kind`` is ``"length"``, ``"intersection"`` or ``"unity"``; ``square(values)`` gives q with ``root² = q``
    from the values of earlier objects (quadratic roots), ``orient(values)`` the sign the principal root has
    (lengths: ``w_A w_B``), ``modulus`` M for ``zeta_M``; ``named`` says whether the statement names the
    principal root (lengths, roots of unity) or means either root (intersections).
    """

    symbol: sympy.Symbol
    node: Node
    kind: str
    text: str
    named: bool
    square: Callable[[dict[Node, Any]], Any] | None = None
    orient: Callable[[dict[Node, Any]], Any] | None = None
    modulus: int | None = None
    words: tuple[str, str] = ("+", "−")
    key: Any = None  # what the root is of (a length: the pair of its points), to share it between constructions


@dataclass
class RootData:
    """What a claim's square-root constructions add: the roots, how to read a branch, what the core builds."""

    roots: list[Root] = field(default_factory=list)
    readings: list[Callable[[dict[sympy.Symbol, int]], str]] = field(default_factory=list)
    # (object, its arguments, the candidates pgsym's core builds from their exact values) for the core check
    core: list[tuple[Node, tuple[Node, ...], Callable[..., Any]]] = field(default_factory=list)


def _data(claim: Claim) -> RootData:
    if claim.square_roots is None:
        claim.square_roots = RootData()
    return claim.square_roots


def roots_of(claim: Claim) -> list[Root]:
    """The roots a claim uses (empty for a claim without square roots).

    >>> from pgsym.proofs.claims import Claim
    >>> roots_of(Claim("x", "x"))
    []
    """
    return [] if claim.square_roots is None else claim.square_roots.roots


def _symbol_name(claim: Claim, name: str) -> str:
    """A name for a new root: the readable ``name`` with every character but letters, digits, ``_`` and ``'``
    replaced (an object written inline is named by its text, ``midpoint A C``), made unique among the claim's
    parameters and objects, so that no two roots, and no root and parameter, ever share a symbol."""
    base = re.sub(r"[^A-Za-z0-9_']+", "_", name).strip("_") or "root"
    taken = {str(p) for p in claim.parameters}
    out, n = base, 1
    while out in taken or f"_{out}" in claim.nodes:
        n += 1
        out = f"{base}_{n}"
    return out


def _new_root(claim: Claim, name: str, kind: str, text: str, named: bool, **kw: Any) -> Root:
    data = _data(claim)
    if len([r for r in data.roots if r.kind != "unity"]) >= MAX_ROOTS and kind != "unity":
        raise ObjectTypeError(f"claim {claim.name!r} would need more than {MAX_ROOTS} square roots; "
                              "the exact evaluation visits every choice of their signs")
    name = _symbol_name(claim, name)
    sym = sympy.Symbol(name)
    claim.parameters.append(sym)
    node = claim._free(f"_{name}", "scalar", (sym,))
    node.root = True  # normalisation: not a free object, fixed by its equation
    root = Root(sym, node, kind, text.replace("{name}", name), named, **kw)
    data.roots.append(root)
    return root


def _similar(node: Node) -> Node:
    """Mark a construction as commuting with the orientation-preserving similarities (the frame A = (0, 0),
    B = (1, 0) of :mod:`~pgsym.proofs.normalisation`): a bisector stays the bisector of the same kind (lengths
    scale by k > 0, so the named roots stay positive), the common points of a line and a circle or two circles
    and the tangents from a point go to those of the images (either root: the pair is what is mapped), and a
    rotation by a fixed angle commutes with every direct similarity."""
    node.group = "similarity"
    return node


# -- coordinates --------------------------------------------------------------------------------------------

def _length_root(claim: Claim, a: Node, b: Node) -> Root:
    """The shared root d with d² = (w_A w_B)²|AB|², principal d = +w_A w_B |AB| (one root per pair of points)."""
    a, b = sorted((a, b), key=lambda n: n.name)
    key = ("length", a.name, b.name)  # names are unique in a claim
    for r in roots_of(claim):
        if r.key == key:
            return r
    x, y = a.label, b.label
    return _new_root(claim, f"d_{x}_{y}", "length", f"{{name}}² = (w_{x} w_{y})²·|{x}{y}|²", True,
                     square=lambda v: alg.squared_distance_fraction(v[a], v[b])[0], orient=lambda v: v[a][2] * v[b][2],
                     words=(f"+|{x}{y}|", f"−|{x}{y}|"), key=key)


def _bisector(claim: Claim, name: str, a: Any, b: Any, c: Any, internal: bool) -> Node:
    a, b, c = (claim._get(x, ("point",), "angle bisector") for x in (a, b, c))
    dba, dbc = _length_root(claim, b, a), _length_root(claim, b, c)
    sgn = 1 if internal else -1

    def line(pa: Any, pb: Any, pc: Any, uba: Any, ubc: Any) -> tuple[Any, ...]:
        va, vc = affine_vector(pb, pa), affine_vector(pb, pc)
        # the unit vectors are va/d_BA and vc/d_BC (d_BA = w_A w_B |BA| on the named branch): added or
        # subtracted, times d_BA d_BC
        ux = ubc * va[0] + sgn * uba * vc[0]
        uy = ubc * va[1] + sgn * uba * vc[1]
        return alg.cross(pb, (ux, uy, ux - ux))

    word = "internal" if internal else "external"
    node = _similar(claim.formula(name, "line", line, a, b, c, dba.node, dbc.node,
                         description=f"{word} bisector of ∠{a.name}{b.name}{c.name}",
                         conditions=[f"{a.name} ≠ {b.name}, {c.name} ≠ {b.name} and {a.name}, {b.name}, {c.name} "
                                     f"not on one line through {b.name} in opposite directions ({name} is defined)"]))

    def reading(signs: dict[sympy.Symbol, int]) -> str:
        same = signs[dba.symbol] * signs[dbc.symbol] * sgn > 0
        return f"{name} is the {'internal' if same else 'external'} bisector of ∠{a.name}{b.name}{c.name}"

    _data(claim).readings.append(reading)

    def core(pa: Any, pb: Any, pc: Any) -> tuple[Any, ...]:
        return metric.angle_bisectors(projective_plane.join(pb, pa), projective_plane.join(pb, pc))

    _data(claim).core.append((node, (a, b, c), core))
    return node


# -- a line meeting a conic -------------------------------------------------------------------------------

def _line_conic(l: Sequence[Any], k: Any, e: Any, sgn: int) -> tuple[Any, ...]:
    """A common point of the line l and the conic K: ``(−β ± e) P + α Q`` with e² = β² − αγ.

    P = l × (b, −a, 0) is the foot of the origin on l, Q = (b, −a, 0) the point at infinity of l; on
    X = s P + t Q the conic reads α s² + 2β s t + γ t² (α = PᵀKP, β = PᵀKQ, γ = QᵀKQ), whose roots are
    (s, t) = (−β ± e, α).
    """
    q = (l[1], -l[0], l[0] - l[0])
    p = alg.cross(l, q)
    kp, kq = alg.matvec(k, p), alg.matvec(k, q)
    alpha, beta = alg.dot(p, kp), alg.dot(p, kq)
    s = sgn * e - beta
    return tuple(s * pi + alpha * qi for pi, qi in zip(p, q, strict=True))


def _discriminant(l: Sequence[Any], k: Any) -> Any:
    q = (l[1], -l[0], l[0] - l[0])
    p = alg.cross(l, q)
    kp, kq = alg.matvec(k, p), alg.matvec(k, q)
    alpha, beta, gamma = alg.dot(p, kp), alg.dot(p, kq), alg.dot(q, kq)
    return beta * beta - alpha * gamma


def _radical_line(k: Any, m: Any) -> tuple[Any, ...]:
    """The radical axis of two circles: ``m₀₀ K − k₀₀ M`` has no quadratic terms, w(2 r₁ x + 2 r₂ y + r₃ w)."""
    r = [[m[0][0] * k[i][j] - k[0][0] * m[i][j] for j in range(3)] for i in range(3)]
    return (r[0][2] + r[0][2], r[1][2] + r[1][2], r[2][2])


def _meet_points(claim: Claim, names: Sequence[str], l: Node | None, k: Node, m: Node | None,
                 what: str, shown: Sequence[str] | None = None) -> list[Node]:
    """One or two common points of a line l (or the radical axis of the circles K, M) and the conic K.

    ``shown`` names the points in a verdict's words when ``names`` are the prover's own (default: ``names``)."""
    shown = list(shown or names)
    key = "_".join(n.lstrip("_") for n in names)
    line_of = (lambda vl, vk, vm: vl) if m is None else (lambda vl, vk, vm: _radical_line(vk, vm))
    base = [x for x in (l, k, m) if x is not None]

    def values(v: dict[Node, Any]) -> tuple[Any, Any, Any]:
        return (v[l] if l is not None else None, v[k], v[m] if m is not None else None)

    root = _new_root(claim, f"e_{key}", "intersection", f"{{name}}² = discriminant of {what}", False,
                     square=lambda v: _discriminant(line_of(*values(v)), v[k]),
                     words=("+", "−"))
    out = []
    for name, sgn in zip(names, (1, -1), strict=False):
        def point(*vals: Any, sgn: int = sgn) -> tuple[Any, ...]:
            *objs, e = vals
            vl, vk, vm = (objs[0], objs[1], objs[2] if m is not None else None) if l is not None else \
                (None, objs[0], objs[1])
            return _line_conic(line_of(vl, vk, vm), vk, e, sgn)

        desc = f"{'the other' if sgn < 0 else 'a'} common point of {what}"
        out.append(_similar(claim.formula(name, "point", point, *base, root.node, description=desc,
                                          conditions=[f"{what} meet ({name} is defined)"])))
    root.text += "; " + (f"{shown[0]} takes +e, {shown[1]} −e" if len(shown) > 1 else f"{shown[0]} takes +e")

    def core(*objs: Any) -> tuple[Any, ...]:
        if m is None:
            return Conic(objs[1]).intersections(objs[0])
        return intersect_conics(Conic(objs[0]), Conic(objs[1]))

    for node in out:
        _data(claim).core.append((node, tuple(base), core))
    readers = list(zip(shown, (1, -1), strict=False))
    _data(claim).readings.append(
        lambda signs: ", ".join(f"{n} = (−β {'+' if signs[root.symbol] * s > 0 else '−'} √Δ)·P + α·Q, the "
                                f"{'first' if signs[root.symbol] * s > 0 else 'second'} common point of {what}"
                                for n, s in readers))
    return out


def _tangents(claim: Claim, names: Sequence[str], p: Any, k: Any) -> list[Node]:
    p, k = claim._get(p, ("point",), "tangentfrom"), claim._get(k, ("conic",), "tangentfrom")
    polar = claim.polar(f"_polar_{k.name}_{p.name}_{'_'.join(names)}", k, p)
    touch = _meet_points(claim, [f"_touch_{n}" for n in names], polar, k, None, f"the polar of {p.name} and {k.name}",
                         [f"the point where {n} touches {k.name}" for n in names])
    lines = [claim.join(n, p, t) for n, t in zip(names, touch, strict=True)]

    def core(pp: Any, kk: Any) -> tuple[Any, ...]:
        return Conic(kk).tangents_from(pp)

    for line in lines:
        _data(claim).core.append((line, (p, k), core))
    return lines


# -- roots of unity: rotations and regular polygons ---------------------------------------------------------

def _zeta(claim: Claim, modulus: int) -> Root:
    for r in roots_of(claim):
        if r.key == ("unity", modulus):
            return r
    return _new_root(claim, f"zeta_{modulus}", "unity", f"Φ_{modulus}({{name}}) = 0 (principal: {{name}} = "
                     f"e^(2πi/{modulus}))", True, modulus=modulus, key=("unity", modulus))


def _cyclotomic_combination(modulus: int, exponents: Sequence[int], imaginary: bool) -> list[tuple[int, int]]:
    """2·Re or 2·Im of Σ ζ^e (ζ = e^{2πi/M}) as a polynomial in ζ with integer coefficients, reduced by Φ_M:
    2 cos a = ζ^k + ζ^{−k}, 2 sin a = −i (ζ^k − ζ^{−k}) with −i = ζ^{3M/4}."""
    z = sympy.Symbol("z")
    m = modulus
    poly = sum((z ** ((-e) % m) if not imaginary else -z ** ((-e) % m)) + z ** (e % m) for e in exponents)
    if imaginary:
        poly = sympy.expand(poly * z ** (3 * m // 4))
    phi = sympy.Poly(sympy.cyclotomic_poly(m, z), z)
    rem = sympy.Poly(poly, z).rem(phi)
    return [(int(mon[0]), int(c)) for mon, c in zip(rem.monoms(), rem.coeffs(), strict=True)]


def _apply_terms(terms: list[tuple[int, int]], z: Any) -> Any:
    out = z - z
    for e, c in terms:
        out = out + c * z ** e if e else out + c * (z ** 0)
    return out


def _turn(claim: Claim, name: str, x: Node, o: Node, turns: Fraction, powers: Sequence[int],
          description: str) -> Node:
    """O + S (X − O) with S = Σ_j R^j over ``powers``, R the rotation by ``turns`` full turns."""
    den = turns.denominator
    if den > MAX_POLYGON:
        raise ObjectTypeError(f"{description}: the angle is a multiple of 1/{den} turn; at most 1/{MAX_POLYGON} "
                              "is supported (the cyclotomic polynomial grows with it)")
    modulus = math.lcm(den, 4)
    k = turns.numerator * (modulus // den)
    exps = [j * k for j in powers]
    re = _cyclotomic_combination(modulus, exps, False)
    im = _cyclotomic_combination(modulus, exps, True)
    rational = all(e == 0 for e, _ in re + im)
    args: list[Node] = [x, o]
    if not rational:
        args.append(_zeta(claim, modulus).node)

    def rotated(px: Any, po: Any, z: Any = None) -> tuple[Any, ...]:
        one = px[2] ** 0 if px[2] else px[2] + 1  # SymPy's ring has no 0**0
        cr = _apply_terms(re, z) if not rational else sum(c for _, c in re) * one
        ci = _apply_terms(im, z) if not rational else sum(c for _, c in im) * one
        u = affine_vector(po, px)
        two_w = 2 * px[2]
        return (two_w * po[0] + cr * u[0] - ci * u[1], two_w * po[1] + ci * u[0] + cr * u[1], two_w * po[2])

    node = _similar(claim.formula(name, "point", rotated, *args, description=description,
                                  conditions=[f"{x.name} and {o.name} are finite points"]))

    def core(px: Any, po: Any) -> tuple[Any, ...]:
        angle = 2 * sympy.pi * turns
        step = metric.rotation(sympy.cos(angle), sympy.sin(angle), po)
        (ox, oy), total, current = po.dehomogenize(), [0, 0], px
        for j in range(max(powers) + 1):  # O + Σ_j R^j (X − O) over the powers, walking round O
            if j in powers:
                cx, cy = current.dehomogenize()
                total = [total[0] + cx - ox, total[1] + cy - oy]
            current = step(current)
        return (Point(ox + total[0], oy + total[1]),)

    _data(claim).core.append((node, (x, o), core))
    return node


class SquareRootConstructions:
    """The constructions with square roots, a base class of :class:`~pgsym.proofs.claims.Claim`.

    Each method adds its roots to ``self.square_roots`` (created with the first one) and returns the new
    objects as nodes of the claim, built with the claim's own ``formula``, ``polar`` and ``join``.
    """

    square_roots: RootData | None

    def angle_bisector(self: Claim, name: str, a: Any, b: Any, c: Any) -> Node:
        """The internal bisector of the angle ABC at B (the line through B with direction BA/|BA| + BC/|BC|).

        Uses the length roots ``d_A_B``, ``d_B_C`` (shared with every other construction that needs those lengths);
        on the named branch both are positive. Needs A ≠ B ≠ C.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> A, B, C = (c.free_point(n) for n in "ABC")
        >>> c.angle_bisector("b", A, B, C).description, [str(r.symbol) for r in roots_of(c)]
        ('internal bisector of ∠ABC', ['d_A_B', 'd_B_C'])
        """
        return _bisector(self, name, a, b, c, True)

    def external_bisector(self: Claim, name: str, a: Any, b: Any, c: Any) -> Node:
        """The external bisector of the angle ABC at B (direction BA/|BA| − BC/|BC|), with the length roots.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> A, B, C = (c.free_point(n) for n in "ABC")
        >>> c.external_bisector("e", A, B, C).conditions[0].startswith("A ≠ B")
        True
        """
        return _bisector(self, name, a, b, c, False)

    def line_conic_intersection(self: Claim, name: str, l: Any, k: Any) -> Node:
        """A common point of the line l and the circle (or conic) K, with no known common point: either root.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
        >>> c.line_conic_intersection("X", c.free_line("l"), K).description
        'a common point of l and K'
        """
        l, k = self._get(l, ("line",), "intersection"), self._get(k, ("conic",), "intersection")
        return _meet_points(self, [name], l, k, None, f"{l.name} and {k.name}")[0]

    def line_conic_intersections(self: Claim, names: Sequence[str], l: Any, k: Any) -> list[Node]:
        """Both common points of the line l and the circle (or conic) K, in either order (the roots ±e).

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
        >>> [n.name for n in c.line_conic_intersections(("X", "Y"), c.free_line("l"), K)]
        ['X', 'Y']
        """
        l, k = self._get(l, ("line",), "intersections"), self._get(k, ("conic",), "intersections")
        return _meet_points(self, list(names)[:2], l, k, None, f"{l.name} and {k.name}")

    def circle_intersection(self: Claim, name: str, k: Any, m: Any) -> Node:
        """A common point of two circles K and M (either root): the radical axis meets K.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
        >>> M = c.conic("M", [[1, 0, -1], [0, 1, 0], [-1, 0, -3]])
        >>> c.circle_intersection("X", K, M).description
        'a common point of K and M'
        """
        k, m = (self._get(x, ("conic",), "intersection") for x in (k, m))
        return _meet_points(self, [name], None, k, m, f"{k.name} and {m.name}")[0]

    def circle_intersections(self: Claim, names: Sequence[str], k: Any, m: Any) -> list[Node]:
        """Both common points of two circles K and M, in either order (the circles must not be concentric).

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
        >>> M = c.conic("M", [[1, 0, -1], [0, 1, 0], [-1, 0, -3]])
        >>> [n.description for n in c.circle_intersections(("X", "Y"), K, M)]
        ['a common point of K and M', 'the other common point of K and M']
        """
        k, m = (self._get(x, ("conic",), "intersections") for x in (k, m))
        return _meet_points(self, list(names)[:2], None, k, m, f"{k.name} and {m.name}")

    def tangent_from(self: Claim, name: str, p: Any, k: Any) -> Node:
        """A tangent from the point P to the circle (or conic) K: the line from P to a point where the polar of P
        meets K (either root; P must be outside K for real tangents).

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
        >>> c.tangent_from("t", c.free_point("P"), K).kind
        'line'
        """
        return _tangents(self, [name], p, k)[0]

    def tangents_from(self: Claim, names: Sequence[str], p: Any, k: Any) -> list[Node]:
        """Both tangents from P to K, in either order (one root: the two points where the polar of P meets K).

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
        >>> [n.name for n in c.tangents_from(("s", "t"), c.free_point("P"), K)], len(roots_of(c))
        (['s', 't'], 1)
        """
        return _tangents(self, list(names)[:2], p, k)

    def rotate_degrees(self: Claim, name: str, x: Any, o: Any, degrees: int) -> Node:
        """X rotated about O by an integer number of degrees (counter-clockwise; cos and sin in ℚ(ζ_M)).

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> c.rotate_degrees("Y", c.free_point("X"), c.free_point("O"), 60).description
        'X rotated about O by 60°'
        >>> [str(r.symbol) for r in roots_of(c)]
        ['zeta_12']
        """
        x, o = self._get(x, ("point",), "rotate"), self._get(o, ("point",), "rotate")
        if not isinstance(degrees, int) or isinstance(degrees, bool):
            raise ObjectTypeError(f"rotate: the angle is an integer number of degrees, got {degrees!r}")
        return _turn(self, name, x, o, Fraction(degrees % 360, 360), [1],
                     f"{x.name} rotated about {o.name} by {degrees}°")

    def polygon_vertex(self: Claim, name: str, a: Any, b: Any, n: int, k: int) -> Node:
        """The k-th vertex of the regular n-gon with consecutive vertices A (k = 0) and B (k = 1),
        counter-clockwise: ``A + (1 + ω + … + ω^{k−1})(B − A)`` with ω = e^{2πi/n}.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> c.polygon_vertex("C", c.free_point("A"), c.free_point("B"), 5, 2).description
        'vertex 2 of the regular 5-gon A B …'
        """
        a, b = self._get(a, ("point",), "polygon"), self._get(b, ("point",), "polygon")
        if not all(isinstance(v, int) and not isinstance(v, bool) for v in (n, k)) or not 3 <= n <= MAX_POLYGON:
            raise ObjectTypeError(f"polygon: n is an integer from 3 to {MAX_POLYGON} and k an integer, "
                                  f"got {n!r}, {k!r}")
        k %= n
        if not k:
            return _similar(self.formula(name, "point", lambda p: p, a, description=f"vertex 0 of the regular {n}-gon"))
        return _turn(self, name, b, a, Fraction(1, n), range(k),
                     f"vertex {k} of the regular {n}-gon {a.name} {b.name} …")
