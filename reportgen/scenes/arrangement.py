"""The arrangement of sheet 1 and of the control work's one sheet, and with it the scale of the plan
of positions (issue 12, «Scales»): the core decides once at which ГОСТ scale the sheet can draw the
mechanism — the largest one not above the scheme's box (:meth:`SceneBoxes.scheme_for`) at which
the scheme's view, the other views (the s–v–a diagrams or Zhukovsky's lever, the table «Масштабы»),
the plans of the plan positions and sheet 1's small velocity plans all fit in the free field — and
the note and the sheet both print it; the sheet draws its views in the rectangles found here and
never tries another scale.

Pure geometry in sheet mm: the views' sizes come from the scenes and the numbers of
:mod:`.boxes` (the lettering's room per language included), the packing from :mod:`.packing`.
Sheet 1's small velocity plans (:mod:`.small_plans`) are a required view (issue 12: added only
where they happened to fit, class3 with three plan positions lost them): the scale is the largest
at which the sheet fits with them at their smallest; their μv is then the largest of their sizes
at which the sheet fits in every catalogue language (:func:`small_choice`), so that it never
depends on the language of the sheet's words.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Callable, Iterable, Mapping, Sequence

from shapely.geometry.base import BaseGeometry

from ..errors import BuildError
from ..gost_scales import Scale
from ..tolerances import MM_EPS
from .boxes import (GROW_PLANS_MM, LEVER_PAD_MM, LEVER_STRIPS_MM, LEVER_TITLE_MM, PAIR_GAP, PLAN_MIN_WIDTH_A3_MM,
                    PLAN_MIN_WIDTH_MM, PLAN_PAD_MM, PLAN_STRIP_MM, PLAN_TITLE_A3_MM, PLAN_TITLE_DIGIT_MM,
                    PLAN_TITLE_MM, SCHEME_CAPTION_STRIP_MM, SCHEME_LETTERS_MIN_MM, SCHEME_LETTERS_MM,
                    SCHEME_MIN_WIDTH_MM,
                    SCHEME_PADS_MM, SCHEME_TITLE_STRIP_MM, SHEET_MM, TABLE_ROW_MM,
                    TABLE_TITLE_MM, VIEW_GAP, control_sheet, free_field, lettering_room)
from .packing import Rect, Request, grow, pack, room, spread, try_pack
from .small_plans import SmallGrid, small_grids

#: The small plans to place: (what to draw, its grids to try), in the order of preference;
#: :func:`arrange` keeps the first that fits.
Smalls = Callable[[], Iterable[tuple[Any, Sequence[SmallGrid]]]]


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
            names: Sequence[tuple[str, str]] | None = None, smalls: Smalls | None = None,
            required: bool = False, apart: bool = True) -> Arrangement | None:
    """Where the plans of the plan positions (and the small plans, if ``smalls`` gives any) go in
    ``region`` (the free field) clear of the views ``placed`` already: the small plans at the first
    of ``smalls`` that fits (else, unless ``required``, left out); among the ways that fit, the one
    that leaves the most room around every view; then the views are moved to share out the room.
    A position's two plans stay one block (:func:`plan_blocks`); only where no such way fits (a
    small sheet) is every plan placed on its own (:func:`apart_blocks`; never unless ``apart``). None:
    the plans (with the small plans if ``required``) do not fit at all."""
    sizes, pairs = list(plan_sizes), list(names) if names is not None else None
    for options in (plan_blocks(sizes, pairs), [apart_blocks(sizes, pairs)])[:2 if apart else 1]:
        best = _best(region, list(placed), options, smalls, required)
        if best is not None:
            return best
    return None


def fits(region: BaseGeometry, placed: Sequence[Rect], plan_sizes: Sequence[tuple[float, float]],
         names: Sequence[tuple[str, str]] | None = None, grids: Sequence[SmallGrid] = (), apart: bool = True,
         hints: list | None = None) -> bool:
    """Whether the plans (and a small plans' block of one of ``grids``, if any) fit in ``region``
    clear of ``placed`` in some way :func:`arrange` tries (every plan on its own only if ``apart``):
    the same trials, stopping at the first that fits (the scale's choice asks this of every scale
    and size it tries). A grid that does not fit beside ``placed`` on its own, or whose area with
    the plans' exceeds the room, is not tried. ``hints``: the trials that fitted before (kept up to
    date here), tried first — the answer is the same, found sooner."""
    sizes, pairs = list(plan_sizes), list(names) if names is not None else None
    free = region.area - sum((r.width + VIEW_GAP) * (r.height + VIEW_GAP) for r in placed)
    plans = sum(w * h for w, h in sizes)
    extras = [g for g in grids if plans + g.width * g.height <= free + MM_EPS
              and try_pack(region, [Request("plans_all", g.width, g.height)], gap=VIEW_GAP, placed=placed) is not None]
    if grids and not extras:
        return False
    trials: dict[tuple, list[Request]] = {}
    for a, options in enumerate((plan_blocks(sizes, pairs), [apart_blocks(sizes, pairs)])[:2 if apart else 1]):
        choices: list[SmallGrid | None] = list(extras) or [None]
        for grid in choices:
            extra = [_small_block(grid)] if grid is not None else []
            for i, blocks in enumerate(options):
                for t, trial in enumerate(_trials(blocks + extra)):
                    key = (a, grid.cols if grid is not None else 0, i, t)
                    trials[key] = [Request(b.name, b.width, b.height, c) for b, c in trial]
    packer = _Packer(region, placed)
    hinted = [key for key in (hints or []) if key in trials]
    for key in itertools.chain(hinted, (key for key in trials if key not in hinted)):
        if packer.pack(trials[key]) is not None:
            if hints is not None:
                if key in hints:
                    hints.remove(key)
                hints.insert(0, key)
            return True
    return False


class _Packer:
    """:func:`try_pack` of many trials in one field clear of the same views: the trials share their
    first views (the same plans at the same corners, the small plans elsewhere), so each prefix of
    requests is packed once (``try_pack`` packs one request after another: packing a prefix and then
    the next request on it is the same)."""

    def __init__(self, region: BaseGeometry, placed: Sequence[Rect]) -> None:
        self.region, self.placed = region, list(placed)
        self.memo: dict[tuple[Request, ...], list[Rect] | None] = {(): []}

    def pack(self, requests: Sequence[Request]) -> list[Rect] | None:
        key = tuple(requests)
        if key in self.memo:
            return self.memo[key]
        head = self.pack(key[:-1])
        found = None
        if head is not None:
            last = try_pack(self.region, key[-1:], gap=VIEW_GAP, placed=[*self.placed, *head])
            found = None if last is None else [*head, *last]
        self.memo[key] = found
        return found


def _small_block(grid: SmallGrid) -> Block:
    return Block("plans_all", grid.width, grid.height, (("plans_all", 0.0, 0.0, grid.width, grid.height),))


def _best(region, placed: list[Rect], options: list[list[Block]], smalls: Smalls | None,
          required: bool = False) -> Arrangement | None:
    """The arrangement with the most room round its views among ``options`` (ways to put the
    plans), with the first small plans of ``smalls`` that fit, else (unless ``required``) without
    them."""
    without = [] if required else [(None, [SmallGrid(0, 0.0, 0.0)])]
    packer = _Packer(region, placed)
    for small, grids in itertools.chain(smalls() if smalls is not None else (), without):
        best: Arrangement | None = None
        for grid in grids:
            extra = [_small_block(grid)] if small is not None else []
            for blocks in options:
                for trial in _trials(blocks + extra):
                    rects = packer.pack([Request(b.name, b.width, b.height, c) for b, c in trial])
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
                        best = Arrangement(MappingProxyType(parts), small, grid.cols, free)
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
    of their sizes, ``project.scenes.small_plan_sets``), the ``diagrams``' scales and pole
    distances — measured as the sheet measures them (:mod:`.lettering`), in ``language`` (default
    the task's); ``given``: the control work's one position, its plans named without a number."""
    from ..numbers import plain, significant
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
        names.append(("small", str(len(project.phi) - 1)))
        values += [("value_v", significant(plans[0].scale, 4)) for plans in project.scenes.small_plan_sets]
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
    the sheet has one; the plans ``plan_v``, ``plan_a``, ``plan_v_<j>`` …; sheet 1's small plans
    ``plans_all``), the views ``placed`` before the plans, the plans' ``plan_sizes`` and view
    ``names`` in :func:`plan_blocks`' order; sheet 1's ``small`` plans (None on the control work's
    sheet) drawn in ``small_cols`` columns."""
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
    small: tuple[Any, ...] | None = None
    small_cols: int = 0

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


@dataclass(frozen=True)
class _Views:
    """The views placed before the plans at one scale (one way of placing them): their rectangles,
    the plans' sizes and names, the table's rows, the scheme's origin."""
    fmt: str
    region: BaseGeometry
    rects: Mapping[str, Rect]
    placed: tuple[Rect, ...]
    sizes: tuple[tuple[float, float], ...]
    names: tuple[tuple[str, str], ...]
    rows: int
    origin: tuple[float, float]


