"""Math of the HTML sheets as MathML, made when the sheets are generated.

Browsers render MathML Core themselves (Chromium since 109, Firefox, Safari), so the pages need no
JavaScript, no MathJax copy and no network: they work right after ``pip install pgsym``. The LaTeX of
an exercise (already restricted by :func:`~pgsym.escaping.math_is_safe`) is converted by the
pure-Python ``latex2mathml``; its result is parsed and kept only if every element and attribute is
plain MathML from :data:`ELEMENTS` / :data:`ATTRIBUTES` (``\\text{<b>}`` passes through the converter
unescaped, so this check is what keeps user text from becoming markup). Anything else is shown as the
LaTeX source in ``<code>``.

>>> mathml(r"\\frac{1}{2}", display=False).startswith('<math xmlns="http://www.w3.org/1998/Math/MathML"')
True
>>> mathml(r"\\text{<img src=x>}", display=False)
'<code class="tex">\\\\text{&lt;img src=x&gt;}</code>'
"""

from __future__ import annotations

import html
from functools import lru_cache
from xml.etree import ElementTree

__all__ = ["ATTRIBUTES", "ELEMENTS", "mathml"]

_NS = "{http://www.w3.org/1998/Math/MathML}"

#: MathML elements a page may receive (presentation MathML only: no links, no foreign content).
ELEMENTS = frozenset("""math mrow mi mn mo mtext mspace ms mfrac msqrt mroot mstyle merror mpadded mphantom
    menclose msub msup msubsup munder mover munderover mmultiscripts mprescripts none mtable mtr mtd
    maligngroup malignmark semantics annotation""".split())

#: Attributes a MathML element may carry (no event handlers, no href, no style).
ATTRIBUTES = frozenset("""display mathvariant displaystyle scriptlevel stretchy fence separator form lspace rspace
    columnalign rowalign columnspacing rowspacing columnlines rowlines frame width height depth linethickness
    accent accentunder movablelimits largeop symmetric minsize maxsize notation class encoding""".split())


def _is_plain_mathml(markup: str) -> bool:
    try:
        root = ElementTree.fromstring(markup)
    except ElementTree.ParseError:
        return False
    for element in root.iter():
        if not (isinstance(element.tag, str) and element.tag.startswith(_NS) and element.tag[len(_NS):] in ELEMENTS):
            return False
        if any(name not in ATTRIBUTES for name in element.attrib):
            return False
    return True


@lru_cache(maxsize=4096)
def mathml(tex: str, display: bool) -> str:
    """MathML of a LaTeX math snippet (``display`` for a block), or the snippet as ``<code>`` if the
    converter fails or produces anything but plain MathML."""
    from latex2mathml.converter import convert  # only the HTML sheets need it

    try:
        markup = convert(tex, display="block" if display else "inline")
    except Exception:  # the converter's own errors have no common base class
        markup = ""
    if markup and _is_plain_mathml(markup):
        return markup
    return f'<code class="tex">{html.escape(tex, quote=False)}</code>'
