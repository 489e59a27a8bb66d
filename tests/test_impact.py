"""Free flight, touchdown and the impact law (issue 20), against independent truths.

Sources of truth, by group: conservation laws and an independent integration of Euler's
equations (free flight); the ballistic closed form (touchdown); Routh's / Stronge's planar
impact solved phase by phase (planar impacts); Glocker's energy identity, angular momentum
about the contact point and a plain proximal-point iteration (impact law); Housner's rocking
block (rim change); the sympy derivation of :mod:`rollingdisk.symbolic.impact` (W, Euler's
equations, the lowest point).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

import rollingdisk as rd
from rollingdisk.phases import impact as im
from rollingdisk.symbolic import impact as si

RNG_SEED = 20


def _rot_matrix(psi, theta, phi):
    """R_Z(psi) R_x(theta) R_y(phi), written out (docs/notation.md)."""
    cz, sz = math.cos(psi), math.sin(psi)
    cx, sx = math.cos(theta), math.sin(theta)
    cy, sy = math.cos(phi), math.sin(phi)
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1.0]])
    Rx = np.array([[1.0, 0, 0], [0, cx, -sx], [0, sx, cx]])
    Ry = np.array([[cy, 0, sy], [0, 1.0, 0], [-sy, 0, cy]])
    return Rz @ Rx @ Ry


def _random_state(rng, z=3.0, spin=4.0):
    return np.array([*rng.normal(size=2), z, rng.uniform(-3, 3), rng.uniform(-1.2, 1.2),
                     rng.uniform(-3, 3), *rng.normal(size=3), *(spin * rng.normal(size=3))])


# ------------------------------------------------------------------ symbolic checks
def test_symbolic_derivation_residuals_vanish():
    ff = si.free_flight()
    for name, res in ff.residuals.items():
        res = res if isinstance(res, list) else [res]
        assert all(sp.simplify(r) == 0 for r in res), name
    k1, k2 = si.inertia()
    assert sp.simplify(k1 - (sp.Rational(1, 4) + si.h ** 2 / 3)) == 0  # eq. (10)
    assert k2 == sp.Rational(1, 2)
    assert si.energy_balance()["identity"] == 0
    rr = si.rocking_ratio()
    assert sp.simplify(rr["housner"] - rr["housner_printed"]) == 0
    assert sp.simplify(rr["disk"] - (15 - 8 * si.h ** 2) / (15 + 16 * si.h ** 2)) == 0


def test_free_flight_euler_equations_match_smooth_ground_where_contact_does_not_enter():
    """d omega3/dt of the smooth-ground equations (49) has no contact force: it is the
    free-flight one (an independent derivation in rollingdisk.symbolic.derivation)."""
    ff = si.free_flight()
    rng = np.random.default_rng(RNG_SEED)
    for _ in range(20):
        h = rng.uniform(0, 2)
        th, a, b, c = rng.uniform(-1.4, 1.4), *rng.normal(size=3)
        sub = {si.k1: 0.25 + h * h / 3, si.k2: 0.5, si.theta: th, si.w1: a, si.w2: b,
               si.w3: c}
        d3 = float(ff.domega[2].subs(sub))
        ref = rd.omega_dot(rd.Disk(h=h), "smooth", th, a, b, c)[2]
        assert d3 == pytest.approx(ref, rel=1e-13, abs=1e-13)


# --------------------------------------------------------------------- free flight
def test_free_flight_conserves_energy_and_angular_momentum_over_many_turns():
    rng = np.random.default_rng(RNG_SEED)
    for h in (0.0, 0.17, 1.3):
        disk = rd.Disk(h=h)
        s0 = _random_state(rng)
        L0 = im.angular_momentum(disk, s0)
        E0 = im.free_energy(disk, s0)
        rot0 = E0 - 0.5 * s0[6:9] @ s0[6:9] - s0[2]
        for t in np.linspace(0.0, 60.0, 41):  # |omega| ~ 7: about 60 turns
            s = im.free_flight(disk, s0, t)
            L = im.angular_momentum(disk, s)
            assert np.max(np.abs(L - L0)) <= 1e-12 * max(1.0, np.linalg.norm(L0))
            rot = im.free_energy(disk, s) - 0.5 * s[6:9] @ s[6:9] - s[2]
            assert abs(rot - rot0) <= 1e-12 * max(1.0, rot0)
            E = im.free_energy(disk, s)
            assert abs(E - E0) <= 1e-12 * max(1.0, 0.5 * s[6:9] @ s[6:9])
            # omega2 (axial spin) is constant
            assert s[10] == pytest.approx(s0[10], abs=1e-12 * max(1.0, abs(s0[10])))


def test_free_flight_is_a_flow():
    rng = np.random.default_rng(RNG_SEED + 1)
    disk = rd.Disk(h=0.4)
    s0 = _random_state(rng)
    np.testing.assert_allclose(im.free_flight(disk, s0, 0.0), s0, rtol=0, atol=1e-14)
    a = im.free_flight(disk, im.free_flight(disk, s0, 1.7), 2.9)
    b = im.free_flight(disk, s0, 4.6)
    Ra, Rb = _rot_matrix(*a[3:6]), _rot_matrix(*b[3:6])
    np.testing.assert_allclose(Ra, Rb, atol=1e-12)
    np.testing.assert_allclose(a[[0, 1, 2, 6, 7, 8, 9, 10, 11]],
                               b[[0, 1, 2, 6, 7, 8, 9, 10, 11]], atol=1e-11)
    back = im.free_flight(disk, b, -4.6)
    np.testing.assert_allclose(_rot_matrix(*back[3:6]), _rot_matrix(*s0[3:6]), atol=1e-12)


def _euler_rhs(k1, k2, body):
    f = sp.lambdify([si.k1, si.k2, *sp.symbols("Omega1 Omega2 Omega3", real=True)],
                    list(body))

    def rhs(t, y):
        R = y[:9].reshape(3, 3)
        Om = y[9:12]
        K = np.array([[0, -Om[2], Om[1]], [Om[2], 0, -Om[0]], [-Om[1], Om[0], 0]])
        return np.concatenate([(R @ K).ravel(), f(k1, k2, *Om), y[15:18],
                               [0.0, 0.0, -1.0]])

    return rhs


@pytest.mark.parametrize("h", [0.0, 0.3, 1.1])
def test_free_flight_agrees_with_integrated_euler_equations(h):
    """Body-frame Euler equations (from the sympy derivation) and dR/dt = R [Omega]
    integrated by DOP853 at rtol 1e-13; the closed form must agree to 1e-9."""
    rng = np.random.default_rng(RNG_SEED + int(10 * h))
    disk = rd.Disk(h=h)
    k1, k2 = disk.k1_sq, disk.k2_sq
    s0 = _random_state(rng, spin=2.0)
    R0 = _rot_matrix(*s0[3:6])
    Q0 = _rot_matrix(s0[3], s0[4], 0.0)
    Om0 = R0.T @ (Q0 @ s0[9:12])  # omega in the body frame
    y0 = np.concatenate([R0.ravel(), Om0, s0[0:3], s0[6:9]])
    T = 25.0
    ts = np.linspace(0, T, 11)
    sol = solve_ivp(_euler_rhs(k1, k2, si.free_flight().body_domega), (0, T), y0,
                    method="DOP853", rtol=1e-13, atol=1e-13, t_eval=ts)
    assert sol.success
    for i, t in enumerate(ts):
        s = im.free_flight(disk, s0, t)
        R = _rot_matrix(*s[3:6])
        np.testing.assert_allclose(R, sol.y[:9, i].reshape(3, 3), atol=1e-9)
        w_space = _rot_matrix(s[3], s[4], 0.0) @ s[9:12]
        np.testing.assert_allclose(w_space, R @ sol.y[9:12, i], atol=1e-9)
        np.testing.assert_allclose(s[0:3], sol.y[12:15, i], atol=1e-9)


def test_free_flight_in_library_angles_agrees_with_eq2_and_derived_euler_equations():
    """The same in the library's variables: eq. (2) and d omega/dt in C xi eta zeta."""
    ff = si.free_flight()
    disk = rd.Disk(h=0.25)
    f = sp.lambdify([si.k1, si.k2, si.theta, si.w1, si.w2, si.w3], list(ff.domega))
    s0 = np.array([0, 0, 5.0, 0.3, 0.2, -0.4, 0.1, 0.2, 0.3, 0.4, 3.0, 0.5])

    def rhs(t, y):
        psi, theta, phi, a, b, c = y
        return [c / math.cos(theta), a, b - c * math.tan(theta),
                *f(disk.k1_sq, 0.5, theta, a, b, c)]

    T = 3.0
    sol = solve_ivp(rhs, (0, T), s0[[3, 4, 5, 9, 10, 11]], method="DOP853", rtol=1e-13,
                    atol=1e-13, dense_output=True)
    for t in np.linspace(0, T, 7):
        s = im.free_flight(disk, s0, t)
        y = sol.sol(t)
        assert abs(y[1]) < 1.4  # the angles stay regular (off the flat position)
        d = s[[3, 4, 5, 9, 10, 11]] - y
        d[[0, 2]] = np.remainder(d[[0, 2]] + math.pi, 2 * math.pi) - math.pi  # mod 2 pi
        np.testing.assert_allclose(d, 0.0, atol=1e-9)


