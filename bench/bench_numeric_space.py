"""Benchmark: the numeric kernels of lines of space, quadrics, harmonic conjugates and complex points, on 10⁶ rows.

Each case times a :mod:`pgsym.numeric` kernel against the obvious NumPy code for the same formula and,
where geometer has the construction, against geometer (a benchmark-only dependency, pinned in
requirements.txt). The obvious NumPy code follows the textbook: Plücker matrices as ``(N, 4, 4)`` stacks
multiplied with ``@`` (``X = L π``, ``π = L* X``, ``L M* = X πᵀ``), one ``X @ Qᵀ`` for the polars of one
quadric (bare, and — case ``..._checked`` — with the kernel's checks: finite, no vertex, on the quadric),
``einsum`` for ``xᵀ Q x``, ``np.cross`` for the P² harmonic conjugate and for complex joins.

Cases: ``intersect_plane_1e6``, ``plane_through_point_1e6``, ``meet_lines_1e6``, ``plane_through_lines_1e6``,
``tangent_plane_1e6_points_one_sphere``, ``polar_1e6_points_one_quadric``, ``form_value_1e6_points_one_quadric``,
``harmonic_conjugate_p1_1e6``, ``harmonic_conjugate_p2_1e6``, ``join_complex_1e6``.

Every line is ``{"bench", "ours_s", "baseline", "baseline_s", "ratio"}`` (ratio = baseline_s / ours_s, > 1: ours
is faster), medians of interleaved runs (``timing.medians``). Ours also checks every result for NaN and
infinity and decides degeneracy (skew lines, points off the quadric, coincident points), which the baselines
do not. One thread (``OPENBLAS_NUM_THREADS=1`` unless set), as in bench_numeric.py and bench_metric.py.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # before NumPy loads its BLAS

from collections.abc import Callable

import numpy as np
from timing import import_geometer, medians, report

import pgsym.numeric as pn

geometer = import_geometer("bench_numeric_space.py")
N = 10**6
REPEATS = 7
GEOMETER_REPEATS = 1  # geometer takes seconds per call on 10⁶ rows

# -- the obvious NumPy code ----------------------------------------------------------------------------
# (row, column, coordinate) of the upper triangle of L for coordinates (l12, l13, l14, l23, l42, l34), l24 = −l42
_UPPER = ((0, 1, 0, 1.0), (0, 2, 1, 1.0), (0, 3, 2, 1.0), (1, 2, 3, 1.0), (1, 3, 4, -1.0), (2, 3, 5, 1.0))


def np_plucker_matrix(c: np.ndarray, dual: bool = False) -> np.ndarray:
    """The (N, 4, 4) Plücker matrices L (or L*, from the reversed coordinates)."""
    c = c[:, ::-1] if dual else c
    L = np.zeros((len(c), 4, 4))
    for i, j, k, sign in _UPPER:
        L[:, i, j] = sign * c[:, k]
        L[:, j, i] = -sign * c[:, k]
    return L


def np_intersect_plane(l: np.ndarray, p: np.ndarray) -> np.ndarray:
    return (np_plucker_matrix(l) @ p[:, :, None])[:, :, 0]


def np_plane_through_point(l: np.ndarray, x: np.ndarray) -> np.ndarray:
    return (np_plucker_matrix(l, dual=True) @ x[:, :, None])[:, :, 0]


def np_meet_lines(l: np.ndarray, m: np.ndarray) -> np.ndarray:
    K = np_plucker_matrix(l) @ np_plucker_matrix(m, dual=True)  # X πᵀ: the column of largest norm is X
    j = np.argmax((K**2).sum(axis=1), axis=1)
    return K[np.arange(len(K)), :, j]


def np_plane_through_lines(l: np.ndarray, m: np.ndarray) -> np.ndarray:
    K = np_plucker_matrix(l) @ np_plucker_matrix(m, dual=True)  # the row of largest norm is π
    i = np.argmax((K**2).sum(axis=2), axis=1)
    return K[np.arange(len(K)), i, :]


def np_harmonic_p1(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    ac = a[:, 0] * c[:, 1] - a[:, 1] * c[:, 0]
    bc = b[:, 0] * c[:, 1] - b[:, 1] * c[:, 0]
    return ac[:, None] * b + bc[:, None] * a


def np_harmonic_p2(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    n = np.cross(a, b)
    alpha = (np.cross(c, b) * n).sum(axis=1)
    beta = (np.cross(a, c) * n).sum(axis=1)
    return alpha[:, None] * a - beta[:, None] * b


def np_tangent_checked(Q: np.ndarray, x: np.ndarray, rtol: float = 1e-10) -> np.ndarray:
    """The obvious NumPy code with the kernel's contract: finite planes, no vertex, every point on the quadric."""
    planes = x @ Q.T
    if not np.isfinite(planes).all():
        raise ValueError("non-finite")
    pp = (planes**2).sum(axis=1)
    if not pp.all():
        raise ValueError("a vertex")
    dot = (x * planes).sum(axis=1)
    if (dot**2 > rtol**2 * (x**2).sum(axis=1) * pp).any():
        raise ValueError("off the quadric")
    return planes


