"""Writing results so that a failure leaves nothing half-written: the one home of atomic output.

Every writer fills a temporary file or folder *inside* the target's parent (so the final rename
never crosses a file system) and moves it into place only when everything was written. A rename
replaces a symlink in the way itself, never the file it points to. An error, Ctrl-C or SIGTERM
leaves the target as it was and removes the temporary files and any folders the writer created.

>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> write_new_folder(root / "out", lambda tmp: (tmp / "a.txt").write_text("1")).name
'out'
>>> (root / "out" / "a.txt").read_text()
'1'
"""

from __future__ import annotations

import os
import shutil
import signal
import tempfile
import threading
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path

from .errors import OutputError

__all__ = ["Terminated", "exists", "replace_file", "replace_files_in_folder", "write_new_folder"]


class Terminated(BaseException):
    """SIGTERM arrived while writing (raised so the temporary files are removed before exiting)."""


@contextmanager
def _terminate_as_exception() -> Iterator[None]:
    """Turn SIGTERM into :class:`Terminated` while writing; only in the main thread, where Python
    can install signal handlers."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum: int, frame: object) -> None:
        raise Terminated(f"stopped by signal {signum}")

    previous = signal.signal(signal.SIGTERM, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def exists(path: Path) -> bool:
    """``path.exists()``, but False where it cannot even be looked at (name too long, no permission):
    writing there then fails with a named error."""
    try:
        return path.exists()
    except OSError:
        return False


def _make_folder(folder: Path) -> list[Path]:
    """Create ``folder`` and its missing parents; return the folders created, outermost first."""
    missing = []
    f = folder
    while not exists(f) and f != f.parent:
        missing.append(f)
        f = f.parent
    if exists(f) and not f.is_dir():
        raise OutputError(f"cannot write into {str(f)!r}: it is a file, not a folder")
    folder.mkdir(parents=True, exist_ok=True)
    return missing[::-1]


def _remove_created(created: list[Path]) -> None:
    for f in reversed(created):
        try:
            f.rmdir()  # only if still empty: never deletes anything the user put there meanwhile
        except OSError:
            return


def _named(err: OSError, target: Path) -> OutputError:
    if isinstance(err, OutputError):  # already named (OutputError is an OSError too)
        return err
    where = err.filename if isinstance(err.filename, str) else str(target)
    return OutputError(f"cannot write {where!r}: {err.strerror or err}")


def write_new_folder(out: str | Path, fill: Callable[[Path], object]) -> Path:
    """Create the folder ``out`` with what ``fill(tmp)`` writes into a temporary folder, or leave nothing.

    ``out`` must not exist or be an empty folder (so earlier results are never mixed with new ones).
    """
    target = Path(out)
    if target.exists() and (not target.is_dir() or any(target.iterdir())):
        raise OutputError(f"the output folder {str(target)!r} exists and is not empty; choose a new folder")
    parent = target.parent if str(target.parent) else Path(".")
    try:
        parent.mkdir(parents=True, exist_ok=True)
        tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.partial-", dir=parent))
        mask = os.umask(0)
        os.umask(mask)
        tmp.chmod(0o777 & ~mask)  # mkdtemp makes the folder private; the result should not be
    except OSError as err:
        raise OutputError(f"cannot write into {str(parent)!r}: {err.strerror or err}") from None
    try:
        with _terminate_as_exception():
            fill(tmp)
            if target.exists():
                target.rmdir()
            os.replace(tmp, target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return target


def replace_files_in_folder(out: Path, names: Iterable[str], fill: Callable[[Path], object]) -> None:
    """Write the files ``names`` into the folder ``out`` (created if missing): ``fill(tmp)`` writes
    them into a temporary folder inside ``out``, then each replaces its namesake.

    Existing files of those names are replaced only after all were written; other files in ``out``
    are left alone.
    """
    names = list(names)
    created: list[Path] = []
    tmp: Path | None = None
    try:
        taken = [n for n in names if exists(out / n) and (out / n).is_dir() and not (out / n).is_symlink()]
        if taken:
            raise OutputError(f"cannot write {str(out / taken[0])!r}: a folder of that name is in the way")
        created = _make_folder(out)
        tmp = Path(tempfile.mkdtemp(prefix=".pgsym-partial-", dir=out))
        with _terminate_as_exception():
            fill(tmp)
            for name in names:
                os.replace(tmp / name, out / name)
    except OSError as err:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
            tmp = None
        _remove_created(created)
        raise _named(err, out) from None
    finally:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)


def replace_file(out: Path, fill: Callable[[Path], object]) -> None:
    """Write the file ``out`` (its folder created if missing): ``fill(tmp)`` writes a temporary file
    next to it, which then replaces ``out``."""
    created: list[Path] = []
    tmp: Path | None = None
    try:
        created = _make_folder(out.parent)
        fd, name = tempfile.mkstemp(prefix=".pgsym-partial-", suffix=out.suffix, dir=out.parent)
        os.close(fd)
        tmp = Path(name)
        with _terminate_as_exception():
            fill(tmp)
            os.replace(tmp, out)
        tmp = None
    except OSError as err:
        if tmp is not None:
            tmp.unlink(missing_ok=True)
            tmp = None
        _remove_created(created)
        raise _named(err, out) from None
    finally:
        if tmp is not None:
            tmp.unlink(missing_ok=True)
