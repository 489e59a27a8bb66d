"""The ``rollingdisk`` command line: one module per command, the parser and the exit-status
contract in :mod:`.app`, the console script's entry (signal handlers first) in :mod:`.entry`.
"""

from rollingdisk.util.lazy import attach as _attach

__getattr__, __dir__, __all__ = _attach(__name__, {
    "main": "rollingdisk.cli.entry",
    "build_parser": "rollingdisk.cli.app",
})
