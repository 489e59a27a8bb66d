"""``simulate_coulomb(quasi_static_slip=...)``: below a slip speed the sliding friction takes
the quasi-static slip direction ``e*`` (docs/friction.md, "Quasi-static micro-slip").

``e*`` is held to an independent derivation of the slip acceleration (the chain rule of eq. (6)
along the full sliding right-hand side, by central differences, not the hand-written
``du/dt`` of the kernels), the run to the full law ``e = u/|u|`` through micro-slip, Coulomb's
bound and the energy balance at every stored point."""

from __future__ import annotations

import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.ivp import fastsegment as fs
from rollingdisk.model import coulomb as cl
from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk


def _flow_slip_accel(h, g, y, e_X, e_Y):
    """``du/dt`` (Cxyz) at ``y``: eq. (6) differentiated along the sliding flow with the
    friction direction fixed to the inertial ``(e_X, e_Y)``, by central differences."""
    cf = g.coefficients
    dy = np.array(cl._coulomb_sliding(h, g.mu_k, *cf, y, e_X, e_Y, u_eps=1.0)[0])
    eps = 1e-6
    up = np.array(cl._slip_velocity(h, y + eps * dy))
    um = np.array(cl._slip_velocity(h, y - eps * dy))
    return (up - um) / (2 * eps)


@pytest.mark.parametrize("seed", range(6))
def test_quasi_static_direction_is_the_fixed_point_of_the_slip_acceleration(seed):
    """At a rolling state beyond the cone, ``e*`` makes ``du/dt`` parallel to ``+e*``."""
    rng = np.random.default_rng(seed)
    h = rng.uniform(0.0, 0.5)
    disk = rd.Disk(h)
    m = rd.steady_motion(disk, "rough", rng.uniform(0.3, 1.0), r_C=rng.uniform(0.5, 2.0))
    yr = [float(v) for v in m.initial_state()]
    yr[5] += rng.uniform(-0.05, 0.05)
    y = rd.rolling_state(disk, yr)
    g = rd.Coulomb(0.5 * m.mu_required, rolling_resistance=1e-3)
    d = rd.slip_direction(disk, g, y)  # the direction the slip starts in (a scan)
    cp, sp = math.cos(y[4]), math.sin(y[4])
    b = math.atan2(d[1], d[0]) + 0.05  # Newton's start: near it (as the slip is), not on it
    start = (math.cos(b), math.sin(b))
    S = (start[0] * cp - start[1] * sp, start[0] * sp + start[1] * cp)  # inertial
    y[2] += 1e-9 * S[0]  # a slip of 1e-9 along the start: Newton starts from u/|u|
    y[3] += 1e-9 * S[1]
    p = np.array([1.0, g.mu_k, g.mu_s, *g.coefficients, S[0], S[1], 1e-8, 1.0, 1.0, 0.0, 0.0,
                  0.0, 1e-8, 1e-3])
    ex, ey, u_eps = fs.namespace()["_quasi_static_ref"](p, h, y, 1.0)
    assert u_eps == 1e-3 and math.hypot(ex, ey) == pytest.approx(1.0, abs=1e-14)
    e = np.array([ex * cp + ey * sp, -ex * sp + ey * cp])  # Cxyz
    a = _flow_slip_accel(h, g, y, ex, ey)
    assert abs(e[0] * a[1] - e[1] * a[0]) <= 1e-7 * np.linalg.norm(a)
    assert e @ a > 0.0
    # the scan of simulate_coulomb's rolling -> sliding transition finds the same direction
    assert abs(d[0] * e[1] - d[1] * e[0]) <= 1e-9 and np.dot(d, e) > 0.0


def _circle():
    """tests/test_coulomb_stiff.py's nudged circle: rolls, then micro-slip from t = 0.2416."""
    disk = rd.Disk(0.3)
    m = rd.steady_motion(disk, "rough", 0.9, r_C=1.0)
    yr = [float(v) for v in m.initial_state()]
    yr[5] += 0.05
    return disk, rd.Coulomb(1.02 * m.mu_required), rd.rolling_state(disk, yr)


@pytest.mark.parametrize("method", ["dop853", "scipy"])
def test_quasi_static_micro_slip_follows_the_full_law(method):
    disk, g, y0 = _circle()
    full = rd.simulate_coulomb(disk, g, (0, 0.5), y0, method="dop853", max_wall_time=600)
    qs = rd.simulate_coulomb(disk, g, (0, 0.5), y0, method=method,
                            quasi_static_slip=1e-3, max_wall_time=600)
    assert qs.status == full.status == "completed"
    assert qs.n_steps < full.n_steps
    assert np.abs(qs.y[:, -1] - full.y[:, -1]).max() <= 1e-6
    assert rd.energy_balance(qs) <= 1e-9
    F_t = np.hypot(qs.F_x, qs.F_y)
    assert np.all(F_t <= g.mu_s * qs.F_z * (1 + 1e-12) + 1e-15)


def test_quasi_static_off_is_the_full_law():
    disk, g, y0 = _circle()
    a = rd.simulate_coulomb(disk, g, (0, 0.5), y0, method="dop853")
    b = rd.simulate_coulomb(disk, g, (0, 0.5), y0, method="dop853", quasi_static_slip=0.0)
    assert np.array_equal(a.y, b.y)


def test_quasi_static_slip_rejects_negative():
    disk, g, y0 = _circle()
    with pytest.raises(rd.ParameterError, match="quasi_static_slip"):
        rd.simulate_coulomb(disk, g, (0, 0.5), y0, quasi_static_slip=-1.0)


@pytest.mark.slow
def test_euler_disk_on_coulomb_ground_falls_at_the_full_laws_time(monkeypatch):
    """The toy (docs/friction.md): the full law e = u/|u| fell flat at t = 1600.8514 after
    75,309,353 DOP853 steps; the quasi-static micro-slip (u_qs = 1e-3, opt-in) holds that
    to 1e-4 relative."""
    from rollingdisk.scenarios import euler_coulomb

    monkeypatch.setattr(euler_coulomb, "QUASI_STATIC_SLIP", 1e-3)
    r = run_euler_disk(EulerDisk(friction="coulomb"), predict=False)
    assert r.status == "completed" and r.end == "fell-flat"
    assert r.t_end == pytest.approx(1600.8514, rel=1e-4)
    assert r.energy_balance <= 1e-8
