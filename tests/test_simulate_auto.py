"""When a process loads the compiled integrator (its uncompiled seconds counted over all its
runs against ``PY_BUDGET``), and what ``simulate(method="auto")`` (the default) runs.

No timing: the clock of the uncompiled seconds is replaced by one that advances by a fixed
amount per reading, and the loader by a spy, so the rule is checked by counting."""

from __future__ import annotations

import math
import types

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.engine import jit as _jit
from rollingdisk.engine import pycore as _pycore

Y0 = [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5]
TICK = 0.01  # "seconds" between two readings of the fake clock: one uncompiled chunk


@pytest.fixture
def fresh(monkeypatch):
    """A process with no compiled code loaded, nothing spent, a clock that advances by
    TICK per reading, and a loader that records when it is called and 'loads' the
    uncompiled module under a wrapper that counts the chunks run 'compiled'."""
    ticks = iter(range(10**9))
    monkeypatch.setattr(_jit, "clock", lambda: next(ticks) * TICK)
    monkeypatch.setattr(_jit, "_core", None)
    monkeypatch.setattr(_jit, "_py_seconds", 0.0)
    monkeypatch.setattr(_jit, "LOAD_WORTH", math.inf)  # the projection rule: its own test
    log = types.SimpleNamespace(loads=[], compiled_chunks=0)

    def integrate(*args):
        log.compiled_chunks += 1
        return _pycore.integrate(*args)

    def load():
        log.loads.append(_jit.py_seconds())
        _jit._core = types.SimpleNamespace(integrate=integrate)
        return 0.0

    monkeypatch.setattr(_jit, "jit_compile", load)
    return log


def test_the_compiled_code_is_loaded_once_the_budget_is_spent_in_total(fresh, monkeypatch):
    monkeypatch.setattr(_jit, "PY_BUDGET", 3.5 * TICK)
    monkeypatch.setattr(_jit, "ready", lambda: True)
    spent = []
    for _ in range(6):  # short runs of one chunk each: TICK uncompiled per run
        before = _jit.py_seconds()
        tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 2), Y0, method="dop853")
        assert tr.status == "completed"
        spent.append(_jit.py_seconds() - before)
    # the first four runs go uncompiled (3 TICK < budget at the start of the fourth);
    # the fifth finds 4 TICK >= budget, loads, and it and the sixth run compiled
    assert spent == pytest.approx([TICK] * 4 + [0.0, 0.0])
    assert fresh.loads == [pytest.approx(4 * TICK)]
    assert fresh.compiled_chunks == 2
    # no single run came near the budget: the old per-run rule would never have loaded
    assert max(spent) < _jit.PY_BUDGET


def test_a_run_switches_when_the_total_reaches_the_budget_mid_run(fresh, monkeypatch):
    monkeypatch.setattr(_jit, "PY_BUDGET", 2.5 * TICK)
    monkeypatch.setattr(_jit, "ready", lambda: True)
    monkeypatch.setattr(_jit, "_py_seconds", 2 * TICK)  # earlier runs spent this much
    plain = rd.simulate(rd.Disk(h=0.2), "rough", (0, 200), Y0, method="dop853")
    assert fresh.loads == [pytest.approx(3 * TICK)]  # after one more chunk, mid-run
    assert fresh.compiled_chunks >= 1
    monkeypatch.setattr(_jit, "_core", None)
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)
    ref = rd.simulate(rd.Disk(h=0.2), "rough", (0, 200), Y0, method="dop853")
    assert abs(plain.n_steps - ref.n_steps) <= 1  # the same steps, paused and resumed
    np.testing.assert_allclose(plain.y[:, -1], ref.y[:, -1], rtol=1e-10, atol=1e-10)


def test_a_cold_cache_starts_one_compiler_and_the_runs_go_on(fresh, monkeypatch):
    monkeypatch.setattr(_jit, "PY_BUDGET", 1.5 * TICK)
    monkeypatch.setattr(_jit, "ready", lambda: False)
    started = []
    monkeypatch.setattr(_jit, "start_background_compile", lambda: started.append(1) or True)
    monkeypatch.setattr(_jit, "worth_waiting", lambda elapsed, fraction: False)
    for _ in range(4):
        tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 2), Y0, method="dop853")
        assert tr.status == "completed"
    assert started and not fresh.loads and _jit.py_seconds() == pytest.approx(4 * TICK)


def test_a_warm_cache_is_loaded_by_the_first_run_projected_past_load_worth(fresh,
                                                                          monkeypatch):
    """With a ready cache a run loads at the first chunk boundary at which the rest of it is
    projected to need more than LOAD_WORTH uncompiled, however little the process spent."""
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)  # the total rule never fires here
    monkeypatch.setattr(_jit, "LOAD_WORTH", 5 * TICK)
    monkeypatch.setattr(_jit, "ready", lambda: True)
    short = rd.simulate(rd.Disk(h=0.2), "rough", (0, 2), Y0, method="dop853")
    assert short.status == "completed" and not fresh.loads  # done in its first chunk
    before = _jit.py_seconds()
    tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 200), Y0, method="dop853")
    assert tr.status == "completed"
    # one uncompiled chunk (1/100 of the span or less: projected >= 5 TICK more), then loaded
    assert fresh.loads == [pytest.approx(before + TICK)]
    assert _jit.py_seconds() - before == pytest.approx(TICK)
    assert fresh.compiled_chunks >= 1
    n = fresh.compiled_chunks
    rd.simulate(rd.Disk(h=0.2), "rough", (0, 2), Y0, method="dop853")  # compiled from start
    assert fresh.compiled_chunks == n + 1 and len(fresh.loads) == 1


