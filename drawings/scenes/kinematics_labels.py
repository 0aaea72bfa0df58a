"""Labels with indices for sheet 1: «aⁿBA», «s₂», «H1», drawn as several TEXT entities (a base, a
raised superscript and a lowered subscript of the next smaller ГОСТ size), placed where they
overlap no text and cross no drawn line."""
from __future__ import annotations

import math
import re
from typing import Callable, Sequence, TypeAlias

import shapely
from shapely.geometry import Polygon, box
from shapely.geometry.base import BaseGeometry

from drawings import style
from drawings.primitives import Canvas, LabelRecord, descent

from reportgen.geometry import Vec2 as Vec
from reportgen.tolerances import ABS_ZERO, AREA_EPS_MM2, MM_ROUNDOFF

from drawings.lettering import Rich, flatten as _flatten, from_tex  # noqa: F401  (one home: drawings/lettering.py)


def _smaller(height: float) -> float:
    sizes = [h for h in style.TEXT_HEIGHTS if h < height - MM_ROUNDOFF]
    return sizes[-1] if sizes else height


def from_letter(key: str, helpers: bool = False) -> Rich:
    """A plan letter: ``s2`` → s₂, ``a3`` → a₃; a helper point (``nba``, ``ka3``) → n_ba, k_a3."""
    if helpers and len(key) > 1:
        return Rich(key[0], "", key[1:])
    m = re.match(r"^(\D+)(\d+)$", key)
    if m:
        return Rich(m.group(1), "", m.group(2))
    return Rich(key)


Label = Rich | tuple[Rich, ...]
#: What a label names: a geometry (sheet mm), a function of the label's letters (their boxes,
#: :func:`text_extent`) giving it, or None.
Names: TypeAlias = "BaseGeometry | Callable[[BaseGeometry], BaseGeometry] | None"
SEPARATOR = ", "
#: What a separator takes on the sheet: the comma's own cell (ГОСТ type B, like the measuring font,
#: gives a comma a letter's advance, most of it blank after the comma: the space a reader needs) —
#: «π, o, c» five cells wide, not seven (issue 12: the shaper's pole letters found no room).
SEPARATOR_ADVANCE = ","


def _items(label: Label) -> tuple[Rich, ...]:
    return (label,) if isinstance(label, Rich) else tuple(label)


def _one_width(rich: Rich, height: float) -> float:
    small = _smaller(height)
    extra = max(style.text_width(rich.sup, small) if rich.sup else 0.0,
                style.text_width(rich.sub, small) if rich.sub else 0.0)
    return style.text_width(rich.base, height) + extra


def size(label: Label, height: float) -> tuple[float, float, float]:
    """Width, depth below the baseline, rise above the base's top (sheet mm)."""
    items = _items(label)
    small = _smaller(height)
    w = sum(_one_width(r, height) for r in items)
    w += style.text_width(SEPARATOR_ADVANCE, height) * (len(items) - 1)
    depth = max(0.35 * height if any(r.sub for r in items) else 0.0,      # the separators' commas descend too
                descent("".join(r.base for r in items) + (SEPARATOR if len(items) > 1 else ""), height))
    rise = max(0.0, 0.45 * height + small - height) if any(r.sup for r in items) else 0.0
    return w, depth, rise


def rich_box(label: Label, center: Vec, height: float, pad: float = 0.5) -> Polygon:
    w, depth, rise = size(label, height)
    x0 = center[0] - w / 2
    y0 = center[1] - height / 2
    return box(x0 - pad, y0 - depth - pad, x0 + w + pad, y0 + height + rise + pad)


def label_name(label: Label) -> str:
    return SEPARATOR.join(r.base + (f"^{r.sup}" if r.sup else "") + (f"_{r.sub}" if r.sub else "")
                          for r in _items(label))


