"""The arrangement of sheet 1 and of the control work's one sheet, and with it the scale of the plan
of positions (issue 12, «Scales»): the core decides once at which ГОСТ scale the sheet can draw the
mechanism — the largest one not above the scheme's box (:meth:`SceneBoxes.scheme_for`) at which
the scheme's view, the other views (the s–v–a diagrams or Zhukovsky's lever, the table «Масштабы»)
and the plans of the plan positions all fit in the free field — and the note and the sheet both
print it; the sheet draws its views in the rectangles found here and never tries another scale.

Pure geometry in sheet mm: the views' sizes come from the scenes and the numbers of
:mod:`.boxes` (the lettering's room per language included), the packing from :mod:`.packing`.
The small velocity plans of sheet 1 are the sheet's own (they never decide the scale: they are
dropped where they do not fit): the sheet passes them to :func:`arrange` as ``smalls``.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Callable, Iterable, Mapping, Sequence

import numpy as np
from shapely.geometry.base import BaseGeometry

from ..errors import BuildError
from ..gost_scales import Scale
from ..tolerances import MM_EPS
from .boxes import (GROW_PLANS_MM, LEVER_PAD_MM, LEVER_STRIPS_MM, LEVER_TITLE_MM, PAIR_GAP, PLAN_MIN_WIDTH_A3_MM,
                    PLAN_MIN_WIDTH_MM, PLAN_PAD_MM, PLAN_STRIP_MM, PLAN_TITLE_A3_MM, PLAN_TITLE_DIGIT_MM,
                    PLAN_TITLE_MM, SCHEME_CAPTION_STRIP_MM, SCHEME_LETTERS_MIN_MM, SCHEME_LETTERS_MM,
                    SCHEME_MIN_WIDTH_MM,
                    SCHEME_PADS_MM, SCHEME_TITLE_STRIP_MM, SHEET_MM, SMALL_PLAN_MM, TABLE_ROW_MM,
                    TABLE_TITLE_MM, VIEW_GAP, control_sheet, free_field, lettering_room)
from .packing import Rect, Request, grow, pack, room, spread, try_pack

#: The small plans the sheet may add: (what to draw, its grids to try as (columns, width, height)),
#: in the order of preference; :func:`arrange` keeps the first that fits.
Smalls = Callable[[], Iterable[tuple[Any, Sequence[tuple[int, float, float]]]]]


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
    rects: Mapping[str, Rect]
    small: Any
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


def arrange(region: BaseGeometry, placed: Sequence[Rect], plan_sizes: Sequence[tuple[float, float]],
            names: Sequence[tuple[str, str]] | None = None, smalls: Smalls | None = None) -> Arrangement | None:
    """Where the plans of the plan positions (and the small plans, if ``smalls`` gives any) go in
    ``region`` (the free field) clear of the views ``placed`` already: the small plans at the first
    of ``smalls`` that fits (else dropped); among the ways that fit, the one that leaves the most
    room around every view; then the views are moved to share out the room. A position's two plans
    stay one block (:func:`plan_blocks`); only where no such way fits (a small sheet) is every plan
    placed on its own (:func:`apart_blocks`). None: the plans do not fit at all."""
    sizes, pairs = list(plan_sizes), list(names) if names is not None else None
    for options in (plan_blocks(sizes, pairs), [apart_blocks(sizes, pairs)]):
        best = _best(region, list(placed), options, smalls)
        if best is not None:
            return best
    return None


def _best(region, placed: list[Rect], options: list[list[Block]], smalls: Smalls | None) -> Arrangement | None:
    """The arrangement with the most room round its views among ``options`` (ways to put the
    plans), with the first small plans of ``smalls`` that fit, else without them."""
    for small, grids in itertools.chain(smalls() if smalls is not None else (), [(None, [(0, 0.0, 0.0)])]):
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
                        best = Arrangement(MappingProxyType(parts), small, cols, free)
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


# ---------------------------------------------------------------------------------------------
# the views' sizes and the whole sheet at one scale


@dataclass(frozen=True)
class SchemeView:
    """The scheme's view: its size and where the model's lower-left bound (``b[0], b[1]``) stands
    from the view's lower-left corner, mm (the sheet places the drawing there)."""
    width: float
    height: float
    origin: tuple[float, float]


