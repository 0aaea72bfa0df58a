"""Sheet 2: every example draws a sheet whose DXF passes the audit, on which nothing overlaps, whose
force polygons close on the drawing (the last arrowhead's tip at the first vector's start), whose
scales are the replica's; LibreCAD prints it."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import ezdxf
import pytest

sys.path.insert(0, str(Path(__file__).parent))
from kst_build import EXAMPLES, project_of  # noqa: E402

from drawings.sheets import kinetostatics as sheet2  # noqa: E402
from reportgen.kinetostatics.results import kinetostatics_of  # noqa: E402


@pytest.fixture(scope="module", params=EXAMPLES)
def drawn(request, tmp_path_factory):
    project = project_of(request.param)
    sheet = sheet2.draw(project, 2, 4)
    path = tmp_path_factory.mktemp(request.param) / "sheet2.dxf"
    sheet.save(path)
    return project, sheet, path


def test_kst_sheet_audit_and_overlaps(drawn):
    project, sheet, path = drawn
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e) for e in auditor.errors]
    assert sheet.overlaps() == []
    texts = " ".join(e.dxf.text for e in doc.modelspace().query("TEXT"))
    assert sheet2.TITLE.split()[0] in texts
    assert "Рычаг Жуковского" in texts


def _tips(doc) -> list[tuple[float, float]]:
    return [(s.dxf.vtx0.x, s.dxf.vtx0.y) for s in doc.modelspace().query("SOLID")]


def test_kst_sheet_polygons_close(drawn):
    project, sheet, path = drawn
    ks = kinetostatics_of(project)
    doc = ezdxf.readfile(path)
    tips = _tips(doc)
    polys = {f"polygon {gg.key}": gg.polygon for gg in ks.graphical.groups}
    polys["polygon crank"] = ks.graphical.crank.polygon
    texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
    for name, poly in polys.items():
        view = sheet.views[name]
        first = view.transform(tuple(poly.vectors[0].start_mm))
        last = [v for v in poly.vectors if math.dist(v.start_mm, v.end_mm) > 1e-6][-1]
        tip = view.transform(tuple(last.end_mm))
        assert math.dist(tip, first) < 0.5, name
        # an arrowhead really ends there on the drawing
        assert min(math.dist(t, first) for t in tips) < 0.5, name
        assert any(t.startswith("μF = ") and t.split("= ")[1].split()[0] ==
                   f"{poly.scale:g}".replace(".", ",") for t in texts), name


@pytest.mark.slow
def test_kst_sheet_librecad(tmp_path):
    from drawings.librecad import check_sheet, missing_tools
    if missing_tools():
        pytest.skip(f"missing: {missing_tools()}")
    project = project_of("press")
    path = tmp_path / "sheet2.dxf"
    sheet2.draw(project, 2, 4).save(path)
    result = check_sheet(path, tmp_path)
    assert result.drawn, result.ink
