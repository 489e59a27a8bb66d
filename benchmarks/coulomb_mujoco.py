"""Sliding -> rolling of an upright disk: rollingdisk (Coulomb ground) against MuJoCo.

The classic case (units m = a = g = 1): a disk standing upright on its rim slides with
V_X = v0 and no rotation; friction mu decelerates it and spins it up until the slip
vanishes at t* = v0/(3 mu), V_X(t*) = 2 v0/3, after dissipating v0^2/6.  (Rotation about
the symmetry axis only, so t* does not depend on the thickness.)

MuJoCo (pip install mujoco; not a dependency of rollingdisk): a free cylinder of radius 1,
half-length 0.05, mass 1, axis horizontal, on a plane, gravity 1, elliptic friction cone,
timestep dt.  Its transition time is where the straight line fitted to the slip speed over
its sliding phase (slip between 0.9 v0 and 0.05 v0) reaches zero (the soft contact never
brings the slip exactly to 0); the first time the slip falls below 1e-3 v0 is printed too.

Run:  PYTHONPATH=src python benchmarks/coulomb_mujoco.py
"""

from __future__ import annotations

import time

import numpy as np

import rollingdisk as rd

V0, MU = 1.0, 0.2
T_EXACT = V0 / (3 * MU)
E_LOSS = V0 * V0 / 6


def ours():
    w = time.perf_counter()
    tr = rd.simulate_coulomb(rd.Disk(0.0), rd.Coulomb(MU), (0, 2 * T_EXACT),
                             [0, 0, V0, 0, 0, 0, 0, 0, 0, 0])
    w = time.perf_counter() - w
    t = tr.transitions[0].t
    return t, tr.dissipated["slip"][-1], rd.energy_balance(tr), w


XML = """
<mujoco>
  <option gravity="0 0 -1" timestep="{dt}" cone="elliptic" integrator="RK4"/>
  <worldbody>
    <geom type="plane" size="50 50 0.1" friction="{mu} 0 0"/>
    <body pos="0 0 1.0" quat="0.70710678 0.70710678 0 0">
      <freejoint/>
      <geom type="cylinder" size="1 0.05" friction="{mu} 0 0" condim="3"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.25083333 0.25083333 0.5"/>
    </body>
  </worldbody>
</mujoco>
"""


def mujoco_run(dt):
    import mujoco

    model = mujoco.MjModel.from_xml_string(XML.format(dt=dt, mu=MU))
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    # settle the penetration of the soft contact first (no horizontal motion), then kick
    for _ in range(int(2.0 / dt)):
        mujoco.mj_step(model, data)
    data.qvel[:] = 0.0
    data.qvel[0] = V0
    mujoco.mj_forward(model, data)

    def energy():
        v = data.qvel
        I = np.array([0.25083333, 0.25083333, 0.5])
        # qvel[3:6] is the angular velocity in the body frame for a free joint
        return 0.5 * (v[:3] @ v[:3]) + 0.5 * (I * v[3:6] ** 2).sum() + data.qpos[2]

    E0 = energy()
    t0 = data.time
    t_stick = None
    hist = []
    w = time.perf_counter()
    while data.time - t0 < 2 * T_EXACT:
        mujoco.mj_step(model, data)
        # slip of the lowest point: v_x + (omega x r)_x, r = (0, 0, -1) in the world frame
        om = np.zeros(3)
        mujoco.mju_rotVecQuat(om, data.qvel[3:6], data.qpos[3:7])
        slip = data.qvel[0] - om[1] * 1.0
        if 0.05 * V0 < slip < 0.9 * V0:
            hist.append((data.time - t0, slip, energy()))
        if t_stick is None and abs(slip) < 1e-3 * V0:
            t_stick = data.time - t0
            E_stick = energy()
    w = time.perf_counter() - w
    h = np.array(hist)
    k, c = np.polyfit(h[:, 0], h[:, 1], 1)
    t_fit = -c / k
    return t_fit, t_stick, E0 - E_stick, w


if __name__ == "__main__":
    t, d, bal, w = ours()
    print(f"exact      t* = {T_EXACT:.12f}  dissipated = {E_LOSS:.12f}")
    print(f"rollingdisk t* = {t:.12f}  error {abs(t - T_EXACT):.1e}; dissipated error "
          f"{abs(d - E_LOSS):.1e}; energy balance {bal:.1e}; wall {w * 1e3:.1f} ms")
    try:
        import mujoco  # noqa: F401
    except ImportError:
        print("mujoco not installed: pip install mujoco")
    else:
        for dt in (1e-3, 1e-4):
            tm, t_thr, dm, wm = mujoco_run(dt)
            if tm is None:
                print(f"mujoco dt={dt:g}: the slip never fell below 1e-3 v0")
                continue
            print(f"mujoco dt={dt:g}: t* = {tm:.6f} (line fit)  error {abs(tm - T_EXACT):.1e} "
                  f"(relative {abs(tm - T_EXACT) / T_EXACT:.1e}); slip < 1e-3 v0 at "
                  f"{t_thr:.6f}; energy lost up to then "
                  f"{dm:.6f}, error {abs(dm - E_LOSS):.1e}; wall {wm * 1e3:.0f} ms")
