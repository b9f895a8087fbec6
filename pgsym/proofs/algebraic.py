"""Constructions that need square roots: algebraic points with defining equations, and which roots a proof covers.

An angle bisector, a line meeting a circle, the tangents from a point, a regular polygon or a rotation by 60°
cannot be written with ``+``, ``−``, ``×`` of the coordinates alone. Each is written here with a few new
quantities, the *roots*, each tied to the parameters by one defining equation:

* a **length root** ``d_A_B`` with ``d² = (x_A w_B − x_B w_A)² + (y_A w_B − y_B w_A)²``, i.e. ``d = ±w_A w_B |AB|``:
  one per segment, shared by every construction that needs the length |AB|. The internal bisector of ∠ABC at
  B has the direction ``d_BC·(A − B) + d_BA·(C − B)`` (scaled unit vectors added), the external one
  ``d_BC·(A − B) − d_BA·(C − B)``. The statement names the *principal* root ``d = +w_A w_B |AB|`` (every
  length positive): then each ``anglebisector`` is internal and each ``exbisector`` external. Changing the
  sign of ``d_A_B`` swaps internal and external at A and at B together;
* an **intersection root** ``e_X`` with ``e² = β² − αγ``, the discriminant of a line meeting a conic
  (:func:`line_conic_intersection`): the two common points are ``(−β ± e) P + α Q``. The statement names no root
  (``intersection`` is either point, ``intersections`` both in either order, ``tangentfrom`` either tangent),
  so a conclusion must hold for both;
* a **root of unity** ``zeta_M`` with ``Φ_M(zeta_M) = 0`` (the cyclotomic polynomial), for rotations by an
  angle and regular polygons: ``cos`` and ``sin`` of a multiple of 360°/M are polynomials in ζ = e^{2πi/M}
  with rational coefficients. The statement names ζ = e^{2πi/M} (counter-clockwise), and its conjugates
  ζ^u replace every angle a by u·a (the clockwise figure, the star polygons).

**Proof for every choice of root.** The defining equations form a triangular set (each root's leading term
is its own power, so they are a Gröbner basis for the lexicographic order with the roots first): a
conclusion polynomial whose remainder modulo them is zero vanishes on every point of the variety, i.e. for
every choice of the roots — this is Wu's method with unit initials. For roots of unity only this is also
necessary: a rational statement true for ζ is true for every conjugate (apply the Galois automorphism).

**Named branches.** When the remainder is not zero, the named branch is tried as a rational branch: a
named length whose square is the square of a polynomial s (Wu's school: B = 0, A = p²(1 − t², 2t) gives
|BA| = p²(1 + t²)), or a polynomial multiple λ of an earlier length, is replaced by ±s (or ±λ·d_j) with the sign
the named root has wherever that sign is evident (a sum of even powers with positive coefficients); if the
conclusion then reduces to zero the verdict is "proved for the named branch only", naming the other branch
where it fails. Otherwise the claim is evaluated exactly at random rational instances on every choice of signs
of the square roots (exact algebraic numbers, decided by :func:`pgsym.exact.is_zero`). A failure on the named
branch (principal lengths, either intersection root) refutes the claim, with the branch said; a claim that
holds on the named branch at every instance but fails on another is *unknown* ("holds on the named branch
only … not proved"), never *proved*. When the defining equations generate a field (generic lengths, a single
root of unity) a rational statement true on one branch is true on all (the Galois group permutes them), so
one-branch statements need a reducible tower, which is exactly what the rational named branch detects.

>>> from pgsym.proofs.claims import Claim
>>> from pgsym.proofs.engine import prove
>>> c = Claim("incentre", "the three internal bisectors of a triangle are concurrent")
>>> A, B, C = (c.free_point(n) for n in "ABC")
>>> bs = [c.angle_bisector(n, *p) for n, p in (("a", (B, A, C)), ("b", (A, B, C)), ("c", (A, C, B)))]
>>> c.conclude_concurrent(*bs)
>>> v = prove(c)
>>> v.status, v.branches.split(":")[0]
('proved', 'proved for every choice of root')
"""

from __future__ import annotations

import itertools
import math
import random
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Any

import sympy

from .. import ring as alg
from ..errors import ObjectTypeError, PgsymError
from ..exact import is_zero
from ..exact import sign as exact_sign
from .polynomials import PolynomialRing, default_backend

__all__ = [
    "MAX_POLYGON",
    "MAX_ROOTS",
    "Root",
    "angle_bisector",
    "circle_intersection",
    "circle_intersections",
    "external_bisector",
    "line_conic_intersection",
    "line_conic_intersections",
    "polygon_vertex",
    "prove_algebraic",
    "recheck_branch",
    "roots_of",
    "rotate_degrees",
    "tangent_from",
    "tangents_from",
]

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


@dataclass
class _Algebraic:
    roots: list[Root] = field(default_factory=list)
    readings: list[Callable[[dict[sympy.Symbol, int]], str]] = field(default_factory=list)
    # (object, its arguments, the candidates pgsym's core builds from their exact values) for the core check
    core: list[tuple[Node, tuple[Node, ...], Callable[..., Any]]] = field(default_factory=list)


def _data(claim: Claim) -> _Algebraic:
    data = claim.__dict__.get("algebraic")
    if data is None:
        data = claim.__dict__["algebraic"] = _Algebraic()
    return data


def roots_of(claim: Claim) -> list[Root]:
    """The roots a claim uses (empty for a claim without square roots).

    >>> roots_of(Claim("x", "x"))
    []
    """
    data = claim.__dict__.get("algebraic")
    return [] if data is None else data.roots


