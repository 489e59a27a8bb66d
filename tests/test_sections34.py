"""The sympy re-derivation of sections 3-4 and the errata table built from it."""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import pytest
import sympy as sp

from rollingdisk.symbolic.identity import changes_sign_at, proportional, same
from rollingdisk.symbolic.paper import checks_sections_1_2
from rollingdisk.symbolic.printed import PRINTED, h, p, w2, w3
from rollingdisk.symbolic.rows import EquationCheck
from rollingdisk.symbolic.sections34 import (
    MARKER,
    checks_sections_3_4,
    derived,
    errata_markdown,
    run,
)

DOC = Path(__file__).resolve().parents[1] / "docs" / "errata.md"

EXPECTED_MISPRINTS = {
    "text after (30)", "(31) first form", "(33)", "text after (33)", "(44)", "(45)", "(48)",
    "text before Conclusion / Conclusion",
}


@pytest.fixture(scope="module")
def rows():
    return checks_sections_3_4()


def test_every_row_resolved(rows):
    assert len(rows) == len(PRINTED) == 66  # with the 16 of section 2: 82 rows in docs/errata.md
    for r in rows:
        assert isinstance(r, EquationCheck)
        assert r.status in ("confirmed", "misprint"), r
        assert r.printed and r.evidence
        assert bool(r.correct) == (r.status == "misprint"), r


def test_misprints_are_the_expected_ones(rows):
    assert {r.equation for r in rows if r.status == "misprint"} == EXPECTED_MISPRINTS
    assert sum(r.status == "misprint" for r in rows) == 8


def test_every_equation_of_sections_3_4_is_covered(rows):
    """(15)-(59) each have a row: (37), (38), (49) with section 2, the others here, once."""
    covered = {int(r.equation.strip("()")) for r in checks_sections_1_2()}
    assert {37, 38, 49} <= covered
    assert not {"(37)", "(38)", "(49)"} & {r.equation for r in rows}
    for r in rows:
        for a, b in re.findall(r"\((\d+)\)(?:-\((\d+)\))?", r.equation):
            covered.update(range(int(a), int(b or a) + 1))
    assert set(range(15, 60)) <= covered


def test_doc_is_up_to_date(rows):
    text = DOC.read_text()
    assert MARKER in text
    generated = text[text.index(MARKER) + len(MARKER):].lstrip("\n")
    assert generated == errata_markdown(rows), (
        "regenerate: python -m rollingdisk.symbolic.sections34 --write docs/errata.md")


def test_rows_are_cached_and_read_only(rows):
    assert checks_sections_3_4() is rows
    with pytest.raises(dataclasses.FrozenInstanceError):
        rows[0].status = "confirmed"


def _wrong(form):
    """A deliberately wrong version of a printed form (numbers, sympy, tuples, rules)."""
    if isinstance(form, tuple):
        return (_wrong(form[0]), *form[1:])
    if isinstance(form, sp.logic.boolalg.Boolean):
        return ~form
    if isinstance(form, (int, float)):
        return form + 0.01 * (abs(form) + 1)
    return sp.sympify(form) * sp.Rational(101, 100) + sp.Rational(1, 100)


def test_every_check_computes_its_verdict(rows):
    """Each registered check, handed a wrong printed form, flags it; handed the correction of a
    misprint, confirms it; handed a wrong correction, says the row is unresolved."""
    for key, pr, row in zip(PRINTED, PRINTED.values(), rows, strict=True):
        assert run(key, dataclasses.replace(pr, form=_wrong(pr.form))).status != "confirmed", key
        if row.status == "confirmed":
            assert run(key, dataclasses.replace(pr, form=_wrong(pr.form))).status == "misprint"
        else:
            assert run(key, dataclasses.replace(pr, form=pr.correct_form)).status == "confirmed"
            wrong_both = dataclasses.replace(pr, correct_form=_wrong(pr.correct_form))
            assert run(key, wrong_both).status == "unresolved", key


def test_proportional_rejects_and_accepts():
    """The test behind (20), (28), (29), (34), (35): a factor of (h, p0) only is allowed."""
    cond = derived("rough")["cond"]
    assert proportional(cond * (15 + 16 * h ** 2) / (1 + p ** 2), cond)
    assert proportional(-cond, cond)
    assert not proportional(cond + 7 * w3 ** 3 + 1, cond)  # not a multiple at all
    assert not proportional(cond * w2, cond)  # the factor depends on omega20
    assert not proportional(cond + sp.Rational(1, 10 ** 20) * w3, cond)
    assert not proportional(0 * cond, cond)  # a zero factor


def test_same_sees_small_differences():
    """The 50-digit identity test behind every row: equal forms pass, a 1e-20 change fails."""
    cond = derived("smooth")["cond"]
    assert same(cond, sp.expand(cond))[0]
    assert not same(cond, cond * (1 + sp.Rational(1, 10 ** 20) * h))[0]
    ok, how = same(cond, cond + sp.Rational(1, 10 ** 20) * p)
    assert not ok and "differs" in how
    assert not same((cond, 0), (cond, sp.Rational(1, 10 ** 20)))[0]


def test_changes_sign_at():
    """The test behind (42), (43), (53), (57): a root of the right sign change only."""
    assert changes_sign_at(w2 ** 2 - (1 + h ** 2), w2, 1 + h ** 2)
    assert not changes_sign_at(w2 ** 2 - (1 + h ** 2), w2, 1 + h ** 2 + sp.Rational(1, 10 ** 20))
    assert not changes_sign_at((1 + h ** 2) - w2 ** 2, w2, 1 + h ** 2)  # wrong direction
