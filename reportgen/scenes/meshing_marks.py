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
from dataclasses import dataclass, replace

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
#: Clearance kept between two texts (and a text and another's leader), paper mm of the placement:
#: no two designations touch (issue 12: «II» touched «αw»).
TEXT_GAP = 1.0
#: The zones of one and two pairs in contact are drawn this far beside ab (sheet mm), their
#: numerals «I», «II» ZONE_H high (sheet mm) beyond them, at 0.9·ZONE_OFFSET_MM from the zone's line.
ZONE_OFFSET_MM = 6.0
ZONE_H = 3.5


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
    #: the letter height on the note's page (page mm) where the note's figure shows this mark (it
    #: was placed at the note's letter size: :func:`reportgen.scenes.meshing.meshing_marks`); 0:
    #: a mark of the sheet only (a point or a dimension outside the note's window)
    page_h: float = 0.0

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
    #: the note's figure shows it too (placed in the note's window)
    detail: bool = False


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
    #: the numerals of the zones of one and two pairs in contact: (ident, text, centre real mm),
    #: :func:`zone_numerals` (the sheet writes them ZONE_H high)
    zones: tuple[tuple[str, str, Point], ...] = ()

    def boxes(self) -> list[tuple[str, Polygon]]:
        """Every text box (real mm): the marks' and the dimensions' texts."""
        out = [(m.name, box(*m.box)) for m in self.marks]
        out += [(d.name, Polygon(d.box)) for d in self.dimensions]
        return out

    def zone_boxes(self, k_sheet: float) -> list[tuple[str, Polygon]]:
        """The zones' numerals' boxes (real mm) as the sheet writes them at ``k_sheet``."""
        out = []
        for ident, text, c in self.zones:
            w, h = (v / k_sheet for v in text_size(text, ZONE_H))
            out.append((ident, _box_at(c, w, h)))
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


def zone_numerals(pic: MeshingPicture, k_sheet: float) -> tuple[tuple[str, str, Point], ...]:
    """The numerals «I», «II» of the zones of one and two pairs in contact (ident, text, centre in
    real mm): beside the middle of each zone's line (drawn ZONE_OFFSET_MM to the lower right of ab
    on the sheet at ``k_sheet``), 0.9·ZONE_OFFSET_MM beyond it."""
    n1, n2 = pic.points["N1"], pic.points["N2"]
    L = math.dist(n1, n2)
    nx, ny = (n2[1] - n1[1]) / L, -(n2[0] - n1[0]) / L          # to the lower right of N1N2
    d = 1.9 * ZONE_OFFSET_MM / k_sheet
    out = []
    for i, z in enumerate(pic.zones):
        if z.pairs == 0:
            continue
        c = ((z.start[0] + z.end[0]) / 2 + nx * d, (z.start[1] + z.end[1]) / 2 + ny * d)
        out.append((f"zone{min(z.pairs, 2)}:{i}", "II" if z.pairs >= 2 else "I", (float(c[0]), float(c[1]))))
    return tuple(out)


def _box_at(c: Point, w: float, h: float) -> Polygon:
    return box(c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)


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

    def free(self, poly: Polygon, leader: LineString | None = None, whole: LineString | None = None) -> bool:
        """``poly`` (a text's box) and ``leader`` clear of the teeth, the room's edge and what is
        placed; ``whole``: the leader with the part near its own point that may cross the teeth
        (``leader`` is the rest), which must still cross no other text or leader."""
        if not self.room.contains(poly):
            return False
        if self.teeth.intersects(poly):
            return False
        if leader is not None and leader.length > 0 and self.teeth.intersects(leader):
            return False
        gap = TEXT_GAP / self.k
        line = whole if whole is not None else leader
        return not any(poly.intersects(p.buffer(gap)) for p in self.placed) and not (
            line is not None and any(line.intersects(p) for p in self.placed))

    def crossings(self, poly) -> int:
        if self.tree is None:
            return 0
        return int(len(self.tree.query(poly, predicate="intersects")))

    def take(self, poly: Polygon) -> None:
        self.placed.append(poly)


def _bounds(poly) -> tuple[float, float, float, float]:
    x0, y0, x1, y1 = poly.bounds
    return (float(x0), float(y0), float(x1), float(y1))


