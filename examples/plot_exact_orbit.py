"""
An exact orbit and its rosette
==============================

On both ideal grounds the disk is integrable: along a motion ``omega2``, ``omega3`` and
``omega1^2`` are functions of the tilt ``theta`` alone, so a motion of any amplitude follows
by quadrature (:mod:`rollingdisk.theory.exact`, ``docs/exact.md``): its turning points, its nutation
period, how far it precesses in one period (``delta_psi``) and the path of the contact point,
a rosette.

Here the steady circle of the README (``h = 0.17``, ``theta0 = 30 deg``, ``r_C = 0.5``, rough
ground) is kicked far beyond the linear range, ``omega1(0) = 0.03``: the tilt swings between
23 and 33 degrees and the period is nearly twice the linear one.
:func:`rollingdisk.plotting.plot_exact` draws ``theta`` over one period, the rosette over
three periods and the backbone curve (frequency against amplitude), which tends to the linear
``varpi`` of eq. (39). The dots are a direct simulation of the same motion, an independent
check of the quadrature.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import rollingdisk as rd
from rollingdisk import plotting
from rollingdisk.theory.exact import backbone, exact_steady

disk = rd.Disk(h=0.17)
m = rd.steady_motion(disk, "rough", theta0=math.radians(30), r_C=0.5)
kick = 0.03
ex = exact_steady(m, kick=kick)
bb = backbone(m, np.geomspace(1e-4, 0.035, 12))
print(f"theta between {ex.theta_min:.4f} and {ex.theta_max:.4f} rad, period {ex.period:.3f} "
      f"(linear: {2 * math.pi / bb.varpi:.3f}), delta_psi {ex.delta_psi:.4f}")

# the same motion simulated over two periods, tightly
T = ex.period
sim = rd.simulate_steady(m, 2 * T, kick=kick, rtol=1e-12, atol=1e-12,
                         t_eval=np.linspace(0, 2 * T, 801))

out = plotting.plot_exact(ex, backbone=bb, n_periods=3)
ax_theta, ax_rosette, _ = out["axes"]
first = sim.t <= T * (1 + 1e-9)
ax_theta.plot(sim.t[first][::8], sim.theta[first][::8], ".", color="tab:orange", ms=4,
              label="simulated")
ax_theta.legend(fontsize="x-small", loc="lower right")
ax_rosette.plot(sim.X_P[first][::4], sim.Y_P[first][::4], ".", color="tab:orange", ms=3)
out["fig"].set_size_inches(12, 4)
out["fig"].tight_layout()
plt.show()

# %%
# Checks against independent truths
# ---------------------------------
# * the simulation follows ``theta(t)`` of the quadrature between its turning points and
#   returns to its initial state after one period, having precessed by ``delta_psi``;
# * the backbone tends to ``varpi`` (eq. 39) at small amplitude;
# * the energy of the quadrature is that of the initial state (eq. 13).
i = np.argmin(np.abs(sim.t - T))  # the sample at T (linspace may put it an ulp below)
assert abs(sim.t[i] - T) < 1e-9 * T
assert np.max(np.abs(sim.theta - ex.theta(sim.t))) < 1e-7
assert ex.theta_min <= sim.theta.min() < ex.theta_min + 1e-3
assert ex.theta_max - 1e-3 < sim.theta.max() <= ex.theta_max
assert abs(sim.theta[i] - sim.theta[0]) < 1e-8
assert abs(sim.component("omega1")[i] - kick) < 1e-8
assert abs(sim.component("psi")[i] - sim.component("psi")[0] - ex.delta_psi) < 1e-7
assert ex.status == "bounded"
assert abs(bb.frequency[0] / bb.varpi - 1) < 1e-5
assert abs(ex.E - rd.energy(disk, "rough", sim.y[:, 0])) < 1e-12