# ------------------------------------------------------------------------ touchdown
def test_touchdown_of_a_non_rotating_disk_is_the_ballistic_closed_form():
    rng = np.random.default_rng(RNG_SEED)
    for _ in range(20):
        h = rng.uniform(0, 1.5)
        th = rng.uniform(-1.5, 1.5)
        off = math.cos(th) + h * abs(math.sin(th))
        Z0 = off + rng.uniform(0, 3)
        VZ = rng.uniform(-2, 2)
        s = np.array([0, 0, Z0, 0.3, th, 0, 0.5, 0, VZ, 0, 0, 0])
        t = im.touchdown_time(rd.Disk(h=h), s)
        exact = VZ + math.sqrt(VZ * VZ + 2 * (Z0 - off))
        assert t == pytest.approx(exact, rel=1e-13, abs=1e-14)


def test_touchdown_of_a_tumbling_disk_is_the_first_root():
    rng = np.random.default_rng(RNG_SEED + 2)
    for h in (0.0, 0.2, 0.9):
        disk = rd.Disk(h=h)
        for _ in range(5):
            s0 = _random_state(rng, z=2.5, spin=6.0)
            t = im.touchdown_time(disk, s0)
            H = [im.lowest_point(disk, im.free_flight(disk, s0, x)).height
                 for x in np.linspace(0, t, 400)[:-1]]
            assert min(H) > 0.0
            assert abs(im.lowest_point(disk, im.free_flight(disk, s0, t)).height) < 1e-12


