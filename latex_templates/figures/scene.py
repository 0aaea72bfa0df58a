"""The note's renderer of a :class:`reportgen.scenes.scene.Scene` (the same scene a sheet draws).

Matplotlib, not TikZ: every other figure of the note is matplotlib already (its fonts, its vector
PDF, NoteBuilder saves it), the label placement needs text extents and collision tests that are
plain Python here and would be TeX macros in TikZ, and a scene of a few thousand entities (the
plan of positions with its trajectories) would slow every LaTeX run.

The figure is drawn at a true scale: 1 mm of the scene is ``reduction`` mm of the page (1, or a
smaller factor when the scene is larger than the text block), and
is included at its natural size (``fig.reportgen_exact``; the template reads ``fig.width_cm``): at
1:1 where it fits the text block (a reader can measure it), else reduced to fill the block. Labels are in the note's font size, placed beside their anchor (a point,
or the middle of their vector) where they overlap no other label; ``fig.reportgen_labels`` keeps
the placed boxes (scene mm) for the tests."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from matplotlib.patches import Circle as MplCircle
from matplotlib.patches import Polygon as MplPolygon

from reportgen import gost_scales
from reportgen.scenes.scene import Arrow, Circle, Label, Polyline, Scene, Segment
from reportgen.tolerances import ABS_ZERO, MM_ROUNDOFF, RTOL_EQUAL

from ..parts import active
from . import new_figure
from .saving import content_keys_read, kept_figure, mark_content
from .labels import names

#: The text block of the note, mm (A4, margins 30 + 15 mm; the height left for a figure and its
#: caption).
TEXT_W_MM, TEXT_H_MM = 160.0, 215.0
#: Letter size of labels, pt, and its height in page mm.
LABEL_PT = 9.0
LABEL_MM = LABEL_PT * 25.4 / 72.0
PAD_MM = 6.0          # page mm round the drawing
HEAD_MM = 3.0         # an arrowhead's length on the page, mm (a sixth of it wide each side)

PENS = {"contour": (1.1, "-"), "thin": (0.45, "-"), "hidden": (0.9, (0, (4, 2))), "phantom": (0.5, (0, (6, 2, 1, 2, 1, 2))),
        "axis": (0.45, (0, (8, 2, 1, 2))), "vectors": (1.0, "-"), "construction": (0.3, ":")}
COLOURS = {"absolute": "black", "relative": "tab:blue", "normal": "tab:green", "tangential": "tab:red",
           "coriolis": "tab:purple", "sliding": "tab:orange",
           "load": "black", "found": "tab:red", "read": "tab:blue", "known": "tab:blue"}


@dataclass(frozen=True)
class PlacedLabel:
    """A label as the note drew it: its text, anchor, box (scene mm) and the distance from the box
    to its anchor point (scene mm)."""
    text: str
    anchor: str
    box: tuple[float, float, float, float]
    distance: float
    leader: bool = False


def reduction_for(scene: Scene, max_w_mm: float = TEXT_W_MM, max_h_mm: float = TEXT_H_MM) -> float:
    """1 if the scene (with its labels' margin) fits the text block, else the reduction that makes
    it fill the block (the caption then says the figure is reduced and which sheet has the scale)."""
    x0, y0, x1, y1 = scene.bounds()
    w, h = x1 - x0, y1 - y0
    fit = min((max_w_mm - 2 * PAD_MM) / max(w, MM_ROUNDOFF), (max_h_mm - 2 * PAD_MM) / max(h, MM_ROUNDOFF))
    return min(1.0, fit)


#: Roles of labels set at their own point (the letter of a polygon's detail on its shelf, the detail's
#: heading «А (5:1)»): placed first, the others kept clear of them.
FIXED_ROLES = ("detail", "detail-title", "detail-scale")


#: Scenes whose vectors' names are kept nearer to their own vector than to any other named vector
#: (issue 12: the force polygons, the lever, the groups' free-body diagrams, the velocity and
#: acceleration plans; tests/labels checks the same figures).
OWN_VECTOR_SCENES = ("polygon", "lever", "free-body", "velocity-plan", "acceleration-plan")


def fixed_text(lb: Label, scene: Scene | None = None) -> str:
    """The text of a label of :data:`FIXED_ROLES`: the detail's index as its letter in the note's
    alphabet (``polygons.letters``), the heading as «letter (ratio)» with the language's decimal mark,
    the detail's scale «μF = 2 Н/мм» (``polygons.detail_scale``, from the ``scene``'s scales)."""
    from markupsafe import Markup

    from ..parts import decimal_mark
    if lb.role == "detail-scale":
        mu = scene.scale(f"μF:{lb.text}").value if scene is not None else 0.0
        return str(active().text("polygons.detail_scale", mu=Markup(f"{mu:.6g}".replace(".", decimal_mark()))))
    letters = str(active().raw("polygons.letters"))
    index, _, ratio = lb.text.partition(" ")
    letter = letters[int(index) % len(letters)]
    return f"{letter} ({gost_scales.Scale.parse(ratio).text(decimal_mark())})" if ratio else letter


def _letters_list(tex: str) -> bool:
    """Is ``tex`` a list of a plan's coincident letters (``π,o,c``: no spaces, no brackets)?"""
    parts = tex.split(",")
    return len(parts) > 1 and all(p and not any(ch in p for ch in " (){}[]") for p in parts)


