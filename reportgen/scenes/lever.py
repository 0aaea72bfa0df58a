"""Zhukovsky's lever as a scene: the velocity plan of the analysed position turned by 90° at the
replica's μv (mm), every load at the image of its point at one round force scale (a force shorter
than ``MIN_ARROW_MM`` drawn at that length), the balancing force F_ур at the image of the crank pin
(found from the lever), each force named beside its own arrow, and the arm of each force with a
non-zero arm (from the pole square to the force's line) named h1, h2, … in the order of the terms
(or by ``arm_names``)."""
from __future__ import annotations

import numpy as np

from .scales import FORCE_SERIES, round_scale
from ..geometry import vec2 as _pt
from .scene import Arrow, Entity, Label, Scale, Scene, Segment, frozen
from .forces import force_tex
from ..tolerances import ABS_ZERO, MM_ROUNDOFF

#: The lever's loads: the largest drawn this long (mm), none shorter than MIN_ARROW_MM.
LEVER_ARROW_MM = 40.0
MIN_ARROW_MM = 7.0


def lever_scene(ks, linkage, arm_names: dict[str, str] | None = None, mu_v: float | None = None) -> Scene:
    """The lever of :class:`reportgen.kinetostatics.Kinetostatics` ``ks`` (its analysed position);
    ``mu_v``: the turned plan at another round μv than the note's (an A3 control sheet)."""
    from ..kinetostatics.zhukovsky import turn_cw
    L, lev, r = ks.graphical.lever, ks.lever, ks.reactions
    kin = r.kin
    mu_v = L.scale if mu_v is None else mu_v
    k_arm = L.scale / mu_v            # the measured arms (mm at the note's μv) at this μv
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
    loads = [(t.name, np.asarray(f.image)[0] / mu_v, np.asarray(f.vector)[0], t.arm_mm_measured * k_arm, "load")
             for t, f in zip(L.terms, lev.forces) if t.magnitude > 0.0]
    pin = np.asarray(lev.crank_pin_image)[0] / mu_v
    fb = np.asarray(r.balancing_force)[0]
    loads.append(("Fур", pin, fb, 0.0, "found"))
    mu_f = round_scale(max([float(np.hypot(*v)) for _, _, v, _, _ in loads] + [ABS_ZERO]), LEVER_ARROW_MM, FORCE_SERIES)
    labels: list[Label] = []
    n_arm = 0
    for name, img, v, arm, style in loads:
        mag = float(np.hypot(*v))
        if mag <= 0:
            continue
        u = v / mag
        end = img + u * max(mag / mu_f, MIN_ARROW_MM)
        a, b = _pt(img), _pt(end)
        ents.append(Arrow(f"force:{name}", a, b, style))
        labels.append(Label(force_tex(name), f"force:{name}", ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2),
                            "vector", (a, b)))
        if arm != 0.0 and style == "load":
            foot = img - float(img @ u) * u
            n_arm += 1
            if float(np.hypot(*foot)) > 3.0:
                ents.append(Segment(f"arm:{name}", (0.0, 0.0), _pt(foot), "construction"))
                h = (arm_names or {}).get(name, f"h_{{{n_arm}}}")
                labels.append(Label(h, f"arm:{name}", (float(foot[0]) / 2, float(foot[1]) / 2), "vector",
                                    ((0.0, 0.0), _pt(foot))))
    for name, p in points.items():
        labels.append(Label(name, f"point:{name}", p, "point"))
    labels.append(Label("p", "point:p", (0.0, 0.0), "point"))
    values = {"pa": L.pa_mm_measured}
    return Scene("lever", (Scale("μv", mu_v, "(м/с)/мм"), Scale("μF", mu_f, "Н/мм")), tuple(ents), tuple(labels),
                 frozen({**points, "p": (0.0, 0.0)}), frozen(values))
