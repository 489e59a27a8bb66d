"""``python -m rollingdisk``: the command-line interface (signal handlers first)."""

import sys

from rollingdisk_cli import main

sys.exit(main())
