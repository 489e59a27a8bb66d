"""Hybrid rolling/sliding simulation on Coulomb ground, with located mode transitions.

The disk is in one of two modes (:mod:`rollingdisk.model.coulomb`):

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
``..., pivot stuck``
    either mode with the vertical spin ``omega_z`` held at 0 by the pivoting friction
    (set-valued: ``|M_z| <= c F_z``).  Entered when ``omega_z`` reaches 0 (event
    ``sz omega_z``, ``sz`` its sign on the segment) and the moment that holds it fits in
    ``c F_z``; left when that moment reaches ``c F_z`` (event ``c F_z - |M_piv|``).
``..., roll stuck``
    any of these with the horizontal angular velocity ``omega_h`` held at 0 by the rolling
    resistance (set-valued: ``|M_h| <= c F_z``).  Outside it the moment is ``-c F_z
    sgn(omega_h . rref) omega_h/|omega_h|``, ``rref`` the direction of ``omega_h`` at the
    last step; at a zero of ``omega_h . rref`` with ``omega_h`` at rest (within
    :data:`STICK_TOL`) it sticks if the moment that holds it fits in ``c F_z``, else the
    moment flips; with ``omega_h`` not at rest ``rref`` is renewed.  Left when the holding
    moment reaches ``c F_z`` (event ``c F_z - |M_h|``).  Both paths (scipy, compiled) run
    every mode.

Terminal guards as on the ideal grounds: lift-off (``F_z = 0``, eq. 11), edge contact
(``theta = 0`` with ``h > 0``), fell flat (``|theta| = pi/2``).

Integration: DOP853 stepped one step at a time; after each step every event function is
evaluated on the step's dense output (at 9 points) and a sign change is located by
``brentq`` on ``sol(t)``, never only at step ends.  Two paths take the same steps: scipy's
``DOP853`` driven from Python, and the compiled loop of :mod:`rollingdisk.ivp.fastsegment`,
which hands the driver only a step where an event function changes sign (``method``,
:data:`PY_BUDGET`).  The energy dissipated by each term is integrated as four extra
quadrature states, so ``E + dissipated = const`` (eq. 12) can be checked along a run.
Budgets of steps (status ``"step-budget"``), wall clock (``"time-budget"``) and transitions
and a minimal step size (``"failed"``) bound the work, each with a message; a cap on the
stored points (thinning beyond it) bounds the memory.
"""

from __future__ import annotations

import functools
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from rollingdisk.engine.methods import check_method
from rollingdisk.ivp import fastsegment as _fs
from rollingdisk.ivp.simulation import _check_state
from rollingdisk.ivp.slipdir import (  # noqa: F401 - _slip_accel: tests and docs use it here
    _direction_scan,
    _slip_accel,
    _slip_direction,
    slip_direction,
)
from rollingdisk.model import coulomb as _cl
from rollingdisk.model.coulomb import MODE_NAMES, check_coulomb, coulomb_contact
from rollingdisk.model.disk import Disk
from rollingdisk.model.ground import Coulomb
from rollingdisk.results.trajectory import Trajectory, Transition
from rollingdisk.util.checks import check_real, check_span, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["simulate_coulomb", "slip_direction", "energy_balance", "DISSIPATION_TERMS"]

#: Names of the dissipation terms recorded in :attr:`Trajectory.dissipated`.
DISSIPATION_TERMS = ("slip", "rolling_resistance", "pivot", "air")

ROLLING, SLIDING, PIVOT_STUCK, ROLL_STUCK = (_cl.ROLLING, _cl.SLIDING, _cl.PIVOT_STUCK,
                                             _cl.ROLL_STUCK)
_NAMES = _cl.MODE_NAMES
_N_SAMPLE = 9  # points of the dense output at which events are looked for, per step
#: Slip speed below which sliding keeps the reference direction (the solved initial slip
#: direction, or the last resolved one): below it u/|u| is rounding noise.
U_EPS = 1e-8
#: Slip speed (relative to 1 + |V|) above which a zero of ``u . u_ref`` is a turn of the slip
#: direction, not the slip coming to rest.
STICK_TOL = 1e-6
#: ``|omega_h|`` below which the rolling resistance keeps its reference direction (as
#: :data:`U_EPS` for the slip).
W_EPS = 1e-8


