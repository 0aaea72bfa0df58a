"""The planetary reducer as plain drawing geometry (sheet mm, ГОСТ 2.770 symbols), shared by the
note's figure (matplotlib) and sheet 4 (DXF).

Side view (the usual kinematic scheme): the central axis is horizontal at y = 0, wheels are vertical
segments of their pitch diameter at the drawing's length scale k, so the mesh points sit at the
heights y = k·r that Kutzbach's velocity triangle (:mod:`reportgen.planetary.velocity`) uses: A
(wheel 1 – planet 2) at k·r1, B (planet axis) at k·a, C (planet – wheel 3) at k·r3. Only the upper
planet is drawn in the side view (the others are in the front view), as course schemes do.

Front view: the wheels as pitch circles about the central axis, K planets equally spaced on the
carrier circle of radius k·a, the carrier arms as thick lines.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from reportgen.planetary.schemes import expand
from ..words import decimal_mark, tr

from reportgen.geometry import Vec2 as Point

ROW_GAP = 36.0        # distance between the two rows of a two-row planet block, sheet mm
FACE = 5.0            # half-width of a wheel's rim tick, sheet mm
SHAFT = 34.0          # length of the input / output shafts, sheet mm
RING_RIM = 8.0        # radial height of a ring's rim beyond its pitch circle, sheet mm
HATCH = 3.0           # length of a hatch stroke, sheet mm


@dataclass(frozen=True)
class SceneLine:
    points: tuple[Point, ...]
    layer: str = "contour"      # contour | thin | axis | hidden


@dataclass(frozen=True)
class SceneCircle:
    centre: Point
    radius: float
    layer: str = "contour"


@dataclass(frozen=True)
class SceneLabel:
    text: str
    point: Point


@dataclass
class Scene:
    lines: list[SceneLine] = field(default_factory=list)
    circles: list[SceneCircle] = field(default_factory=list)
    labels: list[SceneLabel] = field(default_factory=list)
    hatches: list[tuple[Point, Point]] = field(default_factory=list)
    arrows: list[tuple[Point, Point, str]] = field(default_factory=list)    # vectors with a tip label
    marks: dict[str, Point] = field(default_factory=dict)    # named points (A, B, C, axis ends)

    def line(self, *pts: Point, layer: str = "contour") -> None:
        self.lines.append(SceneLine(tuple((float(x), float(y)) for x, y in pts), layer))

    def ground(self, p: Point, q: Point, side: float = 1.0, step: float = 3.0) -> None:
        """A hatched fixed base along p–q; strokes on the ``side`` (+1: left of p→q)."""
        self.line(p, q, layer="contour")
        L = math.dist(p, q)
        ux, uy = (q[0] - p[0]) / L, (q[1] - p[1]) / L
        nx, ny = -uy * side, ux * side
        n = max(2, int(L / step))
        for i in range(n + 1):
            t = i * L / n
            x, y = p[0] + ux * t, p[1] + uy * t
            self.hatches.append(((x, y), (x + (nx - ux) * HATCH * 0.7, y + (ny - uy) * HATCH * 0.7)))

    def bounds(self) -> tuple[float, float, float, float]:
        xs, ys = [], []
        for ln in self.lines:
            for x, y in ln.points:
                xs.append(x)
                ys.append(y)
        for c in self.circles:
            xs += [c.centre[0] - c.radius, c.centre[0] + c.radius]
            ys += [c.centre[1] - c.radius, c.centre[1] + c.radius]
        for (a, b) in self.hatches + [(a, b) for a, b, _ in self.arrows]:
            xs += [a[0], b[0]]
            ys += [a[1], b[1]]
        return min(xs), min(ys), max(xs), max(ys)


def _wheel_external(s: Scene, x: float, y0: float, r: float) -> None:
    """An external wheel about the height y0: vertical segment of its pitch diameter, rim ticks."""
    s.line((x, y0 - r), (x, y0 + r))
    for y in (y0 - r, y0 + r):
        s.line((x - FACE, y), (x + FACE, y))


def side_scheme(design, k: float) -> Scene:
    """The kinematic scheme of ``design`` (``module`` needed) at length scale ``k`` (sheet mm per
    real mm); wheel 1 is driven from the left, the carrier H gives the output to the right."""
    m = design.module
    sch = design.scheme
    z1, z2, z2p, z3 = expand(sch, design.z)
    r1, r2, r2p, r3 = (k * m * z / 2 for z in (z1, z2, z2p, z3))
    a = k * m * design.coaxial.left / 2
    s = Scene()
    x1 = 0.0
    x3 = ROW_GAP if sch.two_row else 0.0
    x_h = x3 + ROW_GAP * 0.75 + (RING_RIM if sch.row2 == "internal" else 0.0)
    top = max(r1, r3, a + max(r2, r2p)) + RING_RIM + 4
    x_in, x_out = x1 - SHAFT - (RING_RIM if sch.row1 == "internal" else 0.0), x_h + SHAFT
    s.line((x_in - 8, 0), (x_out + 8, 0), layer="axis")
    # input shaft and wheel 1
    if sch.row1 == "external":
        s.line((x_in, 0), (x1, 0))
        _wheel_external(s, x1, 0.0, r1)
    else:
        hub = x1 - ROW_GAP * 0.6
        s.line((x_in, 0), (hub, 0))
        s.line((hub, -r1 - RING_RIM), (hub, r1 + RING_RIM))
        for sg in (1, -1):
            s.line((hub, sg * (r1 + RING_RIM)), (x1, sg * (r1 + RING_RIM)), (x1, sg * r1))
            s.line((x1 - FACE, sg * r1), (x1 + FACE, sg * r1))
    # planet block (upper planet) on its axle
    xa0 = x1 - FACE - 4
    for sg in (1, -1):           # the upper and the lower planet
        s.line((xa0, sg * a), (x_h, sg * a))
        _wheel_external(s, x1, sg * a, r2)
        if sch.two_row:
            _wheel_external(s, x3, sg * a, r2p)
    # fixed wheel 3
    if sch.row2 == "internal":
        for sg in (1, -1):
            s.line((x3, sg * r3), (x3, sg * (r3 + RING_RIM)))
            s.line((x3 - FACE, sg * r3), (x3 + FACE, sg * r3))
            p, q = (x3 - 2 * FACE, sg * (r3 + RING_RIM)), (x3 + 2 * FACE, sg * (r3 + RING_RIM))
            s.ground(p, q, side=1.0 if sg > 0 else -1.0)
    else:
        _wheel_external(s, x3, 0.0, r3)
        hub = x3 + FACE + 6
        s.line((x3, 0), (hub, 0))
        s.ground((hub, -8), (hub, 8), side=-1.0)
    # carrier H: arm from the planet axle down to the output shaft
    s.line((x_h, a), (x_h, -a))
    s.line((x_h, 0), (x_out, 0))
    del top
    # labels
    s.labels += [SceneLabel("1", (x1 - 7, r1 * 0.5)), SceneLabel("2", (x1 - 7, a + r2 * 0.5)),
                 SceneLabel("H", (x_h + 6, a * 0.5)), SceneLabel("3", (x3 + 9, r3 + RING_RIM * 0.5))]
    if sch.two_row:
        s.labels.append(SceneLabel("2′", (x3 - 8, a + r2p * 0.5)))
    s.marks.update({"A": (x1, r1), "B": (x_h, a), "C": (x3, r3), "O": (x_out + 8, 0.0)})
    return s


def front_view(design, k: float) -> Scene:
    """Front view: pitch circles of wheel 1, the fixed wheel 3 (hatched outside if internal), the K
    planets (2 solid, 2′ dashed behind it) and the carrier arms."""
    m = design.module
    sch = design.scheme
    z1, z2, z2p, z3 = expand(sch, design.z)
    r1, r2, r2p, r3 = (k * m * z / 2 for z in (z1, z2, z2p, z3))
    a = k * m * design.coaxial.left / 2
    K = design.satellites
    s = Scene()
    ext = max(r1, r3, a + max(r2, r2p)) + 6
    s.line((-ext, 0), (ext, 0), layer="axis")
    s.line((0, -ext), (0, ext), layer="axis")
    s.circles.append(SceneCircle((0, 0), r1, "contour"))
    s.circles.append(SceneCircle((0, 0), r3, "contour"))
    if sch.row2 == "internal":
        # hatch strokes outside the fixed ring, on a few arcs
        for i in range(72):
            t = 2 * math.pi * i / 72
            p = (r3 * math.cos(t), r3 * math.sin(t))
            q = ((r3 + HATCH) * math.cos(t + 0.06), (r3 + HATCH) * math.sin(t + 0.06))
            s.hatches.append((p, q))
    s.circles.append(SceneCircle((0, 0), a, "axis"))
    for i in range(K):
        t = math.pi / 2 + 2 * math.pi * i / K
        c = (a * math.cos(t), a * math.sin(t))
        s.circles.append(SceneCircle(c, r2, "contour"))
        if sch.two_row:
            s.circles.append(SceneCircle(c, r2p, "hidden"))
        s.line((0, 0), c)                  # carrier arm
        s.circles.append(SceneCircle(c, 1.5, "contour"))
    s.circles.append(SceneCircle((0, 0), 1.5, "contour"))
    s.labels += [SceneLabel("1", (0.55 * r1 * math.cos(math.radians(-35)), 0.55 * r1 * math.sin(math.radians(-35)))),
                 SceneLabel("2", (0.55 * r2, a + 0.35 * r2)),
                 SceneLabel("3", ((r3 + 9) * math.cos(math.radians(-60)), (r3 + 9) * math.sin(math.radians(-60)))),
                 SceneLabel("H", (-6, a * 0.45))]
    if sch.two_row:
        s.labels.append(SceneLabel("2′", (-(r2p + 5) * 0.72, a - (r2p + 5) * 0.72)))
    return s


def triangle_scene(tri, x_line: float, scheme_marks: dict[str, Point] | None = None) -> Scene:
    """Kutzbach's velocity triangle with its vertical line at ``x_line`` (heights as in
    :func:`side_scheme` at the triangle's scale): the velocity lines of wheel 1, the planet and the
    carrier, the vectors v_A and v_B, thin projection lines from the scheme's points A, B, C."""
    s = Scene()
    pts = dict(tri.points)
    yc = pts["C"][1]
    s.line((x_line, 0.0), (x_line, yc + 6), layer="thin")
    for seg in tri.lines:
        s.line((x_line + seg.start[0], seg.start[1]), (x_line + seg.end[0], seg.end[1]), layer="contour")
    last_y, shift = -1e9, 0.0
    for lab in ("A", "B", "C"):
        y = pts[lab][1]
        if scheme_marks is not None:
            s.line((scheme_marks[lab][0], y), (x_line, y), layer="thin")
        shift = shift + 8.0 if y - last_y < 7.0 else 0.0     # letters of close points side by side
        s.labels.append(SceneLabel(lab, (x_line - 5 - shift, y + 4)))
        last_y = y
    a, b = pts["a"], pts["b"]
    s.arrows.append(((x_line, a[1]), (x_line + a[0], a[1]), "vA"))
    s.arrows.append(((x_line, b[1]), (x_line + b[0], b[1]), "vB"))
    names = {"1": "1", "2": "2", "H": "H"}
    for seg in tri.lines:
        t = 0.2 if seg.label == "2" else 0.45     # the planet's line: near C, away from v_B
        mx = x_line + t * seg.end[0] + (1 - t) * seg.start[0]
        my = t * seg.end[1] + (1 - t) * seg.start[1]
        s.labels.append(SceneLabel(names[seg.label], (mx - 5, my + 3)))
    s.marks.update({"O": (x_line, 0.0)})
    return s


