"""Part «Динамический анализ механизма и расчёт маховика» (section 3): the reduced moment and the
reduced moment of inertia with numbers for the analysed position and a table over the graph's
positions, the graphs (M_red, works, ΔE, J_red turned, Wittenbauer with tangents, ω(φ)), M_drive from
the balance of one cycle, the flywheel by three methods side by side (exact, the graphical replica,
Мерцалов) with the δ each one really gives, the flywheel's sizes and sketch, and the check of the
motion by integration.

Every number comes from :class:`reportgen.dynamics.DynamicsResult` (``project.dynamics``), from the
project's kinematics and loads, or from the solver's own functions (``steady_motion`` for the δ the
other two flywheels give), through calculation records or filters.
"""
from __future__ import annotations

import math
from typing import Any, cast
from dataclasses import dataclass

import numpy as np
from ..render import Tex

from reportgen.calc import CalcRecord, Var, record
from reportgen.dynamics.hub import hub_of
from reportgen.numbers import ANGLE_DECIMALS, clean_array
from reportgen.scenes.dynamics import MU_J, MU_M, DynamicsScenes
from reportgen.scenes.numbering import diagram_label, first_step, sense, translated_diagram_labels
from reportgen.tolerances import ABS_ROUNDOFF, RTOL_EQUAL

from . import PartContent, tr, unit

NEEDS = ("linkage", "model", "phi", "strokes", "kinematics", "analysed", "dynamics", "scenes")

#: A force or couple whose power is below this share of the largest one is still shown (gravity of
#: a light crank is small but is part of M_red); exactly zero ones (resistance off) are left out.
ZERO_FORCE = ABS_ROUNDOFF


#: |cos α| below this: the force is perpendicular to its point's velocity and does no work.
PERPENDICULAR = RTOL_EQUAL


def available(project) -> bool:
    return project.task.mechanism is not None and project.task.dynamics is not None


# ---------------------------------------------------------------------------------------------
# the analysed position: M_red by the powers of the loads, J_red by the links' shares


@dataclass(frozen=True)
class PowerTerm:
    """One load's power in the analysed position: the record P = F·V·cos α (or M·ω)."""
    name: str
    record: CalcRecord


def _sub(name: str) -> str:
    """``Fпс`` → ``F_\\text{пс}``, ``G4`` → ``G_{4}``, ``M3`` → ``M_{3}`` (LaTeX)."""
    base, rest = name[0], name[1:]
    if not rest:
        return base
    if rest.isdigit():
        return f"{base}_{{{rest}}}"
    return f"{base}_\\text{{{rest}}}"


def _point_velocity(kin, k: int, point: np.ndarray, i: int) -> np.ndarray:
    """Velocity of a point of link k at position i (the rigid-body formula of ``loads.power``)."""
    q, qd = np.asarray(kin.q), np.asarray(kin.qd)
    r = np.asarray(point)[i] - q[i, k, :2]
    return qd[i, k, :2] + qd[i, k, 2] * np.array([-r[1], r[0]])


