"""Primitives: number formatting, transform, labels, arrows, dimensions, symbols."""
from __future__ import annotations

import math

import pytest
from shapely.geometry import box

from drawings import style
from drawings.primitives import Annotations, Canvas, Transform, format_number, format_significant


@pytest.mark.parametrize("value,decimals,expected", [
    (0.02, 2, "0,02"), (0.0200, 4, "0,02"), (12.0, 2, "12"), (-0.0001, 2, "0"),
    (-1.25, 2, "-1,25"), (1234.5678, 1, "1234,6"),
])
def test_format_number(value, decimals, expected):
    assert format_number(value, decimals) == expected


def test_format_significant():
    assert format_significant(0.0012345, 3) == "0,00123"
    assert format_significant(24.544, 4) == "24,54"
    assert format_significant(1230.0, 3) == "1230"


def test_transform_maps_and_inverts():
    t = Transform(scale=400.0, origin=(0.1, -0.2), at=(50.0, 60.0))
    assert t((0.1, -0.2)) == (50.0, 60.0)
    assert t((0.2, -0.2)) == pytest.approx((90.0, 60.0))
    assert t.inverse(t((0.3, 0.05))) == pytest.approx((0.3, 0.05))
    with pytest.raises(ValueError):
        Transform(scale=0.0)


@pytest.fixture()
def canvas():
    doc = style.new_document(420.0, 297.0)
    return Canvas(doc.modelspace(), Transform(scale=2.0, at=(100.0, 100.0)), Annotations(), "t")


def test_labels_at_one_point_do_not_overlap(canvas):
    canvas.line((0, 0), (40, 0))
    canvas.line((0, 0), (0, 40))
    boxes = [canvas.label((0, 0), s) for s in ("A", "B", "C", "D")]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert a.intersection(b).area == pytest.approx(0.0, abs=1e-9)
    # and none of them crosses the two drawn lines
    for b in boxes:
        assert canvas.annotations.crossings(b) == 0


def test_arrow_has_a_filled_head_at_its_tip_and_a_label(canvas):
    canvas.arrow((0, 0), (30, 40), "b")
    solids = canvas.layout.query("SOLID")
    assert len(solids) == 1
    tip = canvas.transform((30, 40))
    assert solids[0].dxf.vtx0.isclose((*tip, 0))
    # head length 5 mm, width 5/3 mm
    v = [solids[0].dxf.get(f"vtx{i}") for i in range(3)]
    assert math.dist(v[1], v[2]) == pytest.approx(5.0 / 3.0)
    texts = [e.dxf.text for e in canvas.layout.query("TEXT")]
    assert texts == ["b"]


def test_dimension_shows_model_size_with_dimlfac(canvas):
    value = canvas.dimension((0, 0), (0.07, 0), offset_mm=10, unit_factor=1000.0, decimals=1)
    assert value == pytest.approx(70.0)
    dim = canvas.layout.query("DIMENSION")[0]
    assert dim.dxf.text == "70"
    assert dim.dxf.dimstyle == style.DIM_STYLE
    assert dim.override().get("dimlfac") == pytest.approx(1000.0 / 2.0)


def test_fixed_pivot_has_hatched_base(canvas):
    n0 = len(canvas.layout.query("LINE[layer=='thin']"))
    canvas.fixed_pivot((0, 0))
    strokes = canvas.layout.query("LINE[layer=='thin']")
    assert len(strokes) - n0 >= 4
    assert len(canvas.layout.query("CIRCLE")) == 1


def test_slider_draws_block_and_guide(canvas):
    canvas.slider((10, 0), angle_deg=30.0)
    blocks = [e for e in canvas.layout.query("LWPOLYLINE") if e.closed]
    assert len(blocks) == 1
    pts = list(blocks[0].get_points("xy"))
    assert math.dist(pts[0], pts[1]) == pytest.approx(14.0)
    assert math.dist(pts[1], pts[2]) == pytest.approx(7.0)


def test_unknown_layer_is_refused(canvas):
    with pytest.raises(ValueError, match="layer"):
        canvas.line((0, 0), (1, 1), layer="bold")


def test_geometry_emits_polygon_rings(canvas):
    canvas.geometry(box(0, 0, 10, 5).difference(box(2, 1, 4, 3)), layer="contour")
    polys = canvas.layout.query("LWPOLYLINE")
    assert len(polys) == 2 and all(p.closed for p in polys)


def test_axes_ticks_and_labels(canvas):
    canvas.axes((0, 0), 100, 50, 20, x_label="φ1", y_label="M",
                x_ticks=[(10, "1"), (20, "2")], y_ticks=[(10, "5")])
    texts = {e.dxf.text for e in canvas.layout.query("TEXT")}
    assert {"φ1", "M", "1", "2", "5"} <= texts
    assert len(canvas.layout.query("SOLID")) == 2


@pytest.mark.parametrize("direction", [-90.0, 180.0, 0.0, 90.0, -45.0])
def test_fixed_pivot_hatching_is_on_the_far_side_of_the_base(canvas, direction):
    canvas.fixed_pivot((0, 0), direction_deg=direction, height_mm=8.0)
    hinge = canvas.transform((0, 0))
    ux, uy = math.cos(math.radians(direction)), math.sin(math.radians(direction))
    strokes = canvas.layout.query("LINE[layer=='thin']")
    assert strokes
    for line in strokes:
        for p in (line.dxf.start, line.dxf.end):
            # distance from the hinge along the hinge→base direction: at or beyond the base line
            assert (p.x - hinge[0]) * ux + (p.y - hinge[1]) * uy >= 8.0 - 1e-6
