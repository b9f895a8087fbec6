"""Order conditions of a claim: which side of a line, between two points, on a ray, inside a triangle.

An olympiad statement fixes which of two intersection points (or which bisector) it means by an order
condition: "the second intersection on the arc not containing A", "on the same side of BC as A", "inside
the triangle". Each condition here is a strict inequality ``p > 0`` of polynomials of the coordinates,
right for any homogeneous representatives (the factors ``w`` make the sign that of the affine quantity):

=================  ==========================================================================================
``sameside``       P Q A B: P and Q strictly on the same side of the line AB
                   (``area(A, B, P)·area(A, B, Q) > 0``)
``oppositeside``   P Q A B: P and Q strictly on opposite sides of the line AB; for P on the circle through
                   Q, A, B: P on the arc AB not containing Q
``between``        X A B: ``(X − A)·(B − X) > 0``; for X on the line AB: X strictly between A and B
``onray``          X V P: ``(X − V)·(P − V) > 0``; for X on the line VP: X on the ray from V through P, X ≠ V
``inside``         X A B C: X strictly inside the triangle ABC (on A's side of BC, B's of CA, C's of AB)
=================  ==========================================================================================

The conditions are kept by every similarity (reflections too) and by nothing larger in general (an affine map
keeps sides, but not the sign of a dot product of vectors that are not parallel). They only select among the
real figures: :func:`pgsym.proofs.engine.prove` proves a claim with order conditions on the branch (or the
region) they select (:func:`pgsym.proofs.algebraic.prove_ordered`).

>>> from pgsym.proofs.claims import Claim
>>> c = Claim("x", "x")
>>> A, B, X = (c.free_point(n) for n in "ABX")
>>> c.where_between(X, A, B).text
'X between A and B'
>>> [w.text for w in c.order_conditions]
['X between A and B']
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from .. import ring as alg
from ..errors import ObjectTypeError
from .operations import affine_vector

if TYPE_CHECKING:
    from .claims import Claim, Node

__all__ = ["CONDITIONS", "MAX_ORDER_CONDITIONS", "OrderCondition", "OrderConditions", "condition_values"]

MAX_ORDER_CONDITIONS = 16
"""The most order conditions one claim may have (each is decided on every branch of every instance)."""

CONDITIONS: dict[str, int] = {"sameside": 4, "oppositeside": 4, "between": 3, "onray": 3, "inside": 4}
"""Each order condition of the statement language and its number of points."""


def _area(a: Sequence[Any], b: Sequence[Any], p: Sequence[Any]) -> Any:
    """det(A, B, P)·w_A w_B w_P: the sign of the signed area of the triangle ABP, for any representatives."""
    return alg.dot(alg.cross(a, b), p) * a[2] * b[2] * p[2]


def _same(p: Any, q: Any, a: Any, b: Any) -> Any:
    return _area(a, b, p) * _area(a, b, q)


_VALUES: dict[str, Callable[..., list[Any]]] = {
    "sameside": lambda p, q, a, b: [_same(p, q, a, b)],
    "oppositeside": lambda p, q, a, b: [-_same(p, q, a, b)],
    # w_A w_X (X − A) · w_X w_B (B − X) has the sign of (X − A)·(B − X) times w_A w_B
    "between": lambda x, a, b: [alg.dot(affine_vector(a, x), affine_vector(x, b)) * a[2] * b[2]],
    "onray": lambda x, v, p: [alg.dot(affine_vector(v, x), affine_vector(v, p)) * x[2] * p[2]],
    "inside": lambda x, a, b, c: [_same(x, a, b, c), _same(x, b, c, a), _same(x, c, a, b)],
}

_WORDS: dict[str, Callable[..., str]] = {
    "sameside": lambda p, q, a, b: f"{p} and {q} on the same side of the line {a}{b}",
    "oppositeside": lambda p, q, a, b: f"{p} and {q} on opposite sides of the line {a}{b}",
    "between": lambda x, a, b: f"{x} between {a} and {b}",
    "onray": lambda x, v, p: f"{x} on the ray from {v} through {p}",
    "inside": lambda x, a, b, c: f"{x} inside the triangle {a}{b}{c}",
}

# the pairs of points that must differ: the line AB of a side, the segment AB, the ray VP, the triangle's vertices
_DISTINCT: dict[str, tuple[tuple[int, int], ...]] = {
    "sameside": ((2, 3),), "oppositeside": ((2, 3),), "between": ((1, 2),), "onray": ((1, 2),),
    "inside": ((1, 2), (2, 3), (1, 3)),
}


@dataclass(frozen=True, eq=False)
class OrderCondition:
    """One order condition: its keyword, its points (nodes of the claim) and its text."""

    kind: str
    points: tuple[Node, ...]
    text: str

    def values(self, values: dict[Node, Any]) -> list[Any]:
        """The polynomials that must all be positive, from the values of the points (any representatives)."""
        return _VALUES[self.kind](*(values[p] for p in self.points))


def condition_values(claim: Claim, values: dict[Node, Any]) -> list[tuple[str, Any]]:
    """Every polynomial of the claim's order conditions with the text of its condition (all must be > 0).

    >>> from pgsym.proofs.claims import Claim
    >>> c = Claim("x", "x")
    >>> A, B, X = c.point("A", 0, 0), c.point("B", 2, 0), c.point("X", 1, 0)
    >>> _ = c.where_between(X, A, B)
    >>> condition_values(c, {A: (0, 0, 1), B: (2, 0, 1), X: (1, 0, 1)})
    [('X between A and B', 1)]
    """
    return [(w.text, p) for w in claim.order_conditions for p in w.values(values)]


class OrderConditions:
    """The order conditions of a claim, a base class of :class:`~pgsym.proofs.claims.Claim`.

    Each method records one condition in ``self.order_conditions`` and returns it.
    """

    order_conditions: list[OrderCondition]

    def _where(self: Claim, kind: str, points: Sequence[Any]) -> OrderCondition:
        nodes = tuple(self._get(p, ("point",), kind) for p in points)
        for i, j in _DISTINCT[kind]:
            if nodes[i] is nodes[j]:
                raise ObjectTypeError(f"{kind}: {nodes[i].name} is given twice; the condition needs two different "
                                      "points there")
        if len(self.order_conditions) >= MAX_ORDER_CONDITIONS:
            raise ObjectTypeError(f"claim {self.name!r} would have more than {MAX_ORDER_CONDITIONS} order conditions")
        # an inline object is named by its text (``midpoint a b``): in brackets, as the statement writes it
        cond = OrderCondition(kind, nodes, _WORDS[kind](*(f"({n.name})" if " " in n.name else n.name for n in nodes)))
        self.order_conditions.append(cond)
        return cond

    def where_same_side(self: Claim, p: Any, q: Any, a: Any, b: Any) -> OrderCondition:
        """P and Q strictly on the same side of the line AB.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> c.where_same_side(*(c.free_point(n) for n in "PQAB")).text
        'P and Q on the same side of the line AB'
        """
        return self._where("sameside", (p, q, a, b))

    def where_opposite_sides(self: Claim, p: Any, q: Any, a: Any, b: Any) -> OrderCondition:
        """P and Q strictly on opposite sides of the line AB (for P on the circle QAB: P on the arc AB without Q).

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> c.where_opposite_sides(*(c.free_point(n) for n in "PQAB")).kind
        'oppositeside'
        """
        return self._where("oppositeside", (p, q, a, b))

    def where_between(self: Claim, x: Any, a: Any, b: Any) -> OrderCondition:
        """``(X − A)·(B − X) > 0``: for X on the line AB, X strictly between A and B.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> c.where_between(*(c.free_point(n) for n in "XAB")).kind
        'between'
        """
        return self._where("between", (x, a, b))

    def where_on_ray(self: Claim, x: Any, v: Any, p: Any) -> OrderCondition:
        """``(X − V)·(P − V) > 0``: for X on the line VP, X on the ray from V through P (and X ≠ V).

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> c.where_on_ray(*(c.free_point(n) for n in "XVP")).text
        'X on the ray from V through P'
        """
        return self._where("onray", (x, v, p))

    def where_inside(self: Claim, x: Any, a: Any, b: Any, c: Any) -> OrderCondition:
        """X strictly inside the triangle ABC.

        >>> from pgsym.proofs.claims import Claim
        >>> c = Claim("x", "x")
        >>> w = c.where_inside(*(c.free_point(n) for n in "XABC"))
        >>> A, B, C = (0, 0, 1), (1, 0, 1), (0, 1, 1)   # X = (1/3, 1/3) inside, X = (2, 2) beyond BC
        >>> [w.values(dict(zip([c.nodes[k] for k in "XABC"], (x, A, B, C)))) for x in ((1, 1, 3), (2, 2, 1))]
        [[3, 3, 3], [-3, 2, 2]]
        """
        return self._where("inside", (x, a, b, c))
