"""Crane sheet «Механизм подъёма» (A1): on the left the reeving scheme of the polyspast with the
table of the rope and polyspast; on the right the kinematic scheme of the hoist (motor – coupling –
brake – reducer – (open gear) – drum, ГОСТ 2.770) with the numbered parts and the table of their
parameters. Every number is a record of ``project.crane.hoist`` printed as the note prints it."""
from __future__ import annotations

from drawings.layout import Rect
from drawings.primitives import Transform
from drawings.scenes import crane_schemes as cs
from drawings.sheet import Sheet
from reportgen.crane import crane_code
from reportgen.crane.steps import plain_number, shown

NEEDS = ("crane",)
TITLE = "Механизм подъёма. Схема запасовки каната, кинематическая схема"
CLEAR_MM = 10.0


def available(project) -> bool:
    return getattr(project.task, "crane", None) is not None


def code(project, number: int) -> str:
    """The sheet's designation: [document] code (ГПМ.КП.00.00 by default) and the sheet's number."""
    return f"{crane_code(project.task.document)}.{number:03d}"


def reeving_rows(project) -> list[tuple[str, str]]:
    calc = project.crane
    h = calc.crane.hoist
    r = calc.hoist.records
    rows = [("Параметр", "Значение"),
            ("Грузоподъёмность Q, т", plain_number(h.capacity_t)),
            ("Масса подвески mп, кг", plain_number(h.hook_mass_kg)),
            ("Кратность полиспаста uп", str(h.polyspast.ratio)),
            ("Ветвей, навиваемых на барабан zб", str(h.polyspast.branches)),
            ("КПД полиспаста ηп", shown(r["eta_p"])),
            ("Наибольшее натяжение Smax, Н", shown(r["S_max"])),
            ("Канат", h.rope.designation),
            ("Разрывное усилие Fразр, Н", plain_number(h.rope.breaking_force_kn * 1000)),
            ("Требуемое разрывное усилие Fтр, Н", shown(r["F_req"])),
            ("Диаметр блока Dбл, мм", shown(r["D_bl"])),
            ("Диаметр барабана Dб, мм", shown(r["D_c"])),
            ("Длина барабана Lб, мм", shown(r["L_dr"])),
            ("Высота подъёма H, м", plain_number(h.lifting_height_m))]
    return rows


def drive_rows(project) -> list[tuple[str, str, str]]:
    calc = project.crane
    h = calc.crane.hoist
    rec = calc.hoist.records
    rows = [("Поз.", "Наименование", "Параметры")]
    m = h.motor
    rows.append(("1", f"Двигатель {m.designation}",
                 f"N = {plain_number(m.power_kw)} кВт при ПВ {plain_number(m.pv_percent)} %, "
                 f"n = {plain_number(m.speed_rpm)} об/мин, Jр = {plain_number(m.rotor_inertia)} кг·м²"))
    for c in h.couplings:
        rows.append(("2", c.designation, f"T = {plain_number(c.rated_torque)} Н·м, J = {plain_number(c.inertia)} кг·м²"))
    b = h.brake
    rows.append(("3", f"Тормоз {b.designation}", f"Tном = {plain_number(b.rated_torque)} Н·м, "
                 f"Tр = {shown(rec['T_br'])} Н·м, Dш = {plain_number(b.pulley_diameter_mm)} мм"))
    red = h.reducer
    rows.append(("4", f"Редуктор {red.designation}", f"uр = {plain_number(red.ratio)}, "
                 f"Tном = {plain_number(red.rated_torque)} Н·м, ηр = {plain_number(red.efficiency)}"))
    pos = 5
    if h.open_gear is not None:
        og = h.open_gear
        rows.append((str(pos), "Открытая зубчатая передача",
                     f"z = {og.z1}/{og.z2}, m = {plain_number(og.module_mm)} мм, uо = {shown(rec['u_og'])}"))
        pos += 1
    rows.append((str(pos), "Барабан", f"Dб = {shown(rec['D_c'])} мм, Lб = {shown(rec['L_dr'])} мм, "
                 f"t = {plain_number(h.drum.groove_pitch_mm)} мм"))
    rows.append(("", "Передаточное число механизма", f"uм = {shown(rec['u_mech'])}"))
    rows.append(("", "Скорость подъёма", f"vф = {shown(rec['v_act'])} м/с "
                 f"(задана {plain_number(h.lifting_speed_m_min / 60)} м/с)"))
    return rows


def draw(project, number: int, count: int) -> Sheet:
    calc = project.crane
    h = calc.crane.hoist
    sheet = Sheet.a1(project.task.document, title=TITLE, code=code(project, number), number=number, count=count)
    fr = sheet.frame
    top = sheet.extra_rect.y0 - CLEAR_MM
    # --- left: reeving scheme and its table
    rv = cs.Reeving(h.polyspast.ratio, h.polyspast.branches)
    height = 160.0
    w = max(rv.width + 120.0, 300.0)
    left = Rect(fr.x0 + CLEAR_MM, top - height - 110.0, fr.x0 + CLEAR_MM + w, top)
    view = sheet.place_view("reeving", left, Transform(1.0, (0.0, 0.0),
                                                         (left.x0 + w / 2, left.y0 + 55.0)))
    view.title("Схема запасовки каната")
    anchors = cs.draw_reeving(view, rv, height)
    lab = [("drum", "Барабан", (25.0, 0.0)), ("hook_block", "Крюковая подвеска", (25.0, -22.0))]
    if "equalizer" in anchors:
        lab.append(("equalizer", "Уравнительный блок", (40.0, 16.0)))
    for key, text, (dx, dy) in lab:
        p = anchors[key]
        q = (p[0] + dx, p[1] + dy)
        view.line(p, q, "thin")
        view.line(q, (q[0] + 48.0, q[1]), "thin")
        view.text((q[0] + 1.0, q[1] + 1.0), text, 3.5)
    view.text((-rv.width / 2 - 40.0, height / 2), f"uп = {h.polyspast.ratio}", 5.0, "center")
    rows = reeving_rows(project)
    widths = (95.0, 85.0)
    tw, th = cs.table_size(rows, widths)
    trect = Rect(left.x0, left.y0 - th - 8.0, left.x0 + tw, left.y0 - 8.0)
    cs.draw_table(sheet, "reeving_table", trect, "Канат и полиспаст", rows, widths)
    # --- right: the kinematic scheme and its table
    x0 = left.x1 + 25.0
    k_rect = Rect(x0, top - 250.0, fr.x1 - CLEAR_MM, top)
    kview = sheet.place_view("hoist_drive", k_rect, Transform(1.0, (0.0, 0.0), (k_rect.x0 + 8.0, k_rect.y0 + 60.0)))
    kview.title("Кинематическая схема механизма подъёма")
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
    cs.draw_table(sheet, "hoist_table", trect2, "Техническая характеристика механизма подъёма", rows2, widths2)
    return sheet
