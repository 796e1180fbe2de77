"""The version of charts (one place; read by the package, the CLI and result files)."""

__version__ = "0.1.0"
