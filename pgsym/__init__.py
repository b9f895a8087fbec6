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
# user never pays for SymPy. The errors are plain Python and are imported eagerly.
from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from .errors import (
    AnswersFileError,
    CoincidentLinesError,
    CoincidentPointsError,
    CollinearPointsError,
    DecompositionError,
    DegenerateConfigurationError,
    DegenerateConicError,
    DependentPlanesError,
    DimensionError,
    IdealPointError,
    ImageError,
    InputLimitError,
    InvalidCoordinatesError,
    ManifestError,
    MathJaxMissingError,
    NonFiniteError,
    NonNumericError,
    NonPolynomialClaimError,
    NotAPencilError,
    NotOnConicError,
    NotOnKleinQuadricError,
    NotOnQuadricError,
    NotSkewSymmetricError,
    ObjectTypeError,
    OptionError,
    OutputError,
    PgsymError,
    RosterError,
    SingularTransformationError,
    TemplateError,
    TeXFailedError,
    TeXMissingError,
    UndecidableError,
    UndefinedConstructionError,
    UndefinedCrossRatioError,
    UnknownClaimError,
    UnknownTopicError,
    UnparsableAnswerError,
    ZeroCoordinateError,
    ZeroVectorError,
)

__version__ = "0.1.0"

_LAZY: dict[str, str] = {
    "Claim": "proofs",
    "Verdict": "proofs",
    "Transformation": "transformations",
    "adjugate": "transformations",
    "homography_from_points": "transformations",
    "classify": "hierarchy",
    "CLASSES_2D": "hierarchy",
    "CLASSES_3D": "hierarchy",
    "EUCLIDEAN_2D": "hierarchy",
    "ISOMETRY_2D": "hierarchy",
    "SIMILARITY_2D": "hierarchy",
    "AFFINE_2D": "hierarchy",
    "PROJECTIVE_2D": "hierarchy",
    "EUCLIDEAN_3D": "hierarchy",
    "SIMILARITY_3D": "hierarchy",
    "AFFINE_3D": "hierarchy",
    "PROJECTIVE_3D": "hierarchy",
    "rotation_2d": "hierarchy",
    "rotation_3d": "hierarchy",
    "INVARIANTS": "invariants",
    "invariant": "invariants",
    "summary_table": "invariants",
    "decompose": "decomposition",
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
    "nullspace_svd": "linalg",
    "plane_at_infinity": "space",
    "plane_through": "space",
    "point_on_planes": "space",
    "rank_exact": "linalg",
    "reciprocal_product": "plucker",
}

if TYPE_CHECKING:  # pragma: no cover
    from .conics import Conic, DualConic, circular_points, conic_through, dual_conic_at_infinity
    from .decomposition import decompose
    from .hierarchy import (
        AFFINE_2D,
        AFFINE_3D,
        CLASSES_2D,
        CLASSES_3D,
        EUCLIDEAN_2D,
        EUCLIDEAN_3D,
        ISOMETRY_2D,
        PROJECTIVE_2D,
        PROJECTIVE_3D,
        SIMILARITY_2D,
        SIMILARITY_3D,
        classify,
        rotation_2d,
        rotation_3d,
    )
    from .homogeneous import HomogeneousVector, is_zero
    from .invariants import INVARIANTS, invariant, summary_table
    from .linalg import nullspace_exact, nullspace_svd, rank_exact
    from .plucker import Line3, cross_ratio_planes, klein_form, reciprocal_product
    from .projective_line import Point1, ProjectiveMap1, bracket, cross_ratio, cross_ratio_lines, harmonic_conjugate
    from .projective_plane import (
        Line,
        Point,
        collinear,
        concurrent,
        cross,
        dual,
        ideal_point,
        incident,
        join,
        line_at_infinity,
        meet,
    )
    from .proofs import Claim, Verdict
    from .proofs import prove as prove_claim
    from .quadrics import Quadric
    from .space import Plane, Point3, coplanar, plane_at_infinity, plane_through, point_on_planes
    from .transformations import Transformation, adjugate, homography_from_points


_SUBPACKAGES = ("numeric", "vision")


def __getattr__(name: str) -> Any:
    if name in _SUBPACKAGES:
        return importlib.import_module(f".{name}", __name__)
    if name == "prove_claim":  # `prove` would be too generic a top-level name
        return importlib.import_module(".proofs", __name__).prove
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'pgsym' has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{module}", __name__), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY) | set(_SUBPACKAGES) | {"prove_claim"})


__all__ = [
    "AFFINE_2D",
    "AFFINE_3D",
    "CLASSES_2D",
    "CLASSES_3D",
    "EUCLIDEAN_2D",
    "EUCLIDEAN_3D",
    "INVARIANTS",
    "ISOMETRY_2D",
    "PROJECTIVE_2D",
    "PROJECTIVE_3D",
    "SIMILARITY_2D",
    "SIMILARITY_3D",
    "AnswersFileError",
    "Claim",
    "CoincidentLinesError",
    "CoincidentPointsError",
    "CollinearPointsError",
    "Conic",
    "DecompositionError",
    "DegenerateConfigurationError",
    "DegenerateConicError",
    "DependentPlanesError",
    "DimensionError",
    "DualConic",
    "HomogeneousVector",
    "IdealPointError",
    "ImageError",
    "InputLimitError",
    "InvalidCoordinatesError",
    "Line",
    "Line3",
    "ManifestError",
    "MathJaxMissingError",
    "NonFiniteError",
    "NonNumericError",
    "NonPolynomialClaimError",
    "NotAPencilError",
    "NotOnConicError",
    "NotOnKleinQuadricError",
    "NotOnQuadricError",
    "NotSkewSymmetricError",
    "ObjectTypeError",
    "OptionError",
    "OutputError",
    "PgsymError",
    "Plane",
    "Point",
    "Point1",
    "Point3",
    "ProjectiveMap1",
    "Quadric",
    "RosterError",
    "SingularTransformationError",
    "TeXFailedError",
    "TeXMissingError",
    "TemplateError",
    "Transformation",
    "UndecidableError",
    "UndefinedConstructionError",
    "UndefinedCrossRatioError",
    "UnknownClaimError",
    "UnknownTopicError",
    "UnparsableAnswerError",
    "Verdict",
    "ZeroCoordinateError",
    "ZeroVectorError",
    "__version__",
    "adjugate",
    "bracket",
    "circular_points",
    "classify",
    "collinear",
    "concurrent",
    "conic_through",
    "coplanar",
    "cross",
    "cross_ratio",
    "cross_ratio_lines",
    "cross_ratio_planes",
    "decompose",
    "dual",
    "dual_conic_at_infinity",
    "harmonic_conjugate",
    "homography_from_points",
    "ideal_point",
    "incident",
    "invariant",
    "is_zero",
    "join",
    "klein_form",
    "line_at_infinity",
    "meet",
    "nullspace_exact",
    "nullspace_svd",
    "numeric",
    "plane_at_infinity",
    "plane_through",
    "point_on_planes",
    "prove_claim",
    "rank_exact",
    "reciprocal_product",
    "rotation_2d",
    "rotation_3d",
    "summary_table",
]
