"""A sweep's stores: the resumable partial folder (one writer at a time), the dataset built
from its records with CF-style attributes, and the finished Zarr store or NetCDF file.

``OUT.partial/`` holds ``lock`` (the writer's lock and pid), a key file (``spec.json`` of
a sweep, ``basin.json`` of a basin sweep) and the finished records (``chunk_NNNNNN.npz``,
``round_NNN.npz``), each written under a temporary name and renamed: that rename is the
record's completion mark.  Only the process that holds the lock reads, resets or writes
the folder, so two runs into one ``out`` never mix their records: the second is refused
while the first runs.  The lock is :mod:`rollingdisk.util.lock`'s (an exclusive ``fcntl.flock``
on ``lock``, released by the kernel when its process dies).
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
from collections.abc import Iterator
from dataclasses import asdict
from pathlib import Path

import numpy as np

from rollingdisk.model.outcomes import outcome
from rollingdisk.sweep.grid import BOUND_FACTOR, GROW_HI, GROW_LO, _Spec
from rollingdisk.util import lock as _locks
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["open_sweep", "check_out", "partial_store", "PartialStore", "describe"]

#: The name of the lock file in a partial folder.
LOCK = "lock"


def check_out(out) -> Path:
    """``out`` as a Path ending in ``.zarr`` or ``.nc`` that a sweep may write: in an
    existing writable folder; a ``.zarr`` not a file, a FIFO or a device, and if it exists a
    Zarr store or an empty folder (it is replaced as a whole); a ``.nc`` not a folder."""
    from rollingdisk.util.files import check_writable

    try:
        out = Path(os.fspath(out))
    except TypeError:
        raise ParameterTypeError(f"out must be a path ending in .zarr or .nc, got "
                                 f"{type(out).__name__} {out!r}") from None
    if out.suffix not in (".zarr", ".nc"):
        raise ParameterError(f"out must end in .zarr or .nc, got {str(out)!r}")
    if not out.parent.is_dir():
        raise ParameterError(f"out: folder {str(out.parent)!r} does not exist")
    if len(out.name) > 200:
        raise ParameterError(f"out: the name is too long ({len(out.name)} characters, at "
                             "most 200 with the .partial folder beside it)")
    zarr = out.suffix == ".zarr"
    target = check_writable(out, name="out", folder=zarr)
    if zarr and target.is_dir():
        try:
            names = set(os.listdir(target))
        except OSError as exc:
            raise ParameterError(f"out: cannot read the folder {target}: "
                                 f"{exc.strerror or exc}") from None
        if names and not names & {".zgroup", ".zattrs", "zarr.json"}:
            raise ParameterError(f"out: {target} is a folder that is not a Zarr store and "
                                 "would be replaced as a whole; give a new name")
    return out


# ------------------------------------------------------------------------------ lock
def _busy(folder: Path, pid: int | None) -> ParameterError:
    who = f"pid {pid}" if pid is not None else "pid unknown"
    return ParameterError(
        f"out: {folder} is being written by another process ({who}); wait for it to "
        f"finish or choose another out (if no such process runs, delete {folder / LOCK})")


def _lock(folder: Path) -> int:
    """Lock ``folder`` (created if missing) for this process; an open fd of its lock file.

    Raises :class:`ParameterError` naming the owner's pid if another process holds it."""
    try:
        return _locks.acquire(folder / LOCK, make_folder=True)
    except _locks.Busy as busy:
        raise _busy(folder, busy.pid) from None


def _unlock(folder: Path, fd: int) -> None:
    _locks.release(folder / LOCK, fd)


