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
#: The designations whose text may stand inside a tooth (never across its outline): the points'
#: letters among the teeth, s on its tooth, p and αw; the circles' and the dimensions' texts keep
#: off the teeth.
INSIDE_TEETH = frozenset({"P", "a", "b", "N1", "N2", "O1", "O2", "s1", "s2", "p", "alpha_w"})
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

    def text_centre(self, w: float, h: float) -> Point:
        """Where a drawing writes this mark's text of ``w`` × ``h`` (real mm): on a leader, in the
        middle of the box; beside its point or circle (no leader), in the box as near to the
        anchor as the box allows (the sheet and the note alike, whatever their letter sizes)."""
        x0, y0, x1, y1 = self.box
        if self.leader:
            return self.centre
        cx = min(max(self.anchor[0], x0 + w / 2), x1 - w / 2) if x1 - x0 > w else (x0 + x1) / 2
        cy = min(max(self.anchor[1], y0 + h / 2), y1 - h / 2) if y1 - y0 > h else (y0 + y1) / 2
        return (cx, cy)


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


def zone_numerals(pic: MeshingPicture, k_sheet: float, lines=()) -> tuple[tuple[str, str, Point], ...]:
    """The numerals «I», «II» of the zones of one and two pairs in contact (ident, text, centre in
    real mm): beside each zone's line (drawn ZONE_OFFSET_MM to the lower right of ab on the sheet at
    ``k_sheet``), 0.9·ZONE_OFFSET_MM beyond it at its middle — or, where a drawn line (``lines``,
    real mm: the circles' arcs through the zone, issue 12) or a numeral placed before would touch
    it there, the first of :data:`ZONE_NUMERAL_AT` × :data:`ZONE_NUMERAL_BEYOND` that keeps
    LINE_CLEAR (sheet mm) off the lines, else the first that meets none of them; always TEXT_GAP
    off a numeral placed before (hypothesis found «I» and «II» 0,84 mm apart)."""
    n1, n2 = pic.points["N1"], pic.points["N2"]
    L = math.dist(n1, n2)
    nx, ny = (n2[1] - n1[1]) / L, -(n2[0] - n1[0]) / L          # to the lower right of N1N2
    tree = shapely.STRtree(list(lines)) if len(lines) else None
    taken: list[Polygon] = []
    out = []
    for i, z in enumerate(pic.zones):
        if z.pairs == 0:
            continue
        text = "II" if z.pairs >= 2 else "I"
        w, h = (v / k_sheet for v in text_size(text, ZONE_H))
        spots = [((z.start[0] + (z.end[0] - z.start[0]) * t + nx * f * ZONE_OFFSET_MM / k_sheet),
                  (z.start[1] + (z.end[1] - z.start[1]) * t + ny * f * ZONE_OFFSET_MM / k_sheet))
                 for f in ZONE_NUMERAL_BEYOND for t in ZONE_NUMERAL_AT]
        # off the lines by LINE_CLEAR where it can be, and always TEXT_GAP off the other numeral
        c = next((q for gap in (LINE_CLEAR, 0.0) for q in spots
                  if _clear_of(_grown(_box_at(q, w, h), gap / k_sheet), tree, [])
                  and _clear_of(_grown(_box_at(q, w, h), TEXT_GAP / k_sheet), None, taken)), spots[0])
        taken.append(_box_at(c, w, h))
        out.append((f"zone{min(z.pairs, 2)}:{i}", text, (float(c[0]), float(c[1]))))
    return tuple(out)


def _clear_of(poly: Polygon, tree, taken: list[Polygon]) -> bool:
    """Does ``poly`` meet none of the lines in ``tree`` (an STRtree or None) and none of ``taken``?"""
    return (tree is None or not tree.query(poly, predicate="intersects").size) \
        and not any(poly.intersects(t) for t in taken)


#: Where along its zone's line a numeral is tried (fractions, the middle first), and how far beyond
#: ab (multiples of ZONE_OFFSET_MM: the zone's line is at 1, its ticks reach 1.4).
ZONE_NUMERAL_AT = (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9, 0.0, 1.0)
ZONE_NUMERAL_BEYOND = (1.9, 2.2, 2.5, 2.8, 3.2)


def _box_at(c: Point, w: float, h: float) -> Polygon:
    return box(c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)


