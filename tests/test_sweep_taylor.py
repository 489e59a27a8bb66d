"""The batch Taylor kernel of the sweeps (``run_sweep(method="taylor")``, the default).

Sources of truth: the numpy kernels of :mod:`rollingdisk.model.equations` (the first coefficient
of the reduced jet is the right-hand side, twice the second its derivative along the flow
by a complex step, the normal force is eq. 11), an independent tight ``solve_ivp`` on the
numpy reduced right-hand side, ``simulate`` (its own integrator and guard location) for
guard times, and the batch DOP853 kernel for whole-run summaries.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

import rollingdisk as rd
from rollingdisk.model import equations as eq

sweep = pytest.importorskip("rollingdisk.sweep")


@pytest.fixture(scope="module")
def nc():
    from rollingdisk.engine import numba_core as _numba_core

    return _numba_core


def _jet4(nc, ground, h, x, P):
    J = np.zeros((4, P + 1))
    A = np.zeros((14, P + 1))
    jet = nc._tay_jet4_rough if ground == "rough" else nc._tay_jet4_smooth
    jet(h, np.asarray(x, dtype=float), J, A, P)
    return J, A


def _rhs(ground, h):
    return lambda t, x: np.array(eq.reduced_rhs(ground == "rough", h, x), dtype=complex
                                 if np.iscomplexobj(x) else float)


states = st.tuples(
    st.sampled_from(["rough", "smooth"]),
    st.sampled_from([0.0, 0.05, 0.17, 0.4, 1.5]),
    st.floats(0.05, 1.4), st.sampled_from([1.0, -1.0]),
    st.floats(-1.5, 1.5), st.floats(-3.0, 3.0), st.floats(-3.0, 3.0))


@settings(max_examples=60, deadline=None)
@given(states)
def test_reduced_jet_starts_with_the_rhs_and_its_flow_derivative(nc, case):
    ground, h, th, sign, w1, w2, w3 = case
    x = np.array([sign * th, w1, w2, w3])
    J, _ = _jet4(nc, ground, h, x, 12)
    f0 = np.array(eq.reduced_rhs(ground == "rough", h, x))
    assert np.allclose(J[:, 0], x, rtol=0, atol=0)
    assert np.allclose(J[:, 1], f0, rtol=1e-13, atol=1e-13)
    eps = 1e-30
    second = np.imag(np.array(eq.reduced_rhs(ground == "rough", h, x + 1j * eps * f0),
                              dtype=complex)) / eps
    assert np.allclose(2.0 * J[:, 2], second, rtol=1e-11, atol=1e-11)


def _short_step(nc, ground, h, x, P):
    """The jet and a step well inside its radius of convergence on which theta keeps its
    sign, with a tight solve_ivp of the numpy reduced system over it."""
    J, A = _jet4(nc, ground, h, x, P)
    rho = min(np.max(np.abs(J[:, P])) ** (-1.0 / P),
              np.max(np.abs(J[:, P - 1])) ** (-1.0 / (P - 1)))
    dt = 0.2 * rho
    while True:
        sol = solve_ivp(_rhs(ground, h), (0.0, dt), x, method="DOP853", rtol=1e-13,
                        atol=1e-13, dense_output=True)
        if np.all(np.sign(sol.sol(np.linspace(0, dt, 50))[0]) == np.sign(x[0])):
            return J, A, dt, sol
        dt *= 0.5


@settings(max_examples=30, deadline=None)
@given(states)
def test_reduced_series_and_normal_force_agree_with_solve_ivp(nc, case):
    """The polynomial (Horner, and the seven-sum sampler) against a tight solve_ivp, and the
    normal force of the sampler and of the F_z series against eq. (11) on its state."""
    ground, h, th, sign, w1, w2, w3 = case
    x = np.array([sign * th, w1, w2, w3])
    P = 20
    J, A, dt, sol = _short_step(nc, ground, h, x, P)
    N = np.zeros(P + 1)
    nc._tay_normal(h, J, A, P, N)
    v = np.empty(5)
    for frac in (0.0, 0.37, 1.0):
        xs = frac * dt
        ref = sol.sol(xs)
        out = np.empty(4)
        nc._tay_eval(J, P, xs, out)
        assert np.allclose(out, ref, rtol=1e-10, atol=1e-10)
        nc._tay_sample(h, J, A, P, xs, v)
        assert np.allclose(v[:4], ref, rtol=1e-10, atol=1e-10)
        fz = eq.normal_force(ground == "rough", h, ref)  # eq. (11) on the true state
        assert math.isclose(v[4], fz, rel_tol=1e-9, abs_tol=1e-9)
        assert math.isclose(nc._tay_poly(N, P - 1, xs), fz, rel_tol=1e-9, abs_tol=1e-9)


def test_poly_root_finds_the_roots_of_a_known_polynomial(nc):
    # (x - 0.3)(x + 2)(x - 5) = x^3 - 3.3 x^2 - 9.1 x + 3
    c = np.array([3.0, -9.1, -3.3, 1.0])
    f = np.polynomial.polynomial.polyval
    r = nc._tay_poly_root(c, 3, 1.0, 0.0, 0.0, 1.0, f(0.0, c), f(1.0, c))
    assert abs(r - 0.3) < 1e-14
    # sg and off: -p(x) - (-1) = 0 where p(x) = 1
    r = nc._tay_poly_root(c, 3, -1.0, -1.0, 0.0, 0.25, 1.0 - f(0.0, c), 1.0 - f(0.25, c))
    assert abs(f(r, c) - 1.0) < 1e-13


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_guard_times_match_simulate(ground):
    """Random states (h = 0.2): every guard the sweep's Taylor kernel reports is the one
    simulate reports, at the same time (simulate: DOP853 at 1e-12, guards located on its
    dense output; the kernel: located on its step polynomial at 1e-9)."""
    rng = np.random.default_rng(3)
    n = 60
    X = np.column_stack([rng.uniform(0.2, 1.4, n), rng.uniform(-1.5, 1.5, n),
                         rng.uniform(-3, 3, n), rng.uniform(-3, 3, n)])
    ds = sweep.run_sweep(sweep.SweepGrid(ground, h=0.2, states=X), 20.0)
    status = ds.status.values.ravel()
    t_end = ds.t_end.values.ravel()
    names = {1: "completed", 2: "lift-off", 3: "edge-contact", 4: "fell-flat"}
    mid_run = 0
    for i in range(n):
        th, w1, w2, w3 = X[i]
        y = (np.array([0, 0, 0, th, 0, w1, w2, w3]) if ground == "rough"
             else np.array([0, 0, 0, 0, 0, th, 0, w1, w2, w3]))
        tr = rd.simulate(rd.Disk(0.2), ground, (0, 20.0), y, rtol=1e-12, atol=1e-12)
        assert tr.status == names[int(status[i])], i
        assert abs(tr.t[-1] - t_end[i]) < 1e-7 * max(1.0, t_end[i]), i
        mid_run += 0.0 < t_end[i] < 20.0
    assert mid_run >= 5  # guards inside runs, not only at t = 0


def test_guards_are_located_inside_steps_not_at_step_ends():
    """A disk falling flat (rough, h = 0.2, theta = 1.3 at rest): the Taylor kernel stops at
    the event time of simulate; the DOP853 kernel at the end of that step, later."""
    x = [(1.3, 0.0, 0.0, 0.0)]
    y = np.array([0, 0, 0, 1.3, 0, 0, 0, 0.0])
    t_ref = rd.simulate(rd.Disk(0.2), "rough", (0, 5.0), y, rtol=1e-12, atol=1e-12).t[-1]
    g = sweep.SweepGrid("rough", h=0.2, states=x)
    tay = sweep.run_sweep(g, 5.0)
    dop = sweep.run_sweep(g, 5.0, method="dop853")
    assert int(tay.status.values.ravel()[0]) == int(dop.status.values.ravel()[0]) == 4
    assert abs(float(tay.t_end.values.ravel()[0]) - t_ref) < 1e-9
    assert float(dop.t_end.values.ravel()[0]) > t_ref + 1e-3
    assert tay.attrs["method"] == "taylor" and dop.attrs["method"] == "dop853"


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_taylor_and_dop853_kernels_give_the_same_summaries(ground):
    g = sweep.SweepGrid(ground, h=0.17, theta0=np.linspace(0.3, 1.2, 6),
                        omega30=np.linspace(-6.0, 6.0, 7))
    tay = sweep.run_sweep(g, 60.0)
    dop = sweep.run_sweep(g, 60.0, method="dop853")
    ok = tay.stable.values >= 0
    assert ok.sum() >= 30
    np.testing.assert_array_equal(tay.status.values, dop.status.values)
    np.testing.assert_array_equal(tay.stable_simulated.values, dop.stable_simulated.values)
    np.testing.assert_array_equal(tay.n_crossings.values, dop.n_crossings.values)
    f1, f2 = tay.frequency.values, dop.frequency.values
    m = np.isfinite(f1)
    assert m.sum() >= 20
    # DOP853 locates crossings on a cubic Hermite interpolant between step ends
    np.testing.assert_allclose(f1[m], f2[m], rtol=1e-5)
    d1, d2 = tay.max_dtheta.values[ok], dop.max_dtheta.values[ok]
    np.testing.assert_allclose(d1, d2, rtol=2e-2)  # both sample the maximum at points
    assert np.nanmax(tay.energy_drift.values) < 1e-8
    # fewer steps at the same tolerance
    assert np.nansum(tay.n_steps.values) < np.nansum(dop.n_steps.values)


def test_method_is_checked():
    from rollingdisk.util.errors import ParameterError

    g = sweep.SweepGrid("rough", h=0.17, theta0=[0.5], omega30=[3.0])
    with pytest.raises(ParameterError, match="method"):
        sweep.run_sweep(g, 1.0, method="rk4")
    with pytest.raises(ParameterError, match="method"):
        sweep.basin_sweep(g, 1.0, method="euler")