def proportional_rows(u: np.ndarray, v: np.ndarray) -> bool:
    """Every row of u is a multiple of the row of v (checked on the normalised rows, sign-free)."""
    un = u / np.linalg.norm(u, axis=1, keepdims=True)
    vn = v / np.linalg.norm(v, axis=1, keepdims=True)
    return bool(np.allclose(np.abs(np.einsum("ij,ij->i", un, vn.conj())), 1.0, atol=1e-9))


def run(bench: str, ours: Callable[[], object], obvious: Callable[[], object],
        geo: Callable[[], object] | None = None, geo_name: str = "") -> None:
    t = medians({"ours": ours, "numpy": obvious}, REPEATS)
    report(bench, t["ours"], "obvious numpy", t["numpy"])
    if geo is not None:
        tg = medians({"ours": ours, "geometer": geo}, GEOMETER_REPEATS)
        report(bench, tg["ours"], f"geometer {geometer.__version__} {geo_name}", tg["geometer"])


def main() -> None:
    rng = np.random.default_rng(0)
    O, A, B, P = (rng.standard_normal((N, 4)) for _ in range(4))
    L, M = pn.plucker_join(O, A), pn.plucker_join(O, B)  # pairs of lines meeting in O
    gL = geometer.join(geometer.PointCollection(O, homogenize=False), geometer.PointCollection(A, homogenize=False))
    gM = geometer.join(geometer.PointCollection(O, homogenize=False), geometer.PointCollection(B, homogenize=False))
    gP, gB = geometer.PlaneCollection(P), geometer.PointCollection(B, homogenize=False)
    sphere = np.diag([1.0, 1, 1, -1])
    u = rng.standard_normal((N, 3))
    on_sphere = np.c_[u / np.linalg.norm(u, axis=1, keepdims=True), np.ones(N)]
    Q = rng.standard_normal((4, 4))
    Q = Q + Q.T
    a2, b2 = rng.standard_normal((N, 2)), rng.standard_normal((N, 2))
    c2 = a2 * rng.uniform(0.5, 2, (N, 1)) + b2 * rng.uniform(0.5, 2, (N, 1))
    a3, b3 = rng.standard_normal((N, 3)), rng.standard_normal((N, 3))
    c3 = a3 * rng.uniform(0.5, 2, (N, 1)) + b3 * rng.uniform(0.5, 2, (N, 1))  # collinear with a3, b3
    za, zb = rng.standard_normal((N, 3)) + 1j * rng.standard_normal((N, 3)), rng.standard_normal((N, 3)) + 0j

    # the answers agree before anything is timed (geometer on the first 1000 rows, up to scale)
    k = slice(0, 1000)
    assert np.allclose(pn.intersect_plane(L, P), np_intersect_plane(L, P))
    assert proportional_rows(pn.intersect_plane(L[k], P[k]), geometer.meet(gL[k], gP[k]).array.real)
    assert np.allclose(pn.plane_through_point(L, B, degenerate="mask")[0], np_plane_through_point(L, B))
    assert proportional_rows(pn.meet_lines(L, M), O) and np.allclose(pn.meet_lines(L, M), np_meet_lines(L, M))
    assert proportional_rows(pn.meet_lines(L[k], M[k]), geometer.meet(gL[k], gM[k]).array.real)
    assert np.allclose(pn.plane_through_lines(L, M), np_plane_through_lines(L, M))
    assert proportional_rows(pn.plane_through_lines(L[k], M[k]), geometer.join(gL[k], gM[k]).array.real)
    geo_sphere = geometer.Quadric(sphere)
    geo_on = geometer.PointCollection(on_sphere, homogenize=False)
    assert np.allclose(pn.tangent_plane(sphere, on_sphere), on_sphere @ sphere.T)
    assert proportional_rows(pn.tangent_plane(sphere, on_sphere[k]), geo_sphere.tangent(at=geo_on[k]).array.real)
    assert np.allclose(pn.polar(Q, on_sphere), on_sphere @ Q.T)
    assert np.allclose(pn.form_value(Q, on_sphere), np.einsum("ni,ij,nj->n", on_sphere, Q, on_sphere))
    assert np.allclose(pn.harmonic_conjugate(a2, b2, c2), np_harmonic_p1(a2, b2, c2))
    h3 = pn.harmonic_conjugate(a3, b3, c3)
    assert np.allclose(h3, np_harmonic_p2(a3, b3, c3))
    g3 = [geometer.PointCollection(x[k], homogenize=False) for x in (a3, b3, c3)]
    assert proportional_rows(h3[k], geometer.harmonic_set(*g3).array.real)
    assert np.allclose(pn.join(za, zb), np.cross(za, zb))

    run("intersect_plane_1e6", lambda: pn.intersect_plane(L, P), lambda: np_intersect_plane(L, P),
        lambda: geometer.meet(gL, gP), "meet(LineCollection, PlaneCollection)")
    run("plane_through_point_1e6", lambda: pn.plane_through_point(L, B), lambda: np_plane_through_point(L, B),
        lambda: geometer.join(gL, gB), "join(LineCollection, PointCollection)")
    run("meet_lines_1e6", lambda: pn.meet_lines(L, M), lambda: np_meet_lines(L, M),
        lambda: geometer.meet(gL, gM), "meet(LineCollection, LineCollection)")
    run("plane_through_lines_1e6", lambda: pn.plane_through_lines(L, M), lambda: np_plane_through_lines(L, M),
        lambda: geometer.join(gL, gM), "join(LineCollection, LineCollection)")
    run("tangent_plane_1e6_points_one_sphere", lambda: pn.tangent_plane(sphere, on_sphere),
        lambda: on_sphere @ sphere.T, lambda: geo_sphere.tangent(at=geo_on), "Quadric.tangent(at=PointCollection)")
    run("tangent_plane_1e6_points_one_sphere_checked", lambda: pn.tangent_plane(sphere, on_sphere),
        lambda: np_tangent_checked(sphere, on_sphere))
    run("polar_1e6_points_one_quadric", lambda: pn.polar(Q, on_sphere), lambda: on_sphere @ Q.T)
    run("form_value_1e6_points_one_quadric", lambda: pn.form_value(Q, on_sphere),
        lambda: np.einsum("ni,ij,nj->n", on_sphere, Q, on_sphere))
    run("harmonic_conjugate_p1_1e6", lambda: pn.harmonic_conjugate(a2, b2, c2), lambda: np_harmonic_p1(a2, b2, c2))
    run("harmonic_conjugate_p2_1e6", lambda: pn.harmonic_conjugate(a3, b3, c3), lambda: np_harmonic_p2(a3, b3, c3),
        lambda: geometer.harmonic_set(*(geometer.PointCollection(x, homogenize=False) for x in (a3, b3, c3))),
        "harmonic_set(PointCollection × 3)")
    run("join_complex_1e6", lambda: pn.join(za, zb), lambda: np.cross(za, zb))


if __name__ == "__main__":
    main()