def draw_rich(canvas: Canvas, center: Vec, label: Label, height: float,
              names: Names = None) -> Polygon:
    """Draw ``label`` centred (its base line) at a sheet point; returns its box (registered once).
    ``names``: what it is the label of (sheet mm; or a function of the label's box giving it),
    recorded with the handles of its texts."""
    small = _smaller(height)
    handles: list[str] = []
    w, _, _ = size(label, height)
    x = center[0] - w / 2
    y0 = center[1] - height / 2
    for k, rich in enumerate(_items(label)):
        if k:
            canvas.text_mm((x, y0), SEPARATOR.strip(), height, register=False)
            handles.append(canvas.last_text_handle)
            x += style.text_width(SEPARATOR_ADVANCE, height)
        canvas.text_mm((x, y0), rich.base, height, register=False)
        handles.append(canvas.last_text_handle)
        xb = x + style.text_width(rich.base, height)
        if rich.sup:
            canvas.text_mm((xb, y0 + 0.45 * height), rich.sup, small, register=False)
            handles.append(canvas.last_text_handle)
        if rich.sub:
            canvas.text_mm((xb, y0 - 0.35 * height), rich.sub, small, register=False)
            handles.append(canvas.last_text_handle)
        x += _one_width(rich, height)
    poly = rich_box(label, center, height)
    # a function of where its letters went (a leader touches a letter, not the gap between two)
    named = names(text_extent(label, center, height)) if callable(names) else names
    if named is not None:
        canvas.annotations.add_label(LabelRecord(label_name(label), tuple(handles), named, canvas.name))
    canvas.annotations.add_box(f"{canvas.name}: «{label_name(label)}»", poly)
    return poly


def place_rich(canvas: Canvas, candidates: Sequence[Vec], label: Label, height: float,
               inside: Polygon | None = None, optional: bool = False,
               names: Names = None, avoid: BaseGeometry | None = None) -> Polygon | None:
    """Draw ``label`` at the first candidate centre (sheet mm) whose box overlaps no text and
    crosses no line (and lies ``inside``), else at the one with the fewest conflicts; an
    ``optional`` label that would overlap a text (or leave ``inside``) is not drawn. ``avoid``:
    lines a label never crosses where any candidate keeps off them (a scheme's links), counted as
    leaving ``inside``."""
    return place_passes(canvas, [(candidates, 0)], label, height, inside, optional, names, avoid)


def place_passes(canvas: Canvas, passes: Sequence[tuple[Sequence[Vec], int]], label: Label,
                 height: float, inside: Polygon | None = None, optional: bool = False,
                 names: Names = None, avoid: BaseGeometry | None = None,
                 strict: bool = False, clear: tuple[float, float] = (0.0, 0.0)) -> Polygon | None:
    """Like :func:`place_rich` over several passes of (candidates, lines it may cross): the first
    candidate of the first pass that overlaps no text, stays ``inside`` (and off ``avoid``) and
    crosses at most that many lines wins; otherwise the candidate with the fewest conflicts over
    all passes (``strict``: none, the label is not drawn — the caller tries a leader next).
    ``clear``: (from texts, from lines) the room (mm) a label keeps beyond its box's padding — a
    clear gap between two names, so that «A» and «2» do not read as «A 2» (issue 12; default none)."""
    boxes = [b for _, b in canvas.annotations.boxes]
    tree = shapely.STRtree(boxes) if boxes else None

    def hits(poly: Polygon) -> int:
        if tree is None:
            return 0
        return sum(1 for j in tree.query(poly) if poly.intersection(boxes[j]).area > AREA_EPS_MM2)

    best: tuple[tuple[int, int, int, int], Vec] | None = None
    rank = 0
    for candidates, tolerate in passes:
        for c in candidates:
            poly = rich_box(label, c, height)
            out = 0 if (inside is None or inside.contains(poly)) and (avoid is None or not avoid.intersects(poly)) else 1
            h = hits(rich_box(label, c, height, 0.5 + clear[0]) if clear[0] else poly)
            crossings = canvas.annotations.crossings(rich_box(label, c, height, 0.5 + clear[1]) if clear[1] else poly) \
                if out == 0 and h == 0 else 99
            if out == 0 and h == 0 and crossings <= tolerate:
                return draw_rich(canvas, c, label, height, names)
            score = (out, h, crossings, rank)
            rank += 1
            if best is None or score < best[0]:
                best = (score, c)
    if best is None or strict or (optional and best[0][:2] != (0, 0)):
        return None
    return draw_rich(canvas, best[1], label, height, names)