class _Placer:
    """Greedy placement against hard obstacles (teeth, placed texts and leaders) and soft ones
    (drawn lines). ``k``: paper mm per real mm of the texts' sizes and gaps (the note's page where
    the note's window is placed); ``unit``: paper mm per real mm of the leaders' lengths and the
    letters' distances from their points (the sheet's: a leader is short on the sheet and, reduced,
    in the note)."""

    def __init__(self, k: float, teeth: list[Polygon], lines: list, room: Polygon,
                 unit: float | None = None, shared: "_Shared | None" = None) -> None:
        self.k = k
        self.unit = unit if unit is not None else k
        self.teeth = (shared.teeth_clear(k) if shared is not None
                      else unary_union([t.buffer(CLEAR / k) for t in teeth]))
        shapely.prepare(self.teeth)
        self._outlines = shared.outlines_clear(k) if shared is not None else None
        self._teeth_list = teeth
        self.lines = list(lines)
        self.tree = shapely.STRtree(self.lines) if self.lines else None
        self.room = room
        self.placed: list[Polygon] = []
        self.texts: list[Polygon] = []
        self._halo: list[Polygon] = []          # the placed ones widened by TEXT_GAP
        self._halo_tree: shapely.STRtree | None = None
        self._placed_tree: shapely.STRtree | None = None
        self._room = room.bounds                 # the room is a box

    @property
    def outlines(self):
        """The teeth's outlines widened by the clearance (a point's letter may stand inside a
        tooth, never across its outline)."""
        if self._outlines is None:
            self._outlines = unary_union([t.exterior.buffer(CLEAR / self.k) for t in self._teeth_list])
            shapely.prepare(self._outlines)
        return self._outlines

    def free(self, poly: Polygon, leader: LineString | None = None, whole: LineString | None = None,
             inside_teeth: bool = False) -> bool:
        """``poly`` (a text's box) and ``leader`` clear of the teeth, the room's edge and what is
        placed; ``whole``: the leader with the part near its own point that may cross the teeth
        (``leader`` is the rest), which must still cross no other text or leader. ``inside_teeth``:
        the box and the leader may stand inside a tooth (a point's letter, s, p, αw), clear of its
        outline."""
        x0, y0, x1, y1 = poly.bounds
        if x0 < self._room[0] or y0 < self._room[1] or x1 > self._room[2] or y1 > self._room[3]:
            return False
        solid = self.outlines if inside_teeth else self.teeth
        if solid.intersects(poly):
            return False
        if leader is not None and leader.length > 0 and solid.intersects(leader):
            return False
        if self._halo_tree is not None and self._halo_tree.query(poly, predicate="intersects").size:
            return False
        line = whole if whole is not None else leader
        return not (line is not None and self._placed_tree is not None
                    and self._placed_tree.query(line, predicate="intersects").size)

    def free_many(self, polys: np.ndarray, probes: np.ndarray, wholes: np.ndarray,
                  inside_teeth: bool = False) -> np.ndarray:
        """:meth:`free` of many candidates at once (arrays of boxes, of leaders less their own
        region — empty where nothing is left — and of whole leaders): a boolean array."""
        b = shapely.bounds(polys)
        rx0, ry0, rx1, ry1 = self._room
        ok = (b[:, 0] >= rx0) & (b[:, 1] >= ry0) & (b[:, 2] <= rx1) & (b[:, 3] <= ry1)
        solid = self.outlines if inside_teeth else self.teeth
        ok &= ~shapely.intersects(solid, polys)
        has = ~shapely.is_empty(probes) & (shapely.length(probes) > 0)
        ok &= ~(has & shapely.intersects(solid, probes))
        n = len(polys)
        if self._halo_tree is not None:
            ok &= np.bincount(self._halo_tree.query(polys, predicate="intersects")[0], minlength=n) == 0
        if self._placed_tree is not None:
            ok &= np.bincount(self._placed_tree.query(wholes, predicate="intersects")[0], minlength=n) == 0
        return ok

    def crossings_many(self, geoms: np.ndarray, but=None) -> np.ndarray:
        """:meth:`crossings` of many geometries at once (an int array)."""
        n = len(geoms)
        if self.tree is None or n == 0:
            return np.zeros(n, dtype=int)
        src, hit = self.tree.query(geoms, predicate="intersects")
        if but is not None:
            keep = np.array([self.lines[i] is not but for i in hit], dtype=bool)
            src = src[keep]
        return np.bincount(src, minlength=n)

    def crossings(self, poly, but=None) -> int:
        """How many drawn lines ``poly`` meets (``but``: one of them not counted, its own)."""
        if self.tree is None:
            return 0
        hits = self.tree.query(poly, predicate="intersects")
        return int(sum(1 for i in hits if self.lines[i] is not but))

    def add_lines(self, geoms) -> None:
        """More drawn lines (a dimension's lines, once placed)."""
        self.lines.extend(geoms)
        self.tree = shapely.STRtree(self.lines)

    def take(self, poly: Polygon, text: bool = True) -> None:
        """``poly`` is taken: a text's box (``text``) or a leader widened."""
        self.placed.append(poly)
        if text:
            self.texts.append(poly)
        gap = TEXT_GAP / self.k
        self._halo.append(_grown(poly, gap) if text else poly.buffer(gap, quad_segs=2))
        self._halo_tree = shapely.STRtree(self._halo)
        self._placed_tree = shapely.STRtree(self.placed)


