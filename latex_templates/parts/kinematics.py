"""Part «Кинематический анализ»: plan of positions, extreme positions, velocity and acceleration
plans of the analysed position with every component, tables over all positions, s–v–a diagrams by
graphical differentiation compared with the exact curves, transmission angles."""
from __future__ import annotations

import math

import numpy as np
from ..render import Tex

from reportgen.calc import Var, record
from reportgen.plans import LEGIBLE_MM, MEASURE_MM, READ_DEVIATION_BOUND

from . import PartContent, tr

NEEDS = ("linkage", "structure", "model", "phi", "strokes", "kinematics", "analysed", "plans",
         "plan_positions", "plans_by_position", "scenes", "output_diagrams")


def available(project) -> bool:
    return project.task.mechanism is not None


def detail_position(project) -> int:
    """The position analysed in detail (the project's stage ``analysed``)."""
    return project.analysed


def scene_caption(project, fig, sheet: int = 1) -> Tex:
    """«рисунок уменьшен, масштаб по листу 1» for a scene's figure (from the strings)."""
    from ..render import Strings
    strings = Strings(project.task.document.language or "ru")
    if fig.reportgen_reduction < 1.0:
        return Tex(str(strings.get("scenes.reduced"))).format(sheet=sheet)
    return Tex(str(strings.get("scenes.natural"))).format(sheet=sheet)


def _len(body, p: str, q: str) -> float:
    return math.dist(body.local[p], body.local[q])


def _plan_rows(plan):
    rows = []
    for c in plan.components:
        rows.append({"name": c.name, "dir": c.direction, "mm": plan.measured_mm(c), "read": plan.read_value(c),
                     "exact": c.value, "dev": 100 * plan.deviation(c), "start": c.start, "end": c.end,
                     "computed": plan.computed(c), "drawn": plan.drawn(c), "compared": plan.compared(c)})
    return rows


def _omega_record(kin, i: int, k: int, seg: Var, lv: Var, mu_v) -> tuple[dict, Var]:
    """ω_k of position i from the velocity plan (segment ``seg`` over the length ``lv``): the note's
    row, and the exact |ω_k| as a variable for the accelerations."""
    omega = float(kin.links[k].omega[i])
    wrec = record(rf"\omega_{{{k}}}", "seg * mu_v / l", "рад/с", seg, lv, mu_v=mu_v,
                  meaning=tr("kinematics.m06", k=k))
    row = {"link": k, "rec": wrec, "exact": omega, "sense": "ccw" if kin.links[k].omega[i] > 0 else "cw"}
    return row, Var("w", rf"\omega_{{{k}}}", abs(omega), "рад/с")


def _epsilon_records(kin, i: int, k: int, aplan, rel: str, segt_symbol: str, lv: Var, w_exact: Var) -> tuple[dict, dict]:
    """The normal acceleration a^n_rel = ω_k²·l and ε_k of position i from the tangential component
    a^τ_rel of the acceleration plan (its segment named ``segt_symbol``): the note's two rows."""
    an = record(f"a^n_{{{rel}}}", "w**2 * l", "м/с²", w_exact, lv)
    comp_t = aplan.component(f"a^{{\\tau}}_{{{rel}}}")
    segt = Var("segt", segt_symbol, aplan.measured_mm(comp_t), "мм",
               Tex(tr("kinematics.m07", rel=rel)))
    erec = record(rf"\varepsilon_{{{k}}}", "segt * mu_a / l", "рад/с²", segt, lv,
                  mu_a=Var("mu_a", r"\mu_a", aplan.scale, "(м/с²)/мм", tr("kinematics.m19")),
                  meaning=tr("kinematics.m08", k=k))
    eps = {"link": k, "rec": erec, "exact": float(kin.links[k].epsilon[i]),
           "sense": "ccw" if kin.links[k].epsilon[i] > 0 else "cw"}
    return {"rec": an, "mm": an.value / aplan.scale}, eps


