"""The catalogue: every claim the book makes, the classical theorems, and deliberate false claims.

Each entry is a function that builds a fresh :class:`~pgsym.proofs.claims.Claim`.
:func:`prove` takes a catalogue name (or a claim) and returns its verdict, so a
chapter can write ``assert prove("pappus").proved`` and the book and the catalogue
cannot drift apart.

>>> len([n for n in catalogue_names() if CATALOGUE[n].expected]) >= 40
True
>>> prove("parallel-lines-meet-at-infinity").proved
True
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

import sympy

from .. import ring as alg
from ..hierarchy import (
    AFFINE_2D,
    AFFINE_3D,
    EUCLIDEAN_2D,
    EUCLIDEAN_3D,
    PROJECTIVE_2D,
    PROJECTIVE_3D,
    SIMILARITY_2D,
    SIMILARITY_3D,
    TransformationClass,
)
from .claims import Claim
from .engine import prove as _prove_claim
from .errors import UnknownClaimError
from .invariance import class_matrix
from .verdicts import Verdict

__all__ = ["CATALOGUE", "Entry", "UnknownClaimError", "catalogue_names", "get_claim", "prove", "prove_all"]



@dataclass(frozen=True)
class Entry:
    """A catalogue entry: its builder, whether the claim is true, the chapter and the title."""

    name: str
    build: Callable[[], Claim]
    expected: bool
    chapter: str
    title: str


CATALOGUE: dict[str, Entry] = {}


def _entry(name: str, title: str, chapter: str, expected: bool = True):  # type: ignore[no-untyped-def]
    def register(fn: Callable[[Claim], None]) -> Callable[[Claim], None]:
        def build() -> Claim:
            c = Claim(name, title, (fn.__doc__ or title).strip(), expected=expected, chapter=chapter)
            fn(c)
            return c

        CATALOGUE[name] = Entry(name, build, expected, chapter, title)
        return fn

    return register


def catalogue_names(expected: bool | None = None) -> list[str]:
    """The names of the catalogue's claims (only true or only false ones if ``expected`` is given).

    >>> "pappus" in catalogue_names(True), "pappus" in catalogue_names(False)
    (True, False)
    """
    return [n for n, e in CATALOGUE.items() if expected is None or e.expected == expected]


def get_claim(name: str) -> Claim:
    """A fresh claim built from the catalogue entry ``name``.

    >>> get_claim("desargues").title
    "Desargues's theorem"
    >>> get_claim("no-such-claim")
    Traceback (most recent call last):
    ...
    pgsym.proofs.errors.UnknownClaimError: no claim named 'no-such-claim' in the catalogue; ...
    """
    if name not in CATALOGUE:
        close = [n for n in CATALOGUE if name.split("-")[0] in n][:5]
        hint = f"did you mean {', '.join(close)}?" if close else "list them with `pgsym prove --list`"
        raise UnknownClaimError(f"no claim named {name!r} in the catalogue; {hint}")
    return CATALOGUE[name].build()


def prove(claim: str | Claim, *, timeout: float | None = 10.0, seed: int = 0) -> Verdict:
    """Prove a catalogue claim (by name) or a :class:`Claim`; see :func:`pgsym.proofs.engine.prove`.

    >>> prove("join-contains-both-points").status
    'proved'
    """
    if isinstance(claim, str):
        claim = get_claim(claim)
    return _prove_claim(claim, timeout=timeout, seed=seed)


def prove_all(names: Iterable[str] | None = None, *, timeout: float | None = 10.0) -> Iterator[Verdict]:
    """Prove the named claims (default: the whole catalogue), one verdict at a time."""
    for name in catalogue_names() if names is None else names:
        yield prove(name, timeout=timeout)


# -- helpers -------------------------------------------------------------------------------

def _ratio_of(r: tuple, s: tuple) -> tuple:
    return (r[0] * s[1], r[1] * s[0])


def _cross_ratio_p2(a: tuple, b: tuple, c: tuple, d: tuple, o: tuple) -> tuple:
    """(A, B; C, D) of four collinear points of P², seen from a point O off their line."""
    return (alg.det([a, c, o]) * alg.det([b, d, o]), alg.det([a, d, o]) * alg.det([b, c, o]))


def _conic_value(c: tuple, x: tuple) -> object:
    return alg.dot(x, alg.matvec(c, x))


def _incident_to_both(c: Claim, free: Callable[[str], object], op: str, name: str, given: str) -> None:
    """Two generic objects, the one ``op`` builds from them, and its incidence with each (join and meet are dual)."""
    objs = [free(n) for n in given]
    new = c.construct(op, name, *objs)
    for obj in objs:
        c.conclude_incident(*((obj, new) if new.kind == "line" else (new, obj)))


def _span(c: Claim, free: Callable[[str], object], a: str, b: str, name: str) -> tuple:
    """Two generic objects and their combination s·a + t·b (parameters s, t first)."""
    s, t = c.params("s t")
    p, q = free(a), free(b)
    return p, q, c.combine(name, p, q, s, t)


# == Part I: points and lines ===================================================================

@_entry("join-contains-both-points", "The join of two points contains both", "points-and-lines")
def _join_contains_both_points(c: Claim) -> None:
    """The line l = A × B passes through A and through B."""
    _incident_to_both(c, c.free_point, "join", "l", "AB")


@_entry("meet-lies-on-both-lines", "The meet of two lines lies on both", "points-and-lines")
def _meet_lies_on_both_lines(c: Claim) -> None:
    """The point x = l × m lies on l and on m."""
    _incident_to_both(c, c.free_line, "meet", "x", "lm")


@_entry("join-is-determinant", "The equation of the join is a determinant", "points-and-lines")
def _join_is_determinant(c: Claim) -> None:
    """For every point X, (A × B)ᵀX = det[X A B]."""
    A, B, X = c.free_point("A"), c.free_point("B"), c.free_point("X")
    l = c.join("l", A, B)
    r = c.formula("r", "scalar", lambda l, x, a, b: alg.dot(l, x) - alg.det([x, a, b]), l, X, A, B,
                  description="lᵀX − det[X A B]")
    c.conclude_zero(r)


@_entry("collinear-iff-determinant", "Collinear points have a zero determinant", "points-and-lines")
def _collinear_iff_determinant(c: Claim) -> None:
    """A point C = sA + tB on the line AB gives det[A B C] = 0."""
    c.conclude_collinear(*_span(c, c.free_point, "A", "B", "C"))


@_entry("concurrent-iff-determinant", "Concurrent lines have a zero determinant", "points-and-lines")
def _concurrent_iff_determinant(c: Claim) -> None:
    """A line n = s l + t m of the pencil of l and m gives det[l m n] = 0."""
    c.conclude_concurrent(*_span(c, c.free_line, "l", "m", "n"))


@_entry("pencil-passes-through-meet", "Every line of a pencil passes through its centre", "points-and-lines")
def _pencil_passes_through_meet(c: Claim) -> None:
    """The lines s l + t m all pass through l × m."""
    l, m, n = _span(c, c.free_line, "l", "m", "n")
    c.conclude_incident(c.meet("x", l, m), n)


@_entry("duality-join-meet", "Duality: join and meet are the same operation", "points-and-lines")
def _duality_join_meet(c: Claim) -> None:
    """The line through A and B has the coordinates of the point where the lines with A's and B's coordinates meet."""
    A, B = c.free_point("A"), c.free_point("B")
    a = c.line("a", *A.data)
    b = c.line("b", *B.data)
    c.conclude_equal(c.join("l", A, B), c.meet("x", a, b))


@_entry("join-ignores-scale", "The join does not depend on the scale of the points", "points-and-lines")
def _join_ignores_scale(c: Claim) -> None:
    """(λA) × B is proportional to A × B for λ ≠ 0."""
    (lam,) = c.params("lam")
    A, B = c.free_point("A"), c.free_point("B")
    A2 = c.combine("A2", A, B, lam, 0)
    c.conclude_proportional(c.join("l2", A2, B), c.join("l", A, B))


# == ideal points ===============================================================================

@_entry("parallel-lines-meet-at-infinity", "Parallel lines meet on the line at infinity", "ideal-points")
def _parallel_lines_meet_at_infinity(c: Claim) -> None:
    """The lines ax + by + p = 0 and ax + by + q = 0 meet in a point with third coordinate 0."""
    a, b, p, q = c.params("a b p q")
    x = c.meet("x", c.line("l", a, b, p), c.line("m", a, b, q))
    c.conclude_incident(x, c.line("l_inf", 0, 0, 1))


@_entry("ideal-point-is-direction", "A line meets the line at infinity in its direction", "ideal-points")
def _ideal_point_is_direction(c: Claim) -> None:
    """l × l∞ is proportional to the direction (b, −a, 0) of l = (a, b, c)."""
    a, b, cc = c.params("a b c")
    l = c.line("l", a, b, cc)
    x = c.meet("x", l, c.line("l_inf", 0, 0, 1))
    c.conclude_proportional(x, c.point("d", b, -a, 0))


@_entry("ideal-points-span-line-at-infinity", "Two ideal points span the line at infinity", "ideal-points")
def _ideal_points_span_line_at_infinity(c: Claim) -> None:
    """The join of (p, q, 0) and (r, s, 0) is proportional to (0, 0, 1)."""
    p, q, r, s = c.params("p q r s")
    l = c.join("l", c.point("U", p, q, 0), c.point("V", r, s, 0))
    c.conclude_proportional(l, c.line("l_inf", 0, 0, 1))


@_entry("parallel-through-a-point", "The line through C and the ideal point of AB is parallel to AB", "ideal-points")
def _parallel_through_a_point(c: Claim) -> None:
    """m = C × (l × l∞) has the same normal direction as l = A × B."""
    A, B, C = c.free_point("A"), c.free_point("B"), c.free_point("C")
    l = c.join("l", A, B)
    D = c.meet("D", l, c.line("l_inf", 0, 0, 1))
    m = c.join("m", C, D)
    r = c.formula("r", "scalar", lambda l, m: l[0] * m[1] - l[1] * m[0], l, m, description="l₁m₂ − l₂m₁")
    c.conclude_zero(r)


# == projective transformations ==================================================================

@_entry("lines-transform-by-inverse-transpose", "Lines transform by H⁻ᵀ", "projective-transformations")
def _lines_transform_by_inverse_transpose(c: Claim) -> None:
    """The join of HA and HB is proportional to adj(H)ᵀ(A × B) = det(H) H⁻ᵀ(A × B)."""
    A, B = c.free_point("A"), c.free_point("B")
    H = c.free_matrix("H", 3)
    l2 = c.join("l2", c.apply("A2", H, A), c.apply("B2", H, B))
    c.conclude_proportional(l2, c.apply_line("m", H, c.join("l", A, B)))


@_entry("homography-preserves-incidence", "A homography preserves incidence", "projective-transformations")
def _homography_preserves_incidence(c: Claim) -> None:
    """If P lies on l then HP lies on H⁻ᵀl."""
    P, Q = c.free_point("P"), c.free_point("Q")
    H = c.free_matrix("H", 3)
    l = c.join("l", P, Q)
    c.conclude_incident(c.apply("P2", H, P), c.apply_line("l2", H, l))


@_entry("homography-preserves-collinearity", "A homography maps collinear points to collinear points",
        "projective-transformations")
def _homography_preserves_collinearity(c: Claim) -> None:
    """det[HA HB HC] = 0 when C = sA + tB."""
    A, B, C = _span(c, c.free_point, "A", "B", "C")
    H = c.free_matrix("H", 3)
    c.conclude_collinear(c.apply("A2", H, A), c.apply("B2", H, B), c.apply("C2", H, C))


@_entry("adjugate-is-scaled-inverse", "H adj(H) = det(H) I", "projective-transformations")
def _adjugate_is_scaled_inverse(c: Claim) -> None:
    """The adjugate is the inverse up to the scale det H, so it can replace H⁻¹ in homogeneous formulas."""
    H = c.free_matrix("H", 3, invertible=False)

    def residual(h: tuple) -> tuple:
        d, prod = alg.det(h), alg.matmul(h, alg.adjugate(h))
        return tuple(tuple(prod[i][j] - (d if i == j else 0 * d) for j in range(3)) for i in range(3))

    c.conclude_zero(c.formula("R", "matrix", residual, H, description="H adj(H) − det(H) I"))


@_entry("conics-transform-by-inverse", "Conics transform by C ↦ H⁻ᵀ C H⁻¹", "projective-transformations")
def _conics_transform_by_inverse(c: Claim) -> None:
    """(HX)ᵀ adj(H)ᵀ C adj(H) (HX) = det(H)² XᵀCX: a point of C maps to a point of the image conic."""
    a, b, cc, d, e, f = c.params("a b c d e f")
    C = c.conic("C", [[a, b, d], [b, cc, e], [d, e, f]])
    X = c.free_point("X")
    H = c.free_matrix("H", 3)
    C2 = c.apply_conic("C2", H, C)
    X2 = c.apply("X2", H, X)
    r = c.formula("r", "scalar", lambda c2, x2, h, c1, x: _conic_value(c2, x2) - alg.det(h) ** 2 * _conic_value(c1, x),
                  C2, X2, H, C, X, description="X2ᵀ C2 X2 − det(H)² XᵀCX")
    c.conclude_zero(r)


# == hierarchy of 2D and 3D transformations: degrees of freedom =======================================

# name, title, chapter, class of the hierarchy, degrees of freedom, parameter names, statement
_DOF_CLAIMS = (
    ("dof-projective-2d", "A 2D homography has 8 degrees of freedom", "hierarchy-2d", PROJECTIVE_2D, 8,
     " ".join(f"h{i}" for i in range(1, 10)),
     "Nine entries up to a common scale: the family of all 3×3 matrices has dimension 8 in P⁸."),
    ("dof-affine-2d", "A 2D affinity has 6 degrees of freedom", "hierarchy-2d", AFFINE_2D, 6, "a b c d tx ty",
     "[[a, b, tx], [c, d, ty], [0, 0, 1]] depends on 6 independent parameters."),
    ("dof-similarity-2d", "A 2D similarity has 4 degrees of freedom", "hierarchy-2d", SIMILARITY_2D, 4, "a b tx ty",
     "[[a, −b, tx], [b, a, ty], [0, 0, 1]] (a = s cos θ, b = s sin θ) depends on 4 independent parameters."),
    ("dof-euclidean-2d", "A 2D Euclidean motion has 3 degrees of freedom", "hierarchy-2d", EUCLIDEAN_2D, 3, "t tx ty",
     "A rotation by the rational parametrisation cos θ = (1 − t²)/(1 + t²), sin θ = 2t/(1 + t²), and a translation."),
    ("dof-projective-3d", "A 3D homography has 15 degrees of freedom", "hierarchy-3d", PROJECTIVE_3D, 15,
     " ".join(f"h{i}" for i in range(1, 17)), "Sixteen entries up to a common scale."),
    ("dof-affine-3d", "A 3D affinity has 12 degrees of freedom", "hierarchy-3d", AFFINE_3D, 12,
     " ".join(f"a{i}" for i in range(1, 13)), "A 3×4 top block and the row (0, 0, 0, 1)."),
    ("dof-similarity-3d", "A 3D similarity has 7 degrees of freedom", "hierarchy-3d", SIMILARITY_3D, 7,
     "k a b c t1 t2 t3", "Scale k, a rotation by the Cayley transform of (a, b, c), and a translation."),
    ("dof-euclidean-3d", "A 3D Euclidean motion has 6 degrees of freedom", "hierarchy-3d", EUCLIDEAN_3D, 6,
     "a b c t1 t2 t3", "A rotation by the Cayley transform of (a, b, c) and a translation."),
)


def _dof_claim(group: TransformationClass, dof: int, names: str, statement: str) -> Callable[[Claim], None]:
    """The builder of one DoF claim: the hierarchy's generic element of ``group`` has ``dof`` degrees of freedom."""

    def build(c: Claim) -> None:
        entries, params = class_matrix(c, group, names)
        c.conclude_dof("H", entries, params, dof)

    # named after the class (e.g. _dof_similarity3) in tracebacks and profiles, like the other builders
    name = f"_dof_{group.key}"
    build.__code__ = build.__code__.replace(co_name=name, co_qualname=name)
    build.__doc__, build.__name__, build.__qualname__ = statement, name, name
    return build


