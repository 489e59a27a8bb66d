"""The command line under random hostile input (a fixed seed, so a failure replays).

Sources of truth: the exit-status contract of ``rollingdisk.cli.app`` (README, "Command
line"): every call ends with 0 or 2, never 1 (a traceback is a bug); exit 2 prints exactly
one line on stderr; JSON never holds NaN or infinity; no output is left half-written (no
temporary file of ``rollingdisk.util.files`` survives); and no call hangs (a generous
per-call bound, a hang guard rather than a speed measurement); and every output lands in
the test's own folder (the calls run there, and every path value names a place under it:
a directory, a missing folder, a 300-character name, a file that is not ours).
"""

import json
import os
import random
import time
from pathlib import Path

import pytest

from rollingdisk.cli import main

#: Cheap, valid calls: one option at a time is replaced by a hostile value.
CHEAP = {
    "steady": ["steady", "--ground", "rough", "--h", "0.17", "--theta0", "30deg",
               "--Omega0", "1.5", "--json"],
    "thresholds": ["thresholds", "--h", "0.17", "--json"],
    "simulate": ["simulate", "--h", "0.17", "--theta0", "30deg", "--Omega0", "1.5",
                 "--t-end", "2", "--kick", "0.01", "--json", "--out", "{tmp}/run.csv"],
    "simulate-coulomb": ["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.17",
                         "--theta0", "30deg", "--rC", "0.5", "--t-end", "1", "--json"],
    "exact": ["exact", "--h", "0.17", "--theta0", "30deg", "--Omega0", "1.5",
              "--kick", "0.01", "--json"],
    "sweep": ["sweep", "--h", "0.17", "--theta0", "0.3:0.5:2", "--omega30", "1:2:2",
              "--t-end", "5", "--workers", "1", "--json", "--out", "{tmp}/s.zarr"],
    "until-rest": ["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.1",
                   "--state", "theta=0.3,omega3=2", "--until-rest", "--t-end", "0.5",
                   "--max-wall-time", "20", "--json", "--out", "{tmp}/rest.csv"],
    "toss-results": ["toss", "--h", "0.1", "--n", "1", "--max-wall", "10",
                     "--results", "{tmp}/t.jsonl", "--json"],
}
#: Calls whose valid form is long (or serves forever): only values no option accepts.
HEAVY = {
    "atlas": ["atlas", "--h", "0.17", "--quick", "--quiet", "--out", "{tmp}/atlas"],
    "figures": ["figures", "--scale", "0.5", "--out", "{tmp}/fig"],
    "euler-disk": ["euler-disk", "--alpha0", "0.3", "--json"],
    "toss": ["toss", "--h", "0.1", "--n", "2", "--json"],
    "edge-odds": ["edge-odds", "--n", "1", "--ratios", "0.3", "--upward-speed", "3", "--json"],
    "animate": ["animate", "--theta0", "30deg", "--Omega0", "2", "--frames", "4",
                "--out", "{tmp}/a.gif"],
    "explore": ["explore", "--h", "0.17", "--no-browser", "--port", "0"],
    "map": ["map", "--h", "0.17", "--kind", "existence", "--out", "{tmp}/m.png"],
    "derive": ["derive", "--sections", "2", "--json"],
    "euler-disk-sound": ["euler-disk", "--alpha0", "0.3", "--sound", "{tmp}/w.wav",
                         "--sound-seconds", "1", "--json"],
    "until-rest-animate": ["simulate", "--ground", "coulomb", "--mu", "0.5", "--h", "0.1",
                           "--state", "theta=0.3,omega3=2", "--until-rest", "--t-end", "0.5",
                           "--animate", "{tmp}/a.gif", "--json"],
}
HOSTILE = ["nan", "inf", "-inf", "1e400", "-1e400", "abc", "", "0x1p3", "1e309", "--", "deg",
           "30degdeg", "1/0", "None", "\u00e9", "1e-400deg"]
MORE = ["-1", "0", "1e308", "-0.0", "1e-320", "30", "4e-324", "1e9", "-30deg", "2e2"]
#: Paths, each under the call's own folder ``{tmp}`` (never "/" or a device: the tests
#: run as whoever runs them, possibly root, and a bug could replace what it names).
PATHS = ["{tmp}", "{tmp}/", "{tmp}/no/such/folder/out.x", "{tmp}/" + "a" * 300,
         "{tmp}/notours.jsonl", "{tmp}/notours.jsonl/x", "{tmp}/.", "{tmp}/out.txt"]


