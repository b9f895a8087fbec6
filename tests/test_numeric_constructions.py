"""The numeric constructions of lines (perpendiculars, bisectors, parallels, midpoints) against the exact ones.

Random exact data from ``tests/strategies.py`` (ideal points and lines through the origin included, and
the line at infinity by hand), converted to float64: the numeric kernel must give the exact object up to
scale, and mask (or raise) exactly where the exact core raises.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strategies import lines, lines3, planes, points, points3

import pgsym.numeric as pn
from pgsym import affine, metric
from pgsym.errors import (
    CoincidentLinesError,
    CoincidentPointsError,
    DegenerateConfigurationError,
    IdealPointError,
    NonFiniteError,
    ZeroVectorError,
)
from pgsym.numeric import metric as nm

FAST = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def coords(objs) -> np.ndarray:
    return np.array([[float(c) for c in o.coords] for o in objs])


def exact_or_none(f, *args):
    """The exact value, or None where the exact core refuses the input (ideal or degenerate)."""
    try:
        return f(*args)
    except (IdealPointError, DegenerateConfigurationError, ZeroVectorError):
        return None


def same_object(row, exact) -> bool:
    """``row`` and the exact coordinates are one projective object: unit vectors equal up to sign."""
    e = np.array([float(c) for c in exact], dtype=float)
    r = np.asarray(row, dtype=float)
    e, r = e / np.linalg.norm(e), r / np.linalg.norm(r)
    return bool(np.allclose(r, e, atol=1e-12) or np.allclose(r, -e, atol=1e-12))


def pairs(a, b):
    n = min(len(a), len(b))
    return a[:n], b[:n]


# -- perpendicular_line ------------------------------------------------------------------------------
@given(st.lists(lines(), min_size=1, max_size=6), st.lists(points(), min_size=1, max_size=6))
@FAST
def test_perpendicular_line_agrees_with_exact(ls, xs):
    ls, xs = pairs(ls, xs)
    values, ok = nm.perpendicular_line(coords(ls), coords(xs), ideal="mask")
    for i, (l, x) in enumerate(zip(ls, xs, strict=True)):
        e = exact_or_none(metric.perpendicular_line, l, x)
        assert ok[i] == (e is not None)
        if e is None:
            assert np.isnan(values[i]).all()
        else:
            # the same formula on integers: proportional by an exact zero cross product
            assert not np.cross(values[i], coords([e])[0]).any()
    if not ok.all():
        with pytest.raises(IdealPointError):
            nm.perpendicular_line(coords(ls), coords(xs))


def test_perpendicular_line_by_hand():
    # to 3x + 4y − 5 = 0 through (1, 2, 1): x × (3, 4, 0) = (2·0 − 1·4, 1·3 − 1·0, 1·4 − 2·3) = (−4, 3, −2),
    # i.e. −4x + 3y = 2, the line of direction (3, 4) through (1, 2): −4 + 6 = 2
    assert nm.perpendicular_line([3.0, 4, -5], [1.0, 2, 1]).tolist() == [-4.0, 3.0, -2.0]
    # component-major layout: two lines through the origin against (2, 0, 2) = (1, 0)
    l = np.array([[1.0, 0], [0, 1], [0, 0]])  # x = 0 and y = 0
    assert nm.perpendicular_line(l, [2.0, 0, 2], axis=0).T.tolist() == [[0.0, 2, 0], [-2.0, 0, 2]]
    with pytest.raises(IdealPointError):
        nm.perpendicular_line([0.0, 0, 1], [1.0, 2, 1])  # the line at infinity has no normal


@pytest.mark.parametrize("scale", [1e-200, 1e200])
def test_perpendicular_line_at_extreme_scales(scale):
    # products of two entries under- or overflow float64; the result is the same line as at scale 1
    values = nm.perpendicular_line(np.array([3.0, 4, -5]) * scale, np.array([1.0, 2, 1]) * scale)
    assert np.isfinite(values).all() and same_object(values, [-4, 3, -2])


# -- angle_bisectors ---------------------------------------------------------------------------------
@given(st.lists(lines(), min_size=1, max_size=6), st.lists(lines(), min_size=1, max_size=6))
@FAST
def test_angle_bisectors_agree_with_exact(ls, ms):
    ls, ms = pairs(ls, ms)
    (plus, minus), ok = nm.angle_bisectors(coords(ls), coords(ms), ideal="mask", degenerate="mask")
    for i, (l, m) in enumerate(zip(ls, ms, strict=True)):
        e = exact_or_none(metric.angle_bisectors, l, m)
        assert ok[i] == (e is not None)
        if e is None:
            assert np.isnan(plus[i]).all() and np.isnan(minus[i]).all()
        else:
            assert same_object(plus[i], e[0].coords) and same_object(minus[i], e[1].coords)


def test_angle_bisectors_by_hand():
    # x = 0 and 3x + 4y = 0: |l| = 1, |m| = 5, so (1, 0, 0) ± (3, 4, 0)/5 = (1.6, 0.8, 0) and (0.4, −0.8, 0)
    plus, minus = nm.angle_bisectors([1.0, 0, 0], [3.0, 4, 0])
    assert plus == pytest.approx([1.6, 0.8, 0]) and minus == pytest.approx([0.4, -0.8, 0])
    # parallel x = 1 and −2x + 6 = 0 (x = 3): u = (1, 0, −1), v = (−1, 0, 3): u + v = (0, 0, 2) is the line at
    # infinity, u − v = (2, 0, −4) the midline x = 2
    plus, minus = nm.angle_bisectors([1.0, 0, -1], [-2.0, 0, 6])
    assert plus.tolist() == [0.0, 0.0, 2.0] and minus.tolist() == [2.0, 0.0, -4.0]
    with pytest.raises(CoincidentLinesError):
        nm.angle_bisectors([1.0, 2, 3], [[1.0, 0, 0], [-3, -6, -9]])  # the second row is the same line
    with pytest.raises(IdealPointError):
        nm.angle_bisectors([0.0, 0, 1], [1.0, 0, 0])
    (plus, minus), ok = nm.angle_bisectors([1.0, 2, 3], [[1.0, 0, 0], [-3, -6, -9]], degenerate="mask")
    assert ok.tolist() == [True, False] and np.isnan(plus[1]).all() and np.isfinite(minus[0]).all()


@pytest.mark.parametrize("scale", [1e-200, 1e200])
def test_angle_bisectors_at_extreme_scales(scale):
    plus, minus = nm.angle_bisectors(np.array([1.0, 0, 0]) * scale, np.array([3.0, 4, 0]) * scale)
    assert same_object(plus, [1.6, 0.8, 0]) and same_object(minus, [0.4, -0.8, 0])


def test_angle_bisectors_name_nan_input():
    with pytest.raises(NonFiniteError):
        nm.angle_bisectors([np.nan, 0, 0], [3.0, 4, 0])


# -- parallel_line, is_parallel, midpoint (pgsym.numeric.affine against pgsym.affine) -----------------
@given(st.lists(lines(), min_size=1, max_size=6), st.lists(points(), min_size=1, max_size=6))
@FAST
def test_parallel_line_in_the_plane_agrees_with_exact(ls, xs):
    ls, xs = pairs(ls, xs)
    values, ok = pn.parallel_line(coords(ls), coords(xs), ideal="mask", degenerate="mask")
    for i, (l, x) in enumerate(zip(ls, xs, strict=True)):
        e = exact_or_none(affine.parallel_line, l, x)
        assert ok[i] == (e is not None)
        if e is None:
            assert np.isnan(values[i]).all()
        else:
            assert not np.cross(values[i], coords([e])[0]).any()  # the same formula on integers


@given(st.lists(planes(), min_size=1, max_size=5), st.lists(points3(), min_size=1, max_size=5))
@FAST
def test_parallel_plane_agrees_with_exact(ps, xs):
    ps, xs = pairs(ps, xs)
    values, ok = pn.parallel_line(coords(ps), coords(xs), ideal="mask", degenerate="mask")
    for i, (p, x) in enumerate(zip(ps, xs, strict=True)):
        e = exact_or_none(affine.parallel_line, p, x)
        assert ok[i] == (e is not None)
        if e is not None:
            assert same_object(values[i], e.coords)


def test_parallel_line_by_hand():
    # to 3x + 4y − 5 = 0 through (2, 1, 1): (w n, −n·x) = (3, 4, −(6 + 4)) = (3, 4, −10)
    assert pn.parallel_line([3.0, 4, -5], [2.0, 1, 1]).tolist() == [3.0, 4.0, -10.0]
    # the same point as (4, 2, 2): (2·3, 2·4, −(12 + 8)) = (6, 8, −20), the same line
    assert pn.parallel_line([3.0, 4, -5], [4.0, 2, 2]).tolist() == [6.0, 8.0, -20.0]
    with pytest.raises(CoincidentPointsError):  # (4, −3, 0) is the direction of the line itself
        pn.parallel_line([3.0, 4, -5], [4.0, -3, 0])
    with pytest.raises(IdealPointError):
        pn.parallel_line([0.0, 0, 1], [4.0, -3, 1])
    # to z = 3 through (1e-200, 1e-200, 1, 1e-200) = (1, 1, 1e200): w n = 1e-400 underflows to 0; rescaled,
    # the plane z = 1e200, i.e. (0, 0, 1e-200, −1)
    v = pn.parallel_line([0.0, 0, 1e-200, -3e-200], [1e-200, 1e-200, 1.0, 1e-200])
    assert same_object(v, [0, 0, 1e-200, -1])


@given(st.lists(lines(), min_size=1, max_size=6), st.lists(lines(), min_size=1, max_size=6))
@FAST
def test_is_parallel_agrees_with_exact(ls, ms):
    ls, ms = pairs(ls, ms)
    for rtol in (0.0, 1e-10):
        values, ok = pn.is_parallel(coords(ls), coords(ms), rtol=rtol, ideal="mask")
        for i, (l, m) in enumerate(zip(ls, ms, strict=True)):
            e = exact_or_none(affine.is_parallel, l, m)
            assert ok[i] == (e is not None)
            assert values[i] == bool(e)


@given(st.lists(lines3(), min_size=1, max_size=4), st.lists(lines3(), min_size=1, max_size=4))
@FAST
def test_is_parallel_of_lines_of_space_agrees_with_exact(ls, ms):
    ls, ms = pairs(ls, ms)
    a = np.array([[float(c) for c in l.coordinates] for l in ls])
    b = np.array([[float(c) for c in m.coordinates] for m in ms])
    values, ok = pn.is_parallel(a, b, ideal="mask")
    for i, (l, m) in enumerate(zip(ls, ms, strict=True)):
        e = exact_or_none(affine.is_parallel, l, m)
        assert ok[i] == (e is not None) and values[i] == bool(e)


def test_is_parallel_by_hand():
    # planes: normals (1, 2, 3) and (−2, −4, −6) are proportional; (1, 2, 3) × (0, 1, 0) = (−3, 0, 1) is not 0
    assert pn.is_parallel([1.0, 2, 3, 4], [[-2.0, -4, -6, 0], [0, 1, 0, 0]]).tolist() == [True, False]
    # lines of P² at 1e±200: (1, 2) against (1, 2 + 2⁻⁴⁰): sin θ ≈ 2⁻⁴⁰/5 ≈ 1.8e-13, under the default 1e-10
    assert pn.is_parallel([1e200, 2e200, 0], [1e-200, (2 + 2.0**-40) * 1e-200, 1]).item()
    assert not pn.is_parallel([1e200, 2e200, 0], [1e-200, (2 + 2.0**-40) * 1e-200, 1], rtol=0).item()
    with pytest.raises(IdealPointError):
        pn.is_parallel([0.0, 0, 0, 1], [1.0, 0, 0, 0])


@given(st.lists(points3(), min_size=1, max_size=5), st.lists(points3(), min_size=1, max_size=5))
@FAST
def test_midpoint_agrees_with_exact(xs, ys):
    xs, ys = pairs(xs, ys)
    values, ok = pn.midpoint(coords(xs), coords(ys), ideal="mask")
    for i, (x, y) in enumerate(zip(xs, ys, strict=True)):
        e = exact_or_none(affine.midpoint, x, y)
        assert ok[i] == (e is not None)
        if e is None:
            assert np.isnan(values[i]).all()
        else:
            assert same_object(values[i], e.coords)


def test_midpoint_by_hand():
    # (1, 2) as (2, 4, 2) and (3, 0) as (−3, 0, −1): (v x + w y, 2 v w) = (−2 − 6, −4 + 0, 2·(−1)·2) = (−8, −4, −4),
    # i.e. (2, 1), the midpoint of (1, 2) and (3, 0)
    assert pn.midpoint([2.0, 4, 2], [-3.0, 0, -1]).tolist() == [-8.0, -4.0, -4.0]
    # at 1e±200 the products 2vw under- or overflow; the scaled recomputation gives (2, 1) again
    v = pn.midpoint(np.array([2.0, 4, 2]) * 1e-200, np.array([-3.0, 0, -1]) * 1e200)
    assert v[:2] / v[2] == pytest.approx([2.0, 1.0])
    with pytest.raises(IdealPointError):
        pn.midpoint([1.0, 0, 0], [0.0, 0, 1])


# -- signed_angle, sin_angle -----------------------------------------------------------------------------
@given(st.lists(st.tuples(points(), points(), points()), min_size=1, max_size=5))
@FAST
def test_signed_angle_agrees_with_exact(triples):
    v, p, q = (coords([t[j] for t in triples]) for j in range(3))
    (c, s), ok = pn.signed_angle(v, p, q, ideal="mask", degenerate="mask")
    for i, t in enumerate(triples):
        e = exact_or_none(metric.signed_angle, *t)
        assert ok[i] == (e is not None)
        if e is None:
            assert np.isnan(c[i]) and np.isnan(s[i])
        else:
            assert (c[i], s[i]) == pytest.approx((float(e[0]), float(e[1])), abs=1e-12)


@given(st.lists(lines(), min_size=1, max_size=6), st.lists(lines(), min_size=1, max_size=6))
@FAST
def test_sin_angle_agrees_with_exact(ls, ms):
    ls, ms = pairs(ls, ms)
    values, ok = pn.sin_angle(coords(ls), coords(ms), ideal="mask")
    for i, (l, m) in enumerate(zip(ls, ms, strict=True)):
        e = exact_or_none(metric.sin_angle, l, m)
        assert ok[i] == (e is not None)
        assert np.isnan(values[i]) if e is None else values[i] == pytest.approx(float(e), abs=1e-12)


def test_signed_angle_by_hand():
    # vertex (1, 1) as (2, 2, 2), p = (2, 1) as (−4, −2, −2), q = (0, 2): rays (1, 0) and (−1, 1), so
    # cos = −1/√2, sin = (1·1 − 0·(−1))/√2 = 1/√2: 135° counterclockwise, whatever the signs of the scales
    c, s = pn.signed_angle([2.0, 2, 2], [-4.0, -2, -2], [0.0, 2, 1])
    assert (c, s) == pytest.approx((-(0.5**0.5), 0.5**0.5))
    # the same at 1e±200 (the homogeneous products under- and overflow)
    c, s = pn.signed_angle(np.array([2.0, 2, 2]) * 1e200, np.array([-4.0, -2, -2]) * 1e-200, [0.0, 2, 1])
    assert (c, s) == pytest.approx((-(0.5**0.5), 0.5**0.5))
    with pytest.raises(CoincidentPointsError):  # p = (3, 3, 3) is the vertex (1, 1)
        pn.signed_angle([1.0, 1, 1], [3.0, 3, 3], [0.0, 2, 1])
    with pytest.raises(IdealPointError):
        pn.signed_angle([1.0, 1, 1], [1.0, 0, 0], [0.0, 2, 1])


def test_component_major_layout_and_out_agree_with_rows():
    rng = np.random.default_rng(1)
    l, m, x, y, z = (rng.integers(-5, 6, (7, 3)).astype(float) for _ in range(5))
    for a in (x, y, z):
        a[:, 2] = rng.integers(1, 4, 7)  # finite points
    l[:, 0] += 10  # no line at infinity, no two equal lines
    m[:, 1] += 10
    for f, args in ((pn.perpendicular_line, (l, x)), (pn.parallel_line, (l, x)), (pn.midpoint, (x, y)),
                    (pn.sin_angle, (l, m)), (pn.is_parallel, (l, m))):
        rows = f(*args)
        assert np.array_equal(f(*(a.T for a in args), axis=0), rows.T)
    for f, args in ((pn.angle_bisectors, (l, m)), (pn.signed_angle, (x, y, z))):
        rows = f(*args)
        cols = f(*(a.T for a in args), axis=0)
        assert all(np.array_equal(c, r.T) for c, r in zip(cols, rows, strict=True))
    out = np.empty((7, 3))
    assert pn.perpendicular_line(l, x, out=out) is out and np.array_equal(out, pn.perpendicular_line(l, x))
    assert pn.midpoint(x, y, out=out) is out and np.array_equal(out, pn.midpoint(x, y))


@pytest.mark.parametrize("scales", [(1e200, 1e-200), (1e-200, 1e-200), (1e200, 1e200)])
def test_sin_angle_at_extreme_scales(scales):
    # x = 0 against 3x − 4y + 1 = 0: (1·(−4) − 0·3) / (1 · 5) = −0.8 at any scale of either line
    l, m = np.array([1.0, 0, 0]) * scales[0], np.array([3.0, -4, 1]) * scales[1]
    assert pn.sin_angle(l, m) == pytest.approx(-0.8)


@given(st.lists(planes(), min_size=1, max_size=5), st.lists(planes(), min_size=1, max_size=5))
@FAST
def test_cos_squared_angle_of_planes_agrees_with_exact(ps, qs):
    ps, qs = pairs(ps, qs)
    values, ok = pn.cos_squared_angle(coords(ps), coords(qs), ideal="mask")
    for i, (p, q) in enumerate(zip(ps, qs, strict=True)):
        e = exact_or_none(metric.cos_squared_angle, p, q)  # rational: (n·m)² / (|n|² |m|²)
        assert ok[i] == (e is not None)
        assert np.isnan(values[i]) if e is None else values[i] == pytest.approx(float(e), rel=1e-13, abs=1e-15)
