"""Issue 12, sheet 1 with 1, 2 and 3 plan positions (``[analysis] plan_positions``) for every
linkage example: the sheet is drawn at the plan of positions' scale the note prints
(``project.scenes.positions``: no silent fallback to a smaller one), the small velocity plans of
every position are on it, each acceleration plan's view sits beside or under its own velocity
plan's (``PAIR_GAP`` apart, the two sharing a side) and nearer to it than to any other plan's view,
and no view overlaps another, leaves the frame or enters the title block."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from drawings.sheets import kinematics as sheet1
from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3")
EPS = 1e-6


def with_plan_positions(example: str, count: int, tmp: Path) -> Project:
    """The example with ``count`` plan positions: the analysed one, the default other-stroke one,
    and for three a position half a turn from the analysed one (the next free one)."""
    path = ROOT / "examples" / example / "task.toml"
    base = Project(load_task(path))
    chosen = list(base.plan_positions[:count])
    n = len(base.phi)
    j = (base.analysed + n // 2) % n
    while len(chosen) < count:
        if j not in chosen:
            chosen.append(j)
        j = (j + 1) % n
    text = path.read_text(encoding="utf-8")
    text = re.sub(r"(?m)^plan_positions\s*=.*\n", "", text)
    line = f"plan_positions = [{', '.join(map(str, chosen))}]\n"
    if re.search(r"(?m)^\[analysis\]\s*$", text):
        text = re.sub(r"(?m)^(\[analysis\][^\n]*\n)", lambda m: m.group(1) + line, text, count=1)
    else:
        text += "\n[analysis]\n" + line
    out = tmp / f"{example}-{count}.toml"
    out.write_text(text, encoding="utf-8")
    project = Project(load_task(out))
    assert sorted(project.plan_positions) == sorted(chosen)
    return project


CASES = [pytest.param((ex, n), id=f"{ex}-{n}") for ex in EXAMPLES for n in (1, 2, 3)]


@pytest.fixture(scope="module", params=CASES)
def drawn(request, tmp_path_factory):
    example, count = request.param
    project = with_plan_positions(example, count, tmp_path_factory.mktemp(f"{example}{count}"))
    return project, sheet1.draw(project, 1, 4)


def _adjacent(v, a) -> bool:
    """``a`` right of ``v`` (a row: same top and bottom) or under it (a column: same sides),
    ``PAIR_GAP`` apart."""
    gap = sheet1.PAIR_GAP
    row = (math.isclose(v.y0, a.y0, abs_tol=EPS) and math.isclose(v.y1, a.y1, abs_tol=EPS)
           and math.isclose(a.x0 - v.x1, gap, abs_tol=0.5 * gap))
    column = (math.isclose(v.x0, a.x0, abs_tol=EPS) and math.isclose(v.x1, a.x1, abs_tol=EPS)
              and math.isclose(v.y0 - a.y1, gap, abs_tol=0.5 * gap))
    return row or column


def _distance(p, q) -> float:
    dx = max(p.x0 - q.x1, q.x0 - p.x1, 0.0)
    dy = max(p.y0 - q.y1, q.y0 - p.y1, 0.0)
    return math.hypot(dx, dy)


def test_drawn_at_the_notes_scale_with_the_small_plans(drawn):
    project, sheet = drawn
    note_scale = project.scenes.positions.scale("μl").value
    assert sheet.views["scheme"].transform.scale == pytest.approx(1.0 / note_scale, rel=1e-12)
    assert "plans_all" in sheet.views, "the small velocity plans were left out"


@pytest.mark.slow
def test_class3_with_three_plan_positions_keeps_its_small_plans(tmp_path):
    """Issue 12: the core chose the scale from the views without the small plans, and the sheet added
    them only where they fitted; once the table «Масштабы» got its real width (2,6 mm wider than the
    old fixed room) class3 with three plan positions lost them. The core now reserves them: the
    scheme drops to the next ГОСТ scale where they need it."""
    project = with_plan_positions("class3", 3, tmp_path)
    assert "plans_all" in sheet1.draw(project, 1, 4).views
    assert project.scenes.positions_scale[1] == "1:5"      # 1:4 of two plan positions leaves them no room


def test_each_acceleration_plan_beside_its_velocity_plan(drawn):
    project, sheet = drawn
    names = {j: sheet1.plan_view_names(j, j == project.analysed) for j in project.plan_positions}
    rects = {n: sheet.views[n].rect for pair in names.values() for n in pair}
    for j, (nv, na) in names.items():
        v, a = rects[nv], rects[na]
        assert _adjacent(v, a), (j, v, a)
        own = _distance(v, a)
        for other, r in rects.items():
            if other not in (nv, na):
                assert _distance(a, r) > own + EPS, (j, other)   # nearer its own plan than any other


def test_nothing_overlaps_or_leaves_the_field(drawn):
    _, sheet = drawn
    assert not sheet.overlaps()
    field = sheet.free_region.buffer(EPS)
    views = list(sheet.views.items())
    for name, view in views:
        assert field.contains(view.rect.polygon()), name            # inside the frame, off the title block
    for k, (n, v) in enumerate(views):
        for m, w in views[k + 1:]:
            assert not v.rect.overlaps(w.rect), (n, m)


def test_a_third_plan_position_takes_height_from_the_schemes_box():
    from reportgen.scenes.boxes import DEFAULT
    from reportgen.scenes.positions import positions_scales
    shaper = (0.0, 0.0, 0.617, 0.640)               # the shaper's plan of positions, m
    assert positions_scales(shaper, DEFAULT, 1)[0][1] == "1:2,5"          # 256 mm ≤ 270 mm
    assert positions_scales(shaper, DEFAULT, 2)[0][1] == "1:2,5"
    assert positions_scales(shaper, DEFAULT, 3)[0][1] == "1:4"            # 256 mm > 230 mm
    press = (0.0, 0.0, 0.948, 0.340)                # wide and low: the width decides
    assert {positions_scales(press, DEFAULT, n)[0][1] for n in (1, 2, 3)} == {"1:2,5"}
