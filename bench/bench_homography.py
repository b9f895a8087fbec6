"""Homography estimation: normalised DLT at 1000 points against cv2.findHomography(..., 0), and
10^4 four-point problems batched against a loop of cv2.getPerspectiveTransform. Also prints the
accuracy of both (reprojection error; fraction of four-point results off by more than 1e-6 / 1e-3)."""

from __future__ import annotations

import cv2
import numpy as np
from timing import paired_medians, report

from pgsym.vision.homography import (
    apply_homography,
    dlt_homography,
    homographies_from_four,
    normalize_homography,
    reprojection_error,
)


def four_point_problems(rng: np.random.Generator, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Random pixel-scale quadrilaterals and their images under random well-conditioned homographies."""
    src = rng.uniform(0, 1000, (n, 4, 2))
    H = np.tile(np.eye(3), (n, 1, 1)) + rng.normal(scale=0.2, size=(n, 3, 3)) * np.array([1, 1, 0, 1, 1, 0, 0, 0, 0]
                                                                                          ).reshape(3, 3)
    H[:, :2, 2] = rng.uniform(-200, 200, (n, 2))
    H[:, 2, :2] = rng.uniform(-4e-4, 4e-4, (n, 2))
    q = np.einsum("nij,nkj->nki", H, np.concatenate([src, np.ones((n, 4, 1))], axis=2))
    dst = q[..., :2] / q[..., 2:]
    return src, dst, normalize_homography(H)


def main() -> None:
    rng = np.random.default_rng(0)
    H = np.array([[1.1, 0.2, 30.0], [-0.1, 0.9, 12.0], [2e-4, 1e-4, 1.0]])
    src = rng.uniform(0, 1000, (1000, 2))
    dst = apply_homography(H, src)
    ours, base = paired_medians(lambda: dlt_homography(src, dst), lambda: cv2.findHomography(src, dst, 0), 201)
    err_ours = float(reprojection_error(dlt_homography(src, dst), src, dst).max())
    err_cv = float(reprojection_error(cv2.findHomography(src, dst, 0)[0], src, dst).max())
    report("dlt_1000_points", ours, "cv2.findHomography(method=0)", base,
           max_reprojection_px_ours=float(f"{err_ours:.3g}"), max_reprojection_px_baseline=float(f"{err_cv:.3g}"))

    n = 10_000
    s, d, truth = four_point_problems(rng, n)
    s32, d32 = s.astype(np.float32), d.astype(np.float32)

    def loop() -> list[np.ndarray]:
        return [cv2.getPerspectiveTransform(s32[i], d32[i]) for i in range(n)]

    ours, base = paired_medians(lambda: homographies_from_four(s, d), loop, 7)
    off_ours = np.abs(homographies_from_four(s, d) - truth).max(axis=(1, 2))
    off_cv = np.abs(normalize_homography(np.stack(loop())) - truth).max(axis=(1, 2))
    report("four_point_batch_10000", ours, "loop of cv2.getPerspectiveTransform", base,
           max_error_ours=float(f"{off_ours.max():.3g}"),
           fraction_off_1e6_ours=float(np.mean(off_ours > 1e-6)),
           fraction_off_1e3_baseline=float(np.mean(off_cv > 1e-3)))


if __name__ == "__main__":
    main()
