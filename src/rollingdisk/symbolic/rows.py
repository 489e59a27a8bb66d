"""The row type of the errata table and the rule that turns a comparison into a verdict.

Owns :class:`EquationCheck` (one row: what ``rollingdisk derive`` prints, what ``--json``
writes, what docs/errata.md lists), :class:`Printed` (a statement as printed in the paper, with
its correction where it is misprinted) and :func:`verdict`, which decides the status of a row
from what a check computed, never by hand:

* ``"confirmed"``: the printed form agrees with the derivation (or the quoted number with the
  computed one, within the stated tolerance);
* ``"misprint"``: it does not, and the correction typed next to it does (or no correction is
  typed: then the row says so);
* ``"unresolved"``: neither the printed form nor the typed correction agrees: the errata would
  be wrong, and the tests fail.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import asdict, dataclass

__all__ = ["STATUSES", "EquationCheck", "Printed", "markdown_table", "verdict"]

STATUSES = ("confirmed", "misprint", "unresolved")


@dataclass(frozen=True)
class EquationCheck:
    """One row of the errata table: a printed equation and what the derivation says of it.

    ``printed`` and ``correct`` are filled for every misprint; sections 3-4 fill ``printed``
    for every row (the statement checked) and ``correct`` only where it differs.
    """

    equation: str  # "(38)", "text after (30)"
    quantity: str  # what it gives ("" where ``printed`` says it)
    status: str  # one of STATUSES
    evidence: str
    printed: str = ""
    correct: str = ""

    def as_dict(self) -> dict:
        return asdict(self)


@dataclass(frozen=True)
class Printed:
    """A statement as printed in the paper, typed once.

    ``form`` is what a check compares: a sympy expression or a tuple of them, a quoted number,
    or ``None`` for prose whose deciding quantity the check computes.  Where the statement is
    misprinted, ``correct`` / ``correct_form`` hold the correction, which the check must
    confirm as well.
    """

    equation: str
    text: str
    form: object = None
    correct: str = ""
    correct_form: object = None


def verdict(printed: Printed, test: Callable[[object], bool], evidence: str) -> EquationCheck:
    """The row for ``printed``, with ``test(form) -> bool`` deciding whether a form is right.

    ``test`` is applied to the printed form and, if that fails and a correction is typed, to
    the correction.
    """
    equation = printed.equation
    if test(printed.form):
        return EquationCheck(equation, "", "confirmed", evidence, printed.text)
    if not printed.correct:
        return EquationCheck(equation, "", "misprint", evidence, printed.text,
                             "(differs from the derivation; no correction typed)")
    status = "misprint" if test(printed.correct_form) else "unresolved"
    return EquationCheck(equation, "", status, evidence, printed.text, printed.correct)


def markdown_table(rows) -> str:
    """A markdown table of the rows: equation, status, printed, correct, evidence."""
    out = ["| Equation | Status | Printed | Correct | Evidence |", "|---|---|---|---|---|"]
    for r in rows:
        cells = [r.equation, r.status, r.printed,
                 r.correct if r.status != "confirmed" else "(as printed)", r.evidence]
        out.append("| " + " | ".join(str(x).replace("|", "\\|") for x in cells) + " |")
    return "\n".join(out)