def _mathtext(tex: str) -> str:
    """A label's TeX (``a^{n}_{BA}``, ``S_{2}``) as matplotlib mathtext; plain words stay plain. A
    list of coincident letters is set like any other (``π,o,c`` as «π, o, c», as ``a,s_{2}``)."""
    if any(ch in tex for ch in "_^\\") or (tex.isalpha() and tex.isascii()) or _letters_list(tex):
        tex = active().localize_latex(tex)      # the note's language: F_{\\text{и}1} → F_{\\text{i}1}
        tex = tex.replace("\\text{", "\\mathrm{")
        tex = tex.replace("'_{", "^{\\prime}_{")     # mathtext sets F'_{и2} as F′ then a lowered и2
        parts = tex.split(",")
        return ", ".join(f"${p}$" for p in parts)
    return tex


def _text_size(text: str, h: float) -> tuple[float, float]:
    """Rough width and height (same units as ``h``, the letter height) of a label."""
    plain = text
    for cmd in ("\\tau", "\\omega", "\\varepsilon", "\\pi"):
        plain = plain.replace(cmd, "t")
    n_base = n_small = 0
    small = False
    depth = 0
    for ch in plain:
        if ch in "_^":
            small = True
            continue
        if ch == "{":
            depth += 1
            continue
        if ch == "}":
            depth -= 1
            if depth == 0:
                small = False
            continue
        if small:
            n_small += 1
            if depth == 0:
                small = False
        else:
            n_base += 1
    return (0.62 * h * n_base + 0.45 * h * n_small + 0.2 * h, 1.25 * h)


def _boxes_hit(b, boxes) -> bool:
    return any(not (b[2] <= o[0] or o[2] <= b[0] or b[3] <= o[1] or o[3] <= b[1]) for o in boxes)


def _dist_box(p, b) -> float:
    dx = max(b[0] - p[0], 0.0, p[0] - b[2])
    dy = max(b[1] - p[1], 0.0, p[1] - b[3])
    return math.hypot(dx, dy)


def _crosses(b, seg) -> bool:
    """Does segment ``seg`` ((x0, y0), (x1, y1)) meet box ``b`` (Liang–Barsky)?"""
    (x0, y0), (x1, y1) = seg
    dx, dy = x1 - x0, y1 - y0
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, x0 - b[0]), (dx, b[2] - x0), (-dy, y0 - b[1]), (dy, b[3] - y0)):
        if p == 0:
            if q < 0:
                return False
            continue
        t = q / p
        if p < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    return True


def _near(s, box) -> bool:
    """Does the bounding box of segment ``s`` touch ``box``?"""
    return (min(s[0][0], s[1][0]) <= box[2] and max(s[0][0], s[1][0]) >= box[0]
            and min(s[0][1], s[1][1]) <= box[3] and max(s[0][1], s[1][1]) >= box[1])


class _Segments:
    """A scene's lines with their bounding boxes as arrays: the candidate boxes of a label are
    tested against the few segments whose bounding boxes they touch (the same count as testing
    every segment, found in one array comparison instead of a Python loop over thousands)."""

    def __init__(self, segs: list) -> None:
        self.segs = segs
        xy = np.asarray(segs, dtype=float).reshape(-1, 2, 2)
        self.x0, self.x1 = xy[:, :, 0].min(axis=1), xy[:, :, 0].max(axis=1)
        self.y0, self.y1 = xy[:, :, 1].min(axis=1), xy[:, :, 1].max(axis=1)

    def crossings(self, box) -> int:
        """How many segments cross ``box``."""
        near = np.flatnonzero((self.x0 <= box[2]) & (self.x1 >= box[0])
                              & (self.y0 <= box[3]) & (self.y1 >= box[1]))
        return sum(1 for i in near if _crosses(box, self.segs[i]))


