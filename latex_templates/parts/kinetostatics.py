"""Part «Силовой расчёт рычажного механизма» (section 2): the analysed position; masses, weights,
inertia forces and moments with their formulas; Fи′ shifted by h; the production resistance from its
law; each Assur group from the last attached (its diagram, R^τ from ΣM about the inner joint with the
arms in mm, the vector equation, the force polygon at μF, the reactions read off it and compared
with the exact ones); the crank (F_ур, M_ур, R01); Zhukovsky's lever; the comparison of the methods;
the near-dead-centre warning; M_ур over the cycle by both methods.

Every number comes from :func:`reportgen.kinetostatics.results.kinetostatics_of` (the replica in
``graphical``) through calculation records or filters. Records that repeat a replica's computation
(R^τ, F_ур) are checked against the replica's value, so a template can never drift from the solver."""
from __future__ import annotations

import math
import re

import numpy as np
from ..render import Tex

from reportgen.balance import Balance, BalanceTerm
from reportgen.calc import CalcRecord, Var, record
from reportgen.errors import InternalError
from reportgen.numbers import clean
from reportgen.kinetostatics.analysis import WARN_TRANSMISSION_DEG
from reportgen.kinetostatics.reactions import pair_name
from reportgen.tolerances import RTOL_EQUAL

from . import PartContent, active, tr

NEEDS = ("linkage", "structure", "kinetostatics", "resistance", "balancing_cycle", "balancing_cycle_dense", "scenes")

#: Terms of one summed moment equation per printed line; longer sums are split into partial sums.
TERMS_PER_RECORD = 3


def _partial_meaning(loads: tuple[Var, ...]) -> str:
    """«сумма моментов сил F_пс, G_1, G_2»: a partial sum named by the loads it sums (the note printed
    «частичная сумма моментов» five times in one «где» list)."""
    if not loads:
        return tr("kinetostatics.m30")
    return tr("kinetostatics.m30f", forces=Tex(", ".join(v.latex for v in loads)))


def available(project) -> bool:
    return project.task.mechanism is not None


def sym(name: str) -> str:
    from ..figures.kinetostatics import symbol
    return symbol(name)


class _Counter:
    """Numbers the arms h1, h2, … through the section, as a student does."""

    def __init__(self) -> None:
        self.n = 0

    def next(self) -> int:
        self.n += 1
        return self.n


def _canon(name: str) -> str | None:
    """``R42`` → ``R24`` (the pair's name, lower id first); None for R^n, R^τ and loads."""
    m = re.fullmatch(r"R(\d+),(\d+)|R(\d)(\d)", name)
    if not m:
        return None
    i, j = (int(m.group(1)), int(m.group(2))) if m.group(1) else (int(m.group(3)), int(m.group(4)))
    return pair_name(min(i, j), max(i, j))


def _check(rec: CalcRecord, expected: float, what: str) -> None:
    if not math.isclose(rec.value, expected, rel_tol=RTOL_EQUAL, abs_tol=RTOL_EQUAL * max(1.0, abs(expected))):
        raise InternalError("kinetostatics note", f"{what} printed as {rec.value!r}, the replica has {expected!r}")


def _arm_terms(terms, read_mags: dict[str, float], centre: str, counter: _Counter, arms_shown: list
               ) -> tuple[list[tuple[float, Var, Var]], list[tuple[str, Var]], list[str]]:
    """The moment terms of a replica as (sign, |F| Var, h Var); zero-arm forces listed apart."""
    out, extra, through = [], [], []
    for t in terms:
        if t.name == "M":
            extra.append(t)
            continue
        if t.arm_mm_measured == 0.0 or t.magnitude == 0.0:
            if t.magnitude != 0.0:
                through.append(t.name)
            continue
        c = _canon(t.name)
        mag = read_mags[c] if c is not None and c in read_mags else t.magnitude
        n = counter.next()
        s = sym(t.name)
        F = Var("F", s, mag, "Н", _meaning(t.name, c in read_mags))
        h = Var("h", f"h_{{{n}}}", abs(t.arm_mm_measured), "мм",
                Tex(tr("kinetostatics.m31", s=Tex(s), centre=centre)))
        arms_shown.append({"n": n, "name": t.name, "mm": abs(t.arm_mm_measured)})
        out.append((math.copysign(1.0, t.arm_mm_measured), F, h))
    return out, extra, through


