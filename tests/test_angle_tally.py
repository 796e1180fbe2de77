"""Angle statistics at scale (``charts.analyses.angle_tally``): the streamed per-member sums
against the whole-array routes of ``charts.analyses.statistics``, the sines route against
the angles route, the GPU route's blocks (its CPU twin) against the sines kept whole."""
import numpy as np
import pytest

from charts.analyses.angle_blocks import angles_on_device
from charts.analyses.angle_tally import EDGES, LAW_X0, VARIANTS, AngleTally
from charts.analyses.forward_pass import angle_settings
from charts.analyses.hyperbolicity import hyperbolicity_ensemble
from charts.analyses.tally_run import StoppedMember, hyperbolicity_tally, tally_on_device
from charts.analyses.singular_values import sin_to_angle
from charts.analyses.statistics import block_minima, small_value_law
from charts.geometry.system import RotorSystem

FIELDS = ("n", "min", "argmin", "zeros", "below", "law_count", "law_logsum", "ladder_count",
          "ladder_sum", "ladder_sumsq", "episodes")


def _angles(L, S, seed=0):
    """Angles with a law A x² near 0 (|φ| of a 2-d Gaussian), a few exact zeros."""
    rng = np.random.default_rng(seed)
    phi = np.hypot(*rng.normal(size=(2, L, S))) * 0.3
    phi[0, min(17, S - 1)] = 0.0
    return phi


def _fed(phi_full, phi_restricted, cuts):
    t = AngleTally.empty(phi_full.shape[0], dict(sample_every=0.1))
    for a, b in zip(cuts[:-1], cuts[1:]):
        t.add(phi_full[:, a:b], variant="full")
        t.add(phi_restricted[:, a:b], variant="restricted")
    return t


def _same(a, b, rtol=0.0):
    for f in FIELDS:
        x, y = getattr(a, f), getattr(b, f)
        if x.dtype.kind == "f":
            np.testing.assert_allclose(x, y, rtol=rtol, atol=0, err_msg=f)
        else:
            assert np.array_equal(x, y), f


def test_blocks_of_any_length_give_the_sums_of_the_whole():
    """Fed in blocks of 7, 993, 1000 and 345 samples or at once: the same counts, minima,
    ladder and episodes (the carried groups and runs); sums to rounding (summed in another
    order)."""
    f, r = _angles(5, 2345, 1), _angles(5, 2345, 2)
    _same(_fed(f, r, [0, 7, 1000, 2000, 2345]), _fed(f, r, [0, 2345]), rtol=1e-13)


def test_the_statistics_equal_the_whole_array_routes():
    """Every number of `statistics` from the routes that hold the whole sample: the minimum
    and where it fell, P(φ < x) on the grid, Hill's law (`small_value_law` of all samples:
    the counts and log sums add), the block minima (`block_minima` of the members' series),
    the episodes counted one by one."""
    L, S = 4, 30000
    phi = _angles(L, S, 3)
    t = _fed(phi, phi, [0, 12345, S])
    s = t.statistics("restricted")
    assert s["n"] == L * S and s["zeros"] == 1 and s["min"] == 0.0
    l, j = np.unravel_index(np.argmin(phi), phi.shape)
    assert (s["min_seed"], s["min_t"]) == (l, j * 0.1)
    for x, p, _ in s["cdf"]:
        assert p == (phi < x).mean()
    pos = phi[phi > 0]
    for law, x0 in zip(s["law"], LAW_X0):
        whole = small_value_law(np.where(phi > 0, phi, 1.0).ravel(), x0)
        assert law["count"] == whole["count"] == (pos < x0).sum()
        assert law["exponent"] == pytest.approx(whole["exponent"], rel=1e-12)
        assert law["coef2"] * (L * S) == pytest.approx(whole["coef2"] * whole["n"], rel=1e-12)
    sizes = [size for size, _, _ in s["block_minima"]]
    assert sizes == [10, 100, 1000, 10000]
    for (size, mean, se), ref in zip(s["block_minima"], block_minima(phi, sizes)):
        assert mean == pytest.approx(ref["mean"], rel=1e-12)
    below = phi < 0.05
    runs = below[:, 0].sum() + (below[:, 1:] & ~below[:, :-1]).sum()
    assert s["episodes"] == runs
    assert s["episode_length"] == pytest.approx(below.sum() / runs)


