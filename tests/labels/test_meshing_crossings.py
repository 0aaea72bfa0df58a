"""No text of sheet 4's meshing picture is crossed by a line or an arc of that picture (issue 12: near
the pole a thin circle arc crossed the press's and the shaper's «a» and «αw»), read back from the
DXF: every TEXT the view «meshing» drew (the designations, the points' letters, the zones'
numerals, the caption) against every LINE, LWPOLYLINE, CIRCLE, ARC and SOLID it drew, but a
designation's own leader (its shelf ends under its letters) — for every example with a gear pair."""
from __future__ import annotations

import ezdxf
import pytest
import shapely
from shapely.geometry import LineString

from drawings.sheets import available_sheets
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task

from .conftest import EXAMPLES, ROOT
from .readback import TOUCH_MM, entity_geometry, text_box

GEARED = [name for name in EXAMPLES if "[gears]" in (ROOT / "examples" / name / "task.toml").read_text()]


def crossed_texts(doc, view) -> list[str]:
    """The texts of ``view`` (a :class:`drawings.sheet.View`, read back by its handles) crossed by a
    line of the same view that is not their own leader (a leader's shelf meets the text's box from
    below, its slanted part ends at what it names: a line that merely touches the box's edge is not
    a crossing, :data:`TOUCH_MM`)."""
    own = set(view.handles)
    texts, lines = [], []
    for e in doc.modelspace():
        if str(e.dxf.handle) not in own:
            continue
        if e.dxftype() == "TEXT":
            if e.plain_text().strip():
                texts.append((e.plain_text(), text_box(e)))
        else:
            g = entity_geometry(e)
            if g is not None:
                lines.append(g)
    tree = shapely.STRtree(lines)
    found = []
    for text, poly in texts:
        inner = poly.buffer(-TOUCH_MM, join_style=2)
        for j in tree.query(inner, predicate="intersects"):
            line = lines[int(j)]
            if isinstance(line, LineString) and _is_leader_of(line, poly):
                continue
            found.append(f"«{text}» crossed by {line.geom_type} {tuple(round(c, 1) for c in line.bounds)}")
    return found


def _is_leader_of(line: LineString, poly) -> bool:
    """A leader: a polyline whose last segment is the shelf under the text (horizontal, within the
    text's width, at most a descender deep into its box)."""
    coords = list(line.coords)
    if len(coords) < 3:
        return False
    (x0, y0), (x1, y1) = coords[-2], coords[-1]
    bx0, by0, bx1, by1 = poly.bounds
    shelf = abs(y1 - y0) < 1e-6 and by0 - 1.0 <= y0 <= by0 + 0.4 * (by1 - by0)
    others = LineString(coords[:-1])
    return shelf and not others.intersects(poly.buffer(-TOUCH_MM, join_style=2).difference(
        LineString([(x0, y0), (x1, y1)]).buffer(0.6)))


@pytest.mark.slow
@pytest.mark.parametrize("name", GEARED)
def test_no_text_of_the_meshing_picture_is_crossed(name, tmp_path):
    project = Project(load_task(ROOT / "examples" / name / "task.toml"))
    todo = available_sheets(project)
    number, mod = next((i, m) for i, (s, m) in enumerate(todo, 1) if "gears" in s)
    sheet = draw_sheet(project, mod, number, len(todo))
    sheet.save(tmp_path / "s.dxf")
    found = crossed_texts(ezdxf.readfile(tmp_path / "s.dxf"), sheet.views["meshing"])
    assert not found, "\n".join(found)


def test_the_check_sees_a_crossed_text(tmp_path):
    """A text with an arc through it is found; one standing on its leader's shelf is not."""
    from drawings.sheet import Sheet

    project = Project(load_task(ROOT / "examples" / "press" / "task.toml"))
    sheet = Sheet.a1(project.task.document, title="t", code="c", number=4, count=4)
    view = sheet.add_view("meshing", 200.0, 100.0)
    x, y = view.rect.x0, view.rect.y0
    view.text_mm((x + 50.0, y + 50.0), "αw", 3.5, "bottom-left")
    view.layout.add_arc((x + 52.0, y + 20.0), 31.5, 60.0, 120.0)                     # through its letters
    view.text_mm((x + 100.0, y + 50.6), "a", 3.5, "bottom-left")
    view.layout.add_lwpolyline([(x + 90.0, y + 40.0), (x + 98.0, y + 50.0), (x + 104.0, y + 50.0)])   # its leader
    sheet.save(tmp_path / "s.dxf")
    found = crossed_texts(ezdxf.readfile(tmp_path / "s.dxf"), view)
    assert len(found) == 1 and found[0].startswith("«αw» crossed by LineString"), found