for _name, _title, _chapter, _group, _dof, _names, _statement in _DOF_CLAIMS:
    _entry(_name, _title, _chapter)(_dof_claim(_group, _dof, _names, _statement))


# == invariants =================================================================================
# the transformations are the hierarchy's generic elements, so each group has one parametrisation

def _affine(c: Claim) -> object:
    return c.matrix("T", class_matrix(c, AFFINE_2D, "a b c d tx ty")[0], invertible=True)


def _similarity(c: Claim) -> object:
    return c.matrix("S", class_matrix(c, SIMILARITY_2D, "a b tx ty")[0], invertible=True)


def _euclidean(c: Claim) -> object:
    return c.matrix("E", class_matrix(c, EUCLIDEAN_2D, "t tx ty")[0], invertible=True)


@_entry("affine-fixes-line-at-infinity", "An affinity maps the line at infinity to itself", "hierarchy-2d")
def _affine_fixes_line_at_infinity(c: Claim) -> None:
    """adj(T)ᵀ (0, 0, 1) is proportional to (0, 0, 1)."""
    T = _affine(c)
    linf = c.line("l_inf", 0, 0, 1)
    c.conclude_proportional(c.apply_line("m", T, linf), linf)


@_entry("affine-preserves-parallelism", "An affinity maps parallel lines to parallel lines", "hierarchy-2d")
def _affine_preserves_parallelism(c: Claim) -> None:
    """The images of ax + by + p = 0 and ax + by + q = 0 still meet on the line at infinity."""
    T = _affine(c)
    a, b, p, q = c.params("la lb p q")
    l2 = c.apply_line("l2", T, c.line("l", a, b, p))
    m2 = c.apply_line("m2", T, c.line("m", a, b, q))
    c.conclude_incident(c.meet("x", l2, m2), c.line("l_inf", 0, 0, 1))