def plan_scene(tri, origin: Point) -> Scene:
    """The angular-velocity plan: pole p at ``origin``, rays parallel to the velocity lines, the
    cutting line at the distance h above; the cut lengths are proportional to ω."""
    s = Scene()
    plan = tri.plan
    ox, oy = origin
    xs = [x for _, x in plan.cuts] + [0.0]
    s.line((ox + min(xs) - 8, oy + plan.h_mm), (ox + max(xs) + 8, oy + plan.h_mm), layer="thin")
    for ray, (lab, x) in zip(plan.rays, plan.cuts):
        s.line((ox, oy), (ox + ray.end[0], oy + ray.end[1]))
        s.labels.append(SceneLabel(lab, (ox + x, oy + plan.h_mm + 5)))
    s.circles.append(SceneCircle((ox, oy), 1.0, "contour"))
    s.labels.append(SceneLabel("p", (ox, oy - 5)))
    return s


def merge(*scenes: Scene) -> Scene:
    out = Scene()
    for sc in scenes:
        out.lines += sc.lines
        out.circles += sc.circles
        out.labels += sc.labels
        out.hatches += sc.hatches
        out.arrows += sc.arrows
        out.marks.update(sc.marks)
    return out


#: The largest radius of the reducer drawn on sheet 4 (front and side views stacked), sheet mm.
SHEET_MAX_RADIUS = 110.0


