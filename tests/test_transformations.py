"""Projective transformations: construction, group structure, and the action on every kind of object.

Worked values are derived by hand in the comments; the properties run on random exact matrices and
random exact objects (ideal points and lines at infinity included).
"""

from __future__ import annotations

import pytest
import sympy
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import (
    homogeneous_triples,
    integers,
    invertible_matrices,
    lines,
    points,
    points3,
    symmetric_forms,
    transformations,
)

from pgsym.errors import DimensionError, ObjectTypeError, PgsymError, SingularTransformationError
from pgsym.projective_plane import Line, Point, collinear, concurrent, cross, incident, join, meet
from pgsym.transformations import Transformation, adjugate

small = integers(6)


def _space():
    import pgsym.space as space

    return space


# -- worked examples ----------------------------------------------------------------------------


def test_translation_moves_points_and_lines():
    # T = [[1,0,5],[0,1,0],[0,0,1]]: (1, 2) -> (6, 2). adj(T) = [[1,0,-5],[0,1,0],[0,0,1]],
    # so lines map by adj(T)^T = [[1,0,0],[0,1,0],[-5,0,1]]: x = 1, i.e. (1, 0, -1) -> (1, 0, -6), x = 6
    T = Transformation([[1, 0, 5], [0, 1, 0], [0, 0, 1]])
    assert T(Point(1, 2)).coords == (6, 2, 1)
    assert T(Line(1, 0, -1)).coords == (1, 0, -6)
    assert T.cofactor == sympy.Matrix([[1, 0, 0], [0, 1, 0], [-5, 0, 1]])


def test_rotation_by_a_quarter_turn():
    # R = [[0,-1,0],[1,0,0],[0,0,1]]: (1,0) -> (0,1); adj(R)^T = R, so the line y = 2, (0,1,-2),
    # becomes (-1, 0, -2), i.e. x = -2: rotating y = 2 by 90 degrees gives x = -2
    R = Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    assert R(Point(1, 0)) == Point(0, 1)
    assert R(Line(0, 1, -2)).coords == (-1, 0, -2)


def test_composition_and_inverse_by_hand():
    # S = diag(2, 2, 1), T = translation by (1, 0): S∘T maps (0,0) -> (1,0) -> (2,0); T∘S maps (0,0) -> (1,0)
    S = Transformation([[2, 0, 0], [0, 2, 0], [0, 0, 1]])
    T = Transformation([[1, 0, 1], [0, 1, 0], [0, 0, 1]])
    assert (S @ T)(Point(0, 0)) == Point(2, 0)
    assert (T @ S)(Point(0, 0)) == Point(1, 0)
    # adj(S) = diag(2, 2, 4) ~ diag(1/2, 1/2, 1)
    assert S.inverse().matrix == sympy.diag(2, 2, 4)
    assert S.inverse() == Transformation([[1, 0, 0], [0, 1, 0], [0, 0, 2]])


def test_equality_is_up_to_scale_and_repr_round_trips():
    H = Transformation([[1, 2, 3], [0, sympy.Rational(1, 2), 1], [0, 0, 1]])
    assert H == Transformation([[-2, -4, -6], [0, -1, -2], [0, 0, -2]])
    assert H != Transformation.identity(2)
    assert eval(repr(H), {"Transformation": Transformation, "S": sympy.S}) == H


def test_adjugate_is_det_times_inverse():
    M = sympy.Matrix([[2, 1, 0], [0, 1, 3], [1, 0, 1]])
    assert adjugate(M) == M.det() * M.inv()


def test_symbolic_transformation_maps_general_point():
    a, b = sympy.symbols("a b")
    H = Transformation([[a, 0, 0], [0, b, 0], [0, 0, 1]])
    x, y = sympy.symbols("x y")
    assert H(Point(x, y)) == Point(a * x, b * y)


