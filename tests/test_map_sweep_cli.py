"""`rollingdisk map --kind nonlinear|basin`: the sweep maps agree with the closed form."""

import pytest

from rollingdisk.cli.app import main

pytest.importorskip("xarray")
pytest.importorskip("matplotlib")


@pytest.mark.slow
@pytest.mark.parametrize("kind", ["nonlinear", "basin"])
def test_sweep_maps_are_written_whole(tmp_path, kind, capsys):
    out = tmp_path / f"{kind}.png"
    assert main(["map", "--ground", "rough", "--h", "0.17", "--kind", kind, "--out",
                 str(out)]) == 0
    assert out.stat().st_size > 10_000 and out.read_bytes()[:4] == b"\x89PNG"
    assert [p.name for p in tmp_path.iterdir()] == [out.name]  # no temp left


def test_sweep_map_bad_output_refused_before_work(tmp_path, capsys):
    assert main(["map", "--ground", "rough", "--kind", "nonlinear", "--out",
                 str(tmp_path / "x.bmpx")]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
