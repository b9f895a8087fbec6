"""Public names resolved on first use (PEP 562), so that importing a package stays light.

A package lists each public name once, with where it lives, and installs the two hooks::

    __getattr__, __dir__ = lazy_names(__name__, {"Point": "projective_plane",   # module.Point
                                                  "prove_claim": "proofs:prove",  # module.attribute
                                                  "numeric": "numeric:"})         # the module itself

>>> getattr_, dir_ = lazy_names("pgsym", {"Point": "projective_plane", "numeric": "numeric:"})
>>> getattr_("Point").__name__, getattr_("numeric").__name__
('Point', 'pgsym.numeric')
"""

from __future__ import annotations

import importlib
import sys
import types
import warnings
from collections.abc import Callable, Mapping, Sequence
from typing import Any

__all__ = ["lazy_names", "moved_names"]


def lazy_names(package: str, table: Mapping[str, str]) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """``(__getattr__, __dir__)`` for ``package``: each name of ``table`` is imported when first used
    and then bound in the package, so the lookup happens once."""

    def __getattr__(name: str) -> Any:
        target = table.get(name)
        if target is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        module_name, colon, attribute = target.partition(":")
        value = importlib.import_module(f".{module_name}", package)
        if not colon or attribute:
            value = getattr(value, attribute or name)
        vars(sys.modules[package])[name] = value
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(table))

    _keep_names_over_submodules(package, table)
    return __getattr__, __dir__


# package name -> its public names that are attributes, not modules (see _LazyPackage)
_ATTRIBUTE_NAMES: dict[str, set[str]] = {}


class _LazyPackage(types.ModuleType):
    """A package whose public names win over its submodules of the same name.

    Importing a submodule binds it as an attribute of its package. Where a public name is also the name of a
    submodule (the function ``fixed_points`` lives in the module ``pgsym.fixed_points``), that binding would
    hide the name as soon as anything imports the module; this class refuses it, so the name keeps resolving
    to the table's value (the module itself stays in ``sys.modules``).
    """

    def __setattr__(self, name: str, value: Any) -> None:
        if isinstance(value, types.ModuleType) and name in _ATTRIBUTE_NAMES.get(self.__name__, ()):
            return
        super().__setattr__(name, value)


def _keep_names_over_submodules(package: str, table: Mapping[str, str]) -> None:
    _ATTRIBUTE_NAMES.setdefault(package, set()).update(name for name, target in table.items()
                                                       if not target.endswith(":"))
    sys.modules[package].__class__ = _LazyPackage


def moved_names(module: str, new_home: str, names: Sequence[str],
                renamed: Mapping[str, str] | None = None) -> Callable[[str], Any]:
    """A module ``__getattr__`` for names that moved to ``new_home``: each use of an old spelling warns
    (:class:`DeprecationWarning`, naming the new home) and returns the name's value there.

    The new home is imported on first use of an old name only, so a module of a lower layer can keep the names
    it lost to a higher one without importing that layer (``tests/test_architecture.py`` lists every such
    forward and checks that nothing in the package uses it). ``renamed`` maps an old name to its new one.

    >>> getattr_ = moved_names("pgsym.old", "pgsym.ring", ["dot"], renamed={"scalar_product": "dot"})
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     getattr_("scalar_product")((1, 2), (3, 4))
    11
    >>> str(caught[0].message)
    'pgsym.old.scalar_product is now pgsym.ring.dot; import it from there'
    """
    table = {name: name for name in names} | dict(renamed or {})

    def __getattr__(name: str) -> Any:
        new = table.get(name)
        if new is None:
            raise AttributeError(f"module {module!r} has no attribute {name!r}")
        warnings.warn(f"{module}.{name} is now {new_home}.{new}; import it from there", DeprecationWarning,
                      stacklevel=2)
        return getattr(importlib.import_module(new_home), new)

    return __getattr__
