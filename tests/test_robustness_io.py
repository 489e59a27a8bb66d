"""Issue 36: budgets known up front, outputs that are not ours, one line and exit 2, signals
in every phase (the command line's run paths; the API's hostile inputs are elsewhere).

No test here depends on the machine's speed: budgets are held with clocks replaced by
counters, refusals come before any work.
"""

from __future__ import annotations

import math
import os
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pytest

import rollingdisk as rd
from rollingdisk.cli.app import main
from rollingdisk.phases import touchdown as _td
from rollingdisk.scenarios.toss import TossDistribution, toss


def test_the_touchdown_scan_of_a_tall_disk_holds_the_wall_budget(monkeypatch):
    """A toss of a disk with h = 1e8 (``toss --h 1e8 --seed 0``) falls for t ~ 1.4e4 on a
    grid step ~ 1e-2: the touchdown scan had 1.4 million heights to evaluate (69 s with a
    5 s budget).  It looks at the clock every 1024 heights: past the deadline it stops,
    and the run ends with status time-budget saying where it was."""
    h = 1e8
    lift, v, w1, tilt, w2, w3, vx = TossDistribution().draw(1, 0)[0]  # toss --seed 0
    s = [0.0, 0.0, 1.0 + h + lift, 0.0, tilt, 0.0, vx, 0.0, v, w1, w2, w3]
    with pytest.raises(_td.Spent):
        _td.touchdown(rd.Disk(h), s, deadline=-math.inf)

    def spent(disk, s, deadline):
        assert deadline == pytest.approx(t0 + 5.0, abs=60.0)
        raise _td.Spent("3")

    from rollingdisk.phases import motion as _motion

    t0 = _td.time.perf_counter()
    monkeypatch.setattr(_motion, "touchdown", spent)
    r = toss(rd.Disk(0.1), 3.0, 1.0, 2.0, 0.3, max_wall=5.0)
    assert (r.outcome, r.motion.status) == ("undecided", "time-budget")
    assert "touchdown" in r.motion.message and "5 s" in r.motion.message


