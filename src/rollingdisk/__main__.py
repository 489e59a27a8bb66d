"""``python -m rollingdisk``: the command-line interface (signal handlers first)."""

import sys

from rollingdisk.cli.entry import main

sys.exit(main())
