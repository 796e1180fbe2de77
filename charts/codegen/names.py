"""Names shared by the code generator and the loaders of generated code (no heavy imports)."""

__all__ = ["SHIPPED_N", "GENERATED_FUNCTIONS", "module_name"]

#: N for which ``generated/rotor_n{N}.py`` is committed.
SHIPPED_N = (3, 4, 5, 6)

#: Functions every generated module defines (see charts/codegen/emit.py).
GENERATED_FUNCTIONS = (
    "metric", "metric_inverse", "christoffel", "riemann",
    "geodesic_acceleration", "transport_rate", "curvature_operator",
    "eliminated_component",
)


def module_name(n: int) -> str:
    return f"rotor_n{n}"