@_entry("similarity-fixes-circular-points", "A similarity fixes the circular points", "hierarchy-2d")
def _similarity_fixes_circular_points(c: Claim) -> None:
    """S (1, i, 0) is proportional to (1, i, 0); i is a parameter with the hypothesis i² + 1 = 0."""
    S = _similarity(c)
    (i,) = c.params("i")
    c.assume_zero(i**2 + 1, "i² + 1 = 0")
    I = c.point("I", 1, i, 0)
    c.conclude_proportional(c.apply("I2", S, I), I)


@_entry("euclidean-preserves-distance", "A Euclidean motion preserves distances", "hierarchy-2d")
def _euclidean_preserves_distance(c: Claim) -> None:
    """|EA − EB|² = |A − B|² for the rational rotation and a translation."""
    E = _euclidean(c)
    A, B = c.free_point("A"), c.free_point("B")
    A2, B2 = c.apply("A2", E, A), c.apply("B2", E, B)
    dist2 = alg.squared_distance_fraction
    c.conclude_equal_ratio(c.formula("d2", "ratio", dist2, A2, B2, description="|A2 B2|²"),
                           c.formula("d", "ratio", dist2, A, B, description="|A B|²"))


@_entry("similarity-preserves-length-ratio", "A similarity preserves ratios of lengths", "hierarchy-2d")
def _similarity_preserves_length_ratio(c: Claim) -> None:
    """|SA SB|² / |SA SC|² = |AB|² / |AC|²."""
    S = _similarity(c)
    A, B, C = c.free_point("A"), c.free_point("B"), c.free_point("C")
    A2, B2, C2 = c.apply("A2", S, A), c.apply("B2", S, B), c.apply("C2", S, C)
    dist2 = alg.squared_distance_fraction
    ratio = lambda a, b, cc: _ratio_of(dist2(a, b), dist2(a, cc))  # noqa: E731
    c.conclude_equal_ratio(c.formula("r2", "ratio", ratio, A2, B2, C2, description="|A2B2|²/|A2C2|²"),
                           c.formula("r", "ratio", ratio, A, B, C, description="|AB|²/|AC|²"))


