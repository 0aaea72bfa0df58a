"""Sheet 1, the kinematic scheme: the mechanism in every analysed position at a ГОСТ 2.302 scale,
position 0 and the analysed position bold (symbols and letters), the others thin and numbered, the
extreme position of the end of the working stroke (dash-two-dots), the trajectories of the centres
of mass and of the crank pin, the stroke H of the slider and the crank angles of the strokes."""
from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import LineString, MultiLineString, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.geometry import Point as ShapelyPoint
from shapely.ops import nearest_points

from drawings import style
from drawings.primitives import format_number, format_significant
from drawings.sheet import View
from drawings.scenes import kinematics_labels as rl
from drawings.scenes import render
from reportgen.geometry import vec2
from reportgen.kinematics import KinematicsResult
from reportgen.project import Project
from reportgen.scenes import positions
from reportgen.scenes.boxes import SCHEME_CAPTION_STRIP_MM, SCHEME_TITLE_STRIP_MM
from reportgen.scenes.positions import BLOCK_MM, SchemeData
from reportgen.scenes.scales import GOST_SCALES, gost_scale  # noqa: F401  (re-exported for the sheet)
from reportgen.scenes.scene import Polyline, Scene, Segment
from reportgen.tolerances import ABS_ROUNDOFF, MM_ROUNDOFF, RTOL_EQUAL

from ..words import tr
#: Link numbers: radius of the circle, text height, mm.
LINK_NUMBER_MM = (2.8, 3.5)
#: The room (mm) the scheme's names keep beyond their boxes' padding: from the other names (their
#: letters at least NAME_GAP_MM apart: more than the word space of ГОСТ 2.304, 0,6·h, so that
#: «A» and the position number «2» beside it do not read as one name «A 2», issue 12) and from the
#: drawn lines (a letter set tight against the crank read as crossed).
NAME_CLEAR = (1.5, 0.5)
NAME_GAP_MM = 1.0 + NAME_CLEAR[0]


def scheme_data(project: Project, analysed: int) -> SchemeData:
    """The scheme's data (the project's, when ``analysed`` is the project's analysed position)."""
    if analysed == project.analysed:
        return project.scenes.scheme_data
    return positions.scheme_data(project, analysed)


def bounds(data: SchemeData, linkage=None) -> tuple[float, float, float, float]:
    """Model bounds of everything the view draws (m); with ``linkage``, the crank circle's too."""
    return positions.bounds(data, linkage)


def _pts(kin: KinematicsResult, i: int) -> dict[str, np.ndarray]:
    return positions.pts(kin, i)


def _guide_dir(kin: KinematicsResult, i: int, slide) -> np.ndarray:
    return positions.guide_dir(kin, i, slide)


# ---------------------------------------------------------------------------------------------


def draw_scheme(view: View, project: Project, data: SchemeData, scale_text: str, mu_l: float,
                scene: Scene | None = None) -> Scene:
    """The plan of positions: the scene (``project.scenes.positions`` at the view's scale) drawn,
    then the sheet's own annotations (crank angles, stroke, letters, numbers). Returns the scene."""
    k = view.transform.scale
    if scene is None:
        scene = project.scenes.positions
        if abs(scene.scale().value * k - 1.0) > RTOL_EQUAL:
            scene = project.scenes.positions_at(k, scale_text)
    render.draw_scene(view, scene, unit=1.0 / k)
    links = scene_links(view, scene, k)
    _draw_crank_angles(view, project, data, links)
    _draw_stroke(view, project, data, links)
    _draw_letters(view, scene, k, links)
    _draw_numbers(view, project, scene, k, links)
    _draw_link_numbers(view, project, data, links)
    caption = tr("sheets.ks01", v1=format_significant(mu_l, 4), scale_text=scale_text)
    width = style.text_width(caption, 5.0)      # lettered down to 3.5 mm where the view is narrower (A3)
    height = 5.0 if width <= view.rect.width - 4.0 else max(3.5, 5.0 * (view.rect.width - 4.0) / width)
    view.text_mm((view.rect.center[0], view.rect.y0 + 4.0), caption, height, "bottom-center")
    if project.task.document.kind == "control-work":
        phi = math.degrees(float(data.kin.phi[data.analysed])) % 360.0
        cw = project.task.control_work
        key = "control.sheet.scheme_title_a3" if cw is not None and cw.sheet == "A3" else "control.sheet.scheme_title"
        view.title(tr(key, phi=format_number(phi, 2)))
    else:
        view.title(tr("sheets.ks02", v1=len(data.kin.phi)))
    return scene


