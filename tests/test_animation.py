"""The drawn disk and the trajectory plots: geometry against eqs. (4), (5), (7).

Sources of truth: the contact condition Z_P = 0 (eq. 5) and that the contact point lies on
a rim of the cylinder, no part of which goes below the plane; the frame C xi eta zeta is
right-handed and orthonormal; the body marker turns by phi about eta; the plotted paths
are the state's (X_C, Y_C) and eq. (5)'s (X_P, Y_P).
"""

import math
from types import SimpleNamespace

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

from rollingdisk import Disk, contact_point, equations_of_motion, omega_dot  # noqa: E402
from rollingdisk.plotting.animation import animate, body_frame, disk_pose, poses
from rollingdisk.plotting.plots import (
    plot_contact_forces,
    plot_energy_error,
    plot_paths,
    plot_theta,
    plot_trajectory,
)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


def _trajectory(h=0.17, ground="rough", t_end=6.0, n=200):
    """A near-steady trajectory integrated here with solve_ivp (not rollingdisk.simulate):
    theta = 0.35, omega3 = 1.2, omega2 such that d omega1/dt = 0 (eq. 38 / 49 is affine in
    omega2), and omega1 = 0.05 as a perturbation."""
    disk = Disk(h)
    th, w3 = 0.35, 1.2
    a = omega_dot(disk, ground, th, 0.0, 0.0, w3)[0]
    b = omega_dot(disk, ground, th, 0.0, 1.0, w3)[0] - a
    w2 = -a / b
    if ground == "rough":
        y0 = [0.3, -0.2, 0.4, th, 0.0, 0.05, w2, w3]
    else:
        y0 = [0.3, -0.2, 0.05, 0.02, 0.4, th, 0.0, 0.05, w2, w3]
    t = np.linspace(0.0, t_end, n)
    sol = solve_ivp(equations_of_motion(disk, ground), (0, t_end), y0, t_eval=t, rtol=1e-10,
                    atol=1e-12, method="DOP853")
    assert sol.success
    return SimpleNamespace(disk=disk, ground=ground, t=sol.t, y=sol.y)


angles = st.floats(-math.pi, math.pi, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(h=st.floats(0.0, 3.0), theta=st.floats(0.01, 1.5), sign=st.sampled_from([-1.0, 1.0]),
       psi=angles, phi=angles)
def test_contact_point_on_plane_and_on_rim(h, theta, sign, psi, phi):
    theta *= sign
    pose = disk_pose(h, 0.7, -1.1, psi, theta, phi, n=360)
    P = pose.contact
    assert P[2] == pytest.approx(0.0, abs=1e-12)  # eq. (5): Z_P = 0
    # eq. (5) in the plane agrees with rollingdisk.contact_point
    XP, YP = contact_point(Disk(h), "rough", np.array([0.7, -1.1, psi, theta, phi, 0, 0, 0]))
    assert P[:2] == pytest.approx([XP, YP], abs=1e-12)
    # P lies on the rim circle about C - h~ eta (radius 1, in the face plane)
    face = pose.center - h * math.copysign(1.0, theta) * pose.axis
    assert np.linalg.norm(P - face) == pytest.approx(1.0, abs=1e-12)
    assert np.dot(P - face, pose.axis) == pytest.approx(0.0, abs=1e-12)
    # nothing drawn goes below the plane, and the lowest rim point is at the contact
    Z = pose.rims[:, 2, :]
    assert Z.min() > -1e-12
    assert Z.min() < 1e-3


@settings(max_examples=30, deadline=None)
@given(psi=angles, theta=st.floats(-1.5, 1.5))
def test_body_frame_right_handed(psi, theta):
    xi, eta, zeta = body_frame(psi, theta)
    M = np.array([xi, eta, zeta])
    assert M @ M.T == pytest.approx(np.eye(3), abs=1e-12)
    assert np.cross(xi, eta) == pytest.approx(zeta, abs=1e-12)
    assert eta[2] == pytest.approx(math.sin(theta))  # axis tilts up by theta


def test_marker_turns_by_phi_about_axis():
    a = disk_pose(0.2, 0, 0, 0.3, 0.4, 0.0)
    b = disk_pose(0.2, 0, 0, 0.3, 0.4, 0.5)
    c0 = a.center - 0.2 * a.axis
    u, v = a.marker[0] - c0, b.marker[0] - c0
    assert np.dot(u, a.axis) == pytest.approx(0.0, abs=1e-12)
    assert math.acos(np.clip(np.dot(u, v), -1, 1)) == pytest.approx(0.5, abs=1e-12)
    assert np.dot(np.cross(u, v), a.axis) > 0  # positive phi turns about +eta


def test_poses_follow_the_trajectory():
    traj = _trajectory()
    tf, ps = poses(traj, 7)
    assert tf[0] == traj.t[0] and tf[-1] == traj.t[-1]
    XP, YP = contact_point(traj.disk, traj.ground, traj.y)
    for ti, p in zip(tf, ps, strict=True):
        i = int(np.argmin(np.abs(traj.t - ti)))
        if abs(traj.t[i] - ti) < 1e-12:
            assert p.contact[:2] == pytest.approx([XP[i], YP[i]], abs=1e-9)


@pytest.mark.parametrize("ground", ["rough", "smooth"])
def test_gif_frames(tmp_path, ground):
    from PIL import Image

    traj = _trajectory(ground=ground, t_end=3.0, n=60)
    out = animate(traj, tmp_path / "m.gif", n_frames=4, fps=5, dpi=40)
    with Image.open(out) as im:
        assert im.n_frames == 4
        frames = []
        for k in range(im.n_frames):
            im.seek(k)
            frames.append(np.asarray(im.convert("RGB"), dtype=float))
    assert np.abs(frames[0] - frames[-1]).mean() > 0.1  # the disk moved


def test_bad_animation_suffix(tmp_path):
    with pytest.raises(ValueError, match="gif"):
        animate(_trajectory(n=10), tmp_path / "m.avi", n_frames=2)


# ------------------------------------------------------------------------ trajectory plots
def test_trajectory_plots_show_the_states():
    traj = _trajectory()
    out = plot_paths(traj)
    assert out["C"].get_xdata() == pytest.approx(traj.y[0])
    XP, YP = contact_point(traj.disk, traj.ground, traj.y)
    assert out["P"].get_ydata() == pytest.approx(YP)
    th = plot_theta(traj, theta0=0.35)
    assert th["theta"].get_ydata() == pytest.approx(traj.y[3])
    e = plot_energy_error(traj)
    dE = e["dE"].get_ydata()
    assert dE[0] == 0.0 and np.abs(dE).max() < 1e-8  # energy conserved (eq. 12)
    f = plot_contact_forces(traj)
    assert np.all(f["F_z"].get_ydata() > 0)  # still in contact
    assert "F_z" in f["F_z"].get_label()


def test_trajectory_summary_and_smooth_forces():
    traj = _trajectory(ground="smooth")
    out = plot_trajectory(traj, theta0=0.35, title="x")
    assert out["axes"].shape == (2, 2)
    assert np.allclose(out["forces"]["F_x"].get_ydata(), 0.0)  # no friction


def test_mp4_needs_ffmpeg(tmp_path):
    import shutil

    if shutil.which("ffmpeg") is not None:
        pytest.skip("ffmpeg is installed here: .mp4 works")
    with pytest.raises(ValueError, match="ffmpeg"):
        animate(_trajectory(n=10), tmp_path / "m.mp4", n_frames=2)
