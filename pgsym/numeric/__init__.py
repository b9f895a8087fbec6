"""The numeric path: pgsym's constructions on float64 arrays of many points, lines and planes.

Every function here takes arrays of shape ``(..., k)`` — the ``k`` homogeneous
coordinates on the last axis, all other axes broadcasting — or, with ``axis=0``, the
component-major layout ``(k, ...)``, which is the fastest. The formulas are those of
the exact core (a cross product for join and meet in P², signed 3×3 minors in P³, the
adjugate for lines, planes and conics), and the tests check each kernel against the
exact result on the same integer data. Only NumPy is imported: ``import pgsym.numeric``
does not import SymPy, and neither does any kernel call (the conversions
:func:`to_array` / :func:`from_array` load the exact core when they run).

The linear algebra of small dense matrices lives here too: numerical rank, null spaces
and least-squares planes by the SVD (:mod:`pgsym.numeric.nullspace`), the SVD of a 2×2
matrix as rotate–stretch–rotate (:mod:`pgsym.numeric.svd`) and the float classifier of
the transformation hierarchy (:mod:`pgsym.numeric.classify`).

Kernels run block by block over the rows, so that their scratch buffers stay in the
processor cache; pass ``out=`` to reuse an output array.

**Non-finite numbers: one policy for pgsym.numeric and pgsym.vision.**

1. NaN or ±inf in any input (coordinates, matrices, scalar parameters) raises
   :class:`~pgsym.errors.NonFiniteError`, naming the argument and the first bad entry;
   so does a finite input whose result overflows float64. No kernel returns NaN or inf
   that the caller did not ask for.
2. Batch kernels take ``nonfinite="mask"``: they then return ``(values, finite)``, with the
   rows that hold NaN or inf set to NaN and ``finite`` False there — the shape of
   ``dehomogenize(..., ideal="mask")``, which masks ideal points the same way.
3. Ideal points have no inhomogeneous coordinates or distances: :func:`dehomogenize`,
   :func:`pgsym.vision.homography.apply_homography` and ``reprojection_error`` raise
   :class:`~pgsym.errors.IdealPointError` (or mask, with ``ideal="mask"``).
4. Every decision is scale-free and every tolerance is a named constant in
   :mod:`pgsym.numeric.tolerances`; transformation matrices are judged after balancing by a
   change of units (:mod:`pgsym.numeric.conditioning`).
5. Images are checked by :func:`pgsym.vision.images.check_image`, which raises
   :class:`~pgsym.vision.errors.ImageError` for NaN or inf pixels.

**Degenerate input: one policy for the constructions.**

6. A construction whose input does not determine its result — collinear points for
   :func:`plane_through`, planes through one line for :func:`point_on_planes`, fewer than
   three independent rows for :func:`plane_through_numeric` / :func:`point_on_planes_numeric`
   — raises the named :class:`~pgsym.errors.DegenerateConfigurationError` subclass
   (:class:`~pgsym.errors.CollinearPointsError`, :class:`~pgsym.errors.DependentPlanesError`).
   It never returns a silent zero vector.
7. The batch constructions take ``degenerate="mask"``: they then return ``(values, ok)`` with
   the degenerate rows set to NaN and ``ok`` False there — the shape of ``ideal="mask"`` and
   ``nonfinite="mask"`` (with both, ``ok`` is False for either cause). The batch kernels decide
   degeneracy exactly (every minor is 0), as the exact core does; the SVD constructions decide
   it by numerical rank (:data:`~pgsym.numeric.tolerances.RANK_EPS`).
8. The joins and meets of lines (:func:`join`, :func:`meet`, :func:`plucker_join`,
   :func:`plucker_meet`, and :func:`meet_lines` / :func:`plane_through_lines` of two lines of space, for which
   skew lines are degenerate too) return the zero vector for coincident input by default
   (``degenerate="zero"``, tested by :func:`is_zero_vector`), as the bare formulas
   :func:`cross` and :func:`triple_cross` always do; they accept ``degenerate="raise"``
   (:class:`~pgsym.errors.CoincidentPointsError`, :class:`~pgsym.errors.CoincidentLinesError`,
   :class:`~pgsym.errors.DependentPlanesError`) and ``"mask"`` as well.

**Complex input.** The kernels whose formulas are polynomial without conjugation — :func:`cross`,
:func:`join`, :func:`meet`, :func:`incident`, :func:`is_zero_vector`, :func:`bracket` and
:func:`harmonic_conjugate` — accept complex arrays and then compute in complex128 (the circular points
``I = (1, i, 0)``, ``J = (1, −i, 0)`` and the lines through them). Every other kernel measures (angles,
distances) or decides with a real tolerance, and refuses complex input with
:class:`~pgsym.errors.NonNumericError` rather than dropping the imaginary parts.

The check costs one BLAS dot product of each output block with itself while the block is
in cache (NaN and inf propagate into a sum of squares); only when it is not finite is
every entry tested.

>>> import numpy as np
>>> from pgsym import numeric as pn
>>> pn.join([np.nan, 0, 1], [[1.0, 1, 1], [0, 1, 1]])   # doctest: +ELLIPSIS
Traceback (most recent call last):
...
pgsym.errors.NonFiniteError: join: 2 of the 2 results are NaN or infinite; the first, at index (0,), comes from...
>>> pn.join([[np.nan, 0, 1], [0, 0, 1]], [1.0, 1, 1], nonfinite="mask")
(array([[nan, nan, nan],
       [-1.,  1.,  0.]]), array([False,  True]))

>>> pn.plane_through([0.0, 0, 0, 1], [1.0, 1, 1, 1], [[2.0, 2, 2, 1], [0, 0, 1, 1]], degenerate="mask")
(array([[nan, nan, nan, nan],
       [ 1., -1.,  0.,  0.]]), array([False,  True]))

>>> lines = pn.join(np.array([[0.0, 0, 1], [0, 1, 1]]), np.array([[1.0, 1, 1], [1, 1, 1]]))
>>> pn.dehomogenize(pn.meet(lines, [1.0, 0, -2]))     # where y = x and y = 1 cross x = 2
array([[2., 2.],
       [2., 1.]])
"""

