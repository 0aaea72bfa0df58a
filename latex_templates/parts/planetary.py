"""Part «Синтез планетарного редуктора» (subsection 4.2): the drive's required ratio, the scheme and
Willis' formula, the tooth numbers with every condition written with its numbers, the alternatives,
Kutzbach's velocity triangle and the angular-velocity plan, the achieved crank speed.

Numbers come from :class:`reportgen.project.PlanetaryStage` (design, drive, triangle, check)
through calculation records or filters.
"""
from __future__ import annotations

from typing import cast

from ..render import Tex

from reportgen.calc import CalcRecord, Var, record
from reportgen.planetary.schemes import expand

from . import PartContent
from . import tr as _t
from .gear_pair import _rec

NEEDS = ("planetary",)


def available(project) -> bool:
    return project.task.planetary is not None


def _zvars(design) -> dict[str, Var]:
    sch = design.scheme
    z1, z2, z2p, z3 = expand(sch, design.z)
    v = {"z1": Var("z1", "z_1", z1, "", _t("planetary.m22")),
         "z2": Var("z2", "z_2", z2, "", _t("planetary.m23")),
         "z3": Var("z3", "z_3", z3, "", _t("planetary.m24"))}
    if sch.two_row:
        v["z2p"] = Var("z2p", "z_{2'}", z2p, "", _t("planetary.m25"))
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
        n = Var("n", r"n_\text{дв}", drive.motor_rpm, "об/мин", _t("planetary.m26"))
        r["omega_m"] = _rec(r"\omega_\text{дв}", "pi * n / 30", "рад/с", 3, _t("planetary.m27"), n=n)
        za = Var("za", "z_a", drive.z1_open, "", _t("planetary.m28"))
        zb = Var("zb", "z_b", drive.z2_open, "", _t("planetary.m29"))
        w1 = Var("w1", r"\omega_\text{кр}", drive.omega_crank, "рад/с", _t("planetary.m30"))
        r["u_req"] = _rec(r"u_\text{тр}", "za * wm / (zb * w1)", "", 4, _t("planetary.m31"),
                          za=za, wm=r["omega_m"], zb=zb, w1=w1)
    names = {k: v for k, v in zv.items() if k in willis_expr(d)}
    r["u1h"] = _rec("u_{1H}^{(3)}", willis_expr(d), "", 4, _t("planetary.m02"), **names)
    u_main = cast(CalcRecord, r["u1h"])
    if d.driver == "carrier":
        r["uh1"] = _rec("u_{H1}^{(3)}", "1 / u1h", "", 4, _t("planetary.m32"), u1h=r["u1h"])
        u_main = cast(CalcRecord, r["uh1"])
    target = Var("ut", r"u_\text{тр}", stage.target, "", _t("planetary.m03"))
    u_shown = Var("u", u_main.symbol, round(abs(u_main.value), 4), "")
    r["deviation"] = _rec(r"\delta_u", "(u - ut) / ut * 100", "%", 2, _t("planetary.m04"),
                          u=u_shown, ut=Var("ut", r"u_\text{тр}", round(stage.target, 4), "", _t("planetary.m41")))
    r["target"] = target
    # adjacency: (2a/m)·sin(π/K) > z_p + 2ha*, and the course's K limit; 2a/m = z1 ± z2
    adj = d.adjacency
    centre = "z1 + z2" if sch.row1 == "external" else "z1 - z2"
    pz = "z2" if adj.planet_label == "2" else "z2p"
    ha = Var("ha", r"h_a^*", adj.ha, "")
    K = Var("K", "K", adj.satellites, "", _t("planetary.m05"))
    r["adj_left"] = _rec(r"\frac{2a}{m}\sin\frac{\pi}{K}", f"({centre}) * sin(pi / K)", "", 3, "",
                         z1=zv["z1"], z2=zv["z2"], K=K)
    r["adj_right"] = _rec(r"z_p + 2h_a^*", f"{pz} + 2 * ha", "", 3, "", ha=ha, **{pz: zv[pz]})
    if adj.planet_z + 2 * adj.ha < adj.centre_sum:
        names = {pz: zv[pz], "z1": zv["z1"], "z2": zv["z2"]}
        r["k_limit"] = _rec(r"K_{\max}", f"180 / degrees(asin(({pz} + 2 * ha) / ({centre})))", "", 3,
                            _t("planetary.m33"), ha=ha, **names)
    # assembly quotient
    asm = d.assembly
    if sch.two_row:
        sign = "+" if asm.sign == "+" else "-"
        g = Var("g", r"\text{НОД}(z_2, z_{2'})", asm.g, "", _t("planetary.m34"))
        expr = f"(z1 * z2p {sign} z3 * z2) / (K * g)" if sign == "+" else "abs(z1 * z2p - z3 * z2) / (K * g)"
        r["assembly"] = _rec("C", expr, "", 4, "", z1=zv["z1"], z2p=zv["z2p"], z3=zv["z3"], z2=zv["z2"], K=K, g=g)
    else:
        r["assembly"] = _rec("C", "(z1 + z3) / K", "", 4, "", z1=zv["z1"], z3=zv["z3"], K=K)
    return r


