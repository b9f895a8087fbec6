"""The small text format of exercises, and the one escaping function per output format.

Exercise text (statements, prompts, choices, solution steps) is Markdown prose with ``**bold**``,
inline math ``$...$`` and display math ``$$...$$``. Everything else a user supplies (names, ids,
roster fields, template titles) is *plain text*: it is never read as markup or math.

Each output format has one function for plain text and one for the small format:

=========  ===================  =========================
format     plain text           small format
=========  ===================  =========================
LaTeX      :func:`tex_escape`   :func:`to_tex`
Markdown   :func:`md_escape`    :func:`to_md` (MyST pages and notebook cells)
HTML       :func:`html_escape`  :func:`to_html`
Moodle     :func:`cloze_escape` :func:`to_moodle` (HTML inside CDATA, Cloze characters as entities)
QTI (XML)  :func:`xml_escape`   :func:`to_html`, then :func:`xml_escape` (HTML carried as text)
=========  ===================  =========================

Math is kept as math only when :func:`math_is_safe` accepts it: ASCII, balanced braces, and only
the control sequences and environments of :data:`MATH_COMMANDS` / :data:`MATH_ENVIRONMENTS` (no
``\\input``, ``\\def``, ``\\catcode``, ``^^`` notation, ``#`` or ``%``). Anything else is printed
literally, dollars included. Control characters and bidirectional overrides become U+FFFD in
every format (:func:`clean`).

>>> split_math("Let $x = 1$ and $$y$$.")
[('text', 'Let '), ('math', 'x = 1'), ('text', ' and '), ('display', 'y'), ('text', '.')]
>>> to_tex("50% of **all** $x_1$")
'50\\\\% of \\\\textbf{all} $x_1$'
>>> to_tex(r"$\\input{/etc/passwd}$")
'\\\\$\\\\textbackslash{}input\\\\{/etc/passwd\\\\}\\\\$'
"""

from __future__ import annotations

import html
import re
from collections.abc import Callable

_MATH = re.compile(r"\$\$(.+?)\$\$|\$(.+?)\$", re.S)
_BOLD = re.compile(r"\*\*(.+?)\*\*")

#: Control words allowed in math (everything the built-in templates and the answer renderer use,
#: plus common symbols). None of them reads or writes files, defines macros or changes catcodes.
MATH_COMMANDS = frozenset("""
    alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi rho sigma
    tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Phi Psi Omega
    frac tfrac dfrac sqrt cdot cdots ldots dots vdots ddots times div pm mp neq ne le leq ge geq approx equiv
    sim simeq cong propto to mapsto rightarrow leftarrow leftrightarrow Rightarrow Leftrightarrow infty
    in notin subset subseteq supset cup cap emptyset forall exists wedge vee oplus otimes circ ast star
    perp parallel angle top mathrm mathbf mathit mathcal mathbb mathsf operatorname text textrm textbf
    left right big Big bigl bigr Bigl Bigr langle rangle lvert rvert lVert rVert vert Vert lfloor rfloor
    lceil rceil quad qquad det rank tr ker dim deg sin cos tan arccos arcsin arctan log ln exp min max
    begin end hat bar tilde vec overline underline prime boldsymbol
""".split())

#: Environments allowed in math (``\\begin{...}`` / ``\\end{...}``).
MATH_ENVIRONMENTS = frozenset({"matrix", "pmatrix", "bmatrix", "vmatrix", "Vmatrix", "smallmatrix", "cases"})

_MATH_SYMBOLS = frozenset(",;:! \\{}|")  # control symbols \, \; \: \! \  \\ \{ \} \|
_MATH_CHARS = re.compile(r"[A-Za-z0-9 \t\n+\-*/=<>()\[\]|,.;:!'^_{}&\\]*")
_CONTROL = re.compile(r"\\([A-Za-z]+|.)", re.S)
_ENV = re.compile(r"\\(?:begin|end)\s*\{([A-Za-z*]*)\}")

REPLACEMENT = "\ufffd"
# C0 controls but tab and newline, DEL and C1, the bidirectional embeddings, overrides and isolates (they
# reorder what a reader sees: never pass them on), surrogates, U+FFFE and U+FFFF
_UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069\ud800-\udfff\ufffe\uffff]")


def clean(text: str) -> str:
    """Text with control characters (except newline and tab), bidirectional overrides, surrogates
    and non-characters replaced by U+FFFD, so no format receives them.

    >>> clean("a\\x00b\\u202ec\\n")
    'a\\ufffdb\\ufffdc\\n'
    """
    return _UNSAFE.sub(REPLACEMENT, str(text))


