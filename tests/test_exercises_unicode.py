"""Every name prints: a roster in many scripts through one `pgsym sheet` run in every format.

The PDF is read back with pdftotext; each name and id must appear exactly (as one run of characters).
LuaLaTeX and pdftotext are installed by `make system-deps`: a missing tool is a failure, not a skip.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import unicodedata
import zipfile
from pathlib import Path

import pytest
from click.testing import CliRunner

from pgsym.cli import main

#: 12 names in 9 scripts (Latin, Han, Hiragana, Katakana, Hangul, Cyrillic, Greek, Arabic, Hebrew), with ids
#: in several scripts too.
ROSTER = [
    ("s01", "José Müller"),
    ("s02", "李雷"),
    ("学生-03", "韩梅梅"),
    ("s04", "やまだ はなこ"),
    ("s05", "タナカ タロウ"),
    ("s06", "김민준"),
    ("студент-07", "Иван Петров"),
    ("s08", "Αλέξανδρος Παπαδόπουλος"),
    ("s09", "محمد علي"),
    ("s10", "דוד כהן"),
    ("s11", "Łukasz Żółć"),
    ("s12", "Nguyễn Thị Ánh"),
]
FORMATS = ["md", "tex", "pdf", "html", "ipynb", "moodle", "qti"]

# pdftotext marks a right-to-left run with the Unicode embedding controls RLE ... PDF: they are layout,
# not text, so they are dropped before comparing
_EMBEDDING = re.compile("[\u202a-\u202e\u2066-\u2069]")


def pdf_text(path: Path) -> str:
    assert shutil.which("pdftotext"), "pdftotext is missing: run `make system-deps` (poppler-utils)"
    out = subprocess.run(["pdftotext", "-enc", "UTF-8", str(path), "-"], capture_output=True, text=True,
                         timeout=60, check=True).stdout
    return unicodedata.normalize("NFC", _EMBEDDING.sub("", out))


@pytest.fixture(scope="module")
def one_run(tmp_path_factory) -> Path:
    assert shutil.which("lualatex"), "LuaLaTeX is missing: run `make system-deps` (texlive-luatex, Noto fonts)"
    folder = tmp_path_factory.mktemp("unicode")
    roster = folder / "roster.csv"
    roster.write_text("id,name\n" + "".join(f"{i},{n}\n" for i, n in ROSTER), encoding="utf-8")
    result = CliRunner().invoke(main, ["sheet", "--topics", "join,meet:2,classify:2", "--roster", str(roster),
                                       "--seed", "5", "--format", ",".join(FORMATS), "--out", str(folder / "out")])
    assert result.exit_code == 0, result.output
    assert "sheets, answer key and key table" in result.output
    return folder / "out"


def test_every_name_and_id_is_in_the_pdf_text(one_run):
    for document in ("sheets.pdf", "key.pdf"):
        text = pdf_text(one_run / document)
        for sid, name in ROSTER:
            assert f"Student id: {sid}" in text, (document, sid)
            assert name in text, (document, name)
        assert "??" not in text and "\ufffd" not in text
    # the key table: one row per student, every name and id in its cells (a long name wraps in its cell)
    table = " ".join(pdf_text(one_run / "key-table.pdf").split())
    for sid, name in ROSTER:
        assert sid in table and name in table, name


def test_one_run_gives_sheets_key_and_table_in_every_format(one_run):
    stems = sorted(p.stem for p in (one_run / "md").iterdir())
    assert len(stems) == len(ROSTER)
    for fmt in ("md", "html", "ipynb"):
        assert sorted(p.stem for p in (one_run / fmt).iterdir()) == stems
        assert sorted(p.stem for p in (one_run / "key" / fmt).iterdir()) == stems
        assert (one_run / f"key-table.{fmt}").is_file()
    for name in ("sheets", "key", "key-table"):
        assert (one_run / f"{name}.tex").is_file()
        assert (one_run / f"{name}.pdf").read_bytes().startswith(b"%PDF")
    assert (one_run / "moodle.xml").is_file() and zipfile.is_zipfile(one_run / "qti.zip")
    # the names are in the other formats too, as typed
    manifest = json.loads((one_run / "manifest.json").read_text(encoding="utf-8"))
    assert [(s["id"], s["name"]) for s in manifest["students"]] == ROSTER
    table = (one_run / "key-table.html").read_text(encoding="utf-8")
    assert all(name in table for _, name in ROSTER)
    # the student sheets have no solutions, the key has every student's
    sheet_pdf, key_pdf = pdf_text(one_run / "sheets.pdf"), pdf_text(one_run / "key.pdf")
    assert "Solution." not in sheet_pdf and key_pdf.count("Solution.") == 3 * len(ROSTER)


def test_deprecated_flags_still_work_with_a_message(tmp_path):
    result = CliRunner().invoke(main, ["sheet", "--topics", "join", "--count", "2", "--format", "md,html",
                                       "--solutions", "--mathjax", str(tmp_path / "nowhere"),
                                       "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    assert "--solutions is deprecated; use --solutions-in-sheets" in result.output
    assert "--mathjax is deprecated and ignored" in result.output
    # --solutions means solutions in the sheets, as before; the key is written as well
    assert "Solution" in (tmp_path / "out" / "md" / "sheet-form-001.md").read_text()
    assert (tmp_path / "out" / "key" / "md" / "sheet-form-001.md").is_file()
    assert not (tmp_path / "out" / "html" / "mathjax").exists()
    new = CliRunner().invoke(main, ["sheet", "--topics", "join", "--count", "1", "--solutions-in-sheets", "--no-key",
                                    "--out", str(tmp_path / "new")])
    assert new.exit_code == 0 and "warning" not in new.output
    assert "Solution" in (tmp_path / "new" / "md" / "sheet-form-001.md").read_text()
    assert not (tmp_path / "new" / "key").exists() and not (tmp_path / "new" / "key-table.md").exists()


def test_clean_replaces_exactly_the_unsafe_code_points():
    # clean() is a single regular expression; compare it with the definition, code point by code point
    from pgsym.escaping import REPLACEMENT, clean

    def unsafe(o: int) -> bool:
        return ((o < 32 and chr(o) not in "\n\t") or 0x7F <= o < 0xA0 or 0x202A <= o <= 0x202E
                or 0x2066 <= o <= 0x2069 or 0xD800 <= o < 0xE000 or o in (0xFFFE, 0xFFFF))

    every = "".join(chr(o) for o in range(0x110000))
    assert clean(every) == "".join(REPLACEMENT if unsafe(ord(c)) else c for c in every)


def test_a_pdf_with_fallback_fonts_is_byte_reproducible():
    from pgsym.exercises import render_tex
    from pgsym.exercises.sheets import build_sheets

    assert shutil.which("lualatex"), "LuaLaTeX is missing: run `make system-deps`"
    tex = render_tex.render_document(build_sheets(["join"], ROSTER[:3] + ROSTER[8:10], 2), solutions=True)
    assert "fallback=pgsym" in tex and "Noto Naskh Arabic" in tex  # this document takes the fallback path
    assert render_tex.compile_pdf(tex) == render_tex.compile_pdf(tex)
