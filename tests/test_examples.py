"""The gallery's examples (examples/plot_*.py) run, draw their figures and pass their checks.

Each example ends with ``assert`` statements against an independent truth (closed forms,
limits, conservation laws), so running it is the test: every example runs in a fresh
interpreter with matplotlib's non-interactive Agg backend, and must exit 0 having drawn at
least one figure.  The structure sphinx-gallery needs (a header docstring with a title) is
checked without running anything.
"""

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("plot_*.py"))
#: Examples that take more than a couple of seconds (numba compiling the sweep kernel on a
#: first run; Euler's disk integrated to its end).
SLOW = {"plot_sweep_basin.py", "plot_euler_disk.py"}

#: Run inside the example's interpreter: Agg, and count the figures open at each show().
RUNNER = """
import runpy, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
shown = []
plt.show = lambda *a, **k: shown.append(len(plt.get_fignums()))
runpy.run_path(sys.argv[1], run_name="__main__")
print("FIGURES", sum(shown) + (0 if shown else len(plt.get_fignums())))
"""


def _params():
    for path in EXAMPLES:
        marks = [pytest.mark.slow] if path.name in SLOW else []
        yield pytest.param(path, id=path.stem, marks=marks)


def test_examples_found():
    assert len(EXAMPLES) >= 6
    assert SLOW <= {p.name for p in EXAMPLES}


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_structure(path):
    """A header docstring whose first line is a title underlined with '=', and checks."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    doc = ast.get_docstring(tree, clean=True)
    assert doc, f"{path.name}: no header docstring"
    title, underline = doc.splitlines()[:2]
    assert title.strip() and set(underline.strip()) == {"="}, path.name
    assert len(underline.strip()) >= len(title.strip()), path.name
    asserts = [n for n in ast.walk(tree) if isinstance(n, ast.Assert)]
    assert len(asserts) >= 3, f"{path.name}: an example must check what it shows"


@pytest.mark.parametrize("path", list(_params()))
def test_example_runs(path, tmp_path):
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "MPLBACKEND": "Agg"}
    res = subprocess.run([sys.executable, "-c", RUNNER, str(path)], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, f"{path.name} failed:\n{res.stdout[-2000:]}\n{res.stderr[-4000:]}"
    figures = int(res.stdout.rsplit("FIGURES", 1)[1])
    assert figures >= 1, f"{path.name} drew no figure"
    assert not list(tmp_path.iterdir()), f"{path.name} wrote files into its working folder"