def power_terms(project, i: int) -> tuple[list[PowerTerm], list[str], list[str]]:
    """P = F·V·cos α of every force and M·ω of every couple acting in position i (inertia excluded,
    as in M_red); also the LaTeX symbols of the loads that act but do no work there (a force
    perpendicular to its point's velocity), and of those whose point does not move."""
    from reportgen.loads import external_loads

    kin = project.kinematics
    loads = external_loads(project.task.mechanism, project.linkage, project.model, kin, project.strokes)
    out: list[PowerTerm] = []
    idle: list[str] = []
    still: list[str] = []
    v_scale = max([float(np.hypot(*np.asarray(m.vel)[i])) for m in kin.points.values()] + [0.0])
    for j, f in enumerate(loads.forces):
        vec = np.asarray(f.vector)[i]
        F = float(np.hypot(*vec))
        if F <= ZERO_FORCE:
            continue
        v = clean_array(_point_velocity(kin, f.link, f.point, i), v_scale)
        V = float(np.hypot(*v))
        if V == 0.0:
            still.append(_sub(f.name))    # its point does not move (a centre of mass on a fixed axis)
            continue
        alpha = math.degrees(math.atan2(abs(vec[0] * v[1] - vec[1] * v[0]), float(vec @ v))) if V > 0 else 90.0
        if abs(float(vec @ v)) <= PERPENDICULAR * F * max(V, ZERO_FORCE):
            idle.append(_sub(f.name))     # perpendicular to its velocity (a slider's weight): no power
            continue
        sym = _sub(f.name)
        where = f.where
        vsym = f"V_{{{where}}}"
        kind = {"resistance": tr("dynamics.m54"), "gravity": tr("dynamics.m55", v1=f.link),
                "force": tr("dynamics.m56", v1=f.link)}.get(f.kind, tr("dynamics.m14", v1=f.name))
        Fv = Var(f"F{j}", sym, F, "Н", kind)
        Vv = Var(f"V{j}", vsym, V, "м/с", tr("dynamics.m41", where=where) if not where.startswith("S")
                 else tr("dynamics.m42", v1=f.link))
        # the angle as the course measures it, to 0,01° (the power follows from the printed angle)
        av = Var(f"a{j}", rf"\alpha_{{{sym}}}", round(alpha, ANGLE_DECIMALS), "°",
                 Tex(tr("dynamics.m43", sym=sym, vsym=vsym)))
        rec = record(f"P_{{{sym}}}", f"F{j} * V{j} * cos(radians(a{j}))", "Вт", Fv, Vv, av,
                     meaning=Tex(tr("dynamics.m57", sym=sym)))
        out.append(PowerTerm(f.name, rec))
    for j, mo in enumerate(loads.moments):
        M = float(np.asarray(mo.value)[i])
        if abs(M) <= ZERO_FORCE:
            continue
        w = float(np.asarray(kin.links[mo.link].omega)[i])
        sym = _sub(mo.name)
        Mv = Var(f"M{j}", sym, M, "Н·м", Tex(tr("dynamics.m44", v1=mo.link)))
        wv = Var(f"w{j}", rf"\omega_{{{mo.link}}}", w, "рад/с", tr("dynamics.m15", v1=mo.link))
        rec = record(f"P_{{{sym}}}", f"M{j} * w{j}", "Вт", Mv, wv, meaning=Tex(tr("dynamics.m58", sym=sym)))
        out.append(PowerTerm(mo.name, rec))
    return out, idle, still


def angle_table(project) -> tuple[list, list]:
    """The force–velocity angles α_i of every load in every position of the analysis (as the course
    tabulates them for M_пр), with M_пр: the header (LaTeX) and the rows. A load whose point does not
    move or that does not act in a position shows «---»; one perpendicular to its velocity 90°."""
    columns: list[str] = []
    per_position = []
    w1 = abs(float(project.linkage.omega))
    for j in range(len(project.phi)):
        terms, idle, still = power_terms(project, j)
        angles: dict[str, float | None] = {}
        for t in terms:
            alpha = next((v for v in t.record.variables if v.name.startswith("a")), None)
            if alpha is not None:                         # a force (a couple has no angle)
                angles[_sub(t.name)] = alpha.value
        angles.update({x: 90.0 for x in idle})
        angles.update({x: None for x in still})
        columns += [x for x in angles if x not in columns]
        total = sum(t.record.value for t in terms)
        per_position.append((j, math.degrees(float(project.phi[j])) % 360.0, angles, total / w1))
    header = [Tex("№"), Tex("$\\varphi_1$, \\textdegree")]
    header += [Tex(f"$\\alpha_{{{c}}}$, \\textdegree") for c in columns]
    header.append(Tex("$M_\\text{пр}$, " + unit("Н$\\cdot$м")))      # the subscript: localize_latex
    rows = []
    for j, phi, angles, M in per_position:
        cells = [angles.get(c) for c in columns]
        rows.append([j, phi] + [Tex("---") if a is None else a for a in cells] + [M])
    return header, rows


