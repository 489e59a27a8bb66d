"""The explorer's JSON endpoints: validated queries in, the library's numbers out.

Every function here takes the query of one request (``{name: [values]}``, as
:func:`urllib.parse.parse_qs` gives it) and returns a JSON-ready dict, or raises
:class:`ApiError` (HTTP 400) with one line naming the parameter and its allowed range.
No physics is written here or in the page's JavaScript: every number comes from
:func:`rollingdisk.steady_motion`, :func:`rollingdisk.stability`,
:func:`rollingdisk.existence_codes`, :func:`rollingdisk.mu_required_map`,
:func:`rollingdisk.simulate_steady` and :func:`rollingdisk.plotting.animation.disk_pose`.

Work per request is bounded: a map has at most ``N_MAX**2`` points, a simulation at most
``T_END_MAX`` time units, ``POINTS_MAX`` stored points and ``SIM_MAX_STEPS`` integration
steps, which keeps a request under about half a second on a busy 2-core machine.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

import rollingdisk as rd

__all__ = ["ApiError", "GROUNDS", "PLANES", "N_MAX", "T_END_MAX", "POINTS_MAX",
           "SIM_MAX_STEPS", "H_RANGE", "map_payload", "steady_payload", "simulate_payload",
           "si_record", "pose_track", "POSE_RIM"]

GROUNDS = ("rough", "smooth")
#: Map planes: the tilt ``theta0`` against ``omega30``, ``Omega0`` or ``r_C`` (Figure 4).
PLANES = ("theta0-omega30", "theta0-Omega0", "theta0-r_C")
#: Largest map grid (points along each axis).
N_MAX = 121
#: Longest simulation (time units sqrt(a/g)) and most points sent back.
T_END_MAX = 200.0
POINTS_MAX = 4000
#: Step budget of one simulation (uncompiled DOP853, about 0.15 ms a step: 0.3 s, under
#: the 0.4 s after which rd.simulate loads its compiled integrator, about 1 s once).
SIM_MAX_STEPS = 2000
#: Half-thickness accepted (units of the radius).
H_RANGE = (0.0, 100.0)
#: Largest |Omega0| (and |omega30|) of a simulated motion: faster ones need more steps
#: than :data:`SIM_MAX_STEPS` allows over a useful time.
SIM_SPEED_MAX = 20.0
#: Largest value of the map's second axis.
YMAX_RANGE = (1e-3, 100.0)
#: Default ``ymax`` per plane.
YMAX_DEFAULT = {"theta0-omega30": 3.0, "theta0-Omega0": 3.0, "theta0-r_C": 2.0}
#: Bounds of the single-point speeds and radii (beyond them the floats lose meaning).
SPEED_MAX = 1e6
RADIUS_MAX = 1e6

CODE_NAMES = {rd.NO_MOTION: "no steady motion", rd.UNSTABLE: "unstable", rd.STABLE: "stable"}


class ApiError(ValueError):
    """A bad request: HTTP 400 with ``{"error": str(self)}``."""


# ------------------------------------------------------------------------ query parsing
def _one(query: dict, name: str) -> str | None:
    values = query.get(name)
    if not values:
        return None
    if len(values) > 1:
        raise ApiError(f"{name} given {len(values)} times; give it once")
    return values[0]


def _check_names(query: dict, allowed: tuple[str, ...]) -> None:
    for name in query:
        if name not in allowed:
            raise ApiError(f"unknown parameter {name!r}; this endpoint takes "
                           f"{', '.join(allowed)}")


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def _real(query: dict, name: str, low: float, high: float, default: float | None = None, *,
          low_open: bool = False, high_open: bool = False, required: bool = False) -> float:
    """A finite number in the interval; the message names ``name`` and the interval."""
    rng = (("(" if low_open else "[") + f"{_fmt(low)}, {_fmt(high)}"
           + (")" if high_open else "]"))
    raw = _one(query, name)
    if raw is None or raw.strip() == "":
        if required or default is None:
            raise ApiError(f"{name} is required: a number in {rng}")
        return default
    try:
        value = float(raw)
    except ValueError:
        raise ApiError(f"{name} must be a number in {rng}, got {raw[:40]!r}") from None
    if not math.isfinite(value):
        raise ApiError(f"{name} must be a finite number in {rng}, got {raw[:40]!r}")
    too_low = value <= low if low_open else value < low
    too_high = value >= high if high_open else value > high
    if too_low or too_high:
        raise ApiError(f"{name} must lie in {rng}, got {_fmt(value)}")
    return value


def _int(query: dict, name: str, low: int, high: int, default: int) -> int:
    raw = _one(query, name)
    if raw is None or raw.strip() == "":
        return default
    try:
        value = int(raw)
    except ValueError:
        raise ApiError(f"{name} must be an integer in [{low}, {high}], "
                       f"got {raw[:40]!r}") from None
    if not low <= value <= high:
        raise ApiError(f"{name} must be an integer in [{low}, {high}], got {value}")
    return value


def _choice(query: dict, name: str, choices: tuple[str, ...], default: str) -> str:
    raw = _one(query, name)
    if raw is None or raw == "":
        return default
    if raw not in choices:
        raise ApiError(f"{name} must be one of {', '.join(choices)}, got {raw[:40]!r}")
    return raw


def _disk_query(query: dict, defaults: dict) -> tuple[str, float]:
    ground = _choice(query, "ground", GROUNDS, defaults.get("ground", "rough"))
    h = _real(query, "h", *H_RANGE, defaults.get("h", rd.DEFAULT_H))
    return ground, h


def _json_float(x) -> float | None:
    """A float for strict JSON (NaN and infinity become None)."""
    if x is None:
        return None
    x = float(x)
    return x if math.isfinite(x) else None


def _rounded(values, decimals: int = 7) -> list:
    """Drawing data to ``decimals`` places (a fifth of the JSON at full precision)."""
    a = np.round(np.asarray(values, dtype=float), decimals)
    return [v if math.isfinite(v) else None for v in a.tolist()]


# ------------------------------------------------------------------------------- map
def _grid(plane: str, n: int, ymax: float) -> tuple[np.ndarray, np.ndarray]:
    """Cell centres: ``theta0`` in ``(0, pi/2)``; the second axis in ``(0, ymax)`` or, for
    ``r_C``, in ``(-ymax, ymax)``."""
    theta0 = (np.arange(n) + 0.5) * (0.5 * math.pi / n)
    if plane == "theta0-r_C":
        y = -ymax + (np.arange(n) + 0.5) * (2.0 * ymax / n)
    else:
        y = (np.arange(n) + 0.5) * (ymax / n)
    return theta0, y


@lru_cache(maxsize=64)
def _map(ground: str, h: float, plane: str, n: int, ymax: float) -> dict:
    theta0, y = _grid(plane, n, ymax)
    TH, Y = np.meshgrid(theta0, y)  # rows: y, columns: theta0
    if plane == "theta0-r_C":
        # Figure 4: eq. (31) for existence, eq. (45) through (47) for stability
        if ground == "rough":
            codes = np.asarray(rd.existence_codes(h, TH, Y))
            mu = np.asarray(rd.mu_required_map(h, TH, Y), dtype=float)
        else:  # smooth ground: C is at rest in every steady circle, r_C = 0 only
            codes = np.full(TH.shape, rd.NO_MOTION, dtype=np.int8)
            mu = np.full(TH.shape, np.nan)
    else:
        # every (theta0, omega30 != 0) is a steady circle: ask the library point by point,
        # so that the map shows exactly what a click there answers
        disk = rd.Disk(h)
        codes = np.full(TH.shape, rd.NO_MOTION, dtype=np.int8)
        mu = np.full(TH.shape, np.nan)
        for (j, i), th in np.ndenumerate(TH):
            m = _motion(disk, ground, float(th), plane.split("-")[1], float(Y[j, i]))
            if m is None:
                continue
            try:
                stable = rd.stability(m).stable
            except rd.ParameterError:
                continue
            codes[j, i] = rd.STABLE if stable else rd.UNSTABLE
            mu[j, i] = m.mu_required
    return {
        "ground": ground, "h": h, "plane": plane, "n": n,
        "x": {"name": "theta0", "unit": "rad", "values": theta0.tolist(),
              "range": [0.0, 0.5 * math.pi]},
        "y": {"name": plane.split("-")[1], "values": y.tolist(),
              "range": [-ymax if plane == "theta0-r_C" else 0.0, ymax]},
        "codes": codes.astype(int).tolist(),
        "mu_required": [[_json_float(v) for v in row] for row in mu],
        "code_names": {str(k): v for k, v in CODE_NAMES.items()},
        "se_theta0": math.atan(h),
    }


def _motion(disk, ground: str, theta0: float, name: str, value: float):
    """The steady motion, or None where the library says there is none."""
    try:
        return _steady(disk, ground, theta0, name, value)
    except rd.ParameterError:
        return None


def _steady(disk, ground: str, theta0: float, name: str, value: float):
    if name == "omega30":
        return rd.steady_motion(disk, ground, theta0, Omega0=value / math.cos(theta0))  # eq. 3
    return rd.steady_motion(disk, ground, theta0, **{name: value})


def map_payload(query: dict, defaults: dict | None = None) -> dict:
    """``/api/map``: the class grid (0 none, 1 unstable, 2 stable) and ``mu_required``.

    Parameters (query): ``ground`` (rough, smooth), ``h`` in [0, 100], ``plane``
    (theta0-omega30, theta0-Omega0, theta0-r_C), ``n`` in [2, 121], ``ymax`` in
    [0.001, 100] (the second axis runs over ``(0, ymax)``, or ``(-ymax, ymax)`` for r_C).

    Returns
    -------
    dict
        ``x``, ``y`` (axis names and cell centres), ``codes[j][i]`` at
        ``(x.values[i], y.values[j])``, ``mu_required[j][i]`` (``|F_t|/F_z``, None where
        no steady motion), ``se_theta0`` (``arctan h``, the static-equilibrium tilt).
    """
    defaults = defaults or {}
    _check_names(query, ("ground", "h", "plane", "n", "ymax"))
    ground, h = _disk_query(query, defaults)
    plane = _choice(query, "plane", PLANES, defaults.get("plane", PLANES[0]))
    n = _int(query, "n", 2, N_MAX, 81)
    ymax = _real(query, "ymax", *YMAX_RANGE, YMAX_DEFAULT[plane])
    return _map(ground, h, plane, n, ymax)


# ---------------------------------------------------------------------------- steady
_MOTION_PARAMS = ("omega30", "Omega0", "r_C", "r_P")


def _motion_query(query: dict, defaults: dict, speed_max: float = SPEED_MAX):
    """``(ground, h, theta0, name, value)`` of a single steady motion."""
    ground, h = _disk_query(query, defaults)
    theta0 = _real(query, "theta0", -0.5 * math.pi, 0.5 * math.pi, low_open=True,
                   high_open=True, required=True)
    if theta0 == 0.0 and h > 0.0:
        raise ApiError("theta0 must lie in (-pi/2, 0) or (0, pi/2) when h > 0 (at theta0 = 0 "
                       "the disk stands on its rim edge, outside the theory)")
    given = [n for n in _MOTION_PARAMS if _one(query, n) not in (None, "")]
    if len(given) != 1:
        raise ApiError("give exactly one of omega30, Omega0, r_C, r_P (got "
                       f"{', '.join(given) or 'none'})")
    name = given[0]
    bound = speed_max if name in ("omega30", "Omega0") else RADIUS_MAX
    value = _real(query, name, -bound, bound, required=True)
    return ground, h, theta0, name, value


def _motion_record(m, s) -> dict:
    rec = {k: (_json_float(v) if isinstance(v, float) else v)
           for k, v in m.as_dict().items()}
    rec.update({k: (_json_float(v) if isinstance(v, float) else v)
                for k, v in s.as_dict().items()})
    rec["exists"] = True
    return rec


def steady_payload(query: dict, defaults: dict | None = None) -> dict:
    """``/api/steady``: one steady motion and its stability, or why there is none.

    Parameters (query): ``ground``, ``h``, ``theta0`` in (-pi/2, pi/2) [rad], and exactly
    one of ``omega30``, ``Omega0`` (|.| <= 1e6), ``r_C``, ``r_P`` (|.| <= 1e6).

    Returns
    -------
    dict
        ``exists``; if True the fields of :meth:`rollingdisk.SteadyMotion.as_dict` (``Omega0,
        omega20, omega30, r_C, r_P, mu_required, ...``) and of
        :meth:`rollingdisk.Stability.as_dict` (``varpi2, stable, period, ...``); if False,
        ``reason``: the library's :class:`rollingdisk.NoSteadyMotion` message.
    """
    defaults = defaults or {}
    _check_names(query, ("ground", "h", "theta0", *_MOTION_PARAMS))
    ground, h, theta0, name, value = _motion_query(query, defaults)
    base = {"ground": ground, "h": h, "theta0": theta0, name: value}
    try:
        m = _steady(rd.Disk(h), ground, theta0, name, value)
        s = rd.stability(m)
    except rd.NoSteadyMotion as exc:
        return {**base, "exists": False, "reason": str(exc)}
    except rd.ParameterError as exc:  # the request is not one motion (e.g. r_C on smooth)
        raise ApiError(str(exc)) from None
    rec = _motion_record(m, s)
    disk = defaults.get("disk")
    if disk is not None and disk.radius is not None and h == disk.h:
        rec["si"] = si_record(disk, m, s)
    return rec


def si_record(disk, m, s) -> dict:
    """SI values of a steady motion of ``disk`` (a disk with a physical size): label ->
    value, the labels naming their unit."""
    ts = float(disk.time_to_si(1.0))
    a = float(disk.length_to_si(1.0))
    out = {"radius [mm]": 1e3 * a, "Omega0 [rad/s]": m.Omega0 / ts,
           "omega20 [rad/s]": m.omega20 / ts, "omega30 [rad/s]": m.omega30 / ts,
           "r_C [mm]": 1e3 * m.r_C * a, "speed of C [m/s]": m.v_C * a / ts}
    if s.period is not None and math.isfinite(s.period):
        out["period [s]"] = s.period * ts
    return {k: _json_float(v) for k, v in out.items()}


# -------------------------------------------------------------------------- simulate
def simulate_payload(query: dict, defaults: dict | None = None) -> dict:
    """``/api/simulate``: the steady motion tilted by ``kick`` and simulated.

    Parameters (query): as ``/api/steady`` (speeds ``|Omega0|, |omega30| <= 20``), ``kick``
    in [-0.5, 0.5] rad (added to ``theta(0)``, ``perturb`` of
    :func:`rollingdisk.simulate_steady`), ``t_end`` in (0, 200], ``points`` in [2, 4000].

    Returns
    -------
    dict
        ``status``, ``message``, ``t_last``, ``n_steps``, the steady motion (``motion``)
        and per stored point the columns ``t, theta, psi, phi, X_C, Y_C, X_P, Y_P`` and
        the drawn pose (:func:`rollingdisk.plotting.animation.disk_pose`): ``Z_C`` and the unit
        vectors ``axis`` (eta), ``e1``, ``e2`` (body-fixed radii), as flat lists.
    """
    from rollingdisk.plotting.animation import disk_pose

    defaults = defaults or {}
    _check_names(query, ("ground", "h", "theta0", *_MOTION_PARAMS, "kick", "t_end", "points"))
    ground, h, theta0, name, value = _motion_query(query, defaults, SIM_SPEED_MAX)
    kick = _real(query, "kick", -0.5, 0.5, 0.01)
    t_end = _real(query, "t_end", 0.0, T_END_MAX, 60.0, low_open=True)
    points = _int(query, "points", 2, POINTS_MAX, 1000)
    try:
        m = _steady(rd.Disk(h), ground, theta0, name, value)
        s = rd.stability(m)
        if abs(m.Omega0) > SIM_SPEED_MAX:
            raise ApiError(f"Omega0 = {_fmt(m.Omega0)} of this steady motion is too fast to "
                           f"simulate here: |Omega0| must be <= {SIM_SPEED_MAX:g}")
        tr = rd.simulate_steady(m, t_end, perturb=kick, t_eval=np.linspace(0.0, t_end, points),
                                max_steps=SIM_MAX_STEPS)
    except rd.ParameterError as exc:  # NoSteadyMotion included: nothing to simulate
        raise ApiError(str(exc)) from None
    poses = [disk_pose(h, float(X), float(Y), float(psi), float(th), float(phi), n=POSE_RIM)
             for X, Y, psi, th, phi in zip(tr.X_C, tr.Y_C, tr.psi, tr.theta, tr.phi)]
    return {
        "motion": _motion_record(m, s), "kick": kick, "t_end": t_end, "h": h,
        "status": tr.status, "message": tr.message, "t_last": float(tr.t[-1]),
        "n_steps": int(tr.n_steps), "max_steps": SIM_MAX_STEPS,
        **pose_track(h, poses, t=tr.t, theta=tr.theta, psi=tr.psi, phi=tr.phi, X_C=tr.X_C,
                     Y_C=tr.Y_C, X_P=tr.X_P, Y_P=tr.Y_P),
    }


#: Points on each rim circle of a pose given to :func:`pose_track`: 4, so that the rim's
#: points 0 and 1 lie at the body-fixed radii e1 and e2.
POSE_RIM = 4


def pose_track(h: float, poses, **columns) -> dict:
    """The track the view draws (``static/view.js``: ``drawScene``), as rounded flat lists.

    Parameters
    ----------
    h : float
        Half-thickness [``a``].
    poses : sequence of DiskPose
        The drawn disk at each stored point
        (:func:`rollingdisk.plotting.animation.disk_pose` with ``n=POSE_RIM``).
    **columns : array_like
        Per stored point: ``t`` [``sqrt(a/g)``], ``X_C, Y_C, X_P, Y_P`` [``a``] (needed),
        and any others (``theta, psi, phi`` [rad]), kept in this order.

    Returns
    -------
    dict
        The columns, then ``Z_C`` (height of C) and the unit vectors ``axis`` (eta), ``e1``,
        ``e2`` (body-fixed radii) of each pose, flattened (``3 k`` to ``3 k + 2``).
    """
    Z_C, axis, e1, e2 = [], [], [], []
    for pose in poses:
        top = pose.center + h * pose.axis  # rim circle 1 is about C + h eta
        Z_C.append(float(pose.center[2]))
        axis.extend(pose.axis.tolist())
        e1.extend((pose.rims[1][:, 0] - top).tolist())
        e2.extend((pose.rims[1][:, 1] - top).tolist())
    return {**{k: _rounded(a) for k, a in columns.items()},
            **{k: _rounded(a) for k, a in (("Z_C", Z_C), ("axis", axis), ("e1", e1),
                                           ("e2", e2))}}
