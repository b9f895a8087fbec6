"""Verdicts: proved (with certificate and conditions), false (with a counterexample) or unknown (with why).

>>> v = Verdict("demo", "a demo", "proved", method="polynomial identity")
>>> v.proved, v.to_dict()["status"]
(True, 'proved')
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from enum import StrEnum
from fractions import Fraction
from typing import Any

from ..escaping import md_code, md_escape, tex_escape

__all__ = ["Certificate", "Condition", "Counterexample", "Status", "Verdict"]


class Status(StrEnum):
    """The outcome of a proof; a member equals, prints and shows as its value.

    >>> Status.PROVED == "proved", f"{Status.FALSE}", Status("unknown") is Status.UNKNOWN
    (True, 'false', True)
    >>> Status.PROVED
    'proved'
    """

    PROVED = "proved"
    FALSE = "false"
    UNKNOWN = "unknown"
    DEGENERATE = "degenerate"

    def __repr__(self) -> str:  # shown as the plain string it was before statuses were an enum
        return repr(self.value)


_STATUS_MARK = {Status.PROVED: "✔ proved", Status.FALSE: "✘ false", Status.UNKNOWN: "? unknown",
                Status.DEGENERATE: "⚠ degenerate construction"}
_STATUS_LATEX = {s: rf"\text{{{s.value}}}" for s in Status}

_INLINE_CONDITIONS = 3
"""The most non-degeneracy conditions a verdict writes on one line; a longer list is written one per line."""


# the engine's few math symbols as LaTeX commands; everything else is escaped as plain text
_TEX_MATH = {"≠": r"$\neq$", "×": r"$\times$", "·": r"$\cdot$", "∧": r"$\wedge$", "−": "-", "λ": r"$\lambda$",
             "ᵀ": r"$^{\top}$", "…": r"\dots{}", "²": r"$^2$", "³": r"$^3$", "¹": r"$^1$", "⁶": r"$^6$",
             "ℚ": r"$\mathbb{Q}$", "ℤ": r"$\mathbb{Z}$", "∞": r"$\infty$", "′": "'", "—": "---", "–": "--"}
_TEX_MATH_SPLIT = re.compile("([" + "".join(_TEX_MATH) + "])")


def _tex(text: str) -> str:
    """Plain text as pdfLaTeX source (:func:`~pgsym.escaping.tex_escape`), the engine's math symbols as commands."""
    return "".join(_TEX_MATH.get(piece) or tex_escape(piece) for piece in _TEX_MATH_SPLIT.split(str(text)))


def _short(text: str, limit: int = 90) -> str:
    return text if len(text) <= limit else text[: limit - 1] + "…"


def poly_str(p: Any, max_terms: int = 40) -> str:
    """A polynomial as text; very long ones are summarised by degree and number of terms.

    >>> poly_str(3)
    '3'
    """
    if hasattr(p, "terms") and len(p) > max_terms:
        return f"<a polynomial of degree {max(sum(m) for m in p.monoms())} with {len(p)} terms>"
    if hasattr(p, "as_expr"):  # SymPy's ring
        return str(p.as_expr())
    if hasattr(p, "context"):  # python-flint: rebuild the expression in the context's variable names
        import sympy  # noqa: PLC0415 — the CLI imports verdicts at start-up; SymPy loads when one is shown


        names = [sympy.Symbol(n) for n in p.context().names()]
        return str(sympy.Add(*(sympy.Rational(str(c)) * sympy.Mul(*(x**e for x, e in zip(names, m, strict=True)))
                               for m, c in p.to_dict().items())))
    return str(p)


@dataclass
class Condition:
    """A non-degeneracy condition: readable text, and polynomials not all of which may vanish.

    ``raw`` holds the polynomials themselves; :attr:`polynomials` gives them as text.
    """

    text: str
    raw: list[Any] = field(default_factory=list, repr=False)

    @property
    def polynomials(self) -> list[str]:
        """The condition's polynomials as text (not all of them may vanish)."""
        return [poly_str(p, 12) for p in self.raw]

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form (very long polynomials are summarised).

        >>> Condition("A ≠ B", ["a - b"]).to_dict()  # raw polynomials, shown as text
        {'text': 'A ≠ B', 'not_all_zero': ['a - b']}
        """
        return {"text": self.text, "not_all_zero": [p if len(p) <= 400 else _short(p, 400) for p in self.polynomials]}


@dataclass
class Certificate:
    """How the conclusion was reduced to zero: the method, the ring and one line per checked polynomial."""

    method: str
    ring: str = ""
    steps: list[str] = field(default_factory=list)
    largest_terms: int = 0
    normalisation: str = ""
    backend: str = ""
    largest_degree: int = 0

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form.

        >>> Certificate("polynomial identity", "QQ[a]", ["a - a → 0"]).to_dict()["steps"]
        ['a - a → 0']
        """
        return {"method": self.method, "ring": self.ring, "steps": self.steps, "largest_terms": self.largest_terms,
                "largest_degree": self.largest_degree, "normalisation": self.normalisation, "backend": self.backend}