def scene_links(view: View, scene: Scene, k: float) -> BaseGeometry:
    """The links of every position as drawn (the bars, cut at their hinges, and the sliders'
    blocks), sheet mm, prepared: the scheme's labels never lie on them (issue 12: the shaper's
    «φх.х.» under its rocker), tests/sheet1/legibility.py reads the same lines back."""
    def at(p):
        return view.transform((p[0] / k, p[1] / k))
    lines = []
    for e in scene.entities:
        if isinstance(e, Segment) and ":link" in e.id:
            a, b = at(e.a), at(e.b)
            d = math.dist(a, b)
            if d > e.trim[0] + e.trim[1]:
                u = ((b[0] - a[0]) / d, (b[1] - a[1]) / d)
                lines.append(LineString([(a[0] + u[0] * e.trim[0], a[1] + u[1] * e.trim[0]),
                                         (b[0] - u[0] * e.trim[1], b[1] - u[1] * e.trim[1])]))
        elif isinstance(e, Polyline) and ":block" in e.id:
            pts = [at(p) for p in e.points]
            lines.append(LineString(pts + ([pts[0]] if e.closed else [])))
    links = MultiLineString(lines)
    shapely.prepare(links)
    return links


def _inside(view: View) -> Polygon:
    """Where labels may go: the view less its title and caption strips."""
    r, bottom, top = view.rect, SCHEME_CAPTION_STRIP_MM, SCHEME_TITLE_STRIP_MM
    return Polygon([(r.x0, r.y0 + bottom), (r.x1, r.y0 + bottom), (r.x1, r.y1 - top), (r.x0, r.y1 - top)])


def _link_outline(names: tuple[str, ...]) -> list[tuple[str, str]]:
    return positions.link_outline(names)


def _towards_links(project: Project, data: SchemeData, link: int, point: str) -> np.ndarray:
    return positions.towards_links(project.linkage, data, link, point)


def _arc_points(o: np.ndarray, r: float, a0: float, sweep: float, n: int = 60) -> list[tuple[float, float]]:
    return [(o[0] + r * math.cos(a0 + sweep * t / n), o[1] + r * math.sin(a0 + sweep * t / n)) for t in range(n + 1)]


def _draw_crank_angles(view: View, project: Project, data: SchemeData, links: BaseGeometry | None = None) -> None:
    """The crank's extreme lines and two arcs: φр.х. (start → end in the direction of rotation)
    and φх.х., each with an arrowhead and its value in degrees."""
    st = project.strokes
    if st is None or data.extremes is None:
        return
    lk = project.linkage
    o = _pts(data.kin, 0)[lk.drive_axis]
    k = view.transform.scale
    r_mm = float(np.hypot(*(_pts(data.kin, 0)[lk.drive_tip] - o))) * k
    sgn = 1.0 if project.model.omega >= 0 else -1.0
    a_start = math.atan2(*(np.asarray(data.extremes.points[lk.drive_tip].pos[0]) - o)[::-1])
    a_end = math.atan2(*(np.asarray(data.extremes.points[lk.drive_tip].pos[1]) - o)[::-1])
    for a in (a_start, a_end):
        ray_end = o + (r_mm + 22.0) / k * np.array([math.cos(a), math.sin(a)])
        view.line(o, tuple(ray_end), "thin")
    work = math.radians(st.working_deg)
    arcs = ((a_start, sgn * work, r_mm + 12.0, tr("sheets.ks03", v1=format_number(st.working_deg, 1))),
            (a_end, sgn * (2 * math.pi - work), r_mm + 18.0, tr("sheets.ks04", v1=format_number(st.idle_deg, 1))))
    for a0, sweep, rad_mm, text in arcs:
        pts = _arc_points(o, rad_mm / k, a0, sweep)
        view.polyline(pts, "thin")
        tip = view.transform(pts[-1])
        prev = view.transform(pts[-3])
        view.arrowhead_mm(tip, (tip[0] - prev[0], tip[1] - prev[1]), 4.0, 1.3, "thin")
        _place_arc_label(view, [view.transform(q) for q in pts], view.transform(tuple(o)), rl.Rich(text), links)


