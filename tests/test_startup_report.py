"""The README's start-up figures and docs/performance.md are generated, never copied by hand:
both are exactly what benchmarks/report.py makes of the data docs/performance.md carries
(written there by the same script from benchmarks/startup.py's JSON)."""

from __future__ import annotations

import copy
import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _report():
    spec = importlib.util.spec_from_file_location("_bench_report",
                                                  ROOT / "benchmarks" / "report.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_readme_and_docs_are_what_the_script_makes_of_the_data():
    report = _report()
    docs = (ROOT / "docs" / "performance.md").read_text()
    data = report.data_from_docs(docs)
    assert docs == report.render_docs(data)
    assert report.readme_block((ROOT / "README.md").read_text()) == report.render_readme(data)


def test_every_figure_of_the_readme_block_comes_from_the_data():
    """Change the data, and the README's paragraph changes with it (no constant figure)."""
    report = _report()
    data = report.data_from_docs((ROOT / "docs" / "performance.md").read_text())
    other = copy.deepcopy(data)
    other["best_s"] = {k: v + 0.5 for k, v in data["best_s"].items()}
    other["ratios"] = {k: v + 1.0 for k, v in data["ratios"].items()}
    other["sweep_10x10_warm_s"] += 0.5
    a, b = report.render_readme(data), report.render_readme(other)
    for key in ("simulate (warm)", "simulate (cold)", "user scipy script"):
        assert f"{data['best_s'][key]:.2f} s" in a and f"{other['best_s'][key]:.2f} s" in b
    assert f"{data['ratios']['simulate_warm_over_script']:.2f}×" in a
    assert f"{other['ratios']['simulate_warm_over_script']:.2f}×" in b
