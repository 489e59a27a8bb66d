"""Sections 3-4 re-derived with sympy and checked, one registered check per printed statement.

Owns the derived quantities of sections 3-4 (:func:`derived`, :func:`kinematics`), the
registry of checks (:func:`check` registers a small function under a key of
:data:`rollingdisk.symbolic.printed.PRINTED`; the functions live in :mod:`.checks3` and
:mod:`.checks4`), :func:`checks_sections_3_4` and :func:`run` that run them, and the generated
part of docs/errata.md (:func:`errata_markdown`, :func:`write_errata`).

Everything starts from the Newton-Euler derivation of :mod:`rollingdisk.symbolic.derivation`
(independent of the paper).  The kinematics of section 3 ((15)-(25)) come from its frame
rates, contact point and balances at a constant state; from its reduced equations this module
derives

* the steady-motion condition: ``d omega1/dt = 0`` at ``omega1 = 0``;
* ``varpi^2``: the linearization of the reduced system ``(theta, omega1, omega2, omega3)`` at
  a steady state has the characteristic polynomial ``lambda^2 (lambda^2 + varpi^2)`` with
  ``varpi^2 = -(d1_theta + d1_omega2 a2 + d1_omega3 a3)``, ``a_k = d(omega_k dot)/d omega1``.

A check compares the printed form with the derived one (:mod:`.identity`: random rational
points, 50 digits) or a quoted number with the one computed by the numeric library (whose
closed forms the tests check against a numerical linearization and against simulation), within
a tolerance stated in the check; :func:`rollingdisk.symbolic.rows.verdict` turns that into the
row's status.  A check takes the printed statement as its argument, so a test can hand it a
wrong one and see the row fail.

``theta0`` is taken in ``(0, pi/2)`` (so ``h~ = h``), written through ``p0 = tan(theta0)``;
negative ``theta0`` follows by the symmetry checked in ``tests/test_steady.py``.
"""

from __future__ import annotations

from functools import lru_cache

from . import checks3, checks4  # noqa: F401 - they register their checks on import
from .printed import PRINTED
from .registry import CHECKS, check, derived, kinematics  # noqa: F401 - re-exported
from .rows import EquationCheck, Printed, markdown_table

__all__ = ["CHECKS", "check", "checks_sections_3_4", "derived", "errata_markdown", "run",
           "write_errata"]


def _register() -> None:
    """Every printed statement has a registered check (checks3, checks4 are imported above)."""
    missing = [k for k in PRINTED if k not in CHECKS]
    if missing:
        raise LookupError(f"printed statements without a check: {missing}")


def run(key: str, printed: Printed | None = None) -> EquationCheck:
    """The row of ``PRINTED[key]``, or of ``printed`` put in its place (to test the check)."""
    _register()
    return CHECKS[key](PRINTED[key] if printed is None else printed)


@lru_cache(maxsize=1)
def checks_sections_3_4() -> tuple[EquationCheck, ...]:
    """One row per printed statement of sections 3-4: eqs. (15)-(59) and the quoted numbers.

    (37), (38) and (49) are checked with section 2
    (:func:`rollingdisk.symbolic.paper.checks_sections_1_2`).  Takes some seconds; cached.
    """
    _register()
    return tuple(run(key) for key in PRINTED)


# ---- the generated part of docs/errata.md ---------------------------------------------------
#: docs/errata.md holds, after this line, the generated part for sections 3-4.
MARKER = ("<!-- generated below by: "
          "python -m rollingdisk.symbolic.sections34 --write docs/errata.md -->")

HEADER = """## Sections 3 and 4: steady motions and their stability

Every row is recomputed by the test suite (`tests/test_sections34.py`), which also fails when
this part of the file is out of date.  Each printed equation is compared with the one
re-derived with sympy from the Newton-Euler derivation: the kinematics (15)-(25) from its frame
rates, contact point and balances at a constant state, the rest from its reduced equations
(random-point identity test at 50 digits; conditions up to a factor of h, p0 only).  (37),
(38) and (49) are in the section 2 table above.  Each quoted number is recomputed with the
library, whose closed forms are checked against a numerical linearization of the equations of
motion (agreement ~1e-12) and against direct simulation (tests/test_stability.py,
tests/test_simulate.py).
`th0` = theta0, `p0` = tan(theta0), `h~` = h sgn(theta0), `w` = omega30.

Summary of misprints: the first form of (31) and (33) (factor 2 on the h~ term, also in the
prose after (33)); the sign in the prose after (30); (44) (3+4h^2 for 3+16h^2); P0 of (45)
(missing sqrt(1+p0^2)); the asymptote (48) (spurious factor 2); and the smooth-ground
conclusion (omega30^2 > 2 must read omega30^2 > 4).  The library uses the corrected forms.
"""


def errata_markdown(rows=None) -> str:
    """The generated part of docs/errata.md, after :data:`MARKER` (from ``rows`` or afresh)."""
    return HEADER + "\n" + markdown_table(rows or checks_sections_3_4()) + "\n"


def write_errata(path) -> None:
    """Replace everything after :data:`MARKER` in the file ``path`` by :func:`errata_markdown`."""
    from pathlib import Path

    from rollingdisk.util.files import atomic_file

    path = Path(path)
    text = path.read_text()
    if MARKER not in text:
        raise ValueError(f"{path} has no line {MARKER!r}")
    head = text[: text.index(MARKER) + len(MARKER)]
    body = errata_markdown()
    with atomic_file(path) as fh:
        fh.write(head + "\n\n" + body)


if __name__ == "__main__":  # pragma: no cover
    import sys

    # the registry lives in the imported module, not in this __main__ copy of it
    from rollingdisk.symbolic import sections34 as _module

    if sys.argv[1:2] == ["--write"] and len(sys.argv) == 3:
        _module.write_errata(sys.argv[2])
    else:
        print(_module.errata_markdown(), end="")
