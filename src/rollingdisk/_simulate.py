"""Nonlinear simulation with physical guard events, and measurements on trajectories.

The equations of motion of :mod:`rollingdisk.equations` (eqs. 1, 2, 37, 38 on rough ground;
2, 8, 49 on smooth ground) are integrated from any initial state.  The model holds only while
the disk touches the plane at one point of its rim edge, so the integration stops, never
integrates through, at the first of these *guard events*:

``"lift-off"``
    the normal force ``F_z`` of eq. (11) reaches 0: the disk leaves the plane;
``"edge-contact"``
    ``theta`` reaches 0 while ``h > 0``: the disk lands on its other rim edge, an impact
    outside the model (for ``h = 0`` the disk passes through ``theta = 0`` smoothly and this
    guard is off);
``"fell-flat"``
    ``|theta|`` reaches ``pi/2``: the disk lies on the plane.

Two integrators: ``method="dop853"`` (default) is a compiled (numba) Dormand-Prince 8(5,3)
with the step-size control of scipy's ``DOP853``, guard events detected at each step and
located by root finding; ``method="scipy"`` runs ``scipy.integrate.solve_ivp`` with the same
method on the plain numpy right-hand side, with the guards as terminal events.  User events
(``events=``, as in ``solve_ivp``) run through the scipy path.

Measurements: :func:`energy_drift`, :func:`oscillation_frequency`, :func:`growth_rate`,
:func:`fit_circle`.
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .disk import Disk, check_ground, check_real
from .equations import (
    contact_force,
    contact_point,
    energy,
    equations_of_motion,
    omega_dot,
    state_index,
    state_names,
)
from .errors import ParameterError

__all__ = [
    "STATUSES",
    "DEFAULT_RTOL",
    "DEFAULT_ATOL",
    "Trajectory",
    "Transition",
    "simulate",
    "simulate_steady",
    "energy_drift",
    "oscillation_frequency",
    "growth_rate",
    "fit_circle",
    "jit_compile",
]

#: Possible values of :attr:`Trajectory.status`.
STATUSES = ("completed", "lift-off", "edge-contact", "fell-flat", "failed")
#: Default relative tolerance: keeps the relative energy drift below 1e-9 over 1000 time
#: units of a perturbed steady motion (checked by the tests).
DEFAULT_RTOL = 1e-11
#: Default absolute tolerance.
DEFAULT_ATOL = 1e-12

_STATUS_OF_CODE = {1: "completed", 2: "lift-off", 3: "edge-contact", 4: "fell-flat",
                   5: "failed"}
_METHODS = ("auto", "dop853", "scipy")


# ---------------------------------------------------------------------------- result
@dataclass(frozen=True)
class Transition:
    """A change of mode on Coulomb ground at time ``t``: ``from_mode -> to_mode``
    (``"rolling"`` / ``"sliding"``)."""

    t: float
    from_mode: str
    to_mode: str

    def as_dict(self) -> dict:
        """``{"t": t, "from": from_mode, "to": to_mode}``."""
        return {"t": self.t, "from": self.from_mode, "to": self.to_mode}


def _layout(ground) -> str:
    """The state layout of ``ground``: Coulomb ground uses the smooth one."""
    return ground if isinstance(ground, str) else "smooth"


@dataclass(frozen=True, eq=False)
class Trajectory:
    """A simulated motion of the disk (dimensionless units, m = a = g = 1).

    Attributes
    ----------
    disk : Disk
        The disk simulated.
    ground : {"rough", "smooth"}
        The ground.
    t : ndarray, shape (n,)
        Times (time unit ``sqrt(a/g)``).  The last one is the event time if a guard fired.
    y : ndarray, shape (n_state, n)
        States, laid out as in :data:`rollingdisk.equations.ROUGH_STATE` /
        :data:`~rollingdisk.equations.SMOOTH_STATE`.
    status : str
        ``"completed"`` (reached the end of ``t_span``, or stopped by a terminal user
        event), ``"lift-off"`` (``F_z`` reached 0, eq. 11), ``"edge-contact"`` (``theta``
        reached 0 with ``h > 0``), ``"fell-flat"`` (``|theta|`` reached ``pi/2``) or
        ``"failed"`` (the integrator gave up; see ``message``).
    message : str
        What happened, in words.
    n_steps, n_rhs : int
        Accepted integration steps and right-hand-side evaluations.
    method : str
        ``"dop853"`` (compiled) or ``"scipy"``.
    t_event : float or None
        Time of the guard event, if one fired.
    wall_time : float
        Seconds spent integrating (not counting compilation or post-processing).
    theta_ref : float or None
        The steady inclination ``theta0`` when started from a steady motion.
    motion : object or None
        The :class:`~rollingdisk.steady.SteadyMotion` it was started from, if any.
    t_events, y_events : tuple
        For user events: per event, the times and states where it occurred.
    mode : ndarray of int8 or None
        Coulomb ground only: the mode at each stored point, codes
        :data:`rollingdisk.equations.MODE_NAMES` (0 rolling, 1 sliding); ``None`` for
        single-mode runs (rough, smooth).
    transitions : tuple of Transition
        Coulomb ground only: the mode changes ``(t, from_mode, to_mode)``, in time order.
    dissipated : dict or None
        Coulomb ground only: energy dissipated so far by each term at each stored point,
        ``{"slip", "rolling_resistance", "pivot", "air"}`` -> arrays (units ``m g a``);
        ``E + sum(dissipated) = const`` (eq. 12).
    """

    disk: Disk
    ground: str
    t: np.ndarray
    y: np.ndarray
    status: str
    message: str
    n_steps: int
    n_rhs: int
    method: str = "dop853"
    t_event: float | None = None
    wall_time: float = math.nan
    theta_ref: float | None = None
    motion: object = None
    t_events: tuple = field(default=())
    y_events: tuple = field(default=())
    mode: np.ndarray | None = None
    transitions: tuple = field(default=())
    dissipated: dict | None = None

    def __post_init__(self):
        for name in ("t", "y"):
            a = np.array(getattr(self, name), dtype=float)
            a.setflags(write=False)
            object.__setattr__(self, name, a)
        if self.mode is not None:
            a = np.array(self.mode, dtype=np.int8)
            a.setflags(write=False)
            object.__setattr__(self, "mode", a)

    def __repr__(self) -> str:
        return (f"Trajectory(ground={self.ground!r}, h={self.disk.h:g}, t=[{self.t[0]:g}, "
                f"{self.t[-1]:g}], n={self.t.size}, status={self.status!r}, "
                f"n_steps={self.n_steps})")

    @property
    def success(self) -> bool:
        """True unless the integrator failed (guard events count as success)."""
        return self.status != "failed"

    def component(self, name: str) -> np.ndarray:
        """The state component ``name`` (e.g. ``"theta"``) along the trajectory."""
        return self.y[state_index(_layout(self.ground), name)]

    # state components, named as in the paper
    X_C = property(lambda self: self.component("X_C"), doc="X_C, centre C in OXYZ.")
    Y_C = property(lambda self: self.component("Y_C"), doc="Y_C, centre C in OXYZ.")
    psi = property(lambda self: self.component("psi"), doc="Spin angle psi.")
    theta = property(lambda self: self.component("theta"), doc="Inclination theta.")
    phi = property(lambda self: self.component("phi"), doc="Rotation angle phi.")
    omega1 = property(lambda self: self.component("omega1"), doc="omega1 (eq. 2).")
    omega2 = property(lambda self: self.component("omega2"), doc="omega2 (eq. 3).")
    omega3 = property(lambda self: self.component("omega3"), doc="omega3 (eq. 3).")

    @property
    def V_X(self) -> np.ndarray:
        """V_X, inertial velocity of C (smooth ground only; constant there)."""
        return self.component("V_X")

    @property
    def V_Y(self) -> np.ndarray:
        """V_Y, inertial velocity of C (smooth ground only; constant there)."""
        return self.component("V_Y")

    @cached_property
    def _P(self):
        return contact_point(self.disk, _layout(self.ground), self.y)

    @cached_property
    def _F(self):
        if isinstance(self.ground, str):
            return contact_force(self.disk, self.ground, self.y)
        from .equations import MODE_NAMES, coulomb_contact

        rows = [coulomb_contact(self.disk, self.ground, MODE_NAMES[m], self.y[:, i])
                for i, m in enumerate(self.mode)]
        return tuple(np.array([r[k] for r in rows]) for k in ("F_x", "F_y", "F_z"))

    @property
    def X_P(self) -> np.ndarray:
        """X_P, contact point on the plane (eq. 5)."""
        return np.asarray(self._P[0])

    @property
    def Y_P(self) -> np.ndarray:
        """Y_P, contact point on the plane (eq. 5)."""
        return np.asarray(self._P[1])

    @property
    def F_x(self) -> np.ndarray:
        """F_x, contact force in Cxyz, units of m g (eq. 8)."""
        return np.asarray(self._F[0])

    @property
    def F_y(self) -> np.ndarray:
        """F_y, contact force in Cxyz, units of m g (eq. 8)."""
        return np.asarray(self._F[1])

    @property
    def F_z(self) -> np.ndarray:
        """F_z, normal force, units of m g (eq. 11)."""
        return np.asarray(self._F[2])

    @cached_property
    def E(self) -> np.ndarray:
        """Total mechanical energy, units of m g a (eq. 13)."""
        return np.asarray(energy(self.disk, _layout(self.ground), self.y))

    def as_columns(self) -> dict[str, np.ndarray]:
        """Columns ``t, X_C, Y_C, psi, theta, phi, omega1, omega2, omega3, X_P, Y_P, F_x,
        F_y, F_z, E`` (the CSV layout of ``rollingdisk simulate --out``), and on smooth
        ground ``V_X, V_Y`` after them, so that a smooth run can be restarted from a row."""
        cols = {"t": self.t, "X_C": self.X_C, "Y_C": self.Y_C, "psi": self.psi,
                "theta": self.theta, "phi": self.phi, "omega1": self.omega1,
                "omega2": self.omega2, "omega3": self.omega3, "X_P": self.X_P,
                "Y_P": self.Y_P, "F_x": self.F_x, "F_y": self.F_y, "F_z": self.F_z,
                "E": self.E}
        if _layout(self.ground) == "smooth":
            cols.update(V_X=self.V_X, V_Y=self.V_Y)
        if self.mode is not None:
            cols["mode"] = self.mode
        return cols


# ---------------------------------------------------------------------------- numba core
_core = None
_compile_time = None


def jit_compile() -> float:
    """Import (and on first use compile) the numba integrator; return the seconds it took.

    The compiled code is cached on disk (``numba`` ``cache=True``), so after the first
    run this is the time to load it.  A cache left stale by an edit of the kernels in
    :mod:`rollingdisk.equations` (eqs. 11, 38, 49) is detected and recompiled.
    :func:`simulate` calls this itself.

    Returns
    -------
    float
        Seconds spent importing, compiling or loading, and checking the compiled code on
        the first call; the same figure again on later calls (nothing is redone).

    Raises
    ------
    ImportError
        If numba is missing, or scipy lacks the DOP853 coefficients the core takes from it.
    """
    global _core, _compile_time
    if _core is None:
        t0 = time.perf_counter()
        from . import _numba_core as core

        y = np.array([0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 1.0, 0.5])
        ys = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 1.0, 0.5])
        guards = np.ones(3, dtype=np.bool_)
        for rough, y0 in ((True, y), (False, ys)):
            core.integrate(rough, 0.1, 0.0, y0, 1e-3, 1e-3, 1e-8, 1e-8, np.inf, 0.0, guards,
                           np.zeros(1), False, 10)
            core.integrate(rough, 0.1, 0.0, y0, 1e-3, 1e-3, 1e-8, 1e-8, np.inf, 0.0, guards,
                           np.array([5e-4]), True, 10)
        if not core.rhs_matches_kernels():  # a stale on-disk cache (see _numba_core)
            core.recompile_all()
            if not core.rhs_matches_kernels():  # pragma: no cover - would be a numba bug
                raise RuntimeError("the compiled right-hand side disagrees with "
                                   "rollingdisk.equations")
        _compile_time = time.perf_counter() - t0
        _core = core
    return _compile_time


# ---------------------------------------------------------------------------- validation
def _check_state(disk: Disk, ground: str, y0) -> np.ndarray:
    names = state_names(ground)
    try:
        y = np.array(y0, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"y0 must be a sequence of {len(names)} real numbers "
                         f"({', '.join(names)}), got {y0!r}") from None
    if y.shape != (len(names),):
        raise ParameterError(f"y0 must have {len(names)} components on {ground} ground "
                         f"({', '.join(names)}), got shape {y.shape}")
    if not np.all(np.isfinite(y)):
        raise ParameterError(f"y0 must be finite, got {y.tolist()}")
    theta = y[names.index("theta")]
    if abs(theta) >= 0.5 * math.pi:
        raise ParameterError(f"theta in y0 must lie in (-pi/2, pi/2) (|theta| = pi/2: the disk "
                         f"lies flat), got {theta!r}")
    if disk.h > 0 and theta == 0.0:
        raise ParameterError("theta in y0 must be nonzero for a disk of finite thickness (h > 0):"
                         " at theta = 0 it stands on a line of its rim, outside the model")
    return y


# ---------------------------------------------------------------------------- simulate
def simulate(disk: Disk, ground: str, y0, t_span: Sequence[float], *,
             method: str = "auto", rtol: float = DEFAULT_RTOL, atol: float = DEFAULT_ATOL,
             max_step: float = math.inf, first_step: float | None = None,
             t_eval=None, events=None, guards: bool = True, max_steps: int = 50_000_000,
             progress: Callable[[float], None] | None = None) -> Trajectory:
    """Integrate the equations of motion from ``y0`` over ``t_span``, with guard events.

    Shaped like :func:`scipy.integrate.solve_ivp`.  Implements eqs. (1), (2), (37), (38)
    on rough and (2), (8), (49) on smooth ground via :mod:`rollingdisk.equations`, and
    stops at the first guard event (module docstring): ``F_z <= 0`` (eq. 11), ``theta = 0``
    for ``h > 0``, ``|theta| = pi/2``.

    Parameters
    ----------
    disk : Disk
        The disk (only ``disk.h`` enters).
    ground : {"rough", "smooth"}
        Rolling without slip, or sliding without friction.
    y0 : array_like, shape (8,) or (10,)
        Initial state, layout of :data:`~rollingdisk.equations.ROUGH_STATE` or
        :data:`~rollingdisk.equations.SMOOTH_STATE`; finite, ``|theta| < pi/2`` and
        ``theta != 0`` if ``h > 0``.
    t_span : (t0, t1)
        Interval of integration, ``t1 > t0``.
    method : {"auto", "dop853", "scipy"}
        ``"dop853"``: compiled DOP853 (numba).  ``"scipy"``: ``solve_ivp(method="DOP853")``
        on the numpy right-hand side.  ``"auto"``: ``"dop853"``, or ``"scipy"`` when user
        ``events`` are given.
    rtol, atol : float
        Relative and absolute tolerances, ``> 0``.  The defaults keep the relative energy
        drift below 1e-9 over 1000 time units of a perturbed steady motion.
    max_step : float
        Largest step, ``> 0``.
    first_step : float, optional
        Initial step, ``> 0``; chosen automatically by default.
    t_eval : array_like, optional
        Increasing times within ``t_span`` at which to store the state (as in solve_ivp,
        from the dense output of DOP853); by default every accepted step is stored.  The
        event point, if a guard fires, is appended.
    events : callable or list of callables, optional
        User events ``event(t, y)`` with optional ``terminal`` and ``direction``
        attributes, as in solve_ivp (scipy path).  A terminal user event ends the run
        with status ``"completed"``; see ``t_events``/``y_events``.
    guards : bool
        Stop at the guard events (default).  ``False`` integrates blindly (for tests).
    max_steps : int
        The compiled integrator gives up (status ``"failed"``) after this many steps.
    progress : callable, optional
        ``progress(fraction)`` called as the run advances, at most 100 times (the compiled
        integrator pauses after the first step past each hundredth of ``t_span``; it takes
        the same steps and gives the same output as without ``progress``).

    Returns
    -------
    Trajectory

    Examples
    --------
    >>> tr = simulate(Disk(h=0.1), "rough", [0, 0, 0, 0.3, 0, 0, 2.0, 0.5], (0, 10))
    >>> tr.status, bool(energy_drift(tr) < 1e-9)
    ('completed', True)
    """
    if not isinstance(disk, Disk):
        raise ParameterError(f"disk must be a rollingdisk.Disk, got {disk!r}")
    ground = check_ground(ground)
    y = _check_state(disk, ground, y0)
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
    max_step = check_real("max_step", max_step, low=0.0, low_open=True) \
        if max_step != math.inf else math.inf
    first_step = None if first_step is None else check_real(
        "first_step", first_step, low=0.0, low_open=True)
    if isinstance(max_steps, bool) or not isinstance(max_steps, (int, np.integer)) \
            or max_steps < 1:
        raise ParameterError(f"max_steps must be an integer >= 1, got {max_steps!r}")
    if method not in _METHODS:
        raise ParameterError(f"method must be one of {_METHODS}, got {method!r}")
    if t_eval is not None:
        t_eval = np.asarray(t_eval, dtype=float).ravel()
        if (t_eval.size == 0 or not np.all(np.isfinite(t_eval)) or np.any(np.diff(t_eval) < 0)
                or t_eval[0] < t0 or t_eval[-1] > t1):
            raise ParameterError("t_eval must be a non-empty increasing sequence of times within "
                             f"t_span = ({t0:g}, {t1:g})")
    if events is not None and callable(events):
        events = [events]
    if events is not None and len(events) == 0:
        events = None
    if method == "auto":
        method = "scipy" if events is not None else "dop853"
    if method == "dop853" and events is not None:
        raise ParameterError("method='dop853' takes no user events; use method='scipy' "
                         "(or 'auto') for events")
    use = np.array([guards, guards and disk.h > 0, guards], dtype=np.bool_)
    if method == "scipy":
        return _simulate_scipy(disk, ground, y, t0, t1, rtol, atol, max_step, first_step,
                               t_eval, events, use)
    return _simulate_numba(disk, ground, y, t0, t1, rtol, atol, max_step, first_step,
                           t_eval, use, int(max_steps), progress)


def _event_message(status: str, t: float, disk: Disk) -> str:
    if status == "lift-off":
        return (f"lift-off at t = {t:.12g}: the normal force F_z (eq. 11) reached 0 and the "
                "disk leaves the plane; the model ends here")
    if status == "edge-contact":
        return (f"edge contact at t = {t:.12g}: theta reached 0 with h = {disk.h:g} > 0, the "
                "disk lands on its other rim edge (an impact, outside the model)")
    if status == "fell-flat":
        return (f"fell flat at t = {t:.12g}: |theta| reached pi/2, the disk lies on the "
                "plane")
    return ""


def _simulate_numba(disk, ground, y, t0, t1, rtol, atol, max_step, first_step, t_eval, use,
                    max_steps, progress):
    jit_compile()
    core = _core
    rough = ground == "rough"
    has_t_eval = t_eval is not None
    te = t_eval if has_t_eval else np.zeros(1)
    start = time.perf_counter()
    first = 0.0 if first_step is None else first_step
    if progress is None:
        ts, ys, n_steps, n_rhs, code, event, *_ = core.integrate(
            rough, disk.h, t0, y, t1, t1, rtol, atol, max_step, first, use, te, has_t_eval,
            max_steps)
    else:
        # pause after the first step past each of 100 marks in time and go on from the end
        # of that step with the step size it chose: the very steps of a run without
        # progress (only f at each pause is evaluated once more)
        t_parts, y_parts = [], []
        n_steps = n_rhs = 0
        h_next = first
        tc, yc = t0, y
        n_chunks = 100
        for i in range(1, n_chunks + 1):
            tb = t1 if i == n_chunks else t0 + (t1 - t0) * i / n_chunks
            if tb <= tc:
                continue
            later = bool(t_parts)
            # requested times at tc were output by the previous chunk
            te_c = te[te > tc] if later and has_t_eval else te
            ts_c, ys_c, ns, nr, code, event, h_next, tc, yc = core.integrate(
                rough, disk.h, tc, yc, t1, tb, rtol, atol, max_step, h_next, use, te_c,
                has_t_eval, max_steps - n_steps)
            n_steps += ns
            n_rhs += nr
            # without t_eval a later chunk starts with the previous one's last point
            skip = 1 if later and not has_t_eval else 0
            t_parts.append(ts_c[skip:])
            y_parts.append(ys_c[skip:])
            t_now = float(ts_c[-1]) if event >= 0 else tc  # the event point, if one fired
            progress((t_now - t0) / (t1 - t0))
            if code != core.RUNNING:
                break
        ts = np.concatenate(t_parts)
        ys = np.concatenate(y_parts)
    wall = time.perf_counter() - start
    status = _STATUS_OF_CODE[int(code)]
    t_event = float(ts[-1]) if status in ("lift-off", "edge-contact", "fell-flat") else None
    if status == "completed":
        message = f"completed: integrated to t = {ts[-1]:.12g} in {n_steps} steps"
    elif status == "failed":
        if n_steps >= max_steps:
            message = f"failed: max_steps = {max_steps} steps taken before t = {t1:g}"
        else:
            message = (f"failed: the step size fell below the round-off limit at t = "
                       f"{ts[-1]:.12g} (singular or non-finite right-hand side?)")
    else:
        message = _event_message(status, t_event, disk)
    return Trajectory(disk=disk, ground=ground, t=ts, y=ys.T, status=status, message=message,
                      n_steps=int(n_steps), n_rhs=int(n_rhs), method="dop853",
                      t_event=t_event, wall_time=wall)


class _Counter:
    def __init__(self, f):
        self.f = f
        self.n = 0

    def __call__(self, t, y):
        self.n += 1
        return self.f(t, y)


def _simulate_scipy(disk, ground, y, t0, t1, rtol, atol, max_step, first_step, t_eval,
                    events, use):
    from scipy.integrate import solve_ivp

    fun = _Counter(equations_of_motion(disk, ground))
    i_theta = state_index(ground, "theta")
    guard_list, guard_status = [], []

    def lift_off(t, yy):
        return contact_force(disk, ground, yy)[2]

    def edge(t, yy):
        return yy[i_theta]

    def flat(t, yy):
        return 0.5 * math.pi - abs(yy[i_theta])

    for ev, st, on, direction in ((lift_off, "lift-off", use[0], -1.0),
                                  (edge, "edge-contact", use[1], 0.0),
                                  (flat, "fell-flat", use[2], -1.0)):
        if on:
            ev.terminal = True
            ev.direction = direction
            guard_list.append(ev)
            guard_status.append(st)
    if use[0] and contact_force(disk, ground, y)[2] <= 0.0:
        return Trajectory(disk=disk, ground=ground, t=[t0], y=y[:, None], status="lift-off",
                          message=_event_message("lift-off", t0, disk), n_steps=0, n_rhs=0,
                          method="scipy", t_event=t0, wall_time=0.0)
    user = list(events or [])
    options = {}
    if first_step is not None:
        options["first_step"] = first_step
    start = time.perf_counter()
    sol = solve_ivp(fun, (t0, t1), y, method="DOP853", rtol=rtol, atol=atol,
                    max_step=max_step, t_eval=t_eval, events=guard_list + user or None,
                    **options)
    wall = time.perf_counter() - start
    ts, ys = sol.t, sol.y
    status, t_event, message = "completed", None, ""
    if sol.status == -1:
        status, message = "failed", f"failed: {sol.message}"
    elif sol.status == 1:
        # the event that stopped the run: a terminal one (``terminal`` True, or a count as
        # in solve_ivp) that occurred as often as it allows; non-terminal events only record
        every = guard_list + user
        fired = []
        for i, ev in enumerate(every):
            allowed = int(getattr(ev, "terminal", False) or 0)
            if allowed > 0 and len(sol.t_events[i]) >= allowed:
                fired.append((sol.t_events[i][-1], i))
        t_hit, i_hit = min(fired)
        if t_hit not in ts:
            ts = np.append(ts, t_hit)
            ys = np.column_stack([ys, sol.y_events[i_hit][-1]])
        if i_hit < len(guard_list):
            status = guard_status[i_hit]
            if status == "edge-contact" and ys[i_theta, -1] * y[i_theta] <= 0:
                # the root may land a rounding error past theta = 0, where h~ = h sgn(theta)
                # flips: report the admissible side, as the compiled path does
                ys = np.array(ys)
                ys[i_theta, -1] = np.nextafter(0.0, y[i_theta])
            t_event = float(t_hit)
            message = _event_message(status, t_event, disk)
        else:
            message = f"completed: stopped by user event {i_hit - len(guard_list)} at " \
                      f"t = {t_hit:.12g}"
    if not message:
        message = f"completed: integrated to t = {ts[-1]:.12g} in {len(sol.t) - 1} steps"
    # solve_ivp reports steps only through its output; with t_eval, estimate them from
    # the evaluations (12 per step attempt, 2 to start)
    n_steps = len(sol.t) - 1 if t_eval is None else max((sol.nfev - 2) // 12, 0)
    t_events = tuple(sol.t_events[len(guard_list):]) if sol.t_events is not None else ()
    y_events = tuple(sol.y_events[len(guard_list):]) if sol.y_events is not None else ()
    return Trajectory(disk=disk, ground=ground, t=ts, y=ys, status=status, message=message,
                      n_steps=n_steps, n_rhs=fun.n, method="scipy", t_event=t_event,
                      wall_time=wall, t_events=t_events, y_events=y_events)


def simulate_steady(motion, t_end: float, *, perturb: float = 0.0, kick: float = 0.0,
                    psi0: float = 0.0, phi0: float = 0.0, **options) -> Trajectory:
    """Simulate from a steady motion, optionally with ``theta(0)`` or ``omega1(0)`` perturbed.

    Parameters
    ----------
    motion : SteadyMotion
        From :func:`rollingdisk.steady.steady_motion` or
        :func:`~rollingdisk.steady.straight_line` (anything with ``ground``, ``h``,
        ``theta0`` and ``initial_state(psi0, phi0)``).
    t_end : float
        End time, ``> 0`` (the run starts at ``t = 0``).
    perturb : float
        Added to ``theta(0)``; all else stays at its steady value (eq. 36 with
        ``theta~(0) = perturb``, ``omega~_i(0) = 0``).  The linearized eq. (39) then has a
        constant right-hand side: the disk oscillates about a neighbouring steady motion.
    kick : float
        Added to ``omega1(0) = d theta/dt``: the oscillation stays centred on ``theta0``.
    psi0, phi0 : float
        Initial spin and rotation angles.
    **options
        Passed to :func:`simulate` (``rtol``, ``atol``, ``t_eval``, ...).

    Returns
    -------
    Trajectory
        With ``theta_ref = motion.theta0`` and ``motion`` set.
    """
    for name in ("ground", "h", "theta0", "initial_state"):
        if not hasattr(motion, name):
            raise ParameterError(f"motion must be a SteadyMotion (it has no {name!r})")
    t_end = check_real("t_end", t_end, low=0.0, low_open=True)
    perturb = check_real("perturb", perturb)
    kick = check_real("kick", kick)
    disk = getattr(motion, "disk", None)
    if not isinstance(disk, Disk):  # keep the motion's disk (and its physical scale)
        disk = Disk(h=float(motion.h))
    i_theta = state_index(motion.ground, "theta")
    y0 = np.array(motion.initial_state(psi0, phi0), dtype=float)
    theta0 = float(y0[i_theta])
    theta = theta0 + perturb
    if abs(theta) >= 0.5 * math.pi or (disk.h > 0 and theta == 0.0):
        allowed = f"({-0.5 * math.pi - theta0:.6g}, {0.5 * math.pi - theta0:.6g})"
        if disk.h > 0:
            allowed += f" other than {-theta0:.6g} (theta = 0 is outside the model for h > 0)"
        raise ParameterError(f"perturb must lie in {allowed}, so that theta(0) = theta0 + perturb "
                         f"stays in (-pi/2, pi/2); got perturb = {perturb!r}, theta(0) = "
                         f"{theta!r}")
    y0[i_theta] = theta
    y0[state_index(motion.ground, "omega1")] += kick
    tr = simulate(disk, motion.ground, y0, (0.0, t_end), **options)
    return dataclasses.replace(tr, theta_ref=float(motion.theta0), motion=motion)


# ---------------------------------------------------------------------------- measurements
def energy_drift(traj: Trajectory) -> float:
    """Largest relative change of the energy (eq. 13) along ``traj``.

    The equations conserve energy on both grounds (eq. 12: the contact force does no work
    without slip or without friction), so this measures the integration error.

    Parameters
    ----------
    traj : Trajectory
        A simulated motion.

    Returns
    -------
    float
        ``max |E(t) - E(t0)| / |E(t0)|`` over the stored points, ``E`` of eq. (13).
    """
    E = traj.E
    return float(np.max(np.abs(E - E[0])) / max(abs(E[0]), np.finfo(float).tiny))


def _hermite5_root(t0, t1, v0, v1, d0, d1, a0, a1):
    """Root in [t0, t1] of the quintic Hermite interpolant of (value, slope, curvature)."""
    dt = t1 - t0

    def p(s):
        # quintic Hermite basis on s in [0, 1]
        s2 = s * s
        s3 = s2 * s
        s4 = s3 * s
        s5 = s4 * s
        h0 = 1 - 10 * s3 + 15 * s4 - 6 * s5
        h1 = s - 6 * s3 + 8 * s4 - 3 * s5
        h2 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5)
        h5 = 10 * s3 - 15 * s4 + 6 * s5
        h4 = -4 * s3 + 7 * s4 - 3 * s5
        h3 = 0.5 * (s3 - 2 * s4 + s5)
        return (h0 * v0 + h1 * dt * d0 + h2 * dt * dt * a0
                + h5 * v1 + h4 * dt * d1 + h3 * dt * dt * a1)

    lo, hi = 0.0, 1.0
    plo = p(lo)
    for _ in range(60):  # bisection to round-off (the bracket is known)
        mid = 0.5 * (lo + hi)
        pm = p(mid)
        if (pm > 0) == (plo > 0):
            lo, plo = mid, pm
        else:
            hi = mid
        if hi - lo < 1e-16:
            break
    return t0 + 0.5 * (lo + hi) * dt


def oscillation_frequency(traj: Trajectory, *, min_periods: int = 2) -> float | None:
    """Angular frequency of the oscillation of ``theta`` along ``traj``, or None.

    The upward crossings of ``theta - c`` (``c`` the time average of ``theta``) are found
    on the quintic Hermite interpolant of ``theta, d theta/dt = omega1`` and
    ``d^2 theta/dt^2 = d omega1/dt`` (eq. 38 / 49) between stored points; the period is the
    least-squares slope of the crossing times against their index, so the offset ``c``
    does not bias it.  Compare with ``varpi`` of eq. (40) / (51).

    Parameters
    ----------
    traj : Trajectory
        A simulated motion, e.g. from :func:`simulate_steady` with a small ``perturb``;
        store points densely enough (``max_step``) that each crossing is bracketed.
    min_periods : int
        Fewest whole periods to measure.

    Returns
    -------
    float or None
        The angular frequency ``2 pi / period``; None if ``theta`` crosses its mean upward
        fewer than ``min_periods + 1`` times.
    """
    t = traj.t
    th = traj.theta
    if t.size < 3:
        return None
    c = float(np.trapezoid(th, t) / (t[-1] - t[0]))
    v = th - c
    w1, w2, w3 = traj.omega1, traj.omega2, traj.omega3
    acc = np.asarray(omega_dot(traj.disk, traj.ground, th, w1, w2, w3)[0])
    up = np.nonzero((v[:-1] < 0) & (v[1:] >= 0))[0]
    if up.size < min_periods + 1:
        return None
    tc = np.array([_hermite5_root(t[i], t[i + 1], v[i], v[i + 1], w1[i], w1[i + 1],
                                  acc[i], acc[i + 1]) for i in up])
    k = np.arange(tc.size, dtype=float)
    period = np.polyfit(k, tc, 1)[0]
    return float(2 * math.pi / period)


def growth_rate(traj: Trajectory, *, theta_ref: float | None = None,
                max_amplitude: float = 1e-6) -> float | None:
    """Exponential growth rate of an unstable departure from a steady motion, or None.

    In the linear regime (eq. 39 / 50 with ``varpi^2 < 0``)
    ``omega1 = alpha e^{lambda t} + beta e^{-lambda t}`` exactly; ``lambda`` (to compare
    with ``sqrt(-varpi^2)``) is fitted by variable projection (``alpha, beta`` by linear
    least squares for each trial ``lambda``, relative residuals) over the stored points
    where ``|theta - theta_ref| <= max_amplitude``, the part still linear.

    Parameters
    ----------
    traj : Trajectory
        A simulated motion started near an unstable steady motion (:func:`simulate_steady`
        with a tiny ``perturb``).
    theta_ref : float, optional
        The steady inclination; ``traj.theta_ref`` (set by :func:`simulate_steady`) or
        ``theta(0)`` by default.
    max_amplitude : float
        Largest departure ``|theta - theta_ref|`` counted as linear.  The nonlinear terms
        bias the result by about this much, relatively.

    Returns
    -------
    float or None
        The growth rate ``lambda``; None when the linear part holds fewer than 8 points or
        shows no growth.
    """
    from scipy.optimize import minimize_scalar

    ref = theta_ref if theta_ref is not None else (
        traj.theta_ref if traj.theta_ref is not None else float(traj.theta[0]))
    dev = np.abs(traj.theta - ref)
    over = np.nonzero(dev > max_amplitude)[0]
    end = over[0] if over.size else traj.t.size
    tau = traj.t[:end] - traj.t[0]
    w = traj.omega1[:end]
    if tau.size < 8 or not np.any(w != 0):
        return None
    scale = np.abs(w) + 1e-3 * np.max(np.abs(w))  # relative residuals, floored near 0

    def misfit(lam):
        e = np.exp(-lam * (tau[-1] - tau))  # e^{lam tau}, normalised at the end
        f = np.exp(-lam * tau)
        M = np.column_stack([e, f]) / scale[:, None]
        coef, *_ = np.linalg.lstsq(M, w / scale, rcond=None)
        r = M @ coef - w / scale
        return float(r @ r)

    # a first guess from the log-slope of the second half
    half = tau >= 0.5 * tau[-1]
    ok = half & (w != 0)
    if np.count_nonzero(ok) < 2:
        return None
    lam0 = np.polyfit(tau[ok], np.log(np.abs(w[ok])), 1)[0]
    if not lam0 > 0:
        return None
    res = minimize_scalar(misfit, bounds=(0.5 * lam0, 2.0 * lam0), method="bounded",
                          options={"xatol": 1e-10 * lam0})
    lam = float(res.x)
    return lam if lam > 0 else None


def fit_circle(x, y) -> tuple[float, float, float]:
    """Algebraic least-squares circle through points ``(x, y)``.

    Solves ``x^2 + y^2 + D x + E y + F = 0`` in the least-squares sense (Kasa fit) on
    coordinates centred at their mean (for conditioning).  Exact for points on a circle.
    Used to check that C and P trace concentric circles about A (eqs. 22-24).

    Parameters
    ----------
    x, y : array_like
        Coordinates of the points (e.g. ``traj.X_P, traj.Y_P``), equally many, at least 3.

    Returns
    -------
    x_c, y_c, r : float
        Centre and radius of the circle.

    Raises
    ------
    ValueError
        If ``x`` and ``y`` differ in length or hold fewer than 3 points.
    """
    x = np.asarray(x, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    if x.shape != y.shape or x.size < 3:
        raise ParameterError("x and y must be equally long with at least 3 points")
    mx, my = x.mean(), y.mean()
    u, v = x - mx, y - my
    M = np.column_stack([u, v, np.ones_like(u)])
    rhs = -(u * u + v * v)
    (D, E, F), *_ = np.linalg.lstsq(M, rhs, rcond=None)
    uc, vc = -0.5 * D, -0.5 * E
    r = math.sqrt(max(uc * uc + vc * vc - F, 0.0))
    return float(uc + mx), float(vc + my), r
