"""Figures of trajectories: angles against time, the N = 3 path on its surface, Poincaré
sections, an animation of the rotors.  Every function draws on a pyplot-free figure (or on
the axes it is given) and returns ``(fig, ax)``; the global matplotlib backend is never
touched.  Angles are shown wrapped to (−π, π] with lines broken at the wrap."""
from __future__ import annotations

import numpy as np

from ..io.result_words import ANGULAR_VELOCITY, counted
from .style import (MAX_POINTS, TIME, broken_at_wraps, figure_axes, new_figure, system_label,
                    time_window, wrap)

__all__ = ["plot_angles_time", "plot_velocities_time", "plot_surface", "plot_poincare", "animate_rotors",
           "plot_trajectory", "save_animation", "section_words", "SECTION_TOL"]


def plot_angles_time(t, theta, *, switches=None, window=None, max_points=MAX_POINTS, ax=None,
                     title=None, system=None):
    """θᵢ(t) wrapped to (−π, π], one line per rotor; chart switches ``(t, from, to)`` as
    thin vertical lines, counted in the title (None: a route without charts, nothing said).
    ``window`` = (t0, t1): only that span (the whole of a long run smears into a block); at
    most ``max_points`` samples per line (every k-th: the title says so); ``system`` (e.g.
    `system_label`'s words) in the title."""
    fig, ax = figure_axes(ax, figsize=(7.5, 3.6))
    t, theta, stride = time_window(t, theta, window, max_points)
    charts_ = switches is not None
    switches = list(switches or ())
    if window is not None:
        switches = [sw for sw in switches if window[0] <= sw[0] <= window[1]]
    for i in range(theta.shape[1]):
        w, tt = broken_at_wraps([theta[:, i]], extra=[t])
        ax.plot(tt, w, lw=1.0, label=f"θ$_{i}$")
    for j, (ts, a, b) in enumerate(switches):
        ax.axvline(ts, color="0.5", lw=0.6, ls="--",
                   label="chart switch" if j == 0 else None)
    ax.set_xlabel(TIME)
    ax.set_ylabel("θᵢ (rad, wrapped to (−π, π])")
    ax.set_ylim(-np.pi * 1.05, np.pi * 1.05)
    ax.set_yticks([-np.pi, -np.pi / 2, 0, np.pi / 2, np.pi], ["−π", "−π/2", "0", "π/2", "π"])
    every = f"every {stride}th sample" if stride > 1 else ""
    notes = ", ".join(x for x in (counted(len(switches), "chart switch", "chart switches") if charts_ else "", every) if x)
    what = f"angles against time, {system}" if system else "angles against time"
    ax.set_title(title or (what + (f" ({notes})" if notes else "")), fontsize=10)
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, frameon=False)
    return fig, ax


def plot_velocities_time(t, u, rotors=None, *, window=None, max_points=MAX_POINTS, axes=None,
                         title=None):
    """The angular velocities uᵢ(t) (rad / time; the paper's figure 2), one panel per
    rotor of ``rotors`` (default all; ``u`` (S, N), or (S, len(rotors)) with ``rotors``
    naming its columns when ``u`` holds only those); ``window`` = (t0, t1) and at most
    ``max_points`` samples per line as `plot_angles_time`.  ``(fig, axes)``."""
    u = np.asarray(u)
    rotors = list(range(u.shape[1])) if rotors is None else list(rotors)
    cols = u if u.shape[1] == len(rotors) else u[:, rotors]
    t, cols, stride = time_window(np.asarray(t), cols, window, max_points)
    if axes is None:
        fig, grid = new_figure(len(rotors), 1, figsize=(8, 1.3 * len(rotors) + 0.9),
                               sharex=True, squeeze=False)
        axes = list(grid[:, 0])
    fig = axes[0].figure
    for ax, r, col in zip(axes, rotors, cols.T):
        ax.plot(t, col, lw=0.7)
        ax.set_ylabel(f"$u_{{{r}}}$ ({ANGULAR_VELOCITY})")
    axes[-1].set_xlabel(TIME)
    every = f", every {stride}th sample" if stride > 1 else ""
    fig.suptitle(title or f"angular velocities ({ANGULAR_VELOCITY}){every}", fontsize=10)
    return fig, axes


def _surface_sheets(system, m=61):
    """The surface Σ cos θ = 0 of N = 3 over (θ₀, θ₁) ∈ (−π, π]²: θ₂ on its two branches
    (``RotorSystem.from_chart`` of chart 2), NaN where |cos θ₀ + cos θ₁| ≥ 1."""
    g = np.linspace(-np.pi, np.pi, m)
    T1, T2 = np.meshgrid(g, g)
    sheets = []
    for branch in (1, -1):
        Z = np.full(T1.shape, np.nan)
        for idx in np.ndindex(T1.shape):
            q = np.array([T1[idx], T2[idx]])
            if abs(np.cos(q).sum()) < 1.0:
                Z[idx] = system.from_chart(q, np.zeros(2), 2, branch)[0][2]
        sheets.append(Z)
    return T1, T2, sheets


