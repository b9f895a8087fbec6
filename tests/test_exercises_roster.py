"""Class lists and answers files the way spreadsheets and learning platforms save them.

Fixtures follow the platforms' documentation:
- Canvas gradebook export ("How do I export grades in the Gradebook?", Canvas Instructor Guide; column
  layout as described e.g. by https://nemogb-dev.github.io/nemogb-r/articles/detailed-canvas-export-info.html):
  columns ``Student, ID, SIS User ID, SIS Login ID, Section, "Title (assignment id)"…``, ``Student`` as
  "Last, First", then a ``Points Possible`` row (and a ``Manual Posting`` row for manually posted
  assignments), and Canvas's "Test Student" without SIS id.
- Moodle grade export "Plain text file" (grade/export/txt/grade_export_txt.php): the user profile fields
  ``First name, Last name, ID number, Institution, Department, Email address`` first, then grade items;
  the separator is chosen by the exporter (comma, tab, semicolon, colon).
- R/exams ``nops_eval`` register: semicolon-separated, columns ``registration, name, id``
  (https://search.r-project.org/CRAN/refmans/exams/html/nops_eval.html).
- Excel: "CSV (semicolon)" in locales with a decimal comma, "Unicode Text" = UTF-16 LE with BOM and tabs,
  plain "CSV" = Windows-1252 on Western Windows.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from pgsym.cli import main
from pgsym.errors import InputLimitError
from pgsym.exercises.errors import AnswersFileError, RosterError
from pgsym.exercises.grading import grade_rows, read_answer_file, summary
from pgsym.exercises.model import Answer
from pgsym.exercises.roster import read_roster
from pgsym.exercises.sheets import read_roster as old_read_roster

NAMES = [("s001", "Ada Lovelace"), ("s002", "Émilie du Châtelet"), ("s003", "D’Angelo, Zoë")]


def write(tmp_path: Path, name: str, data: bytes) -> Path:
    p = tmp_path / name
    p.write_bytes(data)
    return p


def test_the_old_import_path_reads_the_same(tmp_path):
    p = write(tmp_path, "r.csv", b"id,name\ns1,Ada\n")
    assert old_read_roster(p) == read_roster(p) == [("s1", "Ada")]


@pytest.mark.parametrize("sep", [",", ";", "\t", "|"])
def test_every_separator_is_found_from_the_header(tmp_path, sep):
    # the names hold the other separators: only the right one gives two columns on every line
    rows = ["id" + sep + "name", *[sid + sep + '"' + name + '"' for sid, name in NAMES]]
    p = write(tmp_path, "r.csv", ("\r\n".join(rows) + "\r\n").encode())
    assert read_roster(p) == NAMES


def test_excel_sep_line_decides_the_separator(tmp_path):
    p = write(tmp_path, "r.csv", b"sep=;\r\nStudent ID;Name\r\ns1;Ada, A.\r\n")
    assert read_roster(p) == [("s1", "Ada, A.")]


@pytest.mark.parametrize("encoding, bom", [("utf-8", b""), ("utf-8", b"\xef\xbb\xbf"), ("utf-16-le", b"\xff\xfe"),
                                           ("utf-16-be", b"\xfe\xff"), ("utf-16-le", b"")])
def test_utf8_and_excel_unicode_text(tmp_path, encoding, bom):
    text = "id\tname\r\n" + "".join(f"{sid}\t{name}\r\n" for sid, name in NAMES)
    p = write(tmp_path, "r.txt", bom + text.encode(encoding))
    assert read_roster(p) == NAMES


def test_windows_1252_is_read_with_a_note(tmp_path):
    text = "id;name\r\n" + "".join(f"{sid};{name}\r\n" for sid, name in NAMES)
    p = write(tmp_path, "r.csv", text.encode("cp1252"))  # ’ is 0x92 in Windows-1252, invalid as UTF-8
    notes: list[str] = []
    assert read_roster(p, notes=notes) == NAMES
    assert len(notes) == 1 and "Windows-1252" in notes[0] and "CSV UTF-8" in notes[0]


def test_bytes_of_no_known_encoding_say_how_to_resave(tmp_path):
    # 0x81 is undefined in Windows-1252 and invalid UTF-8; it follows "id,name\n" (8 bytes) and "s1,A" (4): byte 13
    p = write(tmp_path, "r.csv", b"id,name\ns1,A\x81da\n")
    with pytest.raises(RosterError, match=r"byte 13 is 0x81\); re-save it as \"CSV UTF-8\""):
        read_roster(p)


def test_a_broken_utf16_file_is_named(tmp_path):
    p = write(tmp_path, "r.txt", b"\xff\xfe" + "id\n".encode("utf-16-le") + b"\x00\xdc")  # a lone low surrogate
    with pytest.raises(RosterError, match="UTF-16-LE byte-order mark"):
        read_roster(p)


def test_limit_counts_bytes_read_from_a_pipe(tmp_path):
    import os

    fifo = tmp_path / "r.csv"
    os.mkfifo(fifo)
    with pytest.raises(InputLimitError, match="not a regular file"):
        read_roster(fifo)


def test_limit_on_a_large_roster(tmp_path, monkeypatch):
    import pgsym.limits

    p = write(tmp_path, "r.csv", b"id,name\n" + b"s1,Ada\n" * 100)
    monkeypatch.setattr(pgsym.limits, "MAX_FILE_BYTES", 50)
    monkeypatch.setattr(pgsym.limits.read_file_bytes, "__defaults__", (50,))
    with pytest.raises(InputLimitError, match="larger than 50 bytes"):
        read_roster(p)


@pytest.mark.parametrize("header, expected", [
    ("Student ID,Name", [("s001", "Ada Lovelace")]),
    ("student_id,Full name", [("s001", "Ada Lovelace")]),
    ("Matriculation number,Name", [("s001", "Ada Lovelace")]),
])
def test_common_id_headers(tmp_path, header, expected):
    p = write(tmp_path, "r.csv", f"{header}\ns001,Ada Lovelace\n".encode())
    assert read_roster(p) == expected


def test_canvas_gradebook_export_takes_sis_user_id_and_student(tmp_path):
    text = ('Student,ID,SIS User ID,SIS Login ID,Section,Week 4 (1234),Current Score\r\n'
            '    Manual Posting,,,,,Manual Posting,\r\n'
            '    Points Possible,,,,,12.00,(read only)\r\n'
            '"Lovelace, Ada",87011,s001,ada,Geometry 1,10.00,83.33\r\n'
            '"D’Angelo, Zoë",87012,s003,zoe,Geometry 1,,0\r\n'
            '"Student, Test",87999,,a1b2c3,Geometry 1,,\r\n')
    p = write(tmp_path, "grades.csv", text.encode("utf-8-sig"))
    assert read_roster(p) == [("s001", "Lovelace, Ada"), ("s003", "D’Angelo, Zoë")]
    # Canvas's own id only on request; the test student has a Canvas id but is still no student
    assert read_roster(p, id_column="ID") == [("87011", "Lovelace, Ada"), ("87012", "D’Angelo, Zoë")]


def test_canvas_student_without_sis_id_is_named(tmp_path):
    text = ('Student,ID,SIS User ID,SIS Login ID,Section\n    Points Possible,,,,\n'
            '"Lovelace, Ada",87011,,ada,G1\n')
    p = write(tmp_path, "grades.csv", text.encode())
    with pytest.raises(RosterError, match=r"line 3 .* no student id \(column 'SIS User ID'\).*--roster-id-column ID"):
        read_roster(p)


def test_canvas_export_without_the_sis_column_is_refused(tmp_path):
    text = 'Student,ID,Section\n    Points Possible,,\n"Lovelace, Ada",87011,G1\n'
    p = write(tmp_path, "grades.csv", text.encode())
    with pytest.raises(RosterError, match="without the 'SIS User ID' column"):
        read_roster(p)
    assert read_roster(p, id_column="ID") == [("87011", "Lovelace, Ada")]


def test_moodle_grade_export_takes_id_number_and_joins_the_names(tmp_path):
    text = ("First name\tLast name\tID number\tInstitution\tDepartment\tEmail address\tQuiz: Week 4 (Real)\n"
            "Ada\tLovelace\ts001\tUni\tMath\tada@example.org\t10.00\n"
            "Zoë\tD’Angelo\ts003\tUni\tMath\tzoe@example.org\t-\n")
    p = write(tmp_path, "grades.txt", b"\xff\xfe" + text.encode("utf-16-le"))
    assert read_roster(p) == [("s001", "Ada Lovelace"), ("s003", "Zoë D’Angelo")]


def test_r_exams_register_takes_the_registration_number(tmp_path):
    p = write(tmp_path, "register.csv", b"registration;name;id\n01234567;Ada Lovelace;alove\n")
    assert read_roster(p) == [("01234567", "Ada Lovelace")]


def test_an_unknown_separator_is_named(tmp_path):
    p = write(tmp_path, "r.csv", b"id:name\ns1:Ada\n")
    with pytest.raises(RosterError, match="the separator looks like ':'"):
        read_roster(p)


def test_the_cli_reads_a_semicolon_utf16_roster(tmp_path):
    roster = write(tmp_path, "r.txt", "\ufeffStudent ID;Name\r\ns1;Zoë\r\n".encode("utf-16-le"))
    result = CliRunner().invoke(main, ["sheet", "--topics", "join", "--roster", str(roster), "--out",
                                       str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "out" / "md" / "sheet-s1.md").read_text().count("Zoë") >= 1


# answers files: read like rosters, and checked against the manifest's questions

KEYS = {"s1": {"1": Answer.projective([1, -2, 0]), "2": Answer.projective([0, 1, 1])}}


def test_answers_with_columns_matching_no_question_are_an_error(tmp_path):
    p = write(tmp_path, "a.csv", b"id,Q1,Q2\ns1,\"(1,-2,0)\",\"(0,1,1)\"\n")
    with pytest.raises(AnswersFileError, match=r"its columns are 'Q1', 'Q2', the questions are 1, 2"):
        read_answer_file(p, KEYS)


def test_answers_in_long_form_matching_no_question_are_an_error(tmp_path):
    p = write(tmp_path, "a.csv", b"id,question,answer\ns1,Q1,\"(1,-2,0)\"\n")
    with pytest.raises(AnswersFileError, match="question cells are 'Q1'"):
        read_answer_file(p, KEYS)


def test_a_stray_column_is_reported_and_platform_columns_are_not_questions(tmp_path):
    p = write(tmp_path, "a.csv", "Student ID;Name;Email address;1;2;Q3\r\ns1;Ada;a@b.c;(2,-4,0);(0,1,1);7\r\n"
              .encode("cp1252"))
    rows, messages = read_answer_file(p, KEYS)
    assert sorted(label for _, label, _ in rows) == ["1", "2"]
    assert messages == ["column 'Q3' of 'a.csv' is no question of the manifest and was not graded"]
    assert summary(grade_rows(KEYS, rows)) == [("s1", 2, 2)]


def test_the_same_row_twice_is_one_answer_and_different_rows_a_conflict(tmp_path):
    p = write(tmp_path, "a.csv", b"id,1,2\ns1,\"(1,-2,0)\",\"(0,1,1)\"\ns1,\"(1,-2,0)\",\"(0,2,2)\"\n")
    report = grade_rows(KEYS, read_answer_file(p, KEYS)[0])
    by_label = {r.label: r for r in report["s1"]}
    assert by_label["1"].correct and not by_label["1"].unreadable  # identical twice: graded once, right
    assert by_label["2"].unreadable and "answered 2 times" in by_label["2"].reason  # (0,1,1) vs (0,2,2) differ


def test_an_unknown_id_header_says_how_to_name_it(tmp_path):
    p = write(tmp_path, "r.csv", b"Kennung;Name\nk1;Ada\n")
    with pytest.raises(RosterError, match=r"found: 'Kennung', 'Name'\); or name the id column with --roster-id-column"):
        read_roster(p)
    assert read_roster(p, id_column="kennung") == [("k1", "Ada")]


def test_an_empty_moodle_id_number_suggests_another_column(tmp_path):
    text = "First name,Last name,ID number,Email address\nAda,Lovelace,,ada@example.org\n"
    p = write(tmp_path, "grades.csv", text.encode())
    with pytest.raises(RosterError, match=r"line 2 .*'ID number'.*--roster-id-column 'Email address'"):
        read_roster(p)
    assert read_roster(p, id_column="Email address") == [("ada@example.org", "Ada Lovelace")]
