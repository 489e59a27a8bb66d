"""The classical thin rolling disc (h = 0), built as in sympy's documentation example.

Test-side helper (not a test file).  The model is the one of the sympy.physics.mechanics
example "A rolling disc, with Kane's method": yaw ``q1`` about N.z, lean ``q2`` about Y.x,
spin ``q3`` about L.y; generalized speeds ``u1, u2, u3`` = the disc's angular velocity in the
lean frame L; the kinematics are built from the contact point up (the material contact point
has zero velocity, the centre is ``r L.z`` above it).  Two coordinates are added to the
example: ``q4, q5``, the position of the contact point on the plane, whose rates follow from
the rolling kinematics (the centre's position ``q4 N.x + q5 N.y + r L.z`` differentiated
must equal its velocity from the rolling, which sympy computes by ``v2pt_theory``).

Mapping to rollingdisk's rough state ``[X_C, Y_C, psi, theta, phi, omega1, omega2, omega3]``
at h = 0 (eqs. 1-5).  The example's frames are built exactly as the paper's: Y = N rotated by
q1 about Z is Cxyz, L = Y rotated by q2 about x is C xi eta zeta, R = L rotated by q3 about
eta (= L.y, the disc axis) is the body; the centre is ``r L.z`` = +zeta above the contact
point, as ``r_CP = -zeta`` in the paper (eq. 4 with h = 0).  Hence, with no offsets::

    q1 = psi, q2 = theta, q3 = phi, u1 = omega1, u2 = omega2, u3 = omega3,
    (q4, q5) = (X_P, Y_P) = (X_C - sin(theta) sin(psi), Y_C + sin(theta) cos(psi))   (eq. 5)

``tests/test_thin_disk.py`` confirms this numerically (the centre computed from the sympy
vectors; the angular accelerations; whole trajectories).
"""

from __future__ import annotations

import functools

import numpy as np
import sympy as sm
import sympy.physics.mechanics as me
from scipy.integrate import solve_ivp

__all__ = ["thin_disk", "rough_to_thin", "thin_to_rough", "thin_rhs", "integrate_thin_disk"]


@functools.cache
def thin_disk():
    """Derive (once) the example's equations; returns lambdified pieces.

    ``rhs(q1..q5, u1..u3) -> (q1'..q5', u1'..u3')`` with r = m = g = 1, and
    ``centre(q1..q5) -> (x, y, z)`` of the disc centre in N (used to confirm the mapping).
    """
    q1, q2, q3, q4, q5, u1, u2, u3 = me.dynamicsymbols("q1 q2 q3 q4 q5 u1 u2 u3")
    t = me.dynamicsymbols._t
    r, m, g = sm.symbols("r m g")

    N = me.ReferenceFrame("N")
    Y = N.orientnew("Y", "Axis", [q1, N.z])
    L = Y.orientnew("L", "Axis", [q2, Y.x])
    R = L.orientnew("R", "Axis", [q3, L.y])
    w_R_N_qd = R.ang_vel_in(N)
    R.set_ang_vel(N, u1 * L.x + u2 * L.y + u3 * L.z)

    C = me.Point("C")
    C.set_vel(N, 0)
    Dmc = C.locatenew("Dmc", r * L.z)
    Dmc.v2pt_theory(C, N, R)

    I = me.inertia(L, m / 4 * r**2, m / 2 * r**2, m / 4 * r**2)  # noqa: E741
    kd = [me.dot(R.ang_vel_in(N) - w_R_N_qd, uv) for uv in L]
    force = (Dmc, -m * g * Y.z)
    body = me.RigidBody("BodyD", Dmc, R, m, (I, Dmc))

    km = me.KanesMethod(N, q_ind=[q1, q2, q3], u_ind=[u1, u2, u3], kd_eqs=kd)
    km.kanes_equations([body], [force])
    kdd = km.kindiffdict()
    udot = km.mass_matrix.LUsolve(km.forcing)
    udot = me.msubs(udot, kdd)

    # added: contact point (q4, q5) on the plane.  Centre = q4 N.x + q5 N.y + r L.z.
    centre = q4 * N.x + q5 * N.y + r * L.z
    v_rolling = me.msubs(Dmc.vel(N), kdd)
    v_geom = me.msubs(centre.diff(t, N), kdd)
    q4d, q5d = sm.symbols("q4d q5d")
    sol = sm.solve([(v_geom - v_rolling).dot(N.x).subs({q4.diff(t): q4d, q5.diff(t): q5d}),
                    (v_geom - v_rolling).dot(N.y).subs({q4.diff(t): q4d, q5.diff(t): q5d})],
                   [q4d, q5d], dict=True)[0]
    # and the vertical component is consistent (the centre stays at r cos q2)
    assert sm.simplify((v_geom - v_rolling).dot(N.z)) == 0

    qs = sm.symbols("q1:6")
    us = sm.symbols("u1:4")
    rep = dict(zip([q1, q2, q3, q4, q5, u1, u2, u3], [*qs, *us], strict=True))
    par = {r: 1, m: 1, g: 1}

    def plain(e):
        return sm.sympify(e).xreplace(rep).xreplace(par)

    qdots = [plain(kdd[qi.diff(t)]) for qi in (q1, q2, q3)] + [plain(sol[q4d]), plain(sol[q5d])]
    rhs_exprs = qdots + [plain(e) for e in udot]
    rhs = sm.lambdify((*qs, *us), rhs_exprs, "numpy", cse=True)
    centre_f = sm.lambdify(qs, [plain(centre.dot(e)) for e in (N.x, N.y, N.z)], "numpy")
    return rhs, centre_f


