"""The sweep's store (issue 18 items 2, 5, 11; issue 19 item 3): one writer at a time,
an unreachable Dask scheduler refused quickly, resumed runs counted honestly, and
self-describing data (CF attributes, consolidated Zarr, labelled plots)."""

import os
import subprocess
import sys
import time
import types
import warnings
from pathlib import Path

import numpy as np
import pytest

from rollingdisk.util.errors import ParameterError

xr = pytest.importorskip("xarray")
sweep = pytest.importorskip("rollingdisk.sweep")
from rollingdisk.util import lock as _locks  # noqa: E402

SRC = Path(__file__).resolve().parents[1] / "src"

# A writer that stops after its first chunk until the test lets it go on.
WRITER = """
import sys, time
from pathlib import Path
from rollingdisk.sweep import SweepGrid, run_sweep
out, ready, go = map(Path, sys.argv[1:4])
def pause(done, total, rate, eta):
    if not ready.exists():
        ready.touch()
        t = time.time()
        while not go.exists() and time.time() - t < 120:
            time.sleep(0.02)
g = SweepGrid("rough", h=0.17, theta0=[0.3, 0.6, 0.9], omega30=[-4.0, -1.0, 2.0, 4.0])
run_sweep(g, 20.0, chunk=2, out=out, progress=pause)
"""


def _grid():
    return sweep.SweepGrid("rough", h=0.17, theta0=[0.3, 0.6, 0.9],
                           omega30=[-4.0, -1.0, 2.0, 4.0])


def _equal(a, b):
    assert set(a.data_vars) == set(b.data_vars)
    for k in a.data_vars:
        np.testing.assert_array_equal(a[k].values, b[k].values, err_msg=k)


def _wait_for(path: Path, proc, seconds=120.0):
    t = time.monotonic()
    while not path.exists():
        if proc.poll() is not None:
            raise AssertionError(f"writer ended early: {proc.communicate()}")
        assert time.monotonic() - t < seconds, "writer never got going"
        time.sleep(0.02)


