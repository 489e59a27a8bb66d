"""The disk with a rounded rim in motion: an :class:`~rollingdisk.engine.contract.Model`
run by the engine's one step loop.

The equations of motion are those of :mod:`rollingdisk.model.rim` (a body of revolution
whose rim is rounded with radius ``rho``, derived in :mod:`rollingdisk.symbolic.rounded`);
this module writes them in the contract's form ``rhs(t, y, p, out)`` on the state layouts
of the sharp disk's :func:`~rollingdisk.simulate` (:data:`~rollingdisk.model.state.ROUGH_STATE`,
:data:`~rollingdisk.model.state.SMOOTH_STATE`) and hands them to
:func:`rollingdisk.engine.driver.solve`, compiled or not.  No step loop is written here.

Dimensionless units (m = a = g = 1): lengths in ``a``, time in ``sqrt(a/g)``, angular
speeds in ``sqrt(g/a)``, forces in ``m g``, energies in ``m g a``.

What is simulated
-----------------
The contact rolls (rough ground) or slides without friction (smooth ground) over the
rounded arc; the motion is smooth for ``0 < |theta| < pi/2``.  The run ends, as a
terminal event located on the dense output, where the one-point contact on the arc ends:

``lift-off``
    the normal force ``F_z`` (:func:`~rollingdisk.model.rim.rounded_normal_force`) falls
    to 0;
``fell-flat``
    ``|theta|`` reaches ``pi/2``: the disk lies on a face;
``tread-contact``
    ``theta`` reaches 0 while ``rho < h``.  There the flat tread (a line of length
    ``2 (h - rho)``) touches and the contact point jumps from one arc to the other: an
    impact-free rocking across a flat tread is not a smooth rolling, so the model ends
    there, as the sharp disk's edge contact does (status ``edge-contact``).  When
    ``rho = h`` the tread is a half circle, ``hp = (h - rho) sgn(theta) = 0`` on both
    sides and the equations are smooth across ``theta = 0``: the disk rocks through it
    with no event and no impact.

The lift-off function is the normal force of the side the motion started on
(``hp = (h - rho) side``), so the jump of ``hp`` at ``theta = 0`` is never taken for a
lift-off (as the sharp disk's :func:`~rollingdisk.model.events.LiftOff`).
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from rollingdisk.engine.contract import Model
from rollingdisk.engine.driver import solve
from rollingdisk.model.disk import Disk, check_ground
from rollingdisk.model.outcomes import EDGE_CONTACT, FELL_FLAT, LIFT_OFF, outcome
from rollingdisk.model.rim import (
    rim_contact,
    rim_inertia,
    rounded_energy,
    rounded_normal_force,
    rounded_omega_dot,
    rounded_rough_omega_dot,
)
from rollingdisk.model.state import ROUGH_STATE, SMOOTH_STATE, as_state
from rollingdisk.results.trajectory import Trajectory
from rollingdisk.util.checks import check_real, check_span
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["ROUNDED_ROUGH", "ROUNDED_SMOOTH", "RoundedTrajectory", "rounded_model",
           "rounded_parameters", "simulate_rounded", "simulate_rounded_steady",
           "rounded_initial_state", "simulate_options", "rounded_frequency"]

# the state components, by name (model.state's layouts)
R_X, R_Y, R_PSI, R_THETA, R_PHI, R_W1, R_W2, R_W3 = range(8)
S_X, S_Y, S_VX, S_VY, S_PSI, S_THETA, S_PHI, S_W1, S_W2, S_W3 = range(10)
# the parameter vector
P_H, P_RHO, P_K1, P_K2, P_SIDE, P_TREAD = range(6)
# the event functions, in the order of Model.event_names
E_TREAD, E_LIFT, E_FLAT = range(3)
_HALF_PI = 0.5 * math.pi


# ------------------------------------------------------------------ the model's functions
def _side_h(h, rho, side, theta):
    """The half-thickness that gives ``hp = (h - rho) side`` at ``theta`` (the kernels use
    ``h`` only through ``hp``): ``h`` on the starting side, ``2 rho - h`` past 0 (and at
    ``theta = 0`` coming from below, which the kernels count as ``0+``)."""
    if theta * side < 0.0 or (theta == 0.0 and side < 0.0):
        return 2.0 * rho - h
    return h


def _guards(rough, p, theta, w1, w2, w3, g):
    """The three event functions, each positive while the arc contact holds."""
    h, rho, side = p[P_H], p[P_RHO], p[P_SIDE]
    if p[P_TREAD] != 0.0:
        g[E_TREAD] = theta * side
    else:
        g[E_TREAD] = 1.0  # rho = h: theta = 0 is on the arc, no event
    hs = _side_h(h, rho, side, theta)
    g[E_LIFT] = rounded_normal_force(rough, hs, rho, p[P_K1], p[P_K2], theta, w1, w2, w3)
    g[E_FLAT] = _HALF_PI - abs(theta)


def rough_rhs(t, y, p, out):
    """``dy/dt`` on rough ground (rolling without slip), :data:`ROUGH_STATE` layout: eqs.
    (1), (2) with ``v_C = -omega x r_CP``, ``r_CP = (0, -H, -A)`` (so ``v_Cx = A omega2 -
    H omega3``, ``v_Cy = omega1 z_P``; eq. 37 at ``rho = 0``) and
    :func:`~rollingdisk.model.rim.rounded_omega_dot`."""
    h, rho, k1, k2 = p[P_H], p[P_RHO], p[P_K1], p[P_K2]
    theta, w1, w2, w3 = y[R_THETA], y[R_W1], y[R_W2], y[R_W3]
    hp, A, H, y_P, z_P = rim_contact(h, rho, theta)
    d1, d2, d3 = rounded_omega_dot(True, h, rho, k1, k2, theta, w1, w2, w3)
    v_x = A * w2 - H * w3
    v_y = w1 * z_P
    cp = math.cos(y[R_PSI])
    sp = math.sin(y[R_PSI])
    c = math.cos(theta)
    out[R_X] = v_x * cp - v_y * sp  # eq. (1)
    out[R_Y] = v_x * sp + v_y * cp
    out[R_PSI] = w3 / c  # eq. (2)
    out[R_THETA] = w1
    out[R_PHI] = w2 - w3 * math.sin(theta) / c
    out[R_W1] = d1
    out[R_W2] = d2
    out[R_W3] = d3


def smooth_rhs(t, y, p, out):
    """``dy/dt`` on smooth ground (no friction), :data:`SMOOTH_STATE` layout: C moves
    horizontally at the constant ``(V_X, V_Y)`` (eq. 8 with ``F_x = F_y = 0``), eq. (2) and
    :func:`~rollingdisk.model.rim.rounded_omega_dot`."""
    h, rho, k1, k2 = p[P_H], p[P_RHO], p[P_K1], p[P_K2]
    theta, w1, w2, w3 = y[S_THETA], y[S_W1], y[S_W2], y[S_W3]
    d1, d2, d3 = rounded_omega_dot(False, h, rho, k1, k2, theta, w1, w2, w3)
    c = math.cos(theta)
    out[S_X] = y[S_VX]
    out[S_Y] = y[S_VY]
    out[S_VX] = 0.0
    out[S_VY] = 0.0
    out[S_PSI] = w3 / c  # eq. (2)
    out[S_THETA] = w1
    out[S_PHI] = w2 - w3 * math.sin(theta) / c
    out[S_W1] = d1
    out[S_W2] = d2
    out[S_W3] = d3


def rough_events(t, y, p, g):
    """The event functions on rough ground (:func:`_guards`)."""
    _guards(True, p, y[R_THETA], y[R_W1], y[R_W2], y[R_W3], g)


def smooth_events(t, y, p, g):
    """The event functions on smooth ground (:func:`_guards`)."""
    _guards(False, p, y[S_THETA], y[S_W1], y[S_W2], y[S_W3], g)


def rough_energy(t, y, p):
    """Energy [``m g a``] on rough ground (:func:`~rollingdisk.model.rim.rounded_energy`)."""
    return float(rounded_energy(True, p[P_H], p[P_RHO], p[P_K1], p[P_K2], y[R_THETA],
                                y[R_W1], y[R_W2], y[R_W3]))


def smooth_energy(t, y, p):
    """Energy [``m g a``] on smooth ground: :func:`~rollingdisk.model.rim.rounded_energy`
    and the (constant) kinetic energy of C's horizontal motion."""
    return float(rounded_energy(False, p[P_H], p[P_RHO], p[P_K1], p[P_K2], y[S_THETA],
                                y[S_W1], y[S_W2], y[S_W3])
                 + 0.5 * (y[S_VX] * y[S_VX] + y[S_VY] * y[S_VY]))