def plot_surface(theta, *, system=None, ax=None, title=None):
    """N = 3: the path θ(t) (wrapped) on the surface cos θ₀ + cos θ₁ + cos θ₂ = 0 in the
    cube (−π, π]³ (a 3D axes)."""
    theta = np.asarray(theta)
    if theta.ndim != 2 or theta.shape[1] != 3:
        raise ValueError(f"the surface plot is for N = 3; theta has shape {theta.shape}")
    if system is None:
        from ..geometry.system import RotorSystem
        system = RotorSystem(3)
    if ax is None:
        fig, _ = new_figure(0, figsize=(6, 5.5))
        ax = fig.add_subplot(projection="3d")
    fig = ax.figure
    T1, T2, sheets = _surface_sheets(system)
    for Z in sheets:
        ax.plot_surface(T1, T2, Z, color="0.75", alpha=0.35, lw=0, rstride=2, cstride=2)
    x, y, z = broken_at_wraps([theta[:, 0], theta[:, 1], theta[:, 2]])
    ax.plot(x, y, z, color="C3", lw=1.0, label="trajectory")
    ax.set_xlabel("θ₀ (rad)")
    ax.set_ylabel("θ₁ (rad)")
    ax.set_zlabel("θ₂ (rad)")
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-np.pi, np.pi)
    ax.set_title(title or "N = 3: the path on cos θ₀ + cos θ₁ + cos θ₂ = 0", fontsize=10)
    return fig, ax


def _state_label(i, n):
    return f"θ$_{i}$ (rad)" if i < n else f"u$_{i - n}$ ({ANGULAR_VELOCITY})"


_SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
#: Largest spread (rad for angles, modulo 2π; relative for velocities) of a state component
#: over the crossings of a section for `section_words` to call it one value: the crossings
#: are located on the steps' interpolants to 1e-14 in time (``charts.solvers.events``), so a
#: coordinate the event fixes spreads far less, and one it does not, far more.
SECTION_TOL = 1e-6
#: Angles named by their multiple of π in `section_words`.
_NAMED_ANGLES = ((-0.5, "−π/2"), (0.0, "0"), (0.5, "π/2"), (1.0, "π"))


def _angle_words(v):
    return next((name for k, name in _NAMED_ANGLES if abs(wrap(v - k * np.pi)) < SECTION_TOL),
                f"{v:.4g}")


def section_words(Y, n):
    """Words naming the section that the event states ``Y`` (m, ≥ 2n: [θ, u, …]) lie on: the
    first component of [θ, u] that takes one value at every crossing, or two (angles modulo
    2π; within `SECTION_TOL`), with the sign of uᵢ there for an angle θᵢ (the direction of
    the crossing): "θ₀ = 0, u₀ > 0", "θ₀ = 0 (u₀ > 0) or π (u₀ < 0)"; None with fewer than
    two crossings (three for two values) or where no single component is fixed (an event
    mixing several)."""
    Y = np.asarray(Y, dtype=float)
    if Y.ndim != 2 or len(Y) < 2 or Y.shape[1] < 2 * n:
        return None
    for c in range(2 * n):
        x = Y[:, c]
        if c < n:
            def near(a, b):
                return np.abs(wrap(a - b)) < SECTION_TOL
        else:
            def near(a, b):
                return np.abs(a - b) < SECTION_TOL * max(1.0, abs(b))
        first = near(x, x[0])
        groups = [first] if first.all() else [first, ~first & near(x, x[~first][0])]
        if not np.logical_or.reduce(groups).all() or (len(groups) == 2 and len(Y) < 3):
            continue
        i = str(c % n).translate(_SUBSCRIPTS)
        pieces = []
        for g in groups:
            if c >= n:
                v = x[g][0]
                pieces.append((v, "0" if abs(v) < SECTION_TOL else f"{v:.4g}", ""))
                continue
            v, rate = float(wrap(x[g][0])), Y[g, n + c]
            v = np.pi if abs(wrap(v - np.pi)) < SECTION_TOL else v      # −π + ε is π
            sign = f"u{i} > 0" if (rate > 0).all() else f"u{i} < 0" if (rate < 0).all() else ""
            pieces.append((v, _angle_words(v), sign))
        name = f"θ{i}" if c < n else f"u{i}"
        if len(pieces) == 1:
            return f"{name} = {pieces[0][1]}" + (f", {pieces[0][2]}" if pieces[0][2] else "")
        return f"{name} = " + " or ".join(w + (f" ({s})" if s else "")
                                          for _, w, s in sorted(pieces))
    return None


