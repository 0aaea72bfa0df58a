"""Figures of section 4: the blocking contour, the meshing picture, the specific sliding graph
(subsection 4.1) and the planetary scheme with the velocity triangle and the angular-velocity plan
(subsection 4.2). Each function takes solver objects and returns a matplotlib figure."""
from __future__ import annotations

import math

import numpy as np

from ..parts import tr
from . import comma, comma_axes, new_figure
from .keyed import keyed_plot

#: Russian names of the contour lines (legend), in drawing order.
CONTOUR_NAMES = {
    "undercut1": tr("figures.gear01"),
    "undercut2": tr("figures.gear02"),
    "sharpening1": tr("figures.gear03"),
    "sharpening2": tr("figures.gear04"),
    "contact_ratio": tr("figures.gear05"),
    "eps_1": "$\\varepsilon_\\alpha = 1$",
    "interference1": tr("figures.gear06"),
    "interference2": tr("figures.gear07"),
    "equal_sliding": "$\\lambda_1(a) = \\lambda_2(b)$",
}
_STYLES = {
    "undercut1": dict(color="C0", ls="-"), "undercut2": dict(color="C0", ls="--"),
    "sharpening1": dict(color="C3", ls="-"), "sharpening2": dict(color="C3", ls="--"),
    "contact_ratio": dict(color="C2", ls="-"), "eps_1": dict(color="C2", ls=":"),
    "interference1": dict(color="C4", ls="-"), "interference2": dict(color="C4", ls="--"),
    "equal_sliding": dict(color="k", ls="-.", lw=1.0),
}


@keyed_plot()
def blocking_contour_figure(pair):
    """The computed blocking contour of the pair with the chosen point (x1, x2)."""
    choice = pair.shift_choice
    bc = choice.contour
    fig = new_figure(16, 12)
    ax = fig.add_subplot(111)
    X1, X2 = np.meshgrid(bc.x1, bc.x2, indexing="ij")
    ax.contourf(X1, X2, bc.feasible.astype(float), levels=[0.5, 1.5], colors=["#dfe9f5"])
    for name, label in CONTOUR_NAMES.items():
        lines = bc.curves.get(name, ())
        for i, ln in enumerate(lines):
            ax.plot(ln[:, 0], ln[:, 1], label=label if i == 0 else None, **_STYLES[name])
    ax.plot([choice.x1], [choice.x2], "o", color="k", ms=5, zorder=5)
    x1_text, x2_text = (comma(v).replace(",", "{,}") for v in (choice.x1, choice.x2))
    ax.annotate(f"$x_1 = {x1_text}$\n$x_2 = {x2_text}$", (choice.x1, choice.x2),
                xytext=(8, 8), textcoords="offset points", fontsize=9,
                bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="0.6", lw=0.5))
    ax.set_xlim(float(bc.x1[0]), float(bc.x1[-1]))
    ax.set_ylim(float(bc.x2[0]), float(bc.x2[-1]))
    ax.set_xlabel("$x_1$")
    ax.set_ylabel("$x_2$")
    comma_axes(ax)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=3, fontsize=8, frameon=False)
    return fig


#: The zones' colours (the note's legend): two pairs, one pair in contact.
ZONE_COLOURS = {2: "#1f77b4", 1: "#d62728"}


def meshing_frame(pic) -> tuple[float, float, float, float]:
    """The note's window of the meshing picture round the pole (real mm): the scene's detail
    (:func:`reportgen.scenes.meshing.detail_frame`)."""
    from reportgen.scenes.meshing import detail_frame
    return detail_frame(pic)


def meshing_reduction(ms) -> float:
    """Page mm per scene mm of the note's window (at most 1: the sheet's scale), the scene's
    :func:`reportgen.scenes.meshing.detail_reduction`."""
    from reportgen.scenes.meshing import detail_reduction
    return detail_reduction(ms.pic, ms.scale)


