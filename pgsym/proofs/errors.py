"""The errors of the proof engine: claims that are not polynomial, undefined constructions, unknown names.

>>> from pgsym.errors import PgsymError
>>> issubclass(UnknownClaimError, PgsymError)
True
"""

from __future__ import annotations

from ..errors import InputLimitError, InvalidCoordinatesError, ObjectTypeError, PgsymError

__all__ = [
    "AlphaGeometryError",
    "NonPolynomialClaimError",
    "PolynomialBackendError",
    "StatementError",
    "StatementKindError",
    "StatementLimitError",
    "StatementNameError",
    "StatementSyntaxError",
    "UndefinedConstructionError",
    "UnknownClaimError",
    "UnsupportedConstructionError",
]


class NonPolynomialClaimError(InvalidCoordinatesError):
    """A coordinate, hypothesis or conclusion is not a polynomial in the claim's parameters."""


class PolynomialBackendError(PgsymError):
    """The requested polynomial backend (python-flint or SymPy) is not available, or cannot hold a value."""


class UndefinedConstructionError(ObjectTypeError):
    """A construction refers to an object or an operation the claim does not define."""


class UnknownClaimError(PgsymError, KeyError):
    """No claim of that name is in the catalogue."""

    def __str__(self) -> str:  # KeyError would quote the message
        return str(self.args[0]) if self.args else ""


class StatementError(PgsymError):
    """A theorem written in the statement language cannot be read; ``line`` and ``column`` say where (1-based).

    ``str()`` is ``"LINE:COL: message"``; ``source`` names the file when it was read from one.

    >>> str(StatementSyntaxError("expected a name", 3, 7))
    '3:7: expected a name'
    """

    def __init__(self, message: str, line: int = 0, column: int = 0, source: str = "") -> None:
        super().__init__(message)
        self.message, self.line, self.column, self.source = message, line, column, source

    def __str__(self) -> str:
        where = f"{self.line}:{self.column}: " if self.line else ""
        return f"{self.source + ':' if self.source else ''}{where}{self.message}"


class StatementSyntaxError(StatementError):
    """The text does not follow the grammar of the statement language (or is not UTF-8 text)."""


class StatementNameError(StatementError):
    """A name is used before it is defined, defined twice, or is a keyword of the language."""


class StatementKindError(StatementError, ObjectTypeError):
    """An object of the wrong kind for a construction or conclusion (a line where a point belongs)."""


class StatementLimitError(StatementError, InputLimitError):
    """The statement exceeds a limit of :mod:`pgsym.limits` (size, line length, nesting, names)."""


class AlphaGeometryError(StatementError):
    """A problem of AlphaGeometry's construction language cannot be read (its syntax, an unknown or undefined
    point, a construction with the wrong number of arguments); ``construction`` names the construction, if any.

    >>> str(AlphaGeometryError("on_line takes 3 points, got 2", 4, construction="on_line"))
    '4: on_line takes 3 points, got 2'
    """

    def __init__(self, message: str, line: int = 0, column: int = 0, source: str = "",
                 construction: str = "") -> None:
        super().__init__(message, line, column, source)
        self.construction = construction

    def __str__(self) -> str:  # a line of the problem file, no column: "FILE:LINE: message"
        where = f"{self.line}{':' + str(self.column) if self.column else ''}: " if self.line else ""
        return f"{self.source + ':' if self.source else ''}{where}{self.message}"


class UnsupportedConstructionError(AlphaGeometryError):
    """A construction or goal of AlphaGeometry's language that pgsym's statement language cannot express
    faithfully (for instance one whose meaning depends on a branch that pgsym cannot name).

    >>> str(UnsupportedConstructionError("unsupported: trisect", 2, construction="trisect"))
    '2: unsupported: trisect'
    """
