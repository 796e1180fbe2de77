"""The command line: ``charts run | scenes | reproduce | sweep | bench | generate``."""
from .main import build_parser, bundled_scenes, main, resolve_scene

__all__ = ["main", "build_parser", "bundled_scenes", "resolve_scene"]
