"""What a template author imports, in one place: the base class (:mod:`pgsym.exercises.template_base`:
:class:`Template`, :class:`Draft`, :func:`check`) and the registry (:mod:`pgsym.exercises.registry`:
:func:`get_template`, :func:`all_templates`, :func:`load_template_folder`).

The package itself imports from those two modules; this one only re-exports them, so that instructor
templates written as ``from pgsym.exercises.template import Draft, Template, check`` keep working.

>>> from pgsym.exercises.template import Template, get_template
>>> isinstance(get_template("join"), Template)
True
"""

from __future__ import annotations

from .errors import TemplateError, UnknownTopicError
from .registry import all_templates, get_template, load_template_folder
from .template_base import Draft, Template, check

__all__ = ["Draft", "Template", "TemplateError", "UnknownTopicError", "all_templates", "check", "get_template",
           "load_template_folder"]
