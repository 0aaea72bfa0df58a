"""Views of sheet 2 (kinetostatics): a group or the crank cut out at μl with its forces at their
schematic lengths (the free-body scenes of :mod:`reportgen.scenes.free_body`, which the note draws too), a force polygon at its μF (the replica's, so the sheet and the note read the same
lengths), and Zhukovsky's lever (the turned velocity plan with the loads and their arms).

Each view is first a :class:`Panel` — its size and a function that draws it into a given rectangle —
so that the sheet can arrange all of them before drawing any (``*_panel``); ``*_view`` pack and draw
one at once. All numbers come from :class:`reportgen.kinetostatics.Kinetostatics`; nothing here
solves."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np
from shapely.geometry import LineString, MultiLineString, Point

from drawings import style
from drawings.layout import Rect
from drawings.primitives import Transform, format_significant
from drawings.sheet import Sheet, View
from ..words import symbol, tr
from reportgen import gost_scales
from reportgen.scenes.forces import polygon_scene
from reportgen.scenes.scene import Arrow as SceneArrow
from reportgen.scenes.scene import Circle as SceneCircle
from reportgen.scenes.scene import Polyline as ScenePolyline
from reportgen.scenes.scene import Scene
from reportgen.scenes.scene import Segment as SceneSegment

from drawings.lettering import from_tex
from drawings.scenes import kinematics_labels as rl

#: Room around a view's drawing for labels, and the title / caption strips, mm.
PAD_MM = 10.0
TITLE_MM = 10.0
CAPTION_MM = 16.0
HINGE_MM = 1.5
LABEL_MM = 3.5
POLY_LABEL_MM = 3.5
POLY_PAD_MM = 10.0
#: The lever's loads: the largest drawn this long (mm) at their own round μF.
LEVER_ARROW_MM = 40.0
def lever_title() -> str:
    return tr("sheets.kv01")


def lever_subtitle() -> str:
    return tr("sheets.kv02")


def plain(name: str) -> str:
    """A solver's name as sheet text in the sheet's language (the ГОСТ font has τ and Cyrillic):
    ``Fи4′`` → ``Fи4'`` (``Fin4'`` in English)."""
    if ":" in name:
        base, point = name.split(":", 1)
        return symbol(f"F{base}({point})")
    return symbol(name.replace("′", "'"))


def force_name(lb) -> rl.Rich:
    """A scene's vector name as the sheet letters it: the note's symbol (``lb.text``,
    ``R^{\\tau}_{24}``) with its indices raised and lowered, smaller (issue 12: sheet 2 printed
    «Rτ24» inline where the note prints R^τ_24); a name without a symbol as the solver writes it."""
    if "_" in lb.text or "^" in lb.text:
        return from_tex(lb.text)
    return rl.Rich(plain(lb.anchor.rsplit(":", 1)[1]))


@dataclass
class Panel:
    """A view not yet placed: ``width`` × ``height`` mm, drawn by ``paint(sheet, rect)``."""
    name: str
    width: float
    height: float
    paint: Callable[[Sheet, Rect], View]

    def place(self, sheet: Sheet, preferred: str) -> View:
        """Packed near ``preferred`` and drawn (a view of its own, as :meth:`Sheet.add_view`)."""
        from drawings.layout import Request, pack
        rect = pack(sheet.free_region, [Request(self.name, self.width, self.height, preferred)],
                    placed=[v.rect for v in sheet.views.values()])[0]
        return self.paint(sheet, rect)


def _title_and_scales(view: View, title: str, upper: str, lower: str) -> None:
    """The view's title, and two captions (e.g. μl and μF) at its bottom."""
    view.title(title)
    view.text_mm((view.rect.center[0], view.rect.y0 + 9.0), upper, 3.5, "bottom-center")
    view.text_mm((view.rect.center[0], view.rect.y0 + 3.0), lower, 3.5, "bottom-center")


