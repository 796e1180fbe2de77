"""Integrators: Runge-Kutta steppers, the chunked integration loop and its formulations
(ambient, chart-switching), ``integrate``, and the fused tangent-space kernel (eqs 8, 17, 18)
that every analysis advances."""
