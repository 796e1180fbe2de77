"""Settings renamed since result files were first written, and how `charts.io.archive`
reads a file that still holds the old names: each old name becomes its new one, and the
settings say so (``renamed_settings``), so that a reader of the result sees what was mapped.

* ``seed`` read two ways: in a single run it seeded the tangent vectors (now
  ``vectors_seed``); in an ensemble or a tally it was the first member's seed (now
  ``members_seed``; member i had seed + i for its initial state and its vectors, so an old
  ensemble's members get ``state_seed`` = their ``vectors_seed``, `EnsembleResult`).
* ``m``, the dimension of the expanding subspace E_u in CLV and angle results, read as a
  mass: now only ``n_unstable`` (the keyword of the calls), which those files hold too.
"""
from __future__ import annotations

__all__ = ["RENAMED", "renamed", "NOTE"]

#: old name → {kind → new name}; ``None`` as kind: any other kind (a single run, or an
#: ensemble's member, whose settings carry no kind).
RENAMED = {
    "seed": {"ensemble": "members_seed", "angle_tally": "members_seed", None: "vectors_seed"},
    "m": {None: "n_unstable"},
}
#: The setting that records what was renamed on reading.
NOTE = "renamed_settings"


def renamed(params: dict, kind: str | None) -> dict:
    """``params`` with the old names of `RENAMED` replaced for a file of ``kind`` (an old
    value yields to a new one the file also holds), and ``renamed_settings``, a text listing
    "old -> new", where any was; ``params`` itself where none was."""
    if not isinstance(params, dict) or not any(old in params for old in RENAMED):
        return params
    out, done = {}, []
    for key, value in params.items():
        new = RENAMED.get(key, {}).get(kind, RENAMED.get(key, {}).get(None))
        if new is None:
            out[key] = value
            continue
        done.append(f"{key} -> {new}")
        if new not in params:
            out[new] = value
    out[NOTE] = "; ".join(done) + " (a file written before the rename)"
    return out
