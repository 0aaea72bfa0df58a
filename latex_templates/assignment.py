"""The assignment (задание) of the note from the task file: its data as tables and the scheme, and
the introduction's paragraphs about this mechanism."""
from __future__ import annotations

import math
import re

import numpy as np

from reportgen.tolerances import ABS_ZERO

from .note import Section
from .render import Strings, Tex


def _lang(project) -> str:
    return project.task.document.language or "ru"


def assignment_section(project) -> Section:
    task = project.task
    ctx: dict = {"mech": None, "control": None, "gears": task.gears, "planetary": task.planetary, "dynamics": task.dynamics,
                 "analysis": task.analysis}
    figures: dict = {}
    strings = Strings(_lang(project))
    if task.mechanism is not None:
        mech = task.mechanism
        lk = project.linkage
        rows = []
        for ln in mech.links:
            b = lk.bodies[ln.id]
            names = b.points
            dims = []
            for i in range(len(names)):
                for j in range(i + 1, len(names)):
                    d = math.dist(b.local[names[i]], b.local[names[j]])
                    dims.append((f"{names[i]}{names[j]}", d))
            rows.append({
                "id": ln.id,
                "kind": strings.get(f"kinds.{ln.kind}"),
                "points": "–".join(names),
                "dims": dims,
                "mass": ln.mass,
                "inertia": ln.inertia,
                "mass_given": ln.mass_given,
            })
        ground = [(n, mech.points[n]) for n in mech.ground]
        slides = []
        for s in mech.slides:
            if s.guide == 0:
                slides.append({"link": s.link, "point": s.point, "text": None,
                               "through": s.through, "angle": s.angle_deg})
            else:
                slides.append({"link": s.link, "point": s.point, "guide": s.guide, "along": s.along})
        loads = []
        for ld in mech.loads:
            loads.append(ld)
        q, _ = project.model.positions(np.array([lk.sketch_phi()]))
        from .figures.mechanism import scheme_figure
        figures["assignment_scheme"] = scheme_figure(lk, q[0])
        ctx["mech"] = {"name": mech.name, "links": rows, "ground": ground, "slides": slides, "loads": loads,
                       "omega": mech.drive.omega, "drive": mech.drive.link, "g": mech.g,
                       "rules": mech.mass_rules, "any_rule": any(not ln.mass_given for ln in mech.links),
                       # the rules' clauses this mechanism uses: no slider, no triangle → not named
                       "rule_slider": any(ln.kind == "slider" and not ln.mass_given for ln in mech.links),
                       "rule_triangle": any(len(ln.points) >= 3 and not ln.inertia_given for ln in mech.links),
                       "n_rpm": abs(mech.drive.omega) * 30 / math.pi}
    cw = task.control_work
    if cw is not None and cw.table is not None and cw.variant is not None:
        from reportgen.control.tables import table
        t = table(cw.table)
        ctx["control"] = {"table": t.number, "variant": cw.variant, "page": t.page,
                          "columns": [(label_tex(c.label, strings), _printed(c.printed[cw.variant - 1], strings))
                                      for c in t.columns],
                          "scheme": scheme_phrases(t.scheme, strings)}
    return Section(key="assignment", title=strings.get("headings.assignment"), template="assignment.tex.j2",
                   context=ctx, figures=figures)


def _expr_tex(expr: str) -> str:
    """A scheme expression of the table's quantities as math: "l_AD + a" → "l_{AD} + a"."""
    return re.sub(r"l_([A-Z]+)", r"l_{\1}", expr.replace("*", r" \cdot ")).replace("+ -", "- ")


def _printed(value: str, strings) -> str:
    """A table value as the manual prints it (decimal comma), with the language's decimal mark."""
    return value.replace(",", strings.decimal_mark())


def label_tex(label: str, strings=None) -> Tex:
    """A printed column heading as LaTeX: "lCE =lEF, м" → "$l_{CE} = l_{EF}$, м", "ϕ , °" → "$\\varphi$, °";
    the unit in the language of ``strings`` (``м`` → ``m``)."""
    name, _, unit = label.partition(",")
    parts = []
    for p in (x.strip() for x in name.split("=")):
        p = p.replace("А", "A").replace("а", "a")
        if p.startswith("l") and len(p) > 1:
            parts.append(f"l_{{{p[1:].strip()}}}")
        elif p == "ϕ":
            parts.append(r"\varphi")
        elif p == "ω1":
            parts.append(r"\omega_1")
        else:
            parts.append(p)
    unit = unit.strip()
    if unit and strings is not None:
        unit = strings.math_word(unit)
    return Tex("$" + " = ".join(parts) + "$" + (f", {unit}" if unit else ""))


