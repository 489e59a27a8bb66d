"""CLI `simulate --ground coulomb`: the classic sliding disk (closed form t* = v0/(3 mu)),
the friction a steady circle needs (closed form mu_required), the energy balance, the CSV
with its mode column, and errors as one line with exit 2."""

from __future__ import annotations

import csv
import json

import pytest

import rollingdisk as rd
from rollingdisk.cli.app import main


def run_json(capsys, *argv):
    assert main(["simulate", "--ground", "coulomb", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_classic_sliding_disk(capsys):
    """h = 0 upright, sliding with V_X = v0: rolls from t = v0/(3 mu) (m = a = g = 1)."""
    d = run_json(capsys, "--mu", "0.25", "--h", "0", "--state", "theta=0,V_X=1.5",
                 "--t-end", "3")
    assert d["status"] == "completed" and d["mode_end"] == "rolling"
    [x] = d["transitions"]
    assert (x["from"], x["to"]) == ("sliding", "rolling")
    assert x["t"] == pytest.approx(1.5 / (3 * 0.25), rel=1e-9)
    assert d["dissipated"]["slip"] == pytest.approx(1.5**2 / 6, rel=1e-9)
    assert d["energy_balance"] < 1e-9


@pytest.mark.parametrize("factor,slides", [(1.01, False), (0.99, True)])
def test_steady_circle_around_mu_required(capsys, factor, slides):
    m = rd.steady_motion(rd.Disk(0.17), "rough", 0.5236, r_C=0.5)
    mu = factor * m.mu_required
    d = run_json(capsys, "--mu", repr(mu), "--h", "0.17", "--theta0", "0.5236", "--rC", "0.5",
                 "--t-end", "2")
    if slides:
        assert d["transitions"][0] == {"t": 0.0, "from": "rolling", "to": "sliding"}
    else:
        assert d["transitions"] == [] and d["mode_end"] == "rolling"
        assert d["theta_max"] == pytest.approx(0.5236, abs=1e-8)


def test_dissipation_and_csv(capsys, tmp_path):
    out = tmp_path / "c.csv"
    d = run_json(capsys, "--mu", "0.6", "--h", "0.1", "--theta0", "0.4", "--Omega0", "3",
                 "--kick", "0.05", "--rolling-resistance", "0.01", "--pivot", "0.005",
                 "--t-end", "5", "--out", str(out))
    assert d["energy_balance"] < 1e-9
    assert d["dissipated"]["rolling_resistance"] > 0 and d["dissipated"]["pivot"] > 0
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    assert rows[0].keys() >= {"t", "theta", "V_X", "V_Y", "mode", "E"}
    assert {r["mode"] for r in rows} <= {"0", "1"}
    E = [float(r["E"]) for r in rows]
    assert all(b <= a + 1e-12 for a, b in zip(E, E[1:]))  # dE/dt <= 0 (eq. 14)
    assert [p.name for p in tmp_path.iterdir()] == ["c.csv"]


@pytest.mark.parametrize("argv,word", [
    (["--ground", "rough", "--mu", "0.3"], "--ground coulomb"),
    (["--ground", "coulomb"], "--mu"),
    (["--ground", "coulomb", "--mu", "0.1", "--mu-k", "0.2"], "mu_k"),
    (["--ground", "coulomb", "--mu", "-1"], "mu_s"),
    (["--ground", "coulomb", "--mu", "0.3", "--air", "nan"], "air"),
    (["--ground", "coulomb", "--mu", "0.3", "--method", "scipy"], "--method"),
])
def test_bad_input_exits_2(capsys, tmp_path, monkeypatch, argv, word):
    monkeypatch.chdir(tmp_path)
    code = main(["simulate", *argv, "--h", "0.1", "--theta0", "0.3", "--Omega0", "2",
                 "--t-end", "1", "--out", "x.csv"])
    assert code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and word in err[0], err
    assert list(tmp_path.iterdir()) == []