def test_the_law_and_the_slopes_find_a_known_law_within_their_errors():
    """Independent angles with P(φ < x) ∝ x² near 0: Hill's β̂ within 4 of its standard
    errors of 2, the block minima's slopes within 4 errors of −1/β = −0.5 (as far as the
    law holds: sizes from 1000 samples, whose minima lie below 0.05)."""
    t = _fed(*(_angles(64, 20000, s) for s in (4, 5)), [0, 20000])
    s = t.statistics()
    for law in s["law"][:3]:
        assert abs(law["exponent"] - 2) < 4 * law["exponent_se"]
    for a, b, slope, se in s["slopes"]:
        if a >= 1000:
            assert abs(slope + 0.5) < 4 * se


def test_sines_give_what_their_angles_give():
    """`add_sines` turns only the candidates below sin(0.05) and the minima into angles:
    the same tally as `add` of all the angles (the angle grows with its sine)."""
    rng = np.random.default_rng(6)
    sines = np.clip(np.abs(rng.normal(size=(3, 3000))) * 0.2, 0, 1)
    sines[1, 5] = -1e-17                                    # rounding below 0: an angle 0
    a = AngleTally.empty(3)
    b = AngleTally.empty(3)
    for v in VARIANTS:
        a.add_sines(sines, variant=v)
        b.add(sin_to_angle(sines), variant=v)
    _same(a, b)
    assert a.zeros[0, 1] == 1


def test_threads_split_the_members_without_changing_a_bit():
    f, r = _angles(7, 1234, 8), _angles(7, 1234, 9)
    sf, sr = np.sin(f), np.sin(r)
    one, three = AngleTally.empty(7), AngleTally.empty(7)
    one.add_both(sf, sr, threads=1)
    three.add_both(sf, sr, threads=3)
    _same(one, three)


def test_the_device_route_tallies_the_sines_it_would_return():
    """The GPU route's logic (its CPU twin, three blocks): the sines consumed block by block
    give the tally of the sines it returns whole (sums to rounding)."""
    S = RotorSystem(4)
    cfg = angle_settings(S, 6.0, t_transient=2.0, checkpoint_every=1.0)
    seeds = [3, 4, 5]
    sf, sr, *_ = angles_on_device(S, cfg, seeds, 1.0, backend="cpu", block=200)
    whole = AngleTally.empty(3)
    whole.add_both(sf, sr)
    got = tally_on_device(S, cfg, AngleTally.empty(3, dict(members_seed=3)), 1.0, backend="cpu",
                          block=200)
    assert got.n.tolist() == [60] * 3
    _same(got, whole, rtol=1e-13)         # the ladder's sums added block by block


def test_the_cpu_route_tallies_the_ensemble():
    """`hyperbolicity_tally` on the CPU: the members of `hyperbolicity_ensemble`, tallied;
    saved and loaded equal; one line of repr."""
    S = RotorSystem(3)
    kw = dict(t_transient=1.0, seed=2, workers=1)
    t = hyperbolicity_tally(S, 3, 4.0, chunk=2, **kw)
    ens = hyperbolicity_ensemble(S, 3, 4.0, **kw)
    ref = AngleTally.empty(3)
    for i, m in enumerate(ens.members):
        ref.add(m.phi_full[None], i, "full")
        ref.add(m.phi_restricted[None], i, "restricted")
    _same(t, ref)
    assert t.params["members_seed"] == 2 and t.params["sample_every"] == 0.1
    assert t.statistics()["min_seed"] in (2, 3, 4)
    assert "\n" not in repr(t) and "angles of 3 members" in repr(t)


