"""Issue 12, sheet 1 as a ТММ teacher reads it, for every course example and a crank–rocker no
example has (tests/sheet1/legibility.py reads the sheet back from its DXF):

- every small velocity plan carries the course's letters (the pole and the images of the moving
  points), each ГОСТ 2.304 size 3,5 at least, crossed by no line, beside its point or on a leader
  drawn to it, inside its own cell (main drew the shaper's 12 plans with every s_k piled on the
  vectors, and dropped the letters it found no room for);
- no text of the scheme lies under a link of any position (main: the shaper's «φх.х.» under its
  rocker, the crank axis's «O» on a crank line).

That no two views' drawings meet (the small plans' cells counting apart) and that sheet 1's views
keep their drawing inside their rectangles is checked with every other sheet's views in
tests/drawings/test_views_apart.py."""
from __future__ import annotations

import pytest

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


def test_small_plans_are_lettered_with_the_course_points_only(tmp_path):
    from drawings.sheets import kinematics as sheet1
    project = project_of("press", tmp_path)
    assert sheet1.small_plan_letters(project) == {"p", "a", "b", "d"}     # not O, C (the pole), not s_k
