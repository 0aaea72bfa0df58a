"""Part «Проектирование эвольвентной зубчатой передачи» (subsection 4.1): the pair of [gears].

Every number of the text comes from the solved :class:`reportgen.gears.pair.GearPair` through a
calculation record (formula = numbers = result) or a filter; the order is the course's (seed 000,
4.1): initial data, shifts, geometry, checks, meshing picture, contact ratio, specific sliding.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from reportgen.calc import CalcRecord, Var, record

from . import PartContent, tr

NEEDS = ("gears", "scenes")


def available(project) -> bool:
    return project.task.gears is not None


def places(value: float, decimals: int) -> int:
    """Significant digits that show ``value`` with ``decimals`` places (integer part kept; at least
    one: a value below the last place shows its first digit, not ``decimals`` more, issue 12:
    «Δu = −0,004594 %» for a difference of numbers printed to 4 places)."""
    if value == 0 or not math.isfinite(value):
        return decimals + 1
    return max(1, math.floor(math.log10(abs(value))) + 1 + decimals)


@dataclass(frozen=True)
class CheckLine:
    """One check for the text: the records shown, the comparison, the verdict."""
    name: str
    records: tuple[CalcRecord, ...]
    value: float
    limit: float
    passed: bool


def _rec(symbol: str, expr: str, unit: str, decimals: int, meaning: str = "", **named) -> CalcRecord:
    """A record whose result shows ``decimals`` places (mm to 3 places, as the course writes)."""
    probe = record(symbol, expr, unit, **named)
    return record(symbol, expr, unit, digits=places(probe.value, decimals), meaning=meaning, **named)


def gear_records(pair) -> dict[str, CalcRecord]:
    """The records of the geometric calculation in the course's order, keyed by short names."""
    g = pair.geometry
    V = {
        "z1": Var("z1", "z_1", g.z1, "", tr("gears.m30")),
        "z2": Var("z2", "z_2", g.z2, "", tr("gears.m31")),
        "m": Var("m", "m", g.m, "мм", tr("gears.wgea02")),
        "x1": Var("x1", "x_1", g.x1, "", tr("gears.m32")),
        "x2": Var("x2", "x_2", g.x2, "", tr("gears.m33")),
        "alpha": Var("alpha", r"\alpha", g.alpha_deg, "°", tr("gears.m34")),
        "ha": Var("ha", r"h_a^*", g.ha, "", tr("gears.m35")),
        "c": Var("c", r"c^*", g.c, "", tr("gears.m36")),
    }
    r: dict[str, CalcRecord] = {}

    def add(key: str, symbol: str, expr: str, unit: str, decimals: int, meaning: str, **names):
        named = {}
        for local, source in names.items():
            named[local] = V[source] if source in V else r[source]
        r[key] = _rec(symbol, expr, unit, decimals, meaning, **named)
        return r[key]

    add("x_sum", r"x_\Sigma", "x1 + x2", "", 3, tr("gears.m02"), x1="x1", x2="x2")
    add("inv_alpha", r"\operatorname{inv}\alpha", "tan(radians(alpha)) - pi * alpha / 180", "", 6,
        tr("gears.m03"), alpha="alpha")
    add("inv_alpha_w", r"\operatorname{inv}\alpha_w", "2 * x_sum * tan(radians(alpha)) / (z1 + z2) + inv_a",
        "", 6, tr("gears.m04"), x_sum="x_sum", alpha="alpha", z1="z1", z2="z2",
        inv_a="inv_alpha")
    V["alpha_w"] = Var("alpha_w", r"\alpha_w", g.alpha_w_deg, "°", tr("gears.m05"))
    add("a", "a", "m * (z1 + z2) / 2", "мм", 3, tr("gears.m06"), m="m", z1="z1", z2="z2")
    add("aw", "a_w", "a * cos(radians(alpha)) / cos(radians(alpha_w))", "мм", 3, tr("gears.m07"),
        a="a", alpha="alpha", alpha_w="alpha_w")
    add("u", "u", "z2 / z1", "", 3, tr("gears.m08"), z1="z1", z2="z2")
    add("y", "y", "(aw - a) / m", "", 5, tr("gears.m09"), aw="aw", a="a", m="m")
    add("dy", r"\Delta y", "x_sum - y", "", 5, tr("gears.m10"), x_sum="x_sum", y="y")
    for i in (1, 2):
        add(f"d{i}", f"d_{i}", f"m * z{i}", "мм", 3, tr("gears.m37", v1=_whose(i)), m="m", **{f"z{i}": f"z{i}"})
    for i in (1, 2):
        add(f"db{i}", f"d_{{b{i}}}", f"d{i} * cos(radians(alpha))", "мм", 3, tr("gears.m38", v1=_whose(i)),
            **{f"d{i}": f"d{i}"}, alpha="alpha")
    add("dw1", "d_{w1}", "2 * aw / (u + 1)", "мм", 3, tr("gears.m11"), aw="aw", u="u")
    add("dw2", "d_{w2}", "2 * aw * u / (u + 1)", "мм", 3, tr("gears.m12"), aw="aw", u="u")
    for i in (1, 2):
        add(f"da{i}", f"d_{{a{i}}}", f"d{i} + 2 * m * (ha + x{i} - dy)", "мм", 3,
            tr("gears.m39", v1=_whose(i)), **{f"d{i}": f"d{i}", f"x{i}": f"x{i}"}, m="m", ha="ha", dy="dy")
    for i in (1, 2):
        add(f"df{i}", f"d_{{f{i}}}", f"d{i} - 2 * m * (ha + c - x{i})", "мм", 3,
            tr("gears.m40", v1=_whose(i)), **{f"d{i}": f"d{i}", f"x{i}": f"x{i}"}, m="m", ha="ha", c="c")
    for i in (1, 2):
        add(f"h{i}", f"h_{i}", f"(da{i} - df{i}) / 2", "мм", 3, tr("gears.m41", v1=_whose(i)),
            **{f"da{i}": f"da{i}", f"df{i}": f"df{i}"})
    add("c_w", "c_w", "aw - (da1 + df2) / 2", "мм", 3, tr("gears.m13"),
        aw="aw", da1="da1", df2="df2")
    add("p", "p", "pi * m", "мм", 3, tr("gears.m14"), m="m")
    add("pb", "p_b", "pi * m * cos(radians(alpha))", "мм", 3, tr("gears.wgea01"), m="m", alpha="alpha")
    for i in (1, 2):
        add(f"s{i}", f"s_{i}", f"m * (pi / 2 + 2 * x{i} * tan(radians(alpha)))", "мм", 3,
            tr("gears.m42", v1=_whose(i)), m="m", alpha="alpha", **{f"x{i}": f"x{i}"})
    for i in (1, 2):
        add(f"alpha_a{i}", rf"\alpha_{{a{i}}}", f"degrees(acos(db{i} / da{i}))", "°", 3,
            tr("gears.m43", v1=_whose(i)), **{f"db{i}": f"db{i}", f"da{i}": f"da{i}"})
        add(f"inv_alpha_a{i}", rf"\operatorname{{inv}}\alpha_{{a{i}}}",
            f"tan(radians(alpha_a{i})) - pi * alpha_a{i} / 180", "", 6, "",
            **{f"alpha_a{i}": f"alpha_a{i}"})
        add(f"sa{i}", f"s_{{a{i}}}", f"da{i} * (s{i} / d{i} + inv_a - inv_aa{i})", "мм", 3,
            tr("gears.m44", v1=_whose(i)),
            **{f"da{i}": f"da{i}", f"s{i}": f"s{i}", f"d{i}": f"d{i}", f"inv_aa{i}": f"inv_alpha_a{i}"},
            inv_a="inv_alpha")
    # the line of action and the contact ratio
    add("g", "N_1N_2", "aw * sin(radians(alpha_w))", "мм", 3, tr("gears.m15"),
        aw="aw", alpha_w="alpha_w")
    add("ab", "ab", "sqrt(da1**2 - db1**2) / 2 + sqrt(da2**2 - db2**2) / 2 - g", "мм", 3,
        tr("gears.m16"), da1="da1", db1="db1", da2="da2", db2="db2", g="g")
    add("eps", r"\varepsilon_\alpha", "ab / pb", "", 3, tr("gears.m17"), ab="ab", pb="pb")
    add("n1p", "N_1P", "db1 / 2 * tan(radians(alpha_w))", "мм", 3, "", db1="db1", alpha_w="alpha_w")
    add("n2a", "N_2a", "sqrt(da2**2 - db2**2) / 2", "мм", 3, "", da2="da2", db2="db2")
    add("n1b", "N_1b", "sqrt(da1**2 - db1**2) / 2", "мм", 3, "", da1="da1", db1="db1")
    add("n1a", "N_1a", "g - n2a", "мм", 3, "", g="g", n2a="n2a")
    return r


