"""``rollingdisk simulate --ground coulomb``: the Coulomb ground, its start and its run (a
helper of :mod:`rollingdisk.cli.simulate`; the physics is :mod:`rollingdisk.ivp.hybrid`)."""

from __future__ import annotations

from rollingdisk.cli._args import CLIError, initial_state, resolve_length
from rollingdisk.cli._format import finite_or_none, has_scale, progress_bar

__all__ = ["FRICTION", "coulomb_ground", "run_coulomb", "run_until_rest"]

#: Coefficient of restitution of ``--until-rest`` when ``--restitution`` is not given.
RESTITUTION = 0.5
#: The options that describe the friction (they need --ground coulomb).
FRICTION = ("mu", "mu_k", "rolling_resistance", "pivot", "air")


def coulomb_ground(args, disk):
    """The :class:`~rollingdisk.model.ground.Coulomb` ground the options ask for, or None."""
    extra = [f"--{n.replace('_', '-')}" for n in FRICTION if getattr(args, n) is not None]
    if getattr(args, "until_rest", False):
        extra.append("--until-rest")
    if getattr(args, "animate", None) is not None and not getattr(args, "until_rest", False):
        raise CLIError("rollingdisk simulate: --animate needs --until-rest (use "
                       "rollingdisk animate for a steady motion)")
    if getattr(args, "restitution", None) is not None and not getattr(args, "until_rest",
                                                                       False):
        raise CLIError("rollingdisk simulate: --restitution needs --until-rest (impacts "
                       "happen only past the guards)")
    if args.ground != "coulomb":
        if extra:
            verb = "needs" if len(extra) == 1 else "need"
            raise CLIError(f"rollingdisk simulate: {', '.join(extra)} {verb} --ground coulomb")
        return None
    if args.mu is None:
        raise CLIError("rollingdisk simulate: --ground coulomb needs --mu (static friction "
                       "coefficient, e.g. --mu 0.3)")
    if args.method not in ("auto", "dop853") or args.error_control != "full":
        raise CLIError("rollingdisk simulate: --method and --error-control are for rough and "
                       "smooth ground; coulomb ground has its own hybrid integrator")
    import rollingdisk as rd

    return rd.Coulomb(args.mu, args.mu_k,
                      rolling_resistance=resolve_length(args.rolling_resistance, disk,
                                                        "--rolling-resistance"),
                      pivot=resolve_length(args.pivot, disk, "--pivot"), air=args.air)


def _coulomb_state(args, disk, motion) -> list[float]:
    """The start on Coulomb ground (the smooth layout, with the velocity of C)."""
    from rollingdisk.model.coulomb import rolling_state
    from rollingdisk.model.state import state_index

    if motion is None:
        y, named = initial_state(args, "smooth", "simulate")
        if not {"V_X", "V_Y"} & named:  # the rolling velocity of C (eq. 37)
            return list(rolling_state(disk, [y[0], y[1], *y[4:]]))
        return y
    y = list(rolling_state(disk, motion.initial_state()))
    y[state_index("smooth", "theta")] += args.perturb
    y[state_index("smooth", "omega1")] += args.kick
    return y


