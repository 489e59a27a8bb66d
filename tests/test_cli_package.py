"""The command-line package: every option documented, ``--version``, no tracker numbers in
user-facing text, and the robustness items of the CLI (bad input is exit 2 with one line,
outputs onto devices, FIFOs and symbolic links, signals before the first command runs)."""

from __future__ import annotations

import argparse
import json
import os
import re
import stat
import subprocess
import sys
import threading
import warnings
from pathlib import Path

import pytest

from rollingdisk.cli import build_parser, main

ROOT = Path(__file__).resolve().parents[1]
SRC = str(ROOT / "src")
STEADY = ["--h", "0.1", "--theta0", "0.3", "--Omega0", "3"]


def _commands():
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return parser, sub.choices


def test_every_option_of_every_command_has_help():
    parser, commands = _commands()
    missing = []
    for name, p in [("rollingdisk", parser), *commands.items()]:
        for action in p._actions:
            if isinstance(action, argparse._SubParsersAction):
                continue
            hidden_alias = action.help is argparse.SUPPRESS and any(
                a.dest == action.dest and a.help not in (None, argparse.SUPPRESS)
                for a in p._actions)  # an old spelling kept working, hidden from --help
            if (not action.help or action.help is argparse.SUPPRESS) and not hidden_alias:
                missing.append(f"{name} {'/'.join(action.option_strings) or action.dest}")
    assert not missing, f"options without help: {missing}"
    listed = {a.dest for a in next(a for a in parser._actions
                                   if isinstance(a, argparse._SubParsersAction))._choices_actions}
    assert listed == set(commands)  # and every command has its one-line help


def test_version(capsys):
    from importlib.metadata import version

    assert main(["--version"]) == 0
    assert capsys.readouterr().out.strip() == f"rollingdisk {version('rollingdisk')}"


ISSUE = re.compile(r"\bissues? #?\d+", re.IGNORECASE)


def test_no_user_facing_text_names_a_tracker_issue():
    parser, commands = _commands()
    texts = [parser.format_help()] + [p.format_help() for p in commands.values()]
    texts += [(ROOT / "README.md").read_text(encoding="utf-8")]
    texts += [p.read_text(encoding="utf-8") for p in sorted((ROOT / "docs").glob("*.md"))]
    texts += [p.read_text(encoding="utf-8")
              for p in sorted((ROOT / "src/rollingdisk/atlas").glob("*.py"))]
    hits = [m.group(0) for t in texts for m in ISSUE.finditer(t)]
    assert not hits, hits


# ---------------------------------------------------------------- bad input is exit 2
@pytest.mark.parametrize("argv, needle", [
    (["steady", "--ground", "smooth", "--h", "0.17", "--theta0", "0.5", "--Omega0", "4e-324"],
     "Omega0"),
    (["simulate", "--ground", "coulomb", "--h", "0.5", "--theta0", "45deg", "--Omega0", "0.5",
      "--mu", "1", "--mu-k", "0.15", "--kick", "0.01", "--t-end", "5", "--rtol", "1"], "rtol"),
    (["simulate", "--ground", "coulomb", "--h", "0.5", "--theta0", "45deg", "--Omega0", "0.5",
      "--mu", "1", "--mu-k", "0.15", "--kick", "0.01", "--t-end", "5", "--rtol", "0.5"],
     "rtol"),
    (["simulate", *STEADY, "--t-end", "1", "--rtol", "1e-16"], "rtol"),
    (["simulate", *STEADY, "--t-end", "1", "--atol", "1"], "atol"),
    (["sweep", "--ground", "rough", "--theta0", "0.5", "--omega30", "1", "--t-end", "nan",
      "--basin", "--out", "s.zarr"], "t_end"),
    (["sweep", "--ground", "rough", "--theta0", "0.2:inf:3", "--omega30", "1", "--t-end", "5",
      "--out", "s.zarr"], "0.2:inf:3"),
    (["sweep", "--ground", "rough", "--theta0", "0.2:1:1e9", "--omega30", "1", "--t-end", "5",
      "--out", "s.zarr"], "N"),
    (["sweep", "--ground", "rough", "--theta0", "0.5", "--omega30", "1", "--t-end", "1e5",
      "--out", "s.zarr"], "t_end must lie in (0, 10000]"),
    (["simulate", *STEADY, "--t-end", "1e9"], "t_end must lie in (0, 1e+06]"),
    (["simulate", "--h", "0.1", "--state", "theta=0.3", "--perturb", "1e308", "--t-end", "1"],
     "perturb"),
    (["exact", "--h", "0.1", "--state", "theta=0.3", "--perturb", "2"], "perturb"),
    (["simulate", "--h", "0.1", "--state", "theta=inf", "--t-end", "1"], "theta"),
])
def test_bad_input_is_one_line_exit_2(tmp_path, monkeypatch, capsys, argv, needle):
    monkeypatch.chdir(tmp_path)
    with warnings.catch_warnings(record=True) as seen:  # no RuntimeWarning before the error
        warnings.simplefilter("always")
        rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 2, err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert needle in err, err
    assert not [w for w in seen if issubclass(w.category, RuntimeWarning)], seen
    assert os.listdir(tmp_path) == []


