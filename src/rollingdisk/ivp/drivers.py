"""The two integration drivers behind :func:`rollingdisk.simulate` (private).

:func:`run_compiled` runs the DOP853 of :mod:`rollingdisk.engine.dop853` in chunks of about
``_CHUNK_SECONDS`` of wall time when compiled and of :data:`rollingdisk.engine.jit.PY_CHUNK`
steps when not (the integrator pauses without changing its steps), so that
``progress`` is called, the step budget is kept and ``KeyboardInterrupt`` or ``Terminated``
(SIGTERM) surfaces between chunks.  Each chunk runs compiled
(:mod:`rollingdisk.engine.numba_core`)
or uncompiled (:mod:`rollingdisk.engine.pycore`), as :mod:`rollingdisk.engine.jit` decides
(uncompiled until the work is worth the compiled code, counted in steps, then loaded,
switching between chunks); ``method="taylor"`` and ``"auto"`` run the Taylor
method of :mod:`rollingdisk.engine.taylor` through the same loop.
:func:`run_scipy` steps scipy's own
``DOP853`` one step at a time and does the same in Python.  Both sample the guards of
:mod:`rollingdisk.model.events` on the dense output inside every step (at ``j / 8`` of it) and
locate the first root on the interpolant; the earliest event of a step wins, an edge
contact before a lift-off at the same instant.
"""

from __future__ import annotations

import time

import numpy as np

from rollingdisk.engine import jit as _jit
from rollingdisk.engine.roots import (
    ILLINOIS_MAXITER,
    illinois_converged,
    illinois_trial,
    illinois_update,
)
from rollingdisk.model import events as _ev
from rollingdisk.model.equations import equations_of_motion
from rollingdisk.model.state import state_index

_CHUNK_SECONDS = 0.05
_NSUB = 8  # as _dop853._NSUB


def _marks(t0, t1, progress):
    """Progress marks: the hundredths of t_span (only t1 without progress)."""
    if progress is None:
        return [t1]
    return [t0 + (t1 - t0) * i / 100 for i in range(1, 100)] + [t1]


def _advance(marks, i, t):
    """(next mark index, whether a mark was passed) after reaching time t."""
    j = i
    while j < len(marks) - 1 and marks[j] <= t:
        j += 1
    return j, j > i


def _call(fn, *args):
    """Call compiled code with SIGINT and SIGTERM held back until it returns (a chunk lasts
    about ``_CHUNK_SECONDS``): a signal then surfaces in Python as ``KeyboardInterrupt`` or
    ``Terminated``, never inside numba's dispatcher (which would turn it into a
    ``SystemError``)."""
    import signal
    import threading

    mask = getattr(signal, "pthread_sigmask", None)
    if mask is None or threading.current_thread() is not threading.main_thread():
        return fn(*args)
    held = {signal.SIGINT, signal.SIGTERM}
    old = mask(signal.SIG_BLOCK, held)
    try:
        return fn(*args)
    finally:
        mask(signal.SIG_SETMASK, old)


class _Dop853Dense:
    """The dense output of one DOP853 step (order 7, Hairer's ``contd8``): ``F`` holds the
    interpolation coefficients of :func:`rollingdisk.engine.dop853._dense_coefficients`;
    the polynomial alternates factors ``x`` and ``1 - x``, ``x = (t - t_old) / h``."""

    def __init__(self, t_old, t, y_old, F):
        self.t_old, self.t, self.h, self.y_old, self.F = t_old, t, t - t_old, y_old, F

    def __call__(self, t):
        t = np.asarray(t, dtype=float)
        x = (t - self.t_old) / self.h
        y = np.zeros(x.shape + self.y_old.shape)
        xs = x[..., None] if x.ndim else x
        for i, f in enumerate(self.F[::-1]):
            y += f
            y *= xs if i % 2 == 0 else 1 - xs
        return (y + self.y_old).T


