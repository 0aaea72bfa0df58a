"""The designations of the meshing picture (sheet 4 and the note's figure): every circle, s, p and
αw named; no text over a tooth, no two texts overlapping — for the examples' pairs and for pairs no
example has (hypothesis over z1, z2, x1, x2); and, read back from sheet 4's DXF, no dimension text
over a tooth (the press's «30,618» crossed one)."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, example, given, settings, strategies as st
from shapely.geometry import Polygon, box

from reportgen.gears.meshing import meshing_picture
from reportgen.gears.pair import solve_gear_pair
from reportgen.project import Project
from reportgen.scenes.meshing import label_room, meshing_marks, meshing_scale
from reportgen.scenes.meshing_marks import CHAR_WIDTH, INSIDE_TEETH, TEXT_GAP, teeth_polygons
from reportgen.taskfile import load_task
from scene_readback import assert_marks_clear

ROOT = Path(__file__).resolve().parents[2]
GEAR_EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml")
                       if re.search(r"^\[gears\]", p.read_text(encoding="utf-8"), re.M))
NAMES = {f"{n}{i}" for n in ("r", "rb", "rw", "ra", "rf") for i in (1, 2)} | {
    "s1", "s2", "p", "alpha_w", "O1", "O2", "P", "N1", "N2", "a", "b"}


def _check(pair):
    pic = meshing_picture(pair, n_teeth=3, positions=241)
    scale = meshing_scale(pair, pic)
    marks = meshing_marks(pair, pic, scale)
    teeth = teeth_polygons(pic)
    names = {m.name for m in marks.marks}
    assert NAMES <= names, NAMES - names
    assert {d.name for d in marks.dimensions} == {"ab", "aw"}
    room = box(*label_room(pair, pic, scale))
    boxes = marks.boxes()
    for name, poly in boxes:
        for t in teeth:
            assert not poly.intersects(t.exterior), f"{name} across a tooth's outline"
            if name not in INSIDE_TEETH:
                assert not poly.intersects(t), f"{name} over a tooth"
        assert room.buffer(1e-9).contains(poly), f"{name} outside its view"
    for i, (n1, b1) in enumerate(boxes):
        for n2, b2 in boxes[i + 1:]:
            assert b1.intersection(b2).area < 1e-9, f"{n1} overlaps {n2}"
    # every designation is near what it names (a letter beside its point or on its leader)
    for m in marks.marks:
        if m.leader:
            assert math.dist(m.leader[0], m.anchor) < 1e-9
            x0, y0, x1, y1 = m.box
            end = m.leader[-1]
            # the shelf under the text (the box is the note's text, placed at its reduced page size)
            assert x0 - 1e-6 <= end[0] <= x1 + 1e-6 and abs(end[1] - y0) < 0.25 * (y1 - y0)
        else:
            assert box(*m.box).distance(Polygon([(m.anchor[0] - 1e-6, m.anchor[1]),
                                                 (m.anchor[0] + 1e-6, m.anchor[1]),
                                                 (m.anchor[0], m.anchor[1] + 1e-6)])) < 12.0 / marks.k
    # no two texts touch on the sheet: a gap of TEXT_GAP mm at least, the zones' numerals included
    k = marks.k
    named = boxes + marks.zone_boxes(k)
    for i, (n1, b1) in enumerate(named):
        for n2, b2 in named[i + 1:]:
            assert b1.distance(b2) * k >= TEXT_GAP - 1e-9, f"{n1} touches {n2} ({b1.distance(b2) * k:.2f} mm)"
    return marks


@pytest.mark.parametrize("name", GEAR_EXAMPLES)
def test_examples_marks_clear_of_teeth(name):
    project = Project(load_task(str(ROOT / "examples" / name / "task.toml")))
    _check(project.gears)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(z1=st.integers(10, 30), dz=st.integers(0, 50), m=st.sampled_from([2.0, 4.0, 5.0, 8.0, 12.0]),
       x1=st.floats(0.0, 0.8), x2=st.floats(-0.3, 0.8))
@example(z1=20, dz=12, m=4.0, x1=0.1875, x2=0.5)     # found by hypothesis: «I» 0,84 mm from «II»
def test_other_pairs_marks_clear_of_teeth(z1, dz, m, x1, x2):
    z2 = z1 + dz
    pair = solve_gear_pair(z1, z2, m, round(x1, 2), round(x2, 2))
    # a pair that can be made and meshes: teeth not pointed, no undercut, contact ratio above 1
    assume(all(pair.check(n).passed for n in ("sharpening1", "sharpening2", "undercut1", "undercut2")))
    assume(pair.geometry.eps_alpha > 1.0)
    _check(pair)


def test_sheet_font_fits_the_estimated_boxes():
    from drawings import style
    for text in ("rb1", "αw", "185,409", "O2", "30,618"):
        assert style.text_width(text, 3.5) <= CHAR_WIDTH * 3.5 * len(text) + 1e-9


def test_sheet4_dimension_texts_clear_of_teeth(tmp_path):
    """Read sheet 4 of the press back: each DIMENSION's text (in its geometry block) lies off every
    tooth, mapped to the sheet by the meshing view's transform; the designations are on the sheet."""
    import ezdxf

    from drawings.sheets import gears as gear_sheet
    from reportgen.commands.pipeline import draw_sheet
    from shapely import affinity

    project = Project(load_task(str(ROOT / "examples" / "press" / "task.toml")))
    sheet = draw_sheet(project, gear_sheet, 4, 4)
    path = tmp_path / "s4.dxf"
    sheet.save(path)
    doc = ezdxf.readfile(path)
    msp = doc.modelspace()
    tr_ = sheet.views["meshing"].transform
    teeth = [affinity.affine_transform(t, [tr_.scale, 0, 0, tr_.scale, tr_.at[0] - tr_.scale * tr_.origin[0],
                                           tr_.at[1] - tr_.scale * tr_.origin[1]])
             for t in teeth_polygons(meshing_picture(project.gears, n_teeth=3))]
    found = 0
    for dim in msp.query("DIMENSION"):
        block = dim.get_geometry_block()
        for e in block:
            if e.dxftype() not in ("MTEXT", "TEXT"):
                continue
            text = e.plain_text() if e.dxftype() == "MTEXT" else e.dxf.text
            h = e.dxf.char_height if e.dxftype() == "MTEXT" else e.dxf.height
            x, y = e.dxf.insert.x, e.dxf.insert.y
            w = CHAR_WIDTH * h * len(text)
            # centred on its insert (the dimension's attachment point is the text's middle)
            ang = math.radians(e.dxf.get("rotation", 0.0))
            ux, uy, nx, ny = math.cos(ang), math.sin(ang), -math.sin(ang), math.cos(ang)
            poly = Polygon([(x + ux * a + nx * b, y + uy * a + ny * b)
                            for a, b in ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2))])
            if poly.distance(sheet.views["meshing"].rect.polygon()) > 0:
                continue
            found += 1
            assert not any(poly.intersects(t) for t in teeth), f"dimension text «{text}» over a tooth"
    assert found == 2
    from labels.readback import sheet_names
    texts = {t.text for t in sheet_names(doc)}
    assert {"rb1", "ra2", "rf1", "rw2", "s1", "s2", "p", "αw"} <= texts


