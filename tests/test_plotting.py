"""Maps and the paper's figures: their content against the paper's quoted results.

Sources of truth: the thin-disk limits and thresholds the paper quotes (and attributes to
O'Reilly, Kuleshov, McDonald): rough SE circle omega30^2 > 4/5, smooth spin omega30^2 > 4
(h = 0); stable for every omega30 on rough ground iff theta0 > 18.6 deg, on smooth ground iff
theta0 > 21.5 deg (h = 0); the boundary r_C* of eq. (32) between existing and impossible
steady circles; the smooth surface varpi^2 = 0 closing at h = 1/2, omega30 = sqrt(3/2).
"""

import math
import os
import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from rollingdisk.plotting import plots as plotting
from rollingdisk.theory.regions import NO_MOTION, STABLE, UNSTABLE, varpi2_zero_surface


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


def _text(ax):
    return " ".join([ax.get_xlabel(), ax.get_ylabel(), ax.get_title()])


# ------------------------------------------------------------------------- existence map
@pytest.mark.parametrize("h", [0.0, 0.17, math.sqrt(3) / 2, 5.0])
def test_existence_boundary_is_r_C_star(h):
    """Eq. (32) and the text after it: for tan(theta0) < h a steady circle exists iff
    r_C < r_C*, for tan(theta0) > h iff r_C > r_C*."""
    m = plotting.plot_existence_map(h, "rough", n=(50, 60), r_C_scale="linear")
    TH, RC = np.meshgrid(m.x, m.y)
    p = np.tan(TH)
    star = -np.cos(TH) * ((3 + 4 * h * h) * p - 6 * h) / (6 * (3 + 2 * h * p))  # eq. (32)
    expect = np.where(p < h, RC < star, RC > star)
    # ignore the cells the boundary passes through
    dr = m.y[1] - m.y[0]
    clear = np.abs(RC - star) > dr
    exists = m.values != NO_MOTION
    assert np.mean(exists[clear] == expect[clear]) > 0.995
    assert "r_C" in _text(m.ax) and r"\theta_0" in _text(m.ax)
    assert "r_C_star" in m.artists


def test_existence_map_thin_disk_large_radius_unstable_small_tilt():
    """h = 0 (Figure 4a): a thin disk on a wide circle (r_C > 0) with small tilt is
    unstable, with large tilt stable; both exist."""
    m = plotting.plot_existence_map(0.0, "rough", n=(90, 60), r_C_range=(0.5, 1.0),
                                    r_C_scale="linear")
    TH, _ = np.meshgrid(m.x, m.y)
    assert m.share(NO_MOTION) == 0.0
    assert m.share(UNSTABLE, TH < 0.2) > 0.95
    assert m.share(STABLE, TH > 0.5) > 0.95


def test_existence_map_smooth_is_the_line_r_C_zero():
    m = plotting.plot_existence_map(0.3, "smooth", n=(20, 21))
    assert m.share(NO_MOTION) == 1.0
    line = m.artists["line"]
    assert np.allclose(line.get_ydata(), 0.0)


# ------------------------------------------------------------------------- stability map
def test_stability_map_rough_thin_disk_threshold():
    """h = 0, theta0 -> 0 (SE circle): stable iff omega30^2 > 4/5 (eq. 43 at h = 0)."""
    m = plotting.plot_stability_map(0.0, "rough", n=(80, 120), omega30_max=3.0)
    col = m.values[:, 0]  # theta0 = pi/2/81, the smallest tilt drawn
    w = m.y
    assert np.all(col[(w > 0.3) & (w < 0.85)] == UNSTABLE)
    assert np.all(col[w > 0.95] == STABLE)
    assert r"\omega_{30}" in _text(m.ax)


def test_stability_map_smooth_thin_disk_threshold():
    """h = 0, theta0 -> 0 (spin): stable iff omega30^2 > 4 (eq. 57 at h = 0)."""
    m = plotting.plot_stability_map(0.0, "smooth", n=(80, 120), omega30_max=3.0)
    col = m.values[:, 0]
    w = m.y
    assert np.all(col[(w > 0.6) & (w < 1.95)] == UNSTABLE)
    assert np.all(col[w > 2.05] == STABLE)


