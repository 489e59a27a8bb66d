"""The sympy re-derivation of sections 3-4 and the errata table built from it."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rollingdisk.symbolic.sections34 import MARKER, checks_sections_3_4, errata_markdown

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
    covered = set()
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