@pytest.mark.parametrize("name", ["press", "crank-slider"])
def test_note_figure_marks_clear_of_teeth(name):
    """The note's figure (a window of sheet 4's scene) places the sheet's designations by the same
    rule at its letter size: every
    circle, s, p, αw named, no text over a tooth, over another text, or outside the figure."""
    import matplotlib
    matplotlib.use("Agg")
    from latex_templates.figures.gears import meshing_figure, meshing_frame
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings

    project = Project(load_task(str(ROOT / "examples" / name / "task.toml")))
    ms = project.scenes.meshing
    pic = ms.pic
    with active_strings(Strings("ru")):
        fig = meshing_figure(project.gears, ms)
    marks = fig.reportgen_marks
    names = {m.name for m in marks.marks}
    assert {f"{n}{i}" for n in ("r", "rb", "rw", "ra", "rf") for i in (1, 2)} | {"s1", "s2", "p", "alpha_w"} <= names
    room = box(*meshing_frame(pic))
    teeth = teeth_polygons(pic)
    assert_marks_clear(marks.boxes(), room, teeth)


# -- sheet 4 at the corners of the blocking contour (issue 12) -----------------------------------

#: Two texts of sheet 4 closer than this (sheet mm, read back from the DXF) touch for a reader.
SHEET_GAP_MM = 1.0


