"""Sheet 1 «Кинематический анализ рычажного механизма» (A1): the mechanism in every analysed
position with the trajectories, the velocity and acceleration plans of the analysed position, the
velocity plans of all positions in small form, the s–v–a diagrams of the output, and a table of
the scales. Every number comes from :class:`reportgen.project.Project` and its result objects."""
from __future__ import annotations

import math


from drawings import style
from drawings.layout import LAYOUT_LIMIT, Rect
from drawings.primitives import Transform, format_number, format_significant
from drawings.sheet import Sheet, View
from drawings.words import decimal_mark
from drawings.scenes import kinematics_diagrams as kd
from drawings.scenes import kinematics_plans as kp
from drawings.scenes import kinematics_scheme as ks
from reportgen.errors import BuildError
from reportgen.diagrams import Diagrams
from reportgen.plans import Plan
from reportgen.project import Project
# the arrangement of this sheet is the core's (it decides the plan of positions' scale from it): the
# names below stay importable from here
from reportgen.scenes.arrangement import (Arrangement, Block, SheetLayout, apart_blocks, arrange,  # noqa: F401
                                          plan_blocks, plan_view_names)
from reportgen.scenes.boxes import GROW_PLANS_MM, PAIR_GAP, SCHEME_PADS_MM, VIEW_GAP  # noqa: F401
from reportgen.scenes.small_plans import small_plans as core_small_plans
from ..words import designation, tr

NEEDS: tuple[str, ...] = ("linkage", "structure", "model", "phi", "strokes", "kinematics", "analysed",
                            "plans", "plan_positions", "plans_by_position", "scenes", "output_diagrams")


def sheet_title() -> str:
    """The sheet's title in the task's language (title block, graph 1)."""
    return tr("sheets.sk101")


def __getattr__(name: str):
    if name == "TITLE":            # the title in the language being drawn
        return sheet_title()
    raise AttributeError(name)

#: The small velocity plans: the crank's vector is at most this long, mm (the core's: it reserves
#: the table of scales for their μv).
from reportgen.scenes.boxes import SMALL_PLAN_MM  # noqa: E402,F401


def available(project: Project) -> bool:
    return project.task.mechanism is not None


def analysed_position(project: Project) -> int:
    """The position the note analyses (the project's stage)."""
    return project.analysed


def diagrams_of(project: Project) -> Diagrams | None:
    """The s–v–a diagrams of the output (the project's stage, the note's)."""
    return project.output_diagrams


def image_keys(project: Project) -> set[str]:
    """Plan letters that are images of mechanism points (not the helper points n…, k…)."""
    return set(project.plans[0].points)


def draw(project: Project, number: int, count: int, *, control: bool = False) -> Sheet:
    """The sheet as the core arranged it (``project.scenes.sheet_layout``): the plan of positions at
    the scale the note prints (``project.scenes.positions``), every view — the small plans at the
    core's μv among them — in the core's rectangle (never another scale). ``control``: the control work's one sheet (:mod:`drawings.sheets.control`):
    the lever instead of the diagrams and the small plans, on A1 or A3 as ``[control_work] sheet``
    says."""
    layout = project.scenes.sheet_layout
    if layout is None:
        if control:
            from . import control as cs
            cs.does_not_fit(project)
        raise BuildError("sheet layout", "the plan of positions, the plans of the plan positions and the other views "
                                         "do not fit in the free field of the sheet at any scale; " + LAYOUT_LIMIT)
    data = project.scenes.scheme_data
    b = ks.bounds(data, project.linkage)
    return draw_at(project, number, count, data, b, layout, control=control)