def test_the_touchdown_scan_is_the_same_without_a_deadline():
    """The deadline changes nothing when it is not reached: the scan (forced by a
    conservative advancement that gives up) finds the closed-form touchdown of a
    disk falling flat, Z_C = 2 - t^2/2 reaching h (theta = pi/2 - 1e-3, no spin)."""
    h, th = 0.1, 0.5 * math.pi - 1e-3
    s = [0.0, 0.0, 2.0, 0.0, th, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    low = abs(math.cos(th)) + h * abs(math.sin(th))
    exact = math.sqrt(2.0 * (2.0 - low))
    real = _td.touchdown_time
    try:
        _td.touchdown_time = lambda *a, **k: (_ for _ in ()).throw(RuntimeError("stall"))
        t = _td.touchdown(rd.Disk(h), s)
        t_late = _td.touchdown(rd.Disk(h), s, deadline=1e300)
    finally:
        _td.touchdown_time = real
    assert t == t_late and abs(t - exact) < 1e-12


def _one_line(capsys, status, args):
    assert main([str(a) for a in args]) == status
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert len(err.splitlines()) == 1, err
    return err, captured.out


@pytest.mark.parametrize("extra", [[], ["--basin"]])
def test_a_sweep_too_large_is_refused_up_front_saying_what_fits(tmp_path, capsys, extra):
    """10^5 x 10^5 points (an ETA of days, a store of hundreds of GB) is refused before
    any work, on stderr even with --json, with the points per range that would fit."""
    out = tmp_path / "s.zarr"
    err, stdout = _one_line(capsys, 2, ["sweep", "--ground", "rough", "--theta0",
                                        "0.3:1.2:100000", "--omega30", "1:3:100000",
                                        "--t-end", "10", "--out", out, "--json", *extra])
    assert stdout == ""
    assert "10000000000" in err or "x 11 rounds" in err
    assert "at most" in err and "points on each of the 2 ranges" in err
    per = int(err.split("at most ")[1].split()[0])
    rounds = 11 if extra else 1
    assert per * per * rounds <= 10_000_000 < (per + 1) ** 2 * rounds
    assert list(tmp_path.iterdir()) == []


# ------------------------------------------------------------------ item 2: outputs
needs_dev_full = pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full")


@needs_dev_full
def test_a_full_disk_under_an_output_other_than_out_is_one_line(capsys, monkeypatch):
    """ENOSPC while writing --sound (the command's --out unset) was a traceback: a full or
    read-only destination is one line naming it, whichever option named it."""
    from rollingdisk.cli import euler_disk as command
    from rollingdisk.util.files import atomic_file

    def run(args):
        with atomic_file(args.sound, "wb") as fh:
            fh.write(b"RIFF" * 4096)
        return 0

    monkeypatch.setattr(command, "run", run)
    err, _ = _one_line(capsys, 2, ["euler-disk", "--sound", "/dev/full"])
    assert err == "rollingdisk euler-disk: error: /dev/full: No space left on device"


@needs_dev_full
@pytest.mark.slow
def test_euler_disk_sound_to_a_full_disk(capsys):
    err, _ = _one_line(capsys, 2, ["euler-disk", "--sound", "/dev/full", "--sound-seconds",
                                   "0.5", "--quiet"])
    assert err.endswith("/dev/full: No space left on device")


def test_a_writer_that_seeks_can_write_to_a_fifo(tmp_path):
    """An animation or image writer seeks in its file (a GIF's header is written last):
    to a FIFO it writes a temporary file that is copied over whole at the end; the FIFO
    stays a FIFO."""
    from rollingdisk.util.files import atomic_file

    fifo = tmp_path / "f.gif"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()))
    reader.start()
    try:
        with atomic_file(fifo, mode=None) as tmp:
            assert tmp.suffix.endswith(".gif") and tmp.is_file()
            with open(tmp, "wb") as f:
                f.write(b"....body")
                f.seek(0)
                f.write(b"HEAD")
    finally:
        if reader.is_alive():  # never leave the reader blocked
            with open(fifo, "wb"):
                pass
        reader.join(timeout=60)
    assert got == [b"HEADbody"]
    assert stat.S_ISFIFO(os.stat(fifo).st_mode) and not tmp.exists()


@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("extra", [[], ["--until-rest"]])
def test_a_ground_beyond_floating_point_range_is_one_line(capsys, extra):
    """--air 1.7e308: the equations are not finite at the start (hybrid._Singular at t =
    0, a traceback, after two RuntimeWarnings): refused in one line, no warning."""
    err, out = _one_line(capsys, 2, ["simulate", "--h", "0.1", "--ground", "coulomb", "--mu",
                                     "0.5", "--air", "1.7e308", "--theta0", "0.3", "--rC",
                                     "2", "--t-end", "1", *extra])
    assert "beyond floating-point range" in err and out == ""


# -------------------------------------------------------------- item 3: sweep outputs
_SWEEP = ["sweep", "--ground", "rough", "--theta0", "0.3:1.2:2", "--omega30", "1:3:2",
          "--t-end", "5"]


@pytest.mark.parametrize("kind", ["fifo", "foreign folder", "file"])
def test_a_sweep_never_replaces_what_is_not_a_store(tmp_path, capsys, kind):
    out = tmp_path / "s.zarr"
    if kind == "fifo":
        os.mkfifo(out)
    elif kind == "foreign folder":
        out.mkdir()
        (out / "thesis.tex").write_text("mine")
    else:
        out.write_text("mine")
    before = sorted(p.name for p in tmp_path.rglob("*"))
    err, _ = _one_line(capsys, 2, [*_SWEEP, "--out", out])
    assert err.startswith("rollingdisk sweep: error: out:")
    assert sorted(p.name for p in tmp_path.rglob("*")) == before
    if kind == "fifo":
        assert stat.S_ISFIFO(os.stat(out).st_mode)


