"""Symbolic derivation of the equations of motion (sympy) and the check of the paper.

Outside the numeric core: nothing in the core imports this package.

- :mod:`.derivation`: Newton-Euler from first principles (frames, inertia, contact point,
  balances, reduced systems on rough and smooth ground).
- :mod:`.paper`: the printed equations of section 2, (37), (38), (49), compared with it.
"""

from __future__ import annotations

import sys

from .derivation import Derivation, derive, lambdified
from .paper import EquationCheck, checks_sections_1_2

__all__ = ["Derivation", "EquationCheck", "check_equations", "derive", "format_table",
           "lambdified"]


def check_equations(progress: bool = False) -> list[EquationCheck]:
    """Derive the equations and check every printed equation against the derivation.

    Parameters
    ----------
    progress : bool
        Print what is being done to stderr (the derivation takes several seconds).
    """
    if progress:
        print("deriving the equations of motion (Newton-Euler, sympy) ...", file=sys.stderr)
    derive()
    if progress:
        print("checking eqs. (1)-(13), (37), (38), (49) ...", file=sys.stderr)
    return list(checks_sections_1_2())


def format_table(rows: list[EquationCheck]) -> str:
    """A plain-text table of the checks, one row per equation."""
    head = f"{'eq.':<6} {'status':<10} {'quantity':<52} evidence"
    lines = [head, "-" * len(head)]
    for r in rows:
        lines.append(f"{r.equation:<6} {r.status:<10} {r.quantity:<52} {r.evidence}")
        if r.status != "confirmed":
            lines.append(f"{'':<17}printed: {r.printed}")
            lines.append(f"{'':<17}correct: {r.correct}")
    n_bad = sum(r.status != "confirmed" for r in rows)
    lines.append(f"{len(rows)} equations checked: {len(rows) - n_bad} confirmed, "
                 f"{n_bad} misprinted")
    return "\n".join(lines)
