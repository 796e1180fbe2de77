"""Statistics of the hyperbolicity angles (section 4) from more samples than memory holds.

The angle test of an ensemble yields its angles block by block, (members × samples); an
`AngleTally` keeps of them only per-member sums, so that 10⁹ angles need a few kilobytes per
member.  The members are independent trajectories, and they are the batches of every error
bar below.  What a tally keeps per member, for both variants (full, restricted):

* the sample count, the smallest angle and the sample at which it fell, exact zeros;
* counts below the edges of a logarithmic grid of angles (the law P(φ < x) near zero);
* for each threshold x₀ of the small-angle law, the count below it and Σ ln(x₀/φ) (Hill's
  estimate of P(φ < x) = A x^β, ``charts.analyses.statistics.law_from_batches``);
* the minima of 10, 100, 1000, … consecutive samples (count, sum, sum of squares): each
  level's minima from the level below, a group left incomplete at the end of a block
  carried into the next;
* episodes: runs of consecutive samples below `SMALL_ANGLE`.

``charts.analyses.hyperbolicity.hyperbolicity_tally`` runs the test and tallies as it goes
(on the GPU the blocks of ``charts.analyses.angle_blocks``; on the CPU the members of
`hyperbolicity_ensemble` in chunks); `AngleTally.statistics` turns the sums into the
verdict's numbers with intervals.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

from ..io.archive import Archivable, attributes, dataset, load
from ..geometry.checks import finite_array, integer, shown
from .singular_values import sin_to_angle
from .statistics import jackknife_slopes, law_from_batches, standard_error
from .tally_checkpoint import check_resumed

__all__ = ["AngleTally", "VARIANTS", "EDGES", "LAW_X0", "LADDER", "JACKKNIFE_GROUPS", "SMALL_ANGLE",
           "carries", "member_bytes"]

#: the two angles of the test, in the order of a tally's first axis.
VARIANTS = ("full", "restricted")
#: the near-tangency threshold (rad): the episodes here, the fraction of small angles of
#: ``charts.analyses.hyperbolicity.angle_statistics``.
SMALL_ANGLE = 0.05
#: edges of the angle grid (rad), ascending: 0.05 · 10^(−j/10), j = 80 … 0 (5e-10 to 0.05).
EDGES = SMALL_ANGLE * 10.0 ** (-np.arange(80, -1, -1) / 10)
#: thresholds x₀ of the small-angle law (rad).
LAW_X0 = (0.05, 0.02, 0.01, 0.005, 0.002)
#: the ladder of block minima: groups of 10 samples, 10 minima, … (sizes 10¹ … 10^LADDER).
LADDER = 9
#: member groups of the jackknife errors of the block-minima slopes.
JACKKNIFE_GROUPS = 32


#: the per-member sums of a tally, its fields in the order of `AngleTally`.
SUMS = ("n", "min", "argmin", "zeros", "below", "law_count", "law_logsum", "ladder_count",
        "ladder_sum", "ladder_sumsq", "episodes")


def _sums(V, L):
    """Zeroed per-member sums of a tally of ``L`` members, for ``V`` variants."""
    return dict(n=np.zeros(L, np.int64), min=np.full((V, L), np.inf),
                argmin=np.full((V, L), -1, np.int64), zeros=np.zeros((V, L), np.int64),
                below=np.zeros((V, L, EDGES.size), np.int64),
                law_count=np.zeros((V, L, len(LAW_X0)), np.int64),
                law_logsum=np.zeros((V, L, len(LAW_X0))),
                ladder_count=np.zeros((V, L, LADDER), np.int64),
                ladder_sum=np.zeros((V, L, LADDER)), ladder_sumsq=np.zeros((V, L, LADDER)),
                episodes=np.zeros((V, L), np.int64))


def member_bytes(V=len(VARIANTS)) -> int:
    """Bytes of one member of a tally of ``V`` variants: its sums, what it carries between
    blocks and its seed (the plan of ``hyperbolicity_tally`` before any allocation)."""
    arrays = list(_sums(V, 1).values()) + list(carries(V, 1).values())
    return sum(a.nbytes for a in arrays) + 8


def carries(V, L):
    """What a tally carries between blocks, per variant: whether each member's last sample
    was below `SMALL_ANGLE`, and the incomplete groups of the ladder's levels; and per member the
    length of a block whose full angles came without their restricted ones yet."""
    out = {"pending": np.zeros(L, np.int64)}   # a block's length, its full angles added
    for v in range(V):
        out[("last", v)] = np.zeros(L, bool)
        for j in range(LADDER):
            out[("carry", v, j)] = np.zeros((L, 9))
    return out


@dataclass(eq=False, repr=False)
class AngleTally(Archivable):
    """Per-member sums of the angles of an ensemble's angle test (module docstring); arrays
    with the axes (variant, member, …) in the order of `VARIANTS`.  ``params``: the system,
    the test's settings (``sample_every`` converts samples to time) and the seeds.
    `add` feeds it, `statistics` reads it."""
    n: np.ndarray
    min: np.ndarray
    argmin: np.ndarray
    zeros: np.ndarray
    below: np.ndarray
    law_count: np.ndarray
    law_logsum: np.ndarray
    ladder_count: np.ndarray
    ladder_sum: np.ndarray
    ladder_sumsq: np.ndarray
    episodes: np.ndarray
    params: dict = field(default_factory=dict)
    #: (members,) each member's seed (its initial state and vectors)
    seeds: np.ndarray | None = None
    _open: dict = field(default_factory=dict)       # carried between blocks: not saved
    #: the variants of the first axis, in the order a block adds them: `VARIANTS`, or
    #: ("restricted",) for a mechanism's angles (its only variant)
    variants: tuple = VARIANTS

    KIND = "angle_tally"

    @classmethod
    def empty(cls, members, params=None, variants=VARIANTS) -> "AngleTally":
        """A tally of ``members`` members with nothing added yet, of the angles ``variants``
        (a tuple of `VARIANTS`' names, in that order)."""
        members = integer("members", members, 1)
        if not isinstance(variants, tuple) or not variants or any(
                v not in VARIANTS for v in variants) or list(variants) != sorted(
                variants, key=VARIANTS.index) or len(set(variants)) != len(variants):
            raise ValueError(f"variants must be a tuple of {VARIANTS} in this order, got "
                             f"{shown(variants)}")
        params = dict(params or {})
        seeds = int(params.get("members_seed", 0)) + np.arange(int(members), dtype=np.int64)
        tally = cls(**_sums(len(variants), int(members)), params=params, seeds=seeds,
                    variants=variants)
        tally._open.update(carries(len(variants), int(members)))
        return tally

    @classmethod
    def merged(cls, tallies) -> "AngleTally":
        """One tally of the members of finished ``tallies`` of the same test on other seeds
        (runs on several machines, or one after another): the members side by side, each
        with its seed.  ValueError where their settings differ (seed and device aside) or a
        seed appears twice."""
        tallies = list(tallies)
        if not tallies or not all(isinstance(t, cls) for t in tallies):
            raise ValueError("merged takes one or more AngleTally")
        own = ("members_seed", "device", "stopped")

        def settings(t):
            return {k: v for k, v in t.params.items() if k not in own}
        if any(settings(t) != settings(tallies[0]) or t.variants != tallies[0].variants
               for t in tallies):
            raise ValueError("the tallies are of different tests (system or settings differ)")
        if any(np.any(t._open.get("pending", np.zeros(1))) for t in tallies):
            raise ValueError("a tally has a block whose restricted angles are missing")
        seeds = np.concatenate([t.seeds for t in tallies])
        if np.unique(seeds).size != seeds.size:
            raise ValueError("a seed appears in more than one tally: its member would count twice")
        arrays = {k: np.concatenate([getattr(t, k) for t in tallies], axis=0 if k == "n" else 1)
                  for k in SUMS}
        params = dict(tallies[0].params, members_seed=int(seeds[0]),
                      device="+".join(sorted({str(t.params.get("device", "?")) for t in tallies})))
        stopped = [s for t in tallies for s in t.params.get("stopped") or []]
        params.pop("stopped", None)
        if stopped:
            params["stopped"] = stopped
        return cls(**arrays, params=params, seeds=seeds, variants=tallies[0].variants)

    @classmethod
    def resumed(cls, path, members, params) -> tuple:
        """(the tally saved at ``path`` by an interrupted run of ``members`` members with
        ``params``, members done): its whole members, ``params["members_done"]`` of them;
        ValueError naming the file where it holds another run's tally, or one whose sums
        disagree with themselves or with its ``members_done``
        (``charts.analyses.tally_checkpoint.check_resumed``): such a
        file would count members twice, or leave some out."""
        try:
            saved = load(path)
        except KeyError as exc:                     # a field the tally needs is not there
            name = re.search(r"'([^']+)'", str(exc))
            raise ValueError(f"{path} is not a usable checkpoint: the field "
                             f"{name.group(0) if name else exc} is missing; remove it to "
                             "start over") from None
        kept = getattr(saved, "params", {})
        if not isinstance(saved, AngleTally) or "members_done" not in kept \
                or {k: v for k, v in kept.items() if k != "members_done"} != params \
                or np.shape(saved.n) != (members,):
            raise ValueError(f"{path} holds the tally of another run; remove it or name "
                             "another checkpoint")
        V = len(saved.variants)
        done = check_resumed(path, saved, saved.params.pop("members_done"), _sums(V, members))
        saved._open.update(carries(V, members))     # whole members: no carry
        return saved, done

    @property
    def n_members(self) -> int:
        return self.n.size

    def add(self, phi, first=0, variant="restricted"):
        """Tally the angles ``phi`` (rad; (l, s): the next s samples of members first …
        first + l − 1, or of the members listed in ``first``, in increasing order; they must
        have seen equally many samples before) of ``variant``.  Call it once per variant for
        each block, with the same shapes; the sample count advances after the last variant
        of `VARIANTS` is added."""
        self._add(finite_array("phi", phi, ndim=2), first, variant, "angles", _same)

    def add_sines(self, sines, first=0, variant="restricted"):
        """`add` for the sines of the angles, as the angle test computes them (φ =
        arcsin of the sine clipped to [0, 1], `sin_to_angle`): only the sines below
        sin(`SMALL_ANGLE`) and the minima are turned into angles, with the same result."""
        self._add(finite_array("sines", sines, ndim=2), first, variant, "sines", sin_to_angle)

    def add_both(self, sines_full, sines_restricted, threads=1, alive=None):
        """`add_sines` of one block of every member, both variants (each (members, s)), the
        members split among ``threads`` threads (NumPy works without the GIL); ``alive``
        (members,) bool: only those members (the others stopped: their block is left out)."""
        from concurrent.futures import ThreadPoolExecutor
        live = np.arange(self.n_members) if alive is None else np.flatnonzero(alive)
        if live.size == 0:
            return
        parts = np.array_split(live, max(1, min(int(threads), live.size)))

        def part(rows):
            self.add_sines(sines_full[rows], rows, "full")
            self.add_sines(sines_restricted[rows], rows, "restricted")
        if len(parts) == 1:
            part(parts[0])
            return
        with ThreadPoolExecutor(len(parts)) as pool:
            list(pool.map(part, parts))

    def _add(self, x, first, v, kind, angle):
        v = _variant(v, self.variants)
        if ("last", v) not in self._open:
            raise ValueError("this tally was loaded from a file: it is complete, and what "
                             "it carried between blocks was not saved")
        l, s = x.shape
        rows = np.asarray(first)
        if not np.issubdtype(rows.dtype, np.integer) or rows.ndim > 1:
            raise ValueError(f"first must be a member index or an array of them, got {first!r}")
        rows = np.arange(int(first), int(first) + l) if rows.ndim == 0 else rows.astype(np.int64)
        if l == 0 or s == 0 or rows.shape != (l,) or rows[0] < 0 or rows[-1] >= self.n_members \
                or np.any(np.diff(rows) <= 0):
            raise ValueError(f"a block of shape {x.shape} from member {first} does not fit a "
                             f"tally of {self.n_members} members")
        if self._open.setdefault("input", kind) != kind:
            raise ValueError(f"this tally was fed {self._open['input']}, not {kind}")
        before = self.n[rows]
        if np.any(before != before[0]):
            raise ValueError("the members of one block must have seen equally many samples")
        pending = self._open["pending"]
        if v == 0 and np.any(pending[rows]):
            raise ValueError("the restricted angles of the last block are missing: add each "
                             "block's full angles, then its restricted ones")
        if v > 0 and np.any(pending[rows] != s):
            raise ValueError("add each block's full angles first, then its restricted ones, "
                             "of the same members and samples")
        n0 = int(before[0])
        if kind == "angles" and np.any(x < 0):
            raise ValueError("angles must be ≥ 0")
        j = x.argmin(axis=1)
        low = angle(x[np.arange(l), j])
        zero = low == 0                 # several sines ≤ 0: the first, as of their angles
        if np.any(zero):
            j[zero] = (x[zero] <= 0).argmax(axis=1)
        better = low < self.min[v, rows]
        self.min[v, rows] = np.where(better, low, self.min[v, rows])
        self.argmin[v, rows] = np.where(better, n0 + j, self.argmin[v, rows])
        self._small(v, rows, x, angle)
        self._ladder(v, rows, x, n0, angle)
        if v < len(self.variants) - 1:
            pending[rows] = s
        else:                           # the block's last variant: its samples count
            pending[rows] = 0
            self.n[rows] += s

    def _small(self, v, rows, x, angle):
        """Zeros, the grid counts, the law's sums and the episodes of the samples below
        `SMALL_ANGLE`: the candidates found on ``x``, then decided on their angles."""
        l = x.shape[0]
        below = x < (SMALL_ANGLE if angle is _same else np.sin(SMALL_ANGLE) * (1 + 1e-9))
        flat = np.flatnonzero(below)
        phi = angle(x.ravel()[flat] if x.flags.c_contiguous else x[below])
        out = phi >= SMALL_ANGLE
        below.ravel()[flat[out]] = False
        r, phi = flat[~out] // x.shape[1], phi[~out]
        last = self._open[("last", v)]
        starts = (below[:, 0] & ~last[rows]).astype(np.int64)
        starts += (below[:, 1:] & ~below[:, :-1]).sum(axis=1)
        self.episodes[v, rows] += starts
        last[rows] = below[:, -1]
        self.zeros[v, rows] += np.bincount(r[phi == 0], minlength=l)
        E = EDGES.size
        # edge e counts φ < EDGES[e]: searchsorted gives the edges ≤ φ, the first edge above
        first_above = np.searchsorted(EDGES, phi, side="right")
        hist = np.bincount(r * (E + 1) + first_above, minlength=l * (E + 1)).reshape(l, E + 1)
        self.below[v, rows] += np.cumsum(hist, axis=1)[:, :E]
        for i, x0 in enumerate(LAW_X0):
            sel = (phi < x0) & (phi > 0)
            self.law_count[v, rows, i] += np.bincount(r[sel], minlength=l)
            self.law_logsum[v, rows, i] += np.bincount(r[sel], weights=np.log(x0 / phi[sel]),
                                                       minlength=l)

    def _ladder(self, v, rows, x, n0, angle):
        """Minima of 10ʲ consecutive samples, each level from the one below (the first on
        ``x``, then turned into angles: the angle grows with its sine); the incomplete group
        at a block's end carried to the next block (at level j a member that has seen n
        samples carries ⌊n / 10ʲ⌋ mod 10 values: equal for the members of a block)."""
        for j in range(LADDER):
            carry = self._open[("carry", v, j)]
            c = n0 // 10 ** j % 10
            if c:
                x = np.concatenate([carry[rows, :c], x], axis=1)
            g, rest = divmod(x.shape[1], 10)
            carry[rows, :rest] = x[:, g * 10:]
            if g == 0:
                break
            mins = x[:, :g * 10].reshape(x.shape[0], g, 10).min(axis=2)
            if j == 0:
                mins = angle(mins)
            self.ladder_count[v, rows, j] += g
            self.ladder_sum[v, rows, j] += mins.sum(axis=1)
            self.ladder_sumsq[v, rows, j] += (mins * mins).sum(axis=1)
            x = mins

    # ---- reading it -------------------------------------------------------------------
    def statistics(self, variant="restricted") -> dict:
        """The numbers of the verdict for ``variant``, JSON-ready, every error bar from the
        spread between members (independent trajectories):

        * ``n``, ``members``, ``min`` with the ``min_seed`` and ``min_t`` where it fell,
          ``zeros`` (angles of exactly 0);
        * ``cdf``: [x, P(φ < x), standard error] on the grid `EDGES` where any angle fell;
        * ``law``: `law_from_batches` (Hill's β̂ ± se, A for β = 2 ± se) at each x₀ of
          `LAW_X0` (None where undefined: no angle below x₀, or the errors where fewer than
          two members have one);
        * ``block_minima``: [size in samples, members' mean minimum, se] per size 10ʲ (j ≥ 1)
          that a member holds, and ``slopes``: d ln(mean minimum) / d ln(size) between
          neighbouring sizes with jackknife errors over `JACKKNIFE_GROUPS` groups of members
          (−1/β for a law A x^β near zero, 0 for angles bounded away from zero);
        * ``episodes`` (runs below `SMALL_ANGLE`), their rate per time unit and mean length in
          samples.

        Every number is finite or None (an error bar from fewer than two members, a time
        without ``sample_every`` in ``params``)."""
        v = _variant(variant, self.variants)
        has = self.n > 0                # a member that stopped in its first block has none
        n = self.n[has].astype(float)
        N = int(self.n.sum())
        if N == 0:
            raise ValueError("the tally holds no angles yet")
        dt = float(self.params.get("sample_every", np.nan))
        l = int(np.argmin(self.min[v]))
        out = dict(variant=self.variants[v], n=N, members=self.n_members,
                   min=float(self.min[v, l]), min_seed=int(self.seeds[l]),
                   min_t=float(self.params.get("t_transient", 0.0) + self.argmin[v, l] * dt),
                   zeros=int(self.zeros[v].sum()), small=SMALL_ANGLE)
        below = self.below[v][has]
        out["cdf"] = [[float(x), float(below[:, e].sum() / N),
                       float(standard_error(below[:, e] / n))]
                      for e, x in enumerate(EDGES) if below[:, e].any()]
        out["law"] = [_finite_or_none(law_from_batches(int(self.law_count[v, :, i].sum()),
                                       float(self.law_logsum[v, :, i].sum()), N,
                                       self.law_count[v, has, i], self.law_logsum[v, has, i],
                                       self.law_count[v, has, i] / n, x0))
                      for i, x0 in enumerate(LAW_X0)]
        count, total = self.ladder_count[v], self.ladder_sum[v]
        levels = [j for j in range(LADDER) if np.count_nonzero(count[:, j])]
        with np.errstate(invalid="ignore", divide="ignore"):
            means = np.where(count > 0, total / count, np.nan)[:, levels]
        out["block_minima"] = [[10 ** (j + 1), float(np.nanmean(means[:, i])),
                                float(standard_error(means[~np.isnan(means[:, i]), i]))]
                               for i, j in enumerate(levels)]
        out["slopes"] = [[10 ** (levels[i] + 1), 10 ** (levels[i + 1] + 1), *slope]
                         for i, slope in enumerate(jackknife_slopes(means, JACKKNIFE_GROUPS))]
        stopped = self.params.get("stopped") or []
        out["stopped"] = [list(x) for x in stopped]
        ep = int(self.episodes[v].sum())
        out.update(episodes=ep, episode_rate=ep / (N * dt),
                   episode_length=float(self.below[v, :, -1].sum() / ep) if ep else None)
        return _finite_or_none(out)

    def plot(self, ax=None, variant="restricted", **kw):
        """The law of the small angles and the block minima of ``variant``
        (``charts.plotting.plot_angle_law``), ``(fig, axes)``."""
        from ..plotting import plot_angle_law
        kw.setdefault("sample_every", float(self.params.get("sample_every", 0.1)))
        kw.setdefault("title", f"smallest angles between $E_u$ and $E_{{cs}}$ ({variant})")
        label = f"N = {self.params['n']}" if "n" in self.params else variant
        return plot_angle_law({label: self.statistics(variant)}, axes=ax, **kw)

    def summary_parts(self):
        if not self.n.any():
            return [f"no angles yet, {self.n_members} members"]
        s = self.statistics("restricted")
        return [f"{s['n']:.3g} angles of {s['members']} members",
                f"min φ restricted {s['min']:.3g} rad"]

    def to_xarray(self):
        """This tally as an ``xarray.Dataset`` (``charts.io.archive``)."""
        member = ("variant", "member")
        return dataset(self.KIND, {
            "n": (("member",), self.n, "1", "angles per member"),
            "min": (member, self.min, "rad", "smallest angle"),
            "argmin": (member, self.argmin, "1", "sample index of the smallest angle"),
            "zeros": (member, self.zeros, "1", "angles of exactly 0"),
            "below": (member + ("edge",), self.below, "1", "angles below the edge"),
            "law_count": (member + ("x0",), self.law_count, "1", "angles below x0"),
            "law_logsum": (member + ("x0",), self.law_logsum, "1",
                           "sum of ln(x0/phi) over the angles below x0"),
            "ladder_count": (member + ("size",), self.ladder_count, "1", "blocks"),
            "ladder_sum": (member + ("size",), self.ladder_sum, "rad",
                           "sum of the blocks' minima"),
            "ladder_sumsq": (member + ("size",), self.ladder_sumsq, "rad2",
                             "sum of the squared minima"),
            "episodes": (member, self.episodes, "1",
                         f"runs of consecutive angles below {SMALL_ANGLE} rad"),
            "state_seed": (("member",), self.seeds, "1",
                           "the seed of the member's initial state (RotorSystem.random_state) "
                           "and of its tangent vectors")},
            coords={"variant": (("variant",), np.array(self.variants), "1"),
                    "edge": (("edge",), EDGES, "rad"),
                    "x0": (("x0",), np.array(LAW_X0), "rad"),
                    "size": (("size",), 10 ** np.arange(1, LADDER + 1), "1",
                             "consecutive samples per block")},
            attrs={"params": self.params})

    @classmethod
    def from_xarray(cls, ds):
        # "seed": the name of the members' state seeds in files written before the rename
        seeds = ds["state_seed"] if "state_seed" in ds else ds["seed"]
        return cls(**{k: ds[k].values for k in SUMS}, params=attributes(ds)["params"],
                   seeds=seeds.values, variants=tuple(str(v) for v in ds["variant"].values))


def _finite_or_none(x):
    """``x`` (nested dicts and lists) with every non-finite float as None: JSON as it is."""
    if isinstance(x, dict):
        return {k: _finite_or_none(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_finite_or_none(v) for v in x]
    if isinstance(x, float) and not np.isfinite(x):
        return None
    return x


def _same(x):
    return x


def _variant(variant, variants=VARIANTS) -> int:
    if not isinstance(variant, str) or variant not in variants:
        raise ValueError(f"variant must be one of {variants}, got {shown(variant)}")
    return variants.index(variant)