def free_body_panel(name: str, title: str, scene: Scene) -> Panel:
    """A free-body diagram's scene (:mod:`reportgen.scenes.free_body`, the note draws the same):
    the group (or the crank) cut out at μl, its hinges and blocks, every force at its point at the
    scene's schematic length (:func:`reportgen.scenes.free_body.schematic_length`, the caption
    says so), each named beside its own arrow, the points' letters and the links' numbers."""
    x0, y0, x1, y1 = scene.bounds()
    lo, hi = np.array([x0, y0]), np.array([x1, y1])
    w = max(hi[0] - lo[0] + 2 * PAD_MM, 110.0)
    h = hi[1] - lo[1] + 2 * PAD_MM + TITLE_MM + CAPTION_MM

    def paint(sheet: Sheet, rect: Rect) -> View:
        cx = rect.x0 + (rect.width - (hi[0] - lo[0])) / 2
        cy = rect.y0 + CAPTION_MM + (rect.height - CAPTION_MM - TITLE_MM - (hi[1] - lo[1])) / 2
        view = sheet.place_view(name, rect, Transform(1.0, (float(lo[0]), float(lo[1])), (cx, cy)))
        for e in scene.entities:
            if isinstance(e, SceneSegment):
                view.segment(e.a, e.b, e.kind, trim_mm=e.trim)
            elif isinstance(e, SceneCircle):
                view.hinge(e.c, e.r)
            elif isinstance(e, ScenePolyline):
                view.polyline(e.points, e.kind, closed=e.closed)
        for e in scene.entities:
            if isinstance(e, SceneArrow):
                view.arrow(e.a, e.b, None, head_mm=min(4.0, e.length))
        inside = view.rect.polygon()

        def line_of(prefix: str):
            """What a link's number or a couple's name names: its lines (sheet mm)."""
            parts = [[view.transform(p) for p in ((e.a, e.b) if isinstance(e, SceneSegment) else e.points)]
                     for e in scene.entities if e.id.startswith(prefix) and isinstance(e, (SceneSegment, ScenePolyline))]
            return MultiLineString(parts) if parts else None

        letters = [view.transform(lb.at) for lb in scene.labels if lb.role == "point" and lb.anchor.startswith("point:")]
        for lb in scene.labels:
            if lb.role == "point":
                kind, ident = lb.anchor.split(":", 1)
                if kind == "point":
                    rl.place_point_label(view, view.transform(lb.at), rl.Rich(ident), 5.0, 135.0, letters,
                                         inside=inside, cross=0)
                else:                # a couple's name over its arc, with its indices (M_{и2})
                    arc = next((e.points for e in scene.entities if e.id == f"{lb.anchor}:arc"
                                and isinstance(e, ScenePolyline)), ())
                    rich = from_tex(lb.text) if ("_" in lb.text or "^" in lb.text) else rl.Rich(plain(ident))
                    named = line_of(lb.anchor)
                    spots = [c for q in [lb.at] + list(arc[::3])
                             for c in rl.around(view.transform(q), rich, LABEL_MM, 45.0, gaps=(1.0, 3.0, 6.0))]
                    if named is not None:       # its letters near its arc (the label check's reach)
                        from reportgen.tolerances import LABEL_NEAR_MM
                        spots = [c for c in spots
                                 if rl.text_extent(rich, c, LABEL_MM).distance(named) < LABEL_NEAR_MM - 1.0] or spots
                    rl.place_passes(view, [(spots, 0), (spots, 1), (spots, 99)], rich, LABEL_MM, inside=inside,
                                    names=named)
        for lb in scene.labels:
            if lb.role == "link":
                named = line_of(f"link{lb.text}:")
                if named is None:      # a link drawn at one point (a block): its block's outline
                    blocks = [e for e in scene.entities if isinstance(e, ScenePolyline) and e.id.startswith("block:")]
                    near = min(blocks, key=lambda e: min(math.dist(q, lb.at) for q in e.points), default=None)
                    named = None if near is None else line_of(near.id)
                place_label(view, [np.asarray(lb.at)], lb.text, LABEL_MM, names=named)
        named = [(lb, view.transform(lb.along[0]), view.transform(lb.along[1])) for lb in scene.labels
                 if lb.role == "vector" and lb.along is not None]
        rivals = tuple(LineString([a, b]) for _, a, b in named)      # each name nearer its own arrow
        place_vector_names(view, [(a, b, force_name(lb), False) for lb, a, b in named], LABEL_MM, inside, rivals)
        _title_and_scales(view, title, tr("sheets.kv03", v1=format_significant(scene.scale("μl").value, 4)),
                          tr("fbd.arrows"))
        return view
    return Panel(name, w, h, paint)


