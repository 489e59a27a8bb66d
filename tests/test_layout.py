"""The numeric core imports neither sympy nor matplotlib (layout rule of the project)."""

import subprocess
import sys

CORE = ["rollingdisk", "rollingdisk.disk", "rollingdisk.equations"]


def test_core_imports_without_sympy_and_matplotlib():
    code = ("import sys\n"
            "sys.modules['sympy'] = None\nsys.modules['matplotlib'] = None\n"
            + "".join(f"import {m}\n" for m in CORE))
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