@_entry("affine-preserves-area-ratio", "An affinity preserves ratios of areas", "hierarchy-2d")
def _affine_preserves_area_ratio(c: Claim) -> None:
    """area(T A, T B, T C) / area(T A, T B, T D) = area(A, B, C) / area(A, B, D)."""
    T = _affine(c)
    A, B, C, D = (c.free_point(n) for n in "ABCD")
    imgs = [c.apply(f"{n}2", T, P) for n, P in zip("ABCD", (A, B, C, D), strict=True)]
    ratio = lambda a, b, cc, d: (alg.det([a, b, cc]) * d[2], alg.det([a, b, d]) * cc[2])  # noqa: E731
    c.conclude_equal_ratio(c.formula("r2", "ratio", ratio, *imgs, description="area ratio after T"),
                           c.formula("r", "ratio", ratio, A, B, C, D, description="area ratio before"))


@_entry("homography-preserves-cross-ratio", "A homography preserves the cross-ratio of collinear points",
        "projective-transformations")
def _homography_preserves_cross_ratio(c: Claim) -> None:
    """(A, B; C, D) of four collinear points, seen from O, equals that of their images seen from another point O2."""
    s, t = c.params("s t")
    A, B, O, O2 = c.free_point("A"), c.free_point("B"), c.free_point("O"), c.free_point("O2")
    C, D = c.combine("C", A, B, 1, s), c.combine("D", A, B, 1, t)
    H = c.free_matrix("H", 3)
    imgs = [c.apply(f"{n}2", H, P) for n, P in zip("ABCD", (A, B, C, D), strict=True)]
    c.conclude_equal_ratio(c.formula("cr2", "ratio", _cross_ratio_p2, *imgs, O2, description="(HA, HB; HC, HD)"),
                           c.formula("cr", "ratio", _cross_ratio_p2, A, B, C, D, O, description="(A, B; C, D)"))


# == the projective line =========================================================================

def _four(c: Claim) -> tuple:
    return tuple(c.free_point1(n) for n in "ABCD")


@_entry("cross-ratio-invariance", "The cross-ratio is invariant under projective maps of the line", "projective-line")
def _cross_ratio_invariance(c: Claim) -> None:
    """(MA, MB; MC, MD) = (A, B; C, D) for every invertible 2×2 matrix M."""
    A, B, C, D = _four(c)
    M = c.free_matrix("M", 2)
    imgs = [c.apply(f"{n}2", M, P) for n, P in zip("ABCD", (A, B, C, D), strict=True)]
    c.conclude_equal_ratio(c.cross_ratio("cr2", *imgs), c.cross_ratio("cr", A, B, C, D))


@_entry("cross-ratio-symmetries", "The cross-ratio is unchanged by swapping both pairs", "projective-line")
def _cross_ratio_symmetries(c: Claim) -> None:
    """(A, B; C, D) = (B, A; D, C) = (C, D; A, B)."""
    A, B, C, D = _four(c)
    cr = c.cross_ratio("cr", A, B, C, D)
    c.conclude_equal_ratio(cr, c.cross_ratio("cr_BADC", B, A, D, C))
    c.conclude_equal_ratio(cr, c.cross_ratio("cr_CDAB", C, D, A, B))


@_entry("cross-ratio-reciprocal", "Swapping C and D inverts the cross-ratio", "projective-line")
def _cross_ratio_reciprocal(c: Claim) -> None:
    """(A, B; C, D) · (A, B; D, C) = 1."""
    A, B, C, D = _four(c)
    r, s = c.cross_ratio("r", A, B, C, D), c.cross_ratio("s", A, B, D, C)
    prod = c.formula("rs", "ratio", lambda r, s: (r[0] * s[0], r[1] * s[1]), r, s, description="r·s")
    c.conclude_equal_ratio(prod, 1)