_EVENTS = ("tread-contact", "lift-off", "fell-flat")
_OUTCOME_OF_EVENT = {"tread-contact": EDGE_CONTACT, "lift-off": LIFT_OFF,
                     "fell-flat": FELL_FLAT}
_HELPERS = (rim_contact, rounded_omega_dot, rounded_rough_omega_dot, rounded_normal_force,
            _side_h, _guards)

#: The rounded disk on rough ground, as the engine takes it.
ROUNDED_ROUGH = Model("rounded disk on rough ground", ROUGH_STATE, rough_rhs, rough_events,
                      _EVENTS, (-1, -1, -1), ("terminal",) * 3, energy=rough_energy,
                      helpers=_HELPERS)
#: The rounded disk on smooth ground, as the engine takes it.
ROUNDED_SMOOTH = Model("rounded disk on smooth ground", SMOOTH_STATE, smooth_rhs,
                       smooth_events, _EVENTS, (-1, -1, -1), ("terminal",) * 3,
                       energy=smooth_energy, helpers=_HELPERS)


def rounded_model(ground: str) -> Model:
    """The :class:`~rollingdisk.engine.contract.Model` of the rounded disk on ``ground``
    (``"rough"`` or ``"smooth"``)."""
    return ROUNDED_ROUGH if check_ground(ground) == "rough" else ROUNDED_SMOOTH


