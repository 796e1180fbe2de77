"""Data shipped inside the package: the bundled scenes (``scenes/``) and sweeps (``sweeps/``),
TOML files listed by ``charts scenes`` and ``charts sweep --list``."""