class _Shared:
    """The geometry every placement of one picture reuses (the sheet's and the note's, the
    dimension aw's): the teeth as polygons, their union widened by the clearance and their
    outlines, per scale; the circles' rings."""

    def __init__(self, pic: MeshingPicture) -> None:
        self.pic = pic
        self.teeth = teeth_polygons(pic)
        self.teeth_union = unary_union(self.teeth)
        self._clear: dict[float, object] = {}
        self._outl: dict[float, object] = {}
        self._wide: dict[float, object] = {}
        self.rings = {c.name: SPoint(c.centre).buffer(c.radius, RING_QUAD_SEGS).exterior for c in pic.circles}

    def teeth_clear(self, k: float):
        if k not in self._clear:
            self._clear[k] = self.teeth_union.buffer(CLEAR / k)
        return self._clear[k]

    def teeth_wide(self, k: float):
        """The teeth widened by 2,5 paper mm at ``k`` (where a circle's name is anchored off them)."""
        if k not in self._wide:
            self._wide[k] = self.teeth_union.buffer(2.5 / k)
        return self._wide[k]

    def outlines_clear(self, k: float):
        if k not in self._outl:
            g = unary_union([t.exterior for t in self.teeth]).buffer(CLEAR / k)
            shapely.prepare(g)
            self._outl[k] = g
        return self._outl[k]


#: Segments per quarter of a circle where the placement needs a circle as a line (at 64 the chords
#: stay within 0,008 % of the radius of the circle: a hundredth of a millimetre on these wheels).
RING_QUAD_SEGS = 64


def _grown(poly, d: float) -> Polygon:
    """A text's box grown by ``d`` on every side (square corners: a little more than a buffer,
    and far cheaper)."""
    x0, y0, x1, y1 = poly.bounds
    return box(x0 - d, y0 - d, x1 + d, y1 + d)


def _glyphs(poly) -> Polygon:
    """The middle of a text's box that the drawn letters fill (GLYPHS of its width and height:
    the box is estimated wide and holds the note's size; the sheet's letters are smaller): a
    line across it crosses the letters."""
    x0, y0, x1, y1 = poly.bounds
    dx, dy = (x1 - x0) * (1 - GLYPHS) / 2, (y1 - y0) * (1 - GLYPHS) / 2
    return box(x0 + dx, y0 + dy, x1 - dx, y1 - dy)


#: The share of a text's box (width and height) its letters fill, as either drawing writes them.
GLYPHS = 0.8


def _bounds(poly) -> tuple[float, float, float, float]:
    x0, y0, x1, y1 = poly.bounds
    return (float(x0), float(y0), float(x1), float(y1))


def _beside(placer: _Placer, name: str, text: str, tex: str, p: Point, height: float,
            prefer_deg: float, own_radius: float = 0.0) -> Mark:
    """A letter beside its point: 16 directions from ``prefer_deg``, at growing distances (sheet
    mm; the nearest is CLEAR of the page off the point, as the teeth's outlines pass through the
    pole); the box may stand inside a tooth, never across a tooth's outline or a drawn line (the
    pole and the ends of ab lie among the teeth: a letter on a leader there piled leaders round P,
    issue 12). Where no such place is near, on a short leader that may cross the teeth within
    ``own_radius`` of the point; where none is free either, the nearest place beside it that
    crosses the fewest lines."""
    k, u = placer.k, placer.unit
    w, h = (v / k for v in text_size(text, height))
    near = (CLEAR + 0.3) / k
    best = None
    order = [prefer_deg + s * i * 22.5 for i in range(9) for s in ((1, -1) if i else (1,))][:16]
    for dist in sorted({max(near, d / u) for d in BESIDE_POINT_MM}):
        for ang in order:
            ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
            t = min((w / 2) / abs(ux) if abs(ux) > ABS_ZERO else math.inf,
                    (h / 2) / abs(uy) if abs(uy) > ABS_ZERO else math.inf)
            c = (p[0] + ux * (t + dist), p[1] + uy * (t + dist))
            poly = _box_at(c, w, h)
            if not placer.free(poly, inside_teeth=True):
                continue
            score = placer.crossings(_grown(poly, LINE_CLEAR / k))
            if best is None or score < best[0]:
                best = (score, poly)
            if score == 0:
                break
        if best is not None and best[0] == 0:
            break
    if best is None or best[0] > 0:        # no clear place beside it: on a leader
        dirs = [prefer_deg + s_ * i * 11.25 for i in range(17) for s_ in ((1, -1) if i else (1,))][:32]
        mark = _leader_mark(placer, name, text, tex, [p], dirs, height,
                            own=SPoint(p).buffer(own_radius) if own_radius else None, last_resort=best is None,
                            inside_teeth=True, long=True)
        if mark is not None:
            return mark
        assert best is not None
    placer.take(best[1])
    return Mark(name, text, tex, (float(p[0]), float(p[1])), (), _bounds(best[1]),
                height)


