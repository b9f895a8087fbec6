"""The numeric metric kernels (pgsym.numeric.metric) against the exact ones (pgsym.metric), ideal elements included."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from strategies import integers

from pgsym import metric
from pgsym.errors import DimensionError, IdealPointError, NonFiniteError, OptionError
from pgsym.numeric import metric as nm
from pgsym.plucker import Line3
from pgsym.projective_plane import Line, Point
from pgsym.space import Plane, Point3

FAST = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

small = integers(5)


def rows(k: int, n: int = 5, ideal_last: bool = True):
    """(n, k) integer arrays with no zero row; the last coordinate is often 0 (ideal points) when allowed."""
    last = st.sampled_from([0, 0, 1, 2, -3]) if ideal_last else st.integers(1, 3)
    row = st.tuples(*([small] * (k - 1)), last).filter(any)
    return st.lists(row, min_size=1, max_size=n).map(lambda r: np.array(r, dtype=float))


def hyperplanes(k: int, n: int = 5):
    """(n, k) integer lines or planes; their normal part is sometimes zero (the line or plane at infinity)."""
    normal = st.tuples(*([st.sampled_from([0, 0, 1, -2, 3])] * (k - 1)), small)
    return st.lists(normal.filter(any), min_size=1, max_size=n).map(lambda r: np.array(r, dtype=float))


def exact_or_none(f, *args):
    """The exact value, or None where the exact core raises IdealPointError (the numeric mask says False)."""
    try:
        return f(*args)
    except IdealPointError:
        return None


def check_against(values, ok, expected, exact_equal=False):
    for i, e in enumerate(expected):
        if e is None:
            assert not ok[i]
            assert np.isnan(values[i]).all()
        else:
            assert ok[i]
            if exact_equal:
                assert list(values[i]) == [float(c) for c in e]
            else:
                assert values[i] == pytest.approx(float(e), rel=1e-12, abs=1e-12)


@given(hyperplanes(3), hyperplanes(3))
@FAST
def test_cos_angle_of_lines_agrees_with_exact(a, b):
    n = min(len(a), len(b))
    a, b = a[:n], b[:n]
    values, ok = nm.cos_angle(a, b, ideal="mask")
    check_against(values, ok, [exact_or_none(metric.cos_angle, Line(*x), Line(*y)) for x, y in zip(a, b, strict=True)])
    perp, ok2 = nm.is_perpendicular(a, b, ideal="mask")
    assert (ok2 == ok).all()
    for i in range(n):
        if ok[i]:
            assert perp[i] == metric.is_perpendicular(Line(*a[i]), Line(*b[i]))
    if not ok.all():
        with pytest.raises(IdealPointError):
            nm.cos_angle(a, b)
    else:
        assert np.array_equal(nm.cos_angle(a, b), values)


@given(hyperplanes(4), hyperplanes(4))
@FAST
def test_cos_angle_of_planes_agrees_with_exact(a, b):
    n = min(len(a), len(b))
    a, b = a[:n], b[:n]
    values, ok = nm.cos_angle(a, b, ideal="mask")
    check_against(
        values, ok, [exact_or_none(metric.cos_angle, Plane(*x), Plane(*y)) for x, y in zip(a, b, strict=True)]
    )


@given(rows(4, 4), rows(4, 4), rows(4, 4), rows(4, 4))
@FAST
def test_cos_angle_of_lines_of_space_agrees_with_exact(p, q, r, s):
    n = min(len(p), len(q), len(r), len(s))
    pairs = []
    for i in range(n):
        assume(not Point3(*p[i]).is_proportional(Point3(*q[i])))
        assume(not Point3(*r[i]).is_proportional(Point3(*s[i])))
        pairs.append((Line3.join(Point3(*p[i]), Point3(*q[i])), Line3.join(Point3(*r[i]), Point3(*s[i]))))
    a = np.array([[float(c) for c in l.coordinates] for l, _ in pairs])
    b = np.array([[float(c) for c in m.coordinates] for _, m in pairs])
    values, ok = nm.cos_angle(a, b, ideal="mask")
    check_against(values, ok, [exact_or_none(metric.cos_angle, l, m) for l, m in pairs])


@given(rows(3), hyperplanes(3))
@FAST
def test_point_line_distance_and_projection_agree_with_exact(x, l):
    n = min(len(x), len(l))
    x, l = x[:n], l[:n]
    values, ok = nm.point_line_distance(x, l, ideal="mask")
    check_against(values, ok, [exact_or_none(metric.distance, Point(*p), Line(*m)) for p, m in zip(x, l, strict=True)])
    feet, ok = nm.orthogonal_projection(x, l, ideal="mask")
    # the same formula on integers: the same numbers, not just the same point
    expected = [exact_or_none(metric.orthogonal_projection, Point(*p), Line(*m)) for p, m in zip(x, l, strict=True)]
    check_against(feet, ok, [None if e is None else e.coords for e in expected], exact_equal=True)
    if not ok.all():
        with pytest.raises(IdealPointError):
            nm.orthogonal_projection(x, l)


@given(rows(4), hyperplanes(4))
@FAST
def test_point_plane_distance_projection_and_reflection_agree_with_exact(x, p):
    n = min(len(x), len(p))
    x, p = x[:n], p[:n]
    values, ok = nm.point_plane_distance(x, p, ideal="mask")
    check_against(
        values, ok, [exact_or_none(metric.distance, Point3(*a), Plane(*b)) for a, b in zip(x, p, strict=True)]
    )
    feet, ok = nm.orthogonal_projection(x, p, ideal="mask")
    expected = [exact_or_none(metric.orthogonal_projection, Point3(*a), Plane(*b)) for a, b in zip(x, p, strict=True)]
    check_against(feet, ok, [None if e is None else e.coords for e in expected], exact_equal=True)
    images, ok = nm.reflect(x, p, ideal="mask")
    expected = [exact_or_none(metric.reflect, Point3(*a), Plane(*b)) for a, b in zip(x, p, strict=True)]
    check_against(images, ok, [None if e is None else e.coords for e in expected], exact_equal=True)


@given(rows(3), hyperplanes(3))
@FAST
def test_reflection_in_lines_agrees_with_exact_and_is_an_involution(x, l):
    n = min(len(x), len(l))
    x, l = x[:n], l[:n]
    images, ok = nm.reflect(x, l, ideal="mask")
    expected = [exact_or_none(metric.reflect, Point(*p), Line(*m)) for p, m in zip(x, l, strict=True)]
    check_against(images, ok, [None if e is None else e.coords for e in expected], exact_equal=True)
    if not ok.any():
        return
    back = nm.reflect(images[ok], l[ok])
    s = (l[ok, 0] ** 2 + l[ok, 1] ** 2)[:, None]  # R² = s² I on integers
    assert np.array_equal(back, s**2 * x[ok])


@given(rows(3), rows(3))
@FAST
def test_point_distance_agrees_with_exact(x, y):
    n = min(len(x), len(y))
    x, y = x[:n], y[:n]
    values, ok = nm.point_distance(x, y, ideal="mask")
    check_against(values, ok, [exact_or_none(metric.distance, Point(*p), Point(*q)) for p, q in zip(x, y, strict=True)])


@given(rows(4), rows(4))
@FAST
def test_point_distance_in_space_agrees_with_exact(x, y):
    n = min(len(x), len(y))
    x, y = x[:n], y[:n]
    values, ok = nm.point_distance(x, y, ideal="mask")
    check_against(
        values, ok, [exact_or_none(metric.distance, Point3(*p), Point3(*q)) for p, q in zip(x, y, strict=True)]
    )


@given(st.floats(-1e6, 1e6), st.floats(-1e6, 1e6), st.floats(0.1, 10), st.floats(-math.pi, math.pi))
@FAST
def test_distances_are_invariant_under_a_rotation_and_translation(tx, ty, w, angle):
    c, s = math.cos(angle), math.sin(angle)
    H = np.array([[c, -s, tx], [s, c, ty], [0, 0, 1]])
    x = np.array([[1.0, 2, 1], [3, -4, 2], [0, 5, w]])
    l = np.array([3.0, 4, -1])
    d = nm.point_line_distance(x, l)
    assert nm.point_line_distance(x @ H.T, np.linalg.inv(H).T @ l) == pytest.approx(d, rel=1e-9, abs=1e-6)
    assert nm.point_distance(x @ H.T, x[::-1] @ H.T) == pytest.approx(nm.point_distance(x, x[::-1]), rel=1e-9)


# -- the policy --------------------------------------------------------------------------------------
def test_nonfinite_inputs_raise_or_mask():
    l = np.array([[1.0, 0, 0], [np.nan, 1, 0], [0, 0, 1]])
    with pytest.raises(NonFiniteError):
        nm.cos_angle(l, [0.0, 1, 0], ideal="mask")
    values, ok = nm.cos_angle(l, [0.0, 1, 0], ideal="mask", nonfinite="mask")
    assert ok.tolist() == [True, False, False] and values[0] == 0 and np.isnan(values[1:]).all()
    # a bad input is reported before an ideal element
    with pytest.raises(NonFiniteError):
        nm.point_line_distance([[np.inf, 0, 1], [1, 0, 0]], [1.0, 0, 0])


def test_intermediate_overflow_is_recomputed_not_reported():
    # the squares 1e400 overflow in the fast formula; the cosine itself is 1/√2
    assert nm.cos_angle([1e200, 1e200, 0], [1e200, 0, 3]) == pytest.approx(1 / math.sqrt(2))
    # (1e300, 0) and (−1e300, 0): the squared difference overflows, the distance 2e300 does not
    assert nm.point_distance([1e300, 0, 1], [-1e300, 0, 1]) == pytest.approx(2e300)
    assert nm.point_line_distance([1e-200, 0, 1e-200], [1e200, 0, -1e200]) == 0.0  # x = 1 through (1, 0)
    # |l|² = 2e400 overflows while lᵀm = 1e200 does not: the fast quotient would be a wrong 0
    assert nm.cos_angle([1e200, 1e200, 0], [1.0, 0, 0]) == pytest.approx(1 / math.sqrt(2))
    # (1, 0) from x + y = 0 is 1/√2 away, however the line is scaled
    assert nm.point_line_distance([1.0, 0, 1], [1e200, 1e200, 0]) == pytest.approx(1 / math.sqrt(2))
    assert nm.point_line_distance([1.0, 0, 1], [1e-170, 1e-170, 0]) == pytest.approx(1 / math.sqrt(2))
    # the foot of (2, 0) on y = x is (1, 1), with the line's coordinates near the ends of float64
    for scale in (1e-170, 1e170):
        foot = nm.orthogonal_projection([2.0, 0, 1], [scale, -scale, 0])
        assert foot[:2] / foot[2] == pytest.approx([1, 1])
    # tiny coordinates: the squares underflow to 0, the line is still x = y
    assert nm.cos_angle([1e-200, -1e-200, 0], [1.0, 0, 0]) == pytest.approx(1 / math.sqrt(2))


def test_a_true_overflow_raises():
    with pytest.raises(NonFiniteError, match="overflow"):
        nm.point_distance([1.7e308, 0, 1], [-1.7e308, 0, 1])
    values, ok = nm.point_distance([[1.7e308, 0, 1], [0, 0, 1]], [-1.7e308, 0, 1], nonfinite="mask")
    assert ok.tolist() == [False, True] and values[1] == pytest.approx(1.7e308)


def test_ideal_elements_raise_with_a_message_or_mask():
    with pytest.raises(IdealPointError, match="ideal='mask'"):
        nm.point_distance([[0.0, 0, 1], [1, 1, 0]], [0.0, 0, 1])
    with pytest.raises(IdealPointError):
        nm.reflect([1.0, 2, 1], [0.0, 0, 1])  # the line at infinity is no mirror
    with pytest.raises(IdealPointError):
        nm.is_perpendicular([0.0, 0, 0, 1], [1.0, 0, 0, 0])
    perp, ok = nm.is_perpendicular([[0.0, 0, 0, 1], [1, 0, 0, 0]], [0.0, 1, 0, 0], ideal="mask")
    assert perp.tolist() == [False, True] and ok.tolist() == [False, True]


def test_options_and_shapes():
    with pytest.raises(OptionError):
        nm.cos_angle([1.0, 0, 0], [0.0, 1, 0], ideal="skip")
    with pytest.raises(OptionError):
        nm.point_distance([1.0, 0, 1], [0.0, 1, 1], nonfinite="ignore")
    with pytest.raises(DimensionError):
        nm.cos_angle([1.0, 0, 0], [0.0, 1, 0, 0])
    with pytest.raises(DimensionError):
        nm.point_line_distance([1.0, 0, 0, 1], [0.0, 1, 0, 0])


def test_layouts_broadcasting_and_out():
    rng = np.random.default_rng(1)
    x = rng.integers(-9, 9, (2, 3, 3)).astype(float)
    x[..., 2] = rng.integers(1, 4, (2, 3))
    l = np.array([1.0, 2, -3])
    feet = nm.orthogonal_projection(x, l)
    assert feet.shape == (2, 3, 3)
    assert np.array_equal(
        nm.orthogonal_projection(np.moveaxis(x, -1, 0), l[:, None, None], axis=0), np.moveaxis(feet, -1, 0)
    )
    out = np.empty((2, 3, 3))
    assert nm.orthogonal_projection(x, l, out=out) is out and np.array_equal(out, feet)
    d = nm.point_line_distance(x, l)
    assert d.shape == (2, 3)
    assert np.allclose(nm.point_line_distance(feet, l), 0)


def test_empty_batches_give_empty_results():
    empty3 = np.empty((0, 3))
    assert nm.cos_angle(empty3, [1.0, 0, 0]).shape == (0,)
    assert nm.reflect(empty3, [1.0, 0, 0]).shape == (0, 3)
    values, ok = nm.point_distance(np.empty((0, 4)), [0.0, 0, 0, 1], ideal="mask")
    assert values.shape == ok.shape == (0,)
