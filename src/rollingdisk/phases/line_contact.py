"""Line contact: the upright disk on its tread line, under set-valued Coulomb friction.

The disk stands upright (``theta = 0``, ``h > 0``) on its tread line.  The line carries its
load at its two ends, the lowest points of the two rim edges ("corners", ``s = +1, -1``, at
``r_s = (0, -s h, -1)`` in Cxyz): a unilateral normal force ``lambda_s >= 0`` and Coulomb
friction ``F_s`` each, ``|F_s| <= mu_s lambda_s`` while corner ``s`` sticks, ``F_s = -mu_k
lambda_s u_s/|u_s|`` while it slips with ``u_s = (v_x - omega2 + s h omega3, v_y)``; besides,
the ground's contact moments (rolling resistance ``M_y = -c_roll sgn(omega2)``, set-valued at
``omega2 = 0``; pivot ``M_z = -c_pivot sgn(omega3)``; air ``M_z = -c_air omega3``).  The
equations, derived in :mod:`rollingdisk.symbolic.line_contact` (Newton-Euler, checked against
Lagrange's equations), in Cxyz turning with ``psi``, ``m = a = g = 1``:

    d v_x/dt = F_x + omega3 v_y,  d v_y/dt = F_y - omega3 v_x,
    k2^2 d omega2/dt = -F_x + M_y,  k1^2 d omega3/dt = h (F_+x - F_-x) + M_z,
    lambda_+ = (h + G)/(2h),  lambda_- = (h - G)/(2h),  G = k2^2 omega2 omega3 + F_y + M_x,

with ``F = F_+ + F_-``.  ``lambda_+ + lambda_- = 1`` always, so the line is never left into
flight; it is left onto corner ``s`` (rocking) where ``lambda_-s`` reaches 0.

Sub-phases (``mode``): both corners slide (:data:`SLIDE`); corner + or - sticks, the other
slides (:data:`STICK_P`, :data:`STICK_M`; the sliding corner's slip is ``(+-2h omega3, 0)``,
so it stops where the spin stops); both stick (:data:`ROLL`: straight rolling, ``omega3 =
v_y = 0``, ``d omega2/dt = M_y/(1 + k2^2)``); bit :data:`ROLL_STUCK`: rolling resistance
holding ``omega2 = 0`` (``|M_y| <= c_roll``).  Each transition is an event of the
integration: a slip reaching 0, a sticking force reaching the cone, ``omega3 = 0``,
``omega2 = 0``, the holding moment reaching ``c_roll``, a ``lambda_s`` reaching 0.

The right-hand side :func:`line_rhs` and the events are plain functions of ``(t, y,
params)``, ``params`` the float array of :func:`line_params`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rollingdisk.model.geometry import inertia
from rollingdisk.phases.line_kernel import kernels as _kernels

__all__ = ["LINE_STATE", "SLIDE", "STICK_P", "STICK_M", "ROLL", "ROLL_STUCK", "MODE_NAMES",
           "line_params", "line_forces", "line_rhs", "line_energy", "line_from_free",
           "free_from_line", "capture_slips", "rests_on_rim", "LineSegment", "LineOutcome",
           "run_line_contact"]

#: State of line contact: centre on the plane, angles, velocity of C in Cxyz, spins, and the
#: energy dissipated since the phase began.
LINE_STATE = ("X_C", "Y_C", "psi", "phi", "v_x", "v_y", "omega2", "omega3", "dissipated")
SLIDE, STICK_P, STICK_M, ROLL = 0, 1, 2, 3
ROLL_STUCK = 4
#: Names of the sub-phases, by mode code (``mode & 3``).
MODE_NAMES = ("tread, sliding", "tread, pivoting on corner +", "tread, pivoting on corner -",
              "tread, rolling")

# params: h, k1^2, k2^2, mu_s, mu_k, c_roll, c_pivot, c_air, mode, d_px, d_py, d_mx, d_my,
#         roll sign (M_y = -c_roll * this while not stuck), slip floor
_H, _K1, _K2, _MUS, _MUK, _CR, _CP, _CA, _MODE, _DP, _DM, _RS, _FLOOR = (
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 13, 14)


def line_params(h, mu_s, mu_k, c_roll=0.0, c_pivot=0.0, c_air=0.0, mode=SLIDE,
                d_p=(0.0, 0.0), d_m=(0.0, 0.0), roll_sign=0.0, floor=1e-9):
    """The float array ``params`` of :func:`line_rhs`: disk (``h``, eq. 10), friction,
    mode, the seeded slip directions used while a slip is below ``floor`` (it has just
    started from rest), the sign of ``omega2`` rolling resistance opposes below it."""
    k1, k2 = inertia(h)
    return np.array([h, k1, k2, mu_s, mu_k, c_roll, c_pivot, c_air, float(mode),
                     d_p[0], d_p[1], d_m[0], d_m[1], roll_sign, floor])


def _slips(h, y):
    vx, vy, w2, w3 = y[4], y[5], y[6], y[7]
    return (vx - w2 + h * w3, vy), (vx - w2 - h * w3, vy)


def _direction(u, seed, floor):
    """Unit slip direction; a seeded corner (``seed != 0``: it has just started to slip
    from rest) keeps its seed until its slip passes ``_START * floor``."""
    n = math.hypot(u[0], u[1])
    if (seed[0] != 0.0 or seed[1] != 0.0) and n <= _START * floor:
        return seed
    return (u[0] / n, u[1] / n) if n > 0.0 else (0.0, 0.0)


def line_forces(y, p):
    """Solve the mode's linear system at state ``y``
    (:func:`rollingdisk.phases.line_kernel.line_system`, compiled where the process runs
    compiled code).

    Returns
    -------
    (acc, lam_p, lam_m, F_p, F_m, M) : (ndarray(4), float, float, ndarray(2), ndarray(2),
    ndarray(3))
        ``(d v_x/dt, d v_y/dt, d omega2/dt, d omega3/dt)``, the normal forces, the corner
        friction forces (Cxyz) and the contact moment.
    """
    f = _kernels()["line_system"](y, p)
    return f[:4], f[4], f[5], f[6:8], f[8:10], np.array([0.0, f[10], f[11]])


def line_rhs(t, y, p):
    """``dy/dt`` of :data:`LINE_STATE` in the mode of ``p`` (plain function of ``(t, y,
    params)``); the last component is the dissipated power ``-(sum F_s . u_s + omega . M)``
    (:func:`rollingdisk.phases.line_kernel.line_rhs_kernel`)."""
    return _kernels()["line_rhs_kernel"](y, p)


def line_energy(h, y):
    """Energy of a line state [``m g a``]: ``(v_x^2 + v_y^2)/2 + k2^2 omega2^2/2 + k1^2
    omega3^2/2 + 1`` (eq. 13 at ``theta = 0``, ``Z_C = 1``)."""
    k1, _ = inertia(h)
    y = np.asarray(y, float)
    return 0.5 * (y[4] ** 2 + y[5] ** 2) + 0.25 * y[6] ** 2 + 0.5 * k1 * y[7] ** 2 + 1.0


def line_from_free(s):
    """Line state (dissipated 0) of a free-body state, dropping ``theta, Z_C - 1, V_Z,
    omega1`` (the projection onto the line)."""
    c, sn = math.cos(s[3]), math.sin(s[3])
    return np.array([s[0], s[1], s[3], s[5], s[6] * c + s[7] * sn, -s[6] * sn + s[7] * c,
                     s[10], s[11], 0.0])


def free_from_line(y):
    """Free-body state (12) of a line state."""
    c, sn = math.cos(y[2]), math.sin(y[2])
    return np.array([y[0], y[1], 1.0, y[2], 0.0, y[3], y[4] * c - y[5] * sn,
                     y[4] * sn + y[5] * c, 0.0, 0.0, y[6], y[7]])


def capture_slips(h, s, mu, v_capture):
    """Zeno rule of the tread: corner slips below ``v_capture`` stop at once.

    Parameters
    ----------
    h : float
    s : ndarray, shape (12,)
        Free-body state on the line (``theta = 0``, ``Z_C = 1``, ``V_Z = omega1 = 0``).
    mu : float
        Friction coefficient; 0 captures nothing.
    v_capture : float
        Slip speed [``sqrt(a g)``] at or below which a corner's slip is captured.

    Returns
    -------
    (state, impulse, lost) : (ndarray(12), ndarray(3), float)
        The state with the captured corners sticking (both: rolling straight, ``omega3 =
        v_y = 0``, ``v_x = omega2``); ``(P_x, P_y, N)`` with ``P`` the tangential impulse of
        the corners in OXYZ and ``N = sum_s |P_s|/mu`` the normal impulse the line gives
        while Coulomb friction ``mu lambda_s`` stops each slip (over ``|P_s|/(mu
        lambda_s)``, a time neglected like the rocking residue); the energy lost ``>= 0``.

    Notes
    -----
    Impulses ``P_s`` at the corners change ``v`` by ``sum P_s``, ``k2^2 omega2`` by ``-sum
    P_sx`` and ``k1^2 omega3`` by ``h (P_+x - P_-x)`` (the balances of
    :func:`rollingdisk.symbolic.line_contact.newton_euler`); their moment about ``x``, ``sum
    P_sy``, is taken up by the line with the residual rocking.  One corner ``s``: ``P_sx =
    -u_sx/(1 + 1/k2^2 + h^2/k1^2)``, ``P_sy = -v_y``; both: ``P_+x + P_-x = (omega2 -
    v_x) k2^2/(1 + k2^2)``, ``P_+x - P_-x = -k1^2 omega3/h``, ``P_sy = -v_y/2``.
    """
    y = line_from_free(s)
    k1, k2 = inertia(h)
    u_p, u_m = _slips(h, y)
    cap = [mu > 0.0 and math.hypot(*u) <= v_capture for u in (u_p, u_m)]
    P = np.zeros((2, 2))  # rows: corner +, corner -
    if cap[0] and cap[1]:
        sx = (y[6] - y[4]) * k2 / (1.0 + k2)
        dx = -k1 * y[7] / h
        P[0] = 0.5 * (sx + dx), -0.5 * y[5]
        P[1] = 0.5 * (sx - dx), -0.5 * y[5]
    elif cap[0] or cap[1]:
        i = 0 if cap[0] else 1
        u = (u_p, u_m)[i]
        P[i] = -u[0] / (1.0 + 1.0 / k2 + h * h / k1), -y[5]
    else:
        return s, np.zeros(3), 0.0
    z = y.copy()
    z[4] += P[0, 0] + P[1, 0]
    z[5] += P[0, 1] + P[1, 1]
    z[6] -= (P[0, 0] + P[1, 0]) / k2
    z[7] += h * (P[0, 0] - P[1, 0]) / k1
    if cap[0] and cap[1]:  # exactly rolling (rounding)
        z[5], z[7], z[4] = 0.0, 0.0, z[6]
    lost = line_energy(h, y) - line_energy(h, z)
    c, sn = math.cos(y[2]), math.sin(y[2])
    Px, Py = P[:, 0].sum(), P[:, 1].sum()
    N = float(np.hypot(P[:, 0], P[:, 1]).sum()) / mu
    return free_from_line(z), np.array([Px * c - Py * sn, Px * sn + Py * c, N]), lost


@dataclass(frozen=True, eq=False)
class LineSegment:
    """The disk upright on its tread line, from ``t[0]`` to ``t[-1]``.

    Attributes
    ----------
    t : ndarray
        Times [``sqrt(a/g)``].
    states : ndarray, shape (9, n)
        Line states (:data:`LINE_STATE`); the last row the energy dissipated since the
        segment began [``m g a``].
    mode : ndarray of int
        Sub-phase code at each time (:data:`MODE_NAMES` of ``mode & 3``).
    normal : ndarray, shape (2, n)
        ``lambda_+, lambda_-`` [``m g``].
    friction : ndarray, shape (2, n)
        ``|F_+|, |F_-|`` [``m g``].
    """

    t: np.ndarray
    states: np.ndarray
    mode: np.ndarray
    normal: np.ndarray
    friction: np.ndarray

    def state(self, t):
        """Free-body state(s) at time(s) ``t`` (linear interpolation of the stored points),
        shape ``(12,)`` or ``(12, n)``."""
        tt = np.atleast_1d(np.asarray(t, float))
        Y = np.array([np.interp(tt, self.t, self.states[i]) for i in range(8)])
        out = np.array([free_from_line(Y[:, j]) for j in range(tt.size)]).T
        return out[:, 0] if np.ndim(t) == 0 else out

    def __repr__(self) -> str:
        return (f"LineSegment(t=[{self.t[0]:.6g}, {self.t[-1]:.6g}], "
                f"dissipated={self.states[8, -1]:.4g})")


# ------------------------------------------------------------------------- modes
_SMALL = 1.5  # a slip at or below _SMALL * floor counts as zero; a seeded slip is armed
_START = 2.0  # once it passes _START * floor, a slip is stopped again at floor (hysteresis)


def _choose(h, ground, y, floor, exclude=(), no_stuck=False):
    """The sub-phase consistent with Coulomb's law at ``y`` (slips at or below ``1.5
    floor`` count as zero; modes in ``exclude`` were just left at the cone): ``(params,
    rest)``.  A corner forced to slide from rest slides against the force that held it."""
    mu_s, mu_k = ground.mu_s, ground.mu_k
    c_r, c_p, c_a = ground.coefficients
    u_p, u_m = _slips(h, y)
    small_p = math.hypot(*u_p) <= _SMALL * floor
    small_m = math.hypot(*u_m) <= _SMALL * floor

    def mk(mode, d_p=(0.0, 0.0), d_m=(0.0, 0.0), rs=0.0):
        return line_params(h, mu_s, mu_k, c_r, c_p, c_a, mode, d_p, d_m, rs, floor)

    def seed(F):
        n = math.hypot(*F)
        return (-F[0] / n, -F[1] / n) if n > 0.0 else (1.0, 0.0)

    cands = []
    if small_p and small_m:
        cands = [ROLL, STICK_P, STICK_M]
    elif small_p:
        cands = [STICK_P]
    elif small_m:
        cands = [STICK_M]
    d_p = d_m = (0.0, 0.0)
    mode = SLIDE
    for i, m in enumerate(cands):
        _, lp, lm, Fp, Fm, _ = line_forces(y, mk(m, d_p, d_m))
        if i == 0:
            d_p, d_m = seed(Fp), seed(Fm)
        if m in exclude:
            continue
        ok_p = m not in (ROLL, STICK_P) or math.hypot(*Fp) <= mu_s * lp
        ok_m = m not in (ROLL, STICK_M) or math.hypot(*Fm) <= mu_s * lm
        if ok_p and ok_m:
            mode = m
            break
    if not (small_p and mode not in (ROLL, STICK_P)):
        d_p = (0.0, 0.0)
    if not (small_m and mode not in (ROLL, STICK_M)):
        d_m = (0.0, 0.0)
    p = mk(mode, d_p, d_m)
    # rolling resistance: stuck at omega2 = 0 while the holding moment stays within c_roll
    if c_r > 0.0 and abs(y[6]) <= floor:
        ps = mk(mode | ROLL_STUCK, d_p, d_m)
        M = line_forces(y, ps)[5]
        if abs(M[1]) <= c_r and not no_stuck:
            p = ps
        elif M[1] != 0.0:  # it turns against the excess: M_y = c_roll sgn(M_hold)
            p = mk(mode, d_p, d_m, rs=-math.copysign(1.0, M[1]))
    rest = (mode == ROLL and (bool(int(p[_MODE]) & ROLL_STUCK) or c_r == 0.0)
            and abs(y[6]) <= floor)
    return p, rest


def _events(h, p, y0):
    """Event functions of the mode in ``p`` (each with ``terminal``, ``direction``,
    ``name``)."""
    mode = int(p[_MODE])
    base, stuck = mode & 3, bool(mode & ROLL_STUCK)
    floor = p[_FLOOR]
    ev = []

    def add(f, direction, name):
        f.terminal, f.direction, f.name = True, direction, name
        ev.append(f)

    add(lambda t, y, *_: line_forces(y, p)[1], -1, "lambda_+ = 0")
    add(lambda t, y, *_: line_forces(y, p)[2], -1, "lambda_- = 0")
    u0 = _slips(h, y0)
    if base == SLIDE:
        for i, nm in ((0, "+"), (1, "-")):
            if math.hypot(*u0[i]) > _SMALL * floor:
                def g(t, y, *_, i=i):
                    return math.hypot(*_slips(h, y)[i]) - floor
                add(g, -1, f"slip {nm} stops")
            else:
                def g(t, y, *_, i=i):
                    return math.hypot(*_slips(h, y)[i]) - _START * floor
                add(g, 1, f"slip {nm} starts")
    if base in (STICK_P, STICK_M):
        j = 0 if base == STICK_P else 1

        def cone(t, y, *_):
            f = line_forces(y, p)
            return p[_MUS] * f[1 + j] - math.hypot(*f[3 + j])
        add(cone, -1, "cone")
        add(lambda t, y, *_: y[7], 0, "spin stops")
    if base == ROLL:
        def cone2(t, y, *_):
            f = line_forces(y, p)
            return min(p[_MUS] * f[1] - math.hypot(*f[3]),
                       p[_MUS] * f[2] - math.hypot(*f[4]))
        add(cone2, -1, "cone")
    if stuck:
        add(lambda t, y, *_: p[_CR] - abs(line_forces(y, p)[5][1]), -1, "roll lets go")
    elif p[_CR] > 0.0 and abs(y0[6]) > floor:
        add(lambda t, y, *_: y[6], 0, "rolling stops")
    return ev


@dataclass
class LineOutcome:
    """How a line-contact run ended.

    Attributes
    ----------
    status : {"rest", "rocking", "end", "failed"}
    t : float
    state : ndarray, shape (12,)
        Free-body state at ``t``.
    side : int
        The rim edge it tips onto (``"rocking"``), else 0.
    message : str
    dissipated : float
        Energy dissipated on the line [``m g a``] (friction, moments).
    """

    status: str
    t: float
    state: np.ndarray
    side: int
    message: str
    dissipated: float


class _Budget(Exception):
    pass


def run_line_contact(h, ground, t0, t1, s, *, rtol=1e-10, atol=1e-12, slip_tol=1e-9,
                     max_events=10_000, max_rhs=200_000):
    """Integrate line contact from the free state ``s`` (upright, touching along the
    tread) until rest, rocking onto a rim edge, or ``t1``.

    Parameters
    ----------
    h : float
        Half-thickness [``a``], ``> 0``.
    ground : Coulomb
        ``mu_s`` (sticking), ``mu_k`` (sliding), rolling resistance, pivot, air.
    t0, t1 : float
        Time span [``sqrt(a/g)``].
    s : ndarray, shape (12,)
        Free-body state; ``theta``, ``Z_C - 1``, ``V_Z`` and ``omega1`` are taken as 0.
    rtol, atol : float
        Tolerances of the integration (scipy's DOP853).
    slip_tol : float
        Slip (relative to ``1 + |v| + |omega|`` at the start) at or below which a corner
        counts as sticking, and spin ``|omega2|`` below which rolling resistance may hold.
    max_events, max_rhs : int
        Budgets of sub-phase changes and of right-hand-side evaluations; beyond either
        ``"failed"`` (a known stall: a slip crossing zero sideways while spinning).

    Returns
    -------
    (segments, outcome) : (list of LineSegment, LineOutcome)
        ``outcome.status``: ``"rest"`` (both corners sticking, ``omega2`` held: every
        velocity zero to ``slip_tol``), ``"rocking"`` (a ``lambda_s`` reached 0),
        ``"end"`` (``t1``) or ``"failed"``.
    """
    from scipy.integrate import solve_ivp

    from rollingdisk.ivp import fastsegment
    from rollingdisk.phases import line_kernel

    if fastsegment.loaded() and not line_kernel.loaded():
        line_kernel.load_compiled()  # the process runs compiled code: this phase too
    y = line_from_free(s)
    t = t0
    segs = []
    n_ev = 0
    floor = slip_tol * (1.0 + math.hypot(y[4], y[5]) + abs(y[6]) + abs(y[7]))
    exclude, no_stuck = (), False
    n_rhs = [0]

    def rhs(t_, y_, p_):
        n_rhs[0] += 1
        if n_rhs[0] > max_rhs:
            raise _Budget
        return line_rhs(t_, y_, p_)

    def out(status, msg, side=0):
        return segs, LineOutcome(status, t, free_from_line(y), side, msg, float(y[8]))

    while True:
        try:
            p, rest = _choose(h, ground, y, floor, exclude, no_stuck)
        except np.linalg.LinAlgError:
            return out("failed", f"line contact: no contact forces at t = {t:.12g} "
                       "(Painleve's paradox of the sliding corners)")
        exclude, no_stuck = (), False
        if rest:
            segs.append(_segment([t], y[:, None].copy(), p))
            y = _snap(h, y, (4, 5, 6, 7))
            return out("rest", f"at rest upright on the tread at t = {t:.12g}")
        lam = line_forces(y, p)[1:3]
        if min(lam) < 0.0:  # the line cannot hold it: it tips onto the loaded corner
            side = 1 if lam[1] < lam[0] else -1
            return out("rocking", f"tips onto rim edge {side:+d} at t = {t:.12g} "
                       f"(lambda_{'-' if side > 0 else '+'} = {min(lam):.3g} < 0)", side)
        if t >= t1:
            return out("end", f"reached t = {t:.12g} on the tread")
        ev = _events(h, p, y)
        try:
            sol = solve_ivp(rhs, (t, t1), y, method="DOP853", rtol=rtol, atol=atol,
                            events=ev, args=(p,))
        except _Budget:
            return out("failed", f"line contact: {max_rhs} right-hand-side evaluations "
                       f"by t = {t:.12g} (the integration stalls)")
        except np.linalg.LinAlgError:
            return out("failed", f"line contact: no contact forces after t = {t:.12g} "
                       "(Painleve's paradox of the sliding corners)")
        if sol.status == -1:
            return out("failed", f"line contact: {sol.message} at t = {t:.12g}")
        segs.append(_segment(sol.t, sol.y, p))
        y = sol.y[:, -1].copy()
        t = float(sol.t[-1])
        if sol.status == 0:
            continue  # reached t1: reported at the top of the loop
        k = next(i for i, te in enumerate(sol.t_events) if te.size)
        name = ev[k].name
        n_ev += 1
        if name.startswith("lambda"):
            side = -1 if name == "lambda_+ = 0" else 1  # the corner still loaded
            return out("rocking", f"tips onto rim edge {side:+d} at t = {t:.12g} ({name})",
                       side)
        if n_ev >= max_events:
            return out("failed", f"line contact: {max_events} sub-phase changes by "
                       f"t = {t:.12g} (stick-slip chatter)")
        if name == "cone":
            exclude = (int(p[_MODE]) & 3,)
        elif name == "roll lets go":
            no_stuck = True
        elif name == "spin stops":
            y = _snap(h, y, (7,))  # the sliding corner's slip is exactly 2h |omega3|
            # at the stop the sliding corner's friction is set-valued: the next sub-phase,
            # chosen by the set-valued law, stores this instant; the single-valued formula
            # of the pivoting one, evaluated at zero slip, would not (it can leave the cone)
            _drop_last(segs)
        elif name == "rolling stops":
            y = _snap(h, y, (6,))


def rests_on_rim(tr):
    """Index of the point of a rim-edge contact segment ``tr``
    (:func:`rollingdisk.simulate_coulomb`) from which the disk rests there to its end:
    rolling with the rolling resistance stuck (mode bits ``& 5 == 4``) and every velocity
    zero to 1e-12, so that the stuck moment (within ``c F_z``) holds it for good; else
    None."""
    still = (tr.mode & 5 == 4) & np.all(np.abs(tr.y[[2, 3, 7, 8, 9]]) <= 1e-12, axis=0)
    if not still[-1]:
        return None
    k = tr.t.size - 1
    while k > 0 and still[k - 1]:
        k -= 1
    return k


def _snap(h, y, idx):
    """``y`` with the components ``idx`` set to 0 at their located zero; the energy they
    held (a rounding remainder) counts as dissipated, so the balance stays closed."""
    z = y.copy()
    z[list(idx)] = 0.0
    z[8] += line_energy(h, y) - line_energy(h, z)
    return z


def _drop_last(segs):
    """The last segment without its last point (the next segment starts there)."""
    seg = segs[-1]
    if seg.t.size > 1:
        segs[-1] = LineSegment(seg.t[:-1], seg.states[:, :-1], seg.mode[:-1],
                               seg.normal[:, :-1], seg.friction[:, :-1])


def _segment(t, Y, p):
    n = len(t)
    lam = np.zeros((2, n))
    fr = np.zeros((2, n))
    for j in range(n):
        _, lp, lm, Fp, Fm, _ = line_forces(Y[:, j], p)
        lam[:, j] = lp, lm
        fr[:, j] = math.hypot(*Fp), math.hypot(*Fm)
    return LineSegment(np.asarray(t, float).copy(), np.asarray(Y, float).copy(),
                       np.full(n, int(p[_MODE])), lam, fr)