@pytest.mark.parametrize("ground,bound", [("rough", 1.0), ("smooth", 4.0)])
@pytest.mark.parametrize("h", [0.0, 0.17, 0.9, 3.0])
def test_stable_above_the_uniform_bound(ground, bound, h):
    """Stable for every h, theta0 if omega30^2 > 1 (rough, the paper's conclusion) or
    omega30^2 > 4 (smooth: the top of the surface varpi^2 = 0 is omega30 = 2 at h = 0, as
    section 4.2 says; the conclusion's "omega30^2 > 2" is a misprint)."""
    m = plotting.plot_stability_map(h, ground, n=(60, 60), omega30_max=3.0)
    _, W = np.meshgrid(m.x, m.y)
    assert m.share(STABLE, W * W > bound * 1.02) == 1.0


def test_smooth_conclusion_bound_two_is_a_misprint():
    """At h = 0, small theta0, smooth ground: 2 < omega30^2 < 4 is unstable, so the
    conclusion's uniform bound omega30^2 > 2 cannot hold (the paper's own limit, eq. (57)
    at h = 0, is omega30^2 > 4)."""
    m = plotting.plot_stability_map(0.0, "smooth", n=(60, 60), omega30_max=3.0)
    TH, W = np.meshgrid(m.x, m.y)
    band = (W * W > 2.2) & (W * W < 3.8) & (TH < 0.1)
    assert m.share(UNSTABLE, band) == 1.0


# ------------------------------------------------------------------- stable for all omega30
@pytest.mark.parametrize("ground,deg", [("rough", 18.6), ("smooth", 21.5)])
def test_all_omega30_thin_disk_angle(ground, deg):
    """h = 0: stable for every omega30 iff theta0 > 18.6 deg (rough, Kuleshov) or
    21.5 deg (smooth); the paper's closed forms give 18.58 and 21.47 deg."""
    m = plotting.plot_all_omega30_stable(ground, n=(180, 11), h_range=(0.0, 1.0))
    row = m.values[0]  # h = 0
    assert np.all(~row[m.x < deg - 0.7])
    assert np.all(row[(m.x > deg + 0.7) & (m.x < 89.0)])
    assert r"\theta_0" in m.ax.get_xlabel() and "deg" in m.ax.get_xlabel()


def test_all_omega30_rough_small_region_near_zero_tilt():
    """Figure 5 (right): a small region near theta0 = 0 is stable for every omega30."""
    m = plotting.plot_all_omega30_stable("rough", n=(40, 40), theta0_deg_range=(0.0, 1.0),
                                         h_range=(0.6, 1.05), asymptote=False)
    assert 0.05 < np.mean(m.values) < 0.95


def test_varpi2_curves_thin_disk_crossing():
    """h = 0 rough, theta0 -> 0: varpi^2 crosses zero at omega30^2 = 4/5 (eq. 43)."""
    out = plotting.plot_varpi2_curves(0.0, "rough", theta0s=[1e-6], n=3000)
    line = out["lines"][1e-6]
    w, v = line.get_xdata(), line.get_ydata()
    i = np.flatnonzero((v[:-1] < 0) & (v[1:] >= 0))[-1]
    assert w[i] == pytest.approx(math.sqrt(0.8), abs=2e-3)
    assert r"\varpi^2" in out["ax"].get_ylabel()
    assert r"\omega_{30}" in out["ax"].get_xlabel()