@dataclass
class Counterexample:
    """Exact values of the parameters at which the constructions are defined and the conclusion fails.

    ``residuals`` are the values of the conclusion polynomials there (not all zero). ``check`` is the prover's
    own re-check of these values (it builds the configuration again with pgsym's core objects); the verdict
    only holds it, so that this data module never imports a prover.
    """

    values: dict[str, Fraction]
    residuals: list[Fraction]
    claim: Any = None
    branch: dict[str, str] = field(default_factory=dict)  # exact values of the claim's square roots, if any
    check: Callable[[], bool] | None = field(default=None, repr=False, compare=False)

    def substitution(self) -> dict[Any, Any]:
        """The values as a SymPy substitution ``{symbol: Rational}``.

        >>> Counterexample({"a": Fraction(1, 2)}, [Fraction(1)]).substitution()
        {a: 1/2}
        """
        import sympy  # noqa: PLC0415 — the CLI imports verdicts at start-up; SymPy loads when one is shown

        return {sympy.Symbol(k): sympy.Rational(v.numerator, v.denominator) for k, v in self.values.items()}

    def recheck(self) -> bool:
        """Rebuild with the core objects at these values: True when the claim indeed fails there.

        >>> Counterexample({"a": Fraction(1)}, [Fraction(1)], check=lambda: True).recheck()
        True
        >>> Counterexample({"a": Fraction(1)}, [Fraction(1)]).recheck()  # no prover attached: nothing confirmed
        False
        """
        return self.check is not None and bool(self.check())

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready form (fractions as strings).

        >>> Counterexample({"a": Fraction(1, 2)}, [Fraction(3)]).to_dict()
        {'values': {'a': '1/2'}, 'residuals': ['3']}
        """
        out = {"values": {k: str(v) for k, v in self.values.items()}, "residuals": [str(r) for r in self.residuals]}
        if self.branch:
            out["branch"] = dict(self.branch)
        return out


@dataclass
class Verdict:
    """The result of proving a claim.

    ``status`` is ``"proved"`` (generically true: the conclusion polynomials
    vanish identically wherever the listed conditions hold), ``"false"`` (an exact
    counterexample is attached) or ``"unknown"`` (``reason`` says why, e.g. a
    timeout). A random evaluation never proves by itself: ``random_pass`` only
    reports what it found.
    """

    name: str
    title: str
    status: Status
    method: str = ""
    statement: str = ""
    conclusion: list[str] = field(default_factory=list)
    constructions: list[tuple[str, str, str]] = field(default_factory=list)
    hypotheses: list[str] = field(default_factory=list)
    conditions: list[Condition] = field(default_factory=list)
    certificate: Certificate | None = None
    counterexample: Counterexample | None = None
    reason: str = ""
    random_pass: str = ""
    core_check: str = ""
    expected: bool = True
    elapsed: float = 0.0
    branches: str = ""  # claims with square roots: which choices of root the verdict covers

    def __post_init__(self) -> None:
        self.status = Status(self.status)  # a plain string is accepted and checked

    @property
    def proved(self) -> bool:
        """True exactly when the status is ``"proved"``."""
        return self.status is Status.PROVED

    @property
    def refuted(self) -> bool:
        """True exactly when the status is ``"false"`` (a counterexample is attached)."""
        return self.status is Status.FALSE

    @property
    def as_expected(self) -> bool:
        """A true claim proved, or a false claim refuted.

        >>> Verdict("x", "x", "false", expected=False).as_expected
        True
        """
        return self.proved if self.expected else self.refuted

    def __repr__(self) -> str:
        return f"<Verdict {self.name}: {self.status}>"

    # -- serialisation -----------------------------------------------------------
    def to_dict(self, timing: bool = True) -> dict[str, Any]:
        """A JSON-ready dictionary (``timing=False`` leaves out the elapsed time)."""
        out: dict[str, Any] = {
            "name": self.name,
            "title": self.title,
            "status": str(self.status),
            "expected": "true" if self.expected else "false",
            "as_expected": self.as_expected,
            "statement": self.statement,
            "method": self.method,
            "hypotheses": self.hypotheses,
            "conclusion": self.conclusion,
            "conditions": [c.to_dict() for c in self.conditions],
            "certificate": None if self.certificate is None else self.certificate.to_dict(),
            "counterexample": None if self.counterexample is None else self.counterexample.to_dict(),
            "reason": self.reason,
            "random_pass": self.random_pass,
            "core_check": self.core_check,
        }
        if self.branches:
            out["branches"] = self.branches
        if timing:
            out["elapsed_ms"] = round(1000 * self.elapsed, 2)
        return out

    def to_json(self, timing: bool = True, **kwargs: Any) -> str:
        """The verdict as a JSON string."""
        return json.dumps(self.to_dict(timing), ensure_ascii=False, **kwargs)

    # -- display -----------------------------------------------------------------
    def identity_size(self) -> str:
        """How big the certified identity is, in words ("" when there is no certificate).

        The polynomial library that did the arithmetic is no part of the proof: it stays in :meth:`to_dict`
        (``certificate.backend``) and is not shown here.

        >>> Verdict("x", "x", "proved", certificate=Certificate("m", "ℤ[a]", [], 12, largest_degree=3,
        ...                                                     backend="flint")).identity_size()
        'largest polynomial expanded: 12 terms of degree 3 in ℤ[a]'
        """
        c = self.certificate
        if c is None:
            return ""
        return f"largest polynomial expanded: {c.largest_terms} terms of degree {c.largest_degree} in {c.ring}"

    def condition_texts(self) -> list[str]:
        """The conditions in words, each once (several constructions may need the same one, e.g. "P is a finite
        point"), in the order of the claim.

        >>> Verdict("x", "x", "proved", conditions=[Condition("A ≠ B"), Condition("C ≠ D"), Condition("A ≠ B")]
        ...         ).condition_texts()
        ['A ≠ B', 'C ≠ D']
        """
        return list(dict.fromkeys(c.text for c in self.conditions))

    def summary(self) -> str:
        """Plain text for a terminal: the verdict, the normalisation, the method, the size, the conditions.

        >>> print(Verdict("x", "A demo", "unknown", reason="timed out").summary())
        A demo: unknown
          why: timed out
        """
        lines = [f"{self.title}: {self.status}" + (f" by {self.method}" if self.method else "")]
        if self.certificate is not None:
            if self.certificate.normalisation:
                lines.append(f"  normalisation: {self.certificate.normalisation}")
            lines.append(f"  {self.identity_size()}")
        if self.conditions:
            texts = self.condition_texts()
            if len(texts) > _INLINE_CONDITIONS:
                lines += ["  provided that:", *(f"    - {t}" for t in texts)]
            else:
                lines.append("  provided that: " + "; ".join(texts))
        if self.counterexample is not None:
            lines.append("  counterexample: " + ", ".join(f"{k} = {v}" for k, v in self.counterexample.values.items()))
            branch = self.counterexample.branch
            if branch:
                lines.append("  on the roots: " + ", ".join(f"{k} = {v}" for k, v in branch.items()))
        if self.branches:
            lines.append(f"  roots: {self.branches}")
        if self.reason:
            lines.append(f"  why: {self.reason}")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()

    def to_markdown(self, timing: bool = True) -> str:
        """A short derivation in Markdown: statement, constructions, conclusion, normalisation, certificate,
        conditions, verdict. Every text that comes from the claim is escaped, so it shows as written.

        >>> print(Verdict("x", "50% *of* A_1", "unknown").to_markdown(timing=False).splitlines()[0])
        **50% \\*of\\* A\\_1** (`x`): **? unknown**
        """
        e = md_escape
        lines = [f"**{e(self.title)}** ({md_code(self.name)}): **{_STATUS_MARK[self.status]}**", ""]
        if self.statement and self.statement != self.title:
            lines += [f"*Claim.* {e(self.statement)}", ""]
        if self.constructions:
            lines.append("*Constructions:*")
            lines += [f"- {e(name)} ({kind}) = {e(_short(desc, 100))}" for name, kind, desc in self.constructions]
            lines.append("")
        if self.hypotheses:
            lines += ["*Hypotheses:* " + "; ".join(e(h) for h in self.hypotheses), ""]
        lines += ["*Conclusion:* " + "; ".join(e(c) for c in self.conclusion), ""]
        if self.certificate is not None:
            if self.certificate.normalisation:
                lines += [f"*Normalisation:* {e(self.certificate.normalisation)}", ""]
            lines.append(f"*Certificate* ({e(self.certificate.method)}, in {e(self.certificate.ring)}):")
            lines += [f"- {md_code(_short(s, 160))}" for s in self.certificate.steps[:8]]
            if len(self.certificate.steps) > 8:
                lines.append(f"- … and {len(self.certificate.steps) - 8} more polynomials, each reduced to 0")
            lines += [f"- {e(self.identity_size())}", ""]
        if self.conditions:
            texts = self.condition_texts()
            if len(texts) > _INLINE_CONDITIONS:
                lines += ["*Non-degeneracy conditions:*", *(f"- {e(t)}" for t in texts)]
            else:
                lines.append("*Non-degeneracy conditions:* " + "; ".join(e(t) for t in texts))
            lines.append("")
        if self.counterexample is not None:
            vals = ", ".join(f"{e(k)} = {v}" for k, v in self.counterexample.values.items())
            lines += [f"*Counterexample:* {vals}", "",
                      "*Residual (should be 0):* "
                      + ", ".join(_short(str(r), 40) for r in self.counterexample.residuals[:4]),
                      ""]
        if self.branches:
            lines += [f"*Roots:* {e(self.branches)}", ""]
        if self.reason:
            lines += [f"*Why:* {e(self.reason)}", ""]
        if timing:
            lines.append(f"*Time:* {1000 * self.elapsed:.1f} ms")
        return "\n".join(lines).rstrip() + "\n"

    markdown = to_markdown

    def _repr_markdown_(self) -> str:
        return self.to_markdown(timing=True)

    def to_latex(self, timing: bool = False) -> str:
        """The derivation as a LaTeX fragment (for the book's PDF): every text from the claim escaped.

        >>> print(Verdict("x", "100% & A_1", "proved", conditions=[Condition("A ≠ B")]).to_latex())
        \\paragraph{100\\% \\& A\\_1} \\textbf{proved}.
        \\begin{itemize}
        \\item Non-degeneracy conditions: A $\\neq$ B
        \\end{itemize}
        """
        t = _tex
        items = []
        if self.statement and self.statement != self.title:
            items.append(f"Claim: {t(self.statement)}")
        if self.hypotheses:
            items.append("Hypotheses: " + "; ".join(t(h) for h in self.hypotheses))
        if self.conclusion:
            items.append("Conclusion: " + "; ".join(t(c) for c in self.conclusion))
        if self.certificate is not None:
            if self.certificate.normalisation:
                items.append(f"Normalisation: {t(self.certificate.normalisation)}")
            items.append(f"Method: {t(self.certificate.method)}; {t(self.identity_size())}")
            items += [r"\texttt{" + t(_short(s, 120)) + "}" for s in self.certificate.steps[:4]]
        if self.conditions:
            texts = self.condition_texts()
            if len(texts) > _INLINE_CONDITIONS:
                items.append("Non-degeneracy conditions:\n" + "\n".join(
                    [r"\begin{itemize}", *(rf"\item {t(x)}" for x in texts), r"\end{itemize}"]))
            else:
                items.append("Non-degeneracy conditions: " + "; ".join(t(x) for x in texts))
        if self.counterexample is not None:
            items.append("Counterexample: " + ", ".join(f"{t(k)} = {t(str(v))}"
                                                         for k, v in self.counterexample.values.items()))
        if self.branches:
            items.append(f"Roots: {t(self.branches)}")
        if self.reason:
            items.append(f"Why: {t(self.reason)}")
        if timing:
            items.append(f"Time: {1000 * self.elapsed:.1f} ms")
        lines = [rf"\paragraph{{{t(self.title)}}} \textbf{{{self.status.value}}}."]
        if items:
            lines += [r"\begin{itemize}", *(rf"\item {i}" for i in items), r"\end{itemize}"]
        return "\n".join(lines)

    def latex(self) -> str:
        """A one-line LaTeX summary (status, statement and the number of conditions)."""
        word = _STATUS_LATEX[self.status]
        return rf"$\text{{{_tex(self.title)}}}:\ {word}\ \ (\text{{{len(self.conditions)} non-degeneracy conditions}})$"

    def _repr_latex_(self) -> str:
        return self.latex()