def _dense_solution(segments, t_end):
    from scipy.integrate import OdeSolution

    pieces = [_Dop853Dense(t, t + dt, y, F) for t, dt, y, F in segments]
    if not pieces:
        return None
    ts = np.array([s[0] for s in segments] + [t_end])
    return OdeSolution(ts, pieces)


def run_compiled(disk, ground, y, t0, t1, *, rtol, atol, max_step, first_step, t_eval,
                 dense_output, events, guards, max_steps, progress, out, finish,
                 mode="dop853", taylor_tol=None):
    """rollingdisk's DOP853 and Taylor method, in chunks of about ``_CHUNK_SECONDS``.

    ``mode``: ``"dop853"`` (each chunk compiled or uncompiled as
    :func:`rollingdisk.engine.jit.pick_core` decides), ``"taylor"`` (compiled or loaded
    first, as :func:`jit_compile`) or ``"auto-taylor"`` (DOP853 as ``"dop853"`` while the
    process has no compiled code, the Taylor method at ``taylor_tol = (rtol, atol)`` from
    the chunk on which it has).  The uncompiled steps are counted against the process's
    budget (:func:`rollingdisk.engine.jit.spend`); uncompiled chunks are
    :data:`rollingdisk.engine.jit.PY_CHUNK` steps, so that the boundaries at which the rule
    is applied are the same on every machine.
    """
    from rollingdisk.engine import taylor as _taylor

    rough = ground == "rough"
    use = np.zeros(3, dtype=np.bool_)
    for g in guards:
        use[g.index] = True
    theta0 = y[state_index(ground, "theta")]
    side = 1.0 if theta0 >= 0 else -1.0
    atolv = np.broadcast_to(np.asarray(atol, dtype=float), y.shape).copy()
    if mode == "taylor":
        taylor_tol = (rtol, atol)
        _jit.jit_compile()
    if taylor_tol is not None:
        t_rtol = taylor_tol[0]
        t_atolv = np.broadcast_to(np.asarray(taylor_tol[1], dtype=float), y.shape).copy()
        finite = t_atolv[np.isfinite(t_atolv)]
        order = _taylor.taylor_order(min(t_rtol, float(finite.min()) if finite.size
                                         else t_rtol))
    has_t_eval = t_eval is not None
    te = t_eval if has_t_eval else np.zeros(1)
    marks = _marks(t0, t1, progress)
    i_mark = 0
    start = time.perf_counter()
    n_steps = n_rhs = 0
    h_next = 0.0 if first_step is None else first_step
    tc, yc = t0, y
    chunk = {"compiled": 2000, "uncompiled": _jit.PY_CHUNK,
             "taylor": 2000 if progress is None else 10}
    steps_here = 0  # uncompiled steps of this run (pick_core projects from them)
    later = False
    segments = []
    kinds = []
    while True:
        core, compiled = _jit.pick_core(steps_here, (tc - t0) / (t1 - t0))
        kind = ("taylor" if compiled and taylor_tol is not None
                else "compiled" if compiled else "uncompiled")
        if not kinds or kinds[-1] != kind:
            kinds.append(kind)
        te_c = te[np.searchsorted(te, tc, side="right"):] if later and has_t_eval else te
        t_before = tc
        w = time.perf_counter()
        if kind == "taylor":
            ts_c, ys_c, ns, code, event, tc, yc = _call(
                core._tay_integrate, rough, disk.h, tc, yc, t1, t_rtol, t_atolv, max_step,
                use, side, te_c, has_t_eval, max_steps - n_steps, chunk[kind], order)
            nr = ns  # one series per step
        else:
            args = (rough, disk.h, tc, yc, t1, marks[i_mark], rtol, atolv, max_step, h_next,
                    use, side, te_c, has_t_eval, max_steps - n_steps, chunk[kind],
                    dense_output)
            (ts_c, ys_c, ns, nr, code, event, h_next, tc, yc, st, sdt, sy, sF) = (
                _call(core.integrate, *args) if compiled else core.integrate(*args))
            if dense_output:
                segments.extend(zip(st, sdt, sy, sF))
        w = time.perf_counter() - w
        if not compiled:
            _jit.spend(ns)
            steps_here += ns
        elif ns > 0:  # compiled chunks: aim at _CHUNK_SECONDS per chunk
            chunk[kind] = int(min(max(chunk[kind] * _CHUNK_SECONDS / max(w, 1e-6), 10),
                                  1_000_000))
            if kind == "taylor" and progress is not None and tc > t_before:
                # the Taylor kernel does not pause at the marks: chunks of about a
                # hundredth of the span, so that progress comes as often as with DOP853
                per = ns * (t1 - t0) / (100.0 * (tc - t_before))
                chunk[kind] = max(1, min(chunk[kind], int(per) + 1))
        n_steps += ns
        n_rhs += nr
        # without t_eval a later chunk starts with the previous one's last point
        skip = 1 if later and not has_t_eval else 0
        out.add(ts_c[skip:], ys_c[skip:])
        later = True
        t_now = float(ts_c[-1]) if event >= 0 and len(ts_c) else tc
        i_mark, crossed = _advance(marks, i_mark, tc)
        if progress is not None and (code != _ev.RUNNING or crossed):
            progress(float((t_now - t0) / (t1 - t0)))
        if code != _ev.RUNNING:
            break
    wall = time.perf_counter() - start
    sol = _dense_solution(segments, t_now) if dense_output else None
    method = "+".join(dict.fromkeys("taylor" if k == "taylor" else "dop853" for k in kinds))
    return finish(disk, ground, method, out, code, t_now, n_steps, n_rhs, wall,
                  max_steps, t1, sol=sol)


