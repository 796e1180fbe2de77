"""The ensembles' lane kernel compiled with LLVM's SLP vectoriser and ``noalias`` arrays.

The lane kernel (``charts.solvers.lanes``) advances `LANE_WIDTH` trajectories in blocks that
are loops of constant length, unrolled before vectorisation: packing them into vector
instructions is the SLP vectoriser's work, which numba leaves off (``NUMBA_SLP_VECTORIZE``,
read once when numba starts).  `LanesCompiler` is numba's nopython pipeline (a
``pipeline_class``, numba's documented way to customise a compilation) with the function's
array arguments marked ``noalias`` (so its callers must pass distinct arrays) and
`VectorLowering`: numba's lowering with SLP on and the loop vectoriser off, for this
function's code only.  Neither changes an arithmetic operation (no fast-math, no FMA
contraction), so each lane keeps the bits of the one-trajectory kernel.

This is the ``vector_lowering`` adaptation (`charts.jit.adaptations`): it sets numba's
``config.SLP_VECTORIZE`` and ``LOOP_VECTORIZE`` and the CPU codegen's ``_loopvect`` during
that lowering (under numba's compiler lock) and restores them after.  Where they are not
there, or under ``CHARTS_NUMBA_PLAIN=1``, `options` is empty: the lanes compile as any
kernel, the same numbers, scalar code.
"""
from __future__ import annotations

from . import adaptations

__all__ = ["usable", "options"]

_compiler = None        # LanesCompiler, made once the check passed


def _check():
    """None, or what differs in numba's pipeline and codegen from what `VectorLowering`
    expects; makes the compiler class on success."""
    global _compiler
    from numba.core import config
    from numba.core.compiler import CompilerBase, DefaultPassBuilder, Flags
    from numba.core.compiler_machinery import register_pass
    from numba.core.registry import cpu_target
    from numba.core.typed_passes import NativeLowering

    for name in ("SLP_VECTORIZE", "LOOP_VECTORIZE"):
        if not hasattr(config, name):
            return f"numba.config.{name} is missing"
    if not hasattr(cpu_target.target_context.codegen(), "_loopvect"):
        return "the CPU codegen keeps no _loopvect"
    if "noalias" not in getattr(Flags, "options", {}):
        return "numba's compiler Flags have no noalias"

    @register_pass(mutates_CFG=False, analysis_only=False)
    class VectorLowering(NativeLowering):
        """numba's lowering with LLVM's SLP vectoriser on, the loop vectoriser off."""

        _name = "charts_vector_lowering"

        def run_pass(self, state):
            codegen = state.targetctx.codegen()
            saved = config.SLP_VECTORIZE, config.LOOP_VECTORIZE, codegen._loopvect
            config.SLP_VECTORIZE, config.LOOP_VECTORIZE, codegen._loopvect = 1, 0, False
            try:
                return super().run_pass(state)
            finally:
                config.SLP_VECTORIZE, config.LOOP_VECTORIZE, codegen._loopvect = saved

    class LanesCompiler(CompilerBase):
        """numba's nopython pipeline with ``noalias`` arrays and `VectorLowering`."""

        def define_pipelines(self):
            self.state.flags.noalias = True
            pm = DefaultPassBuilder.define_nopython_pipeline(self.state)
            pm.passes = [(VectorLowering if p is NativeLowering else p, d)
                         for p, d in pm.passes]
            return [pm]

    _compiler = LanesCompiler
    return None


def usable() -> bool:
    """Whether the lanes compile with `LanesCompiler` in this process."""
    return adaptations.active("vector_lowering", _check)


def options() -> dict:
    """numba's options for the lane kernel: the vectorising pipeline, or none."""
    return {"pipeline_class": _compiler} if usable() else {}