def leader_foot(letters: BaseGeometry, p: Vec) -> Vec:
    """Where a leader from the point ``p`` meets the label's ``letters`` (:func:`text_extent`, or a
    box): their nearest point."""
    from shapely.geometry import Point
    from shapely.ops import nearest_points
    q = nearest_points(letters, Point(p))[0]
    return (q.x, q.y)


def spread_around(p: Vec, reach: float, step: float = 2.0) -> list[Vec]:
    """Candidate centres on a square grid of ``step`` mm round ``p`` out to ``reach`` mm, nearest
    first: where the rings of :func:`around` find no free spot in a crowded cluster, the nearest
    free one farther off (for a label on a leader)."""
    n = int(reach / step)
    pts = [(p[0] + i * step, p[1] + j * step) for i in range(-n, n + 1) for j in range(-n, n + 1)
           if 0 < math.hypot(i, j) * step <= reach]
    return sorted(pts, key=lambda q: (round(math.dist(q, p), 6), q))


#: A leader stops this short of the point (or the vector) it names when the lines it crosses are
#: counted: the vectors that meet there are its own point's, not lines it crosses.
LEADER_GAP_MM = 0.8
#: The step (mm) of the grid over the whole region tried last (:func:`place_on_leader`, ``anywhere``).
ANYWHERE_STEP_MM = 2.5


def region_grid(p: Vec, region: Polygon, step: float = ANYWHERE_STEP_MM) -> list[Vec]:
    """Candidate centres on a square grid of ``step`` mm through ``p`` over the bounds of
    ``region``, nearest to ``p`` first: the last places a label on a leader is tried at, where
    the rings round its point are all taken — a free spot anywhere in the view beats a crossed
    label (issue 12: the shaper's «π, o, c» under a^r)."""
    x0, y0, x1, y1 = region.bounds
    i0, i1 = math.floor((x0 - p[0]) / step), math.ceil((x1 - p[0]) / step)
    j0, j1 = math.floor((y0 - p[1]) / step), math.ceil((y1 - p[1]) / step)
    pts = [(p[0] + i * step, p[1] + j * step) for i in range(i0, i1 + 1) for j in range(j0, j1 + 1) if i or j]
    return sorted(pts, key=lambda q: (round(math.dist(q, p), 6), q))


def _leader_crossings(canvas: Canvas, leader: BaseGeometry) -> int:
    """How many drawn lines ``leader`` (from the letters to what it names) crosses on its way, its
    last ``LEADER_GAP_MM`` (at the point or vector it names, where that point's own lines meet)
    left out."""
    from shapely.geometry import LineString
    (ax, ay), (bx, by) = list(leader.coords)
    d = math.dist((ax, ay), (bx, by))
    if d <= LEADER_GAP_MM:
        return 0
    t = (d - LEADER_GAP_MM) / d
    return canvas.annotations.crossings(LineString([(ax, ay), (ax + (bx - ax) * t, ay + (by - ay) * t)]))


