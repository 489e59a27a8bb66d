"""``rollingdisk animate``: simulate a steady motion from a small perturbation and write a
3D animation (.gif, or .mp4 when ffmpeg is present).

    $ rollingdisk animate --theta0 30deg --Omega0 2 --out motion.gif
    $ rollingdisk animate --h 0.3 --theta0 0.5 --rC 1 --kick 0.05 --t-end 40 --out m.mp4
    $ rollingdisk animate --disk cd --theta0 30deg --Omega0 10rad/s --t-end 2s --out cd.gif
"""

from __future__ import annotations

import sys

from rollingdisk.cli._args import (
    T_END_MAX,
    add_motion_args,
    add_perturbation_args,
    integer,
    motion_from_args,
    t_end_arg,
)
from rollingdisk.cli._format import agg, disk_line, has_scale
from rollingdisk.cli.figures import dpi_arg
from rollingdisk.model.disk import DEFAULT_H


def configure(sub):
    from rollingdisk.plotting.animation import FPS_RANGE, FRAMES_RANGE

    p = sub.add_parser("animate")
    add_motion_args(p, h_default=DEFAULT_H)
    add_perturbation_args(p, kick=0.01)
    t_end_arg(p, high=T_END_MAX, default=20.0)
    p.add_argument("--frames", type=integer("frames", *FRAMES_RANGE), default=60,
                   help=f"number of frames in [{FRAMES_RANGE[0]}, {FRAMES_RANGE[1]}] "
                   "(default 60)")
    p.add_argument("--fps", type=integer("fps", *FPS_RANGE), default=15,
                   help=f"frames per second in [{FPS_RANGE[0]}, {FPS_RANGE[1]}] (default 15)")
    dpi_arg(p, 70)
    p.add_argument("--out", required=True, help="motion.gif (or .mp4 when ffmpeg exists)")
    p.set_defaults(_echo_stderr=True)  # stdout is the path written
    return p


def run(args) -> int:
    import numpy as np

    import rollingdisk as rd
    from rollingdisk.plotting.animation import animate, check_animation, writer_for
    from rollingdisk.util.files import check_writable

    # everything that can be refused, before the simulation
    check_animation(args.frames, args.fps, args.dpi)
    writer_for(args.out, args.fps)
    check_writable(args.out, name="out")
    motion = motion_from_args(args, "animate")
    agg()
    stab = rd.stability(motion)
    traj = rd.simulate_steady(motion, args.t_end, perturb=args.perturb, kick=args.kick,
                              t_eval=np.linspace(0.0, args.t_end, 1200))
    verdict = "stable" if stab.stable else "unstable"
    disk = motion.disk
    if has_scale(disk):  # SI beside
        print(disk_line(disk), file=sys.stderr)
        rate = disk.angular_speed_to_si(motion.Omega0)
        varpi2 = stab.varpi2 / disk.time_unit ** 2
        extra = (f" ({rate:.4g} rad/s)", f" ({varpi2:.4g} 1/s^2)",
                 f" over {disk.time_to_si(args.t_end):.4g} s")
    else:
        extra = ("", "", "")
    print(f"{args.ground} ground, h = {disk.h:g}, theta0 = {motion.theta0:.4g}, "
          f"Omega0 = {motion.Omega0:.4g}{extra[0]}: {verdict}, varpi^2 = "
          f"{stab.varpi2:.4g}{extra[1]}; simulation{extra[2]} {traj.status}",
          file=sys.stderr)
    print(animate(traj, args.out, n_frames=args.frames, fps=args.fps, dpi=args.dpi))
    return 0