#: Gaps between a position number and its crank pin tried, mm (outside the crank circle).
NUMBER_GAPS_MM = (1.0, 2.5, 4.5)
#: Leaders of the position numbers where no spot beside the pin is free, mm.
NUMBER_LEADER_MM = (6.0, 9.0, 12.0, 16.0)
#: Leaders of the scheme's letters where no spot beside the point keeps off the links, mm.
LETTER_LEADER_MM = (8.0, 11.0, 14.0, 18.0, 23.0, 28.0)
#: Where along its arc a crank angle's value is tried (fractions of the sweep, the middle first).
ARC_LABEL_AT = (0.5, 0.42, 0.58, 0.34, 0.66, 0.26, 0.74, 0.18, 0.82, 0.1, 0.9)
#: Gaps between the arc and its value tried, mm (all along the arc at one gap before the next).
ARC_LABEL_GAPS_MM = (1.0, 3.0, 6.0)
#: Lengths of the leader tried, where no spot beside the arc is free of the links' lines (mm), and
#: how far short of the arc a leader's crossings are counted (it ends on the arc).
ARC_LEADER_MM, ARC_LEADER_GAP_MM = (8.0, 12.0, 16.0, 20.0, 25.0), 0.6


def _place_arc_label(view: View, arc: list[tuple[float, float]], centre: tuple[float, float],
                     rich: rl.Rich, links: BaseGeometry | None = None) -> None:
    """The value of a crank angle (φр.х., φх.х.) beside its arc (sheet points ``arc`` round the
    crank's axis ``centre``): beside the arc, at the middle first, then towards its ends, outside
    the arc first, the nearest gap first, where it overlaps no text and crosses no line — the links of the positions
    fan across a crank circle (issue 12: the shaper's «φх.х.» under its rocker); else farther out
    on a thin leader ending on the arc that crosses no line and no text; else beside the middle
    crossing the fewest. The label names its arc (the sheet's label check measures it)."""
    height, inside, ann = 3.5, _inside(view), view.annotations
    line = LineString(arc)
    n = len(arc) - 1
    spots = []
    for t in ARC_LABEL_AT:
        q = arc[round(t * n)]
        out = math.degrees(math.atan2(q[1] - centre[1], q[0] - centre[0]))
        spots.append((q, out))
    beside = [c for gap in ARC_LABEL_GAPS_MM for q, out in spots for c in rl.around(q, rich, height, out, gaps=(gap,))]
    if rl.place_passes(view, [(beside, 0)], rich, height, inside=inside, optional=True, names=line,
                       avoid=links) is not None:
        return
    for length in ARC_LEADER_MM:
        for q, out in spots:
            for turn in (0.0, 20.0, -20.0, 40.0, -40.0):
                a = math.radians(out + turn)
                end = (q[0] + length * math.cos(a), q[1] + length * math.sin(a))
                c = rl.around(end, rich, height, out + turn, gaps=(0.0,))[0]
                poly = rl.rich_box(rich, c, height)
                if not inside.contains(poly) or ann.hits_box(poly) or ann.crossings(poly):
                    continue
                foot = nearest_points(rl.text_extent(rich, c, height), ShapelyPoint(q))[0]
                d = foot.distance(ShapelyPoint(q))
                if d <= ARC_LEADER_GAP_MM:
                    continue
                k = ARC_LEADER_GAP_MM / d
                near_q = (q[0] + (foot.x - q[0]) * k, q[1] + (foot.y - q[1]) * k)
                leader = LineString([(foot.x, foot.y), near_q])
                if ann.crossings(leader) or ann.hits_box(leader.buffer(0.2)):
                    continue
                rl.draw_rich(view, c, rich, height, names=LineString([(foot.x, foot.y), q]))
                view.line(view.transform.inverse((foot.x, foot.y)), view.transform.inverse(q), "thin")
                return
    rl.place_passes(view, [(beside, 0), (beside, 1)], rich, height, inside=inside, names=line, avoid=links)


