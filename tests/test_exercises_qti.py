"""The Canvas QTI 1.2 package: valid against the IMS QTI ASI 1.2 schema, one bank per topic, every variant
in its bank and in its question group, answers in canonical form, hostile names inert."""

from __future__ import annotations

import io
import zipfile
from fractions import Fraction
from pathlib import Path

import pytest
from lxml import etree

from pgsym.exercises import render_qti
from pgsym.exercises.model import Answer, Exercise, Part, Sheet
from pgsym.exercises.sheets import build_sheets, parse_topics

SCHEMA = Path(__file__).parent / "data" / "qti" / "domainProfile_4" / "ims_qtiasiv1p2.xsd"
NS = {"q": render_qti.QTI_NAMESPACE}
TOPICS = "join,incidence:2,classify:2,cross-ratio:3,decompose:3"
HOSTILE_ID = '</mattext><script>alert(1)</script> & "x"'
STUDENTS = [("s1", "Ada"), ("s2", "李雷"), (HOSTILE_ID, "Mallory")]


@pytest.fixture(scope="module")
def schema() -> etree.XMLSchema:
    return etree.XMLSchema(etree.parse(str(SCHEMA)))


@pytest.fixture(scope="module")
def package() -> tuple[list[Sheet], dict[str, bytes]]:
    pairs = parse_topics(TOPICS)
    sheets = build_sheets(pairs, STUDENTS, master_seed=9)
    data = render_qti.render_package(sheets, pairs)
    with zipfile.ZipFile(io.BytesIO(data)) as archive:
        assert archive.testzip() is None
        return sheets, {name: archive.read(name) for name in archive.namelist()}


def test_every_qti_file_validates_against_the_schema(schema, package):
    _, files = package
    qti = [name for name in files if name != "imsmanifest.xml"]
    assert len(qti) == 1 + len(parse_topics(TOPICS))  # the quiz and one bank per topic
    for name in qti:
        doc = etree.fromstring(files[name])
        assert schema.validate(doc), (name, [str(e) for e in schema.error_log][:5])


def test_the_schema_rejects_a_broken_item(schema, package):
    # the validation is not vacuous: an item without its ident, or an unknown element, is refused
    _, files = package
    doc = etree.fromstring(files["quiz.xml"])
    item = doc.find(".//q:item", NS)
    del item.attrib["ident"]
    assert not schema.validate(doc)
    doc = etree.fromstring(files["quiz.xml"])
    etree.SubElement(doc.find(".//q:item", NS), f"{{{render_qti.QTI_NAMESPACE}}}answer").text = "1"
    assert not schema.validate(doc)


def test_banks_and_groups_hold_every_variant(package):
    sheets, files = package
    manifest = etree.fromstring(files["imsmanifest.xml"])
    hrefs = sorted(r.get("href") for r in manifest.iter("{http://www.imsglobal.org/xsd/imscp_v1p1}resource"))
    assert hrefs == sorted(n for n in files if n != "imsmanifest.xml")
    quiz = etree.fromstring(files["quiz.xml"])
    groups = quiz.findall("q:assessment/q:section/q:section", NS)
    assert len(groups) == len(sheets[0].exercises)
    for slot, group in enumerate(groups):
        assert group.findtext("q:selection_ordering/q:selection/q:selection_number", namespaces=NS) == "1"
        titles = [item.get("title") for item in group.findall("q:item", NS)]
        # one item per student, titled with the form and student id
        assert titles == [f"{slot + 1}. {s.exercises[slot].title} [{s.form_id} / {s.student_id}]" for s in sheets]
        topic = sheets[0].exercises[slot].topic
        bank = etree.fromstring(files[f"banks/bank-{slot + 1:02d}-{topic}.xml"])
        assert [i.get("title") for i in bank.findall("q:objectbank/q:item", NS)] == titles


