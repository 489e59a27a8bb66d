"""The engine's contract (docs/architecture.md, "Adding a model"), held to closed forms.

Models that are not a disk -- a bouncing ball, a pendulum hitting a wall, an oscillator, a
driven quadrature -- are plugged through :class:`rollingdisk.engine.contract.Model` into the
one DOP853 step loop, compiled and uncompiled, and their events, impacts and energies are
compared with exact solutions: the bounce times of a ball are a geometric series summing to
the Zeno time, its apex heights fall as e^(2n); the pendulum's impact times are sums of
complete elliptic integrals K(k) with k = e^n sin(theta0 / 2).  Both models run through the
same compiled loop object: a new phase needs no new loop.  The disk itself, plugged in the
same way, takes the very steps of its own compiled DOP853.
"""

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy.special import ellipk

from rollingdisk.engine.contract import CONTINUE, Model
from rollingdisk.engine.driver import solve
from rollingdisk.model.equations import _rough_omega_dot, _rough_rhs
from rollingdisk.model.outcomes import AT_REST
from rollingdisk.util.errors import ParameterError, ParameterTypeError

#: The compiled path loads (or compiles) the one step loop and each model's functions:
#: seconds to a minute, so it runs with the slow checks.
PATHS = [pytest.param(False, id="python"),
         pytest.param(True, id="compiled", marks=pytest.mark.slow)]
FEW = settings(max_examples=4, deadline=None)
TOL = 1e-10

# ------------------------------------------------------------------ a bouncing ball
# state: height above the floor, vertical velocity; p = (g, e, v_rest)
Z, V = 0, 1
G, E, V_REST = 0, 1, 2


def ball_rhs(t, y, p, out):
    out[Z] = y[V]
    out[V] = -p[G]


def ball_events(t, y, p, g):
    g[0] = y[Z]  # the floor: falls through 0
    g[1] = y[V]  # the apex: the velocity falls through 0


def ball_impact(k, t, y, p, out):
    out[Z] = y[Z]
    out[V] = -p[E] * y[V]
    if out[V] < p[V_REST]:
        return AT_REST
    return CONTINUE


def ball_energy(t, y, p):
    return 0.5 * y[V] * y[V] + p[G] * y[Z]


BALL = Model("bouncing ball", ("z", "v"), ball_rhs, ball_events, ("floor", "apex"), (-1, -1),
             ("impact", "record"), ball_impact, ball_energy)


def ball_closed_form(h0, g, e, n):
    """Times of the first n bounces and the Zeno time, from rest at height h0."""
    t1 = math.sqrt(2.0 * h0 / g)
    v1 = g * t1
    times = [t1]
    for j in range(1, n):
        times.append(times[-1] + 2.0 * e ** j * v1 / g)
    return np.array(times), t1 + 2.0 * e * v1 / (g * (1.0 - e))


@pytest.mark.parametrize("compiled", PATHS)
@FEW
@given(e=st.floats(0.3, 0.95), h0=st.floats(0.1, 10.0), g=st.floats(1.0, 20.0))
def test_ball_bounces_apexes_and_energy(compiled, e, h0, g):
    n = 8
    times, t_zeno = ball_closed_form(h0, g, e, n + 1)
    t_end = times[n - 1] + 0.75 * (times[n] - times[n - 1])  # past the n-th apex
    sol = solve(BALL, (0.0, t_end), [h0, 0.0], [g, e, 0.0], rtol=1e-12, atol=1e-12,
                compiled=compiled)
    assert sol.status == "completed" and sol.message.startswith("reached the end time")
    floor = sol.event_index == 0
    apex = sol.event_index == 1
    assert floor.sum() == n and apex.sum() == n
    np.testing.assert_allclose(sol.event_t[floor], times[:n], rtol=0, atol=TOL * (1 + t_zeno))
    # apex j (after bounce j) at e^(2j) h0, half-way between the bounces
    np.testing.assert_allclose(sol.event_y[apex, Z], h0 * e ** (2 * np.arange(1, n + 1)),
                               rtol=0, atol=TOL * h0)
    np.testing.assert_allclose(sol.event_t[apex], 0.5 * (times[:n] + times[1:]),
                               rtol=0, atol=TOL * (1 + t_zeno))
    # each impact keeps e^2 of the energy; between impacts the energy is conserved
    np.testing.assert_allclose(sol.energy_after[floor] / sol.energy_before[floor], e * e,
                               rtol=TOL)
    np.testing.assert_allclose(sol.energy_before[floor][1:], sol.energy_after[floor][:-1],
                               rtol=TOL)
    # the output jumps at an impact: the state before and after at the same time
    i = np.flatnonzero(sol.t == sol.event_t[floor][0])
    assert i.size == 2 and sol.y[i[1], V] == -e * sol.y[i[0], V]


