"""The atlas's helper processes: the first animation, the disk let go to rest and Euler's
disk, each drawn or run in a child process alongside the other steps (the two cores of a
laptop), quiet on Ctrl-C.
"""

from __future__ import annotations

import json
from pathlib import Path

from rollingdisk.model.disk import Disk

__all__ = ["EULER_SOUND"]

#: The atlas's sound of Euler's disk: the last seconds of the run in real time, at a rate
#: that keeps the file near 350 KB (the whirr ends below 200 Hz on the toy).
EULER_SOUND = {"rate": 22050, "speed": 1.0, "max_seconds": 8.0}


def _start_animation(traj, path, kw):
    """Start :func:`rollingdisk.plotting.animation.animate` in a child process (written atomically
    there); returns the process."""
    return _start_child(_animate_in_child, (traj, path, kw))


def _start_to_rest(section, out: Path, quick: bool, disk: Disk):
    """Start ``section(out, quick, [], disk)`` (the atlas's run to rest,
    :func:`rollingdisk.atlas.steps._to_rest_section`, its GIF written into ``out``) in a
    child process; returns ``(process, connection)``: the record arrives on the connection
    (``EOFError`` there if the child died first)."""
    import multiprocessing

    receive, send = multiprocessing.Pipe(duplex=False)
    proc = _start_child(_to_rest_in_child, (section, out, quick, disk, send))
    send.close()  # the child holds the only sending end: its death ends recv()
    return proc, receive


def _to_rest_in_child(section, out: Path, quick: bool, disk: Disk, conn):
    """The run-to-rest helper's body: the record of ``section`` sent on ``conn``."""
    _quiet_signals()
    conn.send(section(out, quick, [], disk))
    conn.close()


def _start_child(target, args):
    """Start ``target(*args)`` in a daemon child process; returns the process."""
    import multiprocessing

    proc = multiprocessing.Process(target=target, args=args, daemon=True)
    proc.start()
    return proc


def _quiet_signals():
    """In a helper: a Ctrl-C or SIGTERM reaches the whole process group; the child ignores
    SIGINT (the parent stops it) and dies quietly on SIGTERM, so the user sees the parent's
    one line and never the child's traceback."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _animate_in_child(traj, path, kw):
    """The animation helper's body (see :func:`_quiet_signals`)."""
    from rollingdisk.plotting.animation import animate

    _quiet_signals()
    animate(traj, path, **kw)


def _euler_disk_in_child(out: Path, quick: bool, dpi: int, disk: Disk | None = None):
    """The Euler's-disk helper's body: the toy run to its end (``quick``: started at
    ``alpha0 = 0.05``, a short run), ``euler_disk.png``, the whirr's frequency
    ``euler_disk_chirp.png``, its sound ``euler_disk.wav`` (not when ``quick``) and
    ``euler_disk.json`` in ``out`` (the atlas's temporary folder; the JSON last, as the sign
    that the others are whole; its ``"sound"`` names the WAV).  The toy is ``disk`` when it
    has a radius and a mass, else the commercial Euler's disk."""
    from matplotlib.figure import Figure

    from rollingdisk.plotting.plots import plot_euler_disk
    from rollingdisk.plotting.sound import chirp, plot_chirp_frequency, sound_window, write_wav
    from rollingdisk.scenarios.euler_disk import EulerDisk, run_euler_disk

    _quiet_signals()
    alpha0 = 0.05 if quick else 0.3
    if disk is not None and disk.radius is not None and disk.mass is not None:
        toy = EulerDisk.from_disk(disk, alpha0=alpha0)
    else:
        toy = EulerDisk(alpha0=alpha0)
    result = run_euler_disk(toy, max_wall_time=60.0)
    fig = Figure(figsize=(10.0, 4.2))
    plot_euler_disk(result, fig)  # title: plots.euler_disk_title, symbols with units
    fig.savefig(out / "euler_disk.png", dpi=dpi)
    snd = EULER_SOUND
    fig = Figure(figsize=(6.4, 3.6))
    plot_chirp_frequency(result, fig, rate=snd["rate"], speed=snd["speed"],
                         max_seconds=snd["max_seconds"])
    fig.savefig(out / "euler_disk_chirp.png", dpi=dpi)
    summary = result.summary()
    if not quick:
        write_wav(out / "euler_disk.wav", chirp(result, **snd), snd["rate"])
        t0, t1 = sound_window(result, snd["speed"], snd["max_seconds"])
        summary["sound"] = {"file": "euler_disk.wav", **snd, "window_s": [t0, t1]}
    (out / "euler_disk.json").write_text(json.dumps(summary, indent=2, allow_nan=False))