def test_lowest_point_against_sympy_and_kinds():
    lp = si.lowest_point()
    f = sp.lambdify([si.Z_C, si.theta, si.h], lp["rim"])
    rng = np.random.default_rng(RNG_SEED)
    for _ in range(30):
        h, th, z = rng.uniform(0, 2), rng.uniform(-math.pi, math.pi), rng.uniform(0, 3)
        s = np.array([0, 0, z, 0.7, th, 0, 0, 0, 0, 0, 0, 0.0])
        got = im.lowest_point(rd.Disk(h=h), s)
        assert got.height == pytest.approx(f(z, th, h), abs=1e-14)
        # the point itself is at that height, and on the disk's rim
        assert got.point[2] == pytest.approx(got.height, abs=1e-14)
    disk = rd.Disk(h=0.3)
    flat = np.array([0, 0, 0.3, 0, math.pi / 2, 0, 0, 0, 0, 0, 0, 0.0])
    tread = np.array([0, 0, 1.0, 0, 0.0, 0, 0, 0, 0, 0, 0, 0.0])
    assert im.lowest_point(disk, flat).kind == "face"
    assert im.lowest_point(disk, flat).height == pytest.approx(float(lp["face"].subs(
        {si.Z_C: 0.3, si.h: 0.3})), abs=1e-15)
    assert im.lowest_point(disk, tread).kind == "tread"
    assert im.lowest_point(rd.Disk(h=0.0), tread).kind == "rim"
    # eq. (4): r = (0, y_P, z_P) for |theta| < pi/2
    for th in (-0.8, 0.3):
        r = im.lowest_point(disk, [0, 0, 2, 0, th, 0, 0, 0, 0, 0, 0, 0]).r
        np.testing.assert_allclose(r[1:], disk.contact_point_xyz(th), atol=1e-15)


