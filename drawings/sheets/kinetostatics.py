"""Sheet 2 «Силовой расчёт рычажного механизма» (A1): each Assur group (last attached first) and the
crank cut out at μl in the analysed position with their forces (schematic lengths, the note's scenes), the force
polygon of each at its μF (the note's scales and lengths), and Zhukovsky's lever. Every number comes
from :func:`reportgen.kinetostatics.results.kinetostatics_of`."""
from __future__ import annotations

import numpy as np

from drawings.primitives import format_number, ratio_label
from drawings.sheet import Sheet
from reportgen.kinetostatics.graphical import round_scale
from reportgen.scenes.forces import first_detail_indices
from reportgen.project import Project
from reportgen.tolerances import MM_EPS
from ..words import designation, tr

NEEDS: tuple[str, ...] = ("linkage", "structure", "phi", "kinematics", "kinetostatics", "scenes")


def sheet_title() -> str:
    """The sheet's title in the task's language (title block, graph 1)."""
    return tr("sheets.sk201")


def __getattr__(name: str):
    if name == "TITLE":            # the title in the language being drawn
        return sheet_title()
    raise AttributeError(name)


def available(project: Project) -> bool:
    return project.task.mechanism is not None


#: Arrangements tried in turn, each a list of (kind, corner) in packing order: ``lever``, ``bodies``
#: (the groups and the crank cut out), ``polygons``, or ``rows`` (each body followed by its polygon).
ARRANGEMENTS: tuple[tuple[tuple[str, str], ...], ...] = (
    (("lever", "top-right"), ("bodies", "top-left"), ("polygons", "top-left")),
    (("lever", "top-right"), ("rows", "top-left")),
    (("lever", "top-right"), ("bodies", "top-left"), ("polygons", "bottom-left")),
    (("lever", "top-right"), ("bodies", "top-left"), ("polygons", "bottom-right")),
    (("bodies", "top-left"), ("lever", "top-right"), ("polygons", "bottom-left")),
    (("lever", "bottom-right"), ("bodies", "top-left"), ("polygons", "top-left")),
    (("polygons", "bottom-left"), ("lever", "top-right"), ("bodies", "top-left")),
)
#: If the views do not fit at the replica's μl, the groups are drawn at the scheme's extent within
#: these many mm (a smaller round scale, written under them) before giving up.
FALLBACK_SCHEME_MM = (300.0, 200.0, 150.0)


def _try_pack(region, requests, placed) -> list | None:
    """:func:`drawings.layout.pack`, or None when a view does not fit."""
    from drawings.layout import pack
    from reportgen.errors import BuildError
    try:
        return pack(region, requests, placed=placed)
    except BuildError:
        return None


def _room(bounds, obstacles: list, r, axis: int) -> tuple[float, float]:
    """Free room (mm) before and after ``r`` along ``axis`` (0: x, 1: y) up to ``obstacles`` and
    ``bounds``."""
    lo, hi = (r.x0, r.x1) if axis == 0 else (r.y0, r.y1)
    a0, a1 = (r.y0, r.y1) if axis == 0 else (r.x0, r.x1)
    b0, b1 = (bounds.x0, bounds.x1) if axis == 0 else (bounds.y0, bounds.y1)
    before, after = lo - b0, b1 - hi
    for o in obstacles:
        o0, o1, c0, c1 = (o.x0, o.x1, o.y0, o.y1) if axis == 0 else (o.y0, o.y1, o.x0, o.x1)
        if not (c0 < a1 and a0 < c1):
            continue
        if o1 <= lo + MM_EPS:
            before = min(before, lo - o1)
        elif o0 >= hi - MM_EPS:
            after = min(after, o0 - hi)
    return max(before, 0.0), max(after, 0.0)


