"""Sheet 1 «Кинематический анализ рычажного механизма» on every example: it is drawn, valid DXF,
nothing overlaps, the plan arrows have the lengths of the plan components, the numbers come from
the result objects, LibreCAD draws it, and the same input gives the same bytes."""
from __future__ import annotations

import math
from pathlib import Path

import ezdxf
import numpy as np
import pytest

from reportgen import gost_scales

from drawings.librecad import check_sheet, missing_tools
from drawings.primitives import format_number, format_significant
from drawings.sheets import available_sheets, kinematics
from drawings.scenes import kinematics_labels as rl
from reportgen.plans import build_plans
from reportgen.project import Project
from reportgen.taskfile import load_task
from scene_readback import drawn_sheet, example_project

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3")


def project_of(name: str) -> Project:
    return Project(load_task(ROOT / "examples" / name / "task.toml"))


@pytest.fixture(scope="module")
def sheets(tmp_path_factory):
    return {name: (example_project(name), drawn_sheet(name, kinematics, 1, tmp_path_factory.mktemp(name))[0])
            for name in EXAMPLES}


@pytest.mark.parametrize("name", EXAMPLES)
def test_registered_and_drawn(name, sheets):
    project, sheet = sheets[name]
    assert any(mod is kinematics for _, mod in available_sheets(project))
    assert {"scheme", "plan_v", "plan_a", "diagrams", "scales"} <= set(sheet.views)
    assert kinematics.TITLE in " ".join(sheet.title_block_texts()).replace("\n", " ") or \
        "Кинематический" in " ".join(sheet.title_block_texts())


@pytest.mark.parametrize("name", EXAMPLES)
def test_audit_has_no_errors(name, sheets, tmp_path):
    _, sheet = sheets[name]
    path = tmp_path / "s1.dxf"
    sheet.save(path)
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]


@pytest.mark.parametrize("name", EXAMPLES)
def test_nothing_overlaps(name, sheets):
    _, sheet = sheets[name]
    assert sheet.overlaps() == []


def _texts(sheet) -> list[str]:
    return [e.dxf.text for e in sheet.msp.query("TEXT")]


def _solids(sheet):
    return [e for e in sheet.msp.query("SOLID") if e.dxf.layer == "vectors"]


def _lines(sheet):
    return [e for e in sheet.msp.query("LINE") if e.dxf.layer == "vectors"]


def _arrow_drawn(sheet, start, end) -> float | None:
    """Length of an arrow drawn from sheet point ``start`` with its head's tip at ``end``: a
    vectors SOLID with its tip at ``end`` and a vectors LINE from ``start`` towards it."""
    tip_ok = any(math.dist((s.dxf.vtx0.x, s.dxf.vtx0.y), end) < 1e-6 for s in _solids(sheet))
    d = math.dist(start, end)
    if d < 1e-6:
        return 0.0
    u = ((end[0] - start[0]) / d, (end[1] - start[1]) / d)
    shaft_ok = d <= 5.0 * 0.9 + 1e-6       # a short arrow is all head
    for ln in _lines(sheet):
        a = (ln.dxf.start.x, ln.dxf.start.y)
        b = (ln.dxf.end.x, ln.dxf.end.y)
        if math.dist(a, start) < 1e-6:
            lb = math.dist(a, b)
            if lb > 0 and abs((b[0] - a[0]) / lb - u[0]) < 1e-6 and abs((b[1] - a[1]) / lb - u[1]) < 1e-6:
                shaft_ok = True
    return d if tip_ok and shaft_ok else None


@pytest.mark.parametrize("name", EXAMPLES)
def test_plan_arrows_have_the_component_lengths(name, sheets):
    project, sheet = sheets[name]
    i = kinematics.analysed_position(project)
    vplan, aplan = build_plans(project.linkage, project.structure, project.kinematics, i)
    for view_name, plan in (("plan_v", vplan), ("plan_a", aplan)):
        tr = sheet.views[view_name].transform
        assert tr.scale == 1.0                           # the plan is drawn at its own scale
        for c in plan.components:
            start, end = tr(plan.points[c.start]), tr(plan.points[c.end])
            drawn = _arrow_drawn(sheet, start, end)
            if not plan.drawn(c):        # a computed component under LEGIBLE_MM is not laid off
                assert drawn is None or plan.length_mm(c) < 1e-6, (view_name, c.name)
                continue
            assert drawn is not None, (view_name, c.name)
            assert drawn == pytest.approx(plan.length_mm(c), abs=1e-6), (view_name, c.name)


@pytest.mark.parametrize("name", EXAMPLES)
def test_scale_captions_come_from_the_results(name, sheets):
    project, sheet = sheets[name]
    i = kinematics.analysed_position(project)
    vplan, aplan = build_plans(project.linkage, project.structure, project.kinematics, i)
    texts = _texts(sheet)
    assert f"μv = {format_significant(vplan.scale, 4)} (м/с)/мм" in texts
    assert f"μa = {format_significant(aplan.scale, 4)} (м/с²)/мм" in texts
    assert f"План скоростей, положение {i}" in texts
    assert f"План ускорений, положение {i}" in texts
    d = kinematics.diagrams_of(project)
    assert any(t.endswith(f"{format_significant(d.mu_v, 4)} {kinematics.kd.names(d).mu_v}") for t in texts)
    assert f"{format_significant(d.mu_t, 4)} с/мм" in texts
    dims = [e.dxf.text for e in sheet.msp.query("DIMENSION")]
    assert f"H1 = {format_number(d.H1, 1)}" in dims and f"H2 = {format_number(d.H2, 1)}" in dims
    # the stroke H of a slider, in mm, from Strokes
    if project.strokes.output.kind == "slider":
        assert f"H = {format_number(project.strokes.stroke * 1000.0, 1)}" in dims


