"""``rollingdisk explore``: the command-line entry of the explorer.

:func:`configure` adds the subcommand to an ``argparse`` subparsers object and
:func:`run` runs it (``args.handler`` is set to :func:`run`, as for every subcommand of
:mod:`rollingdisk.cli`).  ``python -m rollingdisk.explore`` runs the same command alone.

Exit status: 130 on Ctrl-C (after a clean stop, no traceback); 2 when the address cannot
be bound (port in use, unknown host).
"""

from __future__ import annotations

import argparse
import errno
import sys

import rollingdisk as rd
from rollingdisk.util.checks import check_int, check_real

from . import api
from .server import is_loopback, make_server

__all__ = ["configure", "run", "DEFAULT_PORT", "is_loopback"]

#: The port tried first (``--port 0`` picks any free one).
DEFAULT_PORT = 8765
DEFAULT_HOST = "127.0.0.1"




def _type(check):
    def parse(text: str):
        try:
            return check(text)
        except (ValueError, TypeError) as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    return parse


def _h(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = text
    return check_real("h", value, low=api.H_RANGE[0], high=api.H_RANGE[1])


def _port(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = text
    return check_int("port", value, low=0, high=65535)


def configure(subparsers) -> argparse.ArgumentParser:
    """Add the ``explore`` subcommand to ``subparsers`` (from ``add_subparsers``).

    Returns
    -------
    argparse.ArgumentParser
        The subcommand's parser (its ``handler`` default is :func:`run`).
    """
    p = subparsers.add_parser(
        "explore", help="interactive explorer in the web browser: maps, steady motions, 3D",
        allow_abbrev=False,
        description="Serve an interactive explorer of steady motions on this machine and "
                    "open it in the web browser: click a map for a steady motion's numbers, "
                    "watch it kicked in 3D. Everything is served locally (works offline).")
    _add_disk_options(p)
    p.add_argument("--ground", choices=api.GROUNDS, default="rough",
                   help="ground the page starts with (default rough)")
    p.add_argument("--port", type=_type(_port), default=DEFAULT_PORT,
                   help=f"TCP port (default {DEFAULT_PORT}; 0 picks any free port)")
    p.add_argument("--host", default=None,
                   help=f"address to bind (default {DEFAULT_HOST}, this machine only); an "
                        "address beyond this machine serves anyone who can reach it")
    p.add_argument("--no-browser", action="store_true",
                   help="print the URL without opening a browser")
    p.add_argument("--verbose", action="store_true", help="log every request on stderr")
    p.set_defaults(handler=run)
    return p


def _add_disk_options(p) -> None:
    """The disk the page starts with, by the options every disk-taking command has (the
    command line's "the disk" group; written here because the explorer sits below
    :mod:`rollingdisk.cli`): the page works in the paper's units, so only its ``h`` is
    used."""
    g = p.add_argument_group(
        "the disk", "The disk the page starts with, one way: --h H alone, --disk NAME, or "
        "--radius/--diameter with --thickness (or with --h); the page works in the paper's "
        "units (m = a = g = 1), so only h = thickness / (2 radius) matters.")
    g.add_argument("--h", type=_type(_h), default=None, metavar="H",
                   help=f"half-thickness / radius, in [{api.H_RANGE[0]:g}, "
                        f"{api.H_RANGE[1]:g}] (default {rd.DEFAULT_H})")
    g.add_argument("--disk", choices=sorted(rd.DISKS), default=None, metavar="NAME",
                   help="a named disk, one of " + ", ".join(sorted(rd.DISKS)))
    g.add_argument("--radius", default=None, metavar="LENGTH",
                   help="radius a, a length with a unit (11.625mm)")
    g.add_argument("--diameter", default=None, metavar="LENGTH",
                   help="diameter 2a instead of --radius (23.25mm)")
    g.add_argument("--thickness", default=None, metavar="LENGTH",
                   help="full thickness 2 h a (2.33mm), with --radius or --diameter")
    g.add_argument("--mass", default=None, metavar="MASS", help="mass (7.5g); not used")
    g.add_argument("--gravity", default=None, metavar="ACCELERATION",
                   help="gravitational acceleration (9.81m/s^2); not used")


def _start_disk(args):
    """``(h, disk)``: the ``h`` the page starts with, from the disk options (checked in the
    page's range), and the disk when it has a physical size (SI values beside), else None."""
    opts = {k: getattr(args, k, None) for k in ("disk", "radius", "diameter", "thickness",
                                                 "mass", "gravity")}
    h = getattr(args, "h", None)
    if h is None and all(v is None for v in opts.values()):
        return rd.DEFAULT_H, None
    disk = rd.disk_from_options(**opts, h=h, option_prefix="--")
    h = check_real("h", disk.h, low=api.H_RANGE[0], high=api.H_RANGE[1])
    return h, (disk if disk.radius is not None else None)


def _say(line: str) -> None:
    print(line, file=sys.stderr, flush=True)


def run(args) -> int:
    """Serve until Ctrl-C; the exit status.

    Parameters
    ----------
    args : argparse.Namespace
        From the parser of :func:`configure`.

    Returns
    -------
    int
        130 after Ctrl-C (the server stopped cleanly); 2 if the address cannot be bound.
    """
    import webbrowser


    h, disk = _start_disk(args)
    # beyond this machine only when asked for by name, and then with a warning (once the
    # address is bound: an address that cannot be is one line, the error)
    host = args.host if args.host is not None else DEFAULT_HOST
    try:
        server = make_server(h, args.ground, host, args.port, verbose=args.verbose,
                             disk=disk)
    except OSError as exc:
        hint = " (choose another with --port, or --port 0 for any free one)" \
            if exc.errno == errno.EADDRINUSE else ""
        _say(f"rollingdisk explore: error: cannot serve on {host}:{args.port}: "
             f"{exc.strerror or exc}{hint}")
        return 2
    if not is_loopback(host):
        _say(f"rollingdisk explore: warning: binding {host}, beyond localhost: anyone who "
             "can reach this machine can use the explorer (there is no authentication)")
    try:
        print(f"rollingdisk explore: serving {server.url}  (Ctrl-C stops)", flush=True)
        if not args.no_browser:
            webbrowser.open(server.url)
        server.serve_forever()
    except KeyboardInterrupt:
        _say("rollingdisk explore: stopped")
        return 130
    finally:
        server.server_close()
    return 0  # pragma: no cover - serve_forever returns only after shutdown()
