"""The error hierarchy of pgsym.

Every error a user can provoke with bad input is a :class:`PgsymError`. The
concrete classes also derive from the built-in exception a Python user would
expect (``ValueError`` for bad values, ``TypeError`` for bad types), so both
``except PgsymError`` and ``except ValueError`` work.

>>> from pgsym import Point, join
>>> try:
...     join(Point(1, 2), Point(2, 4, 2))
... except PgsymError as err:
...     print(type(err).__name__)
CoincidentPointsError
"""

from __future__ import annotations

__all__ = [
    "CoincidentLinesError",
    "CoincidentPointsError",
    "CollinearPointsError",
    "DecompositionError",
    "DegenerateConfigurationError",
    "DegenerateConicError",
    "DependentPlanesError",
    "DimensionError",
    "IdealPointError",
    "InconsistentDataError",
    "InputLimitError",
    "InvalidCoordinatesError",
    "LineOnQuadricError",
    "NonFiniteError",
    "NonNumericError",
    "NotAPencilError",
    "NotASphereError",
    "NotOnConicError",
    "NotOnKleinQuadricError",
    "NotOnQuadricError",
    "NotSkewSymmetricError",
    "ObjectTypeError",
    "OptionError",
    "OutputError",
    "PgsymError",
    "SingularTransformationError",
    "SkewLinesError",
    "UndecidableError",
    "UndefinedCrossRatioError",
    "ZeroCoordinateError",
    "ZeroVectorError",
]


class PgsymError(Exception):
    """Base class of every error raised by pgsym for bad input."""


class InvalidCoordinatesError(PgsymError, ValueError):
    """Coordinates that cannot describe a projective object."""


class NonNumericError(InvalidCoordinatesError, TypeError):
    """A coordinate is not a number or a SymPy expression (e.g. a string or None)."""


class DimensionError(InvalidCoordinatesError):
    """The wrong number of coordinates for the object asked for."""


class ZeroVectorError(InvalidCoordinatesError):
    """All homogeneous coordinates are zero: the zero vector is no projective object."""


class ObjectTypeError(PgsymError, TypeError):
    """An operation received the wrong kind of geometric object (e.g. a line where a point belongs)."""


class DegenerateConfigurationError(PgsymError, ValueError):
    """The input is a special case for which the construction is undefined."""


class CoincidentPointsError(DegenerateConfigurationError):
    """Two points that were meant to be distinct are the same projective point."""


class CoincidentLinesError(DegenerateConfigurationError):
    """Two lines that were meant to be distinct are the same projective line."""


class IdealPointError(DegenerateConfigurationError):
    """An ideal point (last coordinate zero) has no inhomogeneous coordinates."""


class CollinearPointsError(DegenerateConfigurationError):
    """Points that must span a plane (or fix a homography) lie on one line."""


class DependentPlanesError(DegenerateConfigurationError):
    """Planes that must meet in a single point share a line (or are parallel or equal)."""


class SkewLinesError(DegenerateConfigurationError):
    """Two lines of space that must meet (in a point, or in a common plane) are skew."""


class SingularTransformationError(DegenerateConfigurationError):
    """A transformation matrix is singular (determinant zero) where an invertible one is required."""


class DegenerateConicError(DegenerateConfigurationError):
    """A conic or quadric is degenerate (rank-deficient) where a non-degenerate one is required."""


class UndefinedCrossRatioError(DegenerateConfigurationError):
    """The cross-ratio of the given points is undefined (e.g. three of them coincide)."""


class NotOnKleinQuadricError(InvalidCoordinatesError):
    """Six Plücker coordinates that violate the Klein constraint describe no line."""


class DecompositionError(DegenerateConfigurationError):
    """A matrix has no decomposition of the requested form."""



class ZeroCoordinateError(DegenerateConfigurationError):
    """The coordinate chosen to be fixed to 1 is zero in every solution (method #2 cannot be used)."""


class NotOnQuadricError(DegenerateConfigurationError):
    """A point that must lie on a quadric (e.g. to have a tangent plane there) does not."""


class LineOnQuadricError(DegenerateConfigurationError):
    """A line that was to meet a quadric in one or two points lies on it (a ruling, or a line of a plane pair)."""


class NotASphereError(DegenerateConfigurationError):
    """A quadric asked for a sphere's centre or radius is no real sphere.

    A real sphere has the form ``|X − c|² = r²`` with ``r² > 0``.
    """


class NotSkewSymmetricError(InvalidCoordinatesError):
    """A matrix offered as a (dual) Plücker matrix is not skew-symmetric (``Lᵀ ≠ −L``)."""


class NotAPencilError(DegenerateConfigurationError):
    """Planes that were meant to contain one common line (a pencil of planes) do not."""


class NotOnConicError(DegenerateConfigurationError):
    """A point that must lie on a conic (e.g. for a tangent line) does not."""


class InconsistentDataError(DegenerateConfigurationError):
    """Measured data that no configuration can produce, e.g. image line pairs that are perpendicular in no world.

    Not a special case of a valid configuration: the data contradict the model (a
    measurement error or a wrong assumption). A subclass of
    :class:`DegenerateConfigurationError`, so code that caught that error keeps working.
    """


class OptionError(PgsymError, ValueError):
    """A keyword option of a numeric function has a value it does not accept (e.g. ``ideal="skip"``)."""





class OutputError(PgsymError, OSError):
    """The output folder cannot be created or written."""










class UndecidableError(PgsymError, ValueError):
    """An exact question (is this expression zero? are these equal?) that pgsym cannot decide.

    Raised for entries outside the rational functions over algebraic numbers, such as ``pi``,
    ``exp(1)`` or an unknown function, where answering would mean guessing.
    """


class NonFiniteError(InvalidCoordinatesError):
    """A numeric array holds NaN or an infinity where finite numbers are required."""


class InputLimitError(PgsymError, ValueError):
    """User input exceeds a documented limit (bytes, digits, exponent, nesting, pixels)."""
