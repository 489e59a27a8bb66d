"""Outputs complete or absent: concurrent runs into one folder (rollingdisk._files)."""

import json
import multiprocessing
import os

from rollingdisk._files import atomic_dir


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
