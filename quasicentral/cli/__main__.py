"""``python -m quasicentral.cli``: the command."""

import sys

from quasicentral.cli import main

sys.exit(main())
