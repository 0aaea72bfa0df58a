"""Part «Расчёт механизма передвижения тележки» of the crane note: wheels and rail, resistance,
motor, transmission, motor checks, couplings, brake, adhesion of the driven wheels (start and
braking), a summary table. Numbers: :func:`reportgen.crane.trolley.trolley_calc`."""
from __future__ import annotations

from markupsafe import Markup

from . import PartContent
from .crane_common import Blocks, failed_names, fmt, strings_of, summary
from .crane_hoist import couplings, motor_checks

NEEDS = ("crane",)


def available(project) -> bool:
    return getattr(project.task, "crane", None) is not None


def blocks(project) -> Blocks:
    calc = project.crane
    t = calc.crane.trolley
    s = strings_of(project)
    b = Blocks(calc.trolley, s, "trolley")
    b.sub("wheels")
    b.text("trolley_total")
    b.rec("G_sum")
    b.text("wheel_load")
    b.rec("P_max")
    w = t.wheel
    b.text("wheel_choice", designation=w.designation, d=w.diameter_mm, dj=w.journal_diameter_mm,
           b=w.tread_width_mm, p=w.allowable_load_kn, rail=t.rail.designation, br=t.rail.head_width_mm)
    b.check("wheel_load")
    b.text("tread")
    b.rec("gap")
    b.check("tread_min")
    b.check("tread_max")
    b.sub("resistance")
    b.text("resistance")
    b.rec("W_f", "W_s", "W_st")
    b.sub("motor")
    b.text("trolley_eta")
    b.rec("eta")
    b.text("trolley_nst")
    b.rec("N_st")
    mo = t.motor
    r = calc.rules
    b.text("motor_choice", designation=mo.designation, n=mo.power_kw, pv=mo.pv_percent, rpm=mo.speed_rpm,
           j=mo.rotor_inertia, psi=mo.max_torque_ratio, group=r.group, pvd=r.pv_percent)
    b.sub("transmission")
    b.text("wheel_speed")
    b.rec("n_wh")
    b.text("ratio_req")
    b.rec("u_req")
    red = t.reducer
    b.text("reducer_choice", designation=red.designation, u=red.ratio, t=red.rated_torque, eta=red.efficiency)
    b.text("speed_act")
    b.rec("v_act", "dv")
    b.check("speed")
    motor_checks(b, "mst_trolley")
    couplings(b, t.couplings)
    b.sub("brake")
    b.text("trolley_brake")
    b.rec("W_f0", "W_in", "T_br")
    br = t.brake
    b.text("brake_choice", designation=br.designation, t=br.rated_torque, d=br.pulley_diameter_mm,
           count=fmt(s.get("crane.text.brake_two"), n=br.count) if br.count > 1 else Markup(""))
    b.check("brake")
    b.sub("adhesion")
    b.text("adhesion_intro")
    b.rec("P_d", "m_red", "F_p", "a_0", "F_wp", "k_sp")
    b.check("adhesion_start")
    if "k_sb" in calc.trolley.records:
        b.text("adhesion_brake", t=calc.trolley.value("T_set"))
        b.rec("W_00", "F_b", "a_b0", "F_wb", "k_sb")
        b.check("adhesion_brake")
    else:
        b.text("adhesion_brake_none")
    summary(b)
    return b


def content(project) -> PartContent:
    b = blocks(project)
    return PartContent("sections/crane_blocks.tex.j2", {"blocks": b.items}, {}, (conclusion(project),))


def conclusion(project) -> Markup:
    calc = project.crane
    t = calc.crane.trolley
    tc = calc.trolley
    s = strings_of(project)
    text = fmt(s.get("crane.text.conclusion_trolley"), d=t.wheel.diameter_mm, motor=t.motor.designation,
               reducer=t.reducer.designation, brake=t.brake.designation, v=tc.value("v_act") * 60,
               k=tc.value("k_sp"))
    tail = (s.get("crane.text.conclusion_ok") if tc.passed
            else fmt(s.get("crane.text.conclusion_fail"), names=failed_names(tc, s)))
    return Markup(text + " " + tail)