def _meaning(name: str, read: bool) -> Tex:
    """The «где» phrase of a force by its solver name."""
    m = re.fullmatch(r"(G|Fи|F|Fпс|R)(\d*)(′?)", name.split(",")[0]) if ":" not in name else None
    s = sym(name)
    if name.startswith("Fпс"):
        return Tex(tr("kinetostatics.m19"))
    if m and m.group(1) == "G":
        return Tex(tr("kinetostatics.m20", v1=m.group(2)))
    if m and m.group(1) == "Fи":
        return Tex(tr("kinetostatics.m32", v1=m.group(2)) + (tr("kinetostatics.m40") if m.group(3) else ""))
    if name.startswith("R"):
        return Tex(tr("kinetostatics.m33", s=Tex(s)) + (tr("kinetostatics.m41") if read else ""))
    if ":" in name:
        return Tex(tr("kinetostatics.m22", v1=Tex(sym(name.split(':')[0]))))
    return Tex(tr("kinetostatics.m02", s=Tex(s)))


def _balance_terms(terms: list[tuple[float, Var, Var]]) -> tuple[BalanceTerm, ...]:
    """(sign, force, arm) triples as the known terms of a balance."""
    return tuple(BalanceTerm(1 if sgn > 0 else -1, F, h) for sgn, F, h in terms)


def _couples(extra_terms, mu_l: Var, link: int) -> tuple[BalanceTerm, ...]:
    """Couples enter a sum of moments in N·mm as M/μl."""
    return tuple(BalanceTerm(1 if t.moment >= 0 else -1,
                             Var("M", f"M_{{{link}}}", abs(t.moment), "Н·м", tr("kinetostatics.m42", link=link)),
                             divisor=mu_l) for t in extra_terms)


def _polygon_rows(polygon) -> list[list]:
    rows = []
    for v in list(polygon.vectors) + list(polygon.extra):
        dev = v.deviation_percent if math.isfinite(v.deviation_percent) and v.exact_value > 0 else None
        rows.append([Tex(f"$\\bar {sym(v.name)}$"), _read_mm(polygon, v), v.read_value, v.exact_value,
                     dev if dev is not None else Tex("---"), tr("kinetostatics.wkin09") if not v.known else tr("kinetostatics.wkin10")])
    return rows


def _details(polygon, first: int) -> list:
    """A sentence for each enlarged detail of the polygon's figure
    (:func:`reportgen.scenes.forces.polygon_details`): which vectors it shows, at which ratio and μF."""
    from reportgen.scenes.forces import LEGIBLE_MM, polygon_details
    from . import decimal_mark
    letters = str(active().raw("polygons.letters"))
    out = []
    for d in polygon_details(polygon, first=first):
        names = [Tex(f"${sym(n)}$") for n in d.names]
        key = "polygons.detail" if len(names) > 1 else "polygons.detail_one"
        out.append(tr(key, names=Tex(", ".join(names)), mm=f"{LEGIBLE_MM:g}", letter=letters[d.index % len(letters)],
                      ratio=d.drawing_scale.text(decimal_mark()), mu=d.scale))
    return out


def _read_mm(polygon, v) -> float:
    """The length of a vector as the replica read it off the polygon, mm (read value / μF)."""
    return round(v.read_value / polygon.scale, 6)


def _equation(eq: str) -> Tex:
    lhs = eq.replace(" = 0", "").split(" + ")
    parts = [f"\\bar {sym(x)}" for x in lhs]
    lines = [" + ".join(parts[i:i + 9]) for i in range(0, len(parts), 9)]
    if len(lines) == 1:
        return Tex(f"\\[\n{lines[0]} = 0.\n\\]")
    body = " \\\\\n+ ".join(lines)
    return Tex(f"\\begin{{multline*}}\n{body} = 0.\n\\end{{multline*}}")


def _read_records(polygon, mu_f: Var) -> list[CalcRecord]:
    """Each reaction found on the polygon: R = (length read)·μF."""
    recs = []
    for v in list(polygon.vectors) + list(polygon.extra):
        if v.known or v.name.startswith(("Rτ",)):
            continue
        s = sym(v.name)
        ln = Var("len", f"l_{{{s}}}", _read_mm(polygon, v), "мм",
                 Tex(tr("kinetostatics.m34", s=Tex(s))))
        rec = record(s, "len * mu_F", "Н", ln, mu_F=mu_f)
        _check(rec, v.read_value, f"the reading of {v.name}")
        recs.append(rec)
    return recs


# -- the part --------------------------------------------------------------------------------------