def run_taylor(disk, ground, y, t0, t1, **options):
    """``simulate(method="taylor")``: the compiled Taylor integrator of
    :mod:`rollingdisk.engine.taylor` (compiled or loaded first, as :func:`jit_compile`),
    run in chunks of about ``_CHUNK_SECONDS`` so that progress and signals come through."""
    return run_compiled(disk, ground, y, t0, t1, mode="taylor", **options)


class _LazyDense:
    """The dense output of the solver's last step, formed on first use."""

    def __init__(self, solver):
        self.solver = solver
        self.dense = None

    def get(self):
        if self.dense is None:
            self.dense = self.solver.dense_output()
        return self.dense

    def __call__(self, t):
        return self.get()(t)


def _needs_sampling(guards, solver, g_old, g_new):
    """The rule of the compiled integrator (:func:`rollingdisk.engine.dop853.needs_sampling`)
    on a scipy step: the guards at its start, at the stage state ``MID_STAGE`` and at its
    end."""
    from rollingdisk.engine import dop853 as d

    k = d.MID_STAGE
    y_mid = solver.y_old + solver.h_previous * (d.STAGE_MATRIX[k, :k] @ solver.K[:k])
    use = np.zeros(3, dtype=bool)
    a, m, b = np.ones(3), np.ones(3), np.ones(3)
    for g, va, vb in zip(guards, g_old, g_new):
        use[g.index], a[g.index], m[g.index], b[g.index] = True, va, g(0.0, y_mid), vb
    return d.needs_sampling(a, m, b, use)


class _Counter:
    def __init__(self, f):
        self.f = f
        self.n = 0

    def __call__(self, t, y):
        self.n += 1
        return self.f(t, y)


def _root(fun, a, b, fa):
    """The admissible end of a bracket [a, b] of a root of fun (fun(a) = fa > 0 >= fun(b)),
    shrunk to round-off by the Illinois variant of regula falsi (:mod:`.roots`)."""
    fb = fun(b)
    flag = 0
    for _ in range(ILLINOIS_MAXITER):
        if illinois_converged(a, b):
            break
        c = illinois_trial(a, b, fa, fb)
        a, b, fa, fb, flag = illinois_update(a, b, fa, fb, c, fun(c), flag)
    return a


