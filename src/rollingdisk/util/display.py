"""How results show themselves: short one-line reprs and small HTML tables for notebooks.

Plain strings only (no numpy arrays in a repr, nothing over :data:`MAX_REPR` characters);
:func:`rollingdisk.model.units.result_html` puts units and SI values into the tables.
"""

from __future__ import annotations

import html
import math
import numbers

__all__ = ["MAX_REPR", "fmt", "short_repr", "html_table"]

#: The longest repr a result may have (characters).
MAX_REPR = 1000


def fmt(value, digits: int = 6) -> str:
    """A value for a repr or a table cell: numbers to ``digits`` significant digits, ``None``
    as ``None``, arrays as their shape, long strings cut."""
    if value is None:
        return "None"
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        return repr(x) if not math.isfinite(x) else f"{x:.{digits}g}"
    shape = getattr(value, "shape", None)
    if shape is not None:
        return f"array{tuple(shape)}"
    if isinstance(value, (tuple, list)):
        inner = ", ".join(fmt(v, digits) for v in value[:6])
        more = ", ..." if len(value) > 6 else ""
        return f"({inner}{more})" if isinstance(value, tuple) else f"[{inner}{more}]"
    if isinstance(value, dict):
        inner = ", ".join(f"{k}: {fmt(v, digits)}" for k, v in list(value.items())[:6])
        return "{" + inner + (", ..." if len(value) > 6 else "") + "}"
    text = str(value)
    return text if len(text) <= 120 else text[:117] + "..."


def short_repr(name: str, items: dict) -> str:
    """``Name(a=1.5, b='x', ...)``, cut to :data:`MAX_REPR` characters."""
    parts = []
    for k, v in items.items():
        parts.append(f"{k}={v!r}" if isinstance(v, str) and len(v) <= 80 else f"{k}={fmt(v)}")
    out = f"{name}({', '.join(parts)})"
    return out if len(out) <= MAX_REPR else out[:MAX_REPR - 4] + "...)"


def html_table(title: str, header: tuple, rows: list, note: str | None = None) -> str:
    """A small HTML table: a caption, one header row, one row per quantity.

    Parameters
    ----------
    title : str
        The caption (escaped).
    header : tuple of str
        Column names.
    rows : list of tuple
        Cells, formatted by :func:`fmt` unless already strings.
    note : str, optional
        A line under the table (escaped).
    """
    esc = html.escape
    head = "".join(f"<th style='text-align:left'>{esc(str(h))}</th>" for h in header)
    body = []
    for row in rows:
        cells = "".join(f"<td>{esc(c if isinstance(c, str) else fmt(c))}</td>" for c in row)
        body.append(f"<tr>{cells}</tr>")
    foot = f"<p style='font-size:smaller'>{esc(note)}</p>" if note else ""
    return (f"<div><table><caption style='text-align:left'><b>{esc(title)}</b></caption>"
            f"<thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>{foot}</div>")
