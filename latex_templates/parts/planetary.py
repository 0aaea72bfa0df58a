"""Part «Синтез планетарного редуктора» (subsection 4.2): the drive's required ratio, the scheme and
Willis' formula, the tooth numbers with every condition written with its numbers, the alternatives,
Kutzbach's velocity triangle and the angular-velocity plan, the achieved crank speed.

Numbers come from :class:`reportgen.project.PlanetaryStage` (design, drive, triangle, check)
through calculation records or filters.
"""
from __future__ import annotations

from typing import cast

from ..render import Tex

from reportgen.calc import CalcRecord, Var
from reportgen.planetary.schemes import expand

from . import PartContent
from .gear_pair import _rec

NEEDS = ("planetary",)


def available(project) -> bool:
    return project.task.planetary is not None


def _zvars(design) -> dict[str, Var]:
    sch = design.scheme
    z1, z2, z2p, z3 = expand(sch, design.z)
    v = {"z1": Var("z1", "z_1", z1, "", "число зубьев центрального колеса 1"),
         "z2": Var("z2", "z_2", z2, "", "число зубьев сателлита 2"),
         "z3": Var("z3", "z_3", z3, "", "число зубьев неподвижного центрального колеса 3")}
    if sch.two_row:
        v["z2p"] = Var("z2p", "z_{2'}", z2p, "", "число зубьев венца 2′ сателлита")
    return v


def willis_expr(design) -> str:
    """u1H = 1 − u13^H written for the scheme (Willis)."""
    sch = design.scheme
    if not sch.two_row:
        return "1 + z3 / z1"
    sign = "+" if sch.sigma < 0 else "-"
    return f"1 {sign} z2 * z3 / (z1 * z2p)"


def planetary_records(stage) -> dict[str, object]:
    """Records and number lines of subsection 4.2, keyed by short names."""
    d = stage.design
    sch = d.scheme
    zv = _zvars(d)
    r: dict[str, object] = {}
    drive = stage.drive
    if drive is not None:
        n = Var("n", r"n_\text{дв}", drive.motor_rpm, "об/мин", "частота вращения вала двигателя")
        r["omega_m"] = _rec(r"\omega_\text{дв}", "pi * n / 30", "рад/с", 3, "угловая скорость вала двигателя", n=n)
        za = Var("za", "z_a", drive.z1_open, "", "число зубьев шестерни открытой передачи")
        zb = Var("zb", "z_b", drive.z2_open, "", "число зубьев колеса открытой передачи")
        w1 = Var("w1", r"\omega_\text{кр}", drive.omega_crank, "рад/с", "угловая скорость кривошипа")
        r["u_req"] = _rec(r"u_\text{тр}", "za * wm / (zb * w1)", "", 3, "требуемое передаточное отношение редуктора",
                          za=za, wm=r["omega_m"], zb=zb, w1=w1)
    names = {k: v for k, v in zv.items() if k in willis_expr(d)}
    r["u1h"] = _rec("u_{1H}^{(3)}", willis_expr(d), "", 4, "передаточное отношение от колеса 1 к водилу", **names)
    u_main = cast(CalcRecord, r["u1h"])
    if d.driver == "carrier":
        r["uh1"] = _rec("u_{H1}^{(3)}", "1 / u1h", "", 4, "передаточное отношение от водила к колесу 1", u1h=r["u1h"])
        u_main = cast(CalcRecord, r["uh1"])
    target = Var("ut", r"u_\text{тр}", stage.target, "", "требуемое передаточное отношение")
    u_shown = Var("u", u_main.symbol, round(abs(u_main.value), 4), "")
    r["deviation"] = _rec(r"\delta_u", "(u - ut) / ut * 100", "%", 2, "отклонение передаточного отношения",
                          u=u_shown, ut=Var("ut", r"u_\text{тр}", round(stage.target, 3), "", "требуемое передаточное отношение"))
    r["target"] = target
    # adjacency: (2a/m)·sin(π/K) > z_p + 2ha*, and the course's K limit; 2a/m = z1 ± z2
    adj = d.adjacency
    centre = "z1 + z2" if sch.row1 == "external" else "z1 - z2"
    pz = "z2" if adj.planet_label == "2" else "z2p"
    ha = Var("ha", r"h_a^*", adj.ha, "")
    K = Var("K", "K", adj.satellites, "", "число сателлитов")
    r["adj_left"] = _rec(r"\frac{2a}{m}\sin\frac{\pi}{K}", f"({centre}) * sin(pi / K)", "", 3, "",
                         z1=zv["z1"], z2=zv["z2"], K=K)
    r["adj_right"] = _rec(r"z_p + 2h_a^*", f"{pz} + 2 * ha", "", 3, "", ha=ha, **{pz: zv[pz]})
    if adj.planet_z + 2 * adj.ha < adj.centre_sum:
        names = {pz: zv[pz], "z1": zv["z1"], "z2": zv["z2"]}
        r["k_limit"] = _rec(r"K_{\max}", f"180 / degrees(asin(({pz} + 2 * ha) / ({centre})))", "", 3,
                            "наибольшее число сателлитов по условию соседства", ha=ha, **names)
    # assembly quotient
    asm = d.assembly
    if sch.two_row:
        sign = "+" if asm.sign == "+" else "-"
        g = Var("g", r"\text{НОД}(z_2, z_{2'})", asm.g, "", "наибольший общий делитель чисел зубьев венцов сателлита")
        expr = f"(z1 * z2p {sign} z3 * z2) / (K * g)" if sign == "+" else "abs(z1 * z2p - z3 * z2) / (K * g)"
        r["assembly"] = _rec("C", expr, "", 4, "", z1=zv["z1"], z2p=zv["z2p"], z3=zv["z3"], z2=zv["z2"], K=K, g=g)
    else:
        r["assembly"] = _rec("C", "(z1 + z3) / K", "", 4, "", z1=zv["z1"], z3=zv["z3"], K=K)
    return r