def _whose(i: int) -> str:
    return tr("gears.whose1" if i == 1 else "gears.whose2")


def check_lines(pair, r: dict[str, CalcRecord]) -> list[CheckLine]:
    """The checks of the pair, each with the records that show its numbers (order of the course)."""
    g = pair.geometry
    alpha = Var("alpha", r"\alpha", g.alpha_deg, "°")
    ha = Var("ha", r"h_a^*", g.ha, "")
    out: list[CheckLine] = []
    for i in (1, 2):
        z = Var(f"z{i}", f"z_{i}", getattr(g, f"z{i}"), "")
        xm = _rec(f"x_{{\\min{i}}}", f"ha - z{i} * sin(radians(alpha))**2 / 2", "", 3,
                  tr("gears.m45", v1=_whose(i)), ha=ha, alpha=alpha,
                  **{f"z{i}": z})
        chk = pair.check(f"undercut{i}")
        out.append(CheckLine(f"undercut{i}", (xm,), chk.value, chk.limit, chk.passed))
    k = Var("k", "k", pair.sa_min_factor, "", tr("gears.m18"))
    sa_min = _rec(r"[s_a]", "k * m", "мм", 3, tr("gears.m19"), k=k,
                  m=Var("m", "m", g.m, "мм"))
    for i in (1, 2):
        chk = pair.check(f"sharpening{i}")
        out.append(CheckLine(f"sharpening{i}", (sa_min,) if i == 1 else (), chk.value, chk.limit, chk.passed))
    chk = pair.check("contact_ratio")
    out.append(CheckLine("contact_ratio", (), chk.value, chk.limit, chk.passed))
    for i in (1, 2):
        r_i = Var(f"d{i}", f"d_{i}", getattr(g, f"d{i}"), "мм")
        x_i = Var(f"x{i}", f"x_{i}", getattr(g, f"x{i}"), "")
        rho_l = _rec(rf"\rho_{{l{i}}}", f"d{i} / 2 * sin(radians(alpha)) - (ha - x{i}) * m / sin(radians(alpha))",
                     "мм", 3, tr("gears.m46", v1=_whose(i)),
                     alpha=alpha, ha=ha, m=Var("m", "m", g.m, "мм"), **{f"d{i}": r_i, f"x{i}": x_i})
        rho_p = r["n1a"] if i == 1 else _rec(r"N_2b", "g - n1b", "мм", 3, "", g=r["g"], n1b=r["n1b"])
        chk = pair.check(f"interference{i}")
        out.append(CheckLine(f"interference{i}", (rho_l, rho_p), chk.value, chk.limit, chk.passed))
    return out


