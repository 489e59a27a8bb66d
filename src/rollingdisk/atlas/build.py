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
* a disk let go to rest past the guards (bounces, rocking, falling flat): this disk when it
  has a size, else a generic thick disk (``h = 0.3``, :data:`.steps.TO_REST`) (run in a
  third process alongside the other steps when the machine has more than one core),
* ``index.html`` showing it all, with relative image paths and no external resources: for
  a disk with a size, the object named (``"the 1-euro coin"``, from
  :data:`rollingdisk.model.units.DISKS`) in the title and heading, and its first screen
  the answers a person holding it asks (the speed above which it rolls straight and
  stable, eq. 42 in m/s; how long it spins, from its Euler's-disk run; how it falls, from
  its run to rest), in SI with the paper's units beside; then a
  table of contents, a viewport for phones (images shrink to the width, wide tables
  scroll), units on every number and axis (angles in degrees; the paper's units, or SI
  when the disk given has a physical scale, see :func:`rollingdisk.plotting.plots.axis_label`),
  and where to learn more (the documentation, ``rollingdisk explore``).

The steps live in :mod:`.steps` (the child processes in :mod:`.children`), the page in
:mod:`.page` and its HTML in the templates of ``rollingdisk/atlas/templates/``.  It sits
outside the numeric core (uses matplotlib through :mod:`rollingdisk.plotting.plots`).
"""

from __future__ import annotations

import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from rollingdisk.atlas.children import _euler_disk_in_child, _start_child, _start_to_rest
from rollingdisk.atlas.page import _index_html
from rollingdisk.atlas.steps import (
    _map_steps,
    _motion_steps,
    _thresholds_step,
    _to_rest_section,
    steady_trajectory,
)
from rollingdisk.model.disk import DEFAULT_H, Disk, check_h
from rollingdisk.util.files import atomic_dir, check_replaceable

__all__ = ["AtlasResult", "ATLAS_FILES", "build_atlas", "steady_trajectory"]

#: The files of an atlas folder (the folder is written as a whole, see :func:`build_atlas`).
ATLAS_FILES = ("thresholds.json", "existence.png", "stability.png", "varpi2.png",
               "all_omega30.png", "motion_stable.png", "motion_stable.gif",
               "motion_unstable.png", "motion_unstable.gif", "exact.png", "euler_disk.png",
               "euler_disk.json", "euler_disk_chirp.png", "euler_disk.wav", "to_rest.gif",
               "index.html")


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
        ``thresholds.json`` and the motions' records, is the disk let go to rest, and
        makes the page lead with its answers (named after it when it is in
        :data:`rollingdisk.model.units.DISKS`); with a mass too it is the disk run as
        Euler's disk (else the commercial toy).
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
    # matplotlib and the plotting module, imported once here, are the helpers' too (forked)
    import matplotlib.figure  # noqa: F401

    import rollingdisk.plotting.plots  # noqa: F401

    # Euler's disk and the disk let go to rest (with its animation) run for seconds each on
    # their own: started first, each in a process of its own, and collected after the exact
    # motion (steps 8, 9), so the atlas does not wait for them; with one core the run to
    # rest stays in this process
    euler = _start_child(_euler_disk_in_child, (out, quick, dpi, disk))
    helpers = [euler]
    try:
        rest = (_start_to_rest(_to_rest_section, out, quick, disk)
                if (os.cpu_count() or 1) > 1 else None)
        if rest is not None:
            helpers.append(rest[0])
        return _write_atlas_steps(disk, out, chosen, quick=quick, pr=pr, files=files, dpi=dpi,
                                  n_map=n_map, euler=euler, rest=rest)
    finally:
        for proc in helpers:  # interrupted or failed: stop the helpers (the folder is dropped)
            if proc.is_alive():
                proc.terminate()
                proc.join()


def _write_atlas_steps(disk, out, chosen, *, quick, pr, files, dpi, n_map, euler, rest):
    """The steps of :func:`_write_atlas`, with the helper processes running (Euler's disk;
    ``rest``: the run to rest's process and connection, or None)."""
    thr = _thresholds_step(disk, out, pr, files)
    _map_steps(disk, out, quick=quick, pr=pr, files=files, dpi=dpi, n_map=n_map)
    motions = _motion_steps(disk, out, chosen, quick=quick, pr=pr, files=files, dpi=dpi,
                            euler=euler, rest=rest)
    # 10. index page ------------------------------------------------------------------------
    pr.step("index.html")
    (out / "index.html").write_text(_index_html(disk, thr, motions,
                                                [p.name for p in files]), encoding="utf-8")
    pr.done()
    return files, motions