def test_the_cpu_tally_runs_all_its_chunks_in_one_pool(monkeypatch):
    """Three chunks on two workers: one process pool for the whole tally (none started per
    chunk), and the tally of the run in one process."""
    assert np.diff(np.linspace(0, 6, 6 // 2 + 1).round()).tolist() == [2, 2, 2]
    import charts.analyses.ensemble as ens_mod
    import charts.analyses.tally_run as hyp
    S = RotorSystem(3)
    kw = dict(t_transient=1.0, seed=4, chunk=2)
    ref = hyperbolicity_tally(S, 6, 2.0, workers=1, **kw)
    started = []

    real = hyp.worker_pool

    def counted(max_workers, *a, **k):
        started.append(max_workers)
        return real(max_workers, *a, **k)
    monkeypatch.setattr(hyp, "worker_pool", counted)
    monkeypatch.setattr(ens_mod, "worker_pool", counted)
    got = hyperbolicity_tally(S, 6, 2.0, workers=2, **kw)
    assert started == [2]
    _same(got, ref)


def test_saved_and_loaded(tmp_path):
    pytest.importorskip("xarray")
    from charts import load
    t = _fed(_angles(3, 500), _angles(3, 500, 1), [0, 500])
    t.params.update(n=4, members_seed=0)
    t._open.clear()
    back = load(t.save(tmp_path / "tally.nc"))
    assert back == t and back.statistics() == t.statistics()
    with pytest.raises(ValueError, match="loaded from a file"):
        back.add(_angles(3, 10))


def test_bad_blocks_are_refused():
    t = AngleTally.empty(3)
    with pytest.raises(ValueError, match="variant"):
        t.add(_angles(3, 10), variant="both")
    with pytest.raises(ValueError, match="does not fit"):
        t.add(_angles(4, 10))
    with pytest.raises(ValueError, match="≥ 0"):
        t.add(-_angles(3, 10), variant="full")
    with pytest.raises(ValueError, match="finite"):
        t.add(np.full((3, 10), np.nan), variant="full")
    with pytest.raises(ValueError, match="no angles"):
        t.statistics()
    for v in VARIANTS:
        t.add(_angles(2, 10), variant=v)
    with pytest.raises(ValueError, match="equally many"):
        t.add(_angles(3, 10), variant="full")
    with pytest.raises(ValueError, match="sines"):
        t.add_sines(np.ones((1, 10)), first=2, variant="full")
    with pytest.raises(ValueError, match="members"):
        AngleTally.empty(0)
    assert EDGES[-1] == 0.05


def test_a_member_that_stops_keeps_its_earlier_blocks(monkeypatch):
    """A member that stops (at a singular point) on the GPU route is frozen, not raised: the
    tally keeps its blocks before the stop, records it and warns; the others go on."""
    import charts.analyses.tally_run as hyp
    phi = _angles(3, 300, 11)

    def fake(system, cfg, seeds, speed, consume, **kw):
        consume(np.sin(phi[:, :100]), np.sin(phi[:, :100]), [])
        stop = [(1, seeds[1], 12.5, "stopped at a singular point")]
        consume(np.sin(phi[:, 100:200]), np.sin(phi[:, 100:200]), stop)
        consume(np.sin(phi[:, 200:]), np.sin(phi[:, 200:]), stop)
    monkeypatch.setattr(hyp, "angles_on_device", fake)
    with pytest.warns(StoppedMember, match="singular point"):
        t = tally_on_device(None, None,
                            AngleTally.empty(3, dict(members_seed=7, sample_every=0.1)),
                            1.0, backend="cpu")
    assert t.n.tolist() == [300, 100, 300]
    assert t.params["stopped"] == [[8, 12.5]]
    s = t.statistics()
    assert s["n"] == 700 and s["stopped"] == [[8, 12.5]]
    assert s["min"] == pytest.approx(min(phi[0].min(), phi[1, :100].min(), phi[2].min()))


@pytest.mark.parametrize("workers", [1, 2])
def test_an_interrupted_cpu_tally_goes_on_from_its_checkpoint(tmp_path, monkeypatch, workers):
    """On the CPU the tally of the members done is saved after each chunk merged; a run
    interrupted while merging its second chunk and called again goes on from there, to the
    tally of a run never interrupted, and removes it; a checkpoint of another run is
    refused.  In this process and in a pool of two; resumed with another chunk size too."""
    pytest.importorskip("xarray")
    import charts.analyses.tally_run as hyp
    S = RotorSystem(3)
    kw = dict(t_transient=1.0, workers=workers)
    whole = hyperbolicity_tally(S, 5, 3.0, chunk=2, **kw)
    real, calls = hyp._merge_chunk, []

    def cut(*a, **k):
        calls.append(1)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(*a, **k)
    monkeypatch.setattr(hyp, "_merge_chunk", cut)
    path = tmp_path / "partial.nc"
    with pytest.raises(KeyboardInterrupt):
        hyperbolicity_tally(S, 5, 3.0, checkpoint=path, chunk=2, **kw)
    monkeypatch.setattr(hyp, "_merge_chunk", real)
    from charts import load
    assert load(path).params["members_done"] == 2 and load(path).n[:2].tolist() == [30, 30]
    with pytest.raises(ValueError, match="another run"):
        hyperbolicity_tally(S, 5, 4.0, checkpoint=path, chunk=2, **kw)
    resumed = hyperbolicity_tally(S, 5, 3.0, checkpoint=path, chunk=3 if workers == 1 else 2,
                                  **kw)
    _same(resumed, whole)
    assert resumed.params == whole.params and not path.exists()


def test_the_variants_come_in_order_and_blocks_as_asked():
    """Each block: its full angles, then its restricted ones, of the same members and
    samples; anything else is refused before it changes the tally.  A member index must be
    an integer."""
    phi = _angles(2, 30, 12)
    t = AngleTally.empty(2)
    with pytest.raises(ValueError, match="full angles first"):
        t.add(phi[:, :10], variant="restricted")
    t.add(phi[:, :10], variant="full")
    with pytest.raises(ValueError, match="restricted angles of the last block are missing"):
        t.add(phi[:, 10:20], variant="full")
    with pytest.raises(ValueError, match="same members and samples"):
        t.add(phi[:, :7], variant="restricted")
    t.add(phi[:, :10], variant="restricted")
    assert t.n.tolist() == [10, 10]
    with pytest.raises(ValueError, match="member index"):
        t.add(phi[:1, 10:20], first=1.7, variant="full")


def test_several_zero_sines_give_the_first_zero_as_the_angles_do():
    sines = np.full((1, 12), 0.5)
    sines[0, [3, 7]] = [-1e-17, -1e-16]
    a, b = AngleTally.empty(1), AngleTally.empty(1)
    for v in VARIANTS:
        a.add_sines(sines, variant=v)
        b.add(sin_to_angle(sines), variant=v)
    assert a.argmin.tolist() == b.argmin.tolist() == [[3], [3]]


def test_statistics_are_json_even_where_undefined():
    """One member: no error bars (None), block minima of every size it holds; an empty
    tally prints as one line."""
    import json
    assert "no angles yet" in repr(AngleTally.empty(2))
    t = _fed(_angles(1, 2000, 13), _angles(1, 2000, 14), [0, 2000])
    t.params.pop("sample_every")
    s = t.statistics()
    json.dumps(s, allow_nan=False)
    assert s["min_t"] is None and s["episode_rate"] is None
    assert [size for size, _, se in s["block_minima"]] == [10, 100, 1000]
    assert all(se is None for _, _, se in s["block_minima"])


def test_tallies_of_other_seeds_merge_into_the_tally_of_all():
    """Members run apart (two machines, say) and merged: the tally of one run of them all,
    each member with its seed; the same seed twice or another test is refused."""
    S = RotorSystem(3)
    kw = dict(t_transient=1.0, workers=1)
    whole = hyperbolicity_tally(S, 4, 2.0, seed=5, **kw)
    parts = [hyperbolicity_tally(S, 2, 2.0, seed=s, **kw) for s in (7, 5)]
    merged = AngleTally.merged(parts)
    order = np.argsort(merged.seeds)
    for f in FIELDS:
        x = getattr(merged, f)
        x = x[order] if f == "n" else x[:, order]
        assert np.array_equal(x, getattr(whole, f)), f
    assert merged.statistics()["min"] == whole.statistics()["min"]
    assert merged.statistics()["min_seed"] == whole.statistics()["min_seed"]
    with pytest.raises(ValueError, match="appears in more than one"):
        AngleTally.merged([parts[0], parts[0]])
    with pytest.raises(ValueError, match="different tests"):
        AngleTally.merged([parts[0], hyperbolicity_tally(S, 2, 3.0, seed=1, **kw)])
