"""
The notebook view of a 1-euro coin
==================================

In a notebook (JupyterLab, Notebook 7, VS Code, Colab, marimo), with the extra
``rollingdisk[notebook]`` (anywidget), two lines show a disk's map of steady circles; a click
on the map shows that steady motion's numbers, SI beside them for a coin, and plays the
motion kicked from it in 3D (drag to rotate, wheel to zoom, a time slider)::

    from rollingdisk.explore.widget import widget
    widget("euro-1")

and ``play(result)`` plays any computed motion (a simulation, a motion to rest, a toss).
Python computes every number and sends it to the browser as the widget's traits; the
browser only draws them, with the served explorer's own view module (``view.js``, the same
map and 3D view as ``rollingdisk explore``).

Here the traits of a click at ``theta0 = 0.4 rad``, ``omega30 = 1.5`` are computed without
a browser (:func:`rollingdisk.explore.widget.traits`) and drawn as the view draws them: the
map in the (theta0, omega30) plane (dark: no steady motion, orange: unstable, light: stable;
dashed, the static-equilibrium tilt ``tan theta0 = h``; the click circled) and one frame of
the 3D view: the coin as a cylinder of radius 1 and thickness ``2h`` about its centre C
(axis ``eta``, body-fixed radii ``e1``, ``e2``), the paths of the contact point P (red) and
of C (blue) so far.
"""

import math

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import ListedColormap
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

import rollingdisk as rd
from rollingdisk.explore.widget import traits

coin = rd.disk_from_options(disk="euro-1")
theta0, omega30 = 0.4, 1.5
w = traits(coin, selected=(theta0, omega30))
m, f = w["motion"], w["frames"]
print(f"h = {w['disk']['h']:.5f}, time unit sqrt(a/g) = {1e3 * w['disk']['time_s']:.3f} ms")
print(f"Omega0 = {m['Omega0']:.6f}, varpi^2 = {m['varpi2']:.6f}, stable: {m['stable']}")
for label, value in m["si"].items():
    print(f"  {label:18s} {value:.6g}")

# the view's colours (view.js: COLORS) and its frame: a third of the way through the run
colours = ListedColormap(np.array([[61, 64, 91], [227, 162, 127], [244, 241, 222]]) / 255)
k = len(f["t"]) // 3
C = np.array([f["X_C"][k], f["Y_C"][k], f["Z_C"][k]])
eta, e1, e2 = (np.array(f[n][3 * k:3 * k + 3]) for n in ("axis", "e1", "e2"))
h = f["h"]
a = np.linspace(0.0, 2.0 * np.pi, 97)
rims = [C + side * h * eta + np.outer(np.cos(a), e1) + np.outer(np.sin(a), e2)
        for side in (-1, 1)]

fig = plt.figure(figsize=(11, 4.6), layout="constrained")
ax1 = fig.add_subplot(1, 2, 1)
mp = w["map"]
ax1.imshow(np.array(mp["codes"]), origin="lower", cmap=colours, vmin=0, vmax=2,
           aspect="auto", interpolation="nearest",
           extent=[*np.degrees(mp["x"]["range"]), *mp["y"]["range"]])
ax1.axvline(math.degrees(mp["se_theta0"]), color="#1f5fbf", ls="--", lw=1.2)
ax1.plot(math.degrees(theta0), omega30, "o", ms=11, mfc="none", mec="k", mew=2)
ax1.set_xlabel(r"$\theta_0$ (deg)")
ax1.set_ylabel(r"$\omega_{30}$ ($\sqrt{g/a}$)")
ax1.set_title("the map: a click selects a steady circle")

ax2 = fig.add_subplot(1, 2, 2, projection="3d")
# the faces and the rim band, shaded as the view shades them (a light from (0.3, -0.4, 0.9))
light = np.array([0.3, -0.4, 0.9]) / np.linalg.norm([0.3, -0.4, 0.9])
faces = [rims[0], rims[1]] + [np.array([rims[0][i], rims[0][i + 1], rims[1][i + 1],
                                        rims[1][i]]) for i in range(len(a) - 1)]
