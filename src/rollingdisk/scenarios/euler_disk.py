"""Euler's disk, end to end: the toy spun up and run to its end with dissipation on.

The toy (a thick steel disk on a mirror base) starts on its spin-in-place steady motion
(section 3.2.1 with ``r_C = 0``) at the tilt ``alpha0 = pi/2 - |theta0|`` and runs until it
falls flat, lifts off or comes to rest.  Three dissipative terms:

* **creep friction** (regularized Coulomb): the tangential contact force is proportional to
  the slip at small slip and saturates at ``mu F_z``, in the cubic form of Vermeulen &
  Johnson, "Contact of nonspherical elastic bodies transmitting tangential forces",
  J. Appl. Mech. 31 (1964) 338, written in the slip velocity ``u`` of the contact point
  (eq. 6)::

      F_t = -mu F_z f(|u|/u_s) u/|u|,  f(s) = 1 - (1 - s)^3 (s < 1),  1 (s >= 1),
      u_s = 3 mu / k,

  so that ``F_t ~ -k F_z u`` for small slip (``k``, the creep coefficient) and
  ``|F_t| = mu F_z`` for ``|u| >= u_s``.  The micro-slip of the late stage is then a stiff
  but smooth ODE (no mode switching), integrated by LSODA (stiff/non-stiff switching);
* **rolling resistance** ``M_h = -c F_z omega_h / sqrt(|omega_h|^2 + eps^2)``: the model of
  :class:`rollingdisk.RollingResistance`, smoothed below ``|omega_h| ~ eps``;
* optionally **air**: Moffatt's squeeze film, :class:`rollingdisk.AirDrag` with ``c`` from
  the air viscosity (Moffatt, Nature 404 (2000) 833; the derived constant ``K = 1.28113``),
  or Bildsten's boundary layer, the moment of
  :class:`rollingdisk.model.air_models.BoundaryLayerAirDrag` (Phys. Rev. E 66 (2002)
  056309; ``c`` from the air's viscosity and density), chosen by ``EulerDisk.air_law``.

Equations: the sliding system of :mod:`rollingdisk.symbolic.coulomb` (the Newton-Euler
balances (8), (9) with (11)) with the friction force given: its kernel
:func:`rollingdisk.model.coulomb._sliding_solve` is linear in ``mu e``, so the creep force is
that kernel with the non-unit vector ``e = f(|u|/u_s) u/|u|``.  The velocity of C is
integrated in the turning frame Cxyz (``dv_Cx/dt = F_x + v_Cy Omega``, ``dv_Cy/dt = F_y -
v_Cx Omega``, (8)_1,2), where the spin-in-place family is an equilibrium; ``X_C, Y_C, psi,
phi`` are not needed (nothing depends on them) and are not integrated.  Both are checked
against the sympy derivation in ``tests/test_euler_disk.py``.

Predicted exponents: along the steady spin-in-place family (``F_z = 1``) the energy
``E(alpha)`` and the dissipated power ``P(alpha)`` are known, so the adiabatic decay is
``t0 - t = int_0^alpha E'(a)/|P(a)| da`` and the exponents are the slopes of ``log alpha``,
``log Omega`` and ``log v_P`` against ``log(t0 - t)`` over the fit window (computed, not
quoted).  Dimensionless units (m = a = g = 1); SI through the toy's radius and mass.

The parts: the toy and its laws (:mod:`.euler_toy`), the equations on the reduced state
(:mod:`.euler_kernels`), the predictions and the fit of the exponents
(:mod:`.euler_predict`), the result (:mod:`.euler_result`), the run on Coulomb ground
(:mod:`.euler_coulomb`); this module runs the toy (:func:`run_euler_disk`).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

import numpy as np

from rollingdisk.scenarios.euler_coulomb import COULOMB_POINTS as COULOMB_POINTS
from rollingdisk.scenarios.euler_coulomb import _CoulombToyRun
from rollingdisk.scenarios.euler_kernels import (
    _energy,
    _kicked_state,
    _observables,
    _rhs,
    creep_factor,
)
from rollingdisk.scenarios.euler_predict import (
    _fit_exponents,
    _window,
    predicted_end_time,
    predicted_exponents,
)
from rollingdisk.scenarios.euler_result import EULER_VARIABLES as EULER_VARIABLES
from rollingdisk.scenarios.euler_result import EulerDiskResult
from rollingdisk.scenarios.euler_toy import (
    AIR_DENSITY,
    AIR_LAWS,
    AIR_VISCOSITY,
    END_KINDS,
    EXPONENT_NAMES,
    FIT_WINDOW,
    FIT_WINDOW_AIR,
    FRICTION_LAWS,
    TERMS,
    EulerDisk,
    dissipation_laws,
)
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["EulerDisk", "EulerDiskResult", "run_euler_disk", "predicted_exponents",
           "creep_factor", "predicted_end_time", "END_KINDS", "AIR_VISCOSITY", "FIT_WINDOW",
           "FIT_WINDOW_AIR", "AIR_DENSITY", "AIR_LAWS", "FRICTION_LAWS", "dissipation_laws"]


def _locate(dense, event, t_a, t_b):
    """Time and state in ``[t_a, t_b]`` where ``event(dense(t))`` changes sign (it is
    positive at ``t_a``, not at ``t_b``), by ``brentq`` on the step's interpolant."""
    from scipy.optimize import brentq

    if event(dense(t_a)) <= 0.0:  # nothing to locate (already there at the step start)
        return t_a, dense(t_a)
    t = brentq(lambda s: event(dense(s)), t_a, t_b, xtol=1e-14 * (1.0 + abs(t_b)),
               rtol=8.9e-16)
    return t, dense(t)


