"""``rollingdisk simulate``: the CLI over simulate() (tests call main() directly)."""

from __future__ import annotations

import csv
import io
import json
import math
import os

import numpy as np
import pytest

from rollingdisk import Disk, energy_drift, simulate
from rollingdisk.cli.app import main
from rollingdisk.util.progress import ProgressBar as _ProgressBar

STATE = "theta=0.3,omega2=2.0,omega3=0.5"
COLUMNS = ["t", "X_C", "Y_C", "psi", "theta", "phi", "omega1", "omega2", "omega3", "X_P",
           "Y_P", "F_x", "F_y", "F_z", "E"]


def run_json(capsys, *argv):
    assert main(["simulate", *argv, "--json"]) == 0
    out, err = capsys.readouterr()
    assert err == ""  # no progress bar with --json
    return json.loads(out)


def test_json_from_an_arbitrary_state(capsys):
    rec = run_json(capsys, "--h", "0.1", "--state", STATE, "--t-end", "20", "--method",
                   "dop853")
    for key in ("status", "message", "t_end", "n_steps", "energy_drift", "theta_min",
                "theta_max", "theta_frequency", "varpi", "wall_time_s"):
        assert key in rec
    assert rec["status"] == "completed" and rec["t_end"] == 20.0
    assert rec["varpi"] is None  # no steady motion to predict from
    tr = simulate(Disk(h=0.1), "rough", (0, 20), [0, 0, 0, 0.3, 0, 0, 2.0, 0.5],
                  method="dop853")
    assert rec["n_steps"] == tr.n_steps
    assert rec["energy_drift"] == pytest.approx(energy_drift(tr), rel=1e-6, abs=1e-15)
    assert rec["theta_min"] == pytest.approx(tr.theta.min())
    assert rec["theta_max"] == pytest.approx(tr.theta.max())
    assert rec["theta_frequency"] > 0
    assert 0 <= rec["wall_time_s"] < float("inf")  # reported; speed is measured in benchmarks/


def test_state_angles_in_degrees_and_smooth_ground(capsys):
    rec = run_json(capsys, "--ground", "smooth", "--h", "0.2", "--state",
                   "theta=30deg,omega2=1.0,omega3=2.0,V_X=0.5", "--t-end", "5")
    assert rec["status"] == "completed" and rec["ground"] == "smooth"
    assert rec["theta_max"] >= math.radians(30) - 1e-12


def test_guard_event_is_reported(capsys):
    rec = run_json(capsys, "--h", "0.2", "--state", "theta=0.1,omega1=-0.5,omega2=1",
                   "--t-end", "20")
    assert rec["status"] == "edge-contact" and rec["t_end"] < 1
    assert "edge" in rec["message"]


def test_csv_output(tmp_path, capsys):
    out = tmp_path / "traj.csv"
    assert main(["simulate", "--h", "0.1", "--state", STATE, "--t-end", "5", "--out",
                 str(out), "--method", "dop853"]) == 0
    text = capsys.readouterr().out
    assert "completed" in text and str(out) in text
    with open(out, newline="") as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == COLUMNS
    data = np.array(rows[1:], dtype=float)
    # without --json the run reports progress; it takes the steps of a plain run all the same
    tr = simulate(Disk(h=0.1), "rough", (0, 5), [0, 0, 0, 0.3, 0, 0, 2.0, 0.5],
                  method="dop853")
    assert data.shape == (tr.t.size, len(COLUMNS))
    np.testing.assert_allclose(data[:, COLUMNS.index("F_z")], tr.F_z, rtol=1e-8, atol=1e-10)
    np.testing.assert_allclose(data[:, -1], tr.E, rtol=1e-12)
    assert sorted(os.listdir(tmp_path)) == ["traj.csv"]  # no temporary left behind


