"""
Euler's disk to its end
=======================

The commercial toy (a steel disk 75 mm across and 12.7 mm thick, ``h = 0.169``) is spun up on
its spin-in-place steady motion at a steep tilt and left to itself on a table
(:func:`rollingdisk.scenarios.euler_disk.run_euler_disk`: creep friction, rolling resistance, LSODA
to the end). It loses energy slowly, so it creeps down the family of steady motions: the
tilt ``alpha = pi/2 - |theta|`` falls, the precession rate ``Omega`` and the speed of the
contact point grow, and near the end all three follow power laws of ``t0 - t``.
:func:`rollingdisk.plotting.plot_euler_disk` shows the run against time and on log-log axes,
with the exponents fitted to the simulation and those predicted by the adiabatic decay along
the steady family.
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import rollingdisk as rd
from rollingdisk import plotting
from rollingdisk.scenarios.euler_disk import run_euler_disk

result = run_euler_disk()
disk = result.toy.disk
print(f"{result.status}: {result.end} at t = {result.t_end_s:.1f} s "
      f"({result.n_steps} steps, energy balance {result.energy_balance:.1e})")
for name in result.exponents:
    print(f"{name:>14}: fitted {result.exponents[name]:+.4f}, "
          f"predicted {result.predicted[name]:+.4f}")

plotting.plot_euler_disk(result)
plt.show()

# %%
# Checks against independent truths
# ---------------------------------
# * energy plus what friction dissipated stays constant (eq. 12);
# * along the run the precession rate is that of the steady spin in place at the same tilt
#   (``r_C = 0`` in eq. 31), ever closer as the decay slows relative to the motion;
# * the exponents fitted to the simulation are those of the decay along the steady family.
assert result.status == "completed" and result.end == "fell-flat"
assert result.energy_balance < 1e-8
gaps = []
for alpha in (0.05, 0.01, 0.003):
    i = int(np.argmin(np.abs(result.alpha - alpha)))
    steady = rd.steady_motion(disk, "rough", theta0=math.pi / 2 - result.alpha[i], r_C=0.0)
    gaps.append(abs(result.Omega[i] / abs(steady.Omega0) - 1))
print("Omega / steady Omega0 - 1 at alpha = 0.05, 0.01, 0.003:", np.round(gaps, 5))
assert gaps[0] < 5e-3 and gaps[-1] < 1e-3 and gaps[0] > gaps[1] > gaps[2]
for name in result.exponents:
    assert abs(result.exponents[name] - result.predicted[name]) < 5e-3, name
