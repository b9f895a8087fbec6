"""Benchmark: the numeric metric kernels on 10⁶ elements against the obvious NumPy code and geometer.

Cases (float64, 10⁶ rows of homogeneous coordinates in P², all measured in this one run, each time the
median of interleaved repeats):

* ``cos_angle_1e6_line_pairs``: :func:`pgsym.numeric.metric.cos_angle` of two (N, 3) arrays of lines
  against ``(l1 m1 + l2 m2) / sqrt((l1² + l2²)(m1² + m2²))`` written with NumPy columns, and against
  geometer's ``angle(LineCollection, LineCollection)`` (Laguerre's formula; it returns the angle, whose
  cosine is checked against ours up to the orientation sign);
* ``point_line_distance_1e6``: ``|lᵀx| / (sqrt(l1² + l2²) |x3|)`` against the same in NumPy columns and
  geometer's ``dist(PointCollection, LineCollection)``;
* ``orthogonal_projection_1e6``: the feet ``s x − (lᵀx)(l1, l2, 0)`` against the same in NumPy and
  geometer's ``LineCollection.project(PointCollection)`` (compared up to scale);
* ``point_distance_1e6``: distances of two (N, 3) arrays of finite points against
  ``np.linalg.norm(x[:, :2] / x[:, 2:] − y[:, :2] / y[:, 2:], axis=1)`` and geometer's ``dist``;
* the constructions, against the obvious NumPy code only: ``perpendicular_line_1e6``
  (``np.cross(x, l * (1, 1, 0))``), ``angle_bisectors_1e6`` (``l/|l| ± m/|m|`` with ``np.hypot``),
  ``parallel_line_1e6`` (``(w l1, w l2, −(l1 x + l2 y))`` in columns) and ``midpoint_1e6``
  (``(x/w + y/v) / 2`` dehomogenized; ours stays homogeneous, without a division).

Every line is ``{"bench", "ours_s", "baseline", "baseline_s", "ratio"}`` with ``ratio`` = baseline_s /
ours_s (> 1: we are faster). Our kernels also check every result for NaN, infinity and ideal elements,
which the baselines do not. One thread (``OPENBLAS_NUM_THREADS=1`` unless set), as in bench_numeric.py.

geometer is a benchmark-only dependency (pinned in requirements.txt).
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # before NumPy loads its BLAS

import json
from collections.abc import Callable

import numpy as np
from timing import import_geometer, medians

from pgsym.numeric import affine as na
from pgsym.numeric import metric as nm

geometer = import_geometer("bench_metric.py")
N = 10**6
REPEATS = 11
GEOMETER_REPEATS = 1  # geometer takes seconds per call on 10⁶ rows


def emit(bench: str, ours: float, baseline: str, base: float) -> None:
    line = {"bench": bench, "ours_s": round(ours, 6), "baseline": baseline, "baseline_s": round(base, 6)}
    line["ratio"] = round(base / ours, 2)
    print(json.dumps(line), flush=True)


# -- the obvious NumPy code --------------------------------------------------------------------------
def np_cos_angle(l: np.ndarray, m: np.ndarray) -> np.ndarray:
    return (l[:, 0] * m[:, 0] + l[:, 1] * m[:, 1]) / np.sqrt(
        (l[:, 0] ** 2 + l[:, 1] ** 2) * (m[:, 0] ** 2 + m[:, 1] ** 2)
    )


def np_point_line_distance(x: np.ndarray, l: np.ndarray) -> np.ndarray:
    return np.abs((x * l).sum(axis=1)) / (np.sqrt(l[:, 0] ** 2 + l[:, 1] ** 2) * np.abs(x[:, 2]))


def np_projection(x: np.ndarray, l: np.ndarray) -> np.ndarray:
    s = l[:, 0] ** 2 + l[:, 1] ** 2
    d = (x * l).sum(axis=1)
    out = s[:, None] * x
    out[:, :2] -= d[:, None] * l[:, :2]
    return out


def np_point_distance(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    return np.linalg.norm(x[:, :2] / x[:, 2:] - y[:, :2] / y[:, 2:], axis=1)


def np_perpendicular_line(l: np.ndarray, x: np.ndarray) -> np.ndarray:
    return np.cross(x, l * np.array([1.0, 1.0, 0.0]))


def np_angle_bisectors(l: np.ndarray, m: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    u = l / np.hypot(l[:, 0], l[:, 1])[:, None]
    v = m / np.hypot(m[:, 0], m[:, 1])[:, None]
    return u + v, u - v


def np_parallel_line(l: np.ndarray, x: np.ndarray) -> np.ndarray:
    out = np.empty_like(l)
    out[:, :2] = l[:, :2] * x[:, 2:]
    out[:, 2] = -(l[:, 0] * x[:, 0] + l[:, 1] * x[:, 1])
    return out


def np_midpoint(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    return (x[:, :2] / x[:, 2:] + y[:, :2] / y[:, 2:]) / 2


def constructions(a: np.ndarray, b: np.ndarray, x: np.ndarray, y: np.ndarray) -> None:
    """The construction kernels against the obvious NumPy code (no geometer twin to compare with)."""
    assert np.allclose(nm.perpendicular_line(a, x), np_perpendicular_line(a, x))
    plus, minus = nm.angle_bisectors(a, b)
    np_plus, np_minus = np_angle_bisectors(a, b)
    assert np.allclose(plus, np_plus) and np.allclose(minus, np_minus)
    assert np.allclose(na.parallel_line(a, x), np_parallel_line(a, x))
    mid = na.midpoint(x, y)
    assert np.allclose(mid[:, :2] / mid[:, 2:], np_midpoint(x, y))
    cases = {
        "perpendicular_line_1e6": (lambda: nm.perpendicular_line(a, x), lambda: np_perpendicular_line(a, x)),
        "angle_bisectors_1e6": (lambda: nm.angle_bisectors(a, b), lambda: np_angle_bisectors(a, b)),
        "parallel_line_1e6": (lambda: na.parallel_line(a, x), lambda: np_parallel_line(a, x)),
        "midpoint_1e6": (lambda: na.midpoint(x, y), lambda: np_midpoint(x, y)),
    }
    for bench, (ours, obvious) in cases.items():
        t = medians({"ours": ours, "numpy": obvious}, REPEATS)
        emit(bench, t["ours"], "obvious numpy", t["numpy"])


def data() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(0)
    a, b = rng.standard_normal((N, 3)), rng.standard_normal((N, 3))
    x, y = rng.standard_normal((N, 3)), rng.standard_normal((N, 3))
    x[:, 2] = rng.uniform(0.5, 2.0, N)  # finite points, so that every baseline is defined everywhere
    y[:, 2] = rng.uniform(0.5, 2.0, N)
    return a, b, x, y


def run(
    bench: str,
    ours: Callable[[], np.ndarray],
    obvious: Callable[[], np.ndarray],
    geo: Callable[[], object],
    geo_name: str,
) -> None:
    t = medians({"ours": ours, "numpy": obvious}, REPEATS)
    emit(bench, t["ours"], "obvious numpy", t["numpy"])
    tg = medians({"ours": ours, "geometer": geo}, GEOMETER_REPEATS)
    emit(bench, tg["ours"], f"geometer {geometer.__version__} {geo_name}", tg["geometer"])


def main() -> None:
    a, b, x, y = data()
    ga, gb = geometer.LineCollection(a), geometer.LineCollection(b)
    gx, gy = geometer.PointCollection(x), geometer.PointCollection(y)

    # the answers agree before anything is timed
    ours_cos = nm.cos_angle(a, b)
    assert np.allclose(ours_cos, np_cos_angle(a, b))
    assert np.allclose(np.abs(ours_cos[:1000]), np.abs(np.cos(geometer.angle(ga[:1000], gb[:1000]))))
    assert np.allclose(nm.point_line_distance(x, a), np_point_line_distance(x, a))
    assert np.allclose(nm.point_line_distance(x[:1000], a[:1000]), geometer.dist(gx[:1000], ga[:1000]))
    feet = nm.orthogonal_projection(x, a)
    assert np.allclose(feet, np_projection(x, a))
    g_feet = ga[:1000].project(gx[:1000]).array
    g_feet = (g_feet[:, :2] / g_feet[:, 2:]).real
    assert np.allclose(feet[:1000, :2] / feet[:1000, 2:], g_feet)
    assert np.allclose(nm.point_distance(x, y), np_point_distance(x, y))
    assert np.allclose(nm.point_distance(x[:1000], y[:1000]), geometer.dist(gx[:1000], gy[:1000]))

    run(
        "cos_angle_1e6_line_pairs",
        lambda: nm.cos_angle(a, b),
        lambda: np_cos_angle(a, b),
        lambda: geometer.angle(ga, gb),
        "angle(LineCollection, LineCollection)",
    )
    run(
        "point_line_distance_1e6",
        lambda: nm.point_line_distance(x, a),
        lambda: np_point_line_distance(x, a),
        lambda: geometer.dist(gx, ga),
        "dist(PointCollection, LineCollection)",
    )
    run(
        "orthogonal_projection_1e6",
        lambda: nm.orthogonal_projection(x, a),
        lambda: np_projection(x, a),
        lambda: ga.project(gx),
        "LineCollection.project(PointCollection)",
    )
    run(
        "point_distance_1e6",
        lambda: nm.point_distance(x, y),
        lambda: np_point_distance(x, y),
        lambda: geometer.dist(gx, gy),
        "dist(PointCollection, PointCollection)",
    )
    constructions(a, b, x, y)


if __name__ == "__main__":
    main()
