"""Formatting helpers shared by the commands: strict JSON values, aligned records with
their SI values beside them, the disk's physical scale, and matplotlib without a display."""

from __future__ import annotations

import math

__all__ = ["finite_or_none", "print_record", "agg", "has_scale", "disk_fields", "with_si",
           "si_text", "disk_line", "progress_bar", "numeric_warnings"]


class numeric_warnings:  # noqa: N801 - used as a context manager, like catch_warnings
    """Collect the numeric warnings of a run (``RuntimeWarning``, ``UserWarning`` and their
    kind: numpy's overflow, scipy's LSODA and quad) instead of letting them print, so that
    the result says what happened: :attr:`lines`, one per distinct warning, go into the
    record as ``"warnings"``.  Other warnings are left to the filters in force."""

    def __enter__(self):
        import warnings

        self.lines: list[str] = []
        self._catch = warnings.catch_warnings()
        self._catch.__enter__()
        show = warnings.showwarning

        def record(message, category, filename, lineno, file=None, line=None):
            if issubclass(category, (RuntimeWarning, UserWarning)):
                text = f"{category.__name__}: {' '.join(str(message).split())}"
                if text not in self.lines:
                    self.lines.append(text)
            else:
                show(message, category, filename, lineno, file, line)

        warnings.showwarning = record
        for kind in (RuntimeWarning, UserWarning):
            warnings.simplefilter("always", kind)
        return self

    def __exit__(self, *exc):
        return self._catch.__exit__(*exc)


def finite_or_none(value):
    """``value``, or None for a non-finite float (strict JSON)."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def agg() -> None:
    """matplotlib without a display (the command line writes files only)."""
    import matplotlib

    matplotlib.use("Agg")


def print_record(record: dict, keys) -> None:
    """``  key    value`` lines for the keys of ``record`` that are not None; where the
    record has ``<key>_si`` (and a ``"units"`` map, :func:`with_si`), the SI value and unit
    beside the value, and the value's own unit."""
    units = record.get("units") or {}
    for key in keys:
        val = record.get(key)
        if val is None:
            continue
        text = f"{val:.10g}" if isinstance(val, float) else f"{val}"
        si = record.get(f"{key}_si")
        if si is not None and not isinstance(si, (dict, list)):
            own = units.get(key)
            own = f" {own}" if own and own != "1" else ""
            print(f"  {key:16s} {si_text(si, units.get(f'{key}_si', '')):>18s}   "
                  f"({text}{own})")
        else:
            print(f"  {key:16s} {text}")


def has_scale(disk) -> bool:
    """Whether ``disk`` has a physical size (a radius): then answers come in SI too."""
    return disk is not None and getattr(disk, "radius", None) is not None


def disk_fields(disk) -> dict:
    """The disk's physical scale as JSON fields, ``radius_si`` [m], ``thickness_si`` [m],
    ``mass_si`` [kg], ``gravity_si`` [m/s^2] (those it has), and their ``"units"``; ``{}``
    for a disk without a size."""
    if not has_scale(disk):
        return {}
    out = {"radius_si": disk.radius, "thickness_si": 2.0 * disk.h * disk.radius}
    units = {"radius_si": "m", "thickness_si": "m"}
    if disk.mass is not None:
        out["mass_si"] = disk.mass
        units["mass_si"] = "kg"
    out["gravity_si"] = disk.gravity
    units["gravity_si"] = "m/s^2"
    out["units"] = units
    return out


def with_si(record: dict, *views: dict) -> dict:
    """``record`` with the ``<name>_si`` fields of the SI ``views`` (``to_si()`` results,
    :func:`disk_fields`) added, and one ``"units"`` map merging theirs.  Non-finite floats
    become None (strict JSON)."""
    out = dict(record)
    units = dict(out.pop("units", None) or {})
    for view in views:
        for k, v in view.items():
            if k == "units":
                units.update(v)
            elif k.endswith("_si"):
                out[k] = _plain(v)
    out["units"] = units
    return out


def _plain(v):
    """A number (numpy scalar, list) as a plain finite float or None, for JSON."""
    if v is None or isinstance(v, (bool, str)):
        return v
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    try:
        return finite_or_none(float(v))
    except (TypeError, ValueError):
        return v


def si_text(value, unit: str) -> str:
    """``"0.1973 m/s"``: a value with its SI unit, 4 significant digits unless small."""
    if value is None:
        return "-"
    return f"{float(value):.6g} {unit}".rstrip()


def disk_line(disk) -> str:
    """One line naming the disk's physical size, e.g. ``disk: radius 11.625 mm, thickness
    2.33 mm (h = 0.1002), mass 7.5 g, gravity 9.80665 m/s^2``; ``""`` without a size."""
    if not has_scale(disk):
        return ""
    parts = [f"radius {disk.radius * 1e3:.6g} mm",
             f"thickness {2e3 * disk.h * disk.radius:.6g} mm (h = {disk.h:.6g})"]
    if disk.mass is not None:
        parts.append(f"mass {disk.mass * 1e3:.6g} g")
    parts.append(f"gravity {disk.gravity:.6g} m/s^2")
    return "disk: " + ", ".join(parts)


def progress_bar(args):
    """The progress bar of a command's run on stderr: drawn only on a terminal, or with
    ``--progress``; never with ``--quiet`` or ``--json`` (:func:`~rollingdisk.cli._args.
    show_progress`)."""
    from rollingdisk.cli._args import show_progress
    from rollingdisk.util.progress import ProgressBar

    return ProgressBar(quiet=not show_progress(args))
