"""The Canvas QTI 1.2 package: valid against the IMS QTI ASI 1.2 schema, one bank per topic holding every
variant once, question groups that refer to the banks, essay questions Canvas does not grade (never a
string match that claims to compare up to scale), the variant id in every question, the points of the
manifest, hostile names inert."""

from __future__ import annotations

import io
import zipfile
from fractions import Fraction
from pathlib import Path

import pytest
from lxml import etree

from pgsym.exercises import render_qti
from pgsym.exercises.model import Sheet
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
    bank = next(name for name in files if name.startswith("banks/"))
    doc = etree.fromstring(files[bank])
    item = doc.find(".//q:item", NS)
    del item.attrib["ident"]
    assert not schema.validate(doc)
    doc = etree.fromstring(files[bank])
    etree.SubElement(doc.find(".//q:item", NS), f"{{{render_qti.QTI_NAMESPACE}}}answer").text = "1"
    assert not schema.validate(doc)


def test_banks_hold_every_variant_once_and_groups_refer_to_them(package):
    sheets, files = package
    manifest = etree.fromstring(files["imsmanifest.xml"])
    hrefs = sorted(r.get("href") for r in manifest.iter("{http://www.imsglobal.org/xsd/imscp_v1p1}resource"))
    assert hrefs == sorted(n for n in files if n != "imsmanifest.xml")
    quiz = etree.fromstring(files["quiz.xml"])
    assert quiz.findall(".//q:item", NS) == []  # no variant is imported a second time through the quiz
    groups = quiz.findall("q:assessment/q:section/q:section", NS)
    assert len(groups) == len(sheets[0].exercises)
    for slot, group in enumerate(groups):
        selection = group.find("q:selection_ordering/q:selection", NS)
        assert selection.findtext("q:selection_number", namespaces=NS) == "1"
        topic = sheets[0].exercises[slot].topic
        bank = etree.fromstring(files[f"banks/bank-{slot + 1:02d}-{topic}.xml"])
        assert selection.findtext("q:sourcebank_ref", namespaces=NS) == bank.find("q:objectbank", NS).get("ident")
        titles = [i.get("title") for i in bank.findall("q:objectbank/q:item", NS)]
        # one item per student, titled with the variant id: the form id and the slot
        assert titles == [f"{slot + 1}. {s.exercises[slot].title} [pgsym {s.form_id}#{slot + 1}]" for s in sheets]


def _meta(item: etree._Element, label: str) -> str:
    return item.findtext(f".//q:qtimetadatafield[q:fieldlabel='{label}']/q:fieldentry", namespaces=NS)


def test_items_are_ungraded_essays_that_carry_the_variant_and_the_points(package):
    sheets, files = package
    quiz = etree.fromstring(files["quiz.xml"])
    for slot, group in enumerate(quiz.findall("q:assessment/q:section/q:section", NS)):
        topic = sheets[0].exercises[slot].topic
        bank = etree.fromstring(files[f"banks/bank-{slot + 1:02d}-{topic}.xml"])
        points = {Fraction(_meta(i, "points_possible")) for i in bank.findall("q:objectbank/q:item", NS)}
        expected = sum(p.points for p in sheets[0].exercises[slot].parts)  # 1 per part by default
        assert points == {expected} == {len(sheets[0].exercises[slot].parts)}
        assert Fraction(group.findtext(".//q:points_per_item", namespaces=NS)) == expected
        for sheet, item in zip(sheets, bank.findall("q:objectbank/q:item", NS), strict=True):
            assert _meta(item, "question_type") == "essay_question"
            # Canvas matches nothing: no answer text anywhere, so no string match can mark a right multiple wrong
            assert list(item.iter(f"{{{render_qti.QTI_NAMESPACE}}}varequal")) == []
            text = item.findtext(".//q:mattext", namespaces=NS)
            assert text.startswith(f"<p>pgsym {sheet.form_id}#{slot + 1}</p>")
            assert "Canvas does not grade this answer: pgsym grades it after the quiz" in text
            # the worked solution is the general feedback, linked from the processing
            exercise = sheet.exercises[slot]
            feedback = item.find("q:itemfeedback[@ident='general_fb']", NS).findtext(".//q:mattext", namespaces=NS)
            assert feedback.startswith("<ol><li>") and exercise.parts[-1].answer.display() in feedback
            assert item.find(".//q:displayfeedback", NS).get("linkrefid") == "general_fb"


def test_points_from_the_command_line_reach_every_item():
    pairs = parse_topics("join,classify")
    from pgsym.exercises.points import parse_points

    sheets = build_sheets(pairs, [("s1", "")], master_seed=1, points=parse_points("join=3,classify=1/2+2"))
    data = render_qti.render_package(sheets, pairs)
    archive = zipfile.ZipFile(io.BytesIO(data))
    join = etree.fromstring(archive.read("banks/bank-01-join.xml")).find("q:objectbank/q:item", NS)
    classify = etree.fromstring(archive.read("banks/bank-02-classify.xml")).find("q:objectbank/q:item", NS)
    assert _meta(join, "points_possible") == "3" and _meta(classify, "points_possible") == "2.5"  # 1/2 + 2
    quiz = etree.fromstring(archive.read("quiz.xml"))
    assert [g.text for g in quiz.iter(f"{{{render_qti.QTI_NAMESPACE}}}points_per_item")] == ["3", "2.5"]


def test_hostile_names_stay_text_and_the_zip_is_reproducible(package):
    sheets, files = package
    banks = "".join(files[name].decode() for name in files if name.startswith("banks/"))
    assert "<script>" not in banks
    titles = [i.get("title") for name in files if name.startswith("banks/")
              for i in etree.fromstring(files[name]).iter(f"{{{render_qti.QTI_NAMESPACE}}}item")]
    assert not any(HOSTILE_ID in t for t in titles)  # the title names the variant, never the student
    assert render_qti.render_package(sheets, parse_topics(TOPICS)) == render_qti.render_package(
        sheets, parse_topics(TOPICS))
