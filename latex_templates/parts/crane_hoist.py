"""Part «Расчёт механизма подъёма» of the crane note: rope and polyspast, blocks, drum, motor,
transmission, motor checks, couplings, brake (the order of the course, seed 002), then a summary
table of the checks. Numbers: :func:`reportgen.crane.hoist.hoist_calc`."""
from __future__ import annotations

from markupsafe import Markup

from . import PartContent
from ..render import escape_latex
from .crane_common import Blocks, failed_names, fmt, strings_of, summary

NEEDS = ("crane",)
#: The regimes of the 1969 rules (reportgen.crane.rules.REGIME) → their catalogue keys (crane.regimes).
REGIME_KEYS = {"Л": "light", "С": "medium", "Т": "heavy", "ВТ": "very_heavy"}


def available(project) -> bool:
    return getattr(project.task, "crane", None) is not None


def blocks(project) -> Blocks:
    calc = project.crane
    crane = calc.crane
    h = crane.hoist
    r = calc.rules
    s = strings_of(project)
    b = Blocks(calc.hoist, s, "hoist")
    hc = calc.hoist
    b.sub("rope")
    if r.rules == "1969":
        b.text("rules_1969", group=r.group, regime=s.get(f"crane.regimes.{REGIME_KEYS[r.regime]}"), k=r.rope_factor, e=r.block_ratio, kt=r.brake_factor)
    else:
        b.text("rules_pb", group=r.group, iso=r.iso_class, k=r.rope_factor, e=r.block_ratio, h1=r.drum_ratio,
               kt=r.brake_factor)
    b.text("weight")
    b.rec("G")
    p = h.polyspast
    b.text("polyspast" if p.branches > 1 else "polyspast_single", u=p.ratio, z=p.branches,
           eta=p.block_efficiency)
    b.rec("eta_p")
    b.text("smax")
    b.rec("S_max")
    b.text("rope_req")
    b.rec("F_req")
    b.text("rope_choice", designation=h.rope.designation, d=h.rope.diameter_mm, f=h.rope.breaking_force_kn)
    b.check("rope")
    b.sub("blocks")
    b.text("block_intro")
    b.rec("D_bl_min")
    b.text("block_given", d0=p.hook_block_diameter_mm)
    b.rec("D_bl")
    b.check("block")
    b.sub("drum")
    if r.rules == "1969":
        b.text("drum_ratio_1969")
        b.rec("h_dr")
    b.text("drum_intro")
    b.rec("D_dr_min")
    b.text("drum_given", d0=h.drum.diameter_mm)
    b.rec("D_c")
    b.check("drum")
    b.text("rope_length")
    b.rec("L_k")
    b.text("turns")
    b.rec("z_w")
    b.text("turns_accept", z=hc.value("z_wa"), t=h.drum.groove_pitch_mm, zr=h.drum.reserve_turns,
           zc=h.drum.clamp_turns)
    b.rec("l_n")
    b.check("groove")
    b.check("reserve_turns")
    if p.branches > 1:
        b.text("smooth", l0=h.drum.smooth_length_mm, b=p.hook_block_spread_mm, alpha=hc.value("alpha"),
               hmin=hc.value("h_min"))
        b.rec("l_0max")
        b.check("smooth_min")
        b.check("smooth_max")
    ring = fmt(s.get("crane.text.ring"), b=h.drum.ring_width_mm) if h.drum.ring_width_mm else Markup("")
    b.text("drum_length", lk=h.drum.end_length_mm, ring=ring)
    b.rec("L_dr")
    b.text("wall", w=h.drum.wall_mm, material=h.drum.material or s.get("crane.text.wall_material_none"))
    b.rec("sigma")
    b.check("wall")
    # motor
    b.sub("motor")
    b.text("eta")
    b.rec("eta")
    b.text("nst")
    b.rec("N_st")
    mo = h.motor
    b.text("motor_choice", designation=mo.designation, n=mo.power_kw, pv=mo.pv_percent, rpm=mo.speed_rpm,
           j=mo.rotor_inertia, psi=mo.max_torque_ratio, group=r.group, pvd=r.pv_percent)
    transmission(b, project)
    motor_checks(b, "mst")
    couplings(b, h.couplings)
    b.sub("brake")
    b.text("brake_eta")
    b.rec("eta_t")
    b.text("brake_st")
    b.rec("T_st")
    b.text("brake_req")
    b.rec("T_br")
    br = h.brake
    b.text("brake_choice", designation=br.designation, t=br.rated_torque, d=br.pulley_diameter_mm,
           count=fmt(s.get("crane.text.brake_two"), n=br.count) if br.count > 1 else Markup(""))
    b.check("brake")
    summary(b)
    return b


