"""The compiled contact phase of simulate_coulomb (rollingdisk.ivp.fastsegment) against
the scipy path and against independent truth (closed form, rough-ground integration,
energy balance eq. 12)."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import rollingdisk as rd
from rollingdisk.ivp import fastsegment as fs
from rollingdisk.ivp import hybrid as hy

pytestmark = pytest.mark.skipif(not fs.available(), reason="needs numba")


@pytest.fixture(scope="module")
def ns():
    return fs.compiled()


def _both(disk, ground, span, y0, **kw):
    a = rd.simulate_coulomb(disk, ground, span, y0, method="scipy", **kw)
    b = rd.simulate_coulomb(disk, ground, span, y0, method="dop853", **kw)
    assert a.method == "scipy" and b.method == "dop853"
    assert a.status == b.status
    assert [(x.from_mode, x.to_mode) for x in a.transitions] == [
        (x.from_mode, x.to_mode) for x in b.transitions]
    for x, z in zip(a.transitions, b.transitions):
        assert abs(x.t - z.t) <= 1e-8
    assert a.t[-1] == pytest.approx(b.t[-1], abs=1e-8)
    assert np.abs(a.y[:, -1] - b.y[:, -1]).max() <= 1e-7
    for k in hy.DISSIPATION_TERMS:
        assert abs(a.dissipated[k][-1] - b.dissipated[k][-1]) <= 1e-7
    assert rd.energy_balance(b) <= 1e-9
    return a, b


def test_sliding_disk_rolls_at_the_closed_form_time(ns):
    """h = 0, upright, V = 1, omega = 0, mu = 0.2 (the docstring example of
    simulate_coulomb): dV/dt = -mu, d omega2/dt = mu / k2^2 = 2 mu (eq. 9), so the slip
    u = V - omega2 = 1 - 3 mu t vanishes at t* = 1 / (3 mu) = 5/3, with V = omega2 = 2/3;
    the slip has dissipated 1/2 - (1/2 + 1/4) (2/3)^2 = 1/6."""
    y0 = [0, 0, 1, 0, 0, 0, 0, 0, 0, 0]
    a, b = _both(rd.Disk(0.0), rd.Coulomb(0.2), (0, 2), y0)
    (x,) = b.transitions
    assert (x.from_mode, x.to_mode) == ("sliding", "rolling")
    assert abs(x.t - 5.0 / 3.0) <= 1e-9
    assert b.y[2, -1] == pytest.approx(2.0 / 3.0, abs=1e-12)
    assert b.dissipated["slip"][-1] == pytest.approx(1.0 / 6.0, abs=1e-12)


@pytest.mark.parametrize("h,theta0,r_C,t_end", [(0.0, 0.6, 2.0, 0.3339), (0.3, 0.9, 1.0, 0.2418)])
def test_rolling_starts_to_slide_where_the_rough_motion_leaves_the_cone(ns, h, theta0, r_C,
                                                                         t_end):
    """A steady circle nudged (omega1 + 0.05) on mu = 1.02 mu_required: it slides once
    |F_t| = mu F_z.  Up to then it is the rough-ground motion, so the time is the first
    zero of mu F_z - |F_t| on an independent rough-ground run (simulate, dense output)."""
    disk = rd.Disk(h)
    m = rd.steady_motion(disk, "rough", theta0, r_C=r_C)
    yr = np.array(m.initial_state(), dtype=float)
    yr[5] += 0.05  # omega1 (rough layout: X, Y, psi, theta, phi, omega1, omega2, omega3)
    y0 = rd.rolling_state(disk, yr)
    mu = 1.02 * m.mu_required
    a, b = _both(disk, rd.Coulomb(mu), (0, t_end), y0)
    x = b.transitions[0]
    assert (x.from_mode, x.to_mode) == ("rolling", "sliding")

    rough = rd.simulate(disk, "rough", (0, t_end), yr, method="dop853", rtol=1e-13,
                        atol=1e-14, dense_output=True)

    def margin(t):
        F_x, F_y, F_z = rd.contact_force(disk, "rough", rough.sol(t))
        return mu * F_z - math.hypot(F_x, F_y)

    ts = np.linspace(0.0, t_end, 400)
    vals = [margin(t) for t in ts]
    i = next(i for i in range(1, ts.size) if vals[i - 1] > 0.0 >= vals[i])
    t_ref = brentq(margin, ts[i - 1], ts[i], xtol=1e-15, rtol=8.9e-16)
    assert abs(x.t - t_ref) <= 1e-8


def test_pivot_sticks_at_the_closed_form_time_both_paths(ns):
    """Upright thin disk spinning about the vertical (test_pivot_stick): omega_z = Omega0 -
    4 c t stops at Omega0 / (4 c), then the pivot sticks."""
    Om0, c = 0.7, 0.03
    y0 = [0, 0, 0, 0, 0, 0, 0, 0, 0, Om0]
    a, b = _both(rd.Disk(0.0), rd.Coulomb(0.5, pivot=c), (0.0, 10.0), y0)
    (x,) = b.transitions
    assert (x.from_mode, x.to_mode) == ("rolling", "rolling, pivot stuck")
    assert abs(x.t - Om0 / (4 * c)) <= 1e-9
    assert b.dissipated["pivot"][-1] == pytest.approx(0.125 * Om0 ** 2, rel=1e-12)


def test_spin_in_place_sticks_then_tips_onto_the_edge_both_paths(ns):
    """Disk(0.17) spinning in place with pivot friction (test_pivot_stick): the pivot
    sticks, then the disk lands on its other rim edge: the guard is located the same way."""
    disk = rd.Disk(0.17)
    s = rd.steady_motion(disk, "rough", theta0=0.165, r_C=0.0)
    y0 = rd.rolling_state(disk, s.initial_state())
    a, b = _both(disk, rd.Coulomb(0.5, pivot=rd.PivotFriction(0.05)), (0.0, 20.0), y0,
                 max_steps=2000)
    assert b.status == "edge-contact"
    assert abs(a.t_event - b.t_event) <= 1e-8


def test_all_dissipation_terms_balance_both_paths(ns):
    disk = rd.Disk(0.1)
    g = rd.Coulomb(0.4, 0.3, rolling_resistance=0.005, pivot=0.01, air=0.002)
    m = rd.steady_motion(disk, "rough", 0.5, Omega0=3.0)
    y = rd.rolling_state(disk, m.initial_state())
    y[2] += 0.05
    a, b = _both(disk, g, (0, 10), y)
    assert b.transitions[0].from_mode == "sliding" and rd.energy_balance(b) <= 1e-9


def _random_state(rng):
    y = np.zeros(14)
    y[:2] = rng.uniform(-1, 1, 2)
    y[2:4] = rng.uniform(-0.5, 0.5, 2)
    y[4] = rng.uniform(-3, 3)
    y[5] = rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 1.3)
    y[6] = rng.uniform(-3, 3)
    y[7:10] = rng.uniform(-2, 2, 3)
    y[10:] = rng.uniform(0, 1, 4)
    return y


@pytest.mark.parametrize("mode", range(8))
def test_compiled_rhs_and_events_equal_the_python_kernels(ns, mode):
    """fastsegment's _rhs and _cc_events (compiled) against _Run.rhs and _Run.events (the
    Python kernels of coulomb.py), at random states, in each of the 8 modes."""
    rng = np.random.default_rng(7 + mode)
    for _ in range(20):
        disk = rd.Disk(float(rng.choice([0.0, 0.25])))
        g = rd.Coulomb(0.4, 0.3, rolling_resistance=0.01, pivot=0.02, air=0.003)
        y = _random_state(rng)
        run = hy._Run(disk, g, alpha_min=1e-3)
        run.ref = (0.6, -0.8)
        run.sz = float(rng.choice([-1.0, 1.0]))
        a = rng.uniform(0, 2 * math.pi)
        run.rref = (math.cos(a), math.sin(a))
        run.side = 1.0 if y[5] >= 0 else -1.0
        want = run.rhs(mode)(0.0, y)
        c_roll, c_pivot, c_air = g.coefficients
        p = np.array([mode, g.mu_k, g.mu_s, c_roll, c_pivot, c_air, *run.ref, hy.U_EPS,
                      run.sz, run.side, run.alpha_min, *run.rref, hy.W_EPS, 0.0])
        got = np.empty(14)
        ns["_rhs"](p, disk.h, y, got)
        assert np.allclose(got, want, rtol=1e-12, atol=1e-12)
        K = np.zeros((14, 3))
        ns["_rhs_col"](p, disk.h, y, K, 1)
        assert np.array_equal(K[:, 1], got)
        ev = np.empty(6)
        ns["_cc_events"](p, disk.h, y, ev)
        assert np.allclose(ev, run.events(mode, y), rtol=1e-12, atol=1e-12)


def test_uncompiled_loop_takes_the_compiled_steps(ns):
    """fastsegment.advance run as plain Python takes the steps of its compiled version."""
    py = fs.namespace(compiled=False)
    assert fs.matches_python(ns)
    disk = rd.Disk(0.0)  # Coulomb(0.2): mu_k = mu_s = 0.2 in p0
    y0 = np.array([0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0], dtype=float)
    p0 = np.array([1, 0.2, 0.2, 0, 0, 0, 1.0, 0.0, hy.U_EPS, 1.0, 1.0, 1e-8, 0.0, 0.0,
                   hy.W_EPS, 0.0])
    active = np.array([True, False, True, False, True, False])
    out = []
    for space in (ns, py):
        ts, zs = np.empty(4), np.empty((4, 14))
        r = space["advance"](p0.copy(), disk.h, 0.0, y0, 2.0, 0.0, 1e-11, np.full(14, 1e-12),
                             np.inf, 50, active, ts, zs)
        out.append((r, ts, zs))
    (r1, t1, z1), (r2, t2, z2) = out
    assert r1[0] == r2[0] and r1[1] == r2[1] and r1[2] == r2[2]
    m = r1[1]
    assert np.allclose(t1[:m], t2[:m], rtol=1e-13) and np.allclose(z1[:m], z2[:m], atol=1e-13)


def test_method_argument_is_checked():
    with pytest.raises(rd.ParameterError, match="method"):
        rd.simulate_coulomb(rd.Disk(0.0), rd.Coulomb(0.2), (0, 1), [0] * 10, method="fast")


def test_compiled_slip_direction_is_the_defining_root_and_the_scipy_paths(ns, monkeypatch):
    """The direction in which a rolling disk starts to slide: sliding with friction
    ``-mu_k F_z d``, the slip acceleration (the Python kernels, ``hy._slip_accel``) is along
    ``+d``.  The compiled scan finds the direction the brentq scan finds, at random states
    and every pivot state."""
    rng = np.random.default_rng(7)
    found = 0
    for k in range(80):
        y = np.zeros(10)
        y[2:4] = rng.uniform(-1, 1, 2)
        y[4] = rng.uniform(-3, 3)
        y[5] = rng.uniform(-1.4, 1.4)
        y[7:10] = rng.uniform(-4, 4, 3)
        h, mu = rng.uniform(0, 0.5), rng.uniform(0.05, 1)
        co = tuple(rng.uniform(0, 0.05, 3))
        sz = (None, 1.0, -1.0, 0.0)[k % 4]
        d = hy._slip_direction(h, mu, co, y, sz)  # compiled: the fixture loaded it
        with monkeypatch.context() as m:
            m.setattr(fs, "loaded", lambda: False)
            ref = hy._slip_direction(h, mu, co, y, sz)
        assert (d is None) == (ref is None)
        if d is None:
            continue
        found += 1
        assert np.hypot(d[0] - ref[0], d[1] - ref[1]) <= 1e-12
        ax, ay = hy._slip_accel(h, mu, co, y, d[0], d[1], sz)
        n = math.hypot(ax, ay)
        assert abs(d[0] * ay - d[1] * ax) <= 1e-12 * max(n, 1.0)  # parallel
        assert d[0] * ax + d[1] * ay > 0.0  # and along +d
    assert found >= 40


def test_compiled_touchdown_is_where_the_flying_disk_meets_the_plane(ns, monkeypatch):
    """Touchdown times of random launches (heights from 1e-6 to 2 above the plane, fast
    spins): the compiled advancement finds the scipy-path time, and there the lowest point
    of the closed-form free flight (``free_flight``, an independent evaluation) is on the
    plane while it was above it just before."""
    from rollingdisk.phases import impact as im

    rng = np.random.default_rng(3)
    for _ in range(60):
        h, th = rng.uniform(0, 0.6), rng.uniform(-1.5, 1.5)
        low = abs(math.cos(th)) + h * abs(math.sin(th))
        s = [0, 0, low + rng.uniform(0, 2) * rng.choice([1e-6, 1e-3, 1.0]),
             rng.uniform(-3, 3), th, 0, rng.uniform(-1, 1), rng.uniform(-1, 1),
             rng.uniform(-1, 3), rng.uniform(-10, 10), rng.uniform(-5, 5), rng.uniform(-5, 5)]
        disk = rd.Disk(h)
        t = im.touchdown_time(disk, s)  # compiled: the fixture loaded the loop
        with monkeypatch.context() as m:
            m.setattr(fs, "loaded", lambda: False)
            ref = im.touchdown_time(disk, s)
        assert t == pytest.approx(ref, rel=1e-13, abs=1e-14)
        hit = im.free_flight(disk, s, t)
        assert abs(im._lowest_height(h, hit[2], hit[4])) <= 1e-10
        before = im.free_flight(disk, s, t * (1 - 1e-6))
        assert im._lowest_height(h, before[2], before[4]) > -1e-12


# A toss's rim contact at the cone boundary (h = 0.3, mu = 0.5, c = 0.01): rolling needs
# |F_t| = 1.0062 mu F_z, so the disk starts to slide from u = 0.  At rtol 1e-8 the slip of
# the first microseconds (1e-8) is below what the integration resolves: its interpolant
# changed sign on the first step and each restart found the "slip came to rest" event again
# at the same instant (before: 1000 restarts at t = 2.4e-6, the toss undecided).
CONE_BOUNDARY = [-1.5964969830052462, 4.051714073632696, -0.43113211496797504,
                 0.21349356232622285, 13.316739112691751, -0.9992512774023072,
                 8.887783399695303, -0.5674738734383952, -0.4186399313942376,
                 0.8295890562671745]


@pytest.mark.parametrize("method", ["scipy", "dop853"])
def test_a_slip_started_below_the_resolution_does_not_stall(method, ns):
    disk, g = rd.Disk(0.3), rd.Coulomb(0.5, rolling_resistance=0.01)
    runs = {tol: hy.simulate_coulomb(disk, g, (0.0, 2.0), CONE_BOUNDARY, rtol=tol,
                                     atol=tol * 1e-2, method=method, max_transitions=50,
                                     guards=False) for tol in (1e-8, 1e-10)}
    for tol, tr in runs.items():
        assert tr.status == "completed", tr.message
        assert [x.to_mode for x in tr.transitions] == ["sliding", "rolling", "sliding",
                                                        "rolling"]
        assert hy.energy_balance(tr) <= 100 * tol  # measured 2e-9-7.8e-8, 3.8e-10-5.5e-10
    # the loose run's transitions converge onto the tight one's (measured: 1.2e-5 apart
    # at the last, 1e-7 between rtol 1e-10 and 1e-11): not a tolerance artefact
    loose, tight = ([x.t for x in runs[tol].transitions] for tol in (1e-8, 1e-10))
    assert np.allclose(loose, tight, rtol=0.0, atol=5e-5)


@pytest.mark.parametrize("old, new", [("compiled", "dop853"), ("stiff", "lsoda")])
def test_old_method_spellings_warn_and_mean_the_same(old, new):
    """One method vocabulary (rollingdisk.engine.methods): the old words of simulate_coulomb
    still run, with a DeprecationWarning, and report the new word."""
    if new == "dop853" and not fs.available():
        pytest.skip("numba missing")
    disk, ground = rd.Disk(0.2), rd.Coulomb(0.5)
    y0 = [0, 0, 1, 0, 0, 0.3, 0, 0, 0, 0]
    with pytest.warns(DeprecationWarning, match=f"now spelled '{new}'"):
        a = rd.simulate_coulomb(disk, ground, (0, 0.2), y0, method=old)
    b = rd.simulate_coulomb(disk, ground, (0, 0.2), y0, method=new)
    assert a.method == b.method == new
    np.testing.assert_array_equal(a.y, b.y)


def test_a_method_no_front_door_has_is_refused_naming_the_words():
    with pytest.raises(ValueError, match=r"method must be one of \('auto', 'dop853', "
                                         r"'taylor', 'scipy'\), got 'lsoda'"):
        rd.simulate(rd.Disk(0.2), "rough", (0, 1), [0, 0, 0, 0.3, 0, 0, 1.0, 0], method="lsoda")
    with pytest.raises(TypeError, match="method must be a string"):
        rd.simulate_coulomb(rd.Disk(0.2), rd.Coulomb(0.5), (0, 1),
                            [0, 0, 1, 0, 0, 0.3, 0, 0, 0, 0], method=3)
