"""simulate_coulomb: the scipy path against the compiled contact phase
(rollingdisk.ivp.fastsegment), wall seconds, compile excluded (reported apart).

(a) a long rolling/sliding run: Disk(0.1), Coulomb(0.3, rolling resistance 0.002) from a
    tilted rolling circle, kicked into sliding, to t = T;
(b) one coin toss (rollingdisk.scenarios.toss.toss): simulate_to_rest calls simulate_coulomb
    for each contact phase with method="auto", which goes compiled once the compiled loop is
    loaded (the scipy run forces the scipy path by an infinite PY_BUDGET).

(c) with ``--euler``: Euler's disk on Coulomb ground (``euler-disk --friction coulomb``)
    with the quasi-static micro-slip (u_qs = 1e-3); ``--euler-old`` also runs the full law
    e = u/|u| (u_qs = 0: about 75 million steps, several minutes) and reports the ratio.

Run: PYTHONPATH=src python benchmarks/coulomb.py [T] [--euler | --euler-old]
"""

import json
import math
import sys
import time

import rollingdisk as rd
from rollingdisk.ivp import coulomb_driver as cd
from rollingdisk.ivp import fastsegment as fs
from rollingdisk.ivp import hybrid as hy
from rollingdisk.scenarios.toss import toss


def long_run(method, T):
    disk = rd.Disk(0.1)
    m = rd.steady_motion(disk, "rough", 0.4, Omega0=4.0)
    y = rd.rolling_state(disk, m.initial_state())
    y[2] += 0.1
    t = time.perf_counter()
    tr = rd.simulate_coulomb(disk, rd.Coulomb(0.3, rolling_resistance=0.002), (0, T), y,
                             method=method, max_wall_time=1e4, max_steps=10**8)
    return time.perf_counter() - t, tr


def one_toss():
    t = time.perf_counter()
    r = toss(rd.Disk(0.1), 3.0, 2.0, 25.0, tilt=0.3, mu=0.5, early=False, max_wall=1e4)
    return time.perf_counter() - t, r


def euler_toy(u_qs):
    from rollingdisk.scenarios import euler_coulomb as ec
    from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk

    ec.QUASI_STATIC_SLIP = u_qs
    t = time.perf_counter()
    r = run_euler_disk(EulerDisk(friction="coulomb"), predict=False, max_wall_time=1e4,
                       max_steps=10**9)
    return {"u_qs": u_qs, "wall_s": round(time.perf_counter() - t, 2), "t_end": r.t_end,
            "steps": r.n_steps, "transitions": len(r.extra["transitions"]),
            "energy_balance": r.energy_balance}


def euler_main(old):
    fs.compiled()
    runs = [euler_toy(1e-3)] + ([euler_toy(0.0)] if old else [])
    out = {"euler_coulomb": runs}
    if old:
        out["ratio_old_over_new"] = round(runs[1]["wall_s"] / runs[0]["wall_s"], 1)
    print(json.dumps(out, indent=1))


if __name__ == "__main__" and {"--euler", "--euler-old"} & set(sys.argv):
    euler_main("--euler-old" in sys.argv)
elif __name__ == "__main__":
    T = float(sys.argv[1]) if len(sys.argv) > 1 else 200.0
    cd.PY_BUDGET = math.inf  # "auto" stays on the scipy path until fs is loaded
    ws, a = long_run("scipy", T)
    wt_s, ta = one_toss()
    t = time.perf_counter()
    fs.compiled()
    load = time.perf_counter() - t
    wc, b = long_run("dop853", T)
    wt_c, tb = one_toss()
    dt = max((abs(x.t - z.t) for x, z in zip(a.transitions, b.transitions)), default=0.0)
    print(json.dumps({
        "compile_or_load_s": round(load, 2),
        "long_run": {"T": T, "steps": [a.n_steps, b.n_steps], "status": [a.status, b.status],
                     "transitions": [len(a.transitions), len(b.transitions)],
                     "max_dt_transition": dt,
                     "scipy_s": round(ws, 3), "compiled_s": round(wc, 3),
                     "speedup": round(ws / wc, 1),
                     "balance": [hy.energy_balance(a), hy.energy_balance(b)]},
        "toss": {"outcome": [ta.outcome, tb.outcome], "scipy_s": round(wt_s, 3),
                 "compiled_s": round(wt_c, 3), "speedup": round(wt_s / wt_c, 1)},
    }, indent=1))
