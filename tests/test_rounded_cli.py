"""``rollingdisk thresholds --rim-radius``: the rounded disk's thresholds, text and JSON,
with units; bad input is one line on stderr and exit 2."""

from __future__ import annotations

import json

import pytest

from rollingdisk import Disk
from rollingdisk.cli.app import main
from rollingdisk.theory.rounded import rounded_thresholds


def _run(capsys, *argv):
    rc = main(["thresholds", *argv])
    out = capsys.readouterr()
    return rc, out.out, out.err


def test_json_states_the_rim_and_matches_the_library(capsys):
    rc, out, err = _run(capsys, "--disk", "euro-1", "--rim-radius", "0.3mm", "--json")
    assert rc == 0 and err == ""
    d = json.loads(out)
    assert d["rim_radius_si"] == pytest.approx(3e-4, rel=1e-12)
    assert d["rim_radius"] == pytest.approx(0.3 / 11.625, rel=1e-12)
    disk = Disk(h=1.165 / 11.625, rim_radius=d["rim_radius"])
    want = rounded_thresholds(disk).as_dict()
    assert d["rough"] == pytest.approx(want["rough"], rel=1e-12)
    assert d["smooth"] == pytest.approx(want["smooth"], rel=1e-12)
    assert d["units"]["rough_straight_line_speed_si"] == "m/s"


def test_text_states_the_rim(capsys):
    rc, out, _ = _run(capsys, "--disk", "euro-1", "--rim-radius", "0.3mm")
    assert rc == 0
    assert "rho = 0.0258065 a = 0.3 mm" in out and "m/s" in out


def test_zero_rim_gives_the_sharp_thresholds(capsys):
    rc, out, _ = _run(capsys, "--h", "0.17", "--rim-radius", "0", "--json")
    rounded = json.loads(out)
    rc2, out2, _ = _run(capsys, "--h", "0.17", "--json")
    sharp = json.loads(out2)
    assert rc == rc2 == 0 and rounded["rim_radius"] == 0.0
    for ground in ("rough", "smooth"):
        for key, v in sharp[ground].items():
            assert rounded[ground][key] == pytest.approx(v, rel=1e-13)


@pytest.mark.parametrize("argv, words", [
    (("--h", "0.2", "--rim-radius", "0.3"), "--rim-radius must lie in [0, min(h, 1)]"),
    (("--disk", "euro-1", "--rim-radius", "3mm"), "--rim-radius must lie in [0, min(h, 1)]"),
    (("--h", "0.2", "--rim-radius", "-1"), "rim_radius must lie in [0, inf)"),
    (("--h", "0.2", "--rim-radius", "1mm"), "has a unit"),
    (("--h", "0.2", "--rim-radius", "1 parsec/s"), "--rim-radius"),
    (("--h", "3", "--rim-radius", "1.5"), "[0, min(h, 1)] = [0, 1]"),
])
def test_bad_rim_radius_is_one_line_and_exit_2(capsys, argv, words):
    with pytest.raises(SystemExit) as exc:
        rc = main(["thresholds", *argv])
        raise SystemExit(rc)
    err = capsys.readouterr().err
    assert exc.value.code == 2
    assert words in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err