def draw_at(project: Project, number: int, count: int, data: ks.SchemeData,
            b: tuple[float, float, float, float], layout: SheetLayout, *, control: bool = False) -> Sheet:
    """The sheet with its views in ``layout``'s rectangles (the core's arrangement)."""
    if control:
        from . import control as cs
        sheet = cs.new_sheet(project, number, count)
    else:
        sheet = Sheet.a1(project.task.document, title=sheet_title(), code=designation(project.task.document, number), number=number, count=count)
    k, scale_text = layout.k, layout.scale.text(decimal_mark())
    scheme = place_scheme_view(sheet, b, k, layout.rects["scheme"], layout.scheme_origin)
    ks.draw_scheme(scheme, project, data, scale_text, 1.0 / k)
    sheet.set_scale(scale_text)
    if control:
        cs.place_lever(sheet, project, layout.rects["lever"])
    # the diagrams
    d = None if control else diagrams_of(project)
    if d is not None:
        st = project.strokes
        assert st is not None  # the diagrams are drawn between the extreme positions
        start = math.degrees((d.sign * (st.phi_start - d.phi0)) % (2 * math.pi))
        scene = project.scenes.output_diagrams
        assert scene is not None  # drawn from the same stage
        r = layout.rects["diagrams"]
        view = sheet.place_view("diagrams", r, Transform(1.0, (0.0, 0.0), (r.x0, r.y0)))
        kd.draw_diagrams(view, d, scene, len(project.phi), start, st.working_deg)
    # the plans of every plan position (the note's scales; the analysed one first), the small plans
    # (every position's velocity plan, the core's choice of μv and place), the table of scales
    keys = image_keys(project)
    pairs = dict(project.plans_by_position)   # the note's (the control work on A3: the core's A3 scales)
    plan_views: list[tuple[str, Plan, str]] = []
    for j, (vplan, aplan) in pairs.items():     # the control work's one position: no number (the scheme's title names it)
        names = plan_view_names(j, first=(j == data.analysed))
        plan_views += [(names[0], vplan, tr("control.sheet.vplan_a3") if control else tr("sheets.sk103", i=j)),
                       (names[1], aplan, tr("control.sheet.aplan_a3") if control else tr("sheets.sk104", i=j))]
    small = None if layout.small is None else list(layout.small)
    if "scales" in layout.rects:     # the control work on A3: every view prints its scale under it
        # the core reserved the table for the widest μv of the small plans' sizes: the columns too
        candidates = [scale_rows(1.0 / k, scale_text, pairs, d, list(s), given=control)
                      for s in ([] if control else project.scenes.small_plan_sets)]
        candidates.append(scale_rows(1.0 / k, scale_text, pairs, d, None, given=control))
        r = layout.rects["scales"]
        table = sheet.place_view("scales", r, Transform(1.0, (0.0, 0.0), (r.x0, r.y0)))
        fill_scales_table(table, scale_rows(1.0 / k, scale_text, pairs, d, small, given=control),
                          _table_widths(candidates, table.rect.width))
    for name, plan, title in plan_views:
        kp.place_plan_view(sheet, name, plan, keys, title, layout.rects[name])
    if small is not None:
        kp.place_small_plans(sheet, small, keys, layout.small_cols, layout.rects["plans_all"],
                             small_plan_letters(project))
    return sheet


def place_scheme_view(sheet: Sheet, b: tuple[float, float, float, float], k: float, rect: Rect,
                      origin: tuple[float, float] = SCHEME_PADS_MM[:2]) -> View:
    """The scheme's view in the core's ``rect``: model bounds ``b`` at ``k`` mm per metre, their
    lower-left corner ``origin`` from the view's (the core's ``SheetLayout.scheme_origin``)."""
    left, bottom = origin
    return sheet.place_view("scheme", rect, Transform(k, (b[0], b[1]), (rect.x0 + left, rect.y0 + bottom)))


def small_plan_letters(project: Project) -> set[str]:
    """The letters of the small velocity plans: the pole and the images of the moving points (a, b,
    c, …; a₃ of a slotted link) — the points a teacher reads on them. The images of the fixed
    points are the pole itself, and the centres of mass are left to the analysed positions' plans
    (their velocities in every position: the note's table «Скорости центров масс»): a small plan
    lettered with every s_k too is a pile of letters (issue 12, the shaper's 12 plans)."""
    plan = project.plans[0]
    fixed = {g.lower() for g in project.linkage.ground}
    centres = {f"s{k}" for k in project.kinematics.coms}
    return {k for k in plan.points if k == kp.pole(plan) or (k not in fixed and k not in centres)}


def small_plans(project: Project, crank_mm: float) -> list[Plan]:
    """Velocity plans of every position at one round scale, the crank's vector ≤ ``crank_mm`` (the
    core's, :func:`reportgen.scenes.small_plans.small_plans`)."""
    return list(core_small_plans(project, crank_mm))


def _lower_title(title: str) -> str:
    """«Диаграмма скорости» → «диаграмма скорости», «Displacement diagram» → «displacement diagram»
    (a row of the table names the diagram: its title's first letter in lower case)."""
    return title[:1].lower() + title[1:]


def _positions_text(positions: list[int]) -> str:
    return ", ".join(str(j) for j in sorted(positions))


