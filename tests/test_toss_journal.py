"""``toss --results F``: the journal is ours, checked before the work, never torn, one
writer at a time, validated on resume (issue 36, item 1).

The tosses themselves are replaced by a fake (``_one`` returns an outcome read off the
launch) so that these tests hold the file handling, not the mechanics; the launches are
the real ones.
"""

from __future__ import annotations

import errno
import json
import os
import stat
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import rollingdisk.scenarios.toss as T
from rollingdisk.cli.app import main
from rollingdisk.util import journal as J
from rollingdisk.util.errors import ParameterError

SRC = Path(__file__).resolve().parents[1] / "src"


def _fake(a):
    h, row, e, mu, t_end, max_wall = a
    return ("heads" if row[1] > 2.0 else "tails"), "energy", float(row[0]), 1


@pytest.fixture
def fake(monkeypatch):
    monkeypatch.setattr(T, "_one", _fake)
    monkeypatch.setattr(T, "_load_compiled", lambda: None)


def _toss(path, *extra):
    return ["toss", "--h", "0.1", "--n", "5", "--seed", "3", "--results", str(path), *extra]


def _one_line(capsys, status, args):
    assert main(args) == status
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    return err


def _lines(path):
    return path.read_text().splitlines()


def test_a_new_journal_is_whole_and_resumes(tmp_path, fake, capsys):
    path = tmp_path / "t.jsonl"
    assert main(_toss(path, "--json")) == 0
    first = json.loads(capsys.readouterr().out)
    lines = _lines(path)
    assert len(lines) == 6 and list(json.loads(lines[0])) == ["ensemble"]
    assert sorted(json.loads(x)["i"] for x in lines[1:]) == list(range(5))
    path.write_text("\n".join(lines[:3]) + "\n" + lines[3][:9])  # killed mid-line
    assert main(_toss(path, "--json")) == 0
    again = json.loads(capsys.readouterr().out)
    assert again["counts"] == first["counts"]
    lines = _lines(path)
    assert len(lines) == 6 and all(json.loads(x) for x in lines)  # the torn line cut off


@pytest.mark.parametrize("case", ["missing folder", "folder", "device", "proc", "foreign",
                                  "foreign link", "another ensemble", "fifo"])
def test_a_path_that_is_not_ours_is_refused_before_the_work(tmp_path, fake, capsys, case,
                                                             monkeypatch):
    calls = []
    monkeypatch.setattr(T, "_one", lambda a: calls.append(a) or _fake(a))
    foreign = tmp_path / "notes.txt"
    foreign.write_text("my notes\n")
    path = {"missing folder": tmp_path / "no" / "t.jsonl", "folder": tmp_path,
            "device": Path("/dev/full"), "proc": Path("/proc/self/status"),
            "foreign": foreign, "foreign link": tmp_path / "link.jsonl",
            "another ensemble": tmp_path / "other.jsonl", "fifo": tmp_path / "fifo"}[case]
    if case == "foreign link":
        path.symlink_to(foreign)
    if case == "another ensemble":
        assert main(_toss(path)[:-2] + ["--seed", "4", "--results", str(path)]) == 0
        capsys.readouterr()
    if case == "fifo":
        os.mkfifo(path)
    before = foreign.read_bytes()
    calls.clear()
    err = _one_line(capsys, 2, _toss(path))
    assert err.startswith("rollingdisk toss: error: results:"), err
    assert calls == []  # refused before any toss
    assert foreign.read_bytes() == before
    if case == "fifo":
        assert stat.S_ISFIFO(os.stat(path).st_mode)


def test_a_read_only_folder_is_refused(tmp_path, fake, capsys):
    if os.geteuid() == 0:
        pytest.skip("root writes anywhere")
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    try:
        err = _one_line(capsys, 2, _toss(ro / "t.jsonl"))
    finally:
        ro.chmod(0o700)
    assert "not writable" in err


@pytest.mark.parametrize("bad", ['{"x": 1}', '{"i": "a", "outcome": "heads"}',
                                 '{"i": 99, "outcome": "heads", "decided_by": "rest", '
                                 '"t": 1.0, "n_impacts": 0}',
                                 '{"i": 1, "outcome": "heads", "decided_by": "rest", '
                                 '"t": NaN, "n_impacts": 0}',
                                 '[1, 2]', 'garbage', '{"i": 1'])
def test_a_line_that_is_not_a_toss_is_refused_in_one_line(tmp_path, fake, capsys, bad):
    path = tmp_path / "t.jsonl"
    assert main(_toss(path)) == 0
    capsys.readouterr()
    lines = _lines(path)
    lines.insert(2, bad)
    path.write_text("\n".join(lines) + "\n")
    before = path.read_bytes()
    err = _one_line(capsys, 2, _toss(path))
    assert "line 3" in err and "not a record" in err, err
    assert path.read_bytes() == before