def rounded_parameters(disk: Disk, theta0: float) -> np.ndarray:
    """The parameter vector ``p`` of :func:`rounded_model` for ``disk`` started at tilt
    ``theta0`` [rad]: ``(h, rho, k1^2, k2^2, side, tread)``, ``side = sgn(theta0)``,
    ``tread = 1`` when the tread-contact event is on (``rho < h``), else 0."""
    h, rho = disk.h, disk.rim_radius
    k1, k2 = rim_inertia(h, rho)
    return np.array([h, rho, k1, k2, 1.0 if theta0 >= 0.0 else -1.0,
                     1.0 if rho < h else 0.0])


# ------------------------------------------------------------------ the result
@dataclass(frozen=True, repr=False)
class RoundedTrajectory(Trajectory):
    """A :class:`~rollingdisk.Trajectory` of the rounded disk: the same fields and state
    layouts; the contact point, contact force and energy are those of the rounded rim
    (:mod:`rollingdisk.model.rim`)."""

    def __repr__(self) -> str:
        return super().__repr__().replace(", t=", f", rim_radius={self.disk.rim_radius:g}, t=",
                                          1)

    def _reduced(self):
        i = 3 if self.ground == "rough" else 5
        return self.y[i], self.y[i + 2], self.y[i + 3], self.y[i + 4]

    def _kernel_args(self):
        d = self.disk
        return (self.ground == "rough", d.h, d.rim_radius, *rim_inertia(d.h, d.rim_radius))

    @cached_property
    def _P(self):
        theta = self._reduced()[0]
        psi = self.y[2] if self.ground == "rough" else self.y[4]
        y_P = rim_contact(self.disk.h, self.disk.rim_radius, theta)[3]
        return self.y[0] - y_P * np.sin(psi), self.y[1] + y_P * np.cos(psi)  # eq. (5)

    @cached_property
    def _F(self):
        """``(F_x, F_y, F_z)`` in Cxyz [``m g``]: eq. (8) with the rounded contact.  On rough
        ground ``m a_C`` in the frame turning at ``Omega = omega3 / cos(theta)``:
        ``F_x = d/dt (A omega2 - H omega3) - v_Cy Omega`` with ``A' = -rho sin``,
        ``H' = rho cos``, and ``F_y = d/dt (omega1 z_P) + v_Cx Omega`` with
        ``dz_P/dtheta = y_P``."""
        rough, h, rho, k1, k2 = self._kernel_args()
        theta, w1, w2, w3 = self._reduced()
        F_z = rounded_normal_force(rough, h, rho, k1, k2, theta, w1, w2, w3)
        if not rough:
            return 0.0 * F_z, 0.0 * F_z, F_z
        hp, A, H, y_P, z_P = rim_contact(h, rho, theta)
        d1, d2, d3 = rounded_omega_dot(True, h, rho, k1, k2, theta, w1, w2, w3)
        s, c = np.sin(theta), np.cos(theta)
        Omega = w3 / c
        F_x = A * d2 - H * d3 - rho * w1 * (s * w2 + c * w3) - w1 * z_P * Omega
        F_y = z_P * d1 + y_P * w1 * w1 + (A * w2 - H * w3) * Omega
        return F_x, F_y, F_z

    @cached_property
    def E(self) -> np.ndarray:
        """Mechanical energy [``m g a``] (eq. 13 with the rounded contact,
        :func:`~rollingdisk.model.rim.rounded_energy`; on smooth ground with the constant
        kinetic energy of C's horizontal motion, as the sharp disk's)."""
        E = rounded_energy(*self._kernel_args(), *self._reduced())
        if self.ground != "rough":
            E = E + 0.5 * (self.y[S_VX] ** 2 + self.y[S_VY] ** 2)
        return np.asarray(E)


