"""Output files and folders that appear whole or not at all.

Every file the library or the command line writes goes through :func:`atomic_file` (a
temporary name in the destination folder, renamed over the target at the end) and every
folder of results through :func:`atomic_dir` (built under a temporary name beside the
target, swapped in at the end).  On any exception, ``KeyboardInterrupt`` and
:class:`Terminated` (SIGTERM, see :func:`terminate_as_exception`) included, the temporary
is removed and the target is left as it was.  :func:`check_writable` refuses a destination
before the work, not after it.

Destinations that are not regular files: a symbolic link is written through (the file it
points to is replaced, the link stays, as ``cp`` and shell redirection do); a character
device or a FIFO (``/dev/null``, ``/dev/stdout``, a named pipe) is written directly, never
replaced by a file (a writer that opens the file itself, and may seek in it, writes a
temporary file that is then copied to it).  Permissions follow the umask, as for a file
created with ``open``.
:func:`committed` lists the outputs completed so far, so that an interruption that comes
after them can say they are whole.
"""

from __future__ import annotations

import contextlib
import errno
import os
import shutil
import signal
import stat
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

from rollingdisk.util.errors import ParameterError

__all__ = ["Terminated", "atomic_file", "atomic_dir", "check_writable",
           "check_replaceable", "terminate_as_exception", "check_signals", "pending_signal",
           "committed", "quiet_forked_children", "helpers_block_sigint"]

#: Signals received while :func:`terminate_as_exception` is active (see check_signals).
_PENDING: list[int] = []
#: Outputs put in place by atomic_file / atomic_dir in this process (see committed).
_COMMITTED: list[Path] = []


def committed() -> tuple[Path, ...]:
    """The outputs :func:`atomic_file` and :func:`atomic_dir` completed in this process, in
    order (absolute paths; a device or FIFO written through counts once its writer closed)."""
    return tuple(_COMMITTED)


def _resolve(path) -> Path:
    """The absolute destination, symbolic links followed (a dangling one: its target)."""
    return Path(os.path.realpath(os.path.abspath(os.fspath(path))))


def _is_stream(target: Path) -> bool:
    """Whether ``target`` is a character device or a FIFO: written directly, not replaced."""
    try:
        mode = os.stat(target).st_mode
    except OSError:
        return False
    return stat.S_ISCHR(mode) or stat.S_ISFIFO(mode)


class Terminated(BaseException):  # noqa: N818 - named like KeyboardInterrupt
    """Raised in the main thread on SIGTERM while :func:`terminate_as_exception` is active."""


def _raise_for(signum: int):
    if signum == signal.SIGINT:
        raise KeyboardInterrupt
    raise Terminated(f"terminated by signal {signum}")


@contextlib.contextmanager
def terminate_as_exception() -> Iterator[None]:
    """Turn SIGTERM into a :class:`Terminated` exception and SIGINT into KeyboardInterrupt
    (main thread only), so that the clean-up of :func:`atomic_file` and :func:`atomic_dir`
    runs; each signal is also remembered, so that :func:`check_signals` can raise it again
    if Python swallowed the exception (one raised inside a weakref callback or ``__del__``
    is only printed)."""
    def handler(signum, frame):
        _PENDING.append(signum)
        _raise_for(signum)

    def unraisable(info):  # the swallowed signal is raised again by check_signals
        if not issubclass(info.exc_type, (KeyboardInterrupt, Terminated)):
            old_hook(info)

    _PENDING.clear()
    try:
        old = signal.signal(signal.SIGTERM, handler)
        old_int = signal.signal(signal.SIGINT, handler)
    except ValueError:  # not the main thread: leave the signals alone
        yield
        return
    old_hook, sys.unraisablehook = sys.unraisablehook, unraisable
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, old)
        signal.signal(signal.SIGINT, old_int)
        sys.unraisablehook = old_hook


_STOP_SIGNALS = {signal.SIGINT, signal.SIGTERM}
_FORK_MASK: list = []


def _block_for_fork() -> None:
    _FORK_MASK.append(signal.pthread_sigmask(signal.SIG_BLOCK, _STOP_SIGNALS))


def _unblock_in_parent() -> None:
    if _FORK_MASK:
        signal.pthread_sigmask(signal.SIG_SETMASK, _FORK_MASK.pop())


def _quiet_in_child() -> None:
    _FORK_MASK.clear()
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, _STOP_SIGNALS)


_FORK_HOOKS: list = []