def moment_records(terms: list[PowerTerm], omega1: Var) -> tuple[CalcRecord, CalcRecord]:
    """ΣP of the loads and M_red = ΣP / ω1 for the analysed position."""
    named: dict[str, Any] = {f"P{j}": t.record for j, t in enumerate(terms)}
    expr = " + ".join(named) if named else "0 * omega1"
    total = record(r"P_\Sigma", expr, "Вт", *(() if named else (omega1,)),
                   meaning=tr("dynamics.m16"), **named)
    M = record(r"M_\text{пр}", "P_sum / omega1", "Н·м", omega1, meaning=tr("dynamics.m17"),
               P_sum=total)
    return total, M


def inertia_records(project, i: int, omega1: Var) -> tuple[list[CalcRecord], CalcRecord]:
    """Each link's share (m·V_S² + J_S·ω²)/ω1² in position i, and J_red = J_0 + Σ shares."""
    lk, kin = project.linkage, project.kinematics
    shares: list[CalcRecord] = []
    for k in lk.moving:
        b = lk.bodies[k]
        if b.mass <= 0 and b.inertia <= 0:
            continue
        V = float(np.hypot(*np.asarray(kin.coms[k].vel)[i]))
        w = float(np.asarray(kin.links[k].omega)[i])
        named: dict[str, Var] = {}
        parts = []
        if b.mass > 0:
            named["m"] = Var(f"m{k}", f"m_{{{k}}}", b.mass, "кг", tr("dynamics.m45", k=k))
            named["V"] = Var(f"V{k}", f"V_{{S{k}}}", V, "м/с", tr("dynamics.m46", k=k))
            parts.append(f"m{k} * V{k}**2")
        rotates = b.inertia > 0 and not _translates(lk, k)
        if rotates:
            named["J"] = Var(f"J{k}", f"J_{{S{k}}}", b.inertia, "кг·м²",
                             tr("dynamics.m47", k=k))
            if k == lk.drive_link:
                parts.append(f"J{k} * omega1**2")
            else:
                named["w"] = Var(f"w{k}", rf"\omega_{{{k}}}", abs(w), "рад/с", tr("dynamics.m59", k=k))
                parts.append(f"J{k} * w{k}**2")
        if not parts:
            continue
        expr = "(" + " + ".join(parts) + ") / omega1**2"
        shares.append(record(rf"J_{{\text{{пр}}{k}}}", expr, "кг·м²", omega1, *named.values(),
                             meaning=tr("dynamics.m60", k=k)))
    dyn = project.task.dynamics
    J0 = Var("J0", r"J_0", dyn.crank_inertia, "кг·м²",
             tr("dynamics.m01"))
    named_sh: dict[str, Any] = {f"S{j}": s for j, s in enumerate(shares)}
    expr = " + ".join(["J0", *named_sh])
    total = record(r"J_\text{пр}", expr, "кг·м²", J0, meaning=tr("dynamics.m18"), **named_sh)
    return shares, total


def _translates(lk, k: int) -> bool:
    return any(s.link == k and s.guide == 0 for s in lk.slides)


# ---------------------------------------------------------------------------------------------
# the graphical construction: table, scales, tangents


def position_labels(res, positions: int) -> list[str]:
    """Names of the diagrams' positions in the note's language (the sheet's helper,
    :func:`reportgen.scenes.numbering.translated_diagram_labels`, with the note's catalogue)."""
    return translated_diagram_labels(res, tr, positions)


def _ordinates(scene, id_: str = "curve", axis: int = 1) -> list[float]:
    """The ordinates (``axis`` 1) or abscissae (0) of a scene's polyline, mm as drawn."""
    e = scene.entity(id_)
    return [float(p[axis]) for p in e.points]


def graph_rows(res, scenes: DynamicsScenes, labels: list[str]) -> list[list]:
    """Table 3.1: φ1, M_red, and the lengths of sheet 3's diagrams (read from their scenes) at the
    diagrams' positions."""
    g = res.graphical
    y_M, y_A, y_E = (_ordinates(sc) for sc in (scenes.moment, scenes.work, scenes.energy))
    x_J = _ordinates(scenes.wittenbauer, axis=0)
    mu_M, mu_J = scenes.moment.scale(MU_M).value, scenes.wittenbauer.scale(MU_J).value
    rows = []
    for j in range(g.theta.size - 1):
        phi = math.degrees(float(np.mod(res.phi[0] + _sense(res) * g.theta[j], 2 * math.pi)))
        rows.append([labels[j], phi, y_M[j] * mu_M, y_M[j], y_A[j], y_E[j], x_J[j] * mu_J, x_J[j]])
    return rows


