"""``python -m charts …``: the same as the ``charts`` command."""
import sys

from charts.cli import main

sys.exit(main())