def sheet_triangle(stage):
    """The velocity triangle at the scale of sheet 4 (both views of the reducer stacked on the
    right half): the same construction as ``stage.triangle`` — lengths of the vectors do not
    depend on the length scale — with heights at the sheet's ГОСТ 2.302 scale. None without a
    module."""
    if stage.triangle is None:
        return None
    from reportgen.planetary.velocity import velocity_triangle
    tri = stage.triangle
    omega_in = abs(tri.omega1) if stage.design.driver == "wheel" else abs(tri.omega1) / float(stage.design.ratio_check.u1h)
    return velocity_triangle(stage.design, omega_in, tri.module, max_radius_mm=SHEET_MAX_RADIUS)


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
    from drawings.primitives import Transform, format_number
    d = stage.design
    tri = sheet_triangle(stage)
    k = tri.length_scale
    label = tri.scale_label.replace(".", decimal_mark())
    sheet.set_scale(label)          # «Масштаб» when the reducer is the sheet's main view (no gear pair)
    front = front_view(d, k)
    fx0, fy0, fx1, fy1 = front.bounds()
    fw, fh = fx1 - fx0 + 20, fy1 - fy0 + 24
    frect = Rect(region.x1 - fw, region.y1 - fh, region.x1, region.y1)
    fview = sheet.place_view("reducer_front", frect,
                             Transform(1.0, (0.0, 0.0), (frect.x0 + 10 - fx0, frect.y0 + 8 - fy0)))
    draw_scene(fview, front)
    fview.text_mm((frect.center[0], frect.y1 - 6), tr("sheets.pl01", label=label), 5.0,
                  "bottom-center")
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
               tr("sheets.pl03", v1=format_number(tri.mu_v, 5)), 3.5)
    sview.text((plan_origin[0] - 6, plan_origin[1] - 12),
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
    trect = Rect(region.x0, region.y1 - th - 2, region.x0 + tw + 2, region.y1)
    tview = sheet.place_view("reducer_table", trect, Transform(1.0, (0.0, 0.0), (trect.x0 + 1, trect.y0 + 1)))
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
