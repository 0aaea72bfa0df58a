"""A plan's letter is never crossed by a line, whatever the mechanism (issue 12: on the shaper's
second acceleration plan the pole's «π, o, c» found no free spot round the pole, nor on a leader
within 30 mm, and the placer's last resorts took a spot under a^r_A3A). The cause was in the
placers: where every spot they tried was crossed they took the least crossed one. Now a letter that
must stay uncrossed goes on a leader to the nearest free spot of its whole view (the sheet) or round
the drawing (the note) before it is ever crossed; a plan's coincident letters take the comma's own
cell («π, o, c» five cells wide, not seven) and read the same in the note («π, o, c» as «a, s₂»).
The hard cases here are made so that no spot within the old reach is free."""
from __future__ import annotations

import ezdxf
from shapely.geometry import LineString, Point

from drawings.scenes import kinematics_labels as rl
from drawings.sheet import Sheet
from reportgen.taskfile import load_task

from .conftest import ROOT
from .readback import check_sheet_crossings

#: The hatch round the point: lines 3 mm apart (a 5 mm letter cannot sit between two), 45 mm each
#: side of it — beyond the old placer's reach (30 mm round the point, 18 mm on its far ring).
HATCH_STEP, HATCH_HALF = 3.0, 45.0


def _hatched_view(tmp_path):
    sheet = Sheet.a1(load_task(ROOT / "examples" / "press" / "task.toml").document, title="t", code="c")
    view = sheet.add_view("plan_a_9", 200.0, 140.0)
    p = (view.rect.x0 + 60.0, view.rect.center[1])
    y = p[1] - HATCH_HALF
    while y <= p[1] + HATCH_HALF:
        view.layout.add_line((p[0] - HATCH_HALF, y), (p[0] + HATCH_HALF, y))
        view.annotations.add_obstacle(LineString([(p[0] - HATCH_HALF, y), (p[0] + HATCH_HALF, y)]))
        y += HATCH_STEP
    return sheet, view, p


def test_a_letter_with_no_free_spot_near_its_point_goes_on_a_leader_uncrossed(tmp_path):
    sheet, view, p = _hatched_view(tmp_path)
    label = (rl.Rich("π"), rl.Rich("o"), rl.Rich("c"))
    others = [p]
    poly = rl.place_point_label(view, p, label, 5.0, 45.0, others, inside=view.rect.polygon(), cross=0)
    assert poly is not None
    sheet.save(tmp_path / "s.dxf")
    found = check_sheet_crossings(ezdxf.readfile(tmp_path / "s.dxf"), sheet.annotations.labels, ("plan_a",))
    assert not found, found
    record = next(r for r in sheet.annotations.labels if r.text == "π, o, c")
    assert isinstance(record.anchor, LineString), "on a leader, tied to its point"
    assert record.anchor.distance(Point(p)) < 1e-6


def test_a_vector_name_with_no_free_spot_beside_it_goes_on_a_leader_uncrossed(tmp_path):
    from drawings.scenes.kinetostatics_views import place_vector_name
    sheet, view, p = _hatched_view(tmp_path)
    a, b = (p[0] - 10.0, p[1] + 1.5), (p[0] + 10.0, p[1] + 1.5)
    view.layout.add_line(a, b)
    place_vector_name(view, a, b, rl.from_tex("a^{r}_{A3A}"), 3.5, view.rect.polygon(), uncrossed=True)
    sheet.save(tmp_path / "s.dxf")
    found = check_sheet_crossings(ezdxf.readfile(tmp_path / "s.dxf"), sheet.annotations.labels, ("plan_a",))
    assert not found, found


def test_a_plan_letters_list_takes_the_commas_cell():
    """«π, o, c»: three letters and two commas, each one cell of the measuring font (the space after
    a comma is the blank of its own cell, as ГОСТ type B sets it)."""
    from drawings import style
    label = (rl.Rich("π"), rl.Rich("o"), rl.Rich("c"))
    w, _, _ = rl.size(label, 5.0)
    cell = style.text_width("o", 5.0)
    assert abs(w - 5 * cell) < 1e-9
    assert rl.label_name(label) == "π, o, c"


def test_the_notes_uncrossed_name_finds_a_spot_round_the_drawing():
    """The note's placer (latex_templates.figures.scene): a point inside a hatch wider than its
    leader grid gets a spot off every line, on a leader."""
    from latex_templates.figures.scene import _Segments, _crosses, place_labels
    from reportgen.scenes.scene import Label, Scene, Segment
    lines = [Segment(f"h{k}", (-40.0, -40.0 + 1.5 * k), (40.0, -40.0 + 1.5 * k), "vectors") for k in range(54)]
    scene = Scene("acceleration-plan-9", (), tuple(lines), (Label("\\pi,o,c", "point:π,o,c", (0.0, 0.0)),))
    (lb, _, placed), = place_labels(scene, 1.0, ("point",))
    segs = _Segments([(s.a, s.b) for s in lines])
    assert segs.crossings(placed.box) == 0
    assert placed.leader
    assert not any(_crosses(placed.box, (s.a, s.b)) for s in lines)


def test_the_notes_coincident_letters_read_as_a_list():
    from latex_templates.figures.scene import _mathtext
    from latex_templates.parts import active_strings
    from latex_templates.render import Strings
    with active_strings(Strings("ru")):
        assert _mathtext("π,o,c") == "$π$, $o$, $c$"
        assert _mathtext("a,s_{2}") == "$a$, $s_{2}$"
        assert _mathtext("II(2,3)") == "II(2,3)"
