"""
A small sweep and its basin map
===============================

:mod:`rollingdisk.sweep` runs many simulations at once and returns one ``xarray.Dataset``.
Here: the steady circles of the disk ``h = 0.17`` on rough ground over a 16 x 16 grid of tilt
``theta0`` and spin ``omega30``, each kicked (``omega1(0) = 1e-3``) and simulated for 100 time
units with the batch Taylor kernel. Left: where the simulated motion stays bounded
(``stable_simulated``), with the closed-form boundary ``varpi^2 = 0`` of section 4 drawn over
it. Right: the basin size, the largest kick each circle survives
(:func:`rollingdisk.sweep.basin_sweep`, bisection over ``[0, 1]``).

The grid is kept small so that the example runs in a few seconds (the first run also compiles
the kernel with numba and caches it); ``rollingdisk sweep`` and ``rollingdisk map --kind
basin`` run the same at any size, on every core or a Dask cluster (``docs/sweeps.md``).
"""

import matplotlib.pyplot as plt
import numpy as np

from rollingdisk import plotting
from rollingdisk.sweep import Perturbation, SweepGrid, basin_sweep, run_sweep

grid = SweepGrid("rough", h=0.17, theta0=np.linspace(0.1, 1.3, 16),
                 omega30=np.linspace(0.1, 2.0, 16))
ds = run_sweep(grid, 100.0, perturbation=Perturbation(kick=1e-3))
basin = basin_sweep(grid, 100.0, kick_max=1.0, rounds=6)

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
plotting.plot_nonlinear_map(ds, ax=ax1)
plotting.plot_basin_map(basin, ax=ax2)
plt.show()

# %%
# Checks against independent truths
# ---------------------------------
# * wherever the closed-form ``varpi^2`` is clearly away from zero (``|varpi^2| > 0.05``),
#   the simulated motion is bounded exactly where ``varpi^2 > 0``;
# * the circles that the closed form calls unstable survive no kick, the clearly stable ones
#   (``varpi^2 > 0.5``) a finite one, larger than the bisection's resolution ``2^-6``;
# * energy (eq. 13) is conserved along every completed run.
varpi2 = ds.varpi2.values.ravel()
simulated = ds.stable_simulated.values.ravel()
exists = ds.stable.values.ravel() >= 0
clear = exists & (np.abs(varpi2) > 0.05)
agree = np.mean(simulated[clear] == (varpi2[clear] > 0))
print(f"{clear.sum()} clear points, simulated stability agrees with varpi^2 at {agree:.1%}")
assert clear.sum() > 150 and agree == 1.0

kb = basin.kick_basin.values.ravel()
v2 = basin.varpi2.values.ravel()
assert np.all(kb[v2 < -0.05] == 0.0)
assert np.all(kb[v2 > 0.5] > 0.0)  # weaker ones may have basins below 1/2^6
done = ds.status.values.ravel() == 1
assert np.all(ds.energy_drift.values.ravel()[done] < 1e-8)