#: A letter beside its point keeps this far (paper mm) off the drawn lines: a letter's foot on a
#: line reads as crossed (the sheet writes it at its box's edge nearest the point).
LINE_CLEAR = 0.4
#: The distances (sheet mm) tried between a point and its letter's box, nearest first.
BESIDE_POINT_MM = (1.0, 2.5, 4.0, 6.0)


#: The slanted part of a leader, sheet mm, shortest first (the note's figure draws it reduced).
LEADER_LENGTHS = (6.0, 9.0, 12.0, 16.0, 21.0, 27.0)
#: No leader's slanted part is longer than this on the sheet (mm) where one of LEADER_LENGTHS is
#: free (every example's pair: tests/scenes/test_meshing_lettering.py); a small module crowds the
#: picture, and a leader may then be one of LONG_LEADERS.
LEADER_MAX_MM = LEADER_LENGTHS[-1]
LONG_LEADERS = (34.0, 42.0, 52.0, 64.0)
#: A leader is taken at once when its text is crossed by no line and its slanted part and shelf
#: by at most two (lines across the text, lines across the leader). Lines across the text count
#: twice through its letters (:data:`GLYPHS`), once through the box's margin only: a text whose
#: box's margin alone is crossed (1) still reads clear (the box holds the note's text with room).
GOOD_LEADER = (0, 2)


def _on_leader(placer: _Placer, name: str, text: str, tex: str, anchors: list[Point],
               directions: list[float], height: float, word: bool = False,
               lengths: tuple[float, ...] = LEADER_LENGTHS, own=None, inside_teeth: bool = False) -> Mark:
    """:func:`_leader_mark` with its last resort: always a mark."""
    mark = _leader_mark(placer, name, text, tex, anchors, directions, height, word, lengths, own,
                        inside_teeth=inside_teeth)
    assert mark is not None
    return mark


def _leader_mark(placer: _Placer, name: str, text: str, tex: str, anchors: list[Point],
                 directions: list[float], height: float, word: bool = False,
                 lengths: tuple[float, ...] = LEADER_LENGTHS, own=None, last_resort: bool = True,
                 inside_teeth: bool = False, long: bool = False) -> Mark | None:
    """A designation on a leader: from one of ``anchors`` (in order of preference) a slanted line of
    one of ``lengths`` (sheet mm: :attr:`_Placer.unit`) in one of ``directions`` (degrees), then a
    shelf under the text. The shortest leader wins whose text and line are free and cross the
    fewest drawn lines (ties: the earlier anchor and direction). ``own``: the region (a tooth, the
    teeth round the pole) the leader may cross to reach its anchor; nowhere does it cross another
    text or leader (issue 12: αw's leader crossed b's near the pole); with ``last_resort`` or
    ``long``, where none of ``lengths`` is free, one of LONG_LEADERS. A text crossed by a drawn line
    is the last choice, whatever its leader crosses (issue 12: a circle's arc through «a» and «αw»
    at the pole, taken for a leader that crossed one line fewer); without ``last_resort`` only
    such candidates give None. ``inside_teeth``: the text
    and the leader may stand inside a tooth, across no outline (s on its tooth: a leader out of
    the teeth's band was 20–50 mm long on the sheet). Where nothing is free: the first candidate
    (``last_resort``; a test reports it), else None."""
    k, u = placer.k, placer.unit
    w, h = (v / k for v in text_size(text, height))
    rad = np.radians(np.asarray(directions, dtype=float))
    ux, uy = np.cos(rad), np.sin(rad)
    sx = np.where(ux >= 0, 1.0, -1.0)                     # the shelf to the right or to the left
    best = None
    for L in tuple(lengths) + (LONG_LEADERS if last_resort or long else ()):
        if L > max(lengths) and best is not None and best[0][0] <= 1:
            break           # a short leader with its text clear beats a long one crossing less
        for anchor in anchors:
            # every direction at once (shapely's arrays): the candidates' boxes and leaders
            ex, ey = anchor[0] + ux * L / u, anchor[1] + uy * L / u
            endx = ex + sx * w
            x0 = np.minimum(ex, endx)
            polys = shapely.box(x0, ey + 0.6 / k, x0 + w, ey + 0.6 / k + h)
            sxy = np.stack([anchor[0] + ux * 1.2 / u, anchor[1] + uy * 1.2 / u], axis=1)
            mid = np.stack([ex, ey], axis=1)
            far = np.stack([endx, ey], axis=1)
            wholes = shapely.linestrings(np.stack([sxy, mid, far], axis=1))
            probes = wholes if own is None else shapely.difference(wholes, own)
            ok = placer.free_many(polys, probes, wholes, inside_teeth=inside_teeth)
            if not ok.any():
                continue
            idx = np.flatnonzero(ok)
            g = polys[idx]
            b = shapely.bounds(g)
            dx, dy = (b[:, 2] - b[:, 0]) * (1 - GLYPHS) / 2, (b[:, 3] - b[:, 1]) * (1 - GLYPHS) / 2
            glyphs = shapely.box(b[:, 0] + dx, b[:, 1] + dy, b[:, 2] - dx, b[:, 3] - dy)
            # (lines across the text, lines across the leader): a text crossed by a line is never
            # traded for a leader crossing fewer (issue 12: an arc through «a» and «αw» near P)
            crossed = placer.crossings_many(glyphs) * 2 + placer.crossings_many(g)
            on_leader = placer.crossings_many(probes[idx])
            for j, c_text, c_leader in zip(idx, crossed, on_leader):
                score = (int(c_text), int(c_leader))
                if best is None or score < best[0]:
                    leader = LineString([anchor, tuple(mid[j]), tuple(far[j])])
                    best = (score, polys[j], leader, anchor)
                if score <= GOOD_LEADER:
                    break
            if best is not None and best[0] <= GOOD_LEADER:
                break
        if best is not None and best[0] <= GOOD_LEADER:
            break
    if best is not None and best[0][0] > 1 and not last_resort:
        return None             # only crossed texts: the caller has another way (beside, another wedge)
    if best is None and not last_resort:
        return None
    if best is None:        # no free place: the first candidate (a test reports it)
        anchor, ang = anchors[0], directions[0]
        ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
        elbow = (anchor[0] + ux * lengths[-1] / u, anchor[1] + uy * lengths[-1] / u)
        end = (elbow[0] + (w if ux >= 0 else -w), elbow[1])
        x0 = min(elbow[0], end[0])
        best = ((0, 0), box(x0, elbow[1] + 0.6 / k, x0 + w, elbow[1] + 0.6 / k + h),
                LineString([anchor, elbow, end]), anchor)
    _, poly, leader, anchor = best
    placer.take(poly)
    placer.take(leader.buffer(0.3 / k), text=False)
    return Mark(name, text, tex, (float(anchor[0]), float(anchor[1])),
                tuple((float(x), float(y)) for x, y in leader.coords),
                _bounds(poly), height, word)


