"""CLI `exact`: JSON keys; values against the linear theory and a simulation (independent
truths); every ending status; errors as one line and exit 2; the figure written whole."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.cli.app import main

KEYS = {"status", "theta_min", "theta_max", "period", "delta_psi", "varpi", "t_end",
        "theta_end", "drift", "frequency", "amplitude"}


def run_json(capsys, *argv):
    assert main(["exact", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_small_kick_gives_the_linear_period(capsys):
    d = run_json(capsys, "--h", "0.2", "--theta0", "0.5", "--Omega0", "3", "--kick", "1e-4")
    assert KEYS <= set(d)
    assert d["status"] == "bounded"
    assert d["period"] == pytest.approx(2 * math.pi / d["varpi"], rel=1e-6)


def test_state_and_simulation_agree(capsys):
    d = run_json(capsys, "--ground", "smooth", "--h", "0.1", "--state",
                 "theta=0.5,omega2=0.5,omega3=2.5,omega1=0.1")
    assert d["status"] == "bounded" and d["varpi"] is None
    y0 = [0, 0, 0, 0, 0, 0.5, 0, 0.1, 0.5, 2.5]
    tr = rd.simulate(rd.Disk(0.1), "smooth", (0, 3 * d["period"]), y0, rtol=1e-12,
                     atol=1e-12, dense_output=True)
    th = tr.sol(np.linspace(0, 3 * d["period"], 20001))[5]
    assert th.max() == pytest.approx(d["theta_max"], abs=1e-7)
    assert th.min() == pytest.approx(d["theta_min"], abs=1e-7)


@pytest.mark.parametrize("argv,status", [
    (["--h", "0.1", "--theta0", "0.4", "--Omega0", "3", "--kick", "1.0"], "lift-off"),
    (["--h", "0.3", "--theta0", "0.15", "--Omega0", "1", "--kick=-0.6"], "edge-contact"),
    (["--h", "0", "--state", "theta=0.3", "--ground", "smooth"], "fell-flat"),
    (["--h", "0.2", "--theta0", "0.5", "--Omega0", "3"], "steady"),
])
def test_statuses(capsys, argv, status):
    d = run_json(capsys, *argv)
    assert d["status"] == status
    if status in ("lift-off", "edge-contact", "fell-flat"):
        assert d["period"] is None and d["t_end"] > 0


@pytest.mark.parametrize("argv,word", [
    (["--h", "0.1", "--state", "theta=2"], "theta"),
    (["--h", "0.1", "--theta0", "0.4", "--Omega0", "3", "--kick", "5"], "F_z"),
    (["--h", "0.1", "--theta0", "0.4", "--Omega0", "3", "--kick", "nan"], "kick"),
    (["--h", "0.1", "--theta0", "0.4", "--Omega0", "3", "--out", "x.txt"], "--out"),
    (["--h", "0.1", "--theta0", "0.4", "--Omega0", "3", "--kick", "1", "--out", "x.png"],
     "bounded"),
    (["--h", "0.1", "--state", "theta=0.3", "--theta0", "0.3"], "--state"),
])
def test_bad_input_exits_2_with_one_line(capsys, tmp_path, monkeypatch, argv, word):
    monkeypatch.chdir(tmp_path)
    assert main(["exact", *argv]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and word in err[0], err
    assert list(tmp_path.iterdir()) == []


def test_figure(capsys, tmp_path):
    out = tmp_path / "ex.png"
    assert main(["exact", "--h", "0.1", "--theta0", "0.4", "--Omega0", "3", "--kick", "0.3",
                 "--periods", "5", "--out", str(out)]) == 0
    assert out.stat().st_size > 10_000
    assert [p.name for p in tmp_path.iterdir()] == ["ex.png"]
