"""3D animation of a simulated motion: the disk as a cylinder of thickness 2h on the plane.

Geometry (section 2, Figure 1): the centre C is at ``(X_C, Y_C, Z_C)`` with
``Z_C = -z_P`` (eq. 7); the frame ``C xi eta zeta`` has

* ``xi   = x = (cos psi, sin psi, 0)``,
* ``eta  = cos(theta) y + sin(theta) Z = (-sin psi cos theta, cos psi cos theta, sin theta)``
  (the disk's symmetry axis),
* ``zeta = -sin(theta) y + cos(theta) Z``,

with ``y = (-sin psi, cos psi, 0)``.  Body-fixed points turn by the rotation angle ``phi``
about ``eta``.  The two rims are the circles of radius ``a = 1`` about ``C +- h eta`` in
the plane spanned by ``xi, zeta``; the contact point P (eq. 4) is the lowest point of the
rim at ``C - h~ eta``.

matplotlib is imported only when a drawing function is called.
"""

from __future__ import annotations

import functools
import math
import shutil
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rollingdisk.model.disk import check_h
from rollingdisk.model.geometry import contact_geometry
from rollingdisk.plotting.plots import check_dpi, disk_of, si_factor, trajectory_series
from rollingdisk.util.checks import check_int, check_real
from rollingdisk.util.errors import ParameterError, ParameterTypeError

__all__ = ["DiskPose", "body_frame", "disk_pose", "poses", "draw_disk", "animate",
           "animation_html", "draw_scene", "write_frames",
           "check_animation", "writer_for", "FRAMES_RANGE", "FPS_RANGE", "PIXEL_BUDGET"]

#: Number of frames an animation may have.
FRAMES_RANGE = (2, 2000)
#: Most points on a drawn rim circle (a smooth circle needs ~50).
_RIM_POINTS_MAX = 4096
#: Frames per second.
FPS_RANGE = (1, 60)
#: Largest number of pixels of all frames together (frames x width x height): the GIF
#: writer keeps every frame in memory, 4 bytes a pixel, so this is about 1 GB.
PIXEL_BUDGET = 2.5e8


