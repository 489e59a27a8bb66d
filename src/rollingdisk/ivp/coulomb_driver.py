"""The driver of one run on Coulomb ground (:func:`rollingdisk.ivp.hybrid.simulate_coulomb`):
DOP853 segments between mode events, scipy's or the compiled loop of
:mod:`rollingdisk.ivp.fastsegment`, the stored points, the budgets and the compile policy of
``method="auto"``.  The modes themselves are :mod:`rollingdisk.ivp.coulomb_modes`.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from rollingdisk.ivp import fastsegment as _fs
from rollingdisk.ivp.coulomb_modes import (
    _DOP853,
    _LSODA,
    _NAMES,
    DISSIPATION_TERMS,
    PIVOT_STUCK,
    ROLL_STUCK,
    ROLLING,
    SLIDING,
    STICK_TOL,
    U_EPS,
    W_EPS,
    _active,
    _DenseStep,
    _first_event,
    _inertial_omega_h,
    _inertial_slip,
    _message,
    _roll_turn,
    _Run,
    _Singular,
    _start_event,
    _start_sliding,
)
from rollingdisk.model import coulomb as _cl
from rollingdisk.model.coulomb import MODE_NAMES, coulomb_contact
from rollingdisk.results.trajectory import Trajectory, Transition


@dataclass(frozen=True, eq=False, repr=False)  # Trajectory's short repr, not every array
class CoulombTrajectory(Trajectory):
    """A :class:`~rollingdisk.Trajectory` on Coulomb ground (what :func:`simulate_coulomb`
    returns): the contact force at each stored point follows from that point's mode."""

    @cached_property
    def _F(self):
        rows = [coulomb_contact(self.disk, self.ground, MODE_NAMES[m], self.y[:, i])
                for i, m in enumerate(self.mode)]
        return tuple(np.array([r[k] for r in rows]) for k in ("F_x", "F_y", "F_z"))



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

    def add_block(self, ts, zs, m, mode):
        """:meth:`add` of the regular steps ``ts[:m], zs[:m]`` (copied), at once where no
        step would be skipped or thinned."""
        if self.stride == 1 and len(self.t) + m <= self.max_points:
            self._since = 0
            self._pending = None
            self.t.extend(ts[:m].tolist())
            self.z.extend(zs[:m].copy())
            self.mode.extend([mode] * m)
            self.pinned.extend([False] * m)
            return
        for i in range(m):
            self.add(float(ts[i]), zs[i], mode)

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
        self.run.sz = -1.0 if _cl.omega_z(y[5], y[8], y[9]) < 0.0 else 1.0
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
            z[2], z[3] = _cl.rolling_velocity(h, z)
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
        wz = _cl.omega_z(z[5], z[8], z[9])
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
            run.rref = _cl.to_inertial(self.z[4], -Lx / n, -Ly / n)
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
        except Exception as exc:  # noqa: BLE001 - numba broken: stay on the scipy path
            _compile_failed = True
            import warnings

            warnings.warn(f"the compiled Coulomb loop could not be built ({type(exc).__name__}: "
                          f"{str(exc).splitlines()[0] if str(exc) else ''}); Coulomb runs go on "
                          "on scipy's path, with the same steps but slower", RuntimeWarning,
                          stacklevel=2)
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
                      W_EPS, o.get("quasi_static_slip", 0.0),
                      0.0 if run.armed else run.floor, U_EPS], dtype=float)
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
                    min(o["max_steps"] - self.n_steps, CHUNK), active, ts, zs)
            self.n_steps += n
            run.n_rhs += n_rhs
            self.points.add_block(ts, zs, m, mode)
            run.ref = (float(p[6]), float(p[7]))
            run.rref = (float(p[12]), float(p[13]))
            self.t, self.z = float(t), y.copy()
            if active[0] and not run.armed and mode & 1 == SLIDING:
                run.armed, run.u_eps = True, U_EPS  # armed in the loop (as _arms does)
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
                run.rref = _cl.to_inertial(z[4], -Lx / n, -Ly / n)
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
            z[2], z[3] = _cl.rolling_velocity(self.h, z)  # u = 0 up to the event tolerance
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