# -- errors -------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("build", "error"),
    [
        (lambda: Transformation([[1, 2, 3], [2, 4, 6], [0, 0, 1]]), SingularTransformationError),
        (lambda: Transformation(sympy.eye(5)), DimensionError),  # 2×2 (P¹) to 4×4 (P³) only
        (lambda: Transformation([[1]]), DimensionError),
        (lambda: Transformation(sympy.eye(2))(Point(1, 2)), DimensionError),
        (lambda: Transformation([[1, 0, 0], [0, 1, 0]]), DimensionError),
        (lambda: Transformation("not a matrix"), DimensionError),
        (lambda: Transformation.identity(2)(3), ObjectTypeError),
        (lambda: Transformation.identity(2)(_space().Point3(1, 2, 3)), DimensionError),
        (lambda: Transformation.identity(3)(Point(1, 2)), DimensionError),
        (lambda: Transformation.identity(2) @ Transformation.identity(3), DimensionError),
        (lambda: Transformation.identity(4), DimensionError),
        (lambda: Transformation.identity(2).compose("x"), ObjectTypeError),
    ],
)
def test_named_errors(build, error):
    with pytest.raises(error) as info:
        build()
    assert isinstance(info.value, PgsymError)


def test_symbolic_singular_matrix_is_detected():
    t = sympy.Symbol("t")
    with pytest.raises(SingularTransformationError):
        Transformation([[t, t, 0], [1, 1, 0], [0, 0, 1]])


# -- properties: points and lines -----------------------------------------------------------------


@settings(max_examples=25, deadline=None)
@given(transformations(), points(), points())
def test_join_commutes_with_the_map(H, p, q):
    assume(p != q)
    assert H(join(p, q)) == join(H(p), H(q))


@settings(max_examples=25, deadline=None)
@given(transformations(), lines(), homogeneous_triples())
def test_incidence_is_preserved(H, l, v):
    coords = cross(l.coords, v)  # orthogonal to l: a point on l, unless v is proportional to l
    assume(any(c != 0 for c in coords))
    x = Point(*coords)
    assert incident(x, l) and incident(H(x), H(l))


@settings(max_examples=30, deadline=None)
@given(transformations(), lines(), lines())
def test_meet_commutes_with_the_map(H, l, m):
    assume(l != m)
    assert H(meet(l, m)) == meet(H(l), H(m))


@settings(max_examples=30, deadline=None)
@given(transformations(), points(), points(), st.integers(-4, 4), st.integers(-4, 4))
def test_collinear_and_concurrent_stay_so(H, p, q, s, t):
    combo = [s * a + t * b for a, b in zip(p.coords, q.coords, strict=True)]
    assume(any(c != 0 for c in combo))
    r = Point(*combo)
    assert collinear(H(p), H(q), H(r))
    lp, lq, lr = (Line(*x.coords) for x in (p, q, r))
    assert concurrent(H(lp), H(lq), H(lr))


@settings(max_examples=30, deadline=None)
@given(transformations(), transformations(), points())
def test_composition_and_inverse_act_correctly(H, G, x):
    assert (H @ G)(x) == H(G(x))
    assert H.inverse()(H(x)) == x
    assert (H @ H.inverse()) == Transformation.identity(2)


@settings(max_examples=30, deadline=None)
@given(transformations(), lines())
def test_line_rule_is_h_inverse_transpose(H, l):
    expected = H.matrix.inv().T * sympy.Matrix(l.coords)
    assert H(l) == Line(*expected)


# -- conics and dual conics ----------------------------------------------------------------------


@settings(max_examples=20, deadline=None)
@given(transformations())
def test_points_of_a_conic_map_to_points_of_the_image_conic(H):
    from pgsym.conics import Conic

    C = Conic.circle(0, 0, 5)
    C2 = H(C)
    # the matrix rule: C' ∝ H^-T C H^-1
    assert C2 == Conic(H.matrix.inv().T * C.matrix * H.matrix.inv())
    for p in (Point(3, 4), Point(5, 0), Point(-4, 3), Point(0, -5)):
        assert C.contains(p) and C2.contains(H(p))
        assert H(C.tangent_at(p)) == C2.tangent_at(H(p))


