"""pgsym: exact projective geometry on SymPy.

>>> from pgsym import Point, Line, join, meet
>>> x = meet(join(Point(0, 0), Point(2, 2)), Line(1, 0, -1))
>>> x                      # the raw cross product
Point(-2, -2, -2)
>>> x == Point(1, 1), x.canonical(), x.dehomogenize()
(True, Point(1, 1, 1), (1, 1))
"""

from .conics import Conic, DualConic, circular_points, conic_through, dual_conic_at_infinity
from .errors import (
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
    InvalidCoordinatesError,
    NonNumericError,
    NotAPencilError,
    NotOnConicError,
    NotOnKleinQuadricError,
    NotOnQuadricError,
    NotSkewSymmetricError,
    ObjectTypeError,
    PgsymError,
    SingularTransformationError,
    UndefinedCrossRatioError,
    UnparsableAnswerError,
    ZeroCoordinateError,
    ZeroVectorError,
)
from .homogeneous import HomogeneousVector, is_zero
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
from .quadrics import Quadric
from .space import Plane, Point3, coplanar, plane_at_infinity, plane_through, point_on_planes

__version__ = "0.1.0"

__all__ = [
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
    "InvalidCoordinatesError",
    "Line",
    "Line3",
    "NonNumericError",
    "NotAPencilError",
    "NotOnConicError",
    "NotOnKleinQuadricError",
    "NotOnQuadricError",
    "NotSkewSymmetricError",
    "ObjectTypeError",
    "PgsymError",
    "Plane",
    "Point",
    "Point1",
    "Point3",
    "ProjectiveMap1",
    "Quadric",
    "SingularTransformationError",
    "UndefinedCrossRatioError",
    "UnparsableAnswerError",
    "ZeroCoordinateError",
    "ZeroVectorError",
    "__version__",
    "bracket",
    "circular_points",
    "collinear",
    "concurrent",
    "conic_through",
    "coplanar",
    "cross",
    "cross_ratio",
    "cross_ratio_lines",
    "cross_ratio_planes",
    "dual",
    "dual_conic_at_infinity",
    "harmonic_conjugate",
    "ideal_point",
    "incident",
    "is_zero",
    "join",
    "klein_form",
    "line_at_infinity",
    "meet",
    "nullspace_exact",
    "nullspace_svd",
    "plane_at_infinity",
    "plane_through",
    "point_on_planes",
    "rank_exact",
    "reciprocal_product",
]
