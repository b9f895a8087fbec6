"""PDF sheets: every name prints (or the run names what cannot), each sheet on its own paper.

Read back with poppler (pdftotext per page, pdfinfo, pdfimages), installed by `make system-deps`.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import unicodedata
from pathlib import Path

import pytest
from click.testing import CliRunner

from pgsym.cli import main
from pgsym.exercises import render_tex
from pgsym.exercises.errors import MissingGlyphError
from pgsym.exercises.sheets import build_sheets

NAMES = [("s1", "রবীন্দ্রনাথ ঠাকুর"),  # Bengali
         ("s2", "சுப்பிரமணிய பாரதி"),  # Tamil
         ("s3", "ኃይሌ ገብረሥላሴ"),  # Ethiopic
         ("s4", "សុខ ចាន់"),  # Khmer
         ("s5", "D’Angelo Zoë")]  # a typographic apostrophe, kept
EMOJI = ("s6", "Ada 😀🎓")
_EMBEDDING = re.compile("[\u202a-\u202e\u2066-\u2069]")


def _tool(name: str) -> str:
    path = shutil.which(name)
    assert path, f"{name} is missing: run `make system-deps` (poppler-utils)"
    return path


def pdf_text(path: Path, page: int | None = None) -> str:
    pages = ["-f", str(page), "-l", str(page)] if page else []
    out = subprocess.run([_tool("pdftotext"), "-enc", "UTF-8", *pages, str(path), "-"], capture_output=True,
                         text=True, timeout=60, check=True).stdout
    return unicodedata.normalize("NFC", _EMBEDDING.sub("", out))


def footer(path: Path, page: int) -> str:
    """The text of the page's footer (below the text area of the A4 page: the bottom 52 pt)."""
    out = subprocess.run([_tool("pdftotext"), "-f", str(page), "-l", str(page), "-x", "0", "-y", "790", "-W", "595",
                          "-H", "52", str(path), "-"], capture_output=True, text=True, timeout=60, check=True).stdout
    return out.strip()


def pages(path: Path) -> int:
    info = subprocess.run([_tool("pdfinfo"), str(path)], capture_output=True, text=True, timeout=60, check=True)
    return int(re.search(r"^Pages:\s+(\d+)", info.stdout, re.MULTILINE).group(1))


@pytest.fixture(scope="module")
def run(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("pdf")
    roster = folder / "roster.csv"
    roster.write_text("id,name\n" + "".join(f"{i},{n}\n" for i, n in [*NAMES, EMOJI]), encoding="utf-8")
    # with their solutions, sheets run over a page: some have an odd page count and need a blank page
    result = CliRunner().invoke(main, ["sheet", "--topics", "join,decompose:3,apply-conic:2,classify:3,angle:2",
                                       "--roster", str(roster), "--seed", "4", "--solutions-in-sheets",
                                       "--format", "pdf", "--out", str(folder / "out")])
    assert result.exit_code == 0, result.output
    return folder / "out"


def test_every_script_prints_in_its_font(run):
    # pdftotext may cut a shaped line where a vowel sign sits apart (Tamil): compared without white space
    text = re.sub(r"\s", "", pdf_text(run / "sheets.pdf"))
    for _, name in NAMES:
        assert re.sub(r"\s", "", name) in text, name
    fonts = subprocess.run([_tool("pdffonts"), str(run / "sheets.pdf")], capture_output=True, text=True,
                           check=True).stdout
    for family in ("Bengali", "Tamil", "Ethiopic", "Khmer"):
        assert f"Noto{'Serif'}{family}" in fonts.replace(" ", "") or f"NotoSans{family}" in fonts, family


def test_an_emoji_prints_as_a_colour_image_not_a_box(run):
    # Noto Color Emoji glyphs are bitmaps: LuaLaTeX (HarfBuzz mode) embeds each as an image
    page = next(i for i in range(1, pages(run / "sheets.pdf") + 1) if "Ada" in pdf_text(run / "sheets.pdf", i))
    images = subprocess.run([_tool("pdfimages"), "-f", str(page), "-l", str(page), "-list", str(run / "sheets.pdf")],
                            capture_output=True, text=True, check=True).stdout.splitlines()[2:]
    assert len(images) >= 2  # 😀 and 🎓 (twice the first: title and id line would be more; at least two)


def test_each_sheet_starts_on_an_odd_page_and_numbers_its_pages_from_1(run):
    path = run / "sheets.pdf"
    total = pages(path)
    texts = [pdf_text(path, i) for i in range(1, total + 1)]
    starts = [i + 1 for i, t in enumerate(texts) if "Exercise sheet:" in t]
    assert len(starts) == 6 and all(p % 2 == 1 for p in starts)
    lengths = [b - a for a, b in zip(starts, [*starts[1:], total + 1], strict=True)]
    assert all(n % 2 == 0 for n in lengths[:-1])  # padded to even, so the next one starts on an odd page
    blank = [i + 1 for i, t in enumerate(texts) if not t.strip()]
    assert blank and all(p % 2 == 0 and p + 1 in starts for p in blank)  # only padding is blank
    assert max(lengths) >= 2
    for start, n in zip(starts, lengths, strict=True):
        numbers = [footer(path, start + k) for k in range(n) if texts[start - 1 + k].strip()]
        assert numbers == [str(k) for k in range(1, len(numbers) + 1)]


def test_one_pdf_per_student_holds_exactly_that_sheet(run):
    files = sorted((run / "pdf").iterdir())
    assert [f.name for f in files] == [f"sheet-s{i}.pdf" for i in range(1, 7)]
    key_files = sorted((run / "key" / "pdf").iterdir())
    assert len(key_files) == 6
    for (sid, name), path in zip([*NAMES, EMOJI], files, strict=True):
        text = pdf_text(path)
        assert text.count("Exercise sheet:") == 1 and f"Student id: {sid}" in text
        if sid != "s6":
            assert re.sub(r"\s", "", name) in re.sub(r"\s", "", text)
        assert pdf_text(path, pages(path)).strip()  # no blank padding page at the end of one student's file


def test_a_character_no_font_has_stops_the_run_naming_student_and_character(tmp_path):
    roster = tmp_path / "r.csv"
    roster.write_text("id,name\ns1,Ada\ns2,Bob \u0378\n", encoding="utf-8")  # U+0378 is unassigned: no font has it
    result = CliRunner().invoke(main, ["sheet", "--topics", "join", "--roster", str(roster), "--format", "pdf",
                                       "--out", str(tmp_path / "out")])
    assert result.exit_code == 1 and not (tmp_path / "out").exists()
    assert "MissingGlyphError: the sheet of student s2 (Bob \u0378)" in result.output
    assert "U+0378" in result.output


def test_tex_log_missing_characters_fail_the_run():
    # no fallback fonts in the preamble: the Bengali letters are missing from the main font, TeX logs it
    source = render_tex.preamble("") + "\\begin{document}\nরবী\n\\end{document}\n"
    with pytest.raises(MissingGlyphError, match=r"'র' \(U\+09B0 BENGALI LETTER RA\)"):
        render_tex.compile_pdf(source)


def test_a_class_with_only_latin_names_needs_no_fallback_font():
    tex = render_tex.render_document(build_sheets(["join"], [("s1", "D’Angelo")], 1))
    assert "fallback=pgsym" not in tex and "D’Angelo" in tex
