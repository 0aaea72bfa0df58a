"""No view of a sheet draws over another, read back from the sheet's DXF entities by the handles
each view records (:class:`drawings.sheet.View`), on every sheet of every example and of two
crank–rockers no example has (tests/data/crank-rocker.toml and sheet 1's generated one):

- no two views' drawings meet: lines, circles, arcs, arrowheads, dimensions and the letters of the
  texts, a part of a view drawn as a view of its own (a small velocity plan's cell ``plans_all/3``)
  counting apart from its view and from the other parts;
- no two views' rectangles overlap, and each part lies inside its view;
- on sheets 1 and 2 every view and part keeps its drawing within its rectangle.

What they were written for (issue 12): on main the crank–rocker's sheet 2 set the force polygon's
details «А (2:1)» and «Б (2:1)» over each other, and the details' headings of the press's, the
shaper's, the conveyor's and class3's polygons stood up to 8 mm outside their views (the views
were packed by the circles' size, not by the headings'); the old check compared the views'
rectangles and texts only (:meth:`drawings.sheet.Sheet.overlaps`), not what is drawn in them, and
the 12 small plans were one canvas, so a plan spilling into its neighbour's cell passed."""
from __future__ import annotations

from pathlib import Path

import ezdxf
import pytest
import shapely

from drawings.layout import Rect
from drawings.primitives import Transform
from drawings.sheet import Sheet, View
from drawings.sheets import available_sheets
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task
from reportgen.tolerances import LABEL_NEAR_MM, MM_ROUNDOFF

from tests.labels.readback import TOUCH_MM, check_sheet, drawn_shapes
from sheet1.legibility import rocker_task

ROOT = Path(__file__).resolve().parents[2]
TASKS = {**{p.parent.name: p for p in sorted((ROOT / "examples").glob("*/task.toml"))},
         "crank-rocker": ROOT / "tests" / "data" / "crank-rocker.toml"}
#: Every example, the crank–rocker of tests/data and sheet 1's generated crank–rocker.
CASES = (*TASKS, "rocker")
#: Views whose caption may reach past the view into the free field (sheet 4's reducer, the crane's
#: schemes); every other view and part holds its whole drawing.
LOOSE = ("reducer_front", "reeving", "hoist_drive")


def project_of(name: str, folder: Path) -> Project:
    return Project(load_task(rocker_task(folder) if name == "rocker" else TASKS[name]))


def views_ink(sheet: Sheet) -> list[tuple[str, object]]:
    """(view, shape) for each shape every view and part drew, in sheet mm: its entities in the
    sheet's DXF by the handles it recorded, a text as its letters' box less ``TOUCH_MM`` a side."""
    db = sheet.doc.entitydb
    return [(name, g) for name, view in sheet.all_views.items() for h in view.handles
            for g in drawn_shapes(db[h], TOUCH_MM)]


def _at(geom) -> str:
    p = geom.representative_point()
    return f"({p.x:.1f}, {p.y:.1f})"


def view_findings(sheet: Sheet, loose: tuple[str, ...] = LOOSE) -> list[str]:
    """What draws over what: two views' (or parts') drawings meeting, two views' rectangles
    overlapping, a part outside its view, a view not named in ``loose`` drawing outside its own."""
    ink = views_ink(sheet)
    shapes = [g for _, g in ink]
    found, met = [], set()
    for i, j in zip(*shapely.STRtree(shapes).query(shapes, predicate="intersects").tolist()):
        pair = (ink[i][0], ink[j][0])
        if pair[0] < pair[1] and pair not in met:
            met.add(pair)
            found.append(f"views {pair[0]!r} and {pair[1]!r} meet at {_at(shapes[i].intersection(shapes[j]))}")
    packed = sorted(sheet.views)
    found += [f"the rectangles of {a!r} and {b!r} overlap" for i, a in enumerate(packed) for b in packed[i + 1:]
              if sheet.views[a].rect.polygon().intersection(sheet.views[b].rect.polygon()).area > 0.0]
    for name, part in sheet.all_views.items():
        holder = sheet.views.get(name.split("/", 1)[0])
        if holder is None or not holder.rect.expanded(MM_ROUNDOFF).polygon().contains(part.rect.polygon()):
            found.append(f"part {name!r} not inside a view of its own")
    farthest: dict[str, tuple[float, object]] = {}
    for name, g in ink:
        region = sheet.all_views[name].rect.polygon()
        out = g.difference(region.buffer(TOUCH_MM, join_style=2))
        if name not in loose and not out.is_empty:
            point = max(shapely.points(shapely.get_coordinates(out)), key=region.distance)
            if region.distance(point) > farthest.get(name, (0.0,))[0]:
                farthest[name] = (region.distance(point), point)
    found += [f"view {name!r} draws {mm:.1f} mm outside its rectangle at {_at(point)}"
              for name, (mm, point) in farthest.items()]
    return found