def _new_root(claim: Claim, name: str, kind: str, text: str, named: bool, **kw: Any) -> Root:
    data = _data(claim)
    if len([r for r in data.roots if r.kind != "unity"]) >= MAX_ROOTS and kind != "unity":
        raise ObjectTypeError(f"claim {claim.name!r} would need more than {MAX_ROOTS} square roots; "
                              "the exact evaluation visits every choice of their signs")
    (sym,) = claim.params(name)
    node = claim._free(f"_{name}", "scalar", (sym,))
    node.root = True  # normalisation: not a free object, fixed by its equation
    root = Root(sym, node, kind, text, named, **kw)
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

def _vector(p: Sequence[Any], q: Sequence[Any]) -> tuple[Any, Any]:
    """w_P w_Q (Q/w_Q − P/w_P): the vector from P to Q, scaled by w_P w_Q (right for any representatives)."""
    return (p[2] * q[0] - q[2] * p[0], p[2] * q[1] - q[2] * p[1])


def _length_square(p: Sequence[Any], q: Sequence[Any]) -> Any:
    v = _vector(p, q)
    return v[0] * v[0] + v[1] * v[1]


def _length_root(claim: Claim, a: Node, b: Node) -> Root:
    """The shared root d with d² = (w_A w_B)²|AB|², principal d = +w_A w_B |AB|."""
    x, y = sorted((a.name, b.name))
    name = f"d_{x}_{y}"
    for r in roots_of(claim):
        if str(r.symbol) == name:
            return r
    return _new_root(claim, name, "length", f"{name}² = (w_{x} w_{y})²·|{x}{y}|²", True,
                     square=lambda v: _length_square(v[a], v[b]), orient=lambda v: v[a][2] * v[b][2],
                     words=(f"+|{x}{y}|", f"−|{x}{y}|"))


def _bisector(claim: Claim, name: str, a: Any, b: Any, c: Any, internal: bool) -> Node:
    a, b, c = (claim._get(x, ("point",), "angle bisector") for x in (a, b, c))
    dba, dbc = _length_root(claim, b, a), _length_root(claim, b, c)
    sgn = 1 if internal else -1

    def line(pa: Any, pb: Any, pc: Any, uba: Any, ubc: Any) -> tuple[Any, ...]:
        va, vc = _vector(pb, pa), _vector(pb, pc)
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
        from .. import metric, projective_plane

        return metric.angle_bisectors(projective_plane.join(pb, pa), projective_plane.join(pb, pc))

    _data(claim).core.append((node, (a, b, c), core))
    return node


def angle_bisector(self: Claim, name: str, a: Any, b: Any, c: Any) -> Node:
    """The internal bisector of the angle ABC at B (the line through B with direction BA/|BA| + BC/|BC|).

    Uses the length roots ``d_A_B``, ``d_B_C`` (shared with every other construction that needs those lengths);
    on the named branch both are positive. Needs A ≠ B ≠ C.

    >>> c = Claim("x", "x")
    >>> A, B, C = (c.free_point(n) for n in "ABC")
    >>> c.angle_bisector("b", A, B, C).description, [str(r.symbol) for r in roots_of(c)]
    ('internal bisector of ∠ABC', ['d_A_B', 'd_B_C'])
    """
    return _bisector(self, name, a, b, c, True)


