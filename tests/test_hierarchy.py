"""The classes of the hierarchy: parametrisations, derived DoF, classify, rotations and rigid motions."""

from __future__ import annotations

from fractions import Fraction

import pytest
import strategies
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pgsym.errors import (
    DegenerateConfigurationError,
    DimensionError,
    InvalidCoordinatesError,
    NonFiniteError,
    ObjectTypeError,
    SingularTransformationError,
)
from pgsym.hierarchy import (
    AFFINE_2D,
    AFFINE_3D,
    CLASSES_2D,
    CLASSES_3D,
    EUCLIDEAN_2D,
    EUCLIDEAN_3D,
    ISOMETRY_2D,
    ISOMETRY_3D,
    PROJECTIVE_2D,
    PROJECTIVE_3D,
    SIMILARITY_2D,
    SIMILARITY_3D,
    cayley_parameter,
    class_by_key,
    classify,
    dof_table,
    rotation_2d,
    rotation_3d,
)
from pgsym.homogeneous import is_zero
from pgsym.transformations import Transformation

rationals = strategies.rationals(5, 6)
nonzero = strategies.nonzero_rationals(5, 6)

# -- DoF ------------------------------------------------------------------------------------------

EXPECTED_DOF = {
    "euclidean2": 3, "isometry2": 3, "similarity2": 4, "affine2": 6, "projective2": 8,
    "euclidean3": 6, "isometry3": 6, "similarity3": 7, "affine3": 12, "projective3": 15,
}


@pytest.mark.parametrize("cls", CLASSES_2D + CLASSES_3D, ids=lambda c: c.key)
def test_dof_is_proved(cls):
    d = cls.dof()
    assert d.proved and d.dof == EXPECTED_DOF[cls.key] == d.lower == d.upper


def test_dof_table_gives_the_eight_numbers():
    assert [r["dof"] for r in dof_table()] == [3, 4, 6, 8, 6, 7, 12, 15]


@settings(max_examples=10, deadline=None)
@given(st.integers(0, 10_000))
def test_dof_does_not_depend_on_the_random_point(seed):
    assert [c.dof(seed).dof for c in (SIMILARITY_2D, EUCLIDEAN_3D, PROJECTIVE_2D)] == [4, 6, 8]


def test_upper_bound_uses_homogeneity_only_where_it_holds():
    # the projective parametrisation is linear in its nine entries; the others are not homogeneous
    assert PROJECTIVE_2D.is_homogeneous() and PROJECTIVE_3D.is_homogeneous()
    assert not AFFINE_2D.is_homogeneous() and not SIMILARITY_2D.is_homogeneous()
    assert PROJECTIVE_2D.dof().upper == 8 and AFFINE_2D.dof().upper == 6


def test_rank_at_a_degenerate_point_is_only_a_lower_bound():
    # at k = 0 the 3D similarity collapses to a translation: the columns of a, b, c vanish (k R'), so only
    # those of k, t_x, t_y, t_z and the scale column survive: rank 5, DoF ≥ 4 only, not 7
    J = SIMILARITY_3D.jacobian_at([0, 1, 2, 3, 4, 5, 6])
    from pgsym.hierarchy import _rank

    assert _rank(J) == 5


def test_similarity_2d_is_polynomial_in_its_parameters():
    # sR = [[a, -b], [b, a]] with a = s cos θ, b = s sin θ; the reflected piece negates the second column
    a, b, tx, ty = SIMILARITY_2D.parameters
    assert SIMILARITY_2D.generic() == sympy.Matrix([[a, -b, tx], [b, a, ty], [0, 0, 1]])
    assert SIMILARITY_2D.generic(1) == sympy.Matrix([[a, b, tx], [b, -a, ty], [0, 0, 1]])
    # a = 3, b = 4: scale √(9 + 16) = 5, so (1, 0) ↦ (3, 4) + (1, 1) = (4, 5)
    from pgsym.projective_plane import Point

    assert SIMILARITY_2D.element(3, 4, 1, 1)(Point(1, 0)) == Point(4, 5)
    # a = b = 0 is no transformation at all
    with pytest.raises(SingularTransformationError):
        SIMILARITY_2D.element(0, 0, 1, 1)


@pytest.mark.parametrize("cls", [EUCLIDEAN_2D, SIMILARITY_2D, EUCLIDEAN_3D], ids=lambda c: c.key)
def test_forward_derivatives_equal_the_symbolic_jacobian(cls):
    point = [Fraction(k + 2, k + 3) for k in range(cls.n_parameters)]
    exact = cls.jacobian_at(point)
    J = cls.jacobian().subs(dict(zip(cls.parameters, [sympy.Rational(p.numerator, p.denominator) for p in point],
                                     strict=True)))
    assert [[sympy.Rational(x.numerator, x.denominator) for x in row[:-1]] for row in exact] == J.tolist()


