"""Classical theorems stated in general position are proved in under a second each.

These are the theorems that timed out before coordinates were normalised (issue: Pascal through five
free points, Brianchon from five free tangents, Braikenridge–Maclaurin, Möbius's tetrahedra, Desargues
for two tetrahedra, Menelaus, Ceva). Each is stated with free points (or lines) only, so the engine must
choose the frame itself; the time is that of ``prove`` with the default backend.

The second point of a line on a conic given by a point of it, and the dual conic through five lines
(whose points are lines, so that Brianchon's sixth side is its second tangent through a point), are
written here as operations of their own (the fixture adds them for the test and removes them
afterwards); they commute with homographies, as the engine's normalisation requires.
"""

from __future__ import annotations

import time

import pytest

from pgsym import ring as alg
from pgsym.proofs import Claim, prove
from pgsym.proofs.operations import OPERATIONS, Operation, _conic_from_points

# the target is 1 s (bench/bench_proofs.py measures it); the suite allows 5× for a loaded machine, which still
# fails the expansion without a frame (minutes)
BUDGET_S = 5.0


def _second_point(node, v, scalar):
    # the line through A (on the conic C) and P meets C again at (PᵀCP)·A − 2(AᵀCP)·P:
    # C(λA + μP) = 2λμ AᵀCP + μ² PᵀCP (as AᵀCA = 0) vanishes at λ : μ = PᵀCP : −2AᵀCP
    c, a, p = v
    cp = alg.matvec(c, p)
    pcp, acp = alg.dot(p, cp), alg.dot(a, cp)
    return tuple(pcp * x - 2 * acp * y for x, y in zip(a, p, strict=True))


@pytest.fixture
def conic_operations():
    added = {
        "second_point": Operation("second_point", (("conic",), ("point", "line"), ("point", "line")), 1,
                                  _second_point, lambda n, d: f"second point of {n[1]}{n[2]} on {n[0]}",
                                  lambda n, name, d: [f"{name} is defined ({n[1]}{n[2]} is not tangent to {n[0]})"]),
        "dual_conic_through": Operation("dual_conic_through", (("line",),) * 5, "conic",
                                      lambda node, v, scalar: _conic_from_points(v),
                                      lambda n, d: f"dual conic({', '.join(n)})",
                                      lambda n, name, d: [f"{', '.join(n)} determine one conic"]),
    }
    assert not set(added) & set(OPERATIONS), "the fixture would shadow operations of the table"
    OPERATIONS.update(added)
    yield
    for k in added:
        del OPERATIONS[k]


def _meets(c, pairs):
    return [c.meet(name, c.join(name + "1", p, q), c.join(name + "2", r, s)) for name, (p, q, r, s) in pairs]


def _timed(c):
    t0 = time.perf_counter()
    v = prove(c)
    elapsed = time.perf_counter() - t0
    assert v.proved, (v.status, v.reason)
    assert v.certificate.normalisation.startswith("without loss of generality"), v.certificate.normalisation
    assert elapsed <= BUDGET_S, f"{c.name} took {elapsed:.2f} s"
    return v


def test_pascal_through_five_free_points(conic_operations):
    c = Claim("pascal-general", "Pascal for the conic through five free points")
    A, B, C, D, E, P = (c.free_point(n) for n in "ABCDEP")
    K = c.conic_through("K", A, B, C, D, E)
    F = c._construct("second_point", "F", (K, A, P))
    X, Y, Z = _meets(c, [("X", (A, B, D, E)), ("Y", (B, C, E, F)), ("Z", (C, D, F, A))])
    c.conclude_collinear(X, Y, Z)
    v = _timed(c)
    # the frame A, B, C, D: its four triples are independent, each stated as a condition
    assert [k.text for k in v.conditions[-4:]] == [f"{t} are not collinear (frame)"
                                                  for t in ("A, B, C", "A, B, D", "A, C, D", "B, C, D")]


def test_pascal_with_the_sixth_point_by_harmonic_conjugation():
    # the table's operations only: the polar of P meets AP at H, and F is the harmonic conjugate of A with
    # respect to P and H (built with the complete quadrangle R, S, X, Y); then F is the second point on AP
    c = Claim("pascal-harmonic", "Pascal, sixth point built from the polar")
    A, B, C, D, E, P, R = (c.free_point(n) for n in "ABCDEPR")
    (s,) = c.params("s")
    K = c.conic_through("K", A, B, C, D, E)
    m = c.join("m", A, P)
    H = c.meet("H", c.polar("p", K, P), m)
    S = c.combine("S", R, A, 1, s)
    U = c.meet("U", c.join("PS", P, S), c.join("RH", R, H))
    W = c.meet("W", c.join("HS", H, S), c.join("RP", R, P))
    F = c.meet("F", c.join("UW", U, W), m)
    X, Y, Z = _meets(c, [("X", (A, B, D, E)), ("Y", (B, C, E, F)), ("Z", (C, D, F, A))])
    c.conclude_collinear(X, Y, Z)
    _timed(c)


def test_brianchon_from_five_free_tangents(conic_operations):
    c = Claim("brianchon-general", "Brianchon for the conic tangent to five free lines")
    a, b, cc, d, e, p = (c.free_line(n) for n in ("a", "b", "c", "d", "e", "p"))
    K = c._construct("dual_conic_through", "K", (a, b, cc, d, e))
    f = c._construct("second_point", "f", (K, a, p))  # the other tangent through the point a ∧ p
    sides = [a, b, cc, d, e, f]
    V = [c.meet(f"V{i}", sides[i], sides[(i + 1) % 6]) for i in range(6)]
    c.conclude_concurrent(*(c.join(f"d{i}", V[i], V[i + 3]) for i in range(3)))
    _timed(c)


