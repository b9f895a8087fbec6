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

from .errors import DecompositionError, SingularTransformationError, UndecidableError
from .exact import is_zero, sign
from .matrices import exact_matrix
from .transformations import Transformation

__all__ = ["AffineDecomposition", "Decomposition", "affine_decomposition", "decompose"]


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


# -- the affine decomposition A = R(θ) R(−φ) D R(φ) ----------------------------------------------------
def _rot(c: Any, s: Any) -> ImmutableMatrix:
    return ImmutableMatrix([[c, -s], [s, c]])


@dataclass(frozen=True)
class AffineDecomposition:
    """The factors of ``A = R(θ) R(−φ) D R(φ)`` (Hartley & Zisserman §2.4.3) of a 2×2 linear part.

    ``A`` is the linear part (of an affine map with its last row scaled to ``(0, 0, 1)``), ``t`` its
    translation (zero for a 2×2 input). ``cos_theta, sin_theta`` give the rotation ``R(θ)``;
    ``cos_phi, sin_phi`` the direction φ of the two orthogonal axes that ``D = diag(λ1, λ2)``
    scales. ``λ1 > 0``; ``λ2`` has the sign of ``det A`` (a negative ``λ2`` is the reflection of an
    orientation-reversing map). All entries are exact (nested square roots of rationals in general).
    """

    A: ImmutableMatrix
    t: ImmutableMatrix
    cos_theta: Any
    sin_theta: Any
    cos_phi: Any
    sin_phi: Any
    lambda1: Any
    lambda2: Any

    @property
    def R_theta(self) -> ImmutableMatrix:
        """``R(θ)``."""
        return _rot(self.cos_theta, self.sin_theta)

    @property
    def R_phi(self) -> ImmutableMatrix:
        """``R(φ)``."""
        return _rot(self.cos_phi, self.sin_phi)

    @property
    def D(self) -> ImmutableMatrix:
        """``diag(λ1, λ2)``."""
        return ImmutableMatrix(sympy.diag(self.lambda1, self.lambda2))

    def product(self) -> ImmutableMatrix:
        """``R(θ) R(−φ) D R(φ)``, with radicals brought to normal form."""
        Rm = self.R_phi.T  # R(−φ) = R(φ)ᵀ
        return ImmutableMatrix((self.R_theta * Rm * self.D * self.R_phi).applyfunc(_simplify_radicals))

    def verify(self) -> bool:
        """True when the product is ``A`` entry by entry and both rotations are rotations (``c² + s² = 1``)."""
        ok = all(is_zero(_simplify_radicals(a - b)) for a, b in zip(self.product(), self.A, strict=True))
        ok = ok and is_zero(_simplify_radicals(self.cos_theta**2 + self.sin_theta**2 - 1))
        ok = ok and is_zero(_simplify_radicals(self.cos_phi**2 + self.sin_phi**2 - 1))
        return bool(ok)


def _linear_part(H: Any) -> tuple[Matrix, Matrix]:
    if isinstance(H, Transformation):
        M = Matrix(H.matrix)
    else:
        M = Matrix(exact_matrix(H, square=True, what="an affine map or its 2×2 linear part"))
    if M.shape == (2, 2):
        if is_zero(sympy.expand(M.det())):
            raise SingularTransformationError(f"the linear part {M.tolist()} is singular: no affine map")
        return M, Matrix.zeros(2, 1)
    if M.shape != (3, 3):
        raise DecompositionError(f"A = R(θ) R(−φ) D R(φ) is for affine maps of the plane (3×3 or 2×2), got {M.shape}")
    T = Transformation(M)  # raises for a singular matrix
    if not (is_zero(T.matrix[2, 0]) and is_zero(T.matrix[2, 1])):
        raise DecompositionError(
            f"{M.tolist()} is projective (last row not (0, 0, w)): only an affinity has A = R(θ) R(−φ) D R(φ); "
            "use decompose() for H_S H_A H_P"
        )
    w = M[2, 2]
    return (M[:2, :2] / w).applyfunc(sympy.cancel), (M[:2, 2] / w).applyfunc(sympy.cancel)


