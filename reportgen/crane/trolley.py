"""The trolley travel mechanism of a bridge crane (central drive, two driven wheels): wheel loads,
resistance to travel, motor, reducer, couplings, brake, and the adhesion of the driven wheels at
start and at braking (a check seed 002 lacks).

Formulas (Казак С. А. «Курсовое проектирование грузоподъёмных машин», 1989; Руденко Н. Ф.
«Справочник по кранам»; seed note 002, section 8):

- largest static wheel load P_max = (G + G_т)·k_н/n_к with the unevenness k_н = 1,1 (seed 002);
- rail head b and wheel tread B: B − b = 15…20 mm for two-flange trolley wheels (Казак; seed 002);
- resistance of friction W_тр = (G + G_т)·(2μ + f·d)/D·k_р (μ the arm of rolling friction, f the
  bearing friction reduced to the journal d, k_р the flanges and current supply), of the slope
  W_у = α·(G + G_т); static resistance W_ст = W_тр + W_у (indoors: no wind);
- drive (:mod:`reportgen.crane.drive`): M_ст = W_ст·D/(2·u·η);
- brake: stop the loaded trolley running downhill at the deceleration [a] with the least
  resistance (no flange factor): T_т = k_т·((δ_т·m·a + W_у)·D·η/(2u) − W_тр0·D/(2u·η)), k_т = 1,2
  (seed 002 after the rules for travel mechanisms);
- adhesion: the empty trolley (the least load on the driven wheels) started by the mean starting
  torque and stopped by the brake's set torque; the force through the driven wheels must stay below
  φ·P_пр by the factor k_сц ≥ 1,2 (Руденко: φ = 0,2 indoors, 0,12 outdoors).
"""
from __future__ import annotations

from . import drive
from .hoist import K2_OF_REGIME, MechanismCalc
from .rules import DutyRules
from .spec import Crane
from .steps import Steps, check

#: Unevenness of the wheel loads (seed 002: P_max = (G + G_т)·1,1/n).
WHEEL_UNEVENNESS = 1.1
#: Tread width minus rail head, mm, for two-flange trolley wheels (Казак; seed 002: «норма 15…20»).
TREAD_CLEARANCE_MM = (15.0, 20.0)
#: Coupling service factor k₁ of a travel mechanism (Руденко, выбор муфт).
TRAVEL_K1 = 1.2
#: Safety factor of the travel brake's torque (seed 002: «K_зап = 1,2»).
TRAVEL_BRAKE_FACTOR = 1.2
#: Rotating masses in the inertia force of travel (seed 002: 1,25 for v < 1 m/s).
TRAVEL_DELTA = 1.25