def test_second_writer_is_refused_and_first_store_is_whole(tmp_path):
    """Issue 18 item 2: a second sweep into the same out with other arguments (t_end 21
    instead of 20) while the first runs is refused naming the first's pid; the first's
    store then holds only its own chunks (equal to the same sweep in memory)."""
    out = tmp_path / "c.zarr"
    ready, go = tmp_path / "ready", tmp_path / "go"
    env = dict(os.environ, PYTHONPATH=str(SRC))
    first = subprocess.Popen([sys.executable, "-c", WRITER, str(out), str(ready), str(go)],
                             env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        _wait_for(ready, first)
        with pytest.raises(ParameterError, match=rf"another process \(pid {first.pid}\)"):
            sweep.run_sweep(_grid(), 21.0, chunk=2, out=out)
        assert (tmp_path / "c.zarr.partial" / "chunk_000000.npz").exists()  # left alone
    finally:
        go.touch()
        _, err = first.communicate(timeout=300)
    assert first.returncode == 0, err.decode()
    ds = sweep.open_sweep(out)
    assert ds.attrs["t_end_requested"] == 20.0
    assert ds.attrs["spec"] == sweep.run_sweep(_grid(), 20.0, chunk=2).attrs["spec"]
    _equal(ds, sweep.run_sweep(_grid(), 20.0, chunk=2))
    assert not (tmp_path / "c.zarr.partial").exists()


def _dead_pid() -> int:
    p = subprocess.Popen([sys.executable, "-c", "pass"])
    p.wait()
    return p.pid


def test_stale_lock_of_a_dead_process_is_taken_over(tmp_path):
    out = tmp_path / "s.zarr"
    (tmp_path / "s.zarr.partial").mkdir()
    (tmp_path / "s.zarr.partial" / "lock").write_text(f"{_dead_pid()}\n")
    ds = sweep.run_sweep(_grid(), 5.0, out=out)
    assert out.is_dir() and ds.attrs["n_computed"] == 12
    assert not (tmp_path / "s.zarr.partial").exists()


def test_pid_lock_without_fcntl(tmp_path, monkeypatch):
    """Where fcntl is missing the lock file's pid decides: a live owner refuses, a dead
    one's lock is taken over."""
    monkeypatch.setattr(_locks, "fcntl", None)
    out = tmp_path / "s.nc"
    partial = tmp_path / "s.nc.partial"
    partial.mkdir()
    (partial / "lock").write_text(f"{os.getppid()}\n")  # alive: the test runner's parent
    with pytest.raises(ParameterError, match=rf"pid {os.getppid()}"):
        sweep.run_sweep(_grid(), 5.0, out=out)
    (partial / "lock").write_text(f"{_dead_pid()}\n")
    sweep.run_sweep(_grid(), 5.0, out=out)
    assert out.is_file() and not partial.exists()


def test_unreachable_dask_scheduler_is_a_parameter_error(tmp_path, monkeypatch):
    """Issue 18 item 5: a scheduler that does not answer is refused by name within the
    connection timeout, and no partial folder is left."""
    pytest.importorskip("dask.distributed")
    from rollingdisk.sweep import executors

    monkeypatch.setattr(executors, "CONNECT_TIMEOUT", 1.0)
    out = tmp_path / "d.zarr"
    with pytest.raises(ParameterError, match=r"tcp://127\.0\.0\.1:1"):
        sweep.run_sweep(_grid(), 5.0, out=out, executor="dask",
                        dask_address="tcp://127.0.0.1:1")
    assert sorted(os.listdir(tmp_path)) == []


def test_resumed_sweep_counts_only_what_it_computed(tmp_path, monkeypatch):
    """Issue 18 item 11: resumed chunks are not counted as computed, neither in the
    progress rate (on a clock that ticks once per reading) nor in ``n_computed``."""
    from rollingdisk.sweep import runner

    g = _grid()  # 12 points: chunks of 5, 5, 2
    out = tmp_path / "r.zarr"

    def stop(done, total, rate, eta):
        if done == 5:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        sweep.run_sweep(g, 5.0, chunk=5, out=out, progress=stop)
    ticks = iter(range(1000))
    monkeypatch.setattr(runner, "time", types.SimpleNamespace(
        perf_counter=lambda: float(next(ticks))))
    seen = []
    ds = sweep.run_sweep(g, 5.0, chunk=5, out=out, progress=lambda *a: seen.append(a))
    # clock: 0 at the start, 1 after chunk 1 (5 computed), 2 after chunk 2 (7 computed)
    assert seen == [(10, 12, 5.0, 2 / 5.0), (12, 12, 3.5, 0.0)]
    assert ds.attrs["n_computed"] == 7
    assert sweep.open_sweep(out).attrs["n_computed"] == 7
    assert sweep.run_sweep(g, 5.0, chunk=5).attrs["n_computed"] == 12


def test_basin_counts_only_integrated_trajectories():
    g = sweep.SweepGrid("rough", h=0.17, theta0=[0.6], omega30=[0.0, 4.0])  # 0: no circle
    b = sweep.basin_sweep(g, 5.0, kick_max=0.5, rounds=2)
    assert b.attrs["n_computed"] == 3  # one steady motion, three rounds


def _described(ds):
    for name, var in ds.variables.items():
        if name in ds.dims and name not in ds.coords:
            continue
        assert var.attrs.get("long_name"), name
        assert var.attrs.get("units"), name


def test_every_variable_is_described_and_status_is_a_cf_flag(tmp_path):
    """Issue 19 item 3: long_name and units on every variable and coordinate; the integer
    variables are CF flags whose meanings are the outcome names; plain ``xr.open_zarr``
    reads the store without a warning (consolidated metadata)."""
    from rollingdisk.model.outcomes import OUTCOMES

    g = sweep.SweepGrid("rough", h=0.17, theta0=[0.3, 0.9], omega30=[-4.0, 0.0, 4.0])
    out = tmp_path / "s.zarr"
    sweep.run_sweep(g, 5.0, out=out, perturbation=sweep.Perturbation(kick=[1e-3, 2e-3]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ds = xr.open_zarr(out).load()
    _described(ds)
    assert ds.t_end.attrs["units"] == "sqrt(a/g)" and ds.theta0.attrs["units"] == "rad"
    assert ds.energy_drift.attrs["units"] == "1"
    codes = {o.code: o.name.replace("-", "_") for o in OUTCOMES}
    for name in ("status", "stable", "stable_simulated"):
        values = list(ds[name].attrs["flag_values"])
        meanings = ds[name].attrs["flag_meanings"].split(" ")
        assert len(values) == len(meanings) and " " not in "".join(meanings)
        assert set(np.unique(ds[name].values)) <= set(values), name
    st = ds.status.attrs
    assert st["flag_meanings"].split() == [codes[int(c)] for c in st["flag_values"]]
    assert set(np.unique(ds.status.values)) >= {10}  # omega30 = 0: no-steady-motion
    basin = sweep.basin_sweep(g, 5.0, kick_max=0.5, rounds=1)
    _described(basin)


def test_plots_label_their_axes_with_long_name_and_units():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ds = sweep.run_sweep(sweep.SweepGrid("rough", h=0.17, theta0=[0.3, 0.6, 0.9],
                                         omega30=[-4.0, 2.0, 4.0]), 5.0)
    def labels_hold(label, var):
        return var.attrs["long_name"] in label and f"[{var.attrs['units']}]" in label

    for data in (ds.stable_simulated, ds.stable_simulated.isel(h=0, amplitude=0)):
        fig, ax = plt.subplots()
        mesh = data.plot(ax=ax)  # size-1 dims squeezed: a map over (theta0, omega30)
        assert labels_hold(ax.get_xlabel(), ds.omega30)
        assert labels_hold(ax.get_ylabel(), ds.theta0)
        assert labels_hold(mesh.colorbar.ax.get_ylabel(), ds.stable_simulated)
        plt.close(fig)
    fig, ax = plt.subplots()
    ds.frequency.isel(theta0=0).plot(ax=ax, hue="h")  # a line over omega30
    assert labels_hold(ax.get_xlabel(), ds.omega30) and labels_hold(ax.get_ylabel(),
                                                                      ds.frequency)
    plt.close(fig)
