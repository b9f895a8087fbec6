"""The errors of the instructors' tools: rosters, manifests, answers, templates, TeX and MathJax.

They live beside the exercise package (the core never raises them) and, like every error a user can
provoke, derive from :class:`~pgsym.errors.PgsymError`.

>>> from pgsym.errors import PgsymError
>>> issubclass(RosterError, PgsymError) and issubclass(RosterError, ValueError)
True
"""

from __future__ import annotations

from ..errors import PgsymError

__all__ = [
    "AnswersFileError",
    "LmsReportError",
    "ManifestError",
    "MathJaxMissingError",
    "MissingGlyphError",
    "RosterError",
    "TeXFailedError",
    "TeXMissingError",
    "TemplateError",
    "TemplateNameError",
    "UnknownTopicError",
    "UnparsableAnswerError",
]


class RosterError(PgsymError, ValueError):
    """A roster CSV that cannot be read (no id column, empty, duplicate or blank ids)."""


class ManifestError(PgsymError, ValueError):
    """A manifest file that is missing, not JSON, or not a pgsym exercise manifest."""


class MathJaxMissingError(PgsymError, FileNotFoundError):
    """No local copy of MathJax was found for the HTML sheets."""


class AnswersFileError(PgsymError, ValueError):
    """An answers CSV that cannot be read (missing, not CSV, no id column)."""


class UnknownTopicError(PgsymError, KeyError):
    """A topic name that no built-in or instructor template provides."""

    def __str__(self) -> str:  # KeyError would quote the message
        return str(self.args[0]) if self.args else ""


class TemplateError(PgsymError, ValueError):
    """A template produced an instance that fails its own checks (degenerate, wrong or too large)."""


class TemplateNameError(TemplateError):
    """An instructor template named like a built-in (or another loaded) template, without asking to replace it."""


class TeXMissingError(PgsymError, RuntimeError):
    """LuaLaTeX is not installed, so no PDF can be made."""


class TeXFailedError(PgsymError, RuntimeError):
    """LuaLaTeX ran but failed; the message holds the end of its log."""


class UnparsableAnswerError(PgsymError, ValueError):
    """A typed answer cannot be read as the expected kind of value."""


class MissingGlyphError(TeXFailedError):
    """A character of a sheet that no installed font has (it would print as an empty box)."""


class LmsReportError(AnswersFileError):
    """A Canvas or Moodle quiz report that cannot be graded: no question of the report carries a pgsym
    variant id, a variant the manifest does not know, or a report of neither platform."""