def run_coulomb(args, disk, ground, motion) -> tuple[dict, list]:
    """The hybrid rolling/sliding run; the CSV is written last (a failure leaves none)."""
    from rollingdisk.ivp.hybrid import energy_balance, simulate_coulomb
    from rollingdisk.model.coulomb import MODE_NAMES
    from rollingdisk.results.stream import write_columns
    from rollingdisk.util.files import atomic_file

    y0 = _coulomb_state(args, disk, motion)
    _check_finite_start(disk, ground, y0)
    options = {k: getattr(args, k) for k in ("rtol", "atol") if getattr(args, k) is not None}
    bar = progress_bar(args)
    try:
        traj = simulate_coulomb(disk, ground, (0.0, args.t_end), y0, progress=bar,
                                max_steps=200_000 if args.max_steps is None else
                                args.max_steps, max_wall_time=args.max_wall_time, **options)
    finally:
        bar.close()
    transitions = [x.as_dict() for x in traj.transitions]
    record = {
        "status": traj.status, "message": traj.message, "ground": "coulomb",
        **{k: v for k, v in ground.as_dict().items() if k != "ground"},
        "h": disk.h, "t_end": float(traj.t[-1]), "n_steps": traj.n_steps,
        "mode_end": MODE_NAMES[int(traj.mode[-1])], "transitions": transitions,
        "energy_balance": energy_balance(traj),
        "dissipated": {k: float(v[-1]) for k, v in traj.dissipated.items()},
        "theta_min": float(min(traj.theta)), "theta_max": float(max(traj.theta)),
        "wall_time_s": traj.wall_time, "method": traj.method,
    }
    record = {k: finite_or_none(v) for k, v in record.items()}
    if args.out is not None:
        si = has_scale(disk)
        with atomic_file(args.out, "w", newline="") as csv:
            write_columns(csv, traj.as_columns(si=si),
                          units=traj.csv_header(si=True) if si else None)
    return record, transitions


def run_until_rest(args, disk, ground, motion) -> tuple[dict, list]:
    """``--until-rest``: the motion through every phase to rest (or the end time) with
    :func:`rollingdisk.phases.motion.simulate_to_rest`; its summary and phase changes."""
    from rollingdisk.phases.motion import simulate_to_rest

    if args.animate is not None:
        from rollingdisk.util.files import check_writable

        check_writable(args.animate, name="--animate")
    y0 = _coulomb_state(args, disk, motion)
    _check_finite_start(disk, ground, y0)
    e = RESTITUTION if args.restitution is None else args.restitution
    res = simulate_to_rest(disk, ground, (0.0, args.t_end), y0, e=e,
                           max_wall=args.max_wall_time)
    if args.out is not None:  # the whole motion, every phase in one layout
        from rollingdisk.phases.columns import write_motion_csv
        from rollingdisk.util.files import atomic_file

        with atomic_file(args.out, "w", newline="") as fh:
            write_motion_csv(fh, res, si=has_scale(disk))
    if args.animate is not None:
        from rollingdisk.plotting.motion_anim import animate_motion

        animate_motion(res, args.animate)
    transitions = [x.as_dict() for x in res.transitions]
    record = {
        "status": res.status, "message": res.message, "ground": "coulomb",
        **{k: v for k, v in ground.as_dict().items() if k != "ground"},
        "h": disk.h, "restitution": e, "t_end": float(res.t_end),
        "transitions": transitions, "impacts": [x.as_dict() for x in res.impacts],
        "n_impacts": len(res.impacts), "energy_balance": float(res.energy_balance),
        "impact_loss": float(res.impact_loss), "dissipated_total": float(res.dissipated),
        "wall_time_s": float(res.wall_time),
        **({"animation": args.animate} if args.animate is not None else {}),
    }
    return {k: finite_or_none(v) for k, v in record.items()}, transitions


def _check_finite_start(disk, ground, y0) -> None:
    """Refuse, before the run, a start whose energy or contact forces overflow floating
    point (``omega3 = 1e160``, ``--air 1.7e308``): the run would warn of the overflow in
    every phase, then fail."""
    import numpy as np

    from rollingdisk.model.coulomb import coulomb_contact, coulomb_energy
    from rollingdisk.util.errors import ParameterError

    y = np.asarray(y0, dtype=float)
    with np.errstate(all="ignore"):
        values = [coulomb_energy(disk, y),
                  *coulomb_contact(disk, ground, "rolling", y).values()]
    if not np.all(np.isfinite(np.asarray(values, dtype=float))):
        raise ParameterError("the start is beyond floating-point range: its energy or "
                             "contact forces overflow (a ground coefficient: air, "
                             "rolling_resistance, pivot; or the state), got "
                             f"y0 = {y.tolist()}")
