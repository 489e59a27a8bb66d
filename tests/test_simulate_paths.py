"""The two ways of running the one DOP853 source (issue 9): uncompiled and compiled.

The uncompiled run (rollingdisk.engine.pycore) must take the steps of the compiled one
(rollingdisk.engine.numba_core), a run may switch between them mid-way without changing its
steps, the coefficients are scipy's own table, and a cold compile cache is filled by one
background compiler at a time.  Also: error_control="reduced" keeps the accuracy the
full-state tests ask for.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys

import numpy as np
import pytest

from rollingdisk import Disk, energy_drift, jit_compile, simulate, steady_motion
from rollingdisk.engine import jit as _jit
from rollingdisk.engine import jit as _simulate

SRC = os.path.dirname(os.path.dirname(_jit.__file__))


@pytest.fixture(scope="module", autouse=True)
def compiled():
    return jit_compile()


@pytest.fixture
def uncompiled(monkeypatch):
    """simulate() runs uncompiled throughout (the compiled code counts as not loaded)."""
    monkeypatch.setattr(_simulate, "_core", None)
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)


CASES = [
    ("rough", 0.2, [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5], None),
    ("smooth", 0.25, [0.0, 0.0, 0.3, -0.1, 0.2, 0.4, 0.0, 0.1, 1.5, 0.5], None),
    ("rough", 0.2, [0, 0, 0, 0.1, 0, -0.5, 1.0, 0], "edge-contact"),
    ("rough", 0.5, [0, 0, 0, 0.6, 0, 0, 0, 0], "lift-off"),
]


@pytest.mark.parametrize("ground,h,y0,event", CASES)
def test_uncompiled_run_takes_the_steps_of_the_compiled_one(ground, h, y0, event,
                                                             monkeypatch):
    disk = Disk(h=h)
    te = np.linspace(0, 3, 31)
    ref = simulate(disk, ground, (0, 20), y0, method="dop853")
    ref_te = simulate(disk, ground, (0, 3), y0, t_eval=te, dense_output=True)
    monkeypatch.setattr(_simulate, "_core", None)
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)
    tr = simulate(disk, ground, (0, 20), y0, method="dop853")
    tr_te = simulate(disk, ground, (0, 3), y0, t_eval=te, dense_output=True)
    assert tr.status == ref.status == (event or "completed")
    # the same steps up to round-off in the error estimate; the last few steps before an
    # edge contact straddle the jump of h~ at theta = 0, where round-off picks the step
    # sizes (compiled and scipy differ there as much)
    assert abs(tr.n_steps - ref.n_steps) <= (1 if event is None else 5)
    np.testing.assert_allclose(tr.y[:, -1], ref.y[:, -1], rtol=1e-8, atol=1e-8)
    if event:
        assert tr.t_event == pytest.approx(ref.t_event, abs=1e-9)
    np.testing.assert_allclose(tr_te.y, ref_te.y, rtol=1e-9, atol=1e-9)
    tm = 0.37 * tr_te.t[-1]  # inside the run (it may end early at an event)
    np.testing.assert_allclose(tr_te.sol(tm), ref_te.sol(tm), rtol=1e-9, atol=1e-9)


def test_lift_off_inside_one_step_is_found_uncompiled(uncompiled):
    # the issue-8 case (tests/test_simulate.py) on the uncompiled path
    y0 = [0, 0, 0, -0.7679, 0, -0.8403, -1.2908, 1.1468]
    tr = simulate(Disk(h=1.0), "rough", (0, 30), y0, rtol=1e-6, atol=1e-8)
    assert tr.status == "lift-off" and tr.t_event < 0.011


def test_a_run_switches_to_compiled_code_without_changing_its_steps(monkeypatch):
    disk = Disk(h=0.2)
    y0 = [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5]
    plain = simulate(disk, "rough", (0, 200), y0, progress=lambda f: None, method="dop853")
    monkeypatch.setattr(_simulate, "_core", None)
    monkeypatch.setattr(_jit, "PY_BUDGET", 3 * _jit.PY_CHUNK)
    monkeypatch.setattr(_jit, "_py_steps", 0)  # a fresh process
    used = []
    real = _simulate.jit_compile

    def spy():
        used.append(True)
        return real()

    monkeypatch.setattr(_simulate, "jit_compile", spy)
    tr = simulate(disk, "rough", (0, 200), y0, progress=lambda f: None, method="dop853")
    assert used, "the run never switched to compiled code"
    assert tr.status == plain.status == "completed"
    assert abs(tr.n_steps - plain.n_steps) <= 1
    assert np.all(np.diff(tr.t) > 0)
    np.testing.assert_allclose(tr.y[:, -1], plain.y[:, -1], rtol=1e-8, atol=1e-8)


def test_coefficients_are_scipys_table():
    # read from scipy's file without importing scipy.integrate; the same numbers as the
    # module scipy's own DOP853 uses
    from scipy.integrate._ivp import dop853_coefficients as ref

    from rollingdisk.engine import dop853 as _dop853

    for name in ("N_STAGES", "N_STAGES_EXTENDED", "INTERPOLATOR_POWER", "A", "B", "C", "E3",
                 "E5", "D"):
        np.testing.assert_array_equal(getattr(_dop853._dop, name), getattr(ref, name))


def test_a_second_background_compiler_leaves_at_once(tmp_path):
    import fcntl

    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path), PYTHONPATH=SRC)
    with open(tmp_path / "rollingdisk-jit.lock", "a") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)  # a compiler at work
        res = subprocess.run([sys.executable, "-m", "rollingdisk.engine.jit"], env=env,
                             capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stderr
    assert not any(p.name.endswith(".ready") for p in tmp_path.iterdir())
    assert not any(p.suffix == ".nbi" for p in tmp_path.rglob("*"))  # compiled nothing


def _compilers():
    """Processes running the cache filler ``python -m rollingdisk.engine.jit`` (Linux)."""
    from pathlib import Path

    found = []
    for p in Path("/proc").glob("[0-9]*/cmdline"):
        try:
            if b"rollingdisk.engine.jit" in p.read_bytes():
                found.append(p.parent.name)
        except OSError:
            pass
    return found


@pytest.mark.slow
@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")
def test_a_cold_cache_is_filled_in_the_foreground_and_no_process_outlives_the_run(
        tmp_path):
    """A long run with an empty cache compiles at once, in its own process (no detached
    compiler left running), marks the cache ready, and a later process loads it."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path), PYTHONPATH=SRC)
    code = ("import os, sys, rollingdisk as rd\n"
            "from rollingdisk.engine import jit as _jit\n"
            "_jit.PY_BUDGET = 0\n"
            "tr = rd.simulate(rd.Disk(h=0.1), 'rough', (0, 20), [0, 0, 0, 0.3, 0, 0, 2, 0.5],"
            " method='dop853')\n"
            "assert tr.status == 'completed' and _jit._core is not None\n")
    res = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, timeout=900)
    assert res.returncode == 0, res.stderr
    assert res.stderr == ""  # stderr is no terminal here: the compile said nothing
    assert any(p.name.endswith(".ready") for p in tmp_path.iterdir())
    assert not _compilers()  # nothing left running after the command