def content(project) -> PartContent:
    from reportgen.scenes.forces import first_detail_indices, polygon_scene
    from ..figures.kinetostatics import free_body_figure
    from ..figures.scene import scene_figure
    from .kinematics import scene_caption

    ks = project.kinetostatics
    st = project.structure
    r = ks.reactions
    g = ks.graphical
    counter = _Counter()
    figures: dict = {}
    bodies = {fb.key: fb for fb in project.scenes.free_bodies}      # sheet 2 draws the same scenes
    mu_l = Var("mu_l", r"\mu_l", bodies["crank"].scene.scale("μl").value, "м/мм", tr("kinetostatics.m03"))

    loads_ctx = _loads_section(project, ks, mu_l)
    resistance = _resistance(project)
    read_mags: dict[str, float] = {}
    groups_ctx = []
    by_key = {gr.key: gr for gr in st.groups}
    # the polygons' details are lettered through the work, in sheet 2's order (ГОСТ 2.305 §6)
    firsts = dict(zip((gg.key for gg in g.groups), first_detail_indices([gg.polygon for gg in g.groups])))
    control = project.task.document.kind == "control-work"   # the lever only: no reactions (manual §7)
    for gg in (() if control else g.groups):
        grp = by_key[gg.key]
        tag = gg.key.replace("-", "_")
        figures[f"kst_group_{tag}"] = free_body_figure(bodies[gg.key].scene)
        figures[f"kst_poly_{tag}"] = scene_figure(polygon_scene(gg.polygon, first=firsts[gg.key]))
        mu_f = Var("mu_F", r"\mu_F", gg.polygon.scale, "Н/мм", tr("kinetostatics.m23"))
        splits = []
        for sp in gg.splits:
            arms: list = []
            terms, extra, through = _arm_terms(sp.terms, read_mags, sp.centre, counter, arms)
            P = _pair_letter(r, sp, gg.key)
            l = Var("l", f"{P}{sp.centre}", sp.length_mm_measured, "мм",
                    tr("kinetostatics.m35", P=P, v2=sp.centre))
            bal = Balance(f"\\sum M_{{{sp.centre}}}^{{({sp.link})}}", f"R^{{\\tau}}_{{{sp.name[1:]}}}", "Н",
                          -1, l, _balance_terms(terms) + _couples(extra, mu_l, sp.link),
                          Tex(tr("kinetostatics.m43", v1=Tex(sym(sp.name)))),
                          partial=f"\\Sigma^{{({sp.link})}}", partial_unit="Н·мм", partial_meaning=_partial_meaning,
                          total_meaning=tr("kinetostatics.m30t"), per_line=TERMS_PER_RECORD)
            sol = bal.solve()
            parts, rec = list(sol.parts), sol.result
            _check(rec, sp.tau_measured, f"R^τ {sp.name}")
            splits.append({"name": sp.name, "link": sp.link, "centre": sp.centre, "pair": P, "parts": parts,
                           "rec": rec, "terms": terms, "through": [Tex(f"${sym(x)}$") for x in through],
                           "negative": rec.value < 0, "exact": sp.tau, "dev": sp.deviation_percent,
                           "balance": sol})
        slot = _slot_step(ks, grp, gg, counter, mu_l, read_mags) if gg.method == "exact-read" else None
        reads = _read_records(gg.polygon, mu_f)
        for v in list(gg.polygon.vectors) + list(gg.polygon.extra):
            c = _canon(v.name)
            if c is not None and not v.known:
                read_mags[c] = v.read_value
        groups_ctx.append({"key": gg.key, "tag": tag, "label": grp.label, "kind": gg.kind, "links": grp.links,
                           "method": gg.method, "splits": splits, "mu_f": mu_f, "equation": _equation(gg.polygon.equation),
                           "rows": _polygon_rows(gg.polygon), "reads": reads, "details": _details(gg.polygon, firsts[gg.key]),
                           "unknown": [Tex(f"${sym(v.name)}$") for v in gg.polygon.vectors if not v.known],
                           "mu_tr": ks.transmission_deg.get(gg.key), "slot": slot})
    if control:
        lever_ctx = _lever(project, ks, counter, figures)
        crank_ctx, comparison, cycle = None, None, None
        power = _power_check(project, ks, lever_ctx)
    else:
        crank_ctx = _crank(ks, read_mags, counter, mu_l, figures, bodies["crank"])
        lever_ctx = _lever(project, ks, counter, figures)
        comparison = _comparison(ks, crank_ctx, lever_ctx)
        cycle = _cycle(project, ks, figures)
        power = None
    warnings = [{"group": gk, "label": by_key[gk].label, "mu": mu} for gk, mu in ks.transmission_deg.items()
                if mu < WARN_TRANSMISSION_DEG]
    ctx = {"has_dynamics": project.task.has("dynamics"), "pos": ks.position, "phi": ks.phi_deg, "mu_l": mu_l, "loads": loads_ctx, "resistance": resistance,
           "groups": groups_ctx, "crank": crank_ctx, "lever": lever_ctx, "cmp": comparison, "cycle": cycle,
           "control": control, "power": power,
           "warnings": warnings, "warn_deg": WARN_TRANSMISSION_DEG,
           "M": ks.balancing_moment, "Mz": ks.balancing_moment_zhukovsky,
           "disc": clean(ks.discrepancy_percent, 100.0),
           "first_group": groups_ctx[0]["label"] if groups_ctx else "",
           "trans": [{"label": by_key[k].label, "mu": v} for k, v in ks.transmission_deg.items()],
           "width": {name: _width(fig) for name, fig in figures.items()},
           "fig_note": {name: scene_caption(project, fig, 1 if control and name == "kst_lever" else 2)
                        for name, fig in figures.items() if name.startswith(("kst_group_", "kst_crank", "kst_lever"))}}
    concl = _control_conclusions(project, power) if control else _conclusions(project, ks, comparison)
    return PartContent("sections/kinetostatics.tex.j2", ctx, figures, concl)