@pytest.mark.parametrize("compiled", PATHS)
@FEW
@given(e=st.floats(0.3, 0.9), v_rest=st.floats(1e-3, 0.1))
def test_ball_comes_to_rest_short_of_the_zeno_time(compiled, e, v_rest):
    """The impact map ends the run (at-rest) at the first bounce leaving slower than
    v_rest: the bounce N = ceil(log(v_rest / v1) / log e) of the geometric series, whose
    remainder to the Zeno time is 2 e^N v1 / (g (1 - e))."""
    h0, g = 1.0, 9.81
    v1 = math.sqrt(2.0 * g * h0)
    x = math.log(v_rest / v1) / math.log(e)
    assume(abs(x - round(x)) > 1e-6)
    n = math.ceil(x)
    times, t_zeno = ball_closed_form(h0, g, e, n)
    sol = solve(BALL, (0.0, 2.0 * t_zeno), [h0, 0.0], [g, e, v_rest], rtol=1e-12, atol=1e-12,
                compiled=compiled)
    assert sol.status == "at-rest", sol.message
    assert "floor" in sol.message
    assert np.count_nonzero(sol.event_index == 0) == n
    assert abs(sol.t[-1] - times[-1]) <= TOL * (1 + t_zeno)
    assert abs((t_zeno - sol.t[-1]) - 2.0 * e ** n * v1 / (g * (1.0 - e))) <= TOL * (1 + t_zeno)


# ------------------------------------------------------------------ a pendulum and a wall
# state: angle from the vertical (the wall at 0), angular velocity; p = (omega0^2, e)
TH, OM = 0, 1
W2 = 0


def pend_rhs(t, y, p, out):
    out[TH] = y[OM]
    out[OM] = -p[W2] * math.sin(y[TH])


def pend_events(t, y, p, g):
    g[0] = y[TH]  # the wall
    g[1] = y[OM]  # the turning point


def pend_impact(k, t, y, p, out):
    out[TH] = y[TH]
    out[OM] = -p[1] * y[OM]
    return CONTINUE


def pend_energy(t, y, p):
    return 0.5 * y[OM] * y[OM] + p[W2] * (1.0 - math.cos(y[TH]))


PENDULUM = Model("pendulum at a wall", ("theta", "omega"), pend_rhs, pend_events,
                 ("wall", "turn"), (-1, -1), ("impact", "record"), pend_impact, pend_energy)


@pytest.mark.parametrize("compiled", PATHS)
@FEW
@given(theta0=st.floats(0.2, 2.8), e=st.floats(0.5, 0.95), w0=st.floats(0.5, 3.0))
def test_pendulum_impacts_follow_the_elliptic_integral(compiled, theta0, e, w0):
    """From rest at theta0 the pendulum reaches the wall after K(k0)/w0, k0 = sin(theta0/2);
    it leaves with e times the speed, so k_n = e^n k0, and returns after 2 K(k_n)/w0; it
    turns at 2 arcsin(k_n)."""
    n = 5
    k = math.sin(0.5 * theta0) * e ** np.arange(n)
    times = (ellipk(k[0] ** 2) + np.concatenate(([0.0], np.cumsum(2.0 * ellipk(k[1:] ** 2))))) / w0
    t_end = times[-1] + 0.5 * ellipk(k[-1] ** 2) / w0
    sol = solve(PENDULUM, (0.0, t_end), [theta0, 0.0], [w0 * w0, e], rtol=1e-13, atol=1e-13,
                compiled=compiled)
    assert sol.status == "completed", sol.message
    wall = sol.event_index == 0
    turn = sol.event_index == 1
    np.testing.assert_allclose(sol.event_t[wall], times, rtol=0, atol=TOL * (1 + t_end))
    np.testing.assert_allclose(sol.event_y[turn, TH], 2.0 * np.arcsin(k[1:]), rtol=0, atol=TOL)
    np.testing.assert_allclose(sol.event_t[turn], times[:-1] + ellipk(k[1:] ** 2) / w0,
                               rtol=0, atol=TOL * (1 + t_end))
    np.testing.assert_allclose(sol.energy_after[wall] / sol.energy_before[wall], e * e,
                               rtol=TOL)
    np.testing.assert_allclose(sol.energy_before[wall][1:], sol.energy_after[wall][:-1],
                               rtol=TOL)


