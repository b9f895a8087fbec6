"""IMS QTI 1.2 package (a zip) for Canvas: one question bank per exercise slot holding every student's variant,
and one quiz whose question groups draw one variant from each bank.

Canvas quizzes compare typed answers as strings, never up to a nonzero scale, and cannot give a student
their own variant. So each variant is an **essay question that Canvas does not grade**: the student
types the answer as text (pgsym's syntax, e.g. ``(1, -2, 0)``; any nonzero multiple, fractions, a
Unicode minus are all fine), and ``pgsym check`` grades Canvas's Student Analysis report up to scale,
naming the mistakes (:mod:`pgsym.exercises.lms`); the Canvas gradebook CSV it writes carries the
points. The variant id (:func:`~pgsym.exercises.model.variant_id`) is the first line of every
question's text and part of its title, so the report says which variant each student saw. The worked
solution is the item's general feedback (``itemfeedback`` ``general_fb``), which Canvas shows as the
quiz's settings allow; the mistakes are named by ``pgsym check`` (``--feedback`` pages), since Canvas
never sees a verdict.

The zip holds ``imsmanifest.xml`` (IMS Content Packaging), ``banks/bank-NN-TOPIC.xml`` (an
``objectbank`` per slot, every variant an ``item``, imported once) and ``quiz.xml`` (an ``assessment``
whose sections are question groups that *refer* to the banks through ``sourcebank_ref`` with
``selection_number`` 1, as Canvas's own QTI export writes groups linked to a bank; no item is repeated).
Points are the exercise's points (:mod:`pgsym.exercises.points`): ``points_possible`` of every item
and ``points_per_item`` of every group, the same numbers as the STACK questions and the gradebooks.

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

from ..escaping import one_line, to_html, xml_escape
from .model import Exercise, Part, Sheet, variant_id
from .points import points_text

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


_HOW = {
    "projective": "a vector such as (1, -2, 0); any nonzero multiple is right",
    "vector": "a vector such as (1/2, -3); fractions are exact",
    "scalar": "a number such as -3/4",
    "integer": "an integer",
    "matrix": "a matrix such as [[1, 0, 2], [0, 1, 0], [0, 0, 1]]; any nonzero multiple is right",
    "matrix_exact": "a matrix such as [[1, 1/2], [0, 1]]",
    "choice": "one letter",
}


def _prompt(part: Part, many: bool) -> str:
    how = f"Type {_HOW[part.answer.kind]}" + (f", on a line starting with {part.label}:" if many else "") + "."
    text = f"<p><b>[{html.escape(part.label)}]</b> {to_html(part.prompt)} <i>{html.escape(how)}</i>"
    if part.choices:
        text += '<ol type="A">' + "".join(f"<li>{to_html(c)}</li>" for c in part.choices) + "</ol>"
    return text + "</p>"


def _item(ident: str, sheet: Sheet, ex: Exercise) -> str:
    vid = variant_id(sheet.form_id, ex.slot)
    title = one_line(f"{ex.slot}. {ex.title} [pgsym {vid}]")
    many = len(ex.parts) > 1
    body = (f"<p>pgsym {vid}</p><p>{to_html(ex.statement)}</p>" + "".join(_prompt(p, many) for p in ex.parts)
            + "<p><i>Canvas does not grade this answer: pgsym grades it after the quiz, up to scale where the "
            "answer is homogeneous, and the score reaches the gradebook with the instructor's import.</i></p>")
    return "".join([
        f'<item ident="{ident}" title="{xml_escape(title)}">',
        "<itemmetadata><qtimetadata>" + _field("question_type", "essay_question")
        + _field("points_possible", points_text(ex.points)) + _field("original_answer_ids", "")
        + "</qtimetadata></itemmetadata>",
        "<presentation>" + _material(body)
        + '<response_str ident="response1" rcardinality="Single"><render_fib><response_label ident="answer1" '
        'rshuffle="No"/></render_fib></response_str></presentation>',
        '<resprocessing><outcomes><decvar maxvalue="100" minvalue="0" varname="SCORE" vartype="Decimal"/>'
        '</outcomes><respcondition continue="Yes"><conditionvar><other/></conditionvar>'
        '<displayfeedback feedbacktype="Response" linkrefid="general_fb"/></respcondition>'
        '<respcondition continue="No"><conditionvar><other/></conditionvar></respcondition></resprocessing>',
        '<itemfeedback ident="general_fb"><flow_mat>' + _material(_solution(ex)) + "</flow_mat></itemfeedback>",
        "</item>"])


def _solution(ex: Exercise) -> str:
    """The worked solution and the expected answers: Canvas's general feedback of the item."""
    return ("<ol>" + "".join(f"<li>{to_html(step)}</li>" for step in ex.solution) + "</ol>"
            + "".join(f"<p><b>[{html.escape(p.label)}]</b> {html.escape(p.answer.display())}</p>" for p in ex.parts))


def _slug(topic: str) -> str:
    return re.sub(r"[^A-Za-z0-9_-]", "_", topic)[:40]


def render_package(sheets: Sequence[Sheet], topics: Sequence[tuple[str, int]], title: str = "pgsym exercises") -> bytes:
    """The QTI 1.2 zip of every variant of every student (``topics`` as given to ``pgsym sheet``)."""
    del topics  # the slots of the sheets say everything
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
        worth = points_text(first.points)
        groups.append(f'<section ident="group_{first.slot:02d}" title="{xml_escape(bank_title)}"><selection_ordering>'
                      f"<selection><sourcebank_ref>{bank_id}</sourcebank_ref><selection_number>1</selection_number>"
                      f"<selection_extension><points_per_item>{worth}</points_per_item></selection_extension>"
                      "</selection></selection_ordering></section>")
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
