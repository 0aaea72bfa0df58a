"""One construction drawn twice: the note's figures of section 1 and sheet 1 draw the same scene.
The plan's arrows and the bold position's links in the note's figure data have the lengths of the
vectors and links read back from the sheet's DXF entities; the scales printed by the note are the
sheet's (read back from its texts)."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from drawings.sheets import kinematics as sheet1
from latex_templates.parts import kinematics as part
from reportgen.scenes.scene import Arrow, Segment
from scene_readback import dxf_vectors, part_and_sheet

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ("press", "crank-slider", "shaper", "conveyor", "class3")


@pytest.fixture(scope="module", params=EXAMPLES)
def built(request, tmp_path_factory):
    return part_and_sheet(request.param, part, sheet1, 1, tmp_path_factory.mktemp(request.param))


def _lines(doc, layer: str) -> list[float]:
    return [math.dist(tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]) for e in doc.modelspace().query(f"LINE[layer=='{layer}']")]


def _texts(doc) -> list[str]:
    return [e.dxf.text for e in doc.modelspace().query("TEXT")]


def _number(s: str) -> float:
    return float(s.replace(",", ".").replace("\u2212", "-"))


def test_plan_segments_equal_in_note_and_sheet(built):
    _, content, doc = built
    on_sheet = dxf_vectors(doc)
    for name in ("kin_vplan", "kin_aplan"):
        scene = content.figures[name].scene
        for e in scene.entities:
            if isinstance(e, Arrow) and e.length > 6.0:          # longer than a head: drawn with a shaft
                assert any(abs(x - e.length) < 0.01 for x in on_sheet), (name, e.id, e.length)


def test_positions_links_equal_in_note_and_sheet(built):
    project, content, doc = built
    scene = content.figures["kin_positions"].scene
    contour = _lines(doc, "contour")
    i = project.analysed
    checked = 0
    for e in scene.entities:
        if isinstance(e, Segment) and e.id.startswith(f"pos{i}:link") and e.length > sum(e.trim) + 1.0:
            drawn = e.length - sum(e.trim)
            assert any(abs(x - drawn) < 0.01 for x in contour), (e.id, drawn)
            checked += 1
    assert checked >= 2


def test_scales_printed_by_note_are_the_sheets(built):
    _, content, doc = built
    texts = _texts(doc)
    c = content.context
    mu_l = next(_number(m.group(1)) for t in texts if (m := re.match(r"μl = ([\d,]+) м/мм", t)))
    assert mu_l == pytest.approx(c["mu_l"].value, rel=1e-9)
    captions = [(m.group(1), _number(m.group(2))) for t in texts
                if (m := re.match(r"(μ[va]) = ([\d,]+) \(м/с²?\)/мм$", t))]
    assert any(s == "μv" and math.isclose(v, c["vplan"].scale, rel_tol=1e-9) for s, v in captions), captions
    assert any(s == "μa" and math.isclose(v, c["aplan"].scale, rel_tol=1e-9) for s, v in captions), captions
    assert c["OA_mm"].value == pytest.approx(content.figures["kin_positions"].scene.values[
        next(iter(content.figures["kin_positions"].scene.values))])


def test_note_labels_do_not_overlap_and_stay_near(built):
    _, content, _ = built
    for name in ("kin_positions", "kin_vplan", "kin_aplan"):
        fig = content.figures[name]
        placed = fig.reportgen_labels
        r = fig.reportgen_reduction
        for k, a in enumerate(placed):
            assert a.distance * r < 6.0, (name, a.text, a.distance * r)      # page mm
            for b in placed[k + 1:]:
                ov = min(a.box[2], b.box[2]) - max(a.box[0], b.box[0]), min(a.box[3], b.box[3]) - max(a.box[1], b.box[1])
                assert not (ov[0] > 1e-6 and ov[1] > 1e-6), (name, a.text, b.text)