def _lines(scene: Scene) -> list:
    """The scene's drawn lines as segments (circles as their bounding squares' sides)."""
    out = []
    for e in scene.entities:
        if isinstance(e, (Segment, Arrow)):
            out.append((e.a, e.b))
        elif isinstance(e, Polyline):
            pts = list(e.points) + ([e.points[0]] if e.closed else [])
            out += list(zip(pts[:-1], pts[1:]))
        elif isinstance(e, Circle):
            n = 12
            pts = [(e.c[0] + e.r * math.cos(2 * math.pi * k / n), e.c[1] + e.r * math.sin(2 * math.pi * k / n))
                   for k in range(n + 1)]
            out += list(zip(pts[:-1], pts[1:]))
    return out


def _heads(scene: Scene, r: float) -> list:
    """The outlines of the arrowheads the figure draws at reduction ``r`` (:data:`HEAD_MM` long on
    the page, a third as wide): a name beside a short vector must keep clear of its head too."""
    out = []
    for e in scene.entities:
        if not isinstance(e, Arrow):
            continue
        a, b = np.asarray(e.a, float), np.asarray(e.b, float)
        d = float(np.hypot(*(b - a)))
        if d < MM_ROUNDOFF:
            continue
        head = min(HEAD_MM / r, d)
        u = (b - a) / d
        nrm = np.array([-u[1], u[0]])
        base = b - u * head
        left, right = tuple(base + nrm * head / 6), tuple(base - nrm * head / 6)
        tip = (float(b[0]), float(b[1]))
        out += [(tip, left), (left, right), (right, tip)]
    return out


def _seg_point(p, seg) -> float:
    (x0, y0), (x1, y1) = seg
    dx, dy = x1 - x0, y1 - y0
    m = dx * dx + dy * dy
    t = 0.0 if m == 0.0 else min(1.0, max(0.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / m))
    return math.hypot(p[0] - x0 - t * dx, p[1] - y0 - t * dy)


def box_segment_distance(b, seg) -> float:
    """Distance (mm) between the box ``b`` (x0, y0, x1, y1) and the segment ``seg``."""
    if _crosses(b, seg):
        return 0.0
    corners = ((b[0], b[1]), (b[2], b[1]), (b[2], b[3]), (b[0], b[3]))
    return min([_dist_box(q, b) for q in seg] + [_seg_point(c, seg) for c in corners])


def _along_one_line(own, other) -> bool:
    """Do two vectors lie on one line, overlapping (then their names share the room beside it)?"""
    (ax, ay), (bx, by) = own
    n = math.hypot(bx - ax, by - ay)
    if n == 0.0:
        return False
    off = max(abs((x - ax) * (by - ay) - (y - ay) * (bx - ax)) for x, y in other) / n
    return off < 0.5 and min(_seg_point(other[0], own), _seg_point(other[1], own),
                             _seg_point(own[0], other), _seg_point(own[1], other)) < 0.5


def _rivals_of(own, rivals) -> list:
    """The figure's other named vectors that a name of ``own`` must keep away from: not ``own``
    itself, not one lying along it (their names share the room beside the line) — the nearest to
    its middle first, where a candidate box fails soonest (the test is the same for any order)."""
    mid = ((own[0][0] + own[1][0]) / 2, (own[0][1] + own[1][1]) / 2)
    return sorted((r for r in rivals if r != own and not _along_one_line(own, r)),
                  key=lambda r: _seg_point(mid, r))


def _own_vector(box, own, rivals, margin: float) -> bool:
    """Is ``box`` nearer (by ``margin``) to its vector ``own`` than to any of the ``rivals``
    (:func:`_rivals_of` it, found once per label)? A name nearer to another vector reads as its."""
    d = box_segment_distance(box, own)
    return all(box_segment_distance(box, r) >= d + margin for r in rivals)