def place_on_leader(canvas: Canvas, p: Vec, candidates: Sequence[Vec], label: Label, height: float,
                    inside: Polygon | None = None, names: BaseGeometry | None = None,
                    to: BaseGeometry | None = None, anywhere: bool = False,
                    clear: tuple[float, float] = (0.0, 0.0), leader_uncrossed: bool = False,
                    leader_clear: bool = False) -> Polygon | None:
    """``label`` away from the point ``p`` (sheet mm) on a thin leader to it (or to the nearest point
    of ``to``, its vector): the first candidate centre whose box overlaps no text, crosses no drawn
    line and stays ``inside``, and whose leader crosses no text; the leader is drawn and kept as a
    line that later labels keep clear of. What the label names is the leader with ``names`` (its
    vector). ``anywhere`` (with ``inside``): where no candidate is free, the nearest free spot of
    the whole region (:func:`region_grid`) whose leader crosses the fewest drawn lines. None where
    no spot is free. ``leader_uncrossed`` (the lever's crowded clusters, issue 12): a candidate whose
    leader crosses or runs along a drawn line (another vector, a leader drawn before) is taken only
    where no candidate's leader is clear; a leader along another force's arrow reads as naming it.
    ``leader_clear``: only such a candidate is taken (None where there is none)."""
    from shapely.geometry import LineString, Point
    from shapely.ops import nearest_points
    boxes = [b for _, b in canvas.annotations.boxes]
    tree = shapely.STRtree(boxes) if boxes else None

    def free(c: Vec) -> tuple[Vec, Vec] | None:
        """The leader (foot at the letters, end at the point) of a label centred at ``c``, if its
        box and its leader are free."""
        poly = rich_box(label, c, height)
        if inside is not None and not inside.contains(poly):
            return None
        wide = rich_box(label, c, height, 0.5 + clear[0]) if clear[0] else poly
        if tree is not None and any(wide.intersection(boxes[j]).area > AREA_EPS_MM2 for j in tree.query(wide)):
            return None
        if canvas.annotations.crossings(rich_box(label, c, height, 0.5 + clear[1]) if clear[1] else poly):
            return None
        letters = text_extent(label, c, height)          # the leader touches a letter, not a gap
        q0, q1 = nearest_points(letters, Point(p) if to is None else to)
        foot, end = (q0.x, q0.y), (p if to is None else (q1.x, q1.y))
        if math.dist(foot, end) < MM_ROUNDOFF:
            return None
        leader = LineString([foot, end])
        if tree is not None and any(leader.intersects(boxes[j]) for j in tree.query(leader)):
            return None
        return foot, end

    def draw(c: Vec, foot: Vec, end: Vec) -> Polygon:
        leader = LineString([foot, end])
        named = leader if names is None else leader.union(names)
        drawn = draw_rich(canvas, c, label, height, named)
        canvas.layout.add_line(foot, end, dxfattribs={"layer": "thin"})
        canvas.annotations.add_obstacle(leader)
        return drawn

    first: tuple[Vec, Vec, Vec] | None = None
    for c in candidates:
        found = free(c)
        if found is not None:
            if not (leader_uncrossed or leader_clear) or _leader_crossings(canvas, LineString(found)) == 0:
                return draw(c, *found)
            if leader_clear:
                continue
            if first is None:
                first = (c, *found)
    if leader_clear:
        return None
    if leader_uncrossed and anywhere and inside is not None:
        for c in region_grid(p, inside):
            found = free(c)
            if found is not None and _leader_crossings(canvas, LineString(found)) == 0:
                return draw(c, *found)
    if first is not None:
        return draw(*first)
    if not anywhere or inside is None:
        return None
    best: tuple[int, Vec, Vec, Vec] | None = None
    for c in region_grid(p, inside):
        found = free(c)
        if found is None:
            continue
        n = _leader_crossings(canvas, LineString(found))
        if n == 0:
            return draw(c, *found)
        if best is None or n < best[0]:
            best = (n, c, *found)
    return draw(best[1], best[2], best[3]) if best is not None else None