def _sense(res) -> float:
    return sense(res)


def scale_records(scenes: DynamicsScenes) -> dict[str, CalcRecord | Var]:
    """The scales of the diagrams as sheet 3 draws them (read from the scenes)."""
    mo = scenes.moment
    L = Var("L", r"L_\varphi", mo.values["L_phi"], "мм", Tex(tr("dynamics.m20")))
    mu_phi = record(r"\mu_\varphi", "2 * pi / L", "рад/мм", L, meaning=tr("dynamics.m21"))
    mu_M = Var("mu_M", r"\mu_M", mo.scale(MU_M).value, "Н·м/мм", tr("dynamics.m02"))
    H = Var("H", "H", mo.values["H"], "мм", tr("dynamics.m03"))
    mu_A = record(r"\mu_A", "mu_M * mu_phi * H", "Дж/мм", mu_M, H, mu_phi=mu_phi,
                  meaning=tr("dynamics.m22"))
    k = Var("k", "k", scenes.energy.values["k"], "", tr("dynamics.m04"))
    # k < 1: ΔE is drawn reduced n = 1/k times (the Wittenbauer construction would not fit the sheet
    # at μE = μA, reportgen.dynamics.graphical._enlargement): written μE = μA·n, as a student would
    n = Var("n", "n", 1.0 / k.value, "", tr("dynamics.m04r"))
    mu_E = (record(r"\mu_E", "mu_A / k", "Дж/мм", k, mu_A=mu_A, meaning=tr("dynamics.m23")) if k.value >= 1
            else record(r"\mu_E", "mu_A * n", "Дж/мм", n, mu_A=mu_A, meaning=tr("dynamics.m23")))
    mu_J = Var("mu_J", r"\mu_J", scenes.wittenbauer.scale(MU_J).value, "кг·м²/мм", tr("dynamics.m05"))
    return {"L": L, "mu_phi": mu_phi, "mu_M": mu_M, "H": H, "mu_A": mu_A, "k": k, "n": n, "mu_E": mu_E,
            "mu_J": mu_J}


def tangent_records(scenes: DynamicsScenes, sc: dict, omega: Var, delta: Var) -> dict[str, CalcRecord | Var]:
    """ψmax, ψmin by the course's formula, KL as sheet 3 dimensions it (read to its 0,1 mm: the
    replica's ``KL_read_mm``) and J_fly from that printed value."""
    from .gear_pair import places
    common = dict(mu_J=sc["mu_J"], mu_E=sc["mu_E"])

    def angle(symbol: str, expr: str, meaning: str) -> CalcRecord:
        """An angle to the course's 0,01° (sheet 3 prints the same: ψmin = 9,05°, not 9,046°)."""
        probe = record(symbol, expr, "°", omega, delta, **common)
        return record(symbol, expr, "°", omega, delta, meaning=Tex(meaning),
                      digits=places(probe.value, ANGLE_DECIMALS), **common)
    psi_max = angle(r"\psi_{\max}", "degrees(atan(mu_J * (1 + delta) * omega1**2 / (2 * mu_E)))", tr("dynamics.m50"))
    psi_min = angle(r"\psi_{\min}", "degrees(atan(mu_J * (1 - delta) * omega1**2 / (2 * mu_E)))", tr("dynamics.m51"))
    KL = Var("KL", "KL", scenes.wittenbauer.values["KL_read_mm"], "мм", Tex(tr("dynamics.m24")))
    J_gr = record(r"J_\text{м}^\text{гр}", "KL * mu_E / (omega1**2 * delta)", "кг·м²", KL, omega, delta,
                  mu_E=sc["mu_E"], meaning=tr("dynamics.m25"))
    return {"psi_max": psi_max, "psi_min": psi_min, "KL": KL, "J_gr": J_gr}