# ------------------------------------------------------------------ error_control="reduced"
@pytest.mark.parametrize("ground,h", [("rough", 0.1), ("smooth", 0.3), ("rough", 0.0)])
def test_reduced_error_control_keeps_positions_and_energy(ground, h):
    m = steady_motion(Disk(h=h), ground, 0.4, Omega0=2.5)
    y0 = np.array(m.initial_state(0.0, 0.0), dtype=float)
    y0[3 if ground == "rough" else 5] += 1e-4
    full = simulate(m.disk, ground, (0, 100), y0, method="dop853")
    for method in ("dop853", "scipy"):
        red = simulate(m.disk, ground, (0, 100), y0, error_control="reduced", method=method)
        assert red.status == "completed"
        assert red.n_steps < full.n_steps
        assert energy_drift(red) < 1e-9  # the default tolerances' promise
        # positions and angles agree with the full-state run to the 1e-8 the tests ask
        np.testing.assert_allclose(red.y[:, -1], full.y[:, -1], rtol=1e-8, atol=1e-8)
    a = simulate(m.disk, ground, (0, 100), y0, error_control="reduced", rtol=1e-10,
                 atol=1e-10, method="dop853")
    b = simulate(m.disk, ground, (0, 100), y0, error_control="reduced", rtol=1e-10,
                 atol=1e-10, method="scipy")
    assert abs(a.n_steps - b.n_steps) <= 1  # both methods: the same control


def test_error_control_is_validated():
    with pytest.raises(ValueError, match="error_control"):
        simulate(Disk(h=0.1), "rough", (0, 1), [0, 0, 0, 0.3, 0, 0, 2, 0.5],
                 error_control="positions")


def test_uncompiled_run_falls_back_to_ieee_arithmetic(uncompiled, monkeypatch):
    # math.sin(inf) raises where numba and numpy give nan: the chunk is rerun with numpy
    from rollingdisk.engine import pycore as _pycore

    calls = []

    def failing(*args):
        calls.append(True)
        raise ValueError("math domain error")

    monkeypatch.setattr(_pycore, "_integrate_fast", failing)
    y0 = [0, 0, 0, 0.3, 0, 0, 2.0, 0.5]
    tr = simulate(Disk(h=0.1), "rough", (0, 5), y0, method="dop853")
    monkeypatch.undo()
    ref = simulate(Disk(h=0.1), "rough", (0, 5), y0, method="dop853")
    assert calls and tr.status == "completed"
    assert abs(tr.n_steps - ref.n_steps) <= 1
    np.testing.assert_allclose(tr.y[:, -1], ref.y[:, -1], rtol=1e-9, atol=1e-9)
