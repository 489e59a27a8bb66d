"""Spin-down curves of Euler's disk under several dissipation laws, on one pair of axes.

:func:`plot_spin_down_comparison` draws the tilt ``alpha`` and the whirr's frequency
``Omega / (2 pi)`` against the time left ``t0 - t`` (log-log, ``t0`` each run's fitted
singular time) for runs of :func:`rollingdisk.scenarios.euler_disk.run_euler_disk` (e.g. the
toys of :func:`rollingdisk.scenarios.euler_disk.dissipation_laws`), each law's fitted power
law over its fit window drawn thick, the fitted and predicted exponents in the legend.
matplotlib is imported only when it draws.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["plot_spin_down_comparison"]


def _curves(r):
    """``tau = t0 - t`` [s], ``alpha`` [rad] and ``Omega / 2 pi`` [Hz] where ``tau > 0``,
    thinned evenly in ``log tau`` (the late steps are dense)."""
    unit = r.toy.time_unit
    tau = (r.t0 - r.t) * unit
    ok = np.flatnonzero(tau > 0)
    if ok.size > 1500:
        lt = np.log(tau[ok])
        grid = np.linspace(lt.min(), lt.max(), 1500)
        order = np.argsort(lt)
        pick = order[np.clip(np.searchsorted(lt[order], grid), 0, ok.size - 1)]
        ok = np.unique(ok[pick])
    return tau[ok], r.alpha[ok], r.Omega[ok] / (2.0 * math.pi * unit)


def plot_spin_down_comparison(results, labels=None, fig=None, *,
                              title: str | None = None) -> dict:
    """Spin-down curves, one colour per run: ``alpha`` and ``Omega / (2 pi)`` against ``t0
    - t`` on log-log axes.

    Parameters
    ----------
    results : dict of str to EulerDiskResult, or sequence of EulerDiskResult
        Runs of :func:`rollingdisk.scenarios.euler_disk.run_euler_disk` (a dict: its keys
        are the labels).  A run whose fit window was not reached (``t0`` NaN) is listed in
        the legend as such and not drawn.
    labels : sequence of str, optional
        Labels of a sequence of runs (default "run 1", ...).
    fig : matplotlib Figure, optional
    title : str, optional
        ``""`` for none; by default names the toy.

    Returns
    -------
    dict
        ``fig``, ``axes`` (alpha, frequency) and ``lines``: ``"<label>/alpha"``,
        ``"<label>/Omega"`` (the curves) and ``"<label>/alpha_fit"``, ``"<label>/Omega_fit"``
        (the fitted power laws over the fit window, slopes ``result.exponents``).
    """
    from rollingdisk.plotting.style import _pyplot
    from rollingdisk.scenarios.euler_disk import EulerDiskResult

    if isinstance(results, dict):
        labels, runs = list(results), list(results.values())
    else:
        runs = list(results)
        labels = [f"run {i + 1}" for i in range(len(runs))] if labels is None else list(labels)
    if not runs or len(labels) != len(runs):
        raise ParameterError(f"results: need at least one run and one label per run, got "
                             f"{len(runs)} runs and {len(labels)} labels")
    for r in runs:
        if not isinstance(r, EulerDiskResult):
            raise ParameterTypeError(f"results must be EulerDiskResult objects, got "
                                     f"{type(r).__name__}")
    if fig is None:
        fig = _pyplot().figure(figsize=(11.0, 5.6))
    ax1, ax2 = fig.subplots(1, 2)
    lines = {}
    for k, (label, r) in enumerate(zip(labels, runs)):
        color = f"C{k}"
        if not math.isfinite(r.t0):
            ax1.plot([], [], color=color, label=f"{label}: fit window not reached")
            continue
        tau, alpha, freq = _curves(r)
        lo, hi = r.fit_window
        w = (alpha > lo) & (alpha < hi)
        for ax, name, y, sym in ((ax1, "alpha", alpha, r"$\alpha$"),
                                 (ax2, "Omega", freq, r"$\Omega$")):
            p, q = r.exponents[name], r.predicted[name]
            (lines[f"{label}/{name}"],) = ax.loglog(tau, y, color=color, lw=1.0, alpha=0.55)
            text = f"{label}: {sym} fit {p:+.3f}, predicted {q:+.3f}"
            if np.count_nonzero(w) >= 2:
                tw, yw = tau[w], y[w]
                ref = np.exp(np.mean(np.log(yw) - p * np.log(tw)))
                tt = np.geomspace(tw.min(), tw.max(), 20)
                (lines[f"{label}/{name}_fit"],) = ax.loglog(tt, ref * tt ** p, color=color,
                                                            lw=3.0, label=text)
            else:
                lines[f"{label}/{name}"].set_label(text)
    ax1.set_ylabel(r"tilt $\alpha$ [rad]")
    ax2.set_ylabel(r"whirr frequency $\Omega/2\pi$ [Hz]")
    for ax in (ax1, ax2):  # legends under the axes: the curves fill the axes' corners
        ax.set_xlabel(r"time left $t_0 - t$ [s]  ($t_0$ fitted per run)")
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=7.5,
                  title="exponents against $t_0 - t$ (thick: fit window)", title_fontsize=7.5)
    toy = runs[0].toy
    if title is None:
        title = (f"Euler's disk (a = {toy.radius * 1e3:.4g} mm, m = {toy.mass:.3g} kg, "
                 f"h = {toy.h:.3g}): spin-down under each dissipation law")
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return {"fig": fig, "axes": (ax1, ax2), "lines": lines}