def test_braikenridge_maclaurin():
    # the meets X = AB∧DE, Y = BC∧EF, Z = CD∧FA on one line L through X: F = EY ∧ AZ lies on the conic ABCDE,
    # i.e. on its own polar with respect to that conic
    c = Claim("braikenridge-maclaurin", "Braikenridge–Maclaurin")
    A, B, C, D, E, Q = (c.free_point(n) for n in "ABCDEQ")
    X = c.meet("X", c.join("AB", A, B), c.join("DE", D, E))
    L = c.join("L", X, Q)
    Y = c.meet("Y", c.join("BC", B, C), L)
    Z = c.meet("Z", c.join("CD", C, D), L)
    F = c.meet("F", c.join("EY", E, Y), c.join("AZ", A, Z))
    K = c.conic_through("K", A, B, C, D, E)
    c.conclude_incident(F, c.polar("tF", K, F))
    _timed(c)


def _on_plane(c, name, p, q, r, s, t):
    return c.combine(name, c.combine(name + "'", p, q, 1, s), r, 1, t)


def test_mobius_tetrahedra():
    # B_i lies on the face of A opposite A_i, and A_1, A_2, A_4 on faces of B: then A_3 lies on B_1B_2B_4
    c = Claim("mobius-tetrahedra", "Möbius's mutually inscribed tetrahedra")
    A1, A2, A3, A4 = (c.free_point3(n) for n in ("A1", "A2", "A3", "A4"))
    s1, t1, s2, t2, u = c.params("s1 t1 s2 t2 u")
    B1 = _on_plane(c, "B1", A2, A3, A4, s1, t1)
    B2 = _on_plane(c, "B2", A1, A3, A4, s2, t2)
    W = c.point_on_planes("W", c.plane_through("A1A2A4", A1, A2, A4), c.plane_through("A4B1B2", A4, B1, B2),
                          c.plane_through("A1A2A3", A1, A2, A3))
    B3 = c.combine("B3", A4, W, 1, u)
    B4 = c.point_on_planes("B4", c.plane_through("a4", A1, A2, A3), c.plane_through("A1B2B3", A1, B2, B3),
                           c.plane_through("A2B1B3", A2, B1, B3))
    c.conclude_incident(A3, c.plane_through("B1B2B4", B1, B2, B4))
    _timed(c)


def test_desargues_for_two_tetrahedra():
    c = Claim("desargues-3d", "Two tetrahedra in perspective from a point: corresponding edges meet on a plane")
    O = c.free_point3("O")
    A = [c.free_point3(f"A{i}") for i in range(1, 5)]
    ts = c.params("t1 t2 t3 t4")
    B = [c.combine(f"B{i + 1}", A[i], O, 1, t) for i, t in enumerate(ts)]

    def face(P, i, j, k):
        return c.plane_through(f"{P}{i}{j}{k}", *((A if P == "A" else B)[n - 1] for n in (i, j, k)))

    def edge_meet(i, j):  # line A_iA_j (two A-faces) meets the B-face through B_i, B_j
        k, l = (n for n in (1, 2, 3, 4) if n not in (i, j))
        return c.point_on_planes(f"X{i}{j}", face("A", i, j, k), face("A", i, j, l), face("B", i, j, k))

    X = {(i, j): edge_meet(i, j) for i, j in ((1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4))}
    for other in ((2, 3), (2, 4), (3, 4)):
        c.conclude_coplanar(X[1, 2], X[1, 3], X[1, 4], X[other])
    _timed(c)


def _ratio_along(b, d, cc):
    # the signed ratio BD/DC of collinear points, read on the x coordinate of the affine chart:
    # (D_x/D_w − B_x/B_w) / (C_x/C_w − D_x/D_w) = (D_x B_w − B_x D_w) C_w / ((C_x D_w − D_x C_w) B_w)
    return ((d[0] * b[2] - b[0] * d[2]) * cc[2], (cc[0] * d[2] - d[0] * cc[2]) * b[2])


def _product(*ratios):
    n, d = 1, 1
    for rn, rd in ratios:
        n, d = n * rn, d * rd
    return (n, d)


def test_menelaus():
    c = Claim("menelaus", "Menelaus: a transversal cuts the sides in ratios of product −1")
    A, B, C, P, Q = (c.free_point(n) for n in "ABCPQ")
    L = c.join("L", P, Q)
    D, E, F = (c.meet(n, c.join(n + "s", X, Y), L) for n, X, Y in (("D", B, C), ("E", C, A), ("F", A, B)))
    r = c.formula("r", "ratio", lambda *v: _product(_ratio_along(v[1], v[3], v[2]), _ratio_along(v[2], v[4], v[0]),
                                                     _ratio_along(v[0], v[5], v[1])), A, B, C, D, E, F)
    c.conclude_equal_ratio(r, -1)
    v = prove(c)
    assert v.proved and v.elapsed <= BUDGET_S, (v.status, v.elapsed)


def test_ceva():
    c = Claim("ceva", "Ceva: cevians through one point cut the sides in ratios of product 1")
    A, B, C, O = (c.free_point(n) for n in "ABCO")
    D, E, F = (c.meet(n, c.join(n + "s", X, Y), c.join(n + "c", Z, O))
               for n, X, Y, Z in (("D", B, C, A), ("E", C, A, B), ("F", A, B, C)))
    r = c.formula("r", "ratio", lambda *v: _product(_ratio_along(v[1], v[3], v[2]), _ratio_along(v[2], v[4], v[0]),
                                                     _ratio_along(v[0], v[5], v[1])), A, B, C, D, E, F)
    c.conclude_equal_ratio(r, 1)
    v = prove(c)
    assert v.proved and v.elapsed <= BUDGET_S, (v.status, v.elapsed)
