"""The whole check of the paper, run and printed: what ``rollingdisk derive`` shows."""

from __future__ import annotations

import sys

from .derivation import derive
from .paper import checks_sections_1_2
from .rows import EquationCheck

__all__ = ["check_equations", "format_table"]


def check_equations(progress: bool = False, sections: str = "all") -> list[EquationCheck]:
    """Derive the equations and check every printed equation against the derivation.

    Parameters
    ----------
    progress : bool
        Print what is being done to stderr (the whole check takes about half a minute).
    sections : {"all", "2"}
        ``"2"``: eqs. (1)-(13), (37), (38), (49) only; ``"all"`` adds sections 3-4.
    """
    if sections not in ("all", "2"):
        raise ValueError(f"sections must be 'all' or '2', got {sections!r}")
    if progress:
        print("deriving the equations of motion (Newton-Euler, sympy) ...", file=sys.stderr)
    derive()
    if progress:
        print("checking eqs. (1)-(13), (37), (38), (49) ...", file=sys.stderr)
    rows = list(checks_sections_1_2())
    if sections == "all":
        from .sections34 import checks_sections_3_4

        if progress:
            print("checking sections 3-4: eqs. (15)-(59) and the quoted numbers ...",
                  file=sys.stderr)
        rows += checks_sections_3_4()
    return rows


def format_table(rows: list[EquationCheck]) -> str:
    """A plain-text table of the checks, one row per equation."""
    width = max(len(r.equation) for r in rows)
    head = f"{'eq.':<{width}} {'status':<10} what / evidence"
    lines = [head, "-" * 100]
    for r in rows:
        text = f"{r.quantity}: {r.evidence}" if r.quantity else r.evidence
        text = text if len(text) <= 110 else text[:107] + "..."
        lines.append(f"{r.equation:<{width}} {r.status:<10} {text}")
        if r.status != "confirmed":
            lines.append(f"{'':<{width + 12}}printed: {r.printed}")
            lines.append(f"{'':<{width + 12}}correct: {r.correct}")
    n_bad = sum(r.status == "misprint" for r in rows)
    n_open = sum(r.status == "unresolved" for r in rows)
    lines.append(f"{len(rows)} equations checked: {len(rows) - n_bad - n_open} confirmed, "
                 f"{n_bad} misprinted" + (f", {n_open} UNRESOLVED" if n_open else "")
                 + " (details and evidence: docs/errata.md)")
    return "\n".join(lines)
