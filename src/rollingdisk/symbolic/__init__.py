"""Symbolic derivation of the equations of motion (sympy) and the check of the paper.

Outside the numeric core: nothing in the core imports this package.

- :mod:`.derivation`: Newton-Euler from first principles (frames, inertia, contact point,
  balances, reduced systems on rough and smooth ground).
- :mod:`.identity`: the one identity test (random rational points, 50 digits) every
  comparison uses.
- :mod:`.rows`: the one row type of the errata table, :class:`EquationCheck`, and the rule
  that turns a comparison into a status.
- :mod:`.paper`: the printed equations of section 2, (37), (38), (49), compared with it.
- :mod:`.printed`: the printed statements of sections 3-4 (equations and quoted numbers).
- :mod:`.sections34`: sections 3-4 (steady motions, stability) re-derived from it, the
  registry of checks and the generated part of docs/errata.md; :mod:`.checks3` and
  :mod:`.checks4` hold the checks, one registered function per statement of :mod:`.printed`.

- :mod:`.rounded`: the disk with a rounded rim (Routh's body of revolution): Newton-Euler,
  checked by Lagrange's equations with multipliers, and its inertia by integration.
- :mod:`.report`: :func:`check_equations` and :func:`format_table`, what ``rollingdisk derive``
  prints.

"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "Derivation": "rollingdisk.symbolic.derivation",
    "EquationCheck": "rollingdisk.symbolic.rows",
    "check_equations": "rollingdisk.symbolic.report",
    "derive": "rollingdisk.symbolic.derivation",
    "format_table": "rollingdisk.symbolic.report",
    "lambdified": "rollingdisk.symbolic.derivation",
    "derive_rounded": "rollingdisk.symbolic.rounded",
    "lagrange_rounded": "rollingdisk.symbolic.rounded",
    "rounded_inertia": "rollingdisk.symbolic.rounded",
})