#: Tolerances of :func:`run_euler_disk` by friction law: LSODA's on the creep law,
#: DOP853's on Coulomb friction (energy balance 2.2e-9 over the toy's 7.5e7 steps,
#: docs/friction.md).
TOLERANCES = {"creep": (1e-9, 1e-11), "coulomb": (1e-10, 1e-12)}


def run_euler_disk(toy: EulerDisk | None = None, *, alpha_end: float = 1e-3,
                   t_max: float = 1e5, rtol: float | None = None, atol: float | None = None,
                   max_steps: int = 2_000_000, max_wall_time: float = 120.0,
                   fit_window: tuple | None = None, predict: bool = True, kick: float = 0.0,
                   progress: Callable[[float], None] | None = None) -> EulerDiskResult:
    """Spin the toy up on its spin-in-place steady motion and run it to its end.

    Parameters
    ----------
    toy : EulerDisk, optional
        The toy and its ground (default ``EulerDisk()``).
    alpha_end : float
        "Fell flat" when ``alpha <= alpha_end``, in ``(0, alpha0)``.
    t_max : float
        Stop (status ``"failed"``) at this time if no end came, ``> 0``.
    rtol, atol : float, optional
        Tolerances, ``rtol`` in ``[1e-13, 1e-3]``, ``atol > 0``: LSODA's on the creep law
        (default 1e-9, 1e-11), DOP853's on Coulomb friction (default 1e-10, 1e-12;
        :data:`TOLERANCES`).
    max_steps : int
        Step budget, ``>= 1`` (Coulomb friction: the toy's micro-slip near its end takes
        7.5e7 steps, about 8 minutes, so pass ``max_steps=3 * 10**8`` and a wall budget of
        half an hour; docs/friction.md).
    max_wall_time : float
        Wall-clock budget [s], ``> 0``.
    fit_window : (float, float), optional
        ``alpha`` range of the exponent fits (and of the prediction); default
        :data:`FIT_WINDOW`, or :data:`FIT_WINDOW_AIR` with air drag on (the air film
        drives the disk off the steady family below ``alpha ~ 0.01``, see
        ``docs/friction.md``; the boundary layer holds above ``alpha_c ~ 5e-3``).
    predict : bool
        Compute the predicted exponents (:func:`predicted_exponents`).
    kick : float
        Added to ``omega1`` at ``t = 0``, with ``v_Cy`` such that the disk still rolls
        (eq. 6): a nudge off the steady motion; 0 by default.
    progress : callable, optional
        Called with the fraction done, ``log(alpha0/alpha) / log(alpha0/alpha_end)``.

    Returns
    -------
    EulerDiskResult
        ``status == "completed"`` with ``end`` one of :data:`END_KINDS`; else
        ``"failed"`` (step budget, wall-clock budget, ``t_max``, step sizes collapsing,
        solver failure) with a message, never a hang.

    Notes
    -----
    Ends: fell flat (``alpha <= alpha_end``), lifted off (``F_z < 0``, eq. 11), came to
    rest (``|omega|`` and ``|v_C|`` below ``1e-10``), edge contact (``theta`` changes sign,
    ``h > 0``).  Events are checked at every accepted step and located on its dense output.
    With ``toy.friction == "coulomb"`` the run is :func:`rollingdisk.simulate_coulomb` (its
    compiled loop once loaded) from the same state, ``alpha_end`` its ``alpha_min``; the
    result's ``extra`` holds its ``"transitions"`` (rolling <-> sliding) as well.
    Step sizes collapsing: 50 accepted steps in a row shorter than ``1e-12 (1 + t)``.

    Examples
    --------
    >>> r = run_euler_disk(EulerDisk(alpha0=0.3), t_max=5.0, predict=False)
    >>> r.status, r.end
    ('failed', None)
    """
    toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time, kick, (lo, hi) = \
        _check_run_arguments(toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time,
                             kick, fit_window)
    if toy.friction == "coulomb":
        run = _CoulombToyRun(toy, alpha_end, t_max, rtol, atol, kick)
    else:
        run = _ToyRun(toy, alpha_end, t_max, rtol, atol, kick)
    run.integrate(max_steps, max_wall_time, progress)
    return _result(run, (lo, hi), predict)