# ------------------------------------------------------------------ simulate
def _messages(rho, h):
    return {
        "tread-contact": f"theta reached 0 with rim_radius = {rho:g} < h = {h:g}: the flat "
        "tread touches and the contact jumps to the other arc (outside the model)",
        "lift-off": "the normal force F_z reached 0: the disk leaves the plane",
        "fell-flat": "|theta| reached pi/2: the disk lies on a face"}


def simulate_rounded(disk: Disk, ground: str, t_span, y0, *, rtol: float = 1e-11,
                     atol: float = 1e-12, max_step: float = math.inf,
                     max_steps: int = 10_000_000, compiled: bool | None = None
                     ) -> RoundedTrajectory:
    """Integrate the rounded disk from ``y0`` over ``t_span`` until a terminal event.

    Runs :func:`rounded_model` through :func:`rollingdisk.engine.driver.solve` (DOP853,
    events located on its dense output); the module docstring says what ends a run.

    Parameters
    ----------
    disk : Disk
        Its ``h`` and ``rim_radius`` (``0 <= rho <= min(h, 1)``, units of ``a``) enter;
        ``rim_radius = 0`` is the sharp disk (the tread contact is then its edge contact).
    ground : {"rough", "smooth"}
    t_span : (t0, t1)
        Interval [``sqrt(a/g)``], ``t1 > t0``.
    y0 : array_like, shape (8,) or (10,)
        Initial state in the layout of :data:`~rollingdisk.model.state.ROUGH_STATE` /
        :data:`~rollingdisk.model.state.SMOOTH_STATE`; ``|theta| < pi/2``, and
        ``theta != 0`` unless ``rim_radius = h > 0``.
    rtol, atol : float
        Tolerances of DOP853 (relative; absolute in each component's unit).
    max_step : float
        Largest step [``sqrt(a/g)``].
    max_steps : int
        Step budget (status ``step-budget`` when spent).
    compiled : bool, optional
        Run the engine's loop and the model compiled with numba (both paths take the same
        steps); default: compiled for spans longer than 50 time units.

    Returns
    -------
    RoundedTrajectory
        Status ``completed``, ``lift-off``, ``fell-flat``, ``edge-contact`` (the tread
        contact), ``step-budget`` or ``failed`` (:mod:`rollingdisk.model.outcomes`).

    Raises
    ------
    ParameterTypeError
        If ``disk`` is not a :class:`Disk`.
    ParameterError
        For a state, interval or tolerance out of range (the message names it).
    """
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {type(disk).__name__}")
    ground = check_ground(ground)
    y = np.array(as_state(ground, y0, "y0"), dtype=float)
    theta = float(y[ROUGH_STATE.index("theta") if ground == "rough"
                    else SMOOTH_STATE.index("theta")])
    h, rho = disk.h, disk.rim_radius
    if abs(theta) >= _HALF_PI:
        raise ParameterError(f"theta in y0 must lie in (-pi/2, pi/2), got {theta!r}")
    if theta == 0.0 and rho < h:
        raise ParameterError(f"theta in y0 must be nonzero when rim_radius < h (at theta = 0 "
                             f"the disk stands on its flat tread), got rim_radius = {rho!r}, "
                             f"h = {h!r}")
    t0, t1 = check_span(t_span)
    if compiled is None:
        compiled = t1 - t0 > 50.0
    elif not isinstance(compiled, (bool, np.bool_)):
        raise ParameterTypeError(f"compiled must be True, False or None, got {compiled!r}")
    max_step = math.inf if max_step == math.inf else check_real(
        "max_step", max_step, low=0.0, low_open=True)
    model = rounded_model(ground)
    p = rounded_parameters(disk, theta)
    with np.errstate(all="ignore"):
        ok = np.isfinite(model.energy(t0, y, p))
    if not ok:
        raise ParameterError(f"y0 is too large: its energy overflows, got {y.tolist()}")
    start = time.perf_counter()
    sol = solve(model, (t0, t1), y, p, rtol=rtol, atol=atol, max_step=max_step,
                max_steps=max_steps, compiled=bool(compiled))
    wall = time.perf_counter() - start
    status, t_event = sol.status, None
    message = f"{status} at t = {sol.t[-1]:.12g}: {sol.message}"
    if status == "completed" and sol.event_t.size:  # every event is terminal
        name = model.event_names[int(sol.event_index[-1])]
        status = outcome(_OUTCOME_OF_EVENT[name]).name
        t_event = float(sol.event_t[-1])
        message = f"{name} at t = {t_event:.12g}: {_messages(rho, h)[name]}"
    elif status == "completed":
        message = f"completed: integrated to t = {sol.t[-1]:.12g} in {sol.n_steps} steps"
    return RoundedTrajectory(disk=disk, ground=ground, t=sol.t, y=sol.y.T, status=status,
                             message=message, n_steps=sol.n_steps, n_rhs=sol.n_rhs,
                             method="dop853", t_event=t_event, wall_time=wall)


