"""Every code block of the how-to guides (docs/howto.md) runs as written.

Each ```python block is run in a fresh interpreter (a script: the sweep's main guard is
real), in a temporary folder, and must exit 0 and print what the page says it prints.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BLOCKS = re.findall(r"```python\n(.*?)```", (ROOT / "docs" / "howto.md").read_text(), re.S)
#: what each block prints, in order: a check of its output
EXPECT = ["rolls straight and stable above 0.197 m/s", "stable", "rad s"]


def test_the_page_has_the_blocks_this_test_knows():
    assert len(BLOCKS) == len(EXPECT)


@pytest.mark.parametrize("i", [0, pytest.param(1, marks=pytest.mark.slow), 2])
def test_block_runs_as_written(i, tmp_path):
    script = tmp_path / f"howto_{i}.py"
    script.write_text(BLOCKS[i])
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "MPLBACKEND": "Agg"}
    res = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env,
                         capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stderr[-2000:]
    assert EXPECT[i] in res.stdout, res.stdout
