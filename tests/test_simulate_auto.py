"""When a process loads the compiled integrator (its uncompiled steps counted over all its
runs against ``PY_BUDGET``, a run's remaining steps projected against ``LOAD_WORTH``), and
what ``simulate(method="auto")`` (the default) runs.

No timing: the rule counts steps, and the loader is replaced by a spy that 'loads' the
uncompiled module under a wrapper counting the chunks run 'compiled', so the rule is checked
by counting; a test also holds that no clock reading changes a run."""

from __future__ import annotations

import math
import time
import types

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.engine import jit as _jit
from rollingdisk.engine import pycore as _pycore

Y0 = [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5]


@pytest.fixture
def fresh(monkeypatch):
    """A process with no compiled code loaded, nothing spent, and a loader that records the
    steps spent when it is called."""
    monkeypatch.setattr(_jit, "_core", None)
    monkeypatch.setattr(_jit, "_py_steps", 0)
    monkeypatch.setattr(_jit, "LOAD_WORTH", math.inf)  # the projection rule: its own test
    log = types.SimpleNamespace(loads=[], compiled_chunks=0)

    def integrate(*args):
        log.compiled_chunks += 1
        return _pycore.integrate(*args)

    def load():
        log.loads.append(_jit.py_steps())
        _jit._core = types.SimpleNamespace(integrate=integrate)
        return 0.0

    monkeypatch.setattr(_jit, "jit_compile", load)
    return log


def _short():
    """A run done in one uncompiled chunk, and its number of steps."""
    tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 2), Y0, method="dop853")
    assert tr.status == "completed" and tr.n_steps < _jit.PY_CHUNK
    return tr


def test_the_compiled_code_is_loaded_once_the_budget_is_spent_in_total(fresh, monkeypatch):
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)
    n = _short().n_steps
    monkeypatch.setattr(_jit, "_py_steps", 0)
    monkeypatch.setattr(_jit, "PY_BUDGET", int(3.5 * n))
    spent = []
    for _ in range(6):  # short runs of one chunk each: n uncompiled steps per run
        before = _jit.py_steps()
        _short()
        spent.append(_jit.py_steps() - before)
    # the first four runs go uncompiled (3 n < budget at the start of the fourth);
    # the fifth finds 4 n >= budget, loads, and it and the sixth run compiled
    assert spent == [n] * 4 + [0, 0]
    assert fresh.loads == [4 * n]
    assert fresh.compiled_chunks == 2
    # no single run came near the budget: a per-run rule would never have loaded
    assert max(spent) < _jit.PY_BUDGET


def test_a_run_switches_when_the_total_reaches_the_budget_mid_run(fresh, monkeypatch):
    c = _jit.PY_CHUNK
    monkeypatch.setattr(_jit, "PY_BUDGET", int(2.5 * c))
    monkeypatch.setattr(_jit, "_py_steps", 2 * c)  # earlier runs took this many
    plain = rd.simulate(rd.Disk(h=0.2), "rough", (0, 200), Y0, method="dop853")
    assert fresh.loads == [3 * c]  # after one more chunk, mid-run
    assert fresh.compiled_chunks >= 1
    monkeypatch.setattr(_jit, "_core", None)
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)
    ref = rd.simulate(rd.Disk(h=0.2), "rough", (0, 200), Y0, method="dop853")
    assert abs(plain.n_steps - ref.n_steps) <= 1  # the same steps, paused and resumed
    np.testing.assert_allclose(plain.y[:, -1], ref.y[:, -1], rtol=1e-10, atol=1e-10)


@pytest.mark.parametrize("warm", [True, False])
def test_a_cold_cache_changes_no_decision(fresh, monkeypatch, warm):
    """The rule never asks whether the cache is ready: a cold cache is compiled in the
    foreground at the chunk where a warm one would be loaded (no process left behind)."""
    c = _jit.PY_CHUNK
    monkeypatch.setattr(_jit, "ready", lambda: warm)
    monkeypatch.setattr(_jit, "PY_BUDGET", int(2.5 * c))
    monkeypatch.setattr(_jit, "_py_steps", 2 * c)
    rd.simulate(rd.Disk(h=0.2), "rough", (0, 200), Y0, method="dop853")
    assert fresh.loads == [3 * c]