def affine_decomposition(H: Any) -> AffineDecomposition:
    """``A = R(θ) R(−φ) D R(φ)``: a rotation by φ, scalings λ1, λ2 along the rotated axes, back by −φ, rotation by θ.

    Hartley & Zisserman §2.4.3, from the singular value decomposition ``A = U D Vᵀ``:
    ``R(θ) = U Vᵀ`` and ``R(φ) = Vᵀ``. The eigenvalues of ``AᵀA = [[p, q], [q, r]]`` are
    ``μ = (p + r)/2 ± √(((p − r)/2)² + q²)``, so ``λ1 = √μ₁`` and ``λ2 = det A / λ1``
    (``λ1 |λ2| = |det A|``, rational for rational A); ``V``'s first column is ``(q, μ₁ − p)``
    normalised (``V = I`` when ``q = 0``) and ``U = A V D⁻¹``. ``H`` is an affine 3×3 matrix (or
    Transformation) or a 2×2 linear part; real numeric entries only.

    >>> d = affine_decomposition([[2, 1, 5], [0, 1, 0], [0, 0, 1]])          # a shear and a stretch
    >>> d.lambda1, d.lambda2, d.t.T, d.verify()          # AᵀA = [[4, 2], [2, 2]]: μ = 3 ± √5
    ((sqrt(2) + sqrt(10))/2, (-sqrt(2) + sqrt(10))/2, Matrix([[5, 0]]), True)
    >>> affine_decomposition([[3, 0], [0, 2]]).D              # axis-aligned: φ = θ = 0
    Matrix([
    [3, 0],
    [0, 2]])
    """
    A, t = _linear_part(H)
    if any(e.free_symbols for e in A):
        raise DecompositionError("A = R(θ) R(−φ) D R(φ) needs numeric entries (square roots of their values appear)")
    try:
        for e in A:
            if not is_zero(sympy.im(e)):
                raise UndecidableError(f"the entry {e} is not real")
        detA = sympy.expand(A.det())
        sign(detA)  # decides that det A is real (and nonzero, A being non-singular)
    except UndecidableError as err:
        raise DecompositionError(f"A = R(θ) R(−φ) D R(φ) needs a real linear part: {err}") from err
    N = (A.T * A).applyfunc(sympy.expand)
    p, q, r = N[0, 0], N[0, 1], N[1, 1]
    if is_zero(q):  # AᵀA is diagonal: the axes are the coordinate axes
        c_phi, s_phi = sympy.Integer(1), sympy.Integer(0)
        lam1 = sympy.sqrt(p)
    else:
        mu1 = _simplify_radicals((p + r) / 2 + sympy.sqrt(sympy.expand(((p - r) / 2) ** 2 + q**2)))
        v = (q, _simplify_radicals(mu1 - p))
        norm = sympy.sqrtdenest(sympy.sqrt(_simplify_radicals(v[0] ** 2 + v[1] ** 2)))
        # V = [v1, v2] = [[c, −s], [s, c]] is R(−φ)... written as R(φ) = Vᵀ: cos φ = c, sin φ = −s
        c_phi, s_phi = _simplify_radicals(v[0] / norm), _simplify_radicals(-v[1] / norm)
        lam1 = sympy.sqrtdenest(sympy.sqrt(mu1))  # √(a + √b) = √c + √d where possible
    lam2 = _simplify_radicals(detA / lam1)
    lam1 = _simplify_radicals(lam1)
    V = Matrix([[c_phi, s_phi], [-s_phi, c_phi]])  # = R(φ)ᵀ = R(−φ)
    U = (A * V * Matrix([[1 / lam1, 0], [0, 1 / lam2]])).applyfunc(_simplify_radicals)
    Rt = (U * V.T).applyfunc(_simplify_radicals)
    return AffineDecomposition(ImmutableMatrix(A), ImmutableMatrix(t), Rt[0, 0], Rt[1, 0], c_phi, s_phi, lam1, lam2)
