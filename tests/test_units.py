"""Quantities with units (issue 19): parsing, named disks, the disk carried downstream, SI views.

Sources of truth: hand conversion factors (1 mm = 1e-3 m, 1 in = 25.4 mm exactly, 1 lb =
0.45359237 kg exactly, 1 ft = 0.3048 m exactly); the published dimensions of the named disks;
the paper's eq. (42) and the thin-disk limit v^2 > g a / 3 of the classical rolling coin,
converted to SI by hand here; the definitions of the paper's units (time sqrt(a/g), speed
sqrt(a g), force m g, energy m g a).
"""

import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import rollingdisk as rd
from rollingdisk.model.disk import STANDARD_GRAVITY
from rollingdisk.model.units import (
    DISKS,
    disk_from_options,
    parse_acceleration,
    parse_length,
    parse_mass,
    si_fields,
)
from rollingdisk.scenarios.euler_disk import EulerDisk

SRC = str(Path(__file__).resolve().parents[1] / "src")

LENGTHS = {"mm": 1e-3, "cm": 1e-2, "m": 1.0, "km": 1e3, "um": 1e-6, "in": 0.0254,
           "ft": 0.3048, "inch": 0.0254}
MASSES = {"g": 1e-3, "kg": 1.0, "mg": 1e-6, "lb": 0.45359237, "t": 1e3}
ACCELERATIONS = {"m/s^2": 1.0, "m/s**2": 1.0, "cm/s^2": 1e-2, "ft/s^2": 0.3048,
                 "m s^-2": 1.0}
values = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False, allow_infinity=False)


# -------------------------------------------------------------------------- parsing
@settings(max_examples=150, deadline=None)
@given(values, st.sampled_from(sorted(LENGTHS)), st.sampled_from(["", " "]))
def test_length_round_trip_vs_hand_factor(x, unit, sep):
    assert parse_length(f"{x!r}{sep}{unit}") == pytest.approx(x * LENGTHS[unit], rel=1e-12)


@settings(max_examples=100, deadline=None)
@given(values, st.sampled_from(sorted(MASSES)))
def test_mass_round_trip_vs_hand_factor(x, unit):
    assert parse_mass(f"{x!r} {unit}") == pytest.approx(x * MASSES[unit], rel=1e-12)


@settings(max_examples=100, deadline=None)
@given(values, st.sampled_from(sorted(ACCELERATIONS)))
def test_acceleration_round_trip_vs_hand_factor(x, unit):
    assert parse_acceleration(f"{x!r}{unit}") == pytest.approx(x * ACCELERATIONS[unit],
                                                               rel=1e-12)


@settings(max_examples=100, deadline=None)
@given(st.floats(min_value=1e-300, max_value=1e300))
def test_plain_numbers_are_si(x):
    assert parse_length(repr(x)) == x
    assert parse_mass(x) == x
    assert parse_acceleration(str(x)) == float(str(x))


def test_examples_of_the_issue():
    assert parse_length("23.25mm") == pytest.approx(0.02325, rel=1e-15)
    assert parse_mass("7.5g") == pytest.approx(0.0075, rel=1e-15)
    assert parse_acceleration("9.81m/s^2") == 9.81
    assert parse_acceleration("1g0") == pytest.approx(STANDARD_GRAVITY, rel=1e-15)


@pytest.mark.parametrize("parse,text,words", [
    (parse_length, "3kg", "is a mass"),
    (parse_length, "9.81 m/s^2", "is an acceleration"),
    (parse_length, "3 mm^2", "is an area"),
    (parse_mass, "5mm", "is a length"),
    (parse_acceleration, "1g", "is a mass"),
    (parse_length, "1e400mm", "beyond floating-point range"),
    (parse_length, "1e400", "beyond floating-point range"),
    (parse_length, "10**400 mm", "beyond floating-point range"),
    (parse_length, "10**10**10 mm", "beyond floating-point range"),
    (parse_length, "-3mm", "must be positive"),
    (parse_length, "0 mm", "must be positive"),
    (parse_mass, "0", "must be positive"),
    (parse_length, "5 furlongz", "unknown unit"),
    (parse_length, "nan", "not a number"),
    (parse_length, "mm", "a number with a unit"),
])
def test_bad_quantities_are_named(parse, text, words):
    with pytest.raises(rd.ParameterError) as err:
        parse(text, "--radius")
    msg = str(err.value)
    assert msg.startswith("--radius must be"), msg
    assert words in msg, msg
    assert "such as" in msg  # says what it expects


