"""The sympy re-derivation of sections 3-4 and the errata table built from it."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import sympy as sp

from rollingdisk.symbolic.paper import checks_sections_1_2
from rollingdisk.symbolic.sections34 import (
    MARKER,
    checks_sections_3_4,
    derived,
    errata_markdown,
    h,
    p,
    proportional,
    w2,
    w3,
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
    for r in rows:
        assert set(r) == {"equation", "status", "printed", "correct", "evidence"}
        assert r["status"] in ("confirmed", "misprint"), r


def test_misprints_are_the_expected_ones(rows):
    assert {r["equation"] for r in rows if r["status"] == "misprint"} == EXPECTED_MISPRINTS


def test_every_equation_of_sections_3_4_is_covered(rows):
    """(15)-(59) each have a row: (37), (38), (49) with section 2, the others here, once."""
    covered = {int(r.equation.strip("()")) for r in checks_sections_1_2()}
    assert {37, 38, 49} <= covered
    assert not {"(37)", "(38)", "(49)"} & {r["equation"] for r in rows}
    for r in rows:
        for a, b in re.findall(r"\((\d+)\)(?:-\((\d+)\))?", r["equation"]):
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
    with pytest.raises(TypeError):
        rows[0]["status"] = "confirmed"


def test_proportional_rejects_and_accepts():
    """The test behind (20), (28), (29), (34), (35): a factor of (h, p0) only is allowed."""
    cond = derived("rough")["cond"]
    assert proportional(cond * (15 + 16 * h ** 2) / (1 + p ** 2), cond)
    assert proportional(-cond, cond)
    assert not proportional(cond + 7 * w3 ** 3 + 1, cond)  # not a multiple at all
    assert not proportional(cond * w2, cond)  # the factor depends on omega20
    assert not proportional(cond + sp.Rational(1, 10 ** 20) * w3, cond)
    assert not proportional(0 * cond, cond)  # a zero factor


def test_same_at_points_sees_small_differences():
    """The 50-digit identity test behind the rows: equal forms pass, a 1e-20 change fails."""
    from rollingdisk.symbolic.sections34 import _same_at_points

    cond = derived("smooth")["cond"]
    assert _same_at_points(cond, sp.expand(cond))
    assert not _same_at_points(cond, cond * (1 + sp.Rational(1, 10 ** 20) * h))
    assert not _same_at_points(cond, cond + sp.Rational(1, 10 ** 20) * p)