def simulate_options(disk: Disk, ground: str, t_span, y0, *, method, rtol, atol, max_step,
                     first_step, t_eval, dense_output, events, guards, max_steps,
                     error_control, progress, sink) -> RoundedTrajectory:
    """:func:`rollingdisk.simulate` for a disk with a rounded rim: the options the engine's
    DOP853 honours are passed to :func:`simulate_rounded`; any other option set raises
    :class:`~rollingdisk.util.errors.ParameterError` naming it."""
    unused = {"method": method not in ("auto", "dop853"), "first_step": first_step is not None,
              "t_eval": t_eval is not None, "dense_output": bool(dense_output),
              "events": events is not None, "guards": not guards,
              "error_control": error_control != "full", "progress": progress is not None,
              "sink": sink is not None}
    bad = [name for name, set_ in unused.items() if set_]
    if bad:
        raise ParameterError(
            f"a disk with a rounded rim (rim_radius = {disk.rim_radius:g}) runs on the "
            f"engine's DOP853 (rollingdisk.ivp.rounded.simulate_rounded), which takes "
            f"rtol, atol, max_step and max_steps; not: {', '.join(bad)}")
    return simulate_rounded(disk, ground, t_span, y0, rtol=rtol, atol=atol,
                            max_step=max_step, max_steps=max_steps)


