"""Exact scalars: coercion, the one zero test, signs, the canonical form and printing.

Every decision the exact core takes about a coordinate ("is it zero?", "are these
proportional?", "which sign?") goes through :func:`is_zero` or :func:`sign` here.

**What is decided.** An expression is decided when it is a rational function, in any
symbols, whose coefficients are *algebraic numbers* written with rationals, ``I``,
radicals of constants (``sqrt(3 + 2*sqrt(2))``, ``2**(1/3)``), ``cos``/``sin``/``tan``
of rational multiples of ``pi``, ``exp(I*pi*r)`` (r rational), ``CRootOf`` and
``AlgebraicNumber``:

* rational numbers are compared directly, and rational functions over ℚ by expanding
  the numerator of one fraction (the fast path, no ``simplify``);
* otherwise the numerator is expanded into a polynomial in the symbols and each
  coefficient, an algebraic number, is tested: rigorous interval arithmetic (mpmath
  ``iv``) proves most nonzero numbers nonzero at once; a number whose interval holds 0
  is zero exactly when its minimal polynomial over ℚ is ``x`` (SymPy's
  ``minimal_polynomial``).

**What raises** :class:`~pgsym.errors.UndecidableError` (never a guess): transcendental
or unclassified constants (``pi``, ``E``, ``exp(1)``, ``log(2)``, ``EulerGamma``,
floats inside an expression), unknown functions (``Function('f')(a)``), and symbols
under a radical, a non-integer power or a function (``sqrt(a)`` against
``sqrt(a**2)``: which branch is meant depends on ``a``). An expression whose numerator
expands to 0 is zero whatever its atoms are (``pi - pi``, ``sqrt(a)**2 - a``).
:func:`sign` raises it as well for non-real numbers (they have no sign) and for
symbolic expressions.

**The canonical form** (:func:`canonical_coords`, used by every ``canonical()``) is the
representative of a homogeneous vector up to a nonzero scale that equal objects share:

1. entries that are all rational: the primitive integer vector (coprime integers)
   whose first nonzero entry is positive;
2. entries that are rational functions over ℚ: the denominators are cleared and the
   polynomial content (gcd) removed, giving polynomials with coprime integer
   coefficients; the sign makes the leading coefficient (lexicographic order, symbols
   sorted by name) of the first nonzero entry positive;
3. entries with algebraic numbers: without symbols, the vector is divided by its first
   nonzero entry (which becomes 1); with symbols, the denominators are cleared and the
   content removed over the number field the entries generate, then the vector is
   divided by the leading coefficient of its first nonzero entry (which becomes monic).
   Every algebraic number in the result is written in the normal form of
   :func:`algebraic_normal_form` (``a + b*sqrt(d)`` for degree ≤ 2, else a ``CRootOf``).
   If all numbers turn out rational, the result is put through rule 1 or 2, so a vector
   with a disguised rational scale, such as ``sqrt(2)*(1, 2, 3)``, gets the same form
   as ``(1, 2, 3)``.

>>> from sympy import sqrt, I
>>> is_zero(sqrt(3 + 2*sqrt(2)) - 1 - sqrt(2)), is_zero((1 + I)**2 - 2*I)
(True, True)
>>> canonical_coords((sqrt(2), 2*sqrt(2), 3*sqrt(2)))
(1, 2, 3)
>>> canonical_coords((I, -2, 0))
(1, 2*I, 0)
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from fractions import Fraction
from functools import lru_cache
from typing import Any

import mpmath
import sympy
from mpmath import iv
from sympy import Add, Basic, Expr, Integer, Mul, Rational
from sympy.printing.latex import LatexPrinter
from sympy.printing.str import StrPrinter

from .errors import InvalidCoordinatesError, NonNumericError, UndecidableError

__all__ = [
    "algebraic_normal_form",
    "all_zero",
    "canonical_coords",
    "format_entry",
    "is_zero",
    "latex",
    "primitive_part",
    "sign",
    "to_exact",
]

Scalar = Any
"""A coordinate: int, Fraction, float (read as the decimal it prints as), or a SymPy expression."""

_X = sympy.Dummy("x")
_DECIDES = (
    "pgsym decides equality exactly only for rational functions over algebraic numbers "
    "(rationals, I, radicals of constants, cos/sin of rational multiples of pi)"
)


# -- coercion ------------------------------------------------------------------------------------
def to_exact(value: Scalar) -> Expr:
    """Convert one coordinate to an exact SymPy expression.

    Integers, fractions and SymPy expressions are kept exactly. A float is read
    as the shortest decimal that prints it (``0.1`` becomes ``1/10``), since the
    exact binary value of a float is rarely what the user meant. Strings, ``None``,
    booleans, NaN and infinities are rejected with :class:`NonNumericError`.

    >>> to_exact(0.25), to_exact(Fraction(2, 6)), to_exact(3), to_exact(1j)
    (1/4, 1/3, 3, I)
    >>> to_exact(1 / ((1 + sympy.sqrt(2)) ** 2 - 3 - 2 * sympy.sqrt(2)))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.NonNumericError: the coordinate ... divides by -3 - 2*sqrt(2) + (1 + sqrt(2))**2, which is zero
    """
    if isinstance(value, bool) or value is None or isinstance(value, (str, bytes)):
        raise NonNumericError(
            f"coordinates must be numbers or SymPy expressions, got {value!r} "
            f"of type {type(value).__name__}; use Fraction('1/2') or sympy.Rational(1, 2) for fractions"
        )
    if isinstance(value, Expr):
        result = value
    elif isinstance(value, numbers.Integral):
        result = Integer(int(value))
    elif isinstance(value, Fraction):
        result = Rational(value.numerator, value.denominator)
    elif isinstance(value, numbers.Real):
        as_float = float(value)
        if not math.isfinite(as_float):
            raise NonNumericError(f"coordinates must be finite, got {value!r}; use an ideal point for directions")
        result = Rational(repr(as_float))
    elif isinstance(value, numbers.Complex):
        result = to_exact(value.real) + sympy.I * to_exact(value.imag)
    else:
        raise NonNumericError(
            f"coordinates must be numbers or SymPy expressions, got {value!r} of type {type(value).__name__}"
        )
    if isinstance(result, sympy.Float):
        return to_exact(float(result))
    if result.has(sympy.nan, sympy.zoo, sympy.oo, -sympy.oo):
        raise NonNumericError(f"coordinates must be finite, got {value!r}; use an ideal point for directions")
    if not result.is_Rational:
        _require_nonzero_denominators(result, value)
    return result


def _require_nonzero_denominators(expr: Expr, value: Any) -> None:
    """Reject a division by zero in disguise, such as ``1/((a + 1)**2 - a**2 - 2*a - 1)``."""
    for power in expr.atoms(sympy.Pow):
        if power.exp.is_negative and not power.base.is_Symbol:
            try:
                zero = is_zero(power.base)
            except UndecidableError:
                continue  # undecidable now, and every later decision on it raises
            if zero:
                raise NonNumericError(f"the coordinate {value!r} divides by {power.base}, which is zero")


# -- the zero test -------------------------------------------------------------------------------
def is_zero(expr: Expr) -> bool:
    """Exact test that an expression vanishes identically (see the module docstring for the rules).

    Raises :class:`~pgsym.errors.UndecidableError` where the answer would be a guess.

    >>> a = sympy.Symbol("a")
    >>> is_zero((a + 1) ** 2 - a**2 - 2 * a - 1), is_zero(a)
    (True, False)
    >>> is_zero(sympy.sqrt(5 + 2*sympy.sqrt(6)) * a - (sympy.sqrt(2) + sympy.sqrt(3)) * a)
    True
    >>> is_zero(sympy.pi - 3)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.UndecidableError: cannot decide whether -3 + pi is zero: pi is not known to be algebraic; ...
    """
    if not isinstance(expr, Basic):
        expr = to_exact(expr)
    if expr.is_Rational:
        return bool(expr == 0)
    # a fraction vanishes iff its numerator expands to zero; no gcd (cancel) needed
    numerator, denominator = sympy.fraction(sympy.together(expr))
    numerator = sympy.expand(numerator)
    if numerator == 0:
        return True
    if _is_rational_polynomial(numerator) and _is_rational_function(denominator):
        return False
    return _is_zero_algebraic(expr, numerator, denominator)


def all_zero(values: Any) -> bool:
    """True when every value is zero (:func:`is_zero`); a nonzero rational entry answers at once.

    Rational entries are looked at first, so a vector such as ``(pi, 1)`` is known to be nonzero
    without deciding anything about ``pi``.

    >>> all_zero([sympy.pi, 1]), all_zero([0, sympy.sqrt(2) * sympy.sqrt(2) - 2])
    (False, True)
    """
    deferred = []
    for v in values:
        if not isinstance(v, Basic):
            v = to_exact(v)
        if v.is_Rational:
            if v.p != 0:
                return False
        else:
            deferred.append(v)
    return all(is_zero(v) for v in deferred)


def _is_rational_polynomial(e: Expr) -> bool:
    """True for an expanded polynomial with rational coefficients (the fast path's domain)."""
    for term in Add.make_args(e):
        for f in Mul.make_args(term):
            if f.is_Rational or f.is_Symbol:
                continue
            if f.is_Pow and f.exp.is_Integer and f.base.is_Symbol:
                continue
            return False
    return True


def _is_rational_function(e: Expr) -> bool:
    """True when ``e`` is built from rationals and symbols by +, ×, integer powers."""
    if e.is_Rational or e.is_Symbol:
        return True
    if e.is_Add or e.is_Mul:
        return all(_is_rational_function(a) for a in e.args)
    if e.is_Pow:
        return bool(e.exp.is_Integer) and _is_rational_function(e.base)
    return False


def _undecidable(expr: Expr, reason: str) -> UndecidableError:
    return UndecidableError(
        f"cannot decide whether {expr} is zero: {reason}; {_DECIDES}. "
        "Substitute rational or algebraic values, or compare numerically"
    )


def _check_algebraic(e: Expr, whole: Expr, under: bool = False) -> None:
    """Raise UndecidableError unless ``e`` is a polynomial in symbols over algebraic numbers.

    ``under`` is True inside a radical or a function, where symbols are not allowed.
    """
    if e.is_Rational or e is sympy.I:
        return
    if e.is_Symbol:
        if under:
            raise _undecidable(whole, f"the symbol {e} is under a radical or function, whose branch depends on {e}")
        return
    if e.is_Add or e.is_Mul:
        for a in e.args:
            _check_algebraic(a, whole, under)
        return
    if e.is_Pow:
        if e.exp.is_Integer:
            _check_algebraic(e.base, whole, under)
            return
        if e.exp.is_Rational:
            _check_algebraic(e.base, whole, True)
            return
        raise _undecidable(whole, f"the power {e} has an exponent that is not rational")
    if isinstance(e, (sympy.cos, sympy.sin, sympy.tan)):
        arg = e.args[0]
        if arg.free_symbols:
            _check_algebraic(arg, whole, True)
        if (arg / sympy.pi).is_Rational:
            return
        raise _undecidable(whole, f"{e} is not known to be algebraic (only rational multiples of pi are)")
    if isinstance(e, sympy.exp):
        arg = e.args[0]
        if arg.free_symbols:
            _check_algebraic(arg, whole, True)
        if (arg / (sympy.I * sympy.pi)).is_Rational:
            return
        raise _undecidable(whole, f"{e} is not known to be algebraic (only exp(I*pi*r), r rational, is)")
    if isinstance(e, (sympy.CRootOf, sympy.AlgebraicNumber)):
        return
    if e.free_symbols:
        raise _undecidable(whole, f"{e} is not a polynomial in its symbols ({type(e).__name__})")
    if isinstance(e, sympy.Float):
        raise _undecidable(whole, f"the float {e} is not exact (use a Rational)")
    raise _undecidable(whole, f"{e} is not known to be algebraic")


def _coefficients(numerator: Expr, whole: Expr) -> list[Expr]:
    """The coefficients (numbers) of an expanded polynomial in its symbols, collected by monomial."""
    groups: dict[tuple[Expr, ...], list[Expr]] = {}
    for term in Add.make_args(numerator):
        coeff, monomial = [], []
        for f in Mul.make_args(term):
            (monomial if f.free_symbols else coeff).append(f)
        for f in monomial:
            if not (f.is_Symbol or (f.is_Pow and f.exp.is_Integer and f.exp > 0 and f.base.is_Symbol)):
                raise _undecidable(whole, f"{f} is not a monomial")
        groups.setdefault(tuple(sorted(monomial, key=sympy.default_sort_key)), []).append(Mul(*coeff))
    return [Add(*terms) for terms in groups.values()]


def _is_zero_algebraic(whole: Expr, numerator: Expr, denominator: Expr) -> bool:
    _check_algebraic(numerator, whole)
    if not _is_rational_function(denominator):
        _check_algebraic(denominator, whole)
        if all(_is_zero_number(c) for c in _coefficients(sympy.expand(denominator), whole)):
            raise InvalidCoordinatesError(f"{whole} has a denominator that is zero: the expression is undefined")
    return all(_is_zero_number(c) for c in _coefficients(numerator, whole))


@lru_cache(maxsize=4096)
def _is_zero_number(c: Expr) -> bool:
    """Exact zero test of an algebraic number (already checked by :func:`_check_algebraic`)."""
    if c.is_Rational:
        return bool(c == 0)
    reduced = _in_one_root(c)
    if reduced is not None:
        return reduced
    for prec in (64, 256):
        box = _interval(c, prec)
        if box is not None and (_excludes_zero(box[0]) or _excludes_zero(box[1])):
            return False
    m = _minimal_polynomial(c)
    return m.degree() == 1 and m.TC() == 0


def _in_one_root(c: Expr) -> bool | None:
    """Zero test of a rational function over ℚ of one indexed root ``r``: reduce modulo r's polynomial.

    ``CRootOf`` keeps an irreducible polynomial, so a polynomial in ``r`` vanishes exactly when its
    remainder by that polynomial does — no minimal polynomial of the whole expression is needed
    (SymPy's takes minutes for complex roots). ``None`` when ``c`` is not of that form.
    """
    roots = c.atoms(sympy.CRootOf)
    if len(roots) != 1:
        return None
    (r,) = roots
    t = sympy.Dummy("t")
    numerator, _ = sympy.fraction(sympy.together(c.xreplace({r: t})))
    try:
        p = sympy.Poly(numerator, t, domain="QQ")
    except sympy.polys.polyerrors.PolynomialError:
        return None
    return (p.rem(sympy.Poly(r.poly.as_expr(), r.poly.gen).replace(r.poly.gen, t))).is_zero


def _minimal_polynomial(c: Expr) -> sympy.Poly:
    try:
        return sympy.minimal_polynomial(c, _X, polys=True)
    except (NotImplementedError, ValueError, sympy.polys.polyerrors.PolynomialError) as err:
        raise _undecidable(c, f"its minimal polynomial could not be computed ({err})") from err


# -- rigorous interval evaluation ----------------------------------------------------------------
def _excludes_zero(x: Any) -> bool:
    return bool(x.a > 0) or bool(x.b < 0)


def _interval(c: Expr, prec: int) -> tuple[Any, Any] | None:
    """Boxes (real part, imaginary part) that certainly contain ``c``, or None where not supported."""
    old = iv.prec
    iv.prec = prec
    try:
        return _iv(c, iv)
    except (ZeroDivisionError, ValueError, TypeError, ArithmeticError):
        return None
    finally:
        iv.prec = old


def _iv(e: Expr, iv: Any) -> tuple[Any, Any] | None:
    zero = iv.mpf(0)
    if e.is_Rational:
        return iv.mpf(int(e.p)) / int(e.q), zero
    if e is sympy.I:
        return zero, iv.mpf(1)
    if e.is_Add or e.is_Mul:
        parts = [_iv(a, iv) for a in e.args]
        if any(p is None for p in parts):
            return None
        re, im = parts[0]
        for r2, i2 in parts[1:]:
            if e.is_Add:
                re, im = re + r2, im + i2
            else:
                re, im = re * r2 - im * i2, re * i2 + im * r2
        return re, im
    if e.is_Pow:
        base = _iv(e.base, iv)
        if base is None:
            return None
        if e.exp.is_Integer:
            return _iv_power(base, int(e.exp), iv)
        if e.exp.is_Rational:
            p, q = int(e.exp.p), int(e.exp.q)
            re, im = base
            if im.a == 0 and im.b == 0 and re.a > 0:
                return _iv_power((iv.exp(iv.log(re) / q), zero), p, iv)
            if q == 2:
                return _iv_power(_iv_sqrt(re, im, iv), p, iv)
        return None
    if isinstance(e, (sympy.cos, sympy.sin, sympy.tan)):
        t = e.args[0] / sympy.pi
        if not t.is_Rational:
            return None
        angle = iv.pi * iv.mpf(int(t.p)) / int(t.q)
        f = {sympy.cos: iv.cos, sympy.sin: iv.sin}.get(type(e))
        return (f(angle), zero) if f else (iv.sin(angle) / iv.cos(angle), zero)
    if isinstance(e, sympy.CRootOf):
        return _iv_root(e, iv)
    if isinstance(e, sympy.exp):
        t = e.args[0] / (sympy.I * sympy.pi)
        if not t.is_Rational:
            return None
        angle = iv.pi * iv.mpf(int(t.p)) / int(t.q)
        return iv.cos(angle), iv.sin(angle)
    return None


def _iv_root(r: sympy.CRootOf, iv: Any) -> tuple[Any, Any]:
    """A box around an indexed root from SymPy's own isolating interval, refined to the working precision.

    The interval is rigorous (exact rational endpoints), so no minimal polynomial is needed to tell a
    nonzero expression in complex roots from zero (that computation can take minutes).
    """
    r.eval_rational(n=int(iv.prec * 0.302) + 2)  # refines the cached isolating interval in place
    box = r._get_interval()

    def hull(a: sympy.Rational, b: sympy.Rational) -> Any:
        lo, hi = iv.mpf(int(a.p)) / int(a.q), iv.mpf(int(b.p)) / int(b.q)
        return iv.mpf([lo.a, hi.b])

    if r.is_real:
        return hull(box.a, box.b), iv.mpf(0)
    return hull(box.ax, box.bx), hull(box.ay, box.by)


def _iv_power(z: tuple[Any, Any], n: int, iv: Any) -> tuple[Any, Any]:
    re, im = z
    if n < 0:
        norm = re * re + im * im
        if not _excludes_zero(norm):
            raise ZeroDivisionError
        re, im, n = re / norm, -im / norm, -n
    out = (iv.mpf(1), iv.mpf(0))
    for _ in range(n):
        out = (out[0] * re - out[1] * im, out[0] * im + out[1] * re)
    return out


def _iv_sqrt(re: Any, im: Any, iv: Any) -> tuple[Any, Any]:
    """The principal square root, where the sign of the imaginary part is certain."""
    if im.a == 0 and im.b == 0:
        if re.a >= 0:
            return iv.sqrt(re), iv.mpf(0)
        if re.b <= 0:
            return iv.mpf(0), iv.sqrt(-re)
        raise ValueError("branch")
    if not _excludes_zero(im):
        raise ValueError("branch")
    modulus = iv.sqrt(re * re + im * im)
    real = iv.sqrt((modulus + re) / 2)
    imag = iv.sqrt((modulus - re) / 2)
    return real, (imag if im.a > 0 else -imag)


# -- signs ---------------------------------------------------------------------------------------
def sign(expr: Expr) -> int:
    """The sign (-1, 0 or 1) of a real algebraic number, decided exactly.

    Raises :class:`~pgsym.errors.UndecidableError` for symbolic, non-real or
    non-algebraic input, instead of SymPy's ``TypeError``.

    >>> sign(sympy.sqrt(3) - sympy.Rational(17, 10)), sign(sympy.cos(sympy.pi / 5) - sympy.Rational(1, 4))
    (1, 1)
    >>> sign(1 + sympy.I)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    pgsym.errors.UndecidableError: 1 + I is not a real number, so it has no sign...
    """
    expr = to_exact(expr) if not isinstance(expr, Basic) else expr
    if expr.is_Rational:
        return (expr.p > 0) - (expr.p < 0)
    if expr.free_symbols:
        raise UndecidableError(f"the sign of {expr} depends on its symbols; substitute values first")
    if is_zero(expr):
        return 0
    _check_algebraic(expr, expr)
    for prec in (64, 256, 1024, 4096):
        box = _interval(expr, prec)
        if box is None:
            break
        re, im = box
        if _excludes_zero(im):
            raise UndecidableError(f"{expr} is not a real number, so it has no sign (it cannot be compared with 0)")
        if _excludes_zero(re):
            if not is_zero(sympy.im(expr)):
                raise UndecidableError(f"{expr} is not a real number, so it has no sign")
            return 1 if re.a > 0 else -1
    raise UndecidableError(f"cannot decide the sign of {expr}; {_DECIDES}")


# -- the normal form of an algebraic number ------------------------------------------------------
@lru_cache(maxsize=4096)
def algebraic_normal_form(c: Expr) -> Expr:
    """The normal form of an algebraic number: equal numbers get identical expressions.

    Rationals stay; a number of degree 2 over ℚ becomes ``a + b*sqrt(d)`` with ``d`` a
    squarefree integer (``sqrt(-3) = sqrt(3)*I``); higher degrees become
    ``CRootOf(minimal polynomial, index)``.

    >>> algebraic_normal_form(sympy.sqrt(3 + 2*sympy.sqrt(2))), algebraic_normal_form(sympy.cos(sympy.pi / 6))
    (1 + sqrt(2), sqrt(3)/2)
    """
    c = sympy.sympify(c)
    if c.is_Rational:
        return c
    _check_algebraic(c, c)
    if c.free_symbols:
        raise UndecidableError(f"{c} is not a number")
    m = _minimal_polynomial(c)
    coeffs = [int(k) for k in m.all_coeffs()]
    if m.degree() == 1:
        return Rational(-coeffs[1], coeffs[0])
    if m.degree() == 2:
        a, b, cc = coeffs
        root = sympy.sqrt(Integer(b * b - 4 * a * cc))
        candidates = [sympy.expand((-b + s * root) / (2 * a)) for s in (1, -1)]
    else:
        candidates = _conjugates(m)
    return _match(c, candidates)


def _conjugates(m: sympy.Poly) -> list[Expr]:
    """All roots of an irreducible ``m`` of degree ≥ 3, each in one deterministic form.

    Radicals where SymPy finds them by factoring, decomposition or for binomials and cyclotomic
    polynomials; ``CRootOf`` when all roots are real (their isolation is fast); the cubic and quartic
    formulas otherwise. Complex roots of higher degree without radicals have no normal form here.
    """
    found = sympy.roots(m, cubics=False, quartics=False, multiple=True)
    if len(found) == m.degree():
        return found
    if m.count_roots() == m.degree():
        poly = sympy.Poly(m.as_expr(_X).subs(_X, sympy.Symbol("x")), sympy.Symbol("x"))
        return [sympy.CRootOf(poly, k) for k in range(m.degree())]
    found = sympy.roots(m, multiple=True) if m.degree() <= 4 else []
    if len(found) == m.degree():
        return found
    raise UndecidableError(
        f"no normal form for the roots of {m.as_expr()}: they are not all real and have no radical form"
    )


def _match(c: Expr, candidates: list[Expr]) -> Expr:
    """The one candidate equal to ``c``: the conjugates are distinct roots of one irreducible polynomial,
    so the candidate nearest to a rigorous box around ``c`` is ``c`` once the box is far smaller than
    their separation."""
    with mpmath.workdps(60):
        values = [mpmath.mpc(*(mpmath.mpf(str(part)) for part in cand.evalf(60).as_real_imag()))
                  for cand in candidates]
        gap = min(abs(u - v) for i, u in enumerate(values) for v in values[i + 1:])
        for prec in (64, 256, 1024):
            box = _interval(c, prec)
            if box is None:
                break
            (re_lo, re_hi), (im_lo, im_hi) = (tuple(mpmath.mpf(e) for e in part._mpi_) for part in box)
            if max(re_hi - re_lo, im_hi - im_lo) * 4 < gap:
                centre = mpmath.mpc((re_lo + re_hi) / 2, (im_lo + im_hi) / 2)
                near = [cand for cand, v in zip(candidates, values, strict=True) if abs(v - centre) < gap / 2]
                if len(near) == 1:
                    return near[0]
    hits = [cand for cand in candidates if _is_zero_number(sympy.expand(c - cand))]
    if len(hits) != 1:
        raise _undecidable(c, "its conjugates could not be told apart")
    return hits[0]


# -- canonical form ------------------------------------------------------------------------------
def canonical_coords(coords: Sequence[Expr], keep_sign: bool = False) -> tuple[Expr, ...]:
    """The canonical representative of a nonzero homogeneous vector (rules in the module docstring).

    ``keep_sign`` skips the sign step of rules 1 and 2: the result is then the primitive vector
    reached by a *positive* factor (a basis vector of a null space keeps its direction).

    >>> a = sympy.Symbol("a")
    >>> canonical_coords((Rational(1, 2), Rational(-1, 3), 0)), canonical_coords((-2 * a, 4 * a**2))
    ((3, -2, 0), (1, -2*a))
    >>> canonical_coords((Rational(-1, 2), Rational(1, 3), 0), keep_sign=True)
    (-3, 2, 0)
    """
    coords = [sympy.together(c) for c in coords]
    if all(c.is_Rational for c in coords):
        return _canonical_rational(coords, keep_sign)
    if all(_is_rational_function(c) for c in coords):
        return _canonical_polynomial(coords, keep_sign)
    return _canonical_algebraic(coords, keep_sign)


def _canonical_rational(coords: list[Expr], keep_sign: bool = False) -> tuple[Expr, ...]:
    denominator = sympy.ilcm(*[c.q for c in coords]) if len(coords) > 1 else coords[0].q
    ints = [int(c * denominator) for c in coords]
    content = math.gcd(*ints) or 1
    ints = [i // content for i in ints]
    sgn = -1 if not keep_sign and next((i for i in ints if i != 0), 0) < 0 else 1
    return tuple(Integer(sgn * i) for i in ints)


def _canonical_polynomial(coords: list[Expr], keep_sign: bool = False) -> tuple[Expr, ...]:
    numerators, denominators = zip(*(sympy.fraction(c) for c in coords), strict=False)
    common = sympy.lcm_list(list(denominators))
    polys = [sympy.expand(sympy.cancel(n * common / d)) for n, d in zip(numerators, denominators, strict=False)]
    content = sympy.gcd_list([p for p in polys if p != 0])
    polys = [sympy.expand(sympy.cancel(p / content)) for p in polys]
    lead = next(p for p in polys if p != 0)
    if not keep_sign and sympy.Poly(lead, *sorted(lead.free_symbols, key=str) or [sympy.Symbol("_")]).LC() < 0:
        polys = [-p for p in polys]
    return tuple(polys)


def _canonical_algebraic(coords: list[Expr], keep_sign: bool = False) -> tuple[Expr, ...]:
    for c in coords:
        numerator, denominator = sympy.fraction(c)
        _check_algebraic(numerator, c)
        _check_algebraic(denominator, c)
    symbols = sorted(set().union(*(c.free_symbols for c in coords)), key=str)
    if not symbols:
        k = next(i for i, c in enumerate(coords) if not is_zero(c))
        out = [Integer(1) if i == k else (Integer(0) if is_zero(c) else algebraic_normal_form(sympy.expand(
            sympy.radsimp(c / coords[k])))) for i, c in enumerate(coords)]
    else:
        out = _canonical_algebraic_polynomials(coords, symbols)
    return canonical_coords(out, keep_sign) if all(_is_rational_function(c) for c in out) else tuple(out)


def primitive_part(numerators: Sequence[Any], denominators: Sequence[Any] | None = None) -> list[Any]:
    """The polynomial vector ``n_i / d_i`` with the denominators cleared and the content (gcd) removed.

    Works for the elements of any polynomial ring with ``lcm``, ``gcd`` and ``exquo`` (SymPy's
    ``Poly`` and ``PolyElement``). A homogeneous object is defined up to scale, so the common
    factor carries no information; this is the one primitive form of polynomial vectors of the
    core (:func:`canonical_coords` over number fields, the invariant proofs). The sign (unit) is
    left as it comes; the zero vector is returned unchanged.

    >>> from sympy.polys.rings import ring
    >>> R, a, b = ring("a, b", sympy.ZZ)
    >>> primitive_part([2 * a * b, 4 * a], [R(1), b])     # (2ab, 4a/b) = (2a/b)(b², 2)
    [b**2, 2]
    """
    nums = list(numerators)
    if denominators is not None:
        dens = list(denominators)
        common = dens[0]
        for d in dens[1:]:
            if d != common:
                common = common.lcm(d)
        nums = [n * common.exquo(d) for n, d in zip(nums, dens, strict=True)]
    content = None
    for p in nums:
        if p:
            content = p if content is None else content.gcd(p)
    return nums if content is None else [p.exquo(content) for p in nums]


def _canonical_algebraic_polynomials(coords: list[Expr], symbols: list[sympy.Symbol]) -> list[Expr]:
    """Rule 3 with symbols: polynomials over the number field, content removed, first one monic."""
    fractions = [sympy.fraction(c) for c in coords]
    exprs = [sympy.expand(n) for n, _ in fractions] + [sympy.expand(d) for _, d in fractions]
    try:
        polys, _ = sympy.parallel_poly_from_expr(exprs, *symbols, extension=True)
    except (sympy.polys.polyerrors.PolynomialError, NotImplementedError) as err:
        raise _undecidable(sympy.Tuple(*coords), f"its number field could not be built ({err})") from err
    n = len(coords)
    vec = primitive_part(polys[:n], polys[n:])
    lead = next(p for p in vec if not p.is_zero)
    domain = lead.domain
    lc = domain.from_sympy(lead.LC())
    out = []
    for p in vec:
        terms = []
        for monom, coeff in p.terms():
            value = algebraic_normal_form(sympy.expand(domain.to_sympy(domain.quo(domain.from_sympy(coeff), lc))))
            terms.append(value * Mul(*(s**e for s, e in zip(symbols, monom, strict=True))))
        out.append(sympy.expand(Add(*terms)))
    return out


# -- printing ------------------------------------------------------------------------------------
_SHORT_BITS = 13000  # below 3914 decimal digits: int ↔ str is allowed (Python refuses more than 4300)


def decimal_digits(n: int) -> str:
    """The decimal digits of any integer, also past Python's int-to-str limit (split in halves).

    >>> decimal_digits(-10**5000)[:4], len(decimal_digits(10**5000))
    ('-100', 5001)
    """
    if n < 0:
        return "-" + decimal_digits(-n)
    if n.bit_length() < _SHORT_BITS:
        return str(n)
    half = int(n.bit_length() * 0.30103) // 2
    high, low = divmod(n, 10**half)
    return decimal_digits(high) + decimal_digits(low).rjust(half, "0")


def _int_source(n: int) -> str:
    """Python source for an integer: decimal when short, hexadecimal (not length-limited) when long."""
    if n.bit_length() < _SHORT_BITS:
        return str(n)
    return f"-{-n:#x}" if n < 0 else f"{n:#x}"


class _ReprPrinter(StrPrinter):
    """Prints fractions as ``S(1)/2`` so that ``repr`` evaluates back to exact numbers."""

    def _print_Integer(self, expr: Integer) -> str:
        return _int_source(int(expr.p))

    def _print_Rational(self, expr: Rational) -> str:
        return f"S({_int_source(int(expr.p))})/{_int_source(int(expr.q))}"


class _LatexPrinter(LatexPrinter):
    """SymPy's LaTeX printer (byte-for-byte) with integers of any length."""

    def _print_int(self, expr: int) -> str:
        return decimal_digits(expr)

    def _print_Rational(self, expr: Rational) -> str:
        if expr.q == 1 or max(abs(int(expr.p)), int(expr.q)).bit_length() < _SHORT_BITS:
            return super()._print_Rational(expr)
        sgn = "- " if expr.p < 0 else ""
        p, q = decimal_digits(abs(int(expr.p))), decimal_digits(int(expr.q))
        if self._settings["fold_short_frac"]:
            return f"{sgn}{p} / {q}"
        return sgn + r"\frac{" + p + "}{" + q + "}"


def format_entry(entry: Expr) -> str:
    """The Python source of one coordinate, so that ``repr`` round-trips (``S`` is ``sympy.S``).

    >>> format_entry(Rational(-1, 2)), format_entry(Integer(2) ** 20000)[:6]
    ('S(-1)/2', '0x1000')
    """
    return _ReprPrinter().doprint(entry)


def latex(expr: Any, **settings: Any) -> str:
    """LaTeX of an expression or matrix, as ``sympy.latex`` (same settings) with integers of any length.

    >>> latex(Rational(1, 2)), latex(sympy.Matrix([[1, 2]]), mat_delim="[")
    ('\\\\frac{1}{2}', '\\\\left[\\\\begin{matrix}1 & 2\\\\end{matrix}\\\\right]')
    """
    return _LatexPrinter(settings).doprint(expr)