@_entry("cross-ratio-complement", "Swapping B and C complements the cross-ratio", "projective-line")
def _cross_ratio_complement(c: Claim) -> None:
    """(A, B; C, D) + (A, C; B, D) = 1."""
    A, B, C, D = _four(c)
    r, s = c.cross_ratio("r", A, B, C, D), c.cross_ratio("s", A, C, B, D)
    total = c.formula("r_plus_s", "ratio", lambda r, s: (r[0] * s[1] + s[0] * r[1], r[1] * s[1]), r, s,
                      description="r + s")
    c.conclude_equal_ratio(total, 1)


@_entry("harmonic-conjugate-is-harmonic", "The harmonic conjugate gives the cross-ratio −1", "projective-line")
def _harmonic_conjugate_is_harmonic(c: Claim) -> None:
    """D = [A C] B + [B C] A satisfies (A, B; C, D) = −1."""
    A, B, C = (c.free_point1(n) for n in "ABC")
    D = c.harmonic_conjugate("D", A, B, C)
    c.conclude_equal_ratio(c.cross_ratio("cr", A, B, C, D), -1)


@_entry("harmonic-conjugate-involution", "Taking the harmonic conjugate twice gives the point back",
        "projective-line")
def _harmonic_conjugate_involution(c: Claim) -> None:
    """The harmonic conjugate of D = h(A, B; C) is C again."""
    A, B, C = (c.free_point1(n) for n in "ABC")
    D = c.harmonic_conjugate("D", A, B, C)
    c.conclude_proportional(c.harmonic_conjugate("C2", A, B, D), C)


# == conics =====================================================================================

def _generic_conic(c: Claim) -> object:
    a, b, cc, d, e, f = c.params("a b c d e f")
    return c.conic("C", [[a, b, d], [b, cc, e], [d, e, f]])


@_entry("conic-through-five-points", "The conic through five points contains them", "conics")
def _conic_through_five_points(c: Claim) -> None:
    """The signed 5×5 minors of the 5×6 system give a conic through all five points."""
    pts = [c.free_point(f"P{i}") for i in range(1, 6)]
    C = c.conic_through("C", *pts)
    for i, P in enumerate(pts, start=1):
        c.conclude_zero(c.formula(f"v{i}", "scalar", _conic_value, C, P, description=f"P{i}ᵀ C P{i}"))


@_entry("tangent-touches-conic", "The polar of a point on a conic is tangent there", "conics")
def _tangent_touches_conic(c: Claim) -> None:
    """If PᵀCP = 0 then l = CP passes through P and lᵀ adj(C) l = 0 (l is a tangent line)."""
    C = _generic_conic(c)
    x, y = c.params("x y")
    P = c.point("P", x, y)
    v = sympy.Matrix([x, y, 1])
    c.assume_zero(sympy.expand((v.T * sympy.Matrix(C.data) * v)[0]), "P lies on C")
    l = c.polar("l", C, P)
    c.conclude_incident(P, l)
    c.conclude_zero(c.formula("t", "scalar", lambda l, cc: alg.dot(l, alg.matvec(alg.adjugate(cc), l)), l, C,
                              description="lᵀ adj(C) l"))


@_entry("pole-polar-reciprocity", "La Hire: Q on the polar of P iff P on the polar of Q", "conics")
def _pole_polar_reciprocity(c: Claim) -> None:
    """For Q on the polar of P (Q = polar(P) × m), P lies on the polar of Q."""
    C = _generic_conic(c)
    P, m = c.free_point("P"), c.free_line("m")
    Q = c.meet("Q", c.polar("p", C, P), m)
    c.conclude_incident(P, c.polar("q", C, Q))


@_entry("circle-contains-circular-points", "Every circle passes through the circular points", "conics")
def _circle_contains_circular_points(c: Claim) -> None:
    """(x − a)² + (y − b)² = r² contains (1, ±i, 0), with the hypothesis i² + 1 = 0."""
    a, b, r, i = c.params("a b r i")
    c.assume_zero(i**2 + 1, "i² + 1 = 0")
    C = c.conic("C", [[1, 0, -a], [0, 1, -b], [-a, -b, a**2 + b**2 - r**2]])
    for name, sign in (("I", 1), ("J", -1)):
        P = c.point(name, 1, sign * i, 0)
        c.conclude_zero(c.formula(f"v{name}", "scalar", _conic_value, C, P, description=f"{name}ᵀ C {name}"))


@_entry("dual-conic-is-adjugate", "C adj(C) = det(C) I: the dual conic is C⁻¹ up to scale", "conics")
def _dual_conic_is_adjugate(c: Claim) -> None:
    """For a symmetric C, the adjugate is the inverse up to the scale det C."""
    C = _generic_conic(c)
    D = c.dual_conic("D", C)

    def residual(cc: tuple, d: tuple) -> tuple:
        det, prod = alg.det(cc), alg.matmul(cc, d)
        return tuple(tuple(prod[i][j] - (det if i == j else 0 * det) for j in range(3)) for i in range(3))

    c.conclude_zero(c.formula("R", "matrix", residual, C, D, description="C adj(C) − det(C) I"))


# == points and planes ============================================================================

@_entry("plane-through-three-points", "The plane through three points contains them", "points-and-planes")
def _plane_through_three_points(c: Claim) -> None:
    """π = the signed 3×3 minors of [A; B; C] satisfies πᵀA = πᵀB = πᵀC = 0."""
    A, B, C = (c.free_point3(n) for n in "ABC")
    pi = c.plane_through("pi", A, B, C)
    for P in (A, B, C):
        c.conclude_incident(P, pi)


@_entry("point-on-three-planes", "The point common to three planes lies on each", "points-and-planes")
def _point_on_three_planes(c: Claim) -> None:
    """X = the signed 3×3 minors of [π₁; π₂; π₃] satisfies πᵢᵀX = 0."""
    ps = [c.free_plane(f"p{i}") for i in (1, 2, 3)]
    X = c.point_on_planes("X", *ps)
    for p in ps:
        c.conclude_incident(X, p)


