"""The kernels' one-time compilation, timed and announced.

numba compiles a kernel on its first use for a signature and caches it on disk, so the first
call with a new N (or the first call after an install) can take seconds to minutes.  This
module times that from numba's own ``numba:compile`` events (outermost only; loading a
cached kernel, ~0.05 s, is no such event) and says so once
per call on stderr when it is long (`NOTE_SECONDS`); any layer may use it (no package imports).
"""
from __future__ import annotations

import functools
import inspect
import sys
import threading
from contextlib import contextmanager

__all__ = ["NOTE_SECONDS", "compile_timer", "announces_compilation", "announce", "timed_call",
           "compiling_line", "compiled_for", "compiling_said", "COMPILING_AFTER"]

#: compilations shorter than this pass without a word.
NOTE_SECONDS = 1.0

_depth = threading.local()


@contextmanager
def compile_timer(add):
    """Call ``add(seconds)`` for the time numba spends compiling inside the block (loading
    cached kernels is not counted); entry points called inside it do not announce their own."""
    from numba.core.event import install_timer

    outer = getattr(_depth, "n", 0)
    _depth.n = outer + 1
    try:
        with install_timer("numba:compile", add):
            yield
    finally:
        _depth.n = outer


def compiled_for(system) -> str:
    """What a notice says the kernels were compiled for: a mechanism whose kernels are
    compiled per symbolic model (its class defines ``compiled_jets``: the linkages, a user's
    own) by its name (" for triple_linkage(r=0.1, l=1, R=1)"); the rotors (``RotorSystem``,
    whose structured kernels are compiled per N and which only lends a mechanism's methods)
    by N (" for N = 3"), an int as N; nothing for anything else."""
    if callable(getattr(type(system), "compiled_jets", None)):
        return f" for {getattr(system, 'name', None) or type(system).__name__}"
    n = getattr(system, "n", system)
    return f" for N = {n}" if isinstance(n, int) and not isinstance(n, bool) else ""


def _stderr(line) -> None:
    print(line, file=sys.stderr, flush=True)


def announce(name, seconds, n=None, where="", say=None) -> None:
    """The one-line notice on stderr (or ``say(line)``, e.g. a progress bar's ``write``),
    when ``seconds`` of compiling (wall time, numba's compile events) exceed `NOTE_SECONDS`;
    ``n``: N or the system the kernels were compiled for (`compiled_for`)."""
    if seconds > NOTE_SECONDS:
        (say or _stderr)(f"charts: {name} compiled its kernels{compiled_for(n)}{where} in "
                         f"{seconds:.1f} s of wall time (once: they are cached on disk for the "
                         "next calls and processes; `charts warmup` compiles them all after an "
                         "install)")


def _first_compile(line, say):
    """A numba event listener that says ``line`` at the first compile event after it was made
    or re-armed (``rearm()``), and not again until then; ``spent``: the seconds of compiling
    so far (outermost events, as `compile_timer` counts them, but readable while the block
    runs)."""
    from numba.core.event import TimingListener

    class FirstCompile(TimingListener):
        armed = True

        def on_start(self, event):
            if self.armed:
                self.armed = False
                say(line)
            super().on_start(event)

        def rearm(self):
            self.armed = True

        @property
        def spent(self):
            return self.duration if self.done else 0.0

    return FirstCompile()


@contextmanager
def compiling_said(name, n=None, say=None):
    """While the block runs: the moment numba starts compiling in it (a kernel that is not
    in the on-disk cache; loading one is no compile event), one line "charts: NAME is
    compiling its kernels for N = … …" on stderr (or ``say(line)``); nothing when every
    kernel comes from the cache.  Yields the listener: its ``spent`` is the compiling so far
    (s), its ``rearm()`` lets a later compilation in the block say it again (after the
    notice of the one before)."""
    from numba.core.event import install_listener

    listener = _first_compile(f"charts: {name} is compiling its kernels{compiled_for(n)} (once: "
                              "numba caches them on disk; kernels already there are only "
                              "loaded) …", say or _stderr)
    with install_listener("numba:compile", listener):
        yield listener


#: How long a pool's compiling (`compiling_line`) runs silent before its line: shorter blocks
#: are kernels loaded from the cache; 0 says it at once.
COMPILING_AFTER = 5.0


@contextmanager
def compiling_line(name, where="", after=None):
    """While the block runs (a pool's workers compiling, silent otherwise): one line on
    stderr once it has taken ``after`` seconds (default `COMPILING_AFTER`; 0: at once, before
    the block), saying what it is doing."""
    after = COMPILING_AFTER if after is None else after
    line = (f"charts: {name} is compiling its kernels{where} (once: numba caches them on disk; "
            "kernels already there are only loaded) …")
    if after <= 0:
        _stderr(line)
        yield
        return
    timer = threading.Timer(after, lambda: print(line, file=sys.stderr, flush=True))
    timer.daemon = True
    timer.start()
    try:
        yield
    finally:
        timer.cancel()


def timed_call(fn, *args, **kwargs):
    """(``fn(*args, **kwargs)``, seconds numba spent compiling in it); the entry points
    called inside announce nothing (the caller decides, e.g. a pool's parent)."""
    spent = [0.0]
    with compile_timer(lambda s: spent.__setitem__(0, spent[0] + s)):
        out = fn(*args, **kwargs)
    return out, spent[0]


def announces_compilation(fn=None, *, variant=()):
    """Wrap a public entry point: when its call spent more than `NOTE_SECONDS` compiling,
    print one line on stderr saying so (nested entry points announce only the outermost),
    naming the values of its parameters ``variant`` (e.g. ``("formulation", "method")``:
    each variant compiles kernels of its own)."""
    if fn is None:
        return functools.partial(announces_compilation, variant=tuple(variant))
    signature = inspect.signature(fn) if variant else None

    def label(args, kwargs):
        if not variant:
            return fn.__name__
        try:
            bound = signature.bind(*args, **kwargs)
        except TypeError:                   # the call itself will say what is wrong
            return fn.__name__
        bound.apply_defaults()
        return f"{fn.__name__} ({', '.join(str(bound.arguments[v]) for v in variant)})"

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        if getattr(_depth, "n", 0):
            return fn(*args, **kwargs)
        spent = [0.0]
        try:
            with compile_timer(lambda s: spent.__setitem__(0, spent[0] + s)):
                return fn(*args, **kwargs)
        finally:
            if spent[0] > NOTE_SECONDS:
                announce(label(args, kwargs), spent[0], args[0] if args else None)

    return wrapper
