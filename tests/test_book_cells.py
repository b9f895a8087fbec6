"""What a reader sees in a chapter's code cells, read from the committed notebooks.

- A visible cell asserts the mathematics it shows: checks of how pgsym prints (strings, certificates,
  sizes of expansions, plot internals) live in hidden cells (tag `remove-cell`) or in `tests/`.
- The printing helpers of the chapters have one home, `book/_show.py`: no chapter defines them again.

A cell is visible when the page shows its code without a click: no tag `hide-input`, `hide-cell`,
`remove-input` or `remove-cell`.
"""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "book").glob("*.ipynb"))
HIDDEN = {"hide-input", "hide-cell", "remove-input", "remove-cell"}

# Names whose appearance in an assert means it checks a format, not the mathematics.
FORMAT_CALLS = {"str", "repr", "format"}
FORMAT_ATTRIBUTES = {"startswith", "endswith", "certificate", "ring", "largest_degree", "identity_size",
                     "get_offsets", "get_lines", "get_texts", "get_children"}
SHARED_HELPERS = {"report", "expect", "dot", "xy"}


def visible_cells(path: Path) -> list[tuple[int, str]]:
    nb = json.loads(path.read_text(encoding="utf-8"))
    return [(i, "".join(c["source"])) for i, c in enumerate(nb["cells"])
            if c["cell_type"] == "code" and not HIDDEN & set(c.get("metadata", {}).get("tags", []))]


def _compared_strings(test: ast.expr) -> bool:
    """Does the assert compare with a string, outside call arguments and subscripts (``d["key"]``)?"""
    def strings(node: ast.AST) -> bool:
        if isinstance(node, ast.Constant):
            return isinstance(node.value, str)
        if isinstance(node, (ast.Call, ast.Subscript)):
            return False  # prove("name"), d["key"]: a name, not a printed format
        return any(strings(child) for child in ast.iter_child_nodes(node))
    return any(strings(side) for node in ast.walk(test) if isinstance(node, ast.Compare)
               for side in (node.left, *node.comparators))


def format_checks(source: str) -> list[str]:
    """The asserts of a cell that test a format rather than mathematics, as source text.

    >>> format_checks("assert v.proved\\nassert v.certificate.ring.startswith('Z')\\nassert A == B")
    ["assert v.certificate.ring.startswith('Z')"]
    >>> format_checks("assert str(P) == 'Point(1, 2, 1)'\\nassert prove('join-ignores-scale').proved")
    ["assert str(P) == 'Point(1, 2, 1)'"]
    """
    bad = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Assert):
            continue
        parts = list(ast.walk(node.test))
        if _compared_strings(node.test) or any(
            isinstance(p, ast.Call) and isinstance(p.func, ast.Name) and p.func.id in FORMAT_CALLS for p in parts
        ) or any(isinstance(p, ast.Attribute) and p.attr in FORMAT_ATTRIBUTES for p in parts):
            bad.append(ast.get_source_segment(source, node))
    return bad


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_visible_cells_assert_mathematics_not_formats(path):
    found = [(i, check) for i, src in visible_cells(path) for check in format_checks(src)]
    assert found == [], f"{path.name}: move these checks into a hidden cell (tag remove-cell): {found}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_chapters_import_the_shared_printing_helpers(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    defined = {node.name for c in nb["cells"] if c["cell_type"] == "code"
               for node in ast.walk(ast.parse("".join(c["source"])))
               if isinstance(node, ast.FunctionDef) and node.name in SHARED_HELPERS}
    assert defined == set(), f"{path.name} defines {sorted(defined)}: import them from book/_show.py"


def test_the_format_check_finds_what_it_should():
    # the rule must be able to fail: a certificate check and a string comparison are found, mathematics is not
    assert format_checks("assert v.certificate.ring.startswith('Z')") != []
    assert format_checks("assert v.status == 'proved'") != []
    assert format_checks("assert v.conclusion == ['AA', 'BB']") != []
    assert format_checks("assert join(P, Q) == Line(1, -1, 0)\nassert v.proved") == []
    assert format_checks("assert err['five pairs'] < 0.25 and prove('x').proved") == []