from __future__ import annotations

from ._arrays import CHUNK, OptionError
from .affine import is_parallel, midpoint, parallel_line
from .classify import classify_matrix
from .conic_pencil import intersect_conics
from .convert import from_array, to_array
from .homogeneous import dehomogenize, homogenize, is_ideal
from .metric import (
    angle_bisectors,
    cos_angle,
    cos_squared_angle,
    is_perpendicular,
    orthogonal_projection,
    perpendicular_line,
    point_distance,
    point_line_distance,
    point_plane_distance,
    reflect,
    signed_angle,
    sin_angle,
)
from .nullspace import nullspace_svd, numeric_rank, plane_through_numeric, point_on_planes_numeric
from .plane import cross, incident, is_zero_vector, join, meet
from .plucker import (
    intersect_plane,
    klein_form,
    meet_lines,
    plane_through_lines,
    plane_through_point,
    plucker_join,
    plucker_meet,
)
from .projective_line import bracket, cross_ratio, cross_ratio_homogeneous, harmonic_conjugate
from .quadrics import form_value, polar, tangent_at, tangent_plane
from .space import plane_through, point_on_planes, triple_cross
from .svd import SVDSteps, svd_steps
from .transform import (
    adjugate,
    transform_conics,
    transform_dual_conics,
    transform_lines,
    transform_planes,
    transform_points,
    transform_quadrics,
)

__all__ = [
    "CHUNK",
    "OptionError",
    "SVDSteps",
    "adjugate",
    "angle_bisectors",
    "bracket",
    "classify_matrix",
    "cos_angle",
    "cos_squared_angle",
    "cross",
    "cross_ratio",
    "cross_ratio_homogeneous",
    "dehomogenize",
    "form_value",
    "from_array",
    "harmonic_conjugate",
    "homogenize",
    "incident",
    "intersect_conics",
    "intersect_plane",
    "is_ideal",
    "is_parallel",
    "is_perpendicular",
    "is_zero_vector",
    "join",
    "klein_form",
    "meet",
    "meet_lines",
    "midpoint",
    "nullspace_svd",
    "numeric_rank",
    "orthogonal_projection",
    "parallel_line",
    "perpendicular_line",
    "plane_through",
    "plane_through_lines",
    "plane_through_numeric",
    "plane_through_point",
    "plucker_join",
    "plucker_meet",
    "point_distance",
    "point_line_distance",
    "point_on_planes",
    "point_on_planes_numeric",
    "point_plane_distance",
    "polar",
    "reflect",
    "signed_angle",
    "sin_angle",
    "svd_steps",
    "tangent_at",
    "tangent_plane",
    "to_array",
    "transform_conics",
    "transform_dual_conics",
    "transform_lines",
    "transform_planes",
    "transform_points",
    "transform_quadrics",
    "triple_cross",
]