def _spread(sheet: Sheet, rects: list, placed: list, gap: float = 10.0, rounds: int = 12) -> list:
    """Each rectangle in turn moved to the middle of the room it can slide in along x, then y (sizes
    kept, ``gap`` from the others, inside the free field): the free room shared out, a few rounds."""
    from drawings.layout import Rect
    m = sheet.margin
    bounds = sheet.frame.expanded(-m)
    walls = [sheet.title_rect.expanded(m), sheet.extra_rect.expanded(m)] + [r.expanded(gap) for r in placed]
    out = list(rects)
    for _ in range(rounds):
        moved = 0.0
        for i, r in enumerate(out):
            obstacles = walls + [o.expanded(gap) for j, o in enumerate(out) if j != i]
            for axis in (0, 1):
                before, after = _room(bounds, obstacles, r, axis)
                d = (after - before) / 2.0
                r = Rect(r.x0 + d, r.y0, r.x1 + d, r.y1) if axis == 0 else Rect(r.x0, r.y0 + d, r.x1, r.y1 + d)
                moved = max(moved, abs(d))
            out[i] = r
        if moved < 0.05:
            break
    return out


def arrange(sheet: Sheet, bodies: list, polygons: list, lever, placed: list):
    """Rectangles for the panels (bodies, polygons, lever) by the first of :data:`ARRANGEMENTS` in
    which they all fit, spread over the free field; None if none fits."""
    from drawings.layout import Request
    region = sheet.free_region
    for arrangement in ARRANGEMENTS:
        order = []
        for kind, corner in arrangement:
            if kind == "lever":
                order.append((lever, corner))
            elif kind == "bodies":
                order += [(b, corner) for b in bodies]
            elif kind == "polygons":
                order += [(q, corner) for q in polygons]
            else:
                order += [(x, corner) for pair in zip(bodies, polygons) for x in pair]
        rects = _try_pack(region, [Request(pn.name, pn.width, pn.height, c) for pn, c in order], placed)
        if rects is not None:
            rects = _spread(sheet, rects, placed)
            k = next(i for i, (pn, _) in enumerate(order) if pn is lever)
            rects[k] = _widened(sheet, rects, k, placed)
            return [(pn, r) for (pn, _), r in zip(order, rects)]
    return None


#: The lever's view takes up to this much (mm) of the free room round it on each side: its crowded
#: clusters put names on leaders out there (class3's b, c, d at the edge of its drawing).
LEVER_ROOM_MM = 20.0


def _widened(sheet: Sheet, rects: list, k: int, placed: list, gap: float = 10.0):
    """``rects[k]`` grown into the free room round it, up to :data:`LEVER_ROOM_MM` each side, ``gap``
    from the other views and inside the free field (the drawing stays centred in it)."""
    from drawings.layout import Rect
    m = sheet.margin
    bounds = sheet.frame.expanded(-m)
    walls = [sheet.title_rect.expanded(m), sheet.extra_rect.expanded(m)] + [r.expanded(gap) for r in placed] \
        + [o.expanded(gap) for j, o in enumerate(rects) if j != k]
    r = rects[k]
    left, right = (min(x, LEVER_ROOM_MM) for x in _room(bounds, walls, r, 0))
    r = Rect(r.x0 - left, r.y0, r.x1 + right, r.y1)
    below, above = (min(x, LEVER_ROOM_MM) for x in _room(bounds, walls, r, 1))
    grown = min(below, above)             # as much below as above: the title keeps its place over it
    return Rect(r.x0, r.y0 - grown, r.x1, r.y1 + grown)


def lever_panel_of(project: Project):
    """Zhukovsky's lever of the analysed position as a panel (this sheet's and the control work's), at
    the replica's μv: the scale chosen for the sheet that draws it (``SceneBoxes.lever_for``), which
    the note prints and at which the arms were read."""
    from drawings.scenes import kinetostatics_views as kv
    from reportgen.scenes.lever import lever_scene
    return kv.lever_panel("lever", lever_scene(project.kinetostatics, project.linkage))


