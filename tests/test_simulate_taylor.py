"""``simulate(method="taylor")``: the series against the numpy right-hand side, whole runs
against DOP853, guards, steady motions, energy, and bad input.

Sources of truth: the kernels of :mod:`rollingdisk.model.equations` (the first coefficient is
the right-hand side, the second half its derivative along the flow, computed here by a
complex step through those kernels), an independent tight ``solve_ivp`` on the numpy
right-hand side, DOP853 at tight tolerance, eq. (13) (energy), and the steady motions of
section 3.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

import rollingdisk as rd
from rollingdisk import Disk, energy_drift, equations_of_motion, simulate
from rollingdisk.util.errors import ParameterError


@pytest.fixture(scope="module")
def core():
    rd.jit_compile()
    from rollingdisk.engine import jit as _simulate

    return _simulate._core


def _state(ground, theta, w1, w2, w3, v=(0.2, -0.1)):
    if ground == "rough":
        return np.array([0.3, -0.2, 0.7, theta, 0.1, w1, w2, w3])
    return np.array([0.3, -0.2, v[0], v[1], 0.7, theta, 0.1, w1, w2, w3])


def _jet(core, ground, h, y, P=12):
    J = np.zeros((y.size, P + 1))
    A = np.zeros((19, P + 1))
    core._tay_jet(ground == "rough", h, y, J, A, P)
    return J


states = st.tuples(
    st.sampled_from(["rough", "smooth"]),
    st.sampled_from([0.0, 0.05, 0.4, 1.5]),
    st.floats(0.05, 1.4), st.sampled_from([1.0, -1.0]),
    st.floats(-1.5, 1.5), st.floats(-3.0, 3.0), st.floats(-3.0, 3.0))


@settings(max_examples=60, deadline=None)
@given(states)
def test_first_two_coefficients_are_the_rhs_and_its_flow_derivative(core, case):
    ground, h, th, sign, w1, w2, w3 = case
    disk = Disk(h)
    y = _state(ground, sign * th, w1, w2, w3)
    f = equations_of_motion(disk, ground)
    J = _jet(core, ground, h, y)
    f0 = f(0.0, y)
    assert np.allclose(J[:, 1], f0, rtol=1e-13, atol=1e-13)
    # y'' = (df/dy) f, by a complex step through the numpy kernels: 2 J_2 = y''
    from rollingdisk.model import equations as eq

    kernel = eq.rough_rhs if ground == "rough" else eq.smooth_rhs
    eps = 1e-30
    second = np.imag(np.array(kernel(h, y + 1j * eps * f0), dtype=complex)) / eps
    assert np.allclose(2.0 * J[:, 2], second, rtol=1e-11, atol=1e-11)


@settings(max_examples=25, deadline=None)
@given(states)
def test_series_agrees_with_a_tight_solve_ivp(core, case):
    ground, h, th, sign, w1, w2, w3 = case
    disk = Disk(h)
    y = _state(ground, sign * th, w1, w2, w3)
    P = 20
    J = _jet(core, ground, h, y, P)
    # a step well inside the radius of convergence estimated from the last coefficients
    rho = min(np.max(np.abs(J[:, P])) ** (-1.0 / P),
              np.max(np.abs(J[:, P - 1])) ** (-1.0 / (P - 1)))
    dt = 0.2 * rho
    ith = 3 if ground == "rough" else 5
    while True:  # theta keeps its sign (for h > 0, crossing 0 is the edge-contact guard)
        sol = solve_ivp(equations_of_motion(disk, ground), (0.0, dt), y, method="DOP853",
                        rtol=1e-13, atol=1e-13, dense_output=True)
        if np.all(np.sign(sol.sol(np.linspace(0, dt, 50))[ith]) == np.sign(y[ith])):
            break
        dt *= 0.5
    ref = sol.y[:, -1]
    out = np.empty_like(y)
    core._tay_eval(J, P, dt, out)
    assert np.allclose(out, ref, rtol=1e-10, atol=1e-10)


def _perturbed(ground, h, theta0, Omega0):
    """A steady circle (section 3) with theta + 0.02 (and V_X + 0.1 on smooth ground)."""
    y = rd.steady_motion(Disk(h), ground, theta0, Omega0=Omega0).initial_state()
    y[3 if ground == "rough" else 5] += 0.02
    if ground == "smooth":
        y[2] += 0.1
    return y


@pytest.mark.parametrize("ground, h, y0", [
    ("rough", 0.1, [0, 0, 0, 0.3, 0, 0, 2.0, 0.5]),
    ("rough", 0.0, _perturbed("rough", 0.0, -0.6, 2.5)),
    ("rough", 0.5, _perturbed("rough", 0.5, 0.9, -3.0)),
    ("smooth", 0.3, _perturbed("smooth", 0.3, 0.5, 2.0)),
    ("smooth", 0.0, _perturbed("smooth", 0.0, -0.4, -2.5)),
])
def test_runs_agree_with_dop853_and_keep_energy(ground, h, y0):
    disk = Disk(h)
    grid = np.linspace(0.0, 100.0, 201)
    a = simulate(disk, ground, (0, 100), y0, method="taylor", rtol=1e-13, atol=1e-13,
                 t_eval=grid)
    b = simulate(disk, ground, (0, 100), y0, method="dop853", rtol=1e-13, atol=1e-13,
                 t_eval=grid)
    assert a.status == b.status == "completed" and a.method == "taylor"
    assert np.allclose(a.t, b.t, rtol=0, atol=0)
    assert np.max(np.abs(a.y - b.y)) < 1e-8
    assert energy_drift(a) < 1e-12
    steps = simulate(disk, ground, (0, 100), y0, method="taylor", rtol=1e-13, atol=1e-13)
    assert steps.n_steps < b.n_steps  # fewer, longer steps: the point of the method
    assert np.allclose(steps.y[:, -1], a.y[:, -1], rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_steady_motion_stays_steady(ground):
    m = rd.steady_motion(Disk(0.17), ground, 0.6, Omega0=2.0)
    tr = rd.simulate_steady(m, 100.0, method="taylor", rtol=1e-12, atol=1e-12)
    assert tr.status == "completed"
    assert np.max(np.abs(tr.theta - m.theta0)) < 1e-10


def test_guard_times_agree_with_dop853():
    cases = [(Disk(0.2), "smooth", [0, 0, 0.1, 0, 0, 0.4, 0, 0, 1.5, 2.0]),  # lifts off
             (Disk(0.0), "rough", [0, 0, 0, 1.2, 0, 0, 0.1, 0.0]),
             (Disk(0.3), "rough", [0, 0, 0, 0.2, 0, -0.8, 0.0, 0.0])]  # lands on its edge
    fired = 0
    for disk, ground, y0 in cases:
        a = simulate(disk, ground, (0, 30), y0, method="taylor", rtol=1e-13, atol=1e-13)
        b = simulate(disk, ground, (0, 30), y0, method="dop853", rtol=1e-13, atol=1e-13)
        assert a.status == b.status
        if a.t_event is not None:
            fired += 1
            assert math.isclose(a.t_event, b.t_event, rel_tol=0, abs_tol=1e-9)
            assert np.allclose(a.y[:, -1], b.y[:, -1], atol=1e-8)
    assert fired >= 2


def test_taylor_options_and_bad_input():
    disk, y0 = Disk(0.1), [0, 0, 0, 0.3, 0, 0, 2.0, 0.5]
    with pytest.raises(ParameterError, match="method"):
        simulate(disk, "rough", (0, 1), y0, method="rk4")
    with pytest.raises(ParameterError, match="dense"):
        simulate(disk, "rough", (0, 1), y0, method="taylor", dense_output=True)
    with pytest.raises(ParameterError, match="first_step"):
        simulate(disk, "rough", (0, 1), y0, method="taylor", first_step=0.1)
    with pytest.raises(ParameterError, match="events"):
        simulate(disk, "rough", (0, 1), y0, method="taylor", events=lambda t, y: y[3])
    tr = simulate(disk, "rough", (0, 100), y0, method="taylor", max_steps=5)
    assert tr.status == "step-budget" and tr.n_steps == 5
    seen = []
    tr = simulate(disk, "rough", (0, 100), y0, method="taylor", progress=seen.append)
    assert seen and seen[-1] == 1.0 and all(0 <= p <= 1 for p in seen)


def test_cli_method_taylor(capsys):
    import json

    from rollingdisk.cli.app import main

    argv = ["simulate", "--method", "taylor", "--h", "0.1", "--theta0", "0.3", "--Omega0", "2",
            "--kick", "0.01", "--t-end", "100", "--rtol", "1e-12", "--atol", "1e-12", "--json"]
    assert main(argv) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["method"] == "taylor" and rec["status"] == "completed"
    assert rec["energy_drift"] < 1e-12
    # the measured frequency is the closed form's varpi (eq. 40) at small amplitude
    assert abs(rec["theta_frequency"] - rec["varpi"]) < 1e-3 * rec["varpi"]


def _heyoka_rough_system(h):
    """heyoka's ODE from the kernels of rollingdisk.model.equations (their ``np`` bound to
    heyoka's sin/cos; ``sgn(theta) = 1``: the run below stays at theta > 0)."""
    import types

    import heyoka as hy

    from rollingdisk.model import equations as eq

    class HeyokaNp:
        sin = staticmethod(hy.sin)
        cos = staticmethod(hy.cos)
        sign = staticmethod(lambda x: 1.0)
        real = staticmethod(lambda x: x)

    ns = dict(eq.__dict__, np=HeyokaNp())
    for name in ("_geometry", "_rough_omega_dot", "_rough_rhs"):
        f = eq.__dict__[name]
        ns[name] = types.FunctionType(f.__code__, ns, name)
    xs = hy.make_vars(*rd.ROUGH_STATE)
    return list(zip(xs, ns["_rough_rhs"](h, xs)))


