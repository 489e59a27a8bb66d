"""A resumable journal: a JSON-lines file of ours, one writer at a time, never torn.

The first line is a header ``{KEY: {...}}`` naming the job; each further line is one
finished record, appended in one ``write`` as it ends.  :func:`open_journal` checks the
path before any work (its folder exists and is writable; an existing path is a regular file
of ours, not a folder, a device, a FIFO or a file under ``/proc``; a symbolic link is
judged by the file it leads to), takes the writer's lock (:mod:`rollingdisk.util.lock`,
on ``.NAME.lock`` beside the file: a second writer is refused naming the pid), and reads
back and validates every record of a journal of the same job.  A last line without its
line break (the run was killed while writing it) is cut off; any other line that is not
a record is refused.  A write that fails (a full disk) is undone to the last whole record
and reported as :class:`ParameterError`: the file always ends with a whole line.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import stat
from collections.abc import Callable, Iterator
from pathlib import Path

from rollingdisk.util import lock as _locks
from rollingdisk.util.errors import ParameterError
from rollingdisk.util.files import check_parent_writable

__all__ = ["Journal", "open_journal", "check_journal_path"]

#: Folders of kernel files: never a journal, whatever their permissions say.
_KERNEL_FOLDERS = ("/proc", "/sys", "/dev")


def _finite(obj) -> bool:
    if isinstance(obj, float):
        return math.isfinite(obj)
    if isinstance(obj, dict):
        return all(_finite(v) for v in obj.values())
    if isinstance(obj, (list, tuple)):
        return all(_finite(v) for v in obj)
    return True


def check_journal_path(path, *, name: str = "results") -> Path:
    """Refuse, before any work, a journal path that cannot be ours.

    Parameters
    ----------
    path : path-like
    name : str
        The parameter's name for the messages.

    Returns
    -------
    Path
        The absolute path, symbolic links followed.

    Raises
    ------
    ParameterError
        The folder is missing or not writable; the path is a folder, a device, a FIFO, a
        socket or a kernel file (``/proc``, ``/sys``, ``/dev``); an existing file is not
        readable and writable.
    """
    try:
        target = Path(os.path.realpath(os.path.abspath(os.fspath(path))))
    except (TypeError, ValueError) as exc:
        raise ParameterError(f"{name} must be a file name, got {path!r} ({exc})") from None
    if any(str(target) == k or str(target).startswith(k + "/") for k in _KERNEL_FOLDERS):
        raise ParameterError(f"{name}: {target} is a kernel or device file; give a file "
                             "name in a folder of yours")
    try:
        mode = os.stat(target).st_mode
    except FileNotFoundError:
        mode = None
    except OSError as exc:
        raise ParameterError(f"{name}: cannot read {target}: {exc.strerror or exc}") from None
    if mode is not None and stat.S_ISDIR(mode):
        raise ParameterError(f"{name}: {target} is a folder; give a file name")
    if mode is not None and not stat.S_ISREG(mode):
        raise ParameterError(f"{name}: {target} is not a regular file (a device, a FIFO or "
                             "a socket); give a file name")
    check_parent_writable(target, name)
    if mode is not None and not os.access(target, os.R_OK | os.W_OK):
        raise ParameterError(f"{name}: {target} is not readable and writable; remove it or "
                             "choose another name")
    if len(target.name) > 200:
        raise ParameterError(f"{name}: the file name is too long ({len(target.name)} "
                             "characters, at most 200)")
    return target


class Journal:
    """An open journal (from :func:`open_journal`): :meth:`append` writes one record."""

    def __init__(self, path: Path, fd: int, size: int, name: str):
        self.path, self._fd, self._size, self._name = path, fd, size, name

    def append(self, record: dict) -> None:
        """Write ``record`` as one line (non-finite floats refused), all or nothing."""
        if not _finite(record):
            raise ParameterError(f"{self._name}: a record holds a non-finite number "
                                 f"({record!r}); not written")
        self._write((json.dumps(record, allow_nan=False) + "\n").encode())

    def _write(self, data: bytes) -> None:
        done = 0
        try:
            while done < len(data):
                done += os.write(self._fd, data[done:])
        except OSError as exc:
            with contextlib.suppress(OSError):
                os.ftruncate(self._fd, self._size)  # nothing torn: back to the last line
            raise ParameterError(f"{self._name}: cannot write {self.path}: "
                                 f"{exc.strerror or exc} (the records written so far are "
                                 "whole; rerun to resume)") from None
        self._size += len(data)


@contextlib.contextmanager
def open_journal(path, header: dict, record: Callable[[dict], object], *,
                 name: str = "results", kind: str = "results file") -> Iterator:
    """Open the journal ``path`` of the job ``header`` for this process alone.

    Parameters
    ----------
    path : path-like
        The JSON-lines file (created with ``header`` as its first line if missing or
        empty).
    header : dict
        ``{KEY: value}``, one key: an existing file whose first line has another value
        under KEY is another job's, one without KEY is not ours; both are refused.
    record : callable
        ``record(obj)`` checks one record read back and raises ``ValueError``,
        ``TypeError`` or ``KeyError`` if it is not one; it returns what the caller keeps.
    name, kind : str
        The parameter's name and what the file is, for the messages.

    Yields
    ------
    (Journal, list)
        The open journal and what ``record`` returned for each record already in it, in
        file order.

    Raises
    ------
    ParameterError
        See :func:`check_journal_path`; another process writes the journal (its pid
        named); the file is not ours or holds another job; a line is not a record.
    """
    target = check_journal_path(path, name=name)
    (key, value), = header.items()
    lock = target.with_name(f".{target.name}.lock")
    try:
        lock_fd = _locks.acquire(lock)
    except _locks.Busy as busy:
        who = f"pid {busy.pid}" if busy.pid is not None else "pid unknown"
        raise ParameterError(f"{name}: {target} is being written by another process "
                             f"({who}); wait for it to finish or choose another file (if "
                             f"no such process runs, delete {lock})") from None
    except OSError as exc:
        raise ParameterError(f"{name}: cannot lock {target}: {exc.strerror or exc}") from None
    fd = None
    try:
        kept, size = _read(target, key, value, record, name, kind)
        flags = os.O_WRONLY | os.O_APPEND | os.O_CREAT
        try:
            fd = os.open(target, flags, 0o666)
            os.ftruncate(fd, size)  # a torn last line is cut off
        except OSError as exc:
            raise ParameterError(f"{name}: cannot write {target}: "
                                 f"{exc.strerror or exc}") from None
        journal = Journal(target, fd, size, name)
        if size == 0:
            journal._write((json.dumps(header, allow_nan=False) + "\n").encode())
        yield journal, kept
    finally:
        if fd is not None:
            os.close(fd)
        _locks.release(lock, lock_fd)


def _read(target: Path, key, value, record, name, kind) -> tuple[list, int]:
    """The records of an existing journal of the same job and the size of its whole
    lines; ``([], 0)`` for a missing or empty file (or one holding only the start of our
    header, from a run killed while writing it)."""
    kept: list = []
    if not target.exists():
        return kept, 0
    ours = (json.dumps({key: value}, allow_nan=False) + "\n").encode()
    try:
        with open(target, "rb") as f:
            first = f.readline(max(len(ours) + 1, 1 << 16))
            if ours.startswith(first) and first != ours:
                if f.read(1):
                    first = b""  # more after it: not ours
                else:
                    return kept, 0  # empty, or our header cut short
            if first != ours:
                _refuse_first(first, key, target, name, kind)
            size = len(first)
            for k, raw in enumerate(f, 2):
                if not raw.endswith(b"\n"):
                    break  # killed while writing it: cut off, its record is made again
                try:
                    obj = json.loads(raw, parse_constant=_no_constant)
                    if not isinstance(obj, dict):
                        raise ValueError("not a JSON object")
                    kept.append(record(obj))
                except (ValueError, TypeError, KeyError, RecursionError) as exc:
                    raise ParameterError(f"{name}: line {k} of {target} is not a record of "
                                         f"this {kind} ({exc!s:.200}); delete the file or "
                                         "give a new one") from None
                size += len(raw)
    except OSError as exc:
        raise ParameterError(f"{name}: cannot read {target}: {exc.strerror or exc}") from None
    return kept, size


def _refuse_first(first: bytes, key, target, name, kind):
    try:
        obj = json.loads(first) if first.endswith(b"\n") else None
    except ValueError:
        obj = None
    if isinstance(obj, dict) and list(obj) == [key]:
        raise ParameterError(f"{name}: {target} holds another {key} "
                             f"({json.dumps(obj[key])[:200]}); give a new file")
    raise ParameterError(f"{name}: {target} is not a {kind} of rollingdisk (its first line "
                         "is not our header); give a new file name")


def _no_constant(text: str):
    raise ValueError(f"{text} is not a finite number")
