"""Sheet 1 «Кинематический анализ рычажного механизма» (A1): the mechanism in every analysed
position with the trajectories, the velocity and acceleration plans of the analysed position, the
velocity plans of all positions in small form, the s–v–a diagrams of the output, and a table of
the scales. Every number comes from :class:`reportgen.project.Project` and its result objects."""
from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from drawings import style
from drawings.layout import LAYOUT_LIMIT, Rect, Request, grow, room, spread, try_pack
from drawings.primitives import Transform, format_number, format_significant
from drawings.sheet import Sheet, View
from drawings.scenes import kinematics_diagrams as kd
from drawings.scenes import kinematics_plans as kp
from drawings.scenes import kinematics_scheme as ks
from reportgen.errors import BuildError
from reportgen.diagrams import Diagrams
from reportgen.plans import Plan, build_plans, round_scale
from reportgen.project import Project
from reportgen.tolerances import MM_EPS
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

#: The scheme's view (with its padding) is at most this big, mm (the drawing's own box is
#: ``project.boxes.scheme``, this less ``SCHEME_PADS_MM``).
SCHEME_MAX_MM = (470.0, 400.0)
#: Padding of the scheme around its model bounds: left, bottom, right, top, mm.
SCHEME_PADS_MM = (28.0, 36.0, 28.0, 38.0)
#: The small velocity plans: the crank's vector is at most this long, mm.
SMALL_PLAN_MM = (60.0, 50.0, 40.0, 30.0, 20.0)
#: Gap between views, and between the two plans of a plan position put together (smaller, so that
#: a pair reads as one: the views' own margins keep the drawings ~30 mm apart), mm.
VIEW_GAP, PAIR_GAP = 10.0, 4.0
#: The plans of the analysed position may widen by this much to give their names room, mm.
GROW_PLANS_MM = 40.0


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
    """The sheet at the scale of the plan of positions (``project.scenes.positions``, the largest
    ГОСТ scale that fits the scheme's box); a smaller one only if the other views do not fit. ``control``:
    the control work's one sheet (:mod:`drawings.sheets.control`): the lever instead of the
    diagrams and the small plans, on A1 or A3 as ``[control_work] sheet`` says."""
    i = analysed_position(project)
    data = ks.scheme_data(project, i)
    b = ks.bounds(data, project.linkage)
    failure: BuildError | None = None
    for k, scale_text in project.scenes.positions_scales:
        try:
            return draw_at(project, number, count, data, b, k, scale_text, control=control)
        except BuildError as exc:
            if exc.stage != "sheet layout":
                raise
            failure = exc
    assert failure is not None
    raise failure


