"""One construction drawn twice, section 1: the note's figure of the s–v–a diagrams and sheet 1 draw
the same scene (reportgen.scenes.output_diagrams): the curves through the measured nodes and the
steps' middles have the lengths of the sheet's polylines read back from its DXF, and the pole
distances and scales the note prints are the sheet's."""
from __future__ import annotations

import math
from pathlib import Path

import ezdxf
import pytest

from drawings.primitives import format_number
from drawings.sheets import kinematics as sheet1
from latex_templates.parts import kinematics as part
from reportgen.project import Project
from reportgen.scenes.scene import Polyline
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "shaper", "conveyor")


@pytest.fixture(scope="module", params=EXAMPLES)
def built(request, tmp_path_factory):
    project = Project(load_task(ROOT / "examples" / request.param / "task.toml"))
    content = part.content(project)
    path = tmp_path_factory.mktemp(request.param) / "sheet1.dxf"
    sheet1.draw(project, 1, 4).save(path)
    return project, content, ezdxf.readfile(path)


def _length(points) -> float:
    return sum(math.dist(p, q) for p, q in zip(points[:-1], points[1:]))


def test_curves_have_the_sheets_lengths(built):
    _, content, doc = built
    scene = content.figures["kin_diagrams"].scene
    on_sheet = [_length([tuple(p)[:2] for p in e.get_points("xy")])
                for e in doc.modelspace().query("LWPOLYLINE[layer=='contour']")]
    for id_ in ("s:curve", "v:curve", "a:curve"):
        e = scene.entity(id_)
        assert isinstance(e, Polyline)
        assert any(abs(x - _length(e.points)) < 1e-6 for x in on_sheet), (id_, _length(e.points))


def test_poles_and_scales_printed_by_note_are_the_sheets(built):
    _, content, doc = built
    diag = content.context["diag"]
    scene = content.figures["kin_diagrams"].scene
    dims = [e.dxf.text for e in doc.modelspace().query("DIMENSION")]
    for k in ("H1", "H2"):
        assert f"{k} = {format_number(scene.values[k], 1)}" in dims
    assert diag["mu_s"] == scene.scales[0].value
    assert diag["mu_v"].value == pytest.approx(scene.scales[1].value, rel=1e-12)
    assert diag["mu_a"].value == pytest.approx(scene.scales[2].value, rel=1e-12)
