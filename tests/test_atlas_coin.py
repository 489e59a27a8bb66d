"""The atlas of a named disk (a 1-euro coin) is about the coin.

Sources of truth, independent of the atlas's code: the straight-rolling threshold of eq. (42)
as printed, ``omega20^2 > (3 + 8 h^2) sqrt(1 + h^2) / (3 (3 + 2 h^2))``, turned into a speed
of the centre ``v = a omega20`` with the coin's own scale ``sqrt(g a)`` (from the European
Central Bank's dimensions, written here again); the coin at rest flat on a face has the
energy ``m g h a`` of its centre at height ``h a`` and no kinetic energy; the run's time in
seconds is its time in ``sqrt(a/g)`` times ``sqrt(a/g)``; Euler's disk's end time agrees
with the adiabatic decay along the steady family.  The log-log axis of Euler's disk is
checked by the text extents matplotlib draws (no two tick labels overlap).
"""

from __future__ import annotations

import html
import math
import re

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402

import rollingdisk as rd  # noqa: E402
from rollingdisk.atlas.build import build_atlas  # noqa: E402
from rollingdisk.atlas.page import _object  # noqa: E402

#: The 1-euro coin (European Central Bank): 23.25 mm across, 2.33 mm thick, 7.5 g.
A, THICK, MASS, G = 0.02325 / 2, 0.00233, 0.0075, 9.80665
H = THICK / (2 * A)


def eq42(h: float) -> float:
    """omega20^2 of the rough-ground straight line in the SE position, eq. (42)."""
    return (3 + 8 * h * h) * math.sqrt(1 + h * h) / (3 * (3 + 2 * h * h))


def _text(fragment: str) -> str:
    """The text of an HTML fragment (tags dropped, entities resolved, spaces collapsed)."""
    text = " ".join(html.unescape(re.sub(r"<[^>]+>", " ", fragment)).split())
    return text.replace(" )", ")").replace("( ", "(")


@pytest.fixture(scope="module")
def coin_atlas(tmp_path_factory):
    disk = rd.disk_from_options(disk="euro-1")
    return build_atlas(disk, tmp_path_factory.mktemp("coin") / "atlas", quick=True,
                       progress=False)


@pytest.fixture(scope="module")
def page(coin_atlas):
    return coin_atlas.index.read_text(encoding="utf-8")


def _lead(page: str) -> str:
    """What comes before the first section: the heading, the answers, the introduction."""
    return page[:page.index("<h2")]


def test_the_page_names_the_coin(page):
    title = re.search(r"<title>(.*?)</title>", page).group(1)
    h1 = re.search(r"<h1>(.*?)</h1>", page, re.S).group(1)
    assert "1-euro coin" in title and "1-euro coin" in h1
    assert "11.62 mm" in h1 and "2.33 mm" in h1


def test_it_leads_with_the_straight_rolling_speed(page):
    w = math.sqrt(eq42(H))
    v_si = w * math.sqrt(G * A)  # m/s
    assert f"{v_si:.3g}" == "0.197"
    lead = _text(_lead(page))
    assert lead.index("at a glance") < lead.index("A homogeneous disk")  # before the intro
    assert "It rolls straight and stable above 0.197 m/s" in lead
    assert f"{w * math.sqrt(G / A):.4g} rad/s" in lead  # 16.98 rad/s about its axis
    assert f"{w:.4g} √(ga)" in lead and f"{eq42(H):.4g} g/a, eq. (42)" in lead
    # tilted at the static-equilibrium tilt, tan theta0 = h
    assert f"tilted {math.degrees(math.atan(H)):.4g}° from upright" in lead


def test_how_long_it_spins_is_the_coins_run(coin_atlas, page):
    ed = coin_atlas.motions["euler_disk"]
    p = ed["parameters"]
    assert (p["radius_m"], p["thickness_m"], p["mass_kg"]) == (A, THICK, MASS)
    assert ed["t_end_s"] == pytest.approx(ed["t_end"] * math.sqrt(A / G), rel=1e-12)
    # the run ends where the adiabatic decay along the steady family says
    assert ed["t_end_s"] == pytest.approx(ed["predicted_t_end_s"], rel=0.01)
    lead = _text(_lead(page))
    assert f"it whirrs for {ed['t_end_s']:.3g} s and falls flat" in lead
    assert f"tilt α 0 = {math.degrees(p['alpha0']):.3g}°" in lead
    assert "creep friction" in lead and "rolling resistance" in lead  # what it assumes


