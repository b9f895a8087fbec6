"""CSV that a spreadsheet opens as data: cells that would start a formula are neutralised.

Spreadsheets run a cell that starts with ``=``, ``+``, ``-`` or ``@`` (and, after a tab or
carriage return, whatever follows) as a formula, which can fetch URLs or run commands. As OWASP
recommends for CSV injection, such a cell gets a leading single quote, which spreadsheets show as
text; plain numbers such as ``-3``, ``-0.5`` or ``-1.5e-06`` are left alone (they cannot be
formulas). Every CSV that pgsym writes should go through :func:`write_csv` or :func:`csv_text`.

>>> safe_cell("=HYPERLINK(\\"http://x\\")"), safe_cell("-3"), safe_cell("-2+3"), safe_cell("(1, -2, 0)")
('\\'=HYPERLINK("http://x")', '-3', "'-2+3", '(1, -2, 0)')
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Iterable
from typing import TextIO

__all__ = ["FORMULA_STARTS", "csv_text", "safe_cell", "write_csv"]

FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")
"""First characters that make a spreadsheet read a cell as a formula."""

_NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


def safe_cell(value: object) -> str:
    """The text of one CSV cell, with a ``'`` in front when a spreadsheet would run it as a formula."""
    text = "" if value is None else str(value)
    if text.startswith(FORMULA_STARTS) and not _NUMBER.fullmatch(text):
        return "'" + text
    return text


def write_csv(stream: TextIO, rows: Iterable[Iterable[object]]) -> None:
    """Write rows to ``stream`` as CSV (``\\n`` line ends), every cell through :func:`safe_cell`."""
    writer = csv.writer(stream, lineterminator="\n")
    for row in rows:
        writer.writerow([safe_cell(v) for v in row])


def csv_text(rows: Iterable[Iterable[object]]) -> str:
    """Rows as CSV text (see :func:`write_csv`).

    >>> csv_text([["id", "answer"], ["@SUM(1)", "\\tx"]])
    "id,answer\\n'@SUM(1),'\\tx\\n"
    """
    buf = io.StringIO()
    write_csv(buf, rows)
    return buf.getvalue()