# ---------------------------------------------------------------- outputs that are not files
def test_out_onto_a_character_device_writes_through(capsys):
    assert main(["simulate", *STEADY, "--t-end", "1", "--out", os.devnull, "--json"]) == 0
    assert stat.S_ISCHR(os.stat(os.devnull).st_mode)  # still the device
    assert json.loads(capsys.readouterr().out)["out"] == os.devnull


def test_out_onto_a_fifo_writes_through(tmp_path, capsys):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_text()))
    reader.start()
    rc = main(["simulate", *STEADY, "--t-end", "1", "--out", str(fifo), "--json"])
    reader.join(timeout=600)
    assert rc == 0 and stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert got and got[0].startswith("t,X_C,Y_C") and len(got[0].splitlines()) > 2
    assert sorted(os.listdir(tmp_path)) == ["pipe"]  # no temporary left


def test_out_through_a_symbolic_link_replaces_the_target(tmp_path, capsys):
    target = tmp_path / "real" / "run.csv"
    target.parent.mkdir()
    target.write_text("old")
    link = tmp_path / "link.csv"
    link.symlink_to(target)
    assert main(["simulate", *STEADY, "--t-end", "1", "--out", str(link), "--json"]) == 0
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text().startswith("t,X_C")
    assert sorted(os.listdir(target.parent)) == ["run.csv"]


# ---------------------------------------------------------------- signals
def test_an_output_complete_before_the_signal_is_named(tmp_path, monkeypatch, capsys):
    import rollingdisk.cli.simulate as command

    def stop(*args, **kwargs):  # Ctrl-C after the CSV is in place, while the summary prints
        raise KeyboardInterrupt

    monkeypatch.setattr(command.json, "dumps", stop)
    out = tmp_path / "run.csv"
    assert main(["simulate", *STEADY, "--t-end", "1", "--out", str(out), "--json"]) == 130
    err = capsys.readouterr().err.strip()
    assert err.startswith("rollingdisk: interrupted") and "already complete" in err
    assert str(out) in err and len(err.splitlines()) == 1
    assert out.read_text().startswith("t,X_C")


EARLY = """
import builtins, os, signal, sys
import rollingdisk.cli.entry as rollingdisk_cli
real = builtins.__import__
def hook(name, *args, **kwargs):
    if name == {module!r}:
        builtins.__import__ = real
        os.kill(os.getpid(), signal.{sig})
    return real(name, *args, **kwargs)
builtins.__import__ = hook
sys.exit(rollingdisk_cli.main(["thresholds", "--h", "0.2"]))
"""


@pytest.mark.parametrize("module, where", [("numpy", "while the package is imported"),
                                           ("rollingdisk.cli._format",
                                            "while the parser is built")])
@pytest.mark.parametrize("sig, code, word", [("SIGINT", 130, "interrupted"),
                                             ("SIGTERM", 143, "terminated")])
def test_a_signal_before_the_command_runs(module, where, sig, code, word):
    res = subprocess.run([sys.executable, "-c", EARLY.format(module=module, sig=sig)],
                         capture_output=True, text=True, timeout=120,
                         env=dict(os.environ, PYTHONPATH=SRC))
    assert res.returncode == code, (where, res.stderr)
    assert res.stderr.strip() == f"rollingdisk: {word}", (where, res.stderr)
    assert res.stdout == ""
