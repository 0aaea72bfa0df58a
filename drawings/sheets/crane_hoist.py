"""Crane sheet «hoist mechanism» (A1): on the left the reeving scheme of the polyspast with the
table of the rope and polyspast; on the right the kinematic scheme of the hoist (motor – coupling –
brake – reducer – (open gear) – drum, ГОСТ 2.770) with the numbered parts and the table of their
parameters. Every number is a record of ``project.crane.hoist`` printed as the note prints it;
every word comes from ``crane.sheet`` of the strings catalogue in the task's language."""
from __future__ import annotations

from drawings.layout import Rect
from drawings.primitives import Transform
from drawings.scenes import crane_schemes as cs
from drawings.sheet import Sheet
from drawings.words import decimal_mark, tr, tr_list
from reportgen.crane import crane_code
from reportgen.crane.steps import plain_number, shown

NEEDS = ("crane",)
CLEAR_MM = 10.0


def available(project) -> bool:
    return getattr(project.task, "crane", None) is not None


def code(project, number: int) -> str:
    """The sheet's designation: [document] code (the language's ``crane.sheet.default_code``,
    ГПМ.КП.00.00 in Russian, when the task leaves it) and the sheet's number."""
    return f"{crane_code(project.task.document, tr('crane.sheet.default_code'))}.{number:03d}"


def num(value: float, digits: int = 4) -> str:
    """A number as the note prints it, with the sheet language's decimal mark."""
    return plain_number(value, digits, decimal_mark())


def rec(record) -> str:
    """A record's result as the note prints it, with the sheet language's decimal mark."""
    return shown(record, decimal_mark())


def reeving_rows(project) -> list[tuple[str, ...]]:
    calc = project.crane
    h = calc.crane.hoist
    r = calc.hoist.records
    k = "crane.sheet.reeving."
    rows = [tuple(tr_list(k + "head")),
            (tr(k + "capacity"), num(h.capacity_t)),
            (tr(k + "hook_mass"), num(h.hook_mass_kg)),
            (tr(k + "ratio"), str(h.polyspast.ratio)),
            (tr(k + "branches"), str(h.polyspast.branches)),
            (tr(k + "eta_p"), rec(r["eta_p"])),
            (tr(k + "S_max"), rec(r["S_max"])),
            (tr(k + "rope"), h.rope.designation),
            (tr(k + "F_br"), num(h.rope.breaking_force_kn * 1000)),
            (tr(k + "F_req"), rec(r["F_req"])),
            (tr(k + "D_bl"), rec(r["D_bl"])),
            (tr(k + "D_c"), rec(r["D_c"])),
            (tr(k + "L_dr"), rec(r["L_dr"])),
            (tr(k + "height"), num(h.lifting_height_m))]
    return rows


def drive_rows(project) -> list[tuple[str, ...]]:
    calc = project.crane
    h = calc.crane.hoist
    r = calc.hoist.records
    k = "crane.sheet.drive."
    rows = [tuple(tr_list(k + "head"))]
    m = h.motor
    rows.append(("1", tr(k + "motor", name=m.designation),
                 tr(k + "motor_hoist", n=num(m.power_kw), pv=num(m.pv_percent), rpm=num(m.speed_rpm),
                    j=num(m.rotor_inertia))))
    for c in h.couplings:
        rows.append(("2", c.designation, tr(k + "coupling_hoist", t=num(c.rated_torque), j=num(c.inertia))))
    b = h.brake
    rows.append(("3", tr(k + "brake", name=b.designation),
                 tr(k + "brake_params", t=num(b.rated_torque), tr=rec(r["T_br"]), d=num(b.pulley_diameter_mm))))
    red = h.reducer
    rows.append(("4", tr(k + "reducer", name=red.designation),
                 tr(k + "reducer_hoist", u=num(red.ratio), t=num(red.rated_torque), eta=num(red.efficiency))))
    pos = 5
    if h.open_gear is not None:
        og = h.open_gear
        rows.append((str(pos), tr(k + "open_gear"),
                     tr(k + "open_gear_params", z1=str(og.z1), z2=str(og.z2), m=num(og.module_mm),
                        u=rec(r["u_og"]))))
        pos += 1
    rows.append((str(pos), tr(k + "drum"),
                 tr(k + "drum_params", d=rec(r["D_c"]), l=rec(r["L_dr"]), t=num(h.drum.groove_pitch_mm))))
    rows.append(("", tr(k + "u_mech"), tr(k + "u_mech_value", u=rec(r["u_mech"]))))
    rows.append(("", tr(k + "lifting_speed"),
                 tr(k + "speed_value", v=rec(r["v_act"]), v0=num(h.lifting_speed_m_min / 60))))
    return rows