def quiet_forked_children() -> None:
    """Make every process this one forks from now on (a helper of ``multiprocessing``)
    start with SIGINT ignored and SIGTERM at its default (a quiet death), from its first
    instant: the signals are blocked across ``fork`` and unblocked in the child only once
    its handlers are set.  A Ctrl-C reaches the whole process group; the parent reports
    it in one line and stops its helpers, and a helper forked just then would otherwise
    run the parent's handler and print a traceback.  Installed once per process."""
    if _FORK_HOOKS or not hasattr(os, "register_at_fork") \
            or not hasattr(signal, "pthread_sigmask"):
        return
    os.register_at_fork(before=_block_for_fork, after_in_parent=_unblock_in_parent,
                        after_in_child=_quiet_in_child)
    _FORK_HOOKS.append(True)


@contextlib.contextmanager
def helpers_block_sigint() -> Iterator[None]:
    """Processes started in the block (spawned: a fresh interpreter) never see SIGINT:
    this thread blocks it while they are started, and they inherit the blocked signal
    (SIGTERM stays theirs: it is how their parent stops them).  A Ctrl-C reaches the
    whole process group; the parent reports it in one line and stops its helpers, and a
    helper's KeyboardInterrupt traceback would break that contract.  A Ctrl-C during the
    block stays this process's: it is delivered at the end of the block at the latest."""
    try:
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    except (AttributeError, ValueError, OSError):  # pragma: no cover - not POSIX
        yield
        return
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)


def pending_signal() -> int | None:
    """The last signal received under :func:`terminate_as_exception`, or None: an error
    raised after it (a library that caught the signal's exception and failed in its own
    way) is reported as the interruption it is."""
    return _PENDING[-1] if _PENDING else None


def check_signals() -> None:
    """Raise again a signal received under :func:`terminate_as_exception` whose exception
    was swallowed; called before an output is committed, so that a Ctrl-C or SIGTERM
    never ends in a written result."""
    if _PENDING:
        _raise_for(_PENDING[-1])


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def check_writable(path, *, name: str = "out", folder: bool = False) -> Path:
    """Refuse, before any work, a destination that cannot be written.

    Parameters
    ----------
    path : path-like
        The file (or, with ``folder=True``, the folder) to be written.
    name : str
        The parameter's name for the message.
    folder : bool
        ``path`` is a folder of results (created if missing, replaced as a whole).

    Returns
    -------
    Path
        The absolute path.

    Raises
    ------
    ParameterError
        If the parent folder is missing or not writable, the target is of the wrong kind
        (a folder given for a file or the reverse, a socket or block device), or an
        existing file is read-only.  A symbolic link is checked as the file it points to;
        a character device or FIFO must be writable itself.
    """
    target = _resolve(path)
    if not folder and _is_stream(target):
        if not os.access(target, os.W_OK):
            raise ParameterError(f"{name}: {target} is not writable")
        return target
    if target.exists() and not folder and not (target.is_file() or target.is_dir()):
        raise ParameterError(f"{name}: {target} is not a regular file, a character device "
                             "or a FIFO; give a file name")
    check_parent_writable(target, name)
    if folder:
        if target.exists() and not target.is_dir():
            raise ParameterError(f"{name}: {target} exists and is not a folder")
    else:
        if target.is_dir():
            raise ParameterError(f"{name}: {target} is a folder; give a file name")
        if target.exists() and not os.access(target, os.W_OK):
            raise ParameterError(f"{name}: {target} is read-only; remove it or choose "
                                 "another name")
    return target


def check_parent_writable(target: Path, name: str) -> None:
    """Refuse ``target`` (named ``name`` in the message) unless its parent is an existing
    folder this process may create files in: :class:`ParameterError`."""
    parent = target.parent
    if not parent.is_dir():
        raise ParameterError(f"{name}: no such folder: {parent}")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise ParameterError(f"{name}: the folder {parent} is not writable")


def check_replaceable(path, names, *, name: str = "out") -> Path:
    """Refuse, before any work, a folder of results that :func:`atomic_dir` may not replace.

    :func:`atomic_dir` replaces the target folder as a whole.  That is right for a folder
    this command wrote before (or an empty one), and wrong for any other: ``--out .`` or
    ``--out ~`` must not delete the user's files.

    Parameters
    ----------
    path : path-like
        The folder of results.
    names : iterable of str
        The file names the command writes there.
    name : str
        The parameter's name for the message.

    Returns
    -------
    Path
        The absolute path (checked with :func:`check_writable` too).

    Raises
    ------
    ParameterError
        If the folder exists and holds anything but files named in ``names``.
    """
    target = check_writable(path, name=name, folder=True)
    cwd = os.path.abspath(os.getcwd())
    if os.path.commonpath([cwd, target]) == str(target):
        raise ParameterError(f"{name}: {target} is the current folder or contains it; give a "
                             "folder of its own (e.g. a new name)")
    if target.is_dir():
        allowed = set(names)
        try:
            entries = sorted(os.listdir(target))
        except OSError as exc:
            raise ParameterError(f"{name}: cannot read the folder {target}: "
                                 f"{exc.strerror or exc}") from None
        foreign = [e for e in entries if e not in allowed or not (target / e).is_file()]
        if foreign:
            raise ParameterError(
                f"{name}: the folder {target} holds files this command did not write (e.g. "
                f"{foreign[0]!r}) and would be replaced as a whole; give a new or empty "
                "folder, or one this command wrote")
    return target


