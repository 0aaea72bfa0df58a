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
def _russian(path) -> bool:
    """The examples written in Russian (these tests read Russian text; tests/lang covers uk and en)."""
    import tomllib
    return tomllib.loads(path.read_text(encoding="utf-8")).get("document", {}).get("language", "ru") == "ru"


#: Russian course-project examples with a linkage (examples/crane-hoist is another kind of document,
#: docs/crane.md; the control work has no reactions and no sheet 2: tests/control).
EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml")
                  if _russian(p) and "\n[mechanism]" in "\n" + p.read_text(encoding="utf-8")
                  and p.parent.name != "control-work")


def project_of(example: str) -> Project:
    return Project(load_task(ROOT / "examples" / example / "task.toml"))


def section_note(project: Project) -> NoteBuilder:
    sections, _ = compose(project, Strings(project.task.document.language or "ru"), only=("kinetostatics",))
    note = NoteBuilder(project.task.document, designation="ТММ.КП.00.00.000 ПЗ",
                       conclusions=[c for s in sections for c in s.conclusions])
    for s in sections:
        note.add_section(s.section)
    return note
