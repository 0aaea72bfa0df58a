"""Sheet 3 draws A_дв(φ) as the note defines it (ΔE = A_дв + A_с, A_дв = −A_с(2π)·φ/2π): the line
labelled «Адв» runs from the origin to the end of A_с with its sign changed, not to the end of A_с."""
from __future__ import annotations

import math
from pathlib import Path

import ezdxf
import pytest

from drawings.sheets import dynamics as sheet3
from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("name", ["press", "shaper", "conveyor"])
def test_drive_work_line_rises_as_in_the_note(name, tmp_path):
    project = Project(load_task(ROOT / "examples" / name / "task.toml"))
    sheet = sheet3.draw(project, 3, 4)
    path = tmp_path / "s3.dxf"
    sheet.save(path)
    g = project.dynamics.graphical
    assert g.drive_mm[-1] == pytest.approx(-g.a_mm[-1])
    tr = sheet.views["work"].transform
    o, end, mirror = tr((0.0, 0.0)), tr((float(g.x[-1]), float(g.drive_mm[-1]))), tr((float(g.x[-1]), float(g.a_mm[-1])))
    lines = [(tuple(e.dxf.start)[:2], tuple(e.dxf.end)[:2]) for e in ezdxf.readfile(path).modelspace().query("LINE")]

    def drawn(p, q):
        return any((math.dist(a, p) < 1e-6 and math.dist(b, q) < 1e-6) or (math.dist(a, q) < 1e-6 and math.dist(b, p) < 1e-6)
                   for a, b in lines)
    assert drawn(o, end)
    assert not drawn(o, mirror)
    # the note's A_дв rises over the cycle (its work is positive) and so does the sheet's line
    assert project.dynamics.work_drive[-1] > 0 and g.drive_mm[-1] > 0
