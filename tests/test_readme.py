"""The README's "Asking the library" block runs as written, and says what it computes.

Source of truth: the numbers the README quotes in its comments (themselves checked against
the closed forms by the other tests); here the block is executed and a few of them read back.
"""

import re
from pathlib import Path

README = Path(__file__).resolve().parents[1] / "README.md"


def _block() -> str:
    text = README.read_text()
    section = text.split("## Asking the library", 1)[1]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def test_the_readme_example_runs_and_its_numbers_hold():
    ns: dict = {}
    exec(compile(_block(), "README.md", "exec"), ns)  # noqa: S102 - the README's own code
    m, s, ex = ns["m"], ns["s"], ns["ex"]
    assert abs(m.Omega0 - 0.690) < 5e-4 and abs(m.r_P - 0.853) < 5e-4
    assert abs(s.varpi2 - 0.208) < 5e-4 and s.stable and abs(s.period - 13.78) < 5e-3
    assert abs(ex.period - 14.03) < 5e-3 and abs(ex.delta_psi - 9.64) < 5e-3
    assert abs(ns["tc"].transitions[1].t - 4.97) < 5e-3
