"""Force polygons as scenes (polygon mm at μF are paper mm): the sides head to tail (the loads and
the reactions found by closing it), the reactions read off it as dashed diagonals, each named beside
its own vector; a vector too short to carry its name gets a leader (the name is drawn away from it
with a thin line to its middle).

Where the forces differ by orders of magnitude (a slider's resistance against the weight of a light
link), the largest vector sets μF and the small ones come out shorter than a reader can measure or
name (:data:`LEGIBLE_MM`). They are drawn as they are, and the place where they lie is shown again
as an enlarged detail — a *выносной элемент* of ГОСТ 2.305 §6: on the polygon a thin circle round
them with the detail's letter on a leader's shelf, beside the polygon the circle's content enlarged
k:1 (k a ГОСТ 2.302 enlargement for which μF/k is a round force scale, the smallest that draws the
shortest of them at least :data:`LEGIBLE_MM` long), headed «А (5:1)»; the small vectors are named
in the detail, not on the polygon; under the heading the detail's μF/k. :func:`polygon_details` is
the rule; the note's text names each detail with its ratio and μF/k."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from .. import gost_scales
from ..geometry import vec2 as _pt
from .boxes import DEFAULT as DEFAULT_BOXES
from .scales import FORCE_SERIES, round_up
from .scene import Arrow, Circle, Entity, Label, Point, Scale, Scene, Segment, frozen
from ..tolerances import MM_EPS, RTOL_ROUNDOFF

#: A vector shorter than this (mm) is named with a leader.
LEADER_MM = 12.0
#: A vector of a polygon shorter than this (mm) is not legible at μF (its length cannot be read to a
#: few per cent, its arrowhead is longer than itself): it is shown again in an enlarged detail.
LEGIBLE_MM = 5.0
#: Short vectors nearer to each other than this (mm) share one detail.
DETAIL_JOIN_MM = 2.0 * LEGIBLE_MM
#: The marking circle's clearance round the short vectors, mm of the polygon.
DETAIL_MARGIN_MM = 1.5
#: The largest diameter of a detail, mm (a larger enlargement is not taken).
DETAIL_MAX_MM = 70.0
#: Gap between the polygon and a detail, and room for the detail's heading above it, mm.
DETAIL_GAP_MM = 10.0
DETAIL_TITLE_MM = 14.0
#: The leader to the detail's letter: its slanted part and its shelf, mm.
DETAIL_LEADER_MM = (7.0, 6.0)
#: Letter heights of a detail's heading «А (2:1)» and of its scale «μF = 5 Н/мм» under it (sheet
#: mm, ГОСТ 2.304 sizes: the sheet letters them so; the note's 9 pt are smaller).
DETAIL_HEADING_H, DETAIL_SCALE_H = 5.0, 3.5


def detail_half_width(ratio_text: str, scale: float) -> float:
    """Half the width (mm) a detail's heading and scale line take, estimated from their number of
    characters (:func:`reportgen.scenes.meshing_marks.text_size`, the sheet's lettering with a
    margin): a detail reserves this much beside its centre when it is narrower than its heading —
    on main the crank–rocker's details «А (2:1)» and «Б (2:1)», 16 mm wide, were set 10 mm apart
    under headings 30 mm wide, which overlapped (issue 12)."""
    from .meshing_marks import text_size
    heading = text_size(f"А ({ratio_text})", DETAIL_HEADING_H)[0]
    line = text_size(f"μF = {scale:.6g} Н/мм", DETAIL_SCALE_H)[0]
    return max(heading, line) / 2.0


def force_tex(name: str) -> str:
    """A solver's force or moment name as a TeX symbol: ``Fпс`` → F_{\\text{пс}}, ``G4`` → G_{4},
    ``Fи4′`` → F'_{\\text{и}4}, ``Rn24`` → R^{n}_{24}, ``Rτ24`` → R^{\\tau}_{24}, a lever's couple
    force ``Mи2:B`` → F^{B}_{M\\text{и}2}."""
    text = "\\text"
    if ":" in name:
        base, point = name.split(":", 1)
        m = re.fullmatch(r"M(и|пс)?(.*)", base)
        sub = (f"{text}{{{m.group(1)}}}" if m and m.group(1) else "") + (m.group(2) if m else base)
        return f"F^{{{point}}}_{{M{sub}}}"
    prime = name.endswith("′")
    core = name[:-1] if prime else name
    m = re.fullmatch(r"R([nτ])?(\d+(?:,\d+)?)", core)
    if m:
        sup = {"n": "^{n}", "τ": "^{\\tau}"}.get(m.group(1) or "", "")
        return f"R{sup}_{{{m.group(2)}}}"
    m = re.fullmatch(r"([A-Za-z])(и|пс|ур)?([\d.,]*)", core)
    if not m:
        return core
    letter, word, digits = m.groups()
    sub = (f"{text}{{{word}}}" if word else "") + (digits or "")
    p = "'" if prime else ""
    return f"{letter}{p}_{{{sub}}}" if sub else f"{letter}{p}"


def diagonal(polygon, v) -> tuple[np.ndarray, np.ndarray]:
    """The two vertices of the polygon that the read vector ``v`` joins (tail, head)."""
    verts = [np.asarray(x.start_mm, float) for x in polygon.vectors] + [np.asarray(polygon.vectors[-1].end_mm, float)]
    d = np.asarray(v.end_mm, float)
    best, err = (verts[0], verts[0] + d), math.inf
    for i, a in enumerate(verts):
        for b in verts[i + 1:] + verts[:i]:
            e = float(np.hypot(*((b - a) - d)))
            if e < err:
                best, err = (a, b), e
    return best


@dataclass(frozen=True)
class PolygonDetail:
    """An enlarged detail of a force polygon (see the module's docstring): ``index`` 0, 1, … (the
    renderers letter it А, Б, … in the document's alphabet), ``ratio`` k of k:1, ``scale`` μF/k
    (N/mm), ``names`` the short vectors it shows (solver names), ``centre``/``radius`` the marking
    circle on the polygon and ``at`` the detail's centre (scene mm)."""
    index: int
    ratio: float
    scale: float
    names: tuple[str, ...]
    centre: Point
    radius: float
    at: Point

    @property
    def drawing_scale(self) -> gost_scales.Scale:
        """The detail's ГОСТ 2.302 scale k:1 (its :meth:`~reportgen.gost_scales.Scale.text` prints
        it in a given decimal mark)."""
        return gost_scales.Scale(self.ratio, 1.0)

    @property
    def ratio_text(self) -> str:
        """«5:1», «2,5:1» (ГОСТ 2.302, the core's decimal comma)."""
        return self.drawing_scale.text()


def _sides(polygon) -> list[tuple[str, np.ndarray, np.ndarray, str]]:
    """(name, tail, head, style: "load", "found" or "read" for a diagonal) of every drawn vector of
    the polygon, mm."""
    out = []
    for v in polygon.vectors:
        a, e = np.asarray(v.start_mm, float), np.asarray(v.end_mm, float)
        if float(np.hypot(*(e - a))) >= MM_EPS:
            out.append((v.name, a, e, "load" if v.known else "found"))
    for v in polygon.extra:
        a, b = diagonal(polygon, v)
        if float(np.hypot(*(b - a))) >= MM_EPS:
            out.append((v.name, np.asarray(a, float), np.asarray(b, float), "read"))
    return out


def _seg_dist(p, q, a, b) -> float:
    """Distance between the segments p–q and a–b (mm)."""
    def pt_seg(x, s0, s1):
        d = s1 - s0
        n = float(d @ d)
        t = 0.0 if n == 0.0 else min(1.0, max(0.0, float((x - s0) @ d) / n))
        return float(np.hypot(*(x - s0 - t * d)))
    return min(pt_seg(p, a, b), pt_seg(q, a, b), pt_seg(a, p, q), pt_seg(b, p, q))


def detail_ratio(scale: float, shortest_mm: float, diameter_mm: float) -> float:
    """k of the detail: among the ГОСТ 2.302 enlargements for which μF/k is a round force scale
    (:data:`FORCE_SERIES`), the smallest that draws ``shortest_mm`` at least :data:`LEGIBLE_MM` long,
    if its detail (``diameter_mm`` at 1:1) stays within :data:`DETAIL_MAX_MM`; else the largest that
    does (2:1 at least)."""
    ks = sorted(gost_scales.factor(s) for s in gost_scales.ENLARGEMENTS
                if abs(round_up(scale / gost_scales.factor(s), FORCE_SERIES) - scale / gost_scales.factor(s))
                <= RTOL_ROUNDOFF * scale)
    fit = [k for k in ks if k * diameter_mm <= DETAIL_MAX_MM] or ks[:1]
    legible = [k for k in fit if k * shortest_mm >= LEGIBLE_MM * (1 - RTOL_ROUNDOFF)]
    return legible[0] if legible else fit[-1]


def polygon_details(polygon, box: tuple[float, float] = DEFAULT_BOXES.polygon,
                    first: int = 0) -> tuple[PolygonDetail, ...]:
    """The enlarged details of a force polygon, indexed from ``first`` (the details of one work are
    lettered through all its polygons, ГОСТ 2.305 §6: :func:`first_detail_indices`): one per group of vectors shorter than
    :data:`LEGIBLE_MM` lying within :data:`DETAIL_JOIN_MM` of each other, placed outside the
    polygon's bounding box on the side that keeps the drawing best within ``box`` (turned to lie
    along the polygon's longer side: the room the sheet gives a polygon), then the one that enlarges
    it least, then the nearest to its circle."""
    sides = _sides(polygon)
    short = [i for i, (_, a, b, _r) in enumerate(sides) if float(np.hypot(*(b - a))) < LEGIBLE_MM]
    groups: list[list[int]] = []
    for i in short:
        _, a, b, _r = sides[i]
        near = [g for g in groups if any(_seg_dist(a, b, sides[j][1], sides[j][2]) < DETAIL_JOIN_MM for j in g)]
        merged = [i] + [j for g in near for j in g]
        groups = [g for g in groups if g not in near] + [sorted(merged)]
    groups.sort(key=lambda g: g[0])
    pts = np.array([p for _, a, b, _r in sides for p in (a, b)]) if sides else np.zeros((1, 2))
    lo, hi = pts.min(0), pts.max(0)
    taken: list[tuple[float, float, float, float]] = []
    out = []
    for n, g in enumerate(groups):
        ends = np.array([p for j in g for p in (sides[j][1], sides[j][2])])
        c = (ends.min(0) + ends.max(0)) / 2
        r = max(float(np.max(np.hypot(*(ends - c).T))), LEGIBLE_MM / 2) + DETAIL_MARGIN_MM
        shortest = min(float(np.hypot(*(sides[j][2] - sides[j][1]))) for j in g)
        k = detail_ratio(polygon.scale, shortest, 2 * r)
        scale = float(f"{polygon.scale / k:.12g}")
        R = r * k
        half = max(R, detail_half_width(gost_scales.Scale(k, 1.0).text(), scale))
        at = _detail_place(c, R, lo, hi, taken, box, half)
        taken.append((at[0] - half, at[1] - R, at[0] + half, at[1] + R + DETAIL_TITLE_MM))
        lo = np.minimum(lo, [at[0] - half, at[1] - R])
        hi = np.maximum(hi, [at[0] + half, at[1] + R + DETAIL_TITLE_MM])
        out.append(PolygonDetail(first + n, k, scale, tuple(sides[j][0] for j in g), _pt(c), r, _pt(at)))
    return tuple(out)


def _detail_place(c, R: float, lo, hi, taken, box: tuple[float, float], half: float | None = None) -> np.ndarray:
    """The centre of a detail of radius ``R`` for the circle at ``c``: below, above, left or right of
    the drawing's box ``lo``–``hi`` (the detail's heading above it), level with ``c`` where the box
    allows, clear of the details ``taken``; the place that enlarges the box least, then the nearest.
    ``half``: the half-width it takes (its heading may be wider than the circle; default ``R``)."""
    g, t = DETAIL_GAP_MM, DETAIL_TITLE_MM
    W = R if half is None else half
    x = float(min(max(c[0], lo[0] + W), max(hi[0] - W, lo[0] + W)))
    y = float(min(max(c[1], lo[1] + R), max(hi[1] - R - t, lo[1] + R)))
    cands = [np.array([x, lo[1] - g - t - R]), np.array([x, hi[1] + g + R]),
             np.array([lo[0] - g - W, y]), np.array([hi[0] + g + W, y])]
    wide = hi[0] - lo[0] >= hi[1] - lo[1]
    bw, bh = (max(box), min(box)) if wide else (min(box), max(box))
    best = None
    for rank, p in enumerate(cands):
        for _ in range(20):               # slide along the box's side past the details already placed
            room = (p[0] - W, p[1] - R, p[0] + W, p[1] + R + t)
            hit = [o for o in taken if not (room[2] + g <= o[0] or o[2] + g <= room[0] or room[3] + g <= o[1]
                                            or o[3] + g <= room[1])]
            if not hit:
                break
            if rank < 2:
                p = np.array([max(o[2] for o in hit) + g + W, p[1]])
            else:
                p = np.array([p[0], min(o[1] for o in hit) - g - R - t])
        nlo = np.minimum(lo, [p[0] - W, p[1] - R])
        nhi = np.maximum(hi, [p[0] + W, p[1] + R + t])
        size = nhi - nlo
        key = (round(max(size[0] / bw, size[1] / bh), 6), round(float(np.prod(size)), 6), float(np.hypot(*(p - c))))
        if best is None or key < best[0]:
            best = (key, p)
    assert best is not None
    return best[1]


def _clip(a: np.ndarray, b: np.ndarray, c: np.ndarray, r: float) -> tuple[float, float] | None:
    """The parameters t0 < t1 of the part of a→b inside the disc (c, r), or None."""
    d = b - a
    f = a - c
    A, B, C = float(d @ d), 2.0 * float(f @ d), float(f @ f) - r * r
    if A == 0.0:
        return None
    disc = B * B - 4 * A * C
    if disc <= 0.0:
        return None
    s = math.sqrt(disc)
    t0, t1 = max((-B - s) / (2 * A), 0.0), min((-B + s) / (2 * A), 1.0)
    return (t0, t1) if t1 - t0 > MM_EPS else None


def _detail_entities(det: PolygonDetail, sides) -> tuple[list[Entity], list[Label]]:
    """The detail's drawing: the polygon's lines inside the marking circle enlarged k times about
    its centre to the detail's place (an arrow keeps its head where the head lies inside), the short
    vectors named; the circle and the letter's leader on the polygon; the heading."""
    c, at, k = np.asarray(det.centre), np.asarray(det.at), det.ratio
    ents: list[Entity] = []
    labels: list[Label] = []
    tag = f"detail{det.index}"
    for name, a, b, style in sides:
        span = _clip(a, b, c, det.radius)
        if span is None:
            continue
        t0, t1 = span
        p, q = (_pt(at + (a + (b - a) * t - c) * k) for t in (t0, t1))
        if style == "read":
            ents.append(Segment(f"{tag}:read:{name}", p, q, "hidden"))
        elif t1 >= 1.0 - MM_EPS:
            ents.append(Arrow(f"{tag}:vec:{name}", p, q, style))
        else:
            ents.append(Segment(f"{tag}:vec:{name}", p, q, "vectors"))
        if name in det.names:
            labels.append(Label(force_tex(name), ents[-1].id, ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2), "vector",
                                (p, q), leader=math.dist(p, q) < LEADER_MM))
    ents.append(Circle(f"{tag}:mark", det.centre, det.radius, "thin"))
    # the letter on the shelf of a leader from the circle, away from the detail's side
    out = c - at
    n = float(np.hypot(*out))
    u = out / n if n > MM_EPS else np.array([0.0, 1.0])
    u = np.array([math.copysign(math.sqrt(0.5), u[0] or 1.0), math.copysign(math.sqrt(0.5), u[1] or 1.0)])
    p0 = c + u * det.radius
    p1 = p0 + u * DETAIL_LEADER_MM[0]
    p2 = p1 + np.array([math.copysign(DETAIL_LEADER_MM[1], u[0]), 0.0])
    ents.append(Segment(f"{tag}:leader", _pt(p0), _pt(p1), "thin"))
    ents.append(Segment(f"{tag}:shelf", _pt(p1), _pt(p2), "thin"))
    labels.append(Label(str(det.index), f"{tag}:shelf", _pt((p1 + p2) / 2 + np.array([0.0, 2.5])), "detail"))
    R = det.radius * k
    labels.append(Label(f"{det.index} {det.ratio_text}", f"{tag}:title",
                        _pt(at + np.array([0.0, R + DETAIL_TITLE_MM * 0.75])), "detail-title"))
    labels.append(Label(str(det.index), f"{tag}:scale", _pt(at + np.array([0.0, R + DETAIL_TITLE_MM * 0.3])),
                        "detail-scale"))
    return ents, labels


