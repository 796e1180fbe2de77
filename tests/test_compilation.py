"""The kernels' one-time compilation is timed and announced (charts.jit.compilation)."""


def test_a_long_compilation_is_announced_once(monkeypatch, capsys):
    """An entry point that spent more than NOTE_SECONDS compiling says so on stderr, once,
    naming itself and N; nested entry points (and scenes, which time their own) stay quiet."""
    import numba

    from charts.jit import compilation

    monkeypatch.setattr(compilation, "NOTE_SECONDS", 0.0)

    @compilation.announces_compilation
    def outer(system):
        inner(system)
        return numba.njit(lambda x: x + 1)(1)      # a fresh function: numba compiles it

    @compilation.announces_compilation
    def inner(system):
        return numba.njit(lambda x: x * 2)(1)

    class Sys:
        n = 7

    assert outer(Sys()) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("charts: outer compiled its kernels for N = 7 in ")
    seen = []
    with compilation.compile_timer(seen.append):
        inner(Sys())
    assert capsys.readouterr().err == "" and sum(seen) > 0.0


_TOY = '''
from numba import njit

@njit(cache=True)
def kernel(x):
    s = 0.0
    for i in range(x):
        s += i ** 0.5
    return s

def job(x):
    return [kernel(x)]
'''

_POOL = '''
import sys
sys.path.insert(0, sys.argv[1])
import toy
from charts.jit import compilation
from charts.analyses.ensemble import map_jobs
compilation.NOTE_SECONDS = 0.0
prime = (toy.job, 3) if sys.argv[2] == "prime" else None
print(map_jobs(toy.job, [5, 6, 7, 8], [1] * 4, 2, 1.0, False, "toy", prime=prime, name="toy"))
'''


def _pool_run(tmp_path, prime):
    """The stderr of `map_jobs` with 2 workers over a fresh kernel, in a new process with an
    empty numba cache."""
    import os
    import subprocess
    import sys

    (tmp_path / "toy.py").write_text(_TOY)
    cache = tmp_path / f"numba-{prime}"
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache))
    out = subprocess.run([sys.executable, "-c", _POOL, str(tmp_path), prime], env=env,
                         capture_output=True, text=True, check=True)
    assert out.stdout.strip() == str([sum(i ** 0.5 for i in range(x)) for x in (5, 6, 7, 8)])
    return [line for line in out.stderr.splitlines() if line.startswith("charts: ")]


def test_a_pool_worker_announces_its_compilation_in_the_parent(tmp_path):
    """Without priming, the workers compile, and the parent says so."""
    notes = _pool_run(tmp_path, "none")
    assert notes and all(n.startswith("charts: toy compiled its kernels in a worker process in ")
                         for n in notes)


def test_a_primed_pool_compiles_once_in_the_parent(tmp_path):
    """With priming the parent compiles the kernel once (one notice) and no worker compiles
    anything (a worker's compilation of any length would be announced: NOTE_SECONDS = 0)."""
    notes = _pool_run(tmp_path, "prime")
    assert len(notes) == 1 and notes[0].startswith("charts: toy compiled its kernels in ")


def test_an_ensemble_on_an_empty_cache_announces_one_compilation(tmp_path):
    """`lyapunov_ensemble` with 2 workers on an empty numba cache: one notice, from the
    parent, which compiled the kernels before the workers started."""
    import os
    import subprocess
    import sys

    code = ("import charts; from charts.jit import compilation; compilation.NOTE_SECONDS = 0.0; "
            "S = charts.RotorSystem(3); "
            "print(charts.lyapunov_ensemble(S, 4, 0.4, workers=2, t_transient=0.0, "
            "n_batches=2).exponents)")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"))
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                         check=True)
    notes = [line for line in out.stderr.splitlines() if line.startswith("charts: ")]
    assert len(notes) == 1, out.stderr
    assert notes[0].startswith("charts: lyapunov_ensemble compiled its kernels for N = 3 in ")


