"""The control work's one sheet draws the mechanism as large as the sheet holds, and letters it
legibly (issue 12).

On main the A3 sheet capped the mechanism at a fixed 90 × 90 mm box and reserved sheet 1's pads round
it (28–38 mm for the crank angles and the stroke that a control work never draws): table 4 variant 1
drew its mechanism 55 mm wide at 1:25 beside 120 × 140 mm of empty field, table 1 37 × 43 mm at
1:40 with «S₂», «②», «B» piled at joint A. The checks read the sheet back from its DXF:

- the chosen scale is tight: at the next larger ГОСТ 2.302 scale the mechanism's drawing (what the
  scheme's view draws now, its model part enlarged, the title and caption as they are) finds no room
  in the free field beside what the other views draw (their drawings kept where they are, 10 mm
  apart as the core keeps views);
- no two texts of the scheme closer than 1 mm, none crossed by a link of the mechanism.
"""
from __future__ import annotations

import math

import ezdxf
import pytest
import shapely
from ezdxf import bbox
from shapely.affinity import scale as shapely_scale
from shapely.geometry import box

from drawings.scenes.kinematics_scheme import scene_links
from drawings.sheets import control as control_sheet
from reportgen import gost_scales
from reportgen.control.tables import table
from reportgen.commands.new import task_words
from reportgen.control.task_text import task_text
from reportgen.project import Project
from reportgen.scenes.boxes import SHEET_MM, VIEW_GAP, free_field
from reportgen.scenes.positions import bounds
from reportgen.taskfile import load_task

from labels.readback import TOUCH_MM, sheet_texts
from sheet1.legibility import dxf_lines

TABLES = range(1, 23)
#: Texts of the scheme keep at least this far apart, mm.
TEXTS_APART_MM = 1.0
#: What a view draws reaches at most this far beyond its rectangle, mm (the frame does, across the sheet).
REACH_MM = 20.0
INK = False


def control_task(folder, number: int, variant: int = 1, sheet: str = "A3"):
    path = folder / f"t{number}v{variant}{sheet}.toml"
    t = table(number)
    path.write_text(task_text(t, t.variant(variant), sheet=sheet, words=task_words("ru", number, variant)), encoding="utf-8")
    return path


def drawn_control(folder, number: int, sheet: str = "A3"):
    """(project, sheet as drawn, its DXF read back) of table ``number``'s variant 1."""
    project = Project(load_task(control_task(folder, number, sheet=sheet)))
    drawn = control_sheet.draw(project, 1, 1)
    drawn.save(folder / f"t{number}{sheet}.dxf")
    return project, drawn, ezdxf.readfile(folder / f"t{number}{sheet}.dxf")


def view_ink(doc, rect) -> tuple[float, float, float, float] | None:
    """The extents of what is drawn in a view (entities whose middle lies in its rectangle and
    that reach no farther than ``REACH_MM`` beyond it)."""
    found = []
    for e in doc.modelspace():
        if e.dxftype() == "INSERT":
            continue
        ext = bbox.extents([e], fast=True)
        if not ext.has_data:
            continue
        cx, cy = (ext.extmin.x + ext.extmax.x) / 2, (ext.extmin.y + ext.extmax.y) / 2
        if ext.size.x > rect.width + 2 * REACH_MM or ext.size.y > rect.height + 2 * REACH_MM:
            continue                       # the frame, a line of the title block
        if rect.x0 <= cx <= rect.x1 and rect.y0 <= cy <= rect.y1:
            found.append(e)
    if not found:
        return None
    ext = bbox.extents(found, fast=True)
    return ext.extmin.x, ext.extmin.y, ext.extmax.x, ext.extmax.y


def next_larger(k: float) -> float | None:
    """The next larger ГОСТ 2.302 scale than ``k`` mm per metre (mm per metre), None above the list."""
    larger = [1000.0 * gost_scales.factor(s) for s in gost_scales.GOST_2_302
              if 1000.0 * gost_scales.factor(s) > k * (1 + 1e-9)]
    return min(larger) if larger else None


def fits(region, width: float, height: float) -> bool:
    """Whether a ``width`` × ``height`` rectangle fits in ``region`` (a union of axis-parallel
    rectangles' differences): the region eroded by the rectangle (a square after scaling x) is not
    empty."""
    squeezed = shapely_scale(region, xfact=height / width, yfact=1.0, origin=(0, 0))
    return not squeezed.buffer(-height / 2 + 1e-6, join_style="mitre").is_empty


def larger_findings(project, drawn, doc) -> list[str]:
    """Room for the mechanism at the next larger ГОСТ scale beside the other views' drawings."""
    layout = project.scenes.sheet_layout
    k = layout.k
    up = next_larger(k)
    if up is None:
        return []
    ink = view_ink(doc, drawn.views["scheme"].rect)
    b = bounds(project.scenes.scheme_data, project.linkage)
    grow = up / k - 1.0
    width = ink[2] - ink[0] + grow * (b[2] - b[0]) * k
    height = ink[3] - ink[1] + grow * (b[3] - b[1]) * k
    region = free_field(*SHEET_MM[layout.sheet])
    for name, view in drawn.views.items():
        if name == "scheme":
            continue
        other = view_ink(doc, view.rect) if INK else (view.rect.x0, view.rect.y0, view.rect.x1, view.rect.y1)
        if other is not None:
            region = region.difference(box(*other).buffer(VIEW_GAP, join_style="mitre"))
    if fits(region, width, height):
        return [f"{layout.ratio}: the mechanism at 1:{1000.0 / up:g} ({width:.0f} × {height:.0f} mm with its "
                f"title and caption) fits beside the other views"]
    return []