def _power_check(project, ks, lever) -> dict:
    """The check of P_у by the power balance (exact): M_у = −(ΣF·v + ΣM·ω)/ω1, and the deviation of
    the lever's graphical value from it."""
    from reportgen.control.analysis import control_work_of
    cw = control_work_of(project, ks.phi_deg)
    Mg = Var("M_g", "M_{\\text{у}}^{\\text{Ж}}", lever["M"].value, "Н·м", str(tr("control.note.where.M_lever")))
    Me = Var("M_e", "M_{\\text{у}}^{N}", cw.M_y_power, "Н·м", str(tr("control.note.where.M_power")))
    delta = record("\\delta_M", "100 * (M_g - M_e) / M_e", "%", Mg, Me, meaning=str(tr("control.note.where.delta")))
    return {"M_exact": cw.M_y_power, "P_exact": cw.M_y_power / cw.l_AB, "delta": delta,
            "M_lever_exact": cw.M_y, "dev_exact": cw.deviation_percent, "l_AB": cw.l_AB}


def _control_conclusions(project, power) -> tuple[str, ...]:
    from ..numbers import num
    from ..render import Strings
    strings = Strings(project.task.document.language or "ru")
    return (strings.get("control.note.conclusion").format(
        P=Tex(num(power["P_exact"], 5)), M=Tex(num(power["M_exact"], 5)),
        delta=Tex(num(power["delta"].value, 2))),)


def _width(fig) -> str:
    """A figure's natural width for \\includegraphics (never wider than the text)."""
    return f"{min(fig.get_figwidth() * 2.54, 16.0):.1f}cm"


def _pair_letter(r, sp, key: str) -> str:
    """The letter of the outer pair of a split (its joint)."""
    return next(p.joint for p in r.pairs if p.group == key and p.external and sp.link in (p.lo, p.hi))


