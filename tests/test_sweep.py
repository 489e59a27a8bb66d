"""Sweeps (issue 12): summaries against closed forms and conservation, identical results
whichever executor runs them, atomic store and resume."""

import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.util.errors import ParameterError

sweep = pytest.importorskip("rollingdisk.sweep")


def _small(ground="rough"):
    return sweep.SweepGrid(ground, h=0.17, theta0=np.linspace(0.3, 1.2, 4),
                           omega30=np.linspace(-5.0, 5.0, 5))


def _equal(a, b):
    assert set(a.data_vars) == set(b.data_vars)
    for k in a.data_vars:
        np.testing.assert_array_equal(a[k].values, b[k].values, err_msg=k)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_summaries_match_closed_form(ground):
    """Measured frequency = sqrt(varpi2) of eq. (45)/(55); stable_simulated = sign."""
    ds = sweep.run_sweep(_small(ground), 60.0)
    v = ds.varpi2.values
    assert np.all(np.isnan(v[..., 2, :]))  # omega30 = 0: no circle
    m = np.abs(v) > 0.05
    np.testing.assert_array_equal(ds.stable_simulated.values[m], ds.stable.values[m])
    s = m & (v > 0)
    f = ds.frequency.values[s]
    np.testing.assert_allclose(f, np.sqrt(v[s]), rtol=2e-2)
    # growth: kicked saddle d = K sinh(s t)/s, log-slope between 2K and 10K within 10 % of s
    un = sweep.run_sweep(sweep.SweepGrid(ground, h=0.17, theta0=[0.3], omega30=[0.3]), 30.0)
    s_ = math.sqrt(-float(un.varpi2.values.ravel()[0]))
    assert un.stable_simulated.values.ravel()[0] == 0
    assert math.isclose(float(un.growth_rate.values.ravel()[0]), s_, rel_tol=0.1)
    assert np.nanmax(ds.energy_drift.values[s]) < 1e-7


def test_reduced_energy_is_rollingdisk_energy():
    """The energy kept along a run is rollingdisk.energy of the full rough state."""
    from rollingdisk.sweep import batch as core

    y = np.array([0.1, -0.2, 0.0, 0.4, 0.3, 0.5, -1.2, 2.0])  # X, Y, psi, theta, phi, w1..3
    x = y[[3, 5, 6, 7]]
    e = core._reduced_energy(True, 0.17, rd.Disk(0.17).k1_sq, 0.5, x)
    assert math.isclose(e, rd.energy(rd.Disk(0.17), "rough", y), rel_tol=1e-14)


def test_executors_identical_and_resume(tmp_path):
    g = _small()
    serial = sweep.run_sweep(g, 30.0, chunk=7)
    threads = sweep.run_sweep(g, 30.0, chunk=3, executor="threads", workers=2)
    _equal(serial, threads)
    out = tmp_path / "s.zarr"
    calls = []

    def stop(done, total, rate, eta):
        calls.append(done)
        if len(calls) == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        sweep.run_sweep(g, 30.0, chunk=7, out=out, progress=stop)
    assert not out.exists()
    partial = tmp_path / "s.zarr.partial"
    before = {p.name: p.stat().st_mtime_ns for p in partial.glob("chunk_*.npz")}
    assert len(before) == 2
    seen = []
    ds = sweep.run_sweep(g, 30.0, chunk=7, out=out, progress=lambda *a: seen.append(a[0]))
    assert seen[0] == 14 + 6 and seen[-1] == 20  # 2 chunks of 7 kept, 1 of 6 computed
    assert not partial.exists()
    _equal(serial, ds)
    _equal(serial, sweep.open_sweep(out))


@pytest.mark.slow
def test_dask_identical():
    pytest.importorskip("dask.distributed")
    g = _small()
    _equal(sweep.run_sweep(g, 30.0, chunk=7),
           sweep.run_sweep(g, 30.0, chunk=7, executor="dask", workers=2))


def test_rC_grid_and_basin():
    g = sweep.SweepGrid("rough", h=0.17, theta0=[0.5, 1.0], r_C=[0.5, 2.0])
    ds = sweep.run_sweep(g, 20.0)
    om2 = rd.Omega0_sq(0.17, np.array([0.5, 1.0])[:, None], np.array([0.5, 2.0]))
    assert np.array_equal(np.isnan(ds.varpi2.values[0, :, :, 0]), ~(om2 > 0))
    b = sweep.basin_sweep(sweep.SweepGrid("rough", h=0.17, theta0=[0.6], omega30=[-4.0, 4.0]),
                          20.0, kick_max=0.5, rounds=3)
    assert b.kick_basin.shape == (1, 1, 2)
    assert np.all((b.kick_basin.values >= 0) & (b.kick_basin.values <= 0.5))


