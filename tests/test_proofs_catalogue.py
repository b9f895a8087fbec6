"""The catalogue: every true claim is proved, every false claim is refuted by a re-checkable counterexample."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest
import sympy
from sympy import Matrix, Rational

from pgsym.proofs import catalogue_names, get_claim, prove

TRUE = catalogue_names(True)
FALSE = catalogue_names(False)


def test_catalogue_sizes_and_required_theorems():
    assert len(TRUE) >= 40 and len(FALSE) >= 5
    for name in ("pappus", "desargues", "desargues-converse", "pascal", "brianchon", "complete-quadrilateral-harmonic",
                 "parallel-lines-meet-at-infinity", "lines-transform-by-inverse-transpose", "klein-quadric",
                 "plucker-matrix-rank-two", "cross-ratio-invariance", "plane-through-three-points",
                 "point-on-three-planes", "duality-join-meet", "dof-projective-2d", "dof-euclidean-3d"):
        assert name in TRUE, name


@pytest.mark.parametrize("name", TRUE)
def test_every_true_claim_is_proved_with_a_certificate(name):
    v = prove(name)
    assert v.proved, (v.status, v.reason)
    assert v.certificate is not None and v.certificate.steps
    assert "simplify" not in json.dumps(v.to_dict())
    assert v.counterexample is None
    assert not v.core_check.startswith("MISMATCH")


@pytest.mark.parametrize("name", FALSE)
def test_every_false_claim_is_refuted_and_the_counterexample_rechecks(name):
    v = prove(name)
    assert v.refuted and v.as_expected
    ce = v.counterexample
    assert ce is not None and any(r != 0 for r in ce.residuals)
    assert ce.recheck()  # rebuilt with pgsym's core objects
    assert INDEPENDENT[name](ce.values), "the raw formulas do not confirm the counterexample"


def test_conditions_name_the_constructions():
    v = prove("desargues")
    texts = [c.text for c in v.conditions]
    assert "A ≠ B" in texts and "A'B' ≠ AB" not in texts
    assert any("AB ≠ A'B'" == t for t in texts)
    assert all(c.polynomials for c in v.conditions)


def test_methods_are_named():
    assert prove("tangent-touches-conic").method == "Gröbner basis ideal membership"
    assert prove("similarity-fixes-circular-points").method == "Gröbner basis ideal membership"
    assert prove("pascal").method.startswith("rational parametrisation")
    assert prove("pappus").method.startswith("rational parametrisation")
    assert prove("desargues").method == "polynomial identity (exact expansion)"


def test_get_claim_builds_fresh_claims():
    a, b = get_claim("pappus"), get_claim("pappus")
    assert a is not b and a.nodes.keys() == b.nodes.keys()


# -- independent re-checks: the raw formulas, written out again here -------------------------------

def _q(values, name):
    v = values[name]
    return Rational(v.numerator, v.denominator) if isinstance(v, Fraction) else Rational(v)


def _pt(values, name):
    return Matrix([_q(values, f"{name}_x"), _q(values, f"{name}_y"), 1])


def _H(values, prefix, n=3):
    return Matrix(n, n, [_q(values, f"{prefix}{i}{j}") for i in range(1, n + 1) for j in range(1, n + 1)])


def _not_proportional(u, v):
    return any(u) and any(v) and any(u[i] * v[j] - u[j] * v[i] != 0 for i in range(len(u)) for j in range(len(u)))


def _lines_like_points(vals):
    A, B, H = _pt(vals, "A"), _pt(vals, "B"), _H(vals, "h")
    assert H.det() != 0 and A.cross(B) != sympy.zeros(3, 1)
    return _not_proportional((H * A).cross(H * B), H * A.cross(B))


def _sign_flipped(vals):
    a, b = _pt(vals, "A"), _pt(vals, "B")
    wrong = Matrix([a[1] * b[2] - a[2] * b[1], a[0] * b[2] - a[2] * b[0], a[0] * b[1] - a[1] * b[0]])
    return wrong.dot(a) != 0


def _cr(a, b, c, d):
    # the finite-point formula (a - c)(b - d) / ((a - d)(b - c)); denominators must not vanish
    assert (a - d) * (b - c) != 0
    return (a - c) * (b - d) / ((a - d) * (b - c))


def _squaring(vals):
    a, b, c, d = (_q(vals, n) for n in "abcd")
    return _cr(a, b, c, d) != _cr(a**2, b**2, d**2, c**2)


def _order(vals):
    a, b, c, d = (_q(vals, n) for n in "abcd")
    return _cr(a, b, c, d) != _cr(a, c, b, d)


def _parallelism(vals):
    H = _H(vals, "h")
    assert H.det() != 0
    la, lb, p, q = (_q(vals, n) for n in ("la", "lb", "p", "q"))
    l2 = H.inv().T * Matrix([la, lb, p])
    m2 = H.inv().T * Matrix([la, lb, q])
    x = l2.cross(m2)
    return any(x) and x[2] != 0


def _distance(vals):
    a, b, c, d = (_q(vals, n) for n in ("a", "b", "c", "d"))
    T = Matrix([[a, b], [c, d]])
    assert T.det() != 0
    A = Matrix([_q(vals, "A_x"), _q(vals, "A_y")])
    B = Matrix([_q(vals, "B_x"), _q(vals, "B_y")])
    return (T * (A - B)).dot(T * (A - B)) != (A - B).dot(A - B)  # the translation cancels


def _pascal_free(vals):
    P = {n: _pt(vals, n) for n in "ABCDEF"}

    def meet(p, q, r, s):
        return P[p].cross(P[q]).cross(P[r].cross(P[s]))

    X, Y, Z = meet("A", "B", "D", "E"), meet("B", "C", "E", "F"), meet("C", "D", "F", "A")
    assert any(X) and any(Y) and any(Z)
    return Matrix.hstack(X, Y, Z).det() != 0


def _klein_flipped(vals):
    A = Matrix([_q(vals, "A_x"), _q(vals, "A_y"), _q(vals, "A_z"), 1])
    B = Matrix([_q(vals, "B_x"), _q(vals, "B_y"), _q(vals, "B_z"), 1])
    L = A * B.T - B * A.T
    return L[0, 1] * L[2, 3] + L[0, 2] * L[1, 3] + L[0, 3] * L[1, 2] != 0


INDEPENDENT = {
    "lines-transform-like-points": _lines_like_points,
    "cross-product-sign-flipped": _sign_flipped,
    "cross-ratio-under-squaring": _squaring,
    "cross-ratio-order-irrelevant": _order,
    "homography-preserves-parallelism": _parallelism,
    "affine-preserves-distance": _distance,
    "pascal-without-conic": _pascal_free,
    "klein-relation-sign-flipped": _klein_flipped,
}


def test_every_false_claim_has_an_independent_check():
    assert set(INDEPENDENT) == set(FALSE)


# -- one parametrisation of each group: the hierarchy's ------------------------------------------------------

DOF_CLAIMS = {"dof-projective-2d": "projective2", "dof-affine-2d": "affine2", "dof-similarity-2d": "similarity2",
              "dof-euclidean-2d": "euclidean2", "dof-projective-3d": "projective3", "dof-affine-3d": "affine3",
              "dof-similarity-3d": "similarity3", "dof-euclidean-3d": "euclidean3"}


def _proportional_matrices(M, G):
    u, v = list(M), list(G)
    return any(u) and all(sympy.cancel(u[i] * v[j] - u[j] * v[i]) == 0 for i in range(len(u)) for j in range(len(u)))


@pytest.mark.parametrize("name", sorted(DOF_CLAIMS))
def test_dof_claims_use_the_hierarchy_parametrisation(name):
    from pgsym.hierarchy import class_by_key

    group = class_by_key(DOF_CLAIMS[name])
    claim = get_claim(name)
    # the claim's own parameters stand for the hierarchy's, in the same order
    ours = claim.parameters[: group.n_parameters]
    generic = group.generic().subs(dict(zip(group.parameters, ours, strict=True)), simultaneous=True)
    # the last column of [J | vec H] is vec H: the claim's matrix is the generic element times a scalar
    jac = Matrix(claim.nodes["H"].data)
    n = generic.rows
    H = Matrix(n, n, list(jac[:, -1]))
    assert _proportional_matrices(H, generic)
    assert jac.shape[1] == group.n_parameters + 1
    # and the catalogue's DoF is the one the hierarchy derives independently (exact Jacobian rank at a point)
    _, rank = claim.conclusions[0].args
    assert rank - 1 == group.dof().dof


@pytest.mark.parametrize(("name", "node", "key"), [("euclidean-preserves-distance", "E", "euclidean2"),
                                                   ("similarity-preserves-length-ratio", "S", "similarity2"),
                                                   ("affine-preserves-area-ratio", "T", "affine2")])
def test_invariant_claims_transform_by_the_hierarchy_generic_element(name, node, key):
    from pgsym.hierarchy import class_by_key

    group = class_by_key(key)
    claim = get_claim(name)
    ours = claim.parameters[: group.n_parameters]
    generic = group.generic().subs(dict(zip(group.parameters, ours, strict=True)), simultaneous=True)
    assert _proportional_matrices(Matrix(claim.nodes[node].data), generic)
