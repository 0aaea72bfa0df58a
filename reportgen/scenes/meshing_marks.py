"""The designations of the meshing picture (картина зацепления) of sheet 4 and of the note's figure,
placed once for the drawing scale ``k`` (sheet mm per real mm), so that both draw the same marks.

What a student's sheet carries (ГОСТ 16530-83 names, ГОСТ 2.403 conventions): the radii of the
pitch, base, working (pitch of the mesh), tip and root circles of each wheel (r, rb, rw, ra, rf)
on leaders to their circles; the tooth thickness s on the pitch circle of one tooth of each
wheel and the pitch p of wheel 1 as arcs between the flanks; the working pressure angle αw
between the common tangent at P and the line of action N1N2; the letters O1, O2, P, N1, N2, a,
b; the line of action and its working section ab named on leaders; the dimensions aw and ab.

Placement: a label is a text box of a known height (sheet mm) and an estimated width
(:data:`CHAR_WIDTH` per character and mm of height — the sheet's monospace ГОСТ lettering is
narrower, a test checks it). Candidate positions are tried in order of preference and the first
one is taken whose box and leader cross no tooth outline (the teeth as polygons, widened by a
clearance) and overlap no label placed before; among those left, fewer crossed circles is
better. Everything is in the gear-pair frame, real mm (:mod:`reportgen.gears.meshing`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, Point as SPoint, Polygon, box
from shapely.ops import unary_union

from ..geometry import Vec2 as Point
from ..numbers import plain
from ..gears.meshing import MeshingPicture
from ..tolerances import ABS_ZERO, MM_ROUNDOFF

#: Width of one character per mm of letter height (the sheet's lettering is 0.83 plus 10 % margin:
#: drawings.style.text_width; tests/scenes/test_meshing_marks.py checks the sheet's text fits).
CHAR_WIDTH = 0.92
#: Letter heights, sheet mm: point letters, designations, dimension texts (ГОСТ 2.304 sizes).
POINT_H = 5.0
MARK_H = 3.5
DIM_H = 3.5
#: Clearance kept between a text and a tooth outline, sheet mm.
CLEAR = 1.0


@dataclass(frozen=True)
class Mark:
    """A designation: ``text`` (sheet spelling, e.g. "rb1"; a catalogue key when ``word``), the point
    it names (``anchor``, real mm), its leader (polyline from the anchor to the text's shelf, empty
    for a letter set beside its point) and its box ``(x0, y0, x1, y1)`` (real mm). ``tex`` is the
    note's spelling."""
    name: str
    text: str
    tex: str
    anchor: Point
    leader: tuple[Point, ...]
    box: tuple[float, float, float, float]
    height: float                  # sheet mm
    word: bool = False

    @property
    def centre(self) -> Point:
        x0, y0, x1, y1 = self.box
        return ((x0 + x1) / 2, (y0 + y1) / 2)


@dataclass(frozen=True)
class ArcMark:
    """An arc on a circle between two angles (radians, counter-clockwise from ``a0`` to ``a1``) with
    ticks at its ends: the thickness s of a tooth or the pitch p, read on the pitch circle."""
    name: str
    centre: Point
    radius: float
    a0: float
    a1: float

    def points(self, n: int = 40) -> tuple[Point, ...]:
        t = np.linspace(self.a0, self.a1, n)
        return tuple((float(self.centre[0] + self.radius * math.cos(a)),
                      float(self.centre[1] + self.radius * math.sin(a))) for a in t)


@dataclass(frozen=True)
class AngleMark:
    """The angle αw at P: an arc of ``radius`` (real mm) from direction ``a0`` to ``a1`` (radians)."""
    centre: Point
    radius: float
    a0: float
    a1: float

    def points(self, n: int = 30) -> tuple[Point, ...]:
        t = np.linspace(self.a0, self.a1, n)
        return tuple((float(self.centre[0] + self.radius * math.cos(a)),
                      float(self.centre[1] + self.radius * math.sin(a))) for a in t)


