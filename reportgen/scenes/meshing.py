"""The meshing picture (картина зацепления) of sheet 4 as a scene (:func:`meshing_scene`, the stage
``project.scenes.meshing``): its scale decided once for the window the sheet gives it, its geometry
in paper mm at that scale; the note draws a window of the same scene (reduced, the caption says
so) and quotes the same scale and the length of ab read on the sheet."""
from __future__ import annotations

from dataclasses import dataclass

from ..gears.meshing import GOST_SCALES, MeshingPicture, meshing_picture
from .meshing_marks import MeshingMarks
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
        if self.factor >= 1:
            return f"{self.factor:g}:1".replace(".", ",")
        return f"1:{1 / self.factor:g}".replace(".", ",")


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


def meshing_marks(pair, pic: MeshingPicture, scale: DrawingScale | None = None):
    """The designations of the picture at the sheet's scale (the note draws the same ones)."""
    from .meshing_marks import place_marks
    scale = scale if scale is not None else meshing_scale(pair, pic)
    return place_marks(pair, pic, scale.factor, label_room(pair, pic, scale))


def ab_on_sheet(pic: MeshingPicture, scale: DrawingScale) -> float:
    """|ab| as read on the sheet, to 0,1 mm."""
    return round(pic.ab_drawn * scale.factor, 1)


#: The line kinds of the circles (ГОСТ 2.303: the pitch circle dash-dot, the working one dashed).
CIRCLE_KINDS = {"pitch": "axis", "base": "thin", "working": "hidden", "tip": "thin", "root": "thin"}
#: The radius of the dots at the named points, paper mm.
DOT_MM = 0.8
#: The zones of one and two pairs in contact are drawn this far beside ab (paper mm).
ZONE_OFFSET_MM = 6.0


@dataclass(frozen=True)
class MeshingScene:
    """The meshing picture of sheet 4 as one scene: ``scene`` in paper mm at the sheet's scale
    (real mm × ``scale.factor``, the origin at O1), built from ``pic``; the note's figure is a
    window of it. ``marks`` are the designations as the sheet places them (the note places the
    same names at its own letter size, :func:`reportgen.scenes.meshing_marks.place_marks`)."""
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
        ring = SPoint(c.centre).buffer(c.radius, 720).exterior
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
        mid = ((p[0] + q[0]) / 2 + nx * 0.9 * ZONE_OFFSET_MM, (p[1] + q[1]) / 2 + ny * 0.9 * ZONE_OFFSET_MM)
        labels.append(Label("II" if z.pairs >= 2 else "I", ident, mid, "zone"))
    for name in ("O1", "O2", "P", "N1", "N2", "a", "b"):
        ents.append(Circle(f"point:{name}", mm(pic.points[name]), DOT_MM, "contour"))
    for m in marks.marks:
        labels.append(Label(m.tex, f"mark:{m.name}", mm(m.anchor), "mark"))
    return MeshingScene(pic, scale, Scene("meshing", (Scale("k_l", k, "", scale.label),), tuple(ents),
                                          tuple(labels), frozen({n: mm(p) for n, p in pic.points.items()}),
                                          frozen({"ab": ab_on_sheet(pic, scale)})), marks)
