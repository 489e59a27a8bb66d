"""`rollingdisk atlas`, `figures`, `map`, `animate`: outputs exist, are referenced, make sense.

Sources of truth: the index page may reference only files that exist (and no external
resources); the chosen "stable" motion stays near its steady tilt and the "unstable" one
departs from it, as the closed form says; the CLI contract (exit 2, one line).
"""

import io
import json
import re
import time

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402

from rollingdisk.atlas.build import build_atlas
from rollingdisk.cli.app import main


def _referenced(index_html: str):
    """Files the page references (links to anchors on the page itself, ``#...``, are the
    table of contents: tests/test_atlas_browser.py checks that they resolve)."""
    return [r for r in re.findall(r'(?:src|href)="([^"]+)"', index_html)
            if not r.startswith("#")]


@pytest.fixture(scope="module")
def quick_atlas(tmp_path_factory):
    out = tmp_path_factory.mktemp("atlas")
    stream = io.StringIO()
    result = build_atlas(0.17, out, quick=True, progress=True, stream=stream)
    return result, stream.getvalue()


def test_atlas_index_references_only_existing_files(quick_atlas):
    result, _ = quick_atlas
    html = result.index.read_text(encoding="utf-8")
    refs = _referenced(html)
    assert refs, "the index references nothing"
    for ref in refs:
        assert "://" not in ref and not ref.startswith("/"), ref  # relative, local
        assert (result.out_dir / ref).is_file(), ref
    for name in ("existence.png", "stability.png", "varpi2.png", "all_omega30.png",
                 "motion_stable.png",
                 "motion_unstable.png", "motion_stable.gif", "motion_unstable.gif"):
        assert name in refs
    assert "<link" not in html and "<script" not in html


def test_atlas_thresholds_and_motions(quick_atlas):
    result, _ = quick_atlas
    thr = json.loads((result.out_dir / "thresholds.json").read_text())
    assert thr["h"] == 0.17
    assert set(thr["rough"]) == {"straight_line_omega20_sq", "se_circle_omega30_sq"}
    st, un = result.motions["stable"], result.motions["unstable"]
    assert st["stable"] and not un["stable"]
    # stable: the tilt stays within a few times kick/varpi; unstable: it grows
    assert st["max_theta_dev"] < 3 * st["kick"] / st["varpi"]
    assert un["max_theta_dev"] > 10 * un["kick"] / un["growth_rate"]
    # the simulation oscillates / grows at the closed-form rate
    assert st["measured"] == pytest.approx(st["varpi"], rel=0.02)
    assert un["measured"] == pytest.approx(un["growth_rate"], rel=0.05)
    assert st["energy_error"] < 1e-6 and un["energy_error"] < 1e-6


def test_atlas_progress_lines(quick_atlas):
    _, progress = quick_atlas
    lines = progress.strip().splitlines()
    n = lines[0].split("/")[1].split("]")[0]  # one line per step, counted [k/n]
    assert lines[0].startswith(f"[1/{n}]") and lines[-2].startswith(f"[{n}/{n}]")
    assert not any("integrator" in line for line in lines)  # no compile step (issue 9)
    assert lines[-1].startswith("atlas written to")


def test_cli_atlas_is_a_thin_wrapper(tmp_path, monkeypatch, capsys):
    import rollingdisk.atlas.build as atlas

    calls = []

    def fake(h, out_dir, *, quick, progress):
        calls.append((h, out_dir, quick, progress))
        return atlas.AtlasResult(tmp_path, tmp_path / "index.html", (), h)

    monkeypatch.setattr(atlas, "build_atlas", fake)
    assert main(["atlas", "--out", str(tmp_path), "--quick", "--progress"]) == 0
    assert main(["atlas", "--h", "0.3", "--out", str(tmp_path), "--quiet"]) == 0
    assert main(["atlas", "--h", "0.3", "--out", str(tmp_path)]) == 0  # stderr no terminal
    assert calls == [(0.17, str(tmp_path), True, True), (0.3, str(tmp_path), False, False),
                     (0.3, str(tmp_path), False, False)]
    assert capsys.readouterr().out.strip().endswith("index.html")


@pytest.mark.parametrize("h", [0.0, 0.17, 0.9, 3.0])
def test_example_motions_for_any_disk(h):
    """The motions the atlas shows are what it says: varpi^2 of eq. (45) > 0 and < 0."""
    from rollingdisk import example_motions, varpi2_circle

    m = example_motions(h)
    assert m.stable.ground == m.unstable.ground == "rough" and m.stable.h == h
    assert varpi2_circle(h, "rough", m.stable.theta0, m.stable.omega30) > 0
    assert varpi2_circle(h, "rough", m.unstable.theta0, m.unstable.omega30) < 0