def rounded_initial_state(motion, psi0: float = 0.0, phi0: float = 0.0) -> np.ndarray:
    """The full state of a :class:`~rollingdisk.theory.rounded.RoundedSteadyMotion`: C at
    the origin, ``omega1 = 0``; on smooth ground C at rest horizontally (``r_C = 0``)."""
    theta, w1, w2, w3 = motion.initial_state()
    if motion.ground == "rough":
        return np.array([0.0, 0.0, psi0, theta, phi0, w1, w2, w3])
    return np.array([0.0, 0.0, 0.0, 0.0, psi0, theta, phi0, w1, w2, w3])


def simulate_rounded_steady(motion, t_end: float, *, perturb: float = 0.0, kick: float = 0.0,
                            **options) -> RoundedTrajectory:
    """Simulate the rounded disk from a steady motion of :mod:`rollingdisk.theory.rounded`
    with ``theta(0)`` [rad] perturbed by ``perturb`` and ``omega1(0)`` [``sqrt(g/a)``] by
    ``kick`` (as :func:`rollingdisk.simulate_steady`); ``options`` go to
    :func:`simulate_rounded`.  The trajectory's ``theta_ref`` is ``motion.theta0``."""
    from rollingdisk.theory.rounded import RoundedSteadyMotion

    if not isinstance(motion, RoundedSteadyMotion):
        raise ParameterTypeError(f"motion must be a RoundedSteadyMotion, got "
                                 f"{type(motion).__name__}")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True)
    y0 = rounded_initial_state(motion)
    i = ROUGH_STATE.index("theta") if motion.ground == "rough" else SMOOTH_STATE.index("theta")
    y0[i] += check_real("perturb", perturb)
    y0[i + 2] += check_real("kick", kick)
    tr = simulate_rounded(motion.disk, motion.ground, (0.0, t_end), y0, **options)
    return dataclasses.replace(tr, theta_ref=float(motion.theta0))


def rounded_frequency(traj: Trajectory, *, min_periods: int = 2) -> float | None:
    """Angular frequency [``sqrt(g/a)``] of the oscillation of ``theta`` along ``traj``, or
    None with fewer than ``min_periods`` whole periods.

    The upward crossings of ``theta - c`` (``c`` the time average of ``theta``) are found
    on the cubic Hermite interpolant of ``theta`` and ``d theta/dt = omega1`` between
    stored points (Newton's method from the secant root); the period is the
    least-squares slope of the crossing times against their index.  Store points densely
    (``max_step`` a small fraction of the period): the interpolant's error is
    ``O(dt^4)``.  Compare with ``sqrt(varpi2)`` of
    :func:`rollingdisk.theory.rounded.rounded_varpi2`.
    """
    t, th, w1 = traj.t, traj.theta, traj.omega1
    if t.size < 3:
        return None
    c = float(np.trapezoid(th, t) / (t[-1] - t[0]))
    v = th - c
    up = np.nonzero((v[:-1] < 0) & (v[1:] >= 0))[0]
    if up.size < min_periods + 1:
        return None
    tc = np.empty(up.size)
    for j, i in enumerate(up):
        dt = t[i + 1] - t[i]
        a, b, da, db = v[i], v[i + 1], w1[i] * dt, w1[i + 1] * dt
        x = a / (a - b)
        for _ in range(30):
            h00, h10 = 2 * x**3 - 3 * x**2 + 1, x**3 - 2 * x**2 + x
            h01, h11 = -2 * x**3 + 3 * x**2, x**3 - x**2
            f = h00 * a + h10 * da + h01 * b + h11 * db
            df = ((6 * x**2 - 6 * x) * a + (3 * x**2 - 4 * x + 1) * da
                  + (-6 * x**2 + 6 * x) * b + (3 * x**2 - 2 * x) * db)
            step = f / df
            x = min(max(x - step, 0.0), 1.0)
            if abs(step) < 1e-15:
                break
        tc[j] = t[i] + x * dt
    period = np.polyfit(np.arange(tc.size, dtype=float), tc, 1)[0]
    return float(2 * math.pi / period)
