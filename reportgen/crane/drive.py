"""The drive of a crane mechanism (motor – couplings – brake – reducer), shared by the hoist and the
trolley travel: speed and ratio, motor torques, starting, heating by the equivalent torque, reducer
and coupling torques.

Sources: Александров М. П. «Подъёмно-транспортные машины» (выбор двигателя: статический момент,
время пуска t_п = (δ·ΣJ·ω + m·v²/(ω·η)) / (M_п − M_ст), проверка по перегрузке с падением напряжения
сети на 10 %: M_ст ≤ 0,8·ψ_max·M_ном, эквивалентный момент M_э = √(ΣM_i²t_i/Σt_i) с приведением к
ПВ двигателя); Руденко Н. Ф. «Справочник по кранам» (δ = 1,1…1,25 for the rotating masses not
counted, ψ_п = 1,5…1,6 mean starting torque ratio of a wound-rotor motor, the coupling's
M_р = k₁·k₂·M).
"""
from __future__ import annotations

from .spec import Coupling, Motor, Reducer
from .steps import Steps, check

#: Rotating masses of the drive beyond the motor shaft (Руденко: δ = 1,1…1,25).
DELTA_ROTATING = 1.15
#: The mains voltage may fall by 10 %: the motor's maximum torque falls to 0,9² ≈ 0,8 of it.
VOLTAGE_DROP_FACTOR = 0.8
#: The actual speed may differ from the assignment's by this much, % (Казак; seed 002 «10 %»).
SPEED_TOLERANCE_PERCENT = 10.0
#: Efficiency of one coupling on the fast shaft (Руденко; seed 002: 0,99).
COUPLING_EFFICIENCY = 0.99


def motor_vars(st: Steps, motor: Motor, couplings: tuple[Coupling, ...], pv_duty: float) -> None:
    st.var("N_m", r"N_{дв}", motor.power_kw, "кВт")
    st.var("n_m", r"n_{дв}", motor.speed_rpm, "об/мин")
    st.var("J_r", r"J_{р}", motor.rotor_inertia, "кг·м²")
    st.var("psi_max", r"\psi_{\max}", motor.max_torque_ratio)
    st.var("psi_p", r"\psi_{п}", motor.start_torque_ratio)
    st.var("PV_m", r"ПВ_{дв}", motor.pv_percent, "%")
    st.var("PV", r"ПВ", pv_duty, "%")
    st.var("delta_J", r"\delta", DELTA_ROTATING)
    for i, c in enumerate(couplings, start=1):
        st.var(f"J_c{i}", rf"J_{{м{i}}}" if len(couplings) > 1 else r"J_{м}", c.inertia, "кг·м²")


def motor_torques(st: Steps) -> None:
    """ω, M_ном, the overload limit and the mean starting torque (records omega_m, M_nom, M_lim, M_p)."""
    st.rec("omega_m", r"\omega_{дв}", "pi * n_m / 30", "рад/с")
    st.rec("M_nom", r"M_{ном}", "1000 * N_m / omega_m", "Н·м")
    st.var("k_U", r"k_{U}", VOLTAGE_DROP_FACTOR)
    st.rec("M_lim", r"M_{\max}'", "k_U * psi_max * M_nom", "Н·м")
    st.rec("M_p", r"M_{п}", "psi_p * M_nom", "Н·м")


def rotor_inertia(st: Steps, n_couplings: int) -> None:
    terms = " + ".join(["J_r"] + [f"J_c{i}" for i in range(1, n_couplings + 1)])
    st.rec("J_sum", r"J_{\Sigma}", terms, "кг·м²")


def start_checks(st: Steps, mass_key: str, v_key: str, eta_key: str, a_max: float, t_max: float,
                 st_key: str = "M_st") -> bool:
    """Start time and acceleration; False (and a failed check) if the motor cannot start at all."""
    M_p, M_st = st.value("M_p"), st.value(st_key)
    if M_p <= M_st:
        st.add(check("start_torque", M_p, "≥", M_st, "Н·м", records=("M_p", st_key),
                     advice="motor_torque", advice_value=M_st / st.value("psi_p") * st.value("omega_m") / 1000,
                     advice_unit="кВт"))
        return False
    st.rec("t_p", r"t_{п}", f"(delta_J * J_sum * omega_m + {mass_key} * {v_key}**2 / (omega_m * {eta_key}))"
           f" / (M_p - {st_key})", "с")
    st.rec("a_p", r"a_{п}", f"{v_key} / t_p", "м/с²")
    st.var("a_max", r"[a]", a_max, "м/с²")
    st.var("t_max", r"[t_{п}]", t_max, "с")
    st.add(check("acceleration", st.value("a_p"), "≤", a_max, "м/с²", records=("t_p", "a_p"),
                 advice="slower_start"))
    st.add(check("start_time", st.value("t_p"), "≤", t_max, "с", records=("t_p",),
                 advice="stronger_start"))
    return True


