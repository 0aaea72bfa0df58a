"""The plan of positions (план положений) as a scene: the mechanism in every analysed position at
the ГОСТ 2.302 scale of sheet 1 (the largest within the scheme's box at which the sheet's views all
fit, :mod:`.arrangement`), position 0 and the analysed position bold, the others thin, the extreme
position of the end of the working stroke (dash-two-dots), the trajectories of the centres of mass
and the crank pin, the frame guides and pivots; labels: the letters of the analysed position (and of position 0 with index 0), the centres
of mass, the position numbers at the crank pin. Coordinates: paper mm = metres × k."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..kinematics import KinematicsResult
from ..kinematics.constraints import rot
from .boxes import SceneBoxes
from .scales import gost_scale, gost_scales_from
from .scene import Circle, Entity, Label, Point, Polyline, Scale, Scene, Segment, frozen
from .symbols import block, fixed_pivot, ground
from ..tolerances import ABS_ZERO, FLAT_PATH_RATIO

#: Positions of the dense trajectories.
DENSE = 144
#: Hinge circles of the bold and the thin positions, the slider's block, mm of paper.
HINGE_MM = 2.0
THIN_HINGE_MM = 1.0
BLOCK_MM = (14.0, 7.0)


@dataclass(frozen=True)
class SchemeData:
    """Everything the plan of positions shows, in metres."""
    kin: KinematicsResult            # the analysed positions
    dense: KinematicsResult          # DENSE positions over one turn, for the trajectories
    extremes: KinematicsResult | None  # [start, end] of the working stroke
    bold: tuple[int, ...]            # position 0 and the analysed position
    analysed: int
    start_is_zero: bool              # position 0 is the start of the working stroke


def scheme_data(project, analysed: int) -> SchemeData:
    """The plan of positions' data; one position (a control work) or a crank that cannot turn
    fully: no traces, no strokes."""
    if project.task.document.kind == "control-work" or not project.full_cycle:
        kin = project.kinematics
        return SchemeData(kin, kin, None, tuple(sorted({0, analysed})), analysed, False)
    phis = np.linspace(0.0, 2 * math.pi, DENSE, endpoint=False)
    dense = project.model.solve(project.phi[0] + phis)
    st = project.strokes
    ext = project.model.solve(np.array([st.phi_start, st.phi_end])) if st is not None else None
    start_is_zero = st is not None and abs(math.remainder(float(project.phi[0]) - st.phi_start, 2 * math.pi)) < ABS_ZERO
    bold = tuple(sorted({0, analysed}))
    return SchemeData(project.kinematics, dense, ext, bold, analysed, start_is_zero)


def bounds(data: SchemeData, linkage=None) -> tuple[float, float, float, float]:
    """Model bounds of everything the plan of positions shows (m); with ``linkage``, the crank
    circle's too (one position: no traces hold it)."""
    arrs = [np.asarray(m.pos) for m in data.kin.points.values()]
    arrs += [np.asarray(m.pos) for m in data.dense.coms.values()]
    arrs += [np.asarray(m.pos) for m in data.dense.points.values()]
    if linkage is not None:    # the crank circle is always drawn
        o = np.asarray(data.kin.points[linkage.drive_axis].pos)[0]
        r = float(np.hypot(*(np.asarray(data.kin.points[linkage.drive_tip].pos)[0] - o)))
        arrs.append(np.array([o - r, o + r]))
    allp = np.vstack(arrs)
    return (float(allp[:, 0].min()), float(allp[:, 1].min()), float(allp[:, 0].max()), float(allp[:, 1].max()))


def positions_scales(b: tuple[float, float, float, float], boxes: SceneBoxes, pairs: int = 2,
                     scheme: tuple[float, float] | None = None) -> list[tuple[float, str]]:
    """ГОСТ 2.302 scales (paper mm per metre, «1:2,5») for the plan of positions, largest first from
    the one that fits ``scheme`` (default ``boxes.scheme``; the control work's sheet gives its own,
    :meth:`SceneBoxes.scheme_for`; less ``boxes.scheme_less_per_pair`` of height for each of the
    ``pairs`` plan positions beyond two): the candidates, of which the project takes the largest at
    which the whole sheet fits (:func:`reportgen.scenes.arrangement.choose_layout`)."""
    w, h = boxes.scheme if scheme is None else scheme
    h -= boxes.scheme_less_per_pair * max(pairs - 2, 0)
    k, _ = gost_scale(b[2] - b[0], b[3] - b[1], w, h)
    return gost_scales_from(k)