def scheme_view_size(b: tuple[float, float, float, float], k: float, min_width: float = 0.0) -> tuple[float, float]:
    """Sheet 1's scheme view: model bounds ``b`` (m) at ``k`` mm per metre with ``SCHEME_PADS_MM``
    round them (more below for the scale caption, above for the title), at least ``min_width``."""
    view = scheme_view(b, k, min_width)
    return view.width, view.height


def scheme_view(b: tuple[float, float, float, float], k: float, min_width: float = 0.0,
                drawn: tuple[float, float, float, float] | None = None,
                lettered: Sequence[tuple[float, float]] = ()) -> SchemeView:
    """The scheme's view at ``k`` mm per metre, model bounds ``b`` (m). Sheet 1 (``drawn`` None):
    ``SCHEME_PADS_MM`` round the model bounds (the crank angles, the stroke). The control work's
    scheme (``drawn``: what its scene draws, ``Scene.bounds`` in mm — the bounds with the hinges,
    pivots, guides and blocks; ``lettered``: its letters' points, mm): on each side the room its
    letters need (:func:`letters_room`), the title's and the caption's strips above and below. At
    least ``min_width`` wide, the drawing centred in the extra width."""
    if drawn is None:
        left, bottom, right, top = SCHEME_PADS_MM
        w = (b[2] - b[0]) * k + left + right
        extra = max(min_width - w, 0.0)
        return SchemeView(w + extra, (b[3] - b[1]) * k + bottom + top, (left, bottom))
    left, bottom, right, top = letters_room(drawn, lettered)
    w = drawn[2] - drawn[0] + left + right
    h = drawn[3] - drawn[1] + bottom + top + SCHEME_TITLE_STRIP_MM + SCHEME_CAPTION_STRIP_MM
    extra = max(min_width - w, 0.0)
    origin = (b[0] * k - drawn[0] + left + extra / 2, b[1] * k - drawn[1] + bottom + SCHEME_CAPTION_STRIP_MM)
    return SchemeView(w + extra, h, origin)


def letters_room(drawn: tuple[float, float, float, float], lettered: Sequence[tuple[float, float]]
                 ) -> tuple[float, float, float, float]:
    """Room beyond the drawing ``drawn`` (mm) for the letters at the points ``lettered``: left,
    bottom, right, top — on each side what the point nearest to it needs for a letter reaching
    ``SCHEME_LETTERS_MM`` from it, at least ``SCHEME_LETTERS_MIN_MM``."""
    def need(distances: Iterable[float]) -> float:
        return max([SCHEME_LETTERS_MIN_MM, *(SCHEME_LETTERS_MM - d for d in distances)])
    x0, y0, x1, y1 = drawn
    return (need(p[0] - x0 for p in lettered), need(p[1] - y0 for p in lettered),
            need(x1 - p[0] for p in lettered), need(y1 - p[1] for p in lettered))


def plan_view_size(plan, title_mm: float, min_width: float = PLAN_MIN_WIDTH_MM) -> tuple[float, float]:
    """A plan's view (:class:`reportgen.plans.Plan`, its points in mm): the plan with
    ``PLAN_PAD_MM`` round it and its title and caption strips, at least as wide as its title's room
    and ``min_width``."""
    xs = [float(p[0]) for p in plan.points.values()]
    ys = [float(p[1]) for p in plan.points.values()]
    w = max(max(xs) - min(xs) + 2 * PLAN_PAD_MM, title_mm, min_width)
    return w, max(ys) - min(ys) + 2 * PLAN_PAD_MM + 2 * PLAN_STRIP_MM


def lever_view_size(scene, title_mm: float) -> tuple[float, float]:
    """Zhukovsky's lever's panel: the turned plan (the lever's scene, mm) with ``LEVER_PAD_MM``
    round it and its strips, at least as wide as its title's room."""
    x0, y0, x1, y1 = scene.bounds()
    return max(x1 - x0 + 2 * LEVER_PAD_MM, title_mm), y1 - y0 + 2 * LEVER_PAD_MM + LEVER_STRIPS_MM


def table_rows(plans_by_position: Mapping[int, tuple[Any, Any]], small: bool, diagrams: bool) -> int:
    """The most rows the table «Масштабы» has: μl, one per distinct μv and μa of the plan
    positions, the small plans' μv, the diagrams' seven (μφ, μt, μs, μv, μa, H1, H2)."""
    v = {float(pair[0].scale) for pair in plans_by_position.values()}
    a = {float(pair[1].scale) for pair in plans_by_position.values()}
    return 1 + len(v) + len(a) + (1 if small else 0) + (7 if diagrams else 0)


