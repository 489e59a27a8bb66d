"""``rollingdisk sweep`` on the command line."""

import json

import pytest

from rollingdisk.cli.app import main

pytest.importorskip("xarray")


def test_sweep_cli_json(tmp_path, capsys):
    out = tmp_path / "s.zarr"
    rc = main(["sweep", "--ground", "rough", "--theta0", "0.3:1.2:3", "--omega30=-5:5:3",
               "--t-end", "30", "--kick", "1e-3", "--out", str(out), "--json"])
    assert rc == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["n"] == 9 and rec["agreement"] == 1.0 and out.is_dir()


def test_sweep_cli_straight_lines(tmp_path, capsys):
    out = tmp_path / "s.nc"
    rc = main(["sweep", "--ground", "rough", "--h", "0:0.5:2", "--omega0", "0.3:2:4",
               "--t-end", "50", "--out", str(out), "--json"])
    assert rc == 0
    rec = json.loads(capsys.readouterr().out)
    assert rec["n"] == 8 and rec["agreement"] == 1.0 and out.is_file()


@pytest.mark.parametrize("argv", [
    ["--ground", "rough", "--theta0", "0.5", "--omega0", "1", "--t-end", "5"],
    ["--ground", "rough", "--omega30", "1", "--t-end", "5"],
    ["--ground", "smooth", "--theta0", "0.5", "--rC", "1", "--t-end", "5"],
    ["--ground", "rough", "--theta0", "0.5:1:x", "--omega30", "1", "--t-end", "5"],
    ["--ground", "rough", "--theta0", "0.5", "--omega30", "1", "--t-end", "-5"],
])
def test_sweep_cli_bad_input(tmp_path, capsys, argv):
    assert main(["sweep", *argv, "--out", str(tmp_path / "s.nc")]) == 2
    err = capsys.readouterr().err
    assert err.strip() and err.strip().count("\n") == 0
    assert not (tmp_path / "s.nc").exists()


def test_sweep_plots():
    import matplotlib

    matplotlib.use("Agg")
    from rollingdisk.plotting.plots import plot_basin_map, plot_nonlinear_map
    from rollingdisk.sweep.runner import SweepGrid, basin_sweep, run_sweep

    g = SweepGrid("rough", h=0.17, theta0=[0.4, 0.8, 1.2], omega30=[-4.0, 1.0, 4.0])
    out = plot_nonlinear_map(run_sweep(g, 10.0))
    assert out["mesh"] is not None
    out = plot_basin_map(basin_sweep(g, 10.0, kick_max=0.2, rounds=1))
    assert out["colorbar"] is not None
    s = SweepGrid("smooth", h=[0.0, 0.3, 0.6], omega0=[0.5, 1.5, 2.5])
    out = plot_nonlinear_map(run_sweep(s, 10.0))
    assert out["ax"].get_ylabel() == "$h$" and out["boundary"] is not None
