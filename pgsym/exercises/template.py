"""The base class of exercise templates, and the registry of built-in and instructor templates.

A template turns a random stream and a difficulty level into one exercise instance, built backwards
from a nice answer, and knows how to re-verify an instance independently of the way it built it.

>>> from pgsym.exercises.template import get_template
>>> t = get_template("join")
>>> ex = t.generate(seed=1, level=1, slot=3)
>>> ex.parts[0].label, ex.parts[0].answer.kind
('3', 'projective')
>>> t.verify(ex)
"""

from __future__ import annotations

import random
import string
import sys
import types
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from ..escaping import one_line
from .errors import TemplateError, UnknownTopicError
from .model import Answer, Exercise, Mistake, Part
from .reading import read_user_text


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
        from .mistakes import default_mistakes

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
        from .mistakes import admissible

        parts = tuple(replace(p, mistakes=tuple(admissible(p.answer, self.mistakes(exercise, i))))
                      for i, p in enumerate(exercise.parts))
        return replace(exercise, parts=parts)


def check(condition: bool, message: str) -> None:
    """Raise :class:`TemplateError` with ``message`` unless ``condition`` holds.

    >>> check(True, "fine")
    """
    if not condition:
        raise TemplateError(message)


_BUILTIN: dict[str, Template] = {}
_EXTRA: dict[str, Template] = {}


def _builtin() -> dict[str, Template]:
    if not _BUILTIN:
        from .templates import BUILTIN_TEMPLATES

        for cls in BUILTIN_TEMPLATES:
            _BUILTIN[cls.name] = cls()
    return _BUILTIN


def all_templates() -> dict[str, Template]:
    """Every known template by name: the built-in ones, then those loaded from instructor folders.

    >>> "join" in all_templates() and "decompose" in all_templates()
    True
    """
    return {**_builtin(), **_EXTRA}


def get_template(name: str) -> Template:
    """The template called ``name``; :class:`UnknownTopicError` lists the known ones otherwise.

    >>> get_template("nope")
    Traceback (most recent call last):
    ...
    pgsym.exercises.errors.UnknownTopicError: unknown topic 'nope'; known topics: ...
    """
    templates = all_templates()
    if name not in templates:
        raise UnknownTopicError(f"unknown topic {name!r}; known topics: {', '.join(sorted(templates))}")
    return templates[name]


def load_template_folder(folder: str | Path) -> list[str]:
    """Load instructor templates: every ``*.py`` file in ``folder`` defining subclasses of :class:`Template`.

    Returns the names registered. The files are ordinary Python written by the instructor and are
    run as modules (this is the only place the exercise package runs outside code); each file is read
    within :data:`pgsym.limits.MAX_FILE_BYTES`, and a pipe or device is refused.
    """
    path = Path(folder)
    try:
        is_folder = path.is_dir()
    except OSError as err:  # e.g. a name longer than the file system allows
        raise TemplateError(f"template folder {one_line(str(path))!r} cannot be opened: {err.strerror}") from None
    if not is_folder:
        raise TemplateError(f"template folder {one_line(str(path))!r} does not exist or is not a folder")
    names = []
    for file in sorted(path.glob("*.py")):
        module_name = f"pgsym_user_templates.{file.stem}"
        # read within the limits (a FIFO or device named *.py is refused, not waited on), then run it
        source = read_user_text(file, "template file", TemplateError)
        module = types.ModuleType(module_name)
        module.__file__ = str(file)
        sys.modules[module_name] = module
        try:
            exec(compile(source, str(file), "exec"), module.__dict__)  # the instructor's own code, run as before
        except Exception as err:
            sys.modules.pop(module_name, None)
            raise TemplateError(f"could not load template file {file.name}: {type(err).__name__}: "
                                f"{str(err)[:300]}") from None
        for value in vars(module).values():
            if isinstance(value, type) and issubclass(value, Template) and value is not Template and value.name:
                if value.__module__ != module_name:
                    continue
                _EXTRA[value.name] = value()
                names.append(value.name)
    return names