@pytest.mark.parametrize("bad", [None, True, [1.0], b"3mm"])
def test_non_text_is_a_type_error(bad):
    with pytest.raises(rd.ParameterTypeError, match="--mass must be a mass"):
        parse_mass(bad, "--mass")


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=24))
def test_hostile_text_gives_a_number_or_our_error(text):
    try:
        x = parse_length(text, "--radius")
    except (rd.ParameterError, rd.ParameterTypeError) as err:
        assert "--radius" in str(err)
    else:
        assert math.isfinite(x) and x > 0


def test_import_and_plain_numbers_do_not_load_pint():
    code = ("import sys\nimport rollingdisk as rd\n"
            "assert rd.parse_length('0.5') == 0.5\n"
            "assert abs(rd.disk_from_options(radius=0.05, thickness=0.01).h - 0.1) < 1e-15\n"
            "assert 'pint' not in sys.modules, 'pint loaded'\n"
            "assert 'xarray' not in sys.modules and 'pandas' not in sys.modules\n")
    env = dict(os.environ, PYTHONPATH=SRC)
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert res.returncode == 0, res.stderr


# ----------------------------------------------------------------------- named disks
PUBLISHED = {  # name: (diameter mm, thickness mm, mass g), the sources' numbers
    "euler-disk": (75.0, 12.7, 450.0),
    "euro-1": (23.25, 2.33, 7.5),
    "us-quarter": (24.26, 1.75, 5.670),
    "cd": (120.0, 1.2, 16.0),
    "can": (66.0, 115.0, 350.0),
}


@pytest.mark.parametrize("name", sorted(PUBLISHED))
def test_named_disks_match_their_sources(name):
    diameter, thickness, mass = PUBLISHED[name]
    nd = DISKS[name]
    assert nd.name == name and len(nd.source) > 20
    d = disk_from_options(disk=name)
    assert d.radius == pytest.approx(diameter / 2 * 1e-3, rel=1e-14)
    assert d.h == pytest.approx(thickness / diameter, rel=1e-14)
    assert d.mass == pytest.approx(mass * 1e-3, rel=1e-14)
    assert d.gravity == STANDARD_GRAVITY
    assert set(DISKS) == set(PUBLISHED)


def test_the_can_and_the_cd_say_they_are_approximate():
    assert "approximate" in DISKS["can"].source
    assert "ECMA-130" in DISKS["cd"].source and "European Central Bank" in \
        DISKS["euro-1"].source and "Mint" in DISKS["us-quarter"].source
    assert "Moffatt" in DISKS["euler-disk"].source


def test_euler_disk_named_is_the_toy():
    toy, d = EulerDisk(), disk_from_options(disk="euler-disk")
    assert (toy.radius, toy.mass, toy.gravity) == (d.radius, d.mass, d.gravity)
    assert toy.h == pytest.approx(d.h, rel=1e-15)


# ------------------------------------------------------------------- disk_from_options
def test_disk_from_options_ways():
    a = disk_from_options(diameter="75mm", thickness="12.7mm", mass="450g",
                          gravity="1.62m/s^2")
    assert (a.radius, a.mass, a.gravity) == (pytest.approx(0.0375), pytest.approx(0.45), 1.62)
    assert a.h == pytest.approx(12.7 / 75, rel=1e-14)
    b = disk_from_options(radius="2cm", h="0.25")
    assert (b.radius, b.h, b.mass) == (pytest.approx(0.02), 0.25, None)
    assert disk_from_options(h=0.3) == rd.Disk(h=0.3)
    assert disk_from_options() == rd.Disk(h=rd.DEFAULT_H)
    assert disk_from_options(disk="euro-1", mass="8g").mass == pytest.approx(0.008)


