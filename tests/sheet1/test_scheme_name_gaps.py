"""The names on the mechanism's scheme keep a clear gap (issue 12: on the press's sheet 1 «O», ①,
S₁ and «A 2» crowded at the crank's axis — the position number «2» stood 1,9 mm from «A» and read
as one name). Read back from the DXF of every example's sheet 1 and of the control work's sheet:
the letters of any two names of the scheme (points, centres of mass, position numbers, crank
angles, link numbers) are at least ``NAME_GAP_MM`` apart, and no name's letters come nearer than
LINE_GAP_MM to a drawn line of the scheme other than its own (its leader, its point's hinge or pin
circle, a link number's circle)."""
from __future__ import annotations

import pytest
import shapely
from shapely.geometry import Point

from drawings.scenes.kinematics_scheme import NAME_GAP_MM

from labels.readback import entity_geometry, sheet_texts

from scene_readback import ROOT, draw_named_sheet, sheet_cases

EXAMPLES = sorted(p.parent.name for p in (ROOT / "examples").glob("*/task.toml") if "crane" not in p.parent.name)
#: A name's letters keep this far (mm) from the lines that are not its own (the placer keeps 1 mm:
#: its box's padding and NAME_CLEAR's; the read-back letters are narrower than the box).
LINE_GAP_MM = 0.5
#: A line lying within this many mm of a point is that point's own (its hinge, its pin's circle).
OWN_POINT_MM = 2.5


def scheme_defects(sheet, doc, view_name: str = "scheme") -> list[str]:
    view = sheet.views[view_name]
    own = set(view.handles)
    by_handle = {t.handle: t for t in sheet_texts(doc)}
    names = []
    for r in sheet.annotations.labels:
        if r.view != view_name:
            continue
        boxes = [by_handle[h].box for h in r.handles if h in by_handle]
        if boxes:
            names.append((r.text, shapely.union_all(boxes), r.anchor))
    lines = [entity_geometry(e) for e in doc.modelspace() if str(e.dxf.handle) in own and e.dxftype() != "TEXT"]
    lines = [g for g in lines if g is not None]
    found = []
    for i, (t, s, _) in enumerate(names):
        for u, s2, _ in names[i + 1:]:
            d = s.distance(s2)
            if d < NAME_GAP_MM - 0.05:
                found.append(f"«{t}» and «{u}» {d:.2f} mm apart")
    for t, s, anchor in names:
        mine = anchor.buffer(OWN_POINT_MM) if isinstance(anchor, Point) else anchor.buffer(0.3)
        for g in lines:
            if g.within(mine) or g.distance(s) >= LINE_GAP_MM:
                continue
            if g.geom_type in ("LineString", "LinearRing") and g.is_ring and shapely.Polygon(g).contains(s):
                continue              # a link number's circle round it
            found.append(f"«{t}» {g.distance(s):.2f} mm from a line {tuple(round(c, 1) for c in g.bounds)}")
    return found


@pytest.mark.slow
@pytest.mark.parametrize("name,stem", sheet_cases(EXAMPLES, lambda stem: "kinematics" in stem or "control" in stem))
def test_scheme_names_keep_a_clear_gap(name, stem, tmp_path):
    sheet, doc = draw_named_sheet(name, stem, tmp_path)
    found = scheme_defects(sheet, doc)
    assert not found, "\n".join(found)