def _slot_step(ks, grp, gg, counter, mu_l: Var, read_mags: dict[str, float]) -> dict | None:
    """The course's graphical step for a group of a block sliding in a slotted link pivoted at the
    frame (RPR): the block's reaction on the slotted link is perpendicular to the slot (no friction)
    and acts at the block's point, so ΣM_C(slotted link) = 0 gives it; the polygon follows."""
    from reportgen.kinetostatics.graphical import measure
    r = ks.reactions
    frame = [p for p in r.pairs if p.group == gg.key and p.external and 0 in (p.lo, p.hi) and p.kind == "R"]
    inner = [p for p in r.pairs if p.group == gg.key and not p.external and p.kind == "P"]
    if len(frame) != 1 or len(inner) != 1 or len(grp.links) != 2:
        return None
    k3 = frame[0].other(0)
    P = inner[0]
    if k3 not in (P.lo, P.hi):
        return None
    k2 = P.other(k3)
    C, A, n = frame[0].point[0], P.point[0], np.asarray(P.normal[0], float)
    step = ks.graphical.reading_mm
    mu = mu_l.value
    repl = {x.link: x for x in ks.graphical.inertia}
    arrows: list = []
    couples: list = []
    _loads_on(ks, (k3,), repl, arrows, couples)
    own = {p.name for p in r.pairs if p.group == gg.key}
    for p in r.pairs_of(k3):                                # reactions found on the previous steps
        j = p.other(k3)
        if p.name not in own and j not in grp.links:
            arrows.append({"point": p.point[0], "vector": p.on(k3)[0], "name": pair_name(j, k3), "read": True})
    terms, arms, through = [], [], []
    for a in arrows:
        F = np.asarray(a["vector"], float)
        c = _canon(a["name"]) if a.get("read") else None
        mag = read_mags.get(c, float(np.hypot(*F))) if c else float(np.hypot(*F))
        rr = np.asarray(a["point"], float) - C
        mom = float(rr[0] * F[1] - rr[1] * F[0])
        arm_mm = measure(abs(mom) / mag / mu, step) if mag > 0 else 0.0
        if arm_mm == 0.0:
            through.append(Tex(f"${sym(a['name'])}$"))
            continue
        nmb = counter.next()
        s = sym(a["name"])
        terms.append(BalanceTerm(1 if mom > 0 else -1, Var("F", s, mag, "Н", _meaning(a["name"], bool(c))),
                                 Var("h", f"h_{{{nmb}}}", arm_mm, "мм",
                                     Tex(active().get("marks.slot.arm").format(s=Tex(s), C=frame[0].joint)))))
        arms.append(nmb)
    extra = tuple(BalanceTerm(1 if cp["value"] >= 0 else -1,
                              Var("M", sym(cp["name"]), abs(cp["value"]), "Н·м",
                                  active().get("marks.slot.couple").format(k=k3)), divisor=mu_l) for cp in couples)
    lever = float((A - C)[0] * n[1] - (A - C)[1] * n[0])    # moment of a unit force along n at A about C
    d = n if lever > 0 else -n                              # the positive sense: a counter-clockwise moment
    arm = Var("l", f"{frame[0].joint}{P.joint}", measure(abs(lever) / mu, step), "мм",
              active().get("marks.slot.reaction_arm").format(C=frame[0].joint, A=P.joint))
    name = pair_name(k2, k3)
    sol = Balance(f"\\sum M_{{{frame[0].joint}}}^{{({k3})}}", sym(name), "Н", 1, arm,
                  tuple(terms) + extra, Tex(active().get("marks.slot.reaction").format(R=Tex(sym(name)))),
                  partial=f"\\Sigma^{{({k3})}}", partial_unit="Н·мм", partial_meaning=_partial_meaning,
                  total_meaning=tr("kinetostatics.m30t"),
                  per_line=TERMS_PER_RECORD).solve()
    exact = float(np.asarray(P.on(k3)[0]) @ d)
    return {"balance": sol, "parts": list(sol.parts), "rec": sol.result, "exact": exact, "name": Tex(f"${sym(name)}$"),
            "slot_link": k3, "block": k2, "C": frame[0].joint, "A": P.joint, "through": through,
            "negative": sol.value < 0}


def _loads_section(project, ks, mu_l: Var) -> dict:
    """Per link: G = m·g, Fи = m·a_S, Mи = J_S·ε, and the replacement h = Mи/Fи."""
    lk = project.linkage
    kin = ks.reactions.kin
    gvar = Var("g", "g", lk.g, "м/с²", tr("kinetostatics.m04"))
    repl = {x.link: x for x in ks.graphical.inertia}
    links, rows = [], []
    for k in lk.moving:
        b = lk.bodies[k]
        if b.mass <= 0 and b.inertia <= 0:
            continue
        m = Var("m", f"m_{{{k}}}", b.mass, "кг", tr("kinetostatics.m24", k=k))
        ent: dict = {"k": k, "G": None, "F": None, "M": None, "h": None, "h_mm": None, "repl": None,
                     "F_zero": False}
        a_s = float(np.hypot(*np.asarray(kin.coms[k].acc)[0]))
        eps = abs(float(np.asarray(kin.links[k].epsilon)[0]))
        if b.mass > 0 and a_s == 0.0:          # a centre of mass on a fixed axis (kinematics: exact 0)
            if lk.g:
                ent["G"] = record(f"G_{{{k}}}", "m * g", "Н", m, gvar, meaning=tr("kinetostatics.m57", k=k))
            ent["F_zero"] = True
        elif b.mass > 0:
            if lk.g:
                ent["G"] = record(f"G_{{{k}}}", "m * g", "Н", m, gvar, meaning=tr("kinetostatics.m57", k=k))
            aS = Var("a", f"a_{{S{k}}}", a_s, "м/с²", tr("kinetostatics.m36", k=k))
            ent["F"] = record(f"F_{{\\text{{и}}{k}}}", "m * a", "Н", m, aS, meaning=tr("kinetostatics.m44", k=k))
        if b.inertia > 0 and eps > 0:
            J = Var("J", f"J_{{S{k}}}", b.inertia, "кг·м²", tr("kinetostatics.m37", k=k))
            e = Var("eps", f"\\varepsilon_{{{k}}}", eps, "рад/с²", tr("kinetostatics.m38", k=k))
            ent["M"] = record(f"M_{{\\text{{и}}{k}}}", "J * eps", "Н·м", J, e, meaning=tr("kinetostatics.m45", k=k))
        if k in repl and ent["F"] is not None and ent["M"] is not None:
            x = repl[k]
            h = record(f"h_{{\\text{{и}}{k}}}", "M / F", "м", M=ent["M"], F=ent["F"],
                       meaning=tr("kinetostatics.m46", k=k))
            ent["h"] = h
            ent["h_mm"] = record(f"h_{{\\text{{и}}{k}}}^{{\\text{{сх}}}}", "h / mu_l", "мм", mu_l, h=h,
                                 meaning=tr("kinetostatics.m47"))
            ent["repl"] = {"measured": x.h_mm_measured, "swing": x.swing_point is not None,
                           "sense": "ccw" if x.moment > 0 else "cw"}
        links.append(ent)
        rows.append([k, b.mass, b.inertia, ent["G"].value if ent["G"] else 0.0, a_s,
                     ent["F"].value if ent["F"] else 0.0, eps, ent["M"].value if ent["M"] else 0.0,
                     ent["h"].value if ent["h"] else Tex("---")])
    not_replaced = [k for k in lk.moving
                    if lk.bodies[k].inertia > 0 and k not in repl and
                    abs(float(np.asarray(kin.links[k].epsilon)[0])) > 0 and lk.bodies[k].mass > 0]
    return {"links": links, "rows": rows, "g": gvar, "not_replaced": not_replaced}


