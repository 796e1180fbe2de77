"""``python -m charts …``: the same as the ``charts`` command."""
import sys

from charts.cli import console

if __name__ == "__main__":
    sys.exit(console())
