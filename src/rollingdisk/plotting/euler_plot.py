"""The plot of Euler's disk run to its end: tilt, precession rate and contact-point speed
against the time to the end, with the fitted and predicted exponents.
"""

from __future__ import annotations

import math

import numpy as np

from rollingdisk.plotting.style import _pyplot

__all__ = ["plot_euler_disk", "euler_disk_title"]


def _thin(n: int, k: int = 3000) -> np.ndarray:
    """At most about ``k`` indices of ``n`` points (evenly, plus the last)."""
    if n <= k:
        return np.arange(n)
    return np.unique(np.append(np.linspace(0, n - 1, k).astype(int), n - 1))


def _label_2_5(x, pos=None) -> str:
    """A minor tick's label on a log axis: ``2 x 10^n`` and ``5 x 10^n`` only."""
    if not x > 0:
        return ""
    e = math.floor(math.log10(x) + 1e-9)
    c = x / 10.0 ** e
    if abs(c - round(c)) > 1e-6 or round(c) not in (2, 5):
        return ""
    return rf"$\mathdefault{{{round(c)}\times10^{{{e}}}}}$"


def _sparse_log_labels(ax) -> None:
    """Minor tick labels on the log axes of ``ax`` that cannot overlap: none where an axis
    shows two powers of ten or more (they are labelled), else at 2 and 5 times a power of
    ten only (matplotlib's default labels 2, 3, 4 and 6 times a power of ten on an axis that
    shows one power of ten, and they collide)."""
    from matplotlib.ticker import FuncFormatter, NullFormatter

    for axis, lim in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        lo, hi = sorted(lim)
        if axis.get_scale() != "log" or not lo > 0:
            continue
        if math.floor(math.log10(hi)) - math.ceil(math.log10(lo)) >= 1:
            axis.set_minor_formatter(NullFormatter())
        else:
            axis.set_minor_formatter(FuncFormatter(_label_2_5))


def euler_disk_title(result) -> str:
    """A figure title for Euler's disk run to its end, in one style: symbols with units,
    SI first, the paper's time unit after (``"Euler's disk: fell flat, α = 0.001 rad at
    t = 100.3 s (1623 √(a/g))"``)."""
    r = result
    words = {"fell-flat": "fell flat", "lift-off": "lifted off",
             "edge-contact": "the other rim edge touched", "at-rest": "came to rest"}
    what = words.get(r.end, r.end) if r.end is not None else f"stopped ({r.status})"
    alpha = float(r.alpha[-1]) if np.size(r.alpha) else float("nan")
    return (f"Euler's disk: {what}, α = {alpha:.3g} rad ({math.degrees(alpha):.3g}°) at "
            f"t = {r.t_end_s:.4g} s ({r.t_end:.4g} √(a/g))")


def plot_euler_disk(result, fig=None, *, title: str | None = None) -> dict:
    """Euler's disk run to its end (:func:`rollingdisk.scenarios.euler_disk.run_euler_disk`).

    ``title``: by default :func:`euler_disk_title`; ``""`` for none.

    Left: the tilt ``alpha``, the precession rate ``Omega`` and the contact-point speed
    against time (seconds), the end marked.  Right: the same against ``t0 - t`` on log-log
    axes (``t0`` the fitted singular time), with the fitted power laws over the fit window
    (solid) and the slopes predicted by the steady family (dashed), exponents in the legend.

    Returns
    -------
    dict
        ``fig``, ``axes`` (the two axes) and ``lines`` (name -> Line2D).
    """
    plt = _pyplot()
    if fig is None:
        fig = plt.figure(figsize=(10.0, 4.2))
    ax1, ax2 = fig.subplots(1, 2)
    r = result
    unit = r.toy.time_unit
    i = _thin(r.t.size)
    t = r.t[i] * unit
    series = (("alpha", r"$\alpha$ [deg]", np.degrees(r.alpha), "C0"),
              ("Omega", r"$\Omega$ [rad/s]", r.Omega / unit, "C1"),
              ("contact_speed", r"$v_P$ [m/s]", r.contact_speed
               * math.sqrt(r.toy.radius * r.toy.gravity), "C2"))
    lines = {}
    for name, label, y, color in series:
        (lines[name],) = ax1.semilogy(t, y[i], color=color, lw=1.2, label=label)
    if r.end is not None:
        ax1.axvline(r.t_end_s, color="0.4", ls=":", lw=1)
        ax1.annotate(f"{r.end}\n{r.t_end_s:.1f} s", (r.t_end_s, 0.5),
                     xycoords=("data", "axes fraction"), ha="right", va="center",
                     fontsize=8, color="0.3")
    ax1.set_xlabel("t [s]")
    ax1.legend(loc="upper left", fontsize=8)
    ax1.set_title("tilt, precession rate, contact-point speed", fontsize=9)
    if math.isfinite(r.t0):
        tau = (r.t0 - r.t) * unit
        ok = tau > 0
        j = np.flatnonzero(ok)[_thin(np.count_nonzero(ok))]
        lo, hi = r.fit_window
        w = (r.alpha > lo) & (r.alpha < hi) & ok
        for name, label, y, color in series:
            ax2.loglog(tau[j], y[j], color=color, lw=1.0, alpha=0.6)
            if np.count_nonzero(w) >= 2:
                tw, yw = tau[w], y[w]
                p, q = r.exponents[name], r.predicted[name]
                ref = np.exp(np.mean(np.log(yw) - p * np.log(tw)))
                tt = np.geomspace(tw.min(), tw.max(), 20)
                (lines[f"{name}_fit"],) = ax2.loglog(
                    tt, ref * tt ** p, color=color, lw=2.4,
                    label=f"{label.split(' ')[0]}: fit {p:.4g}, predicted {q:.4g}")
                if math.isfinite(q):
                    qref = np.exp(np.mean(np.log(yw) - q * np.log(tw)))
                    (lines[f"{name}_predicted"],) = ax2.loglog(
                        tt, qref * tt ** q * 1.6, color=color, lw=1.2, ls="--")
        ax2.set_xlabel(r"$t_0 - t$ [s]  ($t_0$ fitted: " + f"{r.t0_s:.2f} s)")
        ax2.legend(loc="best", fontsize=8, title="exponents (dashed: predicted, offset)",
                   title_fontsize=8)
    else:
        ax2.text(0.5, 0.5, "the fit window was not reached", ha="center",
                 transform=ax2.transAxes)
    ax2.set_title(r"log-log against $t_0 - t$", fontsize=9)
    _sparse_log_labels(ax2)
    title = euler_disk_title(r) if title is None else title
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return {"fig": fig, "axes": (ax1, ax2), "lines": lines}