def overload_check(st: Steps, st_key: str = "M_st") -> None:
    M_st = st.value(st_key)
    need = M_st / (VOLTAGE_DROP_FACTOR * st.value("psi_max")) * st.value("omega_m") / 1000
    st.add(check("overload", st.value("M_lim"), "≥", M_st, "Н·м", records=("M_lim",),
                 advice="motor_power", advice_value=need, advice_unit="кВт"))


def heating_check(st: Steps, squares: str, moves: int, started: bool) -> None:
    """The equivalent torque over a cycle of ``moves`` movements, each a start at M_п for t_п and a
    steady run at its static torque for t_у − t_п (``squares`` = the sum of the static torques
    squared), reduced to the motor's ПВ and compared with M_ном::

        M_ск = √(ΣM_i²/n),   M_э = √((M_п²·t_п + M_ск²·(t_у − t_п))/t_у),   M_э' = M_э·√(ПВ/ПВ_дв)

    (the mean of the n movements' M² over time, written with the root mean square static torque).
    """
    st.var("n_mv", r"n_{д}", moves)
    st.rec("M_sq", r"M_{ск}", f"sqrt(({squares}) / n_mv)", "Н·м")
    if started:
        st.rec("M_eq", r"M_{э}", "sqrt((M_p**2 * t_p + M_sq**2 * (t_m - t_p)) / t_m)", "Н·м")
    else:
        st.recs["M_eq"] = st.recs["M_sq"]
    st.rec("M_eq_pv", r"M_{э}'", "M_eq * sqrt(PV / PV_m)", "Н·м")
    need = st.value("M_eq_pv") * st.value("omega_m") / 1000
    st.add(check("heating", st.value("M_nom"), "≥", st.value("M_eq_pv"), "Н·м",
                 records=("M_eq", "M_eq_pv"), advice="motor_power", advice_value=need, advice_unit="кВт"))


def speed_check(st: Steps) -> None:
    st.var("dv_max", r"[\Delta v]", SPEED_TOLERANCE_PERCENT, "%")
    dv = st.value("dv")
    st.add(check("speed", abs(dv), "≤", SPEED_TOLERANCE_PERCENT, "%", records=("v_act", "dv"),
                 advice="reducer_ratio", advice_value=st.value("u_r_req"), advice_unit=""))


def reducer_check(st: Steps, reducer: Reducer) -> None:
    st.var("u_r", r"u_{р}", reducer.ratio)
    st.var("eta_r", r"\eta_{р}", reducer.efficiency)
    st.var("T_r", r"T_{р.ном}", reducer.rated_torque, "Н·м")


def reducer_torque_check(st: Steps) -> None:
    st.rec("T_out", r"T_{т}", "M_nom * u_r * eta_r", "Н·м")
    st.add(check("reducer_torque", st.value("T_r"), "≥", st.value("T_out"), "Н·м", records=("T_out",),
                 advice="reducer_torque", advice_value=st.value("T_out"), advice_unit="Н·м"))


def coupling_checks(st: Steps, couplings: tuple[Coupling, ...], k1: float, k2: float) -> None:
    st.var("k1", r"k_{1}", k1)
    st.var("k2", r"k_{2}", k2)
    st.rec("T_c", r"T_{м.р}", "k1 * k2 * M_nom", "Н·м")
    for i, c in enumerate(couplings, start=1):
        st.var(f"T_c{i}", rf"T_{{м{i}}}" if len(couplings) > 1 else r"T_{м}", c.rated_torque, "Н·м")
        st.add(check(f"coupling{i}", c.rated_torque, "≥", st.value("T_c"), "Н·м", records=("T_c",),
                     advice="coupling_torque", advice_value=st.value("T_c"), advice_unit="Н·м"))
