"""Sheet 1, the plans: the velocity and acceleration plans of the analysed position (pole, every
component of :func:`reportgen.plans.build_plans` as an arrow between its plan points with its
name, the absolute vectors from the pole, the plan letters, the scale caption) and the velocity
plans of all positions in small form."""
from __future__ import annotations

import math
from dataclasses import dataclass

from shapely.geometry import LineString, Point, Polygon, box
from shapely.ops import nearest_points

from drawings import style
from drawings.layout import Rect
from drawings.primitives import Transform, format_significant
from drawings.sheet import Sheet, View
from reportgen.geometry import vec2
from drawings.scenes import kinematics_labels as rl
from reportgen.tolerances import MM_ROUNDOFF
from reportgen.plans import Plan
from ..words import tr
from ..words import unit as words_unit
from reportgen.scenes.plans import UNITS, plan_scene
from reportgen.scenes.scene import Arrow, Scene

from drawings.scenes import render
from drawings.scenes.kinetostatics_views import place_vector_names

#: Room for letters and names around a plan's points, and the caption / title strips, mm (the core's:
#: it arranges sheet 1 with these sizes, reportgen.scenes.arrangement.plan_view_size).
from reportgen.scenes.boxes import PLAN_MIN_WIDTH_MM, PLAN_PAD_MM as PAD_LABELS, PLAN_STRIP_MM as STRIP  # noqa: E402
#: Points of a plan closer than this (mm) share one label.
SAME_MM = 0.3



def pole(plan: Plan) -> str:
    return "p" if plan.kind == "velocity" else "π"


def helpers(plan: Plan, image_keys: set[str]) -> set[str]:
    """Plan points that are not images of mechanism points (ends of normal/Coriolis parts)."""
    return {k for k in plan.points if k not in image_keys and k != pole(plan)}


#: The bounds of a plan's points, mm from its pole (the core's).
from reportgen.scenes.small_plans import plan_extent as extent  # noqa: E402


def view_size(plan: Plan, title: str) -> tuple[float, float, tuple[float, float]]:
    """Width, height and the model point at the lower-left corner of a plan's view."""
    x0, y0, x1, y1 = extent(plan)
    w = max(x1 - x0 + 2 * PAD_LABELS, style.text_width(title, 5.0) + 10.0, PLAN_MIN_WIDTH_MM)
    h = y1 - y0 + 2 * PAD_LABELS + 2 * STRIP
    cx = (x0 + x1) / 2
    return w, h, (cx - w / 2, y0 - PAD_LABELS - STRIP)


def label_region(view: View, small: bool) -> Polygon:
    """Where letters and names may go: the view less its caption and title strips."""
    r = view.rect
    strip = 6.0 if small else STRIP
    return box(r.x0, r.y0 + (0.0 if small else strip), r.x1, r.y1 - strip)


@dataclass(frozen=True)
class Drawn:
    """An arrow drawn in a plan view, for the tests: the component's name, start and end (mm)."""
    name: str
    start: tuple[float, float]
    end: tuple[float, float]


