"""The atlas of one disk: thresholds, maps, two simulated steady motions, one HTML page.

:func:`build_atlas` is the orchestration behind ``rollingdisk atlas``: for a disk (a
:class:`~rollingdisk.model.disk.Disk`, perhaps with a physical size, or its half-thickness
``h``) it writes into a folder

* ``thresholds.json`` and a table of the stability thresholds (eqs. 42, 43, 53, 57 as
  corrected in :mod:`rollingdisk.theory.oscillations`; with SI speeds when the disk has a
  size),
* the existence map on rough ground (``(theta0, r_C)``, Figure 4 style; on smooth ground
  every steady circle exists, which the page says in a sentence), stability maps in
  ``(theta0, omega30)`` on both grounds, and the regions stable
  for every ``omega30`` (Figures 5, 7) with this disk's ``h`` marked,
* one stable and one unstable steady circle on rough ground, simulated from a small tilt
  perturbation, with their plots (paths of C and P, ``theta(t)``, energy error, contact
  force) and a 3D animation each,
* Euler's disk: this disk when it has a size and a mass, else the commercial toy
  (:mod:`rollingdisk.scenarios.euler_disk`, its own ``h = 0.169``), run to its end with
  creep friction and rolling resistance, with the fitted and the predicted exponents
  (run in a second process alongside the other steps),
* ``index.html`` showing it all, with relative image paths and no external resources: a
  table of contents, a viewport for phones (images shrink to the width, wide tables
  scroll), units on every number and axis (angles in degrees; the paper's units, or SI
  when the disk given has a physical scale, see :func:`rollingdisk.plotting.plots.axis_label`),
  and where to learn more (the documentation, ``rollingdisk explore``).

It sits outside the numeric core (uses matplotlib through :mod:`rollingdisk.plotting.plots`).
"""

from __future__ import annotations

import html
import json
import math
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from rollingdisk.model.disk import DEFAULT_H, Disk, check_h
from rollingdisk.util.checks import check_real
from rollingdisk.util.files import atomic_dir, check_replaceable

__all__ = ["AtlasResult", "ATLAS_FILES", "build_atlas", "steady_trajectory"]

#: The files of an atlas folder (the folder is written as a whole, see :func:`build_atlas`).
ATLAS_FILES = ("thresholds.json", "existence.png", "stability.png", "varpi2.png",
               "all_omega30.png", "motion_stable.png", "motion_stable.gif",
               "motion_unstable.png", "motion_unstable.gif", "exact.png", "euler_disk.png",
               "euler_disk.json", "euler_disk_chirp.png", "euler_disk.wav", "to_rest.gif",
               "index.html")
#: The atlas's sound of Euler's disk: the last seconds of the run in real time, at a rate
#: that keeps the file near 350 KB (the whirr ends below 200 Hz on the toy).
EULER_SOUND = {"rate": 22050, "speed": 1.0, "max_seconds": 8.0}
#: The atlas's run past the guards (:func:`rollingdisk.phases.motion.simulate_to_rest`):
#: a thick disk dropped from rest, tilted from upright, onto Coulomb ground; it bounces,
#: rocks over its tread (rim changes) and settles upright.
TO_REST = {"h": 0.3, "Z_C": 1.6, "theta": 0.12, "e": 0.5, "mu": 0.5, "t_max": 100.0}


@dataclass(frozen=True)
class AtlasResult:
    """What :func:`build_atlas` wrote.

    Attributes
    ----------
    out_dir : Path
    index : Path
        The ``index.html`` page.
    files : tuple of Path
        Every file written (images, animations, JSON), index excluded.
    h : float
    timings : dict
        Wall time in seconds of each step.
    motions : dict
        ``{"stable": {...}, "unstable": {...}}``: the chosen steady motions, their
        closed-form stability and what the simulation showed.
    disk : Disk
        The disk of the atlas (with its physical scale, if it has one).
    """

    out_dir: Path
    index: Path
    files: tuple
    h: float
    timings: dict = field(default_factory=dict)
    motions: dict = field(default_factory=dict)
    disk: Disk | None = None


class _Progress:
    """Progress lines on a stream (stderr by default): ``[k/n] step ... 1.2 s``."""

    def __init__(self, n_steps: int, stream=None, enabled: bool = True):
        self.n = n_steps
        self.k = 0
        self.stream = sys.stderr if stream is None else stream
        self.enabled = enabled
        self.t0 = time.perf_counter()
        self.timings: dict[str, float] = {}

    def step(self, name: str):
        self.k += 1
        self._name = name
        self._t = time.perf_counter()
        if self.enabled:
            print(f"[{self.k}/{self.n}] {name} ...", end="", file=self.stream, flush=True)

    def abort(self):
        """End the open progress line (the run was interrupted or failed)."""
        if self.enabled and getattr(self, "_t", None) is not None:
            print(file=self.stream, flush=True)
        self._t = None

    def done(self, note: str = ""):
        dt = time.perf_counter() - self._t
        self.timings[self._name] = dt
        self._t = None
        if self.enabled:
            extra = f" ({note})" if note else ""
            print(f" {dt:.1f} s{extra}", file=self.stream, flush=True)

    def total(self) -> float:
        return time.perf_counter() - self.t0


