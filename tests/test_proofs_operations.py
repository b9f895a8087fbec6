"""Formulas of the proof engine's constructions: the values they give in the proof's polynomial ring."""

from __future__ import annotations

from types import SimpleNamespace

import sympy
from hypothesis import given, settings
from strategies import integers

from pgsym import ring as alg
from pgsym.proofs.budget import Deadline
from pgsym.proofs.evaluation import evaluate
from pgsym.proofs.language import parse_statement
from pgsym.proofs.operations import _centre
from pgsym.proofs.polynomials import PolynomialRing


def values_of(text: str):
    claim = parse_statement(text)
    R = PolynomialRing(claim.parameters)
    values = evaluate(claim, lambda e: R(sympy.sympify(e)), None, Deadline(None))
    return R, {n.name: v for n, v in values.items()}


def test_the_centre_of_a_circle_through_three_points_is_read_off_its_matrix():
    # K = ((a, 0, b), (0, a, c), (b, c, f)) has adj(K)·(0, 0, 1)ᵀ = (−ab, −ac, a²) = a·(−b, −c, a) (cofactors of the
    # last row); the centre is (−b, −c, a), one degree of a lower than the adjugate's column
    R, v = values_of("points A B C\nconic k = circle A B C\npoint O = centre k\nprove on A k")
    k, o = v["k"], v["O"]
    a, b, c = k[0][0], k[0][2], k[1][2]
    assert o == (-b, -c, a)
    adj = alg.adjugate(k)
    assert all(adj[i][2] == a * x for i, x in enumerate(o))
    assert R.degree(o[2]) == R.degree(a) < R.degree(adj[2][2])


def test_the_centre_of_a_circle_given_by_centre_and_point_is_that_centre():
    # K = ((w², 0, −x w), (0, w², −y w), …) for the centre (x, y, w): (−b, −c, a) = (x w, y w, w²) = w·(x, y, w)
    _R, v = values_of("points A B\nconic k = circle A B\npoint O = centre k\nprove on B k")
    x, y, w = v["A"]
    assert v["O"] == (x * w, y * w, w * w)


@settings(max_examples=30, deadline=None)
@given(integers(6), integers(6), integers(6), integers(6), integers(6), integers(6))
def test_the_centre_of_a_general_conic_is_the_last_column_of_its_adjugate(p, q, r, s, t, u):
    # a conic that is no circle (the polar of a point, scaled): the full adjugate's last column, entry by entry
    m = ((p, q, r), (q, s, t), (r, t, u))
    node = SimpleNamespace(args=[SimpleNamespace(operation=SimpleNamespace(circle=False))])
    adj = alg.adjugate(m)
    assert _centre(node, [m], None) == (adj[0][2], adj[1][2], adj[2][2])
