"""Symbolic derivation of the chart geometry (SymPy) and emission of ``generated/``:
``symbolic`` derives, ``emit`` writes the source, ``cache`` derives unshipped N on demand,
``names`` holds the names shared with the loaders (no heavy imports)."""