def energy_balance(traj: Trajectory) -> float:
    """Largest relative violation of ``E + dissipated = const`` along a Coulomb run (eq. 12),
    relative to ``max(|E(0)|, 1)``."""
    if not isinstance(traj, Trajectory):
        raise ParameterTypeError(f"traj must be a rollingdisk.Trajectory, got "
                                 f"{type(traj).__name__} {traj!r}")
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
    """One hybrid run: the right-hand sides and event functions of the modes.

    A mode is ``ROLLING`` or ``SLIDING``, with the bit ``PIVOT_STUCK`` while the pivot
    sticks and ``ROLL_STUCK`` while the rolling resistance sticks.  Outside them the pivot
    moment is ``-c F_z sz`` with ``sz`` (``self.sz``) the sign of ``omega_z`` on the
    current segment, the rolling-resistance moment ``-c F_z sgn(omega_h . rref)
    omega_h/|omega_h|`` with ``rref`` (``self.rref``, inertial) the direction of ``omega_h``
    at the last step: the smooth continuations through ``omega_z = 0``, ``omega_h = 0``,
    where the driver stops (events), as the slip reference does for sliding."""

    def __init__(self, disk, ground, alpha_min=0.0):
        self.alpha_min = alpha_min
        self.side = 1.0  # sgn(theta) on the current segment (edge-contact event)
        self.h = disk.h
        self.g = ground
        self.coeffs = ground.coefficients
        self.c_roll, self.c_pivot = self.coeffs[0], self.coeffs[1]
        self.ref = (1.0, 0.0)  # inertial slip reference direction (sliding)
        # a slip started from u = 0 is resolved once |u| passes a floor (_start_sliding):
        # until then its end is not looked for and the friction keeps the direction ref
        self.armed = True
        self.u_eps = U_EPS  # |u| below which the friction direction is ref
        self.floor = 0.0
        self.sz = 1.0  # sgn(omega_z) on the segment (pivot not stuck)
        self.rref = (0.0, 0.0)  # inertial direction of omega_h (rolling resistance)
        self.n_rhs = 0
        self.u_qs = 0.0  # simulate_coulomb's quasi_static_slip

    def pivot_state(self, mode):
        """``sz`` of the kernels: 0 while the pivot sticks, else the segment's sign."""
        return 0.0 if mode & PIVOT_STUCK else self.sz

    def solve(self, mode, z, rref=None, w_eps=W_EPS):
        """The mode's kernel at ``z``: ``(dy, F_x, F_y, F_z, P_slip, P_roll, P_pivot,
        P_air, M_piv, M_hx, M_hy)`` (``rref``: another rolling-resistance reference)."""
        h, cf, sz = self.h, self.coeffs, self.pivot_state(mode)
        rx, ry = self.rref if rref is None else rref
        rs = bool(mode & ROLL_STUCK)
        if mode & 1 == ROLLING:
            dy, F_x, F_y, F_z, P1, P2, P3, L, Lx, Ly = _cl._coulomb_rolling_full(
                h, *cf, z, sz, rx, ry, w_eps, rs)
            return dy, F_x, F_y, F_z, 0.0, P1, P2, P3, L, Lx, Ly
        ref_X, ref_Y, u_eps = self.ref[0], self.ref[1], self.u_eps
        if self.u_qs > 0.0:
            p = np.array([mode, self.g.mu_k, self.g.mu_s, *cf, ref_X, ref_Y, u_eps, sz, 0.0,
                          0.0, 0.0, 0.0, 0.0, self.u_qs])
            ref_X, ref_Y, u_eps = _quasi_static_ref()(p, h, z, sz)
        return _cl._coulomb_sliding_full(h, self.g.mu_k, *cf, z, ref_X, ref_Y, u_eps, sz, rx,
                                         ry, w_eps, rs)

    def rhs(self, mode):
        def f(t, z):
            self.n_rhs += 1
            dy, F_x, F_y, F_z, P0, P1, P2, P3, *_ = self.solve(mode, z)
            return _finite(t, np.array([*dy, -P0, -P1, -P2, -P3]))
        return f

    def contact(self, mode, z):
        """``(F_t, F_z, u_ref_component, M_piv, M_hx, M_hy)`` at ``z`` in ``mode``."""
        _, F_x, F_y, F_z, *_, L, Lx, Ly = self.solve(mode, z)
        if mode & 1 == ROLLING:
            return math.hypot(F_x, F_y), F_z, 0.0, L, Lx, Ly
        U_X, U_Y = _inertial_slip(self.h, z)
        return math.hypot(F_x, F_y), F_z, U_X * self.ref[0] + U_Y * self.ref[1], L, Lx, Ly

    def events(self, mode, z):
        """Event functions, each crossing from > 0 to <= 0:
        ``[mode end, pivot, lift-off, edge contact, fell flat, roll]``; pivot: ``omega_z``
        reaches 0 (``sz omega_z``), or, while stuck, the moment holding it reaches
        ``c F_z``; roll: ``omega_h`` turns across ``rref`` (``omega_h . rref``, inertial),
        or, while stuck, the moment holding it reaches ``c F_z``."""
        F_t, F_z, along, L, Lx, Ly = self.contact(mode, z)
        end = self.g.mu_s * F_z - F_t if mode & 1 == ROLLING else along
        theta = z[5]
        if mode & PIVOT_STUCK:
            pivot = self.c_pivot * F_z - abs(L)
        else:
            pivot = self.sz * _cl._omega_z(theta, z[8], z[9])
        if mode & ROLL_STUCK:
            roll = self.c_roll * F_z - math.hypot(Lx, Ly)
        else:
            W_X, W_Y = _inertial_omega_h(z)
            roll = W_X * self.rref[0] + W_Y * self.rref[1]
        return [end, pivot, F_z, theta * self.side if self.h > 0 else 1.0,
                0.5 * math.pi - abs(theta) - self.alpha_min, roll]


@functools.cache
def _quasi_static_ref():
    """:func:`rollingdisk.ivp.fastsegment._quasi_static_ref`, uncompiled (the scipy and
    LSODA paths)."""
    return _fs.namespace()["_quasi_static_ref"]


def _DOP853():
    """scipy's DOP853 class, imported when a Coulomb run starts (``import rollingdisk``
    must not load ``scipy.integrate``, 0.3 s)."""
    from scipy.integrate import DOP853

    return DOP853


def _LSODA():
    """scipy's LSODA class (``method="lsoda"``), imported when such a run starts."""
    from scipy.integrate import LSODA

    return LSODA


def _inertial_slip(h, z):
    u_x, u_y = _cl._slip_velocity(h, z)
    return _cl._to_inertial(z[4], u_x, u_y)


def _inertial_omega_h(z):
    """Horizontal angular velocity ``omega_h`` in OXYZ (``(omega_x, omega_y)`` of Cxyz
    turned by ``psi``)."""
    theta, w1, w2, w3 = z[5], z[7], z[8], z[9]
    return _cl._to_inertial(z[4], w1, w2 * math.cos(theta) - w3 * math.sin(theta))


@dataclass(frozen=True, eq=False, repr=False)  # Trajectory's short repr, not every array
class CoulombTrajectory(Trajectory):
    """A :class:`~rollingdisk.Trajectory` on Coulomb ground (what :func:`simulate_coulomb`
    returns): the contact force at each stored point follows from that point's mode."""

    @cached_property
    def _F(self):
        rows = [coulomb_contact(self.disk, self.ground, MODE_NAMES[m], self.y[:, i])
                for i, m in enumerate(self.mode)]
        return tuple(np.array([r[k] for r in rows]) for k in ("F_x", "F_y", "F_z"))


#: Default budgets of :func:`simulate_coulomb`.  A step of this path (scipy's DOP853 with
#: events on each step's dense output, in Python) costs about 0.1-1 ms, so 200 000 steps
#: are 20 s to 3 min; the wall-clock budget bounds the slow end (issue 18, item 4).
DEFAULT_MAX_STEPS = 200_000
DEFAULT_MAX_WALL_TIME = 60.0
#: Stored points beyond which every other regular step is dropped (memory: about 250 bytes
#: a point); above the default step budget, so a run within it keeps every step.
DEFAULT_MAX_POINTS = 500_000
#: ``method="auto"``: scipy-path steps (about half a second), over all Coulomb runs of the
#: process, after which the compiled loop (:mod:`rollingdisk.ivp.fastsegment`) is loaded
#: (or compiled, announced on a terminal) and every later step is compiled; the run under
#: way switches at its next check (every 64 steps) with the step size it would have tried
#: next.  Steps, not seconds: the switch is at the same step on every machine.
PY_BUDGET = 2_000
#: ``method="auto"`` compiles on a cold cache only when the run has at least this many
#: seconds of its wall-clock budget left (so ``max_wall_time`` still bounds it).
COMPILE_ROOM = 30.0
#: Steps the compiled loop takes between returns to Python (wall budget, progress, signals).
CHUNK = 1024

