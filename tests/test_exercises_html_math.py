"""The MathML of the HTML sheets, compared with MathJax 3's MathML for the same TeX and measured in Chromium.

MathJax (node_modules/mathjax, run with node) is the independent reference: for each formula the
sequence of tokens (element, text) must be MathJax's, and where MathJax relies on its own TeX spacing
rules that a browser does not know (a sign starting a term), the page says it in MathML
(``form="prefix"``, no space).
"""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path
from xml.etree import ElementTree

import pytest

from pgsym.exercises.html_math import mathml

ROOT = Path(__file__).resolve().parents[1]
NS = "{http://www.w3.org/1998/Math/MathML}"
CASES = ["(-14, -8, 1)", "x'", "C' \\sim H^{-\\top} C H^{-1}", "a \\sim b", "x - 3", "= -3",
         "\\begin{pmatrix}-1 & 2\\\\ 3 & -4\\end{pmatrix}", "-\\frac{1}{2} + 3", "(1, \\infty)", "x_1'"]

_SCRIPT = """
const mj = require(process.argv[1]);
mj.init({loader: {load: ['input/tex-base', '[tex]/ams']}, tex: {packages: ['base', 'ams']}}).then((MathJax) => {
  const out = JSON.parse(process.argv[2]).map((tex) => MathJax.tex2mml(tex, {display: false}));
  console.log(JSON.stringify(out));
});
"""


@pytest.fixture(scope="module")
def mathjax() -> dict[str, str]:
    node = shutil.which("node")
    assert node, "node is needed to run MathJax (make mathjax installs node_modules)"
    out = subprocess.run([node, "-e", _SCRIPT, str(ROOT / "node_modules" / "mathjax"), json.dumps(CASES)],
                         capture_output=True, text=True, timeout=120, check=True)
    return dict(zip(CASES, json.loads(out.stdout), strict=True))


def tokens(markup: str) -> list[tuple[str, str]]:
    """(element, text) of every token and script element, rows left out (they only group)."""
    root = ElementTree.fromstring(markup)
    return [(e.tag[len(NS):], (e.text or "").strip()) for e in root.iter()
            if e.tag[len(NS):] not in ("math", "mrow", "mstyle", "mtable", "mtr", "mtd")]


@pytest.mark.parametrize("tex", CASES)
def test_the_tokens_are_mathjaxs(tex, mathjax):
    ours = tokens(mathml(tex, display=False))
    theirs = [(tag, "−" if text == "-" else text) for tag, text in tokens(mathjax[tex])]
    assert ours == theirs


def _prefix_signs(markup: str) -> list[str]:
    root = ElementTree.fromstring(markup)
    return [e.text for e in root.iter(NS + "mo") if e.get("form") == "prefix" and e.text in "−+"]


def test_a_sign_starting_a_term_is_prefix_and_a_difference_is_not():
    assert _prefix_signs(mathml("(-14, -8, 1)", False)) == ["−", "−"]
    assert _prefix_signs(mathml("x - 3", False)) == []
    assert _prefix_signs(mathml("a - (-b)", False)) == ["−"]  # the second sign only
    assert _prefix_signs(mathml("|x| - 3", False)) == []  # a closing bar ends a term


def test_a_prime_is_an_operator_in_a_superscript():
    root = ElementTree.fromstring(mathml("x'", False))
    sup = root.find(f".//{NS}msup")
    assert sup is not None and [c.tag[len(NS):] for c in sup] == ["mi", "mo"] and sup[1].text == "′"


def test_chromium_sets_the_minus_against_its_number(browser, tmp_path):
    # the gap between "−" and "14" in "(−14" is at most a hair (TeX: none); an infix minus would get
    # 2 × 0.2222 em (medium math space on both sides) = about 7 px at 16 px
    page = browser.new_page()
    try:
        page.set_content(f"<!doctype html><html><body style='font-size:16px'>{mathml('(-14, -8, 1)', False)}"
                         f"{mathml('x - 3', False)}</body></html>")
        page.wait_for_selector("math")
        gaps = page.evaluate("""() => [...document.querySelectorAll('math')].map((m) => {
            const mo = [...m.querySelectorAll('mo')].find((e) => e.textContent === '\\u2212');
            const next = mo.nextElementSibling, prev = mo.previousElementSibling;
            return [mo.getBoundingClientRect().left - prev.getBoundingClientRect().right,
                    next.getBoundingClientRect().left - mo.getBoundingClientRect().right];
        })""")
    finally:
        page.close()
    (before_unary, after_unary), (before_binary, after_binary) = gaps
    assert after_unary < 1.5 and before_unary < 1.5
    assert after_binary > 2.5 and before_binary > 2.5  # the difference x − 3 keeps its spaces