@dataclass(frozen=True)
class PlacedDimension:
    """A linear dimension between ``p1`` and ``p2`` (real mm) with its line ``offset_mm`` sheet mm to
    the left of p1→p2 (as :meth:`drawings.primitives.Canvas.dimension` draws it), its text and the
    text's box (a polygon, real mm)."""
    name: str
    p1: Point
    p2: Point
    offset_mm: float
    value: float
    text: str
    box: tuple[Point, ...]


@dataclass(frozen=True)
class MeshingMarks:
    """Every designation of the picture at the scale ``k``; ``arcs_window`` is the box (real mm) in
    which the circles are drawn as arcs."""
    k: float
    marks: tuple[Mark, ...]
    arcs: tuple[ArcMark, ...]
    angle: AngleMark
    dimensions: tuple[PlacedDimension, ...]
    arcs_window: tuple[float, float, float, float]

    def boxes(self) -> list[tuple[str, Polygon]]:
        """Every text box (real mm): the marks' and the dimensions' texts."""
        out = [(m.name, box(*m.box)) for m in self.marks]
        out += [(d.name, Polygon(d.box)) for d in self.dimensions]
        return out


def text_size(text: str, height: float) -> tuple[float, float]:
    """Estimated (width, height) of a one-line text, sheet mm."""
    return (CHAR_WIDTH * height * max(len(text), 1), height)


def teeth_polygons(pic: MeshingPicture) -> list[Polygon]:
    """The drawn teeth as polygons (each outline closed across its root)."""
    out = []
    for t in pic.teeth1 + pic.teeth2:
        poly = Polygon(np.asarray(t))
        if not poly.is_valid:
            poly = poly.buffer(0)
        out.append(poly)
    return out


def arcs_window(pair, pic: MeshingPicture) -> tuple[float, float, float, float]:
    """Where the circles are drawn as arcs (as drawn by hand: through the meshing zone only)."""
    m = pair.geometry.m
    vx0, vy0, vx1, vy1 = pic.view
    return (vx0 - 2 * m, vy0 - 3 * m, vx1 + 2 * m, vy1 + 3 * m)


class _Placer:
    """Greedy placement against hard obstacles (teeth, placed texts) and soft ones (drawn lines)."""

    def __init__(self, k: float, teeth: list[Polygon], lines: list, room: Polygon) -> None:
        self.k = k
        self.teeth = unary_union([t.buffer(CLEAR / k) for t in teeth])
        shapely.prepare(self.teeth)
        self.lines = lines
        self.tree = shapely.STRtree(lines) if lines else None
        self.room = room
        self.placed: list[Polygon] = []

    def free(self, poly: Polygon, leader: LineString | None = None) -> bool:
        if not self.room.contains(poly):
            return False
        if self.teeth.intersects(poly):
            return False
        if leader is not None and leader.length > 0 and self.teeth.intersects(leader):
            return False
        gap = 0.8 / self.k
        return not any(poly.intersects(p.buffer(gap)) for p in self.placed) and not (
            leader is not None and any(leader.intersects(p) for p in self.placed))

    def crossings(self, poly) -> int:
        if self.tree is None:
            return 0
        return int(len(self.tree.query(poly, predicate="intersects")))

    def take(self, poly: Polygon) -> None:
        self.placed.append(poly)


def _bounds(poly) -> tuple[float, float, float, float]:
    x0, y0, x1, y1 = poly.bounds
    return (float(x0), float(y0), float(x1), float(y1))


def _box_at(c: Point, w: float, h: float) -> Polygon:
    return box(c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)