def polygon_panel(name: str, title: str, polygon, first: int = 0) -> Panel:
    """A force polygon's scene (:func:`reportgen.scenes.forces.polygon_scene`): head to tail at its
    scale (mm), the diagonals read off it dashed, each name beside its own vector (a short vector's
    name on a leader); its details indexed from ``first``."""
    scene = polygon_scene(polygon, first=first)
    x0, y0, x1, y1 = scene.bounds()
    for lb in scene.labels:        # a detail's heading and scale, wider than the detail, within the view
        if lb.role in ("detail-title", "detail-scale"):
            text, height = (detail_text(lb), 5.0) if lb.role == "detail-title" else \
                (tr("sheets.kv05", v1=format_significant(scene.scale(f"μF:{lb.text}").value, 4)), 3.5)
            half = style.text_width(text, height) / 2 + 1.0
            x0, x1 = min(x0, lb.at[0] - half), max(x1, lb.at[0] + half)
            y1 = max(y1, lb.at[1] + height / 2 + 1.0)
    lo, hi = np.array([x0, y0]), np.array([x1, y1])
    w = max(hi[0] - lo[0] + 2 * POLY_PAD_MM, 90.0)
    h = hi[1] - lo[1] + 2 * POLY_PAD_MM + TITLE_MM + 8.0

    def paint(sheet: Sheet, rect: Rect) -> View:
        cx = rect.x0 + (rect.width - (hi[0] - lo[0])) / 2
        cy = rect.y0 + 8.0 + (rect.height - 8.0 - TITLE_MM - (hi[1] - lo[1])) / 2
        view = sheet.place_view(name, rect, Transform(1.0, (float(lo[0]), float(lo[1])), (cx, cy)))
        for e in scene.entities:
            if isinstance(e, SceneArrow):
                if e.kind == "hidden":
                    view.segment(e.a, e.b, "hidden")
                else:
                    view.arrow(e.a, e.b, None, head_mm=min(4.0, e.length))
            elif isinstance(e, SceneSegment):
                view.segment(e.a, e.b, "hidden" if e.kind == "hidden" else "thin" if e.kind == "thin" else "contour")
            elif isinstance(e, SceneCircle):
                view.circle_mm(e.c, e.r, "thin")
        view.title(title)           # the titles first: the names keep clear of them
        mu = scene.scale()
        view.text_mm((view.rect.center[0], view.rect.y0 + 3.0),
                     tr("sheets.kv05", v1=format_significant(mu.value, 4)), 3.5, "bottom-center")
        inside = view.rect.polygon()
        for lb in scene.labels:            # a detail's letter, heading and scale at their own places first
            if lb.role in ("detail", "detail-title"):
                view.text_mm(view.transform(lb.at), detail_text(lb), 5.0, "center")
            elif lb.role == "detail-scale":
                text = tr("sheets.kv05", v1=format_significant(scene.scale(f"μF:{lb.text}").value, 4))
                view.text_mm(_within(view.sheet.frame, view.transform(lb.at), style.text_width(text, 3.5)), text, 3.5,
                             "center")
        rivals = tuple(LineString([view.transform(lb.along[0]), view.transform(lb.along[1])])
                       for lb in scene.labels if lb.along is not None)
        place_vector_names(view, [(view.transform(lb.along[0]), view.transform(lb.along[1]),
                                   force_name(lb), lb.leader)
                                  for lb in scene.labels if lb.along is not None], POLY_LABEL_MM, inside, rivals)
        return view
    return Panel(name, w, h, paint)


def _within(rect: Rect, centre, width: float) -> tuple[float, float]:
    """A centre moved along x so that a text ``width`` wide stays inside ``rect``, the frame (a detail's scale
    of six digits, «μF = 100000 Н/мм» of the press with its crank 550 times faster, stood 5 mm over
    the frame)."""
    half = width / 2 + 2.0
    x = min(max(centre[0], rect.x0 + half), rect.x1 - half) if rect.x1 - rect.x0 > 2 * half else centre[0]
    return (x, centre[1])