#: Seconds of wall clock between two calls of ``progress`` at most (while the run steps).
REPORT_EVERY = 0.5
_py_steps = 0
METHODS = ("auto", "dop853", "scipy", "lsoda")


def simulate_coulomb(disk: Disk, ground: Coulomb, t_span: Sequence[float], y0, *,
                     rtol: float = 1e-11, atol: float = 1e-12, max_step: float = math.inf,
                     max_steps: int = DEFAULT_MAX_STEPS, max_transitions: int = 10_000,
                     max_wall_time: float = DEFAULT_MAX_WALL_TIME,
                     max_points: int = DEFAULT_MAX_POINTS,
                     slip_tol: float = 1e-12, alpha_min: float = 1e-8, guards: bool = True,
                     progress: Callable[[float], None] | None = None,
                     method: str = "auto", quasi_static_slip: float = 0.0) -> Trajectory:
    """Integrate the disk on Coulomb ground: rolling and sliding with located transitions.

    Parameters
    ----------
    disk : Disk
    ground : Coulomb
        Friction coefficients and dissipative moments (:mod:`rollingdisk.model.ground`).
    t_span : (t0, t1)
        ``t1 > t0``.
    y0 : array_like, shape (10,)
        ``[X_C, Y_C, V_X, V_Y, psi, theta, phi, omega1, omega2, omega3]``
        (:data:`~rollingdisk.model.coulomb.COULOMB_STATE`).  The run starts rolling if the slip
        ``|u|`` (eq. 6) is at most ``slip_tol (1 + |V|)`` and the friction rolling needs
        lies in the cone ``|F_t| <= mu_s F_z``; it starts sliding otherwise (a transition
        ``rolling -> sliding`` at ``t0`` when the slip was zero).  Use
        :func:`rollingdisk.model.coulomb.rolling_state` to start from a rough-ground state.
    rtol, atol : float
        Tolerances of DOP853.
    max_step : float
        Largest step.
    max_steps : int
        Step budget (default :data:`DEFAULT_MAX_STEPS`); once spent the run stops with
        status ``"step-budget"`` and a message saying what to change.
    max_transitions : int
        Budget of mode events (transitions, and slip reversals or turns that restart the
        integrator); beyond it the run stops with status ``"failed"`` and says why.
    max_wall_time : float
        Wall-clock budget in seconds, ``> 0`` (default :data:`DEFAULT_MAX_WALL_TIME`); once
        spent the run stops with status ``"time-budget"`` and a message.
    max_points : int
        Most points stored, ``>= 16`` (default :data:`DEFAULT_MAX_POINTS`): beyond it every
        other regular step is dropped (the first and last points and those of mode events are
        kept) and from then on only every 2nd, 4th, ... step is stored; the message says so.
    slip_tol : float
        Relative slip below which the initial state counts as rolling.
    alpha_min : float
        The disk counts as fallen flat when its tilt ``alpha = pi/2 - |theta|`` reaches
        ``alpha_min`` (``>= 0``): near ``alpha = 0`` the precession rate grows without
        bound (Euler's disk, a finite-time singularity) and the steps would collapse.
    guards : bool
        Stop at lift-off, edge contact and falling flat (default).
    progress : callable, optional
        ``progress(fraction)`` with the fraction of ``t_span`` done, called about every
        percent of it and at least every :data:`REPORT_EVERY` seconds.
    method : {"auto", "dop853", "scipy", "lsoda"}
        Words of :mod:`rollingdisk.engine.methods`.  ``"scipy"``: scipy's DOP853 driven
        from Python.  ``"lsoda"``: scipy's LSODA (BDF where the problem is stiff) driven
        from Python, events located the same way on its interpolant: for long micro-slip at
        the edge of the friction cone, where the slip's direction relaxes at a rate of
        order ``mu g/|u|`` and DOP853 needs about 1e5 steps per time unit (docs/friction.md
        has the measurements).  ``"dop853"``: the steps without events in the compiled loop
        of :mod:`rollingdisk.ivp.fastsegment` (numba, compiled once per machine).
        ``"auto"`` (default): scipy for :data:`PY_BUDGET` steps of the process, then
        compiled (at once if the loop is loaded) where numba is installed.  ``"scipy"`` and
        ``"dop853"`` take the same steps and locate events the same way: transitions agree
        to about 1e-10.
    quasi_static_slip : float
        Slip speed ``u_qs >= 0`` (units ``sqrt(a g)``) below which the sliding friction
        takes the quasi-static slip direction ``e*`` (``e* x du/dt(e*) = 0``, the direction
        the slip's own relaxes to at the rate ``mu g/|u|``), blended continuously into
        ``u/|u|`` at ``|u| = u_qs``; ``|F_t| = mu_k F_z`` as before.  0 (default): off,
        ``e = u/|u|``.  For long micro-slip at the edge of the friction cone, where that
        relaxation makes DOP853's steps proportional to ``|u|`` (docs/friction.md).

    Returns
    -------
    Trajectory
        With ``ground`` the :class:`Coulomb` value, ``mode`` per stored point,
        ``transitions`` and ``dissipated`` (see :class:`Trajectory`); ``method`` is
        ``"dop853"`` if the compiled loop took steps (scipy's may have taken the first
        ones), ``"lsoda"`` with ``"lsoda"``, else ``"scipy"``.

    Examples
    --------
    >>> tr = simulate_coulomb(Disk(0.0), Coulomb(0.2), (0, 2), [0, 0, 1, 0, 0, 0, 0, 0, 0, 0])
    >>> [(round(x.t, 9), x.from_mode, x.to_mode) for x in tr.transitions]
    [(1.666666667, 'sliding', 'rolling')]
    """
    y, (t0, t1), options = _check_arguments(
        disk, ground, t_span, y0, rtol=rtol, atol=atol, max_step=max_step,
        max_steps=max_steps, max_transitions=max_transitions, max_wall_time=max_wall_time,
        max_points=max_points, slip_tol=slip_tol, alpha_min=alpha_min,
        quasi_static_slip=quasi_static_slip)
    method = check_method(method, METHODS)
    if method == "dop853" and not _fs.available():
        raise ParameterError("method='dop853' needs numba (pip install numba)")
    hybrid = _Hybrid(disk, ground, t0, t1, y, options, guards, progress, method)
    try:
        with np.errstate(over="ignore", invalid="ignore"):  # non-finite is caught: _finite
            hybrid.integrate()
    except _Singular as exc:  # a solver's set-up met a right-hand side beyond float range
        if hybrid.t == t0:
            raise ParameterError(f"the equations of motion are not finite at the start "
                                 f"({exc}): a ground coefficient (air, mu, rolling_resistance,"
                                 f" pivot) or the state is beyond floating-point range") from None
        hybrid.status, hybrid.message = "failed", f"the equations became singular at {exc}"
    return hybrid.trajectory()


