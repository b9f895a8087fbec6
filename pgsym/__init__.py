"""pgsym: exact projective geometry on SymPy.

>>> from pgsym import Point, Line, join, meet
>>> x = meet(join(Point(0, 0), Point(2, 2)), Line(1, 0, -1))
>>> x                      # the raw cross product
Point(-2, -2, -2)
>>> x == Point(1, 1), x.canonical(), x.dehomogenize()
(True, Point(1, 1, 1), (1, 1))
"""

# The exact core needs SymPy, which takes a noticeable time to import; the numeric path does not.
# Names are therefore resolved on first use (PEP 562), so `import pgsym` stays light and a numeric
# user never pays for SymPy. The core's errors are plain Python and are bound eagerly. Every public
# name is listed once, in `_LAZY` or in `errors.__all__`; `__all__` is derived from them.
from __future__ import annotations

from . import errors as _errors
from ._lazy import lazy_names

__version__ = "0.1.0"

globals().update({name: getattr(_errors, name) for name in _errors.__all__})

_LAZY: dict[str, str] = {
    "Claim": "proofs",
    "Verdict": "proofs",
    "Transformation": "transformations",
    "adjugate": "transformations",
    "homography_from_points": "transformations",
    "homography_from_points_and_conics": "conic_pencil",
    "classify": "hierarchy",
    "CLASSES_2D": "hierarchy",
    "CLASSES_3D": "hierarchy",
    "EUCLIDEAN_2D": "hierarchy",
    "ISOMETRY_2D": "hierarchy",
    "ISOMETRY_3D": "hierarchy",
    "SIMILARITY_2D": "hierarchy",
    "AFFINE_2D": "hierarchy",
    "PROJECTIVE_2D": "hierarchy",
    "EUCLIDEAN_3D": "hierarchy",
    "SIMILARITY_3D": "hierarchy",
    "AFFINE_3D": "hierarchy",
    "PROJECTIVE_3D": "hierarchy",
    "rotation_2d": "hierarchy",
    "rotation_3d": "hierarchy",
    "INVARIANTS": "proofs.invariance",
    "invariant": "proofs.invariance",
    "invariants_of": "proofs.invariance",
    "summary_markdown": "proofs.invariance",
    "summary_table": "proofs.invariance",
    "decompose": "decomposition",
    "affine_decomposition": "decomposition",
    "FixedSpace": "fixed_points",
    "fixed_lines": "fixed_points",
    "fixed_planes": "fixed_points",
    "fixed_points": "fixed_points",
    "Conic": "conics",
    "DualConic": "conics",
    "HomogeneousVector": "homogeneous",
    "Line": "projective_plane",
    "Line3": "plucker",
    "Plane": "space",
    "Point": "projective_plane",
    "Point1": "projective_line",
    "Point3": "space",
    "ProjectiveMap1": "projective_line",
    "Quadric": "quadrics",
    "DualQuadric": "quadrics",
    "bracket": "projective_line",
    "circular_points": "conics",
    "collinear": "projective_plane",
    "concurrent": "projective_plane",
    "conic_through": "conics",
    "coplanar": "space",
    "cross": "projective_plane",
    "cross_ratio": "projective_line",
    "cross_ratio_lines": "projective_line",
    "cross_ratio_planes": "plucker",
    "dual": "projective_plane",
    "dual_conic_at_infinity": "conics",
    "harmonic_conjugate": "projective_line",
    "ideal_point": "projective_plane",
    "incident": "projective_plane",
    "is_zero": "homogeneous",
    "join": "projective_plane",
    "klein_form": "plucker",
    "line_at_infinity": "projective_plane",
    "meet": "projective_plane",
    "nullspace_exact": "linalg",
    "nullspace_svd": "numeric.nullspace",
    "plane_at_infinity": "space",
    "plane_through": "space",
    "point_on_planes": "space",
    "rank_exact": "linalg",
    "reciprocal_product": "plucker",
    "meet_lines": "plucker",
    "plane_through_lines": "plucker",
    "absolute_dual_quadric": "metric",
    "angle_bisectors": "metric",
    "common_perpendicular": "metric",
    "cos_angle": "metric",
    "cos_squared_angle": "metric",
    "distance": "metric",
    "is_concyclic": "metric",
    "is_perpendicular": "metric",
    "laguerre_cross_ratio": "metric",
    "orthogonal_projection": "metric",
    "perpendicular_line": "metric",
    "perpendicular_plane": "metric",
    "point_distance": "metric",
    "point_line_distance": "metric",
    "point_plane_distance": "metric",
    "reflect": "metric",
    "reflection": "metric",
    "rotation": "metric",
    "scaling": "metric",
    "signed_angle": "metric",
    "sin_angle": "metric",
    "squared_distance": "metric",
    "translation": "metric",
    "intersect_conics": "conic_pencil",
    "conics_through_tangent": "conic_pencil",
    "affine_type": "conic_metric",
    "conic_center": "conic_metric:center",
    "conic_axes": "conic_metric:axes",
    "conic_foci": "conic_metric:foci",
    "semi_axes": "conic_metric",
    "radius": "conic_metric",
    "squared_radius": "conic_metric",
    "cos_intersection_angle": "conic_metric",
    "conic_from_cross_ratio": "conic_pencil",
    "is_parallel": "affine",
    "midpoint": "affine",
    "parallel_line": "affine",
    # the errors of the subsystems live beside them (importing one loads only its small module)
    "AnswersFileError": "exercises.errors",
    "ManifestError": "exercises.errors",
    "MathJaxMissingError": "exercises.errors",
    "RosterError": "exercises.errors",
    "TeXFailedError": "exercises.errors",
    "TeXMissingError": "exercises.errors",
    "TemplateError": "exercises.errors",
    "UnknownTopicError": "exercises.errors",
    "UnparsableAnswerError": "exercises.errors",
    "NonPolynomialClaimError": "proofs.errors",
    "UndefinedConstructionError": "proofs.errors",
    "UnknownClaimError": "proofs.errors",
    "ImageError": "vision.errors",
}

# the subpackages themselves, and the proof engine under a name less generic than `prove`
_LAZY.update({"numeric": "numeric:", "vision": "vision:", "prove_claim": "proofs:prove"})

__getattr__, __dir__ = lazy_names(__name__, _LAZY)

__all__ = sorted([*_errors.__all__, *_LAZY])
