"""Nonlinear simulation (issue 4) checked against independent truth.

Sources of truth, by group:
* linear stability: the frequency of small oscillations about a stable steady motion and
  the growth rate about an unstable one must be sqrt(+-varpi^2), with varpi^2 taken from a
  finite-difference Jacobian of the reduced system (tests/steady_numeric.py), not from the
  code under test;
* steady motion (section 3): an unperturbed steady state stays steady, and C and P trace
  concentric circles, P with radius |r_P| = |r_C + y_P0| where r_C = -v_Cx0 / Omega0
  (eqs. 22-24) with v_Cx0 from the no-slip condition (eq. 37);
* invariants: energy (eq. 12-13) is conserved on both grounds;
* scipy's solve_ivp(DOP853) on the numpy right-hand side: the same steps, the same states,
  the same event times;
* guard events: states built to lift off, land on the other edge, fall flat.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rollingdisk import (
    DEFAULT_ATOL,
    DEFAULT_RTOL,
    Disk,
    Trajectory,
    energy_drift,
    fit_circle,
    growth_rate,
    jit_compile,
    oscillation_frequency,
    simulate,
    simulate_steady,
    stability,
)
from rollingdisk.model.equations import contact_force, rough_rhs, smooth_rhs
from rollingdisk.theory.steady import steady_motion, straight_line
from steady_numeric import steady_omega20, varpi2_numeric

THETA = {"rough": 3, "smooth": 5}


@pytest.fixture(scope="module", autouse=True)
def compiled():
    return jit_compile()


def circle(ground, h, theta0, omega30):
    """The steady circle of rollingdisk.theory.steady with spin component omega30 (eq. 3)."""
    m = steady_motion(Disk(h=h), ground, theta0, Omega0=omega30 / math.cos(theta0))
    # its omega20 makes d omega1/dt = 0, found independently (tests/steady_numeric.py)
    assert m.omega20 == pytest.approx(steady_omega20(h, ground, theta0, m.omega30),
                                      rel=1e-10, abs=1e-12)
    return m


def straight(ground, h, omega20):
    return straight_line(Disk(h=h), ground, omega20)


# (h, theta0, omega30): thin and thick disks, small and large theta0, both spin senses
STABLE = {
    "rough": [(0.0, 0.05, 1.5), (0.0, 0.3, 4.0), (0.0, 0.8, 0.5), (0.0, 1.3, -3.0),
              (0.05, -0.4, 1.5), (0.3, 0.8, 1.5), (0.3, 1.3, 0.5), (0.866, 0.05, 1.5),
              (0.866, 1.3, 4.0), (2.0, 0.3, 1.5), (2.0, 1.3, 0.5), (0.3, -0.4, -3.0)],
    "smooth": [(0.0, 0.3, 0.5), (0.0, 0.8, 1.5), (0.0, 1.3, 4.0), (0.0, -0.4, 0.5),
               (0.05, 0.8, -3.0), (0.3, 0.8, 0.5), (0.3, 1.3, 1.5), (0.866, 0.05, 0.5),
               (0.866, 1.3, -3.0), (2.0, 0.05, 1.5), (2.0, 0.3, 4.0), (2.0, -0.4, 0.5)],
}
STRAIGHT = {"rough": [(0.0, 1.5), (0.1, 2.0), (0.5, 2.0)],
            "smooth": [(0.0, 2.0), (0.1, 2.5), (1.0, 3.0)]}
UNSTABLE = {
    "rough": [(0.0, 0.3, 0.5), (0.3, 0.3, 0.5), (0.866, 0.3, 0.5), (2.0, 0.8, 0.5),
              (0.05, 0.05, 0.5)],
    "smooth": [(0.0, 0.05, 0.5), (0.3, 0.3, 1.5), (0.866, 0.8, 0.5), (2.0, 0.8, 0.5),
               (0.3, -0.4, 0.5)],
}


def _motions(table, straight_table):
    out = []
    for ground, rows in table.items():
        out += [pytest.param(circle(ground, *row), id=f"{ground}-{row}") for row in rows]
    for ground, rows in straight_table.items():
        out += [pytest.param(straight(ground, *row), id=f"{ground}-straight-{row}")
                for row in rows]
    return out


def _varpi2(m):
    return varpi2_numeric(m.h, m.ground, m.theta0, m.omega20, m.omega30)


# ---------------------------------------------------------------------------- linear theory
@pytest.mark.parametrize("motion", _motions(STABLE, STRAIGHT))
def test_frequency_of_small_oscillations_is_varpi(motion):
    v2 = _varpi2(motion)
    assert v2 > 0.1, "the table should list stable motions"
    period = 2 * math.pi / math.sqrt(v2)
    tr = simulate_steady(motion, 60 * period, perturb=1e-7, max_step=period / 20)
    assert tr.status == "completed"
    freq = oscillation_frequency(tr)
    assert freq == pytest.approx(math.sqrt(v2), rel=1e-6)
    assert energy_drift(tr) < 1e-12


@pytest.mark.slow
@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_frequency_matches_varpi_over_random_stable_motions(ground):
    """40 random stable circles per ground: h in [0, 3], |theta0| in [0.02, 1.45]."""
    rng = np.random.default_rng(2024 if ground == "rough" else 2025)
    done = 0
    while done < 40:
        h = float(rng.choice([0.0, rng.uniform(0, 3)]))
        theta0 = float(rng.uniform(0.02, 1.45) * rng.choice([-1, 1]))
        omega30 = float(rng.uniform(0.3, 6) * rng.choice([-1, 1]))
        m = circle(ground, h, theta0, omega30)
        v2 = _varpi2(m)
        if not 0.1 < v2 < 400:
            continue
        period = 2 * math.pi / math.sqrt(v2)
        tr = simulate_steady(m, 60 * period, perturb=1e-7, max_step=period / 20)
        if tr.status != "completed":  # e.g. F_z of the steady state is 1, so never here
            raise AssertionError(f"{ground} {h} {theta0} {omega30}: {tr.message}")
        assert oscillation_frequency(tr) == pytest.approx(math.sqrt(v2), rel=1e-6), (
            ground, h, theta0, omega30)
        done += 1


@pytest.mark.parametrize("motion", _motions(UNSTABLE, {}))
def test_growth_rate_of_unstable_motion_is_sqrt_minus_varpi2(motion):
    v2 = _varpi2(motion)
    assert v2 < -0.05, "the table should list unstable motions"
    lam = math.sqrt(-v2)
    # tiny perturbation and tight atol: 15 e-folds of linear growth before |theta~| = 1e-6
    tr = simulate_steady(motion, 25 / lam, perturb=1e-12, atol=1e-16, max_step=0.1 / lam)
    assert growth_rate(tr, max_amplitude=1e-6) == pytest.approx(lam, rel=1e-3)
    # and the motion does depart: the oscillation theory says it must
    assert np.max(np.abs(tr.theta - motion.theta0)) > 1e-3


@pytest.mark.parametrize("motion", [
    circle("rough", 0.3, 0.8, 1.5), circle("rough", 0.0, 0.3, 4.0),
    circle("rough", 0.866, 1.3, 4.0), circle("rough", 2.0, 1.3, 0.5),
    circle("smooth", 0.3, 0.8, 0.5), circle("smooth", 2.0, 0.3, 4.0)],
    ids=lambda m: f"{m.ground}-{m.h}-{m.theta0}-{m.omega30}")
def test_unperturbed_steady_motion_stays_steady_on_circles(motion):
    tr = simulate_steady(motion, 100.0, psi0=0.4, method="dop853")
    assert tr.status == "completed"
    assert np.max(np.abs(tr.theta - motion.theta0)) < 1e-9
    # expected radii from kinematics (eqs. 3, 4, 24, 37), not from the steady module
    h, th = motion.h, motion.theta0
    ht = h * np.sign(th)
    y_P0 = math.sin(th) - ht * math.cos(th)
    Omega0 = motion.omega30 / math.cos(th)
    v_Cx0 = motion.omega20 - ht * motion.omega30 if motion.ground == "rough" else 0.0
    r_C = -v_Cx0 / Omega0
    r_P = r_C + y_P0
    xa, ya, rp = fit_circle(tr.X_P, tr.Y_P)
    assert rp == pytest.approx(abs(r_P), rel=1e-8, abs=1e-10)
    dist = np.hypot(tr.X_P - xa, tr.Y_P - ya)
    assert np.max(np.abs(dist - abs(r_P))) < 1e-8
    if abs(r_C) > 1e-6:
        xc, yc, rc = fit_circle(tr.X_C, tr.Y_C)
        assert rc == pytest.approx(abs(r_C), rel=1e-8)
        assert math.hypot(xc - xa, yc - ya) < 1e-8  # concentric about A (eqs. 22, 23)
    else:
        assert np.ptp(tr.X_C) < 1e-8 and np.ptp(tr.Y_C) < 1e-8
    # steady contact force, eq. (19): F_x = 0, F_z = 1
    assert np.max(np.abs(tr.F_z - 1)) < 1e-9
    assert np.max(np.abs(tr.F_x)) < 1e-9


# ---------------------------------------------------------------------------- accuracy
@pytest.mark.parametrize("motion", [circle("rough", 0.1, 0.3, 3.0),
                                    circle("rough", 0.866, 1.0, 1.5),
                                    circle("smooth", 0.3, 0.8, 0.5)],
                         ids=["rough-thin", "rough-thick", "smooth"])
def test_default_tolerances_keep_energy_drift_below_1e9_over_1000(motion):
    tr = simulate_steady(motion, 1000.0, perturb=1e-2)
    assert tr.status == "completed"
    assert tr.t[-1] == 1000.0
    assert energy_drift(tr) < 1e-9
    # the perturbed motion does move: a non-trivial check
    assert np.ptp(tr.theta) > 1e-3


@pytest.mark.parametrize("ground,y0", [
    ("rough", [0.1, -0.2, 0.3, 0.3, 0.0, 0.2, 2.0, 0.5]),
    ("smooth", [0.0, 0.0, 0.3, -0.1, 0.2, 0.4, 0.0, 0.1, 1.5, 0.5])])
@pytest.mark.parametrize("h", [0.0, 0.25])
def test_compiled_integrator_takes_the_same_steps_as_scipy(ground, y0, h):
    disk = Disk(h=h)
    a = simulate(disk, ground, (0, 20), y0, method="dop853", rtol=1e-10, atol=1e-10)
    b = simulate(disk, ground, (0, 20), y0, method="scipy", rtol=1e-10, atol=1e-10)
    assert a.status == b.status == "completed"
    # same method, same step control: the same steps up to round-off in the error
    # estimate (a difference of nearly equal sums, so ~1e-7 relative in the step sizes)
    assert abs(a.n_steps - b.n_steps) <= 1
    assert abs(a.n_rhs - b.n_rhs) <= 13
    if a.n_steps == b.n_steps:
        np.testing.assert_allclose(a.t, b.t, rtol=1e-5)
    np.testing.assert_allclose(a.y[:, -1], b.y[:, -1], rtol=1e-8, atol=1e-8)
    assert energy_drift(a) < 1e-9


def test_compiled_rhs_matches_the_numpy_kernels():
    import sys

    core = sys.modules["rollingdisk.engine.numba_core"]
    rng = np.random.default_rng(7)
    for _ in range(50):
        h = rng.uniform(0, 2)
        for rough, n, kernel in ((True, 8, rough_rhs), (False, 10, smooth_rhs)):
            y = rng.uniform(-1.5, 1.5, n)
            out = np.empty(n)
            core._rhs(rough, h, y, out)
            np.testing.assert_allclose(out, np.array(kernel(h, y)), rtol=1e-13, atol=1e-13)
        y = rng.uniform(-1.5, 1.5, 8)
        assert core._normal_force(True, h, y) == pytest.approx(
            contact_force(Disk(h=h), "rough", y)[2], rel=1e-12, abs=1e-12)


def test_t_eval_output_matches_the_step_output():
    disk = Disk(h=0.2)
    y0 = [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5]
    te = np.linspace(0, 10, 37)
    a = simulate(disk, "rough", (0, 10), y0, t_eval=te)
    b = simulate(disk, "rough", (0, 10), y0, method="scipy", t_eval=te)
    assert a.status == b.status == "completed"
    np.testing.assert_array_equal(a.t, te)
    np.testing.assert_allclose(a.y, b.y, rtol=1e-9, atol=1e-9)
    # a run that stops exactly at each requested time agrees too
    for k in (5, 20, 36):
        c = simulate(disk, "rough", (0, te[k]), y0)
        np.testing.assert_allclose(a.y[:, k], c.y[:, -1], rtol=1e-9, atol=1e-9)


def test_progress_chunks_give_the_same_motion():
    disk = Disk(h=0.2)
    y0 = [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5]
    seen = []
    a = simulate(disk, "rough", (0, 50), y0, progress=seen.append)
    b = simulate(disk, "rough", (0, 50), y0)
    assert a.status == b.status == "completed"
    assert seen[-1] == pytest.approx(1.0) and 10 < len(seen) <= 100
    assert np.all(np.diff(seen) > 0)
    assert np.all(np.diff(a.t) > 0)
    np.testing.assert_allclose(a.y[:, -1], b.y[:, -1], rtol=1e-8, atol=1e-8)
    te = np.linspace(0, 50, 11)
    c = simulate(disk, "rough", (0, 50), y0, t_eval=te, progress=lambda f: None)
    np.testing.assert_array_equal(c.t, te)
    np.testing.assert_allclose(c.y[:, -1], b.y[:, -1], rtol=1e-8, atol=1e-8)


@pytest.mark.parametrize("t_eval", [None, np.linspace(0, 100, 37)], ids=["steps", "t_eval"])
def test_progress_takes_exactly_the_steps_of_a_plain_run(t_eval):
    # the chunks for progress() once restarted from the last output point, re-integrating
    # the tail of each chunk (1583 instead of 1302 steps here)
    disk = Disk(h=0.2)
    y0 = [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5]
    a = simulate(disk, "rough", (0, 100), y0, t_eval=t_eval)
    b = simulate(disk, "rough", (0, 100), y0, t_eval=t_eval, progress=lambda f: None)
    assert a.status == b.status == "completed"
    assert a.n_steps == b.n_steps
    assert b.n_rhs - a.n_rhs <= 100  # f once more at each pause, nothing else
    np.testing.assert_array_equal(a.t, b.t)
    np.testing.assert_array_equal(a.y, b.y)


def test_t_eval_output_is_the_dense_output_of_scipys_dop853():
    from scipy.integrate import solve_ivp

    from rollingdisk import equations_of_motion

    disk = Disk(h=0.2)
    y0 = [0, 0, 0, 0.3, 0, 0.05, 2.0, 0.5]
    te = np.linspace(0, 100, 2001)
    a = simulate(disk, "rough", (0, 100), y0, t_eval=te, method="dop853")
    ref = solve_ivp(equations_of_motion(disk, "rough"), (0, 100), y0, method="DOP853",
                    rtol=DEFAULT_RTOL, atol=DEFAULT_ATOL, t_eval=te)
    np.testing.assert_array_equal(a.t, te)
    scale = np.max(np.abs(ref.y), axis=1, keepdims=True)
    assert np.max(np.abs(a.y - ref.y) / scale) < 1e-11
    # dense output: 3 evaluations per step, not a 12-stage step per requested time
    b = simulate(disk, "rough", (0, 100), y0, method="dop853")
    assert a.n_steps == b.n_steps
    assert a.n_rhs <= b.n_rhs + 3 * b.n_steps < b.n_rhs + 12 * te.size


def test_thin_disk_passes_through_theta_zero():
    # h = 0: theta = 0 is an ordinary state (upright), no edge contact
    y0 = [0, 0, 0, 0.05, 0, -0.5, 1.5, 0]  # rolling, tipping through upright
    tr = simulate(Disk(h=0.0), "rough", (0, 50), y0)
    assert tr.status == "completed"
    assert tr.theta.min() < -0.04 and tr.theta.max() > 0.04
    assert energy_drift(tr) < 1e-10


# ---------------------------------------------------------------------------- guard events
GUARD_CASES = [
    # a disk falling with no spin from a moderate lean lifts off before it is flat
    ("lift-off", 0.0, "rough", [0, 0, 0, 0.3, 0, 0.9, 0, 0]),
    ("lift-off", 0.5, "rough", [0, 0, 0, 0.6, 0, 0, 0, 0]),
    # on smooth ground a falling disk reaches theta = pi/2 in contact
    ("fell-flat", 0.1, "smooth", [0, 0, 0, 0, 0, 0.5, 0, 0, 0, 0]),
    ("fell-flat", 0.0, "smooth", [0, 0, 0, 0, 0, 0.3, 0, 0.9, 0, 0]),
    # a thick disk tipping back toward theta = 0 lands on its other edge
    ("edge-contact", 0.2, "rough", [0, 0, 0, 0.1, 0, -0.5, 1.0, 0]),
    ("edge-contact", 0.2, "smooth", [0, 0, 0, 0, 0, 0.1, 0, -0.5, 1.0, 0]),
    ("edge-contact", 0.3, "rough", [0, 0, 0, -0.1, 0, 0.3, 1.0, 0]),
]


@pytest.mark.parametrize("status,h,ground,y0", GUARD_CASES)
def test_guard_events_stop_the_run(status, h, ground, y0):
    disk = Disk(h=h)
    a = simulate(disk, ground, (0, 20), y0)
    b = simulate(disk, ground, (0, 20), y0, method="scipy")
    assert a.status == b.status == status
    assert a.t_event == pytest.approx(b.t_event, rel=1e-9, abs=1e-9)
    assert a.t[-1] == a.t_event < 20
    assert status.split("-")[0] in a.message.replace("fell flat", "fell-flat").split(" ")[0]
    Fz = a.F_z
    theta = a.theta
    # never integrated through: admissible at every stored point
    assert np.all(Fz[:-1] > 0) and Fz[-1] > -1e-9
    assert np.all(np.abs(theta) < math.pi / 2)
    if h > 0:
        assert np.all(np.sign(theta) == np.sign(y0[THETA[ground]]))
    if status == "lift-off":
        assert abs(Fz[-1]) < 1e-9
    elif status == "fell-flat":
        assert abs(theta[-1]) == pytest.approx(math.pi / 2, abs=1e-9)
    else:
        assert abs(theta[-1]) < 1e-9
    assert energy_drift(a) < 1e-9


def test_start_with_negative_normal_force_is_immediate_lift_off():
    y0 = [0, 0, 0, 0.1, 0, 2.0, 0, 0]  # fast tipping near upright: F_z < 0 already
    assert contact_force(Disk(h=0.0), "rough", y0)[2] < 0
    for method in ("dop853", "scipy"):
        tr = simulate(Disk(h=0.0), "rough", (0, 1), y0, method=method)
        assert tr.status == "lift-off" and tr.t_event == 0.0 and tr.t.size == 1


def test_guards_off_integrates_through():
    tr = simulate(Disk(h=0.2), "rough", (0, 0.3), [0, 0, 0, 0.1, 0, -0.5, 1.0, 0],
                  guards=False)
    assert tr.status == "completed" and tr.theta[-1] < 0


def test_user_events_run_through_scipy():
    def half(t, y):
        return y[3] - 0.35

    half.terminal = True
    half.direction = 1
    y0 = [0, 0, 0, 0.3, 0, 0.1, 2.0, 0.5]
    tr = simulate(Disk(h=0.1), "rough", (0, 20), y0, events=half)
    assert tr.method == "scipy" and tr.status == "completed"
    assert tr.theta[-1] == pytest.approx(0.35, abs=1e-10)
    assert "user event 0" in tr.message
    assert len(tr.t_events) == 1 and tr.t_events[0][0] == pytest.approx(tr.t[-1])
    with pytest.raises(ValueError, match="events"):
        simulate(Disk(h=0.1), "rough", (0, 20), y0, events=half, method="dop853")


def _time_event(at, terminal):
    def event(t, y):
        return t - at

    event.terminal = terminal
    return event


@pytest.mark.parametrize("t_eval", [None, np.linspace(0, 20, 81)], ids=["steps", "t_eval"])
def test_only_a_terminal_user_event_stops_the_run(t_eval):
    # a non-terminal event was once reported as the one that stopped the run, and its time
    # appended to t after the end
    y0 = [0, 0, 0, 0.3, 0, 0.1, 2.0, 0.5]
    tr = simulate(Disk(h=0.1), "rough", (0, 20), y0, t_eval=t_eval,
                  events=[_time_event(1.0, False), _time_event(3.0, True)])
    assert tr.status == "completed"
    assert np.all(np.diff(tr.t) > 0)
    assert tr.t[-1] == pytest.approx(3.0, abs=1e-12)
    assert "stopped by user event 1 at t = 3" in tr.message
    assert len(tr.t_events) == 2
    np.testing.assert_allclose(tr.t_events[0], [1.0], atol=1e-12)
    np.testing.assert_allclose(tr.t_events[1], [3.0], atol=1e-12)


def test_a_user_event_with_a_terminal_count_stops_at_that_count():
    def wave(t, y):
        return math.sin(math.pi * (t + 0.5))  # zero at t = 0.5, 1.5, 2.5, ...

    wave.terminal = 2  # solve_ivp: stop at the 2nd occurrence
    y0 = [0, 0, 0, 0.3, 0, 0.1, 2.0, 0.5]
    tr = simulate(Disk(h=0.1), "rough", (0, 20), y0, events=[_time_event(1.0, False), wave])
    assert tr.t[-1] == pytest.approx(1.5, abs=1e-10)
    assert "user event 1 at t = 1.5" in tr.message
    np.testing.assert_allclose(tr.t_events[1], [0.5, 1.5], atol=1e-10)


# ---------------------------------------------------------------------------- measurements
def test_fit_circle_is_exact_on_a_circle():
    a = np.linspace(0.3, 2.0, 17)
    x, y, r = fit_circle(1e3 + 2.5 * np.cos(a), -7 + 2.5 * np.sin(a))
    assert (x, y, r) == pytest.approx((1e3, -7, 2.5), rel=1e-12)
    with pytest.raises(ValueError):
        fit_circle([0, 1], [0, 1])


def test_oscillation_frequency_none_without_oscillation():
    tr = simulate(Disk(h=0.1), "rough", (0, 0.5), [0, 0, 0, 0.5, 0, 0, 0, 0])
    assert oscillation_frequency(tr) is None


# ---------------------------------------------------------------------------- the result
def test_trajectory_is_frozen_and_named():
    y0 = [0, 0, 0, 0.3, 0, 0.1, 2.0, 0.5]
    tr = simulate(Disk(h=0.1), "rough", (0, 1), y0, method="dop853")
    assert isinstance(tr, Trajectory)
    with pytest.raises(AttributeError):
        tr.status = "x"
    with pytest.raises(ValueError):
        tr.t[0] = 1.0
    np.testing.assert_array_equal(tr.theta, tr.y[3])
    np.testing.assert_array_equal(tr.omega3, tr.y[7])
    with pytest.raises(ValueError):
        tr.V_X  # noqa: B018 - rough ground has no V_X in its state
    cols = tr.as_columns()
    assert list(cols) == ["t", "X_C", "Y_C", "psi", "theta", "phi", "omega1", "omega2",
                          "omega3", "X_P", "Y_P", "F_x", "F_y", "F_z", "E"]
    assert all(v.shape == tr.t.shape for v in cols.values())
    assert tr.wall_time >= 0 and tr.n_rhs > tr.n_steps > 0


def test_simulate_steady_perturbs_theta_only():
    m = circle("rough", 0.1, 0.3, 3.0)
    tr = simulate_steady(m, 1.0, perturb=1e-3)
    y0 = m.initial_state()
    y0[3] += 1e-3
    np.testing.assert_array_equal(tr.y[:, 0], y0)
    assert tr.theta_ref == 0.3 and tr.motion is m
    assert tr.disk == m.disk


def test_simulate_steady_keeps_the_disk_of_the_motion():
    # real objects all the way: a physical disk (radius, mass) through steady_motion and
    # straight_line into the trajectory, whose SI conversions need them
    disk = Disk(h=0.1, radius=0.05, mass=0.2)
    for m in (steady_motion(disk, "rough", 0.3, Omega0=3.0),
              straight_line(disk, "smooth", 1.0)):
        assert m.disk is disk and m.h == 0.1
        tr = simulate_steady(m, 1.0, perturb=1e-3)
        assert tr.disk is disk and tr.disk.radius == 0.05 and tr.disk.mass == 0.2


@pytest.mark.parametrize("theta0,perturb", [(0.3, -0.3), (0.3, 1.3), (-1.2, -0.4)])
def test_simulate_steady_names_perturb_when_it_leaves_the_model(theta0, perturb):
    m = circle("rough", 0.1, theta0, 3.0)
    with pytest.raises(ValueError, match=r"^perturb must lie in \(") as info:
        simulate_steady(m, 1.0, perturb=perturb)
    assert "y0" not in str(info.value)
    # kick changes omega1 only: theta(0) stays admissible
    assert simulate_steady(m, 0.1, kick=5.0).status in ("completed", "lift-off")


# ---------------------------------------------------------------------------- validation
@pytest.mark.parametrize("kwargs,match", [
    (dict(ground="ice"), "ground"),
    (dict(y0=[0, 0, 0, 0.3, 0, 0, 2.0]), "y0"),
    (dict(y0=[0, 0, 0, np.nan, 0, 0, 2.0, 0.5]), "y0"),
    (dict(y0=[0, 0, 0, 1.6, 0, 0, 2.0, 0.5]), "theta"),
    (dict(y0=[0, 0, 0, 0.0, 0, 0, 2.0, 0.5]), "theta"),
    (dict(t_span=(1, 1)), "t_span"),
    (dict(t_span=(2, 1)), "t_span"),
    (dict(t_span=(0, np.inf)), "t_span"),
    (dict(t_span=5), "t_span"),
    (dict(rtol=0), "rtol"),
    (dict(atol=-1e-9), "atol"),
    (dict(rtol=np.nan), "rtol"),
    (dict(max_step=0), "max_step"),
    (dict(method="rk4"), "method"),
    (dict(t_eval=[0.5, 0.2]), "t_eval"),
    (dict(t_eval=[0.5, 7]), "t_eval"),
    (dict(max_steps=0), "max_steps"),
])
def test_invalid_input_raises_valueerror_naming_the_parameter(kwargs, match):
    args = dict(disk=Disk(h=0.1), ground="rough", y0=[0, 0, 0, 0.3, 0, 0, 2.0, 0.5],
                t_span=(0, 1))
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        simulate(args.pop("disk"), args.pop("ground"), args.pop("t_span"), args.pop("y0"),
                 **args)


def test_simulate_steady_rejects_non_motions():
    with pytest.raises(TypeError, match="SteadyMotion"):
        simulate_steady(object(), 1.0)
    with pytest.raises(ValueError, match="t_end"):
        simulate_steady(circle("rough", 0.1, 0.3, 3.0), -1.0)


def test_the_integrator_needs_no_private_scipy_module():
    """The DOP853 table is the library's own: with scipy's private table blocked, the
    integrator (uncompiled and compiled source alike) still imports and runs."""
    import os
    import subprocess
    import sys

    import rollingdisk

    code = ("import sys\n"
            "sys.modules['scipy.integrate._ivp.dop853_coefficients'] = None\n"
            "import rollingdisk as rd, rollingdisk.engine.dop853 as d\n"
            "tr = rd.simulate(rd.Disk(h=0.1), 'rough', (0, 1.0),"
            " [0, 0, 0, 0.3, 0, 0, 0.2, 3.0], method='dop853')\n"
            "assert tr.status == 'completed', tr.status\n"
            "print(d._NS, d._NSX)\n")
    src = os.path.dirname(os.path.dirname(rollingdisk.__file__))
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=dict(os.environ, PYTHONPATH=src))
    assert res.returncode == 0, res.stderr
    assert res.stdout.split() == ["12", "16"]


def test_import_is_light_and_the_core_needs_no_sympy_or_matplotlib():
    import subprocess
    import sys

    code = ("import sys\n"
            "sys.modules['sympy'] = None\nsys.modules['matplotlib'] = None\n"
            "import rollingdisk\n"
            "assert 'numba' not in sys.modules, 'import rollingdisk must not load numba'\n"
            "tr = rollingdisk.simulate(rollingdisk.Disk(h=0.1), 'rough',"
            " (0, 1), [0, 0, 0, 0.3, 0, 0, 2.0, 0.5])\n"
            "assert tr.status == 'completed'\n"
            "assert 'numba' not in sys.modules, 'a short run is not worth loading numba'\n"
            "assert 'scipy.integrate' not in sys.modules\n")
    import os

    import rollingdisk

    src = os.path.dirname(os.path.dirname(rollingdisk.__file__))
    env = dict(os.environ, PYTHONPATH=src)
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert res.returncode == 0, res.stderr


@pytest.mark.parametrize("t_eval", [None, np.linspace(1, 20, 50), np.linspace(0.05, 0.15, 5),
                                    np.linspace(0, 0.15, 4)])
def test_event_output_is_the_same_with_and_without_progress_chunks(t_eval):
    y0 = [0, 0, 0, 0.1, 0, -0.5, 1.0, 0]  # lands on its other edge at t ~ 0.2
    a = simulate(Disk(h=0.2), "rough", (0, 20), y0, t_eval=t_eval)
    b = simulate(Disk(h=0.2), "rough", (0, 20), y0, t_eval=t_eval, progress=lambda f: None)
    assert a.status == b.status == "edge-contact"
    assert a.t_event == pytest.approx(b.t_event, abs=1e-12)
    if t_eval is not None:
        np.testing.assert_allclose(a.t, b.t, atol=1e-12)
        np.testing.assert_allclose(a.y, b.y, atol=1e-10)
        expected = [t for t in t_eval if t <= a.t_event] + [a.t_event]
        np.testing.assert_allclose(a.t, expected, atol=1e-12)


# ---------------------------------------------------------------------------- steady module
# (ground, h, theta0, kind, value): circles given Omega0 or r_C, straight lines given omega0
STEADY_ROWS = [
    ("rough", 0.1, 0.3, "Omega0", 2.0), ("rough", 0.5, 1.0, "Omega0", -3.0),
    ("rough", 0.0, 0.8, "r_C", 1.5), ("rough", 2.0, 1.2, "Omega0", 1.0),
    ("rough", 0.3, 0.3, "r_C", 2.0), ("rough", 0.0, 0.3, "Omega0", 0.5),
    ("smooth", 0.3, 0.8, "Omega0", 1.0), ("smooth", 0.0, 0.5, "Omega0", 3.0),
    ("smooth", 0.3, 0.3, "Omega0", 1.5), ("smooth", 1.0, 1.2, "Omega0", -2.0),
    ("rough", 0.1, None, "omega0", 2.0), ("rough", 0.1, None, "omega0", 0.3),
    ("smooth", 0.5, None, "omega0", 3.0),
]


@pytest.mark.parametrize("row", STEADY_ROWS, ids=str)
def test_simulation_confirms_the_stability_module(row):
    """Closed-form varpi^2 of rollingdisk.stability vs the simulated motion (both ways)."""
    from rollingdisk.theory.steady import steady_motion, straight_line

    ground, h, theta0, kind, value = row
    disk = Disk(h=h)
    if kind == "omega0":
        m = straight_line(disk, ground, value)
    else:
        m = steady_motion(disk, ground, theta0, **{kind: value})
    st = stability(m)
    # independent linearization: the finite-difference Jacobian of tests/steady_numeric.py
    assert st.varpi2 == pytest.approx(_varpi2(m), rel=1e-6, abs=1e-9)
    if st.stable:
        period = 2 * math.pi / st.varpi
        tr = simulate_steady(m, 60 * period, perturb=1e-7, max_step=period / 20)
        assert tr.status == "completed"
        assert oscillation_frequency(tr) == pytest.approx(st.varpi, rel=1e-6)
    else:
        lam = st.growth_rate
        tr = simulate_steady(m, 25 / lam, perturb=1e-12, atol=1e-16, method="dop853")
        assert growth_rate(tr) == pytest.approx(lam, rel=1e-3)
    if not st.stable:
        return  # round-off grows on an unstable one
    # unperturbed: it stays on its steady motion; P on its circle of radius |r_P|
    tr0 = simulate_steady(m, 20.0, method="dop853")
    assert np.max(np.abs(tr0.theta - m.theta0)) < 1e-9
    if kind != "omega0":
        assert fit_circle(tr0.X_P, tr0.Y_P)[2] == pytest.approx(abs(m.r_P), rel=1e-8,
                                                                 abs=1e-10)


# ---------------------------------------------------------------------------- issue 8
_LIFT_IN_STEP = [0, 0, 0, -0.7679, 0, -0.8403, -1.2908, 1.1468]  # h = 1


@pytest.mark.parametrize("method", ["dop853", "scipy"])
def test_every_option_means_the_same_on_both_paths(method):
    y0 = [0, 0, 0, 0.3, 0, 0, 2.0, 0.5]
    seen = []
    tr = simulate(Disk(h=0.1), "rough", (0, 10), y0, method=method, max_steps=3,
                  progress=seen.append)
    assert tr.status == "step-budget" and tr.n_steps == 3 and not tr.success
    assert seen and seen[-1] < 1
    seen = []
    tr = simulate(Disk(h=0.1), "rough", (0, 10), y0, method=method, progress=seen.append,
                  dense_output=True)
    assert tr.status == "completed" and seen[-1] == 1.0 and np.all(np.diff(seen) >= 0)
    # dense output interpolates the stored steps exactly at their ends
    assert np.allclose(tr.sol(tr.t[5]), tr.y[:, 5], rtol=0, atol=1e-12)
    chunks = []
    streamed = simulate(Disk(h=0.1), "rough", (0, 10), y0, method=method,
                        sink=lambda t, y: chunks.append((t, y)))
    assert np.array_equal(np.concatenate([c[0] for c in chunks]), tr.t)
    assert streamed.t.tolist() == [tr.t[0], tr.t[-1]]


@pytest.mark.parametrize("method", ["dop853", "scipy"])
def test_lift_off_inside_one_step_is_found_at_loose_tolerance(method):
    # F_z dips to about -0.008 inside one step near t = 0.0106 (found by a robustness
    # sweep); guards sampled only at step ends missed it and ran on to t = 2.376
    tr = simulate(Disk(h=1.0), "rough", (0, 30), _LIFT_IN_STEP, method=method, rtol=1e-6,
                  atol=1e-8)
    assert tr.status == "lift-off" and tr.t_event < 0.011
    # the same event as at tight tolerance
    ref = simulate(Disk(h=1.0), "rough", (0, 30), _LIFT_IN_STEP, method=method)
    assert ref.status == "lift-off" and tr.t_event == pytest.approx(ref.t_event, abs=1e-6)


@pytest.mark.parametrize("method", ["dop853", "scipy"])
def test_edge_contact_is_not_reported_as_lift_off(method):
    # theta reaches 0, where h~ = h sgn(theta) makes F_z jump below 0: an edge contact
    tr = simulate(Disk(h=3.0), "rough", (0, 20), [0, 0, 0, 0.1, 0, -0.2, -2, -0.3],
                  method=method)
    assert tr.status == "edge-contact" and tr.t_event == pytest.approx(0.4241435, abs=1e-6)
    assert tr.F_z[-1] > 0 and tr.theta[-1] > 0


@pytest.mark.parametrize("method", ["dop853", "scipy"])
def test_lift_off_at_the_start_with_t_eval_gives_one_point(method):
    tr = simulate(Disk(h=0.1), "rough", (0, 1), [0, 0, 0, 0.3, 0, 10.0, 0, 0], method=method,
                  t_eval=[0.0, 0.5])
    assert tr.status == "lift-off" and tr.t.tolist() == [0.0]


@pytest.mark.parametrize("kwargs,match", [
    (dict(y0=[0, 0, 0, 0.3, 0, 0, 1e300, 0]), "too large"),
    (dict(y0=[0, 0, 0, 0.3, 0, math.nan, 1, 0]), "finite"),
    (dict(t_span=(0, 1e300)), "t_span"),
    (dict(rtol=2.0), "rtol"),
    (dict(rtol=1e-17), "rtol"),
])
def test_absurd_inputs_are_refused(kwargs, match):
    args = dict(t_span=(0, 1), y0=[0, 0, 0, 0.3, 0, 0, 2.0, 0.5])
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        simulate(Disk(h=0.1), "rough", args.pop("t_span"), args.pop("y0"), **args)


@pytest.mark.parametrize("method", ["dop853", "scipy"])
def test_a_first_step_of_zero_is_a_status_not_an_exception(method):
    m = steady_motion(Disk(h=0.1), "rough", 0.3, Omega0=1e100)
    tr = simulate_steady(m, 1.0, method=method)
    assert tr.status == "failed" and tr.message.startswith("failed")


def test_public_functions_validate_their_arguments():
    from rollingdisk import ParameterError, ParameterTypeError, energy, equations_of_motion

    with pytest.raises(ParameterTypeError, match="disk"):
        contact_force(None, "rough", [0, 0, 0, 0.3, 0, 0, 1, 0])
    with pytest.raises(ParameterError, match="8 components"):
        equations_of_motion(Disk(h=0.1), "rough")(0, None)
    with pytest.raises(ParameterError, match="finite"):
        energy(Disk(h=0.1), "rough", [0, 0, 0, math.nan, 0, 0, 1, 0])


def test_compare_with_theory_one_rule_for_both_kinds():
    from rollingdisk import compare_with_theory

    stable = steady_motion(Disk(h=0.1), "rough", 0.3, Omega0=3.0)
    c = compare_with_theory(simulate_steady(stable, 40.0, perturb=1e-6))
    assert c.kind == "frequency" and c.rel_error < 1e-3
    s = stability(stable)
    assert c.predicted == pytest.approx(s.varpi)
    with pytest.raises(TypeError):
        compare_with_theory(simulate(Disk(h=0.1), "rough", (0, 1), stable.initial_state()))