@settings(max_examples=20, deadline=None)
@given(transformations())
def test_dual_conic_rule_matches_dual_of_image(H):
    from pgsym.conics import Conic, DualConic

    C = Conic.from_coefficients(1, 1, 2, -3, 1, -5)
    assume(not C.is_degenerate)
    assert H(C.dual()) == H(C).dual()
    assert H(C.dual()) == DualConic(H.matrix * C.dual().matrix * H.matrix.T)


# -- 3D ------------------------------------------------------------------------------------------


@settings(max_examples=20, deadline=None)
@given(transformations(4), points3(bound=6), points3(bound=6), points3(bound=6))
def test_planes_map_by_h_inverse_transpose(H, a, b, c):
    space = _space()
    assume(not any(x == y for x, y in ((a, b), (b, c), (a, c))))
    try:
        pi = space.plane_through(a, b, c)
    except PgsymError:
        assume(False)
    img = H(pi)
    assert all(img.contains(H(x)) for x in (a, b, c))
    assert img == space.Plane(*(H.matrix.inv().T * sympy.Matrix(pi.coords)))


@settings(max_examples=15, deadline=None)
@given(transformations(4), points3(bound=6), points3(bound=6))
def test_plucker_matrices_map_by_congruence(H, a, b):
    from pgsym.plucker import Line3

    assume(a != b)
    L = Line3.join(a, b)
    img = H(L)
    assert img == Line3.join(H(a), H(b))
    assert img.matrix == (H.matrix * L.matrix * H.matrix.T).applyfunc(sympy.expand)
    # the dual Plücker matrix maps by H^-T L* H^-1
    Hi = H.matrix.inv()
    assert img == Line3.from_dual_matrix(Hi.T * L.dual_matrix * Hi)


@settings(max_examples=15, deadline=None)
@given(transformations(4))
def test_quadric_points_map_to_image_quadric(H):
    from pgsym.quadrics import Quadric

    space = _space()
    Q = Quadric.sphere((0, 0, 0), 3)
    img = H(Q)
    for X in (space.Point3(3, 0, 0), space.Point3(1, 2, 2), space.Point3(0, -3, 0)):
        assert Q.contains(X) and img.contains(H(X))


# -- a homography from four correspondences -------------------------------------------------------


def test_homography_from_four_points_by_hand():
    # the unit square onto the square of side 2: the scaling diag(2, 2, 1)
    from pgsym.transformations import homography_from_points

    sq = [Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)]
    H = homography_from_points(sq, [Point(0, 0), Point(2, 0), Point(2, 2), Point(0, 2)])
    assert H == Transformation(sympy.diag(2, 2, 1))


@settings(max_examples=20, deadline=None)
@given(transformations(), st.lists(homogeneous_triples(), min_size=4, max_size=4))
def test_homography_from_points_recovers_the_map(H, triples):
    from pgsym.transformations import homography_from_points

    pts = [Point(*t) for t in triples]
    for i in range(4):
        others = [pts[j] for j in range(4) if j != i]
        assume(not collinear(*others))
    assert homography_from_points(pts, [H(p) for p in pts]) == H


def test_homography_from_collinear_points_is_refused():
    from pgsym.errors import CollinearPointsError
    from pgsym.transformations import homography_from_points

    pts = [Point(0, 0), Point(1, 1), Point(2, 2), Point(0, 1)]
    with pytest.raises(CollinearPointsError):
        homography_from_points(pts, pts)
    with pytest.raises(DimensionError):
        homography_from_points(pts[:3], pts[:3])


# -- one Transformation for P¹, P² and P³ ------------------------------------------------------------


def _line():
    import pgsym.projective_line as projective_line

    return projective_line


