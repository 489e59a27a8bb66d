"""The whole motion as one table (phases/columns.py, ``simulate --until-rest --out``)
against independent truth.

Sources of truth: the ballistic centre in flight (``Z_C(t) = Z_0 + V_Z0 (t - t0) - (t -
t0)^2/2``, g = 1) and its constant energy; the contact constraint on a rim edge (the lowest
point of the cylinder at height 0: ``Z_C = |cos theta| + h |sin theta|``, eq. 7); a disk
lying flat has ``Z_C = h``; the disk's scales for SI (``t sqrt(a/g)``, ``X a``, ``E m g a``);
the motion's own final state and phase changes.
"""

import csv
import io
import json
import math

import numpy as np
import pytest

import rollingdisk as rd
from rollingdisk.cli.app import main
from rollingdisk.phases.columns import motion_columns, write_motion_csv
from rollingdisk.phases.flight import FREE_STATE
from rollingdisk.phases.motion import FlatSegment, FlightSegment, simulate_to_rest
from rollingdisk.util.errors import ParameterTypeError

H = 0.3
S0 = [0.0, 0.0, 1.6, 0.0, 0.12, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]


@pytest.fixture(scope="module")
def result():
    """A thick disk dropped tilted: flights, bounces, a contact phase, falls flat, rests."""
    res = simulate_to_rest(rd.Disk(H), rd.Coulomb(0.5), (0.0, 100.0), S0, e=0.3)
    assert res.status == "at-rest"
    return res


@pytest.fixture(scope="module")
def cols(result):
    return motion_columns(result)


def test_layout_and_time_order(cols, result):
    assert list(cols) == ["t", "phase", *FREE_STATE, "E"]
    n = cols["t"].size
    assert all(np.asarray(v).shape == (n,) for v in cols.values())
    assert np.all(np.diff(cols["t"]) >= 0.0)
    assert cols["t"][0] == 0.0 and cols["t"][-1] == result.t_end
    assert {"flight", "flat", "rest"} <= set(cols["phase"])
    assert set(cols["phase"]) & {"rolling", "sliding"}  # a contact phase on a rim edge
    assert cols["phase"][-1] == "rest"
    last = np.array([cols[k][-1] for k in FREE_STATE])
    np.testing.assert_array_equal(last, result.final_state)


def _rows_of_segments(result, cols):
    """``(segment, slice of rows)`` in order: a flight has 24 rows, any other segment one
    per stored point."""
    i, out = 0, []
    for seg in result.segments:
        n = 24 if isinstance(seg, FlightSegment) else len(seg.t)
        out.append((seg, slice(i, i + n)))
        i += n
    assert i == cols["t"].size - 1  # and the final row
    return out


def test_flight_rows_are_ballistic(cols, result):
    flights = [(s, r) for s, r in _rows_of_segments(result, cols)
               if isinstance(s, FlightSegment)]
    assert len(flights) >= 2
    for seg, rows in flights:
        assert set(cols["phase"][rows]) == {"flight"}
        t = cols["t"][rows] - seg.t0
        z0, vz0 = seg.state0[2], seg.state0[8]
        np.testing.assert_allclose(cols["Z_C"][rows], z0 + vz0 * t - 0.5 * t * t,
                                   rtol=0, atol=1e-12)
        np.testing.assert_allclose(cols["E"][rows], cols["E"][rows][0], rtol=0, atol=1e-12)


def test_contact_rows_touch_the_plane_and_flat_rows_lie_on_it(cols):
    h = H
    edge = np.isin(cols["phase"], ["rolling", "sliding"])
    th = cols["theta"][edge]
    np.testing.assert_allclose(cols["Z_C"][edge], np.abs(np.cos(th)) + h * np.abs(np.sin(th)),
                               rtol=0, atol=1e-12)
    flat = np.isin(cols["phase"], ["flat", "rest"])
    np.testing.assert_allclose(cols["Z_C"][flat], h, rtol=0, atol=1e-14)
    np.testing.assert_allclose(np.abs(cols["theta"][flat]), 0.5 * math.pi, rtol=0, atol=1e-14)


