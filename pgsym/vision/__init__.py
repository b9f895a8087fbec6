"""Numeric computer vision on top of pgsym: the lecture's two programming exercises.

The subpackage is the *numeric* path of the project: images are NumPy arrays,
coordinates are floats, and the heavy image primitives come from OpenCV, which is
imported lazily inside the functions that need it (importing this package does
not import ``cv2``).

- :mod:`pgsym.vision.images`: checking, converting, reading and writing images.
- :mod:`pgsym.vision.harris`: the Harris corner detector with every intermediate result.
- :mod:`pgsym.vision.homography`: normalised DLT, the exact four-point homography,
  and a batched solver for many four-point problems.
- :mod:`pgsym.vision.rectify`: rectification from four points, from the vanishing
  line (affine) and from orthogonal line pairs (metric).
- :mod:`pgsym.vision.warp`: warping an image by a homography with bilinear interpolation.

>>> import numpy as np
>>> from pgsym.vision.homography import dlt_homography
>>> square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
>>> H = dlt_homography(square, 2 * square + 3)
>>> np.round(H / H[2, 2], 6).tolist()
[[2.0, 0.0, 3.0], [0.0, 2.0, 3.0], [0.0, 0.0, 1.0]]
"""
