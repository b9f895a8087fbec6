"""The split of the exercise templates into a base class and a registry keeps the old import paths.

The import cycle it removed (the registry imported the templates, which imported the base class beside it)
is checked with every other cycle of the package by tests/test_architecture.py.
"""

from __future__ import annotations


def test_the_old_public_names_still_import():
    from pgsym.exercises.registry import get_template
    from pgsym.exercises.template import Draft, Template, all_templates, check, load_template_folder
    from pgsym.exercises.template import get_template as old_get_template
    from pgsym.exercises.template_base import Template as BaseTemplate

    assert Template is BaseTemplate and old_get_template is get_template
    assert callable(check) and callable(all_templates) and callable(load_template_folder) and Draft