def leader_name(view: View, a, b, rich, height: float, inside, leader_uncrossed: bool = False) -> None:
    """The name of a short vector a→b (sheet mm) on a thin leader to its middle, across it first
    (the leader is part of what ties the name to its vector), where its box and its leader cross
    nothing (:func:`drawings.scenes.kinematics_labels.place_on_leader`); else the nearest spot that
    overlaps no text."""
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    normal = math.degrees(math.atan2(b[0] - a[0], -(b[1] - a[1])))
    line = LineString([a, b])
    if rl.place_on_leader(view, mid, rl.around(mid, rich, height, normal, gaps=LEADER_GAPS_MM)
                          + rl.spread_around(mid, LEADER_REACH_MM), rich, height, inside, names=line, to=line,
                          leader_uncrossed=leader_uncrossed) is not None:
        return
    foot: list = []

    def named(box):
        foot.append(rl.leader_foot(box, mid))
        return line.union(LineString([foot[-1], mid]))

    if rl.place_passes(view, [(rl.around(mid, rich, height, normal, gaps=(5.0, 6.0, 8.0)), 0)],
                       rich, height, inside=inside, names=named) is not None:
        view.layout.add_line(foot[-1], mid, dxfattribs={"layer": "thin"})
        view.annotations.add_obstacle(LineString([foot[-1], mid]))     # later names keep off it


#: Distances (mm) from a vector's middle at which its name is tried on a leader, nearest first.
LEADER_GAPS_MM = (5.0, 6.5, 8.0, 10.0, 12.0, 15.0, 18.0, 22.0)
#: Where none of those is free (a crowded cluster of the lever), the nearest free spot within this
#: many mm of the vector's middle.
LEADER_REACH_MM = 45.0


def detail_text(lb) -> str:
    """A polygon detail's letter (``polygons.letters`` of the sheet's language) or its heading
    «А (5:1)» (:func:`reportgen.scenes.forces.polygon_details`)."""
    from ..words import decimal_mark
    letters = tr("polygons.letters")
    index, _, ratio = lb.text.partition(" ")
    letter = letters[int(index) % len(letters)]
    return f"{letter} ({gost_scales.Scale.parse(ratio).text(decimal_mark())})" if ratio else letter


def polygon_view(sheet: Sheet, name: str, title: str, polygon, preferred: str) -> View:
    """:func:`polygon_panel` packed near ``preferred`` and drawn."""
    return polygon_panel(name, title, polygon).place(sheet, preferred)


def _shares_line(own: LineString, other: LineString) -> bool:
    """Do two vectors lie on one line, overlapping (then their names share the room beside it)?"""
    (ax, ay), (bx, by) = own.coords[0], own.coords[-1]
    n = math.hypot(bx - ax, by - ay)
    if n == 0.0:
        return False
    off = max(abs((x - ax) * (by - ay) - (y - ay) * (bx - ax)) for x, y in (other.coords[0], other.coords[-1])) / n
    return off < 0.5 and own.distance(other) < 0.5


#: A vector's name must be nearer to its own vector than to any other named vector by this much, mm
#: (the label check's half millimetre with a margin for the measuring font).
OWN_MARGIN_MM = 0.8


def near_passes(a, b, rich, height: float, rivals: tuple = ()) -> list[tuple[list, int]]:
    """Passes for the name of the vector a→b (sheet mm) that keep it its own: beside it, then
    round its middle no farther than LABEL_NEAR_MM, crossing no line (issue 12: a name crossed by
    another vector reads as neither's), then (the last resort, after a leader) crossing one, two,
    any — a name is never carried off to where it would read as
    another vector's: nearer to its own vector than to any of the other named vectors ``rivals``
    (LineStrings, sheet mm) that do not lie along it."""
    from reportgen.tolerances import LABEL_NEAR_MM
    near = rl.along(a, b, rich, height)
    middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    normal = math.degrees(math.atan2(b[0] - a[0], -(b[1] - a[1])))
    far = rl.around(middle, rich, height, normal, gaps=(3.0, 4.5, 6.0))
    line = LineString([a, b])

    def close(cands: list) -> list:
        """Those whose letters (:func:`rl.text_extent`: the base and its indices as drawn, not
        their bounding box — a raised index beside a lowered one leaves a corner empty) stay
        near the vector — a wide name beside a short vector must not hang off its end."""
        out = []
        for c in cands:
            text = rl.text_extent(rich, c, height)
            d = text.distance(line)
            if d < LABEL_NEAR_MM - 0.5 and all(text.distance(r) >= d + OWN_MARGIN_MM for r in others):
                out.append(c)
        return out
    others = [r for r in rivals if not r.equals(line) and not _shares_line(line, r)]
    near, far = close(near), close(far)
    return [(near, 0), (near, 1), (far, 0), (far, 1), (near, 2), (near, 99)]


