"""Outputs complete or absent: concurrent runs into one folder (rollingdisk.util.files)."""

import json
import multiprocessing
import os

import pytest

from rollingdisk.util.files import atomic_dir


def _swap_many(base, i, n):
    for _ in range(n):
        with atomic_dir(os.path.join(base, "out")) as d:
            (d / "a.json").write_text(json.dumps(i))
            (d / "b.json").write_text(json.dumps(i))


def test_concurrent_atomic_dirs_leave_one_whole_folder(tmp_path):
    """Four processes swapping folders into one target at once: every swap succeeds (the
    last to finish wins), the folder left is one run's whole output, no temporary is left.
    Before the fix a rename between another run's move-aside and its rename failed with
    'Directory not empty'."""
    ctx = multiprocessing.get_context("spawn")
    procs = [ctx.Process(target=_swap_many, args=(str(tmp_path), i, 10)) for i in range(4)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(timeout=120)
    assert [p.exitcode for p in procs] == [0, 0, 0, 0]
    assert sorted(os.listdir(tmp_path)) == ["out"]
    out = tmp_path / "out"
    assert (out / "a.json").read_text() == (out / "b.json").read_text()


def test_a_swallowed_signal_still_stops_the_commit(tmp_path):
    """A KeyboardInterrupt raised where Python only prints it (a weakref callback, a
    __del__) must not end in a written result: the signal is remembered and raised again
    before the rename (CI caught an atlas that finished after Ctrl-C this way)."""
    import signal as sig

    from rollingdisk.util.files import _PENDING, atomic_dir, atomic_file, terminate_as_exception

    with terminate_as_exception():
        _PENDING.append(sig.SIGINT)  # as the handler does when its exception is swallowed
        with pytest.raises(KeyboardInterrupt):
            with atomic_file(tmp_path / "a.txt") as fh:
                fh.write("x")
        with pytest.raises(KeyboardInterrupt):
            with atomic_dir(tmp_path / "d") as d:
                (d / "x").write_text("x")
        _PENDING.clear()
    assert list(tmp_path.iterdir()) == []
