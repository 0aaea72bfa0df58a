"""The meshing picture (картина зацепления) and the specific-sliding diagram on sheet 4.

The scale is decided once, for the window the sheet gives the picture, by
:func:`reportgen.scenes.meshing.meshing_scale`; the note quotes the same scale (and the length of ab
read on the sheet).
"""
from __future__ import annotations

import math
from reportgen.gears.meshing import GOST_SCALES, MeshingPicture

from reportgen.scenes.meshing import (CAPTION, PADDING, VIEW_H, VIEW_W, WINDOW_H, WINDOW_W,  # noqa: F401
                                     DrawingScale, ab_on_sheet, label_room, meshing_marks,
                                     meshing_scale, model_bounds, model_centre)
from ..words import decimal_mark, tr


# --------------------------------------------------------------------------------------- DXF
CIRCLE_LAYERS = {"pitch": "axis", "base": "thin", "working": "hidden", "tip": "thin", "root": "thin"}


def draw_meshing(sheet, pair, pic: MeshingPicture, rect) -> DrawingScale:
    """The meshing picture in ``rect`` (a :class:`drawings.layout.Rect` of VIEW_W × VIEW_H) at its
    ГОСТ scale: bold teeth, circles as arcs through the meshing zone (pitch dash-dot, working dashed,
    others thin), the line of centres, N1N2, the tangent at P, ab with its zones, and the
    designations placed by :func:`reportgen.scenes.meshing.meshing_marks` (the note draws the same)."""
    from shapely.geometry import LineString, Point as SPoint, box

    from drawings.primitives import Transform

    g = pair.geometry
    scale = meshing_scale(pair, pic)
    k = scale.factor
    marks = meshing_marks(pair, pic, scale)
    cx, cy = model_centre(pair, pic)
    at = (rect.center[0], rect.center[1] - CAPTION / 2)
    view = sheet.place_view("meshing", rect, Transform(k, (cx, cy), at))
    rx0, ry0, rx1, ry1 = label_room(pair, pic, scale)
    window = box(rx0, ry0, rx1, ry1)
    arc_window = box(*marks.arcs_window).intersection(window)
    for c in pic.circles:
        ring = SPoint(c.centre).buffer(c.radius, 720).exterior
        part = ring.intersection(arc_window)
        if not part.is_empty:
            view.geometry(part, CIRCLE_LAYERS[c.kind])
    for tooth in pic.teeth1 + pic.teeth2:
        view.polyline([tuple(p) for p in tooth], "contour")
    view.line((0.0, max(ry0, -g.m)), (0.0, min(ry1, g.aw + g.m)), "axis")
    (tx0, ty0), (tx1, ty1) = pic.segments["tangent"]
    tl = LineString([(tx0, ty0), (tx1, ty1)]).intersection(window)
    if not tl.is_empty:
        view.geometry(tl, "thin")
    n1, n2 = pic.points["N1"], pic.points["N2"]
    view.line(n1, n2, "thin")
    a, b = pic.points["a"], pic.points["b"]
    view.line(a, b, "contour")
    # zones of double (II) and single (I) contact, on a line 6 mm beside ab
    L = math.dist(n1, n2)
    ux, uy = (n2[0] - n1[0]) / L, (n2[1] - n1[1]) / L
    nx, ny = uy, -ux                                   # to the lower right of N1N2
    off = 6.0 / k
    for z in pic.zones:
        if z.pairs == 0:
            continue
        p = (z.start[0] + nx * off, z.start[1] + ny * off)
        q = (z.end[0] + nx * off, z.end[1] + ny * off)
        view.line(p, q, "vectors")
        for e in (p, q):
            view.line((e[0] - nx * off * 0.4, e[1] - ny * off * 0.4), (e[0] + nx * off * 0.4, e[1] + ny * off * 0.4), "thin")
        mid = ((p[0] + q[0]) / 2 + nx * off * 0.9, (p[1] + q[1]) / 2 + ny * off * 0.9)
        view.text(mid, "II" if z.pairs >= 2 else "I", 3.5, "center")
    for name in ("O1", "O2", "P", "N1", "N2", "a", "b"):
        view.circle_mm(pic.points[name], 0.8, "contour")
    draw_marks(view, marks)
    view.text_mm((rect.center[0], rect.y1 - 7), tr("sheets.me01", v1=scale.label.replace(",", decimal_mark())), 5.0, "bottom-center")
    view.text_mm((rect.x0 + 2, rect.y0 + 2), tr("sheets.me02"), 3.5, "bottom-left")
    return scale