def _check_run_arguments(toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time, kick,
                         fit_window):
    """The validated arguments of :func:`run_euler_disk`, ``fit_window`` as ``(lo, hi)``."""
    toy = EulerDisk() if toy is None else toy
    if not isinstance(toy, EulerDisk):
        raise ParameterError(f"toy must be an EulerDisk, got {type(toy).__name__}")
    alpha_end = check_real("alpha_end", alpha_end, low=0.0, high=toy.alpha0, low_open=True,
                           high_open=True)
    t_max = check_real("t_max", t_max, low=0.0, low_open=True)
    rtol = check_real("rtol", TOLERANCES[toy.friction][0] if rtol is None else rtol,
                      low=1e-13, high=1e-3)
    atol = check_real("atol", TOLERANCES[toy.friction][1] if atol is None else atol, low=0.0,
                      low_open=True)
    max_steps = check_int("max_steps", max_steps, low=1)
    max_wall_time = check_real("max_wall_time", max_wall_time, low=0.0, low_open=True)
    kick = check_real("kick", kick)
    if fit_window is None:
        fit_window = (FIT_WINDOW_AIR if toy.c_air > 0 or toy.c_boundary_layer > 0
                      else FIT_WINDOW)
    lo, hi = _window("fit_window", fit_window)
    if not lo < hi < toy.alpha0:
        raise ParameterError(f"fit_window must satisfy 0 < lo < hi < alpha0 = "
                             f"{toy.alpha0:g}, got {fit_window!r}")
    return toy, alpha_end, t_max, rtol, atol, max_steps, max_wall_time, kick, (lo, hi)