def _views_at(project, b: tuple[float, float, float, float], k: float, ratio: str,
              language: str | None = None) -> tuple[_Views, ...]:
    """:func:`_placed_views`, once per scale and language (the choice asks it of every size)."""
    cache = project.scenes.__dict__.setdefault("_views_at", {})
    key = (b, k, ratio, language or project.task.document.language)
    if key not in cache:
        cache[key] = tuple(_placed_views(project, b, k, ratio, key[-1]))
    return cache[key]


def _placed_views(project, b: tuple[float, float, float, float], k: float, ratio: str,
                  language: str | None = None) -> Iterable[_Views]:
    """Sheet 1 (or the control work's sheet) at ``k`` with the views other than the plans placed as
    the sheet places them — the scheme top left, the diagrams top right (the lever top right, else
    bottom left: ``LEVER_CORNERS``), the table bottom right — each way that places them all, with the
    lettering's room of ``language`` (default the task's)."""
    task = project.task
    control = control_sheet(task)
    fmt = control or "A1"
    lang = language or task.document.language
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
    table = [] if fmt == "A3" else [Request("scales", scales_table_width(project, k, ratio, diagrams, small=not control,
                                                                         language=lang, given=bool(control)),
                                            TABLE_ROW_MM * (rows + 1) + TABLE_TITLE_MM, "bottom-right")]
    a3 = fmt == "A3"
    titles = lettering_room(PLAN_TITLE_A3_MM if a3 else PLAN_TITLE_MM, lang)
    least = PLAN_MIN_WIDTH_A3_MM if a3 else PLAN_MIN_WIDTH_MM
    names = tuple(plan_view_names(j, first=(j == project.analysed)) for j in pairs)
    sizes = tuple(plan_view_size(plan, title + (0.0 if a3 else PLAN_TITLE_DIGIT_MM * (len(str(j)) - 1)), least)
                  for j, pair in pairs.items() for plan, title in zip(pair, titles))
    if not _may_fit(region, [scheme, *(second[0] if second else ()), *table], sizes):
        return
    for other in second or [()]:
        placed: list[Rect] = []
        rects: dict[str, Rect] = {}
        try:
            for req in [scheme, *other, *table]:     # one by one, as the sheet reserves them (Sheet.add_view)
                rect = pack(region, [req], gap=VIEW_GAP, placed=placed)[0]
                placed.append(rect)
                rects[req.name] = rect
        except BuildError:
            continue
        yield _Views(fmt, region, MappingProxyType(rects), tuple(placed), sizes, names, rows, view.origin)


