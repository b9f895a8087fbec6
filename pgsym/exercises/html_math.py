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

The converter's output is then corrected where browsers would space or place a symbol unlike TeX
(compared with MathJax 3's MathML for the same input, see ``tests/test_exercises_html_math.py``):

- a sign that starts a term (after ``(``, a comma, a relation, another operator or at the start) is a
  prefix operator, ``<mo form="prefix" lspace="0" rspace="0">−</mo>``: ``(−14, −8, 1)``, not ``( − 14, − 8, 1)``;
- a prime is an operator in a superscript, ``<msup><mi>x</mi><mo>′</mo></msup>`` as MathJax writes it
  (and as the MathML specification recommends), not an identifier in a nested row;
- ``\\sim`` is the relation ``<mo>∼</mo>`` (U+223C), not the identifier ``~``; ``\\infty`` and
  ``\\top`` are ordinary symbols ``<mi>``, without operator spacing.

>>> m = mathml("(-1, 2)", display=False)
>>> '<mo stretchy="false">(</mo><mo form="prefix" lspace="0" rspace="0">−</mo><mn>1</mn>' in m
True
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


ElementTree.register_namespace("", _NS[1:-1])  # MathML as the default namespace: <math xmlns=...>, no prefixes

_SIGNS = frozenset("−-+±∓")
_PRIMES = frozenset("′″‴")
#: operators after which a sign starts a term (opening fences, separators, relations, other operators)
_BEFORE_PREFIX = frozenset("([{⟨,;:=≠<>≤≥∼≃≅≡≈∝→↦⇒⇔∈∉⊂⊆−-+±∓×·⋅∘/")
#: symbols the converter writes as the wrong token: text → (tag, text, attributes)
_TOKENS = {("mi", "~"): ("mo", "∼", {}), ("mo", "∞"): ("mi", "∞", {}),
           ("mo", "⊤"): ("mi", "⊤", {"mathvariant": "normal"})}


def _tidy(root: ElementTree.Element) -> None:
    """Correct the converter's tokens in place (see the module)."""
    for element in root.iter():
        tag = element.tag[len(_NS):] if isinstance(element.tag, str) else ""
        key = (tag, (element.text or "").strip())
        if key in _TOKENS:
            new_tag, text, attributes = _TOKENS[key]
            element.tag, element.text = _NS + new_tag, text
            element.attrib.update(attributes)
        elif tag == "mi" and key[1] in _PRIMES:
            element.tag = _NS + "mo"
    for element in root.iter():
        children = list(element)
        for i, child in enumerate(children):
            tag = child.tag[len(_NS):]
            if tag in ("msup", "msubsup") and len(child) >= 2:
                script = child[-1]  # a prime alone in a row: the row goes, the prime stays
                if script.tag == _NS + "mrow" and len(script) == 1 and (script[0].text or "").strip() in _PRIMES:
                    child.remove(script)
                    child.append(script[0])
            if tag != "mo" or (child.text or "").strip() not in _SIGNS or child.get("form"):
                continue
            before = children[i - 1] if i else None
            if before is None or (before.tag == _NS + "mo" and (before.text or "").strip() in _BEFORE_PREFIX
                                  and before.get("form") != "postfix"
                                  and (before.text or "").strip() not in ")]}⟩"):
                child.set("form", "prefix")
                child.set("lspace", "0")
                child.set("rspace", "0")


def _is_plain(root: ElementTree.Element) -> bool:
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
    from latex2mathml.converter import convert  # noqa: PLC0415 — only the HTML sheets need it

    try:
        markup = convert(tex, display="block" if display else "inline")
    except Exception:  # the converter's own errors have no common base class
        markup = ""
    try:
        root = ElementTree.fromstring(markup) if markup else None
    except ElementTree.ParseError:
        root = None
    if root is not None and _is_plain(root):
        _tidy(root)
        return ElementTree.tostring(root, encoding="unicode", short_empty_elements=False)
    return f'<code class="tex">{html.escape(tex, quote=False)}</code>'
