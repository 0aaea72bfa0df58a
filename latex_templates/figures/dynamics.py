"""Figures of section 3 (dynamics, matplotlib) from :class:`reportgen.dynamics.DynamicsResult`:
M_red with the works and ΔE over the cycle, the Wittenbauer diagram between ΔE(φ) and J_red(φ)
turned (φ downwards, as the course draws it), ω(φ) with the band, and the flywheel's sketch.

The exact curves are drawn from the dense grid; the points and chords of the graphical
construction from ``res.graphical`` (mm × scale), so the figure shows what the sheet draws."""
from __future__ import annotations

import math

import numpy as np
from matplotlib.patches import Circle, Polygon, Rectangle

from ..parts import tr
from . import comma, comma_axes, new_figure
from .labels import names

GRAPH = "tab:blue"        # the graphical construction
EXACT = "black"


def _closed(res, values: np.ndarray, end: float) -> tuple[np.ndarray, np.ndarray]:
    """θ in degrees 0…360 and the values with the value at 360° appended."""
    x = np.append(np.degrees(np.asarray(res.theta)), 360.0)
    return x, np.append(np.asarray(values, dtype=float), end)


def _phi_axis(ax, res, labels: list[str]) -> None:
    """Ticks at the graph's equal positions with their numbers; the break angles dashed."""
    th = np.degrees(np.asarray(res.graphical.theta))
    ticks = [(t, s) for t, s in zip(th, labels) if s.isdigit()]
    ax.set_xticks([t for t, _ in ticks])
    ax.set_xticklabels([s for _, s in ticks])
    for t, s in zip(th, labels):
        if not s.isdigit():
            ax.axvline(t, color="0.4", lw=0.6, ls="--")
    ax.set_xlim(0, 360)


def work_figure(res, labels: list[str]):
    """M_red(φ); A_c(φ) exact and by chords with A_дв; ΔE(φ) exact and by the graph."""
    g = res.graphical
    fig = new_figure(16.0, 17.0)
    axes = fig.subplots(3, 1, sharex=True)
    th = np.degrees(np.asarray(g.theta))
    x, M = _closed(res, res.M_red, float(res.M_red[0]))
    ax = axes[0]
    ax.plot(x, M, color=EXACT)
    ax.plot(th, np.asarray(g.M_mm) * g.mu_M, "o", ms=3, color=GRAPH)
    ax.step(np.degrees(np.asarray(g.theta)), np.append(np.asarray(g.mid_mm) * g.mu_M, g.mid_mm[-1] * g.mu_M),
            where="post", color=GRAPH, lw=0.7)
    ax.set_ylabel(tr("figures.dyn01"))
    ax = axes[1]
    _, A = _closed(res, res.work_resistance, res.work_cycle)
    _, Ad = _closed(res, res.work_drive, res.M_drive * 2 * math.pi)
    ax.plot(x, A, color=EXACT, label=tr("figures.dyn12"))
    ax.plot(th, np.asarray(g.a_mm) * g.mu_A, "o-", ms=3, lw=0.7, color=GRAPH, label=tr("figures.dyn13"))
    ax.plot(x, Ad, color="tab:red", label=tr("figures.dyn14"))
    ax.set_ylabel(tr("figures.dyn02"))
    ax.legend(loc="best", fontsize=8)
    ax = axes[2]
    _, E = _closed(res, res.delta_E, 0.0)
    ax.plot(x, E, color=EXACT, label=tr("figures.wdyn01"))
    ax.plot(th, np.asarray(g.e_mm) * g.mu_E, "o-", ms=3, lw=0.7, color=GRAPH, label=tr("figures.wdyn02"))
    ax.set_ylabel(tr("figures.dyn03"))
    ax.legend(loc="best", fontsize=8)
    ax.set_xlabel(tr("figures.dyn04"))
    for a in axes:
        a.axhline(0, color="0.3", lw=0.6)
        comma_axes(a)
        _phi_axis(a, res, labels)
    fig.tight_layout()
    return fig