# --------------------------------------------------------------- the Delassus matrix
def test_delassus_matrix_against_sympy_at_random_states():
    W = si.delassus()
    sig, c = sp.symbols("sigma c", real=True)
    f = sp.lambdify([si.theta, si.h, si.k1, si.k2, sig, c], W)
    rng = np.random.default_rng(RNG_SEED)
    for _ in range(30):
        h = rng.uniform(0, 3)
        th = rng.uniform(-math.pi, math.pi)
        side = int(rng.choice([1, -1]))
        cs = 1 if math.cos(th) >= 0 else -1
        num = im.contact_delassus(rd.Disk(h=h), th, side, cs)
        ref = np.array(f(th, h, 0.25 + h * h / 3, 0.5, side, cs), dtype=float)
        np.testing.assert_allclose(num, ref, rtol=1e-13, atol=1e-13)
        assert np.all(np.linalg.eigvalsh(num) > 0)


# ---------------------------------------------------------- the planar (Routh) impact
def _routh_planar(I, r_y, r_z, g_T, g_N, e, mu):
    """Planar impact of a body (mass 1, inertia I about C) at the point r = (r_y, r_z),
    tangential direction y, normal z, by Routh's method: the velocity of the contact point
    is integrated along the normal impulse p (Stronge, Impact Mechanics, ch. 5); Newton's
    restitution ends the impact at gamma_N = -e gamma_N-.  Returns the impulse (L_T, L_N)
    and the case, or None where the slip stops and reverses (a case the laws treat apart).
    """
    W = np.array([[1 + r_z ** 2 / I, -r_y * r_z / I], [-r_y * r_z / I, 1 + r_y ** 2 / I]])
    s0 = math.copysign(1.0, g_T)
    if mu == 0.0 or g_T == 0.0 and W[0, 1] == 0.0:
        p = -(1 + e) * g_N / W[1, 1]
        return np.array([0.0, p]), "frictionless"
    slope_N = W[1, 1] - mu * s0 * W[1, 0]
    slope_T = W[0, 1] - mu * s0 * W[0, 0]
    # if it slides throughout (slope_N <= 0: sliding alone never ends the compression)
    p_end = -(1 + e) * g_N / slope_N if slope_N > 0 else math.inf
    p_stop = -g_T / slope_T if slope_T * s0 < 0 else math.inf
    if p_end == p_stop == math.inf:
        return None, "jam"
    if p_stop >= p_end:
        return np.array([-mu * s0 * p_end, p_end]), "gross slip"
    if e != 0.0 or abs(W[0, 1] / W[0, 0]) > mu:
        return None, "stops"
    # e = 0: slip stops in compression, then sticks; compression ends at gamma_N = 0
    gN_stop = g_N + slope_N * p_stop
    if gN_stop >= 0.0:
        return None, "stops after compression"
    k = -W[0, 1] / W[0, 0]  # dL_T/dp while sticking
    p_end = p_stop - gN_stop / (W[1, 1] + W[1, 0] * k)
    return np.array([-mu * s0 * p_stop + k * (p_end - p_stop), p_end]), "stick"


