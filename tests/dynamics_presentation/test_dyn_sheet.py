"""Sheet 3 (dynamics): drawn for every example with [dynamics], DXF audit clean, nothing overlaps, the
KL dimension is the replica's KL, the table holds the solver's numbers, LibreCAD draws it."""
from __future__ import annotations

import math
from pathlib import Path

import ezdxf
import pytest

from drawings.librecad import check_sheet, missing_tools
from drawings.primitives import format_number, format_significant
from drawings.sheets import available_sheets, dynamics
from reportgen.project import Project
from reportgen.taskfile import load_task

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
def _russian(path) -> bool:
    """The examples written in Russian (these tests read Russian text; tests/lang covers uk and en)."""
    import tomllib
    return tomllib.loads(path.read_text(encoding="utf-8")).get("document", {}).get("language", "ru") == "ru"


NAMES = sorted(p.parent.name for p in EXAMPLES.glob("*/task.toml")
               if load_task(p).dynamics is not None and _russian(p))


@pytest.fixture(scope="module")
def sheets():
    out = {}
    for name in NAMES:
        project = Project(load_task(EXAMPLES / name / "task.toml"))
        out[name] = (project, dynamics.draw(project, 3, 4))
    return out


def test_examples_have_dynamics():
    assert {"press", "shaper", "crank-slider", "conveyor"} <= set(NAMES)


@pytest.mark.parametrize("name", NAMES)
def test_registered(name, sheets):
    project, _ = sheets[name]
    assert any(mod is dynamics for _, mod in available_sheets(project))


@pytest.mark.parametrize("name", NAMES)
def test_audit_has_no_errors(name, sheets, tmp_path):
    _, sheet = sheets[name]
    path = tmp_path / "s.dxf"
    sheet.save(path)
    doc = ezdxf.readfile(path)
    assert not doc.audit().has_errors


@pytest.mark.parametrize("name", NAMES)
def test_nothing_overlaps(name, sheets):
    _, sheet = sheets[name]
    assert sheet.overlaps() == []


def _dimensions(sheet):
    return [e for e in sheet.msp if e.dxftype() == "DIMENSION"]


@pytest.mark.parametrize("name", NAMES)
def test_kl_dimension_is_the_replicas_kl(name, sheets):
    project, sheet = sheets[name]
    g = project.dynamics.graphical
    found = [d for d in _dimensions(sheet) if d.dxf.text == format_number(g.KL_mm, 1)]
    assert found, "no dimension shows KL"
    d = found[0]
    p, q = d.dxf.defpoint2, d.dxf.defpoint3
    measured = math.hypot(p[0] - q[0], p[1] - q[1])    # the sheet is 1:1 in mm
    assert measured == pytest.approx(g.KL_mm, abs=1e-6)
    assert math.isclose(abs(p[0] - q[0]), 0.0, abs_tol=1e-9)   # on the ΔE axis, vertical


@pytest.mark.parametrize("name", NAMES)
def test_table_and_titles_come_from_the_results(name, sheets):
    project, sheet = sheets[name]
    res = project.dynamics
    texts = {e.dxf.text for e in sheet.msp if e.dxftype() == "TEXT"}
    assert format_significant(res.J_flywheel, 4) in texts
    assert format_significant(res.merzalov.J_fly, 4) in texts
    assert format_significant(res.graphical.J_fly, 4) in texts
    assert format_significant(res.delta_achieved, 4) in texts
    assert format_number(res.graphical.psi_max_deg, 2) in texts
    assert f"H = {format_number(res.graphical.H, 0)}" in {d.dxf.text for d in _dimensions(sheet)}
    assert "Динамический анализ машинного агрегата" in " ".join(sheet.title_block_texts())


@pytest.mark.parametrize("name", NAMES)
def test_flywheel_dimensions_are_real_mm(name, sheets):
    project, sheet = sheets[name]
    fw = project.dynamics.flywheel
    dims = {d.dxf.text for d in _dimensions(sheet)}
    assert f"Ø{format_number(2000 * fw.radius, 0)}" in dims
    assert format_number(1000 * fw.width, 0) in dims


@pytest.mark.parametrize("name", NAMES)
def test_wittenbauer_shares_the_j_axis_with_j_red(name, sheets):
    _, sheet = sheets[name]
    w, j = sheet.views["wittenbauer"], sheet.views["inertia"]
    assert w.transform((0, 0))[0] == pytest.approx(j.transform((0, 0))[0])
    assert j.rect.y1 <= w.rect.y0


@pytest.mark.slow
@pytest.mark.skipif(bool(missing_tools()), reason=f"missing: {missing_tools()}")
def test_librecad_draws_the_sheet(sheets, tmp_path):
    _, sheet = sheets["press"]
    dxf = tmp_path / "sheet3.dxf"
    sheet.save(dxf)
    result = check_sheet(dxf, tmp_path / "lc")
    assert result.drawn, result