def _beside_arc(placer: _Placer, name: str, text: str, tex: str, ring, anchors: list[Point],
                centre: Point, height: float) -> Mark | None:
    """A circle's designation beside its arc, without a leader (as drawn by hand where there is
    room): the box BESIDE_MM (sheet mm) off the circle at one of ``anchors``, outside or inside
    it, crossing no drawn line, and no other line nearer than BESIDE_CLEAR_MM — read as the
    name of this circle and no other. None where no such place is free."""
    k, u = placer.k, placer.unit
    w, h = (v / k for v in text_size(text, height))
    for q in anchors:
        d = math.dist(q, centre)
        nx, ny = (q[0] - centre[0]) / d, (q[1] - centre[1]) / d
        ext = abs(nx) * w / 2 + abs(ny) * h / 2
        for side in (1.0, -1.0):
            off = BESIDE_MM / u + ext
            c = (q[0] + side * nx * off, q[1] + side * ny * off)
            poly = _box_at(c, w, h)
            if poly.intersects(ring) or not placer.free(poly):
                continue
            if placer.crossings(_grown(poly, max(BESIDE_CLEAR_MM / u, BESIDE_CLEAR_PAGE_MM / k)), but=ring):
                continue
            placer.take(poly)
            return Mark(name, text, tex, (float(q[0]), float(q[1])), (), _bounds(poly), height)
    return None


def _beside_angle(placer: _Placer, centre: Point, radius: float, lo: float, hi: float,
                  height: float) -> Mark | None:
    """αw inside its angle (from ``lo`` to ``hi``, radians, at ``centre``) just beyond its arc of
    ``radius``, crossing no line: None where the angle is too narrow there."""
    k, u = placer.k, placer.unit
    w, h = (v / k for v in text_size("αw", height))
    mid = (lo + hi) / 2
    ux, uy = math.cos(mid), math.sin(mid)
    for extra in (1.0, 3.0, 6.0):
        t = radius + extra / u + abs(ux) * w / 2 + abs(uy) * h / 2
        c = (centre[0] + ux * t, centre[1] + uy * t)
        poly = _box_at(c, w, h)
        if placer.free(poly, inside_teeth=True) and placer.crossings(poly) == 0:
            placer.take(poly)
            tip = (centre[0] + radius * ux, centre[1] + radius * uy)
            return Mark("alpha_w", "αw", "\\alpha_{w}", (float(tip[0]), float(tip[1])), (), _bounds(poly), height)
    return None