def scale_rows(mu_l: float, scale_text: str, pairs: dict[int, tuple[Plan, Plan]], d: Diagrams | None,
               small: list[Plan] | None = None, given: bool = False) -> list[tuple[str, str, str]]:
    """The table «Масштабы»: one row per distinct scale, named by what it draws — the scheme, the
    velocity and acceleration plans of the plan positions (positions sharing a μ share a row; the
    control work's one position, ``given``, unnumbered), the small velocity plans, the diagrams'
    axes and graphs and the pole distances."""
    rows = [("μl", tr("sheets.sk109", scale_text=scale_text), tr("sheets.sk110", v1=format_significant(mu_l, 4)))]
    for symbol, which, one, many, value in (("μv", 0, "sheet1.scales_vplan", "sheet1.scales_vplans", "sheets.sk112"),
                                            ("μa", 1, "sheet1.scales_aplan", "sheet1.scales_aplans", "sheets.sk114")):
        by_mu: dict[str, list[int]] = {}
        for j, plans in pairs.items():
            by_mu.setdefault(format_significant(plans[which].scale, 4), []).append(j)
        for mu, positions in by_mu.items():
            name = (tr(f"sheet1.scales_{'va'[which]}plan_given") if given
                    else tr(one if len(positions) == 1 else many, i=_positions_text(positions)))
            rows.append((symbol, name, tr(value, v1=mu)))
        if which == 0 and small:
            rows.append(("μv", tr("sheet1.scales_small", last=len(small) - 1),
                         tr(value, v1=format_significant(small[0].scale, 4))))
    if d is not None:
        nm = kd.names(d)
        rows += [("μφ", tr("sheets.sk115"), tr("sheets.sk116", v1=format_significant(d.mu_phi, 4))),
                 ("μt", tr("sheets.sk117"), tr("sheets.sk118", v1=format_significant(d.mu_t, 4))),
                 *[(sym, _lower_title(title), f"{format_significant(mu, 4)} {unit}")
                   for sym, title, mu, unit in zip(nm.symbols, nm.titles, (d.mu_s, d.mu_v, d.mu_a),
                                                   (nm.mu_s, nm.mu_v, nm.mu_a))],
                 ("H1", tr("sheets.sk119"), tr("sheets.sk120", v1=format_number(d.H1, 1))),
                 ("H2", tr("sheets.sk121"), tr("sheets.sk122", v1=format_number(d.H2, 1)))]
    return rows


#: Height of a row of the table of scales, and the strip above it for its title, mm (the core's).
from reportgen.scenes.boxes import TABLE_ROW_MM, TABLE_TITLE_MM  # noqa: E402


def _table_header() -> tuple[str, str, str]:
    return (tr("sheets.sk105"), tr("sheets.sk106"), tr("sheets.sk107"))


def _table_widths(candidates: list[list[tuple[str, str, str]]], width: float | None = None) -> tuple[float, ...]:
    """The columns' widths for the longest texts of ``candidates``; with ``width`` (the view the core
    reserved from the same lines, ``reportgen.scenes.arrangement.scales_table_width``) the name column takes the rest of it."""
    every = [_table_header(), *[r for rows in candidates for r in rows]]
    widths = tuple(max(style.text_width(r[c], 3.5) for r in every) + 5.0 for c in range(3))
    if width is None or width <= sum(widths):
        return widths
    return widths[0], width - widths[0] - widths[2], widths[2]


def fill_scales_table(view: View, rows: list[tuple[str, str, str]], widths: tuple[float, ...]) -> None:
    """Draw the table «Масштабы» with ``rows`` (columns ``widths``) at the top of its reserved view."""
    w = sum(widths)
    h = view.rect.height
    row_h = TABLE_ROW_MM
    view.title(tr("sheets.sk108"))
    top = h - TABLE_TITLE_MM                     # view coordinates: mm from its lower-left corner
    x0 = 0.0
    table = Rect(x0, top - row_h * (len(rows) + 1), x0 + w, top)
    for r in range(len(rows) + 2):
        y = top - r * row_h
        view.line((x0, y), (x0 + w, y), "contour" if r in (0, 1, len(rows) + 1) else "thin")
    x = x0
    for wi in (0.0, *widths):
        x += wi
        view.line((x, table.y0), (x, table.y1), "contour")
    for r, row in enumerate([_table_header(), *rows]):
        y = top - r * row_h - row_h / 2
        x = x0
        for wi, text in zip(widths, row):
            view.text((x + 2.0, y), text, 3.5, "middle-left")
            x += wi
