"""The ``rollingdisk`` command line (:mod:`rollingdisk.cli.main`; one module per command)."""

from rollingdisk.cli.main import build_parser, main

__all__ = ["main", "build_parser"]