def one_line(text: str) -> str:
    """Plain text on one line: :func:`clean`, then every run of whitespace as one space.

    >>> one_line(" Ada\\n\\n Lovelace ")
    'Ada Lovelace'
    """
    return " ".join(clean(text).split())


def math_is_safe(tex: str) -> bool:
    """True when a math snippet uses only allowed characters, control sequences and environments,
    with balanced braces (so TeX and MathJax only typeset it).

    >>> math_is_safe(r"\\begin{pmatrix} 1 \\\\ \\tfrac{1}{2} \\end{pmatrix}"), math_is_safe(r"\\input{x}")
    (True, False)
    >>> math_is_safe("x^^5c"), math_is_safe("{x"), math_is_safe(r"\\def\\x{\\x}\\x"), math_is_safe("x\\\\")
    (False, False, False, False)
    """
    if not _MATH_CHARS.fullmatch(tex) or "^^" in tex or "\\" in _CONTROL.sub("", tex):
        return False  # (a backslash left over ends the snippet: it would escape the closing delimiter)
    depth = 0
    for m in re.finditer(r"\\.|[{}]", tex, re.S):
        if m.group() == "{":
            depth += 1
        elif m.group() == "}":
            depth -= 1
            if depth < 0:
                return False
    if depth:
        return False
    for m in _CONTROL.finditer(tex):
        name = m.group(1)
        if name.isalpha() and name.isascii():
            if name not in MATH_COMMANDS:
                return False
        elif name not in _MATH_SYMBOLS:
            return False
    envs = re.findall(r"\\(?:begin|end)\b", tex)
    return len(envs) == len(_ENV.findall(tex)) and all(e in MATH_ENVIRONMENTS for e in _ENV.findall(tex))


def split_math(text: str) -> list[tuple[str, str]]:
    """Split into ('text' | 'math' | 'display', content) segments (math as written, safe or not)."""
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


def segments(text: str) -> list[tuple[str, str]]:
    """Like :func:`split_math` on :func:`clean` text, but math that :func:`math_is_safe` refuses stays
    text, delimiters included (neighbouring text segments are merged).

    >>> segments(r"a $x$ b $\\write18{rm}$")
    [('text', 'a '), ('math', 'x'), ('text', ' b $\\\\write18{rm}$')]
    """
    cleaned = clean(text)
    out: list[tuple[str, str]] = []
    pos = 0
    for m in _MATH.finditer(cleaned):
        display = m.group(1) is not None
        content = m.group(1) if display else m.group(2)
        if math_is_safe(content):
            if m.start() > pos:
                out.append(("text", cleaned[pos:m.start()]))
            out.append(("display" if display else "math", content))
            pos = m.end()
    if pos < len(cleaned):
        out.append(("text", cleaned[pos:]))
    return out


def _bold_pieces(content: str) -> list[tuple[bool, str]]:
    """(is_bold, text) pieces of a text segment."""
    return [(i % 2 == 1, p) for i, p in enumerate(_BOLD.split(content)) if p]


# ---------------------------------------------------------------- LaTeX

_TEX_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "#": r"\#", "_": r"\_", "{": r"\{", "}": r"\}",
                "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "$": r"\$", "\t": " ", "\n": " ",
                "\ufffd": "?"}
_TEX_UNICODE = {"⊂": r"$\subset$", "↔": r"$\leftrightarrow$", "×": r"$\times$", "→": r"$\to$", "≠": r"$\neq$",
                "−": "-", "…": r"\dots{}", "’": "'"}
# with LuaLaTeX and its fonts only what the text font lacks is replaced: the minus sign comes from math
_TEX_UNICODE_LUA = {k: v for k, v in _TEX_UNICODE.items() if k not in "’…−"} | {"−": "$-$"}
_TEX_LIGATURES = {"-": "-", "<": "<", ">": ">", ",": ",", "'": "'", "`": "`", "!": "`", "?": "`"}
_TEX_LINE = 500  # characters of escaped text per source line (TeX reads lines into a fixed buffer)
# A word longer than a line (a path, a URL, a run of CJK characters) would run off the page, where a PDF
# reader loses it: past _TEX_WORD characters it may break after punctuation, and at least every
# _TEX_WORD characters.
_TEX_WORD = 24
_TEX_BREAK_AFTER = frozenset("/\\.,;:=&?!-_)]}|@")
# right-to-left scripts: Hebrew, Arabic, Syriac, Thaana, N'Ko, Samaritan, Mandaic and their presentation forms
_RTL = "\u0590-\u08ff\ufb1d-\ufdff\ufe70-\ufefe"
_RTL_CHAR = re.compile(f"[{_RTL}]")
_BIDI_MARKS = frozenset("\u200e\u200f\u061c")  # LRM, RLM, ALM: the direction of a run is set by \textdir
_RTL_RUN = re.compile(f"[{_RTL}]+(?:[ ]+[{_RTL}]+)*")  # words and the spaces between them, not the ends


