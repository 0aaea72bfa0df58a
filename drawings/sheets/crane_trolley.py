"""Crane sheet «trolley travel mechanism» (A1): the kinematic scheme of the central drive
(ГОСТ 2.770) with the numbered parts and the table of its parameters and checks. Every number is a
record of ``project.crane.trolley`` printed as the note prints it."""
from __future__ import annotations

from drawings.layout import Rect
from drawings.primitives import Transform
from drawings.scenes import crane_schemes as cs
from drawings.sheet import Sheet
from drawings.words import tr, tr_list

from .crane_hoist import CLEAR_MM, code, num, rec

NEEDS = ("crane",)
#: The scheme is not to scale; it is drawn 1,2 times its nominal size to fill its half of the sheet.
SCALE = 1.2


def available(project) -> bool:
    return getattr(project.task, "crane", None) is not None


def rows(project) -> list[tuple[str, ...]]:
    calc = project.crane
    t = calc.crane.trolley
    r = calc.trolley.records
    k = "crane.sheet.drive."
    out = [tuple(tr_list(k + "head"))]
    m = t.motor
    out.append(("1", tr(k + "motor", name=m.designation),
                tr(k + "motor_trolley", n=num(m.power_kw), pv=num(m.pv_percent), rpm=num(m.speed_rpm))))
    b = t.brake
    out.append(("2", tr(k + "brake", name=b.designation),
                tr(k + "brake_params", t=num(b.rated_torque), tr=rec(r["T_br"]), d=num(b.pulley_diameter_mm))))
    for c in t.couplings:
        out.append(("3", c.designation, tr(k + "coupling_trolley", t=num(c.rated_torque))))
    red = t.reducer
    out.append(("4", tr(k + "reducer", name=red.designation),
                tr(k + "reducer_trolley", u=num(red.ratio), t=num(red.rated_torque))))
    w = t.wheel
    out.append(("5", tr(k + "wheel_driven", name=w.designation),
                tr(k + "wheel_driven_params", d=num(w.diameter_mm), n=str(t.driven_wheels),
                   p=num(w.allowable_load_kn))))
    out.append(("6", tr(k + "wheel_idle"), tr(k + "pieces", n=str(t.wheels - t.driven_wheels))))
    out.append(("", tr(k + "rail", name=t.rail.designation), tr(k + "rail_params", b=num(t.rail.head_width_mm))))
    out.append(("", tr(k + "W_st"), tr(k + "W_st_value", w=rec(r["W_st"]))))
    out.append(("", tr(k + "travel_speed"), tr(k + "speed_value", v=rec(r["v_act"]), v0=num(t.speed_m_min / 60))))
    out.append(("", tr(k + "adhesion_start"), tr(k + "adhesion_value", k=rec(r["k_sp"]))))
    if "k_sb" in r:
        out.append(("", tr(k + "adhesion_brake"), tr(k + "adhesion_value", k=rec(r["k_sb"]))))
    return out


def draw(project, number: int, count: int) -> Sheet:
    t = project.crane.crane.trolley
    sheet = Sheet.a1(project.task.document, title=tr("crane.sheet.trolley_title"), code=code(project, number), number=number, count=count)
    fr = sheet.frame
    top = sheet.extra_rect.y0 - CLEAR_MM
    gauge, base = 340.0, 300.0
    table = rows(project)
    widths = (14.0, 120.0, 150.0)
    tw, th = cs.table_size(table, widths)
    x0 = fr.x1 - CLEAR_MM - tw
    trect = Rect(x0, sheet.title_rect.y1 + 10.0, x0 + tw, sheet.title_rect.y1 + 10.0 + th)
    cs.draw_table(sheet, "trolley_table", trect, tr("crane.sheet.trolley_table"),
                  table, widths)
    k_rect = Rect(fr.x0 + CLEAR_MM, fr.y0 + CLEAR_MM, trect.x0 - 8.0, top)
    view = sheet.place_view("trolley_drive", k_rect, Transform(SCALE, (0.0, 0.0),
                                                               (k_rect.x0 + SCALE * (gauge / 2 + 20.0),
                                                                k_rect.center[1] - 10.0)))
    view.title(tr("crane.sheet.trolley_view"))
    sheet.set_scale(Sheet.NO_SCALE)            # schemes are drawn without scale (ГОСТ 2.701)
    anch = cs.draw_trolley_drive(view, t.driven_wheels, t.wheels, gauge, base)
    for key, n, (dx, dy) in (("motor", 1, (-10.0, 40.0)), ("brake", 2, (0.0, 50.0)), ("coupling", 3, (-10.0, 70.0)),
                             ("reducer", 4, (20.0, 60.0)), ("wheel", 5, (25.0, 10.0)),
                             ("idle_wheel", 6, (25.0, 15.0))):
        p = anch[key]
        cs.callout(view, p, (p[0] + dx, p[1] + dy), n)
    view.text((0.0, -base / 2 - 45.0), tr("crane.sheet.gauge_base", gauge=num(t.gauge_m), base=num(t.wheel_base_m)), 3.5, "center")
    return sheet
