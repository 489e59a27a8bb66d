"""The sweeps' vector lanes (rollingdisk.engine.lanes, batch.run_batch_lanes) against
independent truth: numpy's libm for the lanes' sin, cos, log and exp; the scalar Taylor
kernel (held to the model's kernels by tests/test_simulate_taylor.py) for the traced jets,
step sizes, energies and samples; the general step (batch_taylor._tay_advance) for the common
step the lanes take without a branch (batch_taylor._tay_plain), bit for bit; closed-form roots for
the polynomial root finder; and the scalar batch kernel for whole sweeps (equal verdicts,
equal frequencies to 1e-12).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

numba = pytest.importorskip("numba")

from rollingdisk.engine import numba_core as nc  # noqa: E402
from rollingdisk.engine.lanes import (  # noqa: E402
    LANES,
    MAX_ORDER,
    _lane_math,
    lane_jet_rough,
    lane_jet_smooth,
    lane_plain,
    lane_samples,
)
from rollingdisk.sweep import batch, batch_taylor, executors  # noqa: E402
from rollingdisk.sweep.grid import Perturbation, SweepGrid, _Spec  # noqa: E402

W = LANES


@numba.njit
def _apply(which, x, out):
    if which == 0:
        _lane_math("sin", x, out)
    elif which == 1:
        _lane_math("cos", x, out)
    elif which == 2:
        _lane_math("log", x, out)
    else:
        _lane_math("exp", x, out)


def _lanes_of(x):
    x = np.asarray(x, dtype=float).ravel()
    n = -(-x.size // W) * W
    return np.resize(x, n).reshape(-1, W)


def _ulps(got, want):
    return np.max(np.abs(got - want) / np.spacing(np.abs(want)))


@pytest.mark.parametrize("which,f,lo,hi", [(0, np.sin, -4.0, 4.0), (1, np.cos, -4.0, 4.0),
                                           (3, np.exp, -700.0, 700.0)])
def test_lane_sin_cos_exp_are_libm_within_one_ulp(which, f, lo, hi):
    x = _lanes_of(np.random.default_rng(which).uniform(lo, hi, 40000))
    out = np.empty_like(x)
    _apply(which, x, out)
    assert _ulps(out, f(x)) <= 1.0


def test_lane_log_is_libm_within_one_ulp_over_the_normal_range():
    x = _lanes_of(np.exp(np.random.default_rng(7).uniform(-700.0, 700.0, 40000)))
    out = np.empty_like(x)
    _apply(2, x, out)
    assert _ulps(out, np.log(x)) <= 1.0


@given(st.floats(-6.0, 6.0, allow_nan=False))
@settings(max_examples=200, deadline=None)
def test_lane_sin_cos_satisfy_the_pythagorean_identity_and_match_math(t):
    x = _lanes_of([t])
    s, c = np.empty_like(x), np.empty_like(x)
    _apply(0, x, s)
    _apply(1, x, c)
    assert abs(s[0, 0] - math.sin(t)) <= 2.3e-16 * max(1.0, abs(math.sin(t)))
    assert abs(c[0, 0] - math.cos(t)) <= 2.3e-16 * max(1.0, abs(math.cos(t)))
    assert abs(s[0, 0] ** 2 + c[0, 0] ** 2 - 1.0) <= 5e-16


def test_lane_log_and_exp_at_the_ends_of_their_ranges():
    out = np.empty((1, W))
    _apply(2, np.array([[np.inf, 0.0, -1.0, np.nan, 1.0, 2.0, 0.5, 1e-300]]), out)
    assert out[0, 0] == np.inf and out[0, 1] == -np.inf
    assert np.isnan(out[0, 2]) and np.isnan(out[0, 3]) and out[0, 4] == 0.0
    np.testing.assert_allclose(out[0, 5:], np.log([2.0, 0.5, 1e-300]), rtol=2.3e-16)
    _apply(3, np.array([[np.inf, -np.inf, 710.0, -710.0, np.nan, 0.0, 1.0, -1.0]]), out)
    assert out[0, 0] == np.inf and out[0, 1] == 0.0 and out[0, 2] == np.inf
    assert out[0, 3] == 0.0 and np.isnan(out[0, 4]) and out[0, 5] == 1.0
    np.testing.assert_allclose(out[0, 6:], [math.e, 1.0 / math.e], rtol=2.3e-16)


# ------------------------------------------------------------------ traced jets vs scalar
@numba.njit
def _jet(rough, hv, k1v, k2v, Y, J, A, EO, dt, V, P):
    if rough:
        lane_jet_rough(P, hv, k1v, k2v, 1e-9, 1e-9, Y, J, A, EO)
    else:
        lane_jet_smooth(P, hv, k1v, k2v, 1e-9, 1e-9, Y, J, A, EO)
    for i in range(dt.shape[0]):
        dt[i] = EO[1, i]
    lane_samples(P, 2, hv, J, A, dt, V)


@numba.njit
def _jet_p(rough, hv, k1v, k2v, Y, J, A, EO, dt, V, P):
    _jet(rough, hv, k1v, k2v, Y, J, A, EO, dt, V, numba.literally(P))


def _lane_states(rng, tilt, w1, h_max, thin_first=False):
    """LANES random reduced states, tilts of |theta| in ``tilt`` of either sign, and their
    disks (lane 0's of no thickness if ``thin_first``): (Y, h, side, k1, k2), k1 and k2 by
    eq. (10)."""
    Y = np.empty((4, W))
    Y[0] = rng.uniform(*tilt, W) * rng.choice([-1.0, 1.0], W)
    Y[1] = rng.uniform(-w1, w1, W)
    Y[2] = rng.uniform(-2.0, 2.0, W)
    Y[3] = rng.uniform(-5.0, 5.0, W)
    h = rng.uniform(0.0, h_max, W)
    if thin_first:
        h[0] = 0.0
    side = np.where(Y[0] >= 0.0, 1.0, -1.0)
    return Y, h, side, 0.25 + h * h / 3.0, np.full(W, 0.5)


def _lane_buffers(P):
    """Zeroed J, A, EO, V of the lanes for order P and two samples."""
    return (np.zeros((4, P + 1, W)), np.zeros((14, P + 1, W)), np.zeros((2, W)),
            np.zeros((2, 5, W)))


@pytest.mark.parametrize("rough", [True, False])
@pytest.mark.parametrize("P", [6, 12])
def test_traced_jet_step_size_energy_and_samples_are_the_scalar_kernels(rough, P):
    """Every lane of the traced code agrees with the scalar Taylor kernel on its own state,
    for tilts of both signs (the signed h~) and thicknesses from 0."""
    Y, h, side, k1, k2 = _lane_states(np.random.default_rng(P + rough), (0.2, 1.3), 0.3, 1.0,
                                      thin_first=True)
    J, A, EO, V = _lane_buffers(P)
    dt = np.zeros(W)
    _jet_p(rough, h * side, k1, k2, Y, J, A, EO, dt, V, P)
    jet = nc._tay_jet4_rough if rough else nc._tay_jet4_smooth
    for ln in range(W):
        Js = np.zeros((4, P + 1))
        As = np.zeros((14, P + 1))
        y = Y[:, ln].copy()
        jet(h[ln], y, Js, As, P)
        scale = np.abs(Js).max(axis=1, keepdims=True)
        np.testing.assert_allclose(J[:, :, ln], Js, rtol=0, atol=1e-13 * scale.max())
        E = nc._energy_sc(rough, h[ln] * side[ln], k1[ln], 0.5, As[0, 0], As[1, 0], y)
        assert EO[0, ln] == pytest.approx(E, rel=1e-14)
        step = nc._tay_step_size(Js, P, np.full(4, 1e-9), 1e-9)
        assert EO[1, ln] == pytest.approx(step, rel=1e-12)
        v = np.empty(5)
        for m, x in ((0, 0.5 * EO[1, ln]), (1, EO[1, ln])):
            nc._tay_sample(h[ln], Js, As, P, x, v)
            np.testing.assert_allclose(V[m, :, ln], v, rtol=1e-12, atol=1e-13)


# ------------------------------------------------------------------ the common step
@numba.njit
def _steps(rough, h, k1, k2, side, c, E, dt, V, Y, rec, Yb, recb, P, J, A, t_end, max_steps,
           grow_lo, grow_hi, okv, stv):
    """Lane by lane: the common step (batch_taylor._tay_plain) on (Y, rec) and the general one
    (batch_taylor._tay_advance) on copies (Yb, recb), from the same jets."""
    N = np.zeros(P + 1)
    v = np.empty(5)
    for ln in range(Y.shape[1]):
        okv[ln] = batch_taylor._tay_plain(t_end, max_steps, grow_lo, grow_hi, side[ln], c[:, ln],
                                   E[ln], dt[ln], V[:, :, ln], Y[:, ln], rec[:, ln])
        stv[ln] = batch_taylor._tay_advance(rough, h[ln], k1[ln], k2[ln], side[ln], c[1, ln],
                                     c[2, ln], grow_lo, grow_hi, t_end, max_steps, P, J, A,
                                     N, E[ln], dt[ln], V, v, Yb, recb, ln)


@numba.njit
def _plain_lanes(t_end, max_steps, grow_lo, grow_hi, side, c, EO, V, Y, rec, ok):
    lane_plain(batch_taylor._tay_plain, t_end, max_steps, grow_lo, grow_hi, side, c, EO, V, Y,
                rec, ok)


_GROW = (10.0, 100.0)  # grow_lo, grow_hi


def _step_cases(seed, P=12):
    """LANES steps from real jets (rough ground), each record set up so that some steps are
    common and others are not: first steps, last steps, the step budget spent, crossings of
    theta_ref, growth thresholds passed or already timed.  (The guards are left to the
    whole-kernel tests.)"""
    rng = np.random.default_rng(seed)
    Y, h, side, k1, k2 = _lane_states(rng, (0.05, 1.4), 0.5, 0.5)
    J, A, EO, V = _lane_buffers(P)
    _jet_p(True, h * side, k1, k2, Y, J, A, EO, EO[1].copy(), V, P)
    t_end = 10.0
    rec = np.zeros((batch_taylor._NREC, W))
    # theta_ref: the sampled theta's neighbourhood (crossings both ways) or far away
    thr = Y[0] + rng.choice([0.0, 0.0, 1.0], W) * rng.uniform(-1.5, 1.5, W) * np.abs(
        V[1, 0] - Y[0])
    a0 = 10.0 ** rng.uniform(-5.0, -1.0, W)  # the levels 10 a0, 100 a0 passed or not
    c = np.array([h, thr, a0])
    rec[batch_taylor._R_T] = np.choose(rng.integers(0, 4, W), [0.0, 3.0, 3.0, t_end - 0.5 * EO[1]])
    rec[batch_taylor._R_NSTEPS] = rng.choice([0.0, 4.0, 4.0, 4.0, 4.0, 99.0], W)
    rec[batch_taylor._R_MAXD] = rng.uniform(0.0, 0.1, W)
    rec[batch_taylor._R_TLO] = rng.choice([np.nan, 1.0, 1.0], W)
    rec[batch_taylor._R_THI] = rng.choice([np.nan, 2.0, 2.0], W)
    # as in a run: a level the start of the step is already past was timed before it
    d0 = np.abs(Y[0] - thr)
    rec[batch_taylor._R_TLO, d0 > _GROW[0] * a0] = 1.0
    rec[batch_taylor._R_THI, d0 > _GROW[1] * a0] = 2.0
    rec[batch_taylor._R_EDRIFT] = rng.choice([0.0, 1e-9], W)
    rec[batch_taylor._R_E0] = EO[0] * (1.0 + rng.uniform(-1e-8, 1e-8, W))
    rec[batch_taylor._R_NA] = 1.0
    return h, k1, k2, side, c, EO, V, Y, rec, J, A, t_end


@pytest.mark.parametrize("seed", range(24))
def test_the_common_step_is_the_general_steps_result(seed):
    """Where _tay_plain takes the step, _tay_advance takes the same one, bit for bit (the
    general step is the reference); where it declines, it changed nothing, and the general
    step either ended the run, found a root (a crossing, a threshold), or took the first or
    the last step.  The traced lanes give the scalar source's result bit for bit."""
    h, k1, k2, side, c, EO, V, Y, rec, J, A, t_end = _step_cases(seed)
    max_steps, (grow_lo, grow_hi) = 99.0, _GROW
    Ya, reca, Yb, recb = Y.copy(), rec.copy(), Y.copy(), rec.copy()
    ok, st = np.zeros(W), np.zeros(W)
    _steps(True, h, k1, k2, side, c, EO[0].copy(), EO[1].copy(), V, Ya, reca, Yb, recb, 12,
           J, A, t_end, max_steps, grow_lo, grow_hi, ok, st)
    for ln in range(W):
        if ok[ln]:
            assert st[ln] == 0
            np.testing.assert_array_equal(reca[:, ln], recb[:, ln])
            np.testing.assert_array_equal(Ya[:, ln], Yb[:, ln])
        else:
            np.testing.assert_array_equal(reca[:, ln], rec[:, ln])
            np.testing.assert_array_equal(Ya[:, ln], Y[:, ln])
            cr = batch_taylor._R_CR
            changed = not np.array_equal(recb[cr:, ln], rec[cr:, ln])
            timed = (np.isnan(rec[[batch_taylor._R_TLO, batch_taylor._R_THI], ln])
                     != np.isnan(recb[[batch_taylor._R_TLO, batch_taylor._R_THI], ln])).any()
            first = rec[batch_taylor._R_NSTEPS, ln] == 0
            last = rec[batch_taylor._R_T, ln] + EO[1, ln] >= t_end
            assert st[ln] != 0 or changed or timed or first or last
    Yt, rect, okt = Y.copy(), rec.copy(), np.zeros(W)
    _plain_lanes(t_end, max_steps, grow_lo, grow_hi, side, c, EO, V, Yt, rect, okt)
    np.testing.assert_array_equal(okt, ok)
    np.testing.assert_array_equal(rect, reca)
    np.testing.assert_array_equal(Yt, Ya)


def test_the_common_step_cases_cover_both_answers():
    oks = []
    for seed in range(24):
        h, k1, k2, side, c, EO, V, Y, rec, J, A, t_end = _step_cases(seed)
        ok = np.zeros(W)
        _plain_lanes(t_end, 99.0, *_GROW, side, c, EO, V, Y, rec, ok)
        oks.append(ok)
    oks = np.concatenate(oks)
    assert 0.2 < oks.mean() < 0.8


# ------------------------------------------------------------------ the root finder
@given(st.floats(0.01, 0.99), st.floats(1e-6, 10.0), st.sampled_from([1.0, -1.0]))
@settings(max_examples=200, deadline=None)
def test_poly_root_returns_an_admissible_point_at_the_root(r, slope, sg):
    """f(x) = sg slope (x - r) (1 + x^2) on (0, 1]: the root r, found to round-off, at a
    point where f has the sign of f(0) (a guard's admissible side), also on slow
    crossings (slope 1e-6)."""
    # slope (x - r)(1 + x^2) = slope (x^3 - r x^2 + x - r)
    c = slope * np.array([-r, 1.0, -r, 1.0])
    fa = sg * np.polyval(c[::-1], 0.0)
    fb = sg * np.polyval(c[::-1], 1.0)
    x = nc._tay_poly_root(c, 3, sg, 0.0, 0.0, 1.0, fa, fb)
    fx = sg * nc._tay_poly(c, 3, x)  # the sign as the integrator evaluates it (with FMA)
    assert (fx > 0.0) == (fa > 0.0) and fx != 0.0
    assert abs(x - r) <= 1e-14  # the band where the sign of f is rounding noise


def test_poly_root_on_a_step_polynomial_is_numpys_root():
    """Theta crossings of real steps (the jet of a steady motion kicked by 1e-3): the root
    agrees with numpy's companion-matrix roots."""
    import rollingdisk as rd

    m = rd.steady_motion(rd.Disk(0.17), "rough", 0.7, Omega0=4.0 / math.cos(0.7))
    y = np.array([0.7, 1e-3, m.omega20, m.omega30])
    P = 12
    J = np.zeros((4, P + 1))
    A = np.zeros((14, P + 1))
    found = 0
    for _ in range(40):
        nc._tay_jet4_rough(0.17, y, J, A, P)
        dt = nc._tay_step_size(J, P, np.full(4, 1e-9), 1e-9)
        d0 = J[0, 0] - 0.7
        d1 = np.polyval(J[0, ::-1], dt) - 0.7
        if d0 < 0.0 <= d1:
            x = nc._tay_poly_root(J[0].copy(), P, 1.0, 0.7, 0.0, dt, d0, d1)
            c = J[0].copy()
            c[0] -= 0.7
            roots = np.roots(c[::-1])
            real = roots[(abs(roots.imag) < 1e-9) & (roots.real > 0) & (roots.real <= dt)].real
            assert len(real) == 1 and abs(x - real[0]) < 1e-12
            found += 1
        y = np.array([np.polyval(J[i, ::-1], dt) for i in range(4)])
    assert found >= 4


# ------------------------------------------------------------------ whole sweeps
def _inputs(ground, m, kick=1e-3, t_end=100.0):
    g = SweepGrid(ground, h=0.17, theta0=np.linspace(0.3, 1.2, m),
                  omega30=np.linspace(2.0, 6.0, m))
    spec = _Spec(g, Perturbation(kick=kick), t_end, 1e-9, 1e-9, 1_000_000, m * m, m * m)
    return executors.kernel_args(spec)[1]


def _agree(a, b):
    assert np.array_equal(a[:, 0], b[:, 0])  # status
    assert np.array_equal(a[:, 3], b[:, 3])  # crossings counted
    np.testing.assert_array_equal(np.isnan(a[:, 4]), np.isnan(b[:, 4]))
    ok = ~np.isnan(a[:, 4])
    np.testing.assert_allclose(b[ok, 4], a[ok, 4], rtol=1e-12)  # period
    np.testing.assert_allclose(b[:, 1], a[:, 1], rtol=1e-12)  # t_end
    np.testing.assert_allclose(b[:, 2], a[:, 2], rtol=1e-9, atol=1e-15)  # max |dtheta|


@pytest.mark.slow
@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_lanes_give_the_scalar_kernels_verdicts_and_frequencies(ground):
    args = _inputs(ground, 12)
    a = batch.run_batch_taylor(*args, 12)
    b = batch.run_batch_lanes(*args, 12)
    _agree(a, b)


@pytest.mark.slow
@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_lanes_on_a_60_by_60_grid(ground):
    """The acceptance grid: 3600 trajectories per ground, theta0 in [0.3, 1.2] x omega30 in
    [2, 6]."""
    args = _inputs(ground, 60)
    a = batch.run_batch_taylor(*args, 12)
    b = batch.run_batch_lanes(*args, 12)
    _agree(a, b)


@pytest.mark.parametrize("n", [1, 7, 9, 30])
def test_a_trajectorys_result_does_not_depend_on_its_lane_mates(n):
    """Lanes never mix: any subset, in any order, on any number of threads, gives each
    trajectory the same row bit for bit."""
    args = _inputs("rough", 6)
    full = batch.run_batch_lanes(*args, 12)
    idx = np.random.default_rng(n).permutation(len(args[1]))[:n]
    sub = list(args)
    for k in (1, 2, 3, 4, 5, 6):
        sub[k] = np.ascontiguousarray(args[k][idx])
    with batch.threads(2):
        part = batch.run_batch_lanes(*sub, 12)
    np.testing.assert_array_equal(part, full[idx])


def test_lanes_refuse_an_order_they_are_not_compiled_for():
    args = _inputs("rough", 2)
    with pytest.raises(ValueError, match="P = 30"):
        batch.run_batch_lanes(*args, 30)
    assert MAX_ORDER >= 12