@pytest.mark.slow
def test_atlas_default_builds_whole(tmp_path):
    t0 = time.perf_counter()
    result = build_atlas(out_dir=tmp_path, progress=False)
    wall = time.perf_counter() - t0
    assert wall < 900.0  # a hang guard only; the atlas's speed is measured in benchmarks/
    for ref in _referenced(result.index.read_text(encoding="utf-8")):
        assert (tmp_path / ref).is_file()


# ------------------------------------------------------------------------------ CLI
def test_cli_map_kinds(tmp_path, capsys):
    from PIL import Image

    for kind in ("existence", "stability", "all-omega30"):
        out = tmp_path / f"{kind}.png"
        assert main(["map", "--ground", "rough", "--h", "0.17", "--kind", kind,
                     "--out", str(out), "--dpi", "40"]) == 0
        with Image.open(out) as im:
            assert im.size[0] > 100


def test_cli_figures_subset(tmp_path, capsys):
    assert main(["figures", "--out", str(tmp_path), "--scale", "0.1", "--dpi", "40",
                 "--only", "fig4", "fig7"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig4.png", "fig7.png"]


def test_cli_animate(tmp_path, capsys):
    out = tmp_path / "m.gif"
    assert main(["animate", "--theta0", "30deg", "--Omega0", "2", "--t-end", "2",
                 "--frames", "3", "--dpi", "40", "--out", str(out)]) == 0
    assert out.is_file()
    err = capsys.readouterr().err
    assert "stable, varpi^2" in err and "unstable" not in err  # 30 deg, Omega0 = 2: stable


@pytest.mark.parametrize("argv,needle", [
    (["map", "--ground", "rough", "--h", "-1", "--kind", "stability", "--out", "x.png"], "h"),
    (["map", "--ground", "icy", "--kind", "stability", "--out", "x.png"], "ground"),
    (["figures", "--out", "x", "--only", "fig3"], "fig4"),
    (["animate", "--theta0", "0.3", "--Omega0", "1", "--out", "m.avi"], "gif"),
    (["animate", "--theta0", "0.3", "--out", "m.gif"], "Omega0"),
    (["animate", "--theta0", "0.3", "--Omega0", "1", "--dpi", "0", "--out", "m.gif"],
     "dpi must be an integer in [20, 600]"),
    (["animate", "--theta0", "0.3", "--Omega0", "1", "--frames", "0", "--out", "m.gif"],
     "frames must be an integer in [2, 2000]"),
    (["animate", "--theta0", "0.3", "--Omega0", "1", "--out", "nofolder/m.gif"],
     "no such folder"),
    (["animate", "--theta0", "0.3", "--Omega0", "1", "--out", "."], "gif"),
    (["map", "--ground", "rough", "--kind", "stability", "--out", "nofolder/x.png"],
     "no such folder"),
    (["map", "--ground", "rough", "--kind", "stability", "--out", "."], "must end in one of .png"),
    (["map", "--ground", "rough", "--kind", "all-omega30", "--h", "nan", "--out", "x.png"],
     "h must"),
    (["figures", "--out", "x", "--scale", "nan"], "scale must"),
    (["figures", "--out", "x", "--scale", "0"], "scale must"),
    (["figures", "--out", "/proc/rollingdisk-test"], "rollingdisk figures: error"),
    (["atlas", "--h", "-0.1", "--out", "x"], "h must"),
])
def test_cli_errors_one_line_exit_2(tmp_path, monkeypatch, capsys, argv, needle):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and needle in err


def test_atlas_to_rest_section(quick_atlas):
    """The run past the guards: at rest, E(0) = E(end) + impact losses + dissipated (the
    energy balance), and the page has its section in the table of contents."""
    result, _ = quick_atlas
    m = result.motions["to_rest"]
    assert m["status"] == "at-rest" and m["n_impacts"] >= 10 and m["n_rim_change"] >= 1
    assert m["energy_initial"] == pytest.approx(
        m["energy_final"] + m["impact_loss"] + m["dissipated"], abs=1e-9)
    assert m["energy_balance"] <= 1e-9
    html = result.index.read_text(encoding="utf-8")
    assert 'href="#to-rest"' in html and 'id="to-rest"' in html
    assert f"{m['n_impacts']} impacts" in html