def _locate_guards(guards, sol, t_old, t_new, g_old, g_new):
    """(t, guard) of the first guard root in the step, sampled at j/_NSUB of it, or None."""
    order = sorted(guards, key=lambda g: (g.index != 1, g.index))  # edge contact first
    prev_t, prev = t_old, g_old
    for j in range(1, _NSUB + 1):
        t = t_new if j == _NSUB else t_old + (t_new - t_old) * j / _NSUB
        vals = g_new if j == _NSUB else [g(t, sol(t)) for g in guards]
        fired = [g for g in order if vals[guards.index(g)] <= 0.0]
        if fired:
            best = None
            for g in fired:
                fa = prev[guards.index(g)]
                tk = prev_t if not fa > 0 else _root(lambda s, g=g: g(s, sol(s)), prev_t, t,
                                                    fa)
                if best is None or tk < best[0]:
                    best = (tk, g)
            return best
        prev_t, prev = t, vals
    return None


class _UserEvents:
    """The user events of a scipy run, as ``solve_ivp`` treats them: sign changes between
    step ends in the direction asked, located by ``brentq`` on the step's interpolant, and
    the terminal count of each."""

    def __init__(self, events, t0, y):
        self.events = list(events or [])
        self.u_old = [e(t0, y) for e in self.events]
        self.t = [[] for _ in self.events]
        self.y = [[] for _ in self.events]
        self.counts = [0] * len(self.events)

    def step(self, sol, t_old, t_new, y_new, t_stop):
        """Record the events of one step up to ``t_stop``; the first terminal one that
        ends the run, ``(t, k)``, or None."""
        from scipy.optimize import brentq

        u_new = [e(t_new, y_new) for e in self.events]
        stop = None
        for k, e in enumerate(self.events):
            a, b = self.u_old[k], u_new[k]
            d = getattr(e, "direction", 0)
            if (a < 0 <= b or a > 0 >= b) and not (d > 0 and a > b) and not (d < 0 and a < b):
                tr = brentq(lambda s, e=e: e(s, sol(s)), t_old, t_new,
                            xtol=4 * np.finfo(float).eps) if b != 0 else t_new
                if tr > t_stop:
                    continue
                self.t[k].append(tr)
                self.y[k].append(sol(tr))
                self.counts[k] += 1
                term = int(getattr(e, "terminal", False) or 0)
                if term and self.counts[k] >= term and (stop is None or tr < stop[0]):
                    stop = (tr, k)
        self.u_old = u_new
        return stop

    def results(self):
        """``(t_events, y_events)`` as ``solve_ivp`` gives them."""
        return (tuple(np.array(v) for v in self.t),
                tuple(np.array(v).reshape(len(v), -1) for v in self.y))


class _Sampler:
    """Where a scipy run's output goes: every step end, or the points of ``t_eval`` (from
    the interpolant) plus the final state."""

    def __init__(self, out, t_eval, t0, y):
        self.out, self.te, self.ie = out, t_eval, 0
        if t_eval is None:
            out.add([t0], [y])
        else:
            while self.ie < t_eval.size and t_eval[self.ie] <= t0:
                out.add([t0], [y])
                self.ie += 1

    def add(self, t_stop, y_stop, sol, ended):
        te, ie = self.te, self.ie
        if te is None:
            self.out.add([t_stop], [y_stop])
            return
        j = ie
        while j < te.size and te[j] <= t_stop:
            j += 1
        if j > ie:
            self.out.add(te[ie:j], np.array([y_stop if s == t_stop else sol(s)
                                             for s in te[ie:j]]))
        self.ie = j
        if ended and (j == 0 or te[j - 1] != t_stop):
            self.out.add([t_stop], [y_stop])