def pts(kin: KinematicsResult, i: int) -> dict[str, np.ndarray]:
    return {n: np.asarray(m.pos[i]) for n, m in kin.points.items()}


def guide_dir(kin: KinematicsResult, i: int, slide) -> np.ndarray:
    if slide.guide == 0:
        return np.asarray(slide.line_dir, float)
    return rot(np.array([kin.q[i][slide.guide, 2]]), tuple(slide.line_dir))[0]


def centre(data: SchemeData) -> np.ndarray:
    return np.vstack([np.asarray(m.pos) for m in data.dense.points.values()]).mean(axis=0)


def link_outline(names: tuple[str, ...]) -> list[tuple[str, str]]:
    if len(names) == 2:
        return [(names[0], names[1])]
    return [(names[k], names[(k + 1) % len(names)]) for k in range(len(names))]


def towards_links(lk, data: SchemeData, link: int, point: str) -> np.ndarray:
    """Mean direction from a slider's point to the other points of the links joined to it."""
    p = np.asarray(data.kin.points[point].pos)
    acc = np.zeros(2)
    for k in lk.moving:
        if k == link or point not in lk.bodies[k].points:
            continue
        for other in lk.bodies[k].points:
            if other != point:
                acc += (np.asarray(data.kin.points[other].pos) - p).sum(axis=0)
    return acc


def pivot_direction(lk, kin: KinematicsResult, i: int, name: str) -> float:
    """Direction (deg, a multiple of 90) from a fixed pivot to its base: away from its links."""
    ps = pts(kin, i)
    p = ps[name]
    acc = np.zeros(2)
    for k in lk.moving:
        if name in lk.bodies[k].points:
            for other in lk.bodies[k].points:
                if other != name:
                    v = ps[other] - p
                    n = np.hypot(*v)
                    if n > 0:
                        acc += v / n
    if np.hypot(*acc) < ABS_ZERO:
        return -90.0
    ang = math.degrees(math.atan2(-acc[1], -acc[0]))
    return float(round(ang / 90.0) * 90.0)


class _Mm:
    def __init__(self, k: float):
        self.k = k

    def __call__(self, p) -> Point:
        return (float(p[0]) * self.k, float(p[1]) * self.k)


def _position(lk, kin: KinematicsResult, i: int, mm: _Mm, *, bold: bool, tag: str,
              kind: str | None = None) -> list[Entity]:
    ps = pts(kin, i)
    kind = kind or ("contour" if bold else "thin")
    r = HINGE_MM if bold else THIN_HINGE_MM
    out: list[Entity] = []
    for k in lk.moving:
        names = lk.bodies[k].points
        for a, b in link_outline(names) if len(names) >= 2 else []:
            out.append(Segment(f"{tag}:link{k}:{a}{b}", mm(ps[a]), mm(ps[b]), kind, (r, r)))
    for j in lk.joints:
        if 0 in j.bodies:
            continue
        out.append(Circle(f"{tag}:joint:{j.name}", mm(ps[j.name]), r, kind, hinge=bold))
    for s in lk.slides:
        if len(lk.bodies[s.link].points) != 1:
            continue
        d = guide_dir(kin, i, s)
        ang = math.degrees(math.atan2(d[1], d[0]))
        if bold:
            out += block(f"{tag}:block{s.link}", mm(ps[s.point]), ang, *BLOCK_MM, kind, hinge=HINGE_MM)
        else:
            out += block(f"{tag}:block{s.link}", mm(ps[s.point]), ang, BLOCK_MM[0] * 0.7, BLOCK_MM[1], kind)
    return out


