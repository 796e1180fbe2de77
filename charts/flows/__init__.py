"""The equations of motion, each written once: eq (8), its linearisation (17), parallel
transport (19) and the adjoint flow (``ambient``); eqs (14) and (16) in a chart (``chart``).
The projections and invariants they preserve are geometry (``charts.geometry.projection``)."""
