"""
A coin's stability thresholds
=============================

How fast must a 1-euro coin roll to stay upright? The coin is 23.25 mm across, 2.33 mm thick
and weighs 7.5 g, so its half-thickness in units of its radius is ``h = 0.100``.
:func:`rollingdisk.thresholds` gives the four critical speeds of the paper, eqs. (42), (43),
(53), (57): above them the steady motion is stable. The left panel shows them against ``h``
with the coin marked; the right one shows, for the coin rolling on a straight line on rough
ground, the squared frequency ``varpi^2`` of its small oscillations against its rolling rate,
taken from the Jacobian of the equations of motion (a numerical linearization, independent of
the closed form): it changes sign at the threshold.
"""

import math

import matplotlib.pyplot as plt
import numpy as np
from scipy.optimize import brentq

import rollingdisk as rd

coin = rd.Disk.from_dimensions(radius=23.25e-3 / 2, thickness=2.33e-3, mass=7.5e-3)
t = rd.thresholds(coin.h)

# the straight-line threshold in SI: omega20 = v_C in units of sqrt(a g) on rough ground
omega_line = math.sqrt(t.rough_straight_line_omega20_sq)
v_line = coin.speed_to_si(omega_line)
print(f"h = {coin.h:.4f}")
print(f"rough ground, straight line: stable above v = {v_line:.4f} m/s "
      f"({coin.angular_speed_to_si(omega_line):.2f} rad/s rolling rate)")
print(f"rough ground, spinning at the SE tilt: above omega3 = "
      f"{coin.angular_speed_to_si(math.sqrt(t.rough_se_circle_omega30_sq)):.2f} rad/s")

# %%
# The thresholds against the thickness, and the coin's straight line

hs = np.linspace(0.0, 1.5, 151)
rows = [rd.thresholds(h) for h in hs]
labels = {
    "rough_straight_line_omega20_sq": r"rough, straight line $\omega_{20}$ (42)",
    "rough_se_circle_omega30_sq": r"rough, SE circle $\omega_{30}$ (43)",
    "smooth_straight_line_omega20_sq": r"smooth, straight line $\omega_{20}$ (53)",
    "smooth_spin_omega30_sq": r"smooth, spin $\omega_{30}$ (57)",
}

omegas = np.linspace(0.2, 1.2, 81)
varpi2 = np.array([rd.varpi2_linearized(rd.straight_line(coin, "rough", w)) for w in omegas])

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4), layout="constrained")
for name, label in labels.items():
    ax1.plot(hs, np.sqrt([getattr(r, name) for r in rows]), label=label)
ax1.axvline(coin.h, color="k", lw=0.8, ls=":")
ax1.annotate("1-euro coin", (coin.h, 1.9), xytext=(0.25, 1.9), arrowprops={"arrowstyle": "->"})
ax1.set_xlabel("half-thickness h (units of the radius)")
ax1.set_ylabel(r"critical speed (units of $\sqrt{g/a}$)")
ax1.set_title("Stable above these speeds")
ax1.legend(fontsize=8)

ax2.plot(omegas, varpi2, color="C0")
ax2.axhline(0.0, color="k", lw=0.8)
ax2.axvline(omega_line, color="C3", ls="--", label=f"eq. (42): {v_line * 100:.1f} cm/s")
ax2.set_xlabel(r"rolling rate $\omega_{20}$ (units of $\sqrt{g/a}$)")
ax2.set_ylabel(r"$\varpi^2$ from the Jacobian")
ax2.set_title("The coin on a straight line, rough ground")
ax2.legend()
plt.show()

# %%
# Checks against independent truths
# ---------------------------------
# * the root of the numerically linearized ``varpi^2`` is the closed-form threshold (42);
# * the thin-disk limit is the classical rolling-coin criterion ``v^2 > g a / 3``;
# * the SI speed is ``omega sqrt(g a)`` with the coin's own radius and standard gravity.
root = brentq(lambda w: rd.varpi2_linearized(rd.straight_line(coin, "rough", w)), 0.2, 1.2,
              xtol=1e-13)
assert abs(root - omega_line) < 1e-7, (root, omega_line)
assert np.all(varpi2[omegas < 0.99 * omega_line] < 0)
assert np.all(varpi2[omegas > 1.01 * omega_line] > 0)
assert abs(rd.thresholds(0.0).rough_straight_line_omega20_sq - 1.0 / 3.0) < 1e-15
assert abs(coin.h - 2.33 / 23.25) < 1e-12
assert abs(v_line - omega_line * math.sqrt(9.80665 * 23.25e-3 / 2)) < 1e-12
assert 0.19 < v_line < 0.21  # about 20 cm/s: a coin rolled slower than this falls over