@pytest.mark.parametrize("basin", [False, True])
@pytest.mark.parametrize("error", ["input", "disk full"])
def test_a_sweep_that_ends_in_exit_2_leaves_no_partial_folder(tmp_path, capsys, monkeypatch,
                                                              basin, error):
    """The records are written, then the store cannot be (a full disk, a refused value):
    exit 2, one line, and no ``*.partial`` folder behind."""
    import errno

    from rollingdisk.sweep import basin as _basin
    from rollingdisk.sweep import runner as _runner
    from rollingdisk.util.errors import ParameterError

    def save(ds, out):
        if error == "input":
            raise ParameterError("out: refused")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(_basin if basin else _runner, "save", save)
    out = tmp_path / "s.zarr"
    _one_line(capsys, 2, [*_SWEEP, "--out", out, "--json",
                          *(["--basin", "--rounds", "1"] if basin else [])])
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------- item 5: exit 2 is exactly one line
@pytest.mark.parametrize("host", ["no.such.host.invalid", "999.1.1.1", "a..b"])
def test_explore_on_an_address_that_cannot_be_bound_is_one_line(capsys, host):
    """The "binding beyond localhost" warning came before the error (2-4 lines): it is
    now printed only once the address is bound."""
    pytest.importorskip("rollingdisk.explore")
    err, out = _one_line(capsys, 2, ["explore", "--host", host, "--no-browser"])
    assert err.startswith(f"rollingdisk explore: error: cannot serve on {host}:")
    assert out == ""


@pytest.mark.filterwarnings("error")
def test_an_until_rest_start_whose_energy_overflows_is_one_line(capsys):
    """omega3 = 1e160: 49 lines (warnings of every phase, then the error); now one."""
    err, out = _one_line(capsys, 2, ["simulate", "--h", "0.1", "--ground", "coulomb",
                                     "--mu", "0.5", "--until-rest", "--state",
                                     "theta=0.3,omega3=1e160", "--t-end", "10"])
    assert "beyond floating-point range" in err and out == ""


# ------------------------------------------------------------------- item 6: signals
SRC = Path(__file__).resolve().parents[1] / "src"

AFTER_WORK = """
import atexit, os, signal, sys
import rollingdisk.cli.app as app
real = app.main
def main(argv):
    status = real(argv)
    if {when!r} == "returning":
        os.kill(os.getpid(), signal.{sig})
    else:  # during the interpreter's shutdown, before the entry's last word
        atexit.register(os.kill, os.getpid(), signal.{sig})
    return status
app.main = main
import rollingdisk.cli.entry as entry
sys.argv = ["rollingdisk", "thresholds", "--h", "0.2"]
sys.exit(entry.main())
"""


@pytest.mark.parametrize("when", ["returning", "shutdown"])
@pytest.mark.parametrize("sig, code, word", [("SIGINT", 130, "interrupted"),
                                             ("SIGTERM", 143, "terminated")])
def test_a_signal_after_the_work_is_one_line_not_a_silent_death(when, sig, code, word):
    """A signal in the ~0.15 s after the command is done (its outputs complete) killed
    the process with no line (status -2 / -15): the signals are blocked once the work is
    done and the last exit handler reports a pending one."""
    res = subprocess.run([sys.executable, "-c", AFTER_WORK.format(when=when, sig=sig)],
                         capture_output=True, text=True, timeout=120,
                         env=dict(os.environ, PYTHONPATH=str(SRC)))
    assert res.returncode == code, res.stderr
    assert res.stderr.strip() == f"rollingdisk: {word}", res.stderr
    assert res.stdout.startswith("stability thresholds")


FORKED = """
import multiprocessing, os, signal, sys
from rollingdisk.util.files import quiet_forked_children
# a signal in the child's first instant, before anything of its own runs
os.register_at_fork(after_in_child=lambda: os.kill(os.getpid(), signal.{sig}))
quiet_forked_children()
signal.signal(signal.SIGINT, signal.default_int_handler)
p = multiprocessing.get_context("fork").Process(target=print, args=("helper ran",))
p.start()
p.join(60)
print("exitcode", p.exitcode)
"""


