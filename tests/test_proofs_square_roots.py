"""Constructions with square roots whose arguments are written inline, the names of their roots, and the
comparison with pgsym's core at instances where a root has no principal sign.

Every square-root construction of the statement language (``anglebisector``, ``exbisector``,
``intersection(s)``, ``tangentfrom(s)``, ``rotate`` by degrees, ``polygon``) takes an argument of every kind
written inline: an inline point ``(midpoint A C)``, an inline line ``(join A B)``, an inline circle
``(circle C A)``, nested ``(reflect A (join B C))``. Each statement below is a true theorem for every branch,
so the engine must prove it; before, a length root was named after the object's text (spaces: an internal
error) and roots were found again by name (two pairs of points could share one root).
"""

from __future__ import annotations

import pytest

from pgsym.proofs.engine import prove
from pgsym.proofs.language import parse_statement

INLINE = {
    # the reflection of A in a bisector of ∠ABM lies on the line BM (for the internal and the external one)
    "bisector, inline point": ("points A B C\nline l = anglebisector A B (midpoint A C)\n"
                               "prove collinear B (midpoint A C) (reflect A l)"),
    "exbisector, inline points": ("points A B C\nline l = exbisector (midpoint A B) C (reflect A (join B C))\n"
                                  "prove collinear C (reflect A (join B C)) (reflect (midpoint A B) l)"),
    # Thales: a point of the circle on the diameter AB sees AB at a right angle
    "line-circle, inline line and circle": ("points A B C\npoint X = intersection (perpendicular (join A B) C) "
                                            "(circle (midpoint A B) A)\nprove perpendicular (join X A) (join X B)"),
    # both common points lie on the circle, and their midpoint is the foot of the centre
    "both line-circle points, inline": ("points A B C\n"
                                        "points X Y = intersections (join (midpoint A B) C) (circle A B)\n"
                                        "prove equal (midpoint X Y) (foot A (join (midpoint A B) C))\n"
                                        "prove equallength A X A Y"),
    "circle-circle, inline circles": ("points A B C\npoint X = intersection (circle A B) (circle (midpoint A C) B)\n"
                                      "prove equallength A X A B\n"
                                      "prove equallength (midpoint A C) X (midpoint A C) B"),
    "tangent from an inline point": ("points A B C\nline t = tangentfrom (midpoint A B) (circle C A)\n"
                                     "prove tangent t (circle C A)\nprove on (midpoint A B) t"),
    "both tangents, inline": ("points A B C\nlines s t = tangentsfrom (reflect A (join B C)) (circle C B)\n"
                              "prove tangent s (circle C B)\nprove tangent t (circle C B)"),
    # a rotation keeps the distance to its centre; by 90° the radii are perpendicular
    "rotate an inline point": ("points A B C\npoint X = rotate (midpoint A B) C 90\n"
                               "prove equallength C X C (midpoint A B)\n"
                               "prove perpendicular (join C X) (join C (midpoint A B))"),
    "rotate about an inline centre by degrees": ("points A B C\npoint X = rotate A (midpoint B C) -60\n"
                                                 "prove equallength (midpoint B C) X (midpoint B C) A\n"
                                                 "prove equallength (midpoint B C) X X A"),
    "polygon on inline vertices": ("points A B\npoint X = polygon (midpoint A B) B 4 2\n"
                                   "prove equallength (midpoint A B) B B X\n"
                                   "prove perpendicular (join (midpoint A B) B) (join B X)"),
}


@pytest.mark.parametrize("text", INLINE.values(), ids=INLINE.keys())
def test_every_square_root_construction_takes_inline_arguments(text):
    verdict = prove(parse_statement(text), timeout=60)
    assert verdict.status == "proved", verdict.reason
    assert "MISMATCH" not in str(verdict.core_check)


def test_a_false_statement_with_an_inline_bisector_is_not_proved():
    # the internal bisector of ∠ABM (M the midpoint of AC) through C: false (B = (0, 0), A = (2, 0), C = (0, 2):
    # M = (1, 1), the bisectors of ∠ABM are y = x·tan 22.5° and its perpendicular; C = (0, 2) is on neither)
    verdict = prove(parse_statement("points A B C\nline l = anglebisector A B (midpoint A C)\nprove on C l"),
                    timeout=60)
    assert verdict.status == "false"


def test_roots_of_different_pairs_never_share_a_name():
    # d_A_B_C would name the length of both pairs (A_B, C) and (A, B_C); each pair has its own root
    claim = parse_statement("points A_B C A B_C X Y\nline l = anglebisector A_B C X\nline m = anglebisector A B_C Y\n"
                            "prove collinear B_C Y (reflect A m)")
    names = [str(r.symbol) for r in claim.square_roots.roots]
    assert len(names) == len(set(names)) == 4
    assert prove(claim, timeout=60).status == "proved"


def test_a_root_never_takes_a_parameter_s_symbol():
    claim = parse_statement("params e_X d_A_B\npoints A B C\npoint P = (e_X, d_A_B)\n"
                            "point X = intersection (join A B) (circle C A)\nline l = anglebisector A B C\n"
                            "prove equallength C X C A")
    roots = {str(r.symbol) for r in claim.square_roots.roots}
    assert not roots & {"e_X", "d_A_B"}
    assert prove(claim, timeout=60).status == "proved"


def test_the_core_check_skips_an_instance_where_a_length_has_no_sign():
    # D is a point at infinity: the length root d_B_D (principal sign w_B·w_D) has no principal sign, so no
    # branch is named there; before, the root was set to 0 although d² = |direction|² ≠ 0, and the core check
    # compared that non-branch (a mismatch; it could also have refuted on it)
    text = ("points B C\npoint D = (3, 4, 0)\nline l = anglebisector C B D\nline m = exbisector C B D\n"
            "prove perpendicular l m")
    verdict = prove(parse_statement(text), timeout=60)
    assert verdict.status == "proved", verdict.reason
    assert "MISMATCH" not in str(verdict.core_check)