@contextlib.contextmanager
def atomic_file(path, mode: str = "w", **open_kw) -> Iterator:
    """Open a temporary file beside ``path``; on success rename it to ``path``.

    Yields an open file object (``mode`` ``"w"``, ``"wb"``, ...).  With ``mode=None`` it
    yields the temporary :class:`~pathlib.Path` instead (for writers that open the file
    themselves, e.g. ``savefig``; keep the suffix of ``path``).  A symbolic link is
    written through; a character device or FIFO is opened directly (with ``mode=None``:
    a temporary file is yielded and copied to it at the end).
    """
    target = _resolve(path)
    if _is_stream(target):
        try:
            if mode is None:  # the writer may seek: a temporary file, then copied over
                with _stream_copy(target, Path(os.fspath(path)).suffix) as tmp:
                    yield tmp
            else:
                with open(target, mode, **open_kw) as fh:
                    yield fh
        except OSError as exc:
            _name(exc, path)
            raise
        _COMMITTED.append(target)
        return
    fd, tmp = tempfile.mkstemp(prefix=f".{target.stem}.", suffix=f".tmp{target.suffix}",
                               dir=target.parent)
    tmp = Path(tmp)
    try:
        os.chmod(tmp, 0o666 & ~_umask())
        if mode is None:
            os.close(fd)
            yield tmp
        else:
            with os.fdopen(fd, mode, **open_kw) as fh:
                yield fh
        check_signals()
        os.replace(tmp, target)
        _COMMITTED.append(target)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            if mode is None:
                os.close(fd)
        with contextlib.suppress(OSError):
            tmp.unlink()
        if isinstance(exc, OSError):
            _name(exc, path)
        raise


@contextlib.contextmanager
def _stream_copy(target: Path, suffix: str) -> Iterator[Path]:
    """A temporary file (in the system's temporary folder) for a writer that opens its
    file itself and may seek in it (an image or animation writer), copied to the device
    or FIFO ``target`` when the writer is done, and removed in any case."""
    fd, tmp = tempfile.mkstemp(prefix=".rollingdisk.", suffix=f".tmp{suffix}")
    os.close(fd)
    tmp = Path(tmp)
    try:
        yield tmp
        check_signals()
        with open(tmp, "rb") as src, open(target, "wb") as dst:
            shutil.copyfileobj(src, dst)
    finally:
        with contextlib.suppress(OSError):
            tmp.unlink()


def _name(exc: OSError, path) -> None:
    """Name the destination in an error of a write (``write`` and ``close`` leave
    ``filename`` unset: "No space left on device" alone does not say where)."""
    if exc.filename is None and exc.errno is not None:
        with contextlib.suppress(TypeError, ValueError):
            exc.filename = os.fspath(path)


def _swap_in(tmp: Path, target: Path, attempts: int = 50) -> None:
    """Rename the folder ``tmp`` to ``target``, moving an existing ``target`` aside first.

    Another run may swap its own folder in between our moving the old one aside and our
    rename (the rename then fails: the target is not empty); we move that one aside too and
    try again, so the run that finishes last leaves its whole folder.
    """
    for _ in range(attempts):
        old = None
        try:
            if target.exists():
                old = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".old",
                                            dir=target.parent))
                with contextlib.suppress(FileNotFoundError):  # another run moved it first
                    os.replace(target, old / "x")
            try:
                os.replace(tmp, target)
                return
            except OSError as exc:
                if exc.errno not in (errno.ENOTEMPTY, errno.EEXIST):
                    raise
        finally:
            if old is not None:
                shutil.rmtree(old, ignore_errors=True)
    raise OSError(errno.EBUSY, f"could not put the finished folder in place of {target} "
                  f"(other runs kept replacing it)", str(target))


@contextlib.contextmanager
def atomic_dir(path) -> Iterator[Path]:
    """Build a folder under a temporary name beside ``path``; on success swap it in.

    Yields the temporary folder to write into.  At the end an existing ``path`` is moved
    aside, the new folder renamed into its place and the old one deleted: readers see
    either the old folder or the new one, never a mixture, and two runs into the same
    folder leave the whole result of the one that finished last.  A symbolic link to a
    folder is written through (the folder it points to is replaced, the link stays).
    """
    target = _resolve(path)
    tmp = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent))
    try:
        os.chmod(tmp, 0o777 & ~_umask())
        yield tmp
        check_signals()
        _swap_in(tmp, target)
        _COMMITTED.append(target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