def test_a_full_disk_is_one_line_and_leaves_whole_lines(tmp_path, fake, capsys, monkeypatch):
    """The third record's write fails half-way (ENOSPC): exit 2, one line, the file ends
    with a whole line, and a rerun resumes from it."""
    path = tmp_path / "t.jsonl"
    real_write, n = os.write, []

    def write(fd, data):
        n.append(bytes(data[:5]) == b'{"i":')
        if sum(n) == 3 and n[-1]:  # two records, then a torn one
            real_write(fd, data[: len(data) // 2])
            raise OSError(errno.ENOSPC, "No space left on device")
        return real_write(fd, data)

    monkeypatch.setattr(J.os, "write", write)
    err = _one_line(capsys, 2, _toss(path))
    assert "No space left on device" in err
    text = path.read_text()
    assert text.endswith("\n") and len(text.splitlines()) == 3
    monkeypatch.setattr(J.os, "write", real_write)
    assert main(_toss(path)) == 0
    assert len(_lines(path)) == 6


def test_a_toss_whose_time_is_not_finite_is_written_without_nan(tmp_path, monkeypatch):
    monkeypatch.setattr(T, "_one", lambda a: ("undecided", "none", float("nan"), 0))
    monkeypatch.setattr(T, "_load_compiled", lambda: None)
    path = tmp_path / "t.jsonl"
    T.toss_ensemble(T.Disk(0.1), 3, 0, results=path)
    text = path.read_text()
    assert "NaN" not in text and "Infinity" not in text
    assert json.loads(_lines(path)[1])["t"] is None
    with pytest.raises(ParameterError, match="non-finite"):
        with J.open_journal(tmp_path / "j.jsonl", {"k": 1}, dict) as (j, _):
            j.append({"t": float("inf")})


def test_launches_stream_in_blocks_and_equal_the_draw(monkeypatch):
    """Blocks of the generator give :meth:`TossDistribution.draw`'s numbers bit for bit,
    and the workers are handed one block at a time, not the whole ensemble."""
    monkeypatch.setattr(T, "BLOCK", 7)
    dist = T.TossDistribution()
    rows = np.array([r for _, r in T._launches(dist, 23, 5)])
    assert np.array_equal(rows, dist.draw(23, 5))

    taken = []

    def todo():
        for i in range(10**9):  # an ensemble too large to build
            taken.append(i)
            yield i, i

    class Pool:
        def imap(self, f, args, chunksize):
            return iter(args)  # the toss is not the point here

    got = T._blocks(Pool(), todo(), 2)
    assert [next(got) for _ in range(3)] == [(0, 0), (1, 1), (2, 2)]
    assert len(taken) == 7


def test_workers_beyond_the_cpus_are_refused(capsys):
    err = _one_line(capsys, 2, ["toss", "--h", "0.1", "--n", "2", "--workers",
                                str(T.max_workers() + 1)])
    assert "workers" in err and str(T.max_workers()) in err


# A writer whose first toss waits until the test lets it go on.
WRITER = """
import sys, time
from pathlib import Path
import rollingdisk.scenarios.toss as T
from rollingdisk.cli.app import main
path, ready, go = map(Path, sys.argv[1:4])
def one(a):
    if not ready.exists():
        ready.touch()
        t = time.time()
        while not go.exists() and time.time() - t < 120:
            time.sleep(0.02)
    h, row, e, mu, t_end, max_wall = a
    return ("heads" if row[1] > 2.0 else "tails"), "energy", float(row[0]), 1
T._one, T._load_compiled = one, lambda: None
sys.exit(main(["toss", "--h", "0.1", "--n", sys.argv[4], "--seed", "3", "--results",
               str(path), "--json"]))
"""


def _writer(tmp_path, path, n, tag):
    ready, go = tmp_path / f"ready{tag}", tmp_path / "go"
    return subprocess.Popen([sys.executable, "-c", WRITER, str(path), str(ready), str(go),
                             str(n)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=dict(os.environ, PYTHONPATH=SRC)), ready


def _check_whole(path, n):
    lines = _lines(path)
    assert path.read_text().endswith("\n")
    recs = [json.loads(x) for x in lines[1:]]
    assert sorted(r["i"] for r in recs) == list(range(n))


def test_a_second_writer_is_refused_naming_the_pid(tmp_path):
    path = tmp_path / "t.jsonl"
    first, ready = _writer(tmp_path, path, 40, "a")
    try:
        t = time.monotonic()
        while not ready.exists():
            assert first.poll() is None, first.communicate()
            assert time.monotonic() - t < 120
            time.sleep(0.02)
        second, _ = _writer(tmp_path, path, 40, "b")
        out, err = second.communicate(timeout=120)
        assert second.returncode == 2, err
        assert err.strip().splitlines() == [err.strip()]
        assert f"pid {first.pid}" in err and "another process" in err
    finally:
        (tmp_path / "go").touch()
        out, err = first.communicate(timeout=120)
    assert first.returncode == 0, err
    _check_whole(path, 40)


def test_writers_started_together_never_tear_the_file(tmp_path):
    """Three writers at once: each either wins the lock and finishes, finds the work done
    and resumes it, or is refused in one line; the file is whole in every case."""
    path = tmp_path / "t.jsonl"
    (tmp_path / "go").touch()
    procs = [_writer(tmp_path, path, 300, k)[0] for k in range(3)]
    results = [(p, *p.communicate(timeout=180)) for p in procs]
    for p, _out, err in results:
        assert p.returncode in (0, 2), err
        if p.returncode == 2:
            assert len(err.strip().splitlines()) == 1 and "pid" in err, err
    assert any(p.returncode == 0 for p, _, _ in results)
    _check_whole(path, 300)


def test_a_long_ensemble_shows_progress_on_a_terminal_only(fake, capsys, monkeypatch):
    """``toss --n 1000000`` printed nothing until the end: on a terminal a progress line
    is drawn (never with --json or into a pipe)."""
    from rollingdisk.util import progress

    made = []

    class Bar(progress.ProgressBar):
        def __init__(self, *a, **kw):
            super().__init__(*a, **{**kw, "delay": 0.0, "interval": 0.0})
            made.append(self)

    monkeypatch.setattr(progress, "ProgressBar", Bar)
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    assert main(["toss", "--h", "0.1", "--n", "5"]) == 0
    err = capsys.readouterr().err
    assert "tosses [" in err and "5/5" in err and not made[-1].quiet
    assert main(["toss", "--h", "0.1", "--n", "5", "--json"]) == 0
    assert "tossing" not in capsys.readouterr().err and made[-1].quiet
