"""
Friction and sliding
====================

On real ground the disk rolls only while the friction it needs lies inside Coulomb's cone,
``|F_t| <= mu_s F_z``. :func:`rollingdisk.simulate_coulomb` integrates rolling and sliding
and locates every transition between them; :func:`rollingdisk.energy_balance` checks that the
mechanical energy plus what friction dissipated stays constant (eq. 12).

Two runs. First the textbook case: a thin disk standing upright, thrown along the ground
without spin, ``V_X = v0``. Friction slows the centre (``dV_X/dt = -mu``) and spins the disk
up (``d omega2/dt = 2 mu``) until the slip ``V_X - omega2`` vanishes at ``t* = v0 / (3 mu)``,
with ``V_X = 2 v0 / 3``; from then on it rolls. Then the steady circle of the README
(``h = 0.17``, ``theta0 = 30 deg``, ``r_C = 0.5``), which needs ``mu = 0.238`` to roll, put on
ground with ``mu_s = 0.2``: it slides at once, and rolls again later.
"""

import matplotlib.pyplot as plt
import numpy as np

import rollingdisk as rd

# %%
# The upright thin disk thrown without spin

v0, mu = 1.0, 0.2
y0 = [0, 0, v0, 0, 0, 0, 0, 0, 0, 0]  # X_C, Y_C, V_X, V_Y, psi, theta, phi, omega1..3
thin = rd.simulate_coulomb(rd.Disk(0.0), rd.Coulomb(mu), (0, 2 * v0 / (3 * mu)), y0)
t_star = v0 / (3 * mu)
print(thin.transitions)

# %%
# The steady circle on too little friction

disk = rd.Disk(h=0.17)
m = rd.steady_motion(disk, "rough", theta0=0.5236, r_C=0.5)
ground = rd.Coulomb(mu_s=0.2, mu_k=0.15)
tc = rd.simulate_coulomb(disk, ground, (0, 30), rd.rolling_state(disk, m.initial_state()))
balance = rd.energy_balance(tc)
print(f"the circle needs mu = {m.mu_required:.3f}; transitions: {tc.transitions}")
print(f"energy balance: {balance:.2e}")

contact = [rd.coulomb_contact(disk, ground, k, tc.y[:, i]) for i, k in enumerate(tc.mode)]
slip = np.array([np.hypot(c["u_x"], c["u_y"]) for c in contact])
ratio = np.array([c["F_t"] / c["F_z"] for c in contact])
dissipated = sum(tc.dissipated.values())

fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(12, 3.8), layout="constrained")
ax1.plot(thin.t, thin.component("V_X"), label=r"$V_X$")
ax1.plot(thin.t, thin.component("omega2"), label=r"$\omega_2$")
ax1.plot([0, t_star], [v0, 2 * v0 / 3], "k:", lw=1, label=r"$v_0 - \mu t$")
ax1.plot([0, t_star], [0, 2 * v0 / 3], "k--", lw=1, label=r"$2 \mu t$")
ax1.axvline(t_star, color="C3", lw=0.8)
ax1.set_xlabel("t")
ax1.set_title(r"thin disk: rolls from $t^* = v_0/3\mu$")
ax1.legend(fontsize=8)

ax2.plot(tc.t, slip, label="slip speed |u|")
ax2.plot(tc.t, ratio, label=r"$|F_t| / F_z$")
ax2.axhline(ground.mu_s, color="k", lw=0.8, ls=":", label=r"$\mu_s$")
ax2.axhline(ground.mu_k, color="k", lw=0.8, ls="--", label=r"$\mu_k$")
for tr in tc.transitions:
    ax2.axvline(tr.t, color="C3", lw=0.8)
ax2.set_xlabel("t")
ax2.set_title("the circle on Coulomb ground")
ax2.legend(fontsize=8)

ax3.plot(tc.t, tc.E - tc.E[0], label=r"$E - E_0$")
ax3.plot(tc.t, dissipated, label="dissipated")
ax3.plot(tc.t, tc.E + dissipated - tc.E[0], label="sum", color="k")
ax3.set_xlabel("t")
ax3.set_title(f"energy balance {balance:.0e}")
ax3.legend(fontsize=8)
plt.show()

# %%
# Checks against independent truths
# ---------------------------------
# * the thin disk: transition at ``t* = v0/(3 mu)``, ``V_X = omega2 = 2 v0/3`` after it, and
#   slip dissipated ``v0^2/6`` (the kinetic energy lost, in closed form);
# * the circle: it needs more friction than the ground has, so it slides at ``t = 0``;
#   while it slides ``|F_t| = mu_k F_z``, while it rolls ``|F_t| <= mu_s F_z``;
# * energy plus dissipation is conserved (eq. 12) on both runs.
(tt,) = thin.transitions
assert (tt.from_mode, tt.to_mode) == ("sliding", "rolling")
assert abs(tt.t - t_star) < 1e-9
assert abs(thin.component("V_X")[-1] - 2 * v0 / 3) < 1e-9
assert abs(thin.component("omega2")[-1] - 2 * v0 / 3) < 1e-9
assert abs(sum(thin.dissipated.values())[-1] - v0**2 / 6) < 1e-9
assert rd.energy_balance(thin) < 1e-9

assert m.mu_required > ground.mu_s
first = tc.transitions[0]
assert (first.t, first.from_mode, first.to_mode) == (0.0, "rolling", "sliding")
assert any(t.to_mode == "rolling" for t in tc.transitions[1:])
sliding = tc.mode == 1
assert np.allclose(ratio[sliding], ground.mu_k, rtol=1e-9)
assert np.all(ratio[~sliding] <= ground.mu_s * (1 + 1e-9))
assert balance < 1e-9
