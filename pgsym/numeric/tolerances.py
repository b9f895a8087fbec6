"""Every tolerance of the numeric path, in one place, with what it measures and why it has its value.

Each constant is a *relative* quantity (a ratio of singular values, of norms, or of a
cosine), so no decision on the numeric path depends on the units of the data: multiplying
a matrix by ``1e100``, or measuring pixels in kilometres, gives the same answer. Where a
matrix stands for a transformation, it is first balanced (:func:`pgsym.numeric.conditioning.balance`)
by exact powers of two, which is a change of units in the source and target spaces, so
that its translation and projective parts do not swamp its linear part.

``ε`` below is the float64 machine epsilon, ``2⁻⁵² ≈ 2.2e-16``.

>>> SINGULAR_RTOL, CLASS_RTOL
(1e-13, 1e-09)
"""

from __future__ import annotations

__all__ = [
    "CLASS_RTOL",
    "COLLINEAR_RTOL",
    "DLT_EIGEN_GAP_RTOL",
    "DLT_RTOL",
    "DLT_SNAP_RTOL",
    "INCIDENT_RTOL",
    "RANK_EPS",
    "SINGULAR_RTOL",
]

SINGULAR_RTOL = 1e-13
"""A transformation matrix is singular when ``σ_min ≤ SINGULAR_RTOL · σ_max`` after balancing.

Measures: the ratio of the smallest to the largest singular value of the balanced matrix,
i.e. the inverse of its condition number. Why 1e-13 (≈ 450 ε): the singular values of a
matrix whose entries carry rounding errors of size ε are exact to about ``n ε σ_max``, so
a rank-deficient matrix computed in floats shows ``σ_min`` of a few ε times ``σ_max``;
1e-13 stays well above that noise and still accepts every matrix whose inverse loses fewer
than 13 of the 16 significant digits. Used by :func:`pgsym.numeric.classify.classify_matrix`, the
``transform_*`` kernels (their ``rtol=`` default) and :func:`pgsym.vision.warp.check_homography`.
"""

CLASS_RTOL = 1e-9
"""The default ``tol`` of float classification (:func:`pgsym.numeric.classify.classify_matrix`).

Measures: relative deviations from a class, each a ratio that neither a change of units
(conjugation by ``diag(s, …, s, 1)``) nor the overall scale alters. With ``H = [[A, t], [vᵀ, w]]``
and ``α, τ, ν, ω`` the largest entries of ``|A|, |t|, |v|, |w|``: ``ν τ / (α ω)`` for "the last
row is ``(0, …, 0, w)``" (affine; with ``t = 0`` only ``v = 0`` is affine, since units can make
any other ``v`` as large as ``A``), ``max|ÂᵀÂ − g I| / g`` with ``Â = A / α`` for "``A`` is a
multiple of a rotation" (similarity), and ``|r² − 1|`` for its ratio ``r = √g α / ω`` (isometry).
Why 1e-9: matrices built from measured or rounded data (a rotation from an angle in
degrees, a homography from a DLT) agree with their class to 1e-12 … 1e-15, while a
genuinely different matrix differs by far more; 1e-9 separates the two with margin on
both sides.
"""

INCIDENT_RTOL = 1e-10
"""Default of :func:`pgsym.numeric.incident`: ``|x · y| ≤ INCIDENT_RTOL · |x| |y|``.

Measures: the cosine of the angle between the coordinate vectors of a point and a line
(or plane), so scaling either leaves it unchanged. Why 1e-10: the dot product of two
rounded vectors has relative error about ``k ε |x| |y|``; 1e-10 is 10⁵ times that, and
far below the cosine of any configuration one would call "not incident".
"""

COLLINEAR_RTOL = 1e-9
"""Three image points are collinear when ``|area| ≤ COLLINEAR_RTOL · |b − a| |c − a|``.

Measures: twice the triangle area over the product of two side lengths, the sine of the
angle at ``a``: a pure angle. Why 1e-9: after Hartley normalisation the coordinates are of
order one, so the computed sine has error about ε; an angle of 1e-9 rad between two
sides makes the four-point homography lose about 9 digits, which is the point where it
stops being useful.
"""

DLT_RTOL = 1e-10
"""Degeneracy of a DLT point set or system (:func:`pgsym.vision.homography.dlt_homography`).

Measures two ratios of eigenvalues: ``λ_min / λ_max ≤ DLT_RTOL²`` of the 2×2 scatter matrix of
the normalised points (all points on one line), and ``λ₂ / λ_max ≤ DLT_RTOL`` of ``AᵀA`` (a
second null vector: no unique homography). Why 1e-10: both are squares of singular-value
ratios, so 1e-10 on ``AᵀA`` is 1e-5 on ``A``; with noise-free data the true ratios are
order one or below 1e-20, noisy data stays far above it.
"""

DLT_EIGEN_GAP_RTOL = 1e-13
"""When ``ε · λ_max > DLT_EIGEN_GAP_RTOL · λ₂`` the DLT solves with the SVD of ``A`` instead of ``AᵀA``.

Measures: the forward error bound ``ε λ_max / λ₂`` of the eigenvector of ``AᵀA`` (forming
``AᵀA`` squares the condition number of ``A``). Why 1e-13: above it the faster eigenvector
path would lose more than three digits relative to the SVD of ``A``.
"""

RANK_EPS = 2.0**-52
"""Numerical rank (:mod:`pgsym.numeric.nullspace`): singular values ``≤ max(m, n) · RANK_EPS · σ_max`` count as zero.

Measures: the ratio ``σ / σ_max``, after the rows of homogeneous points or planes are scaled to
unit size and the homogeneous column is balanced against the others (both by powers of two, a
change of units that keeps the null space). Why ``max(m, n) ε``: it is the size of the rounding
error of the SVD of an ``m × n`` matrix (the rule of :func:`numpy.linalg.matrix_rank`), so only
singular values that rounding alone could produce are taken for zero.
"""

DLT_SNAP_RTOL = 2.0**-46
"""Entries of a normalised DLT solution ``Ĥ`` with ``|ĥ| ≤ DLT_SNAP_RTOL · max|Ĥ|`` are set to zero.

Measures: an entry against the largest, in the normalised frames where the data has unit
scale. Why 2⁻⁴⁶ (64 ε ≈ 1.4e-14): the computed ``Ĥ`` carries rounding errors of a few ε
times its largest entry, so smaller entries are indistinguishable from zero; leaving that
noise in would let denormalisation multiply it by the data's scale (``1e-17 · 1e200``) and
swamp the true entries, as happens for an affine map of points near ``1e-200``.
"""
