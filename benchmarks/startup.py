"""Benchmark: the wall time a user waits for a whole command, beside the script it replaces.

Cases (each a fresh process; issue #33):

* ``python + numpy``: the interpreter with numpy alone (the floor of any command);
* ``user scipy script``: benchmarks/user_scipy.py, the user's own solve_ivp script for the
  motion below -- the baseline of the ratios;
* ``simulate (warm)``: ``rollingdisk simulate --h 0.17 --theta0 0.5 --Omega0 1.7
  --perturb 1e-4 --t-end 100 --json`` with the compile cache as it is after a first use;
* ``simulate (cold)``: the same with an empty compile cache (``NUMBA_CACHE_DIR`` a new
  empty folder every round), as right after an install;
* ``sweep 10x10 (warm)``: ``rollingdisk sweep --ground rough --h 0.17 --theta0 0.3:1.2:10
  --omega30 2:6:10 --t-end 100 --out S.zarr --json``, kernels in the cache.

The machine is shared: the cases run interleaved, ``--rounds`` rounds of one run each, and
each case's figure is its best (least) wall time, so that a neighbour's load weighs on every
case alike and the ratios come from one run.  Children run with ``PYTHONDONTWRITEBYTECODE``
removed from their environment (an installed package has its bytecode; compiling every
module's source on each start would be counted otherwise).  Targets: simulate warm <= 0.75x
and cold <= 2x the user's script, the 10x10 sweep <= 0.8 s warm.

Then ``python -X importtime`` of each kind of command: which heavy packages it loads, with
their cumulative import time.

Writes everything as JSON to ``--json`` (default ``benchmarks/results/startup.json``,
ignored by git); ``python benchmarks/report.py`` turns it into the README's numbers and
docs/performance.md.

Run:  python benchmarks/startup.py [--rounds 7] [--json PATH] [--baseline SRC
      --baseline-name NAME]
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results"

SIMULATE = ["simulate", "--h", "0.17", "--theta0", "0.5", "--Omega0", "1.7", "--perturb",
            "1e-4", "--t-end", "100", "--json"]
SWEEP = ["sweep", "--ground", "rough", "--h", "0.17", "--theta0", "0.3:1.2:10", "--omega30",
         "2:6:10", "--t-end", "100", "--json"]
STEADY = ["steady", "--h", "0.17", "--theta0", "30deg", "--Omega0", "2"]

#: Packages whose loading a command should pay only when it needs them.
HEAVY = ("numba", "scipy", "scipy.integrate", "scipy.linalg", "xarray", "pandas", "zarr",
         "dask", "dask.array", "matplotlib", "sympy")

TARGETS = {"simulate_warm_over_script": 0.75, "simulate_cold_over_script": 2.0,
           "sweep_10x10_warm_s": 0.8}


def _env(extra: dict | None = None, src: Path = ROOT / "src") -> dict:
    env = dict(os.environ, **(extra or {}))
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPATH"] = str(src) + os.pathsep + env.get("PYTHONPATH", "")
    return env


def _rd(*args: str) -> list[str]:
    return [sys.executable, "-m", "rollingdisk", *args]


def timed(cmd: list[str], env: dict, cwd: Path) -> tuple[float, str]:
    """Wall time [s] of the process ``cmd`` and its stdout; raises if it fails."""
    t0 = time.perf_counter()
    res = subprocess.run(cmd, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if res.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{res.stderr[-2000:]}")
    return wall, res.stdout


def cases(tmp: Path, baseline: Path | None = None) -> dict:
    """name -> a function of the round number giving (command, extra environment, source
    tree); with ``baseline``, the rollingdisk commands again on that tree (``[baseline]``)."""
    src = ROOT / "src"

    def cold(tree):
        return lambda r: (_rd(*SIMULATE), {"NUMBA_CACHE_DIR": tempfile.mkdtemp(
            dir=tmp, prefix="cold")}, tree)

    def sweep(tree, tag):
        return lambda r: (_rd(*SWEEP, "--out", str(tmp / f"s{tag}{r}.zarr")), {}, tree)

    out = {
        "python + numpy": lambda r: ([sys.executable, "-c", "import numpy"], {}, src),
        "user scipy script": lambda r: ([sys.executable, str(ROOT / "benchmarks" /
                                                             "user_scipy.py")], {}, src),
        "simulate (warm)": lambda r: (_rd(*SIMULATE), {}, src),
        "simulate (cold)": cold(src),
        "sweep 10x10 (warm)": sweep(src, ""),
    }
    if baseline is not None:
        out.update({
            "simulate (warm) [baseline]": lambda r: (_rd(*SIMULATE), {}, baseline),
            "simulate (cold) [baseline]": cold(baseline),
            "sweep 10x10 (warm) [baseline]": sweep(baseline, "b"),
        })
    return out


def imports(cmd: list[str], env: dict, cwd: Path) -> dict:
    """``python -X importtime``: cumulative import seconds of each heavy package loaded."""
    res = subprocess.run([cmd[0], "-X", "importtime", *cmd[1:]], env=env, cwd=cwd,
                         capture_output=True, text=True)
    cum = {}
    for line in res.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            _, c, name = line.split("|")
            if c.strip().isdigit():
                cum.setdefault(name.strip(), int(c) / 1e6)
    return {m: round(cum[m], 4) for m in HEAVY if m in cum}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=7)
    ap.add_argument("--json", type=Path, default=RESULTS / "startup.json")
    ap.add_argument("--baseline", type=Path, default=None, metavar="SRC",
                    help="another tree's src folder (e.g. a checkout of main): its commands "
                    "run interleaved with these, labelled [baseline]")
    ap.add_argument("--baseline-name", default=None,
                    help="what the baseline tree is, for the report (e.g. 'main at 619e14f')")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        todo = cases(tmp, args.baseline)
        env0 = _env()
        # warm-up: bytecode written, the compile cache filled for the warm cases
        for name in todo:
            if "cold" not in name:
                cmd, extra, src = todo[name](-1)
                timed(cmd, _env(extra, src), tmp)
        walls = {name: [] for name in todo}
        outputs = {}
        for r in range(args.rounds):
            for name, make in todo.items():
                cmd, extra, src = make(r)
                wall, out = timed(cmd, _env(extra, src), tmp)
                walls[name].append(wall)
                outputs[name] = out
        best = {k: min(v) for k, v in walls.items()}
        loaded = {
            "import rollingdisk": imports([sys.executable, "-c", "import rollingdisk"],
                                          env0, tmp),
            "rollingdisk --help": imports(_rd("--help"), env0, tmp),
            "rollingdisk steady": imports(_rd(*STEADY), env0, tmp),
            "rollingdisk simulate --t-end 100": imports(_rd(*SIMULATE), env0, tmp),
            "rollingdisk sweep 10x10": imports(_rd(*SWEEP, "--out", str(tmp / "i.zarr")),
                                               env0, tmp),
        }
    script = best["user scipy script"]
    sim = json.loads(outputs["simulate (warm)"])
    user = json.loads(outputs["user scipy script"])
    result = {
        "benchmark": "startup",
        "date": datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d"),
        "machine": {"cpus": os.cpu_count(), "python": platform.python_version(),
                    "platform": platform.platform()},
        "rounds": args.rounds,
        "best_s": {k: round(v, 4) for k, v in best.items()},
        "median_s": {k: round(statistics.median(v), 4) for k, v in walls.items()},
        "all_s": {k: [round(x, 4) for x in v] for k, v in walls.items()},
        "ratios": {
            "simulate_warm_over_script": round(best["simulate (warm)"] / script, 3),
            "simulate_cold_over_script": round(best["simulate (cold)"] / script, 3),
            "sweep_10x10_over_script": round(best["sweep 10x10 (warm)"] / script, 3),
        },
        "sweep_10x10_warm_s": round(best["sweep 10x10 (warm)"], 3),
        "baseline": None if args.baseline is None else (args.baseline_name or
                                                        str(args.baseline)),
        "targets": TARGETS,
        "steps": {"simulate": sim["n_steps"], "simulate_method": sim["method"],
                  "user scipy script": user["n_steps"]},
        "imports_s": loaded,
    }
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(result, indent=2) + "\n")
    print(f"whole processes, best of {args.rounds} interleaved rounds "
          f"({os.cpu_count()} CPUs):")
    for k, v in best.items():
        print(f"  {k:22s} {v:7.3f} s   {v / script:5.2f} x the user's script")
    ok = result["ratios"]
    print(f"simulate warm / script {ok['simulate_warm_over_script']:.2f} (target <= 0.75), "
          f"cold / script {ok['simulate_cold_over_script']:.2f} (target <= 2), sweep 10x10 "
          f"{result['sweep_10x10_warm_s']:.2f} s (target <= 0.8 s)")
    print("python -X importtime, heavy packages loaded (cumulative s):")
    for k, v in loaded.items():
        print(f"  {k:34s} " + (", ".join(f"{m} {s:.2f}" for m, s in v.items()) or "none"))
    print(f"wrote {args.json}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
