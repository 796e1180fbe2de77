"""The figures a scene run writes, one PNG per effect with a picture, drawn by the one home
of each picture (:mod:`charts.plotting`, the same functions as the results' ``plot()``).
Each function returns the PNG bytes; the caller writes them.

Units: time in time units of the flow (those of the scene: at speed 1 the paper's), angles
in rad, angular velocities and angular frequencies in rad per unit time.
"""
from __future__ import annotations

import numpy as np

from ..io.result_words import ANGULAR_VELOCITY
from ..plotting import (CURVATURE_QUANTILES, plot_angles, plot_curvature, plot_drift,
                        plot_lyapunov, plot_spectrum, plot_velocities_time)
from ..plotting.style import new_figure, png_bytes

__all__ = ["waveforms_png", "spectrum_png", "drift_png", "lyapunov_png", "angles_png", "clv_png",
           "curvature_png", "CURVATURE_QUANTILES"]

def _title(sc, what):
    s = sc.system
    if s.get("kind") == "linkage":
        return f"{sc.name}: {what}, linkage ε = {s['eps']:g}, ρ = {s['rho']:g}"
    if s.get("kind") == "mechanism":
        from ..plotting.mechanism import mechanism_label
        return f"{sc.name}: {what},\n{mechanism_label(s)}"     # (a label too long for one line)
    return f"{sc.name}: {what}, N = {s['n']}"


def waveforms_png(sc, t, U) -> bytes:
    """The angular velocities uᵢ(t) of the stored window, one panel per rotor."""
    rotors = sc.effects["waveforms"]["rotors"]
    fig, _ = plot_velocities_time(t, U, rotors, max_points=max(1, len(t)),
                                  title=_title(sc, f"angular velocities ({ANGULAR_VELOCITY})"))
    return png_bytes(fig)


def spectrum_png(sc, omega, density, segment_time) -> bytes:
    """Power spectral density of one rotor's velocity against angular frequency ω."""
    rotor = sc.effects["spectrum"]["rotor"]
    fig, ax = plot_spectrum(omega, density, title=_title(sc, f"power spectral density of $u_{{{rotor}}}$")
                            + f"\n(Welch: Hann segments of {segment_time:g} time units, 50 % overlap)")
    ax.set_ylabel(f"$S_{{u_{{{rotor}}}}}(\\omega)$ (({ANGULAR_VELOCITY})² per unit ω)")
    return png_bytes(fig)


def drift_png(sc, t, D) -> bytes:
    """|drift| of the three invariants on a log axis (values at rounding level or exact
    zeros, which a log axis cannot show, are left out and counted in the legend)."""
    names = ("|Σ cos θᵢ| (constraint)", f"|Σ uᵢ sin θᵢ| (tangency, {ANGULAR_VELOCITY})",
             "|E/E₀ − 1| (energy, relative)")
    if sc.system.get("kind", "rotors") != "rotors":
        names = ("max |Fᵢ(q)| (constraints)", "max |(J v)ᵢ| (tangency)",
                 "|E/E₀ − 1| (energy, relative)")
    fig, _ = plot_drift(t, np.asarray(D).T, names, title=_title(sc, "drift of the invariants"))
    return png_bytes(fig)


def lyapunov_png(sc, T, H, res) -> bytes:
    """Running estimates λᵢ(T) at the batch ends against the averaging time T, the final
    estimate ± its batch-means standard error, and the paper's values (dotted) when they
    apply."""
    paper = res.get("paper")
    fig, _ = plot_lyapunov(T, H, res["exponents"], res.get("stderr"), paper=paper,
                           paper_label="paper, section 2 (dotted; scaled by the speed)",
                           title=_title(sc, "Lyapunov exponents"))
    return png_bytes(fig)


def angles_png(sc, arr) -> bytes:
    """Histograms of the angle φ between the expanding and the contracting-neutral subspaces."""
    variants = {v: arr[f"angles_{v}"] for v in ("full", "restricted") if f"angles_{v}" in arr}
    fig, _ = plot_angles(variants, title=_title(sc, "angles between $E_u$ and $E_{cs}$"))
    return png_bytes(fig)


def clv_png(sc, arr, res) -> bytes:
    """Per variant: histograms of φ (CLV route) and of the angle between the leading
    unstable and stable CLVs; the domination fractions against the window length."""
    variants = [v for v in ("full", "restricted") if f"clv_phi_{v}" in arr]
    fig, axes = new_figure(1, len(variants) + 1, figsize=(4.2 * (len(variants) + 1), 3.4),
                           squeeze=False)
    for ax, v in zip(axes[0], variants):
        for key, label in ((f"clv_phi_{v}", "$E_u$ vs $E_{cs}$"),
                           (f"clv_phi_vectors_{v}", "$v_1$ vs leading stable $v_s$")):
            ax.hist(arr[key], bins=60, range=(0, np.pi / 2), density=True, histtype="step",
                    label=f"{label} (min {arr[key].min():.2g})")
        ax.set_xlabel("angle (rad)")
        ax.set_ylabel("probability density")
        ax.set_title(f"{v} tangent space", fontsize=10)
        ax.legend(fontsize=7)
    ax = axes[0, -1]
    for v in variants:
        d = res[v]["domination"]
        w = [float(k) for k in d]
        ax.plot(w, [d[k]["split"] for k in d], "o-", label=v)
    ax.set_xscale("log")
    ax.set_xlabel("window T (time units)")
    ax.set_ylabel("fraction of windows")
    ax.set_title("$E_u$ not dominating $E_{cs}$", fontsize=10)
    ax.legend(fontsize=7)
    fig.suptitle(_title(sc, "covariant Lyapunov vectors"))
    return png_bytes(fig)


def curvature_png(sc, arr) -> bytes:
    """Histograms of the sectional curvatures K_ii, one panel per direction, both routes
    when both were computed; limits from the robust quantiles, the clipped share stated."""
    routes = {r: arr[f"curvature_{r}"] for r in ("numerical", "exact") if f"curvature_{r}" in arr}
    q0, q1 = CURVATURE_QUANTILES
    fig, _ = plot_curvature(routes, title=_title(sc, "sectional curvatures") +
                            f" (axis: {q0:g} %–{q1:g} % quantiles)")
    return png_bytes(fig)