def test_how_it_falls_is_the_coins_run(coin_atlas, page):
    m = coin_atlas.motions["to_rest"]
    assert m["h"] == pytest.approx(H, rel=1e-12)  # the coin, not the generic thick disk
    assert m["status"] == "at-rest" and m["pose"] == "flat" and m["n_face"] >= 1
    # at rest flat: no kinetic energy, the centre at height h a
    assert m["energy_final"] == pytest.approx(H, rel=1e-9)
    assert m["energy_initial"] == pytest.approx(
        m["energy_final"] + m["impact_loss"] + m["dissipated"], abs=1e-9)
    assert m["t_end_si"] == pytest.approx(m["t_end"] * math.sqrt(A / G), rel=1e-12)
    assert m["Z_C_si"] == pytest.approx(m["Z_C"] * A, rel=1e-12)
    lead = _text(_lead(page))
    assert "Let go tilted, it ends flat on a face (outcome at-rest)" in lead
    assert f"after {m['t_end_si']:.3g} s" in lead


def test_every_section_is_about_the_coin(page):
    text = _text(page)
    rest = text[text.index("Past the guards: a disk let go to rest Th"):]
    assert "The 1-euro coin, h = 0.1," in rest and "A thick disk" not in text
    assert "The 1-euro coin (radius 11.62 mm" in text
    assert "commercial toy" not in text


def test_no_answers_without_a_size():
    """The dimensionless disk's page has no answers block; a physical disk that is in no
    table is "this disk"; a named disk keeps its name with another mass."""
    assert _object(rd.Disk(0.17)) is None
    assert _object(rd.disk_from_options(radius="1cm", thickness="2mm")) == "this disk"
    assert _object(rd.disk_from_options(disk="euro-1", mass="10g")) == "the 1-euro coin"
    from rollingdisk.model.units import DISKS

    for name in DISKS:
        what = _object(rd.disk_from_options(disk=name))
        assert what not in (None, "this disk") and ":" not in what, name


# ------------------------------------------------------------------------- log-log ticks
def _tick_label_overlaps(fig, ax) -> list:
    """Pairs of drawn tick labels of ``ax`` (major and minor, inside the view) whose text
    extents overlap, as matplotlib lays them out."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    renderer = canvas.get_renderer()
    pairs = []
    for axis in (ax.xaxis, ax.yaxis):
        lo, hi = sorted(axis.get_view_interval())
        boxes = [t.label1.get_window_extent(renderer)
                 for t in axis.get_major_ticks() + axis.get_minor_ticks()
                 if lo <= t.get_loc() <= hi and t.label1.get_visible()
                 and t.label1.get_text()]
        pairs += [(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:] if a.overlaps(b)]
    return pairs


@pytest.mark.parametrize("lo,hi", [(3.5, 60.0), (6.0, 106.0), (1.2, 3.0), (0.02, 50.0),
                                   (4.0, 9.0), (0.5, 1.5)])
def test_euler_disk_log_log_tick_labels_do_not_overlap(lo, hi):
    """t0 - t from 3.5 s to 60 s is the coin's run from 17 degrees: matplotlib's default
    labels 3 and 4 x 10^0 (and 10^1) on top of each other there."""
    import numpy as np
    from matplotlib.figure import Figure
    from matplotlib.ticker import LogFormatterSciNotation

    from rollingdisk.plotting.euler_plot import _sparse_log_labels

    def draw(fix: bool):
        fig = Figure(figsize=(10.0, 4.2))
        ax = fig.subplots(1, 2)[1]  # the right half, as in plot_euler_disk
        t = np.geomspace(lo, hi, 50)
        ax.loglog(t, 20.0 / t)
        ax.set_xlabel("t0 - t [s]")
        if fix:
            _sparse_log_labels(ax)
        else:
            ax.xaxis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False))
        fig.tight_layout()
        return fig, ax

    if (lo, hi) == (3.5, 60.0):  # the check sees the collision the fix removes
        assert _tick_label_overlaps(*draw(False))
    fig, ax = draw(True)
    assert not _tick_label_overlaps(fig, ax)
    labelled = [t.get_loc() for t in ax.xaxis.get_major_ticks() + ax.xaxis.get_minor_ticks()
                if lo <= t.get_loc() <= hi and t.label1.get_text()]
    assert labelled or hi / lo < 2.0  # an axis of some extent keeps a label


def test_a_disk_without_mass_says_what_it_needs(tmp_path):
    """A disk with a size but no mass: the answers name the missing mass and the Euler's
    disk section stays the commercial toy; the run to rest is still this disk's."""
    from rollingdisk.atlas.page import _answers, _ran_as_euler_disk
    from rollingdisk.atlas.steps import _to_rest_section

    disk = rd.disk_from_options(radius="2cm", thickness="3mm")
    thr = rd.thresholds(disk).as_dict()
    toy = {"parameters": {"radius_m": 0.0375, "mass_kg": 0.45}}
    rest = _to_rest_section(tmp_path, True, [], disk)
    assert rest["h"] == pytest.approx(0.003 / 0.04, rel=1e-12)
    text = _text(_answers(disk, thr, {"euler_disk": toy, "to_rest": rest}))
    assert text.startswith("This disk, at a glance")
    v = math.sqrt(eq42(0.075) * G * 0.02)
    assert f"above {v:.3g} m/s" in text and "needs its mass" in text
    assert _ran_as_euler_disk(disk, {"euler_disk": toy}) is None  # the section: the toy
