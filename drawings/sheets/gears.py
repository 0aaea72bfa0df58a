"""Sheet 4 «Синтез зубчатых механизмов»: on the left the meshing picture of the [gears] pair at a
ГОСТ 2.302 scale with the specific-sliding diagram under it; on the right the planetary reducer of
[planetary] in two views with Kutzbach's velocity triangle, the angular-velocity plan and a table of
the tooth numbers. A half is left out when the task lacks its section; neither runs the linkage
solver."""
from __future__ import annotations

from drawings import Sheet
from drawings.layout import Rect
from ..words import decimal_mark, designation, tr

NEEDS = ("gears", "planetary", "scenes")
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
    """Layout: the meshing picture takes the left of the sheet from the bottom frame to under the
    designation's stamp; right of it the reducer (front view, side scheme with the velocity
    triangle and the angular-velocity plan, table of tooth numbers) on top, the specific-sliding
    diagram and the pair's table (above the title block) below. Without a reducer the diagram
    and the table take the right side; without a gear pair the reducer takes the whole sheet."""
    from drawings.scenes.meshing import VIEW_H, VIEW_W, draw_meshing, draw_sliding
    from drawings.scenes.planetary_dxf import draw_reducer

    task = project.task
    sheet = Sheet.a1(task.document, title=sheet_title(), code=designation(task.document, number), number=number,
                     count=count)
    fr = sheet.frame
    tb = sheet.title_rect
    has_reducer = task.planetary is not None and task.planetary.module is not None
    rest = Rect(fr.x0 + 5, fr.y0 + 5, fr.x1 - 5, fr.y1 - 8)
    if task.gears is not None:
        pair = project.gears
        mesh_rect = Rect(fr.x0 + 5, fr.y0 + 5, fr.x0 + 5 + VIEW_W, fr.y0 + 5 + VIEW_H)
        scale = draw_meshing(sheet, pair, project.scenes.meshing, mesh_rect)
        sheet.set_scale(scale.text(decimal_mark()))                    # the meshing, the main view
        rest = Rect(mesh_rect.x1 + 10, fr.y0 + 5, fr.x1 - 5, fr.y1 - 8)
        table_h = PAIR_ROW_MM * (len(pair_rows(pair)) + 1) + 12.0
        table_rect = Rect(rest.x1 - PAIR_TABLE_W, tb.y1 + 8, rest.x1, tb.y1 + 8 + table_h)
        if has_reducer:            # under the reducer, left of the title block
            slide_rect = Rect(rest.x0, rest.y0, min(table_rect.x0, tb.x0) - 10, rest.y0 + 185.0)
        else:                      # above the table, the width of the right side
            slide_rect = Rect(rest.x0, table_rect.y1 + 12, rest.x1, min(rest.y1, table_rect.y1 + 12 + 320))
        draw_sliding(sheet, pair, slide_rect, scale.factor)
        draw_pair_table(sheet, pair, table_rect)
        rest = Rect(rest.x0, max(slide_rect.y1, table_rect.y1) + 8, rest.x1, rest.y1)
    if has_reducer:
        stage = project.planetary
        region = rest if task.gears is not None else Rect(rest.x0, tb.y1 + 8, rest.x1,
                                                           sheet.extra_rect.y0 - 4)
        draw_reducer(sheet, stage, region)
    # «Масштаб»: the main view's scale (the meshing, else the reducer); each view's scale is in its title
    return sheet


#: Width of the gear pair's table: the name, gear 1, gear 2 (mm).
PAIR_TABLE_COLS = (75.0, 24.0, 24.0)
PAIR_TABLE_W = sum(PAIR_TABLE_COLS)
PAIR_ROW_MM = 7.0


def _word(key: str) -> str:
    """A word of the pair's table in the sheet's language (``marks.sheet4`` of the catalogue)."""
    from drawings.words import tr
    return tr(f"marks.sheet4.{key}")


def pair_rows(pair) -> list[tuple[str, str, str]]:
    """The parameters of the pair as the sheet tabulates them, with the designations of the meshing
    picture (r, rb, rw, ra, rf, s, p, αw): (name, gear 1, gear 2 — empty for a common one)."""
    from drawings.primitives import format_number as f
    g = pair.geometry
    w = _word
    return [
        (w("m"), f(g.m, 3), ""),
        (w("z"), str(g.z1), str(g.z2)),
        (w("x"), f(g.x1, 3), f(g.x2, 3)),
        (w("r"), f(g.d1 / 2, 3), f(g.d2 / 2, 3)),
        (w("rb"), f(g.db1 / 2, 3), f(g.db2 / 2, 3)),
        (w("rw"), f(g.dw1 / 2, 3), f(g.dw2 / 2, 3)),
        (w("ra"), f(g.da1 / 2, 3), f(g.da2 / 2, 3)),
        (w("rf"), f(g.df1 / 2, 3), f(g.df2 / 2, 3)),
        (w("s"), f(g.s1, 3), f(g.s2, 3)),
        (w("sa"), f(g.sa1, 3), f(g.sa2, 3)),
        (w("p"), f(g.p, 3), ""),
        (w("pb"), f(g.pb, 3), ""),
        (w("alpha_w"), f(g.alpha_w_deg, 3), ""),
        (w("aw"), f(g.aw, 3), ""),
        (w("eps"), f(g.eps_alpha, 3), ""),
    ]


def draw_pair_table(sheet, pair, rect) -> None:
    """The table of the pair's parameters (ГОСТ 2.403 asks for one on a gear drawing): a header
    row «Параметр | 1 | 2», then :func:`pair_rows`, 7 mm rows, from the top of ``rect``."""
    from drawings.primitives import Transform
    view = sheet.place_view("pair table", rect, Transform(1.0, (0.0, 0.0), (rect.x0, rect.y0)))
    rows = [(_word("param"), _word("gear1"), _word("gear2"))] + pair_rows(pair)
    top = rect.height - 10.0
    view.text_mm((rect.x0 + rect.width / 2, rect.y1 - 7.0), _word("title"), 5.0, "bottom-center")
    n = len(rows)
    xs = [0.0]
    for w in PAIR_TABLE_COLS:
        xs.append(xs[-1] + w)
    for i in range(n + 1):
        view.line((0.0, top - PAIR_ROW_MM * i), (xs[-1], top - PAIR_ROW_MM * i),
                  "contour" if i in (0, 1, n) else "thin")
    for x in xs:
        view.line((x, top), (x, top - PAIR_ROW_MM * n), "contour")
    for i, row in enumerate(rows):
        y = top - PAIR_ROW_MM * i - PAIR_ROW_MM / 2
        view.text((1.5, y), row[0], 2.5, "middle-left")
        for c in (1, 2):
            if row[c]:
                view.text(((xs[c] + xs[c + 1]) / 2, y), row[c], 3.5 if i else 2.5, "center")
