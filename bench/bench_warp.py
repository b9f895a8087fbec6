"""Warping a 1024×1024 float32 image by a homography (bilinear): ours against cv2.warpPerspective,
and the pure-NumPy reference against the same baseline."""

from __future__ import annotations

import cv2
import numpy as np
import skimage.data
from timing import paired_medians, report

from pgsym.vision.images import to_float_image
from pgsym.vision.warp import warp, warp_numpy


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