def triangle_records(stage, u_main: CalcRecord) -> dict[str, CalcRecord]:
    tri = stage.triangle
    d = stage.design
    z1 = expand(d.scheme, d.z)[0]
    m = Var("m", "m", tri.module, "мм", "модуль колёс редуктора")
    r: dict[str, CalcRecord] = {}
    w1 = Var("w1", r"\omega_1", abs(tri.omega1), "рад/с", "угловая скорость колеса 1")
    r["r1"] = _rec("r_1", "m * z1 / 2", "мм", 3, "радиус делительной окружности колеса 1", m=m,
                   z1=Var("z1", "z_1", z1, ""))
    del z1
    zv = _zvars(d)
    centre = "z1 + z2" if d.scheme.row1 == "external" else "z1 - z2"
    r["a"] = _rec("a", f"m * ({centre}) / 2", "мм", 3, "межосевое расстояние (радиус оси сателлитов)", m=m,
                  z1=zv["z1"], z2=zv["z2"])
    r["v_a"] = _rec("v_A", "w1 * r1 / 1000", "м/с", 4, "скорость точки A", w1=w1, r1=r["r1"])
    la = Var("la", r"\overline{pa}", tri.vector_mm, "мм", "длина вектора скорости точки A на чертеже")
    r["mu_v"] = _rec(r"\mu_v", "v_a / la", "(м/с)/мм", 4, "масштаб скоростей", v_a=r["v_a"], la=la)
    lb = Var("lb", r"\overline{pb}", abs(tri.v_b_mm_read), "мм", "длина вектора скорости точки B, измеренная на чертеже")
    r["v_b"] = _rec("v_B", "mu_v * lb", "м/с", 4, "скорость точки B (оси сателлита)", mu_v=r["mu_v"], lb=lb)
    r["omega_h"] = _rec(r"\omega_H", "v_b / (a / 1000)", "рад/с", 4, "угловая скорость водила", v_b=r["v_b"], a=r["a"])
    if d.driver == "wheel":
        r["u_graph"] = _rec(r"u_\text{гр}", "w1 / wh", "", 4, "передаточное отношение по построению",
                            w1=w1, wh=r["omega_h"])
    else:
        r["u_graph"] = _rec(r"u_\text{гр}", "wh / w1", "", 4, "передаточное отношение по построению",
                            w1=w1, wh=r["omega_h"])
    ug = Var("ug", r"u_\text{гр}", round(r["u_graph"].value, 4), "")
    ua = Var("ua", u_main.symbol, round(abs(u_main.value), 4), "")
    r["diff"] = _rec(r"\Delta u", "(ug - ua) / ua * 100", "%", 3, "", ug=ug, ua=ua)
    plan = tri.plan
    cuts = dict(plan.cuts)
    x1 = Var("x1", r"\overline{p1}", abs(cuts["1"]), "мм", "отрезок луча колеса 1 на плане угловых скоростей")
    xh = Var("xh", r"\overline{pH}", abs(cuts["H"]), "мм", "отрезок луча водила на плане угловых скоростей")
    if d.driver == "wheel":
        r["u_plan"] = _rec(r"u_\text{пл}", "x1 / xh", "", 4, "передаточное отношение по плану угловых скоростей", x1=x1, xh=xh)
    else:
        r["u_plan"] = _rec(r"u_\text{пл}", "xh / x1", "", 4, "передаточное отношение по плану угловых скоростей", x1=x1, xh=xh)
    return r


