"""pgsym: exact projective geometry on SymPy.

>>> from pgsym import Point, Line, join, meet
>>> x = meet(join(Point(0, 0), Point(2, 2)), Line(1, 0, -1))
>>> x                      # the raw cross product
Point(-2, -2, -2)
>>> x == Point(1, 1), x.canonical(), x.dehomogenize()
(True, Point(1, 1, 1), (1, 1))
"""

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
    NotOnKleinQuadricError,
    ObjectTypeError,
    PgsymError,
    SingularTransformationError,
    UndefinedCrossRatioError,
    UnparsableAnswerError,
    ZeroVectorError,
)
from .homogeneous import HomogeneousVector, is_zero
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

__version__ = "0.1.0"

__all__ = [
    "CoincidentLinesError",
    "CoincidentPointsError",
    "CollinearPointsError",
    "DecompositionError",
    "DegenerateConfigurationError",
    "DegenerateConicError",
    "DependentPlanesError",
    "DimensionError",
    "HomogeneousVector",
    "IdealPointError",
    "ImageError",
    "InvalidCoordinatesError",
    "Line",
    "NonNumericError",
    "NotOnKleinQuadricError",
    "ObjectTypeError",
    "PgsymError",
    "Point",
    "SingularTransformationError",
    "UndefinedCrossRatioError",
    "UnparsableAnswerError",
    "ZeroVectorError",
    "__version__",
    "collinear",
    "concurrent",
    "cross",
    "dual",
    "ideal_point",
    "incident",
    "is_zero",
    "join",
    "line_at_infinity",
    "meet",
]
