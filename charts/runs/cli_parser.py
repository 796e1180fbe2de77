"""Argument parsing shared by every ``charts`` command (the CLI and the runs' own parsers):
errors in one line, ``charts: error: …``, exit status 2; counts checked by argparse."""
from __future__ import annotations

import argparse
import sys

__all__ = ["OneLineParser", "positive_count", "EXIT_USAGE"]

EXIT_USAGE = 2


class OneLineParser(argparse.ArgumentParser):
    """An ``ArgumentParser`` whose usage errors are one line on stderr (no usage block)."""

    def error(self, message):
        print(f"charts: error: {self.prog}: {message} (see `{self.prog} --help`)",
              file=sys.stderr)
        sys.exit(EXIT_USAGE)


def positive_count(text: str) -> int:
    """argparse type of ``--workers``-like options: an integer >= 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be an integer >= 1, got {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be an integer >= 1, got {value}")
    return value