def content(project) -> PartContent:
    from dataclasses import replace

    from drawings.scenes.planetary import sheet_triangle
    from latex_templates.figures.gears import planetary_figure

    stage = project.planetary
    if stage.triangle is not None:       # the construction as drawn on sheet 4
        stage = replace(stage, triangle=sheet_triangle(stage))
    d = stage.design
    r = planetary_records(stage)
    u_main = cast(CalcRecord, r.get("uh1", r["u1h"]))
    tr = triangle_records(stage, u_main) if stage.triangle is not None else None
    check = stage.check
    crank = None
    if check is not None:
        drive = stage.drive
        ua = Var("ua", r"u_\text{откр}", drive.open_ratio, "", "передаточное число открытой передачи")
        uu = Var("u", "u", abs(d.ratio), "")
        w = _rec(r"\omega_\text{кр}'", "wm / (ua * u)", "рад/с", 4, "достигнутая угловая скорость кривошипа",
                 wm=r["omega_m"], ua=ua, u=uu)
        ws = Var("ws", r"\omega_\text{кр}'", round(w.value, 4), "рад/с")
        w1 = Var("w1", r"\omega_\text{кр}", round(drive.omega_crank, 4), "рад/с")
        dev = _rec(r"\delta_\omega", "(ws - w1) / w1 * 100", "%", 2, "", ws=ws, w1=w1)
        crank = {"omega": w, "dev": dev}
    z = expand(d.scheme, d.z)
    labels = d.scheme.labels
    z_row = [(Tex(f"$z_{{{lab.replace('′', chr(39))}}}$"), zz) for lab, zz in zip(labels, d.z)]
    alternatives = []
    for cand in d.alternatives:
        alternatives.append(("/".join(str(v) for v in cand.z), cand.satellites, abs(cand.ratio),
                             100 * cand.deviation, cand.size))
    undercut = []
    kinds = {"external": "колесо с~внешними зубьями", "internal": "колесо с~внутренними зубьями",
             "internal mesh": "разность чисел зубьев во~внутреннем зацеплении"}
    for it in d.undercut.items:
        what = it.what.replace("′", "'")
        if it.kind == "internal mesh":
            a_, b_ = what.split("−")
            sym = Tex(f"z_{{{a_}}} - z_{{{b_}}}")
        else:
            sym = Tex(f"z_{{{what}}}")
        undercut.append({"sym": sym, "value": it.value, "limit": it.limit, "holds": it.holds,
                         "kind": Tex(kinds[it.kind])})
    figures = {}
    if stage.triangle is not None:
        figures["planetary_scheme"] = planetary_figure(stage)
    ctx = {"stage": stage, "d": d, "r": r, "tr": tr, "tri": stage.triangle, "crank": crank, "z": z,
           "z_row": z_row, "alternatives": alternatives, "undercut": undercut,
           "coax": _coax_text(d), "u_main": u_main}
    concl = _conclusion(stage, tr)
    return PartContent("sections/planetary.tex.j2", ctx, figures, (concl,))


def _coax_text(d) -> dict:
    """Both sides of the coaxiality condition as LaTeX: symbols and numbers."""
    sch = d.scheme
    z1, z2, z2p, z3 = expand(sch, d.z)
    p_sym, p_val = ("z_{2'}", z2p) if sch.two_row else ("z_2", z2)
    s1 = "+" if sch.row1 == "external" else "-"
    s2 = "+" if sch.row2 == "external" else "-"
    left_sym = f"z_1 {s1} z_2"
    left_num = f"{z1} {s1} {z2}"
    right_sym = f"z_3 {s2} {p_sym}"
    right_num = f"{z3} {s2} {p_val}"
    return {"left_sym": Tex(left_sym), "left_num": Tex(left_num), "left": d.coaxial.left,
            "right_sym": Tex(right_sym), "right_num": Tex(right_num), "right": d.coaxial.right,
            "holds": d.coaxial.holds}


def _conclusion(stage, tr) -> str:
    from latex_templates.numbers import mnum
    d = stage.design
    zs = ", ".join(f"$z_{{{lab.replace('′', chr(39))}}} = {zz}$" for lab, zz in zip(d.scheme.labels, d.z))
    text = (f"Подобран планетарный редуктор ({d.scheme.title_ru}): {zs}, число сателлитов $K = {d.satellites}$; "
            f"передаточное отношение $u = {mnum(abs(d.ratio), 5)}$ при~требуемом ${mnum(stage.target, 5)}$ "
            f"(отклонение ${mnum(100 * d.ratio_check.deviation, 3)}$~\\%).")
    if tr is not None:
        text += (f" По~треугольнику скоростей $u_\\text{{гр}} = {mnum(tr['u_graph'].value, 5)}$ "
                 f"(расхождение ${tr['diff'].result_number_latex()}$~\\%).")
    return Tex(text)