def draw_plan(view: View, plan: Plan, image_keys: set[str], title: str, *, names: bool = True,
              letter_height: float = 5.0, small: bool = False, scene: Scene | None = None,
              letters: set[str] | None = None) -> list[Drawn]:
    """The plan's scene (:func:`reportgen.scenes.plans.plan_scene`) in ``view`` (model = plan mm);
    a ``small`` plan carries only the plan letters in ``letters`` (all if None) and the vectors
    ending at them. Returns the arrows drawn."""
    scene = scene if scene is not None else plan_scene(plan, image_keys)
    helper = helpers(plan, image_keys)
    symbol, unit, _ = UNITS[plan.kind]
    unit = words_unit(unit)
    if small:
        view.text_mm((view.rect.x0 + 2.0, view.rect.y1 - 1.0), title, 3.5, "top-left")
    else:
        scale = scene.scale()
        caption = f"{scale.symbol} = {format_significant(scale.value, 4)} {words_unit(scale.unit)}"
        view.text_mm((view.rect.center[0], view.rect.y0 + 4.0), caption, 5.0, "bottom-center")
        view.title(title)
    head = 3.5 if small else 5.0
    arrows = [e for e in scene.entities if isinstance(e, Arrow)]
    if small and letters is not None:         # no vector ends at a point left unlettered (s_k)
        ends = [plan.points[k] for k in plan.points if k in letters]
        arrows = [e for e in arrows if any(math.dist(e.b, q) < SAME_MM for q in ends)]
    render.draw_entities(view, arrows, head_mm=head)
    drawn = [Drawn(e.id, e.a, e.b) for e in arrows]
    # letters at the points
    inside = label_region(view, small)
    if small:
        place_small_letters(view, scene, helper, letter_height, inside, letters)
    others = [view.transform(lb.at) for lb in scene.labels if lb.role == "point"]
    for lb in scene.labels if not small else ():
        if lb.role != "point":
            continue
        keys = lb.anchor.split(":", 1)[1].split(",")
        label = tuple(rl.from_letter(k, helpers=k in helper) for k in keys)
        p = view.transform(lb.at)
        rl.place_point_label(view, p, label, letter_height, 45.0, others, inside=inside, cross=0)
    # names of the components along their arrows
    if names:
        named = [(lb, view.transform(lb.along[0]), view.transform(lb.along[1])) for lb in scene.labels
                 if lb.role == "vector" and lb.along is not None]
        named = [(lb, a, b) for lb, a, b in named if math.dist(a, b) >= 1.0]
        rivals = tuple(LineString([a, b]) for _, a, b in named)     # each name nearer its own vector
        place_vector_names(view, [(a, b, rl.from_tex(lb.text), False) for lb, a, b in named], 3.5, inside, rivals)
    return drawn


def add_plan_view(sheet: Sheet, name: str, plan: Plan, image_keys: set[str], title: str,
                  preferred: str) -> tuple[View, list[Drawn]]:
    w, h, origin = view_size(plan, title)
    view = sheet.add_view(name, w, h, preferred=preferred, scale=1.0, origin=origin)
    return view, draw_plan(view, plan, image_keys, title)


def place_plan_view(sheet: Sheet, name: str, plan: Plan, image_keys: set[str], title: str,
                    rect: Rect) -> tuple[View, list[Drawn]]:
    """The plan in a given rectangle (at least :func:`view_size`), its drawing centred in it."""
    w, h, origin = view_size(plan, title)
    ox = origin[0] - (rect.width - w) / 2
    oy = origin[1] - (rect.height - h) / 2
    view = sheet.place_view(name, rect, Transform(1.0, (ox, oy), (rect.x0, rect.y0)))
    return view, draw_plan(view, plan, image_keys, title)


#: The small plans: points closer than this on paper share one label (mm; letters 3,5 mm high
#: cannot tell them apart), a label is "at" its point within ``SMALL_NEAR_MM`` of it, farther
#: ones (up to ``SMALL_FAR_MM``) get a thin leader from the point to the label.
SMALL_CLUSTER_MM, SMALL_NEAR_MM, SMALL_FAR_MM = 2.5, 3.0, 18.0
#: A cluster of more letters is labelled in pieces of this many (each placed on its own).
SMALL_LETTERS = 4
#: A leader stops this short of its point (mm), where the plan's vectors meet: it must cross none
#: of them on its way.
LEADER_GAP_MM = 0.8
#: Where no leader crossing no vector reaches a free spot (a point inside a tight triangle of
#: vectors), the leader may cross this many: a thin line over a vector reads, a letter on it not.
LEADER_CROSSINGS = 3