def content(project) -> PartContent:
    from latex_templates.figures.gears import blocking_contour_figure, meshing_figure, sliding_figure
    from reportgen.gears.shifts import RULE_EQUAL_SLIDING

    pair = project.gears
    g = pair.geometry
    r = gear_records(pair)
    checks = check_lines(pair, r)
    ms = project.scenes.meshing                 # sheet 4's picture; the note's figure is a window of it
    pic, scale = ms.pic, ms.scale
    ab_sheet = ms.scene.values["ab"]
    ab_read = Var("ab_read", r"\overline{ab}", ab_sheet, "мм", tr("gears.m20"))
    k_var = Var("k_l", "k_l", scale.factor, "", tr("gears.m21"))
    ab_drawn = _rec(r"ab'", "ab_read / k_l", "мм", 3, tr("gears.m22"),
                    ab_read=ab_read, k_l=k_var)
    eps_drawn = _rec(r"\varepsilon_\alpha'", "ab_d / pb", "", 3, "", ab_d=ab_drawn, pb=r["pb"])
    # the difference between the two printed lengths (both to 0,001 mm, as printed above)
    ab_d_shown = Var("ab_d", "ab'", round(ab_drawn.value, 3), "мм")
    ab_shown = Var("ab_a", "ab", round(r["ab"].value, 3), "мм")
    eps_diff = _rec(r"\delta_{ab}", "(ab_d - ab_a) / ab_a * 100", "%", 2, "",
                    ab_d=ab_d_shown, ab_a=ab_shown)
    # specific sliding
    sl = pair.sliding
    rows = []
    for row in sl.rows:
        rows.append((_point_label(row.label), row.rho, _lam(row.lambda1), _lam(row.lambda2)))
    choice = pair.shift_choice
    figures = {"gear_pair_meshing": meshing_figure(pair, ms), "gear_pair_sliding": sliding_figure(pair)}
    auto = None
    if choice is not None:
        figures["gear_pair_contour"] = blocking_contour_figure(pair)
        auto = {"equal": choice.rule == RULE_EQUAL_SLIDING, "x1_exact": choice.x1_exact,
                "x2_exact": choice.x2_exact, "lambda1_a": choice.lambda1_a, "lambda2_b": choice.lambda2_b}
    failed = [c for c in checks if not c.passed]
    alt = _alternative(pair) if failed else None
    if alt is not None:
        figures["gear_pair_contour"] = blocking_contour_figure(alt["pair"])
    conclusions = [_conclusion(pair, failed, alt, project.task.document.language or "ru")]
    ctx = {
        "g": g, "pair": pair, "r": r, "checks": {c.name: c for c in checks}, "failed": failed,
        "auto": auto, "pic": pic, "scale": scale, "ab_read": ab_read, "ab_drawn": ab_drawn,
        "eps_drawn": eps_drawn, "eps_diff": eps_diff, "k_var": k_var,
        "mesh_note": _mesh_note(project, figures["gear_pair_meshing"]), "sliding_rows": rows, "sl": sl, "zones": _zones(pic), "alt": alt,
    }
    return PartContent("sections/gear_pair.tex.j2", ctx, figures, tuple(conclusions))