def draw(project, number: int, count: int) -> Sheet:
    calc = project.crane
    h = calc.crane.hoist
    sheet = Sheet.a1(project.task.document, title=tr("crane.sheet.hoist_title"), code=code(project, number), number=number, count=count)
    fr = sheet.frame
    top = sheet.extra_rect.y0 - CLEAR_MM
    # --- left: reeving scheme and its table
    rv = cs.Reeving(h.polyspast.ratio, h.polyspast.branches)
    height = 160.0
    w = max(rv.width + 120.0, 300.0)
    left = Rect(fr.x0 + CLEAR_MM, top - height - 110.0, fr.x0 + CLEAR_MM + w, top)
    view = sheet.place_view("reeving", left, Transform(1.0, (0.0, 0.0),
                                                         (left.x0 + w / 2, left.y0 + 55.0)))
    view.title(tr("crane.sheet.reeving_view"))
    anchors = cs.draw_reeving(view, rv, height)
    lab = [("drum", tr("crane.sheet.drum_label"), (25.0, 0.0)),
           ("hook_block", tr("crane.sheet.hook_block_label"), (25.0, -22.0))]
    if "equalizer" in anchors:
        lab.append(("equalizer", tr("crane.sheet.equalizer_label"), (40.0, 16.0)))
    for key, text, (dx, dy) in lab:
        p = anchors[key]
        q = (p[0] + dx, p[1] + dy)
        view.line(p, q, "thin")
        view.line(q, (q[0] + 48.0, q[1]), "thin")
        view.text((q[0] + 1.0, q[1] + 1.0), text, 3.5)
    view.text((-rv.width / 2 - 40.0, height / 2), tr("crane.sheet.ratio_label", u=str(h.polyspast.ratio)), 5.0, "center")
    rows = reeving_rows(project)
    widths = (95.0, 85.0)
    tw, th = cs.table_size(rows, widths)
    trect = Rect(left.x0, left.y0 - th - 8.0, left.x0 + tw, left.y0 - 8.0)
    cs.draw_table(sheet, "reeving_table", trect, tr("crane.sheet.reeving_table"), rows, widths)
    # --- right: the kinematic scheme and its table
    x0 = left.x1 + 25.0
    k_rect = Rect(x0, top - 250.0, fr.x1 - CLEAR_MM, top)
    kview = sheet.place_view("hoist_drive", k_rect, Transform(1.0, (0.0, 0.0), (k_rect.x0 + 8.0, k_rect.y0 + 60.0)))
    kview.title(tr("crane.sheet.hoist_view"))
    sheet.set_scale(Sheet.NO_SCALE)            # schemes are drawn without scale (ГОСТ 2.701)
    anch = cs.draw_hoist_drive(kview, h.open_gear is not None)
    callouts = [("motor", 1, (-10.0, 30.0)), ("coupling", 2, (-8.0, 40.0)), ("brake", 3, (0.0, 40.0)),
                ("reducer", 4, (-20.0, 20.0))]
    pos = 5
    if "open_gear" in anch:
        callouts.append(("open_gear", pos, (-30.0, -70.0)))
        pos += 1
    callouts.append(("drum", pos, (10.0, 25.0)))
    for key, n, (dx, dy) in callouts:
        p = anch[key]
        cs.callout(kview, p, (p[0] + dx, p[1] + dy), n)
    rows2 = drive_rows(project)
    widths2 = (14.0, 120.0, 150.0)
    tw2, th2 = cs.table_size(rows2, widths2)
    trect2 = Rect(x0, sheet.title_rect.y1 + 10.0, x0 + tw2, sheet.title_rect.y1 + 10.0 + th2)
    cs.draw_table(sheet, "hoist_table", trect2, tr("crane.sheet.hoist_table"), rows2, widths2)
    return sheet
