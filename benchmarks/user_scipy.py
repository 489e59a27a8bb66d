"""The baseline of benchmarks/startup.py: the script a user writes for the motion of
``rollingdisk simulate --h 0.17 --theta0 0.5 --Omega0 1.7 --perturb 1e-4 --t-end 100 --json``
with scipy alone: the steady circle's start (rollingdisk.steady_motion), theta(0) + 1e-4,
``scipy.integrate.solve_ivp(method="DOP853")`` on the numpy right-hand side
(rollingdisk.equations_of_motion) at simulate's default tolerances (rtol 1e-11, atol 1e-12),
and a JSON line with the steps, the energy drift and the largest tilt.

Run:  python benchmarks/user_scipy.py
"""

import json

import numpy as np
from scipy.integrate import solve_ivp

import rollingdisk as rd

disk = rd.Disk(h=0.17)
motion = rd.steady_motion(disk, "rough", 0.5, Omega0=1.7)
y0 = np.array(motion.initial_state(), dtype=float)
y0[3] += 1e-4  # theta
sol = solve_ivp(rd.equations_of_motion(disk, "rough"), (0.0, 100.0), y0, method="DOP853",
                rtol=1e-11, atol=1e-12)
E = rd.energy(disk, "rough", sol.y)
print(json.dumps({"status": "completed" if sol.success else "failed",
                  "n_steps": int(sol.t.size - 1), "n_rhs": int(sol.nfev),
                  "energy_drift": float(np.max(np.abs(E - E[0])) / abs(E[0])),
                  "theta_max": float(sol.y[3].max())}))