def test_planar_impact_matches_routh():
    rng = np.random.default_rng(RNG_SEED)
    cases = {}
    for _ in range(800):
        h = rng.uniform(0, 1.5)
        disk = rd.Disk(h=h)
        th = rng.uniform(-1.4, 1.4)
        e = float(rng.choice([0.0, rng.uniform(0, 1)]))
        mu = float(rng.choice([0.0, rng.uniform(0, 2)]))
        lp = im.lowest_point(disk, [0, 0, 5, 0, th, 0, 0, 0, 0, 0, 0, 0])
        r_y, r_z = lp.r[1], lp.r[2]
        Z_C = -r_z
        V_y, V_z, w1 = rng.normal(size=3) * 2
        g_T = V_y - w1 * r_z  # omega x r, omega = w1 x
        g_N = V_z + w1 * r_y
        if g_N >= -1e-3:
            continue
        ref, case = _routh_planar(disk.k1_sq, r_y, r_z, g_T, g_N, e, mu)
        cases[case] = cases.get(case, 0) + 1
        if ref is None:
            continue
        s = np.array([0, 0, Z_C, 0, th, 0, 0, V_y, V_z, w1, 0, 0])
        res = im.impact(disk, s, lp, e=e, mu=mu)
        Lam = np.array([res.impulse_tangential[1], res.impulse_normal])
        scale = abs(g_N) + abs(g_T)
        assert abs(res.impulse_tangential[0]) <= 1e-15 * scale
        np.testing.assert_allclose(Lam, ref, rtol=0, atol=1e-12 * scale)
        # post velocities from the planar momentum balances
        post = res.post_state
        assert post[7] == pytest.approx(V_y + ref[0], abs=1e-12 * scale)
        assert post[8] == pytest.approx(V_z + ref[1], abs=1e-12 * scale)
        dw = (r_y * ref[1] - r_z * ref[0]) / disk.k1_sq
        assert post[9] == pytest.approx(w1 + dw, abs=1e-12 * scale)
        assert res.stick == (case == "stick")
    assert cases.get("gross slip", 0) > 40 and cases.get("stick", 0) > 40
    assert cases.get("frictionless", 0) > 50


# ------------------------------------------------------------ energy of the impact law
def _random_impact(rng, h=None):
    h = rng.uniform(0, 1.5) if h is None else h
    disk = rd.Disk(h=h)
    s = _random_state(rng, spin=3.0)
    lp = im.lowest_point(disk, s)
    s[2] -= lp.height  # touching
    lp = im.lowest_point(disk, s)
    return disk, s, lp


def _kinetic(disk, s):
    return im.free_energy(disk, s) - s[2]


def test_elastic_frictionless_impact_conserves_energy():
    rng = np.random.default_rng(RNG_SEED)
    n = 0
    while n < 100:
        disk, s, lp = _random_impact(rng)
        if lp.kind != "rim":
            continue
        res = im.impact(disk, s, lp, e=1.0, mu=0.0)
        T0 = _kinetic(disk, s)
        if res.impulse_normal == 0.0:
            continue
        n += 1
        assert abs(_kinetic(disk, res.post_state) - T0) <= 1e-13 * T0
        assert abs(res.energy_lost) <= 1e-13 * T0
        assert res.contact_velocity_post[2] == pytest.approx(-res.contact_velocity_pre[2],
                                                             abs=1e-13 * math.sqrt(T0))


@settings(max_examples=200, deadline=None)
@given(seed=st.integers(0, 2 ** 32 - 1), e=st.floats(0, 1), mu=st.floats(0, 2),
       h=st.floats(0, 1.5))