def _tex_char(c: str) -> str:
    if c in _TEX_SPECIAL:
        return _TEX_SPECIAL[c]
    if c in _TEX_UNICODE:
        return _TEX_UNICODE[c]
    # pdfLaTeX with T1 fonts typesets Latin-1; anything else (CJK, emoji, control characters) becomes '?'
    return c if (" " <= c <= "~") or ("\u00a0" <= c <= "\u00ff" and c != "\u00ad") else "?"


def tex_escape(text: str, unicode: bool = False) -> str:
    """Plain text as LaTeX that typesets exactly these characters: every special character escaped,
    ligatures (``--``, ``<<``, ``,,``, ``!```) broken with ``{}``, line breaks as spaces, characters
    outside Latin-1 as ``?``; long text is cut into source lines with ``%`` (TeX's line buffer is finite).

    With ``unicode=True`` (for LuaLaTeX with the fonts of :mod:`pgsym.exercises.render_tex`) every
    character is kept, and a run of right-to-left letters (Arabic, Hebrew, …) is set right to left
    in ``{\\textdir TRT ...}``, so a PDF reader extracts it in its logical order.

    >>> print(tex_escape(r"$\\def\\x{\\x}$ 100% #1 a--b"))
    \\$\\textbackslash{}def\\textbackslash{}x\\{\\textbackslash{}x\\}\\$ 100\\% \\#1 a-{}-b
    >>> tex_escape("李雷 & José"), tex_escape("李雷 & José", unicode=True)
    ('?? \\\\& José', '李雷 \\\\& José')
    >>> print(tex_escape("Ali علي حسن", unicode=True))
    Ali {\\textdir TRT علي حسن}
    >>> print(tex_escape("D’Angelo … −1", unicode=True))
    D’Angelo … $-$1
    """
    text = clean(text)
    out: list[str] = []
    width = run = 0
    for i, c in enumerate(text):
        if unicode:
            # typographic characters stay as typed (D’Angelo is not D'Angelo): the fonts have them
            piece = "" if c in _BIDI_MARKS else (_TEX_SPECIAL.get(c) or _TEX_UNICODE_LUA.get(c) or c)
        else:
            piece = _tex_char(c)
        if c in _TEX_LIGATURES and i + 1 < len(text) and text[i + 1] == _TEX_LIGATURES[c]:
            piece += "{}"
        out.append(piece)
        width += len(piece)
        run = 0 if c in " \t\n" else run + 1
        following = text[i + 1] if i + 1 < len(text) else " "
        if run >= _TEX_WORD and (c in _TEX_BREAK_AFTER or run % _TEX_WORD == 0) and following not in " \t\n" \
                and not (_RTL_CHAR.match(c) or _RTL_CHAR.match(following)):
            out.append(r"\allowbreak{}")
        # '%' + newline joins two source lines without a space; never before a space (TeX would drop it)
        if width >= _TEX_LINE and i + 1 < len(text) and text[i + 1] not in " \t\n" and not (
                unicode and _RTL_CHAR.match(c)):
            out.append("%\n")
            width = 0
    escaped = "".join(out)
    return _RTL_RUN.sub(lambda m: "{\\textdir TRT " + m.group(0) + "}", escaped) if unicode else escaped


def to_tex(text: str, unicode: bool = False) -> str:
    """LaTeX source of a text in the small format: prose escaped, safe math kept, ``**bold**`` as ``\\textbf``
    (``unicode`` as in :func:`tex_escape`)."""
    parts = []
    for kind, content in segments(text):
        if kind == "text":
            parts.append("".join(r"\textbf{" + tex_escape(p, unicode) + "}" if bold else tex_escape(p, unicode)
                                 for bold, p in _bold_pieces(content)))
        elif kind == "math":
            parts.append(f"${content}$")
        else:
            parts.append(f"\\[{content}\\]")
    return "".join(parts)


