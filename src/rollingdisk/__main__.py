"""``python -m rollingdisk``: the command-line interface."""

import sys

from rollingdisk.cli.main import main

sys.exit(main())
