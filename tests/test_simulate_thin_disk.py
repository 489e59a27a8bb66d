"""h = 0: simulate() against an independent thin-disk model derived here with sympy.

The reference model does not share a line with rollingdisk: Euler angles (yaw psi about
Z, lean theta about the line of nodes, spin phi about the disk axis) as coordinates, their
second derivatives as unknowns, sympy.physics.vector kinematics, and the balance of
angular momentum about the centre C with the contact force eliminated through Newton's law
for C:

    rough:  v_C = omega x (C - P) (no slip),  F = a_C + Z  (m = g = a = 1)
    smooth: F = F_z Z, with F_z = 1 + d^2 Z_C/dt^2 and Z_C = cos(theta) (contact)
    d H_C / dt = (P - C) x F,   H_C = diag(1/4, 1/2, 1/4) omega in the disk frame.

This gives three equations linear in (psi'', theta'', phi''), solved numerically at each
step (lambdified), integrated with solve_ivp(DOP853) at tight tolerances, and compared with
simulate() over 20 time units.
"""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rollingdisk import Disk, simulate


@functools.cache
def thin_disk_model(ground: str):
    sp = pytest.importorskip("sympy")
    from sympy.physics.vector import ReferenceFrame, dynamicsymbols

    t = sp.symbols("t")
    psi, th, phi = dynamicsymbols("psi theta phi")
    dpsi, dth, dphi = (sp.diff(q, t) for q in (psi, th, phi))
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [psi, N.z])  # yaw
    B = A.orientnew("B", "Axis", [th, A.x])  # lean; disk plane = B.x, B.z; axis = B.y
    D = B.orientnew("D", "Axis", [phi, B.y])  # spin
    w = D.ang_vel_in(N)
    r_CP = -B.z  # lowest point of the rim of a thin disk of radius 1
    w_B = [w.dot(B.x), w.dot(B.y), w.dot(B.z)]
    H = 0.25 * w_B[0] * B.x + 0.5 * w_B[1] * B.y + 0.25 * w_B[2] * B.z
    dH = H.dt(N)
    if ground == "rough":
        v_C = w.cross(-r_CP)  # no slip: v_P = v_C + w x r_CP = 0
        a_C = v_C.dt(N)
        F = a_C + N.z
    else:
        Z_C = sp.cos(th)  # contact: Z_C = -z_P
        F = (1 + sp.diff(Z_C, t, 2)) * N.z
        v_C = None
    balance = dH - r_CP.cross(F)
    eqs = [balance.dot(B.x), balance.dot(B.y), balance.dot(B.z)]
    acc = sp.symbols("psi_dd theta_dd phi_dd")
    vel = sp.symbols("psi_d theta_d phi_d")
    pos = sp.symbols("psi_s theta_s phi_s")
    subs = {sp.diff(q, t, 2): a for q, a in zip((psi, th, phi), acc, strict=True)}
    subs2 = {d: v for d, v in zip((dpsi, dth, dphi), vel, strict=True)}
    subs3 = {q: p for q, p in zip((psi, th, phi), pos, strict=True)}

    def plain(e):
        return e.subs(subs).subs(subs2).subs(subs3)

    eqs = [plain(e) for e in eqs]
    M, rhs = sp.linear_eq_to_matrix(eqs, acc)
    args = (*pos, *vel)
    fM = sp.lambdify(args, M, "numpy")
    fr = sp.lambdify(args, rhs, "numpy")
    if v_C is not None:
        fv = sp.lambdify(args, [plain(v_C.dot(N.x)), plain(v_C.dot(N.y))], "numpy")
    else:
        fv = None

    def f(t_, s):
        # s = [X_C, Y_C, psi, theta, phi, psi', theta', phi'] (rough)
        a = (*s[2:5], *s[5:8])
        qdd = np.linalg.solve(np.array(fM(*a), dtype=float),
                              np.array(fr(*a), dtype=float).ravel())
        vx, vy = fv(*a) if fv is not None else (0.0, 0.0)
        return np.array([vx, vy, *s[5:8], *qdd])

    return f


def to_euler_rates(theta, w1, w2, w3):
    # eqs. (2): psi' = omega3 / cos(theta), theta' = omega1, phi' = omega2 - omega3 tan(theta)
    return w3 / math.cos(theta), w1, w2 - w3 * math.tan(theta)


