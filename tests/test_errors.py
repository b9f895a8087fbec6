"""Every bad input gets a named pgsym error with a message that says what was wrong."""

from __future__ import annotations

import pytest
import sympy

from pgsym import (
    CoincidentLinesError,
    CoincidentPointsError,
    DegenerateConfigurationError,
    DimensionError,
    IdealPointError,
    Line,
    NonNumericError,
    ObjectTypeError,
    PgsymError,
    Point,
    ZeroVectorError,
    collinear,
    dual,
    incident,
    join,
    line_at_infinity,
    meet,
)


@pytest.mark.parametrize(
    ("build", "error", "words"),
    [
        (lambda: join(Point(1, 2), Point(2, 4, 2)), CoincidentPointsError, "same point"),
        (lambda: meet(Line(1, 2, 3), Line(-2, -4, -6)), CoincidentLinesError, "same line"),
        (lambda: Point(0, 0, 0), ZeroVectorError, "zero vector"),
        (lambda: Line(0, 0, 0), ZeroVectorError, "zero vector"),
        (lambda: Point(1), DimensionError, "got 1"),
        (lambda: Point(1, 2, 3, 4), DimensionError, "got 4"),
        (lambda: Line(1, 2), DimensionError, "needs 3"),
        (lambda: Point("1", 2), NonNumericError, "'1'"),
        (lambda: Point(None, 2), NonNumericError, "None"),
        (lambda: Point(True, 2), NonNumericError, "True"),
        (lambda: Point(float("inf"), 2), NonNumericError, "finite"),
        (lambda: Point(sympy.zoo, 2), NonNumericError, "finite"),
        (lambda: Point(object(), 2), NonNumericError, "object"),
        (lambda: Point(1, 1, 0).dehomogenize(), IdealPointError, "ideal point"),
        (lambda: join(Line(1, 0, 0), Line(0, 1, 0)), ObjectTypeError, "meet()"),
        (lambda: meet(Point(1, 0), Point(0, 1)), ObjectTypeError, "join()"),
        (lambda: collinear(Line(1, 0, 0), Point(0, 1), Point(1, 1)), ObjectTypeError, "concurrent()"),
        (lambda: incident(Point(1, 0), Point(0, 1)), ObjectTypeError, "Point and a Line"),
        (lambda: dual(3), ObjectTypeError, "Point or a Line"),
        (lambda: line_at_infinity().direction, DegenerateConfigurationError, "line at infinity"),
    ],
)
def test_bad_input_raises_a_named_error_with_a_helpful_message(build, error, words):
    with pytest.raises(error) as info:
        build()
    assert isinstance(info.value, PgsymError)
    assert words in str(info.value)


def test_errors_are_also_the_builtin_exceptions_python_users_catch():
    with pytest.raises(ValueError):
        Point(0, 0, 0)
    with pytest.raises(TypeError):
        Point("x", 1)
    with pytest.raises(TypeError):
        join(Line(1, 0, 0), Line(0, 1, 0))


def test_symbolic_coincidence_is_detected_identically():
    a, b = sympy.symbols("a b")
    with pytest.raises(CoincidentPointsError):
        join(Point(a, b), Point(2 * a, 2 * b, 2))


def test_every_error_class_is_exported_at_the_top_level():
    import pgsym
    import pgsym.errors

    assert set(pgsym.errors.__all__) <= set(pgsym.__all__)
    for name in pgsym.errors.__all__:
        assert issubclass(getattr(pgsym, name), PgsymError)