def _check_arguments(disk, ground, t_span, y0, **options):
    """The validated ``(y0, (t0, t1), options)`` of :func:`simulate_coulomb`."""
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {type(disk).__name__} "
                                 f"{disk!r}")
    check_coulomb(ground)
    y = _check_state(disk, "smooth", real_array("y0", y0))
    t0, t1 = check_span(t_span)
    o = dict(options)
    o["rtol"] = check_real("rtol", o["rtol"], low=0.0, low_open=True)
    o["atol"] = check_real("atol", o["atol"], low=0.0, low_open=True)
    if o["max_step"] != math.inf:
        o["max_step"] = check_real("max_step", o["max_step"], low=0.0, low_open=True)
    o["slip_tol"] = check_real("slip_tol", o["slip_tol"], low=0.0)
    o["quasi_static_slip"] = check_real("quasi_static_slip", o["quasi_static_slip"], low=0.0)
    o["alpha_min"] = check_real("alpha_min", o["alpha_min"], low=0.0, high=0.5 * math.pi,
                                high_open=True)
    o["max_wall_time"] = check_real("max_wall_time", o["max_wall_time"], low=0.0,
                                    low_open=True)
    for name, low in (("max_steps", 1), ("max_transitions", 1), ("max_points", 16)):
        v = o[name]
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < low:
            raise ParameterError(f"{name} must be an integer >= {low}, got {v!r}")
    return y, (t0, t1), o


class _Points:
    """The stored points of a run, at most about ``max_points`` of them: beyond, every other
    regular step is dropped (pinned points, those of mode events, are always kept) and the
    stride between stored regular steps doubles."""

    def __init__(self, max_points):
        self.max_points = max_points
        self.t, self.z, self.mode, self.pinned = [], [], [], []
        self.stride = 1
        self._since = 0  # regular steps since the last stored one
        self._pending = None  # the latest regular step not stored (kept for the end)

    def add(self, t, z, mode, pinned=False):
        if not pinned:
            self._since += 1
            if self._since < self.stride:
                self._pending = (t, z.copy(), mode)
                return
            self._since = 0
        self._pending = None
        self.t.append(t)
        self.z.append(z.copy())
        self.mode.append(mode)
        self.pinned.append(pinned)
        if len(self.t) > self.max_points:
            self._thin()

    def _thin(self):
        n = len(self.t)
        keep = [i for i in range(n) if self.pinned[i] or i % 2 == 0 or i == n - 1]
        for name in ("t", "z", "mode", "pinned"):
            old = getattr(self, name)
            setattr(self, name, [old[i] for i in keep])
        self.stride *= 2

    def finish(self):
        """Store the last step if it was skipped (a run ends on its last state)."""
        if self._pending is not None:
            t, z, mode = self._pending
            self._pending = None
            self.t.append(t)
            self.z.append(z)
            self.mode.append(mode)
            self.pinned.append(True)