CASES = [
    ("rough", [0.0, 0.0, 0.0, 0.4, 0.0, 0.1, 0.011, 2.0]),  # near a steady circle
    ("rough", [0.3, -0.2, 0.5, 0.05, 0.2, -0.5, 1.5, 0.2]),  # leans through theta = 0
    ("rough", [0.0, 0.0, 0.0, 0.9, 0.0, 0.1, 0.456, 3.0]),
    ("smooth", [0.0, 0.0, 0.2, -0.1, 0.0, 0.4, 0.0, 0.1, 0.033, 2.0]),
    ("smooth", [0.0, 0.0, 0.2, -0.1, 0.0, -0.6, 0.0, 0.1, 0.65, -3.0]),
    ("smooth", [0.0, 0.0, 0.0, 0.0, 0.3, -0.6, 0.0, -0.2, 1.0, -3.0]),
]


@pytest.mark.parametrize("ground,y0", CASES)
def test_thin_disk_agrees_with_independent_euler_angle_model(ground, y0):
    f = thin_disk_model(ground)
    T = 20.0
    te = np.linspace(0, T, 81)
    tr = simulate(Disk(h=0.0), ground, (0, T), y0, t_eval=te, rtol=1e-12, atol=1e-13)
    assert tr.status == "completed"
    if ground == "rough":
        X, Y, psi, th, phi, w1, w2, w3 = y0
        VX = VY = 0.0
    else:
        X, Y, VX, VY, psi, th, phi, w1, w2, w3 = y0
    s0 = [X, Y, psi, th, phi, *to_euler_rates(th, w1, w2, w3)]
    ref = solve_ivp(f, (0, T), s0, method="DOP853", t_eval=te, rtol=1e-12, atol=1e-13)
    assert ref.success
    X_ref = ref.y[0] + VX * te
    Y_ref = ref.y[1] + VY * te
    for name, mine, theirs in (("X_C", tr.X_C, X_ref), ("Y_C", tr.Y_C, Y_ref),
                               ("psi", tr.psi, ref.y[2]), ("theta", tr.theta, ref.y[3]),
                               ("phi", tr.phi, ref.y[4])):
        err = np.max(np.abs(mine - theirs))
        assert err < 1e-8, f"{name} differs by {err:.2e}"
    # the angular velocities, through eq. (3)
    th_r, psid, thd, phid = ref.y[3], ref.y[5], ref.y[6], ref.y[7]
    np.testing.assert_allclose(tr.omega1, thd, atol=1e-8)
    np.testing.assert_allclose(tr.omega2, phid + psid * np.sin(th_r), atol=1e-8)
    np.testing.assert_allclose(tr.omega3, psid * np.cos(th_r), atol=1e-8)


# ---------------------------------------------------------------------------- Kane's method
@pytest.mark.parametrize("y0", [CASES[0][1], CASES[1][1]])
def test_thin_disk_agrees_with_kanes_method_example(y0):
    """Against the sympy.physics.mechanics rolling-disc example (tests/thin_disk_kane.py)."""
    from thin_disk_kane import integrate_thin_disk

    te = np.linspace(0, 20, 41)
    tr = simulate(Disk(h=0.0), "rough", (0, 20), y0, t_eval=te, rtol=1e-12, atol=1e-13)
    ref = integrate_thin_disk(y0, te).T
    assert tr.status == "completed"
    np.testing.assert_allclose(tr.y, ref, rtol=0, atol=1e-8)


@pytest.mark.parametrize("ground,h,y0", [
    ("rough", 0.3, [0.0, 0.0, 0.0, 0.5, 0.0, 0.1, 0.8, 2.0]),
    ("rough", 1.0, [0.2, 0.1, 0.3, -1.0, 0.0, -0.1, -1.635, 1.5]),
])
def test_thick_disk_agrees_with_kanes_method(ground, h, y0):
    """h > 0 against Kane's equations of the thick disk (tests/kane_model.py)."""
    from kane_model import kane_rhs

    T = 5.0
    te = np.linspace(0, T, 11)
    tr = simulate(Disk(h=h), ground, (0, T), y0, t_eval=te, rtol=1e-12, atol=1e-13)
    assert tr.status == "completed"
    ref = solve_ivp(kane_rhs(ground, h), (0, T), y0, method="DOP853", t_eval=te, rtol=1e-12,
                    atol=1e-13)
    np.testing.assert_allclose(tr.y, ref.y, rtol=0, atol=1e-8)
