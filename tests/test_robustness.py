"""Robustness sweep of the command line (issue 8): bad input never gives a traceback.

Sources of truth: the CLI contract of rollingdisk.cli.app (exit 2 and one line on stderr for
bad input, exit 1 only for a bug, 130/143 on Ctrl-C/SIGTERM), the library's contract for
errors (TypeError/ValueError or their ParameterTypeError/ParameterError subclasses), strict
JSON (no NaN, no infinity), and "every output is complete or absent" (nothing is left
behind by a refused or interrupted command).  Every command runs under a time limit.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import pytest  # noqa: E402
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from rollingdisk.cli.app import main

SRC = str(Path(__file__).resolve().parents[1] / "src")


class _TimeLimit(BaseException):  # noqa: N818 - not an Exception: main() must not catch it
    pass


@contextlib.contextmanager
def time_limit(seconds: float):
    """Raise _TimeLimit in the main thread after ``seconds`` (no hang goes unnoticed)."""
    def handler(signum, frame):
        raise _TimeLimit(f"no answer within {seconds} s")

    old = signal.signal(signal.SIGALRM, handler)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def _strict(text: str):
    def bad(name):
        raise AssertionError(f"non-finite number {name} in JSON output")

    return json.loads(text, parse_constant=bad)


def run(capsys, argv, seconds: float = 30.0):
    with time_limit(seconds):
        rc = main(argv)
    out, err = capsys.readouterr()
    return rc, out, err


def check_contract(rc, out, err, argv):
    assert rc in (0, 2), f"{argv}: exit {rc}\n{err}"
    assert "Traceback" not in err, f"{argv}:\n{err}"
    if rc == 2:
        assert len(err.strip().splitlines()) == 1, f"{argv}: not one line:\n{err}"
    if rc == 0 and "--json" in argv:
        _strict(out)


# ------------------------------------------------------------------ hand-picked cases
STEADY = ["--theta0", "0.3", "--Omega0", "2"]
CASES = [
    # issue 8: tracebacks (MemoryError, FreeType, TypeError) and a RuntimeWarning
    (["figures", "--out", "f", "--scale=1e6"], "scale must lie in (0, 4]"),
    (["figures", "--out", "f", "--dpi=100000"], "dpi must be an integer in [20, 600]"),
    (["figures", "--out", "f", "--dpi=1"], "dpi must be an integer in [20, 600]"),
    (["figures", "--out", "f", "--dpi=1e20"], "dpi must be an integer in [20, 600]"),
    (["animate", *STEADY, "--out", "m.gif", "--t-end=inf"], "t_end must be a finite"),
    (["animate", *STEADY, "--out", "m.gif", "--t-end=1e7"], "t_end must lie in (0, 10000]"),
    (["animate", *STEADY, "--out", "m.gif", "--t-end=nan"], "t_end"),
    (["atlas", "--h=1e8", "--out", "a"], "no unstable steady circle"),
    # every number checked as the library checks it
    (["animate", *STEADY, "--out", "m.gif", "--frames", "2001"], "frames must be an integer"),
    (["animate", *STEADY, "--out", "m.gif", "--fps", "0"], "fps must be an integer in [1, 60]"),
    (["animate", *STEADY, "--out", "m.gif", "--frames", "2000", "--dpi", "600"], "pixels"),
    (["animate", *STEADY, "--out", "m.gif", "--kick", "inf"], "kick must be a finite"),
    (["animate", "--theta0", "0.3", "--Omega0", "1e400", "--out", "m.gif"], "Omega0"),
    (["animate", *STEADY, "--out", "m.txt"], ".gif"),
    (["map", "--ground", "rough", "--kind", "existence", "--out", "x.jpg"], ".png, .pdf"),
    (["map", "--ground", "rough", "--kind", "existence", "--out", "x"], ".png, .pdf"),
    (["map", "--ground", "rough", "--kind", "existence", "--out", "x.png", "--dpi", "x"],
     "dpi must be an integer"),
    (["map", "--ground", "rough", "--kind", "existence", "--h", "1e9", "--out", "x.png"],
     "h must lie in [0, 1e+08]"),
    (["steady", "--h", "0.3", "--theta0", "0.3", "--Omega0", "1e200"], "Omega0"),
    (["steady", "--h", "0.3", "--theta0", "inf", "--Omega0", "1"], "theta0"),
    (["steady", "--h", "abc", "--theta0", "0.3", "--Omega0", "1"], "h must be a real number"),
    (["thresholds", "--h=-inf"], "h must be a finite"),
    (["figures", "--out", "f", "--only", "fig9"], "invalid choice"),
    (["derive", "--sections", "3"], "invalid choice"),
    (["atlas", "--h", "nan"], "h must be a finite"),
    (["atlas", "--out", "."], "current folder"),
    (["atlas", "--out", "no/such/folder"], "no such folder"),
]


@pytest.mark.parametrize("argv,needle", CASES)
def test_hand_picked_bad_input(tmp_path, monkeypatch, capsys, argv, needle):
    """Exit 2, one line naming the problem, and nothing written (not even a folder)."""
    monkeypatch.chdir(tmp_path)
    rc, out, err = run(capsys, argv)
    assert rc == 2, err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert needle in err, err
    assert sorted(os.listdir(tmp_path)) == []


def test_figures_out_refuses_a_folder_with_other_files(tmp_path, capsys):
    """figures/atlas replace their folder as a whole: never a folder of the user's files."""
    (tmp_path / "notes.txt").write_text("mine")
    for argv in (["figures", "--out", str(tmp_path), "--scale", "0.05", "--dpi", "20"],
                 ["atlas", "--out", str(tmp_path), "--quick"]):
        rc, _, err = run(capsys, argv)
        assert rc == 2 and "notes.txt" in err
    assert sorted(os.listdir(tmp_path)) == ["notes.txt"]


