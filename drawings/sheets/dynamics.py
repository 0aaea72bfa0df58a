"""Sheet 3 «Динамический анализ машинного агрегата» (A1): on the left, one under the other, M_red(φ)
with the steps and the pole, the works A_с and A_дв, ΔE(φ); right of ΔE(φ) the Wittenbauer diagram
with the tangents and KL dimensioned, J_red(φ) turned under it; on the right the flywheel's sketch
and the table of results. Every length is the graphical replica's (``project.dynamics.graphical``),
so KL on the sheet is the KL of results.json."""
from __future__ import annotations

from drawings.layout import Rect
from drawings.scenes import dynamics_diagrams as dd
from drawings.scenes import dynamics_flywheel as df
from drawings.sheet import Sheet
from reportgen.dynamics.hub import hub_of
from reportgen.project import Project
from ..words import designation, tr

NEEDS: tuple[str, ...] = ("kinematics", "strokes", "dynamics", "scenes")
def sheet_title() -> str:
    """The sheet's title in the task's language (title block, graph 1)."""
    return tr("sheets.sk301")


def __getattr__(name: str):
    if name == "TITLE":            # the title in the language being drawn
        return sheet_title()
    raise AttributeError(name)

#: Clearance from the frame and from graph 26 / the title block, mm.
CLEAR_MM = 8.0
#: Height of a row of the results table, mm (as in :func:`dynamics_flywheel.draw_results`).
ROW_MM = 8.0
#: The table of results is at most this wide, mm.
TABLE_MAX_MM = 160.0


def available(project: Project) -> bool:
    return project.task.mechanism is not None and project.task.dynamics is not None


def graph_labels(project: Project) -> list[str]:
    """The names of the graph's positions, as the note's table prints them (the same catalogue
    words: the switching angles and the corners of the resistance law)."""
    from reportgen.scenes.numbering import translated_diagram_labels
    return translated_diagram_labels(project.dynamics, tr)


def draw(project: Project, number: int, count: int) -> Sheet:
    res = project.dynamics
    g = res.graphical
    sheet = Sheet.a1(project.task.document, title=sheet_title(), code=designation(project.task.document, number), number=number, count=count)
    fr = sheet.frame
    labels = graph_labels(project)
    y_top = sheet.extra_rect.y0 - CLEAR_MM
    sc = project.scenes.dynamics
    assert sc is not None                  # available(): the task has [dynamics]
    lay = dd.layout(g, labels, fr.x0 + CLEAR_MM, y_top, fr.y0 + CLEAR_MM, dd.omega_height(sc.omega))
    dd.draw_moment(sheet, lay, g, labels, sc.moment)
    dd.draw_work(sheet, lay, g, labels, sc.work)
    dd.draw_energy(sheet, lay, g, labels, sc.energy)
    _, kl = dd.draw_wittenbauer(sheet, lay, g, labels, sc.wittenbauer)
    dd.draw_inertia(sheet, lay, g, labels, sc.inertia)
    assert lay.omega is not None  # layout() always places the ω graph
    dd.draw_omega(sheet, lay.omega, sc.omega, g)
    # the right column, over the title block: the table of results at the top, the flywheel's sketch
    # under it at the largest ГОСТ scale that fits the rest of the column
    x0, x1 = lay.right + 12.0, fr.x1 - CLEAR_MM
    top = fr.y1 - CLEAR_MM
    rows = df.result_rows(res, kl)
    table_h = 12.0 + ROW_MM * len(rows)
    table_w = min(x1 - x0, TABLE_MAX_MM)
    bottom = sheet.title_rect.y1 + CLEAR_MM
    cx = (x0 + x1) / 2
    df.draw_results(sheet, Rect(cx - table_w / 2, top - table_h, cx + table_w / 2, top), rows)
    top -= table_h + 12.0
    if res.J_flywheel > 0:
        k, stacked = df.sketch_fit(res.flywheel, x1 - x0, top - bottom)
        w, h = df.sketch_size(res.flywheel, k, stacked)
        cy = (top + bottom) / 2 if h <= top - bottom else top - h / 2
        sheet.set_scale(df.scale_text(k))                              # the flywheel's sketch
        df.draw_flywheel(sheet, res.flywheel, Rect(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2), k, stacked,
                         hub_of(res.M_drive, 2000.0 * res.flywheel.radius))
    return sheet
