"""Proof by computation: claims, the proof engine, verdicts and the catalogue of the book's theorems.

>>> from pgsym.proofs import prove
>>> prove("pappus").proved
True
>>> v = prove("lines-transform-like-points")   # a deliberately false claim
>>> v.status, v.counterexample.recheck()
('false', True)
"""

from .catalogue import CATALOGUE, UnknownClaimError, catalogue_names, get_claim, prove, prove_all
from .claims import Claim, NonPolynomialClaimError, UndefinedConstructionError
from .engine import PRIME
from .verdicts import Certificate, Condition, Counterexample, Verdict

__all__ = [
    "CATALOGUE",
    "PRIME",
    "Certificate",
    "Claim",
    "Condition",
    "Counterexample",
    "NonPolynomialClaimError",
    "UndefinedConstructionError",
    "UnknownClaimError",
    "Verdict",
    "catalogue_names",
    "get_claim",
    "prove",
    "prove_all",
]
