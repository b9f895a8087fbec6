"""Reading typed answers, and comparing them with the key (up to scale where the answer is projective).

The parser is a small hand-written tokenizer and recursive-descent reader: it never evaluates code
(no ``eval``, no ``sympify`` of the raw text). It reads integers, fractions ``p/q``, decimals,
signs, vectors ``(1, -2/3, 0)`` or ``1, -2/3, 0`` and matrices ``[[1, 0], [0, 1]]``. It bounds the
input length, the nesting depth, the number of entries and the size of every number (so its
running time is bounded too: one pass over at most ``MAX_LENGTH`` characters; no wall-clock limit
that could make grading differ between runs), and raises
:class:`~pgsym.exercises.errors.UnparsableAnswerError` saying what it could not read.

>>> parse_answer("(2, -4, 0)")
(Fraction(2, 1), Fraction(-4, 1), Fraction(0, 1))
>>> parse_answer("[[1, 1/2], [0, 0.25]]")
((Fraction(1, 1), Fraction(1, 2)), (Fraction(0, 1), Fraction(1, 4)))
>>> from pgsym.exercises.model import Answer
>>> grade(Answer.projective([1, -2, 0]), "(-3, 6, 0)")
True
>>> parse_answer("__import__('os')")
Traceback (most recent call last):
...
pgsym.exercises.errors.UnparsableAnswerError: cannot read the answer: unexpected character '_' at position 1; ...
"""

from __future__ import annotations

import hashlib
from fractions import Fraction
from typing import Any

from ..limits import MAX_ANSWER_CHARS, MAX_DIGITS
from ..ring import primitive_integers
from .errors import UnparsableAnswerError
from .model import Answer

MAX_LENGTH = MAX_ANSWER_CHARS
MAX_DEPTH = 3
MAX_ENTRIES = 64

_DIGITS = frozenset("0123456789")
_ALLOWED = set("0123456789+-/.,;()[] \t")
_MINUS_SIGNS = {"\u2212": "-", "\u2013": "-"}  # unicode minus and en dash read as minus

Parsed = Fraction | tuple[Any, ...]


def _fail(message: str) -> UnparsableAnswerError:
    return UnparsableAnswerError(f"cannot read the answer: {message}")