# ------------------------------------------------------------------------------ motions
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


def build_atlas(disk: Disk | float = DEFAULT_H, out_dir="atlas", *, quick: bool = False,
                progress: bool = True, stream=None) -> AtlasResult:
    """Write the atlas of ``disk`` into ``out_dir``.

    The folder is built under a temporary name beside ``out_dir`` and swapped in at the
    end (:func:`rollingdisk.util.files.atomic_dir`): it appears whole or not at all, its
    ``index.html`` and ``thresholds.json`` always describe the same disk, and of two runs
    into the same folder the one that finishes last leaves its whole atlas.  An existing
    ``out_dir`` is replaced only if it holds nothing but atlas files (:data:`ATLAS_FILES`).

    Parameters
    ----------
    disk : Disk or float
        The disk, or its half-thickness ``h`` in units of the radius, ``0 <= h <= 1e8``
        (default :data:`rollingdisk.model.disk.DEFAULT_H` = 0.17, about a commercial
        Euler's disk).  A disk with a physical size (e.g.
        ``rollingdisk.disk_from_options(disk="euro-1")``) adds SI values to
        ``thresholds.json`` and the motions' records, and with a mass too it is the disk
        run as Euler's disk (else the commercial toy).
    out_dir : path-like
        Folder to write; its parent folder must exist.
    quick : bool
        Coarse grids, short simulations and few animation frames (for tests).
    progress : bool
        Print one line per step on ``stream`` (stderr by default).
    stream : file-like, optional
        Where the progress lines go.

    Returns
    -------
    AtlasResult
        The paths written (in ``out_dir``), the timings and the two simulated motions.

    Raises
    ------
    ParameterError
        For a bad ``h``, an ``out_dir`` that cannot be written or holds other files, or a
        disk with no unstable steady circle to show (all before any file is written).
    """
    from rollingdisk.theory.regions import example_motions

    h = check_h(disk)  # a Disk stands for its h
    disk = disk if isinstance(disk, Disk) else Disk(h)
    target = check_replaceable(out_dir, ATLAS_FILES, name="out_dir")
    chosen = example_motions(h)  # before any work: fails for a disk with no unstable circle
    pr = _Progress(10, stream=stream, enabled=bool(progress))
    try:
        with atomic_dir(target) as out:
            files, motions = _write_atlas(disk, out, chosen, quick=bool(quick), pr=pr)
    except BaseException:
        pr.abort()  # the message that follows gets a line of its own
        raise
    index = target / "index.html"
    if progress:
        print(f"atlas written to {index} in {pr.total():.1f} s", file=pr.stream, flush=True)
    return AtlasResult(target, index, tuple(target / p.name for p in files), h,
                       dict(pr.timings), motions, disk)


def _write_atlas(disk, out: Path, chosen, *, quick: bool, pr: _Progress) -> tuple[list, dict]:
    """The steps of :func:`build_atlas`, writing into the (temporary) folder ``out``.

    Returns the paths written (index excluded) and the records of the motions."""
    files: list[Path] = []
    dpi = 60 if quick else 100
    n_map = (60, 50) if quick else (220, 180)
    # Euler's disk runs for seconds on its own: started first, in a second process, and
    # collected after the exact motion (step 8), so the atlas does not wait for it
    euler = _start_child(_euler_disk_in_child, (out, quick, dpi, disk))
    try:
        return _write_atlas_steps(disk, out, chosen, quick=quick, pr=pr, files=files, dpi=dpi,
                                  n_map=n_map, euler=euler)
    finally:
        if euler.is_alive():  # interrupted or failed: stop the helper (the folder is dropped)
            euler.terminate()
            euler.join()


def _write_atlas_steps(disk, out, chosen, *, quick, pr, files, dpi, n_map, euler):
    """The steps of :func:`_write_atlas`, with the Euler's-disk helper process running."""
    thr = _thresholds_step(disk, out, pr, files)
    _map_steps(disk, out, quick=quick, pr=pr, files=files, dpi=dpi, n_map=n_map)
    motions = _motion_steps(disk, out, chosen, quick=quick, pr=pr, files=files, dpi=dpi,
                            euler=euler)
    # 10. index page ------------------------------------------------------------------------
    pr.step("index.html")
    (out / "index.html").write_text(_index_html(disk, thr, motions,
                                                [p.name for p in files]), encoding="utf-8")
    pr.done()
    return files, motions


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