def test_impacts_never_create_energy_and_satisfy_the_law(seed, e, mu, h):
    rng = np.random.default_rng(seed)
    disk, s, lp = _random_impact(rng, h)
    if lp.kind != "rim":
        return
    res = im.impact(disk, s, lp, e=e, mu=mu)
    T0 = _kinetic(disk, s)
    lost = T0 - _kinetic(disk, res.post_state)
    assert lost >= -1e-13 * T0
    assert res.energy_lost == pytest.approx(lost, abs=1e-12 * T0)
    assert res.law_residual <= 1e-14
    # the law itself: xi = gamma+ + e gamma-
    Lam = np.array([*res.impulse_tangential, res.impulse_normal])
    xi = res.contact_velocity_post + e * res.contact_velocity_pre
    v = math.sqrt(T0) + 1.0
    assert Lam[2] >= 0.0
    if res.contact_velocity_pre[2] < 0:
        assert xi[2] >= -1e-12 * v and abs(Lam[2] * xi[2]) <= 1e-12 * v * (Lam[2] + 1)
        lt = math.hypot(*Lam[:2])
        assert lt <= mu * Lam[2] * (1 + 1e-12) + 1e-300
        xt = math.hypot(*xi[:2])
        if xt > 1e-10 * v:  # sliding: opposite to xi_T, on the cone
            assert lt == pytest.approx(mu * Lam[2], rel=1e-12, abs=1e-14)
            if lt > 1e-300:  # a subnormal impulse (mu = 5e-324) has no direction to test
                cosang = -(Lam[:2] @ xi[:2]) / (lt * xt)
                assert cosang == pytest.approx(1.0, abs=1e-12)


def _prox_iteration(W, gamma, e, mu, iters=200000):
    """Plain projected (Jacobi) fixed point Lam <- prox_C(Lam - r xi): an independent,
    slow solver of the same law."""
    Lam = np.zeros(3)
    r = 1.0 / np.max(np.linalg.eigvalsh(W))
    b = (1 + e) * gamma
    for _ in range(iters):
        z = Lam - r * (b + W @ Lam)
        n = max(z[2], 0.0)
        t = z[:2]
        nt = math.hypot(*t)
        if nt > mu * n:
            t = t * (mu * n / nt)
        new = np.array([t[0], t[1], n])
        if np.max(np.abs(new - Lam)) < 1e-15 * (1 + np.max(np.abs(new))):
            return new
        Lam = new
    return Lam


def test_impulse_agrees_with_a_plain_proximal_iteration():
    rng = np.random.default_rng(RNG_SEED + 3)
    n = 0
    while n < 25:
        disk, s, lp = _random_impact(rng)
        if lp.kind != "rim":
            continue
        e, mu = rng.uniform(0, 1), rng.uniform(0, 1.5)
        res = im.impact(disk, s, lp, e=e, mu=mu)
        if res.impulse_normal == 0.0:
            continue
        n += 1
        W = im.contact_delassus(disk, s[4], lp.side, 1 if math.cos(s[4]) >= 0 else -1)
        ref = _prox_iteration(W, res.contact_velocity_pre, e, mu)
        Lam = np.array([*res.impulse_tangential, res.impulse_normal])
        np.testing.assert_allclose(Lam, ref, atol=1e-9 * (1 + np.max(np.abs(ref))))


def test_tangential_restitution_zero_with_normal_one_can_create_energy():
    """Why the law takes one e for all directions: with e_N = 1, e_T = 0 a sticking impact
    changes the energy by the sympy expression 'kane', positive for a small slip whose sign
    is that of -M_NT gamma_N (M = W^-1)."""
    kane = si.energy_balance()["kane"]
    Ms = sp.symbols("M11 M12 M13 M22 M23 M33", real=True)
    gs = sp.symbols("gx gy gz", real=True)
    f = sp.lambdify([*Ms, *gs], kane)
    disk = rd.Disk(h=0.3)
    th = 0.6
    s = np.array([0, 0, 0, 0, th, 0, 0, 0, 0, 0, 0, 0.0])
    lp = im.lowest_point(disk, s)
    s[2] -= lp.height
    W = im.contact_delassus(disk, th, 1)
    M = np.linalg.inv(W)
    gamma = np.array([0.0, 1e-3 * math.copysign(1, M[1, 2]), -1.0])  # g_N < 0
    # a free state with this contact velocity: translation only
    s[6:9] = gamma
    res = im._impact(disk.h, s, lp.r, 1.0, 0.0, 1e6, 1e-9)
    assert res.stick
    dT = -res.energy_lost
    assert dT == pytest.approx(f(*M[np.triu_indices(3)], *gamma), rel=1e-10)
    assert dT > 0.0  # energy created
    # the law of the library (e_T = e_N = 1) conserves it
    assert abs(im.impact(disk, s, lp, e=1.0, mu=1e6).energy_lost) < 1e-13


