"""The sections of the note, each made of parts (``latex_templates.parts.<name>``), in order.

A section whose parts are all unavailable (the task leaves that section out) is left out, and the
introduction says so. A part module that does not exist yet is simply skipped.
"""
from __future__ import annotations

from dataclasses import dataclass
from types import ModuleType
from typing import Any, Callable

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


def compose(project, strings, only: tuple[str, ...] | None = None, *,
            kept: Any = None) -> tuple[list[ComposedSection], list]:
    """Sections with their parts' content; also the titles of the sections left out.

    ``kept`` (the build's cache of sections, ``reportgen.commands.note_cache.KeptSections``): a
    section it keeps for the parts available is taken from it, else made (``kept.section(key,
    title, names, make)``), the parts reading the project through the view it gives
    (``kept.view``: their reads recorded)."""
    out: list[ComposedSection] = []
    left_out: list = []
    kind = getattr(project.task, "kind", "course-project")
    for key, parts in DOCUMENT_SECTIONS.get(kind, SECTIONS):
        title = strings.get(f"sections.{key}")
        if only is not None and key not in only:
            continue
        mods = [(name, mod) for name in parts
                if (mod := part_module(name)) is not None and mod.available(project)]
        if not mods:
            left_out.append(title)
            continue
        view = kept.view if kept is not None else None

        def make(key: str = key, title: str = title, mods: list = mods, view: Any = view) -> ComposedSection:
            return compose_section(project, strings, key, title, mods, view)

        out.append(kept.section(key, title, tuple(n for n, _ in mods), make) if kept is not None else make())
    return out, left_out


def compose_section(project, strings, key: str, title: str, mods: list[tuple[str, ModuleType]],
                    view: Callable[[str, str, ModuleType], Any] | None = None) -> ComposedSection:
    """The section ``key`` of the part modules ``mods`` ((name, module), each available), each
    part reading the project through ``view(key, name, module)`` (default: a :class:`Needs` of the
    stages it declares)."""
    contents: list[tuple[str, PartContent]] = []
    for name, mod in mods:
        needs = view(key, name, mod) if view is not None else Needs(project, mod.NEEDS, f"part {name}")
        with active_strings(strings):
            contents.append((name, mod.content(needs)))
    figures: dict = {}
    for _, pc in contents:
        figures.update(pc.figures)
    ctx = {"parts": [{"name": n, "template": pc.template, "context": pc.context} for n, pc in contents]}
    section = Section(key=key, title=title, template="sections/composite.tex.j2", context=ctx, figures=figures)
    concl = tuple(s for _, pc in contents for s in pc.conclusions)
    return ComposedSection(section, tuple(n for n, _ in contents), concl)
