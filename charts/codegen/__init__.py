"""Symbolic derivation of the chart geometry (SymPy) and emission of ``generated/``:
``symbolic`` derives, ``emit`` writes the source, ``cache`` derives unshipped N on demand,
``names`` holds the names shared with the loaders (no heavy imports); ``mechanism`` derives
and writes a mechanism's jets (shipped or cached, found by the key of its model)."""