def plot_poincare(result, *, coords=(1, 4), event=0, select=None, ax=None, title=None,
                  section=None, **scatter_kw):
    """The points of ``result.y_events[event]`` (an ``integrate`` run with ``events=``) in the
    plane of two state components ``coords`` (indices into [θ, u]; angles wrapped).
    ``select``: a function of the event states (m, …) returning a boolean mask, to keep one
    sheet of a section whose event function vanishes on several (sin θ₀ = 0 holds at θ₀ ≡ 0
    and at θ₀ ≡ π: ``select=lambda Y: np.cos(Y[:, 0]) > 0`` keeps θ₀ ≡ 0).  The title says
    which section: ``section`` (words), else what the points show (`section_words`: the
    coordinate the event fixes, its value and the direction of the crossings), else the
    event's index."""
    if result.y_events is None:
        raise ValueError("the result has no events: integrate with events=[...]")
    n = result.theta.shape[1]
    Y = result.y_events[event]
    if select is not None:
        Y = Y[np.asarray(select(Y), dtype=bool)]
    xy = [wrap(Y[:, c]) if c < n else Y[:, c] for c in coords]
    fig, ax = figure_axes(ax, figsize=(5, 4.6))
    kw = dict(s=4, color="k", lw=0)
    kw.update(scatter_kw)
    ax.scatter(xy[0], xy[1], **kw)
    ax.set_xlabel(_state_label(coords[0], n))
    ax.set_ylabel(_state_label(coords[1], n))
    section = section or section_words(Y, n) or f"zeros of events[{event}]"
    ax.set_title(title or f"Poincaré section {section}: {counted(len(Y), 'crossing')}",
                 fontsize=10)
    return fig, ax


def animate_rotors(t, theta, *, every=1, interval=40, title=None):
    """An animation of the N rotors (a ``matplotlib.animation.FuncAnimation`` on a
    pyplot-free figure): rotor i is a rod at angle θᵢ from the vertical, in its own circle.
    Frames every ``every`` samples, ``interval`` ms apart.  Save it with
    :func:`save_animation`."""
    from matplotlib.animation import FuncAnimation

    theta = np.asarray(theta)[::every]
    t = np.asarray(t)[::every]
    n = theta.shape[1]
    fig, ax = new_figure(figsize=(1.6 * n + 0.6, 2.2))
    ax.set_aspect("equal")
    ax.set_xlim(-1.2, 2.5 * (n - 1) + 1.2)
    ax.set_ylim(-1.3, 1.3)
    ax.set_axis_off()
    phi = np.linspace(0, 2 * np.pi, 100)
    rods = []
    for i in range(n):
        cx = 2.5 * i
        ax.plot(cx + np.cos(phi), np.sin(phi), color="0.7", lw=0.8)
        ax.text(cx, -1.25, f"θ$_{i}$", ha="center", va="top", fontsize=9)
        rods.append(ax.plot([cx, cx], [0, 1], color=f"C{i}", lw=2.5, marker="o", ms=3)[0])
    label = ax.text(0.0, 1.02, "", transform=ax.transAxes, fontsize=9)
    if title:
        fig.suptitle(title, fontsize=10)

    def draw(k):
        for i, rod in enumerate(rods):
            cx = 2.5 * i
            rod.set_data([cx, cx + np.sin(theta[k, i])], [0, np.cos(theta[k, i])])
        label.set_text(f"t = {t[k]:.2f}")
        return rods + [label]

    return FuncAnimation(fig, draw, frames=len(t), interval=interval, blit=False)


def save_animation(anim, path, *, fps=25):
    """Write the animation: ``.gif`` with the pillow writer, ``.mp4`` with ffmpeg.  A
    RuntimeError names the missing writer."""
    from matplotlib.animation import writers

    name = {".gif": "pillow", ".mp4": "ffmpeg"}.get(str(path)[-4:].lower())
    if name is None:
        raise ValueError(f"animation path must end in .gif or .mp4, got {path}")
    if not writers.is_available(name):
        raise RuntimeError(f"no '{name}' animation writer available for {path}: install "
                           f"{'pillow' if name == 'pillow' else 'ffmpeg'} or use the other format")
    anim.save(str(path), writer=name, fps=fps)
    return path


def plot_trajectory(result, kind="angles", **kw):
    """``IntegrationResult.plot``: ``kind`` = ``"angles"``, ``"surface"`` (N = 3),
    ``"poincare"`` or ``"animation"``."""
    if kind == "angles":
        switches = result.switches if result.formulation == "chart" else None
        if result.params.get("n") is not None:
            kw.setdefault("system", system_label(result.params))
        return plot_angles_time(result.t, result.theta, switches=switches, **kw)
    if kind == "surface":
        return plot_surface(result.theta, **kw)
    if kind == "poincare":
        return plot_poincare(result, **kw)
    if kind == "animation":
        return animate_rotors(result.t, result.theta, **kw)
    raise ValueError(f"kind must be 'angles', 'surface', 'poincare' or 'animation', got {kind!r}")
