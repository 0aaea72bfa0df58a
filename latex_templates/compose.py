"""The sections of the note, each made of parts (``latex_templates.parts.<name>``), in order.

A section whose parts are all unavailable (the task leaves that section out) is left out, and the
introduction says so. A part module that does not exist yet is simply skipped.
"""
from __future__ import annotations

from dataclasses import dataclass
from types import ModuleType

from reportgen.modules import optional_module

from .note import Section
from .parts import PartContent

#: (section key, part modules) in the order of the note; the titles are strings ``sections.<key>``.
SECTIONS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("linkage", ("structure", "kinematics")),
    ("kinetostatics", ("kinetostatics",)),
    ("dynamics", ("dynamics",)),
    ("gears", ("gear_pair", "planetary")),
)


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
    for key, parts in SECTIONS:
        title = strings.get(f"sections.{key}")
        if only is not None and key not in only:
            continue
        contents: list[tuple[str, PartContent]] = []
        for name in parts:
            mod = part_module(name)
            if mod is None or not mod.available(project):
                continue
            contents.append((name, mod.content(project)))
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
