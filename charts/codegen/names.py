"""Names shared by the code generator and the loaders of generated code (no heavy imports)."""

__all__ = ["SHIPPED_N", "GENERATED_FUNCTIONS", "module_name"]

#: N for which ``generated/rotor_n{N}.py`` and ``rotor_n{N}_paper.py`` are committed.
SHIPPED_N = (3, 4, 5, 6)

#: Functions every generated module defines (see charts/codegen/emit.py).
GENERATED_FUNCTIONS = (
    "metric", "metric_inverse", "christoffel", "riemann",
    "geodesic_acceleration", "transport_rate", "curvature_operator",
    "eliminated_component",
    # the two above with σ = a sin q, κ = a cos q given (shared by the chart right-hand side)
    "geodesic_acceleration_sc", "transport_rate_sc",
)


def module_name(n: int, paper: bool = False) -> str:
    """``rotor_n{n}`` (the family Σ aᵢ cos θᵢ = c) or ``rotor_n{n}_paper`` (its member a = 1,
    c = 0 specialised before code generation, the paper's kernels bit for bit)."""
    return f"rotor_n{n}_paper" if paper else f"rotor_n{n}"