def place_vector_name(view: View, a, b, rich, height: float, inside, rivals: tuple = (),
                      uncrossed: bool = False, leader_uncrossed: bool = False) -> None:
    """The name of the vector a→b (sheet mm) beside it (:func:`near_passes`, nearer to it than to
    any of the ``rivals``) where it overlaps no text and crosses no line; where every spot beside it
    is taken, farther out on a thin leader to the vector's middle (the leader is part of what ties
    it to its vector); else beside it, overlapping the fewest. ``uncrossed`` (sheet 2's views): a
    name beside its vector crossed by a line is taken only after a leader whose box and leader cross
    nothing (issue 12: «Fур» on the lever crossed by the coupler's image), anywhere in ``inside``
    if need be (:func:`drawings.scenes.kinematics_labels.place_on_leader`)."""
    line = LineString([a, b])
    passes = near_passes(a, b, rich, height, rivals)
    if uncrossed:
        if rl.place_passes(view, [p for p in passes if p[1] == 0], rich, height, inside=inside, optional=True,
                           names=line, strict=True) is not None:
            return
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        normal = math.degrees(math.atan2(b[0] - a[0], -(b[1] - a[1])))
        if rl.place_on_leader(view, mid, rl.around(mid, rich, height, normal, gaps=LEADER_GAPS_MM)
                              + rl.spread_around(mid, LEADER_REACH_MM), rich, height, inside, names=line, to=line,
                              anywhere=True, leader_uncrossed=leader_uncrossed) is not None:
            return
    if rl.place_passes(view, passes, rich, height, inside=inside, optional=True, names=line) is not None:
        return
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    normal = math.degrees(math.atan2(b[0] - a[0], -(b[1] - a[1])))
    leader: list = []

    def named(box):
        leader.append(rl.leader_foot(box, mid))
        return line.union(LineString([leader[0], mid]))

    if rl.place_passes(view, [(rl.around(mid, rich, height, normal, gaps=(9.0, 12.0, 16.0, 20.0)), 0),
                              (rl.around(mid, rich, height, normal, gaps=(9.0, 12.0, 16.0, 20.0)), 1)],
                       rich, height, inside=inside, optional=True, names=named) is not None:
        view.layout.add_line(leader[0], mid, dxfattribs={"layer": "thin"})
        view.annotations.add_obstacle(LineString([leader[0], mid]))     # later names keep off it
        return
    rl.place_passes(view, near_passes(a, b, rich, height), rich, height, inside=inside, names=line)


def _bearing(centre, a, b) -> float:
    """The direction (rad) of the middle of the vector a→b seen from ``centre``."""
    return math.atan2((a[1] + b[1]) / 2 - centre[1], (a[0] + b[0]) / 2 - centre[0])


#: Distances (mm) from a vector's middle at which :func:`_callout` tries its name, and the turns (°)
#: off the direction away from the cluster's middle.
CALLOUT_REACH_MM = (6.0, 8.0, 10.0, 12.5, 15.0, 18.0, 22.0, 26.0, 30.0)
CALLOUT_TURNS_DEG = (0.0, 20.0, -20.0, 40.0, -40.0, 60.0, -60.0, 90.0, -90.0)


def _callout(view: View, a, b, rich, height: float, inside, centre) -> bool:
    """The name of the vector a→b (sheet mm) on a leader to it, away from the crowded cluster round
    ``centre``: the nearest spot, straight out first, whose box overlaps no text and crosses no line
    and whose leader crosses no line or text (the leaders drawn before included). False where none."""
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    ang = _bearing(centre, a, b)
    if math.dist(mid, centre) < 1.0:     # at the middle itself: away across the vector
        ang = math.atan2(b[0] - a[0], -(b[1] - a[1]))
    w, _, _ = rl.size(rich, height)
    cands = []
    for d in CALLOUT_REACH_MM:
        for turn in CALLOUT_TURNS_DEG:
            t = ang + math.radians(turn)
            ux, uy = math.cos(t), math.sin(t)
            cands.append((mid[0] + ux * (d + abs(ux) * w / 2), mid[1] + uy * (d + abs(uy) * height / 2)))
    line = LineString([a, b])
    placed = rl.place_on_leader(view, mid, cands, rich, height, inside, names=line, to=line, leader_clear=True)
    return placed is not None


def _keep_apart(view: View, since: int, gap: float) -> None:
    """Margins of ``gap`` mm round the text boxes placed since the ``since``-th (placing only: the
    DXF is unchanged), so that later names keep that far from them."""
    if gap <= 0.0:
        return
    boxes = view.annotations.boxes
    for name, box in list(boxes[since:]):
        if name != KEEP_APART:
            boxes.append((KEEP_APART, box.buffer(gap, join_style=2)))