def _beside(placer: _Placer, name: str, text: str, tex: str, p: Point, height: float,
            prefer_deg: float, own_radius: float = 0.0) -> Mark:
    """A letter beside its point: 16 directions from ``prefer_deg``, three distances; where none
    is free, on a leader that may cross the teeth within ``own_radius`` of the point."""
    k = placer.k
    w, h = (v / k for v in text_size(text, height))
    best = None
    order = [prefer_deg + s * i * 22.5 for i in range(9) for s in ((1, -1) if i else (1,))][:16]
    for dist in (1.5 / k, (1.5 + height) / k, (1.5 + 1.5 * height) / k):
        for ang in order:
            ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
            t = min((w / 2) / abs(ux) if abs(ux) > ABS_ZERO else math.inf,
                    (h / 2) / abs(uy) if abs(uy) > ABS_ZERO else math.inf)
            c = (p[0] + ux * (t + dist), p[1] + uy * (t + dist))
            poly = _box_at(c, w, h)
            if not placer.free(poly):
                continue
            score = placer.crossings(poly)
            if best is None or score < best[0]:
                best = (score, poly)
            if score == 0:
                break
        if best is not None and best[0] == 0:
            break
    if best is None:        # no free place beside it (among the teeth at the pole): on a leader
        dirs = [prefer_deg + s_ * i * 22.5 for i in range(9) for s_ in ((1, -1) if i else (1,))][:16]
        return _on_leader(placer, name, text, tex, [p], dirs, height,
                          lengths=(8.0, 12.0, 17.0, 23.0, 30.0, 40.0),
                          own=SPoint(p).buffer(own_radius) if own_radius else None)
    placer.take(best[1])
    return Mark(name, text, tex, (float(p[0]), float(p[1])), (), _bounds(best[1]),
                height)


def _on_leader(placer: _Placer, name: str, text: str, tex: str, anchors: list[Point],
               directions: list[float], height: float, word: bool = False,
               lengths: tuple[float, ...] = (7.0, 11.0, 16.0, 22.0, 30.0), own=None) -> Mark:
    """A designation on a leader: from one of ``anchors`` (in order of preference) a slanted line of
    one of ``lengths`` (sheet mm) in one of ``directions`` (degrees), then a shelf under the text.
    The first free candidate with the fewest crossed lines wins (ties: the earlier). ``own``: the
    region (a tooth, the teeth round the pole) the leader may cross to reach its anchor."""
    k = placer.k
    w, h = (v / k for v in text_size(text, height))
    best = None
    for L in lengths:
        for anchor in anchors:
            for ang in directions:
                ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
                elbow = (anchor[0] + ux * L / k, anchor[1] + uy * L / k)
                right = ux >= 0
                end = (elbow[0] + (w if right else -w), elbow[1])
                x0 = min(elbow[0], end[0])
                poly = box(x0, elbow[1] + 0.6 / k, x0 + w, elbow[1] + 0.6 / k + h)
                leader = LineString([anchor, elbow, end])
                # the leader's first mm touches its own line: test the rest
                probe = LineString([(anchor[0] + ux * 1.2 / k, anchor[1] + uy * 1.2 / k), elbow, end])
                if own is not None:
                    probe = probe.difference(own)
                    if probe.is_empty:
                        probe = None
                if not placer.free(poly, probe):
                    continue
                score = placer.crossings(poly) * 3 + (placer.crossings(probe) if probe is not None else 0)
                if best is None or score < best[0]:
                    best = (score, poly, leader, anchor)
                if score <= 2:
                    break
            if best is not None and best[0] <= 2:
                break
        if best is not None and best[0] <= 2:
            break
    if best is None:        # no free place: the first candidate (a test reports it)
        anchor, ang = anchors[0], directions[0]
        ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
        elbow = (anchor[0] + ux * lengths[-1] / k, anchor[1] + uy * lengths[-1] / k)
        end = (elbow[0] + (w if ux >= 0 else -w), elbow[1])
        x0 = min(elbow[0], end[0])
        best = (0, box(x0, elbow[1] + 0.6 / k, x0 + w, elbow[1] + 0.6 / k + h),
                LineString([anchor, elbow, end]), anchor)
    _, poly, leader, anchor = best
    placer.take(poly)
    placer.take(leader.buffer(0.3 / k))
    return Mark(name, text, tex, (float(anchor[0]), float(anchor[1])),
                tuple((float(x), float(y)) for x, y in leader.coords),
                _bounds(poly), height, word)


def _dim_box(p1: Point, p2: Point, offset: float, k: float, text: str) -> Polygon:
    """The text box of an aligned dimension (as Canvas.dimension draws it: the text 2.5 mm beyond
    the dimension line, along it), real mm."""
    d = math.dist(p1, p2)
    ux, uy = (p2[0] - p1[0]) / d, (p2[1] - p1[1]) / d
    nx, ny = -uy, ux
    c = ((p1[0] + p2[0]) / 2 + nx * (offset + 2.5) / k, (p1[1] + p2[1]) / 2 + ny * (offset + 2.5) / k)
    w, h = (v / k for v in text_size(text, DIM_H))
    corners = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]
    return Polygon([(c[0] + ux * a + nx * b, c[1] + uy * a + ny * b) for a, b in corners]).buffer(0.5 / k)


