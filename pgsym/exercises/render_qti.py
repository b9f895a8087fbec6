"""IMS QTI 1.2 package (a zip) for Canvas: one question bank per topic, one quiz with a question group per
topic that draws one of its variants.

The zip holds ``imsmanifest.xml`` (IMS Content Packaging), ``banks/bank-NN-TOPIC.xml`` (an
``objectbank`` per exercise slot, every student's variant an ``item``) and ``quiz.xml`` (an
``assessment`` whose sections are Canvas question groups, ``selection_number`` 1, holding the same
variants). Answers are asked in canonical form, the text ``pgsym check`` reads
(:meth:`~pgsym.exercises.model.Answer.display`; homogeneous answers as coprime integers, first nonzero
entry positive): an integer is a ``numerical_question`` (exact), a single other answer a
``short_answer_question``, a multiple-choice part a ``multiple_choice_question`` and several parts a
``fill_in_multiple_blanks_question`` with one blank per part.

Question text is HTML made by :func:`~pgsym.escaping.to_html` (math as ``\\(...\\)``, which Canvas
typesets) carried as escaped text; names and titles go through :func:`~pgsym.escaping.xml_escape`.
The zip is byte-reproducible (fixed timestamps, fixed order).

>>> import io, zipfile
>>> from pgsym.exercises.sheets import build_sheet
>>> z = zipfile.ZipFile(io.BytesIO(render_package([build_sheet(["join"], "s1", "", 1)], [("join", 1)])))
>>> sorted(z.namelist())
['banks/bank-01-join.xml', 'imsmanifest.xml', 'quiz.xml']
"""

from __future__ import annotations

import html
import io
import re
import zipfile
from collections.abc import Sequence
from fractions import Fraction

from ..escaping import one_line, to_html, xml_escape
from .model import KIND_HINTS, Exercise, Part, Sheet

__all__ = ["QTI_NAMESPACE", "render_package"]

QTI_NAMESPACE = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"
_HEAD = (f'<?xml version="1.0" encoding="UTF-8"?>\n<questestinterop xmlns="{QTI_NAMESPACE}" '
         'xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:schemaLocation="'
         f'{QTI_NAMESPACE} http://www.imsglobal.org/xsd/ims_qtiasiv1p2p1.xsd">\n')
_FIXED_TIME = (1980, 1, 1, 0, 0, 0)


def _field(label: str, entry: str) -> str:
    return (f"<qtimetadatafield><fieldlabel>{label}</fieldlabel>"
            f"<fieldentry>{xml_escape(entry)}</fieldentry></qtimetadatafield>")


def _material(html_text: str) -> str:
    return f'<material><mattext texttype="text/html">{xml_escape(html_text)}</mattext></material>'


def _accepted(part: Part) -> list[str]:
    """The texts accepted for a part: the canonical text, and the same without spaces."""
    text = part.answer.display()
    return list(dict.fromkeys([text, text.replace(" ", "")]))


def _is_integer(part: Part) -> bool:
    return part.answer.kind in ("integer", "scalar") and Fraction(part.answer.value).denominator == 1


def _blank(label: str) -> str:
    return "q" + re.sub(r"[^A-Za-z0-9]", "_", label)


def _prompt(part: Part, blank: str | None) -> str:
    canonical = ("" if part.answer.kind in ("choice", "integer") else
                 f" Type it exactly as {KIND_HINTS[part.answer.kind]}; homogeneous answers as coprime integers "
                 "with the first nonzero entry positive.")
    text = f"<p><b>[{part.label}]</b> {to_html(part.prompt)}{html.escape(canonical, quote=False)}"
    if part.choices:
        text += '<ol type="A">' + "".join(f"<li>{to_html(c)}</li>" for c in part.choices) + "</ol>"
    if blank is not None:
        text += f" Answer: [{blank}]"
    return text + "</p>"


