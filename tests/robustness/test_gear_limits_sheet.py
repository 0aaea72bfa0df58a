"""Sheet 4 for gear pairs on the limits of their blocking contour: the ends of the interference
lines, where the active line a…b leaves N1…N2 (b beyond N2 drew the specific-sliding diagram's
line and letter 13 mm over the frame; a before N1 put «a» over the meshing view). Nothing over the
frame, and the sliding diagram's names clear of each other and of the other views."""
from __future__ import annotations

import pytest

from drawings.sheets import gears
from reportgen.gears.shifts import blocking_contour
from reportgen.project import Project
from reportgen.taskfile import loads_task

from .sheetcheck import outside_frame

_C = blocking_contour(13, 26, 9.0, n=81)
POINTS = [(float(line[i][0]), float(line[i][1])) for key in ("interference1", "interference2")
          for line in _C.curves[key] for i in (0, -1)]


@pytest.mark.parametrize("x1, x2", POINTS, ids=[f"x1={a:.3f},x2={b:.3f}" for a, b in POINTS])
def test_sheet_4_on_the_interference_limits(x1, x2):
    project = Project(loads_task(f"[gears]\nz1 = 13\nz2 = 26\nmodule = 9.0\nx1 = {x1!r}\nx2 = {x2!r}\n"))
    sheet = gears.draw(project, 1, 1)
    assert outside_frame(sheet) == []
    found = sheet.overlaps()
    assert not [o for o in found if "outside the frame" in (o.first, o.second)]
    # a, P, b of the sliding diagram: apart from each other and inside their own view
    names = ("sliding: «a»", "sliding: «P»", "sliding: «b»")
    assert not [o for o in found if o.first in names and (o.second in names or o.second.startswith("view "))]
