"""
A steady circle and its small oscillations
==========================================

A disk of half-thickness ``h = 0.17`` rolls on a circle of radius ``r_C = 0.5`` at the tilt
``theta0 = 30 deg`` on rough ground (:func:`rollingdisk.steady_motion`, eqs. (26)-(31)).
Section 4 gives the squared frequency ``varpi^2`` of its small oscillations in closed form
(:func:`rollingdisk.stability`); here it is positive, so the circle is stable.

:func:`rollingdisk.simulate_steady` starts the nonlinear equations of motion from the steady
state with a kick ``kappa`` to ``omega1 = d theta/dt``; the tilt then oscillates about
``theta0`` as ``(kappa / varpi) sin(varpi t)`` to first order (eq. 39), while the contact
point keeps tracing the circle of radius ``r_P``. :func:`rollingdisk.compare_with_theory`
measures the frequency of the simulated oscillation and compares it with ``varpi``: the
difference vanishes as the square of the amplitude, the nonlinear frequency shift of an
oscillator.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import rollingdisk as rd

disk = rd.Disk(h=0.17)
m = rd.steady_motion(disk, "rough", theta0=math.radians(30), r_C=0.5)
s = rd.stability(m)
print(f"Omega0 = {m.Omega0:.4f}, omega20 = {m.omega20:.4f}, omega30 = {m.omega30:.4f}, "
      f"r_P = {m.r_P:.4f}")
print(f"varpi^2 = {s.varpi2:.4f} (stable: {s.stable}), period {s.period:.2f}")

kappa = 1e-3
tr = rd.simulate_steady(m, 60.0, kick=kappa)
kicks = np.array([1e-5, 1e-4, 1e-3, 1e-2])
errors = np.array([rd.compare_with_theory(rd.simulate_steady(m, 200.0, kick=k)).rel_error
                   for k in kicks])
for k, e in zip(kicks, errors):
    print(f"kick {k:.0e}: |measured frequency / varpi - 1| = {e:.2e}")

fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(12, 3.8), layout="constrained")
ax1.plot(tr.t, (tr.theta - m.theta0) * s.varpi / kappa, label="simulated")
ax1.plot(tr.t, np.sin(s.varpi * tr.t), "k--", lw=1, label=r"$\sin(\varpi t)$, eq. (39)")
ax1.set_xlabel("t")
ax1.set_ylabel(r"$(\theta - \theta_0)\, \varpi / \kappa$")
ax1.set_title(rf"tilt after a kick $\kappa = {kappa:g}$")
ax1.set_ylim(-1.2, 1.7)
ax1.legend(fontsize=8, loc="upper center", ncol=2)

phi = np.linspace(0, 2 * np.pi, 200)
ax2.plot(tr.X_P, tr.Y_P, lw=2, label="contact point P")
ax2.plot(tr.component("X_C"), tr.component("Y_C"), lw=2, label="centre C")
xc, yc, _ = rd.fit_circle(tr.X_P, tr.Y_P)
for r, style in ((m.r_P, "k--"), (m.r_C, "k:")):
    ax2.plot(xc + r * np.cos(phi), yc + r * np.sin(phi), style, lw=1)
ax2.set_aspect("equal")
ax2.set_title(r"paths, with circles of radii $r_P$, $r_C$")
ax2.legend(fontsize=8, loc="center")

ax3.loglog(kicks / s.varpi, errors, "o-", label="simulated")
ax3.loglog(kicks / s.varpi, errors[1] * (kicks / kicks[1]) ** 2, "k:", label="slope 2")
ax3.legend(fontsize=8)
ax3.set_xlabel(r"amplitude $\kappa / \varpi$ (rad)")
ax3.set_ylabel(r"|measured / $\varpi$ - 1|")
ax3.set_title("frequency error vs amplitude")
plt.show()

# %%
# Checks against independent truths
# ---------------------------------
# * the closed-form ``varpi^2`` equals the one of the numerical linearization;
# * the simulated oscillation has the amplitude ``kappa / varpi`` of the linear theory, and
#   its frequency tends to ``varpi`` as the square of the amplitude;
# * energy (eq. 13) is conserved on rough ground;
# * P and C trace concentric circles of the radii of eqs. (22)-(24).
assert s.stable and abs(s.varpi2 - rd.varpi2_linearized(m)) < 1e-9
assert abs(np.ptp(tr.theta) / 2 / (kappa / s.varpi) - 1) < 1e-3
slope = np.polyfit(np.log(kicks[:3]), np.log(errors[:3]), 1)[0]
assert errors[0] < 1e-7 and abs(slope - 2) < 0.05, (errors, slope)
assert rd.energy_drift(tr) < 1e-12
small = rd.simulate_steady(m, 60.0, kick=1e-7)
xc, yc, r_P = rd.fit_circle(small.X_P, small.Y_P)
_, _, r_C = rd.fit_circle(small.component("X_C"), small.component("Y_C"))
assert abs(r_P - m.r_P) < 1e-5 and abs(r_C - m.r_C) < 1e-5
