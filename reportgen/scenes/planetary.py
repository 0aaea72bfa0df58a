"""The planetary reducer as plain drawing geometry (sheet mm, ГОСТ 2.770 symbols), shared by the
note's figure (:func:`latex_templates.figures.gears.planetary_figure`) and sheet 4
(:mod:`drawings.scenes.planetary_dxf`). Pure: no plotting, no DXF.

Side view (the kinematic scheme in section through the axis, ГОСТ 2.770): the central axis is
horizontal at y = 0, wheels are segments of their pitch diameter with the rims' ticks at the
drawing's length scale k, so the mesh points sit at the heights y = k·r that Kutzbach's velocity
triangle (:mod:`reportgen.planetary.velocity`) uses: A (wheel 1 – planet 2) at k·r1, B (planet
axis) at k·a, C (planet – wheel 3) at k·r3. The satellites above and below the axis turn on their
axles (bearings) in the carrier H; the input and output shafts run in bearings in the housing's
walls; the fixed wheel 3 is part of the hatched housing. Each line carries the ``part`` it draws
(wheel1, satellite, ring, housing, bearing, shaft, carrier), which the tests read.

Front view: the wheels as pitch circles about the central axis, K planets equally spaced on the
carrier circle of radius k·a (two of them on a diagonal, clear of the axes through wheel 1), the
carrier arms as thick lines.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..planetary.schemes import expand

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
    part: str = ""              # what it draws: wheel1, satellite, ring, housing, bearing, shaft, carrier


@dataclass(frozen=True)
class SceneCircle:
    centre: Point
    radius: float
    layer: str = "contour"
    part: str = ""


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

    def line(self, *pts: Point, layer: str = "contour", part: str = "") -> None:
        self.lines.append(SceneLine(tuple((float(x), float(y)) for x, y in pts), layer, part))

    def parts(self, part: str) -> list[SceneLine]:
        """The lines that draw ``part``."""
        return [ln for ln in self.lines if ln.part == part]

    def ground(self, p: Point, q: Point, side: float = 1.0, step: float = 3.0, part: str = "housing") -> None:
        """A hatched fixed base along p–q; strokes on the ``side`` (+1: left of p→q)."""
        self.line(p, q, layer="contour", part=part)
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


def _wheel_external(s: Scene, x: float, y0: float, r: float, part: str) -> None:
    """An external wheel about the height y0 (ГОСТ 2.770): a segment of its pitch diameter across
    its shaft with the rim's ticks at both ends."""
    s.line((x, y0 - r), (x, y0 + r), part=part)
    for y in (y0 - r, y0 + r):
        s.line((x - FACE, y), (x + FACE, y), part=part)


def _bearing(s: Scene, x: float, y: float, support: float | None = None) -> None:
    """A radial rolling bearing on a shaft at height ``y`` (ГОСТ 2.770: the outer ring's strokes
    parallel to the shaft on both sides, the rolling element between); ``support`` the height
    (absolute, same sign as the side) of the wall the upper and lower rings are fixed to."""
    for sg in (1, -1):
        yo = y + sg * BEARING_GAP
        s.line((x - BEARING_LEN / 2, yo), (x + BEARING_LEN / 2, yo), part="bearing")
        s.circles.append(SceneCircle((x, y + sg * BEARING_GAP / 2), BEARING_GAP / 2 - 0.4, "thin", "bearing"))
        if support is not None and sg * (support - yo) > 0 and abs(support) > abs(yo):
            s.line((x, yo), (x, support if sg > 0 else -support), part="housing")


BEARING_LEN = 7.0     # length of a bearing's ring stroke, sheet mm
BEARING_GAP = 3.0     # distance of the ring stroke from the shaft, sheet mm
WALL = 14.0           # distance of a housing wall from the nearest wheel or carrier, sheet mm