@keyed_plot()
def meshing_figure(_pair, ms):
    """The meshing picture round the pole: a window of sheet 4's scene
    (:class:`reportgen.scenes.meshing.MeshingScene`, the same teeth, circles, lines and points in
    the sheet's mm), reduced by :func:`meshing_reduction` (the caption says so and names the
    sheet's scale); the zones of one and two pairs coloured, and the designations of sheet 4
    (r, rb, rw, ra, rf of each wheel, s, p, αw, the points, the dimension ab) where the scene
    placed them for both (``ms.marks``, :func:`reportgen.scenes.meshing.meshing_marks`: the same
    places and sides as on sheet 4), at the note's letter sizes; the sheet's marks outside the
    window are left out. ``fig.scene`` is the scene, ``fig.reportgen_reduction`` the reduction,
    ``fig.reportgen_marks`` the marks drawn."""
    from dataclasses import replace

    from matplotlib.lines import Line2D

    from reportgen.scenes.scene import Circle, Polyline, Segment

    from .scene import PENS

    scene, k = ms.scene, ms.scale.factor
    r = meshing_reduction(ms)
    room = meshing_frame(ms.pic)                        # real mm
    marks = replace(ms.marks, marks=tuple(m for m in ms.marks.marks if m.page_h > 0),
                    dimensions=tuple(d for d in ms.marks.dimensions if d.detail))
    x0, y0, x1, y1 = (v * k for v in room)              # scene mm
    w_mm, h_mm = (x1 - x0) * r, (y1 - y0) * r
    fig = new_figure(w_mm / 10.0, h_mm / 10.0)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    for e in scene.entities:
        lw, ls = PENS.get(e.kind, (0.6, "-"))
        if isinstance(e, Polyline):
            xs, ys = zip(*e.points)
            ax.plot(xs, ys, color="k" if e.kind == "contour" else "0.25", lw=lw if e.kind == "contour" else 0.5,
                    ls=ls)
        elif isinstance(e, Segment) and e.id.startswith("zone") and ":tick" not in e.id:
            ax.plot([e.a[0], e.b[0]], [e.a[1], e.b[1]], color=ZONE_COLOURS[int(e.id[4])], lw=4,
                    solid_capstyle="butt", alpha=0.55, zorder=3)
        elif isinstance(e, Segment):
            ax.plot([e.a[0], e.b[0]], [e.a[1], e.b[1]], color="k" if e.kind in ("contour", "vectors") else "0.3",
                    lw=lw if e.kind == "contour" else 0.5, ls=ls)
        elif isinstance(e, Circle):
            ax.plot([e.c[0]], [e.c[1]], "o", color="k", ms=2.5, zorder=4)
    _draw_marks(ax, marks, k, page_k=k * r)
    handles = [Line2D([], [], color=ZONE_COLOURS[2], lw=4, alpha=0.55, label=tr("figures.gear12")),
               Line2D([], [], color=ZONE_COLOURS[1], lw=4, alpha=0.55, label=tr("figures.gear13")),
               Line2D([], [], color="0.25", lw=0.5, ls=PENS["axis"][1], label=tr("figures.gear14")),
               Line2D([], [], color="0.25", lw=0.5, ls=PENS["hidden"][1], label=tr("figures.gear15"))]
    ax.legend(handles=handles, loc="upper left", fontsize=8, frameon=True, framealpha=0.9)
    fig.reportgen_marks = marks          # for the tests: the boxes as placed (real mm)
    fig.reportgen_reduction = r
    fig.scene = scene
    return fig


#: The note's TeX spelling of a designation («r_{b1}») is about this share of the width the
#: placement estimates for the sheet's spelling («rb1») at the same height.
NOTE_TEXT_WIDTH = 0.75


