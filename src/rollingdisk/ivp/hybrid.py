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
    :data:`~rollingdisk.ivp.coulomb_modes.STICK_TOL`) it sticks if the moment that holds it
    fits in ``c F_z``, else the moment flips; with ``omega_h`` not at rest ``rref`` is
    renewed.  Left when the holding moment reaches ``c F_z`` (event ``c F_z - |M_h|``).
    Both paths (scipy, compiled) run every mode.

Terminal guards as on the ideal grounds: lift-off (``F_z = 0``, eq. 11), edge contact
(``theta = 0`` with ``h > 0``), fell flat (``|theta| = pi/2``).

Integration: DOP853 stepped one step at a time; after each step every event function is
evaluated on the step's dense output (at 9 points) and a sign change is located by
``brentq`` on ``sol(t)``, never only at step ends.  Two paths take the same steps: scipy's
``DOP853`` driven from Python, and the compiled loop of :mod:`rollingdisk.ivp.fastsegment`,
which hands the driver only a step where an event function changes sign (``method``,
:data:`~rollingdisk.ivp.coulomb_driver.PY_BUDGET`).  The energy dissipated by each term is
integrated as four extra quadrature states, so ``E + dissipated = const`` (eq. 12) can be
checked along a run.
Budgets of steps (status ``"step-budget"``), wall clock (``"time-budget"``) and transitions
and a minimal step size (``"failed"``) bound the work, each with a message; a cap on the
stored points (thinning beyond it) bounds the memory.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np

from rollingdisk.engine.methods import check_method
from rollingdisk.ivp import fastsegment as _fs
from rollingdisk.ivp.coulomb_driver import CoulombTrajectory, _Hybrid  # noqa: F401
from rollingdisk.ivp.coulomb_modes import (  # noqa: F401 - U_EPS, W_EPS, _Run: tests
    DISSIPATION_TERMS,
    U_EPS,
    W_EPS,
    _Run,
    _Singular,
)
from rollingdisk.ivp.simulation import _check_state
from rollingdisk.ivp.slipdir import (  # noqa: F401 - _slip_accel, _slip_direction: tests use them here
    _slip_accel,
    _slip_direction,
    slip_direction,
)
from rollingdisk.model.coulomb import check_coulomb
from rollingdisk.model.disk import Disk
from rollingdisk.model.ground import Coulomb
from rollingdisk.results.trajectory import Trajectory
from rollingdisk.util.checks import check_real, check_span, real_array
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["simulate_coulomb", "slip_direction", "energy_balance", "DISSIPATION_TERMS"]


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



#: Default budgets of :func:`simulate_coulomb`.  A step of this path (scipy's DOP853 with
#: events on each step's dense output, in Python) costs about 0.1-1 ms, so 200 000 steps
#: are 20 s to 3 min; the wall-clock budget bounds the slow end (issue 18, item 4).
DEFAULT_MAX_STEPS = 200_000
DEFAULT_MAX_WALL_TIME = 60.0
#: Stored points beyond which every other regular step is dropped (memory: about 250 bytes
#: a point); above the default step budget, so a run within it keeps every step.
DEFAULT_MAX_POINTS = 500_000
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
        percent of it and at least every
        :data:`~rollingdisk.ivp.coulomb_driver.REPORT_EVERY` seconds.
    method : {"auto", "dop853", "scipy", "lsoda"}
        Words of :mod:`rollingdisk.engine.methods`.  ``"scipy"``: scipy's DOP853 driven
        from Python.  ``"lsoda"``: scipy's LSODA (BDF where the problem is stiff) driven
        from Python, events located the same way on its interpolant: for long micro-slip at
        the edge of the friction cone, where the slip's direction relaxes at a rate of
        order ``mu g/|u|`` and DOP853 needs about 1e5 steps per time unit (docs/friction.md
        has the measurements).  ``"dop853"``: the steps without events in the compiled loop
        of :mod:`rollingdisk.ivp.fastsegment` (numba, compiled once per machine).
        ``"auto"`` (default): scipy for :data:`~rollingdisk.ivp.coulomb_driver.PY_BUDGET`
        steps of the process, then compiled (at once if the loop is loaded) where numba is
        installed.  ``"scipy"`` and ``"dop853"`` take the same steps and locate events the same
        way: transitions agree to about 1e-10.
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


