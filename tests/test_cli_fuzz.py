"""The command line under random hostile input (a fixed seed, so a failure replays).

Sources of truth: the exit-status contract of ``rollingdisk.cli.app`` (README, "Command
line"): every call ends with 0 or 2, never 1 (a traceback is a bug); exit 2 prints exactly
one line on stderr; JSON never holds NaN or infinity; no output is left half-written (no
temporary file of ``rollingdisk.util.files`` survives); and no call hangs (a generous
per-call bound, a hang guard rather than a speed measurement).
"""

import json
import random
import time

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
}
#: Calls whose valid form is long (or serves forever): only values no option accepts.
HEAVY = {
    "atlas": ["atlas", "--h", "0.17", "--quick", "--quiet", "--out", "{tmp}/atlas"],
    "figures": ["figures", "--scale", "0.5", "--out", "{tmp}/fig"],
    "euler-disk": ["euler-disk", "--alpha0", "0.3", "--json"],
    "toss": ["toss", "--h", "0.1", "--n", "2", "--json"],
    "animate": ["animate", "--theta0", "30deg", "--Omega0", "2", "--frames", "4",
                "--out", "{tmp}/a.gif"],
    "explore": ["explore", "--h", "0.17", "--no-browser", "--port", "0"],
    "map": ["map", "--h", "0.17", "--kind", "existence", "--out", "{tmp}/m.png"],
}
HOSTILE = ["nan", "inf", "-inf", "1e400", "-1e400", "abc", "", "0x1p3", "1e309", "--", "deg",
           "30degdeg", "1/0", "None", "\u00e9", "1e-400deg"]
MORE = ["-1", "0", "1e308", "-0.0", "1e-320", "30", "4e-324", "1e9", "-30deg", "2e2"]


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
        argv[i] = rng.choice(pool)
        yield argv


@pytest.mark.slow
@pytest.mark.parametrize("seed", [20261125])
def test_random_hostile_calls_keep_the_contract(seed, tmp_path, capsys, monkeypatch):
    # a hostile value that replaces an --out path ("None", "nan") is a valid relative path:
    # run where such outputs land in the test's own folder, never in the checkout
    monkeypatch.chdir(tmp_path)
    for k, argv in enumerate(_calls(seed, 300)):
        tmp = tmp_path / f"call{k}"
        tmp.mkdir()
        args = [a.replace("{tmp}", str(tmp)) for a in argv]
        start = time.perf_counter()
        rc = main(args)
        wall = time.perf_counter() - start
        out, err = capsys.readouterr()
        where = f"call {k}: rollingdisk {' '.join(args)}"
        assert rc in (0, 2), f"{where}: exit {rc}\n{err[-2000:]}"
        assert "Traceback" not in err, f"{where}\n{err[-2000:]}"
        if rc == 2:
            lines = [line for line in err.splitlines() if line.strip()]
            assert len(lines) == 1, f"{where}: {lines}"
        if rc == 0 and "--json" in args:
            _strict(out)  # the whole of stdout is one JSON document
        leftovers = [p.name for p in tmp_path.rglob(".*")
                     if ".tmp" in p.name or ".old" in p.name]
        assert not leftovers, f"{where}: {leftovers}"
        assert wall < 120.0, f"{where}: {wall:.0f} s (hang guard)"
