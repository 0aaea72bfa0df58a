"""Sheet 3: the flywheel's sketch (front view and axial section at a ГОСТ 2.302 scale, the section
beside the front view or under it, dimensioned in real millimetres) and the table of the
calculation's results."""
from __future__ import annotations

from drawings.layout import Rect
from drawings.primitives import Transform, format_number, format_significant
from drawings.sheet import Sheet, View
from reportgen import gost_scales
from reportgen.dynamics.graphical import KL_DECIMALS
from reportgen.dynamics.hub import Hub, bore_outline, hub_of, section_rects
from reportgen.tolerances import MM_ROUNDOFF
from ..words import tr

#: Room of the sketch around the two views (dimensions, title), mm.
PAD_MM = 24.0
BETWEEN_MM = 30.0
HATCH_MM = 4.0
#: Offset of the outer diameter's dimension: its text clears the end of the centre line, mm.
DIAMETER_MM = 14.0


def scale_text(k: float) -> str:
    """«1:2,5», «1:1», «2:1» for a factor k (sheet mm per real mm) of the ГОСТ 2.302 list."""
    return gost_scales.Scale.of_factor(k).text()


def sketch_size(fw, k: float, stacked: bool = False) -> tuple[float, float]:
    """Width and height of the sketch at scale ``k``: the section right of the front view, or
    (``stacked``) under it as the view from above."""
    D, b = 2000 * fw.radius, 1000 * fw.width
    if stacked:
        return D * k + 2 * PAD_MM, D * k + b * k + BETWEEN_MM + 2 * PAD_MM + 14
    return D * k + b * k + BETWEEN_MM + 2 * PAD_MM, D * k + 2 * PAD_MM + 14


def sketch_fit(fw, width: float, height: float) -> tuple[float, bool]:
    """The largest ГОСТ scale at which the sketch fits ``width`` × ``height`` and its arrangement
    (section beside the front view where both give the same scale, else under it)."""
    D, b = 2000 * fw.radius, 1000 * fw.width
    candidates = [gost_scales.factor(c) for c in gost_scales.fitting(min(width, height) / max(D, b, MM_ROUNDOFF))]
    for k in candidates:
        for stacked in (False, True):
            w, h = sketch_size(fw, k, stacked)
            if w <= width and h <= height:
                return k, stacked
    return candidates[-1], False


def draw_flywheel(sheet: Sheet, fw, rect: Rect, k: float, stacked: bool = False, hub: Hub | None = None) -> View:
    """Front view (circles, the bore with its keyway, centre lines) and the axial section through
    the keyway (hatched) of the disk or rim with its hub (:mod:`reportgen.dynamics.hub`), the
    section right of the front view or (``stacked``) under it; dimensions in real mm (the view's
    model units are real mm)."""
    R, r, b = 1000 * fw.radius, 1000 * fw.inner_radius, 1000 * fw.width
    if hub is None:
        hub = hub_of(0.0, 2 * R)
    cx = rect.x0 + PAD_MM + R * k
    cy = rect.y0 + PAD_MM + R * k + ((b * k + BETWEEN_MM) if stacked else 0.0)
    view = sheet.place_view("flywheel", rect, Transform(k, (0.0, 0.0), (cx, cy)))
    view.title(tr("sheets.fw01", v1=scale_text(k)))
    view.circle((0.0, 0.0), R, "contour")
    if r > 0:
        view.circle((0.0, 0.0), r, "contour")
        view.circle((0.0, 0.0), hub.hub_d / 2, "contour")
    # the keyway where the section cuts it: up (section beside), to the right (section under)
    bore = bore_outline(hub)
    view.polyline([(y, -x) for x, y in bore] if stacked else bore, "contour", closed=True)
    ext = R + 6.0 / k
    view.line((-ext, 0.0), (ext, 0.0), "axis")
    view.line((0.0, -ext), (0.0, ext), "axis")
    # the bore's diameter under it, the keyway's width beside the slot
    view.dimension((-hub.d / 2, 0.0), (hub.d / 2, 0.0), offset_mm=-(hub.d / 2 * k + 8.0), decimals=0,
                   text=f"Ø{format_number(hub.d, 0)}")
    slot = hub.d / 2 + hub.t2
    if stacked:
        view.dimension((slot, hub.key_b / 2), (slot, -hub.key_b / 2), offset_mm=8.0,
                       decimals=0, text=format_number(hub.key_b, 0))
    else:
        view.dimension((-hub.key_b / 2, slot), (hub.key_b / 2, slot), offset_mm=8.0,
                       decimals=0, text=format_number(hub.key_b, 0))
    rects = section_rects(R, r, b, hub)
    if stacked:
        # the section as the view from above: the axis vertical, the radial sizes along x
        y1 = -R - BETWEEN_MM / k
        y0 = y1 - b
        placed = [(ry0, y0 + ax0, ry1, y0 + ax1) for ax0, ry0, ax1, ry1 in rects]
        _section(view, placed, HATCH_MM / k)
        view.line((0.0, y1 + 6.0 / k), (0.0, y0 - 6.0 / k), "axis")
        view.dimension((-R, y0), (R, y0), offset_mm=-DIAMETER_MM, decimals=0, text=f"Ø{format_number(2 * R, 0)}")
        view.dimension((R, y0), (R, y1), offset_mm=-8.0, decimals=0)
        view.dimension((-hub.d / 2, y1), (slot, y1), offset_mm=10.0, decimals=0,
                       text=format_number(hub.d + hub.t2, 1))
        if r > 0:
            view.dimension((-r, y1), (r, y1), offset_mm=18.0, decimals=0, text=f"Ø{format_number(2 * r, 0)}")
        return view
    # the section, right of the front view
    x0 = R + BETWEEN_MM / k
    placed = [(x0 + ax0, ry0, x0 + ax1, ry1) for ax0, ry0, ax1, ry1 in rects]
    _section(view, placed, HATCH_MM / k)
    view.line((x0 - 6.0 / k, 0.0), (x0 + b + 6.0 / k, 0.0), "axis")
    view.dimension((x0 + b, -R), (x0 + b, R), offset_mm=-DIAMETER_MM, decimals=0, text=f"Ø{format_number(2 * R, 0)}")
    view.dimension((x0, R), (x0 + b, R), offset_mm=8.0, decimals=0)
    view.dimension((x0, -hub.d / 2), (x0, slot), offset_mm=10.0, decimals=0, text=format_number(hub.d + hub.t2, 1))
    if r > 0:
        view.dimension((x0, -r), (x0, r), offset_mm=18.0, decimals=0, text=f"Ø{format_number(2 * r, 0)}")
    return view