def _resistance(project) -> list[dict]:
    """The production resistance at the analysed position (the stage ``resistance``): s/H, the
    law's factor and F = F_max·k as records; checked against the solver's load."""
    out = []
    for r in project.resistance:
        ent = {"link": r.link, "working": r.working, "on": r.on, "force": r.is_force, "value": r.value,
               "law": r.law, "rec": None, "frac": None, "kfac": None}
        if r.k is not None:
            slider = r.unit == "м"
            s = Var("s", "s", r.s, r.unit, tr("kinetostatics.m48") if slider else tr("kinetostatics.m49"))
            H = Var("H", "H", r.H, r.unit, tr("kinetostatics.m50") if slider else tr("kinetostatics.m51"))
            frac = record("s/H", "s / H", "", s, H, meaning=tr("kinetostatics.m52"))
            kv = Var("k", "k", r.k, "", Tex(tr("kinetostatics.m53")))
            if r.is_force:
                fmax = Var("Fmax", "F_{\\text{пс}}^{\\max}", r.maximum, "Н", tr("kinetostatics.m54"))
                rec = record("F_{\\text{пс}}", "Fmax * k", "Н", fmax, kv, meaning=tr("kinetostatics.m58"))
            else:
                mmax = Var("Mmax", "M_{\\text{пс}}^{\\max}", r.maximum, "Н·м", tr("kinetostatics.m55"))
                rec = record("M_{\\text{пс}}", "Mmax * k", "Н·м", mmax, kv, meaning=tr("kinetostatics.m59"))
            _check(rec, r.value, "the production resistance")
            ent.update(rec=rec, frac=frac, kfac=r.k)
        out.append(ent)
    return out


def _loads_on(ks, links, repl, arrows, couples) -> None:
    for f in ks.reactions.loads.forces:
        if f.link not in links:
            continue
        v = np.asarray(f.vector)[0]
        if f.kind == "inertia" and f.link in repl:
            arrows.append({"point": repl[f.link].point, "vector": v, "name": f.name + "′", "role": "load"})
        else:
            arrows.append({"point": np.asarray(f.point)[0], "vector": v, "name": f.name, "role": "load"})
    for m in ks.reactions.loads.moments:
        val = float(np.asarray(m.value)[0])
        if m.link not in links or val == 0.0 or (m.kind == "inertia" and m.link in repl):
            continue
        com = np.asarray(ks.reactions.kin.coms[m.link].pos)[0]
        couples.append({"point": com, "value": val, "name": m.name})


