"""The installed ``pgsym`` console script, run as a user runs it (no stdin, output captured)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from collections.abc import Callable, Mapping
from pathlib import Path

PGSYM = shutil.which("pgsym", path=str(Path(sys.executable).parent))


def run_pgsym(*args: str, cwd: Path | None = None, timeout: float = 300, env: Mapping[str, str] | None = None,
              preexec_fn: Callable[[], None] | None = None) -> subprocess.CompletedProcess[str]:
    """Run ``pgsym ARGS…`` from the venv of this Python and return the finished process (``env``: the whole
    environment of the command; ``preexec_fn``: e.g. a resource limit set in the child before it starts)."""
    assert PGSYM is not None, "the pgsym console script is not installed next to this Python"
    return subprocess.run([PGSYM, *args], capture_output=True, text=True, timeout=timeout,
                          stdin=subprocess.DEVNULL, cwd=cwd, env=env, preexec_fn=preexec_fn)