@settings(max_examples=30, deadline=None)
@given(transformations(2), transformations(2), st.tuples(small, small).filter(any))
def test_projective_map1_and_a_dim_one_transformation_agree(T, G, xy):
    P1 = _line()
    F = P1.ProjectiveMap1(T.matrix)
    p = P1.Point1(*xy)
    assert T.dim == F.dim == 1
    assert F(p) == T(p) and T @ p == F @ p
    assert F == T and T == F and hash(F) == hash(T)
    # composition in either order, with either class on the left, is the same map
    assert (F @ G)(p) == F(G(p))
    assert T @ P1.ProjectiveMap1(G.matrix) == F @ G
    assert type(F @ G) is P1.ProjectiveMap1 and type(G @ F) is Transformation
    assert F.inverse() == T.inverse()


def test_dim_one_transformation_by_hand():
    P1 = _line()
    # x -> 2x + 1 is [[2, 1], [0, 1]]: 3 -> 7, ∞ -> ∞; its adjugate [[1, -1], [0, 2]] is x -> (x - 1)/2
    T = Transformation([[2, 1], [0, 1]])
    assert T(P1.Point1(3)) == P1.Point1(7) and T(P1.Point1(1, 0)) == P1.Point1(1, 0)
    assert T.inverse().matrix == sympy.Matrix([[1, -1], [0, 2]])
    assert Transformation.identity(1) == P1.ProjectiveMap1.identity() == P1.ProjectiveMap1([[5, 0], [0, 5]])
    assert repr(T) == "Transformation([[2, 1], [0, 1]])"
    assert repr(P1.ProjectiveMap1(T)) == "ProjectiveMap1([[2, 1], [0, 1]])"
    with pytest.raises(ObjectTypeError):
        T(3)  # only ProjectiveMap1 reads numbers as points of P¹
    assert P1.ProjectiveMap1(T)(3) == P1.Point1(7)
    with pytest.raises(DimensionError, match=r"lives in P\^1; use a 2×2 matrix"):
        Transformation.identity(2)(P1.Point1(3))
    with pytest.raises(SingularTransformationError, match="maps P¹ onto a single point"):
        Transformation([[1, 2], [2, 4]])


# -- objects know how they transform --------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(transformations(), points(), points())
def test_a_lines_own_rule_is_the_join_of_the_image_points(H, p, q):
    # l = p × q; l' = adj(H)ᵀ l must be the line through H p and H q (the dual of the point rule)
    assume(p != q)
    l = join(p, q)
    assert l._transformed_by(H) == join(p._transformed_by(H), q._transformed_by(H))
    assert l._transformed_by(H) == H(l)


@settings(max_examples=20, deadline=None)
@given(transformations(4), points3(bound=6), points3(bound=6), points3(bound=6))
def test_a_planes_own_rule_is_the_plane_of_the_image_points(H, a, b, c):
    space = _space()
    try:
        pi = space.plane_through(a, b, c)
    except PgsymError:
        assume(False)
    assert pi._transformed_by(H) == space.plane_through(H(a), H(b), H(c))


def test_every_kind_declares_its_space():
    from pgsym.kinds import object_classes

    spaces = {kind: getattr(cls, "ambient_dim", None) for kind, cls in object_classes().items()}
    assert spaces == {"point1": 1, "point": 2, "line": 2, "conic": 2, "dual_conic": 2, "point3": 3,
                      "plane": 3, "line3": 3, "quadric": 3, "dual_quadric": 3, "transformation": None}


def test_a_transformation_names_what_it_acts_on():
    with pytest.raises(ObjectTypeError, match=r"acts on .*Point.*Line.*Conic"):
        Transformation.identity(2)(Transformation.identity(2))
    with pytest.raises(DimensionError, match=r"lives in P\^3; use a 4×4 matrix"):
        Transformation.identity(2)(_space().Point3(1, 2, 3))


# -- one exact matrix coercion ------------------------------------------------------------------------