class _Hybrid:
    """The state of one :func:`simulate_coulomb` run between its mode segments: the current
    time, state and mode, the stored points, the transitions, the budgets spent, and how it
    ended (``status``, ``message``)."""

    def __init__(self, disk, ground, t0, t1, y, options, guards, progress, method="scipy"):
        self.disk, self.ground, self.h = disk, ground, disk.h
        self.method = method
        self.compiled = method == "dop853" or (method == "auto" and _fs.loaded())
        self.used_compiled = False
        self.t0, self.t1 = t0, t1
        self.o = options
        self.guards, self.progress = guards, progress
        self.run = _Run(disk, ground, options["alpha_min"])
        self.run.u_qs = options["quasi_static_slip"]
        self.transitions: list[Transition] = []
        self.points = _Points(options["max_points"])
        self.status, self.message, self.t_event = "completed", "", None
        self.n_steps = 0
        self.n_mode_events = 0
        self.last_turn = None
        self.next_report = 0.01
        self.wall0 = self.last_report = time.perf_counter()
        self.t = t0
        self.z = np.concatenate([y, np.zeros(4)])
        self.run.sz = -1.0 if _cl._omega_z(y[5], y[8], y[9]) < 0.0 else 1.0
        W = _inertial_omega_h(self.z)
        n = math.hypot(*W)
        if n > 0.0:
            self.run.rref = (W[0] / n, W[1] / n)
        self.mode = self._initial_roll(self._initial_pivot(self._initial_mode()))
        self.points.add(t0, self.z, self.mode, pinned=True)

    def _initial_mode(self):
        """Rolling if the slip is negligible and the friction rolling needs lies in the cone
        (a ``rolling -> sliding`` transition at ``t0`` if not), else sliding."""
        run, z, h = self.run, self.z, self.h
        U = _inertial_slip(h, z)
        speed = math.hypot(z[2], z[3])
        if math.hypot(*U) <= self.o["slip_tol"] * (1.0 + speed):
            z[2], z[3] = _cl._rolling_velocity(h, z)
            F_t, F_z, *_ = run.contact(ROLLING, z)
            if F_t > self.ground.mu_s * F_z:
                self.transitions.append(Transition(self.t0, "rolling", "sliding"))
                return _start_sliding(run, self.disk, self.ground, z)
            return ROLLING
        n = math.hypot(*U)
        run.ref = (U[0] / n, U[1] / n)
        return SLIDING

    def _initial_pivot(self, mode):
        """The pivot state at ``t0``: stuck if ``omega_z`` is negligible (``slip_tol``
        relative to ``1 + |omega|``) and the moment holding it lies within ``c F_z``; else
        ``sz = sgn(omega_z)``, or the way it will turn."""
        run, z = self.run, self.z
        if run.c_pivot == 0.0:
            return mode
        wz = _cl._omega_z(z[5], z[8], z[9])
        if abs(wz) > self.o["slip_tol"] * (1.0 + float(np.linalg.norm(z[7:10]))):
            run.sz = 1.0 if wz > 0.0 else -1.0
            return mode
        return self._pivot_settles(mode)

    def _pivot_settles(self, base):
        """At ``omega_z = 0`` in the base mode ``base``: the stuck sub-mode if the moment
        that holds ``omega_z = 0`` lies within ``c F_z``; else ``base`` with ``sz`` the way
        ``omega_z`` turns (the pivot moment at its bound opposes it)."""
        run = self.run
        base &= ~PIVOT_STUCK
        _, F_z, _, L, _, _ = run.contact(base | PIVOT_STUCK, self.z)
        if abs(L) <= run.c_pivot * F_z:
            return base | PIVOT_STUCK
        run.sz = -1.0 if L > 0.0 else 1.0
        return base

    def _initial_roll(self, mode):
        """The rolling-resistance state at ``t0``: stuck if ``omega_h`` is negligible
        (``slip_tol`` relative to ``1 + |omega|``) and the moment holding it lies within
        ``c F_z``; else ``rref`` the direction of ``omega_h``, or the way it will turn."""
        run, z = self.run, self.z
        if run.c_roll == 0.0:
            return mode
        if math.hypot(*_inertial_omega_h(z)) > self.o["slip_tol"] * (
                1.0 + float(np.linalg.norm(z[7:10]))):
            return mode
        return self._roll_settles(mode)

    def _roll_settles(self, mode):
        """At ``omega_h = 0`` in ``mode`` (its ``ROLL_STUCK`` bit ignored): the roll-stuck
        sub-mode if the moment that holds ``omega_h = 0`` lies within ``c F_z``; else the
        mode free, ``rref`` the way ``omega_h`` turns (:func:`_roll_turn`)."""
        run = self.run
        base = mode & ~ROLL_STUCK
        _, F_z, _, _, Lx, Ly = run.contact(base | ROLL_STUCK, self.z)
        n = math.hypot(Lx, Ly)
        if n <= run.c_roll * F_z:
            return base | ROLL_STUCK
        d = _roll_turn(run, base, self.z)
        if d is not None:
            run.rref = d
        elif n > 0.0:  # no consistent direction: along -M_h
            run.rref = _cl._to_inertial(self.z[4], -Lx / n, -Ly / n)
        return base

    def integrate(self):
        """Run mode segment after mode segment until the end, a guard or a budget."""
        while self._segment():
            pass
        self.points.finish()
        if self.status == "completed":
            self.message = f"reached t = {self.t:.12g}"
        if self.points.stride > 1:
            self.message += (f"; {len(self.points.t)} points stored: every "
                             f"{self.points.stride}th step kept past max_points = "
                             f"{self.o['max_points']} (and every mode event)")
        if self.progress is not None:
            self.progress(1.0)

    def _segment(self):
        """Integrate in the current mode until an event; True if the run goes on in a new
        segment (a mode change or a new slip reference), False if it ended."""
        run, o = self.run, self.o
        run.side = 1.0 if self.z[5] >= 0 else -1.0
        if self.compiled:
            return self._segment_compiled(0.0)
        stiff = self.method == "lsoda"
        solver = (_LSODA() if stiff else _DOP853())(
            run.rhs(self.mode), self.t, self.z, self.t1, rtol=o["rtol"], atol=o["atol"],
            max_step=o["max_step"])
        g_old = run.events(self.mode, self.z)
        n_here = 0
        try:
            while solver.status == "running":
                if self._out_of_budget(solver.t) or not self._step(solver):
                    return False
                sol = self._dense(solver)
                if sol is None:
                    return False
                if stiff:  # LSODA's interpolant does not pass through the step's start
                    hit = _start_event(run, self.mode, sol, solver.t_old, g_old, self.h > 0
                                       and self.guards, self.guards)
                    if hit is None:
                        g_old = run.events(self.mode, np.asarray(sol(solver.t_old)))
                else:
                    hit = None
                if hit is None:
                    hit = _first_event(run, self.mode, sol, solver.t_old, solver.t, g_old,
                                       self.h > 0 and self.guards, self.guards)
                if hit is not None:
                    return self._on_event(sol, *hit)
                g_old = self._accept(solver)
                n_here += 1
                if self.method == "auto" and n_here % 64 == 0:
                    _spend(64)
                    if self._switch():
                        return self._segment_compiled(solver.h_abs)
            return False
        finally:
            _spend(n_here % 64)

    def _switch(self):
        """``method="auto"``: whether to go on compiled now (the process has taken
        :data:`PY_BUDGET` steps on the scipy path, numba is there, and a cold cache leaves
        :data:`COMPILE_ROOM` s of the wall budget); loads the compiled loop."""
        global _compile_failed
        if self.compiled:
            return True
        if _compile_failed or _py_steps < PY_BUDGET or not _fs.available():
            return False
        if not _fs.loaded() and not _fs.cache_ready():
            left = self.o["max_wall_time"] - (time.perf_counter() - self.wall0)
            if left < COMPILE_ROOM:
                return False
        if not _fs.loaded() and not _fs.cache_ready():
            from rollingdisk.engine.compile import announce

            announce("compiling rollingdisk's Coulomb loop (once per machine; usually 10-60 s)")
        try:
            _fs.compiled()
        except Exception:  # noqa: BLE001 - numba broken: stay on the scipy path
            _compile_failed = True
            return False
        self.compiled = True
        return True

    def _segment_compiled(self, dt_try):
        """:meth:`_segment` with the steps taken by the compiled loop
        (:func:`rollingdisk.ivp.fastsegment.advance`), ``CHUNK`` steps a call; only a
        step in which an event function changes sign comes back here, to be located by
        :func:`_first_event` and handled by :meth:`_on_event`.  ``dt_try``: the step size
        to try first (``0``: scipy's initial step, a new segment)."""
        ns = _fs.compiled()
        self.used_compiled = True
        run, o, mode, g = self.run, self.o, self.mode, self.ground
        c_roll, c_pivot, c_air = run.coeffs
        p = np.array([mode, g.mu_k, g.mu_s, c_roll, c_pivot, c_air, run.ref[0], run.ref[1],
                      run.u_eps, run.sz, run.side, run.alpha_min, run.rref[0], run.rref[1],
                      W_EPS, o.get("quasi_static_slip", 0.0)], dtype=float)
        atolv = np.full(self.z.shape[0], float(o["atol"]))
        edge = self.h > 0 and self.guards
        active = np.array(_active(run, mode, edge, self.guards), dtype=np.bool_)
        ts = np.empty(CHUNK)
        zs = np.empty((CHUNK, self.z.shape[0]))
        advance = ns["advance"]
        while True:
            if self._out_of_budget(self.t):
                return False
            with np.errstate(all="ignore"):
                (status, m, n, n_rhs, t, y, dt_next, t_new, dt, y_new, F) = advance(
                    p, self.h, self.t, self.z, self.t1, dt_try, o["rtol"], atolv,
                    float(o["max_step"]),
                    min(o["max_steps"] - self.n_steps, CHUNK if active[0] else 1), active, ts,
                    zs)
            self.n_steps += n
            run.n_rhs += n_rhs
            add = self.points.add
            for i in range(m):
                add(float(ts[i]), zs[i], mode)
            run.ref = (float(p[6]), float(p[7]))
            run.rref = (float(p[12]), float(p[13]))
            self.t, self.z = float(t), y.copy()
            if not active[0] and m and self._arms(self.z):  # one step a call while not armed
                active[0] = True
                p[8] = run.u_eps
                p[6], p[7] = run.ref
            self._report()
            if status == _fs.COMPLETED:
                return False
            if status == _fs.FAILED:
                self.status = "failed"
                self.message = (f"the integrator gave up at t = {self.t:.12g} (Required step "
                                "size is less than spacing between numbers.): step sizes "
                                "collapsed")
                return False
            if status == _fs.SINGULAR:
                self.status = "failed"
                self.message = (f"the equations became singular at t = {self.t:.12g} (a "
                                f"non-finite right-hand side, theta = {self.z[5]:.6g} at "
                                "the step start)")
                return False
            if status == _fs.EVENT:
                sol = _DenseStep(ns["_dense_value"], self.t, float(t_new), self.z, F.copy())
                g_old = run.events(mode, self.z)
                hit = _first_event(run, mode, sol, self.t, float(t_new), g_old, edge,
                                   self.guards)
                if hit is not None:
                    return self._on_event(sol, *hit)
                # the compiled events saw a sign change the Python ones do not (round-off
                # at a zero): the step is a regular one
                self._accept_point(float(t_new), np.array(y_new))
                p[6], p[7] = run.ref
                p[12], p[13] = run.rref
            dt_try = dt_next

    def _out_of_budget(self, t):
        """Stop (status and message set) if the step or wall-clock budget is spent."""
        max_steps, max_wall = self.o["max_steps"], self.o["max_wall_time"]
        if self.n_steps >= max_steps:
            self.status = "step-budget"
            self.message = (f"step budget exhausted: {max_steps} steps by t = {t:.12g}; "
                            "raise max_steps or shorten t_span")
            return True
        spent = time.perf_counter() - self.wall0
        if spent > max_wall:
            self.status = "time-budget"
            self.message = (f"wall-clock budget exhausted: max_wall_time = {max_wall:g} s "
                            f"spent by t = {t:.12g} after {self.n_steps} steps "
                            f"({1e3 * spent / max(self.n_steps, 1):.3g} ms a step); raise "
                            "max_wall_time, shorten t_span or loosen rtol")
            return True
        return False

    def _step(self, solver):
        """One DOP853 step; False (status and message set) if it failed."""
        try:
            with np.errstate(all="ignore"):
                msg = solver.step()
        except _Singular as exc:
            self.status = "failed"
            self.message = (f"the equations became singular at {exc} (a non-finite right-hand "
                            f"side, theta = {solver.y[5]:.6g} at the step start)")
            return False
        self.n_steps += 1
        if solver.status == "failed":
            self.status = "failed"
            self.message = (f"the integrator gave up at t = {solver.t:.12g} ({msg}): step "
                            "sizes collapsed")
            return False
        if not np.all(np.isfinite(solver.y)):
            self.status = "failed"
            self.message = (f"the state left floating-point range at t = {solver.t:.12g} "
                            "(the motion became singular)")
            return False
        return True

    def _dense(self, solver):
        """The step's interpolant (it evaluates the right-hand side too); None (status and
        message set) if the equations became singular there."""
        try:
            with np.errstate(all="ignore"):
                return solver.dense_output()
        except _Singular as exc:
            self.status = "failed"
            self.message = (f"the equations became singular at {exc} (a non-finite right-hand "
                            f"side, theta = {solver.y[5]:.6g} at the step end)")
            return None

    def _accept(self, solver):
        """Store a step without events; the event values at its end."""
        return self._accept_point(solver.t, solver.y.copy())

    def _accept_point(self, t, z):
        """Store the regular step ending at ``(t, z)``; in sliding the slip reference
        becomes ``U/|U|`` there, with rolling resistance free ``rref`` becomes
        ``omega_h/|omega_h|``; the event values at ``z``."""
        run, mode = self.run, self.mode
        self.t, self.z = t, z
        self.points.add(self.t, self.z, mode)
        g_old = run.events(mode, self.z)
        renew = False
        if mode & 1 == SLIDING and (run.armed or self._arms(self.z)):
            U = _inertial_slip(self.h, self.z)
            n = math.hypot(*U)
            if n > U_EPS:
                run.ref = (U[0] / n, U[1] / n)
                renew = True
        if run.c_roll > 0.0 and not mode & ROLL_STUCK:
            W = _inertial_omega_h(self.z)
            n = math.hypot(*W)
            if n > W_EPS:
                run.rref = (W[0] / n, W[1] / n)
                renew = True
        if renew:
            g_old = run.events(mode, self.z)
        self._report()
        return g_old

    def _arms(self, z):
        """Whether a slip started from ``u = 0`` has now passed its floor ``STICK_TOL (1 +
        |V|)`` (then its end is looked for again and the friction follows ``u/|u|``).

        Below the floor ``u``, a difference of velocities of order 1, is not resolved by
        the integration (its interpolant's error is larger than it: at rtol 1e-8 a slip of
        1e-8 changes sign several times on one step's dense output), so a zero of ``u .
        ref`` there is not an event: it stalled tosses in thousands of slip-restarts at one
        instant.  The friction keeps the consistent direction of the rolling -> sliding
        scan, ``ref``, meanwhile; the floor is the one at which an event counts the slip
        as at rest (:meth:`_slip_turned`)."""
        run = self.run
        U = _inertial_slip(self.h, z)
        if math.hypot(*U) <= run.floor:
            return False
        run.armed, run.u_eps = True, U_EPS
        return True

    def _report(self):
        """Call ``progress`` about every percent of the span, and at least every
        :data:`REPORT_EVERY` seconds of wall clock (a long run with a far end time)."""
        if self.progress is None:
            return
        done = (self.t - self.t0) / (self.t1 - self.t0)
        now = time.perf_counter()
        if done >= self.next_report or now - self.last_report >= REPORT_EVERY:
            self.progress(min(1.0, done))
            self.next_report = done + 0.01
            self.last_report = now

    def _on_event(self, sol, k, te):
        """Handle event ``k`` at ``te``: a terminal guard ends the run; the end of a mode
        switches mode or slip reference.  True if the run goes on."""
        self.t, self.z = te, np.asarray(sol(te), dtype=float).copy()
        self.points.add(self.t, self.z, self.mode, pinned=True)
        t = self.t
        if k in (2, 3, 4):  # terminal guard
            self.status = ("lift-off", "edge-contact", "fell-flat")[k - 2]
            self.t_event = t
            self.message = _message(self.status, t, self.h)
            return False
        self.n_mode_events += 1
        if self.n_mode_events > self.o["max_transitions"]:
            self.status = "failed"
            self.message = (f"transition budget exhausted: {self.o['max_transitions']} mode "
                            f"events by t = {t:.12g} (sticking and slipping chatter?)")
            return False
        if k == 1:
            self._pivot_event()
            return True
        if k == 5:
            return self._roll_event()
        if self.mode & 1 == SLIDING:
            turned = self._slip_turned()
            if turned is not None:
                return turned
        self._switch_mode()
        return True

    def _pivot_event(self):
        """``omega_z`` reached 0 (the pivot sticks if it can, else the spin reverses), or the
        moment holding the stuck pivot reached ``c F_z`` (the pivot slips, ``sz`` the way
        ``omega_z`` turns)."""
        if self.mode & PIVOT_STUCK:
            L = self.run.contact(self.mode, self.z)[3]
            self.run.sz = -1.0 if L > 0.0 else 1.0
            new = self.mode & ~PIVOT_STUCK
        else:
            new = self._pivot_settles(self.mode)
        if new != self.mode:
            self.transitions.append(Transition(self.t, _NAMES[self.mode], _NAMES[new]))
        self.mode = new

    def _roll_event(self):
        """``omega_h`` turned across ``rref``: at rest (``|omega_h|`` within
        :data:`STICK_TOL` of 0) the rolling resistance sticks if it can, else its moment
        flips; not at rest, ``rref`` is renewed.  Or the moment holding the stuck
        ``omega_h`` reached ``c F_z``: it unsticks, ``omega_h`` turning along ``-M_h``
        (the moment at its bound stays ``M_h``).  True if the run goes on."""
        run, z, t = self.run, self.z, self.t
        if self.mode & ROLL_STUCK:
            *_, Lx, Ly = run.contact(self.mode, z)
            n = math.hypot(Lx, Ly)
            if n > 0.0:
                run.rref = _cl._to_inertial(z[4], -Lx / n, -Ly / n)
            new = self.mode & ~ROLL_STUCK
        else:
            W = _inertial_omega_h(z)
            n = math.hypot(*W)
            if n > STICK_TOL * (1.0 + float(np.linalg.norm(z[7:10]))):
                if self._turned_twice("omega_h"):
                    return False
                run.rref = (W[0] / n, W[1] / n)  # turned without vanishing: no transition
                return True
            new = self._roll_settles(self.mode)
        if new != self.mode:
            self.transitions.append(Transition(t, _NAMES[self.mode], _NAMES[new]))
        self.mode = new
        return True

    def _turned_twice(self, what: str) -> bool:
        """A reference direction turns at ``self.t``: True (status "failed", message set) if
        one turned at the same time already (a discontinuity of the equations, which
        would turn it for ever), else remember the time."""
        t = self.t
        if self.last_turn is not None and t - self.last_turn <= 1e-12 * (1.0 + abs(t)):
            self.status = "failed"
            self.message = (f"stuck at t = {t:.12g}: {what} turned twice at the same time "
                            "(a discontinuity of the equations)")
            return True
        self.last_turn = t
        return False

    def _slip_turned(self):
        """At a zero of ``u . u_ref`` with the slip not at rest: a new slip reference
        (True), or stuck (False, status set); None if the slip came to rest."""
        z = self.z
        U = _inertial_slip(self.h, z)
        n = math.hypot(*U)
        if n <= STICK_TOL * (1.0 + math.hypot(z[2], z[3])):
            return None
        if self._turned_twice("the slip direction"):
            return False
        # u turned across the reference direction without vanishing: a new reference, no
        # transition
        self.run.ref = (U[0] / n, U[1] / n)
        return True

    def _switch_mode(self):
        """The mode after the end of the current one (recorded as a transition if it
        differs): rolling starts to slide; sliding rolls if the cone allows, else slides on.
        A stuck pivot stays stuck if the new contact mode can hold it."""
        run, z, disk, ground = self.run, self.z, self.disk, self.ground
        stuck = self.mode & (PIVOT_STUCK | ROLL_STUCK)
        if self.mode & 1 == ROLLING:
            new = _start_sliding(run, disk, ground, z, stuck)
        else:
            z[2], z[3] = _cl._rolling_velocity(self.h, z)  # u = 0 up to the event tolerance
            F_t, F_z, *_ = run.contact(ROLLING | stuck, z)
            new = (ROLLING if F_t <= ground.mu_s * F_z
                   else _start_sliding(run, disk, ground, z, stuck))
        new |= stuck
        if stuck & PIVOT_STUCK:
            new = self._pivot_settles(new)
        if stuck & ROLL_STUCK:
            new = self._roll_settles(new)
        if new != self.mode:
            self.transitions.append(Transition(self.t, _NAMES[self.mode], _NAMES[new]))
        self.mode = new

    def trajectory(self):
        """The run as a :class:`CoulombTrajectory`."""
        wall = time.perf_counter() - self.wall0
        Z = np.array(self.points.z).T
        return CoulombTrajectory(
            disk=self.disk, ground=self.ground, t=np.array(self.points.t), y=Z[:10],
            status=self.status, message=self.message, n_steps=self.n_steps,
            n_rhs=self.run.n_rhs,
            method=("dop853" if self.used_compiled else "lsoda"
                    if self.method == "lsoda" else "scipy"),
            t_event=self.t_event,
            wall_time=wall, mode=np.array(self.points.mode),
            transitions=tuple(self.transitions),
            dissipated={k: Z[10 + i].copy() for i, k in enumerate(DISSIPATION_TERMS)})


