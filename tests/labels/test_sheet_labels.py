"""Labels on every sheet of every example, read back from the DXF: no two texts overlap, each label
is within LABEL_NEAR_MM of what it names (the sheet records it: Annotations.labels), and no other
point labelled in the same view is nearer to it than its own (issue 12: sheet 3's «5» and «7»)."""
from __future__ import annotations

import ezdxf
import pytest

from drawings.sheets import available_sheets
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task
from reportgen.tolerances import LABEL_NEAR_MM

from .conftest import EXAMPLES, ROOT, case
from .readback import check_sheet

_PROJECTS: dict[str, Project] = {}


def _project(name: str) -> Project:
    if name not in _PROJECTS:
        _PROJECTS[name] = Project(load_task(ROOT / "examples" / name / "task.toml"))
    return _PROJECTS[name]


def _sheet_cases():
    out = []
    for name in EXAMPLES:
        for stem, _ in available_sheets(_project(name)):
            out.append(case(name, stem))
    return out


@pytest.mark.slow
@pytest.mark.parametrize("example,stem", _sheet_cases())
def test_sheet_labels(example, stem, tmp_path):
    project = _project(example)
    todo = available_sheets(project)
    number, mod = next((i, m) for i, (s, m) in enumerate(todo, 1) if s == stem)
    sheet = draw_sheet(project, mod, number, len(todo))
    sheet.save(tmp_path / "s.dxf")
    found = check_sheet(ezdxf.readfile(tmp_path / "s.dxf"), sheet.annotations.labels, LABEL_NEAR_MM)
    assert not found, "\n".join(map(str, found))


def test_the_check_sees_a_misplaced_label(tmp_path):
    """A label moved away from its point, and a label on another label, are found."""
    from shapely.geometry import Point

    from drawings.primitives import LabelRecord
    from drawings.sheet import Sheet

    sheet = Sheet.a1(_project("press").task.document, title="t", code="c", number=1, count=1)
    c = sheet.canvas
    c.text_mm((100.0, 100.0), "A", 5.0, "center", names=Point(100.0, 90.0))        # 7.5 mm off: fine
    c.text_mm((200.0, 100.0), "B", 5.0, "center", names=Point(200.0, 80.0))        # 17.5 mm off
    c.text_mm((300.0, 100.0), "C", 5.0, "center", names=Point(300.0, 97.0))
    c.text_mm((300.0, 98.0), "D", 5.0, "center", names=Point(310.0, 97.0))        # over «C»
    sheet.save(tmp_path / "s.dxf")
    found = check_sheet(ezdxf.readfile(tmp_path / "s.dxf"), sheet.annotations.labels, LABEL_NEAR_MM)
    texts = {(f.what.split(" (")[0], f.first) for f in found}
    assert ("label far from what it names", "B") in texts
    assert ("texts overlap", "C") in texts
    assert not any(f.first == "A" for f in found)
    assert isinstance(sheet.annotations.labels[0], LabelRecord)