@pytest.mark.parametrize("ground, threshold", [("rough", 1 / 3), ("smooth", 1.0)])
def test_straight_line_grid(ground, threshold):
    # an upright thin disk rolling at omega0 is stable iff omega0^2 > 1/3 on rough ground
    # (the classic v^2 > g a / 3) and omega0^2 > I1/I3^2 = 1 on smooth ground (the
    # gyroscopic term (I3 omega0)^2/I1 must beat the toppling moment m g a)
    w = np.array([0.3, 0.45, 0.7, 0.9, 1.2, 2.0, 3.0])
    g = sweep.SweepGrid(ground, h=(0.0, 0.5), omega0=w)
    assert g.shape == (2, w.size) and g.dims == ("h", "omega0")
    ds = sweep.run_sweep(g, 100.0)
    assert ds.varpi2.dims == ("h", "omega0", "amplitude")
    assert np.allclose(ds.theta0.values, np.arctan([0.0, 0.5]))
    assert np.array_equal(ds.stable.values[0, :, 0], (w**2 > threshold).astype(np.int8))
    m = np.abs(ds.varpi2.values) > 0.05
    assert m.sum() >= 10
    assert np.array_equal(ds.stable_simulated.values[m], ds.stable.values[m])
    b = sweep.basin_sweep(g, 20.0, kick_max=0.3, rounds=2)
    assert b.kick_basin.dims == ("h", "omega0")


def test_bad_input():
    with pytest.raises(ParameterError, match="theta0"):
        sweep.SweepGrid("rough", theta0=[0.5], omega0=[1.0])
    with pytest.raises(ParameterError):
        sweep.SweepGrid("icy", theta0=[0.5], omega30=[1.0])
    with pytest.raises(ParameterError):
        sweep.SweepGrid("rough", theta0=[0.5], omega30=[1.0], Omega0=[1.0])
    with pytest.raises(ParameterError):
        sweep.SweepGrid("smooth", theta0=[0.5], r_C=[1.0])
    with pytest.raises(ParameterError):
        sweep.Perturbation(kick=0.0, tilt=0.0)
    with pytest.raises(ParameterError):
        sweep.run_sweep(_small(), 10.0, out="x.csv")


@pytest.mark.slow
@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_agreement_60x60(ground):
    """Issue 12: >= 99.5 % agreement with the sign of varpi2 where |varpi2| > 0.05."""
    g = sweep.SweepGrid(ground, h=0.17, theta0=np.linspace(-1.4, 1.4, 60),
                        omega30=np.linspace(-6.0, 6.0, 60))
    ds = sweep.run_sweep(g, 200.0, executor="threads")
    m = np.abs(ds.varpi2.values) > 0.05
    agree = np.mean(ds.stable_simulated.values[m] == ds.stable.values[m])
    assert agree >= 0.995


def test_basin_sweep_resumes_after_the_last_finished_round(tmp_path):
    """A basin sweep stopped after round 2 resumes at round 3 (no finished round redone)
    and ends with the uninterrupted result; the partial folder goes at the end."""
    g = sweep.SweepGrid("rough", h=0.17, theta0=[0.4, 0.9], omega30=[1.0, 3.0])
    whole = sweep.basin_sweep(g, 20.0, kick_max=0.6, rounds=4)
    out = tmp_path / "b.nc"
    calls = []

    def stop(done, total, rate, eta):
        calls.append(done)
        if done == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        sweep.basin_sweep(g, 20.0, kick_max=0.6, rounds=4, out=out, progress=stop)
    assert not out.exists()
    assert sorted(p.name for p in (tmp_path / "b.nc.partial").glob("round_*")) == \
        ["round_000.npz", "round_001.npz"]
    seen = []
    ds = sweep.basin_sweep(g, 20.0, kick_max=0.6, rounds=4, out=out,
                           progress=lambda *a: seen.append(a[0]))
    assert seen == [3, 4, 5]
    assert not (tmp_path / "b.nc.partial").exists()
    np.testing.assert_array_equal(ds.kick_basin.values, whole.kick_basin.values)
    np.testing.assert_array_equal(sweep.open_sweep(out).kick_basin.values,
                                  whole.kick_basin.values)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
@pytest.mark.parametrize("second", ["omega30", "Omega0"])
def test_grid_setup_is_steady_motion_and_stability_point_by_point(ground, second):
    """The element-wise set-up of circles (eqs. 3, 28/34, 40/51 on whole chunks) against
    rollingdisk.steady_motion and rollingdisk.stability called at every point; NaN exactly
    where they refuse (Omega0 = 0; theta0 = 0 with h > 0)."""
    from rollingdisk.theory import oscillations as _stability

    g = sweep.SweepGrid(ground, h=(0.0, 0.17), theta0=np.linspace(-1.4, 1.4, 9),
                        **{second: np.linspace(-6.0, 6.0, 9)})
    from rollingdisk.sweep.grid import _setup, _Spec

    spec = _Spec(g, sweep.Perturbation(kick=2e-3, tilt=1e-3), 10.0, 1e-9, 1e-9, 1000, 64, 162)
    x0, h, th, varpi2, stable, a0 = _setup(spec, 0, spec.n)
    vals = np.asarray(getattr(g, second))
    for j, (ih, it, iv) in enumerate(np.ndindex(g.shape)):
        hh, t0, v = g.h[ih], g.theta0[it], vals[iv]
        assert h[j] == hh and th[j] == t0
        Omega0 = v / math.cos(t0) if second == "omega30" else v
        try:
            m = rd.steady_motion(rd.Disk(hh), ground, t0, Omega0=Omega0)
        except ValueError:
            assert np.all(np.isnan(x0[j])) and np.isnan(varpi2[j]) and stable[j] == -1
            continue
        np.testing.assert_allclose(x0[j], [t0 + 1e-3, 2e-3, m.omega20, m.omega30], rtol=1e-12,
                                   atol=1e-12)
        w = _stability.stability(m).varpi2
        assert math.isclose(varpi2[j], w, rel_tol=1e-10, abs_tol=1e-10)
        assert stable[j] == (1 if w > 0 else 0)