def _draw_stroke(view: View, project: Project, data: SchemeData, links: BaseGeometry | None = None) -> None:
    """The stroke H of a slider, dimensioned between its extreme positions (beyond the guide)."""
    st = project.strokes
    if st is None or data.extremes is None:
        return
    out = st.output
    if out.point is None:
        return
    if out.kind != "slider":
        piv = np.asarray(data.extremes.points[out.point].pos[0])
        rich = rl.Rich(f"ψ = {format_number(math.degrees(st.stroke), 1)}°")
        rl.place_rich(view, rl.around(view.transform(tuple(piv)), rich, 3.5, -45.0, gaps=(12.0, 16.0, 20.0)),
                      rich, 3.5, inside=_inside(view), avoid=links)
        return
    p0 = np.asarray(data.extremes.points[out.point].pos[0])
    p1 = np.asarray(data.extremes.points[out.point].pos[1])
    d = p1 - p0
    if d[0] < -ABS_ROUNDOFF or (abs(d[0]) <= ABS_ROUNDOFF and d[1] < 0):
        p0, p1, d = p1, p0, -d          # read from the left (text not upside down)
    n = np.array([-d[1], d[0]]) / (np.hypot(*d) or 1.0)
    # beyond the guide, away from the coupler: the left of p0→p1 (offset > 0) or its right
    side = -1.0 if np.dot(_towards_links(project, data, out.link, out.point), n) > 0 else 1.0
    view.dimension(tuple(p0), tuple(p1), offset_mm=side * (BLOCK_MM[1] / 2 + 14.0), unit_factor=1000.0,
                   text=f"H = {format_number(st.stroke * 1000.0, 1)}")


def _draw_letters(view: View, scene: Scene, k: float, links: BaseGeometry | None = None) -> None:
    """The scene's letters: the points of the analysed position, the moving points of position 0
    with index 0, the centres of mass S_k — each beside its point, away from the mechanism's middle,
    crossed by no line (a link, a hinge, a pivot's base, the crank pin's circle: issue 12, the
    control work's «A» on its crank circle), else on a thin leader."""
    pts = [lb.at for lb in scene.labels if lb.role == "point"]
    cx = sum(p[0] for p in pts) / max(len(pts), 1) / k
    cy = sum(p[1] for p in pts) / max(len(pts), 1) / k
    c = view.transform((cx, cy))
    others = [view.transform((lb.at[0] / k, lb.at[1] / k)) for lb in scene.labels
              if lb.role in ("point", "number")]
    for lb in scene.labels:
        if lb.role != "point":
            continue
        p = view.transform((lb.at[0] / k, lb.at[1] / k))
        rich = rl.from_tex(lb.text)
        prefer = 90.0 if lb.text.startswith("S_") else math.degrees(math.atan2(p[1] - c[1], p[0] - c[0]))
        rl.place_point_label(view, p, rich, 5.0, prefer, others, inside=_inside(view), avoid=links,
                             far_gaps=LETTER_LEADER_MM, cross=0, clear=NAME_CLEAR)


def _draw_numbers(view: View, project: Project, scene: Scene, k: float, links: BaseGeometry | None = None) -> None:
    """The scene's position numbers at the crank pin, outside the crank circle first, nearer to
    their pin than to any other labelled point, off the links, crossed by no line and NAME_GAP_MM
    clear of the other names; where no such spot is free, on a thin leader from the pin
    (:func:`drawings.scenes.kinematics_labels.place_point_label`, ``cross=0``)."""
    from reportgen.tolerances import LABEL_NEAR_MM
    lk = project.linkage
    o = view.transform(tuple(_pts(project.scenes.scheme_data.kin, 0)[lk.drive_axis]))
    pins = [view.transform((lb.at[0] / k, lb.at[1] / k)) for lb in scene.labels if lb.role in ("number", "point")]
    inside = _inside(view)
    for lb in scene.labels:
        if lb.role != "number":
            continue
        p = view.transform((lb.at[0] / k, lb.at[1] / k))
        text = lb.text
        if lb.anchor.startswith("extreme1:") and text != "0'":
            text = tr("sheets.ks05")
        elif lb.anchor.startswith("extreme0:"):
            text = tr("sheets.ks06")
        ang = math.degrees(math.atan2(p[1] - o[1], p[0] - o[0]))
        rich = rl.Rich(text)
        cands = rl.around(p, rich, 3.5, ang, gaps=NUMBER_GAPS_MM)
        r = math.dist(p, o)
        cands = [q for q in cands if math.dist(q, o) > r] + [q for q in cands if math.dist(q, o) <= r]
        near = rl.own_point(cands, rich, 3.5, p, pins, LABEL_NEAR_MM - 1.0)
        if near and rl.place_passes(view, [(near, 0)], rich, 3.5, inside=inside, optional=True,
                                    names=ShapelyPoint(p), avoid=links, strict=True, clear=NAME_CLEAR) is not None:
            continue
        rl.place_point_label(view, p, rich, 3.5, ang, pins, inside=inside, avoid=links, far_gaps=NUMBER_LEADER_MM,
                             clear=NAME_CLEAR, cross=0)        # never crossed: on a leader where need be


