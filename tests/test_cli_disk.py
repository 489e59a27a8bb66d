"""CLI with a real disk (issue 19): every command takes the disk options (``--disk``,
``--radius``/``--diameter`` with ``--thickness``, ``--mass``, ``--gravity``) and answers in
SI beside the dimensionless values.

Independent truth: the straight-rolling threshold is computed here from the paper's eq. (42)
and converted by hand (``v = omega20 sqrt(a g)``, no slip); every ``<name>_si`` field of the
JSON must be its dimensionless value times the factor of its unit, computed here from the
radius, mass and gravity the test typed (times x sqrt(a/g), speeds x sqrt(a g), ...); the
SI CSV of ``simulate --out`` must be the dimensionless CSV of the same run, column by column
times the same factors.  Bad units and conflicting options: one line, exit status 2, naming
the option and what it expects.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

from rollingdisk.cli.app import main

G0 = 9.80665
#: The 1-euro coin (ECB): 23.25 mm across, 2.33 mm thick, 7.5 g.
EURO = {"a": 0.02325 / 2, "t": 0.00233, "m": 0.0075, "g": G0}
#: A disk given by its dimensions, with a gravity other than the default.
DIMS = ["--radius", "12.5mm", "--thickness", "0.2cm", "--mass", "10g", "--gravity",
        "9.81m/s^2"]
SCALE = {"a": 0.0125, "t": 0.002, "m": 0.010, "g": 9.81}


def factors(s: dict) -> dict:
    """Paper's unit -> (SI factor, SI units allowed), from the scale typed by hand."""
    a, g, m = s["a"], s["g"], s["m"]
    return {"sqrt(a/g)": (math.sqrt(a / g), {"s"}), "a": (a, {"m"}),
            "sqrt(a g)": (math.sqrt(a * g), {"m/s"}),
            "sqrt(g/a)": (math.sqrt(g / a), {"rad/s", "1/s"}), "g/a": (g / a, {"1/s^2"}),
            "m g": (m * g, {"N"}), "m g a": (m * g * a, {"J"})}


def eq42(h: float) -> float:
    """The rough-ground straight-line threshold omega20^2 of eq. (42), as printed."""
    return (3 + 8 * h * h) * math.sqrt(1 + h * h) / (3 * (3 + 2 * h * h))