# ---------------------------------------------------------------- Markdown / MyST

# inline Markdown, MyST roles/substitutions, math and HTML: escaped wherever they appear
_MD_INLINE = set("\\`*_{}[]<>&$|~!#")  # '#': a heading's closing hashes would be dropped
_MD_BLOCK = r"([ \t]*)(?:([!-/:-@\[-`{-~])|(\d+)([.)]))"
_MD_LINE_START = re.compile(r"(?:\A|(?<=\n))" + _MD_BLOCK)
_MD_NEW_LINE = re.compile(r"(?<=\n)" + _MD_BLOCK)


def md_escape(text: str) -> str:
    """Plain text as Markdown/MyST (pages and notebook cells) that shows exactly these characters.

    Inline syntax (emphasis, code, roles ``{name}``, links, HTML ``<``/``&``) is backslash-escaped
    and a leading block marker (``#``, ``>``, ``-``, ``1.``, ``:::``, ``(label)=``, ``%``) too, on one
    line. Text with a backslash or a dollar becomes an inline code span instead: math scanners that
    read the source before Markdown does (Jupyter's, MyST's ``$``) and MathJax in the page skip code.

    >>> md_escape("# {eval-rst} <b>x</b>")
    '\\\\# \\\\{eval-rst\\\\} \\\\<b\\\\>x\\\\</b\\\\>'
    >>> md_escape(r"\\(\\href{javascript:x}{y}\\) `$`")
    '`` \\\\(\\\\href{javascript:x}{y}\\\\) `$` ``'
    """
    return _md_prose(one_line(text))


def md_code(text: str, line_start: bool = False) -> str:
    """``text`` as one inline code span (line breaks as spaces), delimited by more backticks than it holds.

    >>> md_code("a`b"), md_code("`x")
    ('``a`b``', '`` `x ``')
    """
    text = " ".join(text.split("\n"))
    fence = "`" * (max((len(run) for run in re.findall(r"`+", text)), default=0) + 1)
    # CommonMark strips one space at each end when both ends have one: add it when needed
    pad = " " if text[:1] == "`" or text[-1:] == "`" or (text[:1] == " " and text[-1:] == " ") else ""
    # three backticks at the start of a line would open a fenced block
    lead = "&#32;" if line_start and len(fence) >= 3 else ""
    return f"{lead}{fence}{pad}{text}{pad}{fence}"


def _md_prose(text: str, line_start: bool = True) -> str:
    """Escape Markdown prose; ``line_start`` says whether ``text`` begins a line of the output."""
    if "\\" in text or "$" in text:
        return md_code(text, line_start)
    escaped = "".join("\\" + c if c in _MD_INLINE else c for c in text)

    def start(m: re.Match[str]) -> str:
        if m.group(2) is not None:
            return m.group(1) + ("" if m.group(2) == "\\" else "\\") + m.group(2)
        return m.group(1) + m.group(3) + "\\" + m.group(4)

    return (_MD_LINE_START if line_start else _MD_NEW_LINE).sub(start, escaped)


def to_md(text: str) -> str:
    """Markdown/MyST of a text in the small format: prose escaped, safe math kept, bold kept.

    >>> to_md("Let $x_1$ be **the** {abbr}`x`.")
    'Let $x_1$ be **the** \\\\{abbr\\\\}\\\\`x\\\\`.'
    """
    parts: list[str] = []
    for kind, content in segments(text):
        if kind == "text":
            for bold, p in _bold_pieces(content):
                first = not parts or parts[-1].endswith("\n")
                parts.append(f"**{_md_prose(p, False)}**" if bold else _md_prose(p, first))
        elif kind == "math":
            parts.append(f"${content}$")
        else:
            parts.append(f"$${content}$$")
    return "".join(parts)


# ---------------------------------------------------------------- HTML

#: Elements of this class are skipped by MathJax (its default ``ignoreHtmlClass``); the HTML pages set it too.
NO_MATH_CLASS = "tex2jax_ignore"


def _html_prose(text: str, cloze: bool = False) -> str:
    escaped = html.escape(text, quote=True)
    if cloze:
        escaped = escaped.translate(_CLOZE_TABLE)
    # MathJax reads the page's text, where \( or $$ typed by a user would start math: keep it out
    return f'<span class="{NO_MATH_CLASS}">{escaped}</span>' if ("\\" in text or "$" in text) else escaped