@pytest.mark.skipif(not hasattr(os, "register_at_fork"), reason="no fork")
@pytest.mark.parametrize("sig, exitcode, ran", [("SIGINT", 0, True),
                                                ("SIGTERM", -15, False)])
def test_a_forked_helper_starts_with_no_handler_of_ours(sig, exitcode, ran):
    """atlas's animation helper printed a KeyboardInterrupt traceback when the signal
    reached it before it set its handlers: now it ignores SIGINT and dies quietly on
    SIGTERM from its first instant."""
    res = subprocess.run([sys.executable, "-c", FORKED.format(sig=sig)], capture_output=True,
                         text=True, timeout=120, env=dict(os.environ, PYTHONPATH=str(SRC)))
    assert res.returncode == 0 and res.stderr == "", res.stderr
    assert f"exitcode {exitcode}" in res.stdout
    assert ("helper ran" in res.stdout) == ran


def test_spawned_helpers_never_see_sigint_and_the_parent_keeps_it():
    """Spawned helpers (the toss's workers) start with SIGINT blocked; a Ctrl-C meanwhile
    is the parent's, delivered by the end of the block."""
    import signal
    import threading

    from rollingdisk.util.files import helpers_block_sigint

    got = []
    old = signal.signal(signal.SIGINT, lambda *a: got.append(a[0]))
    try:
        with helpers_block_sigint():
            child = subprocess.run([sys.executable, "-c", "import signal; print(int(signal."
                                    "SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, [])))"],
                                   capture_output=True, text=True, timeout=120)
            # aimed at this thread, which blocks it: pending until the block ends (a signal
            # to the process may go to another thread of the test run, and come later)
            signal.pthread_kill(threading.main_thread().ident, signal.SIGINT)
        assert got == [signal.SIGINT]
        assert signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, [])
    finally:
        signal.signal(signal.SIGINT, old)
    assert child.stdout.strip() == "1"


# -------------------------------------------------------------- item 7: the explorer
def _explorer(monkeypatch, threads=2, timeout=0.5):
    srv_mod = pytest.importorskip("rollingdisk.explore.server")
    monkeypatch.setattr(srv_mod, "MAX_THREADS", threads)
    monkeypatch.setattr(srv_mod._Handler, "timeout", timeout)
    srv = srv_mod.make_server(0.17, "rough", "127.0.0.1", 0)
    srv.start_in_thread()
    return srv


def _pool_threads():
    return sum("process_request_thread" in t.name for t in threading.enumerate())


def test_the_explorer_bounds_its_threads_and_lets_silent_clients_go(monkeypatch):
    """Half-sent requests held a thread each with no time limit (150 held 150): at most
    MAX_THREADS connections are served at once, a silent one is closed after the idle
    timeout, and the server then answers a whole request."""
    import socket
    import time
    import urllib.request

    srv = _explorer(monkeypatch)
    assert srv.request_queue_size >= 128
    port = srv.server_address[1]
    socks = []
    try:
        for _ in range(4):
            s = socket.create_connection(("127.0.0.1", port), timeout=60)
            s.sendall(b"GET /api/steady?h=0.1 HTTP/1.1\r\nHost: x")  # never finished
            socks.append(s)
        t = time.monotonic()
        while _pool_threads() < 2 and time.monotonic() - t < 60:
            time.sleep(0.01)
        assert _pool_threads() <= 2
        for s in socks:  # each is let go by the server: end of stream, or a reset
            try:
                assert s.recv(1024) == b""
            except ConnectionResetError:
                pass
        assert _pool_threads() <= 2
        with urllib.request.urlopen(f"http://127.0.0.1:{port}/explore.css",
                                    timeout=60) as r:
            assert r.status == 200
    finally:
        for s in socks:
            s.close()
        srv.shutdown()
        srv.server_close()


