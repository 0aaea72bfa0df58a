"""Sheet 1's small velocity plans: the velocity plan of every position at one round μv, in a grid of
equal cells under one title and one caption (drawings.scenes.kinematics_plans draws them).

They are a required part of sheet 1 (issue 12: they were added only where they happened to fit,
and class3 with three plan positions lost them): :mod:`.arrangement` chooses the sheet's scale with
their block among the views. Their μv is the crank's vector at most one of ``SMALL_PLAN_MM`` long
(the one round-scale rule, :func:`reportgen.plans.round_scale`); their block's size is the plans'
geometry (:func:`small_cell`) and a lettering reserve that is the same in every catalogue language
(:func:`reportgen.scenes.lettering.small_plans_lettering`), so that their scale never depends on the
language of the sheet's words.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..numbers import significant
from ..plans import Plan, build_plans, round_scale
from .boxes import SMALL_PLAN_MM
from .lettering import small_plans_lettering

#: A cell of the grid: room round the largest plan for its letters, and the strip for its number, mm.
SMALL_CELL_PAD_MM, SMALL_NUMBER_MM = 9.0, 5.0
#: The block's title and caption strips, mm; a title in two lines takes ``SMALL_TITLE_LINE_MM`` more.
SMALL_TITLE_MM, SMALL_CAPTION_MM, SMALL_TITLE_LINE_MM = 14.0, 12.0, 8.0
#: No point of a small plan stands farther from the pole than this many times the crank's vector's
#: largest length (the examples' farthest: 2,9 times, the short-crank shaper's).
SMALL_PLAN_FAR = 4.0
#: The grids tried have 1 to this many rows.
SMALL_GRID_ROWS = 6


@dataclass(frozen=True)
class SmallGrid:
    """The small plans in ``cols`` columns: the block's ``width`` × ``height``, mm (title, cells,
    caption)."""
    cols: int
    width: float
    height: float


def small_plans(project, crank_mm: float) -> tuple[Plan, ...]:
    """Velocity plans of every position at one round μv, the crank's vector at most ``crank_mm`` and
    no point of any position farther than ``SMALL_PLAN_FAR`` × ``crank_mm`` from the pole (as the
    plans' ``PLAN_MAX_MM``: near a toggle a link's velocity is a thousand times the crank's, and the
    plans at the crank's μv would not fit the sheet at all)."""
    kin = project.kinematics
    v_tip = float(np.hypot(*np.asarray(kin.points[project.linkage.drive_tip].vel[0])))
    moving = [*kin.points.values(), *kin.coms.values()]
    v_far = max(float(np.hypot(*np.asarray(m.vel, float).T).max()) for m in moving)
    mu = max(round_scale(v_tip, crank_mm), round_scale(v_far, SMALL_PLAN_FAR * crank_mm))
    return tuple(build_plans(project.linkage, project.structure, kin, j, mu_v=mu)[0] for j in range(len(project.phi)))


def small_plan_sets(project) -> tuple[tuple[Plan, ...], ...]:
    """The small plans at each distinct μv of ``SMALL_PLAN_MM``, the largest drawing first."""
    out: list[tuple[Plan, ...]] = []
    for crank_mm in SMALL_PLAN_MM:
        plans = small_plans(project, crank_mm)
        if not out or plans[0].scale != out[-1][0].scale:
            out.append(plans)
    return tuple(out)


def plan_extent(plan: Plan) -> tuple[float, float, float, float]:
    """The bounds of a plan's points, mm from its pole."""
    arr = np.array(list(plan.points.values()), float)
    return float(arr[:, 0].min()), float(arr[:, 1].min()), float(arr[:, 0].max()), float(arr[:, 1].max())


def small_cell(plans: tuple[Plan, ...] | list[Plan]) -> tuple[float, float]:
    """Width and height of one cell of the grid: the largest plan with room for its letters and its
    number, mm."""
    ext = np.array([plan_extent(p) for p in plans])
    cw = float((ext[:, 2] - ext[:, 0]).max()) + 2 * SMALL_CELL_PAD_MM
    ch = float((ext[:, 3] - ext[:, 1]).max()) + 2 * SMALL_CELL_PAD_MM + SMALL_NUMBER_MM
    return cw, ch


def title_strip(lines: int) -> float:
    """The title strip of the block for a title in ``lines`` lines, mm."""
    return SMALL_TITLE_MM + SMALL_TITLE_LINE_MM * (lines - 1)


def small_grids(plans: tuple[Plan, ...] | list[Plan], max_width: float) -> tuple[SmallGrid, ...]:
    """The grids to try, 1 to ``SMALL_GRID_ROWS`` rows (each number of columns once), no wider in
    cells than ``max_width``: each at least as wide as its title (in one line, else two) and caption
    in the widest catalogue language."""
    cw, ch = small_cell(plans)
    n = len(plans)
    last, mu = str(n - 1), significant(plans[0].scale, 4)
    out: list[SmallGrid] = []
    for rows in range(1, SMALL_GRID_ROWS + 1):
        cols = math.ceil(n / rows)
        if any(g.cols == cols for g in out) or cols * cw > max_width:
            continue
        rows = math.ceil(n / cols)
        lines, need = small_plans_lettering(last, mu, cols * cw)
        out.append(SmallGrid(cols, max(cols * cw, need), rows * ch + title_strip(lines) + SMALL_CAPTION_MM))
    return tuple(out)
