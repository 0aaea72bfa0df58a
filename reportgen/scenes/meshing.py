"""The meshing picture (картина зацепления) of sheet 4 as a scene (:func:`meshing_scene`, the stage
``project.scenes.meshing``): its scale decided once for the window the sheet gives it, its geometry
in paper mm at that scale; the note draws a window of the same scene (reduced, the caption says
so) and quotes the same scale and the length of ab read on the sheet."""
from __future__ import annotations

from dataclasses import dataclass

from shapely.geometry import Polygon

from .. import gost_scales
from ..gears.meshing import GOST_SCALES, MeshingPicture, meshing_picture
from .meshing_marks import ZONE_OFFSET_MM, MeshingMarks
from .scene import Scene

#: The view of the meshing picture on the left of sheet 4, sheet mm: the whole height of the
#: sheet; the picture (teeth, circles' arcs and both centres) fits inside it less the padding, the
#: caption's strip and a margin on each side for the designations' leaders and the dimension aw.
VIEW_W = 390.0
VIEW_H = 560.0
PADDING = 10.0
CAPTION = 8.0
LABEL_MARGIN = 35.0
WINDOW_W = VIEW_W - 2 * PADDING - 2 * LABEL_MARGIN
WINDOW_H = VIEW_H - 2 * PADDING - CAPTION


@dataclass(frozen=True)
class DrawingScale:
    """A ГОСТ 2.302 scale: ``factor`` sheet mm per real mm and its caption text."""
    factor: float

    @property
    def label(self) -> str:
        """«2:1», «2,5:1», «1:2» (decimal comma)."""
        return self.text()

    def text(self, decimal: str = ",") -> str:
        """The ratio with ``decimal`` as the decimal mark (:meth:`reportgen.gost_scales.Scale.text`)."""
        return gost_scales.Scale.of_factor(self.factor).text(decimal)


def model_bounds(pair, pic: MeshingPicture) -> tuple[float, float, float, float]:
    """What the picture shows, real mm: the drawn teeth, N1, N2 and both centres O1, O2."""
    x0, y0, x1, y1 = pic.view
    return (min(x0, 0.0), min(y0, 0.0), max(x1, 0.0), max(y1, pair.geometry.aw))


def meshing_scale(pair, pic: MeshingPicture | None = None,
                  window: tuple[float, float] = (WINDOW_W, WINDOW_H)) -> DrawingScale:
    """The largest ГОСТ 2.302 scale at which the whole picture (centres included) fits ``window``."""
    pic = pic if pic is not None else meshing_picture(pair)
    x0, y0, x1, y1 = model_bounds(pair, pic)
    for k in GOST_SCALES:
        if (x1 - x0) * k <= window[0] and (y1 - y0) * k <= window[1]:
            return DrawingScale(k)
    return DrawingScale(GOST_SCALES[-1])


def model_centre(pair, pic: MeshingPicture) -> tuple[float, float]:
    """The real point drawn at the centre of the view's window."""
    x0, y0, x1, y1 = model_bounds(pair, pic)
    return ((x0 + x1) / 2, (y0 + y1) / 2)


def label_room(pair, pic: MeshingPicture, scale: DrawingScale) -> tuple[float, float, float, float]:
    """The room (real mm) the designations may take: the view less its padding and caption."""
    cx, cy = model_centre(pair, pic)
    k = scale.factor
    hw = (VIEW_W - 2 * PADDING) / 2 / k
    hh = (VIEW_H - 2 * PADDING - CAPTION) / 2 / k
    return (cx - hw, cy - hh, cx + hw, cy + hh)


#: The note's figure is a detail of this scene round the pole: the drawn teeth and a margin for
#: the designations (a share of their width), reduced to at most DETAIL_W × DETAIL_MAX_H page mm
#: (the text block's 0.85 as the figure macro includes it; under the macro's height limit).
DETAIL_W = 140.0
DETAIL_MAX_H = 100.0
DETAIL_MARGIN = 0.22
#: The letter heights the note writes in that detail (page mm): the points, the designations, the
#: dimension ab's text; the note's legend takes the detail's upper left corner (page mm).
DETAIL_POINT_H = 3.5
DETAIL_MARK_H = 2.9
DETAIL_DIM_H = 3.2
DETAIL_LEGEND = (62.0, 24.0)
#: The page mm kept free along the detail's edges.
DETAIL_EDGE = 2.0
#: The sheet writes a designation placed for the note at the largest of these ГОСТ 2.304 sizes
#: that its box holds, at least the sheet's own size, at most POINT_MAX_H for the points' letters
#: and MARK_MAX_H for the other designations (sheet mm).
GOST_HEIGHTS = (3.5, 5.0, 7.0)
POINT_MAX_H = 5.0
MARK_MAX_H = 5.0


def detail_frame(pic: MeshingPicture) -> tuple[float, float, float, float]:
    """The note's window of the meshing picture round the pole (real mm): the drawn teeth and a
    margin for the designations."""
    x0, y0, x1, y1 = pic.view
    pad = DETAIL_MARGIN * (x1 - x0)
    return (x0 - pad, y0 - pad, x1 + pad, y1 + pad)