def content(project) -> PartContent:
    from ..figures.scene import scene_figure

    lk, st, kin = project.linkage, project.structure, project.kinematics
    i = detail_position(project)
    d = lk.drive_link
    axis, tip = lk.drive_axis, lk.drive_tip
    crank = lk.bodies[d]
    l_crank = _len(crank, axis, tip)
    w1 = abs(lk.omega)
    scenes = project.scenes
    figures = {}
    # --- plan of positions ----------------------------------------------------------------------
    positions = scenes.positions
    control = project.task.document.kind == "control-work"      # one position: no plan of positions
    mu_l = Var("mu_l", r"\mu_l", positions.scale("μl").value, "м/мм",
               tr("kinematics.m01_scheme" if control else "kinematics.m01"))
    l_oa = Var("l_OA", f"l_{{{axis}{tip}}}", l_crank, "м", tr("kinematics.m02", axis=axis, tip=tip))
    OA_mm = record(f"{axis}{tip}", "l_OA / mu_l", "мм", l_oa, mu_l, meaning=tr("kinematics.m09", axis=axis, tip=tip))
    # a control work (one position) or a crank that cannot turn fully: no cycle, no traces, no strokes
    cycle = not control and project.full_cycle
    dense_trans = {}
    if cycle:
        dense = np.linspace(0, 2 * math.pi, 121)
        dk = project.model.solve(dense)
        dense_trans = {g.key: float(np.min(dk.transmission_deg[g.key])) for g in st.groups[1:]}
    fig_pos = scene_figure(positions)
    figures["kin_positions"] = fig_pos
    strokes = project.strokes if cycle else None
    stroke_ctx = None
    if strokes is not None:
        wk = Var("phi_w", r"\varphi_\text{р.х}", strokes.working_deg, "°", tr("kinematics.m10"))
        ik = Var("phi_i", r"\varphi_\text{х.х}", strokes.idle_deg, "°", tr("kinematics.m11"))
        K = record("K", "phi_w / phi_i", "", wk, ik, meaning=tr("kinematics.m20"))
        stroke_ctx = {"K": K, "working": strokes.working_deg, "idle": strokes.idle_deg, "H": strokes.stroke,
                      "kind": strokes.output.kind, "link": strokes.output.link, "point": strokes.output.point,
                      "start": math.degrees(strokes.phi_start) % 360, "end": math.degrees(strokes.phi_end) % 360,
                      "construction": _construction(project, strokes)}
    # positions table
    from reportgen.kinematics.extremes import output_coordinate
    out_rows = []
    if strokes is not None:
        x = output_coordinate(project.model, strokes.output, np.asarray(kin.q))
        q0, _ = project.model.positions(np.array([strokes.phi_start]))
        x0 = output_coordinate(project.model, strokes.output, q0)[0]
        s_out = (x - x0) * strokes.direction
    else:
        s_out = np.zeros(len(kin.phi))
    # a rocker's swing in degrees, as the text gives its range (ψ = 47,73°), not in radians
    rocker = strokes is not None and strokes.output.kind != "slider"
    for j, ph in enumerate(kin.phi):
        out_rows.append([j, math.degrees(ph) % 360, math.degrees(float(s_out[j])) if rocker else float(s_out[j])] +
                        [float(kin.transmission_deg[g.key][j]) for g in st.groups[1:]])
    # --- velocity and acceleration plans of every plan position (the analysed one first) --------
    plan_ctx = []
    for j in project.plan_positions:
        ctx_j, figs_j = _plan_context(project, j, first=(j == i))
        plan_ctx.append(ctx_j)
        figures.update(figs_j)
    first = plan_ctx[0]
    # --- tables over all positions ---------------------------------------------------------------
    moving = [k for k in lk.moving if k != d]
    vtab, atab = [], []
    for j in range(len(kin.phi)):
        vtab.append([j, math.degrees(kin.phi[j]) % 360] +
                    [float(np.hypot(*np.asarray(kin.coms[k].vel[j]))) for k in moving] +
                    [float(kin.links[k].omega[j]) for k in moving if not _translates(lk, k)])
        atab.append([j, math.degrees(kin.phi[j]) % 360] +
                    [float(np.hypot(*np.asarray(kin.coms[k].acc[j]))) for k in moving] +
                    [float(kin.links[k].epsilon[j]) for k in moving if not _translates(lk, k)])
    rot_links = [k for k in moving if not _translates(lk, k)]
    omega_eps_rows = []
    if control:
        sense = lambda x: tr("control.note.ccw" if x > 0 else "control.note.cw") if x != 0 else Tex("---")  # noqa: E731
        for k in [d] + rot_links:
            w, e = float(kin.links[k].omega[i]), float(kin.links[k].epsilon[i])
            omega_eps_rows.append([k, abs(w), sense(w), abs(e), sense(e)])
    # --- diagrams ------------------------------------------------------------------------------
    diag = None
    if strokes is not None:
        dg = project.output_diagrams
        dg_scene = project.scenes.output_diagrams
        assert dg is not None and dg_scene is not None     # the output has strokes
        figures["kin_diagrams"] = scene_figure(dg_scene)
        omega1 = Var("omega1", r"\omega_1", w1, "рад/с", tr("kinematics.m03"))
        L = Var("L", "L", dg_scene.values["L"], "мм", Tex(tr("kinematics.m21")))
        mu_phi = record(r"\mu_\varphi", "2 * pi / L", "рад/мм", L, meaning=tr("kinematics.m22"))
        mu_t = record(r"\mu_t", "mu_phi / omega1", "с/мм", omega1, mu_phi=mu_phi, meaning=tr("kinematics.m23"))
        H1 = Var("H1", "H_1", dg_scene.values["H1"], "мм", tr("kinematics.m16"))
        H2 = Var("H2", "H_2", dg_scene.values["H2"], "мм", tr("kinematics.m17"))
        unit_s = "м/мм" if dg.unit == "м" else "рад/мм"
        # the output's own quantities: s, v, a of a slider; ψ, ω, ε of a rocker (as sheet 1's scene)
        sym_s, sym_v, sym_a = (r"\mu_s", r"\mu_{v}", r"\mu_{a}") if dg.unit == "м" else \
            (r"\mu_\psi", r"\mu_{\omega}", r"\mu_{\varepsilon}")
        mu_s = Var("mu_s", sym_s, dg_scene.scales[0].value, unit_s, tr("kinematics.m18"))
        mu_vd = record(sym_v, "mu_s / (mu_t * H1)", "(м/с)/мм" if dg.unit == "м" else "(рад/с)/мм",
                       mu_s, H1, mu_t=mu_t, meaning=tr("kinematics.m24"))
        mu_ad = record(sym_a, "mu_v / (mu_t * H2)", "(м/с²)/мм" if dg.unit == "м" else "(рад/с²)/мм",
                       H2, mu_v=mu_vd, mu_t=mu_t, meaning=tr("kinematics.m25"))
        diag = {"mu_phi": mu_phi, "mu_t": mu_t, "mu_v": mu_vd, "mu_a": mu_ad, "mu_s": dg.mu_s, "sym_s": Tex(sym_s), "n": dg.n,
                "dev_v": 100 * dg.v_deviation, "dev_a": 100 * dg.a_deviation, "unit": dg.unit,
                "vmax": float(np.abs(dg.v).max()), "amax": float(np.abs(dg.a).max())}
    scene_figs = (("kin_positions", fig_pos), ("kin_vplan", figures["kin_vplan"]), ("kin_aplan", figures["kin_aplan"])) + \
        ((("kin_diagrams", figures["kin_diagrams"]),) if "kin_diagrams" in figures else ())
    fig_w = {name: f"{f.width_cm:.2f}cm" for name, f in scene_figs}
    fig_note = {name: scene_caption(project, f) for name, f in scene_figs}
    trans = [{"key": g.key, "label": g.label, "min": float(np.min(kin.transmission_deg[g.key])),
              "at": int(np.argmin(kin.transmission_deg[g.key]))} for g in st.groups[1:]]
    ctx = {
        "i": i, "phi_i": math.degrees(kin.phi[i]) % 360, "n_pos": len(kin.phi), "control": control, "omega_eps_rows": omega_eps_rows,
        "mu_l": mu_l, "OA_mm": OA_mm, "fig_w": fig_w, "fig_note": fig_note, "scale_ratio": positions.scale("μl").ratio, "strokes": stroke_ctx, "out_rows": out_rows,
        "groups": [g.label for g in st.groups[1:]],
        **{k: first[k] for k in _PLAN_KEYS},      # the analysed position's plans, as before
        "plans": plan_ctx,
        "moving": moving, "rot_links": rot_links, "vtab": vtab, "atab": atab,
        "diag": diag, "trans": trans, "dense_trans": dense_trans,
        "near": [{"pos": j, "group": g, "mu": mu} for j, g, mu in kin.near_singular],
        "tip": tip, "axis": axis,
    }
    concl = []
    if stroke_ctx and strokes is not None:
        from ..numbers import num
        from ..render import Strings
        strings = Strings(project.task.document.language or "ru")
        concl.append(strings.get("findings.strokes").format(
            work=Tex(num(strokes.working_deg)), idle=Tex(num(strokes.idle_deg)),
            K=Tex(num(stroke_ctx["K"].value))))
    return PartContent("sections/kinematics.tex.j2", ctx, figures, tuple(concl))


