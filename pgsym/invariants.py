"""Euclidean and projective quantities of configurations, the values the invariants of the hierarchy compare.

Each quantity is written once as a fraction of two ring elements (``*_fraction``: only ``+``, ``-``, ``*``,
so it runs on SymPy numbers, polynomials and integers modulo a prime alike, and never raises), and once as
the checked function a reader calls, which refuses the configurations where the fraction is 0/0 or x/0 with
a named error.

The invariants themselves, their proofs (claims run by the proof engine), their counterexamples and the
summary table of the hierarchy live in :mod:`pgsym.proofs.invariance`; the old names of this module still
reach them, with a :class:`DeprecationWarning` naming the new home.

>>> signed_area([0, 0, 1], [1, 0, 1], [0, 1, 1])
1/2
>>> signed_area_fraction((0, 0, 1), (1, 0, 1), (0, 1, 1))
(1, 2)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy

from ._lazy import moved_names
from .errors import DegenerateConfigurationError, IdealPointError, UndefinedCrossRatioError
from .exact import is_zero
from .ring import cross, det, dot, squared_distance_fraction, transpose

__all__ = [
    "collinear_cross_ratio",
    "collinear_cross_ratio_fraction",
    "cos2_angle",
    "cos2_angle_fraction",
    "distance_squared",
    "signed_area",
    "signed_area_fraction",
    "signed_volume",
    "signed_volume_fraction",
]

Fraction2 = tuple[Any, Any]


# -- the fractions (any ring, no division, no check) ---------------------------------------------------------
def signed_area_fraction(p: Sequence[Any], q: Sequence[Any], r: Sequence[Any]) -> Fraction2:
    """``(det[p q r], 2 p₃ q₃ r₃)``: the signed area of a triangle as numerator and denominator.

    >>> signed_area_fraction((0, 0, 2), (4, 0, 2), (0, 6, 2))      # 48 / 16 = 3
    (48, 16)
    """
    return det(transpose([p, q, r])), 2 * p[-1] * q[-1] * r[-1]


def signed_volume_fraction(p: Sequence[Any], q: Sequence[Any], r: Sequence[Any], s: Sequence[Any]) -> Fraction2:
    """``(−det[p q r s], 6 p₄ q₄ r₄ s₄)``: the signed volume ``det[q − p, r − p, s − p] / 6`` of a tetrahedron.

    >>> signed_volume_fraction((0, 0, 0, 1), (1, 0, 0, 1), (0, 1, 0, 1), (0, 0, 1, 1))
    (1, 6)
    """
    return -det(transpose([p, q, r, s])), 6 * p[-1] * q[-1] * r[-1] * s[-1]


def cos2_angle_fraction(l: Sequence[Any], m: Sequence[Any]) -> Fraction2:
    """``((u·v)², (u·u)(v·v))`` for the normals u, v of two lines (planes): ``cos²`` of their angle.

    >>> cos2_angle_fraction((1, 0, 0), (1, -1, 0))
    (1, 2)
    """
    u, v = l[:-1], m[:-1]
    uv = dot(u, v)
    return uv * uv, dot(u, u) * dot(v, v)


def _is_nonzero(x: Any) -> bool:
    return not is_zero(x) if isinstance(x, (int, sympy.Basic)) else bool(x)


def collinear_cross_ratio_fraction(a: Sequence[Any], b: Sequence[Any], c: Sequence[Any],
                                   d: Sequence[Any]) -> Fraction2:
    """``([AC][BD], [AD][BC])`` for four collinear points of P², with ``[XY]`` one coordinate of ``X × Y``.

    For collinear points every ``X × Y`` is a multiple ``[XY]`` of the same line vector, so the coordinate
    ``k`` where ``A × B`` is nonzero gives the brackets (the first one when ``A = B``: then 0/0).

    >>> collinear_cross_ratio_fraction((0, 0, 1), (1, 0, 1), (2, 0, 1), (3, 0, 1))     # (0−2)(1−3)/((0−3)(1−2))
    (4, 3)
    """
    base = cross(a, b)
    k = next((i for i in range(3) if _is_nonzero(base[i])), 0)
    ac, bd, ad, bc = (cross(x, y)[k] for x, y in ((a, c), (b, d), (a, d), (b, c)))
    return ac * bd, ad * bc


# -- the checked quantities ----------------------------------------------------------------------------------
def _ex(v: Sequence[Any]) -> list[Any]:
    return [sympy.sympify(x) for x in v]


def _finite(*points: Sequence[Any]) -> None:
    for x in points:
        if is_zero(x[-1]):
            raise IdealPointError(f"the point {list(x)} is ideal (last coordinate zero): it has no Euclidean position")


def distance_squared(p: Sequence[Any], q: Sequence[Any]) -> Any:
    """The squared Euclidean distance of two finite points given homogeneously (2D or 3D).

    >>> distance_squared([0, 0, 1], [6, 8, 2])
    25
    """
    p, q = _ex(p), _ex(q)
    _finite(p, q)
    n, d = squared_distance_fraction(p, q)
    return n / d


def signed_area(p: Sequence[Any], q: Sequence[Any], r: Sequence[Any]) -> Any:
    """The signed area of the triangle of three finite points: ``det[p q r] / (2 p₃ q₃ r₃)``.

    >>> signed_area([0, 0, 1], [1, 0, 1], [0, 1, 1])
    1/2
    """
    p, q, r = _ex(p), _ex(q), _ex(r)
    _finite(p, q, r)
    n, d = signed_area_fraction(p, q, r)
    return n / d


def signed_volume(p: Sequence[Any], q: Sequence[Any], r: Sequence[Any], s: Sequence[Any]) -> Any:
    """The signed volume ``det[q − p, r − p, s − p] / 6`` of a tetrahedron of finite points (homogeneous input).

    >>> signed_volume([0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1])
    1/6
    """
    p, q, r, s = _ex(p), _ex(q), _ex(r), _ex(s)
    _finite(p, q, r, s)
    n, d = signed_volume_fraction(p, q, r, s)
    return n / d


def cos2_angle(l: Sequence[Any], m: Sequence[Any]) -> Any:
    """``cos²`` of the angle between two lines (2D) or planes (3D) from their normals; it fixes the angle in [0, π/2].

    >>> cos2_angle([1, 0, 0], [1, -1, 0])
    1/2
    """
    n, d = cos2_angle_fraction(_ex(l), _ex(m))
    if is_zero(d):
        raise DegenerateConfigurationError(
            "an angle needs two ordinary lines (planes) with real directions: the line (plane) at infinity "
            "and isotropic lines have a normal of zero length")
    return n / d


def collinear_cross_ratio(a: Sequence[Any], b: Sequence[Any], c: Sequence[Any], d: Sequence[Any]) -> Any:
    """The cross-ratio ``(A, B; C, D) = [AC][BD] / ([AD][BC])`` of four collinear points of P².

    >>> collinear_cross_ratio([0, 0, 1], [1, 0, 1], [2, 0, 1], [3, 0, 1])     # (0−2)(1−3)/((0−3)(1−2))
    4/3
    """
    a, b, c, d = _ex(a), _ex(b), _ex(c), _ex(d)
    if all(is_zero(x) for x in cross(a, b)):
        raise UndefinedCrossRatioError("the cross-ratio needs A ≠ B: the first two points coincide")
    n, den = collinear_cross_ratio_fraction(a, b, c, d)
    if is_zero(den):
        raise UndefinedCrossRatioError("the cross-ratio is undefined: A = D or B = C makes its denominator zero")
    return n / den


# the invariants, their proofs and the summary table moved up to the proofs (they run the claim engine)
__getattr__ = moved_names(__name__, "pgsym.proofs.invariance", (
    "INVARIANTS", "InvarianceCounterexample", "Invariant", "Proof", "invariant", "invariants_of",
    "summary_markdown", "summary_table"), renamed={"Counterexample": "InvarianceCounterexample"})
