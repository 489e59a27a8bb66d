"""Benchmark: a loop of medium runs in one process, from a cold and from a warm compile cache.

The job (issue 23): ``rd.simulate(Disk(h=0.37), "rough", (0, T), y0)`` with default options
(``method="auto"``, rtol 1e-11, atol 1e-12), ``y0`` the steady circle theta0 = 0.3,
Omega0 = 3 with theta(0) perturbed by 1e-4; ``--runs`` (100) consecutive runs in one fresh
process, for T = 1000 and T = 300.  Each process is started with

* a cold cache: ``NUMBA_CACHE_DIR`` a new empty folder (the first runs go uncompiled; the
  background compiler is started once the process has spent ``PY_BUDGET`` uncompiled);
* a warm cache: ``NUMBA_CACHE_DIR`` a folder filled beforehand by ``jit_compile()`` in
  another process.

Each run is timed from outside (``time.perf_counter`` around ``simulate``: loading, and
waiting if any, included).  After the loop the process calls ``jit_compile()`` and times
the same run ``--runs-compiled`` times: the compiled time, against which the loop is
compared; with ``--per-run`` also a warm process under the rule before issue 23 (the
uncompiled seconds counted per run: the counter reset before each), labelled ``old``.
Printed: the first run, the second, the mean and median of runs 2..N, the mean
of all N, the compiled median, the ratio mean(2..N) / compiled, and which methods ran.

``--tol 1e-10`` gives the issue's own example (0.3 s per run uncompiled at T = 1000, so
that no single run reaches the budget).

Run:  python benchmarks/medium_runs.py [--runs 100] [--T 1000 300] [--tol 1e-10] [--no-cold]
      [--per-run]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

CHILD = r"""
import json, sys, time
import numpy as np
import rollingdisk as rd

T, runs, runs_c = float(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
opts = json.loads(sys.argv[4])
per_run = sys.argv[5] == "per-run"
from rollingdisk.engine import jit
disk = rd.Disk(h=0.37)
m = rd.steady_motion(disk, "rough", 0.3, Omega0=3.0)
y0 = np.array(m.initial_state(0.0, 0.0), dtype=float)
y0[3] += 1e-4
walls, methods = [], []
for _ in range(runs):
    if per_run:
        jit._py_steps = 0  # a budget per run (the rule that the total replaced)
    t = time.perf_counter()
    tr = rd.simulate(disk, "rough", (0.0, T), y0, **opts)
    walls.append(time.perf_counter() - t)
    methods.append(tr.method)
    assert tr.status == "completed", tr.message
rd.jit_compile()
comp = []
for _ in range(runs_c):
    t = time.perf_counter()
    tr = rd.simulate(disk, "rough", (0.0, T), y0, **opts)
    comp.append(time.perf_counter() - t)
print(json.dumps({"walls": walls, "methods": methods, "compiled": comp,
                  "compiled_method": tr.method}))
"""


def child(T, runs, runs_c, cache, opts, rule="total"):
    env = dict(os.environ, NUMBA_CACHE_DIR=cache)
    src = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "src")
    env["PYTHONPATH"] = src + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    t = time.perf_counter()
    out = subprocess.run([sys.executable, "-c", CHILD, str(T), str(runs), str(runs_c),
                          json.dumps(opts), rule],
                         env=env, capture_output=True, text=True, check=True)
    res = json.loads(out.stdout.strip().splitlines()[-1])
    res["process"] = time.perf_counter() - t
    return res


def report(label, T, res):
    w = res["walls"]
    comp = statistics.median(res["compiled"])
    rest = w[1:]
    mean_rest = statistics.fmean(rest)
    counts = {}
    for m in res["methods"]:
        counts[m] = counts.get(m, 0) + 1
    first_taylor = next((i + 1 for i, m in enumerate(res["methods"]) if m == "taylor"), None)
    print(f"{label:5s} T={T:<5g} first {w[0]:7.3f}  second {w[1]:7.3f}  "
          f"mean(2..{len(w)}) {mean_rest:8.4f}  median(2..) {statistics.median(rest):8.4f}  "
          f"mean(all) {statistics.fmean(w):8.4f}  compiled {comp:8.4f}  "
          f"ratio mean(2..)/compiled {mean_rest / comp:6.2f}  "
          f"slowest(2..) {max(rest):7.3f}  "
          f"(loop {sum(w):.2f} s against {len(w) * comp:.2f} s compiled)")
    print(f"      methods: {counts}; all-compiled (taylor) from run {first_taylor}; "
          f"compiled runs: {res['compiled_method']}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=100)
    ap.add_argument("--runs-compiled", type=int, default=20)
    ap.add_argument("--T", type=float, nargs="+", default=[1000.0, 300.0])
    ap.add_argument("--no-cold", action="store_true", help="only the warm cache")
    ap.add_argument("--per-run", action="store_true",
                    help="also the rule before issue 23 (the budget counted per run), warm")
    ap.add_argument("--tol", type=float, default=None,
                    help="rtol = atol (default: simulate's defaults, 1e-11 and 1e-12)")
    args = ap.parse_args(argv)
    opts = {} if args.tol is None else {"rtol": args.tol, "atol": args.tol}
    print(f"job: Disk(h=0.37), rough, steady circle theta0 = 0.3, Omega0 = 3, theta(0) + 1e-4,"
          f" {args.runs} runs per process, options {opts or 'default'}")
    with tempfile.TemporaryDirectory() as warm:
        env = dict(os.environ, NUMBA_CACHE_DIR=warm)
        src = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "src")
        env["PYTHONPATH"] = src
        t = time.perf_counter()
        subprocess.run([sys.executable, "-c", "import rollingdisk as rd; rd.jit_compile()"],
                       env=env, check=True)
        print(f"filled the warm cache in {time.perf_counter() - t:.1f} s (a cold compile)")
        for T in args.T:
            if not args.no_cold:
                with tempfile.TemporaryDirectory() as cold:
                    report("cold", T, child(T, args.runs, args.runs_compiled, cold, opts))
                    time.sleep(0.5)
                    # the background compiler, if still at work, ends with the folder
            report("warm", T, child(T, args.runs, args.runs_compiled, warm, opts))
            if args.per_run:
                report("old", T, child(T, args.runs, args.runs_compiled, warm, opts,
                                       "per-run"))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