def _draw_marks(ax, marks, unit: float = 1.0, page_k: float | None = None) -> None:
    """The designations of :class:`reportgen.scenes.meshing_marks.MeshingMarks` (real mm, drawn
    ×``unit`` on axes in scene mm, ``page_k`` page mm per real mm) with matplotlib: leaders, texts
    in their boxes (TeX spelling), arcs of s and p with end ticks, the arc of αw, the dimension ab
    with its arrows and text."""
    from reportgen.scenes.meshing import DETAIL_DIM_H
    from reportgen.scenes.meshing_marks import text_size

    from .labels import names
    k = marks.k
    page_k = page_k if page_k is not None else k
    pt_per_mm = 72.0 / 25.4

    def u(p):
        return (p[0] * unit, p[1] * unit)

    for arc in marks.arcs:
        xs, ys = zip(*(u(p) for p in arc.points()))
        ax.plot(xs, ys, color="k", lw=0.5)
        for a_ in (arc.a0, arc.a1):
            c, s_ = math.cos(a_), math.sin(a_)
            r0, r1 = arc.radius - 1.5 / k, arc.radius + 1.5 / k
            ax.plot([(arc.centre[0] + r0 * c) * unit, (arc.centre[0] + r1 * c) * unit],
                    [(arc.centre[1] + r0 * s_) * unit, (arc.centre[1] + r1 * s_) * unit], color="k", lw=0.5)
    xs, ys = zip(*(u(p) for p in marks.angle.points()))
    ax.plot(xs, ys, color="k", lw=0.5)
    for m in marks.marks:
        if m.leader:
            lx, ly = zip(*(u(p) for p in m.leader))
            ax.plot(lx, ly, color="k", lw=0.4, zorder=5)
        # beside its point or circle: as near to it as the box allows, as on the sheet (the width
        # of the TeX spelling, subscripts included, about NOTE_TEXT_WIDTH of the sheet's estimate)
        w, h = (v / page_k for v in text_size(m.text, m.page_h))
        cx, cy = u(m.text_centre(w * NOTE_TEXT_WIDTH, h))
        t = ax.text(cx, cy, f"${m.tex}$", fontsize=m.page_h * pt_per_mm * 0.95, ha="center", va="center",
                    zorder=6)
        names(t, *((u(p) for p in m.leader) if m.leader else (u(m.anchor),)))
    for d in marks.dimensions:
        L = math.dist(d.p1, d.p2)
        nx, ny = -(d.p2[1] - d.p1[1]) / L, (d.p2[0] - d.p1[0]) / L
        off = d.offset_mm / k
        q1 = (d.p1[0] + nx * off, d.p1[1] + ny * off)
        q2 = (d.p2[0] + nx * off, d.p2[1] + ny * off)
        for p, q in ((d.p1, q1), (d.p2, q2)):
            ax.plot([p[0] * unit, (q[0] + nx * 1.5 / k * (1 if off > 0 else -1)) * unit],
                    [p[1] * unit, (q[1] + ny * 1.5 / k * (1 if off > 0 else -1)) * unit], color="k", lw=0.4)
        ax.annotate("", xy=u(q2), xytext=u(q1), arrowprops=dict(arrowstyle="<|-|>", lw=0.5, color="k",
                                                                 shrinkA=0, shrinkB=0, mutation_scale=6))
        bx = [p[0] for p in d.box]
        by = [p[1] for p in d.box]
        ang = math.degrees(math.atan2(d.p2[1] - d.p1[1], d.p2[0] - d.p1[0]))
        if ang > 90.0 or ang <= -90.0:
            ang += 180.0
        ax.text((min(bx) + max(bx)) / 2 * unit, (min(by) + max(by)) / 2 * unit, d.text,
                fontsize=DETAIL_DIM_H * pt_per_mm, rotation=ang, rotation_mode="anchor", ha="center", va="center")


