"""The registry of exercise templates: the built-in ones and those loaded from instructor folders.

>>> get_template("meet").title
'The intersection of two lines'
"""

from __future__ import annotations

import sys
import types
from pathlib import Path

from ..escaping import one_line
from .errors import TemplateError, TemplateNameError, UnknownTopicError
from .reading import read_user_text
from .template_base import Template

__all__ = ["all_templates", "get_template", "load_template_folder"]


_BUILTIN: dict[str, Template] = {}
_EXTRA: dict[str, Template] = {}
_ORIGIN: dict[str, Path] = {}  # the file each instructor template came from (loading it again is no clash)


def _builtin() -> dict[str, Template]:
    if not _BUILTIN:
        from .templates import BUILTIN_TEMPLATES  # noqa: PLC0415 — the built-in templates load on first use

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


def load_template_folder(folder: str | Path, replace: bool = False) -> list[str]:
    """Load instructor templates: every ``*.py`` file in ``folder`` defining subclasses of :class:`Template`.

    A template named like a built-in one, or like one loaded before, raises :class:`TemplateNameError`
    unless ``replace`` is true (``pgsym sheet --replace-templates``): a sheet should never get another
    exercise than its topic names without the instructor asking for it.

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
                origin = _ORIGIN.get(value.name)
                if not replace and (value.name in _builtin() or (origin is not None and origin != file.resolve())):
                    where = "a built-in template" if value.name in _builtin() else "a template loaded before"
                    raise TemplateNameError(
                        f"template file {file.name} defines {one_line(value.name)[:60]!r}, the name of {where}; "
                        "rename it (its 'name' attribute), or pass --replace-templates to use it instead")
                _EXTRA[value.name] = value()
                _ORIGIN[value.name] = file.resolve()
                names.append(value.name)
    return names
