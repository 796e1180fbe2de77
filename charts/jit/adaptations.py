"""What charts adapts in numba, for its own compilations only, and the one switch that turns
all of it off.

charts is a guest in numba's house (docs/architecture.md, "numba as a dependency"): nothing
of it runs in a process that does not import charts, and numba's own functions are numba's
for every other compilation.  A few adaptations buy first-call time where numba is slow for
charts' large generated kernels; each is

* **scoped** to charts' own functions: the per-kernel cache (`charts.jit.cache_lock`) is an
  object of charts' own dispatchers; the inliner's one copy and the typing memo
  (`charts.jit.inliner`, `charts.jit.typing_memo`) are in numba's classes only while numba
  compiles a charts function (`compile_scope`, numba's documented event API), and numba's
  own functions are back in place when it ends;
* **fail-safe**: before first use it checks the numba internals it relies on (`active`);
  on any mismatch it stays out, with one notice on stderr, and charts runs on numba's own
  code with the same numbers (an adaptation changes how fast numba compiles, never what);
* **switchable in one place**: ``CHARTS_NUMBA_PLAIN=1`` in the environment turns every
  adaptation off, and numba's functions stay exactly as numba defines them.

`STATE` says, per adaptation, what this process does ("on", "plain", or "off: <why>");
``charts.jit.report()`` runs every check and returns it.
This module imports nothing of numba at import time.
"""
from __future__ import annotations

import os
import sys
import threading

__all__ = ["PLAIN", "STATE", "active", "step_aside", "ours", "compile_scope", "scoped",
           "ADAPTATIONS"]

#: ``CHARTS_NUMBA_PLAIN=1``: stock numba for everything (read once, at import).
PLAIN = os.environ.get("CHARTS_NUMBA_PLAIN", "").strip().lower() in ("1", "true", "yes", "on")

#: The adaptations, by name, and what each buys (docs/performance.md, First use).
ADAPTATIONS = {
    "cache_lock": "numba's disk cache of charts' kernels read and written under a file lock, "
                  "damaged entries healed",
    "inliner": "numba's inliner copies a charts callee's blocks in one deepcopy",
    "typing_memo": "numba's typing of a call remembered while it compiles charts' functions",
    "kernel_address": "a large kernel called by address from the analyses' drivers",
    "vector_lowering": "the ensembles' lanes compiled with LLVM's SLP vectoriser",
    "borrowed_views": "arrays read from a named loop state without reference counts",
}

#: name -> "on", "plain" (CHARTS_NUMBA_PLAIN) or "off: <the mismatch found>".
STATE: dict = {}

_lock = threading.Lock()


def ours(module) -> bool:
    """Whether ``module`` (a module name) is this package's or one of its on-demand modules."""
    module = module or ""
    return module == "charts" or module.startswith(("charts.", "charts_ondemand_"))


def active(name: str, check) -> bool:
    """Whether the adaptation ``name`` is in use in this process.  The first question runs
    ``check()`` (None where numba's internals are as expected, else a short text of what
    differs; an exception counts as a mismatch); under `PLAIN` it is never run."""
    state = STATE.get(name)
    if state is None:
        with _lock:
            state = STATE.get(name)
            if state is None:
                if PLAIN:
                    state = "plain"
                else:
                    try:
                        reason = check()
                    except Exception as exc:        # noqa: BLE001 - any failure is a mismatch
                        reason = f"{type(exc).__name__}: {exc}"
                    state = "on" if not reason else f"off: {reason}"
                    if reason:
                        _notice(name, reason)
                STATE[name] = state
    return state == "on"


def step_aside(name: str, reason: str) -> None:
    """Turn the adaptation ``name`` off for the rest of the process after a mismatch met in
    use, with the one notice."""
    with _lock:
        if STATE.get(name, "on") == "on":
            STATE[name] = f"off: {reason}"
            _notice(name, reason)


def _notice(name: str, reason: str) -> None:
    import numba

    reason = " ".join(str(reason).split())[:200]
    print(f"charts: numba {numba.__version__} is not what the '{name}' adaptation expects "
          f"({reason}); charts uses numba's own code there (the same numbers; first calls "
          "may compile more slowly)", file=sys.stderr, flush=True)


# --- the compile scope: the inliner and the typing memo in numba's classes only while numba
#     compiles a charts function ---------------------------------------------------------

#: (installers, restorers) of the class-level adaptations, registered by their modules.
_SCOPED: list = []
_depth = 0
_registered = False


def scoped(install, restore) -> None:
    """Register a class-level adaptation: ``install()`` when numba starts compiling a charts
    function (outermost), ``restore()`` when it ends."""
    _SCOPED.append((install, restore))
    compile_scope()


def compile_scope() -> None:
    """Listen to numba's compile events (``numba.core.event``, numba's documented event
    API; idempotent): the registered adaptations are installed while numba compiles a
    charts function, numba's own functions restored when it ends (compilations hold numba's
    global compiler lock: no other thread compiles meanwhile)."""
    global _registered
    if _registered or PLAIN:
        return
    from numba.core import event

    class _Scope(event.Listener):
        def on_start(self, ev):
            global _depth
            if _depth:
                _depth += 1
                return
            data = ev.data or {}
            func = getattr(data.get("dispatcher"), "py_func", None)
            if ours(getattr(func, "__module__", "")):
                _depth = 1
                for install, _ in _SCOPED:
                    install()

        def on_end(self, ev):
            global _depth
            if _depth:
                _depth -= 1
                if not _depth:
                    for _, restore in reversed(_SCOPED):
                        restore()

    event.register("numba:compile", _Scope())
    _registered = True
