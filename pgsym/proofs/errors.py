"""The errors of the proof engine: claims that are not polynomial, undefined constructions, unknown names.

>>> from pgsym.errors import PgsymError
>>> issubclass(UnknownClaimError, PgsymError)
True
"""

from __future__ import annotations

from ..errors import InvalidCoordinatesError, ObjectTypeError, PgsymError

__all__ = ["NonPolynomialClaimError", "PolynomialBackendError", "UndefinedConstructionError", "UnknownClaimError"]


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