#: The name of the margins :func:`_keep_apart` adds round placed names.
KEEP_APART = "keep-apart"


def place_vector_names(view: View, items: list, height: float, inside, rivals: tuple = (),
                       gap: float = 0.0, leader_uncrossed: bool = False, outward=None) -> None:
    """The names of sheet 2's vectors ``items`` ((tail, head, rich, on a leader), sheet mm) in two
    rounds: first each beside its own vector where it overlaps no text and crosses no line, then
    the rest (and the short ones, :func:`leader_name`) on leaders — a name on a leader does not take
    the spot another name needs beside its own vector (issue 12: the lever's crowded clusters).
    ``gap`` (mm): every name keeps that far from the texts of the view placed before it and from
    the names placed after it; ``leader_uncrossed``: a leader crossing or running along a drawn line
    is the last resort (:func:`drawings.scenes.kinematics_labels.place_on_leader`; issue 12: on the
    control sheet's lever «FMі4(F)» stood on a leader along «Fі5», leaders crossed at e);
    ``outward`` (a point, sheet mm: the middle of a crowded cluster): a name with no free spot beside
    its vector goes on a leader away from that point (:func:`_callout`), the names taken in turn
    round it, so that their leaders fan out instead of crossing."""
    if gap > 0.0:
        inside_view = view.rect.polygon()
        for name, box in list(view.annotations.boxes):
            if name != KEEP_APART and box.intersects(inside_view):
                view.annotations.boxes.append((KEEP_APART, box.buffer(gap, join_style=2)))
    later = []
    for a, b, rich, short in items:
        n0 = len(view.annotations.boxes)
        if short or rl.place_passes(view, [p for p in near_passes(a, b, rich, height, rivals) if p[1] == 0], rich,
                                    height, inside=inside, optional=True, names=LineString([a, b]),
                                    strict=True) is None:
            later.append((a, b, rich, short))
        _keep_apart(view, n0, gap)
    if outward is not None:          # the rest fanned out of the crowded cluster, in turn round it
        later.sort(key=lambda it: _bearing(outward, it[0], it[1]))
    for a, b, rich, short in later:
        n0 = len(view.annotations.boxes)
        if outward is not None and _callout(view, a, b, rich, height, inside, outward):
            _keep_apart(view, n0, gap)
            continue
        # the old passes, which end with the spot of fewest conflicts: with a third of the margins
        # there (a margin is no text: overlapping one must not push a name onto a letter, table 7's
        # «e» under «FMи3(D)»)
        boxes = view.annotations.boxes
        kept = [bx for bx in boxes if bx[0] != KEEP_APART]
        margins = [bx for bx in boxes if bx[0] == KEEP_APART]
        boxes[:] = kept + [(KEEP_APART, m.buffer(-gap * 2.0 / 3.0, join_style=2)) for _, m in margins]
        if short:
            leader_name(view, a, b, rich, height, inside, leader_uncrossed)
        else:
            place_vector_name(view, a, b, rich, height, inside, rivals, uncrossed=True,
                              leader_uncrossed=leader_uncrossed)
        boxes[:] = [bx for bx in boxes if bx[0] != KEEP_APART] + margins
        _keep_apart(view, len(kept), gap)
    # the margins were for placing only: the sheet's own overlap check reads the boxes
    view.annotations.boxes[:] = [bx for bx in view.annotations.boxes if bx[0] != KEEP_APART]


def place_label(view: View, anchors: list[np.ndarray], text: str, height: float, names=None) -> None:
    """A label near the first anchor (model points) where a box of 16 directions × 3 distances
    overlaps no text and crosses no line; else :meth:`Canvas.label` at the first anchor. ``names``:
    what it names (a geometry, sheet mm) when that is not the anchor point (a link, an arc)."""
    from drawings import style
    from drawings.primitives import text_box
    w = style.text_width(text, height)
    for anchor in anchors:
        p = view.transform(anchor)
        for dist in (1.0, 3.0, 6.0):
            for k in range(16):
                ang = math.radians(45.0 + 22.5 * k)
                c = (p[0] + math.cos(ang) * (w / 2 + dist), p[1] + math.sin(ang) * (height / 2 + dist))
                box = text_box(c, text, height, "center")
                if not view.rect.polygon().contains(box):
                    continue
                if view.annotations.hits_box(box) == 0 and view.annotations.crossings(box) == 0:
                    view.text_mm(c, text, height, "center", names=names if names is not None else Point(p))
                    return
    view.label(anchors[0], text, height, names=names)


