"""The kinds of projective object, derived from the classes themselves.

Every class of an object a user can build, convert or transform declares its kind where it is
defined (``class Point(HomogeneousVector, kind="point")``); this module only collects them, so a
new class is known to the numeric conversions and the proof engine without editing any table.

>>> classes = object_classes()
>>> classes["point"].__name__, classes["quadric"].__name__
('Point', 'Quadric')
>>> classes["point"].kind
'point'
"""

from __future__ import annotations

import importlib
from typing import Any, ClassVar

__all__ = ["Kind", "object_classes"]

_REGISTRY: dict[str, type] = {}

# the modules that define the classes (imported on first use: the registry is filled by importing them)
_MODULES = ("projective_line", "projective_plane", "space", "plucker", "conics", "quadrics", "transformations")


class Kind:
    """Mixin that registers a class under ``kind`` (a keyword of the class statement)."""

    __slots__ = ()
    kind: ClassVar[str]

    def __init_subclass__(cls, kind: str | None = None, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if kind is not None:
            if _REGISTRY.get(kind, cls) is not cls and _REGISTRY[kind].__qualname__ != cls.__qualname__:
                raise TypeError(f"two classes claim the kind {kind!r}: {_REGISTRY[kind].__name__} and {cls.__name__}")
            cls.kind = kind
            _REGISTRY[kind] = cls


def object_classes() -> dict[str, type]:
    """Every registered kind → its class (imports the exact core, and with it SymPy)."""
    for name in _MODULES:
        importlib.import_module(f".{name}", __package__)
    return dict(_REGISTRY)
