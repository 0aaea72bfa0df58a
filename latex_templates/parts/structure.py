"""Part «Структурный анализ»: the scheme, links and pairs, Chebyshev's W, the Assur groups, the
structural formula and the class of the mechanism."""
from __future__ import annotations

import numpy as np

from reportgen.calc import Var, record

from . import PartContent, strings_of

NEEDS = ("linkage", "structure", "kinematics")

def available(project) -> bool:
    return project.task.mechanism is not None


def _motion(project, k: int) -> str:
    lk = project.linkage
    pivoted = any(0 in j.bodies and k in j.bodies for j in lk.joints)
    on_frame_guide = any(s.link == k and s.guide == 0 for s in lk.slides)
    if pivoted:
        return "rotation"
    if on_frame_guide:
        return "translation"
    return "plane"


def content(project) -> PartContent:
    from ..figures.mechanism import scheme_figure
    from ..figures.groups import group_figure

    lk, st = project.linkage, project.structure
    links = []
    for k in lk.moving:
        b = lk.bodies[k]
        links.append({"id": k, "kind": b.kind, "motion": _motion(project, k), "points": "–".join(b.points)})
    pairs = []
    for j in lk.joints:
        for other in j.bodies[1:]:
            pairs.append({"bodies": f"{j.bodies[0]}–{other}", "point": j.name, "kind": "R"})
    for s in lk.slides:
        pairs.append({"bodies": f"{s.guide}–{s.link}", "point": s.point, "kind": "P"})
    S = strings_of(project)
    n = Var("n", "n", st.n, "", S.text("structure.var_n"))
    p1 = Var("p1", "p_1", st.p1, "", S.text("structure.var_p1"))
    p2 = Var("p2", "p_2", st.p2, "", S.text("structure.var_p2"))
    W = record("W", "3 * n - 2 * p1 - p2", "", n, p1, p2, label="eq:chebyshev",
               meaning=S.text("structure.var_W"))
    q0 = np.asarray(project.kinematics.q)[0]
    figures = {"structure_scheme": scheme_figure(lk, q0)}
    groups = []
    for idx, g in enumerate(st.groups[1:], start=1):
        name = f"structure_group{idx}"
        figures[name] = group_figure(lk, q0, g)
        inner = [p for p in g.pairs if not p.external]
        outer = [p for p in g.pairs if p.external]
        groups.append({"label": g.label, "links": g.links, "class": g.group_class, "order": g.order,
                       "kind": g.kind, "figure": name, "n": len(g.links), "p": len(g.pairs),
                       # a prismatic pair is named as such: «внешних B, D» read as the revolute D twice
                       "inner": [{"point": p.point, "prismatic": p.kind == "P"} for p in inner],
                       "outer": [{"point": p.point, "prismatic": p.kind == "P"} for p in outer]})
    ctx = {"links": links, "pairs": pairs, "W": W, "structure": st, "groups": groups,
           "formula": st.formula, "driver": st.groups[0].links[0]}
    from ..render import Tex
    strings = S
    conclusions = (strings.get("findings.structure").format(W=st.W, formula=st.formula,
                                                             cls=Tex(_roman(st.mechanism_class))),)
    return PartContent("sections/structure.tex.j2", ctx, figures, conclusions)


def _roman(k: int) -> str:
    return {1: "I", 2: "II", 3: "III", 4: "IV", 5: "V"}.get(k, str(k))
