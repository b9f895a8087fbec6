"""The decomposition ``H = H_S H_A H_P`` of a projective transformation (similarity · affinity · projectivity).

Write ``H`` in blocks, ``H = [[A, t], [vᵀ, v]]`` with ``A`` the upper-left ``n×n`` block
(``n`` = 2 or 3), ``t`` a column, ``vᵀ`` a row and ``v`` the corner entry. Then

    H_P = [[I, 0], [vᵀ, v]],   H_A = [[K, 0], [0ᵀ, 1]],   H_S = [[s R, t / v], [0ᵀ, 1]]

with ``s R K = A − t vᵀ / v``, where ``K`` is upper triangular with positive diagonal and
``det K = 1``, ``R`` is orthogonal and ``s > 0``. Multiplying out gives exactly ``H``.

**When it exists.** (i) ``v ≠ 0``: the corner entry must be nonzero, i.e. ``H`` maps the
origin ``(0, …, 0, 1)`` to a finite point; otherwise :class:`~pgsym.errors.DecompositionError`
is raised (compose with a translation first). (ii) ``H`` non-singular, which makes
``M = A − t vᵀ/v`` non-singular, because ``det H = v · det M``. Then ``Mᵀ M = s² KᵀK`` is
positive definite, ``s = |det M|^(1/n)`` and ``K`` is the Cholesky factor of
``MᵀM / s²``: the factors are unique. ``R`` is a rotation when ``det M > 0`` and a
rotation composed with a reflection when ``det M < 0``. The entries are exact algebraic
numbers (square roots appear, from the lengths in the Cholesky factor).

>>> d = decompose([[2, 1, 1], [0, 2, 3], [0, 0, 1]])      # an affine map: H_P = I
>>> d.K, d.s
(Matrix([
[1, 1/2],
[0,   1]]), 2)
>>> d.verify()
True
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy
from sympy import ImmutableMatrix, Matrix

from .errors import DecompositionError, UndecidableError
from .exact import is_zero, sign
from .transformations import Transformation

__all__ = ["Decomposition", "decompose"]


def _simplify_radicals(e: Any) -> Any:
    """Exact normal form for expressions with square roots of rationals (no heuristics)."""
    return sympy.radsimp(sympy.expand(e))


@dataclass(frozen=True)
class Decomposition:
    """The factors of ``H = H_S H_A H_P`` and their parts: scale ``s``, orthogonal ``R``, upper-triangular ``K``,
    translation ``t`` (of ``H_S``), and ``v`` (the last row of ``H_P``)."""

    H: ImmutableMatrix
    H_S: ImmutableMatrix
    H_A: ImmutableMatrix
    H_P: ImmutableMatrix
    s: Any
    R: ImmutableMatrix
    K: ImmutableMatrix

    def product(self) -> ImmutableMatrix:
        """``H_S H_A H_P``, with radicals brought to normal form."""
        return ImmutableMatrix((self.H_S * self.H_A * self.H_P).applyfunc(_simplify_radicals))

    def verify(self) -> bool:
        """True when ``H_S H_A H_P = H`` entry by entry and the factors have the stated forms."""
        n = self.R.rows
        ok = all(is_zero(_simplify_radicals(a - b)) for a, b in zip(self.product(), self.H, strict=True))
        RtR = (self.R.T * self.R).applyfunc(_simplify_radicals)
        ok = ok and all(is_zero(RtR[i, j] - (1 if i == j else 0)) for i in range(n) for j in range(n))
        ok = ok and all(is_zero(self.K[i, j]) for i in range(n) for j in range(i))
        ok = ok and is_zero(_simplify_radicals(self.K.det() - 1))
        return bool(ok)


def decompose(H: Any) -> Decomposition:
    """Decompose a 3×3 or 4×4 projective transformation as ``H_S H_A H_P`` (Hartley & Zisserman §2.4.6).

    Raises :class:`~pgsym.errors.DecompositionError` when the corner entry ``v`` is zero
    (the origin is mapped to infinity), and
    :class:`~pgsym.errors.SingularTransformationError` for a singular matrix.

    >>> d = decompose([[1, 0, 0], [0, 1, 0], [1, 0, 1]])     # a pure projectivity
    >>> d.H_S == sympy.eye(3) and d.H_A == sympy.eye(3)
    True
    >>> decompose([[1, 0, 0], [0, 1, 0], [1, 0, 0]])        # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.SingularTransformationError: ...
    >>> decompose([[1, 0, 0], [0, 0, 1], [0, 1, 0]])        # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.DecompositionError: ...
    """
    T = H if isinstance(H, Transformation) else Transformation(H)
    M0 = Matrix(T.matrix)
    n = M0.rows - 1
    v = M0[n, n]
    if is_zero(v):
        raise DecompositionError(
            f"H = {M0.tolist()} has corner entry v = 0: it maps the origin to infinity, so it has no "
            "decomposition H_S H_A H_P; compose H with a translation first (H T moves another point to the origin)"
        )
    A, t, vrow = M0[:n, :n], M0[:n, n], M0[n, :n]
    M = (A - t * vrow / v).applyfunc(sympy.cancel)
    detM = sympy.cancel(M.det())
    if not detM.is_number:
        raise DecompositionError(
            "the decomposition needs numeric entries: the signs of the scale and of det(A − t vᵀ/v) "
            "must be decidable; substitute values for the symbols first"
        )
    try:  # a real matrix is needed: s and R are real, and s depends on the sign of det M
        sign(detM)
        for e in M0:
            if not is_zero(sympy.im(e)):
                raise UndecidableError(f"the entry {e} is not real")
    except UndecidableError as err:
        raise DecompositionError(f"H_S H_A H_P needs a real matrix with decidable signs: {err}") from err
    # Cholesky MᵀM = K'ᵀK' of a rational matrix: only square roots of rationals appear (the squared
    # diagonal entries are ratios of leading principal minors); then K = K'/s and R = M K'⁻¹
    N = (M.T * M).applyfunc(sympy.cancel)
    Kp = Matrix.zeros(n, n)
    for j in range(n):
        for i in range(j + 1):
            acc = N[i, j] - sum((Kp[k, i] * Kp[k, j] for k in range(i)), sympy.Integer(0))
            if i == j:
                Kp[i, i] = sympy.sqrt(_simplify_radicals(acc))
            else:
                Kp[i, j] = _simplify_radicals(acc / Kp[i, i])
    s = sympy.root(abs(detM), n)
    K = (Kp / s).applyfunc(_simplify_radicals)
    Kinv = Kp.inv(method="ADJ").applyfunc(_simplify_radicals)
    R = (M * Kinv).applyfunc(_simplify_radicals)
    H_P = Matrix.eye(n + 1)
    H_P[n, :n] = vrow
    H_P[n, n] = v
    H_A = Matrix.eye(n + 1)
    H_A[:n, :n] = K
    H_S = Matrix.eye(n + 1)
    H_S[:n, :n] = (s * R).applyfunc(_simplify_radicals)
    H_S[:n, n] = (t / v).applyfunc(sympy.cancel)
    return Decomposition(ImmutableMatrix(M0), ImmutableMatrix(H_S), ImmutableMatrix(H_A), ImmutableMatrix(H_P),
                         s, ImmutableMatrix(R), ImmutableMatrix(K))