def test_a_client_that_leaves_early_puts_no_traceback_in_the_log(monkeypatch, capsys):
    srv = _explorer(monkeypatch)
    try:
        for exc in (BrokenPipeError(32, "Broken pipe"), ConnectionResetError(104, "reset")):
            try:
                raise exc
            except OSError:
                srv.handle_error(None, ("127.0.0.1", 5))
        assert capsys.readouterr().err == ""
        try:
            raise RuntimeError("a bug")
        except RuntimeError:
            srv.handle_error(None, ("127.0.0.1", 5))
        assert "RuntimeError: a bug" in capsys.readouterr().err
    finally:
        srv.shutdown()
        srv.server_close()


# ------------------------------------------------- item 8: no stray numeric warnings
@pytest.mark.filterwarnings("error")
@pytest.mark.parametrize("extra, status, says", [
    (["--alpha0", "1.5707"], "completed", "RuntimeWarning: invalid value encountered in sqrt"),
    (["--creep", "1e9a"], "failed", "UserWarning: lsoda: Repeated convergence failures"),
])
def test_euler_disk_on_extreme_values_says_its_warnings_in_the_result(capsys, extra, status,
                                                                       says):
    """Extreme but accepted values made numpy (euler_disk.py) and LSODA print warnings
    beside exit 0; the result now carries them ("warnings") and nothing is printed."""
    import json

    assert main(["euler-disk", *extra, "--quiet", "--json"]) == 0
    captured = capsys.readouterr()
    assert captured.err == ""
    rec = json.loads(captured.out)
    assert rec["status"] == status
    assert any(w.startswith(says) for w in rec["warnings"]), rec["warnings"]


@pytest.mark.filterwarnings("error")
def test_an_overflowing_uncompiled_run_fails_without_warnings(capsys):
    """omega3 = 1e150 on rough ground: the uncompiled DOP853 (pycore) warned of numpy's
    overflow before its status said the run failed; as compiled code, it now only fails."""
    import json

    assert main(["simulate", "--h", "0.1", "--ground", "rough", "--state",
                 "theta=0.3,omega3=1e150", "--t-end", "1", "--json"]) == 0
    captured = capsys.readouterr()
    assert captured.err == ""
    rec = json.loads(captured.out)
    assert rec["status"] == "failed" and "warnings" not in rec


def test_numeric_warnings_are_collected_once_and_others_left_alone():
    import warnings

    import numpy as np

    from rollingdisk.cli._format import numeric_warnings

    with warnings.catch_warnings(record=True) as outside:
        warnings.simplefilter("always")
        with numeric_warnings() as caught:
            for _ in range(3):
                np.sqrt(np.float64(-1.0))
            warnings.warn("old name", DeprecationWarning, stacklevel=1)
    assert caught.lines == ["RuntimeWarning: invalid value encountered in sqrt"]
    assert [w.category for w in outside] == [DeprecationWarning]


def test_a_reader_that_leaves_is_one_line_not_a_traceback():
    """``rollingdisk ... | head``: the output's reader gone before it is written (the read
    end closed first, so that the write fails whatever the timing) is one line, exit 2."""
    r, w = os.pipe()
    os.close(r)
    try:
        res = subprocess.run([sys.executable, "-m", "rollingdisk", "thresholds", "--h", "0.2"],
                             stdout=w, stderr=subprocess.PIPE, text=True, timeout=120,
                             env=dict(os.environ, PYTHONPATH=str(SRC)))
    finally:
        os.close(w)
    assert res.returncode == 2, res.stderr
    assert res.stderr.strip() == ("rollingdisk thresholds: error: the output was closed by "
                                  "its reader (a broken pipe)")


def test_a_coulomb_start_beyond_float_range_is_refused_by_the_api_too():
    """simulate_coulomb itself (not only the CLI) refuses a start whose equations are not
    finite, in one ParameterError and without a RuntimeWarning (was hybrid._Singular)."""
    import warnings

    import rollingdisk as rd

    ground = rd.Coulomb(0.5, air=rd.AirDrag(1.7e308))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(rd.ParameterError, match="not finite at the start"):
            rd.simulate_coulomb(rd.Disk(0.2), ground, (0, 1), [0, 0, 1, 0, 0, 0.3, 0, 0, 0, 2.0],
                                method="scipy")
