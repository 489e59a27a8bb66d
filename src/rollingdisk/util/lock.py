"""Exclusive writers: a lock file that names its holder's pid.

One process at a time may write a resumable output (a sweep's partial folder, a toss
journal).  :func:`acquire` takes an exclusive ``fcntl.flock`` on a lock file and writes
this process's pid into it; the kernel releases the lock when the process dies, however it
dies.  Where ``fcntl`` is missing the file's existence is the lock and its pid lets a later
run take over the lock of a dead process (on POSIX).  A second writer gets :class:`Busy`,
which carries the holder's pid for its one-line message.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path

try:
    import fcntl
except ImportError:  # pragma: no cover - not POSIX
    fcntl = None

__all__ = ["Busy", "acquire", "release", "read_pid"]


class Busy(Exception):  # noqa: N818 - a state, reported by the caller in its own words
    """Another live process holds the lock; ``pid`` is its pid (None if unreadable)."""

    def __init__(self, pid: int | None):
        super().__init__(pid)
        self.pid = pid


def read_pid(path: Path) -> int | None:
    """The pid written in the lock file ``path``, None if unreadable."""
    try:
        return int(Path(path).read_text().split()[0])
    except (OSError, ValueError, IndexError):
        return None


def _pid_alive(pid: int) -> bool:
    if os.name != "posix":  # no safe probe: never take over
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # alive, another user's
        return True
    return True


def _try_flock(path: Path) -> int | None:
    """The fd of ``path`` locked exclusively, None if it vanished meanwhile; raises
    BlockingIOError if another process holds it."""
    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o666)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        # the previous owner may have removed the file between our open and our lock
        if os.stat(path).st_ino == os.fstat(fd).st_ino:
            return fd
    except FileNotFoundError:
        pass
    except BaseException:
        os.close(fd)
        raise
    os.close(fd)
    return None


def _try_pidfile(path: Path) -> int | None:
    """The fd of a newly created ``path``, None after removing a dead owner's; raises
    BlockingIOError if a live process owns it."""
    try:
        return os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666)
    except FileExistsError:
        pid = read_pid(path)
        if pid is None or _pid_alive(pid):
            raise BlockingIOError from None
        with contextlib.suppress(FileNotFoundError):  # a dead owner's: take it over
            path.unlink()
        return None


def acquire(path, *, make_folder: bool = False) -> int:
    """Lock the file ``path`` (created if missing) for this process and write its pid.

    Parameters
    ----------
    path : path-like
        The lock file.
    make_folder : bool
        Create its folder if missing (and again if another process removes it meanwhile).

    Returns
    -------
    int
        The open file descriptor of the lock (hand it to :func:`release`).

    Raises
    ------
    Busy
        Another live process holds the lock.
    """
    path = Path(path)
    for _ in range(20):
        if make_folder:
            path.parent.mkdir(exist_ok=True)
        try:
            fd = _try_flock(path) if fcntl is not None else _try_pidfile(path)
        except BlockingIOError:
            raise Busy(read_pid(path)) from None
        except FileNotFoundError:  # the folder went away meanwhile
            if not make_folder:
                raise
            continue
        if fd is not None:
            os.ftruncate(fd, 0)
            os.write(fd, f"{os.getpid()}\n".encode())
            return fd
    raise Busy(read_pid(path))


def release(path, fd: int) -> None:
    """Remove the lock file ``path`` and close ``fd`` (in this order: a process waiting on
    the old file finds it gone and retries on a new one)."""
    with contextlib.suppress(FileNotFoundError):
        Path(path).unlink()
    os.close(fd)
