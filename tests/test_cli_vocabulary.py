"""One vocabulary across the commands: every subcommand's parser is walked (from
``rollingdisk.cli.app.build_parser()``) and checked for abbreviations, two visible spellings
of one idea, ``--quiet`` on every long command, and the same disk options wherever a disk
is taken; the old spellings still work, hidden from --help."""

from __future__ import annotations

import argparse
import sys

import pytest

from rollingdisk.cli._args import show_progress
from rollingdisk.cli.app import build_parser, main

#: Spellings that would name one idea: at most one of each group may be visible in
#: a command's --help (an old one may live on as a hidden alias).
SYNONYMS = (
    {"--e", "--restitution", "--coefficient-of-restitution", "--cor"},
    {"--max-wall", "--max-wall-time", "--wall-time", "--max-time", "--timeout"},
    {"--quiet", "-q", "--silent", "--no-progress"},
    {"--out", "--output", "-o", "--outdir", "--out-dir"},
    {"--t-end", "--tend", "--t_end", "--duration", "--time"},
    {"--workers", "--jobs", "-j", "--processes", "--cores"},
    {"--json", "--as-json", "--format-json"},
    {"--mu", "--friction-coefficient", "--mu-s"},
    {"--h", "--half-thickness"},
    {"--disk", "--named-disk", "--coin"},
    {"--kick", "--omega1-kick"},
    {"--perturb", "--tilt-perturbation"},
    {"--seed", "--rng-seed", "--random-seed"},
    {"--n", "--count", "--number"},
)

#: Commands that run long enough to draw progress: each takes --quiet (and --progress).
LONG = {"simulate", "sweep", "toss", "atlas", "euler-disk", "figures", "map", "derive",
        "edge-odds"}
#: The options that give the disk, the same wherever a disk is taken.
DISK_FLAGS = {"--h", "--disk", "--radius", "--diameter", "--thickness", "--mass", "--gravity"}
#: Commands that take no disk (edge-odds varies the thickness itself, in units of the
#: radius).
NO_DISK = {"figures", "derive", "edge-odds"}


def _commands() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {"rollingdisk": parser, **sub.choices}


def _visible(p) -> set[str]:
    return {s for a in p._actions if a.help is not argparse.SUPPRESS for s in a.option_strings}


def _hidden(p) -> set[str]:
    return {s for a in p._actions if a.help is argparse.SUPPRESS for s in a.option_strings}


COMMANDS = _commands()


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_no_parser_abbreviates(name):
    assert COMMANDS[name].allow_abbrev is False


@pytest.mark.parametrize("argv", [["figures", "--out", "figs", "--h", "0.3"],
                                  ["derive", "--h", "0.3"], ["figures", "--h", "0.3"],
                                  ["simulate", "--h", "0.1", "--theta0", "0.3", "--Omega0",
                                   "2", "--t-end", "1", "--max-st", "5"]])
def test_an_abbreviation_is_one_line_and_exit_2(argv, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and len(captured.err.strip().splitlines()) == 1
    assert not list(tmp_path.iterdir())  # no work done


@pytest.mark.parametrize("group", SYNONYMS, ids=lambda g: sorted(g)[0])
def test_one_visible_spelling_per_idea(group):
    used = {s for p in COMMANDS.values() for s in _visible(p) & group}
    assert len(used) <= 1, f"{sorted(used)} name one idea: keep one, hide the others"


@pytest.mark.parametrize("name", sorted(LONG))
def test_every_long_command_is_quiet_on_request(name):
    assert {"--quiet", "--progress"} <= _visible(COMMANDS[name])


@pytest.mark.parametrize("name", sorted(set(COMMANDS) - {"rollingdisk"}))
def test_every_disk_taking_command_takes_the_same_disk_options(name):
    flags = _visible(COMMANDS[name]) & DISK_FLAGS
    if name in NO_DISK:
        assert not flags
    else:
        assert flags == DISK_FLAGS, f"{name} lacks {sorted(DISK_FLAGS - flags)}"


def test_old_spellings_are_hidden_aliases_that_still_work():
    p = COMMANDS["toss"]
    assert {"--e", "--max-wall"} <= _hidden(p) and {"--restitution", "--max-wall-time"} <= \
        _visible(p)
    top = build_parser()
    old = top.parse_args(["toss", "--h", "0.1", "--e", "0.3", "--max-wall", "5"])
    new = top.parse_args(["toss", "--h", "0.1", "--restitution", "0.3", "--max-wall-time",
                          "5"])
    assert (old.e, old.max_wall) == (new.e, new.max_wall) == (0.3, 5.0)
    sim = top.parse_args(["simulate", "--h", "0.1", "--state", "theta=0.3", "--t-end", "1",
                          "--max-wall", "7"])
    assert sim.max_wall_time == 7.0
    for name in ("toss", "simulate"):
        text = COMMANDS[name].format_help()
        assert "--max-wall " not in text and "--e " not in text


def test_a_positional_disk_name_is_the_disk_option(capsys):
    assert main(["thresholds", "euro-1", "--json"]) == 0
    positional = capsys.readouterr().out
    assert main(["thresholds", "--disk", "euro-1", "--json"]) == 0
    assert capsys.readouterr().out == positional and "0.1973" in positional
    assert main(["thresholds", "euro-1", "--disk", "cd"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "euro-1" in err and "cd" in err
    for name in ("atlas", "toss", "euler-disk"):
        args = build_parser().parse_args([name, "us-quarter"])
        assert args.disk_name == "us-quarter"


def test_explore_takes_the_disk_options():
    import rollingdisk as rd
    from rollingdisk.explore.command import _start_disk

    parse = build_parser().parse_args
    h, disk = _start_disk(parse(["explore", "--disk", "euro-1"]))
    assert h == rd.DISKS["euro-1"].h and disk.radius == pytest.approx(0.011625)
    assert _start_disk(parse(["explore"])) == (rd.DEFAULT_H, None)
    assert _start_disk(parse(["explore", "--radius", "1cm", "--thickness", "4mm"]))[0] == \
        pytest.approx(0.2, rel=1e-12)


class _Tty:
    def __init__(self, tty):
        self.tty = tty

    def isatty(self):
        return self.tty

    def write(self, text):
        pass


@pytest.mark.parametrize("tty,flags,shown", [
    (True, {}, True), (False, {}, False), (False, {"progress": True}, True),
    (True, {"quiet": True}, False), (True, {"json": True}, False),
])
def test_progress_only_on_a_terminal_unless_asked(monkeypatch, tty, flags, shown):
    monkeypatch.setattr(sys, "stderr", _Tty(tty))
    args = argparse.Namespace(**{"quiet": False, "progress": False, "json": False, **flags})
    assert show_progress(args) is shown


def test_quiet_and_progress_exclude_each_other(capsys):
    assert main(["figures", "--out", "x", "--quiet", "--progress"]) == 2
    assert "not allowed with" in capsys.readouterr().err


def test_a_run_on_a_pipe_writes_no_progress(capsys):
    # stderr is captured (not a terminal): the run's progress bar stays silent
    assert main(["simulate", "--h", "0.1", "--state", "theta=0.3,omega2=1.5,omega3=0.7",
                 "--t-end", "5", "--method", "dop853"]) == 0
    assert capsys.readouterr().err == ""