@pytest.mark.slow
@pytest.mark.parametrize("name", CASES)
def test_no_view_draws_over_another(name, tmp_path):
    project = project_of(name, tmp_path)
    todo = available_sheets(project)
    assert todo, name
    found = []
    for number, (stem, mod) in enumerate(todo, 1):
        sheet = draw_sheet(project, mod, number, len(todo))
        found += [f"{stem}: {f}" for f in view_findings(sheet)]
    assert not found, "\n".join(found)


@pytest.mark.slow
def test_the_crank_rockers_sheet_2_has_no_overlapping_texts(tmp_path):
    project = project_of("crank-rocker", tmp_path)
    todo = available_sheets(project)
    number, mod = next((i, m) for i, (s, m) in enumerate(todo, 1) if s == "sheet2-kinetostatics")
    sheet = draw_sheet(project, mod, number, len(todo))
    sheet.save(tmp_path / "s.dxf")
    assert not sheet.overlaps(), [str(o) for o in sheet.overlaps()]
    found = check_sheet(ezdxf.readfile(tmp_path / "s.dxf"), sheet.annotations.labels, LABEL_NEAR_MM)
    assert not found, "\n".join(map(str, found))


def _blank_sheet() -> Sheet:
    return Sheet.a1(project_of("press", Path()).task.document, title="t", code="c", number=1, count=1)


def test_a_view_records_what_it_draws(tmp_path):
    """A view's entities are those it recorded, read back from the saved DXF: a line drawn through
    its layout (as a leader is) and a dimension are among them, a line of the frame is not; what a
    part of a view draws is the part's."""
    sheet = _blank_sheet()
    view = sheet.add_view("v", 100.0, 50.0)
    part = View(sheet, "v/0", Rect(view.rect.x0, view.rect.y0, view.rect.x0 + 50.0, view.rect.y1), Transform())
    view.line((0.0, 0.0), (10.0, 10.0))
    view.layout.add_line((1.0, 1.0), (2.0, 2.0))
    view.text_mm((view.rect.x0 + 5.0, view.rect.y0 + 5.0), "A", 5.0)
    view.dimension((0.0, 0.0), (20.0, 0.0), 5.0)
    part.circle_mm((view.rect.x0 + 20.0, view.rect.y0 + 20.0), 2.0)
    sheet.save(tmp_path / "s.dxf")
    doc = ezdxf.readfile(tmp_path / "s.dxf")
    kinds = sorted(doc.entitydb[h].dxftype() for h in view.handles)
    assert kinds == ["DIMENSION", "LINE", "LINE", "TEXT"], kinds
    assert [doc.entitydb[h].dxftype() for h in part.handles] == ["CIRCLE"]
    assert sheet.all_views == {"v": view, "v/0": part} and list(sheet.views) == ["v"]
    dim = next(doc.entitydb[h] for h in view.handles if doc.entitydb[h].dxftype() == "DIMENSION")
    kinds = sorted(g.geom_type for g in drawn_shapes(dim))    # its lines, arrowheads and value
    assert kinds == ["LineString"] * 3 + ["Polygon"] * 3, kinds


def test_the_checks_see_what_a_teacher_marks():
    """A plan drawn over its neighbour's cell: the content check sees it where the rectangles'
    check (Sheet.overlaps) does not — the arrow meets the next cell's letter and leaves its cell;
    a detail's heading set over its neighbour's, and beyond its view."""
    sheet = _blank_sheet()
    sheet.place_view("plans_all", Rect(100.0, 100.0, 300.0, 200.0), Transform())
    left = View(sheet, "plans_all/0", Rect(100.0, 100.0, 200.0, 180.0), Transform())
    right = View(sheet, "plans_all/1", Rect(200.0, 100.0, 300.0, 180.0), Transform())
    left.arrow((150.0, 140.0), (215.0, 150.0))           # reaches 15 mm into the next cell
    right.text_mm((212.0, 148.0), "a", 3.5, "center")
    assert not sheet.overlaps()
    found = sorted(view_findings(sheet))
    assert len(found) == 2 and found[1].startswith("views 'plans_all/0' and 'plans_all/1' meet at"), found
    assert found[0].startswith("view 'plans_all/0' draws 15."), found

    sheet = _blank_sheet()
    a = sheet.place_view("polygon A", Rect(100.0, 300.0, 150.0, 350.0), Transform())
    b = sheet.place_view("polygon B", Rect(160.0, 300.0, 220.0, 350.0), Transform())
    a.text_mm((130.0, 340.0), "А (2:1) wide heading", 5.0, "center")     # ≈ 83 mm wide
    b.text_mm((185.0, 340.0), "Б (2:1)", 5.0, "center")
    found = view_findings(sheet)
    assert any(f.startswith("views 'polygon A' and 'polygon B' meet") for f in found), found
    assert any(f.startswith("view 'polygon A' draws") for f in found), found
    assert not any("'polygon B' draws" in f for f in found), found
