"""Units in: dimensional inputs with units in Python and on the command line.

The paper's units are built independently here with pint from the disk's radius a, mass m
and gravity g (time sqrt(a/g), speed sqrt(a g), ...), never with the library's factors; the
round trip SI -> paper -> SI is checked to 1e-12 with hypothesis.
"""

from __future__ import annotations

import argparse
import json
import math

import pint
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rollingdisk as rd
from rollingdisk.cli._args import _Input, _Range, resolve_inputs
from rollingdisk.cli.app import build_parser, main
from rollingdisk.model.inputs import INPUT_KINDS, from_si, read_input, to_paper
from rollingdisk.model.units import to_si
from rollingdisk.util.errors import ParameterError

U = pint.UnitRegistry()
COIN = rd.disk_from_options(disk="euro-1")


def paper_unit(disk, kind) -> pint.Quantity:
    """The paper's unit of ``kind`` for ``disk``, built with pint from a, m, g."""
    a = U.Quantity(disk.radius, "m")
    g = U.Quantity(disk.gravity, "m/s^2")
    m = U.Quantity(disk.mass or 1.0, "kg")
    return {"time": (a / g) ** 0.5, "length": a, "speed": (a * g) ** 0.5,
            "angular_speed": (g / a) ** 0.5 * U.radian, "rolling_rate": (g / a) ** 0.5 *
            U.radian, "force": m * g, "energy": m * g * a,
            "inverse_speed": 1 / (a * g) ** 0.5,
            "moment_per_rate": m * a ** 1.5 * g ** 0.5}[kind]


def expected(disk, kind, text) -> float:
    q = U.Quantity(text)
    if kind == "rolling_rate" and q.dimensionality == U.Quantity("m/s").dimensionality:
        q = q / U.Quantity(disk.radius, "m") * U.radian  # v_C = a d phi/dt (eq. 18)
    return float((q / paper_unit(disk, kind)).to("dimensionless").magnitude)


SI_EXAMPLES = {"time": "2s", "length": "5cm", "speed": "0.3m/s",
               "angular_speed": "30rad/s", "rolling_rate": "0.3m/s",
               "inverse_speed": "5s/m", "moment_per_rate": "1e-9kg*m^2/s"}


# ----------------------------------------------------------------- Disk, both ways
disks = st.builds(lambda a, m, g: rd.Disk(0.1, radius=a, mass=m, gravity=g),
                  st.floats(1e-4, 10.0), st.floats(1e-4, 1e3), st.floats(0.1, 30.0))


@settings(max_examples=200, deadline=None)
@given(disks, st.floats(-1e6, 1e6, allow_nan=False),
       st.sampled_from(["time", "length", "speed", "angular_speed", "force", "energy"]))
def test_si_to_paper_to_si_round_trip(disk, x, kind):
    back = to_si(disk, kind, from_si(disk, kind, x))
    assert back == pytest.approx(x, rel=1e-12, abs=1e-300)
    named = getattr(disk, f"{kind}_to_si")(getattr(disk, f"{kind}_from_si")(x))
    assert named == pytest.approx(x, rel=1e-12, abs=1e-300)


@settings(max_examples=50, deadline=None)
@given(disks, st.floats(1e-3, 1e3),
       st.sampled_from(["time", "length", "speed", "force", "energy"]))
def test_from_si_is_the_paper_unit_built_with_pint(disk, x, kind):
    si = {"time": "s", "length": "m", "speed": "m/s", "force": "N", "energy": "J"}[kind]
    want = (U.Quantity(x, si) / paper_unit(disk, kind)).to("dimensionless").magnitude
    assert from_si(disk, kind, x) == pytest.approx(want, rel=1e-12)


def test_disk_takes_pint_quantities_and_text_with_units():
    d = rd.Disk(0.1, radius=pint.Quantity(1, "cm"), mass=pint.Quantity(2, "kg"),
                gravity="1.62 m/s^2")
    assert (d.radius, d.mass, d.gravity) == (pytest.approx(0.01), 2.0, 1.62)
    e = rd.Disk.from_dimensions(pint.Quantity(11.625, "mm"), "2.33 mm", U.Quantity(7.5, "g"))
    assert e.h == pytest.approx(COIN.h, rel=1e-12) and e.mass == pytest.approx(0.0075)
    assert rd.disk_from_options(disk="euro-1", mass=pint.Quantity(2, "kg")).mass == 2.0
    with pytest.raises(ParameterError, match="mass"):
        rd.Disk(0.1, radius=0.01, mass=pint.Quantity(2, "m"))


