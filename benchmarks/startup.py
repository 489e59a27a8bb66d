"""Benchmark: the speed a user feels, command by command, beside a baseline.

Prints, in one run, the wall time of whole processes (median of ``--repeat`` runs):

* ``import rollingdisk`` (and, apart, the interpreter with numpy alone);
* ``rollingdisk steady ...`` (no integration);
* ``rollingdisk simulate ... --t-end 100`` with a warm compile cache, beside the same
  command with ``--method scipy`` (solve_ivp on the numpy right-hand side);
* the first ``simulate`` after an install: an empty numba cache (``NUMBA_CACHE_DIR`` set
  to a fresh folder);
* ``rollingdisk atlas`` warm, and cold (empty numba cache and empty matplotlib cache, as on
  a fresh install).

Every command also runs against a baseline tree: by default the previous release (the
commit ``BASELINE_REF`` below, exported with ``git archive``), so each line reads
"now / before".  Targets (issue 9): simulate warm <= 0.5 x the scipy path; first run <= 5 s;
atlas <= 8 s warm and <= 15 s cold.

With ``--long``, also ``simulate --t-end 30000`` with an empty cache (the background compiler
at work while the run goes on uncompiled) and warm.  Then ``python -X importtime``: which
heavy packages each kind of command imports.

Run:  python benchmarks/startup.py [--repeat 3] [--baseline REF | --no-baseline] [--no-atlas]
      [--long]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: The release before the speed work (rollingdisk 0.1.0 as of the start of this stage).
BASELINE_REF = "91424fe"

STEADY = ["steady", "--h", "0.17", "--theta0", "30deg", "--Omega0", "2"]
SIMULATE = ["simulate", "--h", "0.17", "--theta0", "30deg", "--Omega0", "2", "--perturb",
            "1e-3", "--t-end", "100", "--json"]


def run(src: Path, args: list[str], env_extra: dict | None = None, repeat: int = 1,
        code: str | None = None) -> float:
    """Median wall time [s] of ``python -m rollingdisk ARGS`` (or ``python -c CODE``) with
    ``src`` first on the path; raises if the command fails."""
    env = dict(os.environ, PYTHONPATH=str(src), **(env_extra or {}))
    cmd = [sys.executable, "-c", code] if code is not None else \
        [sys.executable, "-m", "rollingdisk", *args]
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        res = subprocess.run(cmd, env=env, capture_output=True, text=True)
        times.append(time.perf_counter() - t0)
        if res.returncode != 0:
            raise RuntimeError(f"{' '.join(cmd)} failed:\n{res.stderr[-2000:]}")
    return statistics.median(times)


HEAVY = ("numba", "scipy", "scipy.integrate", "matplotlib", "sympy")


def heavy_imports(src: Path, args: list[str] | None, code: str | None = None) -> str:
    """``python -X importtime``: the cumulative import time of ``rollingdisk`` and of each
    heavy package the command imports (none, for a command that does not integrate)."""
    env = dict(os.environ, PYTHONPATH=str(src))
    cmd = [sys.executable, "-X", "importtime"] + (
        ["-c", code] if code is not None else ["-m", "rollingdisk", *args])
    res = subprocess.run(cmd, env=env, capture_output=True, text=True)
    cum = {}
    for line in res.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            _, c, name = line.split("|")
            if c.strip().isdigit():
                cum[name.strip()] = int(c) / 1e6
    found = [f"{m} {cum[m]:.2f} s" for m in HEAVY if m in cum]
    own = f"rollingdisk {cum.get('rollingdisk', float('nan')):.3f} s"
    return own + "; heavy: " + (", ".join(found) if found else "none")


def export(ref: str, dest: Path) -> Path | None:
    """The ``src`` folder of commit ``ref`` exported into ``dest``, or None if unknown."""
    arch = subprocess.run(["git", "-C", str(ROOT), "archive", ref, "src"], capture_output=True)
    if arch.returncode != 0:
        return None
    subprocess.run(["tar", "-x", "-C", str(dest)], input=arch.stdout, check=True)
    return dest / "src"


LONG = [*SIMULATE[:-3], "--t-end", "30000", "--json"]


def measure(src: Path, repeat: int, atlas: bool, tmp: Path, long: bool = False
            ) -> dict[str, float]:
    out = {}
    fresh = lambda name: {"NUMBA_CACHE_DIR": str(Path(tempfile.mkdtemp(dir=tmp, prefix=name)))}  # noqa: E731
    warm_cache = fresh("warm")
    out["python + numpy"] = run(src, [], code="import numpy", repeat=repeat)
    out["import rollingdisk"] = run(src, [], code="import rollingdisk", repeat=repeat)
    out["rollingdisk steady"] = run(src, STEADY, repeat=repeat)
    out["first simulate (empty cache)"] = run(src, SIMULATE, env_extra=warm_cache)
    out["simulate T=100 (warm)"] = run(src, SIMULATE, env_extra=warm_cache, repeat=repeat)
    out["simulate T=100 --method scipy"] = run(src, [*SIMULATE, "--method", "scipy"],
                                               repeat=repeat)
    if long:  # a long first run: the background compiler against compiling first
        out["first simulate T=30000 (empty cache)"] = run(src, LONG, env_extra=fresh("long"))
        # a short run fills no cache any more: fill it as a user would, then run warm
        run(src, [], env_extra=warm_cache,
            code="import rollingdisk as r; getattr(r, 'jit_compile', lambda: 0)()")
        out["simulate T=30000 (warm)"] = run(src, LONG, env_extra=warm_cache)
    if atlas:
        adir = tmp / f"atlas-{len(os.listdir(tmp))}"
        cold = {**fresh("cold"), "MPLCONFIGDIR": tempfile.mkdtemp(dir=tmp, prefix="mpl")}
        out["atlas (cold)"] = run(src, ["atlas", "--quiet", "--out", str(adir)], env_extra=cold)
        out["atlas (warm)"] = run(src, ["atlas", "--quiet", "--out", str(adir)],
                                  env_extra=cold, repeat=repeat)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--baseline", default=BASELINE_REF, help="git ref of the baseline tree")
    ap.add_argument("--no-baseline", action="store_true")
    ap.add_argument("--no-atlas", action="store_true")
    ap.add_argument("--long", action="store_true",
                    help="also a long run (T = 30000) with an empty and a warm cache")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as t:
        tmp = Path(t)
        now = measure(ROOT / "src", args.repeat, not args.no_atlas, tmp, args.long)
        before = None
        if not args.no_baseline:
            (tmp / "base").mkdir()
            src = export(args.baseline, tmp / "base")
            if src is None:
                print(f"(baseline {args.baseline} not found in this clone: skipped)")
            else:
                before = measure(src, args.repeat, not args.no_atlas, tmp, args.long)
    w = max(len(k) for k in now)
    head = f"{'command':<{w}}  {'now [s]':>9}"
    if before:
        head += f"  {'baseline [s]':>12}  {'ratio':>6}"
    print(f"wall time of whole processes, median of {args.repeat} (cold runs: once); "
          f"baseline = {args.baseline if before else 'none'}")
    print(head)
    for k, v in now.items():
        line = f"{k:<{w}}  {v:9.3f}"
        if before:
            line += f"  {before[k]:12.3f}  {v / before[k]:6.2f}"
        print(line)
    ratio = now["simulate T=100 (warm)"] / now["simulate T=100 --method scipy"]
    print(f"\nsimulate warm / scipy path (same tree): {ratio:.2f}  (target <= 0.5)")
    print(f"first simulate, empty cache: {now['first simulate (empty cache)']:.2f} s "
          "(target <= 5 s)")
    print("\npython -X importtime (cumulative, this tree):")
    for name, cmd, code in (("import rollingdisk", None, "import rollingdisk"),
                            ("rollingdisk --help", ["--help"], None),
                            ("rollingdisk steady", STEADY, None),
                            ("rollingdisk simulate T=100", SIMULATE, None)):
        print(f"  {name:28s} {heavy_imports(ROOT / 'src', cmd, code)}")
    if "atlas (warm)" in now:
        print(f"atlas: {now['atlas (warm)']:.1f} s warm (target <= 8), "
              f"{now['atlas (cold)']:.1f} s cold (target <= 15)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
