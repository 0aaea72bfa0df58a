"""Sheet 1, the kinematic scheme: the mechanism in every analysed position at a ГОСТ 2.302 scale,
position 0 and the analysed position bold (symbols and letters), the others thin and numbered, the
extreme position of the end of the working stroke (dash-two-dots), the trajectories of the centres
of mass and of the crank pin, the stroke H of the slider and the crank angles of the strokes."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from drawings.primitives import format_number
from drawings.sheet import View
from drawings.scenes import kinematics_labels as rl
from reportgen.geometry import vec2
from reportgen.kinematics import KinematicsResult
from reportgen.kinematics.constraints import rot
from reportgen.project import Project

#: ГОСТ 2.302 scales as (paper, real): 1:2,5 is (1, 2.5).
GOST_SCALES: tuple[tuple[float, float], ...] = (
    (10, 1), (5, 1), (4, 1), (2.5, 1), (2, 1), (1, 1), (1, 2), (1, 2.5), (1, 4), (1, 5), (1, 10),
    (1, 15), (1, 20), (1, 25), (1, 40), (1, 50), (1, 75), (1, 100))
#: Positions of the dense trajectories.
DENSE = 144
HINGE_MM = 2.0
THIN_HINGE_MM = 1.0
BLOCK_MM = (14.0, 7.0)
#: Link numbers: radius of the circle, text height, mm.
LINK_NUMBER_MM = (2.8, 3.5)


@dataclass(frozen=True)
class SchemeData:
    """Everything the scheme view draws, in metres."""
    kin: KinematicsResult            # the analysed positions
    dense: KinematicsResult          # DENSE positions over one turn, for the trajectories
    extremes: KinematicsResult | None  # [start, end] of the working stroke (None: no strokes)
    bold: tuple[int, ...]            # position 0 and the analysed position
    analysed: int
    start_is_zero: bool              # position 0 is the start of the working stroke


def scheme_data(project: Project, analysed: int) -> SchemeData:
    phis = np.linspace(0.0, 2 * math.pi, DENSE, endpoint=False)
    dense = project.model.solve(project.phi[0] + phis)
    st = project.strokes
    ext = project.model.solve(np.array([st.phi_start, st.phi_end])) if st is not None else None
    start_is_zero = st is not None and abs(math.remainder(float(project.phi[0]) - st.phi_start, 2 * math.pi)) < 1e-9
    bold = tuple(sorted({0, analysed}))
    return SchemeData(project.kinematics, dense, ext, bold, analysed, start_is_zero)


def gost_scale(width_m: float, height_m: float, max_w_mm: float, max_h_mm: float) -> tuple[float, str]:
    """The largest ГОСТ 2.302 scale that fits; returns (sheet mm per metre, «1:2,5»)."""
    for paper, real in GOST_SCALES:
        k = 1000.0 * paper / real
        if width_m * k <= max_w_mm and height_m * k <= max_h_mm:
            return k, f"{format_number(paper, 1)}:{format_number(real, 1)}"
    paper, real = GOST_SCALES[-1]
    return 1000.0 * paper / real, f"{format_number(paper, 1)}:{format_number(real, 1)}"


def _pts(kin: KinematicsResult, i: int) -> dict[str, np.ndarray]:
    return {n: np.asarray(m.pos[i]) for n, m in kin.points.items()}


def _guide_dir(kin: KinematicsResult, i: int, slide) -> np.ndarray:
    if slide.guide == 0:
        return np.asarray(slide.line_dir, float)
    return rot(np.array([kin.q[i][slide.guide, 2]]), tuple(slide.line_dir))[0]


def bounds(data: SchemeData) -> tuple[float, float, float, float]:
    """Model bounds of everything the view draws (m)."""
    arrs = [np.asarray(m.pos) for m in data.kin.points.values()]
    arrs += [np.asarray(m.pos) for m in data.dense.coms.values()]
    arrs += [np.asarray(m.pos) for m in data.dense.points.values()]
    allp = np.vstack(arrs)
    return (float(allp[:, 0].min()), float(allp[:, 1].min()), float(allp[:, 0].max()), float(allp[:, 1].max()))


def _centre(data: SchemeData) -> np.ndarray:
    return np.vstack([np.asarray(m.pos) for m in data.dense.points.values()]).mean(axis=0)


# ---------------------------------------------------------------------------------------------


def draw_scheme(view: View, project: Project, data: SchemeData, scale_text: str, mu_l: float) -> None:
    _draw_guides(view, project, data)
    _draw_trajectories(view, project, data)
    for i in range(len(data.kin.phi)):
        if i not in data.bold:
            _draw_position(view, project, data.kin, i, bold=False)
    if data.extremes is not None:
        for j in ((1,) if data.start_is_zero else (0, 1)):
            _draw_position(view, project, data.extremes, j, bold=False, layer="phantom")
    for i in data.bold:
        _draw_position(view, project, data.kin, i, bold=True)
    _draw_crank_angles(view, project, data)
    _draw_stroke(view, project, data)
    _draw_letters(view, project, data)
    _draw_numbers(view, project, data)
    _draw_link_numbers(view, project, data)
    view.text_mm((view.rect.center[0], view.rect.y0 + 4.0),
                 f"μl = {format_number(mu_l, 5)} м/мм (М {scale_text})", 5.0, "bottom-center")
    view.title(f"Кинематическая схема механизма ({len(data.kin.phi)} положений)")


def _inside(view: View) -> Polygon:
    """Where labels may go: the view less its title and caption strips."""
    r = view.rect
    return Polygon([(r.x0, r.y0 + 12.0), (r.x1, r.y0 + 12.0), (r.x1, r.y1 - 9.0), (r.x0, r.y1 - 9.0)])


def _link_outline(names: tuple[str, ...]) -> list[tuple[str, str]]:
    if len(names) == 2:
        return [(names[0], names[1])]
    return [(names[k], names[(k + 1) % len(names)]) for k in range(len(names))]


def _draw_position(view: View, project: Project, kin: KinematicsResult, i: int, *, bold: bool,
                   layer: str | None = None) -> None:
    lk = project.linkage
    pts = _pts(kin, i)
    layer = layer or ("contour" if bold else "thin")
    r = HINGE_MM if bold else THIN_HINGE_MM
    for k in lk.moving:
        names = lk.bodies[k].points
        for a, b in _link_outline(names) if len(names) >= 2 else []:
            view.segment(pts[a], pts[b], layer, trim_mm=(r, r))
    for j in lk.joints:
        if 0 in j.bodies:
            continue
        if bold:
            view.hinge(pts[j.name], r)
        else:
            view.circle_mm(pts[j.name], r, layer)
    for s in lk.slides:
        if len(lk.bodies[s.link].points) != 1:
            continue
        d = _guide_dir(kin, i, s)
        ang = math.degrees(math.atan2(d[1], d[0]))
        if bold:
            view.slider(pts[s.point], ang, *BLOCK_MM, guide_mm=None, hinge_mm=HINGE_MM)
        else:
            view.slider(pts[s.point], ang, BLOCK_MM[0] * 0.7, BLOCK_MM[1], guide_mm=None,
                        hinge_mm=0, layer=layer)


def _pivot_direction(project: Project, kin: KinematicsResult, i: int, name: str) -> float:
    """Direction (deg, a multiple of 90) from a fixed pivot to its base: away from its links."""
    lk = project.linkage
    pts = _pts(kin, i)
    p = pts[name]
    acc = np.zeros(2)
    for k in lk.moving:
        if name in lk.bodies[k].points:
            for other in lk.bodies[k].points:
                if other != name:
                    v = pts[other] - p
                    n = np.hypot(*v)
                    if n > 0:
                        acc += v / n
    if np.hypot(*acc) < 1e-9:
        return -90.0
    ang = math.degrees(math.atan2(-acc[1], -acc[0]))
    return float(round(ang / 90.0) * 90.0)


def _draw_guides(view: View, project: Project, data: SchemeData) -> None:
    """Frame guides of the sliders (hatched lines across the travel) and the fixed pivots."""
    lk = project.linkage
    for s in lk.slides:
        if s.guide != 0:
            continue
        d = np.asarray(s.line_dir, float)
        n = np.array([-d[1], d[0]])
        lp = np.asarray(s.line_point, float)
        if np.dot(_towards_links(project, data, s.link, s.point), n) > 0:
            n = -n          # the guide and its hatching on the side away from the coupler
        travel = np.asarray(data.dense.points[s.point].pos) @ d
        half = (BLOCK_MM[0] / 2 + 12.0) / view.transform.scale
        t0, t1 = float(travel.min()) - half, float(travel.max()) + half
        off = n * (BLOCK_MM[1] / 2) / view.transform.scale
        p = lp + d * (t0 - np.dot(lp, d)) + off
        q = lp + d * (t1 - np.dot(lp, d)) + off
        # hatch on the side of n (away from the mechanism): ground() hatches on the right of p→q
        t = q - p
        side = -1.0 if t[0] * n[1] - t[1] * n[0] < 0 else 1.0
        view.ground(tuple(p), tuple(q), side=side)
    pos = data.analysed
    for g in lk.ground:
        if not any(0 in j.bodies and j.name == g for j in lk.joints):
            continue
        view.fixed_pivot(_pts(data.kin, pos)[g], _pivot_direction(project, data.kin, pos, g))


def _towards_links(project: Project, data: SchemeData, link: int, point: str) -> np.ndarray:
    """Mean direction from a slider's point to the other points of the links joined to it."""
    lk = project.linkage
    p = np.asarray(data.kin.points[point].pos)
    acc = np.zeros(2)
    for k in lk.moving:
        if k == link or point not in lk.bodies[k].points:
            continue
        for other in lk.bodies[k].points:
            if other != point:
                acc += (np.asarray(data.kin.points[other].pos) - p).sum(axis=0)
    return acc