def test_a_run_projected_past_load_worth_loads_after_its_first_chunk(fresh, monkeypatch):
    """A run loads at the first chunk boundary at which the rest of it is projected to need
    more than LOAD_WORTH steps uncompiled, however little the process spent."""
    c = _jit.PY_CHUNK
    monkeypatch.setattr(_jit, "PY_BUDGET", math.inf)  # the total rule never fires here
    monkeypatch.setattr(_jit, "LOAD_WORTH", 5 * c)
    short = _short()
    assert not fresh.loads  # done in its first chunk
    before = _jit.py_steps()
    assert before == short.n_steps
    tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 200), Y0, method="dop853")
    assert tr.status == "completed"
    # one uncompiled chunk (about 1/100 of the span: projected > 5 chunks more), then loaded
    assert fresh.loads == [before + c]
    assert fresh.compiled_chunks >= 1
    n = fresh.compiled_chunks
    _short()  # compiled from its start
    assert fresh.compiled_chunks == n + 1 and len(fresh.loads) == 1


def test_worth_loading_projects_the_steps_ahead_from_the_part_done(monkeypatch):
    monkeypatch.setattr(_jit, "LOAD_WORTH", 1000)
    assert _jit.worth_loading(200, 0.1)  # 1800 steps more
    assert not _jit.worth_loading(200, 0.5)  # 200 more
    assert not _jit.worth_loading(0, 0.0) and not _jit.worth_loading(500, 1.0)


def test_no_clock_changes_a_run(monkeypatch):
    """Every decision counts steps: a run on a machine a thousand times slower (a clock
    that races) takes the same steps, in the same chunks, and gives the same bits."""
    monkeypatch.setattr(_jit, "_core", None)
    monkeypatch.setattr(_jit, "_py_steps", 0)
    monkeypatch.setattr(_jit, "jit_compile", lambda: 0.0)  # never load (numba stays out)
    a = rd.simulate(rd.Disk(h=0.2), "rough", (0, 50), Y0, method="dop853")
    real = time.perf_counter
    monkeypatch.setattr(time, "perf_counter", lambda: 1000.0 * real())
    monkeypatch.setattr(_jit, "_py_steps", 0)
    b = rd.simulate(rd.Disk(h=0.2), "rough", (0, 50), Y0, method="dop853")
    assert a.n_steps == b.n_steps and a.method == b.method
    np.testing.assert_array_equal(a.y, b.y)


def test_a_cold_compile_says_so_on_a_terminal_only(monkeypatch, capsys):
    from rollingdisk.engine.compile import announce

    class Tty:
        def __init__(self):
            self.text = ""

        def isatty(self):
            return True

        def write(self, s):
            self.text += s

        def flush(self):
            pass

    tty = Tty()
    monkeypatch.setattr("sys.stderr", tty)
    announce("compiling x (once per machine; usually 10-60 s)")
    assert tty.text == "rollingdisk: compiling x (once per machine; usually 10-60 s)\n"
    monkeypatch.undo()
    announce("compiling x")
    assert capsys.readouterr().err == ""  # not a terminal: silent


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
    monkeypatch.setattr(_jit, "_py_steps", 0)
    monkeypatch.setattr(_jit, "PY_BUDGET", 1)  # spent by the first chunk
    seen = []
    tr = rd.simulate(rd.Disk(h=0.2), "rough", (0, 100), Y0, progress=seen.append)
    ref = rd.simulate(rd.Disk(h=0.2), "rough", (0, 100), Y0, method="dop853")
    assert tr.method == "dop853+taylor" and tr.status == "completed"
    assert np.all(np.diff(tr.t) > 0) and 10 < len(seen) <= 100 and seen[-1] == 1.0
    np.testing.assert_allclose(tr.y[:, -1], ref.y[:, -1], rtol=1e-8, atol=1e-8)