def _coercions():
    from pgsym.conics import Conic, DualConic
    from pgsym.linalg import nullspace_exact, rank_exact
    from pgsym.plucker import Line3
    from pgsym.quadrics import Quadric

    P1 = _line()
    return {"Transformation": Transformation, "ProjectiveMap1": P1.ProjectiveMap1, "Conic": Conic,
            "DualConic": DualConic, "Quadric": Quadric, "Line3.from_matrix": Line3.from_matrix,
            "nullspace_exact": nullspace_exact, "rank_exact": rank_exact}


@pytest.mark.parametrize("name", list(_coercions()))
@pytest.mark.parametrize(
    ("bad", "error"),
    [
        (5, "DimensionError"),                       # no sequence of rows
        ("not a matrix", "DimensionError"),          # a string is no matrix, though iterable
        ([], "DimensionError"),                      # no rows
        ([[]], "DimensionError"),                    # no columns
        ([[1, 2], [3]], "DimensionError"),           # ragged rows
        ([[[1, 0], [0, 1]]], "DimensionError"),      # a 3-index array
        ([[1, "x"], [0, 1]], "NonNumericError"),     # a non-numeric entry (square 2×2, so shape passes first)
        ([[1, None], [0, 1]], "NonNumericError"),
        ([[float("nan"), 0], [0, 1]], "NonNumericError"),
    ],
)
def test_the_one_coercion_rejects_the_same_bad_inputs_everywhere(name, bad, error):
    from pgsym import errors

    build = _coercions()[name]
    expected = getattr(errors, error)
    if error == "NonNumericError" and name in ("Conic", "DualConic", "Quadric", "Line3.from_matrix"):
        expected = errors.DimensionError  # 2×2 is the wrong shape for these, which is checked first
    with pytest.raises(expected) as info:
        build(bad)
    assert isinstance(info.value, PgsymError)


# -- powers --------------------------------------------------------------------------------------------
def test_powers_by_hand():
    from pgsym.errors import InputLimitError

    # a translation by (1, 2) raised to 5 is the translation by (5, 10); to −2 the translation by (−2, −4)
    T = Transformation([[1, 0, 1], [0, 1, 2], [0, 0, 1]])
    assert (T**5).matrix == sympy.Matrix([[1, 0, 5], [0, 1, 10], [0, 0, 1]])
    assert T**-2 == Transformation([[1, 0, -2], [0, 1, -4], [0, 0, 1]])
    assert T**0 == Transformation.identity(2) and (T**0).dim == 2
    # a quarter turn has order 4; a 3D half turn about z squares to the identity
    R = Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    assert R**4 == Transformation.identity() and R**2 == Transformation([[-1, 0, 0], [0, -1, 0], [0, 0, 1]])
    assert Transformation(sympy.diag(-1, -1, 1, 1)) ** 2 == Transformation.identity(3)
    for bad in (1.5, sympy.Rational(1, 2), True, "2"):
        with pytest.raises(ObjectTypeError):
            T**bad
    with pytest.raises(InputLimitError):
        T ** (10**9)
    t = sympy.Symbol("t")
    with pytest.raises(InputLimitError):
        Transformation([[1, t, 0], [0, 1, 0], [0, 0, 1]]) ** 1000
    # symbolic shear: (x, y) ↦ (x + t y, y) raised to 3 is the shear by 3t
    assert Transformation([[1, t, 0], [0, 1, 0], [0, 0, 1]]) ** 3 == Transformation([[1, 3 * t, 0], [0, 1, 0],
                                                                                     [0, 0, 1]])


@settings(max_examples=25, deadline=None)
@given(invertible_matrices(3, 3), st.integers(-4, 4), st.integers(-4, 4))
def test_powers_add_exponents(m, a, b):
    H = Transformation(m)
    assert (H**a) @ (H**b) == H ** (a + b)
    assert H ** (-a) == (H**a).inverse()


@settings(max_examples=10, deadline=None)
@given(invertible_matrices(4, 2), st.integers(-3, 3))
def test_powers_in_space(m, a):
    H = Transformation(m)
    assert (H**a) @ H == H ** (a + 1)