def _guard_stop(ground, guards, solver, sol, g_old, g_new):
    """The first guard of the step, ``(t, y, code)``, or None; an edge contact reports the
    admissible side of theta = 0, where h~ = h sgn(theta) flips."""
    if not guards or not _needs_sampling(guards, solver, g_old, g_new):
        return None
    hit = _locate_guards(guards, sol, solver.t_old, solver.t, g_old, g_new)
    if hit is None:
        return None
    t_stop, y_stop = hit[0], sol(hit[0])
    if hit[1].code == _ev.EDGE_CONTACT:
        i = state_index(ground, "theta")
        if y_stop[i] * hit[1].side <= 0:
            y_stop = np.array(y_stop)
            y_stop[i] = np.nextafter(0.0, hit[1].side)
    return t_stop, y_stop, hit[1].code


def run_scipy(disk, ground, y, t0, t1, *, rtol, atol, max_step, first_step, t_eval,
              dense_output, events, guards, max_steps, progress, out, finish):
    """``simulate(method="scipy")``: scipy's ``DOP853`` stepped one step at a time, with
    the guards located on each step's interpolant and ``solve_ivp``'s user events."""
    from scipy.integrate import DOP853

    fun = _Counter(equations_of_motion(disk, ground))
    g_old = [g(t0, y) for g in guards]
    sampler = _Sampler(out, t_eval, t0, y)
    for g, v in zip(guards, g_old):
        if g.code != _ev.EDGE_CONTACT and v <= 0.0:
            if t_eval is not None and sampler.ie == 0:
                out.add([t0], [y])
            return finish(disk, ground, "scipy", out, g.code, t0, 0, 0, 0.0, max_steps, t1)
    start = time.perf_counter()
    options = {} if first_step is None else {"first_step": first_step}
    solver = DOP853(fun, t0, y, t1, max_step=max_step, rtol=rtol, atol=atol, **options)
    user = _UserEvents(events, t0, y)
    marks, i_mark = _marks(t0, t1, progress), 0
    n_steps, segments, message, t_now, code = 0, [], None, t0, _ev.RUNNING
    while code == _ev.RUNNING:
        if solver.status == "finished":
            code = _ev.COMPLETED
            break
        if n_steps >= max_steps:
            code = _ev.STEP_BUDGET
            break
        msg = solver.step()
        if solver.status == "failed":
            code, message = _ev.FAILED, f"failed: {msg}"
            break
        n_steps += 1
        sol = _LazyDense(solver)  # 3 right-hand sides, only if the step needs them
        g_new = [g(solver.t, solver.y) for g in guards]
        hit = _guard_stop(ground, guards, solver, sol, g_old, g_new)
        t_stop, y_stop, code = hit if hit is not None else (solver.t, solver.y, code)
        stop_user = user.step(sol, solver.t_old, solver.t, solver.y, t_stop)
        if stop_user is not None and (hit is None or stop_user[0] < t_stop):
            t_stop, y_stop, code = stop_user[0], sol(stop_user[0]), _ev.COMPLETED
            message = f"completed: stopped by user event {stop_user[1]} at t = {t_stop:.12g}"
        if dense_output:
            segments.append((solver.t_old, sol.get()))
        sampler.add(t_stop, y_stop, sol, code != _ev.RUNNING)
        t_now, g_old = t_stop, g_new
        i_mark, crossed = _advance(marks, i_mark, t_now)
        if progress is not None and (code != _ev.RUNNING or crossed
                                     or solver.status == "finished"):
            progress(float((t_now - t0) / (t1 - t0)))
    wall = time.perf_counter() - start
    sol = None
    if dense_output and segments:
        from scipy.integrate import OdeSolution

        sol = OdeSolution(np.array([s[0] for s in segments] + [t_now]),
                          [s[1] for s in segments])
    t_ev, y_ev = user.results()
    return finish(disk, ground, "scipy", out, code, t_now, n_steps, fun.n, wall, max_steps,
                  t1, message=message, sol=sol, t_events=t_ev, y_events=y_ev)