# --------------------------------------------------- inelastic sticking: momentum
def test_inelastic_sticking_impact_conserves_angular_momentum_about_the_contact():
    rng = np.random.default_rng(RNG_SEED + 4)
    n = 0
    while n < 40:
        disk, s, lp = _random_impact(rng)
        if lp.kind != "rim":
            continue
        res = im.impact(disk, s, lp, e=0.0, mu=1e3)
        if res.impulse_normal == 0.0 or not res.stick:
            continue  # (sticking may need mu > 1e3, or a pulling normal impulse)
        n += 1
        assert res.mode == "rolling"
        H0 = im.angular_momentum(disk, s, about=lp.point)
        H1 = im.angular_momentum(disk, res.post_state, about=lp.point)
        np.testing.assert_allclose(H1, H0, atol=1e-12 * (1 + np.max(np.abs(H0))))
        np.testing.assert_allclose(res.contact_velocity_post, 0.0,
                                   atol=1e-12 * (1 + np.max(np.abs(res.contact_velocity_pre))))


# ------------------------------------------------------------------------- rocking
@pytest.mark.parametrize("h", [0.05, 0.17, 0.5, 1.0, 1.3])
def test_rim_change_ratio_against_a_direct_impact(h):
    disk = rd.Disk(h=h)
    w = 0.8
    # upright, turning about the edge -h eta... the edge at r = (0, h, -1) (side -1)
    s = np.array([0, 0, 1.0, 0, 0.0, 0, 0, -w, -h * w, w, 0, 0])
    res = im.impact(disk, s, +1, e=0.0, mu=1e3)
    ratio = res.post_state[9] / w
    assert ratio == pytest.approx(im.rim_change_ratio(h), abs=1e-12)
    assert res.stick and res.mode == "rolling"
    # after: turning about the new edge r = (0, -h, -1)
    np.testing.assert_allclose(res.post_state[6:9], ratio * w * np.array([0, -1, h]),
                               atol=1e-12)


def test_rim_change_ratio_limits_and_housner_block():
    assert im.rim_change_ratio(0.0) == 1.0  # thin disk: the two edges coincide
    assert im.rim_change_ratio(im.H_ROCK_MAX) == pytest.approx(0.0, abs=1e-15)
    general = sp.lambdify(sp.symbols("I_C b d", positive=True),
                          si.rocking_ratio()["general"])
    for alpha in (0.1, 0.3, 0.6, 1.0):  # block 2b x 2d, I_C = (b^2 + d^2)/3
        b, d = math.sin(alpha), math.cos(alpha)
        assert general((b * b + d * d) / 3, b, d) == pytest.approx(
            1 - 1.5 * math.sin(alpha) ** 2, abs=1e-15)  # Housner (1963)
    for h in (0.1, 0.7, 1.2):
        assert general(0.25 + h * h / 3, h, 1.0) == pytest.approx(im.rim_change_ratio(h),
                                                                  abs=1e-15)


# --------------------------------------------------------------- state converters
def test_rolling_state_round_trip_and_energy():
    rng = np.random.default_rng(RNG_SEED)
    for _ in range(20):
        h = rng.uniform(0, 1)
        disk = rd.Disk(h=h)
        y = np.array([*rng.normal(size=2), rng.uniform(-3, 3), rng.uniform(-1.4, 1.4),
                      rng.uniform(-3, 3), *rng.normal(size=3)])
        s = im.free_state_from_rolling(disk, "rough", y)
        assert im.lowest_point(disk, s).height == pytest.approx(0.0, abs=1e-14)
        assert im.free_energy(disk, s) == pytest.approx(rd.energy(disk, "rough", y),
                                                        rel=1e-13)
        np.testing.assert_allclose(im.rolling_state_from_free(disk, "rough", s), y,
                                   atol=1e-15)
        ys = rd.rolling_state(disk, y) if hasattr(rd, "rolling_state") else None
        if ys is None:
            from rollingdisk.equations import rolling_state
            ys = rolling_state(disk, y)
        s2 = im.free_state_from_rolling(disk, "smooth", ys)
        np.testing.assert_allclose(s2, s, atol=1e-14)
        assert im.free_energy(disk, s2) == pytest.approx(rd.energy(disk, "smooth", ys),
                                                         rel=1e-13)
        np.testing.assert_allclose(im.rolling_state_from_free(disk, "smooth", s2), ys,
                                   atol=1e-15)