def _new_sheet(project: Project, number: int, count: int):
    """The empty sheet with its scale and the line naming the analysed position: (sheet, that view)."""
    from drawings import style
    ks = project.kinetostatics
    sheet = Sheet.a1(project.task.document, title=sheet_title(), code=designation(project.task.document, number), number=number, count=count)
    where = tr("sheets.sk203", v1=ks.position) if ks.position is not None else ""
    note = tr("sheets.sk204", where=where, v2=format_number(ks.phi_deg, 2, strip=False))
    sheet.set_scale(ratio_label(1.0 / (1000.0 * ks.graphical.length_scale)))       # the groups' schemes at μl
    pv = sheet.add_view("position", style.text_width(note, 5.0) + 4.0, 9.0, preferred="top-left")
    pv.text_mm((pv.rect.x0 + 2.0, pv.rect.y0 + 2.0), note, 5.0)
    return sheet, pv


def _polygon_panels(project: Project) -> list:
    from drawings.scenes import kinetostatics_views as kv
    g = project.kinetostatics.graphical
    by_key = {gr.key: gr for gr in project.structure.groups}
    firsts = first_detail_indices([gg.polygon for gg in g.groups] + [g.crank.polygon])
    polygons = [kv.polygon_panel(f"polygon {gg.key}", tr("sheets.sk205", v1=by_key[gg.key].label), gg.polygon, first)
                for gg, first in zip(g.groups, firsts)]
    polygons.append(kv.polygon_panel("polygon crank", tr("sheets.sk206"), g.crank.polygon, firsts[-1]))
    return polygons


def _body_panels(project: Project, mu_l: float) -> list:
    """The groups and the crank cut out at ``mu_l`` (the replica's, or a fallback)."""
    from drawings.scenes import kinetostatics_views as kv
    by_key = {gr.key: gr for gr in project.structure.groups}
    fbs = project.scenes.free_bodies if mu_l == project.kinetostatics.graphical.length_scale \
        else project.scenes.free_bodies_at(mu_l)
    return [kv.free_body_panel("crank" if fb.key == "crank" else f"group {fb.key}",
                               tr("sheets.sk207") if fb.key == "crank" else tr("sheets.sk208", v1=by_key[fb.key].label),
                               fb.scene) for fb in fbs]


def lever_fits(project: Project, lever) -> bool:
    """Does the lever's panel ``lever`` find room on this sheet beside the groups (at the replica's μl)
    and the polygons? (The lever's μv is chosen in the core; tests/scenes/test_lever_scale.py asks this
    of the lever one round step larger: it must not fit, so that the lever is as large as the sheet
    holds.)"""
    sheet, pv = _new_sheet(project, 2, 4)
    bodies = _body_panels(project, project.kinetostatics.graphical.length_scale)
    return arrange(sheet, bodies, _polygon_panels(project), lever, [pv.rect]) is not None


def draw(project: Project, number: int, count: int) -> Sheet:
    ks = project.kinetostatics
    g = ks.graphical
    sheet, pv = _new_sheet(project, number, count)
    polygons = _polygon_panels(project)
    lever = lever_panel_of(project)
    kin = ks.reactions.kin

    # the groups at the replica's μl (the note's); a smaller round scale only if nothing else fits
    pts = np.array([np.asarray(m.pos)[0] for m in kin.points.values()])
    extent = float(np.hypot(*np.ptp(pts, axis=0)))
    scales = [g.length_scale] + [mu for mu in (round_scale(extent, mm) for mm in FALLBACK_SCHEME_MM)
                                 if mu > g.length_scale]
    for mu_l in scales:
        bodies = _body_panels(project, mu_l)
        layout = arrange(sheet, bodies, polygons, lever, [pv.rect])
        if layout is not None:
            break
    else:   # let the packer name the view that does not fit
        for pn, corner in [(lever, "top-right")] + [(b, "top-left") for b in bodies] + \
                [(q, "bottom-left") for q in polygons]:
            pn.place(sheet, corner)
        return sheet
    for pn, rect in layout:
        pn.paint(sheet, rect)
    return sheet
