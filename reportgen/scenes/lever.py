"""Zhukovsky's lever as a scene: the velocity plan of the analysed position turned by 90° at the
replica's μv (mm), every load at the image of its point at one round force scale (a force shorter
than ``MIN_ARROW_MM`` drawn at that length), the balancing force F_ур at the image of the crank pin
(found from the lever), each force named beside its own arrow, and the arm of each force with a
non-zero arm (from the pole square to the force's line) named h1, h2, … in the order of the terms
(or by ``arm_names``); forces on one line of action share one arm, named «h1 = h9».

Only a force's line of action and sense count on the lever (its moment about the pole), so an arrow
may pull its point (tail at the point) or push it (head at the point), as statics draws either.
Where several forces act at one point or near one another (the slider's and the coupler's images
lie close together at the top of many plans) each arrow, the largest first, takes the way that
lies over fewer of the lines already drawn (:func:`_crowding`): the arrows fan out round the
crowded point instead of lying over each other, and their names find room beside them. A load
whose both ways still lie over a drawn line (an arrow, or a link of the plan along which it acts)
slides along its line of action past the arrows already drawn on it (:func:`_along_line`) when that
lies over less."""
from __future__ import annotations

import numpy as np

from .scales import FORCE_SERIES, round_scale
from ..geometry import vec2 as _pt
from .scene import Arrow, Entity, Label, Scale, Scene, Segment, frozen
from .forces import force_tex
from ..tolerances import ABS_ZERO, MM_EPS, MM_ROUNDOFF

#: The lever's loads: the largest drawn this long (mm), none shorter than MIN_ARROW_MM.
LEVER_ARROW_MM = 40.0
MIN_ARROW_MM = 7.0


#: Lines nearer than this (mm) to an arrow count as lying over it; points nearer than this to it as
#: crowding it (:func:`_crowding`).
CROWD_MM = 3.0


#: Lying over another arrow hides its head and its name: it counts this many times as much as lying
#: over the lever's contour (:func:`_crowding`).
ARROW_WEIGHT = 3.0


def _crowding(way, own: np.ndarray, drawn: list, points: list) -> tuple[float, float]:
    """How much the arrow ``way`` (tail, head; mm) lies over what is drawn: the length of it within
    CROWD_MM of the lines ``drawn`` ((tail, head, weight): the contour 1, an arrow
    :data:`ARROW_WEIGHT`; sampled along it, the heaviest line at each sample), then the number of
    other image points (``points``, its own point ``own`` left out) within CROWD_MM of it. The
    pulling way wins a tie."""
    a, b = way
    n = 16
    over = 0.0
    step = float(np.hypot(*(b - a))) / n
    for k in range(n + 1):
        q = a + (b - a) * k / n
        if float(np.hypot(*(q - own))) < CROWD_MM:
            continue
        over += step * max([w for s0, s1, w in drawn if _seg_dist(q, s0, s1) < CROWD_MM] + [0.0])
    near = sum(1 for p in points if float(np.hypot(*(p - own))) > CROWD_MM and _seg_dist(p, a, b) < CROWD_MM)
    return (round(over, 6), float(near))


def _along_line(img: np.ndarray, d: np.ndarray, arrows: list) -> list:
    """The ways of the arrow ``d`` (mm) acting at ``img`` moved along its own line of action past the
    arrows (``arrows``: (tail, head, weight)) already drawn on that line through ``img``: pulling from
    their far end, pushing into their near end, so that the arrows follow one another along the line
    (a force slides along its line of action without changing its moment about the pole); each
    way's first point is the end where it meets the arrows it follows, never a head against a head.
    Only arrows that start or end at ``img`` count: a force is never carried off to another point's
    arrows on its line.
    Empty when no drawn arrow lies on that line at ``img``."""
    u = d / float(np.hypot(*d))
    n = np.array([-u[1], u[0]])
    ends = [(float((q - img) @ u), k) for a, b, _ in arrows
            if abs(float((a - img) @ n)) < MM_EPS and abs(float((b - img) @ n)) < MM_EPS
            and min(float(np.hypot(*(a - img))), float(np.hypot(*(b - img)))) < CROWD_MM
            for q, k in ((a, "tail"), (b, "head"))]
    if not ends:
        return []
    hi, lo = max(ends + [(0.0, "")]), min(ends + [(0.0, "")])
    out = [(img + hi[0] * u, img + hi[0] * u + d)]
    if lo[1] != "head":          # pushing into another arrow's head would set two heads together
        out.append((img + lo[0] * u, img + lo[0] * u - d))
    return out


def _own_part(foot: np.ndarray, feet: list) -> np.ndarray:
    """Where the arm p–``foot`` stops lying over the shorter arms among ``feet`` (all from the pole p):
    the farthest of their feet within CROWD_MM of it, short of its own foot (the pole when none). The
    arm's name stands at the middle of the rest, its own part, so that the names of arms along one
    line (the weights' arms on the turned plan's axis) follow one another instead of bunching at p."""
    length = float(np.hypot(*foot))
    u = foot / length
    ts = [float(f @ u) for f in feet if 0.0 < float(f @ u) < length - MM_EPS and _seg_dist(f, np.zeros(2), foot) < CROWD_MM]
    return u * max(ts + [0.0])


def _shared_arms(arms: list) -> list:
    """The arms (name, h, foot) with one foot (forces on one line of action: the press's F_пс and F_и5
    at d, G3 and G4 whose images lie on one vertical) drawn once and named once, «h_{1} = h_{9}»
    — as a student writes two equal arms on one line — instead of two names on one segment."""
    out: list = []
    for name, h, foot in arms:
        same = next((k for k, (_, _, f) in enumerate(out) if float(np.hypot(*(f - foot))) < MM_EPS), None)
        if same is None:
            out.append((name, h, foot))
        else:
            n0, h0, f0 = out[same]
            out[same] = (n0, f"{h0} = {h}", f0)
    return out