@_entry("plane-equation-determinant", "The equation of a plane through three points is a determinant",
        "points-and-planes")
def _plane_equation_determinant(c: Claim) -> None:
    """πᵀX = det[X A B C] for every point X."""
    A, B, C, X = (c.free_point3(n) for n in "ABCX")
    pi = c.plane_through("pi", A, B, C)
    c.conclude_zero(c.formula("r", "scalar", lambda p, x, a, b, cc: alg.dot(p, x) - alg.det([x, a, b, cc]),
                              pi, X, A, B, C, description="πᵀX − det[X A B C]"))


@_entry("coplanar-iff-determinant", "Four coplanar points have a zero determinant", "points-and-planes")
def _coplanar_iff_determinant(c: Claim) -> None:
    """D = A + sB + tC gives det[A B C D] = 0."""
    s, t = c.params("s t")
    A, B, C = (c.free_point3(n) for n in "ABC")
    E = c.combine("E", A, B, 1, s)
    D = c.combine("D", E, C, 1, t)
    c.conclude_coplanar(A, B, C, D)


@_entry("parallel-planes-meet-at-infinity", "Parallel planes meet on the plane at infinity", "points-and-planes")
def _parallel_planes_meet_at_infinity(c: Claim) -> None:
    """ax + by + cz + p = 0 and ax + by + cz + q = 0 meet any third plane in an ideal point."""
    a, b, cc, p, q = c.params("a b c p q")
    g = c.free_plane("g")
    X = c.point_on_planes("X", c.plane("P1", a, b, cc, p), c.plane("P2", a, b, cc, q), g)
    c.conclude_incident(X, c.plane("pi_inf", 0, 0, 0, 1))


@_entry("planes-transform-by-inverse-transpose", "Planes transform by H⁻ᵀ", "points-and-planes")
def _planes_transform_by_inverse_transpose(c: Claim) -> None:
    """The plane through HA, HB, HC is proportional to adj(H)ᵀ π for π through A, B, C."""
    A, B, C = (c.free_point3(n) for n in "ABC")
    H = c.free_matrix("H", 4)
    imgs = [c.apply(f"{n}2", H, P) for n, P in zip("ABC", (A, B, C), strict=True)]
    c.conclude_proportional(c.plane_through("pi2", *imgs), c.apply_plane("m", H, c.plane_through("pi", A, B, C)))


# == null space and SVD =============================================================================

@_entry("collinear-points-rank-two", "Three collinear points of P² stack to a rank-2 matrix",
        "null-space-and-svd")
def _collinear_points_rank_two(c: Claim) -> None:
    """[A; B; sA + tB] has rank exactly 2, so its null space is the line through them."""
    A, B, C = _span(c, c.free_point, "A", "B", "C")
    c.conclude_rank(c.formula("M", "matrix", lambda *rows: tuple(rows), A, B, C, description="[A; B; C]"), 2)


@_entry("coplanar-points-rank-three", "Four coplanar points of P³ stack to a rank-3 matrix", "null-space-and-svd")
def _coplanar_points_rank_three(c: Claim) -> None:
    """[A; B; C; D] with D in the plane ABC has rank 3: the plane is its one-dimensional null space."""
    s, t = c.params("s t")
    A, B, C = (c.free_point3(n) for n in "ABC")
    D = c.combine("D", c.combine("E", A, B, 1, s), C, 1, t)
    c.conclude_rank(c.formula("M", "matrix", lambda *rows: tuple(rows), A, B, C, D, description="[A; B; C; D]"), 3)


# == lines in 3D ================================================================================

def _klein(L: tuple) -> object:
    return L[0][1] * L[2][3] - L[0][2] * L[1][3] + L[0][3] * L[1][2]


def _reciprocal(L: tuple, M: tuple) -> object:
    return (L[0][1] * M[2][3] + L[2][3] * M[0][1] + L[0][2] * M[3][1] + L[3][1] * M[0][2]
            + L[0][3] * M[1][2] + L[1][2] * M[0][3])


@_entry("plucker-matrix-rank-two", "A Plücker matrix has rank 2", "lines-in-3d")
def _plucker_matrix_rank_two(c: Claim) -> None:
    """L = ABᵀ − BAᵀ: all 3×3 minors vanish and a 2×2 minor does not."""
    A, B = c.free_point3("A"), c.free_point3("B")
    c.conclude_rank(c.line3("L", A, B), 2)


@_entry("klein-quadric", "Plücker coordinates satisfy the Klein relation", "lines-in-3d")
def _klein_quadric(c: Claim) -> None:
    """l12 l34 − l13 l24 + l14 l23 = 0 for L = ABᵀ − BAᵀ."""
    A, B = c.free_point3("A"), c.free_point3("B")
    L = c.line3("L", A, B)
    c.conclude_zero(c.formula("k", "scalar", _klein, L, description="l12 l34 − l13 l24 + l14 l23"))


@_entry("plucker-meets-plane", "L π is the point where the line L meets the plane π", "lines-in-3d")
def _plucker_meets_plane(c: Claim) -> None:
    """X = Lπ lies on π and on the line AB (rank [A; B; X] = 2)."""
    A, B = c.free_point3("A"), c.free_point3("B")
    L = c.line3("L", A, B)
    pi = c.free_plane("pi")
    X = c.formula("X", "point3", alg.matvec, L, pi, description="L π")
    c.conclude_incident(X, pi)
    c.conclude_rank(c.formula("M", "matrix", lambda *r: tuple(r), A, B, X, description="[A; B; X]"), 2)