_compile_failed = False


def _spend(steps):
    """Count ``steps`` scipy-path steps against :data:`PY_BUDGET`."""
    global _py_steps
    _py_steps += max(0, int(steps))


class _DenseStep:
    """The DOP853 interpolant of one step of the compiled loop, ``sol(t)`` as scipy's
    dense output (:func:`rollingdisk.engine.dop853._dense_value`)."""

    def __init__(self, value, t_old, t, y_old, F):
        self.value, self.t_old, self.dt, self.y_old, self.F = value, t_old, t - t_old, y_old, F

    def __call__(self, t):
        out = np.empty(self.y_old.shape[0])
        self.value(self.y_old, self.F, (t - self.t_old) / self.dt, out)
        return out


def _start_sliding(run, disk, ground, z, stuck=0):
    """Switch to sliding at a state with ``u = 0``: the slip direction is solved (with the
    pivot as it is: stuck if ``stuck`` has ``PIVOT_STUCK``, else the segment's ``sz``; with
    the rolling resistance stuck its moment, set-valued there, is left out of this solve).
    Returns ``SLIDING`` (the caller keeps the stuck bits)."""
    sz = run.pivot_state(stuck)
    coeffs = ground.coefficients
    if stuck & ROLL_STUCK:
        coeffs = (0.0, coeffs[1], coeffs[2])
    d = _slip_direction(disk.h, ground.mu_k, coeffs, z[:10], sz)
    if d is None:  # no consistent slip direction: oppose the rolling friction force
        _, F_x, F_y, *_ = run.solve(ROLLING | stuck, z)
        n = math.hypot(F_x, F_y) or 1.0
        d = (-F_x / n, -F_y / n)
    run.ref = _cl._to_inertial(z[4], d[0], d[1])
    run.armed = False  # the slip's end is looked for once |u| passes the floor (_arms)
    run.floor = run.u_eps = STICK_TOL * (1.0 + math.hypot(z[2], z[3]))
    return SLIDING