def test_worth_loading_projects_from_the_part_done():
    assert _jit.worth_loading(0.02, 0.1)  # 0.18 s more
    assert not _jit.worth_loading(0.02, 0.5)  # 0.02 s more
    assert not _jit.worth_loading(0.0, 0.0) and not _jit.worth_loading(0.5, 1.0)


# ---------------------------------------------------------------------------- auto
def test_auto_method_table():
    floor = 100 * np.finfo(float).eps
    opts = dict(events=False, dense_output=False, first_step=False)
    assert _jit.auto_method("rough", 1e-10, 1e-10, **dict(opts, events=True))[0] == "scipy"
    assert _jit.auto_method("rough", 1e-10, 1e-10, **dict(opts, dense_output=True)) == (
        "dop853", 1e-10, 1e-10)
    assert _jit.auto_method("rough", 1e-10, 1e-10, **dict(opts, first_step=True))[0] == \
        "dop853"
    for tol in (1e-3, 1e-8, 1e-12):
        assert _jit.auto_method("smooth", tol, tol, **opts) == ("dop853", tol, tol)
    f = _jit.TAYLOR_RANGE["rough"][2]
    m, r, a = _jit.auto_method("rough", 1e-8, 1e-9, **opts)
    assert m == "auto-taylor" and r == pytest.approx(1e-8 * f)
    assert a == pytest.approx(1e-9 * f)
    # floored at 100 eps (rtol), never looser than asked (atol)
    m, r, a = _jit.auto_method("rough", 1e-12, 1e-20, **opts)
    assert r == floor and a == pytest.approx(1e-20 * _jit.TAYLOR_RANGE["rough"][2])


@pytest.fixture(scope="module")
def compiled():
    return rd.jit_compile()


@pytest.mark.parametrize("ground,h,tols", [
    ("rough", 0.37, (1e-4, 1e-6, 1e-8, 1e-10)), ("rough", 0.0, (1e-8, 1e-10)),
    ("rough", 0.8, (1e-6, 1e-9))])
def test_auto_with_compiled_code_is_taylor_no_less_accurate_than_dop853(ground, h, tols,
                                                                        compiled):
    # the promise of TAYLOR_RANGE on jobs other than those it was measured on: energy
    # (eq. 13, conserved) drifts no more than under DOP853 at the tolerance asked for
    disk = rd.Disk(h=h)
    m = rd.steady_motion(disk, ground, 0.5, Omega0=2.2)
    y0 = np.array(m.initial_state(0.0, 0.0), dtype=float)
    y0[3 if ground == "rough" else 5] += 1e-3
    grid = np.linspace(0, 300, 3001)
    for tol in tols:
        auto = rd.simulate(disk, ground, (0, 300), y0, rtol=tol, atol=tol, t_eval=grid)
        dop = rd.simulate(disk, ground, (0, 300), y0, rtol=tol, atol=tol, t_eval=grid,
                          method="dop853")
        assert auto.method == "taylor" and auto.status == dop.status == "completed"
        assert rd.energy_drift(auto) <= max(rd.energy_drift(dop), 1e-14)
        if tol <= 1e-8:  # the same motion (the phase error of either grows with tol)
            np.testing.assert_allclose(auto.y[:, -1], dop.y[:, -1], rtol=1e-5, atol=1e-5)


def test_auto_without_compiled_code_runs_uncompiled_dop853(monkeypatch):
    monkeypatch.setattr(_jit, "_core", None)
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)
    tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 5), Y0)
    assert tr.method == "dop853" and tr.status == "completed"
    tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 5), Y0, dense_output=True)
    assert tr.method == "dop853" and tr.sol is not None


def test_auto_on_smooth_ground_is_dop853(compiled):
    m = rd.steady_motion(rd.Disk(h=0.2), "smooth", 0.5, Omega0=2.2)
    assert rd.simulate_steady(m, 5.0, perturb=1e-3).method == "dop853"


def test_auto_goes_on_with_taylor_once_the_code_is_loaded(compiled, monkeypatch):
    monkeypatch.setattr(_jit, "_core", None)
    monkeypatch.setattr(_jit, "_py_seconds", 0.0)
    monkeypatch.setattr(_jit, "PY_BUDGET", 1e-9)  # spent by the first chunk
    monkeypatch.setattr(_jit, "ready", lambda: True)
    seen = []
    tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 100), Y0, progress=seen.append)
    ref = rd.simulate(rd.Disk(h=0.2), "rough", (0, 100), Y0, method="dop853")
    assert tr.method == "dop853+taylor" and tr.status == "completed"
    assert np.all(np.diff(tr.t) > 0) and 10 < len(seen) <= 100 and seen[-1] == 1.0
    np.testing.assert_allclose(tr.y[:, -1], ref.y[:, -1], rtol=1e-8, atol=1e-8)