def thin_rhs(t, x):
    """``d/dt [q1..q5, u1..u3]`` of the thin rolling disc (r = m = g = 1)."""
    rhs, _ = thin_disk()
    return np.array(rhs(*x), dtype=float)


def rough_to_thin(y):
    """rollingdisk rough state (h = 0) -> the example's ``[q1, q2, q3, q4, q5, u1, u2, u3]``.

    ``y`` may be one state (8,) or a stack (8, k).
    """
    X_C, Y_C, psi, theta, phi, w1, w2, w3 = np.asarray(y, dtype=float)
    y_P = np.sin(theta)  # eq. (4) with h = 0
    X_P = X_C - y_P * np.sin(psi)  # eq. (5)
    Y_P = Y_C + y_P * np.cos(psi)
    return np.array([psi, theta, phi, X_P, Y_P, w1, w2, w3])


def thin_to_rough(x):
    """The example's ``[q1..q5, u1..u3]`` -> rollingdisk rough state at h = 0 (inverse)."""
    q1, q2, q3, q4, q5, u1, u2, u3 = np.asarray(x, dtype=float)
    y_P = np.sin(q2)
    return np.array([q4 + y_P * np.sin(q1), q5 - y_P * np.cos(q1), q1, q2, q3, u1, u2, u3])


def integrate_thin_disk(y0_rough_state, t_eval, rtol=1e-12, atol=1e-12):
    """Integrate the sympy-example thin disc from a rollingdisk rough state (h = 0).

    Parameters
    ----------
    y0_rough_state : array_like, shape (8,)
        ``[X_C, Y_C, psi, theta, phi, omega1, omega2, omega3]`` at ``t_eval[0]``.
    t_eval : array_like
        Increasing output times; integration runs from ``t_eval[0]`` to ``t_eval[-1]``.

    Returns
    -------
    ndarray, shape (len(t_eval), 8)
        rollingdisk rough states at ``t_eval`` (solve_ivp, DOP853).
    """
    t_eval = np.asarray(t_eval, dtype=float)
    x0 = rough_to_thin(y0_rough_state)
    sol = solve_ivp(thin_rhs, (t_eval[0], t_eval[-1]), x0, method="DOP853", t_eval=t_eval,
                    rtol=rtol, atol=atol)
    if not sol.success:
        raise RuntimeError(f"thin-disk integration failed: {sol.message}")
    return thin_to_rough(sol.y).T
