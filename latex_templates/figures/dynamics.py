"""Figures of section 3 (dynamics, matplotlib) from :class:`reportgen.dynamics.DynamicsResult`:
ω(φ) with the band and each method's flywheel, and the flywheel's sketch. The diagrams of the
graphical construction (M_red, works, ΔE, Wittenbauer, J_red) are scenes
(:mod:`reportgen.scenes.dynamics`), drawn by :mod:`latex_templates.figures.scene` as on sheet 3."""
from __future__ import annotations


import numpy as np
from matplotlib.patches import Circle, Polygon, Rectangle

from ..parts import tr
from . import comma, comma_axes, new_figure
from .labels import names
from .keyed import keyed_plot

GRAPH = "tab:blue"        # the graphical construction
EXACT = "black"


def _closed(res, values: np.ndarray, end: float) -> tuple[np.ndarray, np.ndarray]:
    """θ in degrees 0…360 and the values with the value at 360° appended."""
    x = np.append(np.degrees(np.asarray(res.theta)), 360.0)
    return x, np.append(np.asarray(values, dtype=float), end)


@keyed_plot()
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


@keyed_plot()
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