def run_json(capsys, *argv) -> dict:
    assert main([*argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def check_si(d: dict, scale: dict, at_least: int = 1) -> int:
    """Every ``x_si`` with a dimensionless ``x`` beside it is ``x`` times the factor of
    its unit; returns how many were checked."""
    f = factors(scale)
    units = d["units"]
    n = 0
    for key, si in d.items():
        if not key.endswith("_si") or key[:-3] not in d or si is None:
            continue
        paper = units[key[:-3]]
        if paper in ("1", "rad"):
            continue
        factor, allowed = f[paper]
        assert units[key] in allowed, (key, units[key])
        base = d[key[:-3]]
        if isinstance(base, dict):
            for k in base:
                assert si[k] == pytest.approx(base[k] * factor, rel=1e-12, abs=1e-300), key
        elif isinstance(base, list):
            np.testing.assert_allclose(si, np.asarray(base) * factor, rtol=1e-12)
        else:
            assert si == pytest.approx(base * factor, rel=1e-12, abs=1e-300), key
        n += 1
    assert n >= at_least, d
    for name, value in (("radius_si", scale["a"]), ("thickness_si", scale["t"]),
                        ("gravity_si", scale["g"])):
        assert d[name] == pytest.approx(value, rel=1e-12)
    return n


# ------------------------------------------------------------------ thresholds
@pytest.mark.parametrize("argv", [
    ["--disk", "euro-1"],
    ["--radius", "11.625mm", "--thickness", "2.33mm", "--mass", "7.5g"],
    ["--diameter", "23.25mm", "--thickness", "2.33mm"],
    ["--diameter", "2.325cm", "--thickness", "0.00233"],  # a plain number is metres
])
def test_thresholds_speed_in_m_per_s(capsys, argv):
    h = EURO["t"] / (2 * EURO["a"])
    w2 = eq42(h)
    v = math.sqrt(w2) * math.sqrt(EURO["a"] * G0)  # rolling: v_C = omega20 (units sqrt(a g))
    assert v == pytest.approx(0.197, abs=5e-4)
    assert main(["thresholds", *argv]) == 0
    text = capsys.readouterr().out
    line = next(x for x in text.splitlines() if "straight line: speed of C" in x)
    m = re.search(r"([\d.]+) m/s\s+\(([\d.]+) sqrt\(a g\); squared ([\d.]+) g/a, eq\. \(42\)",
                  line)
    assert m, line
    assert float(m.group(1)) == pytest.approx(v, rel=1e-5)
    assert float(m.group(2)) == pytest.approx(math.sqrt(w2), rel=1e-5)
    assert float(m.group(3)) == pytest.approx(w2, rel=1e-9)
    d = run_json(capsys, "thresholds", *argv)
    assert d["rough_straight_line_speed_si"] == pytest.approx(v, rel=1e-12)
    assert d["rough"]["straight_line_omega20_sq"] == pytest.approx(w2, rel=1e-12)
    assert d["units"]["rough_straight_line_speed_si"] == "m/s"


def test_thresholds_json_converts_back(capsys):
    d = run_json(capsys, "thresholds", *DIMS)
    assert check_si(d, SCALE, at_least=9) >= 9
    assert d["mass_si"] == pytest.approx(0.010)


def test_dimensionless_thresholds_unchanged(capsys):
    d = run_json(capsys, "thresholds", "--h", "0.08")
    assert set(d) == {"rough", "smooth"}  # no SI without a size
    assert d["rough"]["straight_line_omega20_sq"] == pytest.approx(eq42(0.08), rel=1e-12)


# ------------------------------------------------------- every command: SI converts back
def test_steady_json_converts_back(capsys):
    d = run_json(capsys, "steady", *DIMS, "--theta0", "30deg", "--Omega0", "2a")
    assert check_si(d, SCALE, at_least=8) >= 8
    assert d["h"] == pytest.approx(0.08) and "F_y_si" in d and "period_si" in d
    d = run_json(capsys, "steady", "--disk", "us-quarter", "--motion", "straight",
                 "--omega0", "1a")
    assert d["v_C_si"] == pytest.approx(math.sqrt(0.02426 / 2 * G0), rel=1e-12)


def test_steady_text_has_si_column(capsys):
    assert main(["steady", *DIMS, "--theta0", "30deg", "--Omega0", "2a"]) == 0
    out = capsys.readouterr().out
    assert "rad/s" in out and re.search(r"period .* s ", out) and "radius 12.5 mm" in out


@pytest.mark.parametrize("extra", [
    ["--theta0", "0.4", "--Omega0", "3a", "--kick", "0.05a"],
    ["--ground", "smooth", "--state", "theta=0.3,omega3=2a"],
    ["--ground", "coulomb", "--mu", "0.6", "--theta0", "0.4", "--Omega0", "3a", "--kick",
     "0.3a", "--rolling-resistance", "0.01a", "--pivot", "0.005a"],
])
def test_simulate_json_converts_back(capsys, extra):
    d = run_json(capsys, "simulate", *DIMS, *extra, "--t-end", "3a")
    check_si(d, SCALE, at_least=1)
    assert d["t_end_si"] == pytest.approx(d["t_end"] * math.sqrt(SCALE["a"] / SCALE["g"]))
    for x in d.get("transitions", []):
        assert x["t_si"] == pytest.approx(x["t"] * math.sqrt(SCALE["a"] / SCALE["g"]))


def test_simulate_csv_in_si_is_the_dimensionless_run_scaled(capsys, tmp_path):
    """Same h, same run: the SI CSV is the dimensionless CSV times each column's factor;
    the names stay plain (genfromtxt names=True) and the units are in a comment line."""
    start = ["--theta0", "0.4", "--Omega0", "3a", "--kick", "0.05a", "--t-end", "3a"]
    si_csv, plain_csv = tmp_path / "si.csv", tmp_path / "plain.csv"
    run_json(capsys, "simulate", *DIMS, *start, "--out", str(si_csv))
    run_json(capsys, "simulate", "--h", "0.08", *start, "--out", str(plain_csv))
    lines = si_csv.read_text().splitlines()
    assert lines[0].split(",")[:3] == ["t", "X_C", "Y_C"]
    units = dict(c.split(" [") for c in lines[1].removeprefix("# ").split(","))
    units = {k: u.rstrip("]") for k, u in units.items()}
    assert units["t"] == "s" and units["F_z"] == "N" and units["E"] == "J"
    si = np.genfromtxt(si_csv, delimiter=",", names=True)
    plain = np.genfromtxt(plain_csv, delimiter=",", names=True)
    assert si.dtype.names == plain.dtype.names and si.size == plain.size
    f = factors(SCALE)
    paper = {"s": "sqrt(a/g)", "m": "a", "rad/s": "sqrt(g/a)", "N": "m g", "J": "m g a",
             "m/s": "sqrt(a g)"}
    for name in si.dtype.names:
        factor = 1.0 if units[name] in ("rad", "1") else f[paper[units[name]]][0]
        np.testing.assert_allclose(si[name], plain[name] * factor, rtol=1e-9,
                                   atol=1e-12 * factor, err_msg=name)


def test_coulomb_length_with_a_unit(capsys, tmp_path):
    d = run_json(capsys, "simulate", "--ground", "coulomb", "--mu", "0.5", *DIMS,
                 "--theta0", "0.4", "--Omega0", "3a", "--rolling-resistance", "25um",
                 "--t-end", "1a", "--out", str(tmp_path / "c.csv"))
    assert d["rolling_resistance"] == pytest.approx(25e-6 / SCALE["a"], rel=1e-12)
    assert d["rolling_resistance_si"] == pytest.approx(25e-6, rel=1e-12)
    data = np.genfromtxt(tmp_path / "c.csv", delimiter=",", names=True)
    assert {"t", "theta", "mode", "V_X"} <= set(data.dtype.names)


def test_exact_json_converts_back(capsys):
    d = run_json(capsys, "exact", *DIMS, "--theta0", "0.4", "--Omega0", "3a", "--kick", "0.3a")
    assert d["status"] == "bounded"
    check_si(d, SCALE, at_least=4)
    assert d["period_si"] == pytest.approx(d["period"] * math.sqrt(SCALE["a"] / SCALE["g"]))


@pytest.mark.slow
def test_sweep_json_with_a_disk(capsys, tmp_path):
    d = run_json(capsys, "sweep", "--ground", "rough", *DIMS, "--theta0", "0.5",
                 "--omega30", "1.5a", "--t-end", "2a", "--method", "dop853", "--workers", "1",
                 "--out", str(tmp_path / "s.nc"))
    assert d["n"] == 1 and d["h"] == pytest.approx(0.08)
    check_si(d, SCALE, at_least=1)
    assert main(["sweep", "--ground", "rough", "--disk", "euro-1", "--h", "0:1:3",
                 "--theta0", "0.5", "--omega30", "1.5a", "--t-end", "2a", "--out",
                 str(tmp_path / "t.nc")]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "--h A:B:N" in err


@pytest.mark.slow
def test_euler_disk_any_disk(capsys):
    d = run_json(capsys, "euler-disk", "--disk", "euro-1", "--alpha0", "0.05", "--quiet")
    p = d["parameters"]
    assert (p["radius_m"], p["thickness_m"], p["mass_kg"]) == (0.011625, 0.00233, 0.0075)
    assert d["end"] == "fell-flat"
    assert d["t_end_si"] == pytest.approx(d["t_end"] * math.sqrt(0.011625 / G0), rel=1e-12)
    assert d["t_end_s"] == pytest.approx(d["t_end_si"], rel=1e-12)


def test_euler_disk_needs_a_size_and_a_mass(capsys):
    assert main(["euler-disk", "--h", "0.1", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "--mass" in err


def test_map_and_animate_take_a_disk(capsys, tmp_path):
    png, gif = tmp_path / "m.png", tmp_path / "a.gif"
    assert main(["map", "--ground", "rough", "--disk", "euro-1", "--kind", "existence",
                 "--out", str(png), "--dpi", "20"]) == 0
    assert main(["animate", *DIMS, "--theta0", "30deg", "--Omega0", "2a", "--t-end", "1a",
                 "--frames", "2", "--dpi", "20", "--out", str(gif)]) == 0
    err = capsys.readouterr().err
    assert "radius 12.5 mm" in err and "rad/s" in err
    assert png.read_bytes()[:4] == b"\x89PNG" and gif.read_bytes()[:3] == b"GIF"


@pytest.mark.slow
def test_atlas_about_the_coin(capsys, tmp_path):
    out = tmp_path / "coin"
    assert main(["atlas", "--disk", "euro-1", "--quick", "--quiet", "--out", str(out)]) == 0
    thr = json.loads((out / "thresholds.json").read_text())
    h = EURO["t"] / (2 * EURO["a"])
    assert thr["h"] == pytest.approx(h)
    assert thr["rough_straight_line_speed_si"] == pytest.approx(
        math.sqrt(eq42(h) * EURO["a"] * G0), rel=1e-12)
    ed = json.loads((out / "euler_disk.json").read_text())
    assert ed["parameters"]["radius_m"] == EURO["a"]  # the coin is the one run


# ------------------------------------------------------------------ bad input
BAD = [
    (["--radius", "3kg", "--thickness", "1mm"], ["--radius", "length", "mass"]),
    (["--disk", "euro-1", "--mass", "-1g"], ["--mass", "positive", "mass"]),
    (["--radius", "1cm", "--thickness", "1e400mm"], ["--thickness", "floating-point"]),
    (["--radius", "3parsecs-ish-unknown", "--thickness", "1mm"],
     ["--radius", "unknown unit", "length"]),
    (["--radius", "1cm", "--thickness", "2mm", "--gravity", "3kg"], ["--gravity",
                                                                    "acceleration"]),
    (["--disk", "euro-1", "--radius", "1cm"], ["--disk", "--radius", "not both"]),
    (["--h", "0.1", "--thickness", "2mm", "--radius", "1cm"], ["--thickness", "--h"]),
    (["--radius", "1cm"], ["--radius", "--thickness"]),
    (["--thickness", "2mm"], ["--thickness", "--radius"]),
    (["--disk", "dime"], ["--disk", "euro-1"]),
]


@pytest.mark.parametrize("command", [
    ["thresholds"], ["steady", "--theta0", "0.3", "--Omega0", "2"],
    ["simulate", "--theta0", "0.3", "--Omega0", "2", "--t-end", "1", "--out", "x.csv"],
    ["exact", "--theta0", "0.3", "--Omega0", "2"],
])
@pytest.mark.parametrize("argv,words", BAD)
def test_bad_disk_one_line_exit_2(capsys, tmp_path, monkeypatch, command, argv, words):
    monkeypatch.chdir(tmp_path)
    assert main([*command, *argv]) == 2
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert all(w in lines[0] for w in words), lines[0]
    assert list(tmp_path.iterdir()) == []  # nothing written


def test_length_with_a_unit_needs_a_physical_disk(capsys):
    assert main(["simulate", "--ground", "coulomb", "--mu", "0.3", "--h", "0.1",
                 "--theta0", "0.3", "--Omega0", "2", "--t-end", "1",
                 "--rolling-resistance", "20um"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--rolling-resistance" in err[0] and "radius" in err[0]


def test_no_disk_where_one_is_required(capsys):
    assert main(["thresholds"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--h" in err[0] and "--disk" in err[0]


# ------------------------------------------------------------------ help
def test_help_names_disks_and_units(capsys):
    import rollingdisk as rd

    assert main(["simulate", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert all(name in text for name in rd.DISKS)
    assert "European Central Bank" in text  # each disk with its source
    for needle in ("dimensionless, 0 <= mu_k", "in units of the radius a, or a length with "
                   "a unit", "m a^(3/2) g^(1/2)", "units sqrt(g/a)", "--gravity"):
        assert needle in text, needle
    assert main(["euler-disk", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "friction coefficient at saturation, dimensionless" in text
    assert "1/sqrt(a g)" in text and "units of the radius a" in text
