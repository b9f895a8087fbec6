"""Order conditions read off float figures (pgsym.proofs.order_search)."""

from pgsym.proofs.order_search import condition_holds, restricting_conditions, selecting_conditions


def test_conditions_at_float_points():
    a, b, c = 0j, 4 + 0j, 1 + 3j
    assert condition_holds("sameside", [1 + 1j, 3 + 2j, a, b]) is True  # both above the x-axis
    assert condition_holds("oppositeside", [1 + 1j, 3 - 2j, a, b]) is True
    assert condition_holds("between", [2 + 0j, a, b]) is True and condition_holds("between", [5 + 0j, a, b]) is False
    assert condition_holds("onray", [9 + 0j, a, b]) is True and condition_holds("onray", [-1 + 0j, a, b]) is False
    assert condition_holds("inside", [1.5 + 1j, a, b, c]) is True  # (1.5, 1) is inside the triangle
    assert condition_holds("inside", [3 + 3j, a, b, c]) is False
    assert condition_holds("sameside", [2 + 0j, 1 + 1j, a, b]) is None  # on the line: undecided


def figure(a: complex, b: complex, good: complex, bad: complex) -> dict:
    return {(0,): ({"A": a, "B": b, "X": good}, True), (1,): ({"A": a, "B": b, "X": bad}, False)}


def test_the_condition_that_separates_the_choices_in_every_figure():
    # X on the line AB with |AX| = |AB|/2: the goal holds at the midpoint of AB, not at its mirror image in A
    figures = [figure(0j, 2 + 0j, 1 + 0j, -1 + 0j), figure(1j, 1 + 3j, 0.5 + 2j, -0.5)]
    assert selecting_conditions(figures, ["X"], ["A", "B", "X"]) == [("between", ("X", "A", "B"))]


def test_no_condition_when_the_goal_holds_at_neither_choice_of_a_figure():
    lost = {(0,): ({"A": 0j, "B": 2 + 0j, "X": 1 + 0j}, False), (1,): ({"A": 0j, "B": 2 + 0j, "X": 3 + 0j}, False)}
    assert selecting_conditions([figure(0j, 2 + 0j, 1 + 0j, -1 + 0j), lost], ["X"], ["A", "B", "X"]) is None


def test_no_condition_when_the_figures_disagree():
    # the good point is between A and B in one figure, beyond B in the other: no order condition of A, B, X
    # says which (X on the ray AB in both, the bad point too)
    figures = [figure(0j, 2 + 0j, 1 + 0j, 3 + 0j), figure(0j, 2 + 0j, 3 + 0j, 1 + 0j)]
    assert selecting_conditions(figures, ["X"], ["A", "B", "X"]) is None


def drawn(x: complex, holds: bool) -> dict:
    """A figure without random choices: A = 0, B = 2 on the x-axis, a free point X, and whether the goal holds."""
    return {(): ({"A": 0j, "B": 2 + 0j, "X": x}, holds)}


def test_the_condition_that_keeps_the_figures_where_the_goal_holds():
    # the goal holds when X is beyond B (3, 5, 4 + i), not before A or between A and B (−1, 1): B between A and X
    figures = [drawn(3 + 0j, True), drawn(-1 + 0j, False), drawn(5 + 0j, True), drawn(1 + 0j, False),
               drawn(4 + 1j, True)]
    assert restricting_conditions(figures, ["A", "B", "X"]) == [("between", ("B", "X", "A"))]


def test_the_restricting_condition_that_keeps_most_figures_is_taken():
    # "X between A and B" keeps 1 and 1.5; "X on the ray from A through B" keeps those and 3, all good figures
    figures = [drawn(1 + 0j, True), drawn(1.5 + 0j, True), drawn(3 + 0j, True), drawn(-1 + 0j, False)]
    assert restricting_conditions(figures, ["A", "B", "X"]) == [("onray", ("X", "A", "B"))]


def test_no_restricting_condition_keeps_too_few_figures_or_a_bad_one():
    # good at 1 and 3, bad at 1.5 and 4 (all on the line AB): an order condition on A, B, X that keeps 1 keeps 1.5
    # (both between A and B), one that keeps 3 keeps 4 (both beyond B)
    figures = [drawn(1 + 0j, True), drawn(3 + 0j, True), drawn(1.5 + 0j, False), drawn(4 + 0j, False)]
    assert restricting_conditions(figures, ["A", "B", "X"]) is None
    assert restricting_conditions([drawn(1 + 0j, False)], ["A", "B", "X"]) is None  # the goal holds nowhere