def _beyond_foot(along, w: float, h: float, gap: float) -> list[tuple[float, float]]:
    """Centres for the name of a lever's arm (pole → foot) just past its foot on its own line, and
    beside that end, away from the pole, where the arms of the forces whose lines pass near the pole
    all meet (issue 12: the press's h₁₀, h₁₄ and h₂ on leaders at p): the name reads as the arm's
    as a dimension's value reads as its line's."""
    (ax, ay), (bx, by) = along
    dx, dy = float(bx) - float(ax), float(by) - float(ay)
    n = math.hypot(dx, dy) or 1.0
    ux, uy = dx / n, dy / n
    reach = gap + 0.5 * abs(ux) * w + 0.5 * abs(uy) * h
    out = [(float(bx) + ux * reach, float(by) + uy * reach)]
    side = gap + 0.5 * abs(uy) * w + 0.5 * abs(ux) * h       # beside the foot, across the arm
    for s in (1.0, -1.0):
        out.append((float(bx) - ux * 0.5 * min(n, w) - s * uy * side, float(by) - uy * 0.5 * min(n, w) + s * ux * side))
    return out


def _leader_candidates(lb: Label, w: float, h: float, gap: float,
                       offs: tuple[float, ...] = (4.0, 6.0, 8.0, 11.0)) -> list[tuple[float, float]]:
    """Centres round the anchor (a point, or the middle of a vector: across it first) for a label
    on a leader."""
    # plain floats: the same IEEE arithmetic as numpy's scalars, without their overhead
    px, py = float(lb.at[0]), float(lb.at[1])
    if lb.along is not None:
        (ax, ay), (bx, by) = lb.along
        base = math.atan2(float(bx) - float(ax), -(float(by) - float(ay)))   # across the vector
    else:
        base = math.pi / 4
    out = []
    for off in offs:
        for k in range(16):
            ang = base + (k + 1) // 2 * (1 if k % 2 else -1) * math.pi / 8
            out.append((px + math.cos(ang) * (w / 2 + gap * off), py + math.sin(ang) * (h / 2 + gap * off)))
    return out


def _others_of(p, others: list) -> list:
    """The figure's other labelled points, not ``p`` itself, the nearest first (see _rivals_of)."""
    return sorted((q for q in others if abs(q[0] - p[0]) + abs(q[1] - p[1]) > MM_ROUNDOFF),
                  key=lambda q: math.hypot(q[0] - p[0], q[1] - p[1]))


def _own(box, p, others: list, margin: float) -> bool:
    """Is ``box`` nearer (by ``margin``) to its point ``p`` than to any of the ``others``
    (:func:`_others_of` it, found once per label)? A letter nearer to another point reads as that
    point's."""
    d = _dist_box(p, box)
    return all(_dist_box(q, box) >= d + margin for q in others)


def _leader_end(lb: Label, box) -> tuple[tuple[float, float], tuple[float, float]]:
    """The leader of a label in ``box``: from the box's point nearest to its anchor (the point, or
    the middle of its vector) to that anchor."""
    bx = min(max(lb.at[0], box[0]), box[2])
    by = min(max(lb.at[1], box[1]), box[3])
    return (bx, by), (lb.at[0], lb.at[1])