def _small_options(project) -> tuple[tuple[tuple[Any, ...], tuple[SmallGrid, ...]], ...]:
    """Sheet 1's small plans at each of their sizes (``project.scenes.small_plan_sets``, the largest
    drawing first) with their grids; none on the control work's sheet."""
    if control_sheet(project.task):
        return ()
    x0, _, x1, _ = free_field(*SHEET_MM["A1"]).bounds
    return tuple((plans, small_grids(plans, x1 - x0)) for plans in project.scenes.small_plan_sets)


def layout_at(project, b: tuple[float, float, float, float], k: float, ratio: str, small: int = -1,
              language: str | None = None) -> SheetLayout | None:
    """Sheet 1 (or the control work's sheet) with the plan of positions at ``k``: every view
    placed as the sheet places it (:func:`_views_at`), then the plans and sheet 1's small plans —
    the ``small``-th of their sizes (:func:`_small_options`; default the smallest drawing) — where
    they leave the most room (:func:`arrange`); None where they do not all fit."""
    options = _small_options(project)
    required = options[small] if options else None
    for views in _views_at(project, b, k, ratio, language):
        found = arrange(views.region, views.placed, views.sizes, views.names,
                        (lambda: [required]) if required is not None else None, required=required is not None,
                        apart=_apart(options, small))
        if found is not None:
            rects = {**views.rects, **found.rects}
            return SheetLayout(views.fmt, k, ratio, MappingProxyType(rects), views.placed, views.sizes, views.names,
                               views.rows, views.origin, found.small, found.cols)
    return None