#: The radius of the arc of αw at the pole, sheet mm.
ALPHA_ARC_MM = 18.0
#: A circle's designation beside its arc: this far off it (sheet mm), and no other line nearer
#: than BESIDE_CLEAR_MM to the text.
BESIDE_MM = 1.0
BESIDE_CLEAR_MM = 2.5
#: ... and no nearer than this on the note's page (mm), where the circles stand closer.
BESIDE_CLEAR_PAGE_MM = 1.5


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
             zone_k: float | None = None, shared: "_Shared | None" = None) -> PlacedDimension | None:
    """The dimension aw (O1O2) at scale ``k`` in ``room`` (real mm), clear of the teeth and the
    zones only: placed before the designations, which keep clear of it (None when O1 or O2 is
    outside the room)."""
    inside = box(*room)
    if not (inside.contains(SPoint(pic.points["O1"])) and inside.contains(SPoint(pic.points["O2"]))):
        return None
    marks = place_marks(pair, pic, k, room, zone_k=zone_k, shared=shared,
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
    cross no tooth and no placed text (the lines: where some offset allows it); ``prefer_clear``: among those, the first whose text crosses
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
        # its lines across a designation placed before (a letter at a or b, αw): the last choice
        if any(ln.intersects(t) for ln in (LineString([p1, q1]), LineString([p2, q2]), LineString([q1, q2]))
               for t in placer.texts):
            rank += 10**5
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


def _circle_anchors(ring, window: Polygon, teeth: Polygon, centre: Point, r: float, gear: int,
                    k: float, fractions: tuple[float, ...] = (0.15, 0.5, 0.85)) -> list[Point]:
    """Points of a drawn arc (``ring`` cut by ``window``) outside ``teeth`` (widened by 2,5 paper
    mm: :meth:`_Shared.teeth_wide`), farthest from the pole first (where the arcs are
    uncrowded)."""
    free = ring.intersection(window).difference(teeth)
    pts: list[Point] = []
    geoms = getattr(free, "geoms", [free])
    for g in geoms:
        if g.is_empty or g.length < 3.0 / k:
            continue
        for f in fractions:
            p = g.interpolate(f, normalized=True)
            pts.append((p.x, p.y))
    pts.sort(key=lambda p: -abs(p[0]))
    return pts or [(centre[0], centre[1] + (r if gear == 1 else -r))]


def place_marks(pair, pic: MeshingPicture, k: float,
                room: tuple[float, float, float, float] | None = None, *,
                point_h: float = POINT_H, mark_h: float = MARK_H, dim_h: float = DIM_H,
                keep_out: tuple[tuple[float, float, float, float], ...] = (),
                zone_k: float | None = None, given: MeshingMarks | None = None,
                skip: frozenset[str] = frozenset(), unit: float | None = None,
                shared: _Shared | None = None, lines_drawn: tuple[PlacedDimension, ...] = ()) -> MeshingMarks:
    """Every designation of the meshing picture at scale ``k`` (paper mm per real mm) inside
    ``room`` (real mm; default: the picture's bounds with the centres, widened by 60 paper mm);
    letters ``point_h``, designations ``mark_h`` and the dimensions' texts ``dim_h`` paper mm
    high; ``keep_out`` boxes (real mm) hold other things (a legend, a scale bar). The zones of
    one and two pairs and their numerals (drawn at ``zone_k``, the sheet's scale; default ``k``)
    are kept clear. ``unit``: paper mm per real mm of the leaders' lengths and the letters'
    distances (the sheet's scale; default ``k``); ``shared``: the picture's geometry computed
    once for every placement (:class:`_Shared`); ``lines_drawn``: dimensions placed apart (aw)
    whose lines the texts keep off.

    Order (the most constrained first): the points' letters beside their points, the dimension
    ab, αw, s1, p, s2, then the circles' designations — beside their arcs where there is room,
    else on the shortest free leader.

    ``given``: designations placed already (the note's window, at the note's letter size:
    :func:`reportgen.scenes.meshing.meshing_marks`); only what they lack is placed (the points
    and the dimension aw outside that window), clear of them, and the result holds both, at the
    scale ``k`` (the given dimensions' offsets converted to it). ``skip``: names not to place
    (placed apart: the dimension aw, :func:`place_aw`)."""
    g = pair.geometry
    zone_k = zone_k if zone_k is not None else k
    shared = shared if shared is not None else _Shared(pic)
    teeth = shared.teeth
    aw_box = arcs_window(pair, pic)
    window = box(*aw_box)
    if room is None:
        x0, y0, x1, y1 = pic.view
        pad = 60.0 / k
        room = (min(x0, 0.0) - pad, min(y0, 0.0) - pad, max(x1, 0.0) + pad, max(y1, g.aw) + pad)
    lines = []
    rings = {}
    for c in pic.circles:
        part = shared.rings[c.name].intersection(window)
        if not part.is_empty:
            lines.append(part)
            rings[c.name] = part
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
    lines += [ln for d in lines_drawn for ln in dimension_lines(d, zone_k)]
    placer = _Placer(k, teeth, lines, box(*room), unit=unit, shared=shared)
    placer.teeth = placer.teeth.union(zone_band)
    placer._outlines = placer.outlines.union(zone_band)
    shapely.prepare(placer.teeth)
    shapely.prepare(placer._outlines)
    numerals = zone_numerals(pic, zone_k, lines + [t.exterior for t in teeth])
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
                placer.take(LineString(m.leader).buffer(0.3 / k), text=False)
        for d in given.dimensions:
            placer.take(Polygon(d.box))
        done = {m.name for m in given.marks} | {d.name for d in given.dimensions}
        marks = list(given.marks)
        dims = [replace(d, offset_mm=d.offset_mm * k / given.k) for d in given.dimensions]
    teeth_wide = shared.teeth_wide(k)
    # 1. the letters of the points, and αw after P's
    prefer = {"O1": 0, "O2": 0, "P": 30, "N1": 200, "N2": 20, "a": 150, "b": -30}
    inside = box(*room)

    def place_alpha() -> AngleMark:
        # αw between the common tangent at P and the line of action: right of P (towards N2) or
        # in the vertical angle left of it (towards N1; the zones' band lies right of P below N1N2),
        # wherever its name stands nearer: beside the arc inside the angle, else on the shorter leader
        ang_r = ALPHA_ARC_MM / zone_k
        a_w = math.atan2(n2[1] - P[1], n2[0] - P[0])
        wedges = [(0.0, a_w), (math.pi, math.pi + a_w)]
        own_p = SPoint(P).buffer(max(ang_r + 2.0 / zone_k, 2.4 * g.m))
        alpha: tuple[Mark, AngleMark] | None = None
        for lo, hi in wedges:
            m = _beside_angle(placer, P, ang_r, lo, hi, mark_h)
            if m is not None:
                alpha = (m, AngleMark(P, ang_r, lo, hi))
                break
        for L in (LEADER_LENGTHS if alpha is None else ()):
            for lo, hi in wedges:
                mid = (lo + hi) / 2
                tip = (P[0] + ang_r * math.cos(mid), P[1] + ang_r * math.sin(mid))
                d0 = math.degrees(mid)
                dirs = [d0 + sgn * v for v in range(0, 181, 15) for sgn in ((1, -1) if 0 < v < 180 else (1,))]
                m = _leader_mark(placer, "alpha_w", "αw", "\\alpha_{w}", [tip], dirs, mark_h, lengths=(L,), own=own_p,
                                 last_resort=L == LEADER_LENGTHS[-1] and lo > 0.0, inside_teeth=True)
                if m is not None:
                    alpha = (m, AngleMark(P, ang_r, lo, hi))
                    break
            if alpha is not None:
                break
        assert alpha is not None
        marks.append(alpha[0])
        placer.add_lines([LineString(alpha[1].points())])
        return alpha[1]

    angle = AngleMark(P, 0.0, 0.0, 0.0)
    for name in ("P", "a", "b", "N1", "N2", "O1", "O2"):
        pt = pic.points[name]
        if name in done or name in skip or not inside.contains(SPoint(pt)):
            continue
        marks.append(_beside(placer, name, name, f"{name[0]}_{{{name[1:]}}}" if len(name) > 1 else name,
                             pt, point_h, prefer[name], own_radius=2.4 * g.m))
        if name == "b" and given is None:      # αw next: the pole's other name, after P, a and b
            angle = place_alpha()
    if given is None and angle.radius == 0.0:
        angle = place_alpha()
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
    placer.add_lines([ln for d in dims for ln in dimension_lines(d, k)])
    # 4. s1 on gear 1's tooth right of the central one, s2 on gear 2's tooth left of it, p across
    # one pitch of gear 1 from the central tooth's left flank to the left tooth's: the three
    # away from the pole, each named from a point of its arc farthest from P that has room
    arcs = []

    def pitch_arc(tooth: Polygon, r: float, centre: Point) -> tuple[float, float] | None:
        ring = SPoint(centre).buffer(r, 4 * RING_QUAD_SEGS).exterior
        cut = ring.intersection(tooth)
        if cut.is_empty:
            return None
        seg = max(getattr(cut, "geoms", [cut]), key=lambda s: s.length)
        a_s = [math.atan2(y - centre[1], x - centre[0]) for x, y in (seg.coords[0], seg.coords[-1])]
        return min(a_s), max(a_s)

    def arc_anchors(centre: Point, r: float, a0: float, a1: float) -> list[Point]:
        pts = [(centre[0] + r * math.cos(a0 + f * (a1 - a0)), centre[1] + r * math.sin(a0 + f * (a1 - a0)))
               for f in (0.5, 0.3, 0.7)]
        return sorted(pts, key=lambda q: -math.dist(q, P))

    by_x = [sorted(ts, key=lambda t: float(np.mean(np.asarray(t)[:, 0]))) for ts in (pic.teeth1, pic.teeth2)]
    for gear, r, centre in ((1, g.d1 / 2, (0.0, 0.0)), (2, g.d2 / 2, (0.0, g.aw))):
        ts = by_x[gear - 1]
        tooth = Polygon(np.asarray(ts[-1] if gear == 1 else ts[0])).buffer(0)
        span = pitch_arc(tooth, r, centre)
        if span is None:
            continue
        a0, a1 = span
        arcs.append(ArcMark(f"s{gear}", centre, r, a0, a1))
        dirs = ([300.0, 330.0, 270.0, 0.0, 240.0, 210.0, 180.0, 30.0] if gear == 1
                else [120.0, 150.0, 90.0, 180.0, 60.0, 30.0, 0.0, 210.0])
        dirs += [d for d in (d0 + 15.0 for d0 in dirs) if d % 360.0 not in dirs]
        marks.append(_on_leader(placer, f"s{gear}", f"s{gear}", f"s_{{{gear}}}", arc_anchors(centre, r, a0, a1),
                                dirs, mark_h, own=tooth.buffer(2 * CLEAR / k), inside_teeth=True))
    ts = by_x[0]
    central = min(ts, key=lambda t: abs(float(np.mean(np.asarray(t)[:, 0]))))
    span = pitch_arc(Polygon(np.asarray(central)).buffer(0), g.d1 / 2, (0.0, 0.0))
    if span is not None:
        # one angular pitch on the pitch circle from the central tooth's left flank
        r, step = g.d1 / 2, 2 * math.pi / g.z1
        p_arc = ArcMark("p", (0.0, 0.0), r, span[1], span[1] + step)
        arcs.append(p_arc)
        pm = arc_anchors((0.0, 0.0), r, p_arc.a0, p_arc.a1)
        marks.append(_on_leader(placer, "p", "p", "p", pm, [240.0, 210.0, 270.0, 180.0, 150.0, 300.0, 120.0, 90.0,
                                                            330.0, 60.0],
                                mark_h, own=SPoint(pm[0]).buffer(2.4 * g.m), inside_teeth=True))
    # 5. the circles: beside the arc where there is room, else on a leader (gear 1, below: down
    # and to the left first; gear 2, above: up and to the right)
    order = {"tip": 0, "root": 1, "pitch": 2, "working": 3, "base": 4}
    for c in sorted(pic.circles, key=lambda c: (c.gear, order[c.kind])):
        base_name = {"pitch": "r", "base": "rb", "working": "rw", "tip": "ra", "root": "rf"}[c.kind]
        sub = {"pitch": "", "base": "b", "working": "w", "tip": "a", "root": "f"}[c.kind]
        tex = f"r_{{{sub}{c.gear}}}"
        ring = shared.rings[c.name]
        anchors = _circle_anchors(ring, window, teeth_wide, c.centre, c.radius, c.gear, k,
                                  fractions=(0.05, 0.15, 0.3, 0.5, 0.7, 0.85, 0.95))
        anchors = [q for q in anchors if inside.contains(SPoint(q))] or anchors
        mark = _beside_arc(placer, c.name, f"{base_name}{c.gear}", tex, rings.get(c.name, ring), anchors,
                           c.centre, mark_h)
        if mark is None:
            if c.gear == 1:
                dirs = [225.0, 200.0, 250.0, 315.0, 135.0, 160.0, 270.0, 180.0]
            else:
                dirs = [45.0, 20.0, 70.0, 135.0, 315.0, 340.0, 90.0, 0.0]
            dirs += [d for d in (d0 + 180.0 for d0 in dirs) if d % 360.0 not in dirs]
            mark = _on_leader(placer, c.name, f"{base_name}{c.gear}", tex, anchors, dirs, mark_h)
        marks.append(mark)
    return MeshingMarks(k=k, marks=tuple(marks), arcs=tuple(arcs), angle=angle,
                        dimensions=tuple(dims), arcs_window=aw_box, zones=numerals)


def dimension_lines(d: PlacedDimension, k: float) -> list[LineString]:
    """The dimension line and the two extension lines of ``d`` (real mm) as drawn at ``k``."""
    L = math.dist(d.p1, d.p2)
    nx, ny = -(d.p2[1] - d.p1[1]) / L, (d.p2[0] - d.p1[0]) / L
    off = d.offset_mm / k
    q1 = (d.p1[0] + nx * off, d.p1[1] + ny * off)
    q2 = (d.p2[0] + nx * off, d.p2[1] + ny * off)
    return [LineString([d.p1, q1]), LineString([d.p2, q2]), LineString([q1, q2])]
