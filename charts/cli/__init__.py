"""The command line: ``charts run | scenes | reproduce | sweep | bench | generate``."""
from .main import build_parser, bundled_scenes, console, main, resolve_scene

__all__ = ["main", "console", "build_parser", "bundled_scenes", "resolve_scene"]
