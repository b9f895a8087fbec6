"""Moodle STACK questions (Moodle XML, question type ``stack``) that grade up to scale and name pgsym's mistakes.

One question per exercise variant, one category per exercise slot; each part is an input ``ansK``
with its own potential response tree ``prtK`` worth the part's points
(:mod:`pgsym.exercises.points`), so a multi-part exercise gets partial credit per part. The tree of
a part is a chain of nodes, each the answer test ``AlgEquiv(v, true)`` of a boolean ``v`` the
feedback variables compute in Maxima:

1. ``right``: for a homogeneous answer (a point, line, plane, conic or homography) the student's
   vector is nonzero and a multiple of the key, ``rank(matrix(sa)) = 1`` and ``rank(matrix(sa, key)) = 1``;
   for an exact answer the values are equal (Maxima reduces fractions, so ``-2/6`` is ``-1/3``);
2. one node per mistake the manifest stores for the part (:mod:`pgsym.exercises.mistakes`: the dual
   object, H l instead of H⁻ᵀ l, a transposed or inverted matrix, the points in another order, an ideal
   point given as finite, …), in the order ``pgsym check`` tries them, with pgsym's feedback text;
3. ``wf``: the answer has the right shape (a list of n rational numbers, an r×c matrix, a number, one
   of the letters); otherwise the student is told what to type.

The answer notes (``prtK-right``, ``prtK-mistake-CODE``, ``prtK-wrong``, ``prtK-unreadable``) appear
in Moodle's Responses report, and the worked solution is the general feedback. Every question also
carries STACK question tests (the key, a multiple of it, each stored mistake, with the notes expected),
which Moodle runs under "Question tests & deployed variants". The question note
carries the variant id, so that ``pgsym check`` can grade the Responses report of a quiz that drew
random variants. STACK refuses decimals at validation (``forbidfloat``), so students type fractions;
pgsym reads decimals exactly, the one place where the two differ.

The format follows STACK's documentation (``doc/en/Authoring/Potential_response_trees.md``,
``Answer_Tests/index.md``, ``Inputs/Multiple_choice_input.md`` of maths/moodle-qtype_stack) and its
sample questions. Text goes through :func:`~pgsym.escaping.to_moodle` (CASText's ``{@``, ``{#`` and
``[[`` become entities), names through XML escaping; the Maxima code is made from the key only.

>>> from pgsym.exercises.sheets import build_sheet
>>> xml = render_stack_quiz([build_sheet(["join"], "s1", "", 1)])
>>> '<question type="stack">' in xml and "rank(matrix(sa1,[" in xml
True
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from fractions import Fraction
from xml.sax.saxutils import escape

from ..escaping import one_line, to_moodle
from .answers import matches
from .model import Answer, Exercise, Mistake, Part, Sheet, variant_id
from .points import points_text

__all__ = ["prt_logic", "render_stack_quiz"]

_LETTERS = "ABCDEFGH"


def _num(value: Fraction | int) -> str:
    value = Fraction(value)
    return str(value.numerator) if value.denominator == 1 else f"{value.numerator}/{value.denominator}"


def _list(values: Sequence[Fraction | int]) -> str:
    return "[" + ",".join(_num(v) for v in values) + "]"


def _maxima(answer: Answer) -> str:
    """The Maxima value of an answer (the teacher's answer of the input)."""
    if answer.kind in ("projective", "vector"):
        return _list(answer.value)
    if answer.kind in ("scalar", "integer"):
        return _num(answer.value)
    if answer.kind in ("matrix", "matrix_exact"):
        return "matrix(" + ",".join(_list(row) for row in answer.value) + ")"
    return str(answer.value)


def _flat(answer: Answer) -> str:
    return _list(answer.flat())


def _shape(key: Answer, k: int) -> str:
    """Maxima: is the student's ``sa{k}`` of the key's shape (only exact rational numbers inside)?"""
    sa = f"sa{k}"
    if key.kind in ("projective", "vector"):
        return f"listp({sa}) and is(length({sa})={len(key.value)}) and every(ratnump,{sa})"
    if key.kind == "scalar":
        return f"ratnump({sa})"
    if key.kind == "integer":
        return f"integerp({sa})"
    if key.kind in ("matrix", "matrix_exact"):
        rows, cols = len(key.value), len(key.value[0])
        return (f"matrixp({sa}) and is(length({sa})={rows}) and is(length({sa}[1])={cols}) "
                f"and every(ratnump,flatten(args({sa})))")
    return f"member({sa},[{','.join(_LETTERS)}])"  # every letter pgsym reads is an answer, right or wrong


def _choices(key: Answer) -> int:
    return _LETTERS.index(key.value) + 1 if key.value in _LETTERS else 2


def _equal(candidate: Answer, key_kind: str, k: int) -> str:
    """Maxima: does the well-formed answer match ``candidate`` (up to scale for a homogeneous candidate)?"""
    if candidate.kind in ("projective", "matrix"):
        flat = f"sa{k}" if key_kind in ("projective", "vector") else f"fl{k}"
        return f"is(rank(matrix({flat}))=1) and is(rank(matrix({flat},{_flat(candidate)}))=1)"
    if candidate.kind in ("matrix_exact",):
        return f"is(fl{k}={_flat(candidate)})"
    return f"is(sa{k}={_maxima(candidate)})"


def _ordered(key: Answer, mistakes: Sequence[Mistake]) -> list[Mistake]:
    """The mistakes in the order :func:`pgsym.exercises.mistakes.recognise` tries them: concrete first."""
    return [*(m for m in mistakes if m.answer.kind == key.kind), *(m for m in mistakes if m.answer.kind != key.kind)]


def prt_logic(part: Part, k: int) -> tuple[str, list[tuple[str, str, str]]]:
    """The feedback variables of part ``k`` (Maxima) and its nodes as (variable, answer note, feedback).

    >>> fv, nodes = prt_logic(Part("1", "P", Answer.projective([1, -2, 0])), 1)
    >>> [n[1] for n in nodes]
    ['prt1-right', 'prt1-wrong']
    """
    key = part.answer
    lines = [f"sa{k}:ans{k};", f"wf{k}:{_shape(key, k)};"]
    if key.kind in ("matrix", "matrix_exact"):
        lines.append(f"fl{k}:if wf{k} then flatten(args(sa{k})) else [];")
    lines.append(f"right{k}:if wf{k} then ({_equal(key, key.kind, k)}) else false;")
    nodes = [(f"right{k}", f"prt{k}-right", "")]
    for j, m in enumerate(_ordered(key, part.mistakes), start=1):
        lines.append(f"m{k}x{j}:if wf{k} then ({_equal(m.answer, key.kind, k)}) else false;")
        nodes.append((f"m{k}x{j}", f"prt{k}-mistake-{_code(m)}", m.message))
    nodes.append((f"wf{k}", f"prt{k}-wrong", ""))
    return "\n".join(lines), nodes


_TYPE_HINT = {
    "projective": "a list such as [1, -2, 0]; any nonzero multiple is right (fractions such as 1/2, no decimals)",
    "vector": "a list such as [1/2, -3]; fractions are exact (no decimals)",
    "scalar": "a number such as -3/4 (no decimals)",
    "integer": "an integer",
    "matrix": "the entries of the matrix; any nonzero multiple is right (fractions, no decimals)",
    "matrix_exact": "the entries of the matrix (fractions, no decimals)",
    "choice": "one of the letters",
}


def _html(text: str) -> str:
    return f'<text><![CDATA[{text.replace("]]>", "]]]]><![CDATA[>")}]]></text>'


def _node(index: int, variable: str, note: str, feedback: str, last: bool, right: bool, unreadable_text: str,
          k: int) -> str:
    """One node: AlgEquiv(variable, true); true ends with its score, false goes on (or ends at the last)."""
    true_score = "1" if right else "0"
    true_next = "-1"
    false_next = "-1" if last else str(index + 1)
    false_note = f"prt{k}-unreadable" if last else f"prt{k}-{index}-F"
    false_feedback = unreadable_text if last else ""
    true_feedback = to_moodle(feedback) if feedback else ""
    return (f"      <node>\n        <name>{index}</name>\n        <description/>\n"
            f"        <answertest>AlgEquiv</answertest>\n        <sans>{variable}</sans>\n        <tans>true</tans>\n"
            "        <testoptions/>\n        <quiet>1</quiet>\n"
            f"        <truescoremode>=</truescoremode>\n        <truescore>{true_score}</truescore>\n"
            "        <truepenalty>0</truepenalty>\n"
            f"        <truenextnode>{true_next}</truenextnode>\n"
            f"        <trueanswernote>{escape(note)}</trueanswernote>\n"
            f'        <truefeedback format="html">{_html(true_feedback)}</truefeedback>\n'
            "        <falsescoremode>=</falsescoremode>\n        <falsescore>0</falsescore>\n"
            "        <falsepenalty>0</falsepenalty>\n"
            f"        <falsenextnode>{false_next}</falsenextnode>\n"
            f"        <falseanswernote>{escape(false_note)}</falseanswernote>\n"
            f'        <falsefeedback format="html">{_html(false_feedback)}</falsefeedback>\n'
            "      </node>\n")


def _input(part: Part, k: int) -> str:
    key = part.answer
    if key.kind == "choice":
        kind = "dropdown"
        tans = f"tc{k}"
    elif key.kind in ("matrix", "matrix_exact"):
        kind, tans = "matrix", f"ta{k}"
    else:
        kind, tans = "algebraic", f"ta{k}"
    return (f"    <input>\n      <name>ans{k}</name>\n      <type>{kind}</type>\n      <tans>{tans}</tans>\n"
            "      <boxsize>20</boxsize>\n      <strictsyntax>1</strictsyntax>\n      <insertstars>0</insertstars>\n"
            "      <syntaxhint/>\n      <syntaxattribute>0</syntaxattribute>\n      <forbidwords/>\n"
            "      <allowwords/>\n      <forbidfloat>1</forbidfloat>\n"
            "      <requirelowestterms>0</requirelowestterms>\n"
            "      <checkanswertype>0</checkanswertype>\n      <mustverify>1</mustverify>\n"
            "      <showvalidation>1</showvalidation>\n      <options/>\n    </input>\n")


def _variables(ex: Exercise) -> str:
    lines = []
    for k, part in enumerate(ex.parts, start=1):
        lines.append(f"ta{k}:{_maxima(part.answer)};")
        if part.answer.kind == "choice":
            letters = _LETTERS[:max(len(part.choices), _choices(part.answer))]
            lines.append(f"tc{k}:[" + ",".join(f'[{c},{"true" if c == part.answer.value else "false"},"{c}"]'
                                                for c in letters) + "];")
    return "\n".join(lines)


def _scaled(answer: Answer, factor: int) -> Answer:
    """A nonzero multiple of a homogeneous answer (another right answer); exact answers unchanged."""
    if answer.kind == "projective":
        return Answer("projective", tuple(factor * v for v in answer.value))
    if answer.kind == "matrix":
        return Answer("matrix", tuple(tuple(factor * v for v in row) for row in answer.value))
    return answer


def _qtest(number: int, description: str, inputs: Sequence[str], expected: Sequence[tuple[str, str]]) -> str:
    """A STACK question test: the inputs and, for every tree, the expected score and answer note."""
    given = "".join(f"      <testinput>\n        <name>ans{k}</name>\n        <value>{escape(v)}</value>\n"
                    "      </testinput>\n" for k, v in enumerate(inputs, start=1))
    wanted = "".join(f"      <expected>\n        <name>prt{k}</name>\n        <expectedscore>{score}</expectedscore>\n"
                     "        <expectedpenalty>0</expectedpenalty>\n"
                     f"        <expectedanswernote>{escape(note)}</expectedanswernote>\n      </expected>\n"
                     for k, (score, note) in enumerate(expected, start=1))
    return (f"    <qtest>\n      <testcase>{number}</testcase>\n"
            f"      <description>{escape(description)}</description>\n{given}{wanted}    </qtest>\n")


def _qtests(ex: Exercise) -> str:
    """Question tests Moodle can run ("Question tests & deployed variants"): the key, a multiple of it and
    every stored mistake, each with the verdicts ``pgsym check`` gives."""
    keys = [_maxima(p.answer) for p in ex.parts]
    right = [("1", f"prt{k}-right") for k in range(1, len(ex.parts) + 1)]
    tests = [_qtest(1, "the key", keys, right),
             _qtest(2, "a multiple of the key (right up to scale)", [_maxima(_scaled(p.answer, -2)) for p in ex.parts],
                    right)]
    for k, part in enumerate(ex.parts, start=1):
        ordered = _ordered(part.answer, part.mistakes)
        for m in ordered:
            typed = _scaled(m.answer, 3)  # a multiple of a homogeneous mistake is the same mistake
            caught = next(x for x in ordered if matches(x.answer, typed.value))  # the first node that fires
            inputs = [*keys[:k - 1], _maxima(typed), *keys[k:]]
            expected = [*right[:k - 1], ("0", f"prt{k}-mistake-{_code(caught)}"), *right[k:]]
            tests.append(_qtest(len(tests) + 1, f"part {part.label}: {m.code}", inputs, expected))
    return "".join(tests)


def _code(m: Mistake) -> str:
    return re.sub(r"[^A-Za-z0-9-]", "_", m.code)[:40]


def _question(sheet: Sheet, ex: Exercise) -> str:
    vid = variant_id(sheet.form_id, ex.slot)
    text = [f"<p>{to_moodle(ex.statement)}</p>"]
    prts = []
    for k, part in enumerate(ex.parts, start=1):
        text.append(f"<p><b>[{escape(part.label)}]</b> {to_moodle(part.prompt)} "
                    f"<i>Type {escape(_TYPE_HINT[part.answer.kind])}.</i></p>")
        if part.choices:
            text.append('<ol type="A">' + "".join(f"<li>{to_moodle(c)}</li>" for c in part.choices) + "</ol>")
        text.append(f"<p>[[input:ans{k}]] [[validation:ans{k}]]</p><div>[[feedback:prt{k}]]</div>")
        variables, nodes = prt_logic(part, k)
        unreadable = to_moodle(f"This answer does not have the expected form: type {_TYPE_HINT[part.answer.kind]}.")
        body = "".join(_node(i, var, note, fb, i == len(nodes) - 1, i == 0, unreadable, k)
                       for i, (var, note, fb) in enumerate(nodes))
        prts.append(f"    <prt>\n      <name>prt{k}</name>\n      <value>{points_text(part.points)}</value>\n"
                    "      <autosimplify>1</autosimplify>\n      <feedbackstyle>1</feedbackstyle>\n"
                    f"      <feedbackvariables>\n        <text>{escape(variables)}</text>\n      </feedbackvariables>\n"
                    f"{body}    </prt>\n")
    text.append(f'<p style="font-size:smaller">pgsym variant {vid}</p>')
    solution = "<ol>" + "".join(f"<li>{to_moodle(s)}</li>" for s in ex.solution) + "</ol>"
    solution += "".join(f"<p><b>[{escape(p.label)}]</b> {escape(p.answer.display())}</p>" for p in ex.parts)
    name = one_line(f"{ex.slot}. {ex.title} [pgsym {vid}]")
    return ('  <question type="stack">\n'
            f"    <name><text>{escape(name)}</text></name>\n"
            f'    <questiontext format="html">{_html("".join(text))}</questiontext>\n'
            f'    <generalfeedback format="html">{_html(solution)}</generalfeedback>\n'
            f"    <defaultgrade>{points_text(ex.points)}</defaultgrade>\n    <penalty>0</penalty>\n"
            "    <hidden>0</hidden>\n    <idnumber/>\n"
            f"    <questionvariables>\n      <text>{escape(_variables(ex))}</text>\n    </questionvariables>\n"
            '    <specificfeedback format="html"><text/></specificfeedback>\n'
            f'    <questionnote format="html"><text>pgsym {escape(vid)}</text></questionnote>\n'
            "    <questionsimplify>1</questionsimplify>\n    <assumepositive>0</assumepositive>\n"
            "    <assumereal>0</assumereal>\n"
            '    <prtcorrect format="html"><text>Correct answer, well done.</text></prtcorrect>\n'
            '    <prtpartiallycorrect format="html"><text>Your answer is partially correct.</text>'
            "</prtpartiallycorrect>\n"
            '    <prtincorrect format="html"><text>Incorrect answer.</text></prtincorrect>\n'
            "    <decimals>.</decimals>\n    <multiplicationsign>dot</multiplicationsign>\n"
            "    <sqrtsign>1</sqrtsign>\n    <complexno>i</complexno>\n    <inversetrig>cos-1</inversetrig>\n"
            "    <matrixparens>[</matrixparens>\n    <variantsselectionseed/>\n"
            + "".join(_input(p, k) for k, p in enumerate(ex.parts, start=1)) + "".join(prts) + _qtests(ex)
            + "  </question>\n")


def render_stack_quiz(sheets: Sequence[Sheet], course: str = "pgsym") -> str:
    """The Moodle XML of every variant as STACK questions, one category per exercise slot."""
    out = ['<?xml version="1.0" encoding="UTF-8"?>\n', "<quiz>\n"]
    for index, first in enumerate(sheets[0].exercises if sheets else ()):
        topic = re.sub(r"[^A-Za-z0-9_-]", "_", first.topic)
        category = f"$course$/{one_line(course)}/{first.slot:02d}-{topic}-level{first.level}-stack"
        out.append(f'  <question type="category">\n    <category><text>{escape(category)}</text></category>\n'
                   "  </question>\n")
        out += [_question(sheet, sheet.exercises[index]) for sheet in sheets]
    out.append("</quiz>\n")
    return "".join(out)