# ---------------------------------------------------------------------- the rule
@pytest.mark.parametrize("kind", sorted(INPUT_KINDS))
def test_the_rule_for_every_kind(kind):
    text = SI_EXAMPLES[kind]
    assert to_paper(COIN, kind, text) == pytest.approx(expected(COIN, kind, text), rel=1e-12)
    assert to_paper(COIN, kind, U.Quantity(text)) == pytest.approx(
        expected(COIN, kind, text), rel=1e-12)
    assert to_paper(COIN, kind, "20a") == 20.0 == to_paper(COIN, kind, 20.0)
    assert to_paper(rd.Disk(0.1), kind, "20") == 20.0  # no physical size: the paper's
    with pytest.raises(ParameterError, match=r"x 20 is ambiguous .* x 20\S+ .* x 20a "):
        to_paper(COIN, kind, "20", "x")
    with pytest.raises(ParameterError, match="needs a disk with a physical size"):
        to_paper(rd.Disk(0.1), kind, text, "x")
    with pytest.raises(ParameterError, match="x must be"):
        to_paper(COIN, kind, "3 kg*K", "x")


def test_read_input_says_how_a_value_was_given():
    assert read_input("time", 2.0) == ("paper", 2.0, None)
    assert read_input("time", "2.5a") == ("paper", 2.5, None)
    assert read_input("time", "2") == ("bare", 2.0, None)
    assert read_input("rolling_rate", "3 m/s") == ("si", 3.0, "m/s")
    assert read_input("angular_speed", "60rpm")[1] == pytest.approx(2 * math.pi)


# ---------------------------------------------------------------- the Python API
def test_steady_motion_and_straight_line_take_quantities():
    ref = rd.steady_motion(COIN, "rough", 0.5, Omega0=to_paper(COIN, "angular_speed",
                                                                "30 rad/s"))
    for Omega0 in ("30 rad/s", pint.Quantity(30, "rad/s"), U.Quantity(30, "rad/s")):
        assert rd.steady_motion(COIN, "rough", 0.5, Omega0=Omega0) == ref
    r = rd.steady_motion(COIN, "rough", 0.5, r_C="5 cm")
    assert r.to_si()["r_C_si"] == pytest.approx(0.05, rel=1e-12)
    line = rd.straight_line(COIN, "rough", pint.Quantity(0.3, "m/s"))
    assert line.to_si()["v_C_si"] == pytest.approx(0.3, rel=1e-12)
    with pytest.raises(ParameterError, match="ambiguous"):
        rd.steady_motion(COIN, "rough", 0.5, Omega0="30")
    with pytest.raises(ParameterError, match="physical size"):
        rd.steady_motion(rd.Disk(0.1), "rough", 0.5, Omega0="30 rad/s")


def test_simulate_steady_takes_a_time_with_a_unit():
    m = rd.steady_motion(COIN, "rough", 0.5, Omega0="30 rad/s")
    tr = rd.simulate_steady(m, "0.05 s", kick=pint.Quantity(0.1, "rad/s"), method="scipy")
    assert tr.t[-1] == pytest.approx(expected(COIN, "time", "0.05s"), rel=1e-12)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
@pytest.mark.parametrize("theta0,omega30", [(0.3, 2.0), (-0.7, 1.2), (1.1, -3.0)])
def test_omega30_is_the_maps_coordinate(ground, theta0, omega30):
    from rollingdisk.theory.oscillations import varpi2_circle

    disk = rd.Disk(0.17)
    m = rd.steady_motion(disk, ground, theta0, omega30=omega30)
    assert m.omega30 == pytest.approx(omega30, rel=1e-15)
    assert m == rd.steady_motion(disk, ground, theta0, Omega0=omega30 / math.cos(theta0))
    # the maps' and sweeps' route from (theta0, omega30): eq. (45) corrected / (55)
    assert rd.stability(m).varpi2 == pytest.approx(
        float(varpi2_circle(disk.h, ground, theta0, omega30)), rel=1e-10)
    with pytest.raises(ValueError, match="omega30"):
        rd.steady_motion(disk, ground, theta0, omega30=0.0)
    with pytest.raises(ParameterError, match="exactly one"):
        rd.steady_motion(disk, ground, theta0, omega30=1.0, Omega0=1.0)


# ----------------------------------------------------------------- the command line
def _dimensional_options():
    """(command, option, action) for every option of every command that reads a value
    with a unit (its type is :func:`rollingdisk.cli._args.quantity` or a range of it)."""
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    out = []
    for name, p in sub.choices.items():
        for action in p._actions:
            if not action.option_strings or action.help is argparse.SUPPRESS:
                continue
            try:
                value = action.type("1a") if action.type else None
            except (argparse.ArgumentTypeError, TypeError, ValueError):
                continue
            if isinstance(value, (_Input, _Range)):
                out.append((name, action.option_strings[0], action))
    return out


