"""The manifold (eqs 1-13, 22): ``RotorSystem`` (validation, charts, metric, Christoffel
symbols, Riemann tensor, sectional curvature) and the chart kernels: generated for the shipped
N, structured (``structured``, any N) otherwise (``kernels``)."""
