"""One construction drawn twice, section 1: the note's figure of the s–v–a diagrams and sheet 1 draw
the same scene (reportgen.scenes.output_diagrams): the curves through the measured nodes and the
steps' middles have the lengths of the sheet's polylines read back from its DXF, and the pole
distances and scales the note prints are the sheet's."""
from __future__ import annotations

from pathlib import Path

import pytest

from drawings.primitives import format_number
from drawings.sheets import kinematics as sheet1
from latex_templates.parts import kinematics as part
from reportgen.scenes.scene import Polyline
from scene_readback import part_and_sheet, polyline_length

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "shaper", "conveyor")


@pytest.fixture(scope="module", params=EXAMPLES)
def built(request, tmp_path_factory):
    return part_and_sheet(request.param, part, sheet1, 1, tmp_path_factory.mktemp(request.param))


def test_curves_have_the_sheets_lengths(built):
    _, content, doc = built
    scene = content.figures["kin_diagrams"].scene
    on_sheet = [polyline_length([tuple(p)[:2] for p in e.get_points("xy")])
                for e in doc.modelspace().query("LWPOLYLINE[layer=='contour']")]
    for id_ in ("s:curve", "v:curve", "a:curve"):
        e = scene.entity(id_)
        assert isinstance(e, Polyline)
        assert any(abs(x - polyline_length(e.points)) < 1e-6 for x in on_sheet), (id_, polyline_length(e.points))


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