def _crank(ks, read_mags, counter, mu_l, figures, body) -> dict:
    """The crank's step: its diagram (``body``, the scene sheet 2 draws), F_ур from ΣM about the
    axis, M_ур, the polygon and the frame's reaction read off it."""
    from reportgen.scenes.forces import first_detail_indices, polygon_scene
    from ..figures.kinetostatics import free_body_figure
    from ..figures.scene import scene_figure
    r, c = ks.reactions, ks.graphical.crank
    d = r.crank
    fp = next(p for p in r.pairs if p.group == str(d))
    figures["kst_crank"] = free_body_figure(body.scene)
    # the details are lettered through the work: the crank's come after the groups' (sheet 2 likewise)
    first = first_detail_indices([gg.polygon for gg in ks.graphical.groups] + [c.polygon])[-1]
    figures["kst_poly_crank"] = scene_figure(polygon_scene(c.polygon, first=first))
    arms: list = []
    terms, extra, through = _arm_terms(c.terms, read_mags, r.crank_axis, counter, arms)
    OA = Var("l", f"{r.crank_axis}{r.crank_pin}", c.length_mm_measured, "мм",
             tr("kinetostatics.m05", v1=r.crank_axis, v2=r.crank_pin))
    # F_ур at the pin along the crank turned +90°: its moment about the axis is +F_ур·OA
    sol = Balance(f"\\sum M_{{{r.crank_axis}}}", "F_{\\text{ур}}", "Н", 1, OA,
                  _balance_terms(terms) + _couples(extra, mu_l, d),
                  tr("kinetostatics.m39") + r.crank_pin + tr("kinetostatics.m26"),
                  partial="\\Sigma^{(1)}", partial_unit="Н·мм", partial_meaning=_partial_meaning,
                  total_meaning=tr("kinetostatics.m30t"), per_line=TERMS_PER_RECORD).solve()
    parts, F = list(sol.parts), sol.result
    _check(F, c.balancing_force_measured, "F_ур (groups)")
    l_oa = Var("l_OA", f"l_{{{r.crank_axis}{r.crank_pin}}}", float(np.hypot(*(r.balancing_point[0] - fp.point[0]))),
               "м", tr("kinetostatics.m07", v1=r.crank_axis, v2=r.crank_pin))
    M = record("M_{\\text{ур}}", "F * l_OA", "Н·м", l_oa, F=F, meaning=tr("kinetostatics.m27"))
    _check(M, c.balancing_moment_measured, "M_ур (groups)")
    mu_f = Var("mu_F", r"\mu_F", c.polygon.scale, "Н/мм", tr("kinetostatics.m09"))
    return {"F": F, "M": M, "parts": parts, "through": [Tex(f"${sym(x)}$") for x in through],
            "balance": sol,
            "equation": _equation(c.polygon.equation), "rows": _polygon_rows(c.polygon), "mu_f": mu_f,
            "details": _details(c.polygon, first),
            "reads": _read_records(c.polygon, mu_f), "exact_F": c.balancing_force, "axis": r.crank_axis,
            "pin": r.crank_pin, "link": d,
            "pin_forces": [Tex(f"${sym(f.name)}$") for f in body.forces if f.role == "known"], "R0": pair_name(0, d), "exact_R0": float(np.hypot(*fp.on(d)[0])),
            "R_couple": float(np.hypot(*r.frame_reaction_with_moment[0]))}


def _lever(project, ks, counter, figures) -> dict:
    """Zhukovsky's lever: the record F_ур = ∓ΣF·h/pa with the measured arms, and its figure (the
    lever's scene, as sheet 2 draws it)."""
    from reportgen.scenes.lever import lever_scene
    from ..figures.scene import scene_figure
    lk, r, lev, L = project.linkage, ks.reactions, ks.lever, ks.graphical.lever
    mu_v = L.scale
    terms, loads = [], []
    for t, f in zip(L.terms, lev.forces):
        if t.magnitude == 0.0:
            continue
        ent = {"image": np.asarray(f.image)[0] / mu_v, "vector": np.asarray(f.vector)[0], "name": t.name,
               "arm_mm": t.arm_mm_measured, "h": None}
        if t.arm_mm_measured != 0.0:
            n = counter.next()
            s = sym(t.name)
            Fv = Var("F", s, t.magnitude, "Н", _meaning(t.name, False))
            h = Var("h", f"h_{{{n}}}", abs(t.arm_mm_measured), "мм",
                    Tex(tr("kinetostatics.m56", s=Tex(s))))
            terms.append((math.copysign(1.0, t.arm_mm_measured), Fv, h))
            ent["h"] = f"h_{{{n}}}"
        loads.append(ent)
    mu = Var("mu_v", r"\mu_v", mu_v, "(м/с)/мм", tr("kinetostatics.m10"))
    # moments about the pole, counter-clockwise positive; the direct couples enter as P/μv
    extra = tuple(BalanceTerm(1 if p >= 0 else -1,
                              Var("P", f"P_{{{sym(name)}}}", abs(p), "Вт", Tex(tr("kinetostatics.m60", v1=Tex(sym(name))))),
                              divisor=mu) for name, p in L.direct if p != 0.0)
    pa = Var("pa", f"p{r.crank_pin.lower()}", L.pa_mm_measured, "мм",
             tr("kinetostatics.m11", v1=r.crank_pin))
    # F_ур at the image of the pin: its moment about p is +F·pa when the crank turns counter-clockwise
    sol = Balance("\\sum M_{p}", "F_{\\text{ур}}^{\\text{Ж}}", "Н", 1 if lev.omega1 >= 0 else -1, pa,
                  _balance_terms(terms) + extra, tr("kinetostatics.m12"),
                  partial="\\Sigma^{(\\text{Ж})}", partial_unit="Н·мм", partial_meaning=_partial_meaning,
                  total_meaning=tr("kinetostatics.m30t"), per_line=TERMS_PER_RECORD).solve()
    parts, F = list(sol.parts), sol.result
    _check(F, L.balancing_force_measured, "F_ур (lever)")
    fp = next(p for p in r.pairs if p.group == str(r.crank))
    l_oa = Var("l_OA", f"l_{{{r.crank_axis}{r.crank_pin}}}", float(np.hypot(*(r.balancing_point[0] - fp.point[0]))),
               "м", tr("kinetostatics.m14", v1=r.crank_axis, v2=r.crank_pin))
    M = record("M_{\\text{ур}}^{\\text{Ж}}", "F * l_OA", "Н·м", l_oa, F=F,
               meaning=tr("kinetostatics.m28"))
    _check(M, L.balancing_moment_measured, "M_ур (lever)")
    arm_names = {ld["name"]: ld["h"] for ld in loads if ld["h"]}
    figures["kst_lever"] = scene_figure(lever_scene(ks, lk, arm_names))
    return {"F": F, "M": M, "parts": parts, "mu_v": mu, "pin": r.crank_pin.lower(), "balance": sol,
            "n_zero": sum(1 for t in L.terms if t.arm_mm_measured == 0.0 and t.magnitude > 0),
            "direct": bool(extra)}


