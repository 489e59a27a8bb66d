"""``rollingdisk steady --rim-radius`` and ``rollingdisk simulate --rim-radius``: the rounded
disk's steady circles (theory/rounded.py) and runs (ivp/rounded.py) from the command line,
with units; bad input is one line on stderr and exit 2."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from rollingdisk import Disk
from rollingdisk.cli.app import main
from rollingdisk.model.rim import rim_contact
from rollingdisk.theory.rounded import rounded_steady_motion


def _run(capsys, *argv):
    rc = main(list(argv))
    out = capsys.readouterr()
    return rc, out.out, out.err


def test_steady_json_is_the_library_circle(capsys):
    rc, out, err = _run(capsys, "steady", "--h", "0.2", "--rim-radius", "0.1", "--theta0",
                        "0.4", "--Omega0", "2", "--json")
    assert rc == 0 and err == ""
    d = json.loads(out)
    m = rounded_steady_motion(Disk(0.2, rim_radius=0.1), "rough", 0.4, Omega0=2.0)
    for key in ("Omega0", "omega20", "omega30", "r_C", "r_P", "varpi2"):
        assert d[key] == getattr(m, key), key
    assert d["rim_radius"] == 0.1 and d["stable"] is True
    assert d["period"] == pytest.approx(2 * math.pi / math.sqrt(m.varpi2), rel=1e-15)


def test_steady_rP_and_omega30_name_the_same_circle(capsys):
    """--rP is r_C + y_P of the rounded contact; --omega30 is Omega0 cos(theta0)."""
    disk = Disk(0.2, rim_radius=0.1)
    y_P = float(rim_contact(0.2, 0.1, 0.4)[3])
    m = rounded_steady_motion(disk, "rough", 0.4, r_C=3.0 - y_P)
    rc, out, _ = _run(capsys, "steady", "--h", "0.2", "--rim-radius", "0.1", "--theta0",
                      "0.4", "--rP", "3", "--json")
    d = json.loads(out)
    assert rc == 0 and d["r_P"] == pytest.approx(3.0, abs=1e-14)
    assert d["Omega0"] == pytest.approx(m.Omega0, rel=1e-14)
    rc, out, _ = _run(capsys, "steady", "--h", "0.2", "--rim-radius", "0.1", "--theta0",
                      "0.4", "--omega30", repr(m.omega30), "--json")
    assert rc == 0 and json.loads(out)["Omega0"] == pytest.approx(m.Omega0, rel=1e-14)


def test_steady_with_units(capsys):
    rc, out, _ = _run(capsys, "steady", "--disk", "euro-1", "--rim-radius", "0.3mm",
                      "--theta0", "30deg", "--Omega0", "30rad/s")
    assert rc == 0
    assert "rho = 0.0258065 a" in out and "0.0003 m" in out and "30 rad/s" in out
    rc, out, _ = _run(capsys, "steady", "--disk", "euro-1", "--rim-radius", "0.3mm",
                      "--theta0", "30deg", "--Omega0", "30rad/s", "--json")
    d = json.loads(out)
    assert d["rim_radius_si"] == pytest.approx(3e-4, rel=1e-12)
    assert d["Omega0_si"] == pytest.approx(30.0, rel=1e-12)
    assert d["units"]["r_C_si"] == "m" and d["units"]["period_si"] == "s"


def test_simulate_a_kicked_circle_measures_varpi(capsys, tmp_path):
    out_csv = tmp_path / "run.csv"
    rc, out, err = _run(capsys, "simulate", "--h", "0.2", "--rim-radius", "0.1",
                        "--theta0", "0.4", "--Omega0", "2", "--kick", "1e-4", "--t-end", "40",
                        "--out", str(out_csv), "--json")
    assert rc == 0 and err == ""
    d = json.loads(out)
    assert d["status"] == "completed" and d["rim_radius"] == 0.1
    assert d["energy_drift"] < 1e-10
    assert d["theta_frequency"] == pytest.approx(d["varpi"], rel=1e-4)
    cols = np.genfromtxt(out_csv, delimiter=",", names=True)
    assert cols["t"][-1] == 40.0 and cols.size > 100
    assert np.ptp(cols["E"]) < 1e-10 and np.all(cols["F_z"] > 0)


def test_simulate_a_physical_disk_in_si(capsys, tmp_path):
    out_csv = tmp_path / "coin.csv"
    rc, out, _ = _run(capsys, "simulate", "--disk", "euro-1", "--rim-radius", "0.3mm",
                      "--theta0", "30deg", "--Omega0", "30rad/s", "--kick", "0.3rad/s",
                      "--t-end", "0.5s", "--out", str(out_csv), "--json")
    d = json.loads(out)
    assert rc == 0 and d["status"] == "completed"
    assert d["rim_radius_si"] == pytest.approx(3e-4, rel=1e-12)
    assert d["t_end_si"] == pytest.approx(0.5, rel=1e-12)
    lines = out_csv.read_text().splitlines()
    assert lines[1].startswith("# t [s],X_C [m]") and "F_z [N]" in lines[1]


def test_simulate_a_state_across_theta_zero(capsys):
    """rho = h: --state may start at theta = 0 and the disk rocks through it."""
    rc, out, _ = _run(capsys, "simulate", "--h", "0.2", "--rim-radius", "0.2", "--state",
                      "theta=0,omega1=0.2,omega2=1.07", "--t-end", "30", "--json")
    d = json.loads(out)
    assert rc == 0 and d["status"] == "completed"
    assert d["theta_min"] < -0.1 < 0.1 < d["theta_max"]


def test_simulate_text_ends_at_the_tread(capsys):
    rc, out, _ = _run(capsys, "simulate", "--h", "0.2", "--rim-radius", "0.1", "--state",
                      "theta=0.05,omega1=-0.3,omega2=1.5", "--t-end", "30")
    assert rc == 0
    assert out.startswith("tread-contact at t = ") and "rim_radius" in out


@pytest.mark.parametrize("argv, words", [
    (("steady", "--h", "0.2", "--rim-radius", "0.3", "--theta0", "0.4", "--Omega0", "2"),
     "--rim-radius must lie in [0, min(h, 1)]"),
    (("steady", "--h", "0.2", "--rim-radius", "0.1", "--motion", "straight", "--omega0",
      "2"), "--rim-radius takes a steady circle"),
    (("steady", "--h", "0.2", "--rim-radius", "0.1", "--theta0", "0.4"), "--theta0"),
    (("steady", "--h", "0.2", "--rim-radius", "0.1", "--ground", "smooth", "--theta0",
      "0.4", "--rC", "1"), "rough ground"),
    (("simulate", "--h", "0.2", "--rim-radius", "0.1", "--ground", "coulomb", "--mu",
      "0.3", "--theta0", "0.4", "--Omega0", "2", "--t-end", "1"), "Coulomb"),
    (("simulate", "--h", "0.2", "--rim-radius", "0.1", "--theta0", "0.4", "--Omega0", "2",
      "--t-end", "1", "--method", "taylor"), "--method"),
    (("simulate", "--h", "0.2", "--rim-radius", "0.1", "--state", "theta=0", "--t-end",
      "1"), "tread"),
    (("simulate", "--h", "0.2", "--rim-radius", "1mm", "--theta0", "0.4", "--Omega0", "2",
      "--t-end", "1"), "has a unit"),
])
def test_bad_input_is_one_line_and_exit_2(capsys, argv, words):
    with pytest.raises(SystemExit) as exc:
        rc = main(list(argv))
        raise SystemExit(rc)
    err = capsys.readouterr().err
    assert exc.value.code == 2
    assert words in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err
