"""Crane sheet «Механизм передвижения тележки» (A1): the kinematic scheme of the central drive
(ГОСТ 2.770) with the numbered parts and the table of its parameters and checks. Every number is a
record of ``project.crane.trolley`` printed as the note prints it."""
from __future__ import annotations

from drawings.layout import Rect
from drawings.primitives import Transform
from drawings.scenes import crane_schemes as cs
from drawings.sheet import Sheet
from reportgen.crane.steps import plain_number, shown

from .crane_hoist import CLEAR_MM, code

NEEDS = ("crane",)
TITLE = "Механизм передвижения тележки. Кинематическая схема"
#: The scheme is not to scale; it is drawn 1,2 times its nominal size to fill its half of the sheet.
SCALE = 1.2


def available(project) -> bool:
    return getattr(project.task, "crane", None) is not None


def rows(project) -> list[tuple[str, str, str]]:
    calc = project.crane
    t = calc.crane.trolley
    r = calc.trolley.records
    out = [("Поз.", "Наименование", "Параметры")]
    m = t.motor
    out.append(("1", f"Двигатель {m.designation}",
                f"N = {plain_number(m.power_kw)} кВт при ПВ {plain_number(m.pv_percent)} %, "
                f"n = {plain_number(m.speed_rpm)} об/мин"))
    b = t.brake
    out.append(("2", f"Тормоз {b.designation}", f"Tном = {plain_number(b.rated_torque)} Н·м, "
                f"Tр = {shown(r['T_br'])} Н·м, Dш = {plain_number(b.pulley_diameter_mm)} мм"))
    for c in t.couplings:
        out.append(("3", c.designation, f"T = {plain_number(c.rated_torque)} Н·м"))
    red = t.reducer
    out.append(("4", f"Редуктор {red.designation}", f"uр = {plain_number(red.ratio)}, "
                f"Tном = {plain_number(red.rated_torque)} Н·м"))
    w = t.wheel
    out.append(("5", f"Колесо приводное {w.designation}", f"Dк = {plain_number(w.diameter_mm)} мм, "
                f"{t.driven_wheels} шт.; [P] = {plain_number(w.allowable_load_kn)} кН"))
    out.append(("6", "Колесо неприводное", f"{t.wheels - t.driven_wheels} шт."))
    out.append(("", f"Рельс {t.rail.designation}", f"b = {plain_number(t.rail.head_width_mm)} мм"))
    out.append(("", "Статическое сопротивление", f"Wст = {shown(r['W_st'])} Н"))
    out.append(("", "Скорость передвижения", f"vф = {shown(r['v_act'])} м/с "
                f"(задана {plain_number(t.speed_m_min / 60)} м/с)"))
    out.append(("", "Запас сцепления при пуске", f"kсц = {shown(r['k_sp'])}"))
    if "k_sb" in r:
        out.append(("", "Запас сцепления при торможении", f"kсц = {shown(r['k_sb'])}"))
    return out


def draw(project, number: int, count: int) -> Sheet:
    t = project.crane.crane.trolley
    sheet = Sheet.a1(project.task.document, title=TITLE, code=code(project, number), number=number, count=count)
    fr = sheet.frame
    top = sheet.extra_rect.y0 - CLEAR_MM
    gauge, base = 340.0, 300.0
    table = rows(project)
    widths = (14.0, 120.0, 150.0)
    tw, th = cs.table_size(table, widths)
    x0 = fr.x1 - CLEAR_MM - tw
    trect = Rect(x0, sheet.title_rect.y1 + 10.0, x0 + tw, sheet.title_rect.y1 + 10.0 + th)
    cs.draw_table(sheet, "trolley_table", trect, "Техническая характеристика механизма передвижения тележки",
                  table, widths)
    k_rect = Rect(fr.x0 + CLEAR_MM, fr.y0 + CLEAR_MM, trect.x0 - 8.0, top)
    view = sheet.place_view("trolley_drive", k_rect, Transform(SCALE, (0.0, 0.0),
                                                               (k_rect.x0 + SCALE * (gauge / 2 + 20.0),
                                                                k_rect.center[1] - 10.0)))
    view.title("Кинематическая схема механизма передвижения тележки")
    sheet.set_scale(Sheet.NO_SCALE)            # schemes are drawn without scale (ГОСТ 2.701)
    anch = cs.draw_trolley_drive(view, t.driven_wheels, t.wheels, gauge, base)
    for key, n, (dx, dy) in (("motor", 1, (-10.0, 40.0)), ("brake", 2, (0.0, 50.0)), ("coupling", 3, (-10.0, 70.0)),
                             ("reducer", 4, (20.0, 60.0)), ("wheel", 5, (25.0, 10.0)),
                             ("idle_wheel", 6, (25.0, 15.0))):
        p = anch[key]
        cs.callout(view, p, (p[0] + dx, p[1] + dy), n)
    view.text((0.0, -base / 2 - 45.0), f"Колея {plain_number(t.gauge_m)} м, база {plain_number(t.wheel_base_m)} м "
              "(схема без масштаба)", 3.5, "center")
    return sheet
