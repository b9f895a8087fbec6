"""Fonts of the PDF sheets: the main font, and for every other character an installed Noto font that has it.

The fonts installed are read once from fontconfig (``fc-list`` with each font's character set). For
the characters of a document that the main font lacks, the fallback chain of luaotfload (glyph by
glyph, HarfBuzz shaping) lists the fonts that have them, preferred faces first (colour emoji before
the monochrome symbol fonts, the serif face of a script before its sans face), so a name in Bengali,
Tamil, Ethiopic, Khmer, Egyptian hieroglyphs or emoji prints whenever a Noto font of the machine has it. A character no
installed font has is reported before TeX runs (:func:`missing_characters`), with the package that
usually brings it; nothing prints as an empty box.

Without fontconfig (no ``fc-list``) the chain is the fixed table :data:`STATIC_FALLBACKS`.

>>> chain, missing = fallback_chain("Ada D’Angelo")
>>> chain, missing
([], [])
>>> describe("\\U00013000")
"'𓀀' (U+13000 EGYPTIAN HIEROGLYPH A001)"
"""

from __future__ import annotations

import bisect
import shutil
import subprocess
import unicodedata
from dataclasses import dataclass
from functools import lru_cache

__all__ = ["MAIN_FONT", "STATIC_FALLBACKS", "Font", "describe", "fallback_chain", "installed_fonts",
           "missing_characters", "needs_glyph", "package_hint"]

#: The main font (Debian: fonts-noto-core): Latin, Greek, Cyrillic and the typographic punctuation.
MAIN_FONT = "Noto Serif"

#: Faces preferred for their scripts, with the OpenType features their shaping needs.
PREFERRED = {
    "Noto Serif CJK SC": "",
    "Noto Naskh Arabic": "script=arab;",
    "Noto Serif Hebrew": "script=hebr;",
    "Noto Serif Devanagari": "script=dev2;",
}

#: (code point ranges, luaotfload font) used when fontconfig is not available.
STATIC_FALLBACKS: tuple[tuple[tuple[tuple[int, int], ...], str], ...] = (
    (((0x1100, 0x11FF), (0x2E80, 0x9FFF), (0xA960, 0xA97F), (0xAC00, 0xD7FF), (0xF900, 0xFAFF), (0xFE30, 0xFE4F),
      (0xFF00, 0xFFEF), (0x20000, 0x3FFFF)), "Noto Serif CJK SC:mode=harf;"),
    (((0x0600, 0x06FF), (0x0750, 0x077F), (0x08A0, 0x08FF), (0xFB50, 0xFDFF), (0xFE70, 0xFEFF)),
     "Noto Naskh Arabic:mode=harf;script=arab;"),
    (((0x0590, 0x05FF), (0xFB1D, 0xFB4F)), "Noto Serif Hebrew:mode=harf;script=hebr;"),
    (((0x0900, 0x097F), (0xA8E0, 0xA8FF)), "Noto Serif Devanagari:mode=harf;script=dev2;"),
    (((0x0E00, 0x0E7F),), "Noto Serif Thai:mode=harf;"),
    (((0x0530, 0x058F), (0xFB13, 0xFB17)), "Noto Serif Armenian:mode=harf;"),
    (((0x10A0, 0x10FF), (0x1C90, 0x1CBF), (0x2D00, 0x2D2F)), "Noto Serif Georgian:mode=harf;"),
)


@dataclass(frozen=True)
class Font:
    """An installed font family: its name and the code points it has (sorted, disjoint ranges)."""

    family: str
    starts: tuple[int, ...]
    ends: tuple[int, ...]

    def has(self, point: int) -> bool:
        """True when the font has a glyph for code point ``point``."""
        i = bisect.bisect_right(self.starts, point) - 1
        return i >= 0 and point <= self.ends[i]

    @property
    def spec(self) -> str:
        """The font as luaotfload's fallback list names it (HarfBuzz shaping, the script's features)."""
        return f"{self.family}:mode=harf;{PREFERRED.get(self.family, '')}"


def _rank(family: str) -> tuple[int, str]:
    if family in PREFERRED:
        return (0, f"{list(PREFERRED).index(family):03d}")
    if family == "Noto Color Emoji":  # before the symbol fonts, which have monochrome copies of some emoji
        return (1, family)
    plain = "Display" not in family and "Mono" not in family and "Looped" not in family
    if family.startswith("Noto Serif ") and plain:
        return (2, family)
    if family.startswith("Noto Sans ") and plain and "Unjoined" not in family:
        return (3, family)
    return (4, family)


