"""Library functions that the command line used to hold: stream measurements, the sweep's
agreement, the map sweeps, Euler's disk files, the progress bar; and the two library fixes
found by the CLI's robustness sweep (subnormal Omega0, the Coulomb interpolant)."""

from __future__ import annotations

import io
import json
import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.results.stream import StreamSummary, write_columns
from rollingdisk.util.progress import ProgressBar


def test_stream_summary_measures_what_the_whole_run_measures():
    """Streamed in chunks, the running measures equal those of the stored trajectory."""
    m = rd.steady_motion(rd.Disk(h=0.1), "rough", 0.3, Omega0=3.0)
    whole = rd.simulate_steady(m, 20.0, kick=0.05)
    buf = io.StringIO()
    s = StreamSummary(m.disk, "rough", buf, keep=50)
    streamed = rd.simulate_steady(m, 20.0, kick=0.05, sink=s)
    assert s.n_seen == whole.t.size and s.n_kept == 50
    assert s.energy_drift() == pytest.approx(rd.energy_drift(whole), rel=1e-12, abs=1e-18)
    assert s.theta_min == whole.theta.min() and s.theta_max == whole.theta.max()
    assert np.array_equal(s.kept(streamed).t, whole.t[:50])
    rows = np.loadtxt(io.StringIO(buf.getvalue()), delimiter=",", skiprows=1)
    assert np.array_equal(rows[:, 0], whole.t)  # %.17g round-trips every float
    assert buf.getvalue().count("t,") == 1  # one header


def test_write_columns_round_trips():
    buf = io.StringIO()
    cols = {"a": [0.1, 1 / 3], "b": [math.pi, -2.0]}
    write_columns(buf, cols)
    back = np.genfromtxt(io.StringIO(buf.getvalue()), delimiter=",", names=True)
    assert back["a"].tolist() == cols["a"] and back["b"].tolist() == cols["b"]


def test_progress_bar_takes_every_shape_and_can_be_quiet():
    buf = io.StringIO()
    bar = ProgressBar(buf, label="x", delay=0.0, width=4)
    bar(0.5)
    bar(1, 4)
    bar(2, 4, 10.0, 0.2)
    bar.note("a note")
    bar(4, 4, float("nan"), float("nan"))
    bar.close()
    text = buf.getvalue()
    assert "x [##..]  50.0%" in text and "1/4" in text and "(10/s, ETA 0 s)" in text
    assert "\na note\n" in text and text.endswith("100.0% 4/4\n")
    quiet = io.StringIO()
    q = ProgressBar(quiet, delay=0.0, quiet=True)
    q(0.5)
    q.note("x")
    q.close()
    assert quiet.getvalue() == ""


def test_stability_agreement_counts_far_points_only():
    xr = pytest.importorskip("xarray")
    from rollingdisk.sweep.summary import stability_agreement

    ds = xr.Dataset({"varpi2": ("i", [2.0, -3.0, 0.01, 1.0]),
                     "stable": ("i", [True, False, True, True]),
                     "stable_simulated": ("i", [True, False, False, False])})
    assert stability_agreement(ds) == pytest.approx(2 / 3)
    assert stability_agreement(ds, margin=5.0) is None
    assert stability_agreement(ds.drop_vars("stable_simulated")) is None


@pytest.mark.slow
def test_map_sweep_agrees_with_the_closed_form():
    pytest.importorskip("xarray")
    from rollingdisk.sweep.maps import MAP_OMEGA30, MAP_THETA0, map_sweep
    from rollingdisk.sweep.summary import stability_agreement

    ds = map_sweep("rough", 0.17, "nonlinear", n=3, t_end=30.0)
    assert ds.varpi2.size == 9
    assert float(ds.theta0.min()) == MAP_THETA0[0] and float(ds.omega30.max()) == MAP_OMEGA30[1]
    want = rd.varpi2_circle(0.17, "rough", float(ds.theta0[1]), float(ds.omega30[2]))
    got = ds.varpi2.sel(theta0=ds.theta0[1], omega30=ds.omega30[2]).values.ravel()
    assert got.size == 1 and got[0] == pytest.approx(want, rel=1e-12)
    assert stability_agreement(ds, margin=0.05) == 1.0
    with pytest.raises(ValueError, match="kind"):
        map_sweep("rough", 0.17, "other")


@pytest.mark.slow  # a whole Euler run, about 9 s (the CLI tests cover the writer fast)
def test_write_euler_disk_folder(tmp_path):
    from rollingdisk.plotting.reports import EULER_DISK_FILES, write_euler_disk
    from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk

    result = run_euler_disk(EulerDisk(alpha0=0.05))
    out = write_euler_disk(result, tmp_path / "ed")
    assert sorted(p.name for p in out.iterdir()) == sorted(EULER_DISK_FILES)
    assert json.loads((out / "euler_disk.json").read_text()) == json.loads(
        json.dumps(result.summary()))
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("keep")
    with pytest.raises(ValueError, match="notes.txt"):
        write_euler_disk(result, tmp_path / "mine")


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_subnormal_Omega0_is_no_steady_motion_not_a_crash(ground):  # noqa: N802
    with pytest.raises(ValueError, match="Omega0"):
        rd.steady_motion(rd.Disk(h=0.17), ground, 0.5, Omega0=4e-324)


def test_smooth_omega20_keeps_eq_34_for_small_spin():
    """The reordered division of eq. (34) is still eq. (34): spin on the SE tilt, where
    omega20 = k1 tan(theta0) omega30 / k2 is finite for any tiny omega30."""
    h = 0.3
    theta = math.atan(h)  # static equilibrium: y_P = 0 (eq. 16)
    m = rd.steady_motion(rd.Disk(h=h), "smooth", theta, Omega0=1e-200)
    k1, k2 = 0.25 + h * h / 3.0, 0.5
    assert m.omega20 == pytest.approx(k1 * math.tan(theta) * m.omega30 / k2, rel=1e-12)


def test_coulomb_run_at_a_loose_tolerance_ends_with_a_status():
    """At rtol 0.5 the interpolant of a step leaves floating-point range: a status, not a
    private exception."""
    m = rd.steady_motion(rd.Disk(h=0.5), "rough", math.radians(45), Omega0=0.5)
    from rollingdisk.ivp.hybrid import simulate_coulomb
    from rollingdisk.model.coulomb import rolling_state

    y0 = list(rolling_state(m.disk, m.initial_state()))
    y0[6] += 0.01
    tr = simulate_coulomb(m.disk, rd.Coulomb(1.0, 0.15), (0.0, 5.0), y0, rtol=0.5)
    assert tr.status in ("completed", "failed", "lift-off", "fell-flat", "edge-contact")
