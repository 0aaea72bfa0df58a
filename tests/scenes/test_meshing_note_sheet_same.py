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
from shapely.geometry import Point, box

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
    assert min(m.page_h for m in marks.marks) >= 2.5          # page mm: legible at the note's reduction
    names = {m.name for m in marks.marks}
    assert {f"{n}{i}" for n in ("r", "rb", "rw", "ra", "rf") for i in (1, 2)} | {"s1", "s2", "p", "alpha_w"} <= names
    teeth = teeth_polygons(project.scenes.meshing.pic)
    xlim, ylim = fig.axes[0].get_xlim(), fig.axes[0].get_ylim()
    k = project.scenes.meshing.scale.factor
    room = box(xlim[0] / k, ylim[0] / k, xlim[1] / k, ylim[1] / k)
    assert_marks_clear(marks.boxes(), room, teeth)


def _note_texts(fig, k: float) -> dict[str, list]:
    """The note figure's texts: their string → [(centre, box)] in real mm (the axes are scene mm)."""
    from shapely.geometry import box as sbox
    ax = fig.axes[0]
    renderer = fig.canvas.get_renderer()
    inv = ax.transData.inverted()
    out: dict[str, list] = {}
    for t in ax.texts:
        bb = t.get_window_extent(renderer)
        (x0, y0), (x1, y1) = inv.transform((bb.x0, bb.y0)), inv.transform((bb.x1, bb.y1))
        b = sbox(x0 / k, y0 / k, x1 / k, y1 / k)
        out.setdefault(t.get_text(), []).append(((b.centroid.x, b.centroid.y), b))
    return out


def _sheet_texts(drawn, doc) -> dict[str, list]:
    """Sheet 4's texts inside the meshing view: their string → [centre] in real mm."""
    from labels.readback import mtext_box, text_box
    view = drawn.views["meshing"]
    tr_ = view.transform
    rect = view.rect.polygon()

    def real(p):
        return ((p[0] - tr_.at[0]) / tr_.scale + tr_.origin[0], (p[1] - tr_.at[1]) / tr_.scale + tr_.origin[1])
    out: dict[str, list] = {}
    msp = doc.modelspace()
    for e in msp.query("TEXT"):
        b = text_box(e)
        if b.intersects(rect):
            out.setdefault(e.plain_text(), []).append(real((b.centroid.x, b.centroid.y)))
    prefix = f"{view.name}: «"            # a name with indices (r_b1, α_w): its letters' box as placed
    for name, b in drawn.annotations.boxes:
        if name.startswith(prefix) and ("_" in name or "^" in name) and b.intersects(rect):
            out.setdefault(name[len(prefix):-1], []).append(real((b.centroid.x, b.centroid.y)))
    for d in msp.query("DIMENSION"):
        for v in d.virtual_entities():
            if v.dxftype() == "MTEXT":
                b = mtext_box(v)
                if b.intersects(rect):
                    out.setdefault(v.plain_text(), []).append(real((b.centroid.x, b.centroid.y)))
    return out


def test_designations_at_the_same_places_in_note_and_sheet(built, request, tmp_path):
    """Issue 12: the note's figure placed its designations itself, at its own letter size, and the
    dimension «30,618» came out on the other side of ab from sheet 4's. Read back: every designation
    the note's figure draws is on sheet 4 at the same place relative to the picture (the sheet's
    text inside the note's text box, real mm, with a millimetre of the sheet to spare), and the
    dimension ab's text is on the same side of ab in both."""
    from drawings.lettering import from_tex
    from scene_readback import drawn_sheet
    project, content, doc = built
    fig, _ = _scene(content)
    ms = project.scenes.meshing
    k = ms.scale.factor
    drawn, _ = drawn_sheet(request.node.callspec.params["built"], sheet4, 4, tmp_path)
    note, sheet = _note_texts(fig, k), _sheet_texts(drawn, doc)
    from drawings.words import tr
    checked = 0
    for m in fig.reportgen_marks.marks:            # what the note's figure draws
        spelt = tr(f"marks.sheet4.{m.text}") if m.word else m.text
        if not m.word and ("_" in m.tex or "^" in m.tex):       # lettered with its index
            from drawings.scenes.kinematics_labels import label_name
            spelt = label_name(from_tex(m.tex))
        ((c, b),) = note[f"${m.tex}$"]
        places = sheet.get(spelt, [])
        assert places, f"«{spelt}» is in the note's figure, not on sheet 4"
        near = min(places, key=lambda p: math.dist(p, c))
        assert b.buffer(1.0 / k).contains(Point(near)), (
            f"«{spelt}»: the note draws it at {c}, sheet 4 at {near} (real mm)")
        checked += 1
    assert checked >= 14
    pa, pb = ms.pic.points["a"], ms.pic.points["b"]

    def side(p) -> float:
        return math.copysign(1.0, (pb[0] - pa[0]) * (p[1] - pa[1]) - (pb[1] - pa[1]) * (p[0] - pa[0]))
    ab = next(d for d in fig.reportgen_marks.dimensions if d.name == "ab")
    ((c_note, _),) = note[ab.text]
    on_sheet = [p for p in sheet.get(ab.text, [])]
    assert len(on_sheet) == 1, f"the dimension ab «{ab.text}» on sheet 4: {on_sheet}"
    assert side(on_sheet[0]) == side(c_note), f"«{ab.text}» on the other side of ab in the note and on sheet 4"