class _ToyRun:
    """One run of :func:`run_euler_disk`: the LSODA solver on the creep equations, the
    recorded steps, and how the run ended (``end``, ``status``, ``message``)."""

    def __init__(self, toy, alpha_end, t_max, rtol, atol, kick):
        from scipy.integrate import LSODA

        self.toy, self.alpha_end, self.t_max, self.rtol = toy, alpha_end, t_max, rtol
        self.start = time.monotonic()
        mu = toy.mu
        u_s = 3.0 * mu / toy.creep if mu > 0 else 1.0  # mu = 0: no friction at all
        self.params = (toy.h, mu, u_s, toy.rolling_resistance, toy.c_air, toy.omega_eps)
        self.c_bl = toy.c_boundary_layer
        self.last = [1.0]  # F_z of the latest evaluation (near the accepted point) for lift-off
        x0 = _kicked_state(toy, kick)
        self.solver = LSODA(self._f, 0.0, x0, t_max, rtol=rtol, atol=atol)
        self.ts, self.xs = [0.0], [x0.copy()]
        self.log_span = math.log(toy.alpha0 / alpha_end)
        self.end = None
        self.status, self.message = "failed", ""
        F_z0 = _rhs(*self.params, x0, c_bl=self.c_bl)[1]
        if F_z0 < 0.0:  # the kick asks for a pull from the plane: no motion in contact at all
            self.end, self.status = "lift-off", "completed"
            self.message = f"lifted off at the start: F_z(0) = {F_z0:.4g} < 0 (eq. 11)"
        self.n = 0
        self.n_short = 0
        self.shown = -1.0
        self.side = math.copysign(1.0, x0[2])

    def _f(self, t, x):
        dx, self.last[0], _ = _rhs(*self.params, x, c_bl=self.c_bl)
        return dx

    def forces(self, XT):
        """``(F_z, |u|)`` at the recorded states ``XT`` (9, N)."""
        return _rhs(*self.params, XT, c_bl=self.c_bl)[1:]

    def extra(self) -> dict:
        return {}

    def integrate(self, max_steps, max_wall_time, progress):
        """Step until an end, a budget, ``t_max`` or a failure (``message`` says which)."""
        solver = self.solver
        while self.end is None:
            if self._stopped(max_steps, max_wall_time):
                break
            t_old = solver.t
            msg = solver.step()
            self.n += 1
            if solver.status == "failed":
                self.message = f"LSODA failed at t = {solver.t:.6g}: {msg}"
                break
            x = solver.y
            if not math.isfinite(x.sum()):
                self.message = f"the state left floating-point range at t = {solver.t:.6g}"
                break
            self.ts.append(solver.t)
            self.xs.append(x.copy())
            if self._ended(x, t_old, progress):
                break
        if progress is not None:
            progress(1.0 if self.end is not None else self._done(
                math.pi / 2 - abs(self.xs[-1][2])))

    def _stopped(self, max_steps, max_wall_time):
        """True (message set) if the run reached ``t_max`` or spent a budget."""
        if self.solver.status == "finished":
            self.message = f"reached t_max = {self.t_max:g} before any end (alpha = " \
                           f"{math.pi / 2 - abs(self.xs[-1][2]):.3g})"
        elif self.n >= max_steps:
            self.message = f"step budget exhausted: max_steps = {max_steps} steps reached " \
                           f"at t = {self.ts[-1]:.6g} without an end"
        elif time.monotonic() - self.start > max_wall_time:
            self.message = f"wall-clock budget exhausted: max_wall_time = " \
                           f"{max_wall_time:g} s reached at t = {self.ts[-1]:.6g} without an end"
        else:
            return False
        return True

    def _done(self, alpha):
        """The fraction of the run done at tilt ``alpha``, on a log scale."""
        return min(max(math.log(self.toy.alpha0 / max(alpha, 1e-300)) / self.log_span, 0.0),
                   1.0)

    def _ended(self, x, t_old, progress):
        """Check the ends after an accepted step to state ``x``; True if the run ended
        (``end``, ``status``, ``message`` set, the end located on the step) or the step
        sizes collapsed."""
        solver, params, c_bl = self.solver, self.params, self.c_bl
        F_z = self.last[0]
        if F_z < 0.0:  # confirm at the accepted state itself
            F_z = _rhs(*params, x, c_bl=c_bl)[1]
        tiny = solver.t - t_old < 1e-12 * (1.0 + abs(solver.t))
        self.n_short = self.n_short + 1 if tiny else 0
        alpha = math.pi / 2 - abs(x[2])
        if progress is not None and self.n % 100 == 0:
            done = self._done(alpha)
            if done >= self.shown + 0.005:  # a few hundred updates per run, not one per step
                self.shown = done
                progress(done)
        event = None  # a function of the state that changes sign at the end
        alpha_end, side = self.alpha_end, self.side
        if alpha <= alpha_end:
            self.end, self.message = "fell-flat", f"fell flat: alpha = {alpha_end:g}"
            event = lambda z: math.pi / 2 - abs(z[2]) - alpha_end  # noqa: E731
        elif F_z < 0.0:
            self.end, self.message = "lift-off", "lifted off: F_z = 0 (eq. 11)"
            event = lambda z: _rhs(*params, z, c_bl=c_bl)[1]  # noqa: E731
        elif math.copysign(1.0, x[2]) != side:
            self.end, self.message = "edge-contact", "theta = 0: the other rim edge touches"
            event = lambda z: z[2] * side  # noqa: E731
        elif max(abs(v) for v in x[:2]) < 1e-10 and max(abs(v) for v in x[3:6]) < 1e-10:
            self.end, self.message = "at-rest", "came to rest: |omega|, |v_C| < 1e-10"
        if self.end is not None:
            if event is not None:  # locate it on the step's dense output
                self.ts[-1], self.xs[-1] = _locate(solver.dense_output(), event, t_old,
                                                   solver.t)
            self.status = "completed"
            self.message += f" at t = {self.ts[-1]:.6g} ({self.ts[-1] * self.toy.time_unit:.4g} s)"
            return True
        if self.n_short >= 50:
            self.message = f"step sizes collapsed (50 steps shorter than 1e-12 (1 + t)) at " \
                           f"t = {solver.t:.6g}: the model is too stiff here for rtol = " \
                           f"{self.rtol:g}"
            return True
        return False


