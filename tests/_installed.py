"""The installed ``pgsym`` console script, run as a user runs it (no stdin, output captured)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

PGSYM = shutil.which("pgsym", path=str(Path(sys.executable).parent))


def run_pgsym(*args: str, cwd: Path | None = None, timeout: float = 300) -> subprocess.CompletedProcess[str]:
    """Run ``pgsym ARGS…`` from the venv of this Python and return the finished process."""
    assert PGSYM is not None, "the pgsym console script is not installed next to this Python"
    return subprocess.run([PGSYM, *args], capture_output=True, text=True, timeout=timeout,
                          stdin=subprocess.DEVNULL, cwd=cwd)