def _beside(placer: _Placer, name: str, text: str, tex: str, p: Point, height: float,
            prefer_deg: float, own_radius: float = 0.0) -> Mark:
    """A letter beside its point: 16 directions from ``prefer_deg``, two distances (within half a
    letter of the point: farther, a letter is not read as its point's); where none is free, on a
    leader that may cross the teeth within ``own_radius`` of the point."""
    k = placer.k
    w, h = (v / k for v in text_size(text, height))
    best = None
    order = [prefer_deg + s * i * 22.5 for i in range(9) for s in ((1, -1) if i else (1,))][:16]
    for dist in (1.5 / k, (1.5 + 0.5 * height) / k):
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
                          own=SPoint(p).buffer(own_radius) if own_radius else None, strict=True)
    placer.take(best[1])
    return Mark(name, text, tex, (float(p[0]), float(p[1])), (), _bounds(best[1]),
                height)


def _on_leader(placer: _Placer, name: str, text: str, tex: str, anchors: list[Point],
               directions: list[float], height: float, word: bool = False,
               lengths: tuple[float, ...] = (7.0, 11.0, 16.0, 22.0, 30.0), own=None, strict: bool = False) -> Mark:
    """A designation on a leader: from one of ``anchors`` (in order of preference) a slanted line of
    one of ``lengths`` (sheet mm) in one of ``directions`` (degrees), then a shelf under the text.
    The first free candidate with the fewest crossed lines wins (ties: the earlier). ``own``: the
    region (a tooth, the teeth round the pole) the leader may cross to reach its anchor; ``strict``:
    there too it crosses no other text or leader (a point's letter: two letters' leaders crossing
    near their points swap them for a reader)."""
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
                whole = probe if strict else None
                if own is not None:
                    probe = probe.difference(own)
                    if probe.is_empty:
                        probe = None
                if not placer.free(poly, probe, whole):
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


def _aw_offsets(pic: MeshingPicture, aw_box, room, k: float) -> list[float]:
    """Offsets (paper mm) to try for the dimension aw: right of the line of centres, beyond the
    teeth and the arcs where the room allows, then nearer."""
    teeth_right = max(float(np.max(t[:, 0])) for t in pic.teeth1 + pic.teeth2)
    far = room[2] * k - 8.0
    near = teeth_right * k + 10.0
    start = min(max(aw_box[2] * k + 10.0, near), far)
    cands = [start + v for v in np.arange(0.0, far - start + MM_ROUNDOFF, 6.0)]
    cands += [start - v for v in np.arange(6.0, start - near + MM_ROUNDOFF, 6.0)]
    return [-float(v) for v in cands] or [-near]


def place_aw(pair, pic: MeshingPicture, k: float, room: tuple[float, float, float, float],
             zone_k: float | None = None) -> PlacedDimension | None:
    """The dimension aw (O1O2) at scale ``k`` in ``room`` (real mm), clear of the teeth and the
    zones only: placed before the designations, which keep clear of it (None when O1 or O2 is
    outside the room)."""
    inside = box(*room)
    if not (inside.contains(SPoint(pic.points["O1"])) and inside.contains(SPoint(pic.points["O2"]))):
        return None
    marks = place_marks(pair, pic, k, room, zone_k=zone_k,
                        skip=frozenset(("P", "a", "b", "N1", "N2", "O1", "O2", "ab")),
                        given=MeshingMarks(k=k, marks=(), arcs=(), angle=AngleMark(pic.points["P"], 0.0, 0.0, 0.0),
                                           dimensions=(), arcs_window=arcs_window(pair, pic)))
    return next(d for d in marks.dimensions if d.name == "aw")


def _dim_box(p1: Point, p2: Point, offset: float, k: float, text: str, height: float = DIM_H) -> Polygon:
    """The text box of an aligned dimension (as Canvas.dimension draws it: the text 2.5 mm beyond
    the dimension line, along it), real mm."""
    d = math.dist(p1, p2)
    ux, uy = (p2[0] - p1[0]) / d, (p2[1] - p1[1]) / d
    nx, ny = -uy, ux
    c = ((p1[0] + p2[0]) / 2 + nx * (offset + 2.5) / k, (p1[1] + p2[1]) / 2 + ny * (offset + 2.5) / k)
    w, h = (v / k for v in text_size(text, height))
    corners = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]
    return Polygon([(c[0] + ux * a + nx * b, c[1] + uy * a + ny * b) for a, b in corners]).buffer(0.5 / k)


