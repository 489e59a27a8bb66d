"""Formatting helpers shared by the commands: strict JSON values, aligned records, and
matplotlib without a display."""

from __future__ import annotations

import math

__all__ = ["finite_or_none", "print_record", "agg"]


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
    """``  key    value`` lines for the keys of ``record`` that are not None."""
    for key in keys:
        val = record.get(key)
        if val is None:
            continue
        print(f"  {key:16s} {val:.10g}" if isinstance(val, float) else f"  {key:16s} {val}")
