"""Sheet 2 «Силовой расчёт рычажного механизма» (A1): each Assur group (last attached first) and the
crank cut out at μl in the analysed position with their forces at a stated force scale, the force
polygon of each at its μF (the note's scales and lengths), and Zhukovsky's lever. Every number comes
from :func:`reportgen.kinetostatics.results.kinetostatics_of`."""
from __future__ import annotations

import numpy as np

from drawings.sheet import Sheet
from reportgen.kinetostatics.graphical import round_scale
from reportgen.project import Project

NEEDS: tuple[str, ...] = ("linkage", "structure", "kinematics", "kinetostatics")
TITLE = "Силовой расчёт рычажного механизма"


def available(project: Project) -> bool:
    return project.task.mechanism is not None


def code(number: int) -> str:
    return f"ТММ.КП.00.00.{number:03d}"


def draw(project: Project, number: int, count: int) -> Sheet:
    from drawings.scenes import kinetostatics_views as kv
    from reportgen.kinetostatics.results import kinetostatics_of
    from reportgen.kinetostatics.zhukovsky import turn_cw

    ks = kinetostatics_of(project)
    lk, st = project.linkage, project.structure
    g = ks.graphical
    sheet = Sheet.a1(project.task.document, title=TITLE, code=code(number), number=number, count=count)
    by_key = {gr.key: gr for gr in st.groups}
    where = f"положение {ks.position}, " if ks.position is not None else ""
    pts = np.array([np.asarray(m.pos)[0] for m in ks.reactions.kin.points.values()])
    mu_l = round_scale(float(np.hypot(*np.ptp(pts, axis=0))), kv.SHEET_SCHEME_MM)
    note = f"Положение силового расчёта: {where}φ1 = {ks.phi_deg:.2f}°".replace(".", ",")
    from drawings import style
    pv = sheet.add_view("position", style.text_width(note, 5.0) + 4.0, 9.0, preferred="top-left")
    pv.text_mm((pv.rect.x0 + 2.0, pv.rect.y0 + 2.0), note, 5.0)
    for gg in g.groups:
        grp = by_key[gg.key]
        segs, hinges, sliders, letters = kv.group_geometry(ks, lk, grp.links, gg.key)
        kv.free_body_view(sheet, f"group {gg.key}", f"Группа {grp.label}", segs, hinges, sliders, letters,
                          kv.group_arrows(ks, grp.links, gg.key, gg.splits), mu_l, "top-left")
    segs, hinges, sliders, letters = kv.group_geometry(ks, lk, (ks.reactions.crank,), None)
    kv.free_body_view(sheet, "crank", "Ведущее звено", segs, hinges, sliders, letters, kv.crank_arrows(ks),
                      mu_l, "top-left")
    for gg in g.groups:
        kv.polygon_view(sheet, f"polygon {gg.key}", f"План сил группы {by_key[gg.key].label}", gg.polygon,
                        "bottom-left")
    kv.polygon_view(sheet, "polygon crank", "План сил ведущего звена", g.crank.polygon, "bottom-left")
    kin = ks.reactions.kin
    mu_v = g.lever.scale
    points = {}
    for name, mo in kin.points.items():
        img = turn_cw(np.asarray(mo.vel))[0] / mu_v
        if float(np.hypot(*img)) > 1e-9:
            points[name.lower()] = img
    segments = []
    for k in lk.moving:
        names = [n.lower() for n in lk.bodies[k].points if n.lower() in points]
        segments += [("p", n) for n in names] + list(zip(names, names[1:]))
    loads = [(np.asarray(f.image)[0] / mu_v, np.asarray(f.vector)[0], kv.plain(t.name), t.arm_mm_measured)
             for t, f in zip(g.lever.terms, ks.lever.forces) if t.magnitude > 0.0]
    kv.lever_view(sheet, "lever", points, segments, loads, mu_v, "top-right")
    return sheet
