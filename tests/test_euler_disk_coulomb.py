"""Euler's disk on set-valued Coulomb friction (``EulerDisk(friction="coulomb")``,
``euler-disk --friction coulomb``), against independent truths: the energy balance (eq. 12)
over rolling, sliding and every transition; a disk whose friction cone is never left rolls
throughout (no slip, nothing dissipated by it); the creep law converges to it as its
constant ``k`` grows (the creep law is a regularization of Coulomb's, so the limit k -> oo is
the set-valued law, reached monotonically here).

The toy itself is too long a run for the test suite (``docs/friction.md``: 7.5e7 steps,
about 8 minutes, to its fall at t = 1600.85, balance 2.2e-9); a disk tilted lower (alpha0 =
0.1, c = 1e-2) runs the same physics, rolling and then micro-slip to the end, in seconds."""

from __future__ import annotations

import json

import pytest

from rollingdisk.cli.app import main
from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk
from rollingdisk.util.errors import ParameterError

LOW = dict(alpha0=0.1, rolling_resistance=1e-2)


def test_friction_law_is_checked():
    with pytest.raises(ParameterError, match="friction must be one of creep, coulomb"):
        EulerDisk(friction="viscous")
    with pytest.raises(ParameterError, match="squeeze-film air law only"):
        EulerDisk(friction="coulomb", air_viscosity=1.8e-5, air_law="boundary-layer")


def test_inside_the_cone_it_rolls_to_the_end_without_slip():
    r = run_euler_disk(EulerDisk(mu=5.0, friction="coulomb", **LOW), predict=False)
    assert (r.status, r.end) == ("completed", "fell-flat")
    assert r.extra["transitions"] == ()  # never left the cone: rolling throughout
    assert float(r.slip_speed.max()) <= 1e-9  # eq. (6): u = 0 while rolling
    assert float(r.dissipated["slip"][-1]) == 0.0
    assert r.alpha[-1] == pytest.approx(1e-3, rel=1e-9)  # located on the step
    assert r.energy_balance <= 1e-9  # E + dissipated = E(0), eq. (12)
    # rolling resistance alone took the energy: E(0) - E(end) = its integral
    assert r.E[0] - r.E[-1] == pytest.approx(r.dissipated["rolling_resistance"][-1],
                                             rel=1e-8)


@pytest.mark.slow
def test_creep_runs_approach_the_coulomb_end_time_as_k_grows(monkeypatch):
    """mu = 1: rolling until the cone is left, then micro-slip (rolling <-> sliding) to the
    fall; the creep law's end time for k = 1e3, 1e4, 1e5 moves monotonically onto it.  The
    limit is the full set-valued law: the toy's quasi-static micro-slip (an approximation
    of it, docs/friction.md) is switched off here."""
    from rollingdisk.scenarios import euler_coulomb

    monkeypatch.setattr(euler_coulomb, "QUASI_STATIC_SLIP", 0.0)
    c = run_euler_disk(EulerDisk(mu=1.0, friction="coulomb", **LOW), predict=False,
                       max_steps=10**7, max_wall_time=300)
    assert (c.status, c.end) == ("completed", "fell-flat")
    assert len(c.extra["transitions"]) > 10  # it slid: the limit is not plain rolling
    assert c.dissipated["slip"][-1] > 1e-3
    assert c.energy_balance <= 1e-8
    ends = [run_euler_disk(EulerDisk(mu=1.0, creep=k, **LOW), predict=False).t_end
            for k in (1e3, 1e4, 1e5)]
    gaps = [t - c.t_end for t in ends]
    assert gaps[0] > gaps[1] > gaps[2] > 0.0, (ends, c.t_end)  # monotone, from above
    assert gaps[2] < 1e-2 * gaps[0]


def test_cli_friction_coulomb(capsys):
    args = ["euler-disk", "--friction", "coulomb", "--mu", "5", "--rolling-resistance",
            "0.01a", "--alpha0", "0.1", "--quiet"]
    assert main([*args, "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert (s["status"], s["end"]) == ("completed", "fell-flat")
    assert s["parameters"]["friction"] == "coulomb"
    assert s["n_transitions"] == 0 and s["energy_balance"] <= 1e-9
    assert main(args) == 0
    text = capsys.readouterr().out
    assert "transitions    0" in text and "fell flat" in text


def test_cli_friction_bad_choice(capsys):
    assert main(["euler-disk", "--friction", "glue"]) == 2
    err = capsys.readouterr().err
    assert "--friction" in err and len(err.strip().splitlines()) == 1


@pytest.mark.slow
def test_docs_mu_2_row_is_what_the_run_gives():
    """docs/friction.md's table of the lower disk quotes the mu = 2 run: its end time and its
    number of transitions are checked against a run here, so the page cannot go stale; the
    energy balance (eq. 12) closes over its transitions."""
    import re
    from pathlib import Path

    row = next(line for line in (Path(__file__).parents[1] / "docs" / "friction.md")
               .read_text().splitlines() if line.startswith("| Coulomb, μ = 2 ("))
    n_quoted, t_quoted = re.match(r"\| Coulomb, μ = 2 \((\d+) transitions\) \| ([\d.]+) \|",
                                  row).groups()
    r = run_euler_disk(EulerDisk(mu=2.0, friction="coulomb", **LOW), predict=False,
                       max_steps=10**7, max_wall_time=600)
    assert (r.status, r.end) == ("completed", "fell-flat")
    assert f"{r.t_end:.6f}" == t_quoted
    assert len(r.extra["transitions"]) == int(n_quoted)
    assert r.energy_balance <= 1e-9