def exact_records(res, omega: Var, delta: Var) -> dict[str, CalcRecord | Var]:
    ex = res.exact
    w_max = record(r"\omega_{\max}", "omega1 * (1 + delta / 2)", "рад/с", omega, delta,
                   meaning=tr("dynamics.m26"))
    w_min = record(r"\omega_{\min}", "omega1 * (1 - delta / 2)", "рад/с", omega, delta,
                   meaning=tr("dynamics.m27"))
    K = Var("K", "K", ex.K, "Дж", Tex(tr("dynamics.m28")))
    L = Var("Lk", "L", ex.L, "Дж", Tex(tr("dynamics.m29")))
    J_ex = record(r"J_\text{м}", "(K - Lk) / (omega1**2 * delta)", "кг·м²", K, L, omega, delta,
                  meaning=tr("dynamics.m30"))
    return {"w_max": w_max, "w_min": w_min, "K": K, "L": L, "J_ex": J_ex}


def merzalov_records(res, omega: Var, delta: Var) -> dict[str, CalcRecord | Var]:
    mz = res.merzalov
    T_max = Var("T_max", r"T_{\max}", mz.T_max, "Дж", Tex(tr("dynamics.m31")))
    T_min = Var("T_min", r"T_{\min}", mz.T_min, "Дж", Tex(tr("dynamics.m32")))
    J_I = record(r"J_\text{I}", "(T_max - T_min) / (omega1**2 * delta)", "кг·м²", T_max, T_min, omega, delta,
                 meaning=tr("dynamics.m33"))
    J_c = Var("J_c", r"J_\text{пост}", mz.J_const, "кг·м²",
              tr("dynamics.m06"))
    J_mz = record(r"J_\text{м}^\text{М}", "J_I - J_c", "кг·м²", J_c, J_I=J_I,
                  meaning=tr("dynamics.m34"))
    return {"T_max": T_max, "T_min": T_min, "J_I": J_I, "J_c": J_c, "J_mz": J_mz}


def flywheel_records(res, J_ex: CalcRecord) -> dict[str, CalcRecord | Var]:
    fw = res.flywheel
    J = J_ex.as_var("J_m", tr("dynamics.m07"))
    rho = Var("rho", r"\rho", fw.density, "кг/м³", tr("dynamics.m08"))
    psi = Var("psi", r"\psi", fw.width_ratio, "",
              tr("dynamics.m35") if fw.shape == "disk" else tr("dynamics.m36"))
    out: dict[str, CalcRecord | Var] = {"rho": rho, "psi": psi}
    if fw.shape == "disk":
        R = record("R", "(2 * J_m / (pi * rho * psi))**0.2", "м", J, rho, psi, meaning=tr("dynamics.wdyn01"))
        b = record("b", "psi * R", "м", psi, R=R, meaning=tr("dynamics.wdyn02"))
        m = record("m", "rho * pi * R**2 * b", "кг", rho, R=R, b=b, meaning=tr("dynamics.wdyn03"))
        out.update(R=R, b=b, m=m)
    else:
        k = Var("k_h", "k", fw.thickness / fw.radius, "", tr("dynamics.m37"))
        R = record("R", "(2 * J_m / (pi * rho * psi * k_h * (1 - (1 - k_h)**4)))**0.2", "м", J, rho, psi, k,
                   meaning=tr("dynamics.m52"))
        h = record("h", "k_h * R", "м", k, R=R, meaning=tr("dynamics.wdyn04"))
        b = record("b", "psi * h", "м", psi, h=h, meaning=tr("dynamics.wdyn05"))
        r = record("r", "R - h", "м", R=R, h=h, meaning=tr("dynamics.m53"))
        m = record("m", "rho * pi * (R**2 - r**2) * b", "кг", rho, R=R, r=r, b=b, meaning=tr("dynamics.wdyn06"))
        out.update(k=k, R=R, h=h, b=b, r=r, m=m)
    return out


def drive_records(res) -> dict[str, CalcRecord | Var]:
    A = Var("A_c", r"A_\text{с}", res.work_cycle, "Дж", tr("dynamics.m09"))
    M_d = record(r"M_\text{дв}", "-A_c / (2 * pi)", "Н·м", A, meaning=tr("dynamics.m38"))
    return {"A_c": A, "M_d": M_d}


# ---------------------------------------------------------------------------------------------
# the three flywheels and the δ each really gives