@_entry("dual-plucker-annihilates", "L L* = 0 for the two Plücker matrices of one line", "lines-in-3d")
def _dual_plucker_annihilates(c: Claim) -> None:
    """With π, ρ two planes through A and B, L* = πρᵀ − ρπᵀ satisfies L L* = 0."""
    A, B, C, D = (c.free_point3(n) for n in "ABCD")
    L = c.line3("L", A, B)
    P, Q = c.plane_through("pi", A, B, C), c.plane_through("rho", A, B, D)
    Ld = c.formula("Ld", "matrix", alg.wedge, P, Q, description="π ρᵀ − ρ πᵀ")
    c.conclude_zero(c.formula("R", "matrix", alg.matmul, L, Ld, description="L L*"))


@_entry("reciprocal-product-is-determinant", "The reciprocal product of two lines is det[A B C D]", "lines-in-3d")
def _reciprocal_product_is_determinant(c: Claim) -> None:
    """(AB | CD) = det[A B C D], so two lines are coplanar exactly when it vanishes."""
    A, B, C, D = (c.free_point3(n) for n in "ABCD")
    L, M = c.line3("L", A, B), c.line3("M", C, D)
    c.conclude_zero(c.formula("r", "scalar", lambda l, m, *p: _reciprocal(l, m) - alg.det(list(p)),
                              L, M, A, B, C, D, description="(L|M) − det[A B C D]"))


@_entry("lines-in-a-plane-meet", "Two lines in one plane have reciprocal product 0", "lines-in-3d")
def _lines_in_a_plane_meet(c: Claim) -> None:
    """For D in the plane ABC, the lines AB and CD are coplanar: (AB | CD) = 0."""
    s, t = c.params("s t")
    A, B, C = (c.free_point3(n) for n in "ABC")
    D = c.combine("D", c.combine("E", A, B, 1, s), C, 1, t)
    c.conclude_zero(c.formula("r", "scalar", _reciprocal, c.line3("L", A, B), c.line3("M", C, D),
                              description="(L|M)"))


# == classical theorems ============================================================================

@_entry("pappus", "Pappus's hexagon theorem", "classical-theorems")
def _pappus(c: Claim) -> None:
    """A, B, C on one line and A', B', C' on another: AB'∧A'B, AC'∧A'C, BC'∧B'C are collinear."""
    c.method_note = ("the two lines are y = 0 and the line through the origin with direction (p, q): every pair "
                     "of lines is mapped there by a projective transformation, which preserves incidence")
    a, b, cc, a2, b2, c2, p, q = c.params("a b c a2 b2 c2 p q")
    A, B, C = (c.point(n, t, 0) for n, t in (("A", a), ("B", b), ("C", cc)))
    A2, B2, C2 = (c.point(n, t * p, t * q) for n, t in (("A'", a2), ("B'", b2), ("C'", c2)))
    _collinear_meets(c, ((A, B2), (A2, B)), ((A, C2), (A2, C)), ((B, C2), (B2, C)))


def _collinear_meets(c: Claim, *pairs: tuple) -> None:
    """X, Y, Z = the meets of three pairs of joins ((P, Q), (R, S)) ↦ PQ ∧ RS, concluded collinear."""
    joins = (tuple(c.join(p.name + q.name, p, q) for p, q in pair) for pair in pairs)
    c.conclude_collinear(*(c.meet(name, *lines) for name, lines in zip("XYZ", joins, strict=True)))


def _desargues_triangles(c: Claim) -> tuple:
    a, b, cc = c.params("a b c")
    O, A, B, C = (c.free_point(n) for n in "OABC")
    A2, B2, C2 = (c.combine(n, P, O, 1, t) for n, P, t in (("A'", A, a), ("B'", B, b), ("C'", C, cc)))
    return A, B, C, A2, B2, C2


@_entry("desargues", "Desargues's theorem", "classical-theorems")
def _desargues(c: Claim) -> None:
    """Triangles ABC and A'B'C' in perspective from a point O are in perspective from a line."""
    A, B, C, A2, B2, C2 = _desargues_triangles(c)
    _collinear_meets(c, ((A, B), (A2, B2)), ((B, C), (B2, C2)), ((C, A), (C2, A2)))


@_entry("desargues-converse", "The converse of Desargues's theorem", "classical-theorems")
def _desargues_converse(c: Claim) -> None:
    """If corresponding sides of ABC and A'B'C' meet on one line, then AA', BB', CC' are concurrent."""
    x, y, s = c.params("x y s")
    A, B, C = (c.free_point(n) for n in "ABC")
    X = c.combine("X", B, C, 1, x)
    Y = c.combine("Y", C, A, 1, y)
    Z = c.meet("Z", c.join("axis", X, Y), c.join("AB", A, B))
    A2 = c.free_point("A'")
    B2 = c.combine("B'", A2, Z, 1, s)
    C2 = c.meet("C'", c.join("A'Y", A2, Y), c.join("B'X", B2, X))
    c.conclude_concurrent(c.join("AA'", A, A2), c.join("BB'", B, B2), c.join("CC'", C, C2))


def _on_parabola(c: Claim, names: str) -> list:
    return [c.point(n, t, t**2, 1) for n, t in zip(names, c.params(" ".join(n.lower() for n in names)), strict=True)]


@_entry("pascal", "Pascal's theorem", "classical-theorems")
def _pascal(c: Claim) -> None:
    """For six points of a conic, the meets of opposite sides of the hexagon ABCDEF are collinear."""
    c.method_note = "the six points are (t, t², 1) on the conic y = x², projectively equivalent to every "\
        "non-degenerate conic"
    A, B, C, D, E, F = _on_parabola(c, "ABCDEF")
    _collinear_meets(c, ((A, B), (D, E)), ((B, C), (E, F)), ((C, D), (F, A)))


@_entry("brianchon", "Brianchon's theorem", "classical-theorems")
def _brianchon(c: Claim) -> None:
    """For six tangents of a conic, the diagonals joining opposite vertices of the hexagon are concurrent."""
    c.method_note = "the tangents of y = x² at t are (2t, −1, −t²)"
    ts = c.params("a b c d e f")
    lines = [c.line(n, 2 * t, -1, -(t**2)) for n, t in zip(("la", "lb", "lc", "ld", "le", "lf"), ts, strict=True)]
    V = [c.meet(f"V{i + 1}", lines[i], lines[(i + 1) % 6]) for i in range(6)]
    c.conclude_concurrent(c.join("d1", V[0], V[3]), c.join("d2", V[1], V[4]), c.join("d3", V[2], V[5]))