#: Keys of a plan position's context that the part's context also holds for the analysed position.
_PLAN_KEYS = ("VA", "mu_v", "pa_mm", "pia_mm", "vplan", "vrows", "omega", "aA", "mu_a", "aplan", "arows", "an",
              "cor", "eps", "com_rows", "equations_v", "equations_a", "max_dev_v", "max_dev_a", "by_points")


def _plan_context(project, i: int, first: bool) -> tuple[dict, dict]:
    """The note's context of the plans of plan position ``i`` (``project.plans_by_position``: the
    calculations of section 1's velocity and acceleration plans) and their figures, named
    ``kin_vplan``/``kin_aplan`` for the analysed position (``first``), ``kin_vplan_<i>`` else."""
    from reportgen.plan_positions import stroke_of
    from ..figures.scene import scene_figure
    lk, st, kin = project.linkage, project.structure, project.kinematics
    d = lk.drive_link
    axis, tip = lk.drive_axis, lk.drive_tip
    l_crank = _len(lk.bodies[d], axis, tip)
    w1 = abs(lk.omega)
    vplan, aplan = project.plans_by_position[i]
    l_oa = Var("l_OA", f"l_{{{axis}{tip}}}", l_crank, "м", tr("kinematics.m02", axis=axis, tip=tip))
    # --- velocities -----------------------------------------------------------------------------
    omega1 = Var("omega1", r"\omega_1", w1, "рад/с", tr("kinematics.m03"))
    VA = record(f"V_{{{tip}}}", "omega1 * l_OA", "м/с", omega1, l_oa, meaning=tr("kinematics.m12", tip=tip))
    pa_mm = VA.value / vplan.scale
    pa = Var("pa", f"p{tip.lower()}", pa_mm, "мм", tr("kinematics.m04", tip=tip))
    mu_v = record(r"\mu_v", "V_A / pa", "(м/с)/мм", pa, V_A=VA, meaning=tr("kinematics.m13"))
    vrows = _plan_rows(vplan)
    omega_recs = []
    eps_recs = []
    an_recs = []
    cor_recs = []
    for g in st.groups[1:]:
        if g.group_class != 2:
            continue
        inner = next(p for p in g.pairs if not p.external)
        for k in g.links:
            ext = next(p for p in g.pairs if p.external and k in p.bodies)
            body = lk.bodies[k]
            if g.kind in ("RRR", "RRP") and ext.kind == "R" and inner.kind == "R":
                Q, P = inner.point, ext.point
                l = _len(body, P, Q)
                comp = vplan.component(f"V_{{{Q}{P}}}")
                seg = Var("seg", f"{comp.start}{comp.end}",
                          vplan.measured_mm(comp), "мм", Tex(tr("kinematics.m27", Q=Q, P=P)))
                lv = Var("l", f"l_{{{P}{Q}}}", l, "м", tr("kinematics.m26", P=P, Q=Q))
                omega_rec, w_exact = _omega_record(kin, i, k, seg, lv, mu_v)
                omega_recs.append(omega_rec)
                an_rec, eps_rec = _epsilon_records(kin, i, k, aplan, f"{Q}{P}", f"n_{{{Q}{P}}}{Q.lower()}", lv, w_exact)
                an_recs.append(an_rec)
                eps_recs.append(eps_rec)
            elif g.kind == "RPR":
                s = lk.slides[inner.slide]
                if k != s.guide:
                    continue
                H = next(p for p in g.pairs if p.external and s.link in p.bodies).point
                G = ext.point
                Hg = f"{H}_{{{k}}}"
                comp = vplan.component(f"V_{{{Hg}{G}}}")
                gh = float(np.hypot(*(np.asarray(kin.points[H].pos[i]) - np.asarray(kin.points[G].pos[i]))))
                seg = Var("seg", f"{comp.start}{comp.end}", vplan.measured_mm(comp), "мм",
                          Tex(tr("kinematics.m30", Hg=Hg, G=G)))
                lv = Var("l", f"l_{{{G}{H}}}", gh, "м", tr("kinematics.m28", G=G, H=H))
                omega_rec, w_exact = _omega_record(kin, i, k, seg, lv, mu_v)
                omega_recs.append(omega_rec)
                vrel = vplan.component(f"V_{{{Hg}{H}}}")
                vr = Var("vr", f"V_{{{Hg}{H}}}", vrel.value, "м/с", tr("kinematics.m29"))
                cor = record(f"a^k_{{{Hg}{H}}}", "2 * w * vr", "м/с²", w_exact, vr,
                             meaning=tr("kinematics.m31"))
                cor_recs.append({"rec": cor, "mm": cor.value / aplan.scale})
                end = aplan.component(f"a^{{\\tau}}_{{{Hg}{G}}}").end
                an_rec, eps_rec = _epsilon_records(kin, i, k, aplan, f"{Hg}{G}", f"n{end}", lv, w_exact)
                an_recs.append(an_rec)
                eps_recs.append(eps_rec)
    # centres of mass from the plans (by similarity)
    com_rows = []
    for k in lk.moving:
        if k == d:
            continue
        vs = np.asarray(kin.coms[k].vel[i])
        as_ = np.asarray(kin.coms[k].acc[i])
        mm_v = round(float(np.hypot(*vs)) / vplan.scale / MEASURE_MM) * MEASURE_MM
        mm_a = round(float(np.hypot(*as_)) / aplan.scale / MEASURE_MM) * MEASURE_MM
        com_rows.append([k, mm_v, mm_v * vplan.scale, float(np.hypot(*vs)), mm_a, mm_a * aplan.scale,
                         float(np.hypot(*as_))])
    # --- accelerations --------------------------------------------------------------------------
    aA = record(f"a_{{{tip}}}", "omega1**2 * l_OA", "м/с²", omega1, l_oa, meaning=tr("kinematics.m14", tip=tip))
    pia = Var("pia", f"\\pi {tip.lower()}", aA.value / aplan.scale, "мм", tr("kinematics.m05", tip=tip))
    mu_a = record(r"\mu_a", "a_A / pia", "(м/с²)/мм", pia, a_A=aA, meaning=tr("kinematics.m15"))
    arows = _plan_rows(aplan)
    suffix = "" if first else f"-{i}"
    fv, fa = ("kin_vplan", "kin_aplan") if first else (f"kin_vplan_{i}", f"kin_aplan_{i}")
    fig_v = scene_figure(project.scenes.velocity_plans[i])
    fig_a = scene_figure(project.scenes.acceleration_plans[i])
    sgn = 1.0 if project.model.omega >= 0 else -1.0
    ctx = {"i": i, "phi_i": math.degrees(kin.phi[i]) % 360, "suffix": suffix,
           # a control work gives one position and no resistance: no working or idle stroke to name
           "stroke": None if project.task.document.kind == "control-work" else
           stroke_of(float(kin.phi[i]), project.strokes if project.full_cycle else None, sgn),
           "control": project.task.document.kind == "control-work", "tip": tip, "axis": axis,
           "fig_v": fv, "fig_a": fa, "fig_w_v": f"{fig_v.width_cm:.2f}cm", "fig_w_a": f"{fig_a.width_cm:.2f}cm",
           "fig_note_v": scene_caption(project, fig_v), "fig_note_a": scene_caption(project, fig_a),
           "VA": VA, "mu_v": mu_v, "pa_mm": pa_mm, "pia_mm": aA.value / aplan.scale, "vplan": vplan, "vrows": vrows,
           "omega": omega_recs, "aA": aA, "mu_a": mu_a, "aplan": aplan, "arows": arows, "an": an_recs,
           "cor": cor_recs, "eps": eps_recs, "com_rows": com_rows,
           "equations_v": vplan.equations, "equations_a": aplan.equations,
           # the comparison takes the read, legible segments only (reportgen.plans.LEGIBLE_MM)
           "max_dev_v": max((abs(r["dev"]) for r in vrows if r["compared"]), default=0.0),
           "max_dev_a": max((abs(r["dev"]) for r in arows if r["compared"]), default=0.0),
           "legible_mm": LEGIBLE_MM, "read_bound": 100 * READ_DEVIATION_BOUND,
           "computed": [r for r in arows if r["computed"]],
           "unlaid": [r for r in arows if not r["drawn"]],
           "short": [r for r in vrows + arows if not r["computed"] and not r["compared"]]}
    # the groups that the plans show by the images of their points (class III, two prismatic pairs:
    # reportgen/plans.py) have no vector equations of two points to print: the note says so
    solved = {key for key, _ in vplan.equations}
    ctx["by_points"] = [g.label for g in st.groups[1:] if g.key not in solved]
    return ctx, {fv: fig_v, fa: fig_a}


