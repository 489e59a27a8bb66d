"""Sweep throughput (issue 12): trajectories per second per core, in one run.

Job: perturbed steady circles on rough ground, h = 0.17, theta0 in [0.3, 1.2], omega30 in
[2, 6] (stable and unstable), kick 1e-3 in omega1, T = 100, rtol = atol = 1e-9.

Prints: the sweep on one thread (the batch Taylor kernel in vector lanes, the default, and
the batch DOP853 kernel, ``method="dop853"``); the lanes against the same Taylor kernel one
trajectory at a time (the kernel before the lanes), on the same inputs; a baseline loop
over scipy.integrate.solve_ivp (DOP853, same tolerances) on the numpy right-hand side
rollingdisk.equations_of_motion; the multi-core speed-up; Dask (LocalCluster, one
single-threaded worker process per core) against the plain multi-core run; heyoka's batch
(SIMD) mode on the same job where heyoka is installed.  Timings on a shared machine are
noisy: run it alone for figures to quote.

Writes the figures as JSON to ``--json`` (default ``benchmarks/results/sweep.json``, ignored
by git).

Run: PYTHONPATH=src python benchmarks/sweep.py [N] [--json PATH]   (N = 16384 by default:
with few trajectories Dask's fixed cost per run dominates)
"""

import argparse
import json
import math
import os
import time
from pathlib import Path

import numpy as np

import rollingdisk as rd
from rollingdisk.sweep.runner import Perturbation, SweepGrid, run_sweep

H, T, TOL, KICK = 0.17, 100.0, 1e-9, 1e-3


def grid(n):
    m = max(2, int(math.sqrt(n)))
    return SweepGrid("rough", h=H, theta0=np.linspace(0.3, 1.2, m),
                     omega30=np.linspace(2.0, 6.0, m))


def timed(f):
    t = time.perf_counter()
    r = f()
    return r, time.perf_counter() - t


def scipy_baseline(g, k):
    from scipy.integrate import solve_ivp

    disk = rd.Disk(H)
    f = rd.equations_of_motion(disk, "rough")
    pts = [(th, w) for th in g.theta0 for w in g.omega30][:k]
    t = time.perf_counter()
    for th, w in pts:
        m = rd.steady_motion(disk, "rough", th, Omega0=w / math.cos(th))
        y0 = m.initial_state()
        y0[5] = KICK  # omega1
        solve_ivp(f, (0, T), y0, method="DOP853", rtol=TOL, atol=TOL)
    return len(pts) / (time.perf_counter() - t)


def heyoka_batch(g, k):
    """heyoka's Taylor integrator in batch (SIMD) mode on the same reduced system: eq. (38)
    from the library's own kernel, its code re-bound to heyoka's sin/cos (theta > 0 here,
    so sign(theta) = 1).  Returns (a function that runs the job once and returns its
    trajectories/s, a label), or (None, why not)."""
    try:
        import heyoka as hy
    except ImportError:
        return None, "not installed"
    import types

    from rollingdisk.model import equations as eq

    class _np:
        sin = staticmethod(hy.sin)
        cos = staticmethod(hy.cos)

        @staticmethod
        def sign(x):
            return 1.0

        @staticmethod
        def real(x):
            return x

    ns = dict(eq.__dict__, np=_np)
    for name in ("_geometry", "_rough_omega_dot"):
        f = eq.__dict__[name]
        ns[name] = types.FunctionType(f.__code__, ns, name)
    th, w1, w2, w3 = hy.make_vars("th", "w1", "w2", "w3")
    d1, d2, d3 = ns["_rough_omega_dot"](H, th, w1, w2, w3)
    sys_ = [(th, w1), (w1, d1), (w2, d2), (w3, d3)]
    B = hy.recommended_simd_size()
    disk = rd.Disk(H)
    pts = [(th_, w) for th_ in g.theta0 for w in g.omega30][:k]
    states = []
    for th_, w in pts:
        m = rd.steady_motion(disk, "rough", th_, Omega0=w / math.cos(th_))
        states.append((th_, KICK, m.omega20, m.omega30))
    states = np.array(states)
    nb = len(states) // B
    ta = hy.taylor_adaptive_batch(sys_, np.ascontiguousarray(states[:B].T), tol=TOL)

    def run():
        t = time.perf_counter()
        for i in range(nb):
            ta.set_time(0.0)
            ta.state[:] = states[i * B:(i + 1) * B].T
            ta.propagate_until(T)
        return nb * B / (time.perf_counter() - t)

    return run, f"heyoka {hy.__version__}, SIMD width {B}"


def lanes_vs_scalar(g, pert, other=None, repeat=3):
    """Trajectories/s of the batch Taylor kernel in lanes and one at a time, on the inputs
    the sweep hands its kernel (both compiled and warm), whether their verdicts agree, and
    the best rate of ``other()`` (heyoka), the lanes and ``other`` each the best of
    ``repeat`` runs taken in turn (a neighbour's load on a shared machine then weighs on
    both sides of their ratio)."""
    from rollingdisk.engine.taylor import taylor_order
    from rollingdisk.sweep import batch, executors
    from rollingdisk.sweep.grid import _Spec

    n = int(np.prod(g.shape))
    spec = _Spec(g, pert, T, TOL, TOL, 1_000_000, n, n)
    args = executors.kernel_args(spec)[1]
    P = taylor_order(TOL)
    small = tuple(x[:16] if isinstance(x, np.ndarray) else x for x in args)
    tb = math.inf
    ro = 0.0
    with batch.threads(1):
        batch.run_batch_taylor(*small, P)  # load both from the cache first
        batch.run_batch_lanes(*small, P)
        a, ta = timed(lambda: batch.run_batch_taylor(*args, P))
        for _ in range(repeat):
            b, t = timed(lambda: batch.run_batch_lanes(*args, P))
            tb = min(tb, t)
            if other is not None:
                ro = max(ro, other())
    same = np.array_equal(a[:, 0], b[:, 0])
    m = len(args[4])
    return m / ta, m / tb, same, ro


