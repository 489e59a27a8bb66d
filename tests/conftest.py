"""Shared fixtures and strategies: random states for both grounds, parameter ranges."""

import numpy as np
import pytest
from hypothesis import strategies as st

from rollingdisk import Disk

#: hypothesis strategies shared by the steady-motion and stability tests
H = st.floats(0.0, 5.0)
THETA = st.floats(1e-4, 1.569)  # (0, pi/2); tan(1.569) ~ 560
SIGN = st.sampled_from([1.0, -1.0])


def random_states(ground: str, n: int, seed: int):
    """``n`` random (h, state) pairs: h in [0, 3] (h = 0 included), both signs of theta."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        h = 0.0 if i % 10 == 0 else rng.uniform(0.0, 3.0)
        theta = rng.choice([-1.0, 1.0]) * rng.uniform(0.01, 1.45)
        w = rng.uniform(-5.0, 5.0, 3)
        psi, phi = rng.uniform(-np.pi, np.pi, 2)
        X, Y = rng.uniform(-2, 2, 2)
        if ground == "rough":
            y = np.array([X, Y, psi, theta, phi, *w])
        else:
            VX, VY = rng.uniform(-2, 2, 2)
            y = np.array([X, Y, VX, VY, psi, theta, phi, *w])
        out.append((Disk(h), y))
    return out


@pytest.fixture(scope="session")
def derived():
    """The sympy derivation, lambdified (computed once per test session)."""
    from rollingdisk.symbolic import lambdified

    return lambdified()