@keyed_plot()
def sliding_figure(pair):
    """λ1 and λ2 along N1N2 with the working section ab and the pole marked."""
    sl = pair.sliding
    g = pair.geometry
    rho, l1, l2 = sl.curve(401, clip=0.005)
    fig = new_figure(16, 9)
    ax = fig.add_subplot(111)
    ax.plot(rho, l1, color="C0", label=tr("figures.gear10"))
    ax.plot(rho, l2, color="C3", label=tr("figures.gear11"))
    lo = min(-4.0, 1.3 * min(sl.lambda1_a, sl.lambda2_b))
    ax.set_ylim(lo, 1.5)
    ax.set_xlim(0, sl.g)
    ax.axhline(0, color="k", lw=0.6)
    ax.axhline(1, color="0.4", lw=0.5, ls=":")
    for name, x in (("$a$", g.n1a), ("$P$", g.n1p), ("$b$", g.n1b)):
        ax.axvline(x, color="0.3", lw=0.6, ls="--")
        ax.text(x, 1.52, name, ha="center", va="bottom", fontsize=10)
    ax.axvspan(g.n1a, g.n1b, color="#dfe9f5", zorder=0)
    rows = [r for r in sl.rows if math.isfinite(r.lambda1) and math.isfinite(r.lambda2)]
    ax.plot([r.rho for r in rows], [r.lambda1 for r in rows], "o", color="C0", ms=3)
    ax.plot([r.rho for r in rows], [r.lambda2 for r in rows], "s", color="C3", ms=3)
    ax.set_xlabel(tr("figures.gear09"))
    ax.set_ylabel("$\\lambda$")
    comma_axes(ax)
    ax.legend(loc="lower center", fontsize=9)
    return fig


# ------------------------------------------------------------------------------- planetary
@keyed_plot()
def planetary_figure(stage):
    """The reducer's kinematic scheme (as on sheet 4), Kutzbach's velocity triangle beside it at the
    same heights with projection lines, and the angular-velocity plan below the triangle."""
    from reportgen.scenes.planetary import merge, plan_scene, side_scheme, triangle_scene
    tri = stage.triangle
    scheme = side_scheme(stage.design, tri.length_scale)
    x_line = scheme.bounds()[2] + 25
    triangle = triangle_scene(tri, x_line, scheme.marks)
    pts = dict(tri.points)
    plan_origin = (x_line + 10 - min(0.0, *[x for _, x in tri.plan.cuts]), -tri.plan.h_mm - 25)
    scene = merge(scheme, triangle, plan_scene(tri, plan_origin))
    del pts
    x0, y0, x1, y1 = scene.bounds()
    w_cm = 16.0
    h_cm = min(20.0, w_cm * (y1 - y0 + 10) / (x1 - x0 + 10))
    fig = new_figure(w_cm, h_cm)
    ax = fig.add_axes([0, 0, 1, 1])
    _draw_scene(ax, scene)
    ax.set_aspect("equal")
    ax.set_xlim(x0 - 5, x1 + 5)
    ax.set_ylim(y0 - 5, y1 + 5)
    ax.axis("off")
    return fig


def _draw_scene(ax, scene) -> None:
    """Draw a :class:`reportgen.scenes.planetary.Scene` (mm) with matplotlib."""
    widths = {"contour": 1.3, "thin": 0.4, "axis": 0.5, "hidden": 0.5}
    dashes = {"axis": "-.", "hidden": "--"}
    for line in scene.lines:
        xs, ys = zip(*line.points)
        ax.plot(xs, ys, color="k" if line.layer != "thin" else "0.4", lw=widths.get(line.layer, 0.8),
                ls=dashes.get(line.layer, "-"))
    for c in scene.circles:
        t = np.linspace(0, 2 * math.pi, 361)
        ax.plot(c.centre[0] + c.radius * np.cos(t), c.centre[1] + c.radius * np.sin(t), color="k",
                lw=widths.get(c.layer, 0.8), ls=dashes.get(c.layer, "-"))
    for (x0, y0), (x1, y1) in scene.hatches:
        ax.plot([x0, x1], [y0, y1], color="k", lw=0.5)
    for (x0, y0), (x1, y1), lab in scene.arrows:
        ax.annotate("", xy=(x1, y1), xytext=(x0, y0),
                    arrowprops=dict(arrowstyle="-|>", lw=1.1, color="k", shrinkA=0, shrinkB=0))
        text = {"vA": "$v_A$", "vB": "$v_B$"}.get(lab, lab)
        ax.text(x1 + 2, y1 + 2, text, fontsize=9, ha="left", va="bottom")
    for lab in scene.labels:
        ax.text(lab.point[0], lab.point[1], lab.text, fontsize=9, ha="center", va="center",
                bbox=dict(boxstyle="square,pad=0.05", fc="white", ec="none"))