@pytest.mark.parametrize("tol", [1e-12])
def test_full_control_takes_heyokas_steps(tol):
    """The step-size rule is heyoka's (Jorba & Zou, norms over all components): with
    ``error_control="full"`` the run takes heyoka's number of steps on the benchmark's
    near-steady circle (an independent implementation of the same rule and order)."""
    hy = pytest.importorskip("heyoka")
    disk = Disk(h=0.1)
    y0 = np.array([0.0, 0.0, 0.0, 0.3001, 0.0, 0.0, 0.0, 3.0])
    a = rd.omega_dot(disk, "rough", 0.3, 0.0, 0.0, 3.0)[0]
    b = rd.omega_dot(disk, "rough", 0.3, 0.0, 1.0, 3.0)[0]
    y0[6] = -a / (b - a)
    ta = hy.taylor_adaptive(_heyoka_rough_system(disk.h), y0, tol=tol)
    n_hy = ta.propagate_until(200.0)[3]
    tr = simulate(disk, "rough", (0.0, 200.0), y0, rtol=tol, atol=tol, method="taylor",
                  error_control="full")
    assert tr.status == "completed"
    assert abs(tr.n_steps - n_hy) <= max(2, 0.01 * n_hy)


def test_a_series_beyond_float_range_fails_and_never_completes():
    """omega3 = 1e150: the Taylor step's series is not finite; the run ends 'failed' as
    DOP853's does, never 'completed' with NaN states (which the CLI then refused)."""
    rd.jit_compile()
    y0 = [0, 0, 0, 0.3, 0, 0, 0, 1e150]
    for method in ("taylor", "dop853"):
        tr = rd.simulate(rd.Disk(0.1), "rough", (0, 1), y0, method=method)
        assert tr.status == "failed" and np.all(np.isfinite(tr.y)), method