def letter_clusters(scene: Scene, view: View, letters: set[str] | None = None
                    ) -> list[tuple[tuple[float, float], list[str]]]:
    """The point labels of a small plan merged where their points are within ``SMALL_CLUSTER_MM``
    on paper (single linkage, in the scene's order): (sheet point of the first, plan letters);
    only the plan letters in ``letters`` (all if None), a point with none of them unlabelled."""
    items = []
    for lb in scene.labels:
        if lb.role != "point":
            continue
        keys = [k for k in lb.anchor.split(":", 1)[1].split(",") if letters is None or k in letters]
        if keys:
            items.append((view.transform(lb.at), keys))
    parent = list(range(len(items)))

    def root(k: int) -> int:
        while parent[k] != k:
            k = parent[k]
        return k
    for a in range(len(items)):
        for b in range(a + 1, len(items)):
            if math.dist(items[a][0], items[b][0]) < SMALL_CLUSTER_MM:
                parent[root(b)] = root(a)
    out: dict[int, tuple[tuple[float, float], list[str]]] = {}
    for k, (p, keys) in enumerate(items):
        r = root(k)
        if r in out:
            out[r][1].extend(keys)
        else:
            out[r] = (vec2(p), list(keys))
    return list(out.values())


def place_small_letters(view: View, scene: Scene, helper: set[str], height: float, inside: Polygon,
                        letters: set[str] | None = None) -> int:
    """Letters of a small plan (only ``letters``, if given): each cluster of points
    (:func:`letter_clusters`, in pieces of ``SMALL_LETTERS``) labelled beside it (within
    ``SMALL_NEAR_MM``, nearer to it than to the other labelled points) where it overlaps no text,
    crosses no line and stays in the cell; else farther (up to ``SMALL_FAR_MM``) on a thin leader
    from the point that crosses no line (else no more than ``LEADER_CROSSINGS``) and no text;
    else beside it with the fewest
    conflicts (never left out). Returns how many labels found no clean place (0: every letter
    legible; tests/sheet1 checks the drawn sheet)."""
    clusters = letter_clusters(scene, view, letters)
    others = [p for p, _ in clusters]
    chunks = [(p, keys[n:n + SMALL_LETTERS]) for p, keys in clusters
              for n in range(0, len(keys), SMALL_LETTERS)]
    unclean = 0
    for p, keys in chunks:
        label = tuple(rl.from_letter(k, helpers=k in helper) for k in keys)
        if not _small_label(view, p, label, height, inside, others):
            unclean += 1
    return unclean


def _clean(view: View, poly: Polygon, inside: Polygon) -> bool:
    """Is a label's box ``poly`` within ``inside``, over no text and crossed by no line?"""
    ann = view.annotations
    return inside.contains(poly) and not ann.hits_box(poly) and not ann.crossings(poly)


def _small_label(view: View, p: tuple[float, float], label: rl.Label, height: float, inside: Polygon,
                 others: list[tuple[float, float]]) -> bool:
    """One small plan's label at sheet point ``p`` (see :func:`place_small_letters`); False where
    it had to overlap or cross something."""
    ann = view.annotations
    near = rl.own_point(rl.around(p, label, height, 45.0, gaps=(0.6, 1.2, 2.0)), label, height, p, others,
                        SMALL_NEAR_MM)
    for c in near:
        if _clean(view, rl.rich_box(label, c, height), inside):
            rl.draw_rich(view, c, label, height, names=Point(p))
            return True
    far = rl.around(p, label, height, 45.0, gaps=(4.0, 6.0, 9.0, 12.0, 15.0, SMALL_FAR_MM))
    for crossed in (0, LEADER_CROSSINGS):        # a leader over no vector, else over a few of them
        for c in far:
            poly = rl.rich_box(label, c, height)
            if not _clean(view, poly, inside):
                continue
            q = nearest_points(rl.text_extent(label, c, height), Point(p))[0]     # from the letters
            d = q.distance(Point(p))
            if d <= LEADER_GAP_MM + MM_ROUNDOFF:
                continue
            t = LEADER_GAP_MM / d
            foot = (p[0] + (q.x - p[0]) * t, p[1] + (q.y - p[1]) * t)
            leader = LineString([(q.x, q.y), foot])
            if ann.crossings(leader) > crossed or ann.hits_box(leader.buffer(0.2)):
                continue
            if any(Point(o).distance(leader) < 1.0 for o in others if math.dist(o, p) > MM_ROUNDOFF):
                continue                       # a leader past another point would name it
            rl.draw_rich(view, c, label, height, names=LineString([(q.x, q.y), p]))
            view.line(view.transform.inverse((q.x, q.y)), view.transform.inverse(p), "thin")
            return True
    fallback = near or rl.around(p, label, height, 45.0, gaps=(0.6, 1.2, 2.0))
    rl.place_passes(view, [(fallback, 0), (fallback, 1)], label, height, inside=inside, names=Point(p))
    return False