# --------------------------------------------------------------------- partial store
class PartialStore:
    """The records of an unfinished run in ``OUT.partial/``, for the lock's holder."""

    def __init__(self, folder: Path, key: str):
        self.folder = folder
        self.key = key

    def done(self, prefix: str) -> list[int]:
        """Indices of the finished records ``prefix_NNN.npz``, sorted."""
        return sorted(int(p.stem[len(prefix) + 1:]) for p in self.folder.glob(f"{prefix}_*.npz"))

    def _path(self, prefix: str, k: int) -> Path:
        width = 6 if prefix == "chunk" else 3
        return self.folder / f"{prefix}_{k:0{width}d}.npz"

    def write(self, prefix: str, k: int, arrays: dict) -> None:
        """Record ``arrays`` (with the key they belong to) as ``prefix_k``."""
        target = self._path(prefix, k)
        tmp = self.folder / f".{target.name}.tmp"
        with open(tmp, "wb") as fh:
            np.savez(fh, _key=np.array(self.key), **arrays)
        os.replace(tmp, target)  # the record's completion mark

    def load(self, prefix: str, k: int) -> dict:
        """The arrays of record ``prefix_k``; refuses one written for another key."""
        with np.load(self._path(prefix, k)) as z:
            arrays = {name: z[name] for name in z.files}
        if str(arrays.pop("_key", "")) != self.key:
            raise ParameterError(f"out: {self._path(prefix, k)} was written by a different "
                                 f"run; delete {self.folder} and run again")
        return arrays

    def _reset(self, key_file: str) -> None:
        """Empty the folder (all but the lock) and write the key."""
        for p in self.folder.iterdir():
            if p.name == LOCK:
                continue
            if p.is_dir() and not p.is_symlink():
                shutil.rmtree(p)
            else:
                p.unlink()
        (self.folder / key_file).write_text(self.key)


@contextlib.contextmanager
def partial_store(out: Path, key: str, key_file: str) -> Iterator[PartialStore]:
    """Lock ``OUT.partial`` and yield it as a :class:`PartialStore` for ``key``.

    A folder left by a run with another key is emptied first.  On success the folder is
    removed; on an interruption (Ctrl-C, SIGTERM, a bug) it is kept when it holds
    finished records (a rerun resumes from them); on an input or output error
    (``ParameterError``, ``OSError``) and otherwise it is removed.  The lock is released
    in every case."""
    folder = out.with_name(out.name + ".partial")
    fd = _lock(folder)
    store = PartialStore(folder, key)
    keep = False
    try:
        try:
            old = (folder / key_file).read_text()
        except OSError:
            old = None
        if old != key:
            store._reset(key_file)
        yield store
    except BaseException as exc:
        # finished records of an interrupted run are kept: a rerun resumes from them; a
        # run that ended in an error (exit 2: bad input, an output that cannot be
        # written) leaves nothing behind
        keep = (not isinstance(exc, (ParameterError, ParameterTypeError, OSError))
                and bool(list(folder.glob("*.npz"))))
        raise
    finally:
        if not keep:
            shutil.rmtree(folder, ignore_errors=True)  # the lock file with it
        _unlock(folder, fd)


# --------------------------------------------------------------------------- dataset
_T = "sqrt(a/g)"  # the paper's time unit
_W = f"rad/{_T}"  # an angular velocity
#: (long_name, units) of every variable and coordinate a sweep writes.
ATTRS = {
    "h": ("half-thickness h", "a"),
    "theta0": ("steady tilt theta0", "rad"),
    "omega30": ("steady spin omega30", _W),
    "Omega0": ("steady turning rate Omega0", _W),
    "omega0": ("rolling rate omega0", _W),
    "r_C": ("radius r_C of the circle of C", "a"),
    "theta_init": ("initial tilt theta", "rad"),
    "kick": ("kick in omega1", _W),
    "tilt": ("tilt added to theta0", "rad"),
    "varpi2": ("varpi^2 (closed form)", "g/a"),  # 1/(time unit)^2
    "stable": ("stable (closed form)", "1"),
    "status": ("how the run ended", "1"),
    "t_end": ("time reached", _T),
    "max_dtheta": ("max |theta - theta0|", "rad"),
    "frequency": ("oscillation frequency", _W),
    "growth_rate": ("envelope growth rate", f"1/{_T}"),
    "energy_drift": ("relative energy drift", "1"),
    "n_crossings": ("upward crossings of theta0", "1"),
    "n_steps": ("accepted steps", "1"),
    "stable_simulated": ("bounded (simulated)", "1"),
    "amplitude0": ("initial amplitude |tilt| + |kick|", "1"),
    "kick_basin": ("largest bounded kick in omega1", _W),
}
#: CF flags of the integer variables: (values, names).  -1: no steady motion.
_NO_MOTION = outcome("no-steady-motion")
FLAGS = {
    "stable": ((-1, 0, 1), (_NO_MOTION.name, "unstable", "stable")),
    "stable_simulated": ((-1, 0, 1), (_NO_MOTION.name, "unbounded", "bounded")),
}


