"""The sections of the note, each made of parts (``latex_templates.parts.<name>``), in order.

A section whose parts are all unavailable (the task leaves that section out) is left out, and the
introduction says so. A part module that does not exist yet is simply skipped.
"""
from __future__ import annotations

from dataclasses import dataclass
from types import ModuleType

from reportgen.modules import optional_module

from reportgen.project import Needs

from .note import Section
from .parts import PartContent, active_strings

#: (section key, part modules) in the order of the note; the titles are strings ``sections.<key>``.
SECTIONS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("linkage", ("structure", "kinematics")),
    ("kinetostatics", ("kinetostatics",)),
    ("dynamics", ("dynamics",)),
    ("gears", ("gear_pair", "planetary")),
)

#: The crane note (course «Грузоподъёмные машины», docs/crane.md): hoist, then trolley travel.
CRANE_SECTIONS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("hoist", ("crane_hoist",)),
    ("trolley", ("crane_trolley",)),
)


#: The control work (``[document] kind = "control-work"``, manual §7): one position, the plans with the
#: ω/ε table, the loads and Zhukovsky's lever with the power-balance check; no cycle, no reactions.
CONTROL_SECTIONS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("linkage", ("structure", "kinematics")),
    ("kinetostatics", ("kinetostatics",)),
)

#: The section lists of each kind of document ([document] kind, or Task.kind's inference).
DOCUMENT_SECTIONS = {"course-project": SECTIONS, "crane": CRANE_SECTIONS, "control-work": CONTROL_SECTIONS}


@dataclass(frozen=True)
class ComposedSection:
    section: Section
    parts: tuple[str, ...]
    conclusions: tuple[str, ...]


def part_module(name: str) -> ModuleType | None:
    return optional_module(f"latex_templates.parts.{name}")


def compose(project, strings, only: tuple[str, ...] | None = None) -> tuple[list[ComposedSection], list]:
    """Sections with their parts' content; also the titles of the sections left out."""
    out: list[ComposedSection] = []
    left_out: list = []
    kind = getattr(project.task, "kind", "course-project")
    for key, parts in DOCUMENT_SECTIONS.get(kind, SECTIONS):
        title = strings.get(f"sections.{key}")
        if only is not None and key not in only:
            continue
        contents: list[tuple[str, PartContent]] = []
        for name in parts:
            mod = part_module(name)
            if mod is None or not mod.available(project):
                continue
            with active_strings(strings):
                contents.append((name, mod.content(Needs(project, mod.NEEDS, f"part {name}"))))
        if not contents:
            left_out.append(title)
            continue
        figures: dict = {}
        for _, pc in contents:
            figures.update(pc.figures)
        ctx = {"parts": [{"name": n, "template": pc.template, "context": pc.context} for n, pc in contents]}
        section = Section(key=key, title=title, template="sections/composite.tex.j2", context=ctx, figures=figures)
        concl = tuple(s for _, pc in contents for s in pc.conclusions)
        out.append(ComposedSection(section, tuple(n for n, _ in contents), concl))
    return out, left_out
