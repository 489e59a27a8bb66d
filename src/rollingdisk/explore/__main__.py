"""``python -m rollingdisk.explore``: the ``rollingdisk explore`` command on its own."""

from __future__ import annotations

import argparse
import sys

from .command import configure, run


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m rollingdisk", allow_abbrev=False)
    sub = parser.add_subparsers(dest="command")
    configure(sub)
    args = parser.parse_args(["explore", *(sys.argv[1:] if argv is None else argv)])
    try:
        return run(args)
    except KeyboardInterrupt:  # Ctrl-C before the server started
        return 130
    except ValueError as exc:  # a bad disk (ParameterError): one line, exit status 2
        print(f"python -m rollingdisk.explore: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
