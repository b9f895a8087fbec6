"""The decomposition H = H_S H_A H_P: worked examples, random exact matrices, and when it does not exist."""

from __future__ import annotations

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import integers

from pgsym.decomposition import affine_decomposition, decompose
from pgsym.errors import DecompositionError, SingularTransformationError

small = integers(5)


def test_affine_example_by_hand():
    # H = [[2,1,1],[0,2,3],[0,0,1]]: v = 0 vector, corner 1, so H_P = I and M = A = [[2,1],[0,2]].
    # MᵀM = [[4,2],[2,5]] = K'ᵀK' with K' = [[2,1],[0,2]]; det M = 4, s = 2, K = K'/2 = [[1,1/2],[0,1]],
    # R = M K'^-1 = I.
    d = decompose([[2, 1, 1], [0, 2, 3], [0, 0, 1]])
    assert d.H_P == sympy.eye(3)
    assert d.s == 2 and d.R == sympy.eye(2)
    assert d.K == sympy.Matrix([[1, sympy.Rational(1, 2)], [0, 1]])
    assert d.H_S == sympy.Matrix([[2, 0, 1], [0, 2, 3], [0, 0, 1]])
    assert d.verify()


def test_projective_example_by_hand():
    # H = [[1,0,0],[0,1,0],[1,2,1]]: A = I, t = 0, v = (1, 2), corner 1: M = I, so H_S = H_A = I, H_P = H
    d = decompose([[1, 0, 0], [0, 1, 0], [1, 2, 1]])
    assert d.H_S == sympy.eye(3) and d.H_A == sympy.eye(3)
    assert d.H_P == sympy.Matrix([[1, 0, 0], [0, 1, 0], [1, 2, 1]])


def test_reflection_goes_into_r():
    # diag(1, -1, 1): M = diag(1, -1), det M = -1 < 0, MᵀM = I so K = I, s = 1 and R = M (det R = -1)
    d = decompose(sympy.diag(1, -1, 1))
    assert d.R == sympy.diag(1, -1) and d.K == sympy.eye(2) and d.s == 1


def test_general_3x3_with_radicals():
    d = decompose([[2, 1, 1], [0, 2, 3], [1, 1, 3]])
    assert d.verify()
    assert any(e.has(sympy.sqrt(714)) for e in d.K)


@settings(max_examples=12, deadline=None)
@given(st.lists(small, min_size=9, max_size=9))
def test_random_exact_matrices_decompose(entries):
    M = sympy.Matrix(3, 3, entries)
    assume(M.det() != 0 and M[2, 2] != 0)
    d = decompose(M.tolist())
    assert d.verify()
    # K upper triangular with det 1; H_P carries the last row of H
    assert d.H_P[2, :] == M[2, :]


def test_a_4x4_example():
    d = decompose([[2, 0, 1, 1], [1, 3, 0, 0], [0, 1, 1, 2], [1, 0, 0, 2]])
    assert d.verify()


def test_corner_entry_zero_has_no_decomposition():
    with pytest.raises(DecompositionError, match="corner entry"):
        decompose([[1, 0, 0], [0, 0, 1], [0, 1, 0]])


def test_singular_matrix():
    with pytest.raises(SingularTransformationError):
        decompose([[1, 2, 3], [2, 4, 6], [1, 1, 1]])


def test_symbolic_matrix_is_refused():
    a = sympy.Symbol("a")
    with pytest.raises(DecompositionError):
        decompose([[a, 1, 0], [0, 1, 0], [0, 0, 1]])


# -- A = R(θ) R(−φ) D R(φ) ---------------------------------------------------------------------------------
def test_affine_decomposition_recovers_known_factors():
    # φ with cos 3/5, sin 4/5; D = diag(5, 1): S = R(−φ) D R(φ) = [[61, −48], [−48, 89]] / 25
    # (61/25 = 9/5 + 16/25, −48/25 = −12/5 + 12/25, 89/25 = 16/5 + 9/25; trace 6, det 5).
    # θ a quarter turn: A = [[0, −1], [1, 0]] S = [[48, −89], [61, −48]] / 25
    A = sympy.Matrix([[48, -89], [61, -48]]) / 25
    d = affine_decomposition(A)
    assert (d.lambda1, d.lambda2) == (5, 1)
    assert (d.cos_theta, d.sin_theta) == (0, 1)
    # the axes are fixed up to a half turn: φ or φ + π
    assert (d.cos_phi, d.sin_phi) in {(sympy.Rational(3, 5), sympy.Rational(4, 5)),
                                      (sympy.Rational(-3, 5), sympy.Rational(-4, 5))}
    assert d.verify() and d.product() == A


def test_affine_decomposition_axis_aligned_and_reflections():
    d = affine_decomposition([[3, 0, 1], [0, 2, 2], [0, 0, 1]])
    assert (d.lambda1, d.lambda2, d.cos_theta, d.sin_theta, d.cos_phi, d.sin_phi) == (3, 2, 1, 0, 1, 0)
    assert list(d.t) == [1, 2]
    # the swap [[0, 1], [1, 0]]: AᵀA = I, det −1, so λ = (1, −1) and R(θ) = A diag(1, −1) = [[0, −1], [1, 0]]
    d = affine_decomposition([[0, 1], [1, 0]])
    assert (d.lambda1, d.lambda2, d.cos_theta, d.sin_theta) == (1, -1, 0, 1) and d.verify()
    # a scaled last row is divided out: 2·(x ↦ 3x) is still the scaling by 3
    assert affine_decomposition([[6, 0, 0], [0, 6, 0], [0, 0, 2]]).D == sympy.diag(3, 3)


def test_affine_decomposition_errors():
    with pytest.raises(DecompositionError):
        affine_decomposition([[1, 0, 0], [0, 1, 0], [1, 0, 1]])       # projective
    with pytest.raises(SingularTransformationError):
        affine_decomposition([[1, 2], [2, 4]])
    with pytest.raises(DecompositionError):
        affine_decomposition([[sympy.Symbol("a"), 0], [0, 1]])
    with pytest.raises(DecompositionError):
        affine_decomposition([[sympy.I, 0], [0, 1]])
    with pytest.raises(DecompositionError):
        affine_decomposition(sympy.eye(4))


@settings(max_examples=10, deadline=None)
@given(small, small, small, small, small, small)
def test_affine_decomposition_multiplies_back(a, b, c, e, tx, ty):
    A = sympy.Matrix([[a, b], [c, e]])
    assume(A.det() != 0)
    d = affine_decomposition([[a, b, tx], [c, e, ty], [0, 0, 1]])
    assert d.verify() and list(d.t) == [tx, ty]
    # λ1 λ2 = det A, λ1 > 0, and λ2 has the sign of det A
    from pgsym.exact import is_zero, sign

    assert is_zero(sympy.radsimp(d.lambda1 * d.lambda2 - A.det()))
    assert sign(d.lambda1) == 1 and sign(d.lambda2) == sign(A.det())
