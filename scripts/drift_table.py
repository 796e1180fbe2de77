"""The drift table of docs/integrators.md ("Drift over long runs"): the largest constraint,
tangency and relative energy errors over every accepted step and sample of long runs, both
formulations, with and without projection.

    python scripts/drift_table.py            # about a minute on one core
"""
import numpy as np

from charts import RotorSystem, integrate


def row(label, system, theta, u, t, **kw):
    r = integrate(system, theta, u, t, t_eval=np.arange(0.0, t + 1e-9, 0.1), **kw)
    S = (np.sin(r.theta) ** 2).sum(axis=1).min()
    d = r.drift
    return (f"{label} {kw['formulation']:7s} project={str(kw['project']):5s} "
            f"constraint={d['constraint']:.1e} tangency={d['tangency']:.1e} energy={d['energy']:.1e} "
            f"min S(samples)={S:.1e} steps={r.n_steps} switches={len(r.switches)}")


def main():
    s4 = RotorSystem(4)
    th4, u4 = s4.random_state(0)
    s3 = RotorSystem(3)
    th3, u3 = s3.random_state(5)
    for form in ("ambient", "chart"):
        for project in (False, True):
            print(row("N=4 rk4 dt=0.01 t=2e4", s4, th4, u4, 2e4, formulation=form, method="rk4",
                      dt=0.01, project=project), flush=True)
    for form in ("ambient", "chart"):
        for project in (False, True):
            print(row("N=3 dop853 rtol=1e-10 t=1e5", s3, th3, u3, 1e5, formulation=form,
                      method="dop853", rtol=1e-10, project=project), flush=True)


if __name__ == "__main__":
    main()
