"""The hoist of a bridge crane: rope and polyspast, blocks, drum, motor, transmission, couplings,
brake — in the order of the course (Казак С. А. «Курсовое проектирование грузоподъёмных машин»,
1989; seed note 002), every step a calculation record.

Formulas (each record's expression is the formula printed in the note):

- weight of load and suspension G = (m_гр + m_п)·g;
- polyspast efficiency η_п = (1 − η_бл^u)/(u·(1 − η_бл)) (Александров, «Подъёмно-транспортные
  машины», the efficiency of a polyspast whose rope leaves a fixed block to the drum);
- largest rope force S_max = G/(z·u·η_п·η_бл^n), z branches wound on the drum, n guide blocks;
- required breaking force F ≥ k·S_max, k by the rules of the duty (:mod:`reportgen.crane.rules`);
- blocks and drum along the rope centre D = D₀ + d ≥ h·d (ПБ 10-382-00 табл. 12; 1969 rules: e);
- rope wound on each half L = H·u; working turns z_р = L/(π·D); threaded length
  l_н = t·(z_р + z_неп + z_кр) with at least 1,5 turns never unwound (ПБ 10-382-00) and the clamp
  turns; smooth middle part B ≤ l₀ ≤ B + 2·h_min·tg α with the fleet angle α = 6° of a grooved drum
  (Казак; seed 002); drum length L_б = z·l_н + l₀ + 2·l_к (+ the gear ring);
- drum wall in compression from the wound rope σ = S_max/(δ·t) ≤ [σ] (Александров, расчёт
  барабана; single-layer winding);
- drive: see :mod:`reportgen.crane.drive`; static torque at the motor M_ст = G·D/(2·u_м·η); the
  brake holds the load when lowering, efficiency helping: T_ст = G·D·η_т/(2·u_м), T_т ≥ k_т·T_ст.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Mapping

from ..calc import CalcRecord, Var
from ..errors import NameLookupError
from . import drive
from .rules import DutyRules, brake_factor_each
from .spec import Crane
from .steps import Check, Steps, check
from ..tolerances import WHOLE_EPS

#: Allowed fleet angle of the rope from the groove of a grooved drum (Казак; seed 002: 6°).
FLEET_ANGLE_DEG = 6.0
#: Least distance from the drum axis to the hook block axes, in drum diameters (seed 002: 3·D_б).
HOOK_DISTANCE_FACTOR = 3.0
#: Coupling service factors of a hoist: k₁ (importance) and k₂ (duty) (Руденко, выбор муфт).
HOIST_K1 = 1.3
K2_OF_REGIME = {"Л": 1.1, "С": 1.2, "Т": 1.3, "ВТ": 1.4}


@dataclass(frozen=True)
class MechanismCalc:
    """The records and checks of one mechanism; ``accepted`` holds the values the designer rounds
    (the working turns) as inputs of the next steps."""
    vars: Mapping[str, Var]
    records: Mapping[str, CalcRecord]
    checks: tuple[Check, ...]

    def check(self, key: str) -> Check:
        for c in self.checks:
            if c.key == key:
                return c
        raise NameLookupError("check", key, tuple(c.key for c in self.checks))

    @property
    def passed(self) -> bool:
        return all(c.passed for c in self.checks)

    def value(self, key: str) -> float:
        return self.records[key].value if key in self.records else self.vars[key].value


def polyspast_efficiency(block_efficiency: float, ratio: int) -> float:
    """η_п = (1 − η^u)/(u(1 − η)); 1 for u = 1 (the rope hangs straight)."""
    if block_efficiency == 1.0:
        return 1.0
    return (1 - block_efficiency ** ratio) / (ratio * (1 - block_efficiency))


def working_turns(rope_length_m: float, diameter_mm: float) -> float:
    """z = L/(π·D) turns of a rope of length L wound on a drum of diameter D."""
    return rope_length_m * 1000 / (math.pi * diameter_mm)


def threaded_length(pitch_mm: float, turns: float, reserve: float, clamp: float) -> float:
    """l_н = t·(z_р + z_неп + z_кр), mm."""
    return pitch_mm * (turns + reserve + clamp)


def hoist_calc(crane: Crane, rules: DutyRules) -> MechanismCalc:
    h = crane.hoist
    p = h.polyspast
    st = Steps()
    st.var("m_Q", r"m_{гр}", h.capacity_t * 1000, "кг")
    st.var("m_h", r"m_{п}", h.hook_mass_kg, "кг")
    st.var("g", "g", crane.g, "м/с²")
    st.var("v", r"v_{п}", h.lifting_speed_m_min / 60, "м/с")
    st.var("H", "H", h.lifting_height_m, "м")
    st.var("u_p", r"u_{п}", p.ratio)
    st.var("z", r"z_{б}", p.branches)
    st.var("eta_b", r"\eta_{бл}", p.block_efficiency)
    # --- rope and polyspast
    st.rec("G", "G", "(m_Q + m_h) * g", "Н")
    if p.ratio > 1:
        st.rec("eta_p", r"\eta_{п}", "(1 - eta_b**u_p) / (u_p * (1 - eta_b))")
    else:
        st.var("eta_p", r"\eta_{п}", 1.0)
    if p.guide_blocks:
        st.var("n_g", r"n_{н}", p.guide_blocks)
        st.rec("S_max", r"S_{\max}", "G / (z * u_p * eta_p * eta_b**n_g)", "Н")
    else:
        st.rec("S_max", r"S_{\max}", "G / (z * u_p * eta_p)", "Н")
    st.var("k_rope", r"k_{к}", rules.rope_factor)
    st.rec("F_req", r"F_{тр}", "k_rope * S_max", "Н")
    st.var("F_br", r"F_{разр}", h.rope.breaking_force_kn * 1000, "Н")
    st.add(check("rope", st.value("F_br"), "≥", st.value("F_req"), "Н", records=("F_req",),
                 advice="rope_force", advice_value=st.value("F_req") / 1000, advice_unit="кН"))
    # --- blocks and drum diameters
    st.var("d", r"d_{к}", h.rope.diameter_mm, "мм")
    old = rules.rules == "1969"
    st.var("h_bl", "e" if old else r"h_{2}", rules.block_ratio)
    st.rec("D_bl_min", r"D_{бл\min}", "h_bl * d", "мм")
    st.var("D_bl0", r"D_{бл.0}", p.hook_block_diameter_mm, "мм")
    st.rec("D_bl", r"D_{бл}", "D_bl0 + d", "мм")
    st.add(check("block", st.value("D_bl"), "≥", st.value("D_bl_min"), "мм", records=("D_bl_min", "D_bl"),
                 advice="block_diameter", advice_value=st.value("D_bl_min") - h.rope.diameter_mm,
                 advice_unit="мм"))
    if old:
        st.var("k_dr", r"k_{б}", 0.85)
        st.rec("h_dr", r"e_{б}", "k_dr * h_bl")
    else:
        st.var("h_dr", r"h_{1}", rules.drum_ratio)
    st.rec("D_dr_min", r"D_{б\min}", "h_dr * d", "мм")
    st.var("D_dr0", r"D_{б.0}", h.drum.diameter_mm, "мм")
    st.rec("D_c", r"D_{б}", "D_dr0 + d", "мм")
    st.add(check("drum", st.value("D_c"), "≥", st.value("D_dr_min"), "мм", records=("D_dr_min", "D_c"),
                 advice="drum_diameter", advice_value=st.value("D_dr_min") - h.rope.diameter_mm,
                 advice_unit="мм"))
    # --- drum length
    dr = h.drum
    st.rec("L_k", r"L_{к}", "H * u_p", "м")
    st.rec("z_w", r"z_{р}", "L_k * 1000 / (pi * D_c)", "")
    st.var("z_wa", r"z_{р}'", math.ceil(st.value("z_w") - WHOLE_EPS), "")
    st.var("t", "t", dr.groove_pitch_mm, "мм")
    st.add(check("groove", dr.groove_pitch_mm, "≥", h.rope.diameter_mm + 2.0, "мм",
                 advice="groove_pitch", advice_value=h.rope.diameter_mm + 2.0, advice_unit="мм"))
    st.var("z_res", r"z_{неп}", dr.reserve_turns)
    st.var("z_cl", r"z_{кр}", dr.clamp_turns)
    st.add(check("reserve_turns", dr.reserve_turns, "≥", 1.5, "", advice="reserve_turns",
                 advice_value=1.5))
    st.rec("l_n", r"l_{н}", "t * (z_wa + z_res + z_cl)", "мм")
    st.var("l_k", r"l_{к}", dr.end_length_mm, "мм")
    terms = ["z * l_n"] if p.branches > 1 else ["l_n"]
    if p.branches > 1:
        st.var("l_0", r"l_{0}", dr.smooth_length_mm, "мм")
        st.var("B", "B", p.hook_block_spread_mm, "мм")
        st.var("h_min", r"h_{\min}", dr.hook_distance_mm or HOOK_DISTANCE_FACTOR * dr.diameter_mm, "мм")
        st.var("alpha", r"\alpha", FLEET_ANGLE_DEG, "°")
        st.rec("l_0max", r"l_{0\max}", "B + 2 * h_min * tan(radians(alpha))", "мм")
        st.add(check("smooth_min", dr.smooth_length_mm, "≥", p.hook_block_spread_mm, "мм",
                     advice="smooth_length", advice_value=p.hook_block_spread_mm, advice_unit="мм"))
        st.add(check("smooth_max", dr.smooth_length_mm, "≤", st.value("l_0max"), "мм", records=("l_0max",),
                     advice="smooth_length_max", advice_value=st.value("l_0max"), advice_unit="мм"))
        terms.append("l_0")
    terms.append("2 * l_k")
    if dr.ring_width_mm:
        st.var("b_ring", r"B_{з.в}", dr.ring_width_mm, "мм")
        terms.append("b_ring")
    st.rec("L_dr", r"L_{б}", " + ".join(terms), "мм")
    # --- drum wall
    st.var("delta_w", r"\delta_{с}", dr.wall_mm, "мм")
    st.var("sigma_a", r"[\sigma_{сж}]", dr.allowable_stress_mpa, "МПа")
    st.rec("sigma", r"\sigma_{сж}", "S_max / (delta_w * t)", "МПа")
    st.add(check("wall", dr.allowable_stress_mpa, "≥", st.value("sigma"), "МПа", records=("sigma",),
                 advice="drum_wall", advice_value=st.value("S_max") / (dr.allowable_stress_mpa * dr.groove_pitch_mm),
                 advice_unit="мм"))
    # --- motor: power, speed, ratio
    drive.motor_vars(st, h.motor, h.couplings, rules.pv_percent)
    drive.reducer_check(st, h.reducer)
    st.var("eta_dr", r"\eta_{б}", dr.efficiency)
    st.var("eta_c", r"\eta_{м}", drive.COUPLING_EFFICIENCY)
    og = h.open_gear
    if og is not None:
        st.var("z_1", r"z_{ш}", og.z1)
        st.var("z_2", r"z_{в}", og.z2)
        st.rec("u_og", r"u_{о}", "z_2 / z_1")
        st.var("eta_og", r"\eta_{о}", og.efficiency)
        st.rec("eta", r"\eta", "eta_p * eta_dr * eta_og * eta_r * eta_c")
    else:
        st.rec("eta", r"\eta", "eta_p * eta_dr * eta_r * eta_c")
    st.rec("N_st", r"N_{ст}", "G * v / (1000 * eta)", "кВт")
    st.rec("n_dr", r"n_{б}", "60 * 1000 * v * u_p / (pi * D_c)", "об/мин")
    st.rec("u_req", r"u_{тр}", "n_m / n_dr")
    if og is not None:
        st.rec("u_r_req", r"u_{р.тр}", "u_req / u_og")
        st.rec("u_mech", r"u_{м}", "u_r * u_og * u_p")
    else:
        st.recs["u_r_req"] = st.recs["u_req"]     # the reducer alone gives the whole ratio
        st.rec("u_mech", r"u_{м}", "u_r * u_p")
    st.rec("v_act", r"v_{ф}", "pi * D_c * n_m / (60 * 1000 * u_mech)", "м/с")
    st.rec("dv", r"\Delta v", "(v_act - v) / v * 100", "%")
    drive.speed_check(st)
    # --- motor torques and checks
    drive.motor_torques(st)
    st.rec("M_st", r"M_{ст}", "G * D_c / (2000 * u_mech * eta)", "Н·м")
    drive.overload_check(st)
    drive.rotor_inertia(st, len(h.couplings))
    st.rec("m", "m", "m_Q + m_h", "кг")
    started = drive.start_checks(st, "m", "v", "eta", h.max_acceleration, h.max_start_time)
    st.rec("t_m", r"t_{у}", "H / v", "с")
    st.rec("M_lo", r"M_{оп}", "G * D_c * eta / (2000 * u_mech)", "Н·м")
    st.rec("G_0", r"G_{0}", "m_h * g", "Н")
    st.rec("M_st0", r"M_{ст0}", "G_0 * D_c / (2000 * u_mech * eta)", "Н·м")
    st.rec("M_lo0", r"M_{оп0}", "G_0 * D_c * eta / (2000 * u_mech)", "Н·м")
    drive.heating_check(st, "M_st**2 + M_lo**2 + M_st0**2 + M_lo0**2", 4, started)
    # --- transmission, couplings, brake
    drive.reducer_torque_check(st)
    drive.coupling_checks(st, h.couplings, HOIST_K1, K2_OF_REGIME[rules.regime])
    b = h.brake
    if og is not None:
        st.rec("eta_t", r"\eta_{т}", "eta_p * eta_dr * eta_og * eta_r")
    else:
        st.rec("eta_t", r"\eta_{т}", "eta_p * eta_dr * eta_r")
    st.rec("T_st", r"T_{ст.т}", "G * D_c * eta_t / (2000 * u_mech)", "Н·м")
    st.var("k_T", r"k_{т}", brake_factor_each(rules, b.count))
    st.rec("T_br", r"T_{т.р}", "k_T * T_st", "Н·м")
    st.var("T_bn", r"T_{т.ном}", b.rated_torque, "Н·м")
    st.add(check("brake", b.rated_torque, "≥", st.value("T_br"), "Н·м", records=("T_st", "T_br"),
                 advice="brake_torque", advice_value=st.value("T_br"), advice_unit="Н·м"))
    return MechanismCalc(*st.frozen())