def _place(lb: Label, size: tuple[float, float], boxes: list, centre: np.ndarray, gap: float,
           lines: "_Segments | list | None" = None, others: list | None = None, rivals: list | None = None,
           uncrossed: bool = False, leaders: list | None = None,
           region: tuple[float, float, float, float] | None = None):
    """A box for ``lb`` beside its anchor that hits no placed box: around a point (away from the
    scene's middle first, nearest first, and nearer to it than to any of the ``others``), or
    beside the middle of a vector on either side; where every such box hits one, farther out on a
    leader. ``uncrossed`` (the scenes of :data:`OWN_VECTOR_SCENES`, issue 12): a box crossed by a
    line (or by a leader already drawn, ``leaders``) is taken only when no box beside the anchor
    and none on a leader (whose leader crosses no placed box) is free — on a leader, the nearest
    free spot of ``region`` (the scene's bounds, scene mm) widened by the label's size, beyond which
    nothing is drawn: a free spot always exists. Returns (centre, box, on a leader)."""
    w, h = size
    point = lb.role != "vector" or lb.along is None
    cands: list[tuple[float, float]] = []
    if lb.role == "vector" and lb.along is not None and lb.leader:
        cands = _leader_candidates(lb, w, h, gap)
    elif lb.role == "vector" and lb.along is not None:
        (ax, ay), (bx, by) = lb.along
        ax, ay, bx, by = float(ax), float(ay), float(bx), float(by)
        dx, dy = bx - ax, by - ay
        n = float(np.hypot(dx, dy)) or 1.0
        nx, ny = -(dy / n), dx / n                 # the unit normal
        for off in (1.0, 2.0, 3.5, 5.0):
            reach = gap * off + 0.5 * abs(nx) * w + 0.5 * abs(ny) * h
            for t in (0.5, 0.35, 0.65, 0.2, 0.8):
                for side in (1.0, -1.0):
                    cands.append((ax + dx * t + side * nx * reach, ay + dy * t + side * ny * reach))
            if lb.anchor.startswith("arm:"):
                cands.extend(_beyond_foot(lb.along, w, h, gap * off))
    else:
        p = np.asarray(lb.at)
        v = p - centre
        base = math.atan2(v[1], v[0]) if np.hypot(*v) > MM_ROUNDOFF else math.pi / 4
        px, py = float(p[0]), float(p[1])
        for off in (1.0, 2.0, 3.5, 5.0, 7.0):
            for k in range(16):
                ang = base + (k + 1) // 2 * (1 if k % 2 else -1) * math.pi / 8
                ux, uy = math.cos(ang), math.sin(ang)
                t = min((w / 2) / abs(ux) if abs(ux) > ABS_ZERO else math.inf,
                        (h / 2) / abs(uy) if abs(uy) > ABS_ZERO else math.inf)
                cands.append((px + ux * (t + gap * off), py + uy * (t + gap * off)))
    if not point and rivals:
        rivals = _rivals_of(lb.along, rivals)
        if uncrossed and leaders:        # a leader drawn already reads as the line a name beside it names
            rivals = rivals + list(leaders)
    if point and others:
        others = _others_of(lb.at, others)
    def passes():                # each made only when the passes before it found no free box
        yield cands, lb.leader, False
        if not lb.leader:        # the last resort: farther out, tied to the anchor by a leader
            yield _leader_candidates(lb, w, h, gap, (5.0, 6.5, 8.0, 11.0, 15.0, 20.0)), True, not uncrossed
        if uncrossed:            # and farther still, on a leader, the nearest free spot of a grid
            reach = 12.0 * gap / 0.8
            step = gap * 2.5
            n = int(reach / step)
            px, py = float(lb.at[0]), float(lb.at[1])
            yield sorted(((px + i * step, py + j * step) for i in range(-n, n + 1) for j in range(-n, n + 1)
                          if 0 < math.hypot(i, j) * step <= reach),
                         key=lambda q: (round(math.hypot(q[0] - px, q[1] - py), 9), q)), True, region is None
            if region is not None:   # the last: anywhere round the drawing (issue 12: never a crossed name)
                yield _region_grid((px, py), region, w, h, step), True, True
    first = None
    for group, leader, last in passes():
        best = None
        for rank, c in enumerate(group):
            box = (c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)
            if _boxes_hit(box, boxes):
                continue
            if point and not leader and others and not _own(box, lb.at, others, 0.75 * gap):
                continue
            if not point and not leader and rivals and not _own_vector(box, lb.along, rivals, 0.75 * gap):
                continue
            if not point and leader and uncrossed and rivals and not last \
                    and any(box_segment_distance(box, r) < gap for r in rivals):
                continue         # a name on a leader against another vector reads as that one's
                                 # (issue 12: the press's F^B_Mи4 by F_ур's tail)
            hits = lines.crossings(box) if isinstance(lines, _Segments) else \
                sum(1 for s in (lines or ()) if _near(s, box) and _crosses(box, s))
            if uncrossed:
                hits += sum(1 for s in (leaders or ()) if _near(s, box) and _crosses(box, s))
                if hits == 0 and leader:
                    seg = _leader_end(lb, box)
                    if any(_crosses(o, seg) for o in boxes):
                        continue
            if hits == 0:
                return c, box, leader
            if best is None or (hits, rank) < best[0]:
                best = ((hits, rank), c, box)
        if best is not None and not uncrossed:   # beside its entity, crossing the fewest lines, before a leader
            return best[1], best[2], leader
        if first is None and best is not None:
            first = (best[1], best[2], leader)
    if first is not None:        # nothing free anywhere: beside its entity, crossing the fewest
        return first
    c = cands[0]
    return c, (c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2), lb.leader