def detail_reduction(pic: MeshingPicture, scale: DrawingScale) -> float:
    """Page mm per scene mm of the note's window (at most 1: the sheet's scale)."""
    x0, y0, x1, y1 = detail_frame(pic)
    k = scale.factor
    return min(1.0, DETAIL_W / ((x1 - x0) * k), DETAIL_MAX_H / ((y1 - y0) * k))


def _sheet_height(reserved: float, least: float, most: float) -> float:
    """The sheet's letter height for a text whose box is ``reserved`` sheet mm high."""
    fits = [h for h in GOST_HEIGHTS if least <= h <= min(most, max(reserved, least))]
    return max(fits) if fits else least


def meshing_marks(pair, pic: MeshingPicture, scale: DrawingScale | None = None):
    """The designations of the picture, placed once for both drawings of the scene (issue 12: the
    note placed its own, and the dimension ab came out on the other side from sheet 4's).

    First everything the note's detail shows (:func:`detail_frame`), placed in that window at the
    note's letter sizes on its reduced page (``k·r`` page mm per real mm,
    :func:`detail_reduction`) and never smaller than the sheet's letters reduced — so each box
    holds the note's text and, within it, the sheet's; then, at the sheet's scale and sizes in the
    sheet's view, the points outside that window, clear of the first. The dimension aw (the
    sheet's only) is placed before both, and both keep clear of it.
    Each mark carries the sheet's letter height (``height``) and the note's (``page_h``, 0 for a
    mark of the sheet only); the positions are in real mm, the same for both."""
    from dataclasses import replace

    from .meshing_marks import DIM_H, MARK_H, POINT_H, _Shared, place_aw, place_marks
    scale = scale if scale is not None else meshing_scale(pair, pic)
    k = scale.factor
    r = detail_reduction(pic, scale)
    kn = k * r                                              # page mm per real mm
    fx0, fy0, fx1, fy1 = detail_frame(pic)
    room = label_room(pair, pic, scale)
    sx0, sy0, sx1, sy1 = room
    e = DETAIL_EDGE / kn
    inner = (max(fx0 + e, sx0), max(fy0 + e, sy0), min(fx1 - e, sx1), min(fy1 - e, sy1))
    legend = (fx0, fy1 - DETAIL_LEGEND[1] / kn, fx0 + DETAIL_LEGEND[0] / kn, fy1)
    # the dimension aw (the sheet's only) first, right of the line of centres: the rest keeps clear
    shared = _Shared(pic)          # the teeth, their outlines and the circles, once for the three placements
    aw = place_aw(pair, pic, k, room, zone_k=k, shared=shared)
    aw_keep: tuple[tuple[float, float, float, float], ...] = ()
    if aw is not None:
        bx0, by0, bx1, by1 = Polygon(aw.box).bounds
        aw_keep = ((float(bx0), float(by0), float(bx1), float(by1)),)
    point_h, mark_h = max(DETAIL_POINT_H, POINT_H * r), max(DETAIL_MARK_H, MARK_H * r)
    dim_h = max(DETAIL_DIM_H, DIM_H * r)
    detail = place_marks(pair, pic, kn, inner, point_h=point_h, mark_h=mark_h, dim_h=dim_h,
                         keep_out=(legend, *aw_keep), zone_k=k, skip=frozenset({"aw"}), unit=k, shared=shared,
                         lines_drawn=() if aw is None else (aw,))
    marks = []
    for m in detail.marks:
        letter = m.name in pic.points
        sheet_h = _sheet_height(m.height / r, POINT_H if letter else MARK_H, POINT_MAX_H if letter else MARK_MAX_H)
        marks.append(replace(m, height=sheet_h,
                             page_h=DETAIL_POINT_H if letter else DETAIL_MARK_H))
    detail = replace(detail, marks=tuple(marks),
                     dimensions=tuple(replace(d, detail=True) for d in detail.dimensions))
    full = place_marks(pair, pic, k, room, zone_k=k, given=detail, keep_out=aw_keep, skip=frozenset({"aw"}),
                       shared=shared, lines_drawn=() if aw is None else (aw,))
    return full if aw is None else replace(full, dimensions=full.dimensions + (aw,))


def ab_on_sheet(pic: MeshingPicture, scale: DrawingScale) -> float:
    """|ab| as read on the sheet, to 0,1 mm."""
    return round(pic.ab_drawn * scale.factor, 1)


#: The circles' arcs are drawn as polylines whose chords stay within this of the true circle
#: (sheet mm; 2880 segments a circle before: 10 000 vertices, the most of sheet 4's DXF and preview).
ARC_TOL_MM = 0.01


def arc_quad_segs(radius_mm: float) -> int:
    """Segments per quarter circle of ``radius_mm`` (sheet mm) for chords within ARC_TOL_MM:
    a chord of angle θ leaves the circle by R·(1 − cos θ/2)."""
    import math
    theta = 2 * math.acos(max(-1.0, 1 - ARC_TOL_MM / max(radius_mm, ARC_TOL_MM)))
    return max(8, math.ceil(math.pi / 2 / theta))