def fits_at(project, b: tuple[float, float, float, float], k: float, ratio: str, small: int = -1,
            language: str | None = None) -> bool:
    """Whether :func:`layout_at` finds a layout (the same trials, stopping at the first that fits)."""
    options = _small_options(project)
    grids = options[small][1] if options else ()
    if options and not grids:
        return False                        # no grid of the small plans fits the field's width
    hints = project.scenes.__dict__.setdefault("_fit_hints", [])
    for views in _views_at(project, b, k, ratio, language):
        if grids and not fits(views.region, views.placed, views.sizes, views.names, hints=hints):
            continue                        # the plans alone do not fit: the quick answer
        if fits(views.region, views.placed, views.sizes, views.names, grids, _apart(options, small), hints):
            return True
    return False


def _apart(options: Sequence, small: int) -> bool:
    """Whether the plans may be placed each on its own (:func:`apart_blocks`, the last resort of a
    small sheet): not to make room for a larger drawing of the small plans than their smallest."""
    return not options or small in (-1, len(options) - 1)


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
#: The languages of the catalogues whose lettering the core knows (:mod:`.boxes`, :mod:`.lettering`):
#: the small plans' μv is one that fits sheet 1 in each of them. The widest lettering first (the
#: likeliest not to fit: the choice stops at the first language a size does not fit).
LANGUAGES = tuple(sorted(PLAN_TITLE_MM, key=lambda lang: -sum(PLAN_TITLE_MM[lang])))


@dataclass(frozen=True)
class SheetChoice:
    """The scale of the plan of positions (``k`` mm per metre, ``ratio`` «1:N») and the size of
    sheet 1's small plans (``small``: the index among :func:`_small_options`, -1 none) chosen for a
    project; :func:`layout_at` arranges the sheet at them."""
    k: float
    ratio: str
    small: int = -1


def first_scale(project, b: tuple[float, float, float, float], scales: Sequence[tuple[float, str]],
                language: str | None = None) -> tuple[float, str] | None:
    """The first of ``scales`` (largest first) at which the whole sheet fits in ``language``'s
    lettering (sheet 1 with its small plans at their smallest drawing); None if none does down to a
    drawing ``LEAST_SCHEME_MM`` big."""
    for k, ratio in scales:
        if max(b[2] - b[0], b[3] - b[1]) * k < LEAST_SCHEME_MM:
            break
        if fits_at(project, b, k, ratio, language=language):
            return k, ratio
    return None


def small_choice(project, b: tuple[float, float, float, float], scales: Sequence[tuple[float, str]],
                 chosen: tuple[float, str]) -> int:
    """The size of sheet 1's small plans (index among :func:`_small_options`): the largest drawing
    up to which every size fits the sheet in every catalogue language (``LANGUAGES``), each at the
    scale it would draw the mechanism (``chosen`` for the task's; :func:`first_scale` for the
    others), from the smallest drawing up. The scale of a construction must not depend on the
    language of its words (issue 12: the press's were 0,04 in ru and 0,05 in en, sized in the room
    each language's longer or shorter titles left)."""
    options = _small_options(project)
    if not options:
        return -1
    own = project.task.document.language
    at: dict[str, tuple[float, str]] = {}
    for lang in dict.fromkeys((*LANGUAGES, own)):
        found = chosen if lang == own else first_scale(project, b, scales, lang)
        if found is not None:              # a language that cannot draw the sheet at all has no say
            at[lang] = found
    index = len(options) - 1               # the smallest drawing fits at each language's scale
    while index > 0 and all(fits_at(project, b, *at[lang], small=index - 1, language=lang) for lang in at):
        index -= 1
    return index


def choose_scale(project, b: tuple[float, float, float, float], scales: Sequence[tuple[float, str]]
                 ) -> SheetChoice | None:
    """The scale of the plan of positions (the first of ``scales`` at which the whole sheet fits,
    :func:`first_scale`) and the small plans' size (:func:`small_choice`); None if no scale fits."""
    found = first_scale(project, b, scales)
    if found is None:
        return None
    return SheetChoice(*found, small_choice(project, b, scales, found))


def choose_layout(project, b: tuple[float, float, float, float], scales: Sequence[tuple[float, str]]
                  ) -> SheetLayout | None:
    """The sheet arranged at :func:`choose_scale`'s choice; None if no scale fits."""
    choice = choose_scale(project, b, scales)
    return None if choice is None else layout_at(project, b, choice.k, choice.ratio, choice.small)
