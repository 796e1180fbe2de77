"""Data files shipped inside the package (``charts/data/scenes``, ``charts/data/sweeps``): listed by
name, and named on the command line either by path or by that name."""
from __future__ import annotations

from importlib import resources
from pathlib import Path

__all__ = ["bundled_files", "path_or_bundled"]


def bundled_files(package: str, suffix: str = ".toml") -> dict[str, Path]:
    """Name (the file name without ``suffix``) -> path of every ``*suffix`` file in the
    package folder ``package`` (e.g. ``"charts.data.scenes"``), sorted by name."""
    folder = resources.files(package)
    return {p.name[: -len(suffix)]: Path(str(p))
            for p in sorted(folder.iterdir(), key=lambda p: p.name) if p.name.endswith(suffix)}


def path_or_bundled(arg: str, bundled: dict[str, Path], suffix: str = ".toml") -> Path | None:
    """The file an argument names: a path when it exists or ends in ``suffix``, else the
    bundled file of that name, else None."""
    p = Path(arg)
    if p.exists() or p.suffix == suffix:
        return p
    return bundled.get(arg)