def test_a_bug_is_exit_1_with_traceback(monkeypatch, capsys):
    """A ValueError that is not the library's input error is a bug, and says so."""
    import rollingdisk.theory.oscillations as stab

    def broken(h):
        raise ValueError("internal inconsistency")

    monkeypatch.setattr(stab, "thresholds", broken)
    rc, _, err = run(capsys, ["thresholds", "--h", "0.2"])
    assert rc == 1
    assert "Traceback" in err and "internal inconsistency" in err
    assert "bug" in err.strip().splitlines()[-1]


def test_help_returns_zero(capsys):
    rc, out, _ = run(capsys, ["--help"])
    assert rc == 0 and "atlas" in out


def test_figures_keep_other_figures_and_write_png(tmp_path, capsys):
    out = tmp_path / "figs"
    assert run(capsys, ["figures", "--out", str(out), "--scale", "0.05", "--dpi", "20",
                        "--only", "fig5"])[0] == 0
    assert run(capsys, ["figures", "--out", str(out), "--scale", "0.05", "--dpi", "20",
                        "--only", "fig7"])[0] == 0
    assert sorted(os.listdir(out)) == ["fig5.png", "fig7.png"]
    assert sorted(os.listdir(tmp_path)) == ["figs"]  # no temporary left beside it
    assert (out / "fig5.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


# ------------------------------------------------------------------ hypothesis sweep
NASTY = ["nan", "inf", "-inf", "-1", "0", "1e308", "1e-320", "abc", "", "1e400", "0x10",
         "30deg", "-30deg", "1,2", "None", "True", " ", "1e20", "-0"]


def _values(*good):
    return st.sampled_from(NASTY + list(good))


OPTIONS = {
    "steady": {"--h": _values("0.3", "0"), "--theta0": _values("0.3", "1.2"),
               "--Omega0": _values("2", "-1"), "--rC": _values("1.5"), "--rP": _values("0.5"),
               "--omega0": _values("1"), "--ground": _values("rough", "smooth"),
               "--motion": _values("circle", "straight")},
    "thresholds": {"--h": _values("0.3", "5")},
    "map": {"--ground": _values("rough"), "--kind": _values("existence", "stability"),
            "--h": _values("0.3"), "--dpi": _values("20", "30"),
            "--out": _values("m.png", "m.svg", "m.jpg", "m")},
    "animate": {"--theta0": _values("0.5"), "--Omega0": _values("3"), "--h": _values("0.2"),
                "--t-end": _values("0.5", "1"), "--frames": _values("2", "3"),
                "--fps": _values("5"), "--dpi": _values("20"), "--kick": _values("0.01"),
                "--perturb": _values("0.01"), "--out": _values("m.gif", "m.avi")},
    "figures": {"--out": _values("figs"), "--scale": _values("0.05"), "--dpi": _values("20"),
                "--only": _values("fig4", "fig9")},
    "atlas": {"--h": _values("0.17", "1e8"), "--out": _values("at", ".")},
    "derive": {"--sections": st.sampled_from(["3", "", "nan", "al"])},  # never the long run
}


@st.composite
def command_lines(draw):
    command = draw(st.sampled_from(sorted(OPTIONS)))
    opts = OPTIONS[command]
    names = draw(st.lists(st.sampled_from(sorted(opts)), unique=True, max_size=len(opts)))
    if command == "derive":
        names = ["--sections"]
    argv = [command]
    for name in names:
        argv += [f"{name}={draw(opts[name])}"]
    if draw(st.booleans()) and command in ("steady", "thresholds"):
        argv.append("--json")
    return argv


@pytest.fixture
def cheap_pictures(monkeypatch):
    """figures and atlas with tiny drawings (the sweep is about the arguments)."""
    import rollingdisk.atlas.build as atlas
    import rollingdisk.plotting.figures as figures
    from rollingdisk.model.disk import check_h
    from rollingdisk.util.files import atomic_dir, check_replaceable

    def tiny(scale):
        from matplotlib.figure import Figure

        figures._check_scale(scale)
        return Figure(figsize=(1, 1))

    monkeypatch.setattr(figures, "FIGURES", dict.fromkeys(figures.FIGURES, tiny))

    def fake_atlas(h, out_dir, *, quick, progress):
        h = check_h(h)
        target = check_replaceable(out_dir, atlas.ATLAS_FILES, name="out_dir")
        from rollingdisk.theory.regions import example_motions

        example_motions(h)
        with atomic_dir(target) as tmp:
            (tmp / "index.html").write_text("ok")
        return atlas.AtlasResult(target, target / "index.html", (), h)

    monkeypatch.setattr(atlas, "build_atlas", fake_atlas)


@settings(max_examples=120, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(argv=command_lines())
def test_sweep_cli(tmp_path, monkeypatch, capsys, cheap_pictures, argv):
    """Any mixture of good and nasty values: exit 0 or 2, one line, strict JSON, no hang."""
    import tempfile

    work = Path(tempfile.mkdtemp(dir=tmp_path))
    monkeypatch.chdir(work)
    rc, out, err = run(capsys, argv, seconds=60.0)
    check_contract(rc, out, err, argv)
    if rc == 2:  # refused: nothing written
        assert os.listdir(work) == [], (argv, os.listdir(work))
    leftovers = [n for n in os.listdir(work) if ".tmp" in n or n.startswith(".")]
    assert leftovers == [], (argv, leftovers)


# ------------------------------------------------------------------ API
#: values no argument of these functions accepts
API_VALUES = [None, "a", "0.3", math.nan, math.inf, -1.0, 1e308, True, [], [1.0, 2.0], 1j,
              object(), 10 ** 400]


@settings(max_examples=80, deadline=None)
@given(value=st.sampled_from(API_VALUES),
       which=st.sampled_from(["paper_figures.scale", "paper_figures.dpi", "animate.n_frames",
                              "animate.fps", "animate.dpi", "build_atlas.h", "existence_codes",
                              "varpi2_zero_surface", "example_motions", "check_animation.size",
                              "save_figure.dpi"]))
def test_sweep_api_of_the_edges(tmp_path_factory, value, which):
    """Bad arguments of the edge functions: TypeError or ValueError, nothing written."""
    from matplotlib.figure import Figure

    import rollingdisk as rd
    from rollingdisk.atlas import build as atlas
    from rollingdisk.plotting import animation as animation
    from rollingdisk.plotting import figures as figures
    from rollingdisk.plotting import plots as plotting

    out = tmp_path_factory.mktemp("api")
    calls = {
        "paper_figures.scale": lambda v: figures.paper_figures(out / "f", scale=v),
        "paper_figures.dpi": lambda v: figures.paper_figures(out / "f", dpi=v),
        "animate.n_frames": lambda v: animation.check_animation(n_frames=v),
        "animate.fps": lambda v: animation.check_animation(fps=v),
        "animate.dpi": lambda v: animation.check_animation(dpi=v),
        "check_animation.size": lambda v: animation.check_animation(size=v),
        "build_atlas.h": lambda v: atlas.build_atlas(v, out / "a"),
        "existence_codes": lambda v: rd.existence_codes(v, 0.3, 1.0),
        "varpi2_zero_surface": lambda v: rd.varpi2_zero_surface(0.2, v, 0.3),
        "example_motions": lambda v: rd.example_motions(v),
        "save_figure.dpi": lambda v: plotting.save_figure(Figure(), out / "x.png", dpi=v),
    }
    with time_limit(30.0):
        try:
            calls[which](value)
        except (TypeError, ValueError):
            pass
    assert os.listdir(out) == []


# ------------------------------------------------------------------ signals
def _interrupt(argv, tmp_path, sig, after: float, marker: str | None = None):
    """Run the CLI, send ``sig`` ``after`` seconds after ``marker`` appeared on stderr (or
    after the start), return (exit code, stderr)."""
    import threading

    env = dict(os.environ, PYTHONPATH=SRC, MPLBACKEND="Agg")
    proc = subprocess.Popen([sys.executable, "-m", "rollingdisk", *argv], cwd=tmp_path,
                            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True)
    chunks: list[str] = []
    reader = threading.Thread(target=lambda: chunks.extend(iter(lambda: proc.stderr.read(1), "")))
    reader.start()
    deadline = time.monotonic() + 60
    while marker and marker not in "".join(chunks) and time.monotonic() < deadline:
        time.sleep(0.01)
    time.sleep(after)
    proc.send_signal(sig)
    try:
        proc.wait(timeout=600)
    except subprocess.TimeoutExpired:
        proc.kill()
        raise
    reader.join()
    return proc.returncode, "".join(chunks)


@pytest.mark.slow  # a subprocess each, about 3 s
@pytest.mark.parametrize("sig,rc,word", [(signal.SIGINT, 130, "interrupted"),
                                         (signal.SIGTERM, 143, "terminated")])
@pytest.mark.parametrize("argv", [
    # --progress: the markers waited for are progress lines, drawn unasked on a terminal only
    ["figures", "--out", "figs", "--scale", "1", "--progress"],
    ["animate", "--theta0", "0.5", "--Omega0", "3", "--frames", "400", "--t-end", "5",
     "--out", "m.gif"],
    ["atlas", "--quick", "--out", "at", "--progress"],
    ["euler-disk", "--out", "ed", "--progress"],
], ids=["figures", "animate", "atlas", "euler-disk"])
def test_a_signal_leaves_nothing(tmp_path, argv, sig, rc, word):
    """Ctrl-C or SIGTERM while the pictures are made: one line, the right status, no file,
    no temporary. The atlas is stopped while its animation helper process runs (step 6)."""
    if argv[0] == "atlas":
        code, err = _interrupt(argv, tmp_path, sig, after=0.2, marker="[6/")
    elif argv[0] == "figures":  # done in about 2 s: stop it while fig6 is drawn
        code, err = _interrupt(argv, tmp_path, sig, after=0.05, marker="fig6")
    elif argv[0] == "euler-disk":  # stopped inside the integrator's loop
        code, err = _interrupt(argv, tmp_path, sig, after=0.3, marker="simulating [")
    else:
        code, err = _interrupt(argv, tmp_path, sig, after=2.5)
    assert code == rc, err
    assert err.strip().splitlines()[-1] == f"rollingdisk: {word}", err
    assert "Traceback" not in err
    assert os.listdir(tmp_path) == []


@pytest.mark.slow  # two quick atlases at once, about 20 s
def test_two_atlases_into_one_folder_end_consistent(tmp_path):
    """Two runs into the same folder: the one that finishes last leaves its whole atlas,
    so index.html and thresholds.json describe the same disk."""
    env = dict(os.environ, PYTHONPATH=SRC, MPLBACKEND="Agg")
    procs = [subprocess.Popen([sys.executable, "-m", "rollingdisk", "atlas", "--quick",
                               "--quiet", "--h", h, "--out", "at"], cwd=tmp_path, env=env,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
             for h in ("0.17", "0.4")]
    for proc in procs:
        _, err = proc.communicate(timeout=300)
        assert proc.returncode == 0, err
    h = json.loads((tmp_path / "at" / "thresholds.json").read_text())["h"]
    html = (tmp_path / "at" / "index.html").read_text(encoding="utf-8")
    assert f"h = {h:.4g}</title>" in html
    assert sorted(os.listdir(tmp_path)) == ["at"]  # no temporary folder left