def _dimension(placer: _Placer, name: str, p1: Point, p2: Point, text: str,
               offsets: list[float], prefer_clear: bool = False, height: float = DIM_H) -> PlacedDimension:
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
        poly = _dim_box(p1, p2, off, k, text, height)
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
        best = (10**6, off, _dim_box(p1, p2, off, k, text, height))
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
                point_h: float = POINT_H, mark_h: float = MARK_H, dim_h: float = DIM_H,
                keep_out: tuple[tuple[float, float, float, float], ...] = (),
                zone_k: float | None = None, given: MeshingMarks | None = None,
                skip: frozenset[str] = frozenset()) -> MeshingMarks:
    """Every designation of the meshing picture at scale ``k`` (paper mm per real mm) inside
    ``room`` (real mm; default: the picture's bounds with the centres, widened by 60 paper mm);
    letters ``point_h``, designations ``mark_h`` and the dimensions' texts ``dim_h`` paper mm
    high; ``keep_out`` boxes (real mm) hold other things (a legend, a scale bar). The zones of
    one and two pairs and their numerals (drawn at ``zone_k``, the sheet's scale; default ``k``)
    are kept clear.

    ``given``: designations placed already (the note's window, at the note's letter size:
    :func:`reportgen.scenes.meshing.meshing_marks`); only what they lack is placed (the points
    and the dimension aw outside that window), clear of them, and the result holds both, at the
    scale ``k`` (the given dimensions' offsets converted to it). ``skip``: names not to place
    (placed apart: the dimension aw, :func:`place_aw`)."""
    g = pair.geometry
    zone_k = zone_k if zone_k is not None else k
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
    # the zones of single and double contact are drawn ZONE_OFFSET_MM beside ab, their numerals
    # beyond: a band no designation enters, the numerals' boxes kept TEXT_GAP clear
    pa, pb_ = pic.points["a"], pic.points["b"]
    L = math.dist(n1, n2)
    zn = ((n2[1] - n1[1]) / L, -(n2[0] - n1[0]) / L)           # to the lower right of N1N2
    zone_band = Polygon([(pa[0] + zn[0] * d / zone_k, pa[1] + zn[1] * d / zone_k) for d in (3.0, 11.0)]
                        + [(pb_[0] + zn[0] * d / zone_k, pb_[1] + zn[1] * d / zone_k) for d in (11.0, 3.0)])
    placer = _Placer(k, teeth + [zone_band], lines, box(*room))
    numerals = zone_numerals(pic, zone_k)
    result = MeshingMarks(k=k, marks=(), arcs=(), angle=AngleMark(P, 0.0, 0.0, 0.0), dimensions=(),
                          arcs_window=aw_box, zones=numerals)
    for _, poly in result.zone_boxes(zone_k):
        placer.take(poly)
    for kb in keep_out:
        placer.take(box(*kb))
    done: set[str] = set()
    marks: list[Mark] = []
    dims: list[PlacedDimension] = []
    if given is not None:
        for m in given.marks:
            placer.take(box(*m.box))
            if m.leader:
                placer.take(LineString(m.leader).buffer(0.3 / k))
        for d in given.dimensions:
            placer.take(Polygon(d.box))
        done = {m.name for m in given.marks} | {d.name for d in given.dimensions}
        marks = list(given.marks)
        dims = [replace(d, offset_mm=d.offset_mm * k / given.k) for d in given.dimensions]
    # the common tangent and N1N2 cross the teeth near P; the line of action matters more
    teeth_u = unary_union(teeth)
    # 1. the letters of the points
    prefer = {"O1": 0, "O2": 0, "P": -60, "N1": 200, "N2": 20, "a": 150, "b": -30}
    inside = box(*room)
    for name in ("P", "a", "b", "N1", "N2", "O1", "O2"):
        pt = pic.points[name]
        if name in done or name in skip or not inside.contains(SPoint(pt)):
            continue
        marks.append(_beside(placer, name, name, f"{name[0]}_{{{name[1:]}}}" if len(name) > 1 else name,
                             pt, point_h, prefer[name], own_radius=2.4 * g.m))
    # 2. the dimensions: ab beside the line of action, aw right of the line of centres
    if "ab" not in done and "ab" not in skip:
        ab_text = plain(pic.ab_drawn, 3).replace(".", ",")
        offs = [s * v for v in (12.0, 16.0, 21.0, 27.0, 34.0, 42.0, 52.0, 64.0, 78.0) for s in (-1.0, 1.0)]
        dims.append(_dimension(placer, "ab", pic.points["a"], pic.points["b"], ab_text, offs, height=dim_h))
    if "aw" not in done and "aw" not in skip and inside.contains(SPoint(pic.points["O1"])) \
            and inside.contains(SPoint(pic.points["O2"])):
        dims.append(_dimension(placer, "aw", pic.points["O1"], pic.points["O2"], plain(g.aw, 3).replace(".", ","),
                               _aw_offsets(pic, aw_box, room, k), prefer_clear=True, height=dim_h))
    if given is not None:         # the circles, s, p and αw are the given ones
        return replace(given, k=k, marks=tuple(marks), dimensions=tuple(dims), zones=numerals)
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
                        dimensions=tuple(dims), arcs_window=aw_box, zones=numerals)