def scheme_phrases(sc, strings) -> list:
    """The reconstructed scheme of a control-work table in words (strings control.scheme.*)."""
    out = [strings.get("control.scheme.d").format(x=Tex(_expr_tex(sc.D[0])), y=Tex(_expr_tex(sc.D[1])))]
    if sc.e_kind == "bar":
        out.append(strings.get("control.scheme.e_bar").format(link=sc.e_link, p=sc.e_from, q=sc.e_toward,
                                                              d=Tex(_expr_tex(sc.e_distance))))
    elif sc.e_kind == "triangle":
        out.append(strings.get("control.scheme.e_triangle").format(
            link=sc.e_link, p=sc.e_from, q=sc.e_toward, d1=Tex(_expr_tex(sc.e_distances[0])),
            d2=Tex(_expr_tex(sc.e_distances[1]))))
    else:
        out.append(strings.get("control.scheme.e_none").format(p=sc.f_from, s=sc.slider))
    key = "control.scheme.guide_vertical" if abs(sc.guide_angle_deg - 90.0) < ABS_ZERO else "control.scheme.guide_horizontal"
    coord = sc.guide_through[0] if key.endswith("vertical") else sc.guide_through[1]
    out.append(strings.get(key).format(s=sc.slider, x=Tex(_expr_tex(coord))))
    return out


def introduction_paragraphs(project, left_out) -> list:
    """Paragraphs about this task, from the strings catalogue (``intro.*``)."""
    from .render import Tex
    from .numbers import num
    task = project.task
    # a control work's own words where a course project has its own (control.overrides)
    strings = Strings(_lang(project), overlay="control.overrides" if task.document.kind == "control-work" else None)
    out = []
    if task.mechanism is not None:
        mech = task.mechanism
        name = _in_sentence(mech.name) if mech.name else strings.get("intro.default_name")
        text = strings.get("intro.object").format(
            name=name, link=mech.drive.link, omega=Tex(num(abs(mech.drive.omega))),
            sense=strings.get("intro.ccw" if mech.drive.omega > 0 else "intro.cw"))
        st = project.strokes if task.document.kind != "control-work" else None
        if st is not None:
            key = "intro.output_slider" if st.output.kind == "slider" else "intro.output_rocker"
            text = Tex(text + " ") + strings.get(key).format(
                link=st.output.link, work=Tex(num(st.working_deg)), idle=Tex(num(st.idle_deg)))
            text = Tex(text + " ") + _machine(project, strings)
        out.append(text)
    out += _work_paragraphs(project, strings)
    if left_out:
        # the titles in quotes: «не приводятся: «Проектирование зубчатых передач».», not a capital
        # letter in the middle of the sentence (issue 12)
        q0, q1 = strings.get("title.quote_open"), strings.get("title.quote_close")
        out.append(strings.get("sections.left_out") + Tex(" ")
                   + Tex(", ").join(Tex(q0 + t + q1) for t in left_out) + Tex("."))
    return out


def _machine(project, strings):
    """What this machine does: the motion it makes and the resistance it works against."""
    from .render import Tex
    from .numbers import num
    st, mech = project.strokes, project.task.mechanism
    slider = st.output.kind == "slider"
    H = st.stroke * 1000.0 if slider else math.degrees(st.stroke)
    text = strings.get("marks.intro.machine_slider" if slider else "marks.intro.machine_rocker").format(
        crank=mech.drive.link, link=st.output.link, H=Tex(num(abs(H))))
    for ld in mech.loads:
        if ld.kind == "resistance" and ld.link == st.output.link:
            if ld.force is not None:
                text = Tex(text + " ") + strings.get("marks.intro.load_force").format(F=Tex(num(ld.force)))
            elif ld.moment is not None:
                text = Tex(text + " ") + strings.get("marks.intro.load_moment").format(M=Tex(num(ld.moment)))
            break
    return text


def _work_paragraphs(project, strings) -> list:
    """What the project does (by the sections the task feeds), citing the references."""
    from .render import Tex
    task = project.task
    keys = []
    if task.mechanism is not None:
        keys += ["parts_linkage", "parts_kinetostatics"]
        if task.dynamics is not None:
            keys.append("parts_dynamics")
    if task.gears is not None:
        keys.append("parts_gears")
    if task.planetary is not None:
        keys.append("parts_planetary")
    if not keys:
        return []
    names = [strings.get(f"marks.intro.{k}") for k in keys]
    parts = names[0] if len(names) == 1 else Tex(", ").join(names[:-1]) + strings.get("marks.intro.and") + names[-1]
    return [strings.get("marks.intro.work").format(parts=parts), strings.get("marks.intro.layout").format()]


def _in_sentence(name: str) -> str:
    """A name inside a sentence: its first letter lowered unless the first word is an abbreviation (КШМ)."""
    first = name.split(" ", 1)[0]
    if len(first) > 1 and first[1:2].isupper():
        return name
    return name[:1].lower() + name[1:]
