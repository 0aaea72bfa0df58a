"""One construction drawn twice (issue 13): the note's meshing figure (section 4) is a window of
sheet 4's meshing scene (:class:`reportgen.scenes.meshing.MeshingScene`). For every example with a
gear pair, each tooth of the note's figure data is an LWPOLYLINE of sheet 4's DXF and ab, N1N2 are
its LINEs — the same lengths, at the same places relative to each other (one translation: the
sheet draws the scene's mm at its scale, 1:1); the figure says it is reduced exactly when it is;
|ab| the note reads is the scene's, and the note's designations stay inside its window, off the
teeth and off each other."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest
from shapely.geometry import box

from drawings.sheets import gears as sheet4
from latex_templates.parts import gear_pair as part
from reportgen.scenes.meshing_marks import teeth_polygons
from reportgen.scenes.scene import Polyline, Segment
from scene_readback import ROOT, assert_marks_clear, part_and_sheet

GEAR_EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml")
                       if re.search(r"^\[gears\]", p.read_text(encoding="utf-8"), re.M))
TOL = 0.01       # sheet mm


@pytest.fixture(scope="module", params=GEAR_EXAMPLES)
def built(request, tmp_path_factory):
    return part_and_sheet(request.param, part, sheet4, 4, tmp_path_factory.mktemp(request.param))


def _scene(content):
    fig = content.figures["gear_pair_meshing"]
    scene = getattr(fig, "scene", None)
    assert scene is not None, "the note's meshing figure is not drawn from a scene"
    return fig, scene


def test_meshing_geometry_same_in_note_and_sheet(built):
    _, content, doc = built
    _, scene = _scene(content)
    msp = doc.modelspace()
    polys = [np.array([(p[0], p[1]) for p in e.get_points("xy")]) for e in msp.query("LWPOLYLINE[layer=='contour']")]
    lines = [(np.array(e.dxf.start)[:2], np.array(e.dxf.end)[:2]) for e in msp.query("LINE")]
    teeth = [np.asarray(e.points) for e in scene.entities if isinstance(e, Polyline) and e.id.startswith("tooth")]
    assert len(teeth) >= 4
    first = teeth[0]
    shift = None
    for p in polys:
        if p.shape == first.shape and np.allclose(p - p[0], first - first[0], atol=TOL):
            shift = p[0] - first[0]
            break
    assert shift is not None, "the note's first tooth is not on the sheet"
    for t in teeth:
        assert any(p.shape == t.shape and np.allclose(p, t + shift, atol=TOL) for p in polys), "a tooth moved"
    for ident in ("ab", "N1N2"):
        e = next(x for x in scene.entities if isinstance(x, Segment) and x.id == ident)
        a, b = np.asarray(e.a) + shift, np.asarray(e.b) + shift
        assert any(min(np.hypot(*(s - a)) + np.hypot(*(f - b)), np.hypot(*(s - b)) + np.hypot(*(f - a))) < TOL
                   for s, f in lines), ident


def test_meshing_caption_and_ab_from_the_scene(built):
    project, content, _ = built
    fig, scene = _scene(content)
    c = content.context
    assert c["ab_read"].value == scene.values["ab"]
    assert math.isclose(c["scale"].factor, scene.scale().value, rel_tol=1e-12)
    from latex_templates.render import Strings
    strings = Strings(project.task.document.language or "ru")
    word = "scenes.reduced" if fig.reportgen_reduction < 1.0 else "scenes.natural"
    assert str(c["mesh_note"]) == str(strings.get(word)).format(sheet=4)
    # the page size is the window at the scene's mm times the reduction
    x0, x1 = fig.axes[0].get_xlim()
    assert fig.get_figwidth() * 25.4 == pytest.approx((x1 - x0) * fig.reportgen_reduction, rel=1e-6)


def test_meshing_note_designations_legible_and_clear(built):
    project, content, _ = built
    fig, _ = _scene(content)
    marks = fig.reportgen_marks
    assert min(m.height for m in marks.marks) >= 2.5          # page mm: legible at the note's reduction
    names = {m.name for m in marks.marks}
    assert {f"{n}{i}" for n in ("r", "rb", "rw", "ra", "rf") for i in (1, 2)} | {"s1", "s2", "p", "alpha_w"} <= names
    teeth = teeth_polygons(project.scenes.meshing.pic)
    xlim, ylim = fig.axes[0].get_xlim(), fig.axes[0].get_ylim()
    k = project.scenes.meshing.scale.factor
    room = box(xlim[0] / k, ylim[0] / k, xlim[1] / k, ylim[1] / k)
    assert_marks_clear(marks.boxes(), room, teeth)
