"""Bundled sweep files (``charts sweep --list``)."""
