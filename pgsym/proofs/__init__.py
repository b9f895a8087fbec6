"""Proof by computation: claims, the proof engine, verdicts and the catalogue of the book's theorems.

>>> from pgsym.proofs import prove
>>> prove("pappus").proved
True
>>> v = prove("lines-transform-like-points")   # a deliberately false claim
>>> v.status, v.counterexample.recheck()
('false', True)
"""

# Names resolve on first use (PEP 562): the command line imports the errors of this package
# without paying for SymPy, which the engine and the catalogue need.
from __future__ import annotations

from .._lazy import lazy_names
from . import errors as _errors
from .errors import (  # noqa: F401 (re-exported)
    AlphaGeometryError,
    NonPolynomialClaimError,
    PolynomialBackendError,
    StatementError,
    StatementKindError,
    StatementLimitError,
    StatementNameError,
    StatementSyntaxError,
    UndefinedConstructionError,
    UnknownClaimError,
    UnsupportedConstructionError,
)

_LAZY = {
    "CATALOGUE": "catalogue",
    "catalogue_names": "catalogue",
    "get_claim": "catalogue",
    "prove": "catalogue",
    "prove_all": "catalogue",
    "Claim": "claims",
    "discover": "discovery",
    "parse_statement": "language",
    "read_statement": "language",
    "PRIME": "engine",
    "Certificate": "verdicts",
    "Condition": "verdicts",
    "Counterexample": "verdicts",
    "Status": "verdicts",
    "Verdict": "verdicts",
}


__getattr__, __dir__ = lazy_names(__name__, _LAZY)


__all__ = sorted([*_LAZY, *_errors.__all__])
