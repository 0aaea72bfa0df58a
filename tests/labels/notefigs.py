"""The note's figures of a project, as the build makes them (the sections its kind of document has,
the assignment's scheme), without writing the note."""
from __future__ import annotations


def note_figures(project) -> dict:
    """Every matplotlib figure of the note, by «section:name»."""
    from latex_templates.assignment import assignment_section
    from latex_templates.compose import compose
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings

    if getattr(project.task, "kind", "") == "crane":
        from latex_templates.parts.crane_document import strings_of
        strings = strings_of(project)
    else:
        strings = Strings(project.task.document.language or "ru")
    out = {}
    with active_strings(strings):
        sections, _ = compose(project, strings)
        for s in sections:
            for k, fig in s.section.figures.items():
                out[f"{s.section.key}:{k}"] = fig
        for k, fig in assignment_section(project).figures.items():
            out[f"assignment:{k}"] = fig
    return {k: f for k, f in out.items() if hasattr(f, "savefig")}



#: The groups the checks are reported by, and which figures belong to each (by name prefix).
GROUPS: dict[str, tuple[str, ...]] = {
    "schemes": ("linkage:structure_", "assignment:"),
    "plans": ("linkage:kin_",),
    "kinetostatics": ("kinetostatics:",),
    "dynamics": ("dynamics:",),
    "gears": ("gears:",),
}


def group_of(key: str) -> str:
    """The group of a figure «section:name» (the crane's and any other: «other»)."""
    return next((g for g, prefixes in GROUPS.items() if key.startswith(prefixes)), "other")

