"""The paper's analyses: Lyapunov spectra (section 2), sectional curvature along trajectories
(section 3), the hyperbolicity test by angles (section 4), waveforms and power spectra."""