def around(p: Vec, rich: Label, height: float, prefer_deg: float = 45.0,
           gaps: Sequence[float] = (1.0, 3.0, 6.0, 10.0)) -> list[Vec]:
    """Candidate centres around a sheet point in 16 directions from ``prefer_deg``, at several gaps."""
    w, depth, rise = size(rich, height)
    hw, hh = w / 2 + 0.5, (height + depth + rise) / 2 + 0.5
    out = []
    order = [prefer_deg + s * k * 22.5 for k in range(9) for s in ((1, -1) if k else (1,))][:16]
    for gap in gaps:
        for ang in order:
            ux, uy = math.cos(math.radians(ang)), math.sin(math.radians(ang))
            t = min(hw / abs(ux) if abs(ux) > ABS_ZERO else math.inf, hh / abs(uy) if abs(uy) > ABS_ZERO else math.inf)
            out.append((p[0] + ux * (t + gap), p[1] + uy * (t + gap)))
    return out


def along(a: Vec, b: Vec, rich: Label, height: float) -> list[Vec]:
    """Candidate centres beside the segment a→b (sheet mm): at its middle first, then towards the
    ends, on either side, at growing distances."""
    d = math.dist(a, b)
    if d < MM_ROUNDOFF:
        return around(a, rich, height)
    ux, uy = (b[0] - a[0]) / d, (b[1] - a[1]) / d
    nx, ny = -uy, ux
    w, depth, rise = size(rich, height)
    hw, hh = w / 2 + 0.5, (height + depth + rise) / 2 + 0.5
    reach = abs(nx) * hw + abs(ny) * hh          # half-extent of the box across the segment
    out = []
    for gap in (1.0, 3.0, 6.0):
        for t in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.1, 0.9):
            m = (a[0] + ux * d * t, a[1] + uy * d * t)
            for side in (1, -1):
                k = side * (reach + gap)
                out.append((m[0] + nx * k, m[1] + ny * k))
    return out


def along_passes(a: Vec, b: Vec, rich: Label, height: float) -> list[tuple[list[Vec], int]]:
    """Passes for the name of the vector a→b: beside it crossing no line, then crossing one line
    (still clearly its name), then farther round its middle."""
    near = along(a, b, rich, height)
    middle = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    d = math.dist(a, b) or 1.0
    normal = math.degrees(math.atan2(b[0] - a[0], -(b[1] - a[1]))) if d else 90.0
    far = around(middle, rich, height, normal, gaps=(4.0, 8.0, 12.0, 16.0))
    return [(near, 0), (near, 1), (far, 0)]


def text_extent(label: Label, center: Vec, height: float) -> Polygon:
    """Where the letters of ``label`` centred at ``center`` are: the union of its texts' boxes as
    :func:`draw_rich` sets them (each its advance without the placer's width margin, from its
    descenders to its cap height) — what a reader, and the label check, measures."""
    return shapely.union_all([box(*b) for b in _extent_boxes(label, center, height)])


def _extent_boxes(label: Label, center: Vec, height: float) -> list[tuple[float, float, float, float]]:
    """The boxes (x0, y0, x1, y1) whose union is :func:`text_extent`."""
    small = _smaller(height)
    w, _, _ = size(label, height)
    x = center[0] - w / 2
    y0 = center[1] - height / 2
    pieces = []

    def piece(px: float, py: float, text: str, h: float) -> None:
        pw = style.text_width(text, h) / style.WIDTH_MARGIN
        pieces.append((px, py - descent(text, h), px + pw, py + h))
    for k, rich in enumerate(_items(label)):
        if k:
            piece(x, y0, SEPARATOR.strip(), height)
            x += style.text_width(SEPARATOR_ADVANCE, height)
        piece(x, y0, rich.base, height)
        xb = x + style.text_width(rich.base, height)
        if rich.sup:
            piece(xb, y0 + 0.45 * height, rich.sup, small)
        if rich.sub:
            piece(xb, y0 - 0.35 * height, rich.sub, small)
        x += _one_width(rich, height)
    return pieces


def _distance_to_boxes(boxes: Sequence[tuple[float, float, float, float]], p: Vec) -> float:
    """Distance (mm) from point ``p`` to the union of axis-parallel ``boxes`` (0 inside one)."""
    return min(math.hypot(max(b[0] - p[0], 0.0, p[0] - b[2]), max(b[1] - p[1], 0.0, p[1] - b[3]))
               for b in boxes)