def _dimension(placer: _Placer, name: str, p1: Point, p2: Point, text: str,
               offsets: list[float], prefer_clear: bool = False) -> PlacedDimension:
    """The first offset (sheet mm) at which the text, the dimension line and its extension lines
    cross no tooth and no placed text; ``prefer_clear``: among those, the first whose text crosses
    no drawn line (the arcs), else the one crossing fewest."""
    k = placer.k
    d = math.dist(p1, p2)
    nx, ny = -(p2[1] - p1[1]) / d, (p2[0] - p1[0]) / d
    # 1st choice: text, dimension line and extension lines clear of the teeth; 2nd: the text and
    # the dimension line (thin extension lines may cross a tooth, as on a drawn sheet); 3rd: the text
    best: tuple[int, float, Polygon] | None = None
    for off in offsets:
        poly = _dim_box(p1, p2, off, k, text)
        if not placer.free(poly):
            continue
        q1 = (p1[0] + nx * off / k, p1[1] + ny * off / k)
        q2 = (p2[0] + nx * off / k, p2[1] + ny * off / k)
        rank = 0 if not placer.teeth.intersects(LineString([q1, q2])) else 2
        if rank == 0:
            for p, q in ((p1, q1), (p2, q2)):       # extension lines, clear of their own point
                s = 2.0 / k if off > 0 else -2.0 / k
                start = (p[0] + nx * s, p[1] + ny * s)
                if abs(off) > 2.5 and placer.teeth.intersects(LineString([start, q])):
                    rank = 1
        if prefer_clear:
            rank = rank * 100 + placer.crossings(poly)
        if best is None or rank < best[0]:
            best = (rank, off, poly)
        if rank == 0:
            break
    if best is None:          # no free place for the text: the first offset (a test reports it)
        off = offsets[0]
        best = (10**6, off, _dim_box(p1, p2, off, k, text))
    chosen = (best[1], best[2])
    placer.take(chosen[1])
    return PlacedDimension(name, (float(p1[0]), float(p1[1])), (float(p2[0]), float(p2[1])),
                           float(chosen[0]), float(d), text,
                           tuple((float(x), float(y)) for x, y in chosen[1].exterior.coords))


def _circle_anchors(centre: Point, r: float, window: Polygon, teeth: Polygon, gear: int,
                    k: float) -> list[Point]:
    """Points of a drawn arc outside the teeth, farthest from the pole first (where the arcs are
    uncrowded), alternating the two sides."""
    ring = SPoint(centre).buffer(r, 360).exterior.intersection(window)
    free = ring.difference(teeth.buffer(2.5 / k))
    pts: list[Point] = []
    geoms = getattr(free, "geoms", [free])
    for g in geoms:
        if g.is_empty or g.length < 3.0 / k:
            continue
        for f in (0.15, 0.5, 0.85):
            p = g.interpolate(f, normalized=True)
            pts.append((p.x, p.y))
    pts.sort(key=lambda p: -abs(p[0]))
    return pts[:8] or [(centre[0], centre[1] + (r if gear == 1 else -r))]


