"""``python -m charts …``: the same as the ``charts`` command."""
import sys

from charts.cli import main

if __name__ == "__main__":
    sys.exit(main())