# -------------------------------------------------------------------- hostile input
STATE = [0, 0, 2.0, 0, 0.3, 0, 0, 0, -1.0, 0, 1.0, 0]


@pytest.mark.parametrize("kwargs, err, word", [
    ({"e": 1.5}, rd.ParameterError, "e"),
    ({"e": -0.1}, rd.ParameterError, "e"),
    ({"e": float("nan")}, rd.ParameterError, "e"),
    ({"e": "half"}, rd.ParameterTypeError, "e"),
    ({"mu": -1.0}, rd.ParameterError, "mu"),
    ({"mu": float("inf")}, rd.ParameterError, "mu"),
    ({"mu": True}, rd.ParameterTypeError, "mu"),
    ({"contact": 0}, rd.ParameterError, "contact"),
    ({"contact": True}, rd.ParameterError, "contact"),
    ({"pre_state": [1, 2, 3]}, rd.ParameterError, "pre_state"),
    ({"pre_state": [float("nan")] * 12}, rd.ParameterError, "pre_state"),
    ({"disk": 0.2}, rd.ParameterTypeError, "disk"),
])
def test_impact_refuses_hostile_input(kwargs, err, word):
    args = {"disk": rd.Disk(h=0.2), "pre_state": STATE, "contact": 1, "e": 0.5, "mu": 0.3}
    args.update(kwargs)
    with pytest.raises(err, match=word):
        im.impact(**args)


def test_other_functions_refuse_hostile_input():
    disk = rd.Disk(h=0.2)
    inside = [0, 0, 0.5, 0, 0.3, 0, 0, 0, 0, 0, 0, 0]
    with pytest.raises(rd.ParameterError, match="state.*inside the plane"):
        im.touchdown_time(disk, inside)
    with pytest.raises(rd.ParameterError, match="h"):
        im.rim_change_ratio(1.5)
    with pytest.raises(rd.ParameterError, match="h"):
        im.rim_change_ratio(-0.1)
    with pytest.raises(rd.ParameterError, match="side"):
        im.contact_delassus(disk, 0.3, side=2)
    with pytest.raises(rd.ParameterError, match="t must be finite"):
        im.free_flight(disk, STATE, float("nan"))
    with pytest.raises(rd.ParameterError, match="does not touch"):
        im.rolling_state_from_free(disk, "rough", STATE)
    flat = [0, 0, 0.2, 0, math.pi / 2, 0, 0, 0, -1, 0, 0, 0]
    with pytest.raises(rd.ParameterError, match="face"):
        im.impact(disk, flat, im.lowest_point(disk, flat), 0.5, 0.3)
    tread = [0, 0, 1.0, 0, 0.0, 0, 0, 0, -1, 0, 0, 0]
    with pytest.raises(rd.ParameterError, match="tread"):
        im.impact(disk, tread, im.lowest_point(disk, tread), 0.5, 0.3)
    with pytest.raises(rd.ParameterError, match="theta"):
        im.free_state_from_rolling(disk, "rough", [0, 0, 0, 2.0, 0, 0, 0, 0])


def test_reprs_are_short():
    disk = rd.Disk(h=0.2)
    res = im.impact(disk, [0, 0, 1.0, 0, 0.0, 0, 0, 0, -1.0, 0, 0, 0], 1, 0.5, 0.3)
    assert len(repr(res)) < 120 and "flight" in repr(res)
    assert len(repr(im.lowest_point(disk, STATE))) < 80
