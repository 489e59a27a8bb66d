"""The arguments of :func:`~rollingdisk.sweep.run_sweep` and
:func:`~rollingdisk.sweep.basin_sweep`, checked at the boundary by one validator.

Every argument is checked before any work (no partial folder, no cluster, no compiled
kernel): a wrong type raises :class:`~rollingdisk.util.errors.ParameterTypeError`, a
wrong value :class:`~rollingdisk.util.errors.ParameterError`, each naming the argument and
what it may be.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from rollingdisk.engine.methods import check_method
from rollingdisk.sweep.executors import EXECUTORS, METHODS
from rollingdisk.sweep.grid import Perturbation, SweepGrid
from rollingdisk.sweep.store import check_out
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["RunOptions", "check_run_options", "T_END_MAX", "MAX_STEPS_MAX"]

#: Longest run (units sqrt(a/g)) and largest step budget a sweep accepts.
T_END_MAX = 1e9
MAX_STEPS_MAX = 10 ** 12


@dataclass(frozen=True)
class RunOptions:
    """The checked options of one sweep (see :func:`rollingdisk.sweep.run_sweep`)."""

    t_end: float
    out: Path | None
    executor: str
    workers: int | None
    dask_address: str | None
    chunk: int
    rtol: float
    atol: float
    max_steps: int
    method: str


def _choice(name: str, value, allowed: tuple) -> str:
    if not isinstance(value, str):
        raise ParameterTypeError(f"{name} must be one of {allowed}, got "
                                 f"{type(value).__name__} {value!r}")
    if value not in allowed:
        raise ParameterError(f"{name} must be one of {allowed}, got {value!r}")
    return value


def check_run_options(grid, t_end, *, out=None, executor="serial", workers=None,
                      dask_address=None, chunk=2048, rtol=1e-9, atol=1e-9,
                      max_steps=1_000_000, method="taylor", progress=None,
                      executors: tuple = EXECUTORS) -> RunOptions:
    """Check the arguments shared by ``run_sweep`` and ``basin_sweep``.

    Ranges: ``t_end`` in (0, 1e9]; ``rtol`` in [1e-15, 1]; ``atol`` in [1e-300, 1];
    ``max_steps`` an integer in [1, 1e12]; ``chunk`` an integer in [1, 1e8]; ``workers``
    None or an integer in [1, 4096]; ``executor`` one of ``executors``; ``dask_address``
    None or a string, with ``executor="dask"`` only; ``method`` one of ("taylor",
    "dop853"); ``progress`` None or callable; ``out`` None or a path ending in ``.zarr``
    or ``.nc`` in an existing folder.
    """
    if not isinstance(grid, SweepGrid):
        raise ParameterTypeError(f"grid must be a SweepGrid, got {type(grid).__name__}")
    executor = _choice("executor", executor, executors)
    if dask_address is not None:
        if not isinstance(dask_address, str):
            raise ParameterTypeError(f"dask_address must be a string such as "
                                     f"'tcp://host:8786' or None, got {dask_address!r}")
        if executor != "dask":
            raise ParameterError(f"dask_address is for executor 'dask', not {executor!r}")
    if progress is not None and not callable(progress):
        raise ParameterTypeError(f"progress must be callable or None, got "
                                 f"{type(progress).__name__}")
    return RunOptions(
        t_end=check_real("t_end", t_end, low=0.0, low_open=True, high=T_END_MAX),
        out=None if out is None else check_out(out),
        executor=executor,
        workers=None if workers is None else check_int("workers", workers, low=1, high=4096),
        dask_address=dask_address,
        chunk=check_int("chunk", chunk, low=1, high=10 ** 8),
        rtol=check_real("rtol", rtol, low=1e-15, high=1.0),
        atol=check_real("atol", atol, low=1e-300, high=1.0),
        max_steps=check_int("max_steps", max_steps, low=1, high=MAX_STEPS_MAX),
        method=check_method(method, METHODS),
    )


def check_perturbation(perturbation) -> Perturbation:
    """``perturbation`` or the default kick 1e-3 in omega1 for None."""
    if perturbation is None:
        return Perturbation()
    if not isinstance(perturbation, Perturbation):
        raise ParameterTypeError(f"perturbation must be a Perturbation or None, got "
                                 f"{type(perturbation).__name__}")
    return perturbation