def _tokens(text: str) -> list[tuple[str, str, int]]:
    """Split into (kind, text, position) tokens: number, sign, slash, comma, open, close."""
    if not isinstance(text, str):
        raise _fail(f"expected text, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise _fail(f"the answer is {len(text)} characters long; at most {MAX_LENGTH} are read")
    for bad, good in _MINUS_SIGNS.items():
        text = text.replace(bad, good)
    tokens: list[tuple[str, str, int]] = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch not in _ALLOWED:
            shown = repr(ch) if ch.isprintable() and ch.isascii() else f"U+{ord(ch):04X}"
            raise _fail(f"unexpected character {shown} at position {i + 1}; write numbers such as 3, -2/3 or 0.5, "
                        "vectors (1, 2, 0) and matrices [[1, 0], [0, 1]]")
        if ch in " \t":
            i += 1
        elif ch in _DIGITS or ch == ".":
            j = i
            # ASCII digits only: str.isdigit() also accepts '¹' or '٣', which Fraction cannot read
            while j < n and (text[j] in _DIGITS or text[j] == "."):
                j += 1
            word = text[i:j]
            if word.count(".") > 1 or word == ".":
                raise _fail(f"{word!r} at position {i + 1} is not a number")
            if sum(c in _DIGITS for c in word) > MAX_DIGITS:
                raise _fail(f"the number at position {i + 1} has more than {MAX_DIGITS} digits")
            tokens.append(("number", word, i))
            i = j
        else:
            kind = {"+": "sign", "-": "sign", "/": "slash", ",": "comma", ";": "comma",
                    "(": "open", "[": "open", ")": "close", "]": "close"}[ch]
            tokens.append((kind, ch, i))
            i += 1
    if not tokens:
        raise _fail("the answer is empty")
    return tokens


class _Reader:
    def __init__(self, tokens: list[tuple[str, str, int]]) -> None:
        self.tokens = tokens
        self.i = 0
        self.entries = 0

    def peek(self) -> tuple[str, str, int] | None:
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def take(self, kind: str) -> tuple[str, str, int]:
        tok = self.peek()
        if tok is None:
            raise _fail(f"the answer ends too early (expected {kind_name(kind)})")
        if tok[0] != kind:
            raise _fail(f"expected {kind_name(kind)} at position {tok[2] + 1}, found {tok[1]!r}")
        self.i += 1
        return tok

    def unsigned(self) -> Fraction:
        _, word, _ = self.take("number")
        return Fraction(word)

    def sign(self) -> int:
        """An optional ``+`` or ``-`` (numerator and denominator may each carry one): ``-1`` or ``1``."""
        tok = self.peek()
        if tok is None or tok[0] != "sign":
            return 1
        self.i += 1
        return -1 if tok[1] == "-" else 1

    def scalar(self) -> Fraction:
        sign = self.sign()
        value = self.unsigned()
        tok = self.peek()
        if tok is not None and tok[0] == "slash":
            pos = tok[2]
            self.i += 1
            den_sign = self.sign()
            den = self.unsigned()
            if den == 0:
                raise _fail(f"division by zero at position {pos + 1}")
            value = value / (den_sign * den)
        self.entries += 1
        if self.entries > MAX_ENTRIES:
            raise _fail(f"more than {MAX_ENTRIES} numbers")
        return sign * value

    def item(self, depth: int) -> Parsed:
        tok = self.peek()
        if tok is not None and tok[0] == "open":
            if depth >= MAX_DEPTH:
                raise _fail(f"brackets nested more than {MAX_DEPTH} deep")
            return self.group(depth + 1)
        return self.scalar()

    def sequence(self, depth: int) -> list[Parsed]:
        items = [self.item(depth)]
        while (tok := self.peek()) is not None and tok[0] == "comma":
            self.i += 1
            items.append(self.item(depth))
        return items

    def group(self, depth: int) -> tuple[Parsed, ...]:
        _, opener, pos = self.take("open")
        items = self.sequence(depth)
        _, closer, _ = self.take("close")
        if {"(": ")", "[": "]"}[opener] != closer:
            raise _fail(f"the bracket {opener!r} at position {pos + 1} is closed by {closer!r}")
        return tuple(items)


def kind_name(kind: str) -> str:
    """Human name of a token kind (for messages).

    >>> kind_name("close")
    'a closing bracket'
    """
    return {"number": "a number", "sign": "a sign", "slash": "'/'", "comma": "a comma", "open": "an opening bracket",
            "close": "a closing bracket"}.get(kind, kind)


def parse_answer(text: str) -> Parsed:
    """Read a number, a vector or a matrix exactly, without evaluating anything.

    A bare list ``1, 2, 3`` is a vector; one pair of brackets around a single number is that number.

    >>> parse_answer("-3/4")
    Fraction(-3, 4)
    >>> parse_answer("1, 0, 0")
    (Fraction(1, 1), Fraction(0, 1), Fraction(0, 1))
    >>> parse_answer("1/0")
    Traceback (most recent call last):
    ...
    pgsym.exercises.errors.UnparsableAnswerError: cannot read the answer: division by zero at position 2
    """
    reader = _Reader(_tokens(text))
    items = reader.sequence(0)
    tok = reader.peek()
    if tok is not None:
        raise _fail(f"unexpected {tok[1]!r} at position {tok[2] + 1}")
    value: Parsed = items[0] if len(items) == 1 else tuple(items)
    while isinstance(value, tuple) and len(value) == 1:
        value = value[0]
    return value


def _as_vector(value: Parsed, size: int) -> tuple[Fraction, ...]:
    if isinstance(value, Fraction) or not all(isinstance(v, Fraction) for v in value):
        raise _fail(f"expected a vector of {size} numbers such as (1, -2, 0)")
    if len(value) != size:
        raise _fail(f"expected {size} numbers, got {len(value)}")
    return tuple(value)  # type: ignore[arg-type]


def _as_matrix(value: Parsed, rows: int, cols: int) -> tuple[tuple[Fraction, ...], ...]:
    if isinstance(value, Fraction) or not all(isinstance(r, tuple) for r in value):
        raise _fail(f"expected a {rows}×{cols} matrix such as [[1, 0], [0, 1]]")
    if len(value) != rows:
        raise _fail(f"expected {rows} rows, got {len(value)}")
    return tuple(_as_vector(r, cols) for r in value)  # type: ignore[arg-type]


def read_as(expected: Answer, text: str) -> Any:
    """Read ``text`` as the kind of ``expected``; raise UnparsableAnswerError on anything else.

    >>> read_as(Answer.choice("B"), " b ")
    'B'
    """
    if expected.kind == "choice":
        if not isinstance(text, str) or len(text) > MAX_LENGTH:
            raise _fail("expected one letter")
        letter = text.strip().upper()
        if len(letter) != 1 or letter not in "ABCDEFGH":
            raise _fail(f"expected one letter such as A or B, got {text.strip()[:20]!r}")
        return letter
    value = parse_answer(text)
    if expected.kind in ("scalar", "integer"):
        if not isinstance(value, Fraction):
            raise _fail("expected one number")
        if expected.kind == "integer" and value.denominator != 1:
            raise _fail(f"expected an integer, got {value}")
        return value
    if expected.kind in ("projective", "vector"):
        return _as_vector(value, len(expected.value))
    rows, cols = len(expected.value), len(expected.value[0])
    return _as_matrix(value, rows, cols)


def matches(expected: Answer, value: Any) -> bool:
    """Compare a value already read by :func:`read_as` with the key.

    ``projective`` and ``matrix`` answers are equal up to a nonzero scale (the zero vector never is);
    everything else must be equal exactly.

    >>> matches(Answer.matrix([[1, 0], [0, 2]]), ((Fraction(-1, 2), 0), (0, -1)))
    True
    """
    if expected.kind in ("projective", "matrix"):
        flat = [x for row in value for x in row] if expected.kind == "matrix" else list(value)
        if all(x == 0 for x in flat):
            return False
        key = expected.value if expected.kind == "projective" else tuple(k for row in expected.value for k in row)
        return primitive_integers(flat) == key  # the key is stored in canonical form
    if expected.kind in ("vector", "matrix_exact"):
        flat = [x for row in value for x in row] if expected.kind == "matrix_exact" else list(value)
        return flat == expected.flat()
    if expected.kind in ("scalar", "integer"):
        return Fraction(value) == Fraction(expected.value)
    return value == expected.value


def grade(expected: Answer, text: str) -> bool:
    """True if the typed ``text`` is a correct answer; UnparsableAnswerError if it cannot be read.

    >>> grade(Answer.scalar(Fraction(4, 3)), "4/3"), grade(Answer.projective([1, 0, 0]), "(0, 0, 0)")
    (True, False)
    """
    return matches(expected, read_as(expected, text))


def answer_digest(salt: str, answer: Answer) -> str:
    """A salted BLAKE2 digest of the canonical form of an answer (for self-check notebooks).

    >>> answer_digest("F-1:1", Answer.projective([2, 4, 0])) == answer_digest("F-1:1", Answer.projective([1, 2, 0]))
    True
    """

    return hashlib.blake2b(f"{salt}|{answer.kind}|{answer.display()}".encode(), digest_size=12).hexdigest()


def self_check(salt: str, kind: str, digest: str, text: str) -> bool:
    """Check a typed answer against a digest: used by the generated student notebooks.

    >>> d = answer_digest("F-1:2", Answer.scalar(Fraction(-1, 2)))
    >>> self_check("F-1:2", "scalar", d, "-2/4"), self_check("F-1:2", "scalar", d, "1/2")
    (True, False)
    """
    if kind == "choice":
        return answer_digest(salt, Answer.choice(text.strip()[:1] or "?")) == digest
    value = parse_answer(text)
    try:
        if kind in ("scalar", "integer"):
            if not isinstance(value, Fraction):
                return False
            if kind == "integer" and value.denominator != 1:
                return False
            candidate = Answer.scalar(value) if kind == "scalar" else Answer.integer(int(value))
        elif not isinstance(value, tuple):
            return False
        else:
            candidate = {"projective": Answer.projective, "matrix": Answer.matrix, "vector": Answer.vector,
                         "matrix_exact": Answer.matrix_exact}[kind](value)
    except (ValueError, TypeError, KeyError):
        return False
    return answer_digest(salt, candidate) == digest
