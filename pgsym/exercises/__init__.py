"""Exercise sheets for instructors: randomized per-student variants, answer keys, renderers, grading.

The core package never imports this subpackage. Typical use::

    from pgsym.exercises.sheets import build_sheets
    sheets = build_sheets(["join", "meet"], students=[("s1", "Ada")], master_seed=2026)

>>> from pgsym.exercises.registry import get_template
>>> get_template("meet").title
'The intersection of two lines'
"""
