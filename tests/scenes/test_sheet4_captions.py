"""Sheet 4's specific-sliding diagram carries its caption (the scales μλ, μρ) with it (issue 12:
the caption stood at the top of the view, ~100 mm above the diagram). Read back from the DXF of
every example with a gear pair (ru, uk, en): the caption's text lies within CAPTION_MAX_MM of the
diagram's drawing (its axes and curves) and above it."""
from __future__ import annotations

import re

import ezdxf
import pytest
from shapely.geometry import LineString
from shapely.ops import unary_union

from drawings.sheets import gears as gear_sheet
from labels.readback import sheet_texts
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task
from scene_readback import ROOT

GEAR_EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml")
                       if re.search(r"^\[gears\]", p.read_text(encoding="utf-8"), re.M))
#: A caption further than this (sheet mm) from its diagram is not read as its caption.
CAPTION_MAX_MM = 12.0


def _drawing(doc, area):
    """The lines of the sheet inside ``area`` (LINE, LWPOLYLINE): a view's drawing."""
    geoms = []
    for e in doc.modelspace().query("LINE LWPOLYLINE"):
        pts = ([tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]] if e.dxftype() == "LINE"
               else [tuple(p[:2]) for p in e.get_points("xy")])
        if len(pts) > 1:
            g = LineString(pts)
            if g.within(area):
                geoms.append(g)
    return unary_union(geoms)


@pytest.mark.parametrize("name", GEAR_EXAMPLES)
def test_sliding_caption_with_its_diagram(name, tmp_path):
    project = Project(load_task(str(ROOT / "examples" / name / "task.toml")))
    sheet = draw_sheet(project, gear_sheet, 4, 4)
    sheet.save(tmp_path / "s4.dxf")
    doc = ezdxf.readfile(tmp_path / "s4.dxf")
    area = sheet.views["sliding"].rect.polygon()
    captions = [t for t in sheet_texts(doc) if t.box.within(area.buffer(1.0)) and "μ" in t.text]
    assert len(captions) == 1, [t.text for t in captions]
    caption = captions[0].box
    drawing = _drawing(doc, area.buffer(1.0))
    assert not drawing.is_empty
    gap = caption.distance(drawing)
    assert gap <= CAPTION_MAX_MM, f"the caption «{captions[0].text}» is {gap:.0f} mm from its diagram"
    assert caption.bounds[1] >= drawing.bounds[3] - 1e-6 or gap > 0, "the caption over its diagram"


PLANETARY_EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml")
                            if re.search(r"^\[planetary\]", p.read_text(encoding="utf-8"), re.M))


@pytest.mark.parametrize("name", PLANETARY_EXAMPLES)
def test_planetary_table_has_its_title_above_it(name, tmp_path):
    """The reducer's table (wheel, z, d; K, u) had no title (review, issue 12): its title stands
    above its top line, within the table's view."""
    from latex_templates.render import Strings

    project = Project(load_task(str(ROOT / "examples" / name / "task.toml")))
    sheet = draw_sheet(project, gear_sheet, 4, 4)
    sheet.save(tmp_path / "s4.dxf")
    doc = ezdxf.readfile(tmp_path / "s4.dxf")
    title = Strings(project.task.document.language or "ru").text("sheets.pl07")
    area = sheet.views["reducer_table"].rect.polygon()
    found = [t for t in sheet_texts(doc) if t.text == str(title)]
    assert len(found) == 1 and found[0].box.within(area.buffer(1.0)), [t.text for t in found]
    table = _drawing(doc, area.buffer(1.0))
    assert found[0].box.bounds[1] >= table.bounds[3] - 1e-6, "the title over the table's lines"
