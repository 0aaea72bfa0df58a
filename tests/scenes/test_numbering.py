"""One numbering of positions: section 3 names the analysed position by the number that table 3.1
and sheet 3 give its crank angle (and, where the grids differ, by its number in the plan of
positions too); sheet 3's labels are the note's."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from drawings.sheets import dynamics as sheet3
from latex_templates.parts import dynamics as part
from reportgen.project import Project
from reportgen.scenes.numbering import diagram_label, diagram_labels
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", ["press", "shaper", "conveyor", "crank-slider", "class3"])
def test_same_angle_same_number(name):
    project = Project(load_task(ROOT / "examples" / name / "task.toml"))
    if project.dynamics is None:
        pytest.skip("no [dynamics]")
    c = part.content(project).context
    number = str(c["i"])
    rows = {r[0]: r[1] for r in c["rows"]}
    if number in rows:                         # named in the diagrams' grid: the table's angle
        assert rows[number] == pytest.approx(c["phi_i"], abs=1e-6)
    else:                                      # named in the kinematic grid: that grid's angle
        assert str(project.analysed) in number
        assert math.degrees(float(project.phi[project.analysed])) % 360 == pytest.approx(c["phi_i"])
    if number != str(project.analysed):
        assert "плана положений" in str(c["i_ref"])
    # sheet 3 labels its positions as the note's table
    assert sheet3.graph_labels(project) == [r for r in diagram_labels(project.dynamics)]
    assert [r[0] for r in c["rows"]] == diagram_labels(project.dynamics)[:-1]


def test_diagram_label_of_press():
    project = Project(load_task(ROOT / "examples" / "press" / "task.toml"))
    # seed 000's press: position 2 of the 8-position plan (φ1 = 85,23°) is position 3 of the 12-position diagrams
    assert diagram_label(project.dynamics, float(project.phi[2])) == "3"
    assert diagram_label(project.dynamics, float(project.phi[0])) == "0"