def html_escape(text: str) -> str:
    """Plain text as HTML that shows exactly these characters (``<``, ``&`` and quotes as entities;
    text with a backslash or dollar inside a span MathJax ignores).

    >>> html_escape("</script><b>"), html_escape(r"\\(x\\)")
    ('&lt;/script&gt;&lt;b&gt;', '<span class="tex2jax_ignore">\\\\(x\\\\)</span>')
    """
    return _html_prose(one_line(text))


def to_html(text: str, math: Callable[[str, bool], str] | None = None) -> str:
    """HTML of a text in the small format: prose escaped, safe math as ``\\(...\\)`` and ``\\[...\\]`` for MathJax,
    or, given ``math``, as ``math(tex, display)`` (e.g. MathML made at generation time).

    >>> to_html("a < b, $x<y$")
    'a &lt; b, \\\\(x&lt;y\\\\)'
    """
    parts = []
    for kind, content in segments(text):
        if kind == "text":
            parts.append("".join(f"<b>{_html_prose(p)}</b>" if bold else _html_prose(p)
                                 for bold, p in _bold_pieces(content)))
        elif math is not None:
            parts.append(math(content, kind == "display"))
        elif kind == "math":
            parts.append(r"\(" + html.escape(content, quote=False) + r"\)")
        else:
            parts.append(r"\[" + html.escape(content, quote=False) + r"\]")
    return "".join(parts)


# ---------------------------------------------------------------- Moodle (HTML in CDATA, Cloze)

# Cloze reads {n:TYPE:=answer~...#feedback} in the raw question text, Moodle's TeX filter reads $$ and
# \[ ]; as numeric entities the browser still shows these characters but neither parser sees them
_CLOZE = {c: f"&#{ord(c)};" for c in "{}~=#:$[]\\"}
_CLOZE_TABLE = str.maketrans(_CLOZE)
_MATH_CLOZE_TABLE = str.maketrans({c: e for c, e in _CLOZE.items() if c != "\\"})


def cloze_escape(html_text: str) -> str:
    """Make escaped HTML *text* (no tags) inert for Moodle: Cloze and filter characters as numeric entities.

    >>> cloze_escape("{1:SA:=x}")
    '&#123;1&#58;SA&#58;&#61;x&#125;'
    """
    return html_text.translate(_CLOZE_TABLE)


def to_moodle(text: str) -> str:
    """HTML for a Moodle question (inside CDATA) of a text in the small format: like :func:`to_html`,
    with the Cloze characters of prose *and* math as entities (MathJax reads the decoded text); the
    math delimiters ``\\(`` ``\\)`` and the backslashes of allowed math stay as typed.

    >>> to_moodle("{1:SA:=x} $x = 1$")
    '&#123;1&#58;SA&#58;&#61;x&#125; \\\\(x &#61; 1\\\\)'
    """
    parts = []
    for kind, content in segments(text):
        if kind == "text":
            parts.append("".join(f"<b>{_html_prose(p, True)}</b>" if bold else _html_prose(p, True)
                                 for bold, p in _bold_pieces(content)))
        else:
            inner = html.escape(content, quote=False).translate(_MATH_CLOZE_TABLE)
            parts.append((r"\(" + inner + r"\)") if kind == "math" else (r"\[" + inner + r"\]"))
    return "".join(parts)


def moodle_escape(text: str) -> str:
    """Plain text for a Moodle question text (HTML, then :func:`cloze_escape`).

    >>> moodle_escape("]]> {#1}")
    '&#93;&#93;&gt; &#123;&#35;1&#125;'
    """
    return _html_prose(one_line(text), cloze=True)


# ---------------------------------------------------------------- XML (QTI)

def xml_escape(text: str) -> str:
    """Text (plain, or HTML to be carried *as text*) for an XML element or a quoted attribute: after
    :func:`clean` (XML 1.0 forbids most control characters), ``& < > " '`` become entities.

    >>> xml_escape('<b a="1">Tom & Jerry\x07</b>')
    '&lt;b a=&quot;1&quot;&gt;Tom &amp; Jerry\ufffd&lt;/b&gt;'
    """
    return html.escape(clean(text), quote=True).replace("&#x27;", "&apos;")


def to_plain(text: str) -> str:
    """Text with the math delimiters and bold markers dropped (for names and logs).

    >>> to_plain("**A** $x$")
    'A x'
    """
    return _BOLD.sub(r"\1", "".join(c for _, c in split_math(text)))