def _section(view: View, rects: list, step: float) -> None:
    """Solid parts of a section (rectangles, model units): their joint outline and the hatching."""
    from shapely.geometry import box
    from shapely.ops import unary_union
    view.geometry(unary_union([box(*q) for q in rects]), "contour")
    for q in rects:
        _hatch(view, q[0], q[1], q[2], q[3], step)


def _hatch(view: View, x0: float, y0: float, x1: float, y1: float, step: float) -> None:
    """45° section lines inside the rectangle (model units), ``step`` apart along x."""
    w, h = x1 - x0, y1 - y0
    c = -h
    while c < w:
        # the line x − x0 = (y − y0) + c, clipped to the rectangle
        ya, yb = max(0.0, -c), min(h, w - c)
        if yb > ya:
            view.line((x0 + ya + c, y0 + ya), (x0 + yb + c, y0 + yb), "thin")
        c += step * 1.4142135623730951


def draw_results(sheet: Sheet, rect: Rect, rows: list[tuple[str, str]]) -> View:
    """A two-column table (name, value) of the calculation's results, rows 8 mm high."""
    view = sheet.place_view("results", rect, Transform(1.0, (0.0, 0.0), (rect.x0, rect.y0)))
    w1 = rect.width * 0.62
    top = rect.y1 - 10.0
    view.text_mm((rect.x0 + rect.width / 2, rect.y1 - 7.0), tr("sheets.fw02"), 5.0, "bottom-center")
    n = len(rows)
    y_bottom = top - 8.0 * n
    for i in range(n + 1):
        y = top - 8.0 * i
        view.line((0.0, y - rect.y0), (rect.width, y - rect.y0), "contour" if i in (0, n) else "thin")
    for x in (0.0, w1, rect.width):
        view.line((x, top - rect.y0), (x, y_bottom - rect.y0), "contour")
    for i, (name, value) in enumerate(rows):
        y = top - 8.0 * i - 4.0 - rect.y0
        view.text((2.0, y), name, 3.5, "middle-left")
        view.text((w1 + 2.0, y), value, 3.5, "middle-left")
    return view


def result_rows(res, kl_on_sheet: float) -> list[tuple[str, str]]:
    """Scales, the tangents, KL and the flywheel by the three methods with the δ of the exact one."""
    g, fw = res.graphical, res.flywheel
    names = {"exact": tr("sheets.fw03"), "merzalov": tr("sheets.fw04"), "graphical": tr("sheets.fw05")}
    rows = [(tr("sheets.fw06"), format_significant(g.mu_phi, 4)),
            (tr("sheets.fw07"), format_significant(g.mu_M, 4)),
            (tr("sheets.fw08"), format_number(g.H, 0)),
            (tr("sheets.fw09"), format_significant(g.mu_A, 4)),
            (tr("sheets.fw10"), format_significant(g.mu_E, 4)),
            (tr("sheets.fw11"), format_significant(g.mu_J, 4)),
            (tr("sheets.fw12"), format_number(g.psi_max_deg, 2)),
            (tr("sheets.fw13"), format_number(g.psi_min_deg, 2)),
            (tr("sheets.fw14"), format_number(kl_on_sheet, KL_DECIMALS)),
            (tr("sheets.fw15"), format_significant(res.delta_target, 4))]
    for c in res.comparison:
        rows.append((tr("sheets.fw21", v1=names[c.method]), format_significant(c.J_fly, 4)))
    rows += [(tr("sheets.fw16"), format_significant(res.delta_achieved, 4)),
             (tr("sheets.fw17"), format_significant(res.M_drive, 4)),
             (tr("sheets.fw18"), format_number(1000 * fw.radius, 0)),
             (tr("sheets.fw19"), format_number(1000 * fw.width, 0)),
             (tr("sheets.fw20"), format_significant(fw.mass, 4))]
    return rows