def _item(ident: str, sheet: Sheet, ex: Exercise) -> str:
    title = one_line(f"{ex.slot}. {ex.title} [{sheet.form_id} / {sheet.student_id}]")
    single = len(ex.parts) == 1
    part = ex.parts[0]
    if single and part.answer.kind == "choice":
        qtype = "multiple_choice_question"
    elif single and _is_integer(part):
        qtype = "numerical_question"
    elif single:
        qtype = "short_answer_question"
    else:
        qtype = "fill_in_multiple_blanks_question"
    blanks = qtype == "fill_in_multiple_blanks_question"
    body = f"<p>{to_html(ex.statement)}</p>" + "".join(_prompt(p, _blank(p.label) if blanks else None)
                                                     for p in ex.parts)
    out = [f'<item ident="{ident}" title="{xml_escape(title)}">',
           "<itemmetadata><qtimetadata>" + _field("question_type", qtype) + _field("points_possible", "1.0")
           + _field("original_answer_ids", "") + "</qtimetadata></itemmetadata>",
           "<presentation>" + _material(body)]
    conditions: list[str] = []
    if qtype == "multiple_choice_question":
        labels = "".join(f'<response_label ident="{letter}">' + _material(to_html(choice)) + "</response_label>"
                         for letter, choice in zip("ABCDEFGH", part.choices, strict=False))
        out.append(f'<response_lid ident="response1" rcardinality="Single"><render_choice>{labels}'
                   "</render_choice></response_lid>")
        conditions.append(f'<varequal respident="response1">{xml_escape(str(part.answer.value))}</varequal>')
    elif qtype == "numerical_question":
        value = str(Fraction(part.answer.value).numerator)
        out.append('<response_str ident="response1" rcardinality="Single"><render_fib fibtype="Decimal">'
                   '<response_label ident="answer1"/></render_fib></response_str>')
        conditions.append(f'<or><varequal respident="response1">{value}</varequal><and>'
                          f'<vargte respident="response1">{value}</vargte><varlte respident="response1">{value}'
                          "</varlte></and></or>")
    elif qtype == "short_answer_question":
        out.append('<response_str ident="response1" rcardinality="Single"><render_fib>'
                   '<response_label ident="answer1" rshuffle="No"/></render_fib></response_str>')
        conditions.append("<or>" + "".join(f'<varequal respident="response1">{xml_escape(t)}</varequal>'
                                           for t in _accepted(part)) + "</or>")
    else:
        for p in ex.parts:
            blank = _blank(p.label)
            accepted = [str(p.answer.value)] if p.answer.kind == "choice" else _accepted(p)
            labels = "".join(f'<response_label ident="{ident}_{blank}_{i}">'
                             f'<material><mattext texttype="text/plain">{xml_escape(t)}</mattext></material>'
                             "</response_label>" for i, t in enumerate(accepted))
            out.append(f'<response_lid ident="response_{blank}"><material><mattext>{blank}</mattext></material>'
                       f"<render_choice>{labels}</render_choice></response_lid>")
    out.append("</presentation>")
    out.append('<resprocessing><outcomes><decvar maxvalue="100" minvalue="0" varname="SCORE" vartype="Decimal"/>'
               "</outcomes>")
    if blanks:
        share = f"{100 / len(ex.parts):.2f}"
        for p in ex.parts:
            blank = _blank(p.label)
            n = 1 if p.answer.kind == "choice" else len(_accepted(p))
            alternatives = "".join(f'<varequal respident="response_{blank}">{ident}_{blank}_{i}</varequal>'
                                   for i in range(n))
            out.append(f"<respcondition><conditionvar><or>{alternatives}</or></conditionvar>"
                       f'<setvar varname="SCORE" action="Add">{share}</setvar></respcondition>')
    else:
        out.append(f'<respcondition continue="No"><conditionvar>{conditions[0]}</conditionvar>'
                   '<setvar varname="SCORE" action="Set">100</setvar></respcondition>')
    out.append("</resprocessing></item>")
    return "".join(out)


def _slug(topic: str) -> str:
    return re.sub(r"[^A-Za-z0-9_-]", "_", topic)[:40]


def render_package(sheets: Sequence[Sheet], topics: Sequence[tuple[str, int]], title: str = "pgsym exercises") -> bytes:
    """The QTI 1.2 zip of every variant of every student (``topics`` as given to ``pgsym sheet``)."""
    files: dict[str, str] = {}
    groups = []
    slots = sheets[0].exercises if sheets else ()
    for index, first in enumerate(slots):
        name = f"{first.slot:02d}-{_slug(first.topic)}"
        bank_id = f"bank_{first.slot:02d}"
        bank_title = one_line(f"{first.slot:02d} {first.title} (level {first.level})")
        items = [_item(f"b{first.slot:02d}_{n:05d}", s, s.exercises[index]) for n, s in enumerate(sheets)]
        files[f"banks/bank-{name}.xml"] = (
            _HEAD + f'<objectbank ident="{bank_id}"><qtimetadata>{_field("bank_title", bank_title)}</qtimetadata>\n'
            + "\n".join(items) + "\n</objectbank>\n</questestinterop>\n")
        group_items = [_item(f"g{first.slot:02d}_{n:05d}", s, s.exercises[index]) for n, s in enumerate(sheets)]
        groups.append(f'<section ident="group_{first.slot:02d}" title="{xml_escape(bank_title)}"><selection_ordering>'
                      "<selection><selection_number>1</selection_number><selection_extension>"
                      "<points_per_item>1</points_per_item></selection_extension></selection></selection_ordering>\n"
                      + "\n".join(group_items) + "\n</section>")
    files["quiz.xml"] = (_HEAD + f'<assessment ident="pgsym_quiz" title="{xml_escape(one_line(title))}">'
                         f'<qtimetadata>{_field("cc_maxattempts", "1")}</qtimetadata>'
                         '<section ident="root_section">\n' + "\n".join(groups)
                         + "\n</section></assessment>\n</questestinterop>\n")
    resources = "".join(f'<resource identifier="res_{i}" type="imsqti_xmlv1p2" href="{path}"><file href="{path}"/>'
                        "</resource>" for i, path in enumerate(sorted(files)))
    files["imsmanifest.xml"] = (
        '<?xml version="1.0" encoding="UTF-8"?>\n<manifest identifier="pgsym_qti_package" '
        'xmlns="http://www.imsglobal.org/xsd/imscp_v1p1"><metadata><schema>IMS Content</schema>'
        f"<schemaversion>1.1.3</schemaversion></metadata><organizations/><resources>{resources}</resources>"
        "</manifest>\n")
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for path in sorted(files):
            info = zipfile.ZipInfo(path, _FIXED_TIME)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            archive.writestr(info, files[path].encode("utf-8"))
    return buffer.getvalue()
