"""Units on the axes of the main plots: the paper's units for a dimensionless disk, SI for a
disk with a physical scale, angles in degrees everywhere.

Sources of truth: the tick labels are checked against the conversions written out here
(``sqrt(a/g)`` seconds, ``a`` metres, degrees = radians * 180/pi), not against the library's
converters; the data drawn must stay in the library's units (radians, ``m = a = g = 1``).
"""

from __future__ import annotations

import math
import re

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

import rollingdisk as rd  # noqa: E402
from rollingdisk.plotting import plots  # noqa: E402

G = 9.80665
A = 0.02325 / 2  # the 1-euro coin's radius [m]
COIN = rd.Disk(h=0.00233 / 0.02325, radius=A, mass=0.0075, gravity=G)
PLAIN = rd.Disk(h=0.00233 / 0.02325)  # no physical scale
UNIT = re.compile(r"\[.+\]")


def _ax():
    return Figure().subplots(1, 1)


def _ticks(axis):
    """(position, shown value) of the visible major ticks of an axis."""
    lo, hi = sorted(axis.get_view_interval())
    locs = [v for v in axis.get_majorticklocs() if lo - 1e-12 <= v <= hi + 1e-12]
    texts = axis.get_major_formatter().format_ticks(locs)
    out = [(pos, float(text.replace("\u2212", "-"))) for pos, text in zip(locs, texts)]
    assert len(out) >= 3
    return out


@pytest.fixture(scope="module")
def trajectories():
    out = {}
    for name, disk in (("plain", PLAIN), ("coin", COIN)):
        m = rd.steady_motion(disk, "rough", 0.5, Omega0=1.5)
        out[name] = rd.simulate_steady(m, 2.0, kick=0.01, t_eval=np.linspace(0, 2.0, 81))
    return out


# ------------------------------------------------------------------------------- maps
@pytest.mark.parametrize("disk, length, rate", [(PLAIN, "[$a$]", r"[$\sqrt{g/a}$]"),
                                                (COIN, "[m]", "[rad/s]")])
def test_map_labels(disk, length, rate):
    m = plots.plot_existence_map(disk, "rough", _ax(), n=(20, 20))
    assert m.ax.get_xlabel() == r"$\theta_0$ [deg]"
    assert m.ax.get_ylabel().startswith("$r_C$ " + length)
    s = plots.plot_stability_map(disk, "rough", _ax(), n=(20, 20))
    assert s.ax.get_xlabel() == r"$\theta_0$ [deg]"
    assert s.ax.get_ylabel() == r"$\omega_{30}$ " + rate
    c = plots.plot_varpi2_curves(disk, "rough", _ax(), n=50)
    assert c["ax"].get_xlabel() == r"$\omega_{30}$ " + rate
    assert UNIT.search(c["ax"].get_ylabel())
    a = plots.plot_all_omega30_stable("rough", _ax(), n=(20, 20), mark_h=disk)
    assert a.ax.get_xlabel() == r"$\theta_0$ [deg]" and "h" in a.ax.get_ylabel()


def test_map_ticks_show_degrees_and_si_of_the_data():
    """The grid stays in radians and units of a / sqrt(g/a); the ticks show degrees, metres
    and rad/s of the same positions."""
    m = plots.plot_existence_map(COIN, "rough", _ax(), n=(20, 20), r_C_scale="linear")
    assert m.x.max() < math.pi / 2  # radians
    for pos, shown in _ticks(m.ax.xaxis):
        assert shown == pytest.approx(pos * 180.0 / math.pi, abs=1e-6)
    for pos, shown in _ticks(m.ax.yaxis):
        assert shown == pytest.approx(pos * A, rel=1e-5, abs=1e-9)
    s = plots.plot_stability_map(COIN, "rough", _ax(), n=(20, 20), omega30_max=2.0)
    assert s.y.max() == pytest.approx(2.0)  # units of sqrt(g/a)
    for pos, shown in _ticks(s.ax.yaxis):
        assert shown == pytest.approx(pos * math.sqrt(G / A), rel=1e-5, abs=1e-9)


def test_symlog_r_C_axis_in_metres():
    m = plots.plot_existence_map(COIN, "rough", _ax(), n=(20, 20))
    shown = [v for _, v in _ticks(m.ax.yaxis)]
    assert 0.0 in shown and 0.1 in shown and -0.1 in shown  # decades of metres


