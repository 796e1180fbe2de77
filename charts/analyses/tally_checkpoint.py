"""A tally's checkpoint checked before a resume trusts it (``AngleTally.resumed``): its sums
against their shapes, their values and its ``members_done``."""
from __future__ import annotations

import numpy as np

__all__ = ["check_resumed"]


def check_resumed(path, tally, done, fresh) -> int:
    """``done``, the members_done of the checkpoint ``tally`` read from ``path``, as an
    integer once the file is found consistent with ``fresh`` (the sums of an empty tally of
    as many members, ``charts.analyses.angle_tally._sums``: their shapes, and the values of a
    member without angles): each sum of that shape, finite where a sum must be, and the
    members done exactly those with angles (all of one count), those after them empty;
    ValueError naming the file and the field otherwise."""
    def bad(what):
        raise ValueError(f"{path} is not a usable checkpoint: {what}; remove it to start over")
    L = fresh["n"].shape[0]
    if isinstance(done, bool) or not isinstance(done, (int, np.integer)) or not 0 <= done <= L:
        bad(f"members_done = {done!r} is not a count of its {L} members")
    done = int(done)
    for name, empty in fresh.items():
        x = np.asarray(getattr(tally, name))
        if x.shape != empty.shape:
            bad(f"{name} has shape {x.shape}, a tally of {L} members has {empty.shape}")
        if x.dtype.kind not in "iuf":
            bad(f"{name} holds {x.dtype} values, not numbers")
        if name != "min" and not np.all(np.isfinite(x)):
            bad(f"{name} holds non-finite values")
        if np.any(x < (-1 if name == "argmin" else 0)):
            bad(f"{name} holds negative values")
    if np.any(np.isnan(tally.min)):
        bad("min holds NaN")
    with_angles = np.flatnonzero(tally.n > 0)
    if with_angles.size != done or (done and with_angles[-1] != done - 1):
        bad(f"members_done = {done}, but {with_angles.size} of its members have angles (n > 0)"
            + (f", the last member {int(with_angles[-1])}" if with_angles.size else ""))
    if done and np.any(tally.n[:done] != tally.n[0]):
        bad(f"the members done have unequal counts n ({int(tally.n[:done].min())} to "
            f"{int(tally.n[:done].max())}) where each ran the whole window")
    for name, empty in fresh.items():
        x = np.asarray(getattr(tally, name))
        rest, blank = (x[done:], empty[done:]) if name == "n" else (x[:, done:], empty[:, done:])
        if np.any(rest != blank):
            bad(f"{name} holds sums of members past members_done = {done}")
    return done
