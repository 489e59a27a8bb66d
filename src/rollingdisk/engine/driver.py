"""The driver of the engine's contract: integrate a :class:`~rollingdisk.engine.contract.Model`.

:func:`solve` checks its arguments, runs the one DOP853 step loop
(:func:`rollingdisk.engine.steploop.integrate`) uncompiled or compiled
(:mod:`rollingdisk.engine.steploop_numba`) as the caller asks, evaluates the model's
energy at every event and returns a frozen :class:`~rollingdisk.engine.contract.Solution`
(scipy's ``solve_ivp`` in spirit: one driver, a written contract for what it drives).
The caller chooses the path with ``compiled=``: the engine's policy of when compiled code
pays (:mod:`rollingdisk.engine.jit`) belongs to the disk's drivers, which know their run
lengths.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.engine.contract import Model, Solution
from rollingdisk.engine.steploop import integrate
from rollingdisk.model.outcomes import COMPLETED, FAILED, STEP_BUDGET, outcome
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["solve"]


def solve(model: Model, t_span, y0, p=(), *, rtol: float = 1e-10, atol=1e-12,
          max_step: float = np.inf, first_step: float = 0.0, max_steps: int = 100_000,
          compiled: bool = False) -> Solution:
    """Integrate ``model`` over ``t_span`` from ``y0`` with DOP853 and its events.

    Parameters
    ----------
    model : Model
        The model (:class:`rollingdisk.engine.contract.Model`).
    t_span : (float, float)
        Start and end time ``(t0, t_end)``, ``t_end > t0``, in the model's time unit.
    y0 : array_like, shape (n,)
        Initial state, in the layout ``model.state``.
    p : array_like, shape (n_p,)
        The model's parameters, handed to each of its functions (copied: the caller's
        array is never changed).
    rtol : float
        Relative tolerance, in ``[1e-15, 1)``.
    atol : float or array_like, shape (n,)
        Absolute tolerance, per component or for all, ``> 0`` (``inf``: not controlled).
    max_step : float
        Largest step, ``> 0``.
    first_step : float
        First step to try; ``0``: scipy's initial step.
    max_steps : int
        Accepted steps at most (status ``step-budget`` when spent).
    compiled : bool
        Run the step loop compiled with numba (:mod:`rollingdisk.engine.steploop_numba`;
        the model's functions are compiled too) or as plain Python.  The two take the same
        steps; their results agree to round-off.

    Returns
    -------
    Solution
        Output points, events, status and counts.

    Raises
    ------
    ParameterError, ParameterTypeError
        On an argument out of range or of the wrong type (the message names it).
    """
    if not isinstance(model, Model):
        raise ParameterTypeError(f"model: a rollingdisk.engine.contract.Model, got "
                                 f"{type(model).__name__}")
    try:
        t0, t_end = (float(v) for v in t_span)
    except (TypeError, ValueError):
        raise ParameterTypeError(f"t_span: two times (t0, t_end), got {t_span!r}") from None
    t0 = check_real("t_span[0]", t0)
    t_end = check_real("t_span[1]", t_end, low=t0, low_open=True)
    y = np.array(y0, dtype=float).reshape(-1)
    if y.shape != (model.n_state,) or not np.all(np.isfinite(y)):
        raise ParameterError(f"y0: {model.n_state} finite numbers ({model.state}), got "
                             f"{np.asarray(y0)!r}")
    pv = np.ascontiguousarray(np.array(p, dtype=float).reshape(-1))
    rtol = check_real("rtol", rtol, low=1e-15, high=1.0, high_open=True)
    atolv = np.ascontiguousarray(np.broadcast_to(np.array(atol, dtype=float),
                                                 (model.n_state,)).copy())
    if not np.all(atolv > 0.0):
        raise ParameterError(f"atol: > 0 (inf: not controlled), got {atol!r}")
    max_step = check_real("max_step", max_step, low=0.0, low_open=True) \
        if max_step != np.inf else np.inf
    first_step = check_real("first_step", first_step, low=0.0)
    max_steps = check_int("max_steps", max_steps, low=1)
    args = (pv, t0, y, t_end, rtol, atolv, max_step, first_step, max_steps,
            model.direction_array(), model.action_array())
    if compiled:
        from rollingdisk.engine import steploop_numba

        loop = steploop_numba.loop()
        funcs = steploop_numba.model_functions(model)
    else:
        loop = integrate
        funcs = (model.rhs, model.events, model.impact)
    with np.errstate(all="ignore"):  # IEEE arithmetic, as compiled (numpy's error model)
        ts, ys, ev_t, ev_k, ev_y, ev_yp, status, end_event, n_steps, n_rhs = loop(*funcs,
                                                                                  *args)
    e_before = np.full(ev_t.shape[0], np.nan)
    e_after = np.full(ev_t.shape[0], np.nan)
    if model.energy is not None:
        for i in range(ev_t.shape[0]):
            e_before[i] = model.energy(ev_t[i], ev_y[i], pv)
            e_after[i] = model.energy(ev_t[i], ev_yp[i], pv)
    t_last = float(ts[-1])
    return Solution(t=ts.copy(), y=ys.copy(), event_t=ev_t.copy(), event_index=ev_k.copy(),
                    event_y=ev_y.copy(), event_y_after=ev_yp.copy(), energy_before=e_before,
                    energy_after=e_after, status=outcome(int(status)).name,
                    message=_message(model, int(status), int(end_event), t_last, max_steps),
                    n_steps=int(n_steps), n_rhs=int(n_rhs), compiled=bool(compiled))


def _message(model, status, end_event, t_last, max_steps):
    """Why the run ended, in words."""
    where = f"at t = {t_last!r}"
    if end_event >= 0:
        name = model.event_names[end_event]
        if status == COMPLETED:
            return f"terminal event {name!r} {where}"
        return f"the impact map of event {name!r} ended the run {where} " \
            f"({outcome(status).name})"
    if status == COMPLETED:
        return f"reached the end time {where}"
    if status == STEP_BUDGET:
        return f"max_steps = {max_steps} steps spent {where}"
    if status == FAILED:
        return f"the step size fell below round-off (or came out 0) {where}"
    return f"{outcome(status).name} {where}"
