"""The crane note as a whole (``[document] kind = "crane"`` or a task with ``[crane]``): the
NoteBuilder with the crane's strings overlay, title, assignment, introduction, conclusions. The
sections come from ``compose.CRANE_SECTIONS`` (parts ``crane_hoist``, ``crane_trolley``)."""
from __future__ import annotations

from markupsafe import Markup

from reportgen.crane import crane_code

from ..note import NoteBuilder, Section
from .crane_common import fmt, strings_of



def assignment_section(project) -> Section:
    """The assignment: the data of the task and the chosen catalogue items as two tables."""
    s = strings_of(project)
    cr = project.task.crane
    h, t = cr.hoist, cr.trolley
    words = s.get("crane.assignment")
    data = [
        ("$Q$", "capacity", h.capacity_t, "т"),
        ("$m_{\\text{п}}$", "hook_mass", h.hook_mass_kg, "кг"),
        ("$H$", "height", h.lifting_height_m, "м"),
        ("$v_{\\text{п}}$", "lifting_speed", h.lifting_speed_m_min, "м/мин"),
        ("$v_{\\text{т}}$", "trolley_speed", t.speed_m_min, "м/мин"),
        ("$m_{\\text{т}}$", "trolley_mass", t.mass_t, "т"),
        ("$L$", "span", cr.span_m, "м"),
        ("$b_{\\text{т}}$", "wheel_base", t.wheel_base_m, "м"),
        ("$k_{\\text{т}}$", "gauge", t.gauge_m, "м"),
        ("$u_{\\text{п}}$", "ratio", h.polyspast.ratio, ""),
    ]
    data = [(Markup(sym), getattr(words, key), value, unit) for sym, key, value, unit in data]
    items = [("rope", h.rope.designation), ("hoist_motor", h.motor.designation),
             ("hoist_reducer", h.reducer.designation), ("hoist_brake", h.brake.designation)]
    items += [("hoist_coupling", c.designation) for c in h.couplings]
    items += [("wheel", t.wheel.designation), ("rail", t.rail.designation),
              ("trolley_motor", t.motor.designation), ("trolley_reducer", t.reducer.designation),
              ("trolley_brake", t.brake.designation)]
    items += [("trolley_coupling", c.designation) for c in t.couplings]
    items = [(getattr(words, key), name) for key, name in items]
    classes = (fmt(s.get("crane.assignment_text.classes"), use=cr.use_class, load=cr.load_class or "—")
               if cr.use_class else Markup(""))
    intro = fmt(s.get("crane.assignment_text.intro"), group=cr.group, classes=classes, g=cr.g)
    ctx = {"crane": cr, "data": data, "items": items, "intro": intro,
           "rules": project.crane.rules}
    return Section(key="assignment", title=s.get("headings.assignment"), template="crane_assignment.tex.j2",
                   context=ctx)


def note_builder(project) -> NoteBuilder:
    from ..compose import compose
    s = strings_of(project)
    sections, _ = compose(project, s)
    intro: list = []
    note = NoteBuilder(project.task.document, designation=f"{crane_code(project.task.document)}.000 ПЗ", introduction=intro,
                       conclusions=[c for sec in sections for c in sec.conclusions],
                       assignment=assignment_section(project), strings=s)
    for sec in sections:
        note.add_section(sec.section)
    return note