@pytest.mark.parametrize("kw,words", [
    (dict(disk="euro-1", radius="1cm"), "not both"),
    (dict(disk="euro-1", h=0.1), "not both"),
    (dict(disk="penny"), "must be one of"),
    (dict(radius="1cm", diameter="2cm"), "not both"),
    (dict(radius="1cm"), "needs --thickness"),
    (dict(thickness="1mm"), "needs --radius or --diameter"),
    (dict(radius="1cm", thickness="1mm", h=0.1), "not both"),
    (dict(radius="3kg", thickness="1mm"), "--radius must be a length"),
    (dict(diameter="1cm", thickness="1kg"), "--thickness must be a length"),
    (dict(h="thick"), "--h must be a plain number"),
    (dict(h=-1), "--h must lie in"),
    (dict(h=0.1, gravity="9.81 m/s"), "--gravity must be an acceleration"),
])
def test_disk_from_options_conflicts(kw, words):
    with pytest.raises(rd.ParameterError, match=words.replace("(", r"\(")):
        disk_from_options(**kw, option_prefix="--")


# ------------------------------------------------------------ the scale carried downstream
def test_euro_threshold_speed_vs_closed_form():
    a, t, g = 23.25e-3 / 2, 2.33e-3, 9.80665  # the coin's radius and thickness; standard g
    h = t / (2 * a)
    omega20_sq = (3 + 8 * h * h) * math.sqrt(1 + h * h) / (3 * (3 + 2 * h * h))  # eq. (42)
    v = math.sqrt(omega20_sq) * math.sqrt(a * g)  # v_C = omega20 a' in units sqrt(a g)
    th = rd.thresholds(disk_from_options(disk="euro-1"))
    si = si_fields(th)
    assert si["rough_straight_line_speed_si"] == pytest.approx(v, rel=1e-12)
    assert si["units"]["rough_straight_line_speed_si"] == "m/s"
    assert si["rough_straight_line_speed_si"] == pytest.approx(0.197, abs=5e-4)


@settings(max_examples=30, deadline=None)
@given(st.floats(0.001, 1.0), st.floats(0.5, 30.0))
def test_thin_disk_threshold_is_the_classical_sqrt_g_a_over_3(a, g):
    # the rolling coin of zero thickness: stable straight rolling for v^2 > g a / 3
    si = rd.thresholds(rd.Disk(h=0.0, radius=a, gravity=g)).to_si()
    assert si["rough_straight_line_speed_si"] == pytest.approx(math.sqrt(g * a / 3),
                                                               rel=1e-12)


def test_every_h_function_takes_a_disk():
    d = rd.Disk.from_dimensions(radius=0.02, thickness=0.01, mass=0.1)
    h, th, r, w = d.h, np.array([0.3, 0.7]), np.array([0.5, 2.0]), np.array([0.8, 1.4])
    pairs = [
        (rd.Omega0_sq, (th, r)), (rd.r_C_star, (th,)), (rd.mu_required_map, (th, r)),
        (rd.se_circle_radius, (0.3,)), (rd.existence_codes, (th, r)),
        (rd.varpi2_closed_form, ("rough", 0.3, 0.2, 0.9)),
        (rd.circle_coefficients, ("smooth", th)), (rd.varpi2_circle, ("rough", th, w)),
        (rd.varpi2_rough_rC, (th, r)), (rd.critical_omega30_sq, ("rough", th)),
        (rd.stable_for_all_omega30, ("smooth", th)), (rd.varpi2_zero_surface, ("rough", th)),
        (rd.reduced_jacobian, ("rough", 0.3, 0.2, 0.9)),
    ]
    for f, args in pairs:
        np.testing.assert_array_equal(np.asarray(f(d, *args), dtype=float),
                                      np.asarray(f(h, *args), dtype=float), err_msg=f.__name__)
    assert rd.thresholds(d).as_dict() == rd.thresholds(h).as_dict()
    assert rd.thresholds(d).disk is d
    ex = rd.example_motions(d)
    assert ex.stable.disk is d and ex.unstable.disk is d