def _translates(lk, k: int) -> bool:
    return any(s.link == k and s.guide == 0 for s in lk.slides)


def _construction(project, strokes):
    """The course's construction of the extreme positions, as sentences with their numbers (or None)."""
    from reportgen.kinematics.extremes import extreme_construction
    from ..numbers import num
    from ..render import Strings, Tex
    c = extreme_construction(project.model, strokes)
    if c is None:
        return None
    strings = Strings(project.task.document.language or "ru")
    mu = 1000.0                    # lengths in mm, as on the plan of positions
    if c.kind == "in-line":
        text = strings.get("marks.extremes.in_line").format(O=c.axis, A=c.pin, B=c.far, k=c.coupler)
        for phi, how, ob in c.positions:
            key = "marks.extremes.extended" if how == "extended" else "marks.extremes.folded"
            text = Tex(text + " ") + strings.get(key).format(
                O=c.axis, A=c.pin, B=c.far, AB=Tex(num(c.coupler_length * mu)), OA=Tex(num(c.crank_length * mu)),
                OB=Tex(num(ob * mu)), phi=Tex(num(phi, 5)))
        return text
    text = strings.get("marks.extremes.perpendicular").format(O=c.axis, A=c.pin, B=c.far, k=c.coupler,
                                                               OB=Tex(num(c.positions[0][2] * mu)),
                                                               OA=Tex(num(c.crank_length * mu)))
    phis = [Tex(num(phi, 5)) for phi, _, _ in c.positions]
    return Tex(text + " ") + strings.get("marks.extremes.perpendicular_at").format(phi1=phis[0], phi2=phis[1])
