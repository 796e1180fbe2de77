"""First look (not the study): N = 4, equal weights, leading exponents against the level c."""
import time
import warnings
import numpy as np
from charts import RotorSystem, lyapunov_spectrum
T = 5000.0
print("| c | lambda_1 | lambda_2 | seeds x t |")
print("|---:|---:|---:|---:|")
for c in (0.0, 0.25, 0.5, 1.0, 1.5, 1.9):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        s = RotorSystem(4, level=c)
    ex = []
    for seed in range(4):
        th, u = s.random_state(seed=seed)
        try:
            r = lyapunov_spectrum(s, th, u, T, n_exponents=2, t_transient=50.0)
            ex.append(r.exponents)
        except Exception as e:  # singular points at c = 0
            print("# c", c, "seed", seed, type(e).__name__)
    ex = np.array(ex)
    m = ex.mean(0); se = ex.std(0, ddof=1) / np.sqrt(len(ex))
    print(f"| {c} | {m[0]:.4f} ± {se[0]:.4f} | {m[1]:.4f} ± {se[1]:.4f} | {len(ex)} x {T:g} |", flush=True)
