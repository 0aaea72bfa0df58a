"""Issue 12, sheet 1 and section 1: the plans of both strokes (``[analysis] plan_positions``, by
default one position of the working and one of the idle stroke) are in the note and on sheet 1
(read back from the DXF); sheet 1's table of scales has one row per distinct scale, named by what
it draws, with the note's μ values; the small velocity plans' letters are legible (≥ 2,5 mm),
never overlap and stand at their point or at the end of a leader."""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import Point

from drawings.scenes import kinematics_plans as kp
from drawings.sheets import kinematics as sheet1
from latex_templates import NoteBuilder
from latex_templates.compose import compose
from latex_templates.render import Strings
from reportgen.scenes.scene import Arrow
from scene_readback import drawn_sheet, dxf_vectors, example_project

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3")


@pytest.fixture(scope="module", params=EXAMPLES)
def built(request, tmp_path_factory):
    project = example_project(request.param)
    out = tmp_path_factory.mktemp(request.param)
    sections, _ = compose(project, Strings("ru"), only=("linkage",))
    note = NoteBuilder(project.task.document)
    for s in sections:
        note.add_section(s.section)
    tex = note.render(out).read_text(encoding="utf-8")
    sheet, doc = drawn_sheet(request.param, sheet1, 1, out)
    return project, tex, sheet, doc


def _number(s: str) -> float:
    return float(s.replace(",", ".").replace("\u2212", "-"))


def _texts(doc) -> list:
    return list(doc.modelspace().query("TEXT"))


def test_default_two_plan_positions_one_per_stroke(built):
    project, *_ = built
    assert len(project.plan_positions) == 2


def test_note_has_both_velocity_and_acceleration_plans(built):
    project, tex, *_ = built
    for j in project.plan_positions:
        assert f"План скоростей, положение {j}" in tex, j
        assert f"План ускорений, положение {j}" in tex, j
        assert re.search(rf"Построим план ускорений для положения~{j} \(", tex), j
    # each plan with its own scale record and its own tables
    assert tex.count(r"\caption{Отрезки плана ускорений, положение") == len(project.plan_positions)
    assert tex.count(r"\caption{Отрезки плана скоростей, положение") == len(project.plan_positions)


def test_sheet_draws_both_plans_of_every_plan_position(built):
    project, _, _, doc = built
    texts = [e.dxf.text for e in _texts(doc)]
    on_sheet = dxf_vectors(doc)
    for j in project.plan_positions:
        assert f"План скоростей, положение {j}" in texts, j
        assert f"План ускорений, положение {j}" in texts, j
        for scene in (project.scenes.velocity_plans[j], project.scenes.acceleration_plans[j]):
            for e in scene.entities:
                if isinstance(e, Arrow) and e.length > 6.0:
                    assert any(abs(x - e.length) < 0.01 for x in on_sheet), (j, e.id, e.length)


def _table_rows(sheet, doc) -> list[tuple[str, str, str]]:
    """The rows of the table «Масштабы» read from the DXF: TEXT entities in the view, by line."""
    r = sheet.views["scales"].rect
    lines: dict[float, list] = {}
    for e in _texts(doc):
        x, y = e.dxf.insert.x, e.dxf.insert.y
        if r.x0 <= x <= r.x1 and r.y0 <= y <= r.y1 and e.dxf.text != "Масштабы":
            lines.setdefault(round(y, 1), []).append((x, e.dxf.text))
    rows = [tuple(t for _, t in sorted(v)) for _, v in sorted(lines.items(), reverse=True)]
    assert rows[0] == ("Обозн.", "Величина", "Масштаб"), rows[0]
    return rows[1:]


