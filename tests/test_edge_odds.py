"""Edge odds against thickness (:mod:`rollingdisk.scenarios.odds`): the no-bounce
probabilities against their derivation (sympy) and a Monte Carlo of random orientations; the
curve's counts against the ensembles it is made of, its resume, its CF-attributed file."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import sympy as sp

import rollingdisk as rd
from rollingdisk.scenarios.hand_toss import HandLaunch, table_ensemble
from rollingdisk.scenarios.odds import (
    EDGE_RATIOS,
    NICKEL_RATIO,
    YM_THIRD_ANGLE,
    YM_THIRD_SPHERE,
    EdgeOdds,
    edge_odds,
    no_bounce_edge_angle,
    no_bounce_edge_sphere,
)
from rollingdisk.util.errors import ParameterError


def test_no_bounce_probabilities_are_their_derivation():
    """A coin that stays as it lands rests on its tread when its axis lies within
    beta = arctan(t/d) of the horizontal: on the sphere that band is the area fraction
    (1/2) int_{-beta}^{beta} cos(lat) d lat; with the tilt uniform on [0, pi/2], the fraction
    beta/(pi/2).  Both derived here, and where each is 1/3."""
    r, lat = sp.symbols("r lat", positive=True)
    beta = sp.atan(r)
    sphere = sp.simplify(sp.integrate(sp.cos(lat), (lat, -beta, beta)) / 2)
    angle = beta / (sp.pi / 2)
    for x in (0.02, 0.0919, 0.3, 1 / math.sqrt(8), 1.0):
        assert float(no_bounce_edge_sphere(x)) == pytest.approx(float(sphere.subs(r, x)),
                                                                rel=1e-15)
        assert float(no_bounce_edge_angle(x)) == pytest.approx(float(angle.subs(r, x)),
                                                               rel=1e-15)
    third_sphere = sp.solve(sp.Eq(sphere, sp.Rational(1, 3)), r)
    third_angle = sp.solve(sp.Eq(angle, sp.Rational(1, 3)), r)
    assert [float(x) for x in third_sphere] == [pytest.approx(YM_THIRD_SPHERE, rel=1e-15)]
    assert [float(x) for x in third_angle] == [pytest.approx(YM_THIRD_ANGLE, rel=1e-15)]
    assert YM_THIRD_SPHERE in EDGE_RATIOS and YM_THIRD_ANGLE in EDGE_RATIOS


def test_no_bounce_sphere_is_the_fraction_of_random_axes_near_horizontal():
    """Monte Carlo: axes uniform on the sphere (normalised Gaussians); the fraction whose
    tilt from the horizontal is below arctan(r) lies within 4 standard errors."""
    v = np.random.default_rng(7).normal(size=(400_000, 3))
    v /= np.linalg.norm(v, axis=1)[:, None]
    lat = np.arcsin(np.abs(v[:, 2]))
    for r in (0.0919, 0.354, 1.0):
        p = float(no_bounce_edge_sphere(r))
        got = float(np.mean(lat < math.atan(r)))
        assert abs(got - p) < 4 * math.sqrt(p * (1 - p) / len(lat))


def test_curve_counts_are_the_ensembles_and_resume(tmp_path):
    """Each ratio's counts are the table ensemble of that thickness with the same seed;
    a second call on the same results folder runs nothing and gives the same counts."""
    launch = HandLaunch(upward_speed=3.0, flip_rate=4.0)
    ratios = (0.1, 0.6)
    a = edge_odds(ratios, 3, 5, launch=launch, results=tmp_path / "curve", t_end=200.0)
    assert isinstance(a, EdgeOdds) and a.n == 3 and np.array_equal(a.ratio, ratios)
    assert np.array_equal(sum(a.counts.values()), [3, 3])
    for i, h in enumerate(ratios):
        one = table_ensemble(rd.Disk(h), launch, 3, 5, t_end=200.0)
        assert {k: int(v[i]) for k, v in a.counts.items()} == one.counts
    files = sorted(p.name for p in (tmp_path / "curve").iterdir() if not p.name.startswith("."))
    assert files == ["edge-odds-0.1.jsonl", "edge-odds-0.6.jsonl"]
    b = edge_odds(ratios, 3, 5, launch=launch, results=tmp_path / "curve", t_end=200.0)
    assert all(np.array_equal(a.counts[k], b.counts[k]) for k in a.counts)
    lo, hi = a.interval("edge")
    p = a.probability("edge")
    assert np.all((lo <= p) & (p <= hi))
    assert "hand toss" in a.model and "e = 0.5" in a.model
    assert repr(a).startswith("EdgeOdds(n=3")


def test_file_is_cf_attributed_and_round_trips(tmp_path):
    xr = pytest.importorskip("xarray")
    counts = {"heads": np.array([40, 30]), "tails": np.array([50, 35]),
              "edge": np.array([10, 35]), "undecided": np.array([0, 0])}
    odds = EdgeOdds(np.array([NICKEL_RATIO, 0.5]), counts, 100, 1, 0.5, 0.5)
    path = odds.save(tmp_path / "edge-odds.nc")
    ds = xr.open_dataset(path, engine="scipy")
    assert ds.attrs["Conventions"].startswith("CF-")
    assert "Yong & Mahadevan" in ds.attrs["references"]
    for name, var in ds.data_vars.items():
        assert var.attrs["units"] == "1" and var.attrs["long_name"], name
    assert ds.ratio.attrs["units"] == "1"
    assert ds.count_edge.values.tolist() == [10, 35]
    assert ds.p_edge.values.tolist() == [0.1, 0.35]
    # the Wilson interval: p = 0.35, n = 100
    z = 1.959963984540054
    c = (0.35 + z * z / 200) / (1 + z * z / 100)
    w = z * math.sqrt(0.35 * 0.65 / 100 + z * z / 40000) / (1 + z * z / 100)
    assert ds.p_edge_low.values[1] == pytest.approx(c - w, rel=1e-14)
    assert ds.p_edge_high.values[1] == pytest.approx(c + w, rel=1e-14)


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"ratios": (0.0,)}, "ratios must be thicknesses"),
    ({"ratios": (1.5,)}, "ratios must be thicknesses"),
    ({"ratios": ()}, "ratios must be thicknesses"),
    ({"n": 0}, "n must"),
    ({"n": 10**9}, "n must"),
    ({"e": 1.5}, "e must"),
    ({"mu": -1.0}, "mu must"),
])
def test_bad_input_is_refused_naming_it(kwargs, match):
    with pytest.raises(ParameterError, match=match):
        edge_odds(**{"ratios": (0.3,), "n": 1, **kwargs})


def test_results_that_is_a_file_is_refused(tmp_path):
    f = tmp_path / "f.txt"
    f.write_text("not ours")
    with pytest.raises(ParameterError, match="results: .* is not a folder"):
        edge_odds((0.3,), 1, results=f)
    with pytest.raises(TypeError, match="launch must be a HandLaunch"):
        edge_odds((0.3,), 1, launch="hand")


def test_plot_draws_the_curve_the_no_bounce_lines_and_the_nickel(tmp_path):
    pytest.importorskip("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    from rollingdisk.plotting import plot_edge_odds

    counts = {"heads": np.array([60, 40]), "tails": np.array([40, 30]),
              "edge": np.array([0, 30]), "undecided": np.array([0, 0])}
    odds = EdgeOdds(np.array([0.05, 0.5]), counts, 100, 1, 0.5, 0.5)
    out = plot_edge_odds(odds)
    ax = out["ax"]
    assert ax.get_yscale() == "log"
    x, y = out["lines"]["no-bounce sphere"].get_data()
    assert np.allclose(y, no_bounce_edge_sphere(x), rtol=1e-15)
    # the edge frequency 0 at t/d = 0.05 is drawn at its interval's upper bound
    hi = odds.interval("edge")[1][0]
    assert any(np.allclose(line.get_ydata(), [hi]) for line in ax.get_lines())
    out["fig"].savefig(tmp_path / "edge.png")
    with pytest.raises(TypeError, match="odds must be"):
        plot_edge_odds({"edge": 1})


def test_cli_prints_the_curve_writes_its_file_and_refuses_bad_input(tmp_path, capsys):
    from rollingdisk.cli import main

    out, plot = tmp_path / "e.nc", tmp_path / "e.png"
    argv = ["edge-odds", "--n", "2", "--ratios", "0.1,0.5", "--upward-speed", "3",
            "--flip-rate", "4", "--seed", "3", "--quiet"]
    assert main([*argv, "--out", str(out), "--plot", str(plot)]) == 0
    text = capsys.readouterr().out
    assert text.splitlines()[0].split() == ["t/d", "heads", "tails", "edge", "undecided"]
    assert "model: hand toss" in text and "e = 0.5, mu = 0.5" in text
    assert out.stat().st_size > 0 and plot.read_bytes()[:4] == b"\x89PNG"
    assert main([*argv, "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    want = edge_odds((0.1, 0.5), 2, 3, launch=HandLaunch(upward_speed=3.0, flip_rate=4.0))
    assert got["counts"] == {k: v.tolist() for k, v in want.counts.items()}
    for bad in (["--ratios", "0,0.5"], ["--ratios", "x"], ["--n", "0"], ["--height", "0.2"],
                ["--restitution", "2"]):
        assert main(["edge-odds", "--n", "1", *bad]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith("rollingdisk edge-odds: error:"), err
