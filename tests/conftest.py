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


@pytest.fixture(scope="module")
def chromium():
    """One headless Chromium for a test module's browser tests, its requests logged
    (tests/browser.py: ``set_viewport``, ``assert_local``); skipped where the system's
    Chromium, its driver or selenium is missing."""
    import browser

    with browser.chromium() as driver:
        yield driver


# -- the suite leaves the checkout as it found it ------------------------------------------
#: Caches that tools keep beside the sources (ignored by git, never outputs of a test).
_CACHES = ("__pycache__/", ".pytest_cache/", ".hypothesis/", ".ruff_cache/", ".venv/",
           ".egg-info/", ".nbi", ".nbc")


def _checkout_state(root):
    """``{path: status and content digest}`` of every file git reports as changed, new or
    ignored in the checkout ``root`` (caches aside), or ``None`` outside a git checkout."""
    import hashlib
    import subprocess
    from pathlib import Path

    try:
        res = subprocess.run(["git", "status", "--porcelain", "--ignored",
                              "--untracked-files=all"], cwd=root, capture_output=True,
                             text=True, timeout=120)
    except (OSError, subprocess.SubprocessError):
        return None
    if res.returncode != 0:
        return None
    state = {}
    for line in res.stdout.splitlines():
        path = line[3:].strip('"')
        if any(c in path for c in _CACHES):
            continue
        p = Path(root) / path
        digest = hashlib.sha1(p.read_bytes()).hexdigest() if p.is_file() else "-"
        state[path] = f"{line[:2]} {digest}"
    return state


def pytest_sessionstart(session):
    session.config._checkout_before = _checkout_state(session.config.rootpath)


def pytest_sessionfinish(session, exitstatus):
    """Fail the run if it left, removed or changed a file in the checkout: every test
    writes under a temporary directory (the CLI fuzz tests' hostile ``--out`` values too)."""
    before = getattr(session.config, "_checkout_before", None)
    if before is None:
        return
    after = _checkout_state(session.config.rootpath)
    changed = sorted(p for p in set(before) | set(after) if before.get(p) != after.get(p))
    if changed:
        import sys

        sys.stderr.write("\nthe test suite changed the checkout (every test must write under "
                         "a temporary directory):\n" + "".join(f"  {p}\n" for p in changed))
        session.exitstatus = 1