def _link_number_spots(view: View, project: Project, data: SchemeData, k: int, i: int) -> list[tuple[float, float]]:
    """Candidate centres (sheet mm) of link ``k``'s number in position ``i``: beside its
    segments, from their middles towards the ends, on either side; round a slider's block."""
    lk = project.linkage
    pts = {n: view.transform(tuple(p)) for n, p in _pts(data.kin, i).items()}
    names = lk.bodies[k].points
    r = LINK_NUMBER_MM[0]
    out: list[tuple[float, float]] = []
    if len(names) >= 2:
        segs = _link_outline(names)
        for off in (r + 1.5, r + 3.5, r + 6.0):
            for t in (0.5, 0.38, 0.62, 0.28, 0.72, 0.2, 0.8):
                for a, b in segs:
                    pa, pb = np.asarray(pts[a]), np.asarray(pts[b])
                    d = pb - pa
                    n = float(np.hypot(*d))
                    if n < 4 * r:
                        continue
                    u = d / n
                    nrm = np.array([-u[1], u[0]])
                    for side in (1.0, -1.0):
                        q = pa + d * t + side * nrm * off
                        out.append((float(q[0]), float(q[1])))
        return out
    slide = next((sl for sl in lk.slides if sl.link == k), None)
    p = np.asarray(pts[names[0]])
    if slide is None:
        return [vec2(c) for c in rl.around(vec2(p), rl.Rich("0"), 2 * r, 90.0, gaps=(4.0, 7.0))]
    d = _guide_dir(data.kin, i, slide)
    d = d / (np.hypot(*d) or 1.0)
    nrm = np.array([-d[1], d[0]])
    half_l, half_h = BLOCK_MM[0] / 2, BLOCK_MM[1] / 2
    for extra in (1.5, 3.0, 4.5, 6.0, 7.0):
        for along, across in ((0.0, half_h + r + extra), (0.0, -(half_h + r + extra)),
                              (half_l * 0.6, half_h + r + extra), (-half_l * 0.6, half_h + r + extra),
                              (half_l * 0.6, -(half_h + r + extra)), (-half_l * 0.6, -(half_h + r + extra))):
            q = p + d * along + nrm * across
            out.append((float(q[0]), float(q[1])))
    return out