def trolley_calc(crane: Crane, rules: DutyRules) -> MechanismCalc:
    h, t = crane.hoist, crane.trolley
    w = t.wheel
    st = Steps()
    st.var("m_Q", r"m_{гр}", h.capacity_t * 1000, "кг")
    st.var("m_h", r"m_{п}", h.hook_mass_kg, "кг")
    st.var("m_t", r"m_{т}", t.mass_t * 1000, "кг")
    st.var("g", "g", crane.g, "м/с²")
    st.var("v", r"v_{т}", t.speed_m_min / 60, "м/с")
    st.var("n_w", r"n_{к}", t.wheels)
    st.var("n_d", r"n_{пр}", t.driven_wheels)
    st.rec("G_sum", r"G_{\Sigma}", "(m_Q + m_h + m_t) * g", "Н")
    st.var("k_n", r"k_{н}", WHEEL_UNEVENNESS)
    st.rec("P_max", r"P_{\max}", "G_sum * k_n / n_w", "Н")
    st.var("P_a", r"[P]", w.allowable_load_kn * 1000, "Н")
    st.add(check("wheel_load", w.allowable_load_kn * 1000, "≥", st.value("P_max"), "Н", records=("P_max",),
                 advice="wheel_load", advice_value=st.value("P_max") / 1000, advice_unit="кН"))
    st.var("B_w", r"B_{к}", w.tread_width_mm, "мм")
    st.var("b_r", r"b_{р}", t.rail.head_width_mm, "мм")
    st.rec("gap", r"\Delta_{р}", "B_w - b_r", "мм")
    lo, hi = TREAD_CLEARANCE_MM
    st.add(check("tread_min", st.value("gap"), "≥", lo, "мм", records=("gap",), advice="tread",
                 advice_value=t.rail.head_width_mm + lo, advice_unit="мм"))
    st.add(check("tread_max", st.value("gap"), "≤", hi, "мм", records=("gap",), advice="tread",
                 advice_value=t.rail.head_width_mm + hi, advice_unit="мм"))
    # --- resistance
    st.var("D_w", r"D_{к}", w.diameter_mm, "мм")
    st.var("d_j", r"d_{ц}", w.journal_diameter_mm, "мм")
    st.var("mu", r"\mu", w.rolling_arm_mm, "мм")
    st.var("f", "f", w.bearing_friction)
    st.var("k_fl", r"k_{р}", w.flange_factor)
    st.var("alpha_s", r"\alpha_{у}", t.rail.slope)
    st.rec("W_f", r"W_{тр}", "G_sum * (2 * mu + f * d_j) / D_w * k_fl", "Н")
    st.rec("W_s", r"W_{у}", "alpha_s * G_sum", "Н")
    st.rec("W_st", r"W_{ст}", "W_f + W_s", "Н")
    # --- motor, ratio, speed
    drive.motor_vars(st, t.motor, t.couplings, rules.pv_percent)
    drive.reducer_check(st, t.reducer)
    st.var("eta_c", r"\eta_{м}", drive.COUPLING_EFFICIENCY)
    st.rec("eta", r"\eta", "eta_r * eta_c")
    st.rec("N_st", r"N_{ст}", "W_st * v / (1000 * eta)", "кВт")
    st.rec("n_wh", r"n_{к.об}", "60 * 1000 * v / (pi * D_w)", "об/мин")
    st.rec("u_req", r"u_{тр}", "n_m / n_wh")
    st.recs["u_r_req"] = st.recs["u_req"]
    st.rec("v_act", r"v_{ф}", "pi * D_w * n_m / (60 * 1000 * u_r)", "м/с")
    st.rec("dv", r"\Delta v", "(v_act - v) / v * 100", "%")
    drive.speed_check(st)
    drive.motor_torques(st)
    st.rec("M_st", r"M_{ст}", "W_st * D_w / (2000 * u_r * eta)", "Н·м")
    drive.overload_check(st)
    drive.rotor_inertia(st, len(t.couplings))
    st.rec("m", "m", "m_Q + m_h + m_t", "кг")
    started = drive.start_checks(st, "m", "v", "eta", t.max_acceleration, t.max_start_time)
    # --- heating: a loaded travel and an empty return over the working travel length
    st.var("L_t", r"L_{т}", t.travel_length_m or crane.span_m / 2, "м")
    st.rec("t_m", r"t_{у}", "L_t / v", "с")
    st.rec("G_t", r"G_{т}", "m_t * g", "Н")
    st.rec("W_0", r"W_{0}", "G_t * ((2 * mu + f * d_j) / D_w * k_fl + alpha_s)", "Н")
    st.rec("M_st0", r"M_{ст0}", "W_0 * D_w / (2000 * u_r * eta)", "Н·м")
    drive.heating_check(st, "M_st**2 + M_st0**2", 2, started)
    drive.reducer_torque_check(st)
    drive.coupling_checks(st, t.couplings, TRAVEL_K1, K2_OF_REGIME[rules.regime])
    # --- brake
    st.var("delta_t", r"\delta_{т}", TRAVEL_DELTA)
    st.var("a_b", r"a_{т}", t.brake_deceleration, "м/с²")
    st.rec("W_f0", r"W_{тр}'", "G_sum * (2 * mu + f * d_j) / D_w", "Н")
    st.rec("W_in", r"W_{ин}", "delta_t * m * a_b", "Н")
    st.var("k_b", r"k_{т}", TRAVEL_BRAKE_FACTOR)
    st.rec("T_br", r"T_{т.р}", "k_b * ((W_in + W_s) * D_w * eta / (2000 * u_r) - W_f0 * D_w / (2000 * u_r * eta))",
           "Н·м")
    st.var("T_bn", r"T_{т.ном}", t.brake.rated_torque, "Н·м")
    st.add(check("brake", t.brake.rated_torque, "≥", st.value("T_br"), "Н·м", records=("T_br",),
                 advice="brake_torque", advice_value=st.value("T_br"), advice_unit="Н·м"))
    # --- adhesion of the driven wheels, empty trolley
    st.var("phi", r"\varphi", t.adhesion)
    st.var("k_adh", r"[k_{сц}]", t.adhesion_safety)
    st.rec("P_d", r"P_{пр}", "G_t * n_d / n_w", "Н")
    st.rec("m_red", r"m_{пр}", "m_t + delta_J * J_sum * (2000 * u_r / D_w)**2 * eta", "кг")
    st.rec("F_p", r"F_{п}", "M_p * 2000 * u_r * eta / D_w", "Н")
    st.rec("a_0", r"a_{0}", "(F_p - W_0) / m_red", "м/с²")
    st.rec("F_wp", r"F_{сц.п}", "m_t * a_0 + W_0", "Н")
    st.rec("k_sp", r"k_{сц.п}", "phi * P_d / F_wp")
    st.add(check("adhesion_start", st.value("k_sp"), "≥", t.adhesion_safety, "", records=("P_d", "m_red", "F_p",
                 "a_0", "F_wp", "k_sp"), advice="adhesion_start"))
    T_set = max(st.value("T_br"), 0.0)
    st.var("T_set", r"T_{т}", T_set, "Н·м")
    st.rec("W_00", r"W_{0}'", "G_t * ((2 * mu + f * d_j) / D_w - alpha_s)", "Н")
    st.rec("F_b", r"F_{т}", "T_set * 2000 * u_r / (D_w * eta)", "Н")
    st.rec("a_b0", r"a_{т0}", "(F_b + W_00) / m_red", "м/с²")
    st.rec("F_wb", r"F_{сц.т}", "m_t * a_b0 - W_00", "Н")
    if st.value("F_wb") > 0:
        st.rec("k_sb", r"k_{сц.т}", "phi * P_d / F_wb")
        st.add(check("adhesion_brake", st.value("k_sb"), "≥", t.adhesion_safety, "",
                     records=("W_00", "F_b", "a_b0", "F_wb", "k_sb"), advice="adhesion_brake"))
    return MechanismCalc(*st.frozen())
