"""The one grammar of numbers typed on the ``pgsym`` command line, and the limits it enforces.

Every coordinate argument (``pgsym join "1,-2/3"``, ``pgsym rectify --points "10,20 30,40"``,
``--lines "0,0 9,1; 0,5 9,6"``) and every numeric option is read here, by :func:`parse_argument`:

.. code-block:: text

    argument := group (";" group)*          groups: the lines of --lines
    group    := tuple (WHITESPACE tuple)*    tuples: the points "x,y" of --points
    tuple    := number ("," number)*         spaces around a comma are allowed
    number   := [+-] (digits "/" digits | mantissa [("e"|"E") [+-] digits])
    mantissa := digits ["." [digits]] | "." digits            (ASCII digits only)

Numbers are read exactly (``fractions.Fraction``), never evaluated as code. Limits are checked
on the text, before any arithmetic, so ten typed characters can never cost more than a few
microseconds (:data:`~pgsym.limits.MAX_ARGUMENT_CHARS` characters per argument,
:data:`~pgsym.limits.MAX_DIGITS` digits per numerator and denominator,
:data:`~pgsym.limits.MAX_EXPONENT` for the size of an exponent). ``nan``, ``inf``, unicode digits
and Python expressions are not numbers. Failures raise named :class:`~pgsym.errors.PgsymError`
subclasses, which the click parameter types below turn into usage errors (exit status 2).

>>> parse_argument("1, -2/3 0.5e1")
[[(Fraction(1, 1), Fraction(-2, 3)), (Fraction(5, 1),)]]
>>> parse_number("1e99999999")
Traceback (most recent call last):
...
pgsym.errors.InputLimitError: the exponent of '1e99999999' is out of range: exponents from -40 to 40 are read
"""

from __future__ import annotations

import re
from fractions import Fraction

import click

from ..errors import DimensionError, InputLimitError, InvalidCoordinatesError, NonNumericError, PgsymError
from ..limits import MAX_ARGUMENT_CHARS, MAX_DIGITS, MAX_EXPONENT, MAX_IMAGE_PIXELS

__all__ = [
    "COORDS",
    "LINES",
    "POINTS",
    "SIZE",
    "DecimalRange",
    "IntegerRange",
    "fail",
    "parse_argument",
    "parse_coordinates",
    "parse_lines",
    "parse_number",
    "parse_points",
    "parse_size",
]

_NUMBER = re.compile(
    r"(?P<sign>[+-]?)(?:(?P<num>[0-9]+)/(?P<den>[0-9]+)"
    r"|(?P<int>[0-9]*)(?:\.(?P<frac>[0-9]*))?(?:[eE](?P<esign>[+-]?)(?P<exp>[0-9]+))?)"
)
_COMMA = re.compile(r"\s*,\s*")
_HINT = "write integers, fractions p/q or decimals such as 3, -2/3, 0.5 or 1.5e-3"


def _show(text: str, width: int = 30) -> str:
    """A quoted, escaped and shortened copy of user text for a message."""
    return repr(text if len(text) <= width else text[:width] + "...")


def parse_number(token: str) -> Fraction:
    """Read one number of the grammar exactly, checking its digits and exponent first.

    >>> parse_number("-2/3"), parse_number("1.5e-3"), parse_number(".5")
    (Fraction(-2, 3), Fraction(3, 2000), Fraction(1, 2))
    >>> parse_number("nan")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.NonNumericError: 'nan' is not a number: write integers, fractions p/q or decimals ...
    """
    if len(token) > MAX_ARGUMENT_CHARS:
        raise InputLimitError(f"the number is {len(token)} characters long; at most {MAX_ARGUMENT_CHARS} are read")
    m = _NUMBER.fullmatch(token)
    if m is None or not (m["num"] or m["int"] or m["frac"]):
        bad = next((c for c in token if not c.isascii() or not c.isprintable()), None)
        why = f" ({f'U+{ord(bad):04X}'} is not an ASCII digit or sign)" if bad is not None else ""
        raise NonNumericError(f"{_show(token)} is not a number{why}: {_HINT}")
    if m["num"] is not None:
        for digits in (m["num"], m["den"]):
            _check_digits(token, len(digits))
        if int(m["den"]) == 0:
            raise NonNumericError(f"{_show(token)} is not a number: its denominator is zero")
        value = Fraction(int(m["num"]), int(m["den"]))
    else:
        integer, fraction = m["int"] or "", m["frac"] or ""
        _check_digits(token, len(integer) + len(fraction))
        exponent = 0
        if m["exp"] is not None:
            # the length first: int() of a huge digit string would itself be the slow part
            small = len(m["exp"].lstrip("0")) <= len(str(MAX_EXPONENT))
            exponent = int(m["exp"]) * (-1 if m["esign"] == "-" else 1) if small else MAX_EXPONENT + 1
            if abs(exponent) > MAX_EXPONENT:
                raise InputLimitError(f"the exponent of {_show(token)} is out of range: exponents from "
                                      f"-{MAX_EXPONENT} to {MAX_EXPONENT} are read")
        value = Fraction(int(integer + fraction or "0")) * Fraction(10) ** (exponent - len(fraction))
    return -value if m["sign"] == "-" else value