def first_detail_indices(polygons) -> list[int]:
    """The index of each polygon's first detail, the polygons in the order the work shows them (the
    note's section 2 and sheet 2: the groups as solved, then the crank): a detail's letter (А, Б, …)
    is not repeated on one sheet (ГОСТ 2.305 §6), so the details are numbered through the work."""
    out, n = [], 0
    for polygon in polygons:
        out.append(n)
        n += len(polygon_details(polygon))
    return out


def polygon_scene(polygon, name: str | None = None, first: int = 0) -> Scene:
    """The scene of a :class:`reportgen.kinetostatics.graphical.ForcePolygon` with its details
    (:func:`polygon_details`, indexed from ``first``)."""
    ents: list[Entity] = []
    labels: list[Label] = []
    values: dict[str, float] = {}
    details = polygon_details(polygon, first=first)
    in_detail = {n for d in details for n in d.names}
    for v in polygon.vectors:
        a, e = _pt(v.start_mm), _pt(v.end_mm)
        values[v.name] = v.measured_mm
        values[f"{v.name}:read"] = v.read_value
        if math.dist(a, e) < MM_EPS:
            continue
        ents.append(Arrow(f"vec:{v.name}", a, e, "load" if v.known else "found"))
        if v.name not in in_detail:
            labels.append(Label(force_tex(v.name), f"vec:{v.name}", ((a[0] + e[0]) / 2, (a[1] + e[1]) / 2),
                                "vector", (a, e), leader=math.dist(a, e) < LEADER_MM))
    for v in polygon.extra:
        a, b = (_pt(p) for p in diagonal(polygon, v))
        values[v.name] = v.measured_mm
        values[f"{v.name}:read"] = v.read_value
        if math.dist(a, b) < MM_EPS:
            continue
        ents.append(Arrow(f"read:{v.name}", a, b, "read", "hidden"))
        if v.name not in in_detail:
            labels.append(Label(force_tex(v.name), f"read:{v.name}", ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2),
                                "vector", (a, b), leader=math.dist(a, b) < LEADER_MM))
    sides = _sides(polygon)
    scales = [Scale("μF", polygon.scale, "Н/мм")]
    for d in details:
        e2, l2 = _detail_entities(d, sides)
        ents += e2
        labels += l2
        scales.append(Scale(f"μF:{d.index}", d.scale, "Н/мм", d.ratio_text))
    return Scene(name or f"polygon-{polygon.key}", tuple(scales), tuple(ents),
                 tuple(labels), frozen({}), frozen(values))
