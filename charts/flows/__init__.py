"""The equations of motion, each written once: eq (8) and its linearisation (17), parallel
transport (19), the adjoint flow (ambient); eqs (14) and (16) (charts); the projections onto
the manifold and its constraint-preserving tangent space; the invariants."""
