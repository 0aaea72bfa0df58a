"""The view packer and the overlap checks."""
from __future__ import annotations

import pytest
from shapely.geometry import box

from demo_scene import FakeDocument
from drawings import Sheet
from drawings.layout import Rect, Request, find_overlaps, pack
from drawings.primitives import Transform
from reportgen.errors import BuildError


def test_pack_places_inside_region_without_overlap():
    region = box(0, 0, 300, 200).difference(box(200, 0, 300, 60))  # a notch like a title block
    reqs = [Request(f"v{i}", 90, 70, corner) for i, corner in
            enumerate(["top-left", "top-right", "bottom-left", "top-left", "center"])]
    rects = pack(region, reqs, gap=5)
    for r in rects:
        assert region.buffer(1e-6).contains(r.polygon())
    for i, a in enumerate(rects):
        for b in rects[i + 1:]:
            assert not a.expanded(5 - 1e-6).overlaps(b)


def test_pack_honours_preferred_corner():
    region = box(0, 0, 300, 200)
    tl, br = pack(region, [Request("a", 50, 40, "top-left"), Request("b", 50, 40, "bottom-right")])
    assert (tl.x0, tl.y1) == (0, 200)
    assert (br.x1, br.y0) == (300, 0)


def test_pack_avoids_the_notch():
    region = box(0, 0, 300, 200).difference(box(200, 0, 300, 60))
    (r,) = pack(region, [Request("a", 80, 50, "bottom-right")])
    assert not r.polygon().intersection(box(200, 0, 300, 60)).area > 0
    assert r.x1 == 300 or r.y0 == 0


def test_pack_reports_a_view_that_does_not_fit():
    with pytest.raises(BuildError, match="'huge'"):
        pack(box(0, 0, 100, 100), [Request("huge", 120, 10)])


def test_find_overlaps_ignores_touching_and_reports_area():
    items = [("a", box(0, 0, 10, 10)), ("b", box(10, 0, 20, 10)), ("c", box(5, 5, 15, 15))]
    found = find_overlaps(items)
    assert {(o.first, o.second) for o in found} == {("a", "c"), ("b", "c")}
    assert all(o.area == pytest.approx(25.0) for o in found)


def test_demo_sheet_has_no_overlaps(demo_sheet):
    assert demo_sheet.overlaps() == []
    assert len(demo_sheet.views) == 3
    free = demo_sheet.free_region
    for v in demo_sheet.views.values():
        assert free.buffer(1e-6).contains(v.rect.polygon())


def test_sheet_reports_overlapping_views_and_texts():
    sheet = Sheet.a1(FakeDocument(), title="x", code="y")
    a = sheet.place_view("a", Rect(100, 100, 200, 200), Transform())
    sheet.place_view("b", Rect(150, 150, 250, 250), Transform())
    sheet.place_view("c", Rect(700, 20, 760, 80), Transform())  # inside the title block
    a.text_mm((120, 120), "ТЕКСТ", 5.0)
    a.text_mm((121, 121), "ТЕКСТ", 5.0)
    a.text_mm((830, 300), "за рамкой", 5.0)
    found = {(o.first, o.second) for o in sheet.overlaps()}
    assert ("view a", "view b") in found
    assert ("view c", "title block") in found
    assert ("a: «ТЕКСТ»", "a: «ТЕКСТ»") in found
    assert ("a: «за рамкой»", "outside the frame") in found