@dataclass(frozen=True)
class MethodRow:
    key: str
    J: float
    relative: float            # (J − J_exact)/J_exact
    delta: float               # δ achieved with this flywheel
    omega_max: float
    omega_min: float


def method_rows(project, res) -> tuple[list[MethodRow], dict[str, np.ndarray]]:
    """J_fly by each method, its difference from the exact one, and the δ it gives (the steady
    motion with that flywheel, by the solver's ``steady_motion``); also ω(θ) of each."""
    from reportgen.dynamics import EnergyProfile, ProjectCycle, steady_motion
    from reportgen.dynamics.solve import energy_of

    dyn = project.task.dynamics
    if dyn is not None and res.crank_inertia == dyn.crank_inertia:
        cycle, profile = energy_of(project, len(res.theta))     # the solver's own, computed once
    else:
        cycle = ProjectCycle(project, res.crank_inertia)
        profile = EnergyProfile(cycle, np.asarray(res.theta))
    rows, omegas = [], {}
    for c in res.comparison:
        if c.method == "exact":
            mo = res.motion
        else:
            mo = steady_motion(cycle, profile, max(c.J_fly, 0.0), np.asarray(res.theta), res.delta_target)
        rows.append(MethodRow(c.method, c.J_fly, c.relative, mo.delta, mo.omega_max, mo.omega_min))
        omegas[c.method] = np.asarray(mo.omega)
    return rows, omegas


def motion_records(res) -> dict[str, CalcRecord | Var]:
    mo = res.motion
    w_hi = Var("w_hi", r"\omega_{\max}'", mo.omega_max, "рад/с", tr("dynamics.m10"))
    w_lo = Var("w_lo", r"\omega_{\min}'", mo.omega_min, "рад/с", tr("dynamics.m11"))
    w_m = record(r"\omega_m'", "(w_hi + w_lo) / 2", "рад/с", w_hi, w_lo, meaning=tr("dynamics.m39"))
    d = record(r"\delta'", "(w_hi - w_lo) / w_m", "", w_hi, w_lo, w_m=w_m,
               meaning=tr("dynamics.m40"))
    return {"w_hi": w_hi, "w_lo": w_lo, "w_m": w_m, "delta": d}


# ---------------------------------------------------------------------------------------------