def _strict(text):
    def bad(constant):
        raise ValueError(f"JSON holds {constant}")

    return json.loads(text, parse_constant=bad)


def _calls(seed, n):
    rng = random.Random(seed)
    for _ in range(n):
        heavy = rng.random() < 0.35
        table = HEAVY if heavy else CHEAP
        name = rng.choice(sorted(table))
        argv = list(table[name])
        options = [i for i, a in enumerate(argv) if a.startswith("--") and i + 1 < len(argv)
                   and not argv[i + 1].startswith("--")]
        i = rng.choice(options) + 1
        pool = HOSTILE if heavy else HOSTILE + MORE
        if "{tmp}" in argv[i] and name not in ("atlas", "figures"):
            pool = HOSTILE + PATHS  # a path option: paths too, all under {tmp} (atlas and
            # figures only get values no option accepts: a whole run takes minutes)
        argv[i] = rng.choice(pool)
        yield argv


def _files_outside(root: Path, before: set) -> set:
    return {p for p in os.listdir(root)} - before


def test_every_command_is_fuzzed():
    from rollingdisk.cli.app import COMMANDS

    fuzzed = {argv[0] for argv in (*CHEAP.values(), *HEAVY.values())}
    assert fuzzed == {name for name, _, _ in COMMANDS}


NOT_OURS = "a file that is not a results file\n"

#: The call numbers of the slow run below known to break the contract (none today): each
#: listed one turns the run red once fixed (strict), so the list only shrinks.
KNOWN: dict = {}


@pytest.mark.slow
@pytest.mark.parametrize("seed", [20261125])
def test_random_hostile_calls_keep_the_contract(seed, tmp_path, capsys, monkeypatch):
    # a hostile value that replaces an --out path ("None", "nan") is a valid relative path:
    # run where such outputs land in the test's own folder, never in the checkout
    checkout = Path(__file__).resolve().parents[1]
    before = set(os.listdir(checkout))
    monkeypatch.chdir(tmp_path)
    broken = {}
    for k, argv in enumerate(_calls(seed, 1000)):
        tmp = tmp_path / f"call{k}"
        tmp.mkdir()
        (tmp / "notours.jsonl").write_text(NOT_OURS)
        args = [a.replace("{tmp}", str(tmp)) for a in argv]
        try:
            _one(args, tmp_path, capsys)
            after = (tmp / "notours.jsonl").read_bytes()
            # --out replaces a file (documented); appending to one that is not ours is a bug
            assert not (after != NOT_OURS.encode() and after.startswith(NOT_OURS.encode())), (
                f"{' '.join(a[:60] for a in args)}: appended to a file that is not ours")
        except AssertionError as exc:
            broken[k] = str(exc).splitlines()[0][:300]
    assert not _files_outside(checkout, before)
    unexpected = {k: v for k, v in broken.items() if k not in KNOWN}
    fixed = sorted(set(KNOWN) - set(broken))
    assert not unexpected and not fixed, (
        f"{len(unexpected)} calls broke the contract:\n"
        + "\n".join(f"{k}: {v}" for k, v in sorted(unexpected.items())[:40])
        + f"\nfixed (drop from KNOWN): {fixed}")


def _one(args, tmp_path, capsys):
    """One call under the contract; an AssertionError whose first line says how it broke."""
    start = time.perf_counter()
    rc = main(args)
    wall = time.perf_counter() - start
    out, err = capsys.readouterr()
    where = f"rollingdisk {' '.join(a[:60] for a in args)}"
    last = err.strip().splitlines()[-1][:200] if err.strip() else ""
    assert rc in (0, 2), f"{where}: exit {rc}: {last}\n{err[-2000:]}"
    assert "Traceback" not in err, f"{where}: traceback: {last}\n{err[-2000:]}"
    if rc == 2:
        lines = [line for line in err.splitlines() if line.strip()]
        assert len(lines) == 1, f"{where}: {len(lines)} lines on exit 2: {lines[:4]}"
    if rc == 0 and "--json" in args:
        _strict(out)  # the whole of stdout is one JSON document
    leftovers = [p.name for p in tmp_path.rglob(".*") if ".tmp" in p.name or ".old" in p.name]
    assert not leftovers, f"{where}: left {leftovers}"
    assert wall < 120.0, f"{where}: {wall:.0f} s (hang guard)"