def tangent_lines(res, J_max: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """J from 0 to ``J_max`` and the two exact tangents ΔE = K + J·ω_max²/2, ΔE = L + J·ω_min²/2."""
    ex = res.exact
    J = np.array([0.0, J_max])
    return J, ex.K + J * ex.omega_max ** 2 / 2, ex.L + J * ex.omega_min ** 2 / 2


def wittenbauer_figure(res):
    """ΔE(φ) | Wittenbauer ΔE(J_red) with the tangents, K, L; J_red(φ) turned under it."""
    ex = res.exact
    fig = new_figure(16.5, 16.5)
    gs = fig.add_gridspec(2, 2, width_ratios=(1, 1.25), height_ratios=(1.25, 1))
    ax_e = fig.add_subplot(gs[0, 0])
    ax_w = fig.add_subplot(gs[0, 1], sharey=ax_e)
    ax_j = fig.add_subplot(gs[1, 1], sharex=ax_w)
    x, E = _closed(res, res.delta_E, 0.0)
    _, J = _closed(res, res.J_red, float(res.J_red[0]))
    ax_e.plot(x, E, color=EXACT)
    ax_e.set_xlim(0, 360)
    ax_e.set_xticks(range(0, 361, 90))
    ax_e.set_xlabel(tr("figures.dyn05"))
    ax_e.set_ylabel(tr("figures.dyn06"))
    J_max = float(J.max()) * 1.08
    Jt, up, lo = tangent_lines(res, J_max)
    ax_w.plot(J, E, color=EXACT)
    ax_w.plot(Jt, up, color="tab:red", lw=0.9)
    ax_w.plot(Jt, lo, color="tab:red", lw=0.9)
    ax_w.plot(*ex.point_K, "o", ms=3, color="tab:red")
    ax_w.plot(*ex.point_L, "o", ms=3, color="tab:red")
    ax_w.plot([0, 0], [ex.L, ex.K], color="tab:red", lw=2.2)
    ax_w.annotate("K", (0, ex.K), xytext=(4, 2), textcoords="offset points", fontsize=10, style="italic")
    ax_w.annotate("L", (0, ex.L), xytext=(4, -9), textcoords="offset points", fontsize=10, style="italic")
    ax_w.set_xlim(0, J_max)
    lo_y = min(float(E.min()), ex.L)
    hi_y = max(float(E.max()), ex.K)
    pad = 0.08 * (hi_y - lo_y)
    # ψmax, ψmin on their tangents where these are still inside the diagram (a steep tangent leaves
    # it early: the shaper's)
    for name, y0, slope, dy, top in ((r"$\psi_{\max}$", ex.K, ex.omega_max ** 2 / 2, 6, hi_y + 0.5 * pad),
                                     (r"$\psi_{\min}$", ex.L, ex.omega_min ** 2 / 2, -12, lo_y - 0.5 * pad)):
        j = J_max * 0.55
        if slope * j + y0 > top if dy > 0 else slope * j + y0 < top:
            j = 0.8 * (top - y0) / slope if slope else j
        ax_w.annotate(name, (j, y0 + j * slope), xytext=(0, dy), textcoords="offset points", fontsize=9)
    ax_w.set_ylim(lo_y - pad, hi_y + pad)
    ax_w.set_title(tr("figures.dyn07"), fontsize=10)
    ax_w.tick_params(labelleft=False)
    ax_j.plot(J, x, color=EXACT)
    ax_j.set_ylim(360, 0)
    ax_j.set_yticks(range(0, 361, 90))
    ax_j.set_xlabel(tr("figures.dyn08"))
    ax_j.set_ylabel(tr("figures.dyn09"))
    for a in (ax_e, ax_w, ax_j):
        comma_axes(a)
    fig.tight_layout()
    return fig


def omega_figure(res, omegas: dict[str, np.ndarray]):
    """ω(φ) of the steady motion with each method's flywheel, the band ω_m(1 ± δ/2)."""
    fig = new_figure(16.0, 8.0)
    ax = fig.add_subplot(1, 1, 1)
    names = {"exact": (tr("figures.wdyn03"), EXACT, "-", 1.3), "merzalov": (tr("figures.dyn15"), "tab:green", "--", 0.9),
             "graphical": (tr("figures.dyn16"), GRAPH, ":", 1.1)}
    for key, w in omegas.items():
        label, colour, ls, lw = names[key]
        x, wc = _closed(res, w, float(w[0]))
        ax.plot(x, wc, color=colour, ls=ls, lw=lw, label=label)
    lo, hi = res.motion.band
    for v in (lo, hi):
        ax.axhline(v, color="tab:red", lw=0.7)
    ax.axhline(res.omega_m, color="0.4", lw=0.6, ls="-.")
    ax.set_xlim(0, 360)
    ax.set_xticks(range(0, 361, 30))
    ax.set_xlabel(tr("figures.dyn10"))
    ax.set_ylabel(tr("figures.dyn11"))
    ax.legend(loc="best", fontsize=8)
    comma_axes(ax)
    fig.tight_layout()
    return fig


def flywheel_figure(fw, hub):
    """Sketch of the flywheel: the front view with the bore and its keyway, and the axial section
    through the keyway (the hub's parts of :mod:`reportgen.dynamics.hub`, as sheet 3 draws them),
    with D, b, the bore d and d + t2 dimensioned in millimetres."""
    from reportgen.dynamics.hub import bore_outline, section_rects
    R, b = fw.radius * 1000, fw.width * 1000
    r_in = fw.inner_radius * 1000
    fig = new_figure(15.0, 8.5)
    ax = fig.add_axes([0.02, 0.02, 0.96, 0.96])
    # front view
    ax.add_patch(Circle((0, 0), R, fill=False, lw=1.2))
    if r_in > 0:
        ax.add_patch(Circle((0, 0), r_in, fill=False, lw=1.2))
        ax.add_patch(Circle((0, 0), hub.hub_d / 2, fill=False, lw=1.2))
    bore = np.asarray(bore_outline(hub))
    ax.add_patch(Polygon(bore, closed=True, fill=False, lw=1.0))
    ext = 1.12 * R
    for p, q in (((-ext, 0), (ext, 0)), ((0, -ext), (0, ext))):
        ax.plot(*zip(p, q), color="0.3", lw=0.5, ls="-.")
    # section through the keyway, to the right
    x0 = 1.6 * R
    for ax0, ry0, ax1, ry1 in section_rects(R, r_in, b, hub):
        ax.add_patch(Rectangle((x0 + ax0, ry0), ax1 - ax0, ry1 - ry0, fill=True, facecolor="white", hatch="///",
                               lw=1.2, edgecolor="black"))
    ax.plot([x0 - 0.12 * R, x0 + b + 0.12 * R], [0, 0], color="0.3", lw=0.5, ls="-.")
    # dimensions
    _dim(ax, (x0 + b + 0.25 * R, -R), (x0 + b + 0.25 * R, R), f"Ø{comma(round(2 * R))}", vertical=True)
    _dim(ax, (x0, R + 0.18 * R), (x0 + b, R + 0.18 * R), comma(round(b)), vertical=False)
    _dim(ax, (x0 - 0.12 * R, -hub.d / 2), (x0 - 0.12 * R, hub.d / 2 + hub.t2), comma(hub.d + hub.t2), vertical=True)
    _dim(ax, (-hub.d / 2, -0.3 * R), (hub.d / 2, -0.3 * R), f"Ø{comma(hub.d)}", vertical=False, below=True)
    for xx in (-hub.d / 2, hub.d / 2):
        ax.plot([xx, xx], [0, -0.3 * R - 0.03 * R], color="black", lw=0.4)
    if r_in > 0:
        _dim(ax, (x0 - 0.3 * R, -r_in), (x0 - 0.3 * R, r_in), f"Ø{comma(round(2 * r_in))}", vertical=True)
    ax.set_aspect("equal")
    ax.set_xlim(-1.2 * R, x0 + b + 0.7 * R)
    ax.set_ylim(-1.25 * R, 1.45 * R)
    ax.axis("off")
    return fig


def _dim(ax, p, q, text: str, vertical: bool, below: bool = False) -> None:
    ax.annotate("", xy=q, xytext=p, arrowprops=dict(arrowstyle="<|-|>", lw=0.6, color="black",
                                                    mutation_scale=8, shrinkA=0, shrinkB=0))
    mx, my = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
    if vertical:
        t = ax.text(mx, my, text + " ", rotation=90, ha="right", va="center", fontsize=10)
    else:
        t = ax.text(mx, my, text, ha="center", va="top" if below else "bottom", fontsize=10)
    names(t, p, q)