def place_marks(pair, pic: MeshingPicture, k: float,
                room: tuple[float, float, float, float] | None = None, *,
                point_h: float = POINT_H, mark_h: float = MARK_H,
                keep_out: tuple[tuple[float, float, float, float], ...] = ()) -> MeshingMarks:
    """Every designation of the meshing picture at scale ``k`` (paper mm per real mm) inside
    ``room`` (real mm; default: the picture's bounds with the centres, widened by 60 paper mm);
    letters ``point_h`` and designations ``mark_h`` paper mm high. Sheet 4 places them at its
    scale in its view; the note's figure, a detail of the same picture round the pole, at its
    own scale in its frame (points and the dimension aw outside it are left out); ``keep_out``
    boxes (real mm) hold other things (a legend, a scale bar)."""
    g = pair.geometry
    teeth = teeth_polygons(pic)
    aw_box = arcs_window(pair, pic)
    window = box(*aw_box)
    if room is None:
        x0, y0, x1, y1 = pic.view
        pad = 60.0 / k
        room = (min(x0, 0.0) - pad, min(y0, 0.0) - pad, max(x1, 0.0) + pad, max(y1, g.aw) + pad)
    lines = []
    for c in pic.circles:
        part = SPoint(c.centre).buffer(c.radius, 360).exterior.intersection(window)
        if not part.is_empty:
            lines.append(part)
    n1, n2 = pic.points["N1"], pic.points["N2"]
    P = pic.points["P"]
    lines.append(LineString([n1, n2]))
    lines.append(LineString(pic.segments["tangent"]))
    lines.append(LineString([(0.0, room[1]), (0.0, room[3])]))
    # the zones of single and double contact are drawn 6 mm beside ab, their numerals beyond
    pa, pb_ = pic.points["a"], pic.points["b"]
    L = math.dist(n1, n2)
    zn = ((n2[1] - n1[1]) / L, -(n2[0] - n1[0]) / L)           # to the lower right of N1N2
    zone_band = Polygon([(pa[0] + zn[0] * d / k, pa[1] + zn[1] * d / k) for d in (3.0, 11.0)]
                        + [(pb_[0] + zn[0] * d / k, pb_[1] + zn[1] * d / k) for d in (11.0, 3.0)])
    placer = _Placer(k, teeth + [zone_band], lines, box(*room))
    for kb in keep_out:
        placer.take(box(*kb))
    # the common tangent and N1N2 cross the teeth near P; the line of action matters more
    teeth_u = unary_union(teeth)
    # 1. the letters of the points
    marks: list[Mark] = []
    prefer = {"O1": 0, "O2": 0, "P": -60, "N1": 200, "N2": 20, "a": 150, "b": -30}
    inside = box(*room)
    for name in ("P", "a", "b", "N1", "N2", "O1", "O2"):
        pt = pic.points[name]
        if not inside.contains(SPoint(pt)):
            continue
        marks.append(_beside(placer, name, name, f"{name[0]}_{{{name[1:]}}}" if len(name) > 1 else name,
                             pt, point_h, prefer[name], own_radius=2.4 * g.m))
    # 2. the dimensions: ab beside the line of action, aw right of the line of centres
    ab_text = plain(pic.ab_drawn, 3).replace(".", ",")
    offs = [s * v for v in (12.0, 16.0, 21.0, 27.0, 34.0, 42.0, 52.0, 64.0, 78.0) for s in (-1.0, 1.0)]
    dims = [_dimension(placer, "ab", pic.points["a"], pic.points["b"], ab_text, offs)]
    # aw: right of the line of centres, beyond the teeth and the arcs where the room allows
    teeth_right = max(float(np.max(t[:, 0])) for t in pic.teeth1 + pic.teeth2)
    far = room[2] * k - 8.0
    near = teeth_right * k + 10.0
    start = min(max(aw_box[2] * k + 10.0, near), far)
    cands = [start + v for v in np.arange(0.0, far - start + MM_ROUNDOFF, 6.0)]
    cands += [start - v for v in np.arange(6.0, start - near + MM_ROUNDOFF, 6.0)]
    aw_text = plain(g.aw, 3).replace(".", ",")
    if inside.contains(SPoint(pic.points["O1"])) and inside.contains(SPoint(pic.points["O2"])):
        dims.append(_dimension(placer, "aw", pic.points["O1"], pic.points["O2"], aw_text,
                               [-float(v) for v in cands] or [-near], prefer_clear=True))
    # 3. the circles: gear 1 (below) on the left, leaders down-left; gear 2 (above) on the right
    order = {"tip": 0, "root": 1, "pitch": 2, "working": 3, "base": 4}
    for c in sorted(pic.circles, key=lambda c: (c.gear, order[c.kind])):
        anchors = _circle_anchors(c.centre, c.radius, window, teeth_u, c.gear, k)
        if c.gear == 1:
            dirs = [225.0, 200.0, 250.0, 315.0, 135.0, 160.0, 270.0, 180.0]
        else:
            dirs = [45.0, 20.0, 70.0, 135.0, 315.0, 340.0, 90.0, 0.0]
        base_name = {"pitch": "r", "base": "rb", "working": "rw", "tip": "ra", "root": "rf"}[c.kind]
        sub = {"pitch": "", "base": "b", "working": "w", "tip": "a", "root": "f"}[c.kind]
        tex = f"r_{{{sub}{c.gear}}}"
        anchors = [q for q in anchors if inside.contains(SPoint(q))] or anchors
        marks.append(_on_leader(placer, c.name, f"{base_name}{c.gear}", tex, anchors, dirs, mark_h))
    # 4. s1, s2 on a tooth beside the central one, p across one pitch of gear 1
    arcs = []
    for gear, teeth_g, r, centre in ((1, pic.teeth1, g.d1 / 2, (0.0, 0.0)), (2, pic.teeth2, g.d2 / 2, (0.0, g.aw))):
        idx = 0 if len(teeth_g) > 1 else 0          # the first tooth (left of P for gear 1)
        tooth = Polygon(np.asarray(teeth_g[idx])).buffer(0)
        ring = SPoint(centre).buffer(r, 1440).exterior
        cut = ring.intersection(tooth)
        if cut.is_empty:
            continue
        seg = max(getattr(cut, "geoms", [cut]), key=lambda s: s.length)
        a_s = [math.atan2(y - centre[1], x - centre[0]) for x, y in (seg.coords[0], seg.coords[-1])]
        a0, a1 = min(a_s), max(a_s)
        arcs.append(ArcMark(f"s{gear}", centre, r, a0, a1))
        mid = (centre[0] + r * math.cos((a0 + a1) / 2), centre[1] + r * math.sin((a0 + a1) / 2))
        dirs = [240.0, 210.0, 270.0, 180.0, 300.0] if gear == 1 else [60.0, 30.0, 90.0, 0.0, 120.0]
        marks.append(_on_leader(placer, f"s{gear}", f"s{gear}", f"s_{{{gear}}}", [mid], dirs, mark_h,
                                lengths=(9.0, 14.0, 20.0, 28.0, 38.0), own=tooth.buffer(2 * CLEAR / k)))
        if gear == 1:
            # p: from this tooth's left flank to the next tooth's left flank (one angular pitch)
            step = 2 * math.pi / g.z1
            p_arc = ArcMark("p", centre, r, a1, a1 + step)
            arcs.append(p_arc)
            pm = (centre[0] + r * math.cos(a1 + step / 2), centre[1] + r * math.sin(a1 + step / 2))
            marks.append(_on_leader(placer, "p", "p", "p", [pm], [250.0, 290.0, 220.0, 270.0, 200.0],
                                    mark_h, lengths=(12.0, 18.0, 26.0, 36.0, 48.0),
                                    own=SPoint(pm).buffer(2.4 * g.m)))
    # 5. αw between the tangent at P (towards +x) and the line of action (towards N2)
    ang_r = 18.0 / k
    a_w = math.atan2(n2[1] - P[1], n2[0] - P[0])
    angle = AngleMark(P, ang_r, 0.0, a_w)
    tip = (P[0] + ang_r * math.cos(a_w / 2), P[1] + ang_r * math.sin(a_w / 2))
    marks.append(_on_leader(placer, "alpha_w", "αw", "\\alpha_{w}", [tip],
                            [10.0, -20.0, 40.0, 70.0, 90.0, 110.0, 300.0, 270.0, 250.0, 135.0, 200.0, 160.0,
                             -45.0, 20.0, 55.0, 125.0, 180.0, 225.0],
                            mark_h, lengths=(10.0, 16.0, 24.0, 34.0, 46.0, 60.0, 75.0, 90.0),
                            own=SPoint(P).buffer(max(ang_r + 2.0 / k, 2.4 * g.m))))
    return MeshingMarks(k=k, marks=tuple(marks), arcs=tuple(arcs), angle=angle,
                        dimensions=tuple(dims), arcs_window=aw_box)