def _check_digits(token: str, digits: int) -> None:
    if digits > MAX_DIGITS:
        raise InputLimitError(f"the number {_show(token)} has {digits} digits; at most {MAX_DIGITS} are read "
                              "(numerator and denominator each)")


def _read(text: str, what: str) -> list[list[tuple[str, tuple[Fraction, ...]]]]:
    """The groups of an argument, each a list of (typed word, tuple of numbers); blank groups are skipped."""
    if not isinstance(text, str):
        raise NonNumericError(f"the {what} must be text, got {type(text).__name__}")
    if len(text) > MAX_ARGUMENT_CHARS:
        raise InputLimitError(f"the {what} is {len(text)} characters long; at most {MAX_ARGUMENT_CHARS} are read")
    groups = []
    for chunk in text.split(";"):
        group = []
        for word in _COMMA.sub(",", chunk).split():
            entries = word.split(",")
            if "" in entries:
                raise InvalidCoordinatesError(
                    f"empty entry in {_show(word)} (two commas in a row, or a comma at an end)")
            group.append((word, tuple(parse_number(entry) for entry in entries)))
        if group:
            groups.append(group)
    if not groups:
        raise InvalidCoordinatesError(f"the {what} is empty")
    return groups


def parse_argument(text: str, what: str = "argument") -> list[list[tuple[Fraction, ...]]]:
    """Read one argument of the grammar into groups of tuples of exact numbers.

    >>> parse_argument("0,0 10,0; 0,5 10,6")[1]
    [(Fraction(0, 1), Fraction(5, 1)), (Fraction(10, 1), Fraction(6, 1))]
    >>> parse_argument("1,,2")
    Traceback (most recent call last):
    ...
    pgsym.errors.InvalidCoordinatesError: empty entry in '1,,2' (two commas in a row, or a comma at an end)
    """
    return [[numbers for _, numbers in group] for group in _read(text, what)]


def _one_group(text: str, what: str, example: str) -> list[tuple[str, tuple[Fraction, ...]]]:
    groups = _read(text, what)
    if len(groups) != 1:
        raise InvalidCoordinatesError(f"a {what} has no ';': write it like {example!r}")
    return groups[0]


def parse_coordinates(text: str) -> tuple[Fraction, ...]:
    """Read a coordinate list ``"1, -2/3, 0.5"`` or ``"1 -2/3 0.5"`` (``join`` and ``meet``).

    >>> parse_coordinates("1 -1 3")
    (Fraction(1, 1), Fraction(-1, 1), Fraction(3, 1))
    """
    return tuple(x for _, numbers in _one_group(text, "coordinate list", "1,2,1") for x in numbers)


def parse_points(text: str, count: int | None = None) -> list[tuple[float, float]]:
    """Read ``"x1,y1 x2,y2 ..."`` into a list of (x, y) pairs of floats.

    >>> parse_points("10,20 30.5,40")
    [(10.0, 20.0), (30.5, 40.0)]
    >>> parse_points("1,2 3", 2)
    Traceback (most recent call last):
    ...
    pgsym.errors.DimensionError: '3' is not a point: write each point as x,y
    """
    return _pairs(_one_group(text, "point list", "10,20 30,40"), count)


def _pairs(group: list[tuple[str, tuple[Fraction, ...]]], count: int | None) -> list[tuple[float, float]]:
    points = []
    for word, numbers in group:
        if len(numbers) != 2:
            raise DimensionError(f"{_show(word)} is not a point: write each point as x,y")
        points.append((float(numbers[0]), float(numbers[1])))  # |x| < 10**81: always a finite float
    if count is not None and len(points) != count:
        raise DimensionError(f"expected {count} points 'x,y' separated by spaces, got {len(points)}")
    return points