#: The line kinds of the circles (ГОСТ 2.303: the pitch circle dash-dot, the working one dashed).
CIRCLE_KINDS = {"pitch": "axis", "base": "thin", "working": "hidden", "tip": "thin", "root": "thin"}
#: The radius of the dots at the named points, paper mm.
DOT_MM = 0.8


@dataclass(frozen=True)
class MeshingScene:
    """The meshing picture of sheet 4 as one scene: ``scene`` in paper mm at the sheet's scale
    (real mm × ``scale.factor``, the origin at O1), built from ``pic``; the note's figure is a
    window of it. ``marks`` are the designations, placed once for both (:func:`meshing_marks`)."""
    pic: MeshingPicture
    scale: DrawingScale
    scene: Scene
    marks: MeshingMarks


def meshing_scene(pair, pic: MeshingPicture | None = None) -> MeshingScene:
    """The picture's geometry at the sheet's scale: the teeth (contour), the circles as arcs through
    the meshing zone (pitch dash-dot, working dashed, others thin), the line of centres, the common
    tangent at P, the line of action N1N2, its working section ab, the zones of one and two pairs
    (ticked, beside ab), the named points as dots; the designations as labels tied to what they
    name; values: |ab| as read on the sheet."""
    import math

    from shapely.geometry import LineString
    from shapely.geometry import Point as SPoint
    from shapely.geometry import box

    from .meshing_marks import arcs_window
    from .scene import Circle, Entity, Label, Polyline, Scale, Segment, frozen

    pic = pic if pic is not None else meshing_picture(pair, n_teeth=3)
    scale = meshing_scale(pair, pic)
    k = scale.factor
    g = pair.geometry
    marks = meshing_marks(pair, pic, scale)

    def mm(p) -> tuple[float, float]:
        return (float(p[0]) * k, float(p[1]) * k)

    def lines_of(geom) -> list:
        if geom.is_empty:
            return []
        return [list(x.coords) for x in getattr(geom, "geoms", [geom]) if x.geom_type == "LineString"]

    rx0, ry0, rx1, ry1 = label_room(pair, pic, scale)
    window = box(rx0, ry0, rx1, ry1)
    arc_window = box(*arcs_window(pair, pic)).intersection(window)
    ents: list[Entity] = []
    for c in pic.circles:
        ring = SPoint(c.centre).buffer(c.radius, arc_quad_segs(c.radius * k)).exterior
        for j, line in enumerate(lines_of(ring.intersection(arc_window))):
            ents.append(Polyline(f"circle:{c.name}:{j}", tuple(mm(p) for p in line), CIRCLE_KINDS[c.kind]))
    for gear, teeth in ((1, pic.teeth1), (2, pic.teeth2)):
        for i, tooth in enumerate(teeth):
            ents.append(Polyline(f"tooth{gear}:{i}", tuple(mm(p) for p in tooth), "contour"))
    ents.append(Segment("centres", mm((0.0, max(ry0, -g.m))), mm((0.0, min(ry1, g.aw + g.m))), "axis"))
    for line in lines_of(LineString(pic.segments["tangent"]).intersection(window)):
        ents.append(Segment("tangent", mm(line[0]), mm(line[-1]), "thin"))
    n1, n2 = pic.points["N1"], pic.points["N2"]
    ents.append(Segment("N1N2", mm(n1), mm(n2), "thin"))
    ents.append(Segment("ab", mm(pic.points["a"]), mm(pic.points["b"]), "contour"))
    length = math.dist(n1, n2)
    nx, ny = (n2[1] - n1[1]) / length, -(n2[0] - n1[0]) / length        # to the lower right of N1N2
    labels: list[Label] = []
    for i, z in enumerate(pic.zones):
        if z.pairs == 0:
            continue
        p = (z.start[0] * k + nx * ZONE_OFFSET_MM, z.start[1] * k + ny * ZONE_OFFSET_MM)
        q = (z.end[0] * k + nx * ZONE_OFFSET_MM, z.end[1] * k + ny * ZONE_OFFSET_MM)
        ident = f"zone{min(z.pairs, 2)}:{i}"
        ents.append(Segment(ident, p, q, "vectors"))
        for j, e in enumerate((p, q)):
            t = 0.4 * ZONE_OFFSET_MM
            ents.append(Segment(f"{ident}:tick{j}", (e[0] - nx * t, e[1] - ny * t), (e[0] + nx * t, e[1] + ny * t),
                                "thin"))
    for name in ("O1", "O2", "P", "N1", "N2", "a", "b"):
        ents.append(Circle(f"point:{name}", mm(pic.points[name]), DOT_MM, "contour"))
    for ident, text, c in marks.zones:       # placed with the designations: none touches them
        labels.append(Label(text, ident, mm(c), "zone"))
    for m in marks.marks:
        labels.append(Label(m.tex, f"mark:{m.name}", mm(m.anchor), "mark"))
    return MeshingScene(pic, scale, Scene("meshing", (Scale("k_l", k, "", scale.label),), tuple(ents),
                                          tuple(labels), frozen({n: mm(p) for n, p in pic.points.items()}),
                                          frozen({"ab": ab_on_sheet(pic, scale)})), marks)
