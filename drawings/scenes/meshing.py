"""The meshing picture (картина зацепления) and the specific-sliding diagram on sheet 4.

The scale is decided once, for the window the sheet gives the picture, by
:func:`reportgen.scenes.meshing.meshing_scale`; the note quotes the same scale (and the length of ab
read on the sheet).
"""
from __future__ import annotations

import math
from reportgen.gears.meshing import GOST_SCALES

from reportgen.scenes.meshing import (CAPTION, PADDING, VIEW_H, VIEW_W, WINDOW_H, WINDOW_W,  # noqa: F401
                                     DrawingScale, MeshingScene, ab_on_sheet, label_room, meshing_marks,
                                     meshing_scale, model_bounds, model_centre)
from drawings import style
from drawings.lettering import from_tex
from ..words import decimal_mark, tr


# --------------------------------------------------------------------------------------- DXF
def draw_meshing(sheet, pair, ms: MeshingScene, rect) -> DrawingScale:
    """The meshing picture (:class:`reportgen.scenes.meshing.MeshingScene`, the note draws a
    window of the same scene) in ``rect`` (a :class:`drawings.layout.Rect` of VIEW_W × VIEW_H) at
    its ГОСТ scale: the scene's entities, the zones' numerals, and the designations as
    :func:`reportgen.scenes.meshing.meshing_marks` placed them for the sheet."""
    from drawings.primitives import Transform
    from drawings.scenes.render import draw_entities

    pic, scale, scene = ms.pic, ms.scale, ms.scene
    k = scale.factor
    cx, cy = model_centre(pair, pic)
    at = (rect.center[0], rect.center[1] - CAPTION / 2)
    view = sheet.place_view("meshing", rect, Transform(k, (cx, cy), at))      # model: real mm
    draw_entities(view, scene.entities, 1.0 / k)
    for lb in scene.labels:
        if lb.role == "zone":
            view.text((lb.at[0] / k, lb.at[1] / k), lb.text, 3.5, "center")
    draw_marks(view, ms.marks)
    view.text_mm((rect.center[0], rect.y1 - 7), tr("sheets.me01", v1=scale.text(decimal_mark())), 5.0, "bottom-center")
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
        if not m.word and ("_" in m.tex or "^" in m.tex):
            _draw_indexed(view, m, from_tex(m.tex))
            continue
        text = tr(f"marks.sheet4.{m.text}") if m.word else m.text
        x0, y0, x1, y1 = m.box
        if m.leader:
            # the box holds the note's text too (placed once for both, at the note's size): the
            # sheet's text in its middle on the leader's shelf, the shelf to the text's far end
            w = style.text_width(text, m.height) / k
            leader = list(m.leader)
            elbow, end = leader[-2], leader[-1]
            right = end[0] >= elbow[0]
            cx = (x0 + x1) / 2
            leader[-1] = ((cx + w / 2) if right else (cx - w / 2), elbow[1])
            view.polyline(leader, "thin")
            view.text((cx, y0), text, m.height, "bottom-center")
        else:
            # a letter beside its point, a name beside its circle: in its box, as near to what it
            # names as the box allows (Mark.text_centre: the note's figure writes it so too)
            view.text(m.text_centre(style.text_width(text, m.height) / k, m.height / k), text, m.height, "center")
    for d in marks.dimensions:
        view.dimension(d.p1, d.p2, offset_mm=d.offset_mm, unit_factor=1.0, text=d.text)


def _at(rho, lam, rho_at: float, k: float, per_unit: float, lam_low: float, dx: float) -> tuple[float, float]:
    """A point (view mm) ``dx`` beside the curve λ(ρ) where ρ is nearest ``rho_at`` (cut at λ's lowest)."""
    i = min(range(len(rho)), key=lambda j: abs(rho[j] - rho_at))
    return (rho[i] * k + dx, max(lam[i], lam_low) * per_unit)


def _draw_indexed(view, m, rich) -> None:
    """A designation with an index (r_b1, α_w, s_1, O_1; :func:`drawings.lettering.from_tex`), its
    index one ГОСТ size smaller and lowered: on a leader, standing on its shelf (the index clear of
    it) in the middle of its box; else in its box as near to its point as the box allows."""
    from drawings.scenes import kinematics_labels as rl
    k = view.transform.scale
    w, depth, _ = rl.size(rich, m.height)
    x0, y0, x1, y1 = m.box
    if m.leader:
        leader = list(m.leader)
        elbow, end = leader[-2], leader[-1]
        right = end[0] >= elbow[0]
        cx = (x0 + x1) / 2
        leader[-1] = ((cx + w / 2 / k) if right else (cx - w / 2 / k), elbow[1])
        view.polyline(leader, "thin")
        bx, by = view.transform((cx, y0))
        rl.draw_rich(view, (bx, by + depth + m.height / 2 + SHELF_GAP_MM), rich, m.height)
    else:
        c = m.text_centre(w / k, (m.height + depth) / k)
        cx, cy = view.transform(c)
        rl.draw_rich(view, (cx, cy + depth / 2), rich, m.height)


#: An indexed designation's lowest letters (its index) stand this far over its leader's shelf, mm.
SHELF_GAP_MM = 0.3


