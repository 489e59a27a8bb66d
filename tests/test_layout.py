"""The numeric core imports neither sympy nor matplotlib (layout rule of the project)."""

import os
import subprocess
import sys
from pathlib import Path

CORE = ["rollingdisk", "rollingdisk.model.disk", "rollingdisk.model.equations", "rollingdisk.theory.steady",
        "rollingdisk.theory.oscillations", "rollingdisk.integrate.simulation", "rollingdisk.theory.regions",
        "rollingdisk.theory.exact", "rollingdisk.friction.euler_disk"]
SRC = str(Path(__file__).resolve().parents[1] / "src")


def test_core_imports_without_sympy_and_matplotlib():
    code = ("import sys\n"
            "sys.modules['sympy'] = None\nsys.modules['matplotlib'] = None\n"
            + "".join(f"import {m}\n" for m in CORE)
            + "assert 'numba' not in sys.modules, 'import rollingdisk must not load numba'\n")
    env = dict(os.environ, PYTHONPATH=SRC)  # this checkout, whatever is installed
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert res.returncode == 0, res.stderr
