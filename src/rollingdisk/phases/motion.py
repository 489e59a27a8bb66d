"""The whole motion to rest: contact, flight, impacts, rim changes and the flat disk.

Wires the pieces that each stop at a guard into one run (``docs/motion.md``):

* contact on a rim edge, rolling or sliding on Coulomb ground:
  :func:`rollingdisk.ivp.hybrid.simulate_coulomb`, until lift-off, edge contact or
  falling flat;
* free flight in closed form and the located touchdown
  (:func:`~rollingdisk.phases.flight.free_flight`,
  :func:`~rollingdisk.phases.flight.touchdown_time`);
* the Newton-Coulomb impact law at the touching rim point
  (:func:`~rollingdisk.phases.impact.impact`), also when an upright disk changes rim
  edge (``theta`` through 0, ``h > 0``);
* line contact when an upright disk stands on its tread (its rim changes accumulate, or
  it starts there): both rim edges down under set-valued Coulomb friction
  (:mod:`rollingdisk.phases.line_contact`), until rest or it tips onto one rim edge;
* a face impact when the disk falls flat, then the flat disk sliding and spinning on its
  face with Coulomb friction under uniform pressure until it stops.

Units m = a = g = 1.  Energy: ``E + dissipated + impact losses = const`` along the run.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence

import numpy as np

from rollingdisk.ivp.hybrid import simulate_coulomb, slip_direction
from rollingdisk.model import coulomb as _cl
from rollingdisk.model.coulomb import MODE_NAMES, coulomb_contact, coulomb_energy
from rollingdisk.model.disk import Disk
from rollingdisk.model.geometry import K2, inertia
from rollingdisk.model.ground import Coulomb
from rollingdisk.model.outcomes import outcome
from rollingdisk.phases.flat import flat_friction, flat_run
from rollingdisk.phases.flight import (
    _cross,
    _flight_one,
    _lowest_height,
    _r_xyz,
    _rot_x,
    _rot_z,
    _state_energy,
    lowest_point,
)
from rollingdisk.phases.impact import _impact
from rollingdisk.phases.line_contact import (
    capture_slips,
    free_from_line,
    line_energy,
    line_from_free,
    rests_on_rim,
    run_line_contact,
)
from rollingdisk.phases.records import (  # noqa: F401 - offered here too
    FlatSegment,
    FlightSegment,
    ImpactRecord,
    ModeChange,
    MotionResult,
)
from rollingdisk.phases.touchdown import Spent, touchdown
from rollingdisk.util.checks import check_int, check_real, check_span
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["simulate_to_rest", "MotionResult", "FlightSegment", "FlatSegment",
           "ModeChange", "ImpactRecord", "flat_friction", "PHASES", "GUARDS"]

#: Phases of a motion, as named in :attr:`MotionResult.transitions`.
PHASES = ("rolling", "sliding", "flight", "flat", "tread", "rest")
#: The guards of the contact phase that ``stop_at`` may name.
GUARDS = ("lift-off", "edge-contact", "fell-flat")



# ------------------------------------------------------------------- state helpers
def _kinetic(h, s):
    return _state_energy(h, s) - float(s[2])


def _free_from_contact(h, y, side):
    """Free state of a Coulomb state ``y`` touching with rim edge ``side`` (eq. 7 with
    ``h~ = side h``, whatever the sign of a ``theta`` near 0)."""
    X, Y, VX, VY, psi, theta, phi, w1, w2, w3 = y
    r = _r_xyz(h, theta, side, 1.0)
    return np.array([X, Y, -r[2], psi, theta, phi, VX, VY, -w1 * r[1], w1, w2, w3])


def _contact_from_free(s, side):
    """Coulomb state of a free state touching with rim edge ``side``; a ``theta`` of the
    wrong sign (rounding, at a rim change) becomes ``side * 1e-13``."""
    theta = s[4]
    if theta * side <= 0.0:
        theta = side * 1e-13
    return np.array([s[0], s[1], s[6], s[7], s[3], theta, s[5], s[9], s[10], s[11]])


def _edge_velocity(h, s, side):
    """Velocity of the lowest point of rim edge ``side`` in Cxyz, and its height."""
    psi, theta = s[3], s[4]
    r = _r_xyz(h, theta, side, 1.0 if math.cos(theta) >= 0.0 else -1.0)
    V = _rot_z(psi).T @ s[6:9]
    w = _rot_x(theta) @ s[9:12]
    return V + _cross(w, r), s[2] + r[2]


def _normalise_launch(s):
    """Angles on the branch ``cos theta >= 0``: ``(psi, theta, phi) ~ (psi + pi, pi - theta,
    phi + pi)`` with ``omega -> (-omega1, omega2, -omega3)`` (the frame turns by pi about
    eta)."""
    s = s.copy()
    if math.cos(s[4]) < 0.0:
        s[3] += math.pi
        s[4] = math.remainder(math.pi - s[4], 2.0 * math.pi)
        s[5] += math.pi
        s[9], s[11] = -s[9], -s[11]
    return s


def _rim_impact(h, s, side, e, mu):
    """:func:`~rollingdisk.phases.impact.impact` at rim edge ``side`` of the checked free
    state ``s`` (the run's own: the public function's checks of its arguments skipped)."""
    r = _r_xyz(h, s[4], side, 1.0 if math.cos(s[4]) >= 0.0 else -1.0)
    return _impact(h, s, r, e, e, mu, 1e-9)


def _face_impact(h, s):
    """Plastic, frictionless impact of the face: ``V_Z`` and the tilting rates vanish, the
    horizontal velocity and the angular momentum about the vertical through C are kept;
    the disk is laid exactly flat (``theta = +-pi/2``, ``Z_C = h``).  Returns the flat
    state, the vertical spin, the face (+1 eta up) and the energy lost."""
    theta = s[4]
    face = 1 if math.sin(theta) >= 0.0 else -1
    k1, _ = inertia(h)
    w1, w2, w3 = s[9:12]
    L_Z = k1 * w3 * math.cos(theta) + K2 * w2 * math.sin(theta)  # eta_Z = sin, zeta_Z = cos
    spin = L_Z / K2  # about +Z
    flat = s.copy()
    flat[2] = h
    flat[4] = face * 0.5 * math.pi
    flat[8] = 0.0
    flat[9], flat[10], flat[11] = 0.0, spin * face, 0.0  # omega2 along eta = face Z
    lost = _state_energy(h, s) - _state_energy(h, flat)
    return flat, spin, face, lost, -s[8]


# --------------------------------------------------------------------- the loop
def _check_inputs(disk, ground, t_span, y0, e, mu_impact, stop_at):
    if not isinstance(disk, Disk):
        raise ParameterTypeError(f"disk must be a rollingdisk.Disk, got {disk!r}")
    if not isinstance(ground, Coulomb):
        raise ParameterTypeError(f"ground must be a rollingdisk.Coulomb(...) value, got "
                                 f"{ground!r}")
    t0, t1 = check_span(t_span)
    e = check_real("e", e, low=0.0, high=1.0)
    mu = ground.mu_k if mu_impact is None else check_real("mu_impact", mu_impact, low=0.0)
    if isinstance(stop_at, str):
        stop_at = (stop_at,)
    for g in stop_at:
        if g not in GUARDS:
            raise ParameterError(f"stop_at must name guards among {GUARDS}, got {g!r}")
    try:
        y = np.asarray(y0, dtype=float)
    except (TypeError, ValueError):
        raise ParameterTypeError(f"y0 must be an array of real numbers, got {y0!r}") from None
    except OverflowError:  # an integer beyond floating-point range
        raise ParameterError("y0 must be a finite state: a component is beyond "
                             "floating-point range") from None
    if y.shape not in ((10,), (12,)) or not np.all(np.isfinite(y)):
        raise ParameterError("y0 must be a finite Coulomb state (10 components, touching) "
                             "or a free-body state (12 components, in flight), got shape "
                             f"{y.shape}")
    return t0, t1, e, mu, tuple(stop_at), y


def simulate_to_rest(disk: Disk, ground: Coulomb, t_span: Sequence[float], y0, *,
                     e: float = 0.5, mu_impact: float | None = None,
                     stop_at: Sequence[str] = (), max_segments: int = 20_000,
                     max_wall: float = 600.0, alpha_flat: float = 1e-3,
                     v_capture: float = 1e-3, zeno_count: int = 20,
                     zeno_window: float = 0.05, rest_energy: float = 1e-10,
                     rtol: float = 1e-10, atol: float = 1e-12, chunk: float = math.inf,
                     max_steps: int = 2_000_000, max_transitions: int = 10_000,
                     decide: Callable | None = None,
                     progress: Callable[[float], None] | None = None) -> MotionResult:
    """Run the disk through contact, flight, impacts and the flat phase, to rest.

    Parameters
    ----------
    disk : Disk
    ground : Coulomb
        Friction of the contact phases (``mu_s``, ``mu_k``, moments) and, with ``mu_k``,
        of the flat disk.
    t_span : (t0, t1)
        Time span [``sqrt(a/g)``], ``t1 > t0``.
    y0 : array_like, shape (10,) or (12,)
        A Coulomb state touching the plane (:data:`~rollingdisk.model.coulomb.COULOMB_STATE`)
        or a free-body state above it (:data:`~rollingdisk.phases.flight.FREE_STATE`).
    e : float
        Restitution of the impact law, ``[0, 1]`` (normal and tangential, Glocker).
    mu_impact : float, optional
        Friction of the impact law, ``>= 0``; default ``ground.mu_k``.
    stop_at : sequence of {"lift-off", "edge-contact", "fell-flat"}
        Guards that end the run as :func:`simulate_coulomb` would (the old statuses).
    max_segments : int
        Budget of segments (contact, flight, flat); beyond it: ``"step-budget"``.
    max_wall : float
        Budget of wall-clock seconds; beyond it: ``"time-budget"``.
    alpha_flat : float
        Tilt ``pi/2 - |theta|`` [rad] at which a disk on its rim counts as fallen flat
        (then a face impact); ``(0, 0.5]``.
    v_capture : float
        Zeno rule: an impact whose contact point would leave at a normal speed below
        ``v_capture`` [``sqrt(a g)``] is replaced by the plastic one (``e = 0``).
    zeno_count, zeno_window : int, float
        Zeno rule: after ``zeno_count`` impacts within ``zeno_window`` time units every
        further impact is plastic until a contact phase lasts longer than the window.
    rest_energy : float
        Kinetic energy [``m g a``] below which a disk upright on its tread (at a rim
        change, or at the end of a contact phase) enters line contact (which decides
        whether and when it rests).
    rtol, atol : float
        Tolerances of the contact phases.
    max_steps : int
        Step budget of one contact segment (:func:`simulate_coulomb`); beyond it the run
        ends ``"failed"``.
    max_transitions : int
        Budget of mode events of one contact segment (:func:`simulate_coulomb`; stick-slip
        chatter); beyond it the run ends ``"failed"``.
    chunk : float
        Longest contact segment [``sqrt(a/g)``] before ``decide`` is asked again.
    decide : callable, optional
        ``decide(E, free_state) -> str | None``, asked at every segment boundary; a
        string ends the run with status ``"completed"`` and that text in the message
        (:func:`toss` uses it for the energy trap).
    progress : callable, optional
        ``progress(fraction_of_time)``.

    Returns
    -------
    MotionResult

    Notes
    -----
    The rules (``docs/motion.md``): touchdown is located in closed form; the impact at a
    rim point follows Glocker's law; a contact phase starts when the post-impact contact
    point has no normal velocity (plastic, or captured by the Zeno rule) and the normal
    force needed is positive, else the disk flies.  At an edge contact (``theta`` through
    0, ``h > 0``) the other rim edge strikes: impact there, then each edge in turn while
    one approaches (at most 50 rounds).  At ``|theta| = pi/2 - alpha_flat`` the face
    strikes: plastic and frictionless (vertical velocity and tilting rates vanish, the
    horizontal velocity and the vertical angular momentum stay); then the flat disk
    slides and spins under uniform pressure (:func:`flat_friction`) until both stop.

    Examples
    --------
    >>> import rollingdisk as rd
    >>> s0 = [0, 0, 2.0, 0, 0.4, 0, 0, 0, 0, 0, 0, 0]  # tilted, dropped from rest
    >>> res = simulate_to_rest(rd.Disk(0.1), rd.Coulomb(0.5), (0, 200), s0, e=0.3)
    >>> res.status, res.energy_balance < 1e-9
    ('at-rest', True)
    """
    t0, t1, e, mu, stop_at, y = _check_inputs(disk, ground, t_span, y0, e, mu_impact,
                                              stop_at)
    max_segments = check_int("max_segments", max_segments, low=1)
    max_wall = check_real("max_wall", max_wall, low=0.0, low_open=True)
    alpha_flat = check_real("alpha_flat", alpha_flat, low=0.0, high=0.5, low_open=True)
    v_capture = check_real("v_capture", v_capture, low=0.0)
    zeno_count = check_int("zeno_count", zeno_count, low=2)
    zeno_window = check_real("zeno_window", zeno_window, low=0.0)
    rest_energy = check_real("rest_energy", rest_energy, low=0.0)
    chunk = check_real("chunk", chunk, low=0.0, low_open=True) if chunk != math.inf \
        else math.inf
    run = _Motion(disk, ground, t0, t1, e, mu, stop_at, max_segments, max_wall, alpha_flat,
                  v_capture, zeno_count, zeno_window, rest_energy, rtol, atol, chunk,
                  decide, progress)
    run.max_steps = check_int("max_steps", max_steps, low=1)
    run.max_transitions = check_int("max_transitions", max_transitions, low=1)
    return run.go(y)


class _Motion:
    """One run: the phase loop and its bookkeeping."""

    def __init__(self, disk, ground, t0, t1, e, mu, stop_at, max_segments, max_wall,
                 alpha_flat, v_capture, zeno_count, zeno_window, rest_energy, rtol, atol,
                 chunk, decide, progress):
        self.disk, self.h, self.ground = disk, disk.h, ground
        self.t0, self.t1, self.e, self.mu = t0, t1, e, mu
        self.stop_at, self.max_segments, self.max_wall = stop_at, max_segments, max_wall
        self.alpha_flat, self.v_capture = alpha_flat, v_capture
        self.zeno_count, self.zeno_window = zeno_count, zeno_window
        self.rest_energy, self.rtol, self.atol = rest_energy, rtol, atol
        self.chunk, self.decide, self.progress = chunk, decide, progress
        self.segments, self.transitions, self.impacts = [], [], []
        self.D = 0.0  # dissipated by friction and moments
        self.L = 0.0  # impact losses
        self.dev = 0.0
        self.phase = None
        self.impact_times: list[float] = []

    # -- bookkeeping -------------------------------------------------------------------
    def _check(self, E):
        self.dev = max(self.dev, float(np.max(np.abs(np.asarray(E) + self.D + self.L
                                                     - self.E0))))

    def _enter(self, t, phase):
        if phase != self.phase and self.phase is not None:
            self.transitions.append(ModeChange(float(t), self.phase, phase))
        self.phase = phase

    def _impact_record(self, t, kind, impulse, lost, e):
        self.impacts.append(ImpactRecord(float(t), kind, np.asarray(impulse, float),
                                         float(lost), float(e)))
        self.L += lost
        self.impact_times.append(float(t))

    def _zeno(self, t):
        n = self.zeno_count
        return len(self.impact_times) >= n and t - self.impact_times[-n] <= self.zeno_window

    def _result(self, status, message, t, s):
        scale = max(abs(self.E0), 1.0)
        if self.phase is not None and status == "at-rest":
            self._enter(t, "rest")
        self._check(_state_energy(self.h, s))
        return MotionResult(self.disk, self.ground, tuple(self.segments),
                            tuple(self.transitions), tuple(self.impacts), outcome(status).name,
                            message, float(t), np.asarray(s, float), self.dev / scale,
                            self.E0, self.D, self.L, time.perf_counter() - self.wall0)

    # -- the loop ----------------------------------------------------------------------
    def go(self, y):
        h = self.h
        self.wall0 = time.perf_counter()
        t = self.t0
        if y.shape == (12,):
            s = _normalise_launch(y)
            H = _lowest_height(h, s[2], s[4])
            if H < -1e-12:
                raise ParameterError(f"y0: the disk is inside the plane (lowest point at "
                                     f"Z = {H:.3g} < 0); a launch state needs Z_C >= "
                                     f"|cos theta| + h |sin theta|")
            self.E0 = _state_energy(h, s)
            upright = h > 0.0 and s[4] == 0.0 and s[2] == 1.0 and s[8] == 0.0 == s[9]
            nxt = ("line", s, None) if upright else ("flight", s, None)
        else:
            if not abs(y[5]) < 0.5 * math.pi:
                raise ParameterError(f"y0: theta must lie in (-pi/2, pi/2) on a rim edge, "
                                     f"got {y[5]!r}")
            side = 1 if y[5] >= 0.0 else -1
            s = _free_from_contact(h, y, side)
            self.E0 = float(coulomb_energy(self.disk, y))
            nxt = ("contact", s, side)
        n_seg = 0
        while True:
            kind, s, side = nxt
            if t >= self.t1:
                return self._result("completed", f"reached t = {t:.12g}", t, s)
            if n_seg >= self.max_segments:
                return self._result("step-budget", f"segment budget exhausted: "
                                    f"{self.max_segments} segments by t = {t:.12g}", t, s)
            if time.perf_counter() - self.wall0 > self.max_wall:
                return self._result("time-budget", f"wall-time budget exhausted: "
                                    f"{self.max_wall:g} s by t = {t:.12g}", t, s)
            if self.decide is not None:
                why = self.decide(_state_energy(h, s), s)
                if why:
                    return self._result("completed", f"decided at t = {t:.12g}: {why}", t, s)
            if self.progress is not None:
                self.progress(min(1.0, (t - self.t0) / (self.t1 - self.t0)))
            n_seg += 1
            if kind == "flight":
                out = self._flight(t, s)
            elif kind == "contact":
                out = self._contact(t, s, side)
            elif kind == "face":
                out = self._flat(t, s)
            elif kind == "line":
                out = self._line(t, s)
            else:  # pragma: no cover
                raise AssertionError(kind)
            if out[0] == "end":
                _, status, message, t, s = out
                return self._result(status, message, t, s)
            t, nxt = out[1], out[2:]

    # -- phases ------------------------------------------------------------------------
    def _after_impact(self, t, s, side):
        """Where a disk touching with rim edge ``side`` and no approaching edge goes."""
        h = self.h
        if 0.5 * math.pi - abs(s[4]) <= self.alpha_flat:
            return ("next", t, "face", s, side)
        gam, _ = _edge_velocity(h, s, side)
        if gam[2] > 1e-9 * max(1.0, float(np.linalg.norm(gam))):
            return ("next", t, "flight", s, None)
        return ("next", t, "contact", s, side)

    def _strike(self, t, s, side, kind):
        """Impacts at rim edge ``side``, then at whichever edge still approaches (an upright
        disk touches with both), at most 50 rounds.  Returns the state and the edge that
        keeps contact."""
        h = self.h
        for _ in range(50):
            e = 0.0 if self._zeno(t) else self.e
            res = _rim_impact(h, s, side, e, self.mu)
            if e > 0.0 and 0.0 < res.contact_velocity_post[2] < self.v_capture:
                e = 0.0
                res = _rim_impact(h, s, side, 0.0, self.mu)
            self._impact_record(t, kind, [*res.impulse_tangential, res.impulse_normal],
                                res.energy_lost, e)
            s = res.post_state
            other = -side
            gam_o, H_o = _edge_velocity(h, s, other)
            if h > 0.0 and H_o <= 1e-9 and gam_o[2] < -1e-12:
                side, kind = other, "rim-change"
                continue
            return s, side
        return s, side

    def _flight(self, t, s):
        h = self.h
        self._enter(t, "flight")
        s_start, t_skip = s, 0.0
        if _lowest_height(h, s[2], s[4]) <= 1e-9:  # leaving the plane: step clear of it
            for d in 10.0 ** np.arange(-7.0, -1.5, 0.5):
                sd = _flight_one(self.h, s, float(d))
                if _lowest_height(h, sd[2], sd[4]) > 1e-12:
                    s_start, t_skip = sd, float(d)
                    break
            else:
                return ("end", "failed", f"the disk neither stays on nor leaves the plane "
                        f"at t = {t:.12g}: F_z = 0 in contact but the free disk would sink "
                        "(Painleve's paradox of sliding with large friction; an impact "
                        "without collision, outside this model)", t, s)
        try:
            tau = t_skip + touchdown(self.disk, s_start, self.wall0 + self.max_wall)
        except Spent as spent:
            return ("end", "time-budget", f"wall-time budget exhausted: {self.max_wall:g} s "
                    f"by t = {t:.12g} (finding a flight's touchdown, at t + {spent})", t, s)
        t_hit = t + tau
        if t_hit >= self.t1:
            s1 = _flight_one(self.h, s, self.t1 - t)
            self.segments.append(FlightSegment(self.disk, t, self.t1, s, s1))
            self._check([_state_energy(h, s), _state_energy(h, s1)])
            return ("end", "completed", f"reached t = {self.t1:.12g} in flight", self.t1, s1)
        s1 = _flight_one(self.h, s_start, tau - t_skip)
        self.segments.append(FlightSegment(self.disk, t, t_hit, s, s1))
        self._check([_state_energy(h, s), _state_energy(h, s1)])
        lp = lowest_point(self.disk, s1, tol=1e-9)
        if lp.kind == "face" or 0.5 * math.pi - abs(s1[4]) <= self.alpha_flat:
            return ("next", t_hit, "face", s1, None)
        if lp.kind == "tread":
            g = {sd: _edge_velocity(h, s1, sd)[0][2] for sd in (1, -1)}
            side = min(g, key=g.get)
        else:
            side = lp.side
        s2, side = self._strike(t_hit, s1, side, "rim")
        return self._after_impact(t_hit, s2, side)

    def _contact(self, t, s, side):
        h = self.h
        y = _contact_from_free(s, side)
        if _kinetic(h, s) <= self.rest_energy and h > 0.0 and abs(s[4]) < 1e-6:
            return self._line(t, s)
        if self._start_force(s, side, y) <= 0.0 and self._separates(s):
            # the plane cannot hold it: it flies off at zero normal velocity
            if "lift-off" in self.stop_at:
                return ("end", "lift-off", f"lift-off at t = {t:.12g}: F_z <= 0 at the "
                        "start of a contact phase", t, s)
            return ("next", t, "flight", s, None)
        t_stop = min(self.t1, t + self.chunk)
        tr = simulate_coulomb(self.disk, self.ground, (t, t_stop), y, rtol=self.rtol,
                              atol=self.atol, slip_tol=1e-9, alpha_min=self.alpha_flat,
                              max_steps=self.max_steps,
                              max_transitions=self.max_transitions,
                              # the run's wall budget, what is left
                              max_wall_time=max(1e-3, self.max_wall
                                                - (time.perf_counter() - self.wall0)))
        self.segments.append(tr)
        self._enter(t, MODE_NAMES[int(tr.mode[0])])  # pivot-stuck sub-modes included
        for tx in tr.transitions:
            self._enter(tx.t, tx.to_mode)
        self._check(tr.E + sum(tr.dissipated.values()))
        self.D += float(sum(v[-1] for v in tr.dissipated.values()))
        t = float(tr.t[-1])
        yend = np.array(tr.y[:, -1])
        s = _free_from_contact(h, yend, side)
        if tr.status in self.stop_at:
            return ("end", tr.status, tr.message, t, s)
        if tr.status in ("completed", "time-budget", "step-budget"):
            held = rests_on_rim(tr)
            if held is not None:
                k = held
                s = _free_from_contact(h, np.array(tr.y[:, k]), side)
                s[6:12] = 0.0
                return ("end", "at-rest", f"at rest on rim edge {side:+d} at t = "
                        f"{tr.t[k]:.12g}, held by rolling resistance", float(tr.t[k]), s)
        if tr.status == "completed":
            if h > 0.0 and abs(s[4]) < 1e-6 and _kinetic(h, s) <= self.rest_energy:
                return self._line(t, s)
            if t >= self.t1:
                return ("end", "completed", tr.message, t, s)
            return ("next", t, "contact", s, side)
        if tr.status == "lift-off":
            return ("next", t, "flight", s, None)
        if tr.status == "fell-flat":
            return ("next", t, "face", s, None)
        if tr.status == "edge-contact":
            if _kinetic(h, s) <= self.rest_energy or self._rim_changes_accumulate(t):
                return self._line(t, s)
            s2, side2 = self._strike(t, s, -side, "rim-change")
            return self._after_impact(t, s2, side2)
        return ("end", tr.status, tr.message, t, s)

    def _start_force(self, s, side, y):
        """``F_z`` in the mode :func:`simulate_coulomb` starts in at ``y``: rolling if the
        slip is zero and rolling's friction lies in the cone, else sliding (in the solved
        slip direction when the slip is zero)."""
        h, g = self.h, self.ground
        slip, _ = _edge_velocity(h, s, side)
        U = math.hypot(slip[0], slip[1])
        if U <= 1e-9 * (1.0 + math.hypot(s[6], s[7])):
            c = coulomb_contact(self.disk, g, "rolling", y)
            if c["F_t"] <= g.mu_s * c["F_z"]:
                return c["F_z"]
            d = slip_direction(self.disk, g, y)
            if d is None:
                return c["F_z"]
            ref = _cl.to_inertial(y[4], d[0], d[1])
        else:
            ref = _cl.to_inertial(y[4], slip[0] / U, slip[1] / U)
        return _cl.coulomb_sliding(h, g.mu_k, *g.coefficients, y, ref[0], ref[1])[3]

    def _separates(self, s):
        """Whether the free disk leaves the plane within 1e-2 (its lowest point rises)."""
        h = self.h
        for d in (1e-4, 1e-3, 1e-2):
            sd = _flight_one(self.h, s, float(d))
            if _lowest_height(h, sd[2], sd[4]) > 1e-12:
                return True
        return False

    def _rim_changes_accumulate(self, t):
        """Zeno rule of the rim changes: the last ``zeno_count`` impacts were all rim changes
        within ``zeno_window`` (the rocking has died out, or the disk rolls upright on its
        tread and its contact jumps from edge to edge at one instant)."""
        n = self.zeno_count
        last = self.impacts[-n:]
        return (len(last) == n and all(x.kind == "rim-change" for x in last)
                and t - last[0].t <= self.zeno_window)

    def _line(self, t, s):
        """Line contact (:func:`run_line_contact`) until rest, tipping onto a rim edge,
        ``chunk`` or the end.  Entered from rocking, the state is projected onto the line
        (the limit of the accumulating rim changes, their friction neglected: an impact
        ``"tread"``), then slips below ``v_capture`` stop (:func:`capture_slips`)."""
        h = self.h
        s1 = free_from_line(line_from_free(s))
        if s[4] != 0.0 or s[2] != 1.0 or s[8] != 0.0 or s[9] != 0.0:
            lost = _state_energy(h, s) - _state_energy(h, s1)
            self._impact_record(t, "tread", np.array([0.0, 0.0, -s[8]]), lost, 0.0)
            s1, P, lost = capture_slips(h, s1, self.mu, self.v_capture)
            if lost != 0.0 or P[2] != 0.0:
                self._impact_record(t, "tread-slip", P, lost, 0.0)
        self._enter(t, "tread")
        t_stop = min(self.t1, t + self.chunk)
        segs, out = run_line_contact(h, self.ground, t, t_stop, s1, rtol=self.rtol,
                                     atol=self.atol)
        for g in segs:
            self.segments.append(g)
            self._check(line_energy(h, g.states) + g.states[8])
        self.D += out.dissipated
        t2, s2 = out.t, out.state
        if out.status == "rest":
            return ("end", "at-rest", out.message, t2, s2)
        if out.status == "rocking":
            return ("next", t2, "contact", s2, out.side)
        if out.status == "failed":
            return ("end", "failed", out.message, t2, s2)
        if t2 >= self.t1:
            return ("end", "completed", f"reached t = {t2:.12g} on the tread", t2, s2)
        return ("next", t2, "line", s2, None)

    def _flat(self, t, s):
        h = self.h
        flat, spin, face, lost, dVz = _face_impact(h, s)
        self._impact_record(t, "face", np.array([0.0, 0.0, dVz]), lost, 0.0)
        self._check(_state_energy(h, flat))
        if "fell-flat" in self.stop_at:
            return ("end", "fell-flat", f"fell flat at t = {t:.12g}", t, s)
        self._enter(t, "flat")
        V = math.hypot(flat[6], flat[7])
        d = (flat[6] / V, flat[7] / V) if V > 0.0 else (1.0, 0.0)
        ts, Vs, Ws, Ds, dist, ang = flat_run(self.ground.mu_k, V, abs(spin), t, self.t1)
        end = flat.copy()
        end[0] += d[0] * dist
        end[1] += d[1] * dist
        sg = 1.0 if spin >= 0.0 else -1.0
        end[3] += sg * ang  # the angle about the vertical turns with the spin
        end[6], end[7] = d[0] * Vs[-1], d[1] * Vs[-1]
        end[10] = sg * Ws[-1] * face
        seg = FlatSegment(ts, Vs, Ws, Ds, flat, end, face)
        self.segments.append(seg)
        self._check(h + 0.5 * Vs ** 2 + 0.5 * K2 * Ws ** 2 + Ds)
        self.D += float(Ds[-1])
        if Vs[-1] == 0.0 and Ws[-1] == 0.0:
            return ("end", "at-rest", f"at rest flat ({'eta up' if face > 0 else 'eta down'})"
                    f" at t = {ts[-1]:.12g}", float(ts[-1]), end)
        return ("end", "completed", f"reached t = {self.t1:.12g} lying flat, still moving",
                float(ts[-1]), end)
