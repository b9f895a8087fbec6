"""The float classifier (pgsym.numeric.classify) agrees with the exact one and loads no SymPy."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
import sympy
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import rationals

from pgsym.errors import SingularTransformationError
from pgsym.hierarchy import CLASSES_2D, CLASSES_3D, classify
from pgsym.numeric.classify import classify_matrix
from pgsym.numeric.tolerances import CLASS_RTOL

# small rationals: their floats are exact to 1e-16, far inside CLASS_RTOL, so the float verdict must be the exact one


@st.composite
def exact_members(draw):
    """(class, exact 3×3 or 4×4 matrix) drawn from the generic element of a random class of the hierarchy."""
    c = draw(st.sampled_from(CLASSES_2D + CLASSES_3D))
    component = draw(st.integers(0, len(c.components) - 1))
    values = draw(st.lists(rationals(6, 5), min_size=c.n_parameters, max_size=c.n_parameters))
    try:
        return c, c.element(*values, component=component).matrix
    except SingularTransformationError:  # e.g. an affine map with a singular linear part: the float path refuses too
        matrix = sympy.Matrix(c.builder([sympy.Rational(v.numerator, v.denominator) for v in values], component))
        return c, matrix


@settings(max_examples=150, deadline=None)
@given(exact_members())
def test_float_classification_agrees_with_the_exact_one(member):
    _, M = member
    floats = np.array(M.tolist(), dtype=float)
    if M.det() == 0:
        with pytest.raises(SingularTransformationError):
            classify(floats)
        return
    want = classify(M).key
    assert classify(floats).key == want == classify_matrix(floats)
    # up to scale and in other units: conjugating by diag(s, …, s, 1) and scaling change no class
    n = floats.shape[0]
    D = np.diag([1024.0] * (n - 1) + [1.0])
    assert classify_matrix(-3.0 * D @ floats @ np.linalg.inv(D)) == want


def test_worked_examples_give_the_class_keys():
    # [[0, -2], [2, 0]] = 2 · (rotation by 90°): AᵀA = 4 I, a similarity whose ratio √4 / w = 2 ≠ 1
    assert classify_matrix([[0.0, -2, 5], [2, 0, 1], [0, 0, 1]]) == "similarity2"
    # diag(1, -1) has AᵀA = I and det −1: an isometry with a reflection
    assert classify_matrix(np.diag([1.0, -1, 1])) == "isometry2"
    # a projective row v = (1e-3, 0) with translation t = 0 is never affine (units can make v as large as A)
    assert classify_matrix([[1.0, 0, 0], [0, 1, 0], [1e-3, 0, 1]]) == "projective2"
    # a shear in 3D: AᵀA = [[1, 1, 0], [1, 2, 0], [0, 0, 1]] is no multiple of I, last row (0, 0, 0, 1)
    assert classify_matrix([[1.0, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) == "affine3"


def test_tolerance_is_the_named_constant():
    # A = [[1, δ], [0, 1]]: AᵀA − I has the off-diagonal entry δ, so δ below CLASS_RTOL is a rotation, above it not
    near = [[1.0, CLASS_RTOL / 10, 0], [0, 1, 0], [0, 0, 1]]
    far = [[1.0, CLASS_RTOL * 10, 0], [0, 1, 0], [0, 0, 1]]
    assert classify_matrix(near) == "euclidean2" and classify_matrix(far) == "affine2"
    assert classify_matrix(far, tol=1e-6) == "euclidean2"


def test_importing_the_classifier_loads_no_sympy_and_exact_classification_loads_no_numpy():
    code = (
        "import sys\n"
        "from pgsym.numeric.classify import classify_matrix\n"
        "assert classify_matrix([[1.0, 0, 0], [0, 1, 0], [0, 0, 1]]) == 'euclidean2'\n"
        "print('sympy' in sys.modules)\n"
    )
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout == "False\n"
    code = (
        "import sys\n"
        "from pgsym.hierarchy import classify\n"
        "assert classify([[1, 2, 0], [0, 1, 0], [0, 0, 1]]).key == 'affine2'\n"
        "print('numpy' in sys.modules)\n"
    )
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout == "False\n"


def test_improper_maps_of_space_agree_with_the_exact_classifier():
    import sympy

    # mirror z = 0 (isometry), a point reflection scaled by 3 (similarity), the mirror with w = −1 (a half turn)
    for M, key in ((np.diag([1.0, 1, -1, 1]), "isometry3"), (np.diag([-3.0, -3, -3, 1]), "similarity3"),
                   (np.diag([1.0, 1, -1, -1]), "euclidean3")):
        assert classify_matrix(M) == key
        assert classify(sympy.Matrix(M.astype(int).tolist())).key == key
