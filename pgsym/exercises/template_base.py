"""The base class of exercise templates: :class:`Template`, the :class:`Draft` it builds and :func:`check`.

A template turns a random stream and a difficulty level into one exercise instance, built backwards
from a nice answer, and knows how to re-verify an instance independently of the way it built it.
Every template (built-in or an instructor's) imports this module; the registry of templates is
:mod:`pgsym.exercises.registry`, which imports the templates, so nothing here imports a template.

>>> from pgsym.exercises.registry import get_template
>>> t = get_template("join")
>>> ex = t.generate(seed=1, level=1, slot=3)
>>> ex.parts[0].label, ex.parts[0].answer.kind
('3', 'projective')
>>> t.verify(ex)
"""

from __future__ import annotations

import random
import string
from dataclasses import dataclass, field, replace
from typing import Any

from .errors import TemplateError
from .mistakes import admissible, default_mistakes
from .model import Answer, Exercise, Mistake, Part

__all__ = ["Draft", "Template", "TemplateError", "check"]


@dataclass
class Draft:
    """What a template's :meth:`Template.build` returns: text, parts and solution of one instance.

    ``parts`` holds ``(prompt, answer, choices)`` triples; the labels are filled in by
    :meth:`Template.generate`.
    """

    statement: str
    parts: list[tuple[str, Answer, tuple[str, ...]]]
    solution: list[str]
    params: dict[str, Any] = field(default_factory=dict)


class Template:
    """Base class: subclass it, set ``name``, ``title``, ``levels`` and implement :meth:`build` and
    :meth:`verify`.

    ``max_entry`` bounds the size of every number in an answer (numerators and denominators);
    the stress check enforces it.
    """

    name: str = ""
    title: str = ""
    levels: tuple[int, ...] = (1, 2, 3)
    max_entry: int = 1000

    def build(self, rng: random.Random, level: int) -> Draft:  # pragma: no cover - abstract
        """Build one instance at ``level`` from the random stream ``rng``."""
        raise NotImplementedError

    def verify(self, exercise: Exercise) -> None:  # pragma: no cover - abstract
        """Re-check the instance from its ``params`` and answers; raise :class:`TemplateError` if wrong."""
        raise NotImplementedError

    def mistakes(self, exercise: Exercise, index: int) -> list[Mistake]:
        """The common wrong answers of part ``index`` that ``pgsym check`` should recognise.

        The default is :func:`pgsym.exercises.mistakes.default_mistakes` of the part's answer (a sign
        lost, an ideal point given as finite, a matrix transposed or inverted, a multiple where the
        exact value is asked). Override it to add a template's own, e.g.
        ``return [*super().mistakes(exercise, index), mistake("dual", Answer.projective(p))]``;
        candidates equivalent to the right answer are dropped before they are stored.
        """

        return default_mistakes(exercise.parts[index].answer)

    def generate(self, seed: int, level: int, slot: int) -> Exercise:
        """The instance of this template for a variant seed, at a level, numbered ``slot`` on the sheet."""
        if level not in self.levels:
            raise TemplateError(f"template {self.name!r} has levels {list(self.levels)}, not {level}")
        draft = self.build(random.Random(seed), level)
        many = len(draft.parts) > 1
        parts = tuple(
            Part(f"{slot}{string.ascii_lowercase[i]}" if many else str(slot), prompt, answer, tuple(choices))
            for i, (prompt, answer, choices) in enumerate(draft.parts)
        )
        exercise = Exercise(self.name, self.title, level, slot, seed, draft.statement, parts,
                            tuple(draft.solution), draft.params)
        return self.with_mistakes(exercise)

    def with_mistakes(self, exercise: Exercise) -> Exercise:
        """``exercise`` with the admissible :meth:`mistakes` of every part attached (for the manifest)."""

        parts = tuple(replace(p, mistakes=tuple(admissible(p.answer, self.mistakes(exercise, i))))
                      for i, p in enumerate(exercise.parts))
        return replace(exercise, parts=parts)


def check(condition: bool, message: str) -> None:
    """Raise :class:`TemplateError` with ``message`` unless ``condition`` holds.

    >>> check(True, "fine")
    """
    if not condition:
        raise TemplateError(message)