def test_element_constructors_and_errors():
    # t = 1: cos = 0, sin = 1, a quarter turn; translation (2, 3)
    assert EUCLIDEAN_2D.element(1, 2, 3).matrix == sympy.Matrix([[0, -1, 2], [1, 0, 3], [0, 0, 1]])
    # reflection component with t = 0: diag(1, -1)
    assert ISOMETRY_2D.element(0, 0, 0, component=1).matrix == sympy.diag(1, -1, 1)
    with pytest.raises(DimensionError):
        AFFINE_2D.element(1, 2, 3)
    with pytest.raises(DimensionError):
        AFFINE_2D.generic(1)
    with pytest.raises(SingularTransformationError):
        AFFINE_2D.element(1, 2, 2, 4, 0, 0)
    with pytest.raises(ObjectTypeError):
        class_by_key("conformal")


# -- rotations ------------------------------------------------------------------------------------


def test_rational_rotation_2d_by_hand():
    # t = 1/2: (1 - 1/4)/(1 + 1/4) = 3/5, (2 * 1/2)/(5/4) = 4/5
    assert rotation_2d(sympy.Rational(1, 2)) == [[sympy.Rational(3, 5), -sympy.Rational(4, 5)],
                                                 [sympy.Rational(4, 5), sympy.Rational(3, 5)]]
    assert cayley_parameter(sympy.Rational(3, 5), sympy.Rational(4, 5)) == sympy.Rational(1, 2)
    with pytest.raises(DegenerateConfigurationError):
        cayley_parameter(-1, 0)
    with pytest.raises(InvalidCoordinatesError):
        cayley_parameter(1, 1)


def test_generic_rotations_are_orthogonal_with_determinant_one():
    for cls in (EUCLIDEAN_2D, EUCLIDEAN_3D):
        n = cls.dim
        R = cls.generic()[:n, :n]
        assert all(is_zero(e) for e in (R.T * R - sympy.eye(n)))
        assert is_zero(R.det() - 1)
    R = ISOMETRY_2D.generic(1)[:2, :2]
    assert all(is_zero(e) for e in (R.T * R - sympy.eye(2))) and is_zero(R.det() + 1)


def test_rigid_motion_preserves_length_and_cross_product():
    a, b, c = sympy.symbols("a b c")
    R = sympy.Matrix(rotation_3d(a, b, c))
    u, v = sympy.Matrix(sympy.symbols("u1:4")), sympy.Matrix(sympy.symbols("v1:4"))
    assert all(is_zero(e) for e in (R * u).cross(R * v) - R * u.cross(v))
    assert is_zero((R * u).dot(R * u) - u.dot(u))
    # the columns of R are the images of the axes
    for i in range(3):
        assert R * sympy.eye(3)[:, i] == R[:, i]


def test_float_rotation_3d_is_finite_or_a_named_error():
    # (a, b, c) = (0, 0, 1): the quarter turn about z, as for exact input
    assert rotation_3d(0.0, 0.0, 1.0) == [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]
    # (0, 0, 1e200) is the quaternion (1e-200, 0, 0, 1) up to scale: R00 = w² − c² = −1, R01 = −2wc = −2e-200
    R = rotation_3d(0.0, 0.0, 1e200)
    assert R[0][:2] == [-1.0, -2e-200] and R[2][2] == 1.0
    # (1/2, 0, 0): n = 5/4, R11 = (1 − 1/4)/n = 3/5, R21 = 2a/n = 4/5
    R = rotation_3d(0.5, 0.0, 0.0)
    assert abs(R[1][1] - 0.6) < 1e-15 and abs(R[2][1] - 0.8) < 1e-15
    for bad in ((0.0, float("inf"), 0.0), (float("nan"), 0.0, 0.0), (0, 0, float("-inf"))):
        with pytest.raises(NonFiniteError, match="rotation_3d"):
            rotation_3d(*bad)


def test_homogeneous_and_inhomogeneous_forms_agree():
    # X' = R X + t  <->  [R t; 0 1] (X, 1)
    H = EUCLIDEAN_3D.element(0, 0, 1, 1, 2, 3)  # quarter turn about z, then translation (1, 2, 3)
    from pgsym.space import Point3

    # (1, 0, 0) -> R: (0, 1, 0) -> + t: (1, 3, 3)
    assert H(Point3(1, 0, 0)).dehomogenize() == (1, 3, 3)


# -- classify -------------------------------------------------------------------------------------


@settings(max_examples=20, deadline=None)
@given(rationals, rationals, rationals, st.integers(1, 6))
def test_classify_euclidean_and_reflections(t, tx, ty, scale):
    H = EUCLIDEAN_2D.element(t, tx, ty)
    assert classify(H) is EUCLIDEAN_2D
    assert classify(Transformation(scale * H.matrix)) is EUCLIDEAN_2D
    assert classify(ISOMETRY_2D.element(t, tx, ty, component=1)) is ISOMETRY_2D


@settings(max_examples=20, deadline=None)
@given(rationals, rationals, rationals, rationals, st.integers(0, 1))
def test_classify_similarities(a, b, tx, ty, comp):
    # the scale is √(a² + b²): zero is singular, one is an isometry
    assume(a * a + b * b not in (0, 1))
    assert classify(SIMILARITY_2D.element(a, b, tx, ty, component=comp)) is SIMILARITY_2D