#: The lever's names keep at least this far (mm) from one another and from its letters (issue 12:
#: «Fі4», «Fі5», «FMі4(F)», «G4», «FMі3(E)» piled at the pole of the control sheet's lever).
LEVER_NAME_GAP_MM = 1.5


def lever_panel(name: str, scene: Scene) -> Panel:
    """Zhukovsky's lever (:func:`reportgen.scenes.lever.lever_scene`): the turned plan (mm) with each
    load and F_ур at its image point, each named beside its own arrow, the arms thin."""
    from drawings import style
    x0, y0, x1, y1 = scene.bounds()
    lo, hi = np.array([x0, y0]), np.array([x1, y1])
    pad = 12.0
    w = max(hi[0] - lo[0] + 2 * pad, style.text_width(lever_title(), 5.0) + 4.0,
            style.text_width(lever_subtitle(), 3.5) + 4.0)
    h = hi[1] - lo[1] + 2 * pad + TITLE_MM + 6.0 + CAPTION_MM

    def paint(sheet: Sheet, rect: Rect) -> View:
        x0 = rect.x0 + (rect.width - (hi[0] - lo[0])) / 2
        y0 = rect.y0 + CAPTION_MM + (rect.height - CAPTION_MM - TITLE_MM - 6.0 - (hi[1] - lo[1])) / 2
        view = sheet.place_view(name, rect, Transform(1.0, (float(lo[0]), float(lo[1])), (x0, y0)))
        for e in scene.entities:
            if isinstance(e, SceneSegment):
                view.line(e.a, e.b, "vectors" if e.kind != "construction" else "construction")
                if e.kind == "construction":      # the arms: thin, but a name crossed by one is crossed
                    view.annotations.add_obstacle(LineString([view.transform(e.a), view.transform(e.b)]))
        for e in scene.entities:
            if isinstance(e, SceneArrow):
                view.arrow(e.a, e.b, None, head_mm=3.5)
        _title_and_scales(view, lever_title(), tr("sheets.kv06", v1=format_significant(scene.scale('μv').value, 4)),
                          tr("sheets.kv07", v1=format_significant(scene.scale('μF').value, 4)))
        view.text_mm((view.rect.center[0], view.rect.y1 - TITLE_MM - 4.5), lever_subtitle(), 3.5, "bottom-center")
        inside = view.rect.polygon()
        points = [view.transform(lb.at) for lb in scene.labels if lb.role == "point"]
        for lb in scene.labels:
            if lb.role == "point":
                rl.place_point_label(view, view.transform(lb.at), rl.Rich(lb.anchor.split(":", 1)[1]), 5.0,
                                     -135.0 if lb.anchor == "point:p" else 45.0, points, inside=inside, cross=0)
        rivals = tuple(LineString([view.transform(lb.along[0]), view.transform(lb.along[1])])
                       for lb in scene.labels if lb.role == "vector" and lb.along is not None
                       and lb.anchor.startswith("force:"))
        items = []
        for lb in scene.labels:
            if lb.role != "vector" or lb.along is None:
                continue
            kind, ident = lb.anchor.split(":", 1)
            if kind == "arm":
                continue            # the arms are numbered by the note's equations (h1, h2, … of section 2)
            rich = force_name(lb)
            items.append((view.transform(lb.along[0]), view.transform(lb.along[1]), rich, False))
        # the middle of the crowd: the mean of the loads' middles nearest to the pole (the images of
        # the slow points pile there; the crank pin's F_ур stands far off)
        mids = sorted(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2) for a, b, _, _ in items)
        pole = view.transform((0.0, 0.0))
        near = sorted(mids, key=lambda m: math.dist(m, pole))[:max(1, len(mids) // 2)]
        hub = tuple(np.mean(near, axis=0)) if near else None
        place_vector_names(view, items, POLY_LABEL_MM, inside, rivals, gap=LEVER_NAME_GAP_MM,
                           leader_uncrossed=True, outward=hub)
        return view
    return Panel(name, w, h, paint)


def lever_view(sheet: Sheet, name: str, scene: Scene, preferred: str) -> View:
    """:func:`lever_panel` packed near ``preferred`` and drawn."""
    return lever_panel(name, scene).place(sheet, preferred)
