"""The control work's one sheet (``[document] kind = "control-work"``): the mechanism at φ to scale,
its velocity and acceleration plans and Zhukovsky's lever, on A1 (as the course sheets) or A3
(``[control_work] sheet``). It is sheet 1's drawing with the lever of sheet 2 in place of the
diagrams and the small plans — the same scenes, no second copy of a plan or a lever."""
from __future__ import annotations

from drawings.layout import Rect
from drawings.sheet import A1, A3, Sheet, TitleBlock
from reportgen.errors import InternalError, TaskError
from reportgen.project import Project
from reportgen.tolerances import MM_EPS

from ..words import designation, tr

NEEDS: tuple[str, ...] = ("linkage", "structure", "model", "phi", "strokes", "kinematics", "analysed", "plans",
                            "plan_positions", "plans_by_position", "scenes", "kinetostatics")   # sheet 1's drawing
#: Every scale of this sheet is the note's, chosen in the core from the box this sheet gives each
#: construction (``reportgen.scenes.boxes.SceneBoxes``: ``scheme_for``, ``plan_mm_for``,
#: ``lever_for`` — A1 or A3) and, for the mechanism, from the sheet's whole arrangement
#: (``reportgen.scenes.arrangement``), so the note prints the sheet's.


def available(project: Project) -> bool:
    return project.task.mechanism is not None and project.task.document.kind == "control-work"


def new_sheet(project: Project, number: int, count: int) -> Sheet:
    cw = project.task.control_work
    fmt = A3 if cw is not None and cw.sheet == "A3" else A1
    return Sheet(fmt, TitleBlock.from_document(project.task.document, title=tr("control.sheet.title"), code=designation(project.task.document, number),
                                               number=number, count=count, scale="", letter=""))


def is_a3(project: Project) -> bool:
    cw = project.task.control_work
    return cw is not None and cw.sheet == "A3"


def place_lever(sheet: Sheet, project: Project, rect: Rect) -> None:
    """Zhukovsky's lever in the core's ``rect`` (at least the panel's size: the core sizes it from the
    same scene and the lettering's room of :mod:`reportgen.scenes.boxes`)."""
    from .kinetostatics import lever_panel_of
    panel = lever_panel_of(project)
    if panel.width > rect.width + MM_EPS or panel.height > rect.height + MM_EPS:
        raise InternalError("control sheet", f"the lever's panel ({panel.width:.1f} × {panel.height:.1f} mm) is larger "
                                             f"than the core's view ({rect.width:.1f} × {rect.height:.1f} mm)")
    panel.paint(sheet, rect)


def does_not_fit(project: Project) -> None:
    """Stop: the views of this variant do not fit on its sheet at any scale. On A3: bad input (exit 2)
    naming the key and suggesting A1; on A1 the caller reports a limit of the layout."""
    if is_a3(project):
        raise TaskError("control_work.sheet", "the mechanism, its velocity and acceleration plans and "
                        "Zhukovsky's lever of this variant do not fit on one A3 sheet at any scale",
                        '"A1": an A1 sheet has room for them')


def draw(project: Project, number: int, count: int) -> Sheet:
    from . import kinematics
    return kinematics.draw(project, number, count, control=True)