def scales_table_width(project, k: float, ratio: str, diagrams, small: bool, language: str | None = None,
                       given: bool = False) -> float:
    """The width (mm) of sheet 1's table «Масштабы» from its own lines — the rows
    drawings.sheets.kinematics.scale_rows writes: μl with the scheme's ratio, the μv and μa of the
    plan positions (positions sharing a μ on one line), the small velocity plans' μv (the widest
    of the crank vectors ``SMALL_PLAN_MM`` the sheet may choose), the ``diagrams``' scales and pole
    distances — measured as the sheet measures them (:mod:`.lettering`), in ``language`` (default
    the task's); ``given``: the control work's one position, its plans named without a number."""
    from ..numbers import plain, significant
    from ..plans import round_scale
    from .lettering import scales_table_width as width
    names: list[tuple[str, str]] = [("scheme", ratio)]
    values: list[tuple[str, str]] = [("value_l", significant(1.0 / k, 4))]
    for which, one, many, unit in ((0, "vplan", "vplans", "value_v"), (1, "aplan", "aplans", "value_a")):
        by_mu: dict[str, list[int]] = {}
        for j, pair in project.plans_by_position.items():
            by_mu.setdefault(significant(pair[which].scale, 4), []).append(j)
        for mu, positions in by_mu.items():
            names.append((one + "_given", "") if given else
                         (one if len(positions) == 1 else many, ", ".join(str(j) for j in sorted(positions))))
            values.append((unit, mu))
    if small:
        kin = project.kinematics
        v_tip = float(np.hypot(*np.asarray(kin.points[project.linkage.drive_tip].vel[0])))
        names.append(("small", str(len(project.phi) - 1)))
        values += [("value_v", significant(round_scale(v_tip, mm), 4)) for mm in SMALL_PLAN_MM]
    symbols = ["μl", "μv", "μa"]
    if diagrams is not None:
        kind = "m" if diagrams.unit == "м" else "rad"        # a slider's s, v, a or a rocker's ψ, ω, ε
        names += [("phi_axis", ""), ("t_axis", ""), (f"diagrams_{kind}", ""), ("pole", "")]
        values += [("value_phi", significant(diagrams.mu_phi, 4)), ("value_t", significant(diagrams.mu_t, 4)),
                   *((f"value_{kind}", significant(mu, 4)) for mu in (diagrams.mu_s, diagrams.mu_v, diagrams.mu_a)),
                   ("value_mm", plain(diagrams.H1, 1)), ("value_mm", plain(diagrams.H2, 1))]
        symbols += ["μφ", "μt", "μs", "μψ", "μω", "με", "H1", "H2"]
    return width(language or project.task.document.language, names, values, symbols)


@dataclass(frozen=True)
class SheetLayout:
    """The sheet's views at the plan of positions' scale ``k`` (mm per metre, ``ratio`` «1:N»):
    ``rects`` of every view by name (``scheme``; ``diagrams`` or ``lever``; ``scales``, the table, if
    the sheet has one; the plans ``plan_v``, ``plan_a``, ``plan_v_<j>`` …), the views ``placed``
    before the plans (the sheet adds its small plans among the plans with :func:`arrange`), the
    plans' ``plan_sizes`` and view ``names`` in :func:`plan_blocks`' order."""
    sheet: str                       # "A1" or "A3"
    k: float
    ratio: str
    rects: Mapping[str, Rect]
    placed: tuple[Rect, ...]
    plan_sizes: tuple[tuple[float, float], ...]
    names: tuple[tuple[str, str], ...]
    table_rows: int
    #: where the model's lower-left bound stands from the scheme view's lower-left corner, mm
    scheme_origin: tuple[float, float] = SCHEME_PADS_MM[:2]

    @property
    def scale(self) -> Scale:
        """The plan of positions' scale, to print in a language's decimal mark (``Scale.text``)."""
        return Scale.parse(self.ratio)

    @property
    def field(self) -> BaseGeometry:
        return free_field(*SHEET_MM[self.sheet])


#: Where the lever's panel of the control work's sheet may go, in order of preference: top right (as
#: sheet 2's), else bottom left under the scheme (an A3 sheet whose plans need the middle's height).
LEVER_CORNERS = ("top-right", "bottom-left")