def _region_grid(p: tuple[float, float], region: tuple[float, float, float, float], w: float, h: float,
                 step: float) -> list[tuple[float, float]]:
    """Centres on a grid of ``step`` through ``p`` over ``region`` widened by a label's width ``w``
    and height ``h`` on each side (boxes wholly outside the drawing are among them), nearest
    first."""
    x0, y0, x1, y1 = region[0] - w - step, region[1] - h - step, region[2] + w + step, region[3] + h + step
    px, py = p
    i0, i1 = math.floor((x0 - px) / step), math.ceil((x1 - px) / step)
    j0, j1 = math.floor((y0 - py) / step), math.ceil((y1 - py) / step)
    return sorted(((px + i * step, py + j * step) for i in range(i0, i1 + 1) for j in range(j0, j1 + 1) if i or j),
                  key=lambda q: (round(math.hypot(q[0] - px, q[1] - py), 9), q))


def anchor_distance(lb: Label, b) -> float:
    """Distance (scene mm) from a label's box to what it names: its point, or its vector."""
    if lb.role == "vector" and lb.along is not None:
        (ax, ay), (bx, by) = lb.along
        return min(_dist_box((ax + (bx - ax) * t / 40, ay + (by - ay) * t / 40), b) for t in range(41))
    return _dist_box(lb.at, b)


def place_labels(scene: Scene, r: float, roles: tuple[str, ...],
                 sizes: dict[int, tuple[float, float]] | None = None) -> list[tuple[Label, tuple[float, float], PlacedLabel]]:
    """The labels of ``roles`` placed for a figure at reduction ``r``: (label, centre, placed);
    ``sizes``: a label's measured width and height (scene mm) by its index in ``scene.labels``,
    else the estimate from its text."""
    h = LABEL_MM / r
    gap = 0.8 / r
    pts = np.array([lb.at for lb in scene.labels]) if scene.labels else np.zeros((1, 2))
    centre = pts.mean(axis=0)
    out = []
    boxes: list = []
    lines = _Segments(_lines(scene) + _heads(scene, r))
    others = [lb.at for lb in scene.labels if lb.role in roles and (lb.role != "vector" or lb.along is None)]
    rivals = [lb.along for lb in scene.labels if lb.role == "vector" and lb.along is not None] \
        if scene.name.startswith(OWN_VECTOR_SCENES) else []
    fixed = sorted((i for i, lb in enumerate(scene.labels) if lb.role in FIXED_ROLES),
                   key=lambda i: scene.labels[i].at[1])
    for i in fixed:          # the fixed ones first, the lowest first, each moved up clear of those below
        lb = scene.labels[i]
        w, hh = sizes[i] if sizes is not None and i in sizes else _text_size(fixed_text(lb, scene), h)
        c = (lb.at[0], lb.at[1])
        b = (c[0] - w / 2, c[1] - hh / 2, c[0] + w / 2, c[1] + hh / 2)
        while _boxes_hit(b, boxes):
            top = max(o[3] for o in boxes if not (b[2] <= o[0] or o[2] <= b[0] or b[3] <= o[1] or o[3] <= b[1]))
            c = (c[0], top + hh / 2 + gap / 2)
            b = (c[0] - w / 2, c[1] - hh / 2, c[0] + w / 2, c[1] + hh / 2)
        boxes.append(b)
        out.append((lb, c, PlacedLabel(lb.text, lb.anchor, b, 0.0, False)))
    uncrossed = scene.name.startswith(OWN_VECTOR_SCENES)
    region = scene.bounds()
    leaders: list = []
    order = list(enumerate(scene.labels))
    if uncrossed:            # the points' letters first: a vector's name keeps clear of their leaders
        order.sort(key=lambda il: il[1].role == "vector")
    for i, lb in order:
        if lb.role not in roles or lb.role in FIXED_ROLES:
            continue
        size = sizes[i] if sizes is not None and i in sizes else _text_size(lb.text, h)
        c, b, leader = _place(lb, size, boxes, centre, gap, lines, others, rivals, uncrossed, leaders, region)
        boxes.append(b)
        if leader:
            leaders.append(_leader_end(lb, b))
        out.append((lb, c, PlacedLabel(lb.text, lb.anchor, b, anchor_distance(lb, b), leader)))
    return out


