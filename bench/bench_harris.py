"""Harris on a 1024×1024 float32 photograph: ours (all intermediates + NMS) against same-run baselines.

Baselines: the bare OpenCV primitives (Sobel, GaussianBlur, response formula, no NMS),
cv2.cornerHarris, and scikit-image's corner_harris. Prints one JSON line per case, and one
line with the response correlation with scikit-image (interior and mirror-padded).
"""

from __future__ import annotations

import cv2
import numpy as np
import skimage.data
import skimage.feature
from timing import paired_medians, report

from pgsym.vision.harris import harris
from pgsym.vision.images import to_float_image

K, SIGMA = 0.05, 1.0


def opencv_primitives(img: np.ndarray) -> np.ndarray:
    ix = cv2.Sobel(img, cv2.CV_32F, 1, 0, ksize=3)
    iy = cv2.Sobel(img, cv2.CV_32F, 0, 1, ksize=3)
    sxx = cv2.GaussianBlur(ix * ix, (9, 9), SIGMA)
    syy = cv2.GaussianBlur(iy * iy, (9, 9), SIGMA)
    sxy = cv2.GaussianBlur(ix * iy, (9, 9), SIGMA)
    return sxx * syy - sxy * sxy - K * (sxx + syy) ** 2


def paired(name, ours, baseline, repeat):  # type: ignore[no-untyped-def]
    a, b = paired_medians(ours, baseline, repeat)
    return a, name, b


def main() -> None:
    img = cv2.resize(to_float_image(skimage.data.camera()), (1024, 1024), interpolation=cv2.INTER_LINEAR)
    ours = lambda: harris(img, k=K, sigma=SIGMA)  # noqa: E731
    report("harris_1024", *paired("opencv_primitives", ours, lambda: opencv_primitives(img), 21))
    report("harris_1024", *paired("cv2.cornerHarris", ours, lambda: cv2.cornerHarris(img, 3, 3, K), 21))
    r = harris(img, k=K, sigma=SIGMA).response
    sk = skimage.feature.corner_harris(img, k=K, sigma=SIGMA)
    b = int(np.ceil(4 * SIGMA)) + 2  # scikit-image pads with zeros; compare away from the border
    interior = float(np.corrcoef(r[b:-b, b:-b].ravel(), sk[b:-b, b:-b].ravel())[0, 1])
    a = skimage.feature.structure_tensor(img, sigma=SIGMA, mode="mirror", order="rc")
    mirror = a[0] * a[2] - a[1] ** 2 - K * (a[0] + a[2]) ** 2
    whole = float(np.corrcoef(r.ravel(), mirror.ravel())[0, 1])
    report("harris_1024", *paired("skimage.corner_harris", ours,
                                  lambda: skimage.feature.corner_harris(img, k=K, sigma=SIGMA), 9),
           response_correlation_interior=round(interior, 9), response_correlation_mirror=round(whole, 9))

if __name__ == "__main__":
    main()
