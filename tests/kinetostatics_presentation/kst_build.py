"""Helpers of the kinetostatics presentation tests: the note with section 2 alone (other sections are
other people's work in progress and would only slow the tests down)."""
from __future__ import annotations

from pathlib import Path

from latex_templates import NoteBuilder
from latex_templates.compose import compose
from latex_templates.render import Strings
from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
#: The course-project examples (the control work has no reactions and no sheet 2: tests/control).
EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml") if p.parent.name != "control-work")


def project_of(example: str) -> Project:
    return Project(load_task(ROOT / "examples" / example / "task.toml"))


def section_note(project: Project) -> NoteBuilder:
    sections, _ = compose(project, Strings(project.task.document.language or "ru"), only=("kinetostatics",))
    note = NoteBuilder(project.task.document, designation="ТММ.КП.00.00.000 ПЗ",
                       conclusions=[c for s in sections for c in s.conclusions])
    for s in sections:
        note.add_section(s.section)
    return note
