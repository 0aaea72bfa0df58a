"""The assignment (задание) of the note from the task file: its data as tables and the scheme, and
the introduction's paragraphs about this mechanism."""
from __future__ import annotations

import math

import numpy as np

from .note import Section
from .render import Strings


def _lang(project) -> str:
    return project.task.document.language or "ru"


def assignment_section(project) -> Section:
    task = project.task
    ctx: dict = {"mech": None, "gears": task.gears, "planetary": task.planetary, "dynamics": task.dynamics,
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
                       "n_rpm": abs(mech.drive.omega) * 30 / math.pi}
    return Section(key="assignment", title=strings.get("headings.assignment"), template="assignment.tex.j2",
                   context=ctx, figures=figures)


def introduction_paragraphs(project, left_out) -> list:
    """Paragraphs about this task, from the strings catalogue (``intro.*``)."""
    from .render import Tex
    from .numbers import num
    strings = Strings(_lang(project))
    task = project.task
    out = []
    if task.mechanism is not None:
        mech = task.mechanism
        name = _in_sentence(mech.name) if mech.name else strings.get("intro.default_name")
        text = strings.get("intro.object").format(
            name=name, link=mech.drive.link, omega=Tex(num(abs(mech.drive.omega))),
            sense=strings.get("intro.ccw" if mech.drive.omega > 0 else "intro.cw"))
        st = project.strokes
        if st is not None:
            key = "intro.output_slider" if st.output.kind == "slider" else "intro.output_rocker"
            text = Tex(text + " ") + strings.get(key).format(
                link=st.output.link, work=Tex(num(st.working_deg)), idle=Tex(num(st.idle_deg)))
        out.append(text)
    if left_out:
        out.append(strings.get("sections.left_out") + Tex(" ") + Tex("; ").join(left_out) + Tex("."))
    return out


def _in_sentence(name: str) -> str:
    """A name inside a sentence: its first letter lowered unless the first word is an abbreviation (КШМ)."""
    first = name.split(" ", 1)[0]
    if len(first) > 1 and first[1:2].isupper():
        return name
    return name[:1].lower() + name[1:]