def external_bisector(self: Claim, name: str, a: Any, b: Any, c: Any) -> Node:
    """The external bisector of the angle ABC at B (direction BA/|BA| − BC/|BC|), with the length roots.

    >>> c = Claim("x", "x")
    >>> A, B, C = (c.free_point(n) for n in "ABC")
    >>> c.external_bisector("e", A, B, C).conditions[0].startswith("A ≠ B")
    True
    """
    return _bisector(self, name, a, b, c, False)


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
                 what: str) -> list[Node]:
    """One or two common points of a line l (or the radical axis of the circles K, M) and the conic K."""
    key = "_".join(names)
    line_of = (lambda vl, vk, vm: vl) if m is None else (lambda vl, vk, vm: _radical_line(vk, vm))
    base = [x for x in (l, k, m) if x is not None]

    def values(v: dict[Node, Any]) -> tuple[Any, Any, Any]:
        return (v[l] if l is not None else None, v[k], v[m] if m is not None else None)

    root = _new_root(claim, f"e_{key}", "intersection", f"e_{key}² = discriminant of {what}", False,
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
    root.text += "; " + (f"{names[0]} takes +e, {names[1]} −e" if len(names) > 1 else f"{names[0]} takes +e")

    def core(*objs: Any) -> tuple[Any, ...]:
        from ..conic_pencil import intersect_conics
        from ..conics import Conic

        if m is None:
            return Conic(objs[1]).intersections(objs[0])
        return intersect_conics(Conic(objs[0]), Conic(objs[1]))

    for node in out:
        _data(claim).core.append((node, tuple(base), core))
    readers = list(zip(names, (1, -1), strict=False))
    _data(claim).readings.append(
        lambda signs: ", ".join(f"{n} = (−β {'+' if signs[root.symbol] * s > 0 else '−'} √Δ)·P + α·Q, the "
                                f"{'first' if signs[root.symbol] * s > 0 else 'second'} common point of {what}"
                                for n, s in readers))
    return out


def line_conic_intersection(self: Claim, name: str, l: Any, k: Any) -> Node:
    """A common point of the line l and the circle (or conic) K, with no known common point: either root.

    >>> c = Claim("x", "x")
    >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
    >>> c.line_conic_intersection("X", c.free_line("l"), K).description
    'a common point of l and K'
    """
    l, k = self._get(l, ("line",), "intersection"), self._get(k, ("conic",), "intersection")
    return _meet_points(self, [name], l, k, None, f"{l.name} and {k.name}")[0]


def line_conic_intersections(self: Claim, names: Sequence[str], l: Any, k: Any) -> list[Node]:
    """Both common points of the line l and the circle (or conic) K, in either order (the roots ±e).

    >>> c = Claim("x", "x")
    >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
    >>> [n.name for n in c.line_conic_intersections(("X", "Y"), c.free_line("l"), K)]
    ['X', 'Y']
    """
    l, k = self._get(l, ("line",), "intersections"), self._get(k, ("conic",), "intersections")
    return _meet_points(self, list(names)[:2], l, k, None, f"{l.name} and {k.name}")


def circle_intersection(self: Claim, name: str, k: Any, m: Any) -> Node:
    """A common point of two circles K and M (either root): the radical axis meets K.

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

    >>> c = Claim("x", "x")
    >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
    >>> M = c.conic("M", [[1, 0, -1], [0, 1, 0], [-1, 0, -3]])
    >>> [n.description for n in c.circle_intersections(("X", "Y"), K, M)]
    ['a common point of K and M', 'the other common point of K and M']
    """
    k, m = (self._get(x, ("conic",), "intersections") for x in (k, m))
    return _meet_points(self, list(names)[:2], None, k, m, f"{k.name} and {m.name}")


def _tangents(claim: Claim, names: Sequence[str], p: Any, k: Any) -> list[Node]:
    p, k = claim._get(p, ("point",), "tangentfrom"), claim._get(k, ("conic",), "tangentfrom")
    polar = claim.polar(f"_polar_{k.name}_{p.name}_{'_'.join(names)}", k, p)
    touch = _meet_points(claim, [f"_touch_{n}" for n in names], polar, k, None,
                         f"the polar of {p.name} and {k.name}")
    lines = [claim.join(n, p, t) for n, t in zip(names, touch, strict=True)]

    def core(pp: Any, kk: Any) -> tuple[Any, ...]:
        from ..conics import Conic

        return Conic(kk).tangents_from(pp)

    for line in lines:
        _data(claim).core.append((line, (p, k), core))
    return lines


def tangent_from(self: Claim, name: str, p: Any, k: Any) -> Node:
    """A tangent from the point P to the circle (or conic) K: the line from P to a point where the polar of P
    meets K (either root; P must be outside K for real tangents).

    >>> c = Claim("x", "x")
    >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
    >>> c.tangent_from("t", c.free_point("P"), K).kind
    'line'
    """
    return _tangents(self, [name], p, k)[0]


def tangents_from(self: Claim, names: Sequence[str], p: Any, k: Any) -> list[Node]:
    """Both tangents from P to K, in either order (one root: the two points where the polar of P meets K).

    >>> c = Claim("x", "x")
    >>> K = c.conic("K", [[1, 0, 0], [0, 1, 0], [0, 0, -1]])
    >>> [n.name for n in c.tangents_from(("s", "t"), c.free_point("P"), K)], len(roots_of(c))
    (['s', 't'], 1)
    """
    return _tangents(self, list(names)[:2], p, k)


# -- roots of unity: rotations and regular polygons ---------------------------------------------------------

def _zeta(claim: Claim, modulus: int) -> Root:
    name = f"zeta_{modulus}"
    for r in roots_of(claim):
        if str(r.symbol) == name:
            return r
    return _new_root(claim, name, "unity", f"Φ_{modulus}({name}) = 0 (principal: {name} = e^(2πi/{modulus}))",
                     True, modulus=modulus)


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
        one = px[2] ** 0
        cr = _apply_terms(re, z) if not rational else sum(c for _, c in re) * one
        ci = _apply_terms(im, z) if not rational else sum(c for _, c in im) * one
        u = _vector(po, px)
        two_w = 2 * px[2]
        return (two_w * po[0] + cr * u[0] - ci * u[1], two_w * po[1] + ci * u[0] + cr * u[1], two_w * po[2])

    node = _similar(claim.formula(name, "point", rotated, *args, description=description,
                                  conditions=[f"{x.name} and {o.name} are finite points"]))

    def core(px: Any, po: Any) -> tuple[Any, ...]:
        from .. import metric
        from ..projective_plane import Point

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


def rotate_degrees(self: Claim, name: str, x: Any, o: Any, degrees: int) -> Node:
    """X rotated about O by an integer number of degrees (counter-clockwise; cos and sin in ℚ(ζ_M)).

    >>> c = Claim("x", "x")
    >>> c.rotate_degrees("Y", c.free_point("X"), c.free_point("O"), 60).description
    'X rotated about O by 60°'
    >>> [str(r.symbol) for r in roots_of(c)]
    ['zeta_12']
    """
    x, o = self._get(x, ("point",), "rotate"), self._get(o, ("point",), "rotate")
    if not isinstance(degrees, int) or isinstance(degrees, bool):
        raise ObjectTypeError(f"rotate: the angle is an integer number of degrees, got {degrees!r}")
    return _turn(self, name, x, o, Fraction(degrees % 360, 360), [1], f"{x.name} rotated about {o.name} by {degrees}°")


def polygon_vertex(self: Claim, name: str, a: Any, b: Any, n: int, k: int) -> Node:
    """The k-th vertex of the regular n-gon with consecutive vertices A (k = 0) and B (k = 1), counter-clockwise:
    ``A + (1 + ω + … + ω^{k−1})(B − A)`` with ω = e^{2πi/n}.

    >>> c = Claim("x", "x")
    >>> c.polygon_vertex("C", c.free_point("A"), c.free_point("B"), 5, 2).description
    'vertex 2 of the regular 5-gon A B …'
    """
    a, b = self._get(a, ("point",), "polygon"), self._get(b, ("point",), "polygon")
    if not all(isinstance(v, int) and not isinstance(v, bool) for v in (n, k)) or not 3 <= n <= MAX_POLYGON:
        raise ObjectTypeError(f"polygon: n is an integer from 3 to {MAX_POLYGON} and k an integer, got {n!r}, {k!r}")
    k %= n
    return _turn(self, name, b, a, Fraction(1, n), range(k), f"vertex {k} of the regular {n}-gon {a.name} {b.name} …") \
        if k else _similar(self.formula(name, "point", lambda p: p, a, description=f"vertex 0 of the regular {n}-gon"))


# -- the proof -------------------------------------------------------------------------------------------

class _Tower:
    """The defining equations as a triangular set (a lex Gröbner basis: leading terms root², or ζ^φ(M))."""

    def __init__(self, claim: Claim, gens: Sequence[sympy.Symbol], backend: str | None = None) -> None:
        roots = roots_of(claim)
        self.order = [r.symbol for r in reversed(roots)]
        self.R = PolynomialRing([*self.order, *gens], integral=False, order="lex",
                                backend=backend or default_backend())
        self.basis: list[Any] = []
        self.text: list[str] = []

    def add(self, root: Root, values: dict[Node, Any]) -> None:
        x = self.R(root.symbol)
        if root.kind == "unity":
            z = sympy.Symbol(str(root.symbol))
            poly = self.R(sympy.cyclotomic_poly(root.modulus, z).xreplace({z: root.symbol}))
        else:
            poly = x * x - self.reduce(root.square(values))
        self.basis.append(poly)
        self.text.append(root.text)

    def reduce(self, p: Any) -> Any:
        if not self.basis or isinstance(p, int):
            return p
        if self.R.backend == "sympy":
            return p.rem(self.basis)
        for g in reversed(self.basis):  # the latest root is the highest variable: its remainder first
            p = divmod(p, g)[1]
        return p


def _evaluate(claim: Claim, scalar: Callable[[Any], Any], tower: _Tower, deadline: Any,
              estimate: bool = False) -> dict[Node, Any]:
    """Every object's value, reduced modulo the roots' equations as they appear; with ``estimate`` a construction
    that would need more than the engine's MAX_WORK term products raises before it starts (a product in C cannot
    be interrupted by the time limit)."""
    from .engine import MAX_WORK, _estimate, _map, _TooLarge

    by_node = {r.node: r for r in roots_of(claim)}
    values: dict[Node, Any] = {}
    for node in claim.nodes.values():
        deadline.check(f"constructing {node.name}")
        args = [values[a] for a in node.args if isinstance(a, Node)]
        if estimate:
            work = _estimate(lambda v, node=node: node.operation.formula(node, v, scalar), args, tower.R)
            if work is not None and work > MAX_WORK:
                raise _TooLarge(f"{node.name} would need about {work:.1e} term products")
        values[node] = _map(node.operation.formula(node, args, scalar), tower.reduce)
        if node in by_node:
            tower.add(by_node[node], values)
    return values


def _requirements(claim: Claim, values: dict[Node, Any]) -> list[tuple[str, list[Any]]]:
    from .engine import _nonzero_requirements, _objects_to_check
    from .operations import flat

    out = list(_nonzero_requirements(claim, values))
    out += [(f"{n.name} is not the zero vector", flat(values[n])) for n in _objects_to_check(claim)]
    return out


def _sympy_value(R: PolynomialRing, p: Any, sub: dict[sympy.Symbol, Any]) -> sympy.Expr:
    if isinstance(p, (int, Fraction)):
        return sympy.Rational(p)
    return R.to_expr(p).xreplace(sub)


def _radical_zeta(modulus: int) -> bool:
    """SymPy writes cos and sin of 2π/M with radicals (M | 24 or M | 20, and a few more)."""
    angle = 2 * sympy.pi / modulus
    return not (sympy.cos(angle) + sympy.I * sympy.sin(angle)).has(sympy.cos, sympy.sin)


def _zeta_value(modulus: int) -> sympy.Expr:
    """e^{2πi/M} as an exact algebraic number (a root of Φ_M, chosen by its isolating interval)."""
    z = sympy.Symbol("z")
    target = complex(math.cos(2 * math.pi / modulus), math.sin(2 * math.pi / modulus))
    roots = sympy.Poly(sympy.cyclotomic_poly(modulus, z), z).all_roots()
    angle = 2 * sympy.pi / modulus
    radicals = sympy.cos(angle) + sympy.I * sympy.sin(angle)
    if not radicals.has(sympy.cos, sympy.sin):
        return radicals
    return min(roots, key=lambda r: abs(complex(r.evalf(30)) - target))  # selection only; roots differ by > 0.1


@dataclass
class _Branch:
    signs: dict[sympy.Symbol, int]
    values: dict[sympy.Symbol, sympy.Expr]
    named: bool
    text: str


def _branches(claim: Claim, tower: _Tower, values: dict[Node, Any], point: dict[sympy.Symbol, Any]):
    """Every real choice of the square roots at a rational point: their exact values and which branch it is."""
    roots = roots_of(claim)
    quadratic = [r for r in roots if r.kind != "unity"]
    base = {r.symbol: _zeta_value(r.modulus) for r in roots if r.kind == "unity"}
    R = tower.R
    for signs in itertools.product((1, -1), repeat=len(quadratic)):
        sgn = dict(zip((r.symbol for r in quadratic), signs, strict=True))
        sub = dict(base)
        real = True
        for r in quadratic:
            q = _sympy_value(R, tower.reduce(r.square(values)), sub)
            s = exact_sign(q)
            if s < 0:
                real = False
                break
            principal = 1
            if r.orient is not None:
                o = _sympy_value(R, tower.reduce(r.orient(values)), sub)
                principal = exact_sign(o)
            sub[r.symbol] = sgn[r.symbol] * principal * sympy.sqrt(q)
        if not real:
            continue
        named = all(sgn[r.symbol] > 0 for r in quadratic if r.named)
        words = [f"{r.symbol} = {r.words[0] if sgn[r.symbol] > 0 else r.words[1]}" for r in quadratic]
        readings = [f(sgn) for f in _data(claim).readings]
        text = "; ".join(x for x in (", ".join(words), "; ".join(readings)) if x)
        yield _Branch(sgn, sub, named, text or "the principal root of unity")


def _vanishes(R: PolynomialRing, p: Any, sub: dict[sympy.Symbol, Any], tower: _Tower | None = None) -> bool:
    if tower is not None:  # one root of unity and nothing else: Q[ζ]/Φ_M is the field Q(ζ), zero iff remainder zero
        return tower.reduce(p) == 0
    e = _sympy_value(R, p, sub)
    return bool(e == 0) if e.is_Rational else is_zero(e)


def _check_branch(claim: Claim, R: PolynomialRing, values: dict[Node, Any], reqs: list[tuple[str, list[Any]]],
                  branch: _Branch, deadline: Any, tower: _Tower | None = None) -> tuple[str, list[Any]]:
    from .engine import _conclusion_polys

    roots = roots_of(claim)
    if tower is not None and not (len(roots) == 1 and roots[0].kind == "unity"):
        tower = None

    def vanishes(p: Any, sub: dict[sympy.Symbol, Any]) -> bool:
        return _vanishes(R, p, sub, tower)

    for text, polys in reqs:
        deadline.check("checking a branch")
        if all(vanishes(p, branch.values) for p in polys):
            return "degenerate", [text]
    residuals = []
    for _label, poly in _conclusion_polys(claim, values):
        deadline.check("evaluating the conclusion on a branch")
        if not vanishes(poly, branch.values):
            residuals.append(_sympy_value(R, poly, branch.values))
    return ("fails", residuals) if residuals else ("holds", [])


def _instance(claim: Claim, rng: random.Random, bound: int, deadline: Any):
    params = [p for p in claim.parameters if p not in {r.symbol for r in roots_of(claim)}]
    point = {p: sympy.Integer(rng.randint(-bound, bound)) for p in params}
    tower = _Tower(claim, [])
    R = tower.R
    values = _evaluate(claim, lambda e: R(sympy.sympify(e).xreplace(point)), tower, deadline)
    return point, tower, values


def recheck_branch(claim: Claim, values: dict[str, Any], branch: dict[str, str]) -> bool:
    """True when, at these rational parameters and these exact values of the roots, the roots satisfy their
    defining equations, the constructions are defined and the conclusion fails (exact arithmetic throughout).

    >>> c = Claim("x", "x")
    >>> A, B, C = (c.point(n, *xy) for n, xy in zip("ABC", ((0, 0), (4, 0), (0, 3))))
    >>> c.conclude_incident(c.point("P", 1, 1), c.angle_bisector("a", B, A, C))   # the internal one: true
    >>> recheck_branch(c, {}, {"d_A_B": "4", "d_A_C": "3"}), recheck_branch(c, {}, {"d_A_B": "4", "d_A_C": "-3"})
    (False, True)
    """
    from .engine import _Deadline

    roots = {str(r.symbol): r for r in roots_of(claim)}
    point = {p: sympy.Rational(values[str(p)]) for p in claim.parameters if str(p) not in roots}
    tower = _Tower(claim, [])
    R = tower.R
    vals = _evaluate(claim, lambda e: R(sympy.sympify(e).xreplace(point)), tower, _Deadline(None))
    sub = {roots[k].symbol: sympy.sympify(v) for k, v in branch.items()}
    for r in roots.values():
        if r.kind == "unity":
            if not is_zero(sympy.cyclotomic_poly(r.modulus, sub[r.symbol])):
                return False
        elif not is_zero(sub[r.symbol] ** 2 - _sympy_value(R, tower.reduce(r.square(vals)), sub)):
            return False
    b = _Branch({}, sub, True, "")
    kind, _ = _check_branch(claim, R, vals, _requirements(claim, vals), b, _Deadline(None))
    return kind == "fails"


def _proportional(u: Sequence[Any], v: Sequence[Any]) -> bool:
    return all(is_zero(sympy.expand(u[i] * v[j] - u[j] * v[i])) for i in range(len(u)) for j in range(i + 1, len(u)))


def _core_object(node: Node, value: Any, tower: _Tower, branch: _Branch) -> Any:
    """A point, line or conic matrix of pgsym's core with the exact coordinates of ``value`` on the branch."""
    from ..projective_plane import Line, Point
    from .operations import flat

    if node.kind == "conic":
        return sympy.Matrix([[_sympy_value(tower.R, x, branch.values) for x in row] for row in value])
    coords = [_sympy_value(tower.R, x, branch.values) for x in flat(value)]
    return (Point if node.kind == "point" else Line)(*coords)


def _core_check(claim: Claim, rng: random.Random, deadline: Any) -> str:
    """At a rational instance, on the named branch, every algebraic object must be one of the objects pgsym's
    core builds from the same exact arguments (``metric.angle_bisectors``, ``Conic.intersections``,
    ``Conic.tangents_from``, ``metric.rotation``), so the proof's formulas and the library cannot drift."""
    from .operations import flat

    records = _data(claim).core
    if not records:
        return "not needed"
    slow = [r.modulus for r in roots_of(claim) if r.kind == "unity" and not _radical_zeta(r.modulus)]
    if slow:  # exact decisions about roots of unity without radicals (cos 2π/7, …) take too long
        return f"skipped: e^(2πi/{slow[0]}) has no expression in radicals here"
    for _ in range(8):
        deadline.check("comparing with pgsym's core objects")
        point, tower, values = _instance(claim, rng, 6, deadline)
        branch = next((b for b in _branches(claim, tower, values, point) if b.named), None)
        if branch is None:
            continue

        try:
            for node, args, build in records:
                mine = [_sympy_value(tower.R, x, branch.values) for x in flat(values[node])]
                candidates = build(*(_core_object(a, values[a], tower, branch) for a in args))
                if not any(_proportional(mine, list(c.coords)) for c in candidates):
                    return f"MISMATCH at {node.name}"
        except PgsymError as err:  # a degenerate instance or an undecidable cos(2π/7): try another
            last = str(err)
            continue
        return f"{len(records)} algebraic objects agree with pgsym's core at a rational instance (named branch)"
    return "skipped: no rational instance where the core could build every object" + (
        f" ({last[:80]})" if "last" in locals() else "")


def prove_algebraic(claim: Claim, timeout: float | None = 10.0, seed: int = 0, instances: int = 4,
                    backend: str | None = None) -> Any:
    """Decide a claim with square roots (called by :func:`pgsym.proofs.engine.prove` when the claim has roots).

    Proved for every choice of root when the conclusion is in the ideal of the defining equations (possibly
    after a non-degeneracy condition); otherwise evaluated exactly at ``instances`` random rational instances on
    every choice of signs of the roots: false (with the branch) when the named branch fails, unknown when only
    another branch fails. ``backend`` chooses the polynomial arithmetic as in :func:`~pgsym.proofs.engine.prove`.

    >>> c = Claim("x", "x")
    >>> A, B, C = (c.free_point(n) for n in "ABC")
    >>> c.conclude_perpendicular(c.angle_bisector("b", A, B, C), c.external_bisector("e", A, B, C))
    >>> prove_algebraic(c).branches[:33]
    'proved for every choice of root: '
    """
    from .engine import _alarm, _Deadline, _rng, _Timeout, _TooLarge
    from .verdicts import Certificate, Condition, Counterexample, Status, Verdict

    start = time.perf_counter()
    deadline = _Deadline(timeout)
    roots = roots_of(claim)
    rootsyms = {r.symbol for r in roots}
    base = dict(name=claim.name, title=claim.title, statement=claim.statement, expected=claim.expected,
                constructions=[(n.name, n.kind, n.description) for k, n in claim.nodes.items()
                               if not k.startswith("_")],
                hypotheses=[t for _, t in claim.hypotheses] + [r.text for r in roots],
                conclusion=[c.text for c in claim.conclusions])

    def done(status: Any, **kw: Any) -> Any:
        return Verdict(status=status, elapsed=time.perf_counter() - start, **base, **kw)

    def proved(certificate: Certificate, branches: str) -> Any:
        # the core rebuilds the objects at a rational instance first: a disagreement withholds the proof
        core = _core_check(claim, _rng(claim, seed), deadline)
        if core.startswith("MISMATCH"):
            return done(Status.UNKNOWN, core_check=core, branches="no decision",
                        reason=f"pgsym's core and the proof formulas disagree ({core})")
        return done(Status.PROVED, method=certificate.method, certificate=certificate, conditions=conditions,
                    branches=branches, core_check=core)

    if claim.hypotheses:
        return done(Status.UNKNOWN, reason="equation hypotheses together with square-root constructions are not "
                                           "supported", branches="no decision")
    try:
        with _alarm(timeout):
            from .engine import _conclusion_polys
            from .normalisation import normalise

            norm, _why = normalise(claim)
            sub = norm.substitution if norm is not None else {}
            params = [p for p in claim.parameters if p not in rootsyms and p not in sub]
            tower = _Tower(claim, params, backend)
            R = tower.R
            cache: dict[Any, Any] = {}

            def conv(e: Any) -> Any:
                if e not in cache:
                    cache[e] = R(sympy.sympify(e).xreplace(sub) if sub else e)
                return cache[e]

            values = _evaluate(claim, conv, tower, deadline, estimate=True)
            reqs = _requirements(claim, values)
            conditions = []
            for text, polys in reqs:
                deadline.check("checking the non-degeneracy conditions")
                if all(p == 0 for p in polys):
                    return done(Status.DEGENERATE, reason=f"the condition {text} fails identically (for every "
                                "value of the parameters and every choice of root)", branches="no decision")
                if not text.endswith("is not the zero vector"):
                    conditions.append(Condition(text, raw=[p for p in polys if p != 0][:3]))
            if norm is not None and norm.condition:
                conditions.append(Condition(f"{norm.condition} (frame)"))
            steps = ["triangular set (lex, roots first; a Gröbner basis): " + "; ".join(tower.text)]
            failing = None
            for label, poly in _conclusion_polys(claim, values, ring=R):
                deadline.check("reducing the conclusion")
                if poly == 0:
                    steps.append(f"{label} reduces to 0 modulo the defining equations")
                    continue
                needed = next((text for text, polys in reqs
                               if polys and all(tower.reduce(c * poly) == 0 for c in polys)), None)
                if needed is None:
                    failing = (label, poly)
                    break
                steps.append(f"{label} is not in the ideal, but c·({label}) is for every polynomial c of the "
                             f"condition {needed}: it vanishes wherever {needed}")
            if failing is None:
                from .operations import flat

                entries = [p for v in values.values() for p in flat(v) if not isinstance(p, int)]
                certificate = Certificate("ideal membership modulo the defining equations (Wu's method: a "
                                          "triangular set with unit initials)", R.field + f"[{len(R.symbols)} "
                                          "variables, lex, roots first]", steps,
                                          max((R.nterms(p) for p in entries), default=0), backend=R.backend,
                                          largest_degree=max((R.degree(p) for p in entries), default=0),
                                          normalisation="" if norm is None else norm.describe())
                return proved(certificate, _every_root(roots))
            named = _named_branch_proof(claim, values, tower, deadline)
            if named is not None:
                text, lines = named
                certificate = Certificate("ideal membership on the named branch: the named roots replaced by their "
                                          "rational values there, then reduction modulo the remaining equations",
                                          R.field + f"[{len(R.symbols)} variables, lex, roots first]",
                                          [*steps, *lines], 0, backend=R.backend,
                                          normalisation="" if norm is None else norm.describe())
                return proved(certificate, text)
            return _sample(claim, failing, R, rng=_rng(claim, seed), instances=instances, deadline=deadline,
                           done=done, counterexample=Counterexample)
    except _TooLarge as err:
        return done(Status.UNKNOWN, reason=f"the expansion is too large: {err.args[0]}", branches="no decision")
    except _Timeout as err:
        stage = err.args[0] if err.args else "working"
        return done(Status.UNKNOWN, reason=f"timed out after {timeout} s while {stage}", branches="no decision")
    except PgsymError as err:
        return done(Status.UNKNOWN, reason=f"the exact evaluation could not decide: {err}", branches="no decision")


def _evidently_positive(e: sympy.Expr, gens: Sequence[sympy.Symbol]) -> bool:
    """Every term has even exponents and a positive coefficient: positive wherever it is not zero."""
    poly = sympy.Poly(e, *gens) if gens else None
    if poly is None:
        return bool(e > 0)
    return not poly.is_zero and all(c > 0 and all(k % 2 == 0 for k in m) for m, c in poly.terms())


def _rational_root(q: sympy.Expr, gens: Sequence[sympy.Symbol]) -> sympy.Expr | None:
    """s with s² = q when q is the square of a polynomial with rational coefficients (else None)."""
    coeff, factors = sympy.factor_list(q, *gens) if gens else (q, [])
    if coeff < 0 or any(e % 2 for _, e in factors):
        return None
    c = sympy.sqrt(coeff)
    if not c.is_Rational:
        return None
    return c * sympy.Mul(*(f ** (e // 2) for f, e in factors))


def _named_branch_proof(claim: Claim, values: dict[Node, Any], tower: _Tower, deadline: Any
                        ) -> tuple[str, list[str]] | None:
    """Prove the conclusion on the named branch when that branch is rational: a named root whose square is the
    square of a polynomial s (e.g. |AB| for B = A + p²(1 − t², 2t), the tangent half-angle of Wu's school), or
    equals the square of an earlier root. The sign of the named root is then evident (s·w_A w_B a sum of even
    powers with positive coefficients), the root is replaced by ±s, and the conclusion must reduce to zero."""
    from .engine import _conclusion_polys

    R = tower.R
    roots = roots_of(claim)
    gens = [g for g in R.symbols if g not in {r.symbol for r in roots}]
    sub: dict[sympy.Symbol, sympy.Expr] = {}
    lines = []
    squares: dict[sympy.Symbol, sympy.Expr] = {}
    orients: dict[sympy.Symbol, sympy.Expr] = {}
    for r in roots:
        deadline.check("looking for a rational named branch")
        if r.kind == "unity":
            continue
        q = R.to_expr(tower.reduce(r.square(values)))
        squares[r.symbol] = q
        if not r.named or q.free_symbols & {x.symbol for x in roots}:
            continue
        orient = R.to_expr(r.orient(values)) if r.orient is not None else sympy.Integer(1)
        orients[r.symbol] = orient
        candidates = []  # (value up to sign, an expression with the sign of value·orient on the named branch)
        s = _rational_root(q, gens)
        if s is not None:
            candidates.append((s, s * orient))
        # the same square as an earlier length d_j: d = ±d_j; on the named branch d_j·orient_j > 0, so the sign of
        # d_j·orient is that of orient_j·orient (or d_j's value there, when it has one)
        # (or d = ±λ d_j when q = λ² q_j for a polynomial λ, e.g. a representative with w = 2)
        for same, qt in squares.items():
            if same == r.symbol or qt == 0 or same not in orients:  # only named lengths have a named sign
                continue
            num, den = sympy.fraction(sympy.cancel(q / qt))
            lam = _rational_root(num, gens) if den == 1 else None
            if lam is not None:
                candidates.append((lam * sub[same], lam * sub[same] * orient) if same in sub
                                  else (lam * same, lam * orients[same] * orient))
                break
        known = [*gens, *(x for x in squares if x != r.symbol)]
        for value, sign_of in candidates:
            product = sympy.expand(sign_of)
            if _evidently_positive(product, known):
                sub[r.symbol] = value
                break
            if _evidently_positive(-product, known):
                sub[r.symbol] = -value
                break
        else:
            continue
        lines.append(f"on the named branch {r.symbol} = {sub[r.symbol]} (its square is {r.symbol}² = {q}; "
                     f"its sign is that of the named root, as ({sub[r.symbol]})·({orient}) > 0)")
    if not sub:
        return None
    others = []
    for label, poly in _conclusion_polys(claim, values):
        deadline.check("reducing the conclusion on the named branch")
        expr = R.to_expr(tower.reduce(poly))
        named = tower.reduce(R(sympy.expand(expr.xreplace(sub))))
        if named != 0:
            return None
        lines.append(f"{label} reduces to 0 on the named branch")
        for signs in itertools.product((1, -1), repeat=len(sub)):
            flipped = {k: e * v for e, (k, v) in zip(signs, sub.items(), strict=True)}
            if not others and tower.reduce(R(sympy.expand(expr.xreplace(flipped)))) != 0:
                others.append((label, flipped))
    words = ", ".join(f"{k} = {v}" for k, v in sub.items())
    if others:
        label, flipped = others[0]
        other = f"on the other branch {', '.join(f'{k} = {v}' for k, v in flipped.items())}, {label} does not vanish"
    else:
        other = "it holds with every sign of these roots as well"
    return (f"proved for the named branch only ({words}: {_named_words(claim, sub)}); {other}", lines)


def _named_words(claim: Claim, sub: dict[sympy.Symbol, sympy.Expr]) -> str:
    signs = {r.symbol: 1 for r in roots_of(claim)}
    readings = [f(signs) for f in _data(claim).readings]
    return "; ".join(readings) or "the named roots"


def _every_root(roots: list[Root]) -> str:
    parts = []
    if any(r.kind == "length" for r in roots):
        parts.append("both signs of every length root (so internal and external bisectors alike, swapped in pairs)")
    if any(r.kind == "intersection" for r in roots):
        parts.append("both common points of every intersection")
    for m in sorted({r.modulus for r in roots if r.kind == "unity"}):
        parts.append(f"every conjugate ζ ↦ ζ^u of ζ = e^(2πi/{m}) (u prime to {m}: each angle a becomes u·a, "
                     "e.g. the clockwise figure and the star polygons)")
    return "proved for every choice of root: " + "; ".join(parts)


def _coordinates(claim: Claim, tower: _Tower, values: dict[Node, Any], branch: _Branch) -> str:
    """The exact coordinates of the claim's algebraic points on a branch, as text ("; X = (1, 2 + √3)")."""
    from .operations import flat

    out = []
    for node, _args, _build in _data(claim).core:
        if node.kind != "point" or node.name.startswith("_"):
            continue
        x, y, w = (_sympy_value(tower.R, v, branch.values) for v in flat(values[node]))
        if w == 0 or is_zero(w):
            continue
        out.append(f"{node.name} = ({sympy.radsimp(x / w)}, {sympy.radsimp(y / w)})")
    return "; " + "; ".join(out) if out else ""


def _sample(claim: Claim, failing: tuple[str, Any], R0: PolynomialRing, rng: random.Random, instances: int,
            deadline: Any, done: Callable[..., Any], counterexample: Any) -> Any:
    from .verdicts import Status

    seen = 0
    other_failure = None
    for attempt in range(12 * instances):
        deadline.check("evaluating random instances")
        point, tower, values = _instance(claim, rng, 3 + attempt // 4, deadline)
        reqs = _requirements(claim, values)
        branches = list(_branches(claim, tower, values, point))
        if not branches:
            continue
        results = [(b, _check_branch(claim, tower.R, values, reqs, b, deadline, tower)) for b in branches]
        if any(kind == "degenerate" for b, (kind, _) in results if b.named):
            continue
        for b, (kind, residuals) in results:
            if kind == "fails" and b.named:
                b.text += _coordinates(claim, tower, values, b)
                ce = counterexample({str(s): Fraction(int(v.p), int(v.q)) for s, v in point.items()},
                                    residuals, claim, branch={str(s): str(v) for s, v in b.values.items()})
                return done(Status.FALSE, counterexample=ce,
                            method="exact evaluation at a rational instance on each choice of root",
                            reason=f"the conclusion fails on the named branch ({b.text})",
                            branches=f"fails on the named branch: {b.text}")
            if kind == "fails" and other_failure is None:
                b.text += _coordinates(claim, tower, values, b)
                other_failure = (point, b, residuals)
        seen += 1
        if seen >= instances:
            break
    label, poly = failing
    if other_failure is not None:
        point, b, _ = other_failure
        at = ", ".join(f"{s} = {v}" for s, v in point.items())
        return done(Status.UNKNOWN,
                    reason=f"{label} is not in the ideal of the defining equations; the conclusion holds on the "
                           f"named branch at {seen} random instances, but fails on another branch, e.g. at {at} "
                           f"with {b.text}: not proved",
                    branches=f"holds on the named branch only ({_named_words(claim, {})}) at {seen} random instances; "
                             "not proved; "
                             f"fails on the branch {b.text}")
    return done(Status.UNKNOWN,
                reason=f"{label} has the nonzero remainder {R0.text(poly)[:200]} modulo the defining equations, "
                       f"yet the conclusion held on every branch at {seen} random instances (a degenerate component?)",
                branches=f"held on every branch at {seen} random instances; not proved")


# last, so that either module may be imported first: claims.py attaches the constructions above to Claim at its end
from .claims import Claim, Node  # noqa: E402
