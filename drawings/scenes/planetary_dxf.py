"""Sheet 4, the planetary reducer: the scenes of :mod:`reportgen.scenes.planetary` drawn on DXF
views (the front view, the side view with Kutzbach's triangle and the angular-velocity plan, the
table of tooth numbers)."""
from __future__ import annotations

from drawings.words import decimal_mark, tr
from reportgen import gost_scales
from reportgen.scenes.planetary import Scene, front_view, merge, plan_scene, sheet_triangle, side_scheme, triangle_scene


def draw_scene(view, scene: Scene, label_height: float = 5.0) -> None:
    """Draw a scene on a DXF view whose transform maps scene mm to the sheet (scale 1)."""
    for ln in scene.lines:
        view.polyline(list(ln.points), ln.layer)
    for c in scene.circles:
        view.circle(c.centre, c.radius, c.layer)
    for p, q in scene.hatches:
        view.line(p, q, "thin")
    names = {"vA": "vA", "vB": "vB"}
    for p, q, lab in scene.arrows:
        view.arrow(p, q, names.get(lab, lab))
    for scene_label in scene.labels:
        view.text(scene_label.point, scene_label.text, label_height, "center")


def draw_reducer(sheet, stage, region) -> None:
    """The right half of sheet 4 in ``region`` (a Rect): the front view on top, the side view with
    the velocity triangle and the angular-velocity plan below, a table of the tooth numbers."""
    from drawings.layout import Rect
    from drawings.primitives import Transform, format_number, format_significant
    d = stage.design
    tri = sheet_triangle(stage)
    k = tri.length_scale
    label = gost_scales.Scale.of_factor(k).text(decimal_mark())
    sheet.set_scale(label)          # «Масштаб» when the reducer is the sheet's main view (no gear pair)
    front = front_view(d, k)
    fx0, fy0, fx1, fy1 = front.bounds()
    fw, fh = fx1 - fx0 + 20, fy1 - fy0 + 24
    frect = Rect(region.x1 - fw, region.y1 - fh, region.x1, region.y1)
    fview = sheet.place_view("reducer_front", frect,
                             Transform(1.0, (0.0, 0.0), (frect.x0 + 10 - fx0, frect.y0 + 8 - fy0)))
    draw_scene(fview, front)
    from drawings.style import text_width
    title = tr("sheets.pl01", label=label)
    tx = min(frect.center[0], region.x1 - text_width(title, 5.0) / 2 - 2)
    fview.text_mm((tx, frect.y1 - 6), title, 5.0, "bottom-center")
    side = side_scheme(d, k)
    x_line = side.bounds()[2] + 25
    triangle = triangle_scene(tri, x_line, side.marks)
    plan_origin = (x_line + 10 - min(0.0, *[x for _, x in tri.plan.cuts]), -tri.plan.h_mm - 30)
    scene = merge(side, triangle, plan_scene(tri, plan_origin))
    sx0, sy0, sx1, sy1 = scene.bounds()
    sw, sh = sx1 - sx0 + 20, sy1 - sy0 + 24
    srect = Rect(region.x0, frect.y0 - 8 - sh, region.x0 + sw, frect.y0 - 8)
    sview = sheet.place_view("reducer_side", srect,
                             Transform(1.0, (0.0, 0.0), (srect.x0 + 10 - sx0, srect.y0 + 8 - sy0)))
    draw_scene(sview, scene)
    sview.text_mm((srect.x0 + 4, srect.y1 - 6), tr("sheets.pl02", label=label), 5.0, "bottom-left")
    sview.text((x_line + tri.vector_mm * 0.15, tri.point("C")[1] + 12),
               tr("sheets.pl03", v1=format_significant(tri.mu_v, 5)), 3.5)   # as section 4 prints it
    sview.text((plan_origin[0] - 6, plan_origin[1] - 16),          # under the pole's «p» (5 mm letters at −5)
               tr("sheets.pl04", v1=format_number(abs(tri.plan.mu_omega), 4), v2=format_number(tri.plan.h_mm, 0)),
               3.5)
    # table of tooth numbers, left of the front view
    rows = [(tr("sheets.pl05"), "z", tr("sheets.pl06"))] + [(lab, str(zz), format_number(tri.module * zz, 1))
                                         for lab, zz in zip(d.scheme.labels, d.z)]
    rows.append(("K", str(d.satellites), ""))
    rows.append(("u", format_number(abs(d.ratio), 4), ""))
    widths = (20.0, 22.0, 24.0)
    h = 8.0
    tw, th = sum(widths), h * len(rows)
    table_title = tr("sheets.pl07")
    title_h = 5.0                                      # the title's letters, 3 mm above the table
    trect = Rect(region.x0, region.y1 - th - 2 - title_h - 3,
                 region.x0 + max(tw + 2, text_width(table_title, title_h) + 2), region.y1)
    tview = sheet.place_view("reducer_table", trect, Transform(1.0, (0.0, 0.0), (trect.x0 + 1, trect.y0 + 1)))
    tview.text((tw / 2 if text_width(table_title, title_h) <= tw else text_width(table_title, title_h) / 2,
                th + 3), table_title, title_h, "bottom-center")
    for i in range(len(rows) + 1):
        tview.line((0, i * h), (tw, i * h), "contour" if i in (0, len(rows), len(rows) - 1) else "thin")
    x = 0.0
    for j, w in enumerate((0.0,) + widths):
        x += w
        tview.line((x, 0), (x, th), "contour" if j in (0, len(widths)) else "thin")
    for i, row in enumerate(rows):
        x = 0.0
        for w, cell in zip(widths, row):
            tview.text((x + w / 2, th - (i + 0.5) * h), cell, 3.5, "center")
            x += w