def own_point(candidates: Sequence[Vec], label: Label, height: float, p: Vec,
              others: Sequence[Vec], near_mm: float) -> list[Vec]:
    """Those candidate centres whose label box lies within ``near_mm`` of its point ``p`` and no
    nearer to any of the ``others`` (the view's other labelled points) than to ``p`` — a letter a
    reader would take for another point's is no place for it (issue 12: «O» nearer to S₁)."""
    qs = [q for q in others if math.dist(q, p) > MM_ROUNDOFF]
    out = []
    for c in candidates:        # the distances to text_extent's union, from its boxes directly
        b = _extent_boxes(label, c, height)
        d = _distance_to_boxes(b, p)
        if d <= near_mm and all(_distance_to_boxes(b, q) >= d + 0.5 for q in qs):
            out.append(c)
    return out


def place_point_label(canvas: Canvas, p: Vec, label: Label, height: float, prefer_deg: float,
                      others: Sequence[Vec], inside: Polygon | None = None,
                      optional: bool = False, avoid: BaseGeometry | None = None,
                      far_gaps: Sequence[float] = (8.0, 11.0, 14.0, 18.0), cross: int = 1,
                      clear: tuple[float, float] = (0.0, 0.0)) -> Polygon | None:
    """A point's letter: beside ``p`` (within LABEL_NEAR_MM, nearer to it than to the ``others``)
    where it overlaps no text and crosses no line, then crossing up to ``cross`` lines (0: a letter
    is never crossed by a line, issue 12); where no such spot is free, farther out (``far_gaps``) on
    a thin leader from the point (the leader is part of what it names; with ``cross`` 0 anywhere in
    ``inside``, :func:`place_on_leader`); else beside it, overlapping the fewest (with ``cross`` 0
    only where the whole region has no free spot). ``avoid``: see :func:`place_passes`."""
    from shapely.geometry import LineString, Point
    from reportgen.tolerances import LABEL_NEAR_MM
    near = own_point(around(p, label, height, prefer_deg, gaps=(0.6, 1.5, 3.0, 4.5, 6.0)),
                     label, height, p, others, LABEL_NEAR_MM - 1.0)
    poly = place_passes(canvas, [(near, k) for k in range(cross + 1)], label, height, inside, optional=True,
                        names=Point(p), avoid=avoid, strict=cross == 0 or any(clear), clear=clear) if near else None
    if poly is not None:
        return poly
    if cross == 0:                  # never crossed: on a leader, anywhere in the region if need be
        poly = place_on_leader(canvas, p, around(p, label, height, prefer_deg, gaps=(6.0, 8.0, 11.0, 14.0, 18.0))
                               + spread_around(p, 30.0), label, height, inside, anywhere=True, clear=clear)
        if poly is not None:
            return poly
        fallback = near or around(p, label, height, prefer_deg, gaps=(1.0, 3.0, 6.0))
        return place_passes(canvas, [(fallback, 0), (fallback, 1)], label, height, inside, optional,
                            names=Point(p), avoid=avoid)
    leader: list = []

    def named(letters: BaseGeometry):
        leader.append(leader_foot(letters, p))
        return LineString([leader[-1], p])

    far = around(p, label, height, prefer_deg, gaps=far_gaps)
    poly = place_passes(canvas, [(far, 0)], label, height, inside, optional=True, names=named, avoid=avoid,
                        clear=clear)
    if poly is not None:
        canvas.layout.add_line(leader[0], p, dxfattribs={"layer": "thin"})
        canvas.annotations.add_obstacle(LineString([leader[0], p]))     # later labels keep off it
        return poly
    fallback = near or around(p, label, height, prefer_deg, gaps=(1.0, 3.0, 6.0))
    return place_passes(canvas, [(fallback, 0), (fallback, 1)], label, height, inside, optional,
                        names=Point(p), avoid=avoid)