# -- three points and a conic ----------------------------------------------------------------------------
CIRCLE_25 = [(5, 0), (0, 5), (-5, 0), (0, -5), (3, 4), (4, 3), (-3, 4), (-4, -3), (3, -4), (-4, 3)]


def test_homography_from_points_and_conics_by_hand():
    from pgsym.conic_pencil import homography_from_points_and_conics as hpc
    from pgsym.conics import Conic

    # the unit circle to itself, (1, 0), (0, 1), (−1, 0) to (0, 1), (−1, 0), (0, −1): the quarter turn
    C = Conic.circle(0, 0, 1)
    H = hpc([Point(1, 0), Point(0, 1), Point(-1, 0)], [Point(0, 1), Point(-1, 0), Point(0, -1)], C, C)
    assert H == Transformation([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    # (1, 0) ↔ (0, 1) and (−1, 0) ↦ (0, −1): the reflection in the line y = x
    H = hpc([Point(1, 0), Point(0, 1), Point(-1, 0)], [Point(0, 1), Point(1, 0), Point(0, -1)], C, C)
    assert H == Transformation([[0, 1, 0], [1, 0, 0], [0, 0, 1]])
    # the unit circle onto the parabola X² = YW with (0, −1), (0, 1), (1, 0) ↦ (0, 0), (0, 1, 0), (1, 1):
    # (x, y, w) ↦ (x, y + w, w − y) does it, since x² − (y + w)(w − y) = x² + y² − w², and
    # (0, −1, 1) ↦ (0, 0, 2), (0, 1, 1) ↦ (0, 2, 0), (1, 0, 1) ↦ (1, 1, 1); being unique, it is the answer
    P = Conic.from_coefficients(1, 0, 0, 0, -1, 0)
    src, dst = [Point(0, -1), Point(0, 1), Point(1, 0)], [Point(0, 0), Point(0, 1, 0), Point(1, 1)]
    assert hpc(src, dst, C, P) == Transformation([[1, 0, 0], [0, 1, 1], [0, -1, 1]])


def test_homography_from_points_and_conics_with_surds():
    from pgsym.conic_pencil import homography_from_points_and_conics as hpc
    from pgsym.conics import Conic

    r = sympy.sqrt(2)
    C = Conic.circle(0, 0, r)  # x² + y² = 2 through (1, 1), (−1, 1), (√2, 0)
    src = [Point(1, 1), Point(-1, 1), Point(r, 0)]
    G = Transformation([[1, 2, 0], [0, 1, 1], [1, 0, 2]])
    H = hpc(src, [G(p) for p in src], C, G(C))
    assert H == G


@settings(max_examples=15, deadline=None)
@given(invertible_matrices(3, 3), st.lists(st.sampled_from(CIRCLE_25), min_size=3, max_size=3, unique=True))
def test_homography_from_points_and_conics_is_the_unique_one(m, pts):
    from pgsym.conic_pencil import homography_from_points_and_conics as hpc
    from pgsym.conics import Conic

    G, C = Transformation(m), Conic.circle(0, 0, 5)
    src = [Point(*p) for p in pts]
    assert hpc(src, [G(p) for p in src], C, G(C)) == G


def test_homography_from_points_and_conics_errors():
    from pgsym.conic_pencil import homography_from_points_and_conics as hpc
    from pgsym.conics import Conic
    from pgsym.errors import CoincidentPointsError, DegenerateConicError, NotOnConicError

    C = Conic.circle(0, 0, 1)
    on = [Point(1, 0), Point(0, 1), Point(-1, 0)]
    with pytest.raises(NotOnConicError):
        hpc([Point(1, 0), Point(0, 1), Point(2, 0)], on, C, C)
    with pytest.raises(CoincidentPointsError):
        hpc([Point(1, 0), Point(1, 0), Point(-1, 0)], on, C, C)
    with pytest.raises(DegenerateConicError):
        hpc(on, on, C, Conic.from_coefficients(1, 0, -1, 0, 0, 0))
    with pytest.raises(DimensionError):
        hpc(on[:2], on[:2], C, C)
    with pytest.raises(ObjectTypeError):
        hpc(on, on, C, "circle")
    with pytest.raises(DimensionError):
        hpc(5, on, C, C)


# -- each class's image rule, in any ring ---------------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(invertible_matrices(3), points(), lines(), symmetric_forms(3))
def test_the_image_rules_run_on_plain_integers_as_on_sympy_objects(h, p, l, form):
    # the rule each class states (its image classmethod) gives on Python integers, with ring.Action, the
    # coordinates the transformation gives on the exact objects; and the rules keep the forms' values up to
    # det(H)²: lines map by adj(H)ᵀ, so (adj(H)ᵀ l)ᵀ (H x) = lᵀ adj(H) H x = det(H) lᵀx, and likewise
    # (Hx)ᵀ adj(H)ᵀ C adj(H) (Hx) = det(H)² xᵀCx, (adj(H)ᵀ l)ᵀ H C* Hᵀ (adj(H)ᵀ l) = det(H)² lᵀC*l
    from pgsym.conics import Conic, DualConic
    from pgsym.ring import Action, det, dot, matvec

    H, action, d = Transformation(h), Action(h), det(h)
    x, m = [int(v) for v in p.coords], [int(v) for v in l.coords]
    c = [[int(e) for e in row] for row in form.tolist()]
    for obj, data in ((p, x), (l, m), (Conic(form), c), (DualConic(form), c)):
        image = H(obj)
        expected = image.coords if hasattr(image, "coords") else tuple(tuple(r) for r in image.matrix.tolist())
        assert type(obj).image(data, action) == expected
    hx, hl = Point.image(x, action), Line.image(m, action)
    assert dot(hl, hx) == d * dot(m, x)
    assert dot(hx, matvec(Conic.image(c, action), hx)) == d * d * dot(x, matvec(c, x))
    assert dot(hl, matvec(DualConic.image(c, action), hl)) == d * d * dot(m, matvec(c, m))


def test_the_plucker_rule_maps_a_join_to_the_join_of_the_images():
    # L = A Bᵀ − B Aᵀ goes to H L Hᵀ = (HA)(HB)ᵀ − (HB)(HA)ᵀ: with A = (1, 0, 0, 1), B = (0, 1, 0, 1) and
    # H = [[1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] (x += y), HA = (1, 0, 0, 1), HB = (1, 1, 0, 1)
    from pgsym.plucker import Line3
    from pgsym.ring import Action

    space = _space()
    h = [[1, 1, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    line = Line3.join(space.Point3(1, 0, 0, 1), space.Point3(0, 1, 0, 1))
    image = Line3.image(line.coords, Action(h))
    assert image == Line3.join(space.Point3(1, 0, 0, 1), space.Point3(1, 1, 0, 1)).coords
    assert Transformation(h)(line).coords == image


def test_the_old_bare_coordinate_methods_warn_and_keep_their_values():
    """map_vector / map_form were public: they stay, deprecated, with the values they always had."""
    H = Transformation([[2, 0, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.warns(DeprecationWarning, match="H.action.point"):
        assert H.map_vector((1, 2, 3)) == (2, 2, 3)  # (2·1, 2, 3)
    with pytest.warns(DeprecationWarning):
        assert H.map_vector((1, 2, 3), covariant=True) == (1, 4, 6)  # adj(H)ᵀ = diag(1, 2, 2)
    with pytest.warns(DeprecationWarning, match="hyperplane_form"):
        assert H.map_form(sympy.eye(3)) == sympy.diag(4, 1, 1)  # H I Hᵀ = diag(4, 1, 1)
    with pytest.warns(DeprecationWarning):
        assert H.map_form(sympy.eye(3), covariant=True) == sympy.diag(1, 4, 4)  # diag(1, 2, 2)²