def triangle_records(stage, u_main: CalcRecord) -> dict[str, CalcRecord]:
    tri = stage.triangle
    d = stage.design
    z1 = expand(d.scheme, d.z)[0]
    m = Var("m", "m", tri.module, "мм", _t("planetary.m06"))
    r: dict[str, CalcRecord] = {}
    w1 = Var("w1", r"\omega_1", abs(tri.omega1), "рад/с", _t("planetary.m07"))
    r["r1"] = _rec("r_1", "m * z1 / 2", "мм", 3, _t("planetary.m08"), m=m,
                   z1=Var("z1", "z_1", z1, ""))
    del z1
    zv = _zvars(d)
    centre = "z1 + z2" if d.scheme.row1 == "external" else "z1 - z2"
    r["a"] = _rec("a", f"m * ({centre}) / 2", "мм", 3, _t("planetary.m09"), m=m,
                  z1=zv["z1"], z2=zv["z2"])
    r["v_a"] = _rec("v_A", "w1 * r1 / 1000", "м/с", 4, _t("planetary.m10"), w1=w1, r1=r["r1"])
    la = Var("la", r"\overline{pa}", tri.vector_mm, "мм", _t("planetary.m11"))
    # 5 significant digits, as sheet 4 prints it (drawings/scenes/planetary_dxf.py)
    r["mu_v"] = record(r"\mu_v", "v_a / la", "(м/с)/мм", digits=5, meaning=_t("planetary.m12"), v_a=r["v_a"], la=la)
    lb = Var("lb", r"\overline{pb}", abs(tri.v_b_mm_read), "мм", _t("planetary.m13"))
    r["v_b"] = _rec("v_B", "mu_v * lb", "м/с", 4, _t("planetary.m14"), mu_v=r["mu_v"], lb=lb)
    r["omega_h"] = _rec(r"\omega_H", "v_b / (a / 1000)", "рад/с", 4, _t("planetary.m15"), v_b=r["v_b"], a=r["a"])
    if d.driver == "wheel":
        r["u_graph"] = _rec(r"u_\text{гр}", "w1 / wh", "", 4, _t("planetary.m35"),
                            w1=w1, wh=r["omega_h"])
    else:
        r["u_graph"] = _rec(r"u_\text{гр}", "wh / w1", "", 4, _t("planetary.m36"),
                            w1=w1, wh=r["omega_h"])
    ug = Var("ug", r"u_\text{гр}", round(r["u_graph"].value, 4), "")
    ua = Var("ua", u_main.symbol, round(abs(u_main.value), 4), "")
    r["diff"] = _rec(r"\Delta u", "(ug - ua) / ua * 100", "%", 3, "", ug=ug, ua=ua)
    plan = tri.plan
    cuts = dict(plan.cuts)
    x1 = Var("x1", r"\overline{p1}", abs(cuts["1"]), "мм", _t("planetary.m16"))
    xh = Var("xh", r"\overline{pH}", abs(cuts["H"]), "мм", _t("planetary.m17"))
    if d.driver == "wheel":
        r["u_plan"] = _rec(r"u_\text{пл}", "x1 / xh", "", 4, _t("planetary.m37"), x1=x1, xh=xh)
    else:
        r["u_plan"] = _rec(r"u_\text{пл}", "xh / x1", "", 4, _t("planetary.m38"), x1=x1, xh=xh)
    return r


def content(project) -> PartContent:
    from dataclasses import replace

    from reportgen.scenes.planetary import sheet_triangle
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
        ua = Var("ua", r"u_\text{откр}", drive.open_ratio, "", _t("planetary.m39"))
        uu = Var("u", "u", abs(d.ratio), "")
        w = _rec(r"\omega_\text{кр}'", "wm / (ua * u)", "рад/с", 4, _t("planetary.m40"),
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
    kinds = {"external": _t("planetary.m18"), "internal": _t("planetary.m19"),
             "internal mesh": _t("planetary.m20")}
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
    concl = _conclusion(stage, tr, cast(CalcRecord, r["deviation"]))
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


def _conclusion(stage, tr, deviation: CalcRecord) -> str:
    """The conclusion's item; the deviation is the printed record's number (one rounding of one
    quantity, issue 12: −0,213 % in the text against −0,22 % in the conclusion)."""
    from latex_templates.numbers import mnum
    d = stage.design
    zs = ", ".join(f"$z_{{{lab.replace('′', chr(39))}}} = {zz}$" for lab, zz in zip(d.scheme.labels, d.z))
    text = _t("planetary.m01", v1=_t("planetary_schemes." + d.scheme.name), zs=Tex(zs), v3=d.satellites,
              v4=Tex(mnum(abs(d.ratio), 5)), v5=Tex(mnum(stage.target, 5)),
              v6=Tex(deviation.result_number_latex()))
    if tr is not None:
        text += _t("planetary.m21", v1=Tex(mnum(tr['u_graph'].value, 5)), v2=Tex(tr['diff'].result_number_latex()))
    return Tex(text)