DIMENSIONAL = _dimensional_options()


def test_the_dimensional_options_are_all_there():
    found = {(c, o) for c, o, _ in DIMENSIONAL}
    for command in ("steady", "simulate", "exact", "animate"):
        for option in ("--Omega0", "--omega30", "--rC", "--rP", "--omega0"):
            assert (command, option) in found
    for command in ("simulate", "sweep", "animate"):
        assert (command, "--t-end") in found
    for command in ("simulate", "exact", "animate", "sweep"):
        assert (command, "--kick") in found
    assert {("simulate", "--rolling-resistance"), ("simulate", "--pivot"),
            ("simulate", "--air"), ("euler-disk", "--rolling-resistance"),
            ("euler-disk", "--creep"), ("sweep", "--omega30"), ("sweep", "--rC"),
            ("sweep", "--Omega0"), ("sweep", "--omega0")} <= found


@pytest.mark.parametrize("command,option,action", DIMENSIONAL,
                         ids=[f"{c} {o}" for c, o, _ in DIMENSIONAL])
def test_every_dimensional_option_takes_units(command, option, action):
    kind = (action.type("1a").ends[0] if isinstance(action.type("1a"), _Range)
            else action.type("1a")).kind
    text = SI_EXAMPLES[kind]
    ns = argparse.Namespace(value=action.type(text))
    echo = resolve_inputs(ns, COIN)
    want = expected(COIN, kind, text)
    got = ns.value[0] if isinstance(ns.value, list) else ns.value
    assert got == pytest.approx(want, rel=1e-12)
    assert echo and option in echo[0] and text in echo[0]
    bare = argparse.Namespace(value=action.type("2"))
    with pytest.raises(ParameterError, match=rf"{option} 2 is ambiguous.*{option} 2a"):
        resolve_inputs(bare, COIN)
    plain = argparse.Namespace(value=action.type("2"))
    resolve_inputs(plain, rd.Disk(0.1))
    assert (plain.value[0] if isinstance(plain.value, list) else plain.value) == 2.0


def test_a_range_with_units():
    parse = build_parser().parse_args
    args = parse(["sweep", "--ground", "rough", "--disk", "euro-1", "--theta0", "0.5",
                  "--omega30", "10rad/s:30rad/s:3", "--t-end", "1s", "--out", "x.nc"])
    resolve_inputs(args, COIN)
    f = expected(COIN, "angular_speed", "1rad/s")
    assert args.omega30 == pytest.approx([10 * f, 20 * f, 30 * f], rel=1e-12)


def _json(capsys, *argv) -> dict:
    assert main([*argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_done_when_thresholds(capsys):
    assert main(["thresholds", "--disk", "euro-1"]) == 0
    out = capsys.readouterr().out
    assert "0.197365 m/s" in out and "rad/s" in out


def test_done_when_steady_straight_in_m_per_s(capsys):
    assert main(["steady", "--disk", "euro-1", "--motion", "straight", "--omega0",
                 "0.3m/s"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("units: --omega0 0.3m/s = 0.888514") and "0.3 m/s" in out
    d = _json(capsys, "steady", "--disk", "euro-1", "--motion", "straight", "--omega0",
              "0.3m/s")
    assert d["v_C_si"] == pytest.approx(0.3, rel=1e-12)


def test_done_when_simulate_two_seconds(capsys):
    argv = ["simulate", "--disk", "euro-1", "--theta0", "30deg", "--Omega0", "30rad/s",
            "--kick", "0.1rad/s", "--t-end", "2s", "--method", "dop853"]
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert "--t-end 2s = 58.0889936" in out and "2 s" in out
    d = _json(capsys, *argv)
    assert d["t_end_si"] == pytest.approx(2.0, rel=1e-12)


def test_done_when_bare_number_is_one_line(capsys):
    assert main(["simulate", "--disk", "euro-1", "--theta0", "30deg", "--Omega0", "30rad/s",
                 "--t-end", "20"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["rollingdisk simulate: error: --t-end 20 is ambiguous with a physical "
                   "disk: write --t-end 20s (seconds) or --t-end 20a (paper units, "
                   "sqrt(a/g))"]


def test_state_components_take_units(capsys):
    d = _json(capsys, "simulate", "--disk", "euro-1", "--state",
              "theta=0.3,omega3=20rad/s,V_X=1cm/s", "--ground", "smooth", "--t-end", "0.01s")
    assert d["status"] == "completed"
    assert main(["simulate", "--disk", "euro-1", "--state", "theta=0.3,omega3=2",
                 "--t-end", "1s"]) == 2
    assert "--state omega3=2 is ambiguous" in capsys.readouterr().err