#: The names a, P, b of the sliding diagram keep this far from each other and from the λ axis's
#: name (sheet mm, between their boxes padded by 0,5 mm: 2 mm between the letters).
NAME_CLEAR_MM = 1.0
#: The ρ axis goes this far beyond N2 (or b beyond it): its name «ρ, мм» clear of N2's tick (sheet mm).
AXIS_BEYOND_N2_MM = 28.0
#: The sliding diagram's caption stands this far above the end of its λ axis (sheet mm).
CAPTION_ABOVE_MM = 6.0
#: Sheet mm per unit of λ, the largest that fits the view first.
SLIDING_UNITS = (40.0, 30.0, 25.0, 20.0, 15.0, 10.0, 5.0)


def draw_sliding(sheet, pair, rect, k: float) -> None:
    """The specific-sliding diagram λ1, λ2 over ρ = N1K (x at the meshing scale ``k``)."""
    from drawings.primitives import Transform, format_number, text_box
    sl = pair.sliding
    g = pair.geometry
    # ρ at a ГОСТ scale that uses the width of the view; the active line a…b can stand out of
    # N1…N2 (interference: a pair on that limit of its blocking contour drew b 13 mm over the frame)
    x_lo, x_hi = min(0.0, g.n1a), max(g.g, g.n1b)
    k = next((f for f in GOST_SCALES if (x_hi - x_lo) * f <= rect.width - 70), GOST_SCALES[-1])
    x_len = g.g * k
    lam_low = math.floor(min(sl.lambda1_a, sl.lambda2_b, -1.0) * 1.5)
    # near the limits of the blocking contour λ at a or b runs to −∞ (a at N1: undercut): the
    # axis is cut where the smallest unit still fits the view, the curves leave it at the bottom
    lam_low = max(lam_low, 1 - math.floor((rect.height - 38) / SLIDING_UNITS[-1]))
    span = 1.0 - lam_low
    per_unit = next(v for v in SLIDING_UNITS if v * span <= rect.height - 38)
    ox = rect.x0 + 22 - x_lo * k
    oy = rect.y0 + 14 + (-lam_low) * per_unit
    view = sheet.place_view("sliding", rect, Transform(1.0, (0.0, 0.0), (ox, oy)))
    yt = [(v * per_unit, format_number(v, 0)) for v in range(int(lam_low), 2)]
    view.axes((0.0, 0.0), max(x_len, x_hi * k) + AXIS_BEYOND_N2_MM, per_unit * 1.0 + 10, y_down_mm=-lam_low * per_unit,
              x_label=tr("sheets.me04"), y_label="λ", y_ticks=yt)
    rho, l1, l2 = sl.curve(801, clip=0.002)
    for lam in (l1, l2):
        pts = [(r_ * k, v * per_unit) for r_, v in zip(rho, lam) if v >= lam_low]
        if len(pts) > 1:
            view.polyline(pts, "contour")
    # a, P, b above their lines, each on the lowest level where it keeps NAME_CLEAR_MM from the
    # names before it and from the λ axis's name (a at ρ = 0 touched «λ» at a corner of the
    # blocking contour; P near a or b at its limits)
    taken = [text_box((ox + 2.5, oy + per_unit + 10.0), "λ", 5.0, "top-left")]
    for name, x in sorted((("a", g.n1a), ("P", g.n1p), ("b", g.n1b)), key=lambda item: item[1]):
        level = 0
        while True:
            at = (x * k + 1.5, per_unit + 1.5 + 5.0 * level)
            poly = text_box((ox + at[0], oy + at[1]), name, 3.5, "bottom-left")
            if all(poly.distance(t) >= NAME_CLEAR_MM for t in taken) or level > 6:
                break
            level += 1
        taken.append(poly)
        view.line((x * k, lam_low * per_unit), (x * k, per_unit + 5.0 * level), "thin")
        view.text(at, name, 3.5)
    view.line((g.g * k, -2.0), (g.g * k, 2.0), "thin")
    from drawings.scenes import kinematics_labels as rl
    for tex, (x, y), side in (("N_{2}", (g.g * k, -3.0), 0),
                              ("\\lambda_{1}", _at(rho, l1, 0.2 * g.g, k, per_unit, lam_low, 2.0), 1),
                              ("\\lambda_{2}", _at(rho, l2, 0.8 * g.g, k, per_unit, lam_low, -2.0), -1)):
        rich = from_tex(tex)           # with its index (issue 12): N₂ under its tick, λ₁ and λ₂ beside their curves
        w, depth, _ = rl.size(rich, 3.5)
        px, py = view.transform((x, y))
        centre = (px, py - 3.5 / 2) if side == 0 else (px + side * w / 2, py + depth + 3.5 / 2)
        rl.draw_rich(view, centre, rich, 3.5)
    # the caption with its diagram (issue 12: at the top of a tall view it stood ~100 mm above
    # it): CAPTION_ABOVE_MM over the λ axis's end and the names a, P, b, from the diagram's left
    mu = 1.0 / per_unit
    caption = tr("sheets.me03", v1=format_number(mu, 4), v2=format_number(1 / k, 4))
    top = max(oy + per_unit + 10.0, *(t.bounds[3] for t in taken)) + CAPTION_ABOVE_MM
    x = min(ox - 12.0, rect.x1 - 2.0 - style.text_width(caption, 3.5))
    if top + 3.5 > rect.y1 - 2.0:        # no room over it (a, P, b stacked high): under it
        top = rect.y0 + 3.0
    view.text_mm((max(rect.x0 + 2.0, x), top), caption, 3.5, "bottom-left")
