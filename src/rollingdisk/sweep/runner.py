"""Parameter sweeps: many perturbed steady motions, integrated in batches (issue 12).

A sweep integrates the reduced system ``(theta, omega1, omega2, omega3)`` (eq. 2 with
eq. 38 on rough / eq. 49 on smooth ground) from a perturbed steady circle at every point of
a grid and keeps a few summaries per trajectory (no per-step storage), next to the
closed-form ``varpi^2`` (eq. 45 corrected / 55) and its sign.

Rules (stated once, used everywhere):

* Perturbation: ``theta(0) = theta0 + tilt``, ``omega1(0) = kick``; omega2, omega3 keep
  their steady values.  The *initial amplitude* is ``a0 = |tilt| + |kick|`` (kick in
  rad per unit time sqrt(a/g); for a linear oscillation of frequency varpi the amplitude is
  ``sqrt(tilt^2 + kick^2/varpi^2)``, at most ``a0 * max(1, 1/varpi)``).
* ``stable_simulated``: the run completed (no guard fired: lift-off F_z <= 0 eq. 11, edge
  contact theta crossing 0, falling flat |theta| >= pi/2) and
  ``max|theta - theta0| <= BOUND_FACTOR * a0`` with ``BOUND_FACTOR = 20``.
* ``frequency``: ``2 pi / period``, the period being the least-squares slope of the times
  of the upward crossings of ``theta - theta0`` against their index; NaN with fewer than 2
  crossings.  The crossings are located on the step polynomial (``method="taylor"``, the
  default) or by cubic Hermite interpolation with omega1 as derivative (``"dop853"``).
* ``growth_rate``: ``ln(GROW_HI / GROW_LO) / (t_hi - t_lo)`` with ``t_lo`` (``t_hi``) the
  time at which ``|theta - theta0|`` first exceeds ``GROW_LO * a0`` (``GROW_HI * a0``),
  ``GROW_LO = 2``, ``GROW_HI = 10``: the log-slope of the envelope in the linear window;
  NaN when the departure never reaches ``GROW_HI * a0``.  ``taylor`` samples every step
  at its middle and end, ``dop853`` at its end, and both locate the time inside.
* Guards: ``taylor`` locates a guard inside the step where it fires (``t_end`` is the
  event time); ``dop853`` stops at the end of that step.
* ``energy_drift``: ``max_t |E(t) - E(0)| / |E(0)|`` over accepted steps, E of the reduced
  state (eq. 13 with eqs. 37 and 7 on rough ground; on smooth ground the part without the
  constant horizontal velocity of C).

The results are the same bit for bit whichever executor computes them (each trajectory's
computation depends on its own inputs only).  Results are stored chunk by chunk in
``OUT.partial/`` and the final Zarr store (or NetCDF file) appears under its name only once
complete; a run interrupted for any reason resumes from the finished chunks.

Why one module of ~540 lines: grids, perturbations, the three executors and the chunked
store share one chunk layout (which trajectory goes in which chunk, how a chunk is marked
done); keeping them together keeps that layout in one place.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from rollingdisk.model.disk import Disk, check_ground, check_h
from rollingdisk.model.geometry import _inertia
from rollingdisk.util.checks import check_real
from rollingdisk.util.errors import ParameterError

__all__ = ["SweepGrid", "Perturbation", "run_sweep", "basin_sweep", "open_sweep",
           "BOUND_FACTOR", "GROW_LO", "GROW_HI"]

#: A run counts as bounded (``stable_simulated``) if ``max|theta - theta0|`` stays within
#: ``BOUND_FACTOR`` times the initial departure ``a0``.
BOUND_FACTOR = 20.0
#: ``growth_rate`` is the log-slope of ``|theta - theta0|`` between the first times it
#: exceeds ``GROW_LO * a0`` and ``GROW_HI * a0``.
GROW_LO = 2.0
#: Upper end of the growth-rate window (see :data:`GROW_LO`).
GROW_HI = 10.0
_SECOND = ("omega30", "r_C", "Omega0", "omega0")


@dataclass(frozen=True)
class Perturbation:
    """Perturbation of the steady state: ``tilt`` added to theta, ``kick`` set as omega1.

    Either may be a sequence (the ``amplitude`` axis of the sweep); a scalar is repeated.
    """

    kick: tuple = (1e-3,)
    tilt: tuple = (0.0,)

    def __post_init__(self):
        k = np.atleast_1d(np.asarray(self.kick, dtype=float))
        e = np.atleast_1d(np.asarray(self.tilt, dtype=float))
        if k.ndim != 1 or e.ndim != 1:
            raise ParameterError("kick and tilt must be scalars or 1-d sequences")
        n = max(k.size, e.size)
        if k.size not in (1, n) or e.size not in (1, n):
            raise ParameterError(f"kick ({k.size}) and tilt ({e.size}) must have equal lengths"
                                 " or length 1")
        k = np.broadcast_to(k, (n,))
        e = np.broadcast_to(e, (n,))
        for name, v in (("kick", k), ("tilt", e)):
            if not np.all(np.isfinite(v)):
                raise ParameterError(f"{name} must be finite")
        if np.any(np.abs(k) + np.abs(e) == 0):
            raise ParameterError("each amplitude needs kick != 0 or tilt != 0")
        object.__setattr__(self, "kick", tuple(float(x) for x in k))
        object.__setattr__(self, "tilt", tuple(float(x) for x in e))


@dataclass(frozen=True)
class SweepGrid:
    """A grid of steady motions on one ground: circles ``h x theta0 x (omega30 | r_C |
    Omega0)`` or straight lines ``h x omega0``.

    Give exactly one of ``omega30``, ``r_C`` (rough ground: Omega0^2 from eq. 31, NaN where
    no steady motion has that radius), ``Omega0`` (each with ``theta0``), or ``omega0``
    (without ``theta0``): straight lines rolling at ``omega20 = omega0`` at the
    static-equilibrium tilt ``theta0 = arctan(h)`` of each h (section 3.1; the lean
    ``-arctan(h)`` is the mirror image, eq. 18's symmetry, with the same stability).
    Alternatively give ``states``, a list of arbitrary reduced initial states ``(theta,
    omega1, omega2, omega3)`` (then theta0 of each is its own theta and no perturbation is
    added).

    Examples
    --------
    >>> SweepGrid("rough", h=(0.0, 0.5), omega0=(0.5, 1.0, 2.0)).shape
    (2, 3)
    >>> SweepGrid("rough", theta0=(0.1, 0.2), omega30=(1.0,)).dims
    ('h', 'theta0', 'omega30')
    """

    ground: str
    h: tuple = (0.17,)
    theta0: tuple = ()
    omega30: tuple | None = None
    r_C: tuple | None = None
    Omega0: tuple | None = None
    omega0: tuple | None = None
    states: tuple | None = None

    def __post_init__(self):
        check_ground(self.ground)
        hs = tuple(check_h(x) for x in np.atleast_1d(np.asarray(self.h, dtype=float)))
        object.__setattr__(self, "h", hs)
        if self.states is not None:
            s = np.asarray(self.states, dtype=float)
            if s.ndim != 2 or s.shape[1] != 4 or not np.all(np.isfinite(s)):
                raise ParameterError("states must be a list of finite (theta, omega1, omega2,"
                                     " omega3)")
            if len(hs) != 1:
                raise ParameterError("states need a single h")
            object.__setattr__(self, "states", tuple(map(tuple, s.tolist())))
            return
        given = [k for k in _SECOND if getattr(self, k) is not None]
        if len(given) != 1:
            raise ParameterError(f"give exactly one of {_SECOND}, got {given}")
        if given[0] == "r_C" and self.ground != "rough":
            raise ParameterError("r_C determines Omega0 on rough ground only (eq. 31)")
        if given[0] == "omega0":
            if np.size(self.theta0):
                raise ParameterError("omega0 (straight lines) fixes theta0 = arctan(h); "
                                     "do not give theta0")
            object.__setattr__(self, "theta0", ())
            v = tuple(check_real("omega0", x) for x in np.atleast_1d(self.omega0))
            if not v:
                raise ParameterError("omega0 must not be empty")
            object.__setattr__(self, "omega0", v)
            return
        th = tuple(check_real("theta0", x, low=-math.pi / 2, high=math.pi / 2, low_open=True,
                              high_open=True) for x in np.atleast_1d(self.theta0))
        if not th:
            raise ParameterError("theta0 must not be empty")
        object.__setattr__(self, "theta0", th)
        v = tuple(check_real(given[0], x) for x in np.atleast_1d(getattr(self, given[0])))
        if not v:
            raise ParameterError(f"{given[0]} must not be empty")
        object.__setattr__(self, given[0], v)

    @property
    def second(self) -> str:
        return next(k for k in _SECOND if getattr(self, k) is not None)

    @property
    def straight(self) -> bool:
        """True for a grid of straight lines (``omega0``)."""
        return self.states is None and self.omega0 is not None

    @property
    def dims(self) -> tuple:
        """Names of the grid's axes (the dataset's dims before ``amplitude``)."""
        if self.states is not None:
            return ("point",)
        if self.straight:
            return ("h", "omega0")
        return ("h", "theta0", self.second)

    @property
    def shape(self) -> tuple:
        if self.states is not None:
            return (len(self.states),)
        if self.straight:
            return (len(self.h), len(self.omega0))
        return (len(self.h), len(self.theta0), len(getattr(self, self.second)))

    def coords(self) -> dict:
        """The grid's coordinates for an ``xarray.Dataset`` (straight lines also carry
        their tilt ``theta0`` along h)."""
        if self.states is not None:
            return {"theta_init": ("point", [s[0] for s in self.states])}
        if self.straight:
            return {"h": list(self.h), "omega0": list(self.omega0),
                    "theta0": ("h", [math.atan(x) for x in self.h])}
        return {"h": list(self.h), "theta0": list(self.theta0),
                self.second: list(getattr(self, self.second))}


@dataclass(frozen=True)
class _Spec:
    grid: SweepGrid
    perturbation: Perturbation
    t_end: float
    rtol: float
    atol: float
    max_steps: int
    chunk: int
    n: int = field(default=0)
    method: str = "taylor"

    def to_json(self) -> str:
        return json.dumps(asdict(self), sort_keys=True, allow_nan=False)


def _setup(spec: _Spec, i0: int, i1: int):
    """Initial states and closed-form columns of the flat points i0 ... i1 - 1."""
    from rollingdisk.theory import oscillations as _stability
    from rollingdisk.theory import steady as steady

    g = spec.grid
    p = spec.perturbation
    na = len(p.kick)
    idx = np.arange(i0, i1)
    a_i = idx % na
    q = idx // na
    n = i1 - i0
    x0 = np.full((n, 4), np.nan)
    h = np.empty(n)
    theta_ref = np.empty(n)
    varpi2 = np.full(n, np.nan)
    stable = np.full(n, -1, dtype=np.int8)
    kick = np.asarray(p.kick)[a_i]
    tilt = np.asarray(p.tilt)[a_i]
    if g.states is not None:
        s = np.asarray(g.states)[q]
        h[:] = g.h[0]
        x0[:] = s
        theta_ref[:] = s[:, 0]
        kick = np.zeros(n)
        tilt = np.zeros(n)
        return x0, h, theta_ref, varpi2, stable, np.full(n, np.nan)
    second = g.second
    vals = np.asarray(getattr(g, second))
    if g.straight:
        ih, iv = np.unravel_index(q, g.shape)
        it = ih
        thetas = [math.atan(x) for x in g.h]  # the SE tilt of each h (section 3.1)
    else:
        ih, it, iv = np.unravel_index(q, g.shape)
        thetas = g.theta0
    if second in ("omega30", "Omega0"):  # the whole chunk at once
        return _setup_circles(g, second, np.asarray(g.h)[ih], np.asarray(thetas)[it],
                              vals[iv], tilt, kick)
    for j in range(n):
        hh = g.h[ih[j]]
        th = thetas[it[j]]
        v = vals[iv[j]]
        h[j] = hh
        theta_ref[j] = th
        disk = Disk(hh)
        try:
            if second == "omega0":
                m = steady.straight_line(disk, g.ground, v)
                th = theta_ref[j] = m.theta0
            elif second == "omega30":
                if v == 0:
                    continue
                m = steady.steady_motion(disk, g.ground, th, Omega0=v / math.cos(th))
            elif second == "Omega0":
                if v == 0:
                    continue
                m = steady.steady_motion(disk, g.ground, th, Omega0=v)
            else:
                m = steady.steady_motion(disk, g.ground, th, r_C=v)
        except ValueError:  # NoSteadyMotion or no motion with these parameters
            continue
        x0[j] = (th + tilt[j], kick[j], m.omega20, m.omega30)
        w = _stability.stability(m).varpi2
        varpi2[j] = w
        stable[j] = 1 if w > 0 else 0
    a0 = np.abs(kick) + np.abs(tilt)
    return x0, h, theta_ref, varpi2, stable, a0


_METHODS = ("taylor", "dop853")


def _check_method(method) -> str:
    if method not in _METHODS:
        raise ParameterError(f"method must be one of {_METHODS}, got {method!r}")
    return method


def _kernel(method, rough, h, x0, theta_ref, a0, t_end, rtol, atol, max_steps):
    """Summaries (n, NCOL) of the trajectories from the rows of ``x0`` by ``method``: the
    batch Taylor kernel (order from min(rtol, atol),
    :func:`rollingdisk.integrate.taylor.taylor_order`)
    or the batch DOP853 kernel of :mod:`rollingdisk.integrate.batch`."""
    from rollingdisk.integrate import batch as core
    from rollingdisk.integrate.taylor import taylor_order

    k1 = _inertia(h)[0]  # eq. (10)
    k2 = np.full(k1.shape, 0.5)
    args = (rough, h, k1, k2, np.ascontiguousarray(x0), theta_ref, a0, GROW_LO, GROW_HI,
            t_end, rtol, atol, max_steps)
    if method == "taylor":
        return core.run_batch_taylor(*args, taylor_order(min(rtol, atol)))
    return core.run_batch(*args)


def _setup_circles(g, second, h, theta0, v, tilt, kick):
    """:func:`_setup` for circles given by omega30 or Omega0, element-wise on the chunk
    (eqs. 3, 28/34 through :func:`rollingdisk.theory.steady._omega20`, and eq. 40/51 through
    :func:`rollingdisk.theory.oscillations.varpi2_closed_form`): 26 -> 0.2 us a point, which
    kept the Python set-up from limiting the speed-up of the threads."""
    from rollingdisk.model.geometry import h_tilde
    from rollingdisk.theory import oscillations as _stability
    from rollingdisk.theory.steady import _omega20

    s, c = np.sin(theta0), np.cos(theta0)
    omega30 = v if second == "omega30" else v * c  # eq. (3)
    ht = h_tilde(h, theta0)
    with np.errstate(all="ignore"):
        omega20 = _omega20(g.ground, h, ht, s, c, omega30)
    # as steady_motion: Omega0 = 0 is no circle, theta0 = 0 is outside the theory for h > 0
    ok = (v != 0) & ~((h > 0) & (theta0 == 0)) & np.isfinite(omega20)
    n = h.size
    varpi2 = np.full(n, np.nan)
    varpi2[ok] = _stability.varpi2_closed_form(h[ok], g.ground, theta0[ok], omega20[ok],
                                               omega30[ok])
    ok &= np.isfinite(varpi2)
    varpi2[~ok] = np.nan
    x0 = np.full((n, 4), np.nan)
    x0[ok] = np.column_stack([theta0 + tilt, kick, omega20, omega30])[ok]
    stable = np.where(ok, (varpi2 > 0).astype(np.int8), -1).astype(np.int8)
    return x0, h, theta0.copy(), varpi2, stable, np.abs(kick) + np.abs(tilt)


def _compute_chunk(spec: _Spec, k: int, n_threads: int | None = None) -> dict:
    """Summaries of chunk k (a dict of 1-d arrays); deterministic."""
    from rollingdisk.integrate import batch as core

    if n_threads is not None:
        core.set_threads(n_threads)
    i0 = k * spec.chunk
    i1 = min(spec.n, i0 + spec.chunk)
    x0, h, theta_ref, varpi2, stable, a0 = _setup(spec, i0, i1)
    ok = np.all(np.isfinite(x0), axis=1)
    out = np.full((i1 - i0, core.NCOL), np.nan)
    if ok.any():
        a0o = np.where(np.isfinite(a0[ok]), a0[ok], 1.0)
        out[ok] = _kernel(spec.method, spec.grid.ground == "rough", h[ok], x0[ok],
                          theta_ref[ok], a0o, spec.t_end, spec.rtol, spec.atol, spec.max_steps)
    cols = dict(zip(core.COLUMNS, out.T))
    status = np.where(ok, cols["status"], 0).astype(np.int8)
    period = cols["period"]
    with np.errstate(all="ignore"):
        freq = 2 * np.pi / period
        growth = math.log(GROW_HI / GROW_LO) / (cols["t_grow_hi"] - cols["t_grow_lo"])
        bounded = (status == core.COMPLETED) & (cols["max_dtheta"] <= BOUND_FACTOR * a0)
    stable_sim = np.where(ok, bounded.astype(np.int8), -1).astype(np.int8)
    return {"varpi2": varpi2, "stable": stable, "status": status, "t_end": cols["t_end"],
            "max_dtheta": cols["max_dtheta"], "frequency": freq, "growth_rate": growth,
            "energy_drift": cols["energy_drift"], "n_crossings": cols["n_crossings"],
            "n_steps": cols["n_steps"], "stable_simulated": stable_sim, "amplitude0": a0}


def _write_chunk(folder: Path, k: int, res: dict) -> None:
    tmp = folder / f".chunk_{k:06d}.npz.tmp"
    with open(tmp, "wb") as fh:
        np.savez(fh, **res)
    os.replace(tmp, folder / f"chunk_{k:06d}.npz")  # the chunk's completion record


def _done_chunks(folder: Path) -> set:
    return {int(p.name[6:12]) for p in folder.glob("chunk_*.npz")}


def _dataset(spec: _Spec, cols: dict, executor: str):
    from importlib.metadata import version

    import xarray as xr

    from rollingdisk.integrate.batch import STATUS_NAMES

    __version__ = version("rollingdisk")

    g = spec.grid
    p = spec.perturbation
    na = len(p.kick)
    dims = (*g.dims, "amplitude")
    shape = (*g.shape, na)
    coords = g.coords()
    coords["kick"] = ("amplitude", list(p.kick))
    coords["tilt"] = ("amplitude", list(p.tilt))
    data = {k: (dims, np.asarray(v).reshape(shape)) for k, v in cols.items()}
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update({
        "ground": g.ground, "h": json.dumps(list(g.h)), "rtol": spec.rtol, "atol": spec.atol,
        "t_end_requested": spec.t_end, "max_steps": spec.max_steps, "method": spec.method,
        "rollingdisk_version": __version__, "executor": executor, "spec": spec.to_json(),
        "perturbation": json.dumps(asdict(p)),
        "status_codes": json.dumps({str(k): v for k, v in STATUS_NAMES.items()}
                                   | {"0": "no steady motion"}),
        "rules": (f"stable_simulated: completed and max_dtheta <= {BOUND_FACTOR} * "
                  f"(|tilt| + |kick|); growth_rate: ln({GROW_HI}/{GROW_LO})/(t_hi - t_lo); "
                  "frequency: 2 pi / least-squares period of upward crossings; -1 = none"),
    })
    return ds


def _save(ds, out: Path) -> None:
    from rollingdisk.util.files import atomic_dir, atomic_file

    if out.suffix == ".nc":
        with atomic_file(out, mode=None) as tmp:
            ds.to_netcdf(tmp)
    else:
        with atomic_dir(out) as tmp:
            ds.to_zarr(tmp, mode="w", consolidated=False)


def _check_out(out) -> Path:
    out = Path(os.fspath(out))
    if out.suffix not in (".zarr", ".nc"):
        raise ParameterError(f"out must end in .zarr or .nc, got {str(out)!r}")
    if not out.parent.is_dir():
        raise ParameterError(f"out: folder {str(out.parent)!r} does not exist")
    return out


def run_sweep(grid: SweepGrid, t_end: float, *, perturbation: Perturbation | None = None,
              out=None, executor: str = "serial", workers: int | None = None,
              dask_address: str | None = None, chunk: int = 2048, rtol: float = 1e-9,
              atol: float = 1e-9, max_steps: int = 1_000_000, method: str = "taylor",
              progress=None):
    """Integrate a perturbed steady motion from every grid point; an ``xarray.Dataset``.

    Parameters
    ----------
    grid : SweepGrid
    t_end : float
        Duration of each run (units sqrt(a/g)).
    perturbation : Perturbation, optional
        Default: kick 1e-3 in omega1.
    out : path, optional
        ``*.zarr`` or ``*.nc``.  Finished chunks are kept in ``out + ".partial"``; the store
        appears only once complete.  A rerun with the same arguments resumes.
    executor : {"serial", "threads", "dask"}
        ``serial``: one thread; ``threads``: numba threads over ``workers`` (default all)
        cores; ``dask``: ``dask.distributed`` tasks of ``chunk`` trajectories on a
        LocalCluster with ``workers`` processes, or on the scheduler ``dask_address``.
    rtol, atol : float
        Tolerances (for ``taylor`` the order is ``ceil(-ln min(rtol, atol) / 2) + 1``).
    max_steps : int
        Step budget per trajectory; a trajectory that exhausts it has status "failed".
    method : {"taylor", "dop853"}
        ``taylor`` (default): the batch Taylor kernel (:mod:`rollingdisk.integrate.taylor`; guards,
        crossings and thresholds located on the step polynomials, 2.0-2.1 times the
        trajectories per second of ``dop853``, docs/sweeps.md); ``dop853``: the batch
        DOP853 kernel (guards checked at step ends).
    progress : callable, optional
        ``progress(done, total, rate, eta)`` after each chunk (trajectories, per second,
        seconds).  An exception it raises interrupts the sweep (finished chunks are kept).

    Returns
    -------
    xarray.Dataset
        Dims ``(h, theta0, omega30|r_C|Omega0, amplitude)``, ``(h, omega0, amplitude)``
        for straight lines, or ``(point, amplitude)``;
        variables varpi2, stable (closed form, -1 where no steady motion), status, t_end,
        max_dtheta, frequency, growth_rate, energy_drift, stable_simulated, ... (module
        docstring for the rules).
    """
    if not isinstance(grid, SweepGrid):
        raise ParameterError("grid must be a SweepGrid")
    perturbation = perturbation or Perturbation()
    t_end = check_real("t_end", t_end, low=0.0, low_open=True, high=1e9)
    rtol = check_real("rtol", rtol, low=1e-15, high=1.0)
    atol = check_real("atol", atol, low=1e-300, high=1.0)
    if executor not in ("serial", "threads", "dask"):
        raise ParameterError(f"executor must be serial, threads or dask, got {executor!r}")
    if not (isinstance(chunk, int) and chunk >= 1):
        raise ParameterError("chunk must be an integer >= 1")
    if workers is not None and not (isinstance(workers, int) and workers >= 1):
        raise ParameterError("workers must be an integer >= 1")
    n = int(np.prod(grid.shape)) * len(perturbation.kick)
    _check_method(method)
    spec = _Spec(grid, perturbation, t_end, rtol, atol, int(max_steps), chunk, n, method)
    n_chunks = -(-n // chunk)
    folder = None
    done: set = set()
    results: dict = {}
    if out is not None:
        out = _check_out(out)
        folder = out.with_name(out.name + ".partial")
        if folder.exists():
            try:
                old = (folder / "spec.json").read_text()
            except OSError:
                old = None
            if old != spec.to_json():
                shutil.rmtree(folder)
        folder.mkdir(exist_ok=True)
        (folder / "spec.json").write_text(spec.to_json())
        done = _done_chunks(folder)
    todo = [k for k in range(n_chunks) if k not in done]
    t0 = time.perf_counter()
    count = [sum(min(n, (k + 1) * chunk) - k * chunk for k in done), 0]

    def finished(k, res):
        if folder is not None:
            _write_chunk(folder, k, res)
        else:
            results[k] = res
        m = min(n, (k + 1) * chunk) - k * chunk
        count[0] += m
        count[1] += m
        if progress is not None:
            dt = time.perf_counter() - t0
            rate = count[1] / dt if dt > 0 else float("nan")
            progress(count[0], n, rate, (n - count[0]) / rate if rate > 0 else float("nan"))

    if executor == "dask":
        _run_dask(spec, todo, workers, dask_address, finished)
    else:
        from rollingdisk.integrate import batch as core

        nt = 1 if executor == "serial" else workers
        with core.threads() as all_threads:
            for k in todo:
                finished(k, _compute_chunk(spec, k, nt if nt else all_threads))
    if folder is not None:
        parts = [dict(np.load(folder / f"chunk_{k:06d}.npz")) for k in range(n_chunks)]
    else:
        parts = [results[k] for k in range(n_chunks)]
    cols = {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}
    ds = _dataset(spec, cols, executor)
    if out is not None:
        _save(ds, out)
        shutil.rmtree(folder, ignore_errors=True)
    return ds


def _run_dask(spec, todo, workers, address, finished):
    from dask.distributed import Client, LocalCluster, as_completed

    cluster = None
    if address in (None, "local"):
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                               processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(address)
    try:
        futs = {client.submit(_compute_chunk, spec, k, 1, pure=False): k for k in todo}
        for fut in as_completed(futs):
            finished(futs[fut], fut.result())
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def open_sweep(path):
    """Open a finished sweep store (``.zarr`` or ``.nc``) as an ``xarray.Dataset``."""
    import xarray as xr

    path = Path(os.fspath(path))
    if not path.exists():
        raise ParameterError(f"path: no sweep at {str(path)!r}")
    if path.suffix == ".nc":
        return xr.load_dataset(path)
    return xr.open_zarr(path, consolidated=False).load()


def basin_sweep(grid: SweepGrid, t_end: float, *, kick_max: float = 1.0, rounds: int = 10,
                out=None, executor: str = "serial", workers: int | None = None,
                chunk: int = 2048, rtol: float = 1e-9, atol: float = 1e-9,
                max_steps: int = 1_000_000, method: str = "taylor", progress=None):
    """Finite-amplitude stability: per steady motion the largest kick in omega1 (bisection
    over ``[0, kick_max]``, ``rounds`` rounds, each round one batch over the whole grid)
    that still gives bounded motion (``stable_simulated``) over ``t_end``.

    ``method`` as in :func:`run_sweep`.  Returns an ``xarray.Dataset`` with ``kick_basin``
    (lower end of the final bracket; 0
    where even the first trial failed, ``kick_max`` where it never failed, NaN where there
    is no steady motion) and the closed-form ``varpi2``, ``stable``.
    """
    kick_max = check_real("kick_max", kick_max, low=0.0, low_open=True, high=100.0)
    if not (isinstance(rounds, int) and 1 <= rounds <= 60):
        raise ParameterError("rounds must be an integer in [1, 60]")
    _check_method(method)
    if grid.states is not None:
        raise ParameterError("basin_sweep needs a grid of steady motions, not states")
    shape = grid.shape
    lo = np.zeros(shape)
    hi = np.full(shape, kick_max)
    first = None
    # round 0 tests kick_max itself; then bisection
    trial = hi.copy()
    start = 0
    folder = None
    if out is not None:  # each finished round is kept: a rerun resumes after the last one
        out = _check_out(out)
        folder = out.with_name(out.name + ".partial")
        key = json.dumps({"grid": asdict(grid), "t_end": t_end, "kick_max": kick_max,
                          "rtol": rtol, "atol": atol, "max_steps": int(max_steps),
                          "method": method},
                         sort_keys=True, allow_nan=False)
        saved = _last_round(folder, key)
        if saved is not None:
            start, lo, hi, trial, first = saved
        else:
            if folder.exists():
                shutil.rmtree(folder)
            folder.mkdir()
            (folder / "basin.json").write_text(key)
    for r in range(start, rounds + 1):
        # one batch: every point with its own kick (the grid's states list)
        ds = _basin_round(grid, trial, t_end, executor, workers, chunk, rtol, atol, max_steps,
                          method)
        ok = ds["stable_simulated"].values.reshape(shape) == 1
        if first is None:
            first = {"stable": ds["stable"].values.reshape(shape),
                     "varpi2": ds["varpi2"].values.reshape(shape)}
            lo = np.where(ok, kick_max, 0.0)
            hi = np.where(ok, kick_max, kick_max)
        else:
            lo = np.where(ok, trial, lo)
            hi = np.where(ok, hi, trial)
        trial = 0.5 * (lo + hi)
        if folder is not None:
            tmp = folder / f".round_{r:03d}.npz.tmp"
            with open(tmp, "wb") as fh:
                np.savez(fh, lo=lo, hi=hi, trial=trial, **first)
            os.replace(tmp, folder / f"round_{r:03d}.npz")  # the round's completion record
        if progress is not None:
            progress(r + 1, rounds + 1, float("nan"), float("nan"))
    import xarray as xr

    st = first["stable"]
    basin = np.where(st >= 0, lo, np.nan)
    dims = grid.dims
    res = xr.Dataset(
        {"kick_basin": (dims, basin), "varpi2": (dims, first["varpi2"]),
         "stable": (dims, st)},
        coords=grid.coords())
    res.attrs.update({"ground": grid.ground, "t_end": t_end, "kick_max": kick_max,
                      "rounds": rounds, "rtol": rtol, "atol": atol, "method": method,
                      "rule": f"bounded: completed and max_dtheta <= {BOUND_FACTOR} * kick"})
    if out is not None:
        _save(res, out)
        shutil.rmtree(folder, ignore_errors=True)
    return res


def _last_round(folder: Path, key: str):
    """``(next round, lo, hi, trial, first)`` from the last finished round of a basin
    sweep with the same arguments (``key``), or None."""
    try:
        if (folder / "basin.json").read_text() != key:
            return None
    except OSError:
        return None
    rounds = sorted(folder.glob("round_*.npz"))
    if not rounds:
        return None
    with np.load(rounds[-1]) as z:
        first = {"stable": z["stable"], "varpi2": z["varpi2"]}
        return (int(rounds[-1].stem.split("_")[1]) + 1, z["lo"], z["hi"], z["trial"], first)


def _basin_round(grid, kicks, t_end, executor, workers, chunk, rtol, atol, max_steps,
                 method):
    """One batch: the steady state of every grid point with its own kick."""
    spec = _Spec(grid, Perturbation(kick=1.0), t_end, rtol, atol, int(max_steps), chunk,
                 int(np.prod(grid.shape)), method)
    x0, h, theta_ref, varpi2, stable, _ = _setup(spec, 0, spec.n)
    k = np.ravel(kicks)
    x0[:, 1] = k
    ok = np.all(np.isfinite(x0), axis=1)
    from rollingdisk.integrate import batch as core

    with core.threads(1 if executor == "serial" else workers):
        out = np.full((spec.n, core.NCOL), np.nan)
        if ok.any():
            out[ok] = _kernel(method, grid.ground == "rough", h[ok], x0[ok], theta_ref[ok],
                              k[ok], t_end, rtol, atol, max_steps)
    bounded = (out[:, 0] == core.COMPLETED) & (out[:, 2] <= BOUND_FACTOR * k)
    import xarray as xr

    return xr.Dataset({"stable_simulated": ("p", np.where(ok, bounded, False).astype(np.int8)),
                       "varpi2": ("p", varpi2), "stable": ("p", stable)})