# ------------------------------------------------------------------ compiled = uncompiled
@pytest.mark.parametrize("model, y0, p, t_end", [
    (BALL, [2.0, 1.0], [9.81, 0.7, 0.0], 3.0),
    (PENDULUM, [2.5, 0.0], [4.0, 0.8], 12.0),
    # e = 1e-12: the amplitude falls into subnormal numbers, where the Illinois secant
    # divides 0 by 0 (bisection then, on both paths)
    (PENDULUM, [2.5, 0.0], [4.0, 1e-12], 45.0),
])
def test_compiled_and_uncompiled_take_the_same_steps(model, y0, p, t_end):
    a = solve(model, (0.0, t_end), y0, p, rtol=1e-11, atol=1e-11, compiled=False)
    b = solve(model, (0.0, t_end), y0, p, rtol=1e-11, atol=1e-11, compiled=True)
    assert (a.n_steps, a.n_rhs, a.status) == (b.n_steps, b.n_rhs, b.status)
    np.testing.assert_array_equal(a.event_index, b.event_index)
    np.testing.assert_allclose(b.t, a.t, rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(b.y, a.y, rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(b.event_t, a.event_t, rtol=1e-14, atol=1e-15)
    assert a.status == "completed"


def test_every_model_runs_through_one_compiled_loop():
    """The proof that a new phase needs no new loop: the ball, the pendulum and the
    oscillator below run through the same compiled loop, compiled once."""
    from rollingdisk.engine import steploop_numba

    for model, y0, p in ((BALL, [1.0, 0.0], [9.81, 0.5, 0.0]),
                         (PENDULUM, [1.0, 0.0], [1.0, 0.5]), (OSC, [1.0, 0.0], [])):
        solve(model, (0.0, 2.0), y0, p, compiled=True)
    assert len(steploop_numba.loop().signatures) == 1


# ------------------------------------------------------------------ directions, terminal
def osc_rhs(t, y, p, out):
    out[0] = y[1]
    out[1] = -y[0]


def osc_events(t, y, p, g):
    g[0] = y[0]
    g[1] = y[0]
    g[2] = y[0]
    g[3] = y[1] - 0.5  # terminal: the velocity falls through 1/2 at t = 2 pi - pi / 6


OSC = Model("harmonic oscillator", ("x", "v"), osc_rhs, osc_events,
            ("down", "up", "both", "stop"), (-1, 1, 0, -1),
            ("record", "record", "record", "terminal"))


@pytest.mark.parametrize("compiled", PATHS)
def test_event_directions_and_a_terminal_event(compiled):
    """x = cos t falls through 0 at pi/2 and rises through it at 3 pi/2; v = -sin t falls
    through 1/2 at 2 pi - pi/6 (after rising through it at pi + pi/6, ignored)."""
    sol = solve(OSC, (0.0, 10.0), [1.0, 0.0], [], rtol=1e-12, atol=1e-12, compiled=compiled)
    assert sol.status == "completed"
    assert sol.message.startswith("terminal event 'stop'")
    got = {sol_k: sol.event_t[sol.event_index == sol_k] for sol_k in range(4)}
    np.testing.assert_allclose(got[0], [0.5 * np.pi], atol=TOL)
    np.testing.assert_allclose(got[1], [1.5 * np.pi], atol=TOL)
    np.testing.assert_allclose(got[2], [0.5 * np.pi, 1.5 * np.pi], atol=TOL)
    np.testing.assert_allclose(got[3], [2.0 * np.pi - np.pi / 6.0], atol=TOL)
    assert sol.t[-1] == sol.event_t[-1]


def drive_rhs(t, y, p, out):
    out[0] = math.cos(p[0] * t)


DRIVEN = Model("driven quadrature", ("y",), drive_rhs)


@pytest.mark.parametrize("compiled", PATHS)
def test_a_time_dependent_right_hand_side_sees_each_stage_time(compiled):
    """y' = cos(w t): y = sin(w t) / w; a stage evaluated at the wrong time would be off by
    O(dt)."""
    sol = solve(DRIVEN, (0.0, 20.0), [0.0], [3.0], rtol=1e-12, atol=1e-12, compiled=compiled)
    np.testing.assert_allclose(sol.y[:, 0], np.sin(3.0 * sol.t) / 3.0, rtol=0, atol=TOL)
    assert sol.event_t.size == 0 and np.isnan(sol.energy_before).all()


@pytest.mark.parametrize("compiled", PATHS)
def test_the_step_budget_ends_a_run(compiled):
    sol = solve(OSC, (0.0, 10.0), [1.0, 0.0], [], max_steps=3, compiled=compiled)
    assert sol.status == "step-budget" and sol.n_steps == 3
    assert "max_steps = 3" in sol.message


def test_bad_models_and_arguments_are_named():
    with pytest.raises(ParameterError, match="directions"):
        Model("m", ("x",), osc_rhs, osc_events, ("a",), (2,), ("record",))
    with pytest.raises(ParameterError, match="impact"):
        Model("m", ("x",), osc_rhs, osc_events, ("a",), (1,), ("impact",))
    with pytest.raises(ParameterError, match="actions"):
        Model("m", ("x",), osc_rhs, osc_events, ("a",), (1,), ("bounce",))
    with pytest.raises(ParameterError, match="distinct"):
        Model("m", ("x", "x"), osc_rhs)
    with pytest.raises(ParameterTypeError, match="rhs"):
        Model("m", ("x",), None)
    assert OSC.index("v") == 1
    with pytest.raises(ParameterError, match="name"):
        OSC.index("w")
    with pytest.raises(ParameterError, match="y0"):
        solve(OSC, (0.0, 1.0), [1.0], [])
    with pytest.raises(ParameterError, match="t_span"):
        solve(OSC, (1.0, 0.0), [1.0, 0.0], [])
    with pytest.raises(ParameterError, match="rtol"):
        solve(OSC, (0.0, 1.0), [1.0, 0.0], [], rtol=0.0)
    with pytest.raises(ParameterError, match="atol"):
        solve(OSC, (0.0, 1.0), [1.0, 0.0], [], atol=-1.0)
    with pytest.raises(ParameterTypeError, match="model"):
        solve("ball", (0.0, 1.0), [1.0, 0.0], [])


def _drive(w, t):
    """A plain helper a model's right-hand side calls by its global name."""
    return math.cos(w * t)


def helped_rhs(t, y, p, out):
    out[0] = _drive(p[0], t)


HELPED = Model("driven quadrature, with a helper", ("y",), helped_rhs, helpers=(_drive,))


@pytest.mark.parametrize("compiled", PATHS)
def test_a_model_calls_its_helpers_on_both_paths(compiled):
    a = solve(HELPED, (0.0, 5.0), [0.0], [3.0], rtol=1e-12, atol=1e-12, compiled=compiled)
    b = solve(DRIVEN, (0.0, 5.0), [0.0], [3.0], rtol=1e-12, atol=1e-12, compiled=compiled)
    np.testing.assert_array_equal(a.t, b.t)
    np.testing.assert_array_equal(a.y, b.y)


def test_a_numba_function_is_taken_as_it_is():
    import numba

    from rollingdisk.engine.steploop_numba import RHS_SIGNATURE

    jitted = numba.njit(RHS_SIGNATURE)(osc_rhs)
    model = Model("oscillator, jitted", ("x", "v"), jitted)
    sol = solve(model, (0.0, 3.0), [1.0, 0.0], [], rtol=1e-12, atol=1e-12, compiled=True)
    np.testing.assert_allclose(sol.y[:, 0], np.cos(sol.t), rtol=0, atol=TOL)
    wrong = numba.njit("void(float64, float64[::1], float64[::1])")(lambda t, y, out: None)
    with pytest.raises(ParameterError, match="engine calls it as"):
        solve(Model("wrong", ("x",), wrong), (0.0, 1.0), [0.0], [], compiled=True)


# ------------------------------------------------------------------ the disk, through it
def disk_rhs(t, y, p, out):
    from_kernel = _rough_rhs(p[0], y)
    for i in range(8):
        out[i] = from_kernel[i]


@pytest.mark.slow
def test_the_disk_takes_the_steps_of_its_own_compiled_dop853():
    """Same arithmetic: the disk on rough ground (eqs. 1, 2, 10) through the contract takes
    the very steps of the disk's compiled DOP853 (``engine/numba_core.py``, guards off),
    to the last bit, compiled and uncompiled."""
    from rollingdisk.engine import numba_core
    from rollingdisk.model.geometry import _geometry, _inertia

    disk = Model("disk on rough ground", ("X", "Y", "psi", "theta", "phi", "w1", "w2", "w3"),
                 disk_rhs, helpers=(_rough_rhs, _rough_omega_dot, _inertia, _geometry))
    h, t_end = 0.17, 5.0
    y0 = np.array([0.0, 0.0, 0.0, 0.5, 0.0, 0.3, 1.1, 0.9])
    ref = numba_core.integrate(True, h, 0.0, y0.copy(), t_end, np.inf, 1e-10,
                               np.full(8, 1e-12), np.inf, 0.0, np.zeros(3, np.bool_), 1.0,
                               np.empty(0), False, 10**6, 10**9, False)
    for compiled in (True, False):
        sol = solve(disk, (0.0, t_end), y0, [h], rtol=1e-10, atol=1e-12, compiled=compiled)
        assert sol.n_steps == ref[2] and sol.n_rhs == ref[3]
        np.testing.assert_array_equal(sol.t, ref[0])
        np.testing.assert_array_equal(sol.y, ref[1])