def _parse_charset(text: str) -> list[tuple[int, int]]:
    ranges = []
    for item in text.split():
        lo, _, hi = item.partition("-")
        try:
            ranges.append((int(lo, 16), int(hi or lo, 16)))
        except ValueError:
            continue
    return ranges


@lru_cache(maxsize=1)
def installed_fonts() -> tuple[Font, ...]:
    """The installed Noto families (regular faces), preferred first; empty without fontconfig."""
    fc_list = shutil.which("fc-list")
    if fc_list is None:
        return ()
    try:
        out = subprocess.run([fc_list, "--format", "%{family[0]}\t%{style[0]}\t%{charset}\n"], capture_output=True,
                             text=True, timeout=60, check=True).stdout
    except (OSError, subprocess.SubprocessError):
        return ()
    charsets: dict[str, list[tuple[int, int]]] = {}
    for line in out.splitlines():
        family, _, rest = line.partition("\t")
        style, _, charset = rest.partition("\t")
        if family.startswith("Noto") and style in ("Regular", "Book"):
            charsets.setdefault(family, []).extend(_parse_charset(charset))
    fonts = []
    for family in sorted(charsets, key=_rank):
        merged: list[tuple[int, int]] = []
        for lo, hi in sorted(charsets[family]):
            if merged and lo <= merged[-1][1] + 1:
                merged[-1] = (merged[-1][0], max(hi, merged[-1][1]))
            else:
                merged.append((lo, hi))
        fonts.append(Font(family, tuple(lo for lo, _ in merged), tuple(hi for _, hi in merged)))
    return tuple(fonts)


def needs_glyph(char: str) -> bool:
    """False for characters that print nothing themselves (controls, joiners, variation selectors)."""
    point = ord(char)
    if point < 0x80:
        return False
    category = unicodedata.category(char)
    return not (category in ("Cc", "Cf", "Zl", "Zp") or 0xFE00 <= point <= 0xFE0F or 0xE0100 <= point <= 0xE01EF)


@lru_cache(maxsize=65536)
def _font_for(char: str) -> str | None:
    """The family that prints ``char``: "" for the main font, None when no installed font has it."""
    fonts = installed_fonts()
    point = ord(char)
    main = next((f for f in fonts if f.family == MAIN_FONT), None)
    if main is not None and main.has(point):
        return ""
    return next((f.family for f in fonts if f.family != MAIN_FONT and f.has(point)), None)


def fallback_chain(text: str) -> tuple[list[str], list[str]]:
    """The luaotfload fallback fonts ``text`` needs (preferred first) and the characters no installed font has.

    Without fontconfig the chain comes from :data:`STATIC_FALLBACKS` and nothing is reported missing
    (TeX's log still is checked).
    """
    chars = sorted({c for c in text if needs_glyph(c)})
    fonts = installed_fonts()
    if not fonts:
        points = {ord(c) for c in chars}
        return [font for ranges, font in STATIC_FALLBACKS
                if any(lo <= p <= hi for p in points for lo, hi in ranges)], []
    needed, missing = set(), []
    for char in chars:
        family = _font_for(char)
        if family is None:
            missing.append(char)
        elif family:
            needed.add(family)
    return [f.spec for f in fonts if f.family in needed], missing


def missing_characters(text: str) -> list[str]:
    """The characters of ``text`` that no installed font has (empty without fontconfig).

    >>> missing_characters("Ada \\u0378")  # U+0378 is not assigned: no font has it
    ['\\u0378']
    """
    return fallback_chain(text)[1]


def describe(char: str) -> str:
    """A character for an error message: itself, its code point and its Unicode name."""
    return f"{char!r} (U+{ord(char):04X} {unicodedata.name(char, 'unnamed')})"


def package_hint(char: str) -> str:
    """Which Debian package usually brings a font for ``char``.

    >>> package_hint("😀")
    'fonts-noto-color-emoji'
    """
    point = ord(char)
    if 0x1F000 <= point <= 0x1FAFF or 0x2600 <= point <= 0x27BF:
        return "fonts-noto-color-emoji"
    if 0x2E80 <= point <= 0x9FFF or 0xAC00 <= point <= 0xD7FF or point >= 0x20000:
        return "fonts-noto-cjk (fonts-noto-cjk-extra for rare ideographs)"
    return "fonts-noto-core, or fonts-noto-extra for rarer scripts"