normals = [-eta, eta] + [math.cos(am) * e1 + math.sin(am) * e2 for am in (a[:-1] + a[1:]) / 2]
base = [(176, 184, 196)] * 2 + [(120, 128, 140)] * (len(a) - 1)
shade = [np.array(b) / 255 * (0.55 + 0.45 * max(0.0, n @ light)) for b, n in zip(base, normals)]
ax2.add_collection3d(Poly3DCollection(faces, facecolors=shade, edgecolors=shade, lw=0.3))
ax2.plot(f["X_P"][:k + 1], f["Y_P"][:k + 1], 0.0, color="#c0392b", lw=1.6)
ax2.plot(f["X_C"][:k + 1], f["Y_C"][:k + 1], f["Z_C"][:k + 1], color=(0.16, 0.38, 1.0),
         lw=1.2)
ax2.plot(*zip(C + h * eta, C + h * eta + e1), color="#b03030", lw=2.5)  # turns with phi
ax2.scatter([f["X_P"][k]], [f["Y_P"][k]], [0.0], color="#c0392b", s=16)
centre = np.array([np.mean(f["X_C"]), np.mean(f["Y_C"])])
xs, ys = np.array(f["X_P"] + f["X_C"]), np.array(f["Y_P"] + f["Y_C"])  # both paths
span = 1.2 * max(np.ptp(xs), np.ptp(ys), 2.0) / 2
top = 1.1 * max(r[:, 2].max() for r in rims)
ax2.set(xlim=(centre[0] - span, centre[0] + span), ylim=(centre[1] - span, centre[1] + span),
        zlim=(0.0, top), xlabel="X", ylabel="Y", zlabel="Z")
ax2.set_box_aspect((2 * span, 2 * span, top))  # lengths true to scale
# the camera 60 deg round from the axis, to see the tilt (in the view: drag to turn it)
ax2.view_init(elev=15.0, azim=math.degrees(math.atan2(eta[1], eta[0])) + 60.0)
ax2.set_title(f"the 3D view at t = {f['t'][k]:.2f} $\\sqrt{{a/g}}$ "
              f"({1e3 * f['t'][k] * w['disk']['time_s']:.1f} ms)")
plt.show()

# %%
# Checks against independent truths
# ---------------------------------
# * the numbers the click sends are the library's own (``steady_motion``, ``stability``);
# * the SI values are the paper's times the coin's scales, ``sqrt(g/a)`` for a rate;
# * the map's cell under the click has the stability of that steady motion;
# * the drawn coin stands on the plane ``Z = 0`` at the contact point P (eqs. 5, 7).
truth = rd.steady_motion(coin, "rough", theta0, Omega0=omega30 / math.cos(theta0))  # eq. 3
stab = rd.stability(truth)
for key, value in (("Omega0", truth.Omega0), ("omega20", truth.omega20), ("r_C", truth.r_C),
                   ("varpi2", stab.varpi2), ("mu_required", truth.mu_required)):
    assert abs(m[key] - value) <= 1e-9 * max(1.0, abs(value)), key
rate = math.sqrt(coin.gravity / coin.radius)  # 1 / (time unit), s^-1
assert abs(m["si"]["Omega0 [rad/s]"] - truth.Omega0 * rate) <= 1e-9 * abs(truth.Omega0 * rate)
assert abs(m["si"]["r_C [mm]"] - 1e3 * truth.r_C * coin.radius) <= 1e-9
i = int(np.argmin(np.abs(np.array(mp["x"]["values"]) - theta0)))
j = int(np.argmin(np.abs(np.array(mp["y"]["values"]) - omega30)))
assert mp["codes"][j][i] == (rd.STABLE if stab.stable else rd.UNSTABLE)
fine = np.linspace(0.0, 2.0 * np.pi, 3601)
ring = np.concatenate([C + side * h * eta + np.outer(np.cos(fine), e1)
                       + np.outer(np.sin(fine), e2) for side in (-1, 1)])
low = ring[np.argmin(ring[:, 2])]
assert abs(low[2]) < 1e-5 and math.hypot(low[0] - f["X_P"][k], low[1] - f["Y_P"][k]) < 5e-3
