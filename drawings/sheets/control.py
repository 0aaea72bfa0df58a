"""The control work's one sheet (``[document] kind = "control-work"``): the mechanism at φ to scale,
its velocity and acceleration plans and Zhukovsky's lever, on A1 (as the course sheets) or A3
(``[control_work] sheet``). It is sheet 1's drawing with the lever of sheet 2 in place of the
diagrams and the small plans — the same scenes, no second copy of a plan or a lever."""
from __future__ import annotations

from drawings.sheet import A1, A3, Sheet, TitleBlock
from reportgen.project import Project

from ..words import tr

NEEDS: tuple[str, ...] = ("linkage", "structure", "model", "phi", "strokes", "kinematics", "analysed", "plans",
                            "plan_positions", "plans_by_position", "scenes", "kinetostatics")   # sheet 1's drawing
#: Every scale of this sheet is the note's, chosen in the core from the box this sheet gives each
#: construction (``reportgen.scenes.boxes.SceneBoxes``: ``scheme_for``, ``plan_mm_for``,
#: ``lever_for`` — A1 or A3), so the note prints the sheet's.
#: The scheme's view is at least as wide as its title (5 mm letters): «Механизм в заданном положении,
#: φ1 = …°» on A1, «Механизм, φ1 = …°» on A3.
SCHEME_MIN_WIDTH_MM = {"A1": 125.0, "A3": 65.0}


def available(project: Project) -> bool:
    return project.task.mechanism is not None and project.task.document.kind == "control-work"


def new_sheet(project: Project, number: int, count: int) -> Sheet:
    cw = project.task.control_work
    fmt = A3 if cw is not None and cw.sheet == "A3" else A1
    return Sheet(fmt, TitleBlock.from_document(project.task.document, title=tr("control.sheet.title"), code=project.task.document.sheet_code(number),
                                               number=number, count=count, scale="", letter=""))


def is_a3(project: Project) -> bool:
    cw = project.task.control_work
    return cw is not None and cw.sheet == "A3"


def place_lever(sheet: Sheet, project: Project) -> None:
    from .kinetostatics import lever_panel_of
    lever_panel_of(project).place(sheet, "top-right")


def draw(project: Project, number: int, count: int) -> Sheet:
    from . import kinematics
    return kinematics.draw(project, number, count, control=True)
