"""Hybrid rolling/sliding simulation on Coulomb ground, with located mode transitions.

The disk is in one of two modes (:mod:`rollingdisk.friction.coulomb`):

``rolling``
    no slip; the friction force ``F_t`` follows from the constraint.  It ends when
    ``|F_t|`` reaches ``mu_s F_z`` (event ``mu_s F_z - |F_t| = 0``): the disk starts to
    slide, in the direction ``d`` for which the slip acceleration produced by the friction
    ``-mu_k F_z d`` points along ``d`` (solved, see :func:`slip_direction`).
``sliding``
    ``F_t = -mu_k F_z u/|u|``.  It ends when the slip velocity ``u`` reaches 0 (event
    ``u . u_ref = 0``, ``u_ref`` the slip direction when the step began, on the smooth
    continuation of the sliding solution): the disk rolls if the rolling friction force
    lies inside the cone ``|F_t| <= mu_s F_z``, else it slides on in the new direction.

Terminal guards as on the ideal grounds: lift-off (``F_z = 0``, eq. 11), edge contact
(``theta = 0`` with ``h > 0``), fell flat (``|theta| = pi/2``).

Integration: scipy's ``DOP853`` stepped one step at a time; after each step every event
function is evaluated on the step's dense output (at 9 points) and a sign change is located
by ``brentq`` on ``sol(t)``, never only at step ends.  The energy dissipated by each term is
integrated as four extra quadrature states, so ``E + dissipated = const`` (eq. 12) can be
checked along a run.  A step budget, a transition budget and a minimal step size bound the
work: the run then ends with status ``"failed"`` and a message, never a hang.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from rollingdisk.friction import coulomb as _cl
from rollingdisk.friction.coulomb import MODE_NAMES, coulomb_contact
from rollingdisk.friction.ground import Coulomb
from rollingdisk.integrate.simulation import _check_state
from rollingdisk.integrate.trajectory import Trajectory, Transition
from rollingdisk.model.disk import Disk
from rollingdisk.model.geometry import _geometry
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["simulate_coulomb", "slip_direction", "energy_balance", "DISSIPATION_TERMS"]

#: Names of the dissipation terms recorded in :attr:`Trajectory.dissipated`.
DISSIPATION_TERMS = ("slip", "rolling_resistance", "pivot", "air")

ROLLING, SLIDING = _cl.ROLLING, _cl.SLIDING
_NAMES = _cl.MODE_NAMES
_N_SAMPLE = 9  # points of the dense output at which events are looked for, per step
#: Slip speed below which sliding keeps the reference direction (the solved initial slip
#: direction, or the last resolved one): below it u/|u| is rounding noise.
U_EPS = 1e-8
#: Slip speed (relative to 1 + |V|) above which a zero of ``u . u_ref`` is a turn of the slip
#: direction, not the slip coming to rest.
STICK_TOL = 1e-6


def _slip_accel(h, mu_k, coeffs, y, e_x, e_y):
    """Slip acceleration ``du/dt`` (Cxyz) at a state with ``u = 0``, sliding with friction
    ``-mu_k F_z e`` (``e`` in Cxyz): eq. (6) differentiated along (8), (9), (11)."""
    theta, w1, w2, w3 = y[5], y[7], y[8], y[9]
    ht, s, c, p, y_P, z_P = _geometry(h, theta)
    M = _cl._coulomb_moments(*coeffs, theta, w1, w2, w3)
    d1, d2, d3, F_x, F_y, F_z = _cl._sliding_solve(h, mu_k, e_x, e_y, theta, w1, w2, w3, *M)
    Om = w3 / c
    v_Cx = w2 - ht * w3  # u = 0
    v_Cy = w1 * z_P
    dv_Cx = F_x + v_Cy * Om  # eq. (8)_1: rate of the Cxyz component
    dv_Cy = F_y - v_Cx * Om  # eq. (8)_2
    # u_x = v_Cx - w2 + h~ w3, u_y = v_Cy - w1 z_P; d z_P/d theta = y_P; at u = 0 the
    # turning of Cxyz adds nothing to du/dt
    return dv_Cx - d2 + ht * d3, dv_Cy - d1 * z_P - w1 * w1 * y_P


def slip_direction(disk: Disk, ground: Coulomb, y) -> tuple[float, float] | None:
    """The direction in which a rolling disk at state ``y`` (``u = 0``) starts to slide.

    The unit vector ``d`` (Cxyz components) such that, sliding with friction
    ``-mu_k F_z d``, the slip acceleration ``du/dt`` is along ``+d`` (so that the slip
    grows in the direction friction assumed).  Found by scanning the angle of ``d`` and
    ``brentq`` on ``d x du/dt = 0``; among the roots with ``d . du/dt > 0`` the one of
    largest slip acceleration.  ``None`` if there is none (the disk can keep rolling).
    """
    h = disk.h
    mu_k = ground.mu_k
    coeffs = ground.coefficients
    y = np.asarray(y, dtype=float)

    from scipy.optimize import brentq

    def parts(a):
        ex, ey = math.cos(a), math.sin(a)
        ax, ay = _slip_accel(h, mu_k, coeffs, y, ex, ey)
        return ex * ay - ey * ax, ex * ax + ey * ay

    grid = np.linspace(0.0, 2.0 * math.pi, 145)
    vals = [parts(a)[0] for a in grid]
    best = None
    for i in range(grid.size - 1):
        f0, f1 = vals[i], vals[i + 1]
        if f0 == 0.0:
            a = grid[i]
        elif f0 * f1 < 0.0:
            a = brentq(lambda x: parts(x)[0], grid[i], grid[i + 1], xtol=1e-15, rtol=8.9e-16)
        else:
            continue
        along = parts(a)[1]
        if along > 0.0 and (best is None or along > best[1]):
            best = (a, along)
    if best is None:
        return None
    return math.cos(best[0]), math.sin(best[0])


def energy_balance(traj: Trajectory) -> float:
    """Largest relative violation of ``E + dissipated = const`` along a Coulomb run (eq. 12),
    relative to ``max(|E(0)|, 1)``."""
    if traj.dissipated is None:
        raise ParameterError("energy_balance needs a Coulomb-ground trajectory")
    total = traj.E + sum(traj.dissipated.values())
    return float(np.max(np.abs(total - total[0])) / max(abs(total[0]), 1.0))


class _Singular(ArithmeticError):
    """The right-hand side left floating-point range (scipy's DOP853 would loop on NaN)."""


def _finite(t, out):
    if not np.all(np.isfinite(out)):
        raise _Singular(f"t = {t:.12g}")
    return out


class _Run:
    """One hybrid run: the right-hand sides and event functions of both modes."""

    def __init__(self, disk, ground, alpha_min=0.0):
        self.alpha_min = alpha_min
        self.side = 1.0  # sgn(theta) on the current segment (edge-contact event)
        self.h = disk.h
        self.g = ground
        self.coeffs = ground.coefficients
        self.ref = (1.0, 0.0)  # inertial slip reference direction (sliding)
        self.n_rhs = 0

    def rhs(self, mode):
        h, g, cf = self.h, self.g, self.coeffs

        if mode == ROLLING:
            def f(t, z):
                self.n_rhs += 1
                dy, F_x, F_y, F_z, P1, P2, P3 = _cl._coulomb_rolling(h, *cf, z)
                return _finite(t, np.array([*dy, 0.0, -P1, -P2, -P3]))
        else:
            def f(t, z):
                self.n_rhs += 1
                dy, F_x, F_y, F_z, P0, P1, P2, P3 = _cl._coulomb_sliding(
                    h, g.mu_k, *cf, z, self.ref[0], self.ref[1], U_EPS)
                return _finite(t, np.array([*dy, -P0, -P1, -P2, -P3]))
        return f

    def contact(self, mode, z):
        """``(F_t, F_z, u_ref_component)`` at ``z`` in ``mode``."""
        h, cf = self.h, self.coeffs
        if mode == ROLLING:
            _, F_x, F_y, F_z, *_ = _cl._coulomb_rolling(h, *cf, z)
            return math.hypot(F_x, F_y), F_z, 0.0
        _, F_x, F_y, F_z, *_ = _cl._coulomb_sliding(h, self.g.mu_k, *cf, z, *self.ref, U_EPS)
        u_x, u_y = _cl._slip_velocity(h, z)
        U_X, U_Y = _cl._to_inertial(z[4], u_x, u_y)
        return math.hypot(F_x, F_y), F_z, U_X * self.ref[0] + U_Y * self.ref[1]

    def events(self, mode, z):
        """Event functions, each crossing from > 0 to <= 0:
        ``[mode end, lift-off, edge contact, fell flat]``."""
        F_t, F_z, along = self.contact(mode, z)
        end = self.g.mu_s * F_z - F_t if mode == ROLLING else along
        theta = z[5]
        return [end, F_z, theta * self.side if self.h > 0 else 1.0,
                0.5 * math.pi - abs(theta) - self.alpha_min]


def _DOP853():
    """scipy's DOP853 class, imported when a Coulomb run starts (``import rollingdisk``
    must not load ``scipy.integrate``, 0.3 s)."""
    from scipy.integrate import DOP853

    return DOP853


def _inertial_slip(h, z):
    u_x, u_y = _cl._slip_velocity(h, z)
    return _cl._to_inertial(z[4], u_x, u_y)


@dataclass(frozen=True, eq=False, repr=False)  # Trajectory's short repr, not every array
class CoulombTrajectory(Trajectory):
    """A :class:`~rollingdisk.Trajectory` on Coulomb ground (what :func:`simulate_coulomb`
    returns): the contact force at each stored point follows from that point's mode."""

    @cached_property
    def _F(self):
        rows = [coulomb_contact(self.disk, self.ground, MODE_NAMES[m], self.y[:, i])
                for i, m in enumerate(self.mode)]
        return tuple(np.array([r[k] for r in rows]) for k in ("F_x", "F_y", "F_z"))


def simulate_coulomb(disk: Disk, ground: Coulomb, t_span: Sequence[float], y0, *,
                     rtol: float = 1e-11, atol: float = 1e-12, max_step: float = math.inf,
                     max_steps: int = 2_000_000, max_transitions: int = 10_000,
                     slip_tol: float = 1e-12, alpha_min: float = 1e-8, guards: bool = True,
                     progress: Callable[[float], None] | None = None) -> Trajectory:
    """Integrate the disk on Coulomb ground: rolling and sliding with located transitions.

    Parameters
    ----------
    disk : Disk
    ground : Coulomb
        Friction coefficients and dissipative moments (:mod:`rollingdisk.friction.ground`).
    t_span : (t0, t1)
        ``t1 > t0``.
    y0 : array_like, shape (10,)
        ``[X_C, Y_C, V_X, V_Y, psi, theta, phi, omega1, omega2, omega3]``
        (:data:`~rollingdisk.friction.coulomb.COULOMB_STATE`).  The run starts rolling if the slip
        ``|u|`` (eq. 6) is at most ``slip_tol (1 + |V|)`` and the friction rolling needs
        lies in the cone ``|F_t| <= mu_s F_z``; it starts sliding otherwise (a transition
        ``rolling -> sliding`` at ``t0`` when the slip was zero).  Use
        :func:`rollingdisk.friction.coulomb.rolling_state` to start from a rough-ground state.
    rtol, atol : float
        Tolerances of DOP853.
    max_step : float
        Largest step.
    max_steps, max_transitions : int
        Budgets of steps and of mode events (transitions, and slip reversals or turns that
        restart the integrator); beyond either the run stops with status ``"failed"`` and
        says why.
    slip_tol : float
        Relative slip below which the initial state counts as rolling.
    alpha_min : float
        The disk counts as fallen flat when its tilt ``alpha = pi/2 - |theta|`` reaches
        ``alpha_min`` (``>= 0``): near ``alpha = 0`` the precession rate grows without
        bound (Euler's disk, a finite-time singularity) and the steps would collapse.
    guards : bool
        Stop at lift-off, edge contact and falling flat (default).
    progress : callable, optional
        ``progress(fraction)``, called at most about 100 times.

    Returns
    -------
    Trajectory
        With ``ground`` the :class:`Coulomb` value, ``mode`` per stored point,
        ``transitions`` and ``dissipated`` (see :class:`Trajectory`); ``method="dop853-scipy"``.

    Examples
    --------
    >>> tr = simulate_coulomb(Disk(0.0), Coulomb(0.2), (0, 2), [0, 0, 1, 0, 0, 0, 0, 0, 0, 0])
    >>> [(round(x.t, 9), x.from_mode, x.to_mode) for x in tr.transitions]
    [(1.666666667, 'sliding', 'rolling')]
    """
    if not isinstance(disk, Disk):
        raise ParameterError(f"disk must be a rollingdisk.Disk, got {disk!r}")
    if not isinstance(ground, Coulomb):
        raise ParameterError(f"ground must be a rollingdisk.Coulomb(...) value, got {ground!r}")
    y = _check_state(disk, "smooth", y0)
    try:
        t0, t1 = (float(v) for v in t_span)
    except (TypeError, ValueError):
        raise ParameterError(f"t_span must be a pair (t0, t1) of real numbers, got {t_span!r}") \
            from None
    if not (math.isfinite(t0) and math.isfinite(t1) and t1 > t0):
        raise ParameterError(f"t_span must be a pair (t0, t1) of finite numbers with t1 > t0, "
                             f"got {t_span!r}")
    rtol = check_real("rtol", rtol, low=0.0, low_open=True)
    atol = check_real("atol", atol, low=0.0, low_open=True)
    if max_step != math.inf:
        max_step = check_real("max_step", max_step, low=0.0, low_open=True)
    slip_tol = check_real("slip_tol", slip_tol, low=0.0)
    alpha_min = check_real("alpha_min", alpha_min, low=0.0, high=0.5 * math.pi, high_open=True)
    for name, v in (("max_steps", max_steps), ("max_transitions", max_transitions)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 1:
            raise ParameterError(f"{name} must be an integer >= 1, got {v!r}")

    h = disk.h
    run = _Run(disk, ground, alpha_min)
    z = np.concatenate([y, np.zeros(4)])
    transitions: list[Transition] = []
    ts, zs, modes = [t0], [], []

    # -- initial mode ----------------------------------------------------------------------
    U = _inertial_slip(h, z)
    speed = math.hypot(z[2], z[3])
    if math.hypot(*U) <= slip_tol * (1.0 + speed):
        z[2], z[3] = _cl._rolling_velocity(h, z)
        F_t, F_z, _ = run.contact(ROLLING, z)
        mode = ROLLING
        if F_t > ground.mu_s * F_z:
            mode = _start_sliding(run, disk, ground, z)
            transitions.append(Transition(t0, "rolling", "sliding"))
    else:
        mode = SLIDING
        n = math.hypot(*U)
        run.ref = (U[0] / n, U[1] / n)
    zs.append(z.copy())
    modes.append(mode)

    status, message, t_event = "completed", "", None
    n_steps = 0
    n_mode_events = 0
    last_turn = None
    next_report = 0.01
    wall0 = time.perf_counter()
    t = t0
    while True:  # one mode segment per pass
        run.side = 1.0 if z[5] >= 0 else -1.0
        solver = _DOP853()(run.rhs(mode), t, z, t1, rtol=rtol, atol=atol, max_step=max_step)
        g_old = run.events(mode, z)
        switched = False
        while solver.status == "running":
            if n_steps >= max_steps:
                status = "failed"
                message = (f"step budget exhausted: {max_steps} steps by t = {solver.t:.12g}; "
                           "raise max_steps or shorten t_span")
                break
            try:
                with np.errstate(all="ignore"):
                    msg = solver.step()
            except _Singular as exc:
                status = "failed"
                message = (f"the equations became singular at {exc} (a non-finite right-hand "
                           f"side, theta = {solver.y[5]:.6g} at the step start)")
                break
            n_steps += 1
            if solver.status == "failed":
                status = "failed"
                message = (f"the integrator gave up at t = {solver.t:.12g} ({msg}): step sizes "
                           "collapsed")
                break
            if not np.all(np.isfinite(solver.y)):
                status = "failed"
                message = (f"the state left floating-point range at t = {solver.t:.12g} "
                           "(the motion became singular)")
                break
            ta, tb = solver.t_old, solver.t
            try:  # the interpolant evaluates the right-hand side too
                with np.errstate(all="ignore"):
                    sol = solver.dense_output()
            except _Singular as exc:
                status = "failed"
                message = (f"the equations became singular at {exc} (a non-finite right-hand "
                           f"side, theta = {solver.y[5]:.6g} at the step end)")
                break
            hit = _first_event(run, mode, sol, ta, tb, g_old, h > 0 and guards, guards)
            if hit is None:
                t, z = tb, solver.y.copy()
                ts.append(t)
                zs.append(z.copy())
                modes.append(mode)
                g_old = run.events(mode, z)
                if mode == SLIDING:
                    U = _inertial_slip(h, z)
                    n = math.hypot(*U)
                    if n > U_EPS:
                        run.ref = (U[0] / n, U[1] / n)
                        g_old = run.events(mode, z)
                if progress is not None and (t - t0) / (t1 - t0) >= next_report:
                    progress(min(1.0, (t - t0) / (t1 - t0)))
                    next_report = (t - t0) / (t1 - t0) + 0.01
                continue
            k, te = hit
            t, z = te, np.asarray(sol(te), dtype=float).copy()
            ts.append(t)
            zs.append(z.copy())
            modes.append(mode)
            if k > 0:  # terminal guard
                status = ("lift-off", "edge-contact", "fell-flat")[k - 1]
                t_event = t
                message = _message(status, t, h)
                break
            n_mode_events += 1
            if n_mode_events > max_transitions:
                status = "failed"
                message = (f"transition budget exhausted: {max_transitions} mode events by "
                           f"t = {t:.12g} (sticking and slipping chatter?)")
                break
            if mode == SLIDING:
                U = _inertial_slip(h, z)
                n = math.hypot(*U)
                if n > STICK_TOL * (1.0 + math.hypot(z[2], z[3])):
                    if last_turn is not None and t - last_turn <= 1e-12 * (1.0 + abs(t)):
                        status = "failed"
                        message = (f"stuck at t = {t:.12g}: the slip direction turned twice at "
                                   "the same time (a discontinuity of the equations)")
                        break
                    last_turn = t
                    # u turned across the reference direction without vanishing: a new
                    # reference, no transition
                    run.ref = (U[0] / n, U[1] / n)
                    switched = True
                    break
            if mode == ROLLING:
                new = _start_sliding(run, disk, ground, z)
            else:
                z[2], z[3] = _cl._rolling_velocity(h, z)  # u = 0 up to the event tolerance
                F_t, F_z, _ = run.contact(ROLLING, z)
                new = ROLLING if F_t <= ground.mu_s * F_z else _start_sliding(run, disk,
                                                                               ground, z)
            if new != mode:
                transitions.append(Transition(t, _NAMES[mode], _NAMES[new]))
            mode = new
            switched = True
            break
        if not switched:
            break
    wall = time.perf_counter() - wall0
    if status == "completed":
        message = f"reached t = {t:.12g}"
    Z = np.array(zs).T
    if progress is not None:
        progress(1.0)
    return CoulombTrajectory(disk=disk, ground=ground, t=np.array(ts), y=Z[:10], status=status,
                      message=message, n_steps=n_steps, n_rhs=run.n_rhs, method="dop853-scipy",
                      t_event=t_event, wall_time=wall, mode=np.array(modes),
                      transitions=tuple(transitions),
                      dissipated={k: Z[10 + i].copy() for i, k in enumerate(DISSIPATION_TERMS)})


def _start_sliding(run, disk, ground, z):
    """Switch to sliding at a state with ``u = 0``: the slip direction is solved."""
    d = slip_direction(disk, ground, z[:10])
    if d is None:  # no consistent slip direction: oppose the rolling friction force
        _, F_x, F_y, *_ = _cl._coulomb_rolling(disk.h, *ground.coefficients, z)
        n = math.hypot(F_x, F_y) or 1.0
        d = (-F_x / n, -F_y / n)
    run.ref = _cl._to_inertial(z[4], d[0], d[1])
    return SLIDING


def _first_event(run, mode, sol, ta, tb, g_old, edge, guards):
    """The first event in ``(ta, tb]`` on the dense output ``sol``: ``(index, time)``."""
    from scipy.optimize import brentq

    active = [True, guards, edge, guards]
    ts = np.linspace(ta, tb, _N_SAMPLE)
    prev = g_old
    best = None
    for i in range(1, ts.size):
        gi = run.events(mode, np.asarray(sol(ts[i])))
        for k in range(4):
            if active[k] and prev[k] > 0.0 and gi[k] <= 0.0:
                def fk(s, k=k):
                    return run.events(mode, np.asarray(sol(s)))[k]
                te = ts[i] if gi[k] == 0.0 else brentq(fk, ts[i - 1], ts[i], xtol=1e-15,
                                                        rtol=8.9e-16, maxiter=200)
                if best is None or te < best[1]:
                    best = (k, te)
        if best is not None:
            k, te = best
            if k != 2 and active[2] and prev[2] > 0.0 and gi[2] <= 0.0:
                # theta crossing 0 flips h~ and makes u and F jump: an event of the mode
                # found at that jump is the edge contact itself
                te2 = ts[i] if gi[2] == 0.0 else brentq(
                    lambda s: run.events(mode, np.asarray(sol(s)))[2], ts[i - 1], ts[i],
                    xtol=1e-15, rtol=8.9e-16, maxiter=200)
                if te2 - te <= 1e-9 * (1.0 + abs(te2)):
                    return 2, te2
            return best
        prev = gi
    return None


def _message(status, t, h):
    if status == "lift-off":
        return (f"lift-off at t = {t:.12g}: the normal force F_z (eq. 11) reached 0 and the "
                "disk leaves the plane; the model ends here")
    if status == "edge-contact":
        return (f"edge contact at t = {t:.12g}: theta reached 0 with h = {h:g} > 0, the disk "
                "lands on its other rim edge (an impact, outside the model)")
    return (f"fell flat at t = {t:.12g}: the tilt pi/2 - |theta| reached alpha_min, the disk "
            "lies on the plane")