def positions_scene(project, data: SchemeData, k: float, ratio: str) -> Scene:
    """The plan of positions at ``k`` paper mm per metre (ratio «1:2,5»)."""
    lk = project.linkage
    mm = _Mm(k)
    ents: list[Entity] = []
    # frame guides of the sliders (hatched, across the travel, away from the coupler) and pivots
    for s in lk.slides:
        if s.guide != 0:
            continue
        d = np.asarray(s.line_dir, float)
        n = np.array([-d[1], d[0]])
        lp = np.asarray(s.line_point, float)
        if np.dot(towards_links(lk, data, s.link, s.point), n) > 0:
            n = -n
        travel = np.asarray(data.dense.points[s.point].pos) @ d
        half = (BLOCK_MM[0] / 2 + 12.0) / k
        t0, t1 = float(travel.min()) - half, float(travel.max()) + half
        off = n * (BLOCK_MM[1] / 2) / k
        p = mm(lp + d * (t0 - np.dot(lp, d)) + off)
        q = mm(lp + d * (t1 - np.dot(lp, d)) + off)
        t = (q[0] - p[0], q[1] - p[1])
        side = -1.0 if t[0] * n[1] - t[1] * n[0] < 0 else 1.0
        ents += ground(f"guide{s.link}", p, q, side)
    for g in lk.ground:
        if any(0 in j.bodies and j.name == g for j in lk.joints):
            ents += fixed_pivot(f"pivot:{g}", mm(pts(data.kin, data.analysed)[g]),
                                pivot_direction(lk, data.kin, data.analysed, g))
    # trajectories: the crank pin's circle, the centres of mass
    o = pts(data.kin, 0)[lk.drive_axis]
    r_crank = float(np.hypot(*(pts(data.kin, 0)[lk.drive_tip] - o)))
    ents.append(Circle("trajectory:" + lk.drive_tip, mm(o), r_crank * k, "thin"))
    for kk, m in sorted(data.dense.coms.items()):
        path = np.asarray(m.pos)
        if float(np.ptp(path, axis=0).max()) * k < 2.0:
            continue
        x, y = path[:, 0], path[:, 1]
        area = 0.5 * abs(float(np.dot(x, np.roll(y, 1)) - np.dot(y, np.roll(x, 1))))
        length = float(np.hypot(*np.diff(np.vstack([path, path[:1]]), axis=0).T).sum())
        if area < FLAT_PATH_RATIO * length ** 2:
            continue          # a straight path (a slider on the frame): its guide shows it
        if np.allclose(path, np.asarray(data.dense.points[lk.drive_tip].pos)):
            continue          # the crank pin's circle is drawn already
        ents.append(Polyline(f"trajectory:S{kk}", tuple(mm(p) for p in path), "thin", closed=True))
    # the positions: thin, the extreme(s) dash-two-dots, the bold ones last
    for i in range(len(data.kin.phi)):
        if i not in data.bold:
            ents += _position(lk, data.kin, i, mm, bold=False, tag=f"pos{i}")
    if data.extremes is not None:
        for j in ((1,) if data.start_is_zero else (0, 1)):
            ents += _position(lk, data.extremes, j, mm, bold=False, tag=f"extreme{j}", kind="phantom")
    for i in data.bold:
        ents += _position(lk, data.kin, i, mm, bold=True, tag=f"pos{i}")
    # labels
    labels: list[Label] = []
    i = data.analysed
    ps = pts(data.kin, i)
    for name in ps:
        labels.append(Label(name, f"pos{i}:{name}", mm(ps[name]), "point"))
    if i != 0:
        for name, p0 in pts(data.kin, 0).items():
            if name not in lk.ground:
                labels.append(Label(f"{name}_{{0}}", f"pos0:{name}", mm(p0), "point"))
    for kk, m in sorted(data.kin.coms.items()):
        pos = np.asarray(m.pos[i])
        if any(np.allclose(pos, ps[n]) for n in ps):
            continue
        ents.append(Circle(f"pos{i}:S{kk}", mm(pos), 1.0, "contour"))
        labels.append(Label(f"S_{{{kk}}}", f"pos{i}:S{kk}", mm(pos), "point"))
    tip = lk.drive_tip
    for j in range(len(data.kin.phi) if len(data.kin.phi) > 1 else 0):   # one position (a control work): no number
        labels.append(Label(str(j), f"pos{j}:{tip}", mm(data.kin.points[tip].pos[j]), "number"))
    if data.extremes is not None:
        end = "0'" if data.start_is_zero else "к.р.х."
        labels.append(Label(end, f"extreme1:{tip}", mm(data.extremes.points[tip].pos[1]), "number"))
        if not data.start_is_zero:
            labels.append(Label("н.р.х.", f"extreme0:{tip}", mm(data.extremes.points[tip].pos[0]), "number"))
    values = {f"{lk.drive_axis}{tip}": r_crank * k}
    points = {name: mm(p) for name, p in ps.items()}
    return Scene("positions", (Scale("μl", 1.0 / k / 1.0, "м/мм", ratio),), tuple(ents), tuple(labels),
                 frozen(points), frozen(values))
