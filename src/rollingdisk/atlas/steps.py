"""The steps of an atlas: each computes one part (the thresholds, the maps, two simulated
steady circles, the exact motion, a disk let go to rest), writes its images and JSON into
the atlas's folder and returns the record the page shows.
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path

import numpy as np

from rollingdisk.atlas.children import _start_animation
from rollingdisk.model.disk import Disk
from rollingdisk.util.checks import check_real

__all__ = ["steady_trajectory", "TO_REST"]

#: The atlas's run past the guards (:func:`rollingdisk.phases.motion.simulate_to_rest`):
#: a thick disk dropped from rest, tilted from upright, onto Coulomb ground; it bounces,
#: rocks over its tread (rim changes) and settles upright.  A disk with a physical size
#: (a coin) is let go the same way with its own ``h`` (:func:`_to_rest_section`).
TO_REST = {"h": 0.3, "Z_C": 1.6, "theta": 0.12, "e": 0.5, "mu": 0.5, "t_max": 100.0}


def steady_trajectory(h: float, ground: str, theta0: float, *, Omega0: float | None = None,
                      r_C: float | None = None, r_P: float | None = None,
                      perturb: float = 0.0, kick: float = 0.0, t_end: float = 20.0,
                      n_out: int = 1200):
    """Build the steady motion of eqs. (26)-(35) and simulate it from a small disturbance.

    ``perturb`` is added to ``theta(0)``, ``kick`` to ``omega1(0) = d theta/dt``.  A tilt
    alone moves the disk onto a neighbouring steady motion, about which it then oscillates
    (eq. 39 has a constant right-hand side then); a kick ``omega1`` keeps the oscillation
    centred on ``theta0`` (linear theory: ``omega~2 - c theta~`` is conserved, eq. 39).
    The trajectory is sampled at ``n_out`` equally spaced times in ``[0, t_end]``.

    Returns ``(motion, stability, trajectory)``.
    """
    from rollingdisk.ivp.simulation import simulate_steady
    from rollingdisk.theory.oscillations import stability
    from rollingdisk.theory.steady import steady_motion

    disk = h if isinstance(h, Disk) else Disk(h)  # a Disk keeps its physical scale
    motion = steady_motion(disk, ground, theta0, Omega0=Omega0, r_C=r_C, r_P=r_P)
    t_end = check_real("t_end", t_end, low=0.0, low_open=True)
    traj = simulate_steady(motion, t_end, perturb=perturb, kick=kick,
                           t_eval=np.linspace(0.0, t_end, max(2, int(n_out))))
    return motion, stability(motion), traj


# ------------------------------------------------------------------------------ atlas
def _save(fig, path: Path, dpi: int, files: list):
    fig.savefig(path, dpi=dpi)
    files.append(path)
    return path


def _thresholds_step(disk, out, pr, files) -> dict:
    """Step 1: ``thresholds.json`` (SI beside when the disk has a size); the thresholds."""
    from rollingdisk.theory.oscillations import thresholds

    pr.step("thresholds")
    thr = thresholds(disk).as_dict()
    (out / "thresholds.json").write_text(
        json.dumps({"h": disk.h, **_floats(thr), **_thresholds_si(disk)}, indent=2,
                   allow_nan=False))
    files.append(out / "thresholds.json")
    pr.done()
    return thr


def _map_steps(disk, out, *, quick, pr, files, dpi, n_map):
    """Steps 2-4: the existence, stability, varpi^2 and stable-for-every-omega30 maps.  The
    disk as given: one with a physical scale labels the axes in SI (``plots.axis_label``)."""
    from matplotlib.figure import Figure  # no pyplot: the user's backend is left alone

    from rollingdisk.plotting import plots as plotting
    from rollingdisk.theory.regions import STABLE

    h = disk.h
    # 2. existence map (rough ground; on smooth ground every steady circle exists: a
    # sentence on the page, not a panel of "none")
    pr.step("existence map")
    fig = Figure(figsize=(6.4, 5.0))
    ax = fig.subplots(1, 1)
    m_ex = plotting.plot_existence_map(disk, "rough", ax, n=n_map,
                                       title=f"rough ground, $h={h:.4g}$")
    fig.tight_layout()
    _save(fig, out / "existence.png", dpi, files)
    pr.done(f"stable share {m_ex.share(STABLE):.2f}")
    # 3. stability maps
    pr.step("stability maps")
    fig = Figure(figsize=(10.0, 5.0))
    for ax, ground in zip(fig.subplots(1, 2), ("rough", "smooth"), strict=True):
        plotting.plot_stability_map(disk, ground, ax, n=n_map,
                                    omega30_max=2.0 if ground == "rough" else 2.5)
    fig.tight_layout()
    _save(fig, out / "stability.png", dpi, files)
    fig = Figure(figsize=(10.0, 3.8))
    for ax, ground in zip(fig.subplots(1, 2), ("rough", "smooth"), strict=True):
        plotting.plot_varpi2_curves(disk, ground, ax, n=120 if quick else 400)
    fig.tight_layout()
    _save(fig, out / "varpi2.png", dpi, files)
    pr.done()
    # 4. stable for every omega30
    pr.step("regions stable for every omega30")
    fig = Figure(figsize=(10.0, 5.0))
    for ax, ground in zip(fig.subplots(1, 2), ("rough", "smooth"), strict=True):
        plotting.plot_all_omega30_stable(ground, ax, n=n_map,
                                         h_range=(0.0, max(1.5, 2.0 * h)), mark_h=h)
    fig.tight_layout()
    _save(fig, out / "all_omega30.png", dpi, files)
    pr.done()


def _motion_steps(disk, out, chosen, *, quick, pr, files, dpi, euler, rest=None) -> dict:
    """Steps 6-9: two steady circles simulated (the first animation drawn in a second
    process while this one goes on: the two cores of a laptop), the stable one's exact
    motion, the disk let go to rest (``rest``: its process and connection, run alongside
    since the start; None: run here) and Euler's disk (run alongside since the start).  No
    compile step: the two short runs run the integrator uncompiled, so a cold atlas never
    waits for numba."""
    motions = {}
    helpers = []
    try:
        for kind in ("stable", "unstable"):
            motions[kind] = _one_motion(disk, out, getattr(chosen, kind), kind, quick=quick,
                                        pr=pr, files=files, dpi=dpi, helpers=helpers)
        pr.step("exact motion: quadrature, rosette, backbone")
        motions["exact"] = _exact_section(chosen.stable, out, dpi, files)
        pr.done(f"period {motions['exact']['period']:.6g}")
        pr.step("a disk let go to rest: bounces, rocking")
        motions["to_rest"] = (_to_rest_section(out, quick, files, disk) if rest is None
                              else _collect_to_rest(rest, out, quick, files))
        pr.done(f"{motions['to_rest']['n_impacts']} impacts, at rest at "
                f"t = {motions['to_rest']['t_end']:.4g}")
        pr.step("Euler's disk (run alongside)")
        euler.join()
        if euler.exitcode != 0:
            raise RuntimeError(f"the Euler's disk process ended with exit code "
                               f"{euler.exitcode}")
        motions["euler_disk"] = json.loads((out / "euler_disk.json").read_text())
        files += [out / "euler_disk.png", out / "euler_disk_chirp.png", out / "euler_disk.json"]
        if (out / "euler_disk.wav").is_file():
            files.append(out / "euler_disk.wav")
        ed = motions["euler_disk"]
        pr.done(f"{ed['end']} at {ed['t_end_s']:.4g} s")
        for proc in helpers:
            proc.join()
            if proc.exitcode != 0:
                raise RuntimeError(f"the animation process ended with exit code "
                                   f"{proc.exitcode}")
    finally:
        for proc in helpers:  # interrupted: stop the helper too (the folder is dropped)
            if proc.is_alive():
                proc.terminate()
                proc.join()
    return motions


def _one_motion(disk, out, chosen_motion, kind, *, quick, pr, files, dpi, helpers) -> dict:
    """One steady circle (``kind``: "stable" or "unstable"): simulated from a small kick,
    plotted and animated; its record for the page."""
    from matplotlib.figure import Figure

    from rollingdisk.plotting import plots as plotting
    from rollingdisk.plotting.animation import animate

    pr.step(f"{kind} steady circle: simulate, plot, animate")
    theta0, Omega0 = chosen_motion.theta0, chosen_motion.Omega0
    kick = 0.05 if kind == "stable" else 1e-4
    motion, stab, traj = steady_trajectory(disk, "rough", theta0, Omega0=Omega0, kick=kick,
                                           t_end=12.0 if quick else 30.0,
                                           n_out=300 if quick else 1500)
    fig = Figure(figsize=(9.0, 6.5))
    plotting.plot_trajectory(traj, fig, theta0=theta0,
                             title=f"{kind} steady circle, rough ground, h = {disk.h:.4g}")
    _save(fig, out / f"motion_{kind}.png", dpi, files)
    gif = out / f"motion_{kind}.gif"
    kw = dict(n_frames=6 if quick else 60, fps=12, dpi=55 if quick else 70,
              title=f"{kind} circle, h = {disk.h:.4g}")
    if kind == "stable" and (os.cpu_count() or 1) > 1:
        helpers.append(_start_animation(traj, gif, kw))
    else:
        animate(traj, gif, **kw)
    files.append(gif)
    record = _motion_record(motion, stab, traj, kick)
    pr.done(f"status {record['status']}")
    return record


def _collect_to_rest(rest, out: Path, quick: bool, files: list) -> dict:
    """The record of the run to rest from its helper process
    (:func:`.children._start_to_rest`); its GIF joins ``files``."""
    proc, conn = rest
    try:
        record = conn.recv()
    except EOFError:
        record = None
    finally:
        conn.close()
    proc.join()
    if record is None or proc.exitcode != 0:
        raise RuntimeError(f"the run-to-rest process ended with exit code {proc.exitcode}")
    if record["gif"]:
        files.append(out / "to_rest.gif")
    return record


def _exact_section(motion, out: Path, dpi: int, files: list) -> dict:
    """The exact motion about the stable circle, kicked hard (a finite amplitude), with its
    backbone curve (:mod:`rollingdisk.theory.exact`)."""
    from matplotlib.figure import Figure

    from rollingdisk.plotting import plots as plotting
    from rollingdisk.theory import exact as exact
    from rollingdisk.theory.oscillations import stability

    varpi = stability(motion).varpi
    kicks = np.linspace(0.01, 1.0, 25) * varpi * 0.3
    bb = exact.backbone(motion, kicks)
    ok = np.nonzero(np.isfinite(bb.period))[0]
    kick = float(kicks[ok[len(ok) // 2]])
    ex = exact.exact_steady(motion, kick=kick)
    fig = Figure(figsize=(12.6, 4.0))
    plotting.plot_exact(ex, fig, backbone=bb, n_periods=20,
                        title="exact motion about the stable circle, kicked by "
                              rf"$d\theta/dt(0)$ = {kick:.3g} $\sqrt{{g/a}}$")
    _save(fig, out / "exact.png", dpi, files)
    return {"kick": kick, "theta_min": ex.theta_min, "theta_max": ex.theta_max,
            "period": ex.period, "linear_period": 2.0 * math.pi / varpi,
            "delta_psi": ex.delta_psi, "status": ex.status,
            "largest_amplitude": float(np.nanmax(bb.amplitude)),
            "frequency_at_largest": float(bb.frequency[ok[-1]]), "varpi": varpi}


def _to_rest_section(out: Path, quick: bool, files: list, disk: Disk | None = None) -> dict:
    """The run :data:`TO_REST` to rest (:func:`~rollingdisk.phases.motion.simulate_to_rest`),
    its animation ``to_rest.gif`` (not when ``quick``) and its record for the page.

    A ``disk`` with a physical size is the one let go (its ``h``; the record gains ``*_si``
    times and lengths); any other disk stands for the generic thick disk of :data:`TO_REST`.
    ``pose`` is how it lies at the end: ``"flat"`` on a face, ``"upright"`` on its tread,
    ``"rim"`` on a rim edge (the kind of the last segment)."""
    from rollingdisk.model.ground import Coulomb
    from rollingdisk.phases.line_contact import LineSegment
    from rollingdisk.phases.motion import FlatSegment, FlightSegment, simulate_to_rest
    from rollingdisk.plotting.motion_anim import animate_motion

    sized = disk is not None and disk.radius is not None
    r = {**TO_REST, "h": disk.h} if sized else TO_REST
    s0 = [0.0, 0.0, r["Z_C"], 0.0, r["theta"], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    res = simulate_to_rest(Disk(r["h"]), Coulomb(r["mu"]), (0.0, r["t_max"]), s0, e=r["e"])
    if not quick:
        animate_motion(res, out / "to_rest.gif", n_frames=120, fps=12, dpi=70,
                       title=f"let go, h = {r['h']:g}")
        files.append(out / "to_rest.gif")
    kinds = [i.kind for i in res.impacts]
    last = res.segments[-1] if res.segments else None
    pose = ("flat" if isinstance(last, FlatSegment) else
            "upright" if isinstance(last, LineSegment) else "rim")
    record = {**r, "status": res.status, "message": res.message, "t_end": res.t_end,
              "n_impacts": len(kinds), "n_rim": kinds.count("rim"),
              "n_rim_change": kinds.count("rim-change"), "n_face": kinds.count("face"),
              "n_flights": sum(isinstance(g, FlightSegment) for g in res.segments),
              "n_segments": len(res.segments), "energy_initial": res.energy_initial,
              "energy_final": res.energy_final, "impact_loss": res.impact_loss,
              "dissipated": res.dissipated, "energy_balance": res.energy_balance,
              "wall_time": res.wall_time, "gif": not quick, "pose": pose}
    if sized:
        record.update(t_end_si=float(disk.time_to_si(res.t_end)),
                      Z_C_si=float(disk.length_to_si(r["Z_C"])))
    return record


def _thresholds_si(disk) -> dict:
    """The thresholds' SI fields (``<name>_si``: speeds in m/s, angular speeds in rad/s),
    the disk's size and a ``"units"`` map, for ``thresholds.json``; ``{}`` without a size."""
    from rollingdisk.theory.oscillations import thresholds

    if disk.radius is None:
        return {}
    view = thresholds(disk).to_si()
    out = {k: float(v) for k, v in view.items() if k != "units" and not isinstance(v, bool)}
    units = dict(view["units"])
    out.update(radius_si=disk.radius, thickness_si=2.0 * disk.h * disk.radius,
               gravity_si=disk.gravity)
    units.update(radius_si="m", thickness_si="m", gravity_si="m/s^2")
    if disk.mass is not None:
        out["mass_si"] = disk.mass
        units["mass_si"] = "kg"
    out["units"] = units
    return out


