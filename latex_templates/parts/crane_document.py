"""The crane note as a whole (``[document] kind = "crane"`` or a task with ``[crane]``): the
NoteBuilder with the crane's strings overlay, title, assignment, introduction, conclusions. The
sections come from ``compose.CRANE_SECTIONS`` (parts ``crane_hoist``, ``crane_trolley``)."""
from __future__ import annotations

from markupsafe import Markup

from reportgen.crane import crane_code

from ..note import NoteBuilder, Section
from .crane_common import fmt, strings_of, symbol_in



def assignment_section(project) -> Section:
    """The assignment: the data of the task and the chosen catalogue items as two tables."""
    s = strings_of(project)
    cr = project.task.crane
    h, t = cr.hoist, cr.trolley
    words = s.get("crane.assignment")
    # (symbol, its quantity key in crane_symbols, words key, value, unit)
    data = [
        ("Q", "Q", "capacity", h.capacity_t, "т"),
        ("m_{\\text{п}}", "m_h", "hook_mass", h.hook_mass_kg, "кг"),
        ("H", "H", "height", h.lifting_height_m, "м"),
        ("v_{\\text{п}}", "hoist.v", "lifting_speed", h.lifting_speed_m_min, "м/мин"),
        ("v_{\\text{т}}", "trolley.v", "trolley_speed", t.speed_m_min, "м/мин"),
        ("m_{\\text{т}}", "m_t", "trolley_mass", t.mass_t, "т"),
        ("L", "L", "span", cr.span_m, "м"),
        ("b_{\\text{т}}", "b_t", "wheel_base", t.wheel_base_m, "м"),
        ("k_{\\text{т}}", "k_t", "gauge", t.gauge_m, "м"),
        ("u_{\\text{п}}", "u_p", "ratio", h.polyspast.ratio, ""),
    ]
    rows = [(Markup("$" + symbol_in(s, *_split(qkey), sym) + "$"), getattr(words, key), value,
             Markup(s.math_word(unit)) if unit else unit)
            for sym, qkey, key, value, unit in data]
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
    ctx = {"crane": cr, "data": rows, "items": items, "intro": intro,
           "rules": project.crane.rules}
    return Section(key="assignment", title=s.get("headings.assignment"), template="crane_assignment.tex.j2",
                   context=ctx)


def _split(qkey: str) -> tuple[str, str]:
    """``"hoist.v"`` → (mechanism, key); ``"Q"`` → ("", key)."""
    mechanism, _, key = qkey.rpartition(".")
    return mechanism, key


def note_builder(project) -> NoteBuilder:
    from ..compose import compose
    s = strings_of(project)
    sections, _ = compose(project, s)
    intro: list = []
    note = NoteBuilder(project.task.document, designation=crane_code(project.task.document, str(s.get("crane.sheet.default_code")))
                       + str(s.get("designation.note_suffix")), introduction=intro,
                       conclusions=[c for sec in sections for c in sec.conclusions],
                       assignment=assignment_section(project), strings=s,
                       default_title="document_defaults.crane_title")
    for sec in sections:
        note.add_section(sec.section)
    return note