def test_converters_take_sequences_and_arrays():
    d = rd.Disk.from_dimensions(radius=0.05, thickness=0.01, mass=0.4)
    m = rd.steady_motion(d, "rough", 0.5, Omega0=2.0)
    v = rd.velocity_of_C(d, "rough", m.initial_state())  # a tuple
    assert isinstance(v, tuple)
    np.testing.assert_allclose(d.speed_to_si(v), np.array(v, float) * math.sqrt(0.05 * 9.80665),
                               rtol=1e-15)
    root = math.sqrt(0.05 / 9.80665)
    for conv, factor in ((d.length_to_si, 0.05), (d.time_to_si, root),
                         (d.angular_speed_to_si, 1 / root), (d.force_to_si, 0.4 * 9.80665),
                         (d.energy_to_si, 0.4 * 9.80665 * 0.05)):
        np.testing.assert_allclose(conv([1.0, 2.0]), [factor, 2 * factor], rtol=1e-15)
        assert isinstance(conv(2.0), float)


def test_one_gravity_per_disk():
    toy = EulerDisk()
    assert toy.gravity == STANDARD_GRAVITY == rd.Disk(h=0.1).gravity
    assert toy.disk.gravity == STANDARD_GRAVITY
    coin = disk_from_options(disk="euro-1", gravity="1.62 m/s^2")  # on the Moon
    toy2 = EulerDisk.from_disk(coin, mu=0.2)
    assert (toy2.radius, toy2.mass, toy2.gravity, toy2.mu) == (coin.radius, coin.mass, 1.62, 0.2)
    assert toy2.h == pytest.approx(coin.h, rel=1e-14)
    with pytest.raises(rd.ParameterError, match="no physical scale"):
        EulerDisk.from_disk(rd.Disk(h=0.1))
    with pytest.raises(rd.ParameterError, match="from the disk"):
        EulerDisk.from_disk(coin, gravity=9.0)


# --------------------------------------------------------------------------- SI views
scales = st.tuples(st.floats(1e-3, 10.0), st.floats(1e-3, 100.0), st.floats(0.1, 30.0))


@settings(max_examples=40, deadline=None)
@given(scales, st.floats(0.1, 1.2), st.floats(0.3, 3.0))
def test_si_fields_convert_back(scale, theta0, Omega0):
    a, mass, g = scale
    d = rd.Disk(h=0.17, radius=a, mass=mass, gravity=g)
    m = rd.steady_motion(d, "rough", theta0, Omega0=Omega0)
    T = math.sqrt(a / g)  # the unit of time, by hand
    si = si_fields(m)
    assert si["Omega0_si"] * T == pytest.approx(m.Omega0, rel=1e-12)
    assert si["omega20_si"] * T == pytest.approx(m.omega20, rel=1e-12)
    assert si["r_C_si"] / a == pytest.approx(m.r_C, rel=1e-12)
    assert si["v_C_si"] / math.sqrt(a * g) == pytest.approx(m.v_C, rel=1e-12)
    assert si["F_y_si"] / (mass * g) == pytest.approx(m.F_y, rel=1e-12)
    assert si["theta0"] == m.theta0 and "theta0_si" not in si
    assert si["units"]["F_y_si"] == "N" and si["units"]["F_y"] == "m g"
    s = rd.stability(m)
    ss = si_fields(s, d)
    assert ss["varpi2_si"] * T * T == pytest.approx(s.varpi2, rel=1e-12)
    if s.stable:
        assert ss["period_si"] / T == pytest.approx(s.period, rel=1e-12)
        assert ss["units"]["period_si"] == "s"
    else:
        assert ss["growth_rate_si"] * T == pytest.approx(s.growth_rate, rel=1e-12)


def test_si_view_needs_a_scale():
    m = rd.steady_motion(rd.Disk(h=0.17), "rough", 0.5, Omega0=2.0)
    with pytest.raises(rd.ParameterError, match="no physical scale"):
        si_fields(m)
    with pytest.raises(rd.ParameterError, match="physical scale"):
        rd.thresholds(0.17).to_si()
    with pytest.raises(rd.ParameterTypeError, match="SI view"):
        si_fields(3.0)
    # a radius but no mass: speeds convert, forces stay in units of m g
    si = si_fields(rd.steady_motion(rd.Disk(h=0.17, radius=0.05), "rough", 0.5, Omega0=2.0))
    assert "v_C_si" in si and "F_y_si" not in si