def _draw_link_numbers(view: View, project: Project, data: SchemeData, links: BaseGeometry | None = None) -> None:
    """The numbers of the moving links on the analysed position (the bold one with letters), in
    small circles beside the links, off every position's links, where they overlap no text and
    cross no line (else crossing as few lines as possible; never over a text); where no spot beside
    a link is off the links (a crank among its twelve positions), on a thin leader to the link, as
    ГОСТ 2.109 numbers items; never left out. A leader crossing a line (the crank pin's circle round
    a crank) is preferred to a number crossed by one (issue 12: «①» on the control work's crank
    circle, «②» on a pivot's base)."""
    lk = project.linkage
    r, h = LINK_NUMBER_MM
    inside = _inside(view)
    ann = view.annotations
    leaders: list[LineString] = []          # the numbers' leaders never cross one another

    def square(c: tuple[float, float]) -> Polygon:
        return Polygon([(c[0] - r - 0.3, c[1] - r - 0.3), (c[0] + r + 0.3, c[1] - r - 0.3),
                        (c[0] + r + 0.3, c[1] + r + 0.3), (c[0] - r - 0.3, c[1] + r + 0.3)])

    def off_links(sq: Polygon) -> bool:
        return links is None or not links.intersects(sq)
    from reportgen.tolerances import LABEL_NEAR_MM
    for k in lk.moving:
        own = _link_lines(view, project, data, k)
        best: tuple[tuple[int, int, int], tuple[float, float], tuple[float, float] | None] | None = None
        spots: list[tuple[tuple[float, float], tuple[float, float] | None]] = [
            (c, None) for c in _link_number_spots(view, project, data, k, data.analysed)]
        spots += [(c, foot) for c, foot in _link_number_leader_spots(view, project, data, k, data.analysed)]
        for c, foot in spots:
            sq = square(c)
            if not inside.contains(sq) or ann.hits_box(ShapelyPoint(c).buffer(r + NAME_GAP_MM, 16)):
                continue
            if foot is not None:
                leader = LineString([_circle_edge(c, foot, r), foot])
                if not off_links(sq) or ann.hits_box(leader.buffer(0.2)):
                    continue
                # a line through the number is worse than one across its thin leader (which meets its
                # link), and two numbers' leaders crossing worse than a leader across another line
                tangled = sum(LEADER_TANGLE for q in leaders if leader.intersects(q))
                score = (0, ann.crossings(sq), ann.crossings(leader) - 1 + tangled)
            else:
                if ShapelyPoint(c).distance(own) > LABEL_NEAR_MM - 0.5:
                    continue                  # beside its link, else on a leader (the label check's reach)
                score = (0 if off_links(sq) else 2, ann.crossings(sq), 0)
            if best is None or score < best[0]:
                best = (score, c, foot)
            if score == (0, 0, 0):
                break
        if best is None or best[0][0] != 0:      # on the links wherever beside it: anywhere, on a leader
            best = _link_number_anywhere(view, project, data, k, square, off_links) or best
        if best is None:
            continue
        _, c, foot = best
        named = _link_lines(view, project, data, k)
        if foot is not None:
            edge = _circle_edge(c, foot, r)
            view.line(view.transform.inverse(edge), view.transform.inverse(foot), "thin")
            leaders.append(LineString([edge, foot]))
            named = shapely.union_all([named, LineString([edge, foot])])
        view.circle_mm(view.transform.inverse(c), r, "thin")
        view.text_mm(c, str(k), h, "center", register=False, names=named)
        ann.add_box(f"{view.name}: «{k}»", Polygon([(c[0] - r, c[1] - r), (c[0] + r, c[1] - r),
                                                   (c[0] + r, c[1] + r), (c[0] - r, c[1] + r)]))


def _link_number_anywhere(view: View, project: Project, data: SchemeData, k: int, square, off_links):
    """Link ``k``'s number where no spot beside its link nor on a short leader keeps off every
    position's links (a crank inside the fan of a slotted link's twelve positions): the nearest
    spot of the scheme's view (:func:`drawings.scenes.kinematics_labels.region_grid`) whose circle
    is off the links, over no text and crossed by no line, on a leader to the middle half of the
    link that crosses no text and passes no joint, of the nearest ``ANYWHERE_SPOTS`` such spots the shortest for the
    lines it crosses —
    ((0, 0), centre, foot), or None where the view has no such spot."""
    r = LINK_NUMBER_MM[0]
    link = _link_lines(view, project, data, k)
    if isinstance(link, MultiLineString):      # the leader meets the link's middle, not a joint it shares
        link = MultiLineString([LineString([(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t) for t in (0.25, 0.75)])
                                for a, b in (tuple(g.coords) for g in link.geoms)])
    mid = link.centroid
    joints = [ShapelyPoint(view.transform(tuple(q))) for q in _pts(data.kin, data.analysed).values()]
    ann = view.annotations
    inside = _inside(view)
    best: tuple[float, tuple[float, float], tuple[float, float]] | None = None
    free = 0
    for c in rl.region_grid((mid.x, mid.y), inside, step=2.0):
        sq = square(c)
        if not inside.contains(sq) or ann.hits_box(sq) or not off_links(sq) or ann.crossings(sq):
            continue
        q = nearest_points(link, ShapelyPoint(c))[0]
        foot = (q.x, q.y)
        if math.dist(c, foot) <= r + MM_ROUNDOFF:
            continue
        leader = LineString([_circle_edge(c, foot, r), foot])
        if ann.hits_box(leader.buffer(0.2)) or any(j.distance(leader) < JOINT_CLEAR_MM for j in joints):
            continue                             # a leader past a joint would name what meets there
        n = ann.crossings(leader) - 1            # the leader meets its own link
        cost = leader.length + LEADER_CROSSING_MM * n
        if best is None or cost < best[0]:
            best = (cost, c, foot)
        free += 1
        if free >= ANYWHERE_SPOTS:
            break
    return ((0, 0), best[1], best[2]) if best is not None else None