def _motion_steps(disk, out, chosen, *, quick, pr, files, dpi, euler) -> dict:
    """Steps 6-9: two steady circles simulated (the first animation drawn in a second
    process while this one goes on: the two cores of a laptop), the stable one's exact
    motion, and Euler's disk (run alongside since the start).  No compile step: the two
    short runs run the integrator uncompiled, so a cold atlas never waits for numba."""
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
        motions["to_rest"] = _to_rest_section(out, quick, files)
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


def _to_rest_section(out: Path, quick: bool, files: list) -> dict:
    """The run :data:`TO_REST` to rest (:func:`~rollingdisk.phases.motion.simulate_to_rest`),
    its animation ``to_rest.gif`` (not when ``quick``) and its record for the page."""
    from rollingdisk.model.ground import Coulomb
    from rollingdisk.phases.motion import FlightSegment, simulate_to_rest
    from rollingdisk.plotting.motion_anim import animate_motion

    r = TO_REST
    s0 = [0.0, 0.0, r["Z_C"], 0.0, r["theta"], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    res = simulate_to_rest(Disk(r["h"]), Coulomb(r["mu"]), (0.0, r["t_max"]), s0, e=r["e"])
    if not quick:
        animate_motion(res, out / "to_rest.gif", n_frames=120, fps=12, dpi=70,
                       title=f"let go, h = {r['h']:g}")
        files.append(out / "to_rest.gif")
    kinds = [i.kind for i in res.impacts]
    return {**r, "status": res.status, "message": res.message, "t_end": res.t_end,
            "n_impacts": len(kinds), "n_rim": kinds.count("rim"),
            "n_rim_change": kinds.count("rim-change"), "n_face": kinds.count("face"),
            "n_flights": sum(isinstance(g, FlightSegment) for g in res.segments),
            "n_segments": len(res.segments), "energy_initial": res.energy_initial,
            "energy_final": res.energy_final, "impact_loss": res.impact_loss,
            "dissipated": res.dissipated, "energy_balance": res.energy_balance,
            "wall_time": res.wall_time, "gif": not quick}


def _start_animation(traj, path, kw):
    """Start :func:`rollingdisk.plotting.animation.animate` in a child process (written atomically
    there); returns the process."""
    return _start_child(_animate_in_child, (traj, path, kw))


def _start_child(target, args):
    """Start ``target(*args)`` in a daemon child process; returns the process."""
    import multiprocessing

    proc = multiprocessing.Process(target=target, args=args, daemon=True)
    proc.start()
    return proc


def _quiet_signals():
    """In a helper: a Ctrl-C or SIGTERM reaches the whole process group; the child ignores
    SIGINT (the parent stops it) and dies quietly on SIGTERM, so the user sees the parent's
    one line and never the child's traceback."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _animate_in_child(traj, path, kw):
    """The animation helper's body (see :func:`_quiet_signals`)."""
    from rollingdisk.plotting.animation import animate

    _quiet_signals()
    animate(traj, path, **kw)


def _euler_disk_in_child(out: Path, quick: bool, dpi: int, disk: Disk | None = None):
    """The Euler's-disk helper's body: the toy run to its end (``quick``: started at
    ``alpha0 = 0.05``, a short run), ``euler_disk.png``, the whirr's frequency
    ``euler_disk_chirp.png``, its sound ``euler_disk.wav`` (not when ``quick``) and
    ``euler_disk.json`` in ``out`` (the atlas's temporary folder; the JSON last, as the sign
    that the others are whole; its ``"sound"`` names the WAV).  The toy is ``disk`` when it
    has a radius and a mass, else the commercial Euler's disk."""
    from matplotlib.figure import Figure

    from rollingdisk.plotting.plots import plot_euler_disk
    from rollingdisk.plotting.sound import chirp, plot_chirp_frequency, sound_window, write_wav
    from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk

    _quiet_signals()
    alpha0 = 0.05 if quick else 0.3
    if disk is not None and disk.radius is not None and disk.mass is not None:
        toy = EulerDisk.from_disk(disk, alpha0=alpha0)
    else:
        toy = EulerDisk(alpha0=alpha0)
    result = run_euler_disk(toy, max_wall_time=60.0)
    fig = Figure(figsize=(10.0, 4.2))
    plot_euler_disk(result, fig)  # title: plots.euler_disk_title, symbols with units
    fig.savefig(out / "euler_disk.png", dpi=dpi)
    snd = EULER_SOUND
    fig = Figure(figsize=(6.4, 3.6))
    plot_chirp_frequency(result, fig, rate=snd["rate"], speed=snd["speed"],
                         max_seconds=snd["max_seconds"])
    fig.savefig(out / "euler_disk_chirp.png", dpi=dpi)
    summary = result.summary()
    if not quick:
        write_wav(out / "euler_disk.wav", chirp(result, **snd), snd["rate"])
        t0, t1 = sound_window(result, snd["speed"], snd["max_seconds"])
        summary["sound"] = {"file": "euler_disk.wav", **snd, "window_s": [t0, t1]}
    (out / "euler_disk.json").write_text(json.dumps(summary, indent=2, allow_nan=False))


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


#: The page's style: readable at phone width (the viewport meta tag, images no wider than
#: the screen, wide tables scroll inside their box), 16 px body text.
_CSS = """html{-webkit-text-size-adjust:100%;text-size-adjust:100%}
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;font-size:16px;
max-width:1050px;margin:1.5em auto;padding:0 1em;color:#222;line-height:1.5;
overflow-wrap:break-word}
h1{font-size:1.6em;line-height:1.25}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;
margin-top:1.8em}h3{margin-top:1.4em}
nav.toc{background:#f6f7f9;border:1px solid #dde;border-radius:6px;padding:.6em 1.2em;
margin:1em 0}nav.toc ol{margin:.3em 0;padding-left:1.4em}nav.toc li{margin:.15em 0}
.scroll{overflow-x:auto;-webkit-overflow-scrolling:touch;max-width:100%}
table{border-collapse:collapse;margin:.8em 0}
td,th{border:1px solid #bbb;padding:.3em .6em;text-align:right;vertical-align:top}
th{background:#eee}td:first-child,th:first-child{text-align:left}
td.text,th.text{text-align:left}
img{max-width:100%;height:auto;border:1px solid #ddd}figure{margin:1em 0}
figcaption{color:#555;font-size:.9em}
.pair{display:flex;gap:1em;flex-wrap:wrap;align-items:flex-start}
.pair img{flex:1 1 300px;min-width:0}
.note{color:#555;font-size:.92em}code{background:#f4f4f4;padding:0 .2em}
pre{background:#f4f4f4;padding:.6em;overflow-x:auto}
@media (max-width:600px){body{margin:.8em auto;padding:0 .7em}h1{font-size:1.35em}
td,th{padding:.25em .4em}}"""


def _fmt(x, nd=4):
    if x is None:
        return "&ndash;"
    if isinstance(x, bool):
        return "yes" if x else "no"
    return f"{x:.{nd}g}"


def _deg(x, nd=4):
    """An angle in radians, shown in degrees."""
    return "&ndash;" if x is None else f"{math.degrees(x):.{nd}g}&deg;"


#: Units of the page (HTML): the paper's, ``m = a = g = 1``.
_T = "&radic;(a/g)"
_W = "&radic;(g/a)"


def _img(src: str, alt: str, width: int | None = None) -> str:
    """An image that opens at full size when tapped (a phone shrinks it to the screen)."""
    w = f' width="{width}"' if width else ""
    return f'<a href="{src}"><img src="{src}" alt="{html.escape(alt)}"{w}></a>'


def _euler_block(ed: dict) -> str:
    """The section "Euler's disk" of the index page, from the run's JSON summary."""
    p = ed["parameters"]
    rows = "\n".join(
        f"<tr><td>{name}</td><td>{_fmt(ed['exponents'][key])}</td>"
        f"<td>{_fmt(ed['predicted'][key])}</td></tr>"
        for key, name in (("alpha", "tilt &alpha;"), ("Omega", "precession rate &Omega;"),
                          ("contact_speed", "contact-point speed")))
    lo, hi = ed["fit_window_alpha"]
    alpha_end = ed.get("alpha_end")
    at = f"&alpha; = {_deg(alpha_end, 3)} at " if alpha_end is not None else ""
    return f"""<h2 id="euler-disk">Euler's disk</h2>
<p>The commercial toy (radius {p['radius_m'] * 1e3:.4g} mm, thickness
{p['thickness_m'] * 1e3:.4g} mm, so h = {p['h']:.4g}; mass {p['mass_kg']:.3g} kg) started on
its spin-in-place steady motion at tilt &alpha;<sub>0</sub> = 90&deg; &minus; &theta;<sub>0</sub>
= {_deg(p['alpha0'], 3)} and run to its end with creep friction (&mu; = {p['mu']:.3g}, creep
coefficient {p['creep']:.4g}) and rolling resistance (length {p['rolling_resistance']:.3g}
a); <code>rollingdisk euler-disk</code>, <code>docs/friction.md</code>. End: <b>{ed['end']}</b>,
{at}t = {_fmt(ed['t_end_s'])} s (status <code>{html.escape(ed['status'])}</code>; the adiabatic
decay along the steady family predicts {_fmt(ed['predicted_t_end_s'])} s); energy
balance {_fmt(ed['energy_balance'], 2)}; {ed['n_steps']} steps in {ed['wall_time_s']:.1f} s.
Exponents against t<sub>0</sub> &minus; t over &alpha; in ({lo:g}, {hi:g}) rad, fitted with
t<sub>0</sub> = {_fmt(ed['t0_s'])} s, beside those of the adiabatic decay along the steady
family (an exponent has no unit):</p>
<div class="scroll"><table><tr><th>quantity</th><th>fitted</th><th>predicted</th></tr>
{rows}</table></div>
{_img("euler_disk.png", "Euler's disk: tilt, precession rate and contact-point speed")}
{_sound_block(ed)}"""


def _sound_block(ed: dict) -> str:
    """The whirr under the section "Euler's disk": the frequency plot, the sound (when the
    run wrote one) and where the comparison of the dissipation laws is."""
    snd = ed.get("sound")
    audio = ""
    if snd:
        t0, t1 = snd["window_s"]
        audio = (f'<p>Listen: the last {t1 - t0:.3g} s of the run in real time '
                 f'(<code>rollingdisk euler-disk --sound chirp.wav</code>).</p>\n'
                 f'<audio controls src="{html.escape(snd["file"])}"></audio>\n')
    return f"""<p>The whirr: the contact point runs round its circle at the precession rate
&Omega;, so the toy sounds at &Omega;/2&pi;, rising to the end. The spin-down under each
dissipation law alone (rolling resistance, the squeeze film, the boundary layer) and the
toy's mix, with their exponents, is compared in <code>docs/friction.md</code>
(<code>docs/gallery/euler_disk_laws.png</code>).</p>
{audio}{_img("euler_disk_chirp.png", "the whirr's frequency against the time to the end")}"""


def _units_paragraph(h) -> str:
    """The page's units, and the SI conversion when the disk has a physical scale."""
    text = (f"Units: the paper's, m = a = g = 1: lengths in a (the radius), times in {_T}, "
            f"angular speeds in {_W}, &varpi;&sup2; in g/a, forces in mg, energies in mga; "
            "angles in degrees (the JSON files keep radians).")
    a = getattr(h, "radius", None)
    if a is not None:
        T = math.sqrt(a / h.gravity)
        text += (f" For this disk (a = {a * 1e3:.4g} mm, g = {h.gravity:.4g} m/s&sup2;): "
                 f"{_T} = {T:.4g} s, {_W} = {1.0 / T:.4g} rad/s, a = {a:.4g} m; the plots "
                 "are labelled in SI units.")
    return f'<p class="note">{text}</p>'


#: Sections of the page: (anchor, title) for the table of contents.
_SECTIONS = (("thresholds", "Stability thresholds"),
             ("existence", "Where steady circles exist"),
             ("stability", "Stability of steady circles"),
             ("all-omega30", "Stable for every &omega;<sub>30</sub>"),
             ("motions", "Two steady circles, simulated"),
             ("exact", "The stable circle at finite amplitude"),
             ("to-rest", "Past the guards: a disk let go to rest"),
             ("euler-disk", "Euler's disk"),
             ("learn-more", "Learn more"),
             ("files", "Files"))


def _toc() -> str:
    items = "\n".join(f'<li><a href="#{a}">{t}</a></li>' for a, t in _SECTIONS)
    return f'<nav class="toc" aria-label="Contents"><b>Contents</b><ol>\n{items}\n</ol></nav>'


def _thresholds_table(thr: dict, disk=None) -> str:
    """One row per steady motion; the threshold of |omega20| and of |omega30| in columns of
    their own (each row has one of them); in rad/s too when the disk has a size."""
    a = getattr(disk, "radius", None)
    w_si = None if a is None else math.sqrt(disk.gravity / a)  # sqrt(g/a) in rad/s
    rows = [
        ("rough", "straight line in the SE position", "42", "omega20",
         thr["rough"]["straight_line_omega20_sq"]),
        ("rough", "circle in the SE position", "43", "omega30",
         thr["rough"]["se_circle_omega30_sq"]),
        ("smooth", "straight line", "53", "omega20", thr["smooth"]["straight_line_omega20_sq"]),
        ("smooth", "spin in place", "57", "omega30", thr["smooth"]["spin_omega30_sq"]),
    ]

    def cell(which, key, v):
        if which != key:
            return '<td class="empty">&ndash;</td>'
        sym = "&omega;<sub>20</sub>" if key == "omega20" else "&omega;<sub>30</sub>"
        si = "" if w_si is None else f"<br>= {_fmt(math.sqrt(v) * w_si)} rad/s"
        return (f'<td>{_fmt(math.sqrt(v))} <span class="note">({sym}&sup2; &gt; '
                f'{_fmt(v)})</span>{si}</td>')

    body = "\n".join(
        f"<tr><td>{g}</td><td class=\"text\">{what}</td><td>({eq})</td>"
        f"{cell('omega20', key, v)}{cell('omega30', key, v)}</tr>"
        for g, what, eq, key, v in rows)
    return f"""<div class="scroll"><table>
<tr><th>ground</th><th class="text">steady motion</th><th>eq.</th>
<th>stable if |&omega;<sub>20</sub>| &gt;<br>[{_W}]</th>
<th>stable if |&omega;<sub>30</sub>| &gt;<br>[{_W}]</th></tr>
{body}</table></div>"""


def _learn_more() -> str:
    return """<h2 id="learn-more">Learn more</h2>
<p>The documentation (notation and units, the equations and their errata, simulation,
friction, exact motions, sweeps, the gallery) is built from the project's
<code>docs/</code> folder; in a checkout, with the <code>docs</code> extra:</p>
<pre><code>pip install -e ".[docs]"
python -m sphinx -b html docs docs/_build/html</code></pre>
<p>and then open <code>docs/_build/html/index.html</code>. To explore the steady motions of
any disk interactively (click a map, see the motion in 3D, change h, the ground, the
friction), run</p>
<pre><code>rollingdisk explore</code></pre>
<p>which opens the explorer in the web browser (<code>docs/explorer.md</code>). This page
itself is <code>rollingdisk atlas --out DIR</code>; <code>rollingdisk --help</code> lists the
other commands.</p>"""


def _index_html(h, thr: dict, motions: dict, names: list) -> str:
    """The atlas page: every section in order, with relative image paths only."""
    hv = check_h(h)  # h, or a Disk with or without a physical scale
    disk = h if hasattr(h, "radius") else None
    return "".join([_page_head(h, hv), _thresholds_section(thr, disk), _MAPS_SECTION,
                    _motions_section(motions), _exact_html(motions["exact"]),
                    _to_rest_html(motions["to_rest"]), _page_tail(motions, names)])


def _title(h, hv) -> str:
    """What the atlas is about: the disk's size when it has one, its h always."""
    a = getattr(h, "radius", None)
    if a is None:
        return f"a disk of half-thickness h = {hv:.4g}"
    return (f"a disk of radius {a * 1e3:.4g} mm and thickness {2 * hv * a * 1e3:.4g} mm "
            f"(h = {hv:.4g})")


def _page_head(h, hv) -> str:
    """The page's head, title, introduction, units and table of contents."""
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>rollingdisk atlas, h = {hv:.4g}</title><style>{_CSS}</style></head><body>
<h1>Atlas of {_title(h, hv)}</h1>
<p>A homogeneous disk of radius a and thickness 2h&nbsp;=&nbsp;{2 * hv:.4g}&nbsp;a on a
horizontal plane, after M. Batista, <i>Steady Motion of a Rigid Disk of Finite Thickness on a
Horizontal Plane</i>. &theta;<sub>0</sub> is the tilt from the vertical, &Omega;<sub>0</sub>
the rate at which the disk turns about the vertical, &omega;<sub>20</sub> its spin about its
own axis (eq. 2; on a straight line, the rolling rate), &omega;<sub>30</sub> =
&Omega;<sub>0</sub> cos&theta;<sub>0</sub> (eq. 3), r<sub>C</sub> the signed radius of the
circle of the centre C (positive: the disk leans toward the centre A of the circle). The
static equilibrium (SE) tilt is tan&theta;<sub>0</sub> = h, &theta;<sub>0</sub> =
{_deg(math.atan(hv))}. All numbers come from the library (formulas derived and checked; see
<code>docs/errata.md</code> for where they differ from the printed paper).</p>
{_units_paragraph(h)}
{_toc()}

"""


def _thresholds_section(thr: dict, disk=None) -> str:
    """The thresholds section: what they mean, and the table."""
    return f"""<h2 id="thresholds">Stability thresholds</h2>
<p>The steady motions whose stability depends on one rate only. A straight line is stable
when the disk spins fast enough about its own axis (|&omega;<sub>20</sub>| above the
threshold), a circle in the SE position and the spin in place when it turns fast enough
(|&omega;<sub>30</sub>| above the threshold). The squares are in
<code>thresholds.json</code>.</p>
{_thresholds_table(thr, disk)}

"""


#: The maps' sections (existence, stability, stable for every omega30): text and images.
_MAPS_SECTION = (f"""<h2 id="existence">Where steady circles exist</h2>
<p><b>Rough ground</b> (rolling without slip): in the (&theta;<sub>0</sub>, r<sub>C</sub>)
plane a steady circle exists where &Omega;<sub>0</sub>&sup2; of eq. (31) is positive; dark:
none, gray: it exists but is unstable (&varpi;&sup2; &lt; 0), white: stable. The red curve is
r<sub>C</sub>* of eq. (32), where the denominator of eq. (31) vanishes.</p>
{_img("existence.png", "existence map on rough ground")}
<p><b>Smooth ground</b> (no friction) needs no map: the only horizontal force on the disk is
zero, so its centre C moves in a straight line, and in a steady circle C is at rest
(r<sub>C</sub> = 0). For every tilt 0&deg; &lt; &theta;<sub>0</sub> &lt; 90&deg; and every
turning rate &Omega;<sub>0</sub> &ne; 0 there is exactly one steady circle (&omega;<sub>20</sub>
from eq. (54)): the contact point P runs round C on a circle of radius |y<sub>P0</sub>| = |sin
&theta;<sub>0</sub> &minus; h cos &theta;<sub>0</sub>|, and the disk presses on the ground with
its weight. Which of these circles are stable is the right-hand map of the next section.</p>

<h2 id="stability">Stability of steady circles</h2>
<p>For every &theta;<sub>0</sub> and every &omega;<sub>30</sub> &ne; 0 a steady circle exists
on either ground (&omega;<sub>20</sub> from eq. (44) or (54)). Gray: &varpi;&sup2; &lt; 0
(unstable), white: stable. The dotted line is the uniform bound above which every steady
circle is stable whatever h and &theta;<sub>0</sub>: &omega;<sub>30</sub>&sup2; = g/a on
rough ground, &omega;<sub>30</sub>&sup2; = 4 g/a on smooth ground (the paper's conclusion
prints 2, but its own eq. (57) at h = 0 needs 4; see <code>docs/figures.md</code>).</p>
{_img("stability.png", "stability maps")}
<p>The same along a few vertical lines of these maps: &varpi;&sup2; against
&omega;<sub>30</sub>. Where &varpi;&sup2; &gt; 0, &varpi; is the angular frequency of the small
oscillation of the tilt; where &varpi;&sup2; &lt; 0, &radic;(&minus;&varpi;&sup2;) is the rate at
which a disturbance grows.</p>
{_img("varpi2.png", "varpi squared against omega30")}

<h2 id="all-omega30">Stable for every &omega;<sub>30</sub></h2>
<p>White: at this (&theta;<sub>0</sub>, h) the steady circle is stable whatever
&omega;<sub>30</sub> (conditions (46) and (59); the paper's Figures 5 and 7). The blue line
marks this disk.</p>
{_img("all_omega30.png", "regions stable for every omega30")}

""")


def _motions_section(motions: dict) -> str:
    """The two simulated steady circles."""
    return f"""<h2 id="motions">Two steady circles, simulated</h2>
<p>Each motion starts on the steady circle with a small kick d&theta;/dt, and is integrated
with the full nonlinear equations (rough ground: eqs. (1), (2), (37), (38)). The plots show
the paths of C and of the contact point P, &theta;(t), the energy error and the contact force
(F<sub>z</sub> &gt; 0 keeps contact). The animation draws the disk as a cylinder of thickness
2h; the red sectors are fixed in the body, so they show the rotation &phi;; the red line on the
plane is the path of P.</p>
{_motion_block(motions["stable"], "stable")}
{_motion_block(motions["unstable"], "unstable")}

"""


def _exact_html(ex: dict) -> str:
    """The stable circle's exact motion at finite amplitude."""
    return f"""<h2 id="exact">The stable circle at finite amplitude: the exact motion</h2>
<p>On rough and smooth ground the disk is integrable: &omega;<sub>2</sub>,
&omega;<sub>3</sub> and (d&theta;/dt)&sup2; are functions of &theta; alone, and time,
&psi; and the contact point's path follow by quadrature (<code>rollingdisk exact</code>,
<code>docs/exact.md</code>). Kicked by d&theta;/dt(0) = {_fmt(ex['kick'], 3)} {_W},
the stable circle nutates between &theta; = {_deg(ex['theta_min'], 6)} and
{_deg(ex['theta_max'], 6)} with period {_fmt(ex['period'], 8)} {_T}
(linear theory: 2&pi;/&varpi; = {_fmt(ex['linear_period'], 8)} {_T}), the frame
turning by &Delta;&psi; = {_deg(ex['delta_psi'], 6)} per period. Left: &theta;(t)
over one period; middle: the contact point over 20 periods; right: the backbone, frequency
against amplitude, which starts at &varpi; and reaches
{_fmt(ex['frequency_at_largest'], 5)} {_W} at amplitude
{_deg(ex['largest_amplitude'], 3)}.</p>
{_img("exact.png", "exact motion: theta over a period, rosette, backbone")}

"""


def _to_rest_html(m: dict) -> str:
    """The section "Past the guards": the run :data:`TO_REST` and its numbers."""
    gif = (_img("to_rest.gif", "a thick disk let go: it bounces, rocks and settles", 350)
           if m["gif"] else '<p class="note">(The quick atlas draws no animation here.)</p>')
    flat = " and falls flat" if m["n_face"] else ""
    e = html.escape
    return f"""<h2 id="to-rest">Past the guards: a disk let go to rest</h2>
<p>The motions above stop at their guards (lift-off, the rim edge, falling flat);
<code>simulate_to_rest</code> goes on through free flight, impacts (Newton&ndash;Coulomb,
restitution e = {_fmt(m['e'], 3)}), rim changes and the flat disk, to rest
(<code>rollingdisk simulate --ground coulomb --until-rest</code>,
<code>docs/motion.md</code>). A thick disk, h = {_fmt(m['h'], 3)}, on Coulomb ground
(&mu; = {_fmt(m['mu'], 3)}) is let go from rest with its centre at Z<sub>C</sub> =
{_fmt(m['Z_C'], 3)} a, tilted {_deg(m['theta'], 3)} from upright: it bounces
({m['n_rim']} rim impacts in {m['n_flights']} flights), then rocks over its tread
({m['n_rim_change']} rim changes){flat}; end: <b>{e(m['status'])}</b>
at t = {_fmt(m['t_end'])} {_T} ({e(m['message'])}).</p>
<p>Energy [mga]: {_fmt(m['energy_initial'])} at the start, {_fmt(m['energy_final'])} at rest
(the potential energy of the centre where it stops);
{_fmt(m['impact_loss'])} lost in the {m['n_impacts']} impacts, {_fmt(m['dissipated'])}
dissipated by friction in contact; the balance E + dissipated + impact losses holds to
{_fmt(m['energy_balance'], 2)} (relative); {m['n_segments']} segments in
{m['wall_time']:.2g} s.</p>
{gif}

"""


def _page_tail(motions: dict, names: list) -> str:
    """Euler's disk, where to learn more, the files, the end of the page."""
    e = html.escape
    return f"""{_euler_block(motions["euler_disk"])}

{_learn_more()}

<h2 id="files">Files</h2>
<p class="note">{" &middot; ".join(f'<a href="{e(n)}">{e(n)}</a>' for n in names)}</p>
</body></html>
"""


def _si_row(m: dict) -> str:
    """The motion's row in SI (rad/s, m) when its disk has a size, else nothing."""
    if m.get("Omega0_si") is None:
        return ""
    cells = "".join(f"<td>{_fmt(m[k])} {u}</td>" for k, u in (
        ("Omega0_si", "rad/s"), ("omega20_si", "rad/s"), ("omega30_si", "rad/s"),
        ("r_C_si", "m"), ("r_P_si", "m")) if m.get(k) is not None)
    return f'\n<tr><td class="text">SI</td>{cells}</tr>'


def _motion_block(m: dict, kind: str) -> str:
    """The page's section of one simulated steady circle."""
    e = html.escape
    verdict = (f"stable: &varpi;&sup2; = {_fmt(m['varpi2'])} g/a, &varpi; = "
               f"{_fmt(m['varpi'])} {_W} (period {_fmt(m['period'])} {_T}); the "
               f"simulation oscillates at {_fmt(m['measured'])} {_W}" if m["stable"] else
               f"unstable: &varpi;&sup2; = {_fmt(m['varpi2'])} g/a, growth rate "
               f"&radic;(&minus;&varpi;&sup2;) = {_fmt(m['growth_rate'])} {_W}; the "
               f"simulation grows at {_fmt(m['measured'])} {_W}")
    return f"""
<h3 id="{kind}">{kind.capitalize()} steady circle</h3>
<div class="scroll"><table><tr><th>&theta;<sub>0</sub></th><th>&Omega;<sub>0</sub> [{_W}]</th>
<th>&omega;<sub>20</sub> [{_W}]</th><th>&omega;<sub>30</sub> [{_W}]</th>
<th>r<sub>C</sub> [a]</th><th>r<sub>P</sub> [a]</th></tr>
<tr><td>{_deg(m['theta0'])}</td><td>{_fmt(m['Omega0'])}</td><td>{_fmt(m['omega20'])}</td>
<td>{_fmt(m['omega30'])}</td><td>{_fmt(m['r_C'])}</td><td>{_fmt(m['r_P'])}</td></tr>{_si_row(m)}
</table></div>
<p>Closed form (section 4.1): {verdict}. Simulated from the steady state with a kick
d&theta;/dt(0) = {_fmt(m['kick'], 2)} {_W} until t = {_fmt(m['t_end'])} {_T} (status
<code>{e(m['status'])}</code>):
largest |&theta; &minus; &theta;<sub>0</sub>| = {_deg(m['max_theta_dev'], 3)}, largest energy
error {_fmt(m['energy_error'], 2)} mga.</p>
<div class="pair">{_img(f"motion_{kind}.png", f"{kind} motion plots", 620)}
{_img(f"motion_{kind}.gif", f"{kind} motion animation", 350)}</div>"""

