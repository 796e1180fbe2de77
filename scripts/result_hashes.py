"""Hashes of every analysis's numbers, to show that a change left them bit for bit the same.

    python scripts/result_hashes.py          # run before and after a change: equal lines

Prints one line of short SHA-1 hashes: the Lyapunov exponents, numerical curvature, both
angle variants, CLV angles and an ensemble's members (lanes=False and lanes=True each) of one
N = 4 state, and per N = 3…6 the exact curvature and a chart integration."""
import hashlib

import numpy as np

import charts


def digest(*arrays) -> str:
    h = hashlib.sha1()
    for a in arrays:
        h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()[:12]


def main() -> None:
    s = charts.RotorSystem(4)
    th, u = s.random_state(0)
    out = {}
    out["lyap"] = digest(charts.lyapunov_spectrum(s, th, u, 50.0, t_transient=5.0).exponents)
    c = charts.curvature_along_trajectory(s, th, u, 10.0, t_transient=1.0)
    out["curv"] = digest(c.K_numeric)
    a = charts.hyperbolicity_angles(s, th, u, 20.0, t_transient=5.0)
    out["ang"] = digest(a.phi_restricted, a.phi_full)
    v = charts.covariant_lyapunov_vectors(s, th, u, 10.0, t_transient=5.0)
    out["clv"] = digest(v.phi, v.exponents)
    for lanes in (False, True):
        try:
            e = charts.lyapunov_ensemble(s, 3, 20.0, t_transient=1.0, workers=1, lanes=lanes)
        except TypeError:       # a checkout from before the choice (3 members: the lanes)
            e = charts.lyapunov_ensemble(s, 3, 20.0, t_transient=1.0, workers=1)
        out[f"ens lanes={lanes}"] = digest(*[m.exponents for m in e.members])
    for n in (3, 4, 5, 6):
        sn = charts.RotorSystem(n)
        th, u = sn.random_state(seed=2)
        K = charts.curvature_along_trajectory(sn, th, u, 5.0, t_transient=0.0).K_exact
        r = charts.integrate(sn, th, u, 5.0)
        out[f"exact+chart N={n}"] = digest(K, r.theta, r.u)
    print(out)


if __name__ == "__main__":
    main()