def test_flat_rows_carry_the_segments_speed_and_spin(cols, result):
    seg = next(s for s in result.segments if isinstance(s, FlatSegment))
    rows = np.isin(cols["phase"], ["flat", "rest"]) & (cols["t"] >= seg.t[0]) & (
        cols["t"] <= seg.t[-1])
    rows[-1] = False  # the final row
    speed = np.hypot(cols["V_X"][rows], cols["V_Y"][rows])
    np.testing.assert_allclose(speed, seg.speed, rtol=0, atol=1e-15)
    np.testing.assert_allclose(np.abs(cols["omega2"][rows]), seg.spin, rtol=0, atol=1e-15)
    # the energy of a flat disk: h + V^2/2 + k2 Omega^2/2 (k2 = 1/2, eq. 10 at rest on a face)
    np.testing.assert_allclose(cols["E"][rows], H + 0.5 * seg.speed ** 2
                               + 0.25 * seg.spin ** 2, rtol=0, atol=1e-14)


def test_si_columns_are_the_paper_columns_times_the_scales():
    disk = rd.Disk.from_dimensions(radius=0.0116, thickness=2 * H * 0.0116, mass=0.0075)
    res = simulate_to_rest(disk, rd.Coulomb(0.5), (0.0, 100.0), S0, e=0.3)
    paper, si = motion_columns(res), motion_columns(res, si=True)
    a, g, m = 0.0116, disk.gravity, 0.0075
    np.testing.assert_allclose(si["t"], paper["t"] * math.sqrt(a / g), rtol=1e-14)
    for k in ("X_C", "Y_C", "Z_C"):
        np.testing.assert_allclose(si[k], paper[k] * a, rtol=1e-14)
    for k in ("V_X", "V_Y", "V_Z"):
        np.testing.assert_allclose(si[k], paper[k] * math.sqrt(a * g), rtol=1e-14)
    for k in ("omega1", "omega2", "omega3"):
        np.testing.assert_allclose(si[k], paper[k] * math.sqrt(g / a), rtol=1e-14)
    np.testing.assert_allclose(si["E"], paper["E"] * m * g * a, rtol=1e-14)
    for k in ("psi", "theta", "phi", "phase"):
        np.testing.assert_array_equal(si[k], paper[k])


def test_bad_result_is_a_type_error():
    with pytest.raises(ParameterTypeError, match="result must be a MotionResult"):
        motion_columns("not a motion")


def test_cli_writes_the_whole_motion(tmp_path, capsys):
    out = tmp_path / "motion.csv"
    assert main(["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.1", "--state",
                 "theta=0.3", "--t-end", "100", "--until-rest", "--out", str(out), "--json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["status"] == "at-rest" and rec["out"] == str(out)
    with out.open() as fh:
        rows = list(csv.reader(fh))
    names, units, body = rows[0], rows[1], rows[2:]
    assert names == ["t", "phase", *FREE_STATE, "E"]
    assert units[0] == "# t [sqrt(a/g)]"
    phases = [r[1] for r in body]
    assert phases[0] == "rolling" and phases[-1] == "rest" and "flat" in phases
    assert float(body[-1][0]) == rec["t_end"]
    # the phases change where the run says they do
    # the phase changes between two rows only where the run says a transition happens
    said = [x["t"] for x in rec["transitions"]]
    for q, r in zip(body[:-1], body[1:], strict=True):
        if q[1] != r[1]:
            assert any(float(q[0]) <= t <= float(r[0]) for t in said), (q[:2], r[:2])
    # in memory, the same table
    # the start on Coulomb ground: X, Y, V_X, V_Y, psi, theta, phi, omega1..3, at rest
    y0 = [0.0, 0.0, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0]
    res = simulate_to_rest(rd.Disk(0.1), rd.Coulomb(0.5), (0.0, 100.0), y0, e=0.5)

    buf = io.StringIO()
    write_motion_csv(buf, res)
    assert buf.getvalue().splitlines()[2:] == out.read_text().splitlines()[2:]


def test_cli_si_header_with_a_physical_disk(tmp_path, capsys):
    out = tmp_path / "coin.csv"
    assert main(["simulate", "--ground", "coulomb", "--mu", "0.5", "--disk", "euro-1",
                 "--state", "theta=0.3", "--t-end", "2s", "--until-rest", "--out", str(out),
                 "--quiet"]) == 0
    capsys.readouterr()
    head = out.read_text().splitlines()[1]
    assert head.startswith("# t [s],phase [1],X_C [m]") and "E [J]" in head


def test_restitution_without_until_rest_is_refused(capsys):
    code = main(["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.1", "--state",
                 "theta=0.3", "--t-end", "10", "--restitution", "0.3"])
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1
    assert "--restitution needs --until-rest" in err[0]
