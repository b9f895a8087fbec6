"""Warping a 1024×1024 float32 image by a homography (bilinear): ours against cv2.warpPerspective,
and the pure-NumPy reference against the same baseline."""

from __future__ import annotations

import json
import time

import cv2
import numpy as np
import skimage.data

from pgsym.vision.images import to_float_image
from pgsym.vision.warp import warp, warp_numpy


def median_time(fn, repeat: int) -> float:
    fn()
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return float(np.median(times))


def paired_medians(ours, baseline, repeat: int) -> tuple[float, float]:
    """Median times of two functions run alternately, so that both see the same machine load."""
    ours()
    baseline()
    a, b = [], []
    for _ in range(repeat):
        t = time.perf_counter()
        ours()
        a.append(time.perf_counter() - t)
        t = time.perf_counter()
        baseline()
        b.append(time.perf_counter() - t)
    return float(np.median(a)), float(np.median(b))


def report(name: str, ours: float, baseline: str, base: float) -> None:
    print(json.dumps({"bench": name, "ours_s": round(ours, 6), "baseline": baseline,
                      "baseline_s": round(base, 6), "ratio": round(base / ours, 3)}))


def main() -> None:
    img = cv2.resize(to_float_image(skimage.data.camera()), (1024, 1024), interpolation=cv2.INTER_LINEAR)
    H = np.array([[0.9, 0.15, 40.0], [-0.05, 1.05, 20.0], [1e-4, 2e-4, 1.0]])
    size = (1024, 1024)
    def baseline() -> np.ndarray:
        return cv2.warpPerspective(img, H, size, flags=cv2.INTER_LINEAR)

    ours, base = paired_medians(lambda: warp(img, H, size), baseline, 41)
    report("warp_1024", ours, "cv2.warpPerspective", base)
    ours, base = paired_medians(lambda: warp_numpy(img, H, size), baseline, 7)
    report("warp_1024_numpy_reference", ours, "cv2.warpPerspective", base)


if __name__ == "__main__":
    main()
