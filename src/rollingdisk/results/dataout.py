"""Data out: a run as an ``xarray.Dataset`` or a ``pandas.DataFrame``, every variable with
``units`` and ``long_name`` (CF conventions), in SI when the disk has a physical scale.

Used by :meth:`rollingdisk.Trajectory.to_xarray` / :meth:`~rollingdisk.Trajectory.to_dataframe`
(and so by the Coulomb runs, which are trajectories) and by
:class:`rollingdisk.scenarios.euler_disk.EulerDiskResult`.  A variable is converted to SI
when the disk's scale allows it (times, lengths, speeds need the radius; forces the mass;
energies both); otherwise it stays in the paper's units and its ``units`` attribute names
them (``"sqrt(a/g)"``, ``"a"``, ``"m g"``, ...).  xarray and pandas are imported only here,
when called.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.model.units import KINDS, can_convert, to_si
from rollingdisk.util.errors import ParameterTypeError

__all__ = ["TRAJECTORY_VARIABLES", "variable_info", "convert_columns", "column_units",
           "csv_header", "to_xarray", "to_dataframe"]

#: Columns of a trajectory (:meth:`rollingdisk.Trajectory.as_columns`): name -> (kind of
#: quantity, a key of :data:`rollingdisk.model.units.KINDS`; long name).
TRAJECTORY_VARIABLES = {
    "t": ("time", "time"),
    "X_C": ("length", "centre C, X in the inertial frame OXYZ"),
    "Y_C": ("length", "centre C, Y in the inertial frame OXYZ"),
    "psi": ("angle", "spin angle psi (eq. 1)"),
    "theta": ("angle", "inclination theta (eq. 1)"),
    "phi": ("angle", "rotation angle phi (eq. 1)"),
    "omega1": ("angular_speed", "angular velocity omega1 in C xi eta zeta (eq. 2)"),
    "omega2": ("angular_speed", "angular velocity omega2 in C xi eta zeta (eq. 3)"),
    "omega3": ("angular_speed", "angular velocity omega3 in C xi eta zeta (eq. 3)"),
    "X_P": ("length", "contact point P, X on the plane (eq. 5)"),
    "Y_P": ("length", "contact point P, Y on the plane (eq. 5)"),
    "F_x": ("force", "contact force F_x in Cxyz (eq. 8)"),
    "F_y": ("force", "contact force F_y in Cxyz (eq. 8)"),
    "F_z": ("force", "normal force F_z (eq. 11)"),
    "E": ("energy", "mechanical energy (eq. 13)"),
    "V_X": ("speed", "velocity of C, V_X in OXYZ"),
    "V_Y": ("speed", "velocity of C, V_Y in OXYZ"),
    "mode": ("dimensionless", "contact mode on Coulomb ground (0 rolling, 1 sliding)"),
}


def variable_info(name: str, table: dict | None = None) -> tuple[str, str]:
    """``(kind, long_name)`` of a column; ``dissipated_<term>`` columns are energies."""
    table = TRAJECTORY_VARIABLES if table is None else table
    if name in table:
        return table[name]
    if name.startswith("dissipated_"):
        return "energy", f"energy dissipated so far by {name[len('dissipated_'):]} (eq. 12)"
    return "dimensionless", name


def _use_si(disk, si) -> bool:
    if si is None:
        return disk is not None and getattr(disk, "radius", None) is not None
    return bool(si)


def column_units(columns, disk, si: bool | None = None, table: dict | None = None) -> dict:
    """Column name -> unit: SI where ``si`` (default: when the disk has a radius) and the
    disk's scale converts that kind, the paper's unit otherwise."""
    use = _use_si(disk, si)
    out = {}
    for name in columns:
        kind = variable_info(name, table)[0]
        out[name] = KINDS[kind][1] if use and can_convert(disk, kind) else KINDS[kind][0]
    return out


def convert_columns(cols: dict, disk, si: bool | None = None, table: dict | None = None
                    ) -> dict:
    """``cols`` with each column converted to SI where :func:`column_units` says SI."""
    use = _use_si(disk, si)
    out = {}
    for name, v in cols.items():
        kind = variable_info(name, table)[0]
        if use and kind not in ("angle", "dimensionless") and can_convert(disk, kind):
            out[name] = np.asarray(to_si(disk, kind, np.asarray(v, dtype=float)))
        else:
            out[name] = np.asarray(v)
    return out


def csv_header(columns, disk, si: bool | None = False, table: dict | None = None) -> str:
    """A CSV header with units: ``t [sqrt(a/g)],X_C [a],...`` (``si=False``, the default:
    the values of :meth:`~rollingdisk.Trajectory.as_columns`) or ``t [s],X_C [m],...``
    (``si=True``: the values of ``as_columns(si=True)``)."""
    units = column_units(columns, disk, si, table)
    return ",".join(f"{n} [{u}]" for n, u in units.items())


def _attrs(disk, extra: dict) -> dict:
    attrs = {"h": float(disk.h)} if disk is not None else {}
    for name in ("radius", "mass", "gravity"):
        v = getattr(disk, name, None)
        if v is not None:
            attrs[f"{name}_si"] = float(v)
    attrs["units_system"] = ("SI where the disk's physical scale allows, else the paper's "
                             "units (m = a = g = 1)")
    for k, v in extra.items():
        if v is None:
            continue
        attrs[k] = v if isinstance(v, (str, int, float)) else str(v)
    return attrs


def to_xarray(cols: dict, disk, *, si: bool | None = None, table: dict | None = None,
              attrs: dict | None = None):
    """An ``xarray.Dataset`` of the columns, along the dimension ``t`` (a coordinate);
    ``units`` and ``long_name`` on every variable; ``mode`` with CF flags.

    Parameters
    ----------
    cols : dict
        Column name -> 1-D array (must contain ``"t"``).
    disk : Disk or None
        Its scale converts the variables (see :func:`column_units`).
    si : bool, optional
        ``None`` (default): SI when the disk has a radius; ``False``: the paper's units.
    table : dict, optional
        Name -> ``(kind, long_name)``; :data:`TRAJECTORY_VARIABLES` by default.
    attrs : dict, optional
        Dataset attributes (ground, status, ...), added to the disk's.
    """
    import xarray as xr

    if "t" not in cols:
        raise ParameterTypeError("cols must contain the times 't'")
    conv = convert_columns(cols, disk, si, table)
    units = column_units(cols, disk, si, table)
    t = conv.pop("t")
    ds = xr.Dataset(coords={"t": ("t", t, {"units": units["t"],
                                           "long_name": variable_info("t", table)[1],
                                           "standard_name": "time"})})
    for name, v in conv.items():
        var_attrs = {"units": units[name], "long_name": variable_info(name, table)[1]}
        if name == "mode":
            var_attrs.update(flag_values=[0, 1], flag_meanings="rolling sliding")
            var_attrs["units"] = "1"
        ds[name] = ("t", v, var_attrs)
    ds.attrs.update(_attrs(disk, attrs or {}))
    return ds


def to_dataframe(cols: dict, disk, *, si: bool | None = None, table: dict | None = None,
                 attrs: dict | None = None):
    """A ``pandas.DataFrame`` of the columns (one row per stored point, ``t`` a column),
    with ``df.attrs["units"]`` and ``df.attrs["long_name"]`` naming every column, and
    the run's attributes; as :func:`to_xarray` for the conversions."""
    import pandas as pd

    conv = convert_columns(cols, disk, si, table)
    df = pd.DataFrame(conv)
    df.attrs.update(_attrs(disk, attrs or {}))
    df.attrs["units"] = column_units(cols, disk, si, table)
    if "mode" in df.attrs["units"]:
        df.attrs["units"]["mode"] = "1"
    df.attrs["long_name"] = {n: variable_info(n, table)[1] for n in cols}
    return df
