"""Issue 12, sheet 1 as a ТММ teacher reads it, for every course example and a crank–rocker no
example has (tests/sheet1/legibility.py reads the sheet back from its DXF):

- every small velocity plan carries the course's letters (the pole and the images of the moving
  points), each ГОСТ 2.304 size 3,5 at least, crossed by no line, beside its point or on a leader
  drawn to it, inside its own cell (main drew the shaper's 12 plans with every s_k piled on the
  vectors, and dropped the letters it found no room for);
- no text of the scheme lies under a link of any position (main: the shaper's «φх.х.» under its
  rocker, the crank axis's «O» on a crank line);
- no two views' drawings meet, on any sheet of any example, the small plans' cells counting as
  views of their own, and sheet 1's views keep their drawing inside their rectangles (main's
  check compared rectangles and texts only, and drew all 12 small plans as one canvas)."""
from __future__ import annotations

import pytest

from drawings.layout import Rect
from drawings.primitives import Transform
from drawings.sheet import Sheet, View
from drawings.sheets import available_sheets
from reportgen.commands.pipeline import draw_sheet

from legibility import (CASES, drawn_sheet1, project_of, scheme_label_findings, small_plan_findings)

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("sheet1-legible")


@pytest.mark.parametrize("case", CASES)
def test_small_plans_carry_the_course_letters_legibly(case, folder):
    project, sheet, doc = drawn_sheet1(case, folder)
    found = small_plan_findings(project, sheet, doc)
    assert not found, "\n".join(found)


@pytest.mark.parametrize("case", CASES)
def test_no_scheme_label_under_a_link(case, folder):
    project, sheet, doc = drawn_sheet1(case, folder)
    found = scheme_label_findings(project, sheet, doc)
    assert not found, "\n".join(found)


@pytest.mark.parametrize("case", CASES)
def test_sheet1_views_keep_their_drawing_to_themselves(case, folder):
    _, sheet, _ = drawn_sheet1(case, folder)
    assert not sheet.content_overlaps(), sheet.content_overlaps()[:5]
    assert not sheet.content_outside(), sheet.content_outside()[:5]
    cells = [n for n in sheet.annotations.regions if n.startswith("plans_all/")]
    assert len(cells) == len(sheet.annotations.regions) - len(sheet.views), cells


#: Every example (each of its sheets).
EVERY_EXAMPLE = ("press", "shaper", "conveyor", "crank-slider", "class3", "press-en", "shaper-uk",
                 "control-work", "crane-hoist")


@pytest.mark.parametrize("case", EVERY_EXAMPLE)
def test_no_two_views_drawings_meet_on_any_sheet(case, tmp_path):
    project = project_of(case, tmp_path)
    todo = available_sheets(project)
    for number, (stem, mod) in enumerate(todo, 1):
        sheet = draw_sheet(project, mod, number, len(todo))
        assert not sheet.content_overlaps(), (stem, sheet.content_overlaps()[:5])


def test_the_checks_see_what_a_teacher_marks(tmp_path):
    """A plan drawn over its neighbour's cell, a label on a line: the content check sees the
    first where the rectangles' check (Sheet.overlaps) does not."""
    from drawings.sheets import kinematics as sheet1
    project = project_of("press", tmp_path)
    sheet = Sheet.a1(project.task.document, title="t", code="c", number=1, count=1)
    holder = sheet.place_view("plans_all", Rect(100.0, 100.0, 300.0, 200.0), Transform())
    left = View(sheet, "plans_all/0", Rect(100.0, 100.0, 200.0, 180.0), Transform())
    right = View(sheet, "plans_all/1", Rect(200.0, 100.0, 300.0, 180.0), Transform())
    left.arrow((150.0, 140.0), (215.0, 150.0))           # reaches 15 mm into the next cell
    right.text_mm((212.0, 148.0), "a", 3.5, "center")
    assert holder and not sheet.overlaps()
    meet = sheet.content_overlaps()
    assert any({o.first, o.second} == {"view plans_all/0", "view plans_all/1"} for o in meet), meet
    assert any(s.startswith("view plans_all/0: line") for s in sheet.content_outside())
    assert sheet1.small_plan_letters(project) == {"p", "a", "b", "d"}     # not O, C (the pole), not s_k