# ------------------------------------------------------------------------ trajectories
def test_trajectory_labels_dimensionless(trajectories):
    out = plots.plot_trajectory(trajectories["plain"], Figure())
    labels = {k: (out[k]["ax"].get_xlabel(), out[k]["ax"].get_ylabel())
              for k in ("paths", "theta", "energy", "forces")}
    assert labels["paths"] == ("$X$ [$a$]", "$Y$ [$a$]")
    for k in ("theta", "energy", "forces"):
        assert labels[k][0] == r"$t$ [$\sqrt{a/g}$]"
    assert labels["theta"][1] == r"$\theta$ [deg]"
    assert labels["energy"][1].endswith("[$mga$]") and labels["forces"][1].endswith("[$mg$]")


def test_trajectory_labels_and_ticks_si(trajectories):
    traj = trajectories["coin"]
    out = plots.plot_trajectory(traj, Figure())
    assert out["paths"]["ax"].get_xlabel() == "$X$ [m]"
    assert out["paths"]["ax"].get_ylabel() == "$Y$ [m]"
    for k in ("theta", "energy", "forces"):
        assert out[k]["ax"].get_xlabel() == "$t$ [s]"
    assert out["energy"]["ax"].get_ylabel().endswith("[J]")
    assert out["forces"]["ax"].get_ylabel().endswith("[N]")
    # the data stay dimensionless: theta in radians, t in sqrt(a/g)
    line = out["theta"]["theta"]
    assert line.get_xdata() == pytest.approx(np.asarray(traj.t))
    assert line.get_ydata() == pytest.approx(np.asarray(traj.theta))
    for pos, shown in _ticks(out["theta"]["ax"].xaxis):
        assert shown == pytest.approx(pos * math.sqrt(A / G), rel=1e-5, abs=1e-9)
    for pos, shown in _ticks(out["theta"]["ax"].yaxis):
        assert shown == pytest.approx(math.degrees(pos), abs=1e-6)
    for pos, shown in _ticks(out["paths"]["ax"].xaxis):
        assert shown == pytest.approx(pos * A, rel=1e-5, abs=1e-9)


def test_radius_without_mass_keeps_forces_in_mg():
    disk = rd.Disk(h=0.1, radius=0.05)
    m = rd.steady_motion(disk, "rough", 0.5, Omega0=1.5)
    traj = rd.simulate_steady(m, 0.5, t_eval=np.linspace(0, 0.5, 11))
    out = plots.plot_trajectory(traj, Figure())
    assert out["forces"]["ax"].get_xlabel() == "$t$ [s]"
    assert out["forces"]["ax"].get_ylabel().endswith("[$mg$]")  # forces need the mass
    assert out["energy"]["ax"].get_ylabel().endswith("[$mga$]")


def test_animation_clock_has_its_unit(trajectories):
    from rollingdisk.plotting.animation import _scene

    for name, unit in (("plain", "√(a/g)"), ("coin", " s")):
        fig = Figure()
        tf, draw = _scene(trajectories[name], fig, 2, None)
        draw(1)
        title = fig.texts[0].get_text()  # the title above the 3D axes, with the clock
        assert title.endswith(unit), title
        if name == "coin":
            shown = float(title.split("t =")[1].split()[0])
            assert shown == pytest.approx(tf[1] * math.sqrt(A / G), abs=0.006)


def test_exact_motion_labels(trajectories):
    m = rd.steady_motion(COIN, "rough", 0.5, Omega0=1.5)
    from rollingdisk.theory.exact import exact_steady

    ex = exact_steady(m, kick=0.05)
    out = plots.plot_exact(ex, Figure())
    assert out["theta"]["ax"].get_xlabel() == "$t$ [s]"
    assert out["theta"]["ax"].get_ylabel() == r"$\theta$ [deg]"
    assert out["rosette"]["ax"].get_xlabel() == "$X_P$ [m]"


def test_euler_disk_title_and_labels():
    """The title in one style (symbols with units, SI first) and Omega in rad/s."""
    from types import SimpleNamespace

    r = SimpleNamespace(end="fell-flat", status="completed", alpha=np.array([0.3, 0.001]),
                        t_end=1623.0, t_end_s=100.3)
    title = plots.euler_disk_title(r)
    assert title == ("Euler's disk: fell flat, α = 0.001 rad (0.0573°) at t = 100.3 s "
                     "(1623 √(a/g))")