def _comparison(ks, crank, lever) -> dict:
    Fg = Var("F_g", "F_{\\text{ур}}", crank["F"].value, "Н", tr("kinetostatics.m16"))
    Fz = Var("F_z", "F_{\\text{ур}}^{\\text{Ж}}", lever["F"].value, "Н", tr("kinetostatics.m17"))
    delta = record("\\delta", "100 * (F_g - F_z) / F_z", "%", Fg, Fz, meaning=tr("kinetostatics.m29"))
    _check(delta, ks.graphical.discrepancy_percent, "the graphical discrepancy")
    return {"delta": delta}


def _cycle(project, ks, figures) -> dict:
    """M_ур over the cycle from the stages ``balancing_cycle`` (the positions) and
    ``balancing_cycle_dense`` (the curve)."""
    from ..figures import kinetostatics as kf
    at, dense = project.balancing_cycle, project.balancing_cycle_dense
    order = np.argsort(np.mod(np.degrees(dense.phi), 360.0))
    deg = np.mod(np.degrees(dense.phi), 360.0)[order]
    figures["kst_cycle"] = kf.cycle_figure(deg, np.asarray(dense.groups)[order], np.mod(np.degrees(at.phi), 360.0),
                                           np.asarray(at.zhukovsky), ks.phi_deg, ks.balancing_moment)
    rows = []
    for j in range(len(at.phi)):
        mg, mz = float(at.groups[j]), float(at.zhukovsky[j])
        dev = clean(100.0 * (mg - mz) / mz, 100.0) if mz != 0 else 0.0
        rows.append([j, math.degrees(float(at.phi[j])) % 360.0, mg, mz, Tex(f"${_sci(dev)}$")])
    return {"rows": rows, "max": float(np.max(dense.groups)), "min": float(np.min(dense.groups)),
            "mean": float(np.mean(np.asarray(dense.groups)[:-1]))}


def _sci(x: float) -> str:
    from reportgen.calc import format_decimal
    return format_decimal(x, 2)


def _conclusions(project, ks, comparison) -> tuple[str, ...]:
    """The section's findings: φ1 to 0,01° and the discrepancy as the note prints them elsewhere
    (issue 12: one quantity, one rounding — «φ1 = 338,4°» against 338,39° in the text)."""
    from ..numbers import mfixed, num
    from ..render import Strings
    strings = Strings(project.task.document.language or "ru")
    out = [strings.get("findings_kinetostatics.balancing").format(
        phi=Tex(mfixed(ks.phi_deg, 2)), M=Tex(num(ks.balancing_moment, 6)),
        Mz=Tex(num(ks.balancing_moment_zhukovsky, 6)),
        delta=Tex("$" + comparison["delta"].result_number_latex() + "$"))]   # as printed in 2.7
    if any(mu < WARN_TRANSMISSION_DEG for mu in ks.transmission_deg.values()):
        out.append(strings.get("findings_kinetostatics.dead_centre"))
    return tuple(out)