def test_every_public_entry_point_that_compiles_announces_it():
    """The README's promise: a call that compiled for more than a second says so, whichever
    public entry point it was (the ensembles announce through their pools, tested above)."""
    import charts

    for name in ("integrate", "lyapunov_spectrum", "hyperbolicity_angles",
                 "covariant_lyapunov_vectors", "curvature_along_trajectory", "waveform",
                 "linkage_run", "linkage_trajectory"):
        fn = getattr(charts, name)
        assert getattr(fn, "__wrapped__", None) is not None, name


def test_the_notice_names_the_variant_that_compiled(monkeypatch, capsys):
    """An entry point whose variants compile kernels of their own (``integrate``'s
    formulation and method) names the variant, defaults included."""
    import numba

    from charts.jit import compilation

    monkeypatch.setattr(compilation, "NOTE_SECONDS", 0.0)

    @compilation.announces_compilation(variant=("formulation", "method"))
    def run(system, t, *, formulation="chart", method="dop853"):
        return numba.njit(lambda x: x + 3)(1)      # a fresh function: numba compiles it

    class Sys:
        n = 4

    assert run(Sys(), 1.0, method="rk4") == 4
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(
        "charts: run (chart, rk4) compiled its kernels for N = 4 in "), err


def test_the_notice_names_a_mechanism_by_its_name_and_the_rotors_by_n(monkeypatch, capsys):
    """A mechanism whose kernels are compiled per symbolic model is named by its name (the
    Appendix linkage has 7 ambient coordinates, not N = 7 rotors); the rotors keep "N = n",
    also as an ensemble's int; the rotors as a generic Mechanism are that mechanism."""
    import numba

    import charts
    from charts.jit import compilation
    from charts.mechanism.instances import rotors

    monkeypatch.setattr(compilation, "NOTE_SECONDS", 0.0)
    count = iter(range(100))

    @compilation.announces_compilation
    def entry(system):
        k = next(count)
        return numba.njit(lambda x: x + k)(1)      # a fresh function: numba compiles it

    linkage, triple = charts.LinkageSystem(0.05), charts.triple_linkage(0.1)
    cases = [(linkage, f"for {linkage.name} in "),
             (triple, "for triple_linkage(r=0.1, l=1, R=1) in "),
             (charts.RotorSystem(4), "for N = 4 in "), (rotors(3), "for rotors(n=3) in ")]
    for system, words in cases:
        entry(system)
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1, err
        assert err[0].startswith(f"charts: entry compiled its kernels {words}"), err
        assert "N = 7" not in err[0] and "N = 5" not in err[0]
    assert linkage.name.startswith("LinkageSystem(eps=0.05")
    compilation.announce("pool", 2.0, 3, where=" in a worker process")
    assert capsys.readouterr().err.startswith("charts: pool compiled its kernels for N = 3 in a "
                                              "worker process in 2.0 s")
    compilation.announce("pool", 2.0, None)
    assert capsys.readouterr().err.startswith("charts: pool compiled its kernels in 2.0 s")


def test_a_pool_that_compiles_says_so_while_it_does(capsys):
    """`compiling_line`: one line once the block has run ``after`` seconds, none for a block
    that ends before (the line is printed by a timer thread: the test waits for the block's
    end, an event, not for a time)."""
    import threading

    from charts.jit import compilation

    printed = threading.Event()
    real_print = print

    def spy(*args, **kwargs):
        real_print(*args, **kwargs)
        printed.set()

    compilation.print = spy
    try:
        with compilation.compiling_line("toy", " in 2 workers", after=0.0):
            assert printed.wait(timeout=120)
        err = capsys.readouterr().err.strip().splitlines()
        assert err == ["charts: toy is compiling its kernels in 2 workers (once: numba caches "
                       "them on disk; kernels already there are only loaded) …"]
        with compilation.compiling_line("toy", after=3600.0):
            pass
        assert capsys.readouterr().err == ""
    finally:
        del compilation.print