def scheme_texts(drawn, doc) -> list[tuple[str, object]]:
    """The scheme's texts as a reader sees them: a label's letter and its index as one (the sheet's
    label records group their handles), a link's number as its circle."""
    from drawings.scenes.kinematics_scheme import LINK_NUMBER_MM
    rect = drawn.views["scheme"].rect.polygon()
    texts = {t.handle: t for t in sheet_texts(doc) if rect.contains(t.box.centroid)}
    circles = [shapely.Point(tuple(e.dxf.center)[:2]).buffer(float(e.dxf.radius), 32)
               for e in doc.modelspace().query("CIRCLE")
               if abs(float(e.dxf.radius) - LINK_NUMBER_MM[0]) < 1e-6 and rect.contains(shapely.Point(tuple(e.dxf.center)[:2]))]
    groups = []
    for r in drawn.annotations.labels:
        parts = [texts.pop(h) for h in r.handles if h in texts]
        if parts:
            groups.append((r.text, shapely.union_all([t.box for t in parts])))
    groups += [(t.text, t.box) for t in texts.values()]
    out = []
    for text, shape in groups:
        ring = next((c for c in circles if c.contains(shape.centroid)), None)
        out.append((f"({text})", ring) if ring is not None else (text, shape))
    return out


def drawn_lines(doc, rect) -> list:
    """Every line drawn in ``rect`` (sheet 1's read-back, :func:`sheet1.legibility.dxf_lines`),
    sheet mm, clipped to it."""
    area = rect.polygon()
    return [g for g in (line.intersection(area) for line in dxf_lines(doc)) if not g.is_empty]


def scheme_text_findings(project, drawn, doc) -> list[str]:
    """Texts of the scheme's view closer than ``TEXTS_APART_MM`` to one another, crossed by a link of
    the mechanism or by any other line the view draws (a hinge, a pivot's base, a guide's hatching)."""
    view = drawn.views["scheme"]
    k = view.transform.scale
    links = shapely.STRtree(list(scene_links(view, project.scenes.positions_at(k, ""), k).geoms))
    lines = shapely.STRtree(drawn_lines(doc, view.rect))
    texts = scheme_texts(drawn, doc)
    found = []
    for i, (text, shape) in enumerate(texts):
        core = shape.buffer(-TOUCH_MM, join_style="mitre")
        if len(links.query(core, predicate="intersects")):
            found.append(f"«{text}» crossed by a link")
        elif len(lines.query(core, predicate="intersects")):
            found.append(f"«{text}» crossed by a line")
        for other, second in texts[i + 1:]:
            gap = shape.distance(second)
            if gap < TEXTS_APART_MM - 1e-6:
                found.append(f"«{text}» and «{other}» {gap:.2f} mm apart")
    return found


@pytest.fixture(scope="module")
def a3_sheets(tmp_path_factory):
    folder = tmp_path_factory.mktemp("a3")
    return {n: drawn_control(folder, n) for n in TABLES}


def test_the_mechanism_is_drawn_at_the_largest_scale_the_sheet_holds(a3_sheets):
    found = {n: f for n, sheet in a3_sheets.items() if (f := larger_findings(*sheet))}
    assert not found, found


def test_the_schemes_texts_keep_apart_and_off_the_links(a3_sheets):
    found = {n: f for n, sheet in a3_sheets.items() if (f := scheme_text_findings(*sheet))}
    assert not found, found


def test_the_checks_see_a_wasted_sheet(tmp_path):
    """The checks themselves: the mechanism drawn two ГОСТ steps smaller than chosen leaves room for
    one step larger; a scheme text moved onto another is found."""
    from drawings.sheets import kinematics as sheet1
    from reportgen.scenes.arrangement import layout_at
    project = Project(load_task(control_task(tmp_path, 4)))
    chosen = project.scenes.sheet_layout
    smaller = [s for s in project.scenes.positions_scales if s[0] < chosen.k * (1 - 1e-9)][1]
    layout = layout_at(project, bounds(project.scenes.scheme_data, project.linkage), *smaller)
    drawn = sheet1.draw_at(project, 1, 1, project.scenes.scheme_data,
                           bounds(project.scenes.scheme_data, project.linkage), layout, control=True)
    drawn.save(tmp_path / "small.dxf")
    doc = ezdxf.readfile(tmp_path / "small.dxf")
    project.scenes.__dict__["sheet_layout"] = layout
    assert larger_findings(project, drawn, doc)
    texts = [e for e in doc.modelspace().query("TEXT")
             if drawn.views["scheme"].rect.polygon().contains(shapely.Point(tuple(e.dxf.insert)[:2]))]
    texts = [e for e in texts if len(e.dxf.text) <= 2]
    texts[1].dxf.insert = texts[0].dxf.insert
    texts[1].dxf.align_point = texts[0].dxf.get("align_point", texts[0].dxf.insert)
    assert any("apart" in f for f in scheme_text_findings(project, drawn, doc))
    assert math.isfinite(chosen.k)