def body_frame(psi: float, theta: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Unit vectors ``xi, eta, zeta`` of the frame C xi eta zeta in OXYZ (Figure 1).

    Parameters
    ----------
    psi, theta : float
        Spin and inclination angles [rad].

    Returns
    -------
    (xi, eta, zeta) : tuple of (3,) ndarray
    """
    psi, theta = check_real("psi", psi), check_real("theta", theta)
    sp, cp = math.sin(psi), math.cos(psi)
    st, ct = math.sin(theta), math.cos(theta)
    xi = np.array([cp, sp, 0.0])
    eta = np.array([-sp * ct, cp * ct, st])
    zeta = np.array([sp * st, -cp * st, ct])
    return xi, eta, zeta


@dataclass(frozen=True)
class DiskPose:
    """The drawn disk at one instant, in OXYZ (units of ``a``).

    Attributes
    ----------
    center : (3,) ndarray
        The centre C, ``Z_C = -z_P`` (eq. 7).
    rims : (2, 3, n) ndarray
        The rim circles about ``C - h eta`` (index 0) and ``C + h eta`` (index 1).
    marker : (3, 3) ndarray
        Body-fixed marker: the rim points at body angle 0 on face 0 and face 1, and the
        point on face 1 opposite (so the line turns with ``phi``).
    contact : (3,) ndarray
        The contact point P of eq. (4)/(5): ``C + y_P y + z_P Z``.
    axis : (3,) ndarray
        ``eta``.
    """

    center: np.ndarray
    rims: np.ndarray
    marker: np.ndarray
    contact: np.ndarray
    axis: np.ndarray


def disk_pose(h: float, X_C: float, Y_C: float, psi: float, theta: float, phi: float,
              n: int = 48, *, Z_C: float | None = None) -> DiskPose:
    """Positions of the drawn disk for one state (eqs. 4, 5, 7).

    Parameters
    ----------
    h : float
        Half-thickness.
    X_C, Y_C, psi, theta, phi : float
        The centre C on the plane and the three angles [rad].
    n : int
        Points on each rim circle, 3 to 4096.
    Z_C : float, optional
        Height of C for a disk off the contact (flight, flat on a face); then ``contact``
        is the lowest point of the disk (the centre of the lower face when it lies flat).
        Default: touching, ``Z_C = -z_P`` (eq. 7).

    Returns
    -------
    DiskPose
    """
    h = check_h(h)
    X_C, Y_C, psi, theta, phi = (check_real(k, v) for k, v in (
        ("X_C", X_C), ("Y_C", Y_C), ("psi", psi), ("theta", theta), ("phi", phi)))
    Z_C = None if Z_C is None else check_real("Z_C", Z_C)
    n = check_int("n", n, low=3, high=_RIM_POINTS_MAX)
    xi, eta, zeta = body_frame(psi, theta)
    _, _, _, _, y_P, z_P = contact_geometry(h, theta)
    y_P, z_P = float(y_P), float(z_P)
    C = np.array([X_C, Y_C, -z_P if Z_C is None else float(Z_C)])  # eq. (7)
    # body-fixed radial directions: xi, zeta turned by phi about eta (Rodrigues, v _|_ eta)
    cf, sf = math.cos(phi), math.sin(phi)
    e1 = cf * xi - sf * zeta
    e2 = sf * xi + cf * zeta
    a = np.linspace(0.0, 2.0 * math.pi, n + 1)
    ring = np.cos(a)[None, :] * e1[:, None] + np.sin(a)[None, :] * e2[:, None]
    rims = np.stack([C[:, None] - h * eta[:, None] + ring, C[:, None] + h * eta[:, None] + ring])
    marker = np.stack([C - h * eta + e1, C + h * eta + e1, C + h * eta - e1])
    y_dir = np.array([-math.sin(psi), math.cos(psi), 0.0])
    if Z_C is None:
        P = C + y_P * y_dir + np.array([0.0, 0.0, z_P])  # eq. (5): Z_P = Z_C + z_P = 0
    else:
        P = _lowest_point(h, C, theta, eta, zeta)
    return DiskPose(C, rims, marker, P, eta)


def _lowest_point(h, C, theta, eta, zeta) -> np.ndarray:
    """The lowest point of the disk about C: on the lower rim (centre ``C -+ h eta``), the
    point ``-sgn(cos theta) zeta`` from its centre (``Z = sin(theta) eta + cos(theta)
    zeta``); the lower face's centre for a disk lying flat."""
    st, ct = math.sin(theta), math.cos(theta)
    c_low = C - (1.0 if st >= 0.0 else -1.0) * h * eta
    if abs(ct) < 1e-12:
        return c_low
    return c_low - (1.0 if ct > 0.0 else -1.0) * zeta


def poses(traj, n_frames: int = 60, *, n: int = 48) -> tuple[np.ndarray, list[DiskPose]]:
    """Frame times (uniform in ``t``) and the disk poses of a trajectory at them.

    Parameters
    ----------
    traj : Trajectory
        Or any object with ``disk, ground, t, y``.
    n_frames : int
        Number of frames, at most 2000 (fewer than 2 count as 2).
    n : int
        Points on each rim circle, 3 to 4096.

    Returns
    -------
    (times, poses) : (ndarray, list of DiskPose)
    """
    if not all(hasattr(traj, k) for k in ("disk", "ground", "t", "y")):
        raise ParameterTypeError(f"traj must be a Trajectory (or have disk, ground, t, y), "
                                 f"got {type(traj).__name__}")
    n_frames = max(FRAMES_RANGE[0], check_int("n_frames", n_frames, high=FRAMES_RANGE[1]))
    n = check_int("n", n, low=3, high=_RIM_POINTS_MAX)
    t = np.asarray(traj.t, float)
    tf = np.linspace(t[0], t[-1], n_frames)
    s = {k: np.interp(tf, t, trajectory_series(traj, k))
         for k in ("X_C", "Y_C", "psi", "theta", "phi")}
    h = traj.disk.h
    return tf, [disk_pose(h, s["X_C"][i], s["Y_C"][i], s["psi"][i], s["theta"][i],
                          s["phi"][i], n=n) for i in range(len(tf))]


def _limits(paths, frames, pad: float = 0.3):
    """Axis limits that hold the paths (``(t, X_P, Y_P, X_C, Y_C)``, NaN where a path is
    broken) and every drawn disk, with equal scales."""
    rims = np.concatenate([np.concatenate(f.rims, axis=1) for f in frames], axis=1)  # (3, N)
    _, XP, YP, XC, YC = paths
    xs = np.concatenate([XP, XC, rims[0]])
    ys = np.concatenate([YP, YC, rims[1]])
    xs, ys = xs[np.isfinite(xs)], ys[np.isfinite(ys)]
    cx, cy = 0.5 * (xs.min() + xs.max()), 0.5 * (ys.min() + ys.max())
    half = 0.5 * max(xs.max() - xs.min(), ys.max() - ys.min()) + pad
    return (cx - half, cx + half), (cy - half, cy + half), (0.0, rims[2].max() + pad)


def draw_disk(ax, pose: DiskPose, *, face_color="#9ecae1", side_color="#4a7fb0",
              marker_color="tab:red", shadow: bool = True) -> dict:
    """Draw one :class:`DiskPose` on a 3D axes: two faces, side surface, body-fixed red
    sectors (they show ``phi``), the contact point P and the shadow on ``Z = 0``.

    Everything on the plane gets a lower ``zorder`` than the disk; with
    ``ax.computed_zorder = False`` (as :func:`animate` sets) the disk, which never goes
    below the plane, is then always painted over them.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
    pose : DiskPose
    face_color, side_color, marker_color : color
    shadow : bool
        Draw the shadow on ``Z = 0``.

    Returns
    -------
    dict
        The artists, by role (``"body"``, ``"contact"``, ``"shadow"``).
    """
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    out = {}
    r0, r1 = pose.rims[0].T, pose.rims[1].T  # (n + 1, 3)
    quads = [np.array([r0[i], r0[i + 1], r1[i + 1], r1[i]]) for i in range(len(r0) - 1)]
    # one collection, so that matplotlib depth-sorts faces and side quads together
    # body-fixed red sectors on both faces (the first eighth of the rim, from the marker),
    # lifted slightly off the faces, so that the rotation phi is visible
    m = max(2, (len(r0) - 1) // 8)
    lift = 0.01 * pose.axis
    c0, c1 = r0[:-1].mean(axis=0), r1[:-1].mean(axis=0)  # face centres C -+ h eta
    sectors = [np.vstack([c0 - lift, r0[: m + 1] - lift]),
               np.vstack([c1 + lift, r1[: m + 1] + lift])]
    polys = [r0, r1] + quads + sectors
    colors = [face_color, face_color] + [side_color] * len(quads) + [marker_color] * 2
    edges = ["k", "k"] + [side_color] * len(quads) + [marker_color] * 2
    widths = [0.6, 0.6] + [0.2] * len(quads) + [0.3, 0.3]
    body = Poly3DCollection(polys, facecolors=colors, edgecolors=edges, linewidths=widths,
                            alpha=1.0)
    if shadow:
        # the disk's shadow straight below it: helps to read height and tilt
        flat = [np.column_stack([r[:, 0], r[:, 1], 0.0 * r[:, 0]]) for r in (r0, r1)]
        out["shadow"] = ax.add_collection3d(Poly3DCollection(
            flat, facecolor="0.45", edgecolor="none", alpha=0.3, zorder=1))
    (out["contact"],) = ax.plot(*pose.contact[:, None], "o", color="tab:red", ms=3,
                                zorder=1.5)
    body.set_zorder(2)
    out["body"] = ax.add_collection3d(body)
    return out


def check_animation(n_frames=60, fps=15, dpi=70, size=(5.0, 4.4)) -> tuple:
    """Validate the options of :func:`animate` before any work.

    Parameters
    ----------
    n_frames : int
        In :data:`FRAMES_RANGE`.
    fps : int
        In :data:`FPS_RANGE`.
    dpi : int
        In :data:`rollingdisk.plotting.plots.DPI_RANGE`.
    size : (float, float)
        Width and height in inches, each in ``(0, 20]``.

    Returns
    -------
    tuple
        ``(n_frames, fps, dpi, size)``, checked.

    Raises
    ------
    ParameterError
        For a value out of range, or more than :data:`PIXEL_BUDGET` pixels in all.
    """
    n_frames = check_int("n_frames", n_frames, low=FRAMES_RANGE[0], high=FRAMES_RANGE[1])
    fps = check_int("fps", fps, low=FPS_RANGE[0], high=FPS_RANGE[1])
    dpi = check_dpi(dpi)
    try:
        w, h = size
    except (TypeError, ValueError):
        raise ParameterTypeError(f"size must be (width, height) in inches, got {size!r}") \
            from None
    size = (check_real("width", w, low=0.0, high=20.0, low_open=True),
            check_real("height", h, low=0.0, high=20.0, low_open=True))
    pixels = n_frames * (size[0] * dpi) * (size[1] * dpi)
    if pixels > PIXEL_BUDGET:
        raise ParameterError(
            f"{n_frames} frames of {size[0] * dpi:.0f} x {size[1] * dpi:.0f} pixels are "
            f"{pixels:.3g} pixels, more than {PIXEL_BUDGET:.3g} (about 1 GB in memory): "
            "give fewer frames or a lower dpi")
    return n_frames, fps, dpi, size


def _plane(x0, x1, y0, y1):
    """The plane ``Z = 0`` over the drawn area, light gray with a darker rim, painted first."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    quad = np.array([[x0, y0, 0.0], [x1, y0, 0.0], [x1, y1, 0.0], [x0, y1, 0.0]])
    return Poly3DCollection([quad], facecolor=(0.85, 0.85, 0.85, 1.0), edgecolor="0.55",
                            linewidth=0.8, zorder=0.5)


def writer_for(path, fps: int):
    """A matplotlib animation writer for ``path``: Pillow for ``.gif``, ffmpeg for ``.mp4``.

    Parameters
    ----------
    path : path-like
        The file to write, ``.gif`` or ``.mp4``.
    fps : int
        Frames per second.

    Returns
    -------
    matplotlib.animation.AbstractMovieWriter

    Raises
    ------
    ParameterError
        For another suffix, or ``.mp4`` without ffmpeg.
    """
    from matplotlib import animation as mpl_animation

    try:
        suffix = Path(path).suffix.lower()
    except TypeError:
        raise ParameterTypeError(f"out must be a file name, got {type(path).__name__} "
                                 f"{path!r}") from None
    if suffix == ".gif":
        return _one_palette_gif_writer()(fps=fps)
    if suffix == ".mp4":
        if shutil.which("ffmpeg") is None:
            raise ParameterError("out: writing .mp4 needs ffmpeg, which was not found; "
                             "use a .gif file name instead")
        return mpl_animation.FFMpegWriter(fps=fps)
    raise ParameterError(f"out must end in .gif or .mp4, got {str(path)!r}")


#: Frames that a GIF's one palette is taken from (evenly spaced, first and last included).
_PALETTE_SAMPLE = 8


@functools.cache
def _one_palette_gif_writer():
    """matplotlib's Pillow writer, with one palette for all frames of a GIF.

    Pillow's own GIF writer runs a median-cut quantisation on every frame (most of the
    cost of writing an animation).  Here one 256-colour palette (Pillow's fast octree) is
    taken from :data:`_PALETTE_SAMPLE` frames spread over the animation and every frame is
    mapped onto it without dithering: the quantisation is done once instead of per frame
    and the file is smaller, each pixel within about 1/255 of its colour on average
    (``tests/test_atlas_gif.py``).  Frames with transparency keep Pillow's per-frame
    palettes."""
    from matplotlib.animation import PillowWriter
    from PIL import Image

    class OnePaletteGifWriter(PillowWriter):
        def finish(self):
            frames = self._frames
            if not frames or any(f.mode != "RGB" for f in frames):
                return super().finish()
            pick = np.unique(np.linspace(0, len(frames) - 1, _PALETTE_SAMPLE).round())
            w, h = frames[0].size
            sample = Image.new("RGB", (w, h * len(pick)))
            for j, i in enumerate(pick.astype(int)):
                sample.paste(frames[i], (0, h * j))
            palette = sample.quantize(256, method=Image.Quantize.FASTOCTREE)
            mapped = [f.quantize(palette=palette, dither=Image.Dither.NONE) for f in frames]
            # no ``palette=`` here: Pillow would map every frame again, slowly; each frame
            # gets a local table, the part of the one palette that it uses
            mapped[0].save(self.outfile, save_all=True, append_images=mapped[1:],
                           duration=int(1000 / self.fps), loop=0)

    return OnePaletteGifWriter


def _abandon(writer) -> None:
    """Stop a movie writer without finishing its file (ffmpeg: end the process)."""
    proc = getattr(writer, "_proc", None)
    if proc is not None:
        import contextlib

        with contextlib.suppress(Exception):
            proc.kill()
            proc.wait()


def _check_trajectory(traj) -> None:
    if not all(hasattr(traj, name) for name in ("disk", "ground", "t", "y")):
        raise ParameterTypeError(f"traj must be a Trajectory (disk, ground, t, y), got "
                                 f"{type(traj).__name__}")
    t = np.asarray(traj.t, float)
    if t.ndim != 1 or t.size < 1 or not np.all(np.isfinite(t)):
        raise ParameterError("traj.t must be a non-empty 1-D array of finite times")


def _scene(traj, fig, n_frames: int, title: str | None):
    """The 3D axes on ``fig`` and ``(frame times, draw)``: ``draw(i)`` paints frame ``i``."""
    tf, frames = poses(traj, n_frames)
    paths = (np.asarray(traj.t, float),
             *(trajectory_series(traj, k) for k in ("X_P", "Y_P", "X_C", "Y_C")))
    head = title if title is not None else f"{traj.ground} ground, h = {traj.disk.h:.4g}"
    return tf, draw_scene(fig, tf, frames, paths, head, disk_of(traj))


def draw_scene(fig, tf, frames, paths, head: str | Callable[[int], str],
               disk=None) -> Callable[[int], list]:
    """The 3D axes on ``fig`` and ``draw(i)``, which paints frame ``i``: the plane, the paths
    up to ``tf[i]``, the disk ``frames[i]`` (:func:`draw_disk`) and the clock in the title.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    tf : (n,) ndarray
        Frame times [``sqrt(a/g)``].
    frames : list of DiskPose
        One per frame.
    paths : (t, X_P, Y_P, X_C, Y_C) of 1-D arrays
        The paths of the contact point P (red) and of C projected on the plane (dashed),
        in time order; NaN breaks a path (P in flight).
    head : str or callable
        The title before the clock, or ``head(i)`` giving it for frame ``i``.
    disk : Disk, optional
        With a physical scale the clock runs in seconds, else in ``sqrt(a/g)``.

    Returns
    -------
    callable
    """
    t, XP, YP, XC, YC = (np.asarray(p, float) for p in paths)
    (x0, x1), (y0, y1), (z0, z1) = _limits((t, XP, YP, XC, YC), frames)
    ax = fig.add_subplot(1, 1, 1, projection="3d")
    # the title is a figure text: an axes title is placed above the axes' tick labels,
    # which a 3D axes computes on every frame even with its axis off
    title = fig.text(0.5, 0.96, "", ha="center", va="top", fontsize=9)
    # the clock in the title: seconds when the disk has a physical scale, else sqrt(a/g)
    ft = si_factor(disk, "time")
    clock = ((lambda ti: f"t = {ti * ft:6.2f} s") if ft != 1.0
             else (lambda ti: f"t = {ti:6.2f} √(a/g)"))

    # the scene is set up once; a frame moves the paths and redraws the disk only (an
    # axes cleared and set up again on every frame cost most of a frame's time)
    ax.set_autoscale_on(False)  # fixed limits: no autoscaling from the drawn parts
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_zlim(z0, z1)
    # no axis machinery (ticks, grids and panes): the plane Z = 0 is one polygon under
    # everything else
    ax.set_axis_off()
    ax.add_collection3d(_plane(x0, x1, y0, y1))
    ax.computed_zorder = False  # plane first, then the disk (see draw_disk)
    (path_p,) = ax.plot([], [], [], color="tab:red", lw=1.0, zorder=1.2)
    (path_c,) = ax.plot([], [], [], color="tab:blue", lw=0.7, ls="--", zorder=1.2)
    ax.set_box_aspect((x1 - x0, y1 - y0, z1 - z0))
    ax.view_init(elev=28, azim=-60)
    drawn: dict = {}

    def draw(i):
        ti, pose = tf[i], frames[i]
        for artist in drawn.values():
            artist.remove()
        k = int(np.searchsorted(t, ti, side="right"))
        path_p.set_data_3d(XP[:k], YP[:k], 0.0 * XP[:k])
        path_c.set_data_3d(XC[:k], YC[:k], 0.0 * XC[:k])
        drawn.clear()
        drawn.update(draw_disk(ax, pose))
        text = head(i) if callable(head) else head
        title.set_text(f"{text}   {clock(ti)}")
        return []

    return draw


def animate(traj, out, *, n_frames: int = 60, fps: int = 15, dpi: int = 70,
            size: tuple[float, float] = (5.0, 4.4), title: str | None = None,
            progress: Callable[[int, int], None] | None = None) -> Path:
    """Write a 3D animation of ``traj`` (a :class:`~rollingdisk.Trajectory` or any
    object with ``disk, ground, t, y``) to ``out`` (``.gif`` or ``.mp4``).

    The disk is drawn as a cylinder of thickness ``2h`` with a body-fixed red marker (so
    the rotation ``phi`` is visible); the path of the contact point P is traced on the
    plane ``Z = 0`` up to the current time, the projection of C's path dashed.

    The file is written under a temporary name and renamed at the end: it appears whole
    or not at all (an interrupted run leaves nothing).

    Parameters
    ----------
    traj : Trajectory
        The motion to draw (``disk, ground, t, y``).
    out : path-like
        ``.gif``, or ``.mp4`` when ffmpeg is installed; its folder must exist.
    n_frames, fps, dpi, size
        Checked by :func:`check_animation`.
    title : str, optional
        Title above the frames (default: the ground and ``h``).
    progress : callable, optional
        Called with ``(frame, n_frames)`` after each frame.

    Returns
    -------
    Path
        ``out``.
    """
    from rollingdisk.util.files import check_writable

    _check_trajectory(traj)
    n_frames, fps, dpi, size = check_animation(n_frames, fps, dpi, size)
    writer = writer_for(out, fps)
    out = Path(out)
    check_writable(out, name="out")
    from matplotlib.figure import Figure

    fig = Figure(figsize=size)
    tf, draw = _scene(traj, fig, n_frames, title)
    return write_frames(fig, len(tf), draw, out, writer, dpi, progress)


def write_frames(fig, n: int, draw: Callable[[int], object], out: Path, writer, dpi: int,
                 progress: Callable[[int, int], None] | None = None) -> Path:
    """Paint frames ``draw(0) .. draw(n - 1)`` on ``fig`` into ``out`` with ``writer``
    (:func:`writer_for`), under a temporary name renamed at the end: the file appears
    whole or not at all.  Returns ``out``."""
    import matplotlib as mpl

    from rollingdisk.util.files import atomic_file

    # not writer.saving(): it finishes the file even when interrupted, and an exception in
    # that clean-up would hide the interruption; here an unfinished file is just dropped
    with atomic_file(out, mode=None) as tmp, mpl.rc_context({"savefig.bbox": None}):
        writer.setup(fig, str(tmp), dpi)
        try:
            for i in range(n):
                draw(i)
                writer.grab_frame()
                if progress:
                    progress(i + 1, n)
        except BaseException:
            _abandon(writer)
            raise
        writer.finish()
    return out


def animation_html(traj, *, n_frames: int = 60, fps: int = 15, dpi: int = 70,
                   size: tuple[float, float] = (5.0, 4.4), title: str | None = None) -> str:
    """The 3D animation of ``traj`` (as :func:`animate` draws it) as inline HTML for a
    notebook: matplotlib's ``to_jshtml`` (frames embedded as PNG, play controls), no file.

    Parameters
    ----------
    traj : Trajectory
        The motion to draw (``disk, ground, t, y``).
    n_frames, fps, dpi, size
        Checked by :func:`check_animation`.
    title : str, optional
        Title above the frames (default: the ground and ``h``).

    Returns
    -------
    str
        HTML; in Jupyter, ``IPython.display.HTML(animation_html(traj))`` shows it.

    Examples
    --------
    >>> import rollingdisk as rd
    >>> m = rd.steady_motion(rd.Disk(h=0.17), "rough", 0.5, Omega0=2.0)
    >>> html = animation_html(rd.simulate_steady(m, 2.0), n_frames=2, dpi=20)
    >>> "<img" in html or "img id" in html
    True
    """
    _check_trajectory(traj)
    n_frames, fps, dpi, size = check_animation(n_frames, fps, dpi, size)
    import matplotlib as mpl
    from matplotlib import animation as mpl_animation
    from matplotlib.figure import Figure

    fig = Figure(figsize=size, dpi=dpi)
    tf, draw = _scene(traj, fig, n_frames, title)
    anim = mpl_animation.FuncAnimation(fig, draw, frames=len(tf), interval=1000.0 / fps,
                                       blit=False, repeat=True)
    with mpl.rc_context({"savefig.bbox": None, "animation.embed_limit": 200.0}):
        return anim.to_jshtml(fps=fps, default_mode="loop")