def _seg_dist(x: np.ndarray, s0: np.ndarray, s1: np.ndarray) -> float:
    """Distance from the point ``x`` to the segment s0–s1 (mm)."""
    d = s1 - s0
    m = float(d @ d)
    t = 0.0 if m == 0.0 else min(1.0, max(0.0, float((x - s0) @ d) / m))
    return float(np.hypot(*(x - s0 - t * d)))


def lever_scene(ks, linkage, arm_names: dict[str, str] | None = None) -> Scene:
    """The lever of :class:`reportgen.kinetostatics.Kinetostatics` ``ks`` (its analysed position) at
    the replica's μv — the one scale of the sheet that draws it and of the note — with the arms as
    the replica measured them there."""
    from ..kinetostatics.zhukovsky import turn_cw
    L, lev, r = ks.graphical.lever, ks.lever, ks.reactions
    kin = r.kin
    mu_v = L.scale
    points: dict[str, tuple[float, float]] = {}
    for name, mo in kin.points.items():
        img = turn_cw(np.asarray(mo.vel))[0] / mu_v
        if float(np.hypot(*img)) > MM_ROUNDOFF:
            points[name.lower()] = _pt(img)
    ents: list[Entity] = []
    for k in linkage.moving:
        names = [n.lower() for n in linkage.bodies[k].points if n.lower() in points]
        for n in names:
            ents.append(Segment(f"ray:{n}", (0.0, 0.0), points[n], "thin"))
        for a, b in zip(names, names[1:]):
            ents.append(Segment(f"link{k}:{a}{b}", points[a], points[b], "contour"))
    loads = [(t.name, np.asarray(f.image)[0] / mu_v, np.asarray(f.vector)[0], t.arm_mm_measured, "load")
             for t, f in zip(L.terms, lev.forces) if t.magnitude > 0.0]
    pin = np.asarray(lev.crank_pin_image)[0] / mu_v
    fb = np.asarray(r.balancing_force)[0]
    loads.append(("Fур", pin, fb, 0.0, "found"))
    mu_f = round_scale(max([float(np.hypot(*v)) for _, _, v, _, _ in loads] + [ABS_ZERO]), LEVER_ARROW_MM, FORCE_SERIES)
    labels: list[Label] = []
    n_arm = 0
    arms: list[tuple[str, str, np.ndarray]] = []
    drawn = [(np.asarray(e.a, float), np.asarray(e.b, float), 1.0) for e in ents if isinstance(e, Segment)
             and e.kind == "contour"]
    others = [np.asarray(p, float) for p in points.values()] + [np.zeros(2)]
    order = sorted(range(len(loads)), key=lambda i: -float(np.hypot(*loads[i][2])))
    ways: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    for i in order:
        name, img, v, arm, style = loads[i]
        mag = float(np.hypot(*v))
        if mag <= 0:
            continue
        d = v / mag * max(mag / mu_f, MIN_ARROW_MM)
        pull, push = (img, img + d), (img - d, img)
        way = min((pull, push), key=lambda w: _crowding(w, img, drawn, others))
        arrows = [x for x in drawn if x[2] == ARROW_WEIGHT]
        if style == "load" and _crowding(way, img, drawn, [])[0] > 0.0:
            # lying over an arrow or along a link (the press's and the shaper's F_и5 hid in the
            # contour d–b, f–e): slide along its line of action past the arrows drawn on it, if that
            # lies over less (a slid way's own point is where it meets the arrow it follows)
            slid = [(w, w[0]) for w in _along_line(img, d, arrows)]
            best = min(slid + [(way, img)], key=lambda wo: _crowding(wo[0], wo[1], drawn, others))[0]
            way = best if best is way else ((best[0], best[1]) if float((best[1] - best[0]) @ d) > 0
                                            else (best[1], best[0]))
        ways[i] = way
        drawn.append((way[0], way[1], ARROW_WEIGHT))
    for i, (name, img, v, arm, style) in enumerate(loads):
        mag = float(np.hypot(*v))
        if mag <= 0:
            continue
        u = v / mag
        a, b = _pt(ways[i][0]), _pt(ways[i][1])
        ents.append(Arrow(f"force:{name}", a, b, style))
        labels.append(Label(force_tex(name), f"force:{name}", ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2),
                            "vector", (a, b)))
        if arm != 0.0 and style == "load":
            foot = img - float(img @ u) * u
            n_arm += 1
            if float(np.hypot(*foot)) > 3.0:
                arms.append((name, (arm_names or {}).get(name, f"h_{{{n_arm}}}"), foot))
    for name, h, foot in _shared_arms(arms):
        ents.append(Segment(f"arm:{name}", (0.0, 0.0), _pt(foot), "construction"))
        start = _own_part(foot, [f for _, _, f in arms])
        labels.append(Label(h, f"arm:{name}", _pt((start + foot) / 2), "vector", (_pt(start), _pt(foot))))
    for name, p in points.items():
        labels.append(Label(name, f"point:{name}", p, "point"))
    labels.append(Label("p", "point:p", (0.0, 0.0), "point"))
    values = {"pa": L.pa_mm_measured}
    return Scene("lever", (Scale("μv", mu_v, "(м/с)/мм"), Scale("μF", mu_f, "Н/мм")), tuple(ents), tuple(labels),
                 frozen({**points, "p": (0.0, 0.0)}), frozen(values))