@pytest.mark.parametrize("name", EXAMPLES)
def test_scheme_scale_is_gost_and_positions_are_numbered(name, sheets):
    project, sheet = sheets[name]
    k = sheet.views["scheme"].transform.scale
    assert any(math.isclose(k, 1000.0 * gost_scales.factor(s)) for s in gost_scales.GOST_2_302)
    texts = _texts(sheet)
    for j in range(len(project.phi)):
        assert str(j) in texts
    assert "0'" in texts or "к.р.х." in texts


def test_labels_with_indices():
    assert rl.from_tex(r"a^{\tau}_{BA}") == rl.Rich("a", "τ", "BA")
    assert rl.from_tex(r"a^{k}_{A_{3}A}") == rl.Rich("a", "k", "A3A")
    assert rl.from_tex("V_{D}") == rl.Rich("V", "", "D")
    assert rl.from_letter("s2") == rl.Rich("s", "", "2")
    assert rl.from_letter("nba", helpers=True) == rl.Rich("n", "", "ba")
    assert rl.from_letter("π") == rl.Rich("π")


def test_same_input_same_bytes(tmp_path):
    a, b = tmp_path / "a.dxf", tmp_path / "b.dxf"
    kinematics.draw(project_of("shaper"), 1, 4).save(a)
    kinematics.draw(project_of("shaper"), 1, 4).save(b)
    assert a.read_bytes() == b.read_bytes()


def test_trajectories_are_dense(sheets):
    project, sheet = sheets["press"]
    closed = [e for e in sheet.msp.query("LWPOLYLINE") if e.closed and e.dxf.layer == "thin"]
    assert len(closed) >= 3                          # S2, S3, S4 of the press
    assert all(len(e) >= 120 for e in closed if len(e) > 8)
    assert np.isfinite([p[0] for e in closed for p in e.get_points("xy")]).all()


@pytest.mark.slow
@pytest.mark.skipif(bool(missing_tools()), reason=f"missing: {missing_tools()}")
@pytest.mark.parametrize("name", ("press", "shaper"))
def test_librecad_draws_the_sheet(name, sheets, tmp_path):
    _, sheet = sheets[name]
    path = tmp_path / "sheet1.dxf"
    sheet.save(path)
    result = check_sheet(path, tmp_path / "out")
    assert result.drawn, result


@pytest.mark.parametrize("name", EXAMPLES)
def test_links_are_numbered_in_circles(name, sheets):
    project, sheet = sheets[name]
    r = kinematics.ks.LINK_NUMBER_MM[0]
    circles = [(c.dxf.center.x, c.dxf.center.y) for c in sheet.msp.query("CIRCLE")
               if abs(c.dxf.radius - r) < 1e-9]
    texts = {e.dxf.text: [] for e in sheet.msp.query("TEXT")}
    for e in sheet.msp.query("TEXT"):
        texts[e.dxf.text].append((e.dxf.align_point.x, e.dxf.align_point.y))
    scheme = sheet.views["scheme"].rect
    for k in project.linkage.moving:
        spots = [p for p in texts.get(str(k), []) if any(math.dist(p, c) < 1e-6 for c in circles)]
        assert spots, f"link {k} has no circled number"
        assert all(scheme.x0 < x < scheme.x1 and scheme.y0 < y < scheme.y1 for x, y in spots)


@pytest.mark.parametrize("name", EXAMPLES)
def test_plans_of_the_analysed_position_stay_together(name, sheets):
    project, sheet = sheets[name]
    v, a = sheet.views["plan_v"].rect, sheet.views["plan_a"].rect
    gap = kinematics.PAIR_GAP
    side_by_side = (math.isclose(v.y0, a.y0) and math.isclose(v.y1, a.y1)
                    and gap - 1e-6 <= a.x0 - v.x1 <= 2 * gap)
    stacked = math.isclose(v.x0, a.x0) and math.isclose(v.x1, a.x1) and math.isclose(v.y0 - a.y1, gap)
    assert side_by_side or stacked, (v, a)
    # no two views closer than the packer's gap, but a plan position's two plans (PAIR_GAP)
    pairs = {frozenset(kinematics.plan_view_names(j, j == project.analysed)) for j in project.plan_positions}
    views = list(sheet.views.items())
    for i, (n, w) in enumerate(views):
        for m, u in views[i + 1:]:
            gap = kinematics.PAIR_GAP if frozenset((n, m)) in pairs else kinematics.VIEW_GAP
            assert not w.rect.expanded(gap - 1e-6).overlaps(u.rect), (n, m)