#: Of the free spots anywhere in the scheme's view, the nearest this many are compared for the
#: shortest leader, each line it crosses counted as ``LEADER_CROSSING_MM`` more of it.
ANYWHERE_SPOTS, LEADER_CROSSING_MM = 60, 4.0
#: Such a leader keeps this far (mm) from every joint of the analysed position.
JOINT_CLEAR_MM = 2.5


def _circle_edge(c: tuple[float, float], towards: tuple[float, float], r: float) -> tuple[float, float]:
    d = math.dist(c, towards) or 1.0
    return (c[0] + (towards[0] - c[0]) * r / d, c[1] + (towards[1] - c[1]) * r / d)


#: Distances of a link number on a leader from its link, mm (where none beside it is off the links).
LINK_LEADER_MM = (9.0, 12.0, 16.0, 20.0, 25.0)
#: A link number's circle keeps this far from every text, mm.
TEXT_GAP_MM = 1.0
#: A link number's leader crossing another's counts as this many crossed lines.
LEADER_TANGLE = 3


def _link_number_leader_spots(view: View, project: Project, data: SchemeData, k: int, i: int
                              ) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """(centre, foot on the link) of link ``k``'s number on a leader: across its segments at
    ``LINK_LEADER_MM``, from their middles towards the ends; round a slider's block."""
    lk = project.linkage
    pts = {n: view.transform(tuple(p)) for n, p in _pts(data.kin, i).items()}
    names = lk.bodies[k].points
    out: list[tuple[tuple[float, float], tuple[float, float]]] = []
    if len(names) >= 2:
        for off in LINK_LEADER_MM:
            for t in (0.5, 0.62, 0.38, 0.72, 0.28):
                for a, b in _link_outline(names):
                    pa, pb = np.asarray(pts[a]), np.asarray(pts[b])
                    d = pb - pa
                    n = float(np.hypot(*d))
                    if n < 1.0:
                        continue
                    nrm = np.array([-d[1], d[0]]) / n
                    foot = pa + d * t
                    for ang in (0.0, 30.0, -30.0, 55.0, -55.0):
                        rot = math.radians(ang)
                        v = np.array([nrm[0] * math.cos(rot) - nrm[1] * math.sin(rot),
                                      nrm[0] * math.sin(rot) + nrm[1] * math.cos(rot)])
                        for side in (1.0, -1.0):
                            q = foot + side * v * off
                            out.append(((float(q[0]), float(q[1])), (float(foot[0]), float(foot[1]))))
        return out
    p = np.asarray(pts[names[0]])
    for off in LINK_LEADER_MM:
        for ang in range(0, 360, 30):
            q = p + off * np.array([math.cos(math.radians(ang)), math.sin(math.radians(ang))])
            out.append(((float(q[0]), float(q[1])), (float(p[0]), float(p[1]))))
    return out


def _link_lines(view: View, project: Project, data: SchemeData, k: int):
    """Link ``k`` of the analysed position as sheet lines (its outline; a slider: its point)."""
    pts = {n: view.transform(tuple(p)) for n, p in _pts(data.kin, data.analysed).items()}
    names = project.linkage.bodies[k].points
    if len(names) < 2:
        return ShapelyPoint(pts[names[0]]).buffer(BLOCK_MM[1] / 2)       # its block
    return MultiLineString([LineString([pts[a], pts[b]]) for a, b in _link_outline(names)])
