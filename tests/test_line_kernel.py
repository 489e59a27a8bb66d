"""Line contact's kernels (phases/line_kernel.py): the compiled ones give the plain ones'
numbers bit for bit, so that a toss ends the same way compiled or not.

Sources of truth: ``math.hypot`` of the running Python for the ported slip length; the
plain kernels (themselves checked against the closed form of newton_euler in
test_line_contact.py) for the compiled ones.
"""

import math

import numpy as np
import pytest

from rollingdisk.phases import line_contact as lc
from rollingdisk.phases import line_kernel as lk


def test_python_hypot_is_cpythons_to_the_last_bit():
    rng = np.random.default_rng(3)
    xs = rng.standard_normal((20000, 2)) * 10.0 ** rng.uniform(-15.0, 3.0, (20000, 1))
    xs[::2, 1] *= 1e-6  # one component much smaller, as a slip along x
    pairs = [*map(tuple, xs), (0.0, 0.0), (-0.0, 3.0), (5e-324, 1e-320), (1e308, 1e308),
             (math.inf, 1.0), (3.0, 4.0)]
    assert all(lk.python_hypot(a, b) == math.hypot(a, b) for a, b in pairs)
    assert math.isnan(lk.python_hypot(math.nan, 1.0))


def _states(rng):
    for mode in range(8):
        for seeded in (False, True):
            y = rng.uniform(-1.0, 1.0, 9)
            d = (0.0, 0.0, 0.0, 0.0)
            if seeded:  # corner slips below the floor: the seeds decide
                y[4] = y[6] - 0.2 * y[7] + 1e-9
                y[5] = 1e-9
                d = tuple(rng.uniform(-1.0, 1.0, 4))
            p = lc.line_params(0.2, 0.6, 0.5, 0.01, 0.002, 0.001, mode, d[:2], d[2:],
                               roll_sign=1.0, floor=1e-9)
            yield y, p


def test_compiled_kernels_give_the_plain_numbers():
    pytest.importorskip("numba")
    assert lk.load_compiled()
    ns = lk.kernels()
    assert lk.loaded() and ns is not lk._PYTHON
    rng = np.random.default_rng(11)
    for y, p in _states(rng):
        for name in ("corner_directions", "line_system", "line_rhs_kernel"):
            assert np.array_equal(np.array(ns[name](y, p)), np.array(lk._PYTHON[name](y, p)))


def test_line_rhs_matches_line_forces():
    """The right-hand side is the kinematics plus line_forces' accelerations and power."""
    rng = np.random.default_rng(5)
    for y, p in _states(rng):
        acc, _, _, Fp, Fm, M = lc.line_forces(y, p)
        dy = lc.line_rhs(0.0, y, p)
        h = p[0]
        up = (y[4] - y[6] + h * y[7], y[5])
        um = (y[4] - y[6] - h * y[7], y[5])
        power = Fp @ up + Fm @ um + y[6] * M[1] + y[7] * M[2]
        assert np.allclose(dy[4:8], acc, rtol=0, atol=0)
        assert dy[8] == pytest.approx(-power, rel=1e-12, abs=1e-15)
        assert dy[0] == pytest.approx(y[4] * math.cos(y[2]) - y[5] * math.sin(y[2]))