def scene_figure(scene: Scene, *, max_w_mm: float = TEXT_W_MM, max_h_mm: float = TEXT_H_MM,
                 colours: bool = True, roles: tuple[str, ...] = ("point", "vector", "number")):
    """The scene as a matplotlib figure at a true reduction (see the module's docstring); inside a
    build whose cache keeps this figure, a stand-in with its sizes (:func:`.saving.kept_figure`)."""
    from ..parts import active_strings
    strings = active()
    key = figure_key(scene, max_w_mm=max_w_mm, max_h_mm=max_h_mm, colours=colours, roles=roles) \
        if content_keys_read() else None

    def make():         # perhaps later (a kept PDF gone): in the language of now
        with active_strings(strings):
            return _make_scene_figure(scene, max_w_mm=max_w_mm, max_h_mm=max_h_mm, colours=colours, roles=roles,
                                      key=key)

    kept = kept_figure(key, make) if key is not None else None
    return kept if kept is not None else make()


def _add_patch(ax: Any, patch: Any) -> None:
    """``ax.add_patch`` without its update of the data limits (≈ 0.6 ms a patch: ~0.2 s of CPU
    over the press's scene figures): a scene figure's limits are set before anything is drawn
    (autoscaling off), so they are never read. The same children, clip path and transform as
    ``add_patch`` gives, hence the same PDF bytes."""
    ax.add_artist(patch)