def _answers(item: etree._Element) -> tuple[str, list[str]]:
    qtype = item.findtext(".//q:qtimetadatafield[q:fieldlabel='question_type']/q:fieldentry", namespaces=NS)
    return qtype, [v.text for v in item.iter(f"{{{render_qti.QTI_NAMESPACE}}}varequal")]


def test_answers_are_canonical(package):
    sheets, files = package
    quiz = etree.fromstring(files["quiz.xml"])
    groups = quiz.findall("q:assessment/q:section/q:section", NS)
    seen = set()
    for slot, group in enumerate(groups):
        for sheet, item in zip(sheets, group.findall("q:item", NS), strict=True):
            parts = sheet.exercises[slot].parts
            qtype, values = _answers(item)
            seen.add(qtype)
            if qtype == "multiple_choice_question":
                assert values == [parts[0].answer.value]
            elif qtype == "numerical_question":
                value = Fraction(parts[0].answer.value)
                assert value.denominator == 1 and values == [str(value.numerator)]
                bounds = [e.text for e in item.iter() if e.tag.endswith(("}vargte", "}varlte"))]
                assert bounds == [str(value.numerator)] * 2  # Canvas's exact answer: = or (>= and <=)
            elif qtype == "short_answer_question":
                text = parts[0].answer.display()
                assert values == list(dict.fromkeys([text, text.replace(" ", "")]))
            else:
                assert qtype == "fill_in_multiple_blanks_question"
                labels = {lab.get("ident"): lab.findtext(".//q:mattext", namespaces=NS)
                          for lab in item.iter(f"{{{render_qti.QTI_NAMESPACE}}}response_label")}
                accepted = {labels[v] for v in values}
                for p in parts:
                    assert (p.answer.value if p.answer.kind == "choice" else p.answer.display()) in accepted
    assert {"multiple_choice_question", "fill_in_multiple_blanks_question", "short_answer_question"} <= seen


def test_projective_answer_is_asked_in_canonical_form():
    # the key (2, -4, 6) is stored as the primitive vector (1, -2, 3); the accepted text is exactly that
    part = Part("1", "Give the line.", Answer.projective((2, -4, 6)))
    sheet = Sheet("s1", "", "F-1", 0, (Exercise("join", "Join", 1, 1, 0, "S", (part,), ("s",), {}),))
    data = render_qti.render_package([sheet], [("join", 1)])
    bank = zipfile.ZipFile(io.BytesIO(data)).read("banks/bank-01-join.xml")
    qtype, values = _answers(etree.fromstring(bank))
    assert qtype == "short_answer_question" and values == ["(1, -2, 3)", "(1,-2,3)"]
    # an integer answer is a numerical question; a fraction stays text in lowest terms (-6/4 -> -3/2)
    for answer, expected in ((Answer.integer(-7), ("numerical_question", ["-7"])),
                             (Answer.scalar(Fraction(-6, 4)), ("short_answer_question", ["-3/2"]))):
        one = Sheet("s1", "", "F-1", 0, (Exercise("t", "T", 1, 1, 0, "S", (Part("1", "P", answer),), ("s",), {}),))
        bank = zipfile.ZipFile(io.BytesIO(render_qti.render_package([one], [("t", 1)]))).read("banks/bank-01-t.xml")
        assert _answers(etree.fromstring(bank)) == expected


def test_hostile_names_stay_text_and_the_zip_is_reproducible(package):
    sheets, files = package
    quiz = files["quiz.xml"].decode()
    assert "<script>" not in quiz and "&lt;script&gt;" in quiz  # escaped into the title attribute
    titles = [i.get("title") for i in etree.fromstring(files["quiz.xml"]).iter(f"{{{render_qti.QTI_NAMESPACE}}}item")]
    assert sum(HOSTILE_ID in t for t in titles) == len(sheets[0].exercises)  # read back as the literal id
    assert render_qti.render_package(sheets, parse_topics(TOPICS)) == render_qti.render_package(
        sheets, parse_topics(TOPICS))
