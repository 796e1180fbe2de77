"""The manifold (eqs 1-13, 22): ``RotorSystem`` (validation, charts, metric, Christoffel
symbols, Riemann tensor, sectional curvature) and the compiled generated chart kernels."""