def layout_at(project, b: tuple[float, float, float, float], k: float, ratio: str) -> SheetLayout | None:
    """Sheet 1 (or the control work's sheet) with the plan of positions at ``k``: every view
    placed as the sheet places it — the scheme top left, the diagrams top right (the lever top
    right, else bottom left: ``LEVER_CORNERS``), the table bottom right, then the plans
    (:func:`arrange`) — or None where they do not all fit."""
    task = project.task
    control = control_sheet(task)
    fmt = control or "A1"
    lang = task.document.language
    region = free_field(*SHEET_MM[fmt])
    if control:
        scene = project.scenes.positions_at(k, ratio)
        view = scheme_view(b, k, SCHEME_MIN_WIDTH_MM[fmt], scene.bounds(),
                           [lb.at for lb in scene.labels if lb.role == "point"])
    else:
        view = scheme_view(b, k)
    scheme = Request("scheme", view.width, view.height, "top-left")
    second: list[tuple[Request, ...]] = []   # the second view, in the corners to try
    diagrams = None
    if control:
        size = lever_view_size(project.scenes.lever, lettering_room(LEVER_TITLE_MM, lang))
        second = [(Request("lever", *size, corner),) for corner in LEVER_CORNERS]
    else:
        diagrams = project.output_diagrams
        if diagrams is not None:
            from .output_diagrams import size as diagrams_size
            second = [(Request("diagrams", *diagrams_size(diagrams), "top-right"),)]
    pairs = project.plans_by_position
    rows = table_rows(pairs, small=not control, diagrams=diagrams is not None)
    # the A3 field has no room for the table: each view prints its scale
    table = [] if fmt == "A3" else [Request("scales", scales_table_width(project, k, ratio, diagrams, small=not control, given=bool(control)),
                                            TABLE_ROW_MM * (rows + 1) + TABLE_TITLE_MM, "bottom-right")]
    a3 = fmt == "A3"
    titles = lettering_room(PLAN_TITLE_A3_MM if a3 else PLAN_TITLE_MM, lang)
    least = PLAN_MIN_WIDTH_A3_MM if a3 else PLAN_MIN_WIDTH_MM
    names = [plan_view_names(j, first=(j == project.analysed)) for j in pairs]
    sizes = [plan_view_size(plan, title + (0.0 if a3 else PLAN_TITLE_DIGIT_MM * (len(str(j)) - 1)), least)
             for j, pair in pairs.items() for plan, title in zip(pair, titles)]
    if not _may_fit(region, [scheme, *(second[0] if second else ()), *table], sizes):
        return None
    for other in second or [()]:
        requests = [scheme, *other, *table]
        placed: list[Rect] = []
        rects: dict[str, Rect] = {}
        try:
            for req in requests:          # one by one, as the sheet reserves them (Sheet.add_view)
                rect = pack(region, [req], gap=VIEW_GAP, placed=placed)[0]
                placed.append(rect)
                rects[req.name] = rect
        except BuildError:
            continue
        found = arrange(region, placed, sizes, names)
        if found is not None:
            rects.update(found.rects)
            return SheetLayout(fmt, k, ratio, MappingProxyType(rects), tuple(placed), tuple(sizes), tuple(names), rows,
                               view.origin)
    return None


def _may_fit(region, requests: Sequence[Request], sizes: Sequence[tuple[float, float]]) -> bool:
    """A quick necessary condition before the packing (the control work tries its scales from the
    whole field down): every view fits the field's extent, and their areas together its area."""
    x0, y0, x1, y1 = region.bounds
    views = [(r.width, r.height) for r in requests] + list(sizes)
    if any(w > x1 - x0 + MM_EPS or h > y1 - y0 + MM_EPS for w, h in views):
        return False
    return sum(w * h for w, h in views) <= region.area + MM_EPS


#: The smallest drawing of the mechanism worth trying, mm (its larger side): below it the plan of
#: positions is a blot, and a sheet that needs it does not fit.
LEAST_SCHEME_MM = 15.0


def choose_layout(project, b: tuple[float, float, float, float], scales: Sequence[tuple[float, str]]
                  ) -> SheetLayout | None:
    """The first of ``scales`` (largest first) at which the whole sheet fits; None if none does
    down to a drawing ``LEAST_SCHEME_MM`` big."""
    for k, ratio in scales:
        if max(b[2] - b[0], b[3] - b[1]) * k < LEAST_SCHEME_MM:
            break
        found = layout_at(project, b, k, ratio)
        if found is not None:
            return found
    return None
