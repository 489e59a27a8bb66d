"""CLI `steady` and `thresholds`: JSON keys, values equal to the library's, errors as exit 2."""

from __future__ import annotations

import json
import math

import pytest

from rollingdisk import Disk, stability, thresholds
from rollingdisk.cli.app import main
from rollingdisk.theory.steady import steady_motion, straight_line

KEYS = {"ground", "h", "motion", "theta0", "Omega0", "omega0", "omega20", "omega30", "r_C",
        "r_P", "F_y", "varpi2", "stable", "period", "v_C"}


def run_json(capsys, *argv):
    assert main([*argv, "--json"]) == 0
    out = capsys.readouterr().out
    return json.loads(out)


def test_steady_circle_json(capsys):
    d = run_json(capsys, "steady", "--ground", "rough", "--h", "0.3", "--theta0", "30deg",
                 "--rC", "1.5")
    assert KEYS <= set(d)
    m = steady_motion(Disk(h=0.3), "rough", math.radians(30), r_C=1.5)
    assert d["theta0"] == pytest.approx(math.radians(30))
    assert d["Omega0"] == pytest.approx(m.Omega0) and d["r_C"] == pytest.approx(1.5)
    assert d["stable"] is False and d["period"] is None
    assert d["varpi2"] == pytest.approx(stability(m).varpi2)


def test_steady_other_parameters(capsys):
    d = run_json(capsys, "steady", "--h", "0.3", "--theta0", "0.9", "--Omega0", "2")
    assert d["motion"] == "circle" and d["stable"] is True
    assert d["period"] == pytest.approx(2 * math.pi / math.sqrt(d["varpi2"]))
    e = run_json(capsys, "steady", "--h", "0.3", "--theta0", "0.9", "--rP", str(d["r_P"]))
    assert e["Omega0"] == pytest.approx(2.0)
    s = run_json(capsys, "steady", "--ground", "smooth", "--h", "0.5", "--theta0",
                 str(math.atan(0.5)), "--Omega0", "3")
    assert s["motion"] == "spin" and s["F_y"] == 0.0 and s["r_C"] == 0.0
    n = run_json(capsys, "steady", "--h", "0.3", "--theta0=-30deg", "--Omega0", "1")
    assert n["theta0"] == pytest.approx(-math.pi / 6)


def test_steady_straight_json(capsys):
    d = run_json(capsys, "steady", "--h", "0", "--motion", "straight", "--omega0", "1")
    m = straight_line(Disk(h=0.0), "rough", 1.0)
    assert d["motion"] == "straight" and d["r_C"] is None and d["stable"] is True
    assert d["varpi2"] == pytest.approx(stability(m).varpi2)
    d = run_json(capsys, "steady", "--h", "0", "--motion", "straight", "--omega0", "0.5")
    assert d["stable"] is False  # 0.25 < 1/3, eq. (42)


def test_steady_table(capsys):
    assert main(["steady", "--h", "0.3", "--theta0", "30deg", "--rC", "1.5"]) == 0
    out = capsys.readouterr().out
    assert "Omega0" in out and "varpi2" in out and "stable" in out


def test_thresholds(capsys):
    d = run_json(capsys, "thresholds", "--h", "0")
    assert d == {"rough": {"straight_line_omega20_sq": pytest.approx(1 / 3),
                           "se_circle_omega30_sq": pytest.approx(0.8)},
                 "smooth": {"straight_line_omega20_sq": pytest.approx(1.0),
                            "spin_omega30_sq": pytest.approx(4.0)}}
    assert d == thresholds(0.0).as_dict()
    assert main(["thresholds", "--h", "0.7"]) == 0
    assert "(57)" in capsys.readouterr().out


@pytest.mark.parametrize("argv,needle", [
    (["steady", "--h", "0.3", "--theta0", "10deg", "--rC", "1.5"], "r_C <"),
    (["steady", "--h", "-1", "--theta0", "0.3", "--Omega0", "1"], "h must"),
    (["steady", "--h", "0.3", "--theta0", "abc", "--Omega0", "1"], "invalid angle"),
    (["steady", "--h", "0.3", "--theta0", "0.3"], "one of"),
    (["steady", "--h", "0.3", "--Omega0", "1"], "--theta0"),
    (["steady", "--h", "0.3", "--theta0", "0.3", "--Omega0", "1", "--rC", "2"], "not allowed"),
    (["steady", "--h", "0.3", "--theta0", "0.3", "--motion", "straight", "--omega0", "1"],
     "arctan"),
    (["steady", "--h", "0.3", "--motion", "straight"], "--omega0"),
    (["steady", "--ground", "smooth", "--h", "0.3", "--theta0", "0.3", "--rC", "1"],
     "smooth"),
    (["steady", "--h", "0.3", "--theta0", "100deg", "--Omega0", "1"], "theta0"),
    (["steady", "--h", "0.3", "--theta0", "0.3", "--Omega0", "0"], "straight"),
    (["thresholds", "--h", "nan"], "h must"),
    (["thresholds"], "--h"),
])
def test_errors_exit_2_one_line(capsys, argv, needle):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert needle in err
