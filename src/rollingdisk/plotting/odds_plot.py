"""The edge odds of :func:`rollingdisk.edge_odds` against the thickness, beside the
no-bounce probabilities and the literature's marks.  matplotlib is imported when it draws.
"""

from __future__ import annotations

import numpy as np

from rollingdisk.util.errors import ParameterTypeError

__all__ = ["plot_edge_odds"]


def plot_edge_odds(odds, ax=None, *, title: str | None = None) -> dict:
    """P(edge), P(heads) and P(tails) against ``t/d``, with 95 % Wilson intervals.

    Drawn beside them: the two no-bounce edge probabilities (axis uniform on the sphere,
    tilt uniform; :mod:`rollingdisk.scenarios.odds`), the level 1/3 with the two thicknesses
    where those reach it (Yong & Mahadevan 2011), and Murray & Teare's nickel (``t/d =
    0.092``, about 1 in 6000).  The probability axis is logarithmic, so that a rare edge is
    seen; a frequency of 0 is drawn at its interval's upper bound as a down-pointing mark.

    Parameters
    ----------
    odds : EdgeOdds
        The curve (:func:`rollingdisk.edge_odds`).
    ax : matplotlib Axes, optional
    title : str, optional
        ``""`` for none; by default names the launch and the tosses per ratio.

    Returns
    -------
    dict
        ``fig``, ``ax`` and ``lines`` (``"edge"``, ``"heads"``, ``"tails"``,
        ``"no-bounce sphere"``, ``"no-bounce angle"``).
    """
    from rollingdisk.scenarios.odds import (
        NICKEL_RATIO,
        YM_THIRD_ANGLE,
        YM_THIRD_SPHERE,
        EdgeOdds,
        no_bounce_edge_angle,
        no_bounce_edge_sphere,
    )

    if not isinstance(odds, EdgeOdds):
        raise ParameterTypeError(f"odds must be a rollingdisk EdgeOdds (rollingdisk.edge_odds),"
                                 f" got {type(odds).__name__}")
    import matplotlib.pyplot as plt

    if ax is None:
        fig, ax = plt.subplots(figsize=(7.0, 4.6))
    else:
        fig = ax.figure
    r = np.asarray(odds.ratio, float)
    lines = {}
    for k, color in (("edge", "C3"), ("heads", "C0"), ("tails", "C2")):
        p = odds.probability(k)
        lo, hi = odds.interval(k)
        shown = p > 0
        lines[k] = ax.errorbar(r[shown], p[shown], yerr=[p[shown] - lo[shown],
                                                       hi[shown] - p[shown]],
                               fmt="o-", color=color, ms=4, capsize=2,
                               label=f"P({k}), table toss")
        if np.any(~shown):
            ax.plot(r[~shown], hi[~shown], "v", color=color, ms=5)
    grid = np.linspace(max(min(r.min(), 0.02), 1e-3), max(r.max(), 1.0), 200)
    lines["no-bounce sphere"], = ax.plot(grid, no_bounce_edge_sphere(grid), "--", color="0.4",
                                         label="no bounce, axis uniform on the sphere")
    lines["no-bounce angle"], = ax.plot(grid, no_bounce_edge_angle(grid), ":", color="0.4",
                                        label="no bounce, tilt uniform")
    ax.axhline(1 / 3, color="0.75", lw=0.8)
    for x in (YM_THIRD_SPHERE, YM_THIRD_ANGLE):
        ax.axvline(x, color="0.75", lw=0.8)
    ax.plot([NICKEL_RATIO], [1 / 6000], "*", color="k", ms=9,
            label="Murray & Teare: nickel, 1 in 6000")
    ax.set_yscale("log")
    ax.set_xlabel("thickness / diameter  t/d")
    ax.set_ylabel("probability")
    ax.set_xlim(0.0, grid[-1] * 1.02)
    ax.legend(fontsize=7, loc="lower right")
    if title is None:
        title = f"Edge odds, {odds.n} hand tosses a thickness (e = {odds.e:g}, mu = {odds.mu:g})"
    if title:
        ax.set_title(title, fontsize=9)
    return {"fig": fig, "ax": ax, "lines": lines}