# ------------------------------------------------------------------------------ surfaces
def test_surface_roots_are_zeros_of_varpi2():
    """varpi^2 (the library's closed form) changes sign across each sheet drawn."""
    from rollingdisk import varpi2_circle

    th = np.linspace(0.05, 1.4, 15)
    hh = np.linspace(0.0, 2.0, 9)
    TH, H = np.meshgrid(th, hh)
    for ground in ("rough", "smooth"):
        lo, hi = varpi2_zero_surface(H, ground, TH)
        assert np.isfinite(lo).any() and np.isfinite(hi).any()
        apart = ~(np.abs(hi - lo) < 0.02 * hi)  # skip near-double roots
        for sheet in (lo, hi):
            ok = np.isfinite(sheet) & apart & (sheet > 0.01)  # tiny roots: near the SE tilt
            below = np.asarray(varpi2_circle(H[ok], ground, TH[ok], sheet[ok] * 0.99))
            above = np.asarray(varpi2_circle(H[ok], ground, TH[ok], sheet[ok] * 1.01))
            assert np.all(below * above < 0)


def test_surface_thin_disk_top_values():
    """theta0 -> 0, h = 0: the surface reaches omega30 = sqrt(4/5) (rough) and 2 (smooth)."""
    _, hi = varpi2_zero_surface(0.0, "rough", 1e-4)
    assert hi == pytest.approx(math.sqrt(0.8), rel=1e-3)
    _, hi = varpi2_zero_surface(0.0, "smooth", 1e-4)
    assert hi == pytest.approx(2.0, rel=1e-3)


def test_surface_smooth_closes_at_h_one_half():
    """Section 4.2: at theta0 = 0 the smooth surface ends at h = 1/2, omega30 = sqrt(3/2)."""
    lo, hi = varpi2_zero_surface(0.499, "smooth", 1e-4)
    assert lo == pytest.approx(math.sqrt(1.5), abs=0.06)
    assert hi == pytest.approx(math.sqrt(1.5), abs=0.06)
    lo, hi = varpi2_zero_surface(0.52, "smooth", 1e-4)
    assert np.isnan(lo) and np.isnan(hi)


def test_plot_surface_labels():
    m = plotting.plot_varpi2_surface("rough", n=(20, 20))
    assert {"lower", "upper"} <= set(m.artists)
    ax = m.ax
    assert r"\omega_{30}" in ax.get_zlabel() and "h" in ax.get_ylabel()


# ------------------------------------------------------------------------------ figures
def test_paper_figures_low_resolution(tmp_path):
    from PIL import Image

    from rollingdisk.plotting.figures import paper_figures

    paths = paper_figures(tmp_path, scale=0.12, dpi=40)
    assert [p.name for p in paths] == [f"fig{i}.png" for i in range(4, 9)]
    for p in paths:
        with Image.open(p) as im:
            assert im.size[0] > 100 and im.size[1] > 100


def test_figure4_panels():
    from rollingdisk.plotting.figures import FIGURE_HS, figure4

    fig = figure4(scale=0.15)
    assert len(fig.maps) == 4
    titles = [m.ax.get_title() for m in fig.maps]
    assert "$h = 0.17$" in titles[1] and r"\sqrt{3}/2" in titles[2]
    for m, h in zip(fig.maps, FIGURE_HS, strict=True):
        # every panel shows all three classes: none, unstable, stable
        assert all(m.share(c) > 0.01 for c in (NO_MOTION, UNSTABLE, STABLE)), h


def test_figure5_and_7_have_magnified_panel():
    from rollingdisk.plotting.figures import figure5, figure7

    for fig in (figure5(0.12), figure7(0.12)):
        main, zoom = fig.maps
        assert zoom.x.max() < main.x.max() / 5


def test_paper_figures_rejects_unknown(tmp_path):
    from rollingdisk.plotting.figures import paper_figures

    with pytest.raises(ValueError, match="fig4"):
        paper_figures(tmp_path, only=["fig3"])


def test_plotting_imports_without_matplotlib():
    """matplotlib is imported only inside the plot functions."""
    code = ("import sys\nsys.modules['matplotlib'] = None\n"
            "import rollingdisk.plotting.plots, rollingdisk.plotting.animation, "
            "rollingdisk.plotting.figures, "
            "rollingdisk.atlas.build\n")
    src = str(Path(__file__).resolve().parents[1] / "src")
    env = {**os.environ, "PYTHONPATH": src}
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert res.returncode == 0, res.stderr