def _mesh_note(project, fig):
    """«рисунок уменьшен, масштаб по листу 4» for the meshing figure (a window of sheet 4's scene)."""
    from .kinematics import scene_caption
    return scene_caption(project, fig, 4)


def _point_label(label: str):
    from ..render import Tex
    names = {"N1": "$N_1$", "N2": "$N_2$", "a": "$a$", "b": "$b$", "P": "$P$", "": ""}
    return Tex(names[label])


def _lam(v: float):
    from ..render import Tex
    if math.isinf(v):
        return Tex(r"$-\infty$" if v < 0 else r"$\infty$")
    return v


def _zones(pic) -> dict:
    """Lengths of the zones of double and single contact along ab, mm."""
    double = sum(math.dist(z.start, z.end) for z in pic.zones if z.pairs >= 2)
    single = sum(math.dist(z.start, z.end) for z in pic.zones if z.pairs == 1)
    gap = sum(math.dist(z.start, z.end) for z in pic.zones if z.pairs == 0)
    return {"double": double, "single": single, "gap": gap}


def _alternative(pair) -> dict | None:
    """The passing shift pair of the blocking contour when the given one fails (with its numbers)."""
    from reportgen.gears.pair import passing_alternative
    alt = passing_alternative(pair)
    if alt is None:
        return {"pair": None}
    a = alt.geometry
    return {"pair": alt, "x1": a.x1, "x2": a.x2, "aw": a.aw, "eps": a.eps_alpha, "sa1": a.sa1, "sa2": a.sa2,
            "eps_min": alt.eps_min, "sa_min": alt.sa_min_factor * a.m,
            "rho": [(alt.check(f"interference{i}").value, alt.check(f"interference{i}").limit) for i in (1, 2)],
            "xmin": [alt.check(f"undercut{i}").limit for i in (1, 2)]}


def _conclusion(pair, failed, alt=None, language: str = "ru") -> str:
    """A sentence for the conclusions (trusted LaTeX, numbers with a decimal comma)."""
    from ..render import Tex
    from latex_templates.numbers import mnum
    g = pair.geometry
    text = tr("gears.m01", v1=g.z1, v2=g.z2, v3=Tex(mnum(g.m)), v4=Tex(mnum(g.x1)), v5=Tex(mnum(g.x2)),
              v6=Tex(mnum(g.aw, places(g.aw, 3))), v7=Tex(mnum(g.eps_alpha, places(g.eps_alpha, 3))))
    names = {"undercut1": tr("gears.m23"), "undercut2": tr("gears.m24"),
             "sharpening1": tr("gears.m25"), "sharpening2": tr("gears.m26"),
             "contact_ratio": f"$\\varepsilon_\\alpha \\ge {mnum(pair.eps_min)}$",
             "interference1": tr("gears.m27"),
             "interference2": tr("gears.m28")}
    if failed:
        text += tr("gears.m47") + "; ".join(names[c.name] for c in failed) + "."
        if alt is not None and alt["pair"] is not None:
            text += " " + _strings(language).get("marks.gear_alt_conclusion").format(
                x1=Tex(mnum(alt["x1"])), x2=Tex(mnum(alt["x2"])), aw=Tex(mnum(alt["aw"], places(alt["aw"], 3))),
                eps=Tex(mnum(alt["eps"], places(alt["eps"], 3))))
    else:
        text += tr("gears.m29")
    return Tex(text)


def _strings(language: str):
    from latex_templates.render import Strings
    return Strings(language)