def contour_corners(z1: int, z2: int, eps_min: float, n: int = 41) -> list[tuple[float, float]]:
    """The feasible shifts of the pair z1/z2 farthest in eight directions of the (x1, x2) plane (the
    corners of its blocking contour: the pairs at the limits of every check), to 0,01."""
    import numpy as np

    from reportgen.gears.shifts import blocking_contour
    bc = blocking_contour(z1, z2, n=n, eps_min=eps_min)
    X1, X2 = np.meshgrid(bc.x1, bc.x2, indexing="ij")
    pts = np.stack([X1[bc.feasible], X2[bc.feasible]], axis=1)
    out: list[tuple[float, float]] = []
    for d in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, -1), (1, -1), (-1, 1)):
        i = int(np.argmax(pts @ np.asarray(d, dtype=float)))
        p = (round(float(pts[i, 0]), 2), round(float(pts[i, 1]), 2))
        if p not in out:
            out.append(p)
    return out


def _corner_cases():
    out = []
    for name in GEAR_EXAMPLES:
        task = load_task(str(ROOT / "examples" / name / "task.toml"))
        if name.endswith(("-en", "-uk")):         # the same pairs in another language
            continue
        g = task.gears
        for x1, x2 in contour_corners(g.z1, g.z2, g.eps_min):
            out.append(pytest.param(name, x1, x2, id=f"{name}-{x1}-{x2}"))
    return out


def sheet4_text_gaps(project, tmp_path) -> list[str]:
    """Pairs of texts of sheet 4 (read back from its DXF: the meshing picture, the sliding diagram,
    the reducer; the title block's and the tables' cells left out) closer than SHEET_GAP_MM."""
    import ezdxf

    from drawings.sheets import gears as gear_sheet
    from reportgen.commands.pipeline import draw_sheet
    from labels.readback import sheet_names

    sheet = draw_sheet(project, gear_sheet, 4, 4)
    sheet.save(tmp_path / "s4.dxf")
    views = [v.rect.polygon() for name, v in sheet.views.items() if name in ("meshing", "sliding")]
    # a name with indices (a base and its smaller TEXTs) is one name
    texts = [t for t in sheet_names(ezdxf.readfile(tmp_path / "s4.dxf")) if any(t.box.intersects(v) for v in views)]
    found = []
    for i, a in enumerate(texts):
        for b in texts[i + 1:]:
            d = a.box.distance(b.box)
            if d < SHEET_GAP_MM:
                found.append(f"«{a.text}» / «{b.text}»: {d:.2f} mm")
    return found


@pytest.mark.parametrize("name,x1,x2", _corner_cases())
def test_sheet4_texts_apart_at_contour_corners(name, x1, x2, tmp_path):
    """Sheet 4 of a pair at a corner of its blocking contour: no two texts of the meshing picture
    and the sliding diagram touch (issue 12: «II» touched «αw», «a» touched the axis name «λ»; a
    pair with a at N1 stopped the sheet with a bare StopIteration)."""
    from dataclasses import replace

    task = load_task(str(ROOT / "examples" / name / "task.toml"))
    project = Project(replace(task, gears=replace(task.gears, x1=x1, x2=x2)))
    found = sheet4_text_gaps(project, tmp_path)
    assert not found, "\n".join(found)


@pytest.mark.parametrize("name", GEAR_EXAMPLES)
def test_sheet4_texts_apart(name, tmp_path):
    project = Project(load_task(str(ROOT / "examples" / name / "task.toml")))
    found = sheet4_text_gaps(project, tmp_path)
    assert not found, "\n".join(found)