def _result(run, window, predict):
    """The :class:`EulerDiskResult` of a finished :class:`_ToyRun` or
    :class:`_CoulombToyRun`: observables along the run, the energy balance, fitted and
    predicted exponents."""
    toy = run.toy
    h = toy.h
    t = np.array(run.ts)
    X = np.array(run.xs)
    XT = X.T  # (9, N): every recorded quantity in one element-wise call
    alpha, Omega, vp = _observables(h, XT)
    fz, us = run.forces(XT)
    E = _energy(h, XT)
    dissipated = {k: X[:, 6 + i] for i, k in enumerate(TERMS)}
    total = E + X[:, 6:].sum(axis=1)
    balance = float(np.max(np.abs(total - total[0])) / max(abs(total[0]), 1.0))
    t0, fitted = _fit_exponents(t, alpha, Omega, vp, window)
    predicted = (predicted_exponents(toy, window) if predict
                 else {k: math.nan for k in EXPONENT_NAMES})
    pred_end, pred_t0 = (predicted_end_time(toy, run.alpha_end) if predict
                         else (math.nan, math.nan))
    return EulerDiskResult(toy=toy, t=t, alpha=alpha, Omega=Omega, contact_speed=vp,
                           slip_speed=us, F_z=fz, E=E,
                           dissipated=dissipated, t_end=float(t[-1]), end=run.end,
                           status=run.status, message=run.message, t0=t0, exponents=fitted,
                           predicted=predicted, fit_window=window, predicted_t_end=pred_end,
                           predicted_t0=pred_t0, energy_balance=balance, n_steps=run.n,
                           wall_time=time.monotonic() - run.start,
                           extra={"state": X, **run.extra()})