def parse_lines(text: str) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """Read lines given by two points each, separated by semicolons: ``"x1,y1 x2,y2; x3,y3 x4,y4"``.

    >>> parse_lines("0,0 10,0; 0,5 10,6")
    [((0.0, 0.0), (10.0, 0.0)), ((0.0, 5.0), (10.0, 6.0))]
    """
    lines = []
    for i, group in enumerate(_read(text, "line list")):
        try:
            p, q = _pairs(group, 2)
        except DimensionError as err:
            shown = " ".join(word for word, _ in group)
            raise DimensionError(f"line {i + 1} ({_show(shown)}): {err}") from None
        lines.append((p, q))
    return lines


def parse_size(text: str) -> tuple[int, int]:
    """Read ``"WxH"`` (e.g. ``"400x300"``) into ``(width, height)``; at most MAX_IMAGE_PIXELS pixels.

    >>> parse_size("400x300")
    (400, 300)
    """
    m = re.fullmatch(r"\s*([0-9]{1,5})\s*[xX×]\s*([0-9]{1,5})\s*", text[:MAX_ARGUMENT_CHARS])
    if not m or len(text) > MAX_ARGUMENT_CHARS:
        raise InvalidCoordinatesError(f"{_show(text)} is not a size: write it as WIDTHxHEIGHT, e.g. 400x300")
    w, h = int(m.group(1)), int(m.group(2))
    if not (2 <= w <= 16384 and 2 <= h <= 16384):
        raise InvalidCoordinatesError(f"the size {w}x{h} is out of range: each side must be 2 to 16384 pixels")
    if w * h > MAX_IMAGE_PIXELS:
        raise InputLimitError(f"the size {w}x{h} has {w * h} pixels; at most {MAX_IMAGE_PIXELS} are written")
    return w, h


def _message(err: PgsymError) -> str:
    return f"{type(err).__name__}: {err}"


class _Parsed(click.ParamType):
    """A click type reading its text with one of the parsers above (errors: usage errors, exit 2)."""

    def __init__(self, name: str, parser) -> None:  # type: ignore[no-untyped-def]
        self.name = name
        self._parser = parser

    def convert(self, value, param, ctx):  # type: ignore[no-untyped-def]
        if not isinstance(value, str):
            return value
        try:
            return self._parser(value)
        except PgsymError as err:
            self.fail(_message(err), param, ctx)


COORDS = _Parsed("COORDS", parse_coordinates)
POINTS = _Parsed("POINTS", parse_points)
LINES = _Parsed("LINES", parse_lines)
SIZE = _Parsed("WxH", parse_size)


def _scalar(value: str, param, ctx, kind: click.ParamType) -> Fraction:  # type: ignore[no-untyped-def]
    try:
        groups = parse_argument(value, "number")
    except PgsymError as err:
        kind.fail(_message(err), param, ctx)
    if len(groups) != 1 or len(groups[0]) != 1 or len(groups[0][0]) != 1:
        kind.fail(f"{_show(value)} is not one number", param, ctx)
    return groups[0][0][0]


class DecimalRange(click.FloatRange):
    """``click.FloatRange`` reading its text with the grammar above (so never NaN or infinite).

    >>> DecimalRange(0, 1).convert("0.25", None, None)
    0.25
    """

    def convert(self, value, param, ctx):  # type: ignore[no-untyped-def]
        if isinstance(value, str):
            value = float(_scalar(value, param, ctx, self))
        return super().convert(value, param, ctx)


class IntegerRange(click.IntRange):
    """``click.IntRange`` reading its text with the grammar above (an integer of at most MAX_DIGITS digits).

    >>> IntegerRange(1, 9).convert("3", None, None)
    3
    """

    def convert(self, value, param, ctx):  # type: ignore[no-untyped-def]
        if isinstance(value, str):
            number = _scalar(value, param, ctx, self)
            if number.denominator != 1:
                self.fail(f"{_show(value)} is not an integer", param, ctx)
            value = int(number)
        return super().convert(value, param, ctx)


def fail(err: Exception) -> click.ClickException:
    """A library error as the one-line message every command prints (``Error: TypeName: message``)."""
    return click.ClickException(f"{type(err).__name__}: {err}")