@settings(max_examples=20, deadline=None)
@given(st.lists(rationals, min_size=6, max_size=6))
def test_classify_affine(p):
    a11, a12, a21, a22 = p[:4]
    assume(a11 * a22 - a12 * a21 != 0)
    # a similarity exactly when the columns are orthogonal and of equal length
    similar = a11 * a12 + a21 * a22 == 0 and a11**2 + a21**2 == a12**2 + a22**2
    assume(not similar)
    assert classify(AFFINE_2D.element(*p)) is AFFINE_2D


@settings(max_examples=20, deadline=None)
@given(st.lists(st.integers(-5, 5), min_size=9, max_size=9))
def test_classify_projective(p):
    M = sympy.Matrix(3, 3, p)
    assume(M.det() != 0 and (M[2, 0], M[2, 1]) != (0, 0))
    assert classify(M.tolist()) is PROJECTIVE_2D


@settings(max_examples=15, deadline=None)
@given(rationals, rationals, rationals, nonzero)
def test_classify_3d(a, b, c, k):
    assume(abs(k) != 1 and k > 0)
    assert classify(EUCLIDEAN_3D.element(a, b, c, 1, 2, 3)) is EUCLIDEAN_3D
    assert classify(SIMILARITY_3D.element(k, a, b, c, 0, 0, 0)) is SIMILARITY_3D


@settings(max_examples=15, deadline=None)
@given(rationals, rationals, rationals, nonzero, st.integers(1, 5))
def test_classify_improper_3d(a, b, c, k, scale):
    # R diag(1, 1, −1): orthogonal with det −1, so an isometry but no rigid motion; k times it a similarity
    assume(abs(k) != 1)
    M = ISOMETRY_3D.element(a, b, c, 1, 2, 3, component=1)
    assert Transformation(M.matrix[:3, :3]).det < 0
    assert classify(M) is ISOMETRY_3D and classify(Transformation(scale * M.matrix)) is ISOMETRY_3D
    assert classify(SIMILARITY_3D.element(k, a, b, c, 0, 0, 0, component=1)) is SIMILARITY_3D
    # the float classifier agrees
    import numpy as np

    assert classify(np.array(M.matrix.tolist(), dtype=float)) is ISOMETRY_3D


def test_classify_3d_by_hand():
    # the mirror z = 0: AᵀA = I and det A = −1, an improper isometry, neither rigid motion nor merely affine
    assert classify(sympy.diag(1, 1, -1, 1)) is ISOMETRY_3D
    # the point reflection x ↦ −x (det −1 in 3D) with a translation; twice it (scale 2) is a similarity
    assert classify([[-1, 0, 0, 5], [0, -1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]]) is ISOMETRY_3D
    assert classify([[-2, 0, 0, 5], [0, -2, 0, 0], [0, 0, -2, 0], [0, 0, 0, 1]]) is SIMILARITY_3D
    # an improper isometry written with w = −1: A/w = diag(−1, −1, 1), det +1 — a half turn, a rigid motion
    assert classify(sympy.diag(1, 1, -1, -1)) is EUCLIDEAN_3D
    assert ISOMETRY_3D.contains(sympy.diag(1, 1, -1, 1)) and not EUCLIDEAN_3D.contains(sympy.diag(1, 1, -1, 1))
    assert SIMILARITY_3D.contains(sympy.diag(1, 1, -1, 1))
    assert classify([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]) is PROJECTIVE_3D
    assert classify(sympy.diag(2, 1, 1, 1)) is AFFINE_3D


def test_classify_numeric_with_tolerance():
    import numpy as np

    c, s = np.cos(0.3), np.sin(0.3)
    R = np.array([[c, -s, 1.5], [s, c, -2.0], [0.0, 0.0, 1.0]])
    assert classify(R) is EUCLIDEAN_2D
    assert classify(3.0 * R) is EUCLIDEAN_2D
    assert classify(R @ np.diag([2.0, 2.0, 1.0])) is SIMILARITY_2D
    sheared = R.copy()
    sheared[0, 0] += 1e-3  # no longer a similarity: the columns have different lengths
    assert classify(sheared) is AFFINE_2D
    assert classify(sheared, tol=1e-2) is EUCLIDEAN_2D
    with pytest.raises(SingularTransformationError):
        classify(np.zeros((3, 3)))
    with pytest.raises(DimensionError):
        classify(np.eye(2))


def test_classify_symbolic_generic_elements():
    # membership identically in the parameters
    assert classify(SIMILARITY_2D.generic()) is SIMILARITY_2D
    assert classify(AFFINE_2D.generic()) is AFFINE_2D
    assert classify(PROJECTIVE_3D.generic()) is PROJECTIVE_3D
    assert SIMILARITY_2D.contains(EUCLIDEAN_2D.element(1, 0, 0)) and not EUCLIDEAN_2D.contains(sympy.diag(2, 2, 1))