def content(project) -> PartContent:
    from ..figures import dynamics as fig
    from ..numbers import num
    from ..render import Strings
    from ..figures.scene import scene_figure
    from .kinematics import detail_position, scene_caption

    res = project.dynamics
    kin = project.kinematics
    i = detail_position(project)
    w1 = abs(float(project.linkage.omega))
    omega = Var("omega1", r"\omega_1", w1, "рад/с", tr("dynamics.m12"))
    delta = Var("delta", r"\delta", res.delta_target, "", tr("dynamics.m13"))
    terms, idle, still = power_terms(project, i)
    P_sum, M_rec = moment_records(terms, omega)
    shares, J_rec = inertia_records(project, i, omega)
    positions = int(round(2 * math.pi / float(_first_step(res.graphical.theta))))
    labels = position_labels(res, positions)
    i_dyn = diagram_label(res, float(kin.phi[i]))
    scenes = project.scenes.dynamics
    sc = scale_records(scenes)
    tg = tangent_records(scenes, sc, omega, delta)
    ex = exact_records(res, omega, delta)
    mz = merzalov_records(res, omega, delta)
    fw = flywheel_records(res, cast(CalcRecord, ex["J_ex"])) if res.exact.J_fly > 0 else None
    drv = drive_records(res)
    rows, omegas = method_rows(project, res)
    mot = motion_records(res)
    fig_work = scene_figure(scenes.column_group())
    fig_witt = scene_figure(scenes.wittenbauer_group())
    fig_note = {"dyn_work": scene_caption(project, fig_work, 3), "dyn_wittenbauer": scene_caption(project, fig_witt, 3)}
    hub = hub_of(res.M_drive, 2000.0 * res.flywheel.radius)          # the sketch's bore and keyway (sheet 3's)
    figures = {
        "dyn_work": fig_work,
        "dyn_wittenbauer": fig_witt,
        "dyn_omega": fig.omega_figure(res, omegas),
        "dyn_flywheel": fig.flywheel_figure(res.flywheel, hub),
    }
    resistance_on = any(t.name.startswith(("Fпс", "Mпс")) for t in terms)
    # the text names the resistance as it is given: a force (a slider) or a moment (a rocker)
    resistance_force = all(ld.force is not None for ld in project.task.mechanism.loads if ld.kind == "resistance")
    ctx = {
        "i": _position_ref(project, i, i_dyn, short=True), "i_ref": _position_ref(project, i, i_dyn), "phi_i": math.degrees(float(kin.phi[i])) % 360.0, "terms": [t.record for t in terms],
        "resistance_on": resistance_on, "resistance_force": resistance_force, "P_sum": P_sum, "idle": [Tex(f"${x}$") for x in idle],
        "still": [Tex(f"${x}$") for x in still], "M_rec": M_rec, "shares": shares, "J_rec": J_rec,
        "rows": graph_rows(res, scenes, labels), "positions": positions, "n_analysis": len(project.phi),
        "n_breaks": len(labels) - positions - 1, "corners": any(not x.isdigit() and x not in (tr("dynamics.m48"), tr("dynamics.m49")) for x in labels),
        "mz_diff": rows[1].J - rows[0].J, "gr_diff": rows[2].J - rows[0].J, "sc": sc, "tg": tg, "ex": ex, "mz": mz, "fw": fw,
        "drv": drv, "mot": mot, "methods": rows, "res": res, "g": res.graphical,
        "J_var": float(res.J_red.max() - res.J_red.min()), "J_mean": float(res.J_red.mean()),
        "omega": omega, "delta": delta, "shape": res.flywheel.shape, "hub": hub,
        "index_K": labels[int(scenes.wittenbauer.values["index_K"])],
        "index_L": labels[int(scenes.wittenbauer.values["index_L"])], "fig_note": fig_note,
        "fig_w": {k: f"{f.width_cm:.2f}cm" for k, f in (("dyn_work", fig_work), ("dyn_wittenbauer", fig_witt))},
        "theta_K": math.degrees(res.exact.theta_K), "theta_L": math.degrees(res.exact.theta_L),
        "J_zero": res.exact.J_fly <= 0,
        "angles": angle_table(project),
    }
    strings = Strings(project.task.document.language or "ru")
    concl = [strings.get("findings_dynamics.flywheel").format(
        J=Tex(num(res.J_flywheel)), shape=strings.get(f"findings_dynamics.{res.flywheel.shape}"), delta=Tex(num(res.delta_target)),
        R=Tex(num(res.flywheel.radius)), b=Tex(num(res.flywheel.width)), m=Tex(num(res.flywheel.mass)),
        achieved=Tex(num(mot["delta"].value))),
        strings.get("findings_dynamics.methods").format(
            merzalov=Tex(num(abs(100 * rows[1].relative), 2)), merzalov_sense=_sense_word(strings, rows[1]),
            graphical=Tex(num(abs(100 * rows[2].relative), 2)), graphical_sense=_sense_word(strings, rows[2]))]
    return PartContent("sections/dynamics.tex.j2", ctx, figures, tuple(concl))


def _position_ref(project, i: int, i_dyn: str | None, short: bool = False) -> Tex:
    """The analysed position named in the diagrams' grid (table 3.1, sheet 3) and, when its number
    differs there, in the grid of the kinematic analysis too: «3 по нумерации диаграмм листа 3
    (положение 2 плана положений)»; ``short``: the diagrams' number alone. An angle that is not on
    the diagrams' grid is named in the kinematic grid: «2 плана положений»."""
    from ..render import Strings
    if i_dyn == str(i):
        return Tex(i_dyn)
    strings = Strings(project.task.document.language or "ru")
    if i_dyn is None:
        return Tex(str(strings.get("scenes.position_kin"))).format(kin=i)
    if short:
        return Tex(i_dyn)
    return Tex(str(strings.get("scenes.position_in_both"))).format(dyn=i_dyn, kin=i)


def _sense_word(strings, row: MethodRow) -> Tex:
    return strings.get("findings_dynamics.more" if row.relative > 0 else "findings_dynamics.less")


def _first_step(theta: np.ndarray) -> float:
    return first_step(theta)