def _roll_turn(run, mode, z):
    """The inertial direction ``d`` along which ``omega_h`` starts to grow from 0 in
    ``mode`` (not roll stuck) when the rolling resistance cannot hold it: with the moment
    ``-c F_z d``, ``d omega_h/dt`` is along ``+d`` (the Cxyz rates of (9), ``d omega_y/dt =
    domega2 cos - domega3 sin - omega1 omega_z``).  Found as :func:`slip_direction`
    finds the slip direction: a scan of the angle, ``brentq`` on ``d x d omega_h/dt = 0``,
    among the roots with ``d . d omega_h/dt > 0`` the one of largest rate; ``None`` if
    there is none."""
    psi, theta, w1, w2, w3 = z[4], z[5], z[7], z[8], z[9]
    s, c = math.sin(theta), math.cos(theta)
    wz = w2 * s + w3 * c

    def parts(a):
        ex, ey = math.cos(a), math.sin(a)  # Cxyz
        dy = run.solve(mode, z, _cl._to_inertial(psi, ex, ey), math.inf)[0]
        ax, ay = dy[7], dy[8] * c - dy[9] * s - w1 * wz
        return ex * ay - ey * ax, ex * ax + ey * ay

    a = _direction_scan(parts)
    return None if a is None else _cl._to_inertial(psi, math.cos(a), math.sin(a))