def _make_scene_figure(scene: Scene, *, max_w_mm: float, max_h_mm: float, colours: bool,
                       roles: tuple[str, ...], key: str | None = None, shrink: float = 1.0):
    r = reduction_for(scene, max_w_mm, max_h_mm) / shrink

    def frame(r: float):
        """The labels placed at reduction ``r`` and the figure's extent (scene mm) and size (page mm)."""
        labels = place_labels(scene, r, roles)
        x0, y0, x1, y1 = scene.bounds()
        for _, _, pl in labels:
            x0, y0 = min(x0, pl.box[0]), min(y0, pl.box[1])
            x1, y1 = max(x1, pl.box[2]), max(y1, pl.box[3])
        pad = 1.5 / r
        x0, y0, x1, y1 = x0 - pad, y0 - pad, x1 + pad, y1 + pad
        return labels, (x0, y0, x1, y1), pad, (x1 - x0) * r, (y1 - y0) * r

    for _ in range(4):                   # the labels' boxes widen the figure: shrink until it fits
        labels, (x0, y0, x1, y1), pad, w_mm, h_mm = frame(r)
        over = max(w_mm / max_w_mm, h_mm / max_h_mm)
        if over <= 1.0 + RTOL_EQUAL:
            break
        r /= over * 1.001
    else:                                # the last reduction's own frame (widened below if need be)
        labels, (x0, y0, x1, y1), pad, w_mm, h_mm = frame(r)
    fig = new_figure(w_mm / 10.0, h_mm / 10.0)
    ax = fig.add_axes([0.0, 0.0, 1.0, 1.0])
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.axis("off")
    for e in scene.entities:
        lw, ls = PENS.get(e.kind, (0.6, "-"))
        if isinstance(e, Segment):
            a, b = np.asarray(e.a), np.asarray(e.b)
            d = float(np.hypot(*(b - a)))
            if d <= sum(e.trim):
                continue
            u = (b - a) / d
            a2, b2 = a + u * e.trim[0], b - u * e.trim[1]
            ax.plot([a2[0], b2[0]], [a2[1], b2[1]], color="black", lw=lw, ls=ls, solid_capstyle="round")
        elif isinstance(e, Polyline):
            xy = np.asarray(e.points)
            if e.closed:
                xy = np.vstack([xy, xy[:1]])
            ax.plot(xy[:, 0], xy[:, 1], color="black", lw=lw, ls=ls)
        elif isinstance(e, Circle):
            _add_patch(ax, MplCircle(e.c, e.r, facecolor="white" if e.hinge else "none", edgecolor="black",
                                   lw=min(lw, 0.8), ls=ls, zorder=4 if e.hinge else 2))
        elif isinstance(e, Arrow):
            a, b = np.asarray(e.a), np.asarray(e.b)
            d = float(np.hypot(*(b - a)))
            if d < MM_ROUNDOFF:
                continue
            colour = COLOURS.get(e.style, "black") if colours else "black"
            head = min(HEAD_MM / r, d)           # a 3 mm head on the page
            u = (b - a) / d
            nrm = np.array([-u[1], u[0]])
            base = b - u * head
            ax.plot([a[0], base[0]], [a[1], base[1]], color=colour, lw=lw, solid_capstyle="butt")
            _add_patch(ax, MplPolygon([b, base + nrm * head / 6, base - nrm * head / 6], closed=True,
                                    facecolor=colour, edgecolor=colour, lw=0.3, zorder=3))
    texts = {}
    for lb, c, _pl in labels:
        if lb.role in FIXED_ROLES:
            texts[id(lb)] = ax.text(c[0], c[1], fixed_text(lb, scene), fontsize=LABEL_PT, ha="center", va="center", zorder=6)
            continue
        t = ax.text(c[0], c[1], _mathtext(lb.text), fontsize=LABEL_PT, ha="center", va="center",
                    style="italic" if lb.role == "point" else "normal",
                    color="tab:blue" if lb.role == "number" else "black", zorder=6)
        texts[id(lb)] = names(t, *(lb.along if lb.role == "vector" and lb.along is not None else (lb.at,)))
    # placed again with the sizes the renderer measures (the estimate misjudges indices and Cyrillic)
    renderer = fig.canvas.get_renderer()
    per_mm = fig.dpi / 25.4 * r                    # display units per scene mm
    index = {id(lb): i for i, lb in enumerate(scene.labels)}
    sizes = {}
    for lb, _, _ in labels:
        bb = texts[id(lb)].get_window_extent(renderer)
        sizes[index[id(lb)]] = (bb.width / per_mm + 0.4 / r, bb.height / per_mm + 0.4 / r)
    labels = place_labels(scene, r, roles, sizes)
    for lb, c, pl in labels:
        texts[id(lb)].set_position((c[0], c[1]))
        if pl.leader:           # the leader is part of what ties the label to its entity
            (bx, by), _ = _leader_end(lb, pl.box)
            ax.plot([bx, lb.at[0]], [by, lb.at[1]], color="0.3", lw=0.4)
            names(texts[id(lb)], (bx, by), lb.at, *(lb.along or ()))
    # the measured boxes may reach past the first estimate's frame: widen the figure (same reduction)
    # so that no label is cut off or runs out of the figure onto the page
    nx0, ny0, nx1, ny1 = x0 + pad, y0 + pad, x1 - pad, y1 - pad
    for _, _, pl in labels:
        nx0, ny0 = min(nx0, pl.box[0]), min(ny0, pl.box[1])
        nx1, ny1 = max(nx1, pl.box[2]), max(ny1, pl.box[3])
    nx0, ny0, nx1, ny1 = nx0 - pad, ny0 - pad, nx1 + pad, ny1 + pad
    if nx0 < x0 or ny0 < y0 or nx1 > x1 or ny1 > y1:
        x0, y0, x1, y1 = min(x0, nx0), min(y0, ny0), max(x1, nx1), max(y1, ny1)
        w_mm, h_mm = (x1 - x0) * r, (y1 - y0) * r
        fig.set_size_inches(w_mm / 25.4, h_mm / 25.4)
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    over = max(w_mm / max_w_mm, h_mm / max_h_mm)
    if over > 1.0 + RTOL_EQUAL and shrink < 2.0:     # larger than its room (the text block): reduce more
        import matplotlib.pyplot as plt
        plt.close(fig)
        return _make_scene_figure(scene, max_w_mm=max_w_mm, max_h_mm=max_h_mm, colours=colours,
                                  roles=roles, key=key, shrink=shrink * over * 1.001)
    fig.reportgen_exact = True
    fig.reportgen_labels = tuple(pl for _, _, pl in labels)
    fig.reportgen_reduction = r
    fig.width_cm = w_mm / 10.0
    fig.scene = scene
    fig.reportgen_key = key          # its content key, where one is read (saving.content_keys_read)
    if key is not None:
        mark_content(fig)
    return fig


def figure_key(scene: Scene, **options) -> str:
    """The content key of the figure of ``scene`` drawn with ``options``: the scene's data, the
    options and the note's language (its catalogue and decimal mark; the code and the libraries'
    versions are added by the build cache, :meth:`reportgen.cache.BuildCache.restore_figure`)."""
    from reportgen.cache import content_digest

    strings = active()
    return content_digest(("scene_figure", scene, sorted(options.items()),
                           strings.language, getattr(strings, "_overlay", None)))