def _draw_trajectories(view: View, project: Project, data: SchemeData) -> None:
    lk = project.linkage
    o = _pts(data.kin, 0)[lk.drive_axis]
    r = float(np.hypot(*(_pts(data.kin, 0)[lk.drive_tip] - o)))
    view.circle(o, r, "thin")
    for _k, m in sorted(data.dense.coms.items()):
        path = np.asarray(m.pos)
        span = float(np.ptp(path, axis=0).max())
        if span * view.transform.scale < 2.0:
            continue
        ring = Polygon(path)
        if ring.is_valid and ring.area < 1e-4 * ring.length ** 2:
            continue          # a straight path (a slider on the frame): its guide shows it
        if np.allclose(path, np.asarray(data.dense.points[lk.drive_tip].pos)):
            continue          # the crank pin's circle is drawn already
        view.polyline([tuple(p) for p in path], "thin", closed=True)


def _arc_points(o: np.ndarray, r: float, a0: float, sweep: float, n: int = 60) -> list[tuple[float, float]]:
    return [(o[0] + r * math.cos(a0 + sweep * t / n), o[1] + r * math.sin(a0 + sweep * t / n)) for t in range(n + 1)]


def _draw_crank_angles(view: View, project: Project, data: SchemeData) -> None:
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
    arcs = ((a_start, sgn * work, r_mm + 12.0, f"φр.х. = {format_number(st.working_deg, 1)}°"),
            (a_end, sgn * (2 * math.pi - work), r_mm + 18.0, f"φх.х. = {format_number(st.idle_deg, 1)}°"))
    for a0, sweep, rad_mm, text in arcs:
        pts = _arc_points(o, rad_mm / k, a0, sweep)
        view.polyline(pts, "thin")
        tip = view.transform(pts[-1])
        prev = view.transform(pts[-3])
        view.arrowhead_mm(tip, (tip[0] - prev[0], tip[1] - prev[1]), 4.0, 1.3, "thin")
        am = math.degrees(a0 + sweep / 2)
        mid = view.transform(pts[len(pts) // 2])
        rich = rl.Rich(text)
        rl.place_rich(view, rl.around(mid, rich, 3.5, am), rich, 3.5, inside=_inside(view))


def _draw_stroke(view: View, project: Project, data: SchemeData) -> None:
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
                      rich, 3.5, inside=_inside(view))
        return
    p0 = np.asarray(data.extremes.points[out.point].pos[0])
    p1 = np.asarray(data.extremes.points[out.point].pos[1])
    d = p1 - p0
    if d[0] < -1e-12 or (abs(d[0]) <= 1e-12 and d[1] < 0):
        p0, p1, d = p1, p0, -d          # read from the left (text not upside down)
    n = np.array([-d[1], d[0]]) / (np.hypot(*d) or 1.0)
    # beyond the guide, away from the coupler: the left of p0→p1 (offset > 0) or its right
    side = -1.0 if np.dot(_towards_links(project, data, out.link, out.point), n) > 0 else 1.0
    view.dimension(tuple(p0), tuple(p1), offset_mm=side * (BLOCK_MM[1] / 2 + 14.0), unit_factor=1000.0,
                   text=f"H = {format_number(st.stroke * 1000.0, 1)}")


def _draw_letters(view: View, project: Project, data: SchemeData) -> None:
    """Letters of the points in the analysed position; moving points of position 0 with index 0;
    the centres of mass S_k of the analysed position."""
    lk = project.linkage
    i = data.analysed
    pts = _pts(data.kin, i)
    c = view.transform(tuple(_centre(data)))
    for name in pts:
        p = view.transform(tuple(pts[name]))
        prefer = math.degrees(math.atan2(p[1] - c[1], p[0] - c[0]))
        rl.place_rich(view, rl.around(p, rl.Rich(name), 5.0, prefer), rl.Rich(name), 5.0, inside=_inside(view))
    if i != 0:
        p0s = _pts(data.kin, 0)
        for name in p0s:
            if name in lk.ground:
                continue
            p = view.transform(tuple(p0s[name]))
            prefer = math.degrees(math.atan2(p[1] - c[1], p[0] - c[0]))
            rich = rl.Rich(name, "", "0")
            rl.place_rich(view, rl.around(p, rich, 5.0, prefer), rich, 5.0, inside=_inside(view))
    for k, m in sorted(data.kin.coms.items()):
        pos = tuple(np.asarray(m.pos[i]))
        if any(np.allclose(pos, pts[n]) for n in pts):
            continue
        view.circle_mm(pos, 1.0, "contour")
        p = view.transform(pos)
        rich = rl.Rich("S", "", str(k))
        rl.place_rich(view, rl.around(p, rich, 5.0, 90.0), rich, 5.0, inside=_inside(view))


def _draw_numbers(view: View, project: Project, data: SchemeData) -> None:
    """Position numbers at the crank pin, outside the crank circle; «0'» at the end extreme."""
    lk = project.linkage
    o = view.transform(tuple(_pts(data.kin, 0)[lk.drive_axis]))
    items = [(str(i), tuple(np.asarray(data.kin.points[lk.drive_tip].pos[i]))) for i in range(len(data.kin.phi))]
    if data.extremes is not None:
        items.append(("0'" if data.start_is_zero else "к.р.х.", tuple(np.asarray(data.extremes.points[lk.drive_tip].pos[1]))))
        if not data.start_is_zero:
            items.append(("н.р.х.", tuple(np.asarray(data.extremes.points[lk.drive_tip].pos[0]))))
    for text, pos in items:
        p = view.transform(pos)
        ang = math.degrees(math.atan2(p[1] - o[1], p[0] - o[0]))
        rich = rl.Rich(text)
        cands = rl.around(p, rich, 3.5, ang, gaps=(1.0, 2.5, 4.5))
        # keep the number outside the crank circle
        r = math.dist(p, o)
        cands = [q for q in cands if math.dist(q, o) > r] or cands
        rl.place_rich(view, cands, rich, 3.5, inside=_inside(view))


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
    for extra in (1.5, 4.0, 7.0):
        for along, across in ((0.0, half_h + r + extra), (0.0, -(half_h + r + extra)),
                              (half_l * 0.6, half_h + r + extra), (-half_l * 0.6, half_h + r + extra),
                              (half_l * 0.6, -(half_h + r + extra)), (-half_l * 0.6, -(half_h + r + extra))):
            q = p + d * along + nrm * across
            out.append((float(q[0]), float(q[1])))
    return out


def _draw_link_numbers(view: View, project: Project, data: SchemeData) -> None:
    """The numbers of the moving links on the analysed position (the bold one with letters), in
    small circles beside the links, where they overlap no text and cross no line (else crossing
    as few lines as possible; never over a text)."""
    lk = project.linkage
    r, h = LINK_NUMBER_MM
    inside = _inside(view)
    ann = view.annotations
    for k in lk.moving:
        best: tuple[int, tuple[float, float]] | None = None
        for c in _link_number_spots(view, project, data, k, data.analysed):
            square = Polygon([(c[0] - r - 0.3, c[1] - r - 0.3), (c[0] + r + 0.3, c[1] - r - 0.3),
                              (c[0] + r + 0.3, c[1] + r + 0.3), (c[0] - r - 0.3, c[1] + r + 0.3)])
            if not inside.contains(square) or ann.hits_box(square):
                continue
            crossings = ann.crossings(square)
            if best is None or crossings < best[0]:
                best = (crossings, c)
            if crossings == 0:
                break
        if best is None:
            continue
        c = best[1]
        view.circle_mm(view.transform.inverse(c), r, "thin")
        view.text_mm(c, str(k), h, "center", register=False)
        ann.add_box(f"{view.name}: «{k}»", Polygon([(c[0] - r, c[1] - r), (c[0] + r, c[1] - r),
                                                   (c[0] + r, c[1] + r), (c[0] - r, c[1] + r)]))