def side_scheme(design, k: float) -> Scene:
    """The kinematic scheme of ``design`` (``module`` needed) at length scale ``k`` (sheet mm per
    real mm), ГОСТ 2.770 symbols, in section through the axis: the input shaft from the left on its
    bearing in the housing's wall, wheel 1 on it; the satellite blocks (2, 2′) above and below the
    axis at the carrier radius, each turning on its axle (a bearing) fixed in the carrier H; the
    carrier's output shaft to the right on its bearing; the fixed wheel 3 part of the housing,
    drawn whole (above and below) with the housing hatched."""
    m = design.module
    sch = design.scheme
    z1, z2, z2p, z3 = expand(sch, design.z)
    r1, r2, r2p, r3 = (k * m * z / 2 for z in (z1, z2, z2p, z3))
    a = k * m * design.coaxial.left / 2
    s = Scene()
    x1 = 0.0
    x3 = ROW_GAP if sch.two_row else 0.0
    x_h = x3 + ROW_GAP * 0.75 + (RING_RIM if sch.row2 == "internal" else 0.0)
    outer = max(r1 + (RING_RIM if sch.row1 == "internal" else 0.0),
                r3 + (RING_RIM if sch.row2 == "internal" else 0.0), a + max(r2, r2p)) + 6.0
    hub1 = x1 - ROW_GAP * 0.6 if sch.row1 == "internal" else x1
    x_wl = hub1 - WALL
    x_wr = x_h + WALL
    x_in, x_out = x_wl - SHAFT * 0.6, x_wr + SHAFT * 0.6
    s.line((x_in - 8, 0), (x_out + 8, 0), layer="axis")
    # the housing: walls with the shafts' bearings, the shell hatched outside
    s.ground((x_wl, outer), (x_wr, outer), side=1.0)
    s.ground((x_wr, -outer), (x_wl, -outer), side=1.0)
    s.line((x_wl, BEARING_GAP), (x_wl, outer), part="housing")
    s.line((x_wl, -BEARING_GAP), (x_wl, -outer), part="housing")
    s.line((x_wr, BEARING_GAP), (x_wr, outer), part="housing")
    s.line((x_wr, -BEARING_GAP), (x_wr, -outer), part="housing")
    _bearing(s, x_wl, 0.0)
    _bearing(s, x_wr, 0.0)
    # input shaft and wheel 1
    if sch.row1 == "external":
        s.line((x_in, 0), (x1, 0), part="shaft")
        _wheel_external(s, x1, 0.0, r1, "wheel1")
    else:
        s.line((x_in, 0), (hub1, 0), part="shaft")
        s.line((hub1, -r1 - RING_RIM), (hub1, r1 + RING_RIM), part="wheel1")
        for sg in (1, -1):
            s.line((hub1, sg * (r1 + RING_RIM)), (x1, sg * (r1 + RING_RIM)), (x1, sg * r1), part="wheel1")
            s.line((x1 - FACE, sg * r1), (x1 + FACE, sg * r1), part="wheel1")
    # the satellite blocks above and below the axis, on their axles in the carrier
    xa0 = x1 - FACE - 3
    for sg in (1, -1):
        y = sg * a
        s.line((xa0, y), (x3 + FACE + 2, y), part="satellite")          # the block's sleeve
        _wheel_external(s, x1, y, r2, "satellite")
        if sch.two_row:
            _wheel_external(s, x3, y, r2p, "satellite")
        x_b = (x3 + FACE + x_h) / 2
        s.line((x3 + FACE + 2, y), (x_h, y), part="carrier")             # the axle
        _bearing(s, x_b, y)
    # fixed wheel 3
    if sch.row2 == "internal":
        for sg in (1, -1):
            s.line((x3, sg * r3), (x3, sg * outer), part="ring")
            s.line((x3 - FACE, sg * r3), (x3 + FACE, sg * r3), part="ring")
    else:
        _wheel_external(s, x3, 0.0, r3, "ring")
        hub = x3 + FACE + 3            # its hub fixed to the housing (a hatched base), round the shaft
        for sg in (1, -1):
            s.line((x3, sg * 2.0 * BEARING_GAP), (hub, sg * 2.0 * BEARING_GAP), part="ring")
            s.ground((hub, sg * 2.0 * BEARING_GAP), (hub, sg * 4.0 * BEARING_GAP), side=-sg, part="ring")
    # carrier H: arm from the upper axle to the lower one, the output shaft to the right
    s.line((x_h, a), (x_h, -a), part="carrier")
    s.line((x_h, 0), (x_out, 0), part="shaft")
    # labels
    s.labels += [SceneLabel("1", (x1 - 7, r1 * 0.5)), SceneLabel("2", (x1 - 7, a + r2 * 0.5)),
                 SceneLabel("H", (x_h + 6, a * 0.5)),
                 SceneLabel("3", (x3 + 7, (r3 + outer) / 2 if sch.row2 == "internal" else -r3 * 0.5))]
    if sch.two_row:
        s.labels.append(SceneLabel("2′", (x3 + 8, a - r2p * 0.55)))
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
    start = math.pi / 2 + (math.pi / 4 if K == 2 else 0.0)   # two satellites: on a diagonal
    for i in range(K):
        t = start + 2 * math.pi * i / K
        c = (a * math.cos(t), a * math.sin(t))
        s.circles.append(SceneCircle(c, r2, "contour", "satellite"))
        if sch.two_row:
            s.circles.append(SceneCircle(c, r2p, "hidden", "satellite"))
        s.line((0, 0), c, part="carrier")                  # carrier arm
        s.circles.append(SceneCircle(c, 1.5, "contour"))
    s.circles.append(SceneCircle((0, 0), 1.5, "contour"))
    def at(r: float, deg: float, c: Point = (0.0, 0.0)) -> Point:
        t = start + math.radians(deg)
        return (c[0] + r * math.cos(t), c[1] + r * math.sin(t))

    c0 = at(a, 0.0)
    s.labels += [SceneLabel("1", at(0.55 * r1, -90.0)),
                 SceneLabel("2", at(0.55 * r2, -55.0, c0)),
                 SceneLabel("3", ((r3 + 9) * math.cos(math.radians(-60)), (r3 + 9) * math.sin(math.radians(-60)))),
                 SceneLabel("H", (0.45 * c0[0] + 5 * math.cos(start + math.pi / 2),
                                  0.45 * c0[1] + 5 * math.sin(start + math.pi / 2)))]
    if sch.two_row:
        s.labels.append(SceneLabel("2′", at(r2p + 5, 125.0, c0)))
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
SHEET_MAX_RADIUS = 80.0


def sheet_triangle(stage):
    """The velocity triangle at the scale of sheet 4 (both views of the reducer stacked on the
    right half): the same construction as ``stage.triangle`` — lengths of the vectors do not
    depend on the length scale — with heights at the sheet's ГОСТ 2.302 scale. None without a
    module."""
    if stage.triangle is None:
        return None
    from ..planetary.velocity import velocity_triangle
    tri = stage.triangle
    omega_in = abs(tri.omega1) if stage.design.driver == "wheel" else abs(tri.omega1) / float(stage.design.ratio_check.u1h)
    return velocity_triangle(stage.design, omega_in, tri.module, max_radius_mm=SHEET_MAX_RADIUS)