def _status_flags():
    from rollingdisk.sweep.batch import STATUS_NAMES

    codes = (_NO_MOTION.code, *sorted(STATUS_NAMES))
    return codes, tuple(outcome(c).name for c in codes)


def describe(ds):
    """Give every variable and coordinate of ``ds`` its CF ``long_name`` and ``units``
    (:data:`ATTRS`) and the integer variables their ``flag_values`` / ``flag_meanings``
    (names from :mod:`rollingdisk.model.outcomes`, ``-`` written ``_``); returns ``ds``."""
    flags = dict(FLAGS, status=_status_flags())
    for name, var in ds.variables.items():
        if name in ATTRS:
            var.attrs["long_name"], var.attrs["units"] = ATTRS[name]
        if name in flags:
            values, meanings = flags[name]
            var.attrs["flag_values"] = np.array(values, dtype=var.dtype)
            var.attrs["flag_meanings"] = " ".join(m.replace("-", "_") for m in meanings)
    return ds


def build_dataset(spec: _Spec, cols: dict, executor: str, n_computed: int):
    """The sweep's ``xarray.Dataset`` from its concatenated columns, described."""
    from importlib.metadata import version

    from rollingdisk.results.xrload import xr

    g = spec.grid
    p = spec.perturbation
    dims = (*g.dims, "amplitude")
    shape = (*g.shape, len(p.kick))
    coords = g.coords()
    coords["kick"] = ("amplitude", list(p.kick))
    coords["tilt"] = ("amplitude", list(p.tilt))
    data = {k: (dims, np.asarray(v).reshape(shape)) for k, v in cols.items()}
    ds = xr.Dataset(data, coords=coords)
    codes, names = _status_flags()
    ds.attrs.update({
        "ground": g.ground, "h": json.dumps(list(g.h)), "rtol": spec.rtol, "atol": spec.atol,
        "t_end_requested": spec.t_end, "max_steps": spec.max_steps, "method": spec.method,
        "rollingdisk_version": version("rollingdisk"), "executor": executor,
        "spec": spec.to_json(), "perturbation": json.dumps(asdict(p)),
        "n_computed": n_computed, "time_unit": "sqrt(a/g) (a: radius, g: gravity)",
        "status_codes": json.dumps({str(c): m for c, m in zip(codes, names)}),
        "rules": (f"stable_simulated: completed and max_dtheta <= {BOUND_FACTOR} * "
                  f"(|tilt| + |kick|); growth_rate: ln({GROW_HI}/{GROW_LO})/(t_hi - t_lo); "
                  "frequency: 2 pi / least-squares period of upward crossings; -1 = none"),
    })
    return describe(ds)


def save(ds, out: Path) -> None:
    """Write ``ds`` to ``out`` (NetCDF or Zarr with consolidated metadata), atomically."""
    from rollingdisk.util.files import atomic_dir, atomic_file

    if out.suffix == ".nc":
        with atomic_file(out, mode=None) as tmp:
            ds.to_netcdf(tmp)
    else:
        import zarr

        # Zarr format 2: its consolidated metadata is part of the spec (zarr 3 warns that
        # format 3's is not), and every Zarr reader opens it
        fmt = {"zarr_format": 2} if int(zarr.__version__.split(".")[0]) >= 3 else {}
        with atomic_dir(out) as tmp:
            ds.to_zarr(tmp, mode="w", consolidated=True, **fmt)


def open_sweep(path):
    """Open a finished sweep store (``.zarr`` or ``.nc``) as an ``xarray.Dataset``."""
    from rollingdisk.results.xrload import xr

    path = Path(os.fspath(path))
    try:
        if not path.exists():
            raise ParameterError(f"path: no sweep at {str(path)!r}")
        if path.suffix == ".nc":
            return xr.load_dataset(path)
        return xr.open_zarr(path).load()
    except (OSError, KeyError, ValueError) as exc:  # a name too long, or not a sweep store
        if isinstance(exc, ParameterError):
            raise
        raise ParameterError(f"path: {str(path)[:80]!r} is no sweep store we can read "
                             f"({type(exc).__name__}: {str(exc)[:120]})") from None