def test_csv_is_not_left_half_written(tmp_path, monkeypatch):
    out = tmp_path / "traj.csv"

    def boom(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(np, "savetxt", boom)
    assert main(["simulate", "--h", "0.1", "--state", STATE, "--t-end", "1", "--out",
                 str(out)]) == 130
    assert os.listdir(tmp_path) == []


def test_progress_bar_draws_on_stderr():
    buf = io.StringIO()
    bar = _ProgressBar(buf, delay=0.0, width=10)
    for f in (0.0, 0.5, 1.0):
        bar(f)
    bar.close()
    text = buf.getvalue()
    assert "[#####.....]" in text and "100.0%" in text and text.endswith("\n")
    quiet = io.StringIO()
    bar = _ProgressBar(quiet, delay=60.0)
    bar(0.5)
    bar.close()
    assert quiet.getvalue() == ""


@pytest.mark.parametrize("argv,match", [
    (["--h", "0.1", "--t-end", "5"], "--theta0"),
    (["--h", "0.1", "--state", "theta=0.3,omega9=1", "--t-end", "5"], "omega9"),
    (["--h", "0.1", "--state", "omega2=1", "--t-end", "5"], "theta"),
    (["--h", "0.1", "--state", "theta=abc", "--t-end", "5"], "theta"),
    (["--h", "0.1", "--state", "theta=0.3", "--theta0", "0.3", "--t-end", "5"], "--state"),
    (["--h", "0.1", "--state", "theta=0.3", "--t-end", "-5"], "t_end"),
    (["--h", "0.1", "--state", "theta=0.3", "--t-end", "5", "--rtol", "0"], "rtol"),
    (["--h", "-1", "--state", "theta=0.3", "--t-end", "5"], "h"),
    (["--h", "0.1", "--state", "theta=0.3", "--t-end", "5", "--out", "/nonexistent/x.csv"],
     "no such folder"),
])
def test_bad_input_exits_2_with_one_line(capsys, argv, match):
    assert main(["simulate", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and match in err


# ---------------------------------------------------------------------------- steady starts
def test_perturbed_steady_circle_oscillates_at_varpi(capsys):
    rec = run_json(capsys, "--h", "0.1", "--theta0", "0.3", "--Omega0", "2", "--perturb",
                   "1e-7", "--t-end", "200")
    assert rec["status"] == "completed"
    assert rec["theta_frequency"] == pytest.approx(rec["varpi"], rel=1e-6)


def test_straight_line_start(capsys):
    rec = run_json(capsys, "--h", "0.1", "--motion", "straight", "--omega0", "2", "--perturb",
                   "1e-7", "--t-end", "100")
    assert rec["status"] == "completed"
    assert abs(rec["theta_max"] - math.atan(0.1)) < 1e-5


def test_unstable_circle_reports_its_growth_rate(capsys):
    rec = run_json(capsys, "--h", "0.3", "--theta0", "0.3", "--rC", "2", "--perturb", "1e-9",
                   "--t-end", "60")
    assert rec["varpi2"] < 0 and rec["varpi"] is None
    assert rec["growth_rate"] == pytest.approx(math.sqrt(-rec["varpi2"]), rel=1e-3)


# ---------------------------------------------------------------------------- issue 8
@pytest.fixture(scope="module")
def compiled_cache():
    """The compile cache filled first (``python -m rollingdisk.engine.jit``, as the docs
    say to do up front): these tests time the stop of a run in the compiled loop, and a
    compilation in progress (up to a minute on a cold cache) does not see a signal until
    it returns."""
    import subprocess
    import sys

    import rollingdisk

    src = os.path.dirname(os.path.dirname(rollingdisk.__file__))
    subprocess.run([sys.executable, "-m", "rollingdisk.engine.jit"], check=True,
                   capture_output=True, timeout=1800, env=dict(os.environ, PYTHONPATH=src))


def _interrupt(tmp_path, sig, *extra):
    import signal
    import subprocess
    import sys
    import time

    import rollingdisk

    src = os.path.dirname(os.path.dirname(rollingdisk.__file__))
    cmd = [sys.executable, "-m", "rollingdisk", "simulate", "--h", "0.17", "--theta0", "0.5",
           "--Omega0", "2", "--perturb", "0.01", "--t-end", "1e6", *extra]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         cwd=tmp_path, env=dict(os.environ, PYTHONPATH=src))
    time.sleep(2.0)
    p.send_signal(getattr(signal, sig))
    t = time.monotonic()
    out, err = p.communicate(timeout=600)
    return p.returncode, time.monotonic() - t, out, err


@pytest.mark.parametrize("sig,code,word,extra", [
    ("SIGINT", 130, "interrupted", ("--json", "--out", "run.csv")),
    pytest.param("SIGTERM", 143, "terminated", ("--json", "--out", "run.csv"),
                 marks=pytest.mark.slow),
    pytest.param("SIGINT", 130, "interrupted", ("--out", "run.csv"), marks=pytest.mark.slow),
    pytest.param("SIGTERM", 143, "terminated", (), marks=pytest.mark.slow),
    pytest.param("SIGINT", 130, "interrupted", ("--method", "scipy", "--json"),
                 marks=pytest.mark.slow),
])
def test_a_signal_during_simulate_ends_cleanly(compiled_cache, tmp_path, sig, code, word,
                                                extra):
    # once SystemError: CPUDispatcher(...) returned a result with an exception set, or the
    # signal waited for the end of the compiled loop; SIGTERM left a .tmp file behind
    rc, dt, out, err = _interrupt(tmp_path, sig, *extra)
    # it stops at the next check, not at the end of a 1e6-unit run: 60 s is a guard against
    # waiting for the end, wide enough for a loaded machine (a check is milliseconds apart)
    assert rc == code and dt < 60.0, (rc, dt, err)
    last = err.replace("\r", "\n").strip().splitlines()[-1]
    assert last == f"rollingdisk: {word}" and "Traceback" not in err
    if "--json" in extra:
        assert err.strip() == last  # the one line on stderr
    assert os.listdir(tmp_path) == []  # no partial CSV, no temporary left


@pytest.mark.skipif(os.geteuid() == 0, reason="root may write a read-only file")
def test_simulate_refuses_a_read_only_out_before_the_work(tmp_path, capsys):
    path = tmp_path / "ro.csv"
    path.write_text("keep")
    path.chmod(0o444)
    assert main(["simulate", "--h", "0.1", "--theta0", "0.3", "--Omega0", "3", "--t-end", "1",
                 "--out", str(path)]) == 2
    assert "read-only" in capsys.readouterr().err and path.read_text() == "keep"


def test_simulate_json_is_strict_and_a_step_budget_is_a_status(capsys):
    rec = run_json(capsys, "--h", "0.1", "--theta0", "0.3", "--Omega0", "3",
                   "--t-end", "1000", "--max-steps", "50")
    assert rec["status"] == "step-budget" and rec["n_steps"] == 50
    assert main(["simulate", "--h", "0.1", "--theta0", "0.3", "--Omega0", "3", "--t-end", "1",
                 "--kick=1e300", "--json"]) == 2
    assert "too large" in capsys.readouterr().err


def test_simulate_out_streams_the_same_csv_as_the_trajectory(tmp_path, capsys):
    path = tmp_path / "a.csv"
    assert main(["simulate", "--h", "0.1", "--theta0", "0.3", "--Omega0", "3", "--t-end", "5",
                 "--out", str(path), "--json", "--method", "dop853"]) == 0
    rows = np.loadtxt(path, delimiter=",", skiprows=1)
    from rollingdisk import simulate_steady, stability, steady_motion

    m = steady_motion(Disk(h=0.1), "rough", 0.3, Omega0=3.0)
    # a steady start: the CLI samples the dense output every 1/20 of 1/|varpi| (for the
    # measured frequency) and at t_end
    dt = 0.05 / math.sqrt(abs(stability(m).varpi2))
    t_eval = np.append(np.arange(0.0, 5.0, dt), 5.0)
    tr = simulate_steady(m, 5.0, method="dop853", t_eval=t_eval)
    assert np.array_equal(rows[:, 0], tr.t) and np.array_equal(rows[:, 0], t_eval)
    assert np.array_equal(rows[:, 4], tr.theta)
    assert oct(path.stat().st_mode & 0o777) == oct(0o666 & ~_umask())


def _umask():
    m = os.umask(0)
    os.umask(m)
    return m
