"""Argument parsing shared by every ``charts`` command (the CLI and the runs' own parsers):
errors in one line, ``charts: error: …``, exit status 2; counts checked by argparse."""
from __future__ import annotations

import argparse
import sys

__all__ = ["OneLineParser", "positive_count", "transient_arg", "EXIT_USAGE"]

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


def transient_arg(text: str):
    """argparse type of ``--t-transient``: a number of time units, or the name of a
    transient rule ("scaled", "auto": ``charts.analyses.transients``)."""
    import difflib

    from ..analyses.transients import TRANSIENT_RULES
    if text in TRANSIENT_RULES:
        return text
    try:
        return float(text)
    except ValueError:
        near = difflib.get_close_matches(text, TRANSIENT_RULES, n=1, cutoff=0.5)
        hint = f" (did you mean {near[0]!r}?)" if near else ""
        raise argparse.ArgumentTypeError(f"must be a number of time units, 'scaled' or 'auto', "
                                         f"got {text!r}{hint}") from None
