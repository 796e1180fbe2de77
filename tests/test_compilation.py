"""The kernels' one-time compilation is timed and announced (charts.compilation)."""


def test_a_long_compilation_is_announced_once(monkeypatch, capsys):
    """An entry point that spent more than NOTE_SECONDS compiling says so on stderr, once,
    naming itself and N; nested entry points (and scenes, which time their own) stay quiet."""
    import numba

    from charts import compilation

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
