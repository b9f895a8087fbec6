"""The small text format of exercises: Markdown prose with ``**bold**``, inline math ``$...$`` and
display math ``$$...$$``; conversions to HTML and LaTeX.

>>> split_math("Let $x = 1$ and $$y$$.")
[('text', 'Let '), ('math', 'x = 1'), ('text', ' and '), ('display', 'y'), ('text', '.')]
>>> to_tex("50% of **all** $x_1$")
'50\\\\% of \\\\textbf{all} $x_1$'
"""

from __future__ import annotations

import html
import re

_MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$", re.S)
_BOLD = re.compile(r"\*\*(.+?)\*\*")

_TEX_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "#": r"\#", "_": r"\_", "{": r"\{", "}": r"\}",
                "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "$": r"\$"}
_TEX_UNICODE = {"⊂": r"$\subset$", "↔": r"$\leftrightarrow$", "×": r"$\times$", "→": r"$\to$", "≠": r"$\neq$",
                "−": "-", "…": r"\dots{}", "’": "'"}


def split_math(text: str) -> list[tuple[str, str]]:
    """Split into ('text' | 'math' | 'display', content) segments."""
    out: list[tuple[str, str]] = []
    pos = 0
    for m in _MATH.finditer(text):
        if m.start() > pos:
            out.append(("text", text[pos:m.start()]))
        out.append(("display", m.group(1)) if m.group(1) is not None else ("math", m.group(2)))
        pos = m.end()
    if pos < len(text):
        out.append(("text", text[pos:]))
    return out


def _tex_char(c: str) -> str:
    if c in _TEX_SPECIAL:
        return _TEX_SPECIAL[c]
    if c in _TEX_UNICODE:
        return _TEX_UNICODE[c]
    # pdfLaTeX with T1 fonts typesets Latin-1; anything else (CJK, emoji, control characters) becomes '?'
    return c if (" " <= c <= "~") or ("\u00a0" <= c <= "\u00ff") else "?"


def _tex_text(text: str) -> str:
    escaped = "".join(_tex_char(c) for c in text)
    return re.sub(r"\\textasciicircum\{\}", r"\\textasciicircum{}", escaped)


def to_tex(text: str) -> str:
    """LaTeX source of a text: prose escaped, math kept, ``**bold**`` as ``\\textbf``."""
    parts = []
    for kind, content in split_math(text):
        if kind == "text":
            pieces = _BOLD.split(content)
            parts.append("".join(_tex_text(p) if i % 2 == 0 else r"\textbf{" + _tex_text(p) + "}"
                                 for i, p in enumerate(pieces)))
        elif kind == "math":
            parts.append(f"${content}$")
        else:
            parts.append(f"\\[{content}\\]")
    return "".join(parts)


def to_html(text: str) -> str:
    """HTML of a text: prose escaped, math as ``\\(...\\)`` and ``\\[...\\]`` for MathJax.

    >>> to_html("a < b, $x<y$")
    'a &lt; b, \\\\(x&lt;y\\\\)'
    """
    parts = []
    for kind, content in split_math(text):
        if kind == "text":
            pieces = _BOLD.split(html.escape(content, quote=False))
            parts.append("".join(p if i % 2 == 0 else f"<b>{p}</b>" for i, p in enumerate(pieces)))
        elif kind == "math":
            parts.append(r"\(" + html.escape(content, quote=False) + r"\)")
        else:
            parts.append(r"\[" + html.escape(content, quote=False) + r"\]")
    return "".join(parts)


def to_plain(text: str) -> str:
    """Text with the math delimiters and bold markers dropped (for names and logs).

    >>> to_plain("**A** $x$")
    'A x'
    """
    return _BOLD.sub(r"\1", "".join(c for _, c in split_math(text)))
