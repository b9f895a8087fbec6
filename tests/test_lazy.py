"""Public names resolved on first use (pgsym/_lazy.py): a name that is also a submodule's name."""

from __future__ import annotations

import subprocess
import sys


def test_a_public_name_is_not_hidden_by_the_submodule_of_the_same_name() -> None:
    # fixed_lines lives in the module pgsym.fixed_points, whose import binds the package attribute
    # `fixed_points`; the public name must still be the function, in a fresh interpreter where nothing
    # else has resolved it first
    code = ("from pgsym import fixed_lines\n"
            "import pgsym.fixed_points\n"
            "from pgsym import fixed_points\n"
            "print(type(fixed_points).__name__, fixed_points([[2, 0], [0, 3]]) != [])\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["function", "True"]
