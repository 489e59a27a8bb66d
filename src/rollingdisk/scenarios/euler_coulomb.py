"""Euler's disk on set-valued Coulomb ground: the toy's run handed to
:func:`rollingdisk.simulate_coulomb` and read back in the reduced variables of the creep run.
"""

from __future__ import annotations

import math
import time

import numpy as np

from rollingdisk.model import coulomb as _cl
from rollingdisk.model.disk import Disk
from rollingdisk.scenarios.euler_kernels import _kicked_state
from rollingdisk.scenarios.euler_predict import predicted_end_time


class _CoulombToyRun:
    """One run of :func:`run_euler_disk` on Coulomb ground: :func:`rollingdisk.
    simulate_coulomb` from the toy's state, its trajectory in the reduced variables of
    :class:`_ToyRun` (``ts``, ``xs``; ``end``, ``status``, ``message``, ``n``)."""

    #: simulate_coulomb's statuses that are ends of the toy's run.
    ENDS = {"fell-flat": "fell-flat", "lift-off": "lift-off", "edge-contact": "edge-contact"}

    def __init__(self, toy, alpha_end, t_max, rtol, atol, kick):
        self.toy, self.alpha_end, self.t_max, self.rtol, self.atol = (toy, alpha_end, t_max,
                                                                      rtol, atol)
        self.start = time.monotonic()
        self.x0 = _kicked_state(toy, kick)
        self.end, self.status, self.message = None, "failed", ""
        self.n = 0
        self.traj = None
        self.ts, self.xs = [0.0], [self.x0.copy()]

    def ground(self):
        from rollingdisk.model.ground import Coulomb

        toy = self.toy
        return Coulomb(toy.mu, rolling_resistance=toy.rolling_resistance or None,
                       air=toy.c_air or None)

    def integrate(self, max_steps, max_wall_time, progress):
        from rollingdisk.ivp.hybrid import simulate_coulomb

        toy, x0 = self.toy, self.x0
        y0 = np.array([0.0, 0.0, x0[0], x0[1], 0.0, x0[2], 0.0, x0[3], x0[4], x0[5]])
        report = None
        if progress is not None:
            t_guess = max(predicted_end_time(toy, self.alpha_end)[0], 1.0)
            if not math.isfinite(t_guess):
                t_guess = self.t_max

            def report(fraction):  # fraction of (0, t_max) -> of the predicted end time
                progress(min(fraction * self.t_max / t_guess, 0.99))
        tr = simulate_coulomb(
            Disk(toy.h), self.ground(), (0.0, self.t_max), y0, rtol=self.rtol,
            atol=self.atol, max_steps=max_steps, max_transitions=max_steps,
            max_wall_time=max(max_wall_time - (time.monotonic() - self.start), 1e-3),
            max_points=COULOMB_POINTS, alpha_min=self.alpha_end, progress=report,
            quasi_static_slip=QUASI_STATIC_SLIP)
        self.traj, self.n = tr, tr.n_steps
        Y = tr.y
        cp, sp = np.cos(Y[4]), np.sin(Y[4])
        D = tr.dissipated
        self.ts = tr.t
        self.xs = np.column_stack([Y[2] * cp + Y[3] * sp, -Y[2] * sp + Y[3] * cp, Y[5],
                                   Y[7], Y[8], Y[9], D["slip"],
                                   D["rolling_resistance"] + D["pivot"], D["air"]])
        if tr.status in self.ENDS:
            self.end, self.status = self.ENDS[tr.status], "completed"
            self.message = tr.message
        elif tr.status == "completed":
            self.message = (f"reached t_max = {self.t_max:g} before any end (alpha = "
                            f"{math.pi / 2 - abs(Y[5, -1]):.3g})")
        else:
            self.message = tr.message
        if progress is not None and self.end is not None:
            progress(1.0)

    def forces(self, XT):
        """``(F_z, |u|)`` at the recorded points: the contact force of each point's mode."""
        tr = self.traj
        u_x, u_y = _cl.slip_velocity(self.toy.h, tr.y)
        return tr.F_z, np.hypot(u_x, u_y)

    def extra(self) -> dict:
        tr = self.traj
        return {"transitions": tr.transitions, "mode": tr.mode, "method": tr.method}


#: Most points :class:`_CoulombToyRun` stores (every k-th step beyond, and every
#: transition): a run through micro-slip takes millions of steps.
COULOMB_POINTS = 400_000


#: Slip speed (units sqrt(a g)) below which the friction takes the quasi-static slip direction
#: (``simulate_coulomb(quasi_static_slip=...)``, docs/friction.md).  0: the full set-valued
#: law.  1e-3 (below which the toy's micro-slip, 1e-8 to 2e-4, lies) runs the commercial toy
#: in 1.38 M steps instead of 75 M, but a low disk (alpha0 = 0.1, mu = 1, c = 0.01) does not
#: finish with it within 300 s: off until it is robust.
QUASI_STATIC_SLIP = 0.0