def draw_marks(view, marks) -> None:
    """The designations (:class:`reportgen.scenes.meshing_marks.MeshingMarks`) on a view whose
    model unit is the real mm: leaders thin, texts at their boxes, arcs of s and p with end
    ticks, the arc of αw, the dimensions ab and aw at their chosen offsets."""
    k = marks.k
    for arc in marks.arcs:
        view.polyline(arc.points(), "thin")
        for a_ in (arc.a0, arc.a1):
            c, s_ = math.cos(a_), math.sin(a_)
            r0, r1 = arc.radius - 1.8 / k, arc.radius + 1.8 / k
            view.line((arc.centre[0] + r0 * c, arc.centre[1] + r0 * s_),
                      (arc.centre[0] + r1 * c, arc.centre[1] + r1 * s_), "thin")
    view.polyline(marks.angle.points(), "thin")
    for m in marks.marks:
        if m.leader:
            view.polyline(list(m.leader), "thin")
        text = tr(f"marks.sheet4.{m.text}") if m.word else m.text
        x0, y0, x1, y1 = m.box
        view.text(((x0 + x1) / 2, (y0 + y1) / 2), text, m.height, "center")
    for d in marks.dimensions:
        view.dimension(d.p1, d.p2, offset_mm=d.offset_mm, unit_factor=1.0, text=d.text)


def draw_sliding(sheet, pair, rect, k: float) -> None:
    """The specific-sliding diagram λ1, λ2 over ρ = N1K (x at the meshing scale ``k``)."""
    from drawings.primitives import Transform, format_number
    sl = pair.sliding
    g = pair.geometry
    # ρ at a ГОСТ scale that uses the width of the view
    k = next((f for f in GOST_SCALES if g.g * f <= rect.width - 70), GOST_SCALES[-1])
    x_len = g.g * k
    lam_low = math.floor(min(sl.lambda1_a, sl.lambda2_b, -1.0) * 1.5)
    span = 1.0 - lam_low
    per_unit = next(v for v in (40.0, 30.0, 25.0, 20.0, 15.0, 10.0, 5.0) if v * span <= rect.height - 38)
    ox = rect.x0 + 22
    oy = rect.y0 + 14 + (-lam_low) * per_unit
    view = sheet.place_view("sliding", rect, Transform(1.0, (0.0, 0.0), (ox, oy)))
    yt = [(v * per_unit, format_number(v, 0)) for v in range(int(lam_low), 2)]
    view.axes((0.0, 0.0), x_len + 12, per_unit * 1.0 + 10, y_down_mm=-lam_low * per_unit,
              x_label=tr("sheets.me04"), y_label="λ", y_ticks=yt)
    rho, l1, l2 = sl.curve(801, clip=0.002)
    for lam in (l1, l2):
        pts = [(r_ * k, v * per_unit) for r_, v in zip(rho, lam) if v >= lam_low]
        if len(pts) > 1:
            view.polyline(pts, "contour")
    for name, x in (("a", g.n1a), ("P", g.n1p), ("b", g.n1b)):
        view.line((x * k, lam_low * per_unit), (x * k, per_unit), "thin")
        view.text((x * k + 1.5, per_unit + 1.5), name, 3.5)
    view.line((g.g * k, -2.0), (g.g * k, 2.0), "thin")
    view.text((g.g * k, -3.0), "N2", 3.5, "top-center")
    i1 = min(range(len(rho)), key=lambda i: abs(rho[i] - 0.2 * g.g))
    view.text((rho[i1] * k + 2, max(l1[i1], lam_low) * per_unit), "λ1", 3.5)
    i2 = min(range(len(rho)), key=lambda i: abs(rho[i] - 0.8 * g.g))
    view.text((rho[i2] * k - 2, max(l2[i2], lam_low) * per_unit), "λ2", 3.5, "bottom-right")
    mu = 1.0 / per_unit
    view.text_mm((rect.x1 - 2, rect.y1 - 7), tr("sheets.me03", v1=format_number(mu, 4), v2=format_number(1 / k, 4)), 3.5, "bottom-right")
