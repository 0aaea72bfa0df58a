"""No two views of a sheet overlap, read back from the DXF: what each view drew (its entities, by
the handles :class:`drawings.sheet.View` records) stays within its own rectangle on sheets 1 and 2,
and no view's drawing meets another's on any sheet — for every example and for a crank–rocker
(tests/data/crank-rocker.toml: on main its sheet 2 set the force polygon's details «А (2:1)» and
«Б (2:1)» over each other, and the details' headings of the press's, the shaper's, the conveyor's
and class3's polygons stood up to 8 mm outside their views: the views were packed by the circles'
size, not by the headings')."""
from __future__ import annotations

from pathlib import Path

import ezdxf
import pytest
import shapely

from drawings.sheets import available_sheets
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task

from tests.labels.readback import check_sheet, entity_geometry
from reportgen.tolerances import LABEL_NEAR_MM

ROOT = Path(__file__).resolve().parents[2]
TASKS = {**{p.parent.name: p for p in sorted((ROOT / "examples").glob("*/task.toml"))},
         "crank-rocker": ROOT / "tests" / "data" / "crank-rocker.toml"}
#: Sheets whose views must hold their whole drawing (the others' captions may reach past a view
#: into the free field: sheet 4's reducer, the crane's schemes).
CONTAINED = ("sheet1-kinematics", "sheet2-kinetostatics")
#: How far (mm) a view's drawing may reach past its rectangle: round-off of the text boxes.
SLACK_MM = 0.3


def _cases():
    return [pytest.param(name, stem, id=f"{name}-{stem}")
            for name, path in TASKS.items() for stem, _ in available_sheets(Project(load_task(path)))]


_PROJECT: dict[str, Project] = {}


def _drawn(name: str, stem: str, tmp_path):
    if name not in _PROJECT:
        _PROJECT.clear()
        _PROJECT[name] = Project(load_task(TASKS[name]))
    project = _PROJECT[name]
    todo = available_sheets(project)
    number, mod = next((i, m) for i, (s, m) in enumerate(todo, 1) if s == stem)
    sheet = draw_sheet(project, mod, number, len(todo))
    sheet.save(tmp_path / "s.dxf")
    return sheet, ezdxf.readfile(tmp_path / "s.dxf")


def views_ink(sheet, doc) -> dict:
    """What each view drew, as one geometry (sheet mm; a text as its letters' box)."""
    out = {}
    for name, view in sheet.views.items():
        parts = [entity_geometry(doc.entitydb[h]) for h in view.handles if h in doc.entitydb]
        parts = [g.buffer(-0.25, join_style=2) if g.geom_type == "Polygon" else g for g in parts if g is not None]
        parts = [g for g in parts if not g.is_empty]
        if parts:
            out[name] = shapely.union_all(parts)
    return out


@pytest.mark.slow
@pytest.mark.parametrize("name,stem", _cases())
def test_views_do_not_overlap(name, stem, tmp_path):
    sheet, doc = _drawn(name, stem, tmp_path)
    ink = views_ink(sheet, doc)
    found = []
    names = sorted(ink)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if ink[a].intersects(ink[b]):
                found.append(f"views {a!r} and {b!r} overlap")
            ra, rb = sheet.views[a].rect.polygon(), sheet.views[b].rect.polygon()
            if ra.intersection(rb).area > 0.0:
                found.append(f"the rectangles of {a!r} and {b!r} overlap")
    if stem in CONTAINED:
        for a in names:
            out = ink[a].difference(sheet.views[a].rect.polygon().buffer(SLACK_MM, join_style=2))
            if not out.is_empty:
                found.append(f"view {a!r} draws outside its rectangle at {tuple(round(v, 1) for v in out.bounds)}")
    assert not found, "\n".join(found)


@pytest.mark.slow
def test_the_crank_rockers_sheet_2_has_no_overlapping_texts(tmp_path):
    sheet, doc = _drawn("crank-rocker", "sheet2-kinetostatics", tmp_path)
    assert not sheet.overlaps(), [str(o) for o in sheet.overlaps()]
    found = check_sheet(doc, sheet.annotations.labels, LABEL_NEAR_MM)
    assert not found, "\n".join(map(str, found))


def test_a_view_records_what_it_draws(tmp_path):
    """The check reads a view's entities by the handles it recorded: a line drawn through the view's
    layout (as a leader is) is among them, a line of the frame is not."""
    from drawings.sheet import Sheet

    sheet = Sheet.a1(Project(load_task(TASKS["press"])).task.document, title="t", code="c", number=1, count=1)
    view = sheet.add_view("v", 100.0, 50.0)
    view.line((0.0, 0.0), (10.0, 10.0))
    view.layout.add_line((1.0, 1.0), (2.0, 2.0))
    view.text_mm((view.rect.x0 + 5.0, view.rect.y0 + 5.0), "A", 5.0)
    sheet.save(tmp_path / "s.dxf")
    doc = ezdxf.readfile(tmp_path / "s.dxf")
    kinds = sorted(doc.entitydb[h].dxftype() for h in view.handles)
    assert kinds == ["LINE", "LINE", "TEXT"], kinds