def _active(run, mode, edge, guards):
    """Which of :meth:`_Run.events` are looked for: the mode's end (in sliding once the
    slip passed its floor), the pivot's and the rolling resistance's if on, the guards."""
    return [run.armed or mode & 1 == ROLLING, run.c_pivot > 0.0, guards, edge, guards,
            run.c_roll > 0.0]


def _start_event(run, mode, sol, ta, g_old, edge, guards):
    """An event at the very start ``ta`` of a step whose interpolant does not pass through
    the accepted state (LSODA's): one that is ``> 0`` at the accepted state and ``<= 0`` on
    the interpolant at ``ta``, as ``(index, ta)``; else None."""
    active = _active(run, mode, edge, guards)
    g0 = run.events(mode, np.asarray(sol(ta)))
    for k in range(len(g0)):
        if active[k] and g_old[k] > 0.0 and g0[k] <= 0.0:
            return k, ta
    return None


def _first_event(run, mode, sol, ta, tb, g_old, edge, guards):
    """The first event in ``(ta, tb]`` on the dense output ``sol``: ``(index, time)``."""
    from scipy.optimize import brentq

    active = _active(run, mode, edge, guards)
    ts = np.linspace(ta, tb, _N_SAMPLE)
    prev = g_old
    best = None
    for i in range(1, ts.size):
        gi = run.events(mode, np.asarray(sol(ts[i])))
        for k in range(6):
            if active[k] and prev[k] > 0.0 and gi[k] <= 0.0:
                def fk(s, k=k):
                    return run.events(mode, np.asarray(sol(s)))[k]
                te = ts[i] if gi[k] == 0.0 else brentq(fk, ts[i - 1], ts[i], xtol=1e-15,
                                                        rtol=8.9e-16, maxiter=200)
                if best is None or te < best[1]:
                    best = (k, te)
        if best is not None:
            k, te = best
            if k != 3 and active[3] and prev[3] > 0.0 and gi[3] <= 0.0:
                # theta crossing 0 flips h~ and makes u and F jump: an event of the mode
                # found at that jump is the edge contact itself
                te2 = ts[i] if gi[3] == 0.0 else brentq(
                    lambda s: run.events(mode, np.asarray(sol(s)))[3], ts[i - 1], ts[i],
                    xtol=1e-15, rtol=8.9e-16, maxiter=200)
                if te2 - te <= 1e-9 * (1.0 + abs(te2)):
                    return 3, te2
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
