"""CLI `euler-disk`: the files appear complete (PNG, CSV, JSON), the summary agrees with
itself (energy balance of the CSV columns, end kind), and bad input is one line with exit 2.

A short run (``--alpha0 0.05``: the toy started lower, so it reaches its end quickly) keeps
these tests fast; the full toy is checked in tests/test_euler_disk.py."""

from __future__ import annotations

import json

import numpy as np
import pytest

from rollingdisk.cli.app import main
from rollingdisk.plotting.reports import EULER_DISK_FILES

SHORT = ["--alpha0", "0.05", "--quiet"]


def test_out_folder_complete(tmp_path, capsys):
    out = tmp_path / "run"
    assert main(["euler-disk", *SHORT, "--out", str(out)]) == 0
    captured = capsys.readouterr()
    text = captured.out
    assert "fell flat" in text and "exponents" in text
    assert captured.err == ""  # --quiet: no progress bar
    assert sorted(p.name for p in out.iterdir()) == sorted(EULER_DISK_FILES)
    png, csv, js = (out / name for name in EULER_DISK_FILES)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    s = json.loads(js.read_text())
    assert s["status"] == "completed" and s["end"] == "fell-flat"
    assert set(s["exponents"]) == set(s["predicted"]) == {"alpha", "Omega", "contact_speed"}
    data = np.genfromtxt(csv, delimiter=",", names=True)
    assert data["t"][-1] == pytest.approx(s["t_end"], rel=1e-10)
    assert data["alpha"][-1] == pytest.approx(1e-3, rel=1e-9)
    # E + dissipated = E(0) (eq. 12), from the CSV's own columns
    total = data["E"] + sum(data[f"dissipated_{k}"] for k in ("slip", "rolling_resistance",
                                                               "air"))
    assert np.max(np.abs(total - total[0])) <= 1e-8 * abs(total[0])
    assert not list(tmp_path.glob(".*tmp*"))  # no temporary left behind


@pytest.mark.slow
def test_json_on_stdout_and_rerun_replaces(tmp_path, capsys):
    out = tmp_path / "run"
    for _ in range(2):  # an earlier result folder is replaced whole
        assert main(["euler-disk", *SHORT, "--json", "--out", str(out)]) == 0
        s = json.loads(capsys.readouterr().out)
        assert s["out"] == str(out) and s["energy_balance"] < 1e-9
    assert sorted(p.name for p in out.iterdir()) == sorted(EULER_DISK_FILES)


def test_step_budget_is_a_status(capsys):
    assert main(["euler-disk", "--quiet", "--json", "--max-steps", "5"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["status"] == "failed" and s["end"] is None and "step budget" in s["message"]


@pytest.mark.parametrize("argv, word", [
    (["--mu", "-1"], "mu"), (["--creep", "0"], "creep"), (["--alpha0", "2"], "alpha0"),
    (["--rolling-resistance", "nan"], "rolling_resistance"), (["--max-steps", "0"], ""),
    (["--max-wall-time", "-3"], "max_wall_time"),
])
def test_bad_input_exit_2(capsys, argv, word):
    assert main(["euler-disk", *argv]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and word in err and "Traceback" not in err


def test_bad_out_exit_2_before_work(tmp_path, capsys):
    afile = tmp_path / "file"
    afile.write_text("x")
    foreign = tmp_path / "mine"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("keep me")
    for out in (tmp_path / "missing" / "run", afile, foreign):
        assert main(["euler-disk", "--quiet", "--out", str(out)]) == 2
        err = capsys.readouterr().err
        assert len(err.strip().splitlines()) == 1 and "--out" in err
    assert (foreign / "notes.txt").read_text() == "keep me"
