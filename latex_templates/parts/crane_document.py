"""The crane note as a whole (``[document] kind = "crane"`` or a task with ``[crane]``): the
NoteBuilder with the crane's strings overlay, title, assignment, introduction, conclusions. The
sections come from ``compose.CRANE_SECTIONS`` (parts ``crane_hoist``, ``crane_trolley``)."""
from __future__ import annotations

from markupsafe import Markup

from ..note import NoteBuilder, Section
from .crane_common import strings_of

#: The designation of the crane note (ГОСТ 2.201 style, course code ГПМ).
DESIGNATION = "ГПМ.КП.00.00.000 ПЗ"


def assignment_section(project) -> Section:
    """The assignment: the data of the task and the chosen catalogue items as two tables."""
    s = strings_of(project)
    cr = project.task.crane
    h, t = cr.hoist, cr.trolley
    data = [
        ("$Q$", "грузоподъёмность", h.capacity_t, "т"),
        ("$m_{п}$", "масса крюковой подвески", h.hook_mass_kg, "кг"),
        ("$H$", "высота подъёма", h.lifting_height_m, "м"),
        ("$v_{п}$", "скорость подъёма", h.lifting_speed_m_min, "м/мин"),
        ("$v_{т}$", "скорость передвижения тележки", t.speed_m_min, "м/мин"),
        ("$m_{т}$", "масса тележки", t.mass_t, "т"),
        ("$L$", "пролёт крана", cr.span_m, "м"),
        ("$b_{т}$", "база тележки", t.wheel_base_m, "м"),
        ("$k_{т}$", "колея тележки", t.gauge_m, "м"),
        ("$u_{п}$", "кратность полиспаста", h.polyspast.ratio, ""),
    ]
    items = [("канат", h.rope.designation), ("двигатель подъёма", h.motor.designation),
             ("редуктор подъёма", h.reducer.designation), ("тормоз подъёма", h.brake.designation)]
    items += [("муфта подъёма", c.designation) for c in h.couplings]
    items += [("колесо тележки", t.wheel.designation), ("рельс", t.rail.designation),
              ("двигатель тележки", t.motor.designation), ("редуктор тележки", t.reducer.designation),
              ("тормоз тележки", t.brake.designation)]
    items += [("муфта тележки", c.designation) for c in t.couplings]
    ctx = {"crane": cr, "data": [(Markup(a), b, c, d) for a, b, c, d in data], "items": items,
           "rules": project.crane.rules}
    return Section(key="assignment", title=s.get("headings.assignment"), template="crane_assignment.tex.j2",
                   context=ctx)


def note_builder(project) -> NoteBuilder:
    from ..compose import compose
    s = strings_of(project)
    sections, _ = compose(project, s)
    intro = []
    note = NoteBuilder(project.task.document, designation=DESIGNATION, introduction=intro,
                       conclusions=[c for sec in sections for c in sec.conclusions],
                       assignment=assignment_section(project), strings=s)
    for sec in sections:
        note.add_section(sec.section)
    return note
