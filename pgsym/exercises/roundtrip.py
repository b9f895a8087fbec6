"""What ``pgsym check`` hands to its outputs, whichever file the answers came from.

An answers CSV of pgsym names the students of the manifest, each answering their own variants; a
Canvas or Moodle quiz report names the platform's users, each answering the variants the quiz drew
for them (:mod:`pgsym.exercises.lms`). :class:`Graded` holds either: the results per person, who
they are (for the gradebooks), which variant each answered part belongs to (for the feedback pages)
and the problems met.

>>> from pgsym.exercises.model import Answer
>>> from pgsym.exercises.sheets import ManifestData
>>> data = ManifestData(keys={"s1": {"1": Answer.scalar(2)}}, names={"s1": "Ada"},
...                     variants={"F-0123456789#1": ("s1", ("1",))})
>>> people_of_manifest(data)["s1"].sis_id, own_variants(data)
('s1', {'s1': {'1': 'F-0123456789#1'}})
"""

from __future__ import annotations

from dataclasses import dataclass

from .grading import Result
from .lms import Person
from .sheets import ManifestData

__all__ = ["Graded", "own_variants", "people_of_manifest"]


@dataclass
class Graded:
    """Results per person key, the people, person → label → variant id, problems, and the source
    (``"pgsym"``, ``"canvas"`` or ``"moodle"``)."""

    report: dict[str, list[Result]]
    people: dict[str, Person]
    variants: dict[str, dict[str, str]]
    problems: list[str]
    source: str

    @property
    def names(self) -> dict[str, str]:
        """Person key → name (the key itself when the name is unknown)."""
        return {k: p.name or k for k, p in self.people.items()}


def people_of_manifest(data: ManifestData) -> dict[str, Person]:
    """The students of a manifest as people: the roster id is their SIS id."""
    return {sid: Person(sid, name, sis_id=sid, id_number=sid) for sid, name in data.names.items()}


def own_variants(data: ManifestData) -> dict[str, dict[str, str]]:
    """Every student of the manifest answers their own variants: student → label → variant id."""
    out: dict[str, dict[str, str]] = {sid: {} for sid in data.names}
    for vid, (sid, labels) in data.variants.items():
        for label in labels:
            out.setdefault(sid, {})[label] = vid
    return out