def _floats(d):
    if isinstance(d, dict):
        return {k: _floats(v) for k, v in d.items()}
    return float(d)


def _motion_record(motion, stab, traj, kick) -> dict:
    from rollingdisk.plotting.plots import trajectory_series
    from rollingdisk.results.measure import compare_with_theory

    theta = trajectory_series(traj, "theta")
    E = trajectory_series(traj, "E")
    measured = compare_with_theory(traj, stab).measured  # the CLI's rule for the linear range
    si = {}
    if motion.disk.radius is not None:  # SI beside (rad/s, m, s)
        view = {**motion.to_si(), **stab.to_si(motion.disk)}
        si = {k: (None if v is None else float(v)) for k, v in view.items()
              if k.endswith("_si") and k[:-3] in ("Omega0", "omega20", "omega30", "r_C",
                                                   "r_P", "varpi", "period", "growth_rate")}
        si["t_end_si"] = float(motion.disk.time_to_si(float(np.asarray(traj.t)[-1])))
    record = {
        "theta0": float(motion.theta0), "Omega0": float(motion.Omega0),
        "omega20": float(motion.omega20), "omega30": float(motion.omega30),
        "r_C": float(motion.r_C), "r_P": float(motion.r_P),
        **stab.as_dict(),
        "measured": None if measured is None else float(measured),
        "kick": float(kick), "status": traj.status,
        "t_end": float(np.asarray(traj.t)[-1]),
        "max_theta_dev": float(np.max(np.abs(theta - motion.theta0))),
        "energy_error": float(np.max(np.abs(E - E[0]))),  # absolute, units of m g a
    }
    return {**record, **si}
