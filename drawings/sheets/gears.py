"""Sheet 4 «Синтез зубчатых механизмов»: on the left the meshing picture of the [gears] pair at a
ГОСТ 2.302 scale with the specific-sliding diagram under it; on the right the planetary reducer of
[planetary] in two views with Kutzbach's velocity triangle, the angular-velocity plan and a table of
the tooth numbers. A half is left out when the task lacks its section; neither runs the linkage
solver."""
from __future__ import annotations

from drawings import Sheet
from drawings.layout import Rect
from ..words import designation, tr

NEEDS = ("gears", "planetary")
def sheet_title() -> str:
    """The sheet's title in the task's language (title block, graph 1)."""
    return tr("sheets.sk401")


def __getattr__(name: str):
    if name == "TITLE":            # the title in the language being drawn
        return sheet_title()
    raise AttributeError(name)


def available(project) -> bool:
    return project.task.gears is not None or (
        project.task.planetary is not None and project.task.planetary.module is not None)


def draw(project, number: int, count: int) -> Sheet:
    from drawings.scenes.meshing import draw_meshing, draw_sliding
    from drawings.scenes.planetary_dxf import draw_reducer
    from reportgen.gears.meshing import meshing_picture

    task = project.task
    sheet = Sheet.a1(task.document, title=sheet_title(), code=designation(task.document, number), number=number,
                     count=count)
    fr = sheet.frame
    left = Rect(fr.x0 + 5, fr.y0 + 5, fr.x0 + 5 + 395, fr.y1 - 19)
    right = Rect(left.x1 + 12, fr.y0 + 5, fr.x1 - 5, fr.y1 - 5)
    if task.gears is not None:
        pair = project.gears
        pic = meshing_picture(pair, n_teeth=3)
        mesh_rect = Rect(left.x0, left.y1 - 415, left.x1, left.y1)
        scale = draw_meshing(sheet, pair, pic, mesh_rect)
        slide_rect = Rect(left.x0, left.y0, left.x1, mesh_rect.y0 - 10)
        draw_sliding(sheet, pair, slide_rect, scale.factor)
    if task.planetary is not None and task.planetary.module is not None:
        stage = project.planetary
        region = right if task.gears is not None else Rect(left.x0, left.y0, right.x1, left.y1)
        draw_reducer(sheet, stage, Rect(region.x0, sheet.title_rect.y1 + 8, region.x1, region.y1))
    # the views have different scales, each written in its caption: «Масштаб» stays blank (ГОСТ 2.104)
    return sheet