def _warm_worker():
    """Load the compiled kernels in a Dask worker (from numba's cache)."""
    run_sweep(grid(16), 1.0, perturbation=Perturbation(kick=KICK))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("n", nargs="?", type=int, default=16384)
    ap.add_argument("--json", type=Path, default=Path(__file__).resolve().parent / "results" /
                    "sweep.json")
    args = ap.parse_args()
    n = args.n
    fig = {"benchmark": "sweep", "cpus": os.cpu_count(), "t_end": T, "tol": TOL}
    g = grid(n)
    pert = Perturbation(kick=KICK)
    ncores = os.cpu_count() or 1
    run_sweep(grid(16), 1.0, perturbation=pert)  # compile
    kw = dict(perturbation=pert, rtol=TOL, atol=TOL, chunk=1024)
    ds1, t1 = timed(lambda: run_sweep(g, T, executor="serial", **kw))
    n = ds1.varpi2.size
    r1 = n / t1
    run_sweep(grid(16), 1.0, perturbation=pert, method="dop853")  # compile
    dsd8, t8 = timed(lambda: run_sweep(g, T, executor="serial", method="dop853", **kw))
    r8 = n / t8
    same = all(np.array_equal(ds1[k].values, dsd8[k].values) for k in ("status",
                                                                       "stable_simulated"))
    dsm, tm = timed(lambda: run_sweep(g, T, executor="threads", workers=ncores, **kw))
    rm = n / tm
    fig.update(n=n, sweep_per_s_1_thread=r1, dop853_per_s_1_thread=r8, threads_per_s=rm,
               same_verdicts_dop853=bool(same))
    print(f"trajectories: {n}, T = {T}, rtol = atol = {TOL}, cores: {ncores}")
    print(f"sweep, 1 thread:          {r1:9.0f} traj/s/core  (Taylor, "
          f"{np.nanmean(ds1.n_steps.values):.0f} steps/trajectory)")
    print(f"  method='dop853':        {r8:9.0f} traj/s/core  (Taylor is {r1 / r8:.2f}x; "
          f"{np.nanmean(dsd8.n_steps.values):.0f} steps; same status/stability: {same})")
    rs = scipy_baseline(g, 40)
    fig.update(scipy_per_s=rs, sweep_over_scipy=r1 / rs)
    print(f"scipy solve_ivp baseline: {rs:9.1f} traj/s/core  (sweep is {r1 / rs:.0f}x)")
    print(f"sweep, {ncores} threads:         {rm:9.0f} traj/s  speed-up {rm / r1:.2f}x"
          f" (identical: {all((ds1[k].values.tobytes() == dsm[k].values.tobytes()) for k in ds1)})")
    try:
        from dask.distributed import Client, LocalCluster

        with LocalCluster(n_workers=ncores, threads_per_worker=1, dashboard_address=None) as c:
            with Client(c) as cl:
                # every worker loads the compiled kernels before the clock starts (a
                # warm-up sweep of one task would warm one worker only)
                cl.run(_warm_worker)
                addr = c.scheduler_address
                dsd, td = timed(lambda: run_sweep(g, T, executor="dask", dask_address=addr,
                                                  **kw))
        rd_ = n / td
        fig.update(dask_per_s=rd_, dask_over_threads=rd_ / rm)
        same = all(ds1[k].values.tobytes() == dsd[k].values.tobytes() for k in ds1)
        print(f"dask, {ncores} workers:          {rd_:9.0f} traj/s  efficiency vs threads "
              f"{rd_ / rm:.0%} (identical: {same})")
    except ImportError:
        print("dask: not installed")
    from rollingdisk.engine.lanes import LANES

    run_heyoka, note = heyoka_batch(g, n)
    rsc, rln, same, rh = lanes_vs_scalar(g, pert, run_heyoka)
    fig.update(lanes_per_s=rln, scalar_per_s=rsc, lanes_same_verdicts=bool(same),
               heyoka_batch_per_s=rh or None,
               lanes_over_heyoka=rln / rh if rh else None, heyoka=note)
    print(f"kernel alone, 1 thread:   {rln:9.0f} traj/s/core in {LANES} "
          f"lanes, {rsc:.0f} one at a time ({rln / rsc:.2f}x; same verdicts: {same})")
    if run_heyoka is None:
        print(f"heyoka batch mode: {note}")
    else:
        print(f"heyoka batch mode:        {rh:9.0f} traj/s/core ({note}; best of 3, in turn "
              f"with the lanes kernel)  lanes kernel/heyoka {rln / rh:.2f}, "
              f"sweep/heyoka {r1 / rh:.2f}")
    args.json.parent.mkdir(parents=True, exist_ok=True)
    args.json.write_text(json.dumps(fig, indent=2) + "\n")
    print(f"wrote {args.json}")


if __name__ == "__main__":
    main()