def transmission(b: Blocks, project) -> None:
    h = project.crane.crane.hoist
    b.sub("transmission")
    b.text("drum_speed")
    b.rec("n_dr")
    b.text("ratio_req")
    b.rec("u_req")
    if h.open_gear is not None:
        og = h.open_gear
        b.text("open_gear", z1=og.z1, z2=og.z2, m=og.module_mm)
        b.rec("u_og")
        b.text("ratio_red")
        b.rec("u_r_req")
    red = h.reducer
    b.text("reducer_choice", designation=red.designation, u=red.ratio, t=red.rated_torque, eta=red.efficiency)
    b.text("ratio_mech")
    b.rec("u_mech")
    b.text("speed_act")
    b.rec("v_act", "dv")
    b.check("speed")


def motor_checks(b: Blocks, mst_key: str) -> None:
    b.sub("motor_check")
    b.text("omega")
    b.rec("omega_m", "M_nom")
    b.text(mst_key)
    b.rec("M_st")
    b.text("overload")
    b.rec("M_lim")
    b.check("overload")
    if "t_p" in b.calc.records:
        b.text("start")
        b.rec("J_sum", "m", "t_p", "a_p")
        b.check("acceleration")
        b.check("start_time")
    else:
        b.text("cannot_start")
        b.check("start_torque")
    b.text("heating" if b.mech == "hoist" else "heating_trolley")
    if b.mech == "hoist":
        b.rec("t_m", "M_lo", "G_0", "M_st0", "M_lo0", "M_sq", "M_eq")
    else:
        b.rec("t_m", "G_t", "W_0", "M_st0", "M_sq", "M_eq")
    b.text("heating_pv")
    b.rec("M_eq_pv")
    b.check("heating")
    b.text("reducer_torque")
    b.rec("T_out")
    b.check("reducer_torque")


def couplings(b: Blocks, items) -> None:
    b.sub("couplings")
    b.text("coupling_intro")
    b.rec("T_c")
    for i, c in enumerate(items, start=1):
        kind = str(b.s.get("crane.text.coupling_kind"))
        # «Муфта зубчатая …» typed by the student is not preceded by a second «Муфта»
        lead = Markup("") if c.designation.lower().startswith(kind.lower()) else Markup(escape_latex(kind) + " ")
        b.text("coupling_item", kind=lead, designation=c.designation, t=c.rated_torque, j=c.inertia)
        b.check(f"coupling{i}")


def content(project) -> PartContent:
    b = blocks(project)
    return PartContent("sections/crane_blocks.tex.j2", {"blocks": b.items}, {}, (conclusion(project),))


def conclusion(project) -> Markup:
    calc = project.crane
    h = calc.crane.hoist
    hc = calc.hoist
    s = strings_of(project)
    text = fmt(s.get("crane.text.conclusion_hoist"), rope=h.rope.designation, d=hc.value("D_c"),
               l=hc.value("L_dr"), motor=h.motor.designation, reducer=h.reducer.designation,
               brake=h.brake.designation, v=hc.value("v_act") * 60)
    tail = (s.get("crane.text.conclusion_ok") if hc.passed
            else fmt(s.get("crane.text.conclusion_fail"), names=failed_names(hc, s)))
    return Markup(text + " " + tail)