@_entry("complete-quadrilateral-harmonic", "The harmonic property of the complete quadrangle", "classical-theorems")
def _complete_quadrilateral_harmonic(c: Claim) -> None:
    """For four points A, B, C, D with diagonal points E = AB∧CD, F = AD∧BC, G = AC∧BD and H = AC∧EF,
    (A, C; G, H) = −1."""
    A, B, C, D = (c.free_point(n) for n in "ABCD")
    E = c.meet("E", c.join("AB", A, B), c.join("CD", C, D))
    F = c.meet("F", c.join("AD", A, D), c.join("BC", B, C))
    AC = c.join("AC", A, C)
    G = c.meet("G", AC, c.join("BD", B, D))
    H = c.meet("H", AC, c.join("EF", E, F))
    O = c.free_point("O")
    cr = c.formula("cr", "ratio", _cross_ratio_p2, A, C, G, H, O, description="(A, C; G, H) seen from O")
    c.conclude_equal_ratio(cr, -1)


# == deliberately false claims ======================================================================

@_entry("lines-transform-like-points", "FALSE: lines transform by H like points", "projective-transformations",
        expected=False)
def _lines_transform_like_points(c: Claim) -> None:
    """Claims (HA) × (HB) ∝ H (A × B); the correct rule is H⁻ᵀ."""
    A, B = c.free_point("A"), c.free_point("B")
    H = c.free_matrix("H", 3)
    l2 = c.join("l2", c.apply("A2", H, A), c.apply("B2", H, B))
    l = c.join("l", A, B)
    c.conclude_proportional(l2, c.formula("Hl", "line", alg.matvec, H, l, description="H l"))


@_entry("cross-product-sign-flipped", "FALSE: a cross product with the middle sign flipped", "points-and-lines",
        expected=False)
def _cross_product_sign_flipped(c: Claim) -> None:
    """Claims that (a₂b₃ − a₃b₂, a₁b₃ − a₃b₁, a₁b₂ − a₂b₁) passes through A."""
    A, B = c.free_point("A"), c.free_point("B")
    wrong = lambda u, v: (u[1] * v[2] - u[2] * v[1], u[0] * v[2] - u[2] * v[0], u[0] * v[1] - u[1] * v[0])  # noqa: E731
    c.conclude_incident(A, c.formula("l", "line", wrong, A, B, description="A × B with a sign flipped"))


@_entry("cross-ratio-under-squaring", "FALSE: a reordered cross-ratio is invariant under x ↦ x²", "projective-line",
        expected=False)
def _cross_ratio_under_squaring(c: Claim) -> None:
    """Claims (A, B; C, D) = (A², B²; D², C²): wrong order, and squaring is not projective."""
    A, B, C, D = _four(c)
    sq = lambda p: (p[0] * p[0], p[1] * p[1])  # noqa: E731
    imgs = [c.formula(f"{n}2", "point1", sq, P, description=f"{n}²") for n, P in zip("ABCD", (A, B, C, D), strict=True)]
    c.conclude_equal_ratio(c.cross_ratio("cr", A, B, C, D), c.cross_ratio("cr2", imgs[0], imgs[1], imgs[3], imgs[2]))


@_entry("cross-ratio-order-irrelevant", "FALSE: the order of the four points does not matter", "projective-line",
        expected=False)
def _cross_ratio_order_irrelevant(c: Claim) -> None:
    """Claims (A, B; C, D) = (A, C; B, D)."""
    A, B, C, D = _four(c)
    c.conclude_equal_ratio(c.cross_ratio("r", A, B, C, D), c.cross_ratio("s", A, C, B, D))


@_entry("homography-preserves-parallelism", "FALSE: a homography keeps parallel lines parallel", "hierarchy-2d",
        expected=False)
def _homography_preserves_parallelism(c: Claim) -> None:
    """Claims that the images of two parallel lines under a general H meet on the line at infinity."""
    H = c.free_matrix("H", 3)
    a, b, p, q = c.params("la lb p q")
    l2 = c.apply_line("l2", H, c.line("l", a, b, p))
    m2 = c.apply_line("m2", H, c.line("m", a, b, q))
    c.conclude_incident(c.meet("x", l2, m2), c.line("l_inf", 0, 0, 1))


@_entry("affine-preserves-distance", "FALSE: an affinity preserves distances", "hierarchy-2d", expected=False)
def _affine_preserves_distance(c: Claim) -> None:
    """Claims |TA TB|² = |AB|² for an affinity T."""
    T = _affine(c)
    A, B = c.free_point("A"), c.free_point("B")
    dist2 = alg.squared_distance_fraction
    c.conclude_equal_ratio(c.formula("d2", "ratio", dist2, c.apply("A2", T, A), c.apply("B2", T, B)),
                           c.formula("d", "ratio", dist2, A, B))


@_entry("pascal-without-conic", "FALSE: Pascal's line for any six points", "classical-theorems", expected=False)
def _pascal_without_conic(c: Claim) -> None:
    """Claims Pascal's collinearity for six free points, not on one conic."""
    A, B, C, D, E, F = (c.free_point(n) for n in "ABCDEF")
    _collinear_meets(c, ((A, B), (D, E)), ((B, C), (E, F)), ((C, D), (F, A)))


@_entry("klein-relation-sign-flipped", "FALSE: the Klein relation with a sign flipped", "lines-in-3d", expected=False)
def _klein_relation_sign_flipped(c: Claim) -> None:
    """Claims l12 l34 + l13 l24 + l14 l23 = 0."""
    A, B = c.free_point3("A"), c.free_point3("B")
    L = c.line3("L", A, B)
    c.conclude_zero(c.formula("k", "scalar", lambda L: L[0][1] * L[2][3] + L[0][2] * L[1][3] + L[0][3] * L[1][2], L,
                              description="l12 l34 + l13 l24 + l14 l23"))
