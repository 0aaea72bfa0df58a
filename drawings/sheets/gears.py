"""Sheet 4 «Синтез зубчатых механизмов»: on the left the meshing picture of the [gears] pair at a
ГОСТ 2.302 scale with the specific-sliding diagram under it; on the right the planetary reducer of
[planetary] in two views with Kutzbach's velocity triangle, the angular-velocity plan and a table of
the tooth numbers. A half is left out when the task lacks its section; neither runs the linkage
solver."""
from __future__ import annotations

from drawings import Sheet
from drawings.layout import Rect

NEEDS = ("gears", "planetary")
TITLE = "Синтез зубчатых механизмов"


def available(project) -> bool:
    return project.task.gears is not None or (
        project.task.planetary is not None and project.task.planetary.module is not None)


def draw(project, number: int, count: int) -> Sheet:
    from drawings.scenes.meshing import draw_meshing, draw_sliding
    from drawings.scenes.planetary import draw_reducer
    from reportgen.gears.meshing import meshing_picture

    task = project.task
    sheet = Sheet.a1(task.document, title=TITLE, code=f"ТММ.КП.00.00.{number:03d}", number=number,
                     count=count)
    fr = sheet.frame
    left = Rect(fr.x0 + 5, fr.y0 + 5, fr.x0 + 5 + 395, fr.y1 - 19)
    right = Rect(left.x1 + 12, fr.y0 + 5, fr.x1 - 5, fr.y1 - 5)
    if task.gears is not None:
        pair = project.gears
        pic = meshing_picture(pair, n_teeth=3)
        mesh_rect = Rect(left.x0, left.y1 - 415, left.x1, left.y1)
        scale = draw_meshing(sheet, pair, pic, mesh_rect)
        sheet.set_scale(scale.label)                                   # the meshing, the main view
        slide_rect = Rect(left.x0, left.y0, left.x1, mesh_rect.y0 - 10)
        draw_sliding(sheet, pair, slide_rect, scale.factor)
    if task.planetary is not None and task.planetary.module is not None:
        stage = project.planetary
        region = right if task.gears is not None else Rect(left.x0, left.y0, right.x1, left.y1)
        draw_reducer(sheet, stage, Rect(region.x0, sheet.title_rect.y1 + 8, region.x1, region.y1))
    # «Масштаб»: the main view's scale (the meshing, else the reducer); each view's scale is in its title
    return sheet