def test_scale_table_one_row_per_scale_with_the_notes_values(built):
    project, tex, sheet, doc = built
    rows = _table_rows(sheet, doc)
    assert all(len(r) == 3 for r in rows), rows
    assert len({r[:2] for r in rows}) == len(rows), rows           # every row names what it draws
    named: dict[str, dict[int, float]] = {"μv": {}, "μa": {}}
    for sym, name, value in rows:
        m = re.search(r"план[ы]? (?:скоростей|ускорений) положени[яй] ([\d, ]+)$", name)
        if m and sym in named:
            positions = [int(x) for x in m.group(1).split(",")]
            mu = _number(value.split()[0])
            for j in positions:
                assert j not in named[sym], (sym, j, rows)              # one row per position
                named[sym][j] = mu
    for sym, which in (("μv", 0), ("μa", 1)):
        assert sorted(named[sym]) == sorted(project.plan_positions), (sym, rows)
        values = [mu for mu in named[sym].values()]
        rows_of_sym = [r for r in rows if r[0] == sym and re.search(r"положени[яй] [\d, ]+$", r[1])]
        assert len(rows_of_sym) == len(set(values)), rows_of_sym      # positions sharing a μ share a row
        for j in project.plan_positions:
            plan = project.plans_by_position[j][which]
            assert named[sym][j] == pytest.approx(plan.scale, rel=1e-12)
            # the note prints the same μ for that position
            symbol = r"\mu_v" if which == 0 else r"\mu_a"
            assert symbol in tex


def test_note_prints_each_plan_scale(built):
    project, tex, *_ = built
    for j in project.plan_positions:
        v, a = project.plans_by_position[j]
        for plan in (v, a):
            shown = f"{plan.scale:g}".replace(".", "{,}")
            assert f"= {shown}" in tex, (j, plan.kind, shown)


def test_small_plans_letters_legible_apart_and_at_their_points(built):
    project, _, sheet, doc = built
    if "plans_all" not in sheet.views:
        pytest.skip("no room for the small plans on this sheet")
    rect = sheet.views["plans_all"].rect
    inside = lambda x, y: rect.x0 <= x <= rect.x1 and rect.y0 <= y <= rect.y1  # noqa: E731
    msp = doc.modelspace()
    heights = [e.dxf.height for e in msp.query("TEXT") if inside(e.dxf.insert.x, e.dxf.insert.y)]
    assert heights and min(heights) >= 2.5 - 1e-9, min(heights)
    points = [tuple(np.array(e.dxf.start)[:2]) for e in msp.query("LINE[layer=='vectors']")
              if inside(e.dxf.start.x, e.dxf.start.y)]
    points += [tuple(np.array(e.dxf.vtx0)[:2]) for e in msp.query("SOLID[layer=='vectors']")
               if inside(e.dxf.vtx0.x, e.dxf.vtx0.y)]
    leaders = [(tuple(np.array(e.dxf.start)[:2]), tuple(np.array(e.dxf.end)[:2]))
               for e in msp.query("LINE[layer=='thin']") if inside(e.dxf.start.x, e.dxf.start.y)]
    boxes = [(n, b) for n, b in sheet.annotations.boxes if n.startswith("plans_all") and b.centroid.within(rect.polygon())]
    # the plan letters (not the cells' numbers, the title or the μv caption); each cell is a canvas
    # of its own, «plans_all/<position>»
    letters = [(n, b) for n, b in boxes if re.fullmatch(r"plans_all/\d+: «(?!\d+»)[a-zπ_0-9, ]+»", n)]
    assert len(letters) >= len(project.phi), len(letters)
    for k, (n, b) in enumerate(boxes):
        for m, c in boxes[k + 1:]:
            assert b.intersection(c).area < 1e-6, (n, m)
    for n, b in letters:
        near = min(b.exterior.distance(Point(p)) for p in points)
        if near <= kp.SMALL_NEAR_MM + 1e-6:
            continue
        # a leader from the letters (inside the label's box) to the point
        led = any(min(b.distance(Point(q)) for q in (s, e)) < 1e-3 and
                  min(math.dist(p, s if b.distance(Point(e)) < b.distance(Point(s)) else e) for p in points) < 1e-3
                  for s, e in leaders)
        assert led, (n, near)