def draw_at(project: Project, number: int, count: int, data: ks.SchemeData,
            b: tuple[float, float, float, float], k: float, scale_text: str, *, control: bool = False) -> Sheet:
    if control:
        from . import control as cs
        sheet = cs.new_sheet(project, number, count)
    else:
        sheet = Sheet.a1(project.task.document, title=sheet_title(), code=designation(project.task.document, number), number=number, count=count)
    i = data.analysed
    scheme = add_scheme_view(sheet, b, k, min_width=cs.SCHEME_MIN_WIDTH_MM["A3" if cs.is_a3(project) else "A1"] if control else 0.0)
    ks.draw_scheme(scheme, project, data, scale_text, 1.0 / k)
    sheet.set_scale(scale_text)
    if control:
        cs.place_lever(sheet, project)
    # the diagrams
    d = None if control else diagrams_of(project)
    if d is not None:
        st = project.strokes
        assert st is not None  # the diagrams are drawn between the extreme positions
        start = math.degrees((d.sign * (st.phi_start - d.phi0)) % (2 * math.pi))
        scene = project.scenes.output_diagrams
        assert scene is not None  # drawn from the same stage
        kd.add_diagrams_view(sheet, d, scene, len(project.phi), start, st.working_deg, "top-right")
    # the plans of every plan position (the note's scales; the analysed one first), the table of scales
    keys = image_keys(project)
    pairs = dict(project.plans_by_position)   # the note's (the control work on A3: the core's A3 scales)
    small_cache: dict[float, list[Plan]] = {}

    def small_of(crank_mm: float) -> list[Plan] | None:
        if control:
            return None
        if crank_mm not in small_cache:
            small_cache[crank_mm] = small_plans(project, crank_mm)
        return small_cache[crank_mm]
    plan_views: list[tuple[str, Plan, str]] = []
    for j, (vplan, aplan) in pairs.items():
        names = plan_view_names(j, first=(j == i))
        plan_views += [(names[0], vplan, tr("sheets.sk103", i=j)), (names[1], aplan, tr("sheets.sk104", i=j))]
    # the table's rows name the small plans too, whose μv the arrangement chooses: the table's view
    # is reserved for its most rows first and filled once the small plans are known
    candidates = [scale_rows(1.0 / k, scale_text, pairs, d, small_of(c)) for c in SMALL_PLAN_MM]
    candidates.append(scale_rows(1.0 / k, scale_text, pairs, d, None))
    # the control work on A3: every view prints its scale under it; the field has no room for the table
    table = None if control and cs.is_a3(project) else reserve_scales_table(sheet, candidates)
    arrangement = arrange(sheet, [kp.view_size(pl, title)[:2] for _, pl, title in plan_views], small_of,
                          [(plan_views[2 * m][0], plan_views[2 * m + 1][0]) for m in range(len(plan_views) // 2)])
    if table is not None:
        fill_scales_table(table, scale_rows(1.0 / k, scale_text, pairs, d, arrangement.small),
                          _table_widths(candidates))
    for name, plan, title in plan_views:
        kp.place_plan_view(sheet, name, plan, keys, title, arrangement.rects[name])
    if arrangement.small is not None:
        kp.place_small_plans(sheet, arrangement.small, keys, arrangement.cols, arrangement.rects["plans_all"],
                             small_plan_letters(project))
    return sheet


@dataclass(frozen=True)
class Block:
    """Views placed together: ``parts`` are (name, dx, dy, width, height) from the lower-left
    corner of the block."""
    name: str
    width: float
    height: float
    parts: tuple[tuple[str, float, float, float, float], ...]


@dataclass(frozen=True)
class Arrangement:
    """Where the plans and the small plans go (``rects`` by view name), the small plans drawn
    (None if dropped) in ``cols`` columns."""
    rects: dict[str, Rect]
    small: list[Plan] | None
    cols: int
    room: float


def plan_view_names(position: int, first: bool) -> tuple[str, str]:
    """The views of the plans of a plan position: ``plan_v``/``plan_a`` for the analysed one,
    ``plan_v_<j>``/``plan_a_<j>`` for the others."""
    return ("plan_v", "plan_a") if first else (f"plan_v_{position}", f"plan_a_{position}")


def _pair_names(sizes: list[tuple[float, float]]) -> list[tuple[str, str]]:
    return [plan_view_names(k, k == 0) for k in range(len(sizes) // 2)]


def plan_blocks(sizes: list[tuple[float, float]], names: list[tuple[str, str]] | None = None
                ) -> list[list[Block]]:
    """Ways to put the plans of the plan positions together (``sizes``: velocity, acceleration of
    each position in turn; ``names`` their views). A position's two plans always form one block
    (its pair): side by side (titles and captions on one line) or the acceleration plan under the
    velocity plan, ``PAIR_GAP`` apart. The pairs go into one block (one above the other, or in
    one row) or each into a block of its own; a plan is never put apart from its pair."""
    pairs = [(sizes[2 * k], sizes[2 * k + 1]) for k in range(len(sizes) // 2)]
    names = names or _pair_names(sizes)

    def row(k: int, nv: str, na: str) -> Block:
        (wv, hv), (wa, ha) = pairs[k]
        h = max(hv, ha)
        return Block(f"pair{k}", wv + PAIR_GAP + wa, h, ((nv, 0.0, 0.0, wv, h), (na, wv + PAIR_GAP, 0.0, wa, h)))

    def column(k: int, nv: str, na: str) -> Block:
        (wv, hv), (wa, ha) = pairs[k]
        w = max(wv, wa)
        return Block(f"pair{k}", w, hv + PAIR_GAP + ha, ((nv, 0.0, ha + PAIR_GAP, w, hv), (na, 0.0, 0.0, w, ha)))

    def stacked(blocks: list[Block]) -> Block:         # one above the other, the first on top
        w = max(b.width for b in blocks)
        h = sum(b.height for b in blocks) + VIEW_GAP * (len(blocks) - 1)
        parts, y = [], h
        for b in blocks:
            y -= b.height
            parts += [(n, dx, y + dy, pw, ph) for n, dx, dy, pw, ph in b.parts]
            y -= VIEW_GAP
        return Block("plans", w, h, tuple(parts))

    def in_row(blocks: list[Block]) -> Block:
        h = max(b.height for b in blocks)
        parts, x = [], 0.0
        for b in blocks:
            parts += [(n, x + dx, dy, pw, ph) for n, dx, dy, pw, ph in b.parts]
            x += b.width + VIEW_GAP
        return Block("plans", x - VIEW_GAP, h, tuple(parts))

    rows = [row(k, *names[k]) for k in range(len(pairs))]
    cols = [column(k, *names[k]) for k in range(len(pairs))]
    if len(pairs) == 1:
        return [[Block("plans", rows[0].width, rows[0].height, rows[0].parts)],
                [Block("plans", cols[0].width, cols[0].height, cols[0].parts)]]
    out = [[stacked(rows)], [in_row(cols)], [in_row(rows)]]
    out += [list(choice) for choice in itertools.product(*zip(rows, cols))]
    return out


def apart_blocks(sizes: list[tuple[float, float]], names: list[tuple[str, str]] | None = None) -> list[Block]:
    """Every plan in a block of its own: the last resort of :func:`arrange`, where no way of keeping
    a position's two plans together fits the free field (a small sheet: the control work on A3)."""
    names = names or _pair_names(sizes)
    return [Block(n, *sizes[2 * k + m], ((n, 0.0, 0.0, *sizes[2 * k + m]),))
            for k in range(len(sizes) // 2) for m, n in enumerate(names[k])]


def _trials(blocks: list[Block]) -> list[list[tuple[Block, str]]]:
    """Orders and preferred corners to try for ``blocks`` (the first block is the plans)."""
    corners = ("top-left", "bottom-left", "bottom-right")
    plans = [b for b in blocks if b.name != "plans_all"]
    rest = [b for b in blocks if b.name == "plans_all"]
    out: list[list[tuple[Block, str]]] = []
    for c_plans in corners:
        for c_rest in corners if rest else corners[:1]:  # no rest: one pass, c_rest unused
            first = [(b, c_plans) for b in plans]
            second = [(b, c_rest) for b in rest]
            out.append(first + second)
            if rest:
                out.append(second + first)
    return out


def arrange(sheet: Sheet, plan_sizes: list[tuple[float, float]], small_of,
            names: list[tuple[str, str]] | None = None) -> Arrangement:
    """Find where the plans of the analysed position and the small plans go in the free field
    left by the scheme, the diagrams and the table: the small plans at the largest crank vector
    of ``SMALL_PLAN_MM`` that fits (else dropped); among the ways that fit, the one that leaves
    the most room around every view; then the views are moved to share out the room. A position's
    two plans stay one block (:func:`plan_blocks`); only where no such way fits (a small sheet) is
    every plan placed on its own (:func:`apart_blocks`), rather than refusing the sheet."""
    region = sheet.free_region
    placed = [v.rect for v in sheet.views.values()]
    for options in (plan_blocks(plan_sizes, names), [apart_blocks(plan_sizes, names)]):
        best = _best(region, placed, options, sheet.frame.width, small_of)
        if best is not None:
            return best
    raise BuildError("sheet layout", "the plans of the analysed position do not fit in the free field "
                                     "of the sheet; " + LAYOUT_LIMIT)


def _best(region, placed: list[Rect], options: list[list[Block]], max_width: float, small_of
          ) -> Arrangement | None:
    """The arrangement with the most room round its views among ``options`` (ways to put the
    plans), with the small plans at the largest crank vector that fits, else without them."""
    scales_tried: set[float] = set()
    for crank_mm in (*SMALL_PLAN_MM, None):
        small = small_of(crank_mm) if crank_mm is not None else None
        if small is not None:
            if small[0].scale in scales_tried:
                continue                  # the same round μv as a larger crank vector
            scales_tried.add(small[0].scale)
        grids = kp.small_grids(small, max_width) if small is not None else [(0, 0.0, 0.0)]
        best: Arrangement | None = None
        for cols, sw, sh in grids:
            extra = [Block("plans_all", sw, sh, (("plans_all", 0.0, 0.0, sw, sh),))] if small is not None else []
            for blocks in options:
                for trial in _trials(blocks + extra):
                    rects = try_pack(region, [Request(b.name, b.width, b.height, c) for b, c in trial],
                                     gap=VIEW_GAP, placed=placed)
                    if rects is None:
                        continue
                    free = room(region, rects, gap=VIEW_GAP, placed=placed)
                    if best is None or free > best.room + MM_EPS:
                        rects = spread(region, rects, gap=VIEW_GAP, placed=placed)
                        rects = _grow(region, [b for b, _ in trial], rects, placed)
                        parts = {}
                        for (b, _), r in zip(trial, rects):
                            sx, sy = r.width / b.width, r.height / b.height     # grown
                            for name, dx, dy, w, h in b.parts:
                                parts[name] = Rect.from_size(r.x0 + dx * sx, r.y0 + dy * sy, w * sx, h * sy)
                        best = Arrangement(parts, small, cols, free)
        if best is not None:
            return best
    return None


def _grow(region, blocks: list[Block], rects: list[Rect], placed: list[Rect]) -> list[Rect]:
    """Give the views some of the room left round them: the small plans' cells and the plans'
    margins (more room for the names) grow into half of it, within limits."""
    for k, b in enumerate(blocks):
        if b.name == "plans_all":
            limit = (0.35 * b.width, 0.35 * b.height)
        else:
            limit = (GROW_PLANS_MM, 0.0)
        rects = grow(region, rects, k, gap=VIEW_GAP, placed=placed, max_grow=limit)
    return rects


def add_scheme_view(sheet: Sheet, b: tuple[float, float, float, float], k: float,
                    min_width: float = 0.0) -> View:
    """The scheme's view: model bounds ``b`` at ``k`` mm per metre with padding, more below (the
    scale caption) and above (the title); at least ``min_width`` mm wide (its title's width)."""
    left, bottom, right, top = SCHEME_PADS_MM
    w = max((b[2] - b[0]) * k + left + right, min_width)
    h = (b[3] - b[1]) * k + bottom + top
    view = sheet.add_view("scheme", w, h, preferred="top-left")
    view.transform = Transform(k, (b[0], b[1]), (view.rect.x0 + left, view.rect.y0 + bottom))
    return view


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
    """Velocity plans of every position at one round scale, the crank's vector ≤ ``crank_mm``."""
    kin = project.kinematics
    tip = project.linkage.drive_tip
    v_tip = float(np.hypot(*np.asarray(kin.points[tip].vel[0])))
    mu = round_scale(v_tip, crank_mm)
    return [build_plans(project.linkage, project.structure, kin, j, mu_v=mu)[0] for j in range(len(project.phi))]


def _lower_title(title: str) -> str:
    """«Диаграмма скорости» → «диаграмма скорости» (a row of the table names the diagram)."""
    return title.replace(tr("sheets.sk123"), tr("sheets.sk124"))


def _positions_text(positions: list[int]) -> str:
    return ", ".join(str(j) for j in sorted(positions))


def scale_rows(mu_l: float, scale_text: str, pairs: dict[int, tuple[Plan, Plan]], d: Diagrams | None,
               small: list[Plan] | None = None) -> list[tuple[str, str, str]]:
    """The table «Масштабы»: one row per distinct scale, named by what it draws — the scheme, the
    velocity and acceleration plans of the plan positions (positions sharing a μ share a row), the
    small velocity plans, the diagrams' axes and graphs and the pole distances."""
    rows = [("μl", tr("sheets.sk109", scale_text=scale_text), tr("sheets.sk110", v1=format_significant(mu_l, 4)))]
    for symbol, which, one, many, value in (("μv", 0, "sheet1.scales_vplan", "sheet1.scales_vplans", "sheets.sk112"),
                                            ("μa", 1, "sheet1.scales_aplan", "sheet1.scales_aplans", "sheets.sk114")):
        by_mu: dict[str, list[int]] = {}
        for j, plans in pairs.items():
            by_mu.setdefault(format_significant(plans[which].scale, 4), []).append(j)
        for mu, positions in by_mu.items():
            name = tr(one if len(positions) == 1 else many, i=_positions_text(positions))
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


#: Height of a row of the table of scales, and the strip above it for its title, mm.
TABLE_ROW_MM, TABLE_TITLE_MM = 8.0, 12.0


def _table_header() -> tuple[str, str, str]:
    return (tr("sheets.sk105"), tr("sheets.sk106"), tr("sheets.sk107"))


def _table_widths(candidates: list[list[tuple[str, str, str]]]) -> tuple[float, ...]:
    every = [_table_header(), *[r for rows in candidates for r in rows]]
    return tuple(max(style.text_width(r[c], 3.5) for r in every) + 5.0 for c in range(3))


def reserve_scales_table(sheet: Sheet, candidates: list[list[tuple[str, str, str]]]) -> View:
    """The table's view, big enough for the longest of ``candidates`` (row lists): the small
    plans' μv, one of its rows, is chosen once the other views are placed."""
    w = sum(_table_widths(candidates))
    n = max(len(rows) for rows in candidates)
    return sheet.add_view("scales", w, TABLE_ROW_MM * (n + 1) + TABLE_TITLE_MM, preferred="bottom-right")


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


def add_scales_table(sheet: Sheet, mu_l: float, scale_text: str, pairs: dict[int, tuple[Plan, Plan]],
                     d: Diagrams | None, small: list[Plan] | None = None) -> View:
    """The table «Масштабы» (reserved and filled at once)."""
    rows = scale_rows(mu_l, scale_text, pairs, d, small)
    view = reserve_scales_table(sheet, [rows])
    fill_scales_table(view, rows, _table_widths([rows]))
    return view