#: The small plans' view: title and caption strips, a second title line, the letters' height, mm
#: (the core's: it reserves their block with these, reportgen.scenes.small_plans).
from reportgen.scenes.lettering import SMALL_TITLE_H, SMALL_TITLE_PAD_MM  # noqa: E402
from reportgen.scenes.small_plans import (SMALL_CAPTION_MM, SMALL_TITLE_LINE_MM, SMALL_TITLE_MM,  # noqa: E402,F401
                                          small_cell, title_strip)


def small_title(plans: list[Plan]) -> str:
    return tr("sheets.kp01", v1=len(plans) - 1)


def title_lines(text: str, width: float, height: float = SMALL_TITLE_H) -> list[str]:
    """``text`` in one line if it fits ``width`` (less ``SMALL_TITLE_PAD_MM``), else split at the
    space that makes the longer of two lines shortest (the core reserves the room by the same rule,
    reportgen.scenes.lettering.title_lines)."""
    if style.text_width(text, height) + SMALL_TITLE_PAD_MM <= width or " " not in text:
        return [text]
    words = text.split(" ")
    splits = [(" ".join(words[:k]), " ".join(words[k:])) for k in range(1, len(words))]
    return list(min(splits, key=lambda ab: max(style.text_width(t, height) for t in ab)))


def small_title_strip(lines: list[str]) -> float:
    return title_strip(len(lines))


def small_caption(plans: list[Plan]) -> str:
    return tr("sheets.kp02", v1=format_significant(plans[0].scale, 4))


def place_small_plans(sheet: Sheet, plans: list[Plan], image_keys: set[str], cols: int,
                      rect: Rect, letters: set[str] | None = None) -> View:
    """All velocity plans in ``rect``, a grid of ``cols`` equal cells numbered by position, the
    cells sharing out the rectangle; each cell a canvas of its own (``plans_all/<position>``), the
    plans lettered with ``letters`` only (all plan letters if None)."""
    holder = sheet.place_view("plans_all", rect, Transform())
    lines = title_lines(small_title(plans), rect.width)
    for k, line in enumerate(lines):     # the title, in two lines if the grid is narrower than it
        holder.text_mm((rect.center[0], rect.y1 - SMALL_TITLE_H - 1.0 - k * SMALL_TITLE_LINE_MM), line,
                       SMALL_TITLE_H, "bottom-center")
    holder.text_mm((rect.center[0], rect.y0 + 4.0), small_caption(plans), SMALL_TITLE_H, "bottom-center")
    strip = small_title_strip(lines)
    n = len(plans)
    rows = math.ceil(n / cols)
    cw = rect.width / cols
    ch = (rect.height - strip - SMALL_CAPTION_MM) / rows
    for i, plan in enumerate(plans):
        r, c = divmod(i, cols)
        x0 = rect.x0 + c * cw
        y1 = rect.y1 - strip - r * ch
        cell = Rect(x0, y1 - ch, x0 + cw, y1)
        e = extent(plan)
        cx, cy = (e[0] + e[2]) / 2, (e[1] + e[3]) / 2
        tr = Transform(1.0, (cx, cy), ((cell.x0 + cell.x1) / 2, (cell.y0 + cell.y1 - 5.0) / 2))
        sub = View(sheet, f"plans_all/{i}", cell, tr)
        draw_plan(sub, plan, image_keys, f"{i}", names=False, letter_height=3.5, small=True, letters=letters)
    return holder
