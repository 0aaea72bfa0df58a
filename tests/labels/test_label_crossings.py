"""No label's letters are crossed by a drawn line (issue 12: on main the press's and the shaper's
Zhukovsky lever had «Fур» and «FMи4(D)» crossed by the images of links and by other forces): on
sheet 1's plans, on sheet 2 (the lever, the groups' and the crank's free-body views, the force
polygons) and on the control work's sheet, read back from the DXF; in the note's figures of the same
scenes, read back from matplotlib — for every example and for a crank–rocker (tests/data). A
name on a leader is tied to its vector by the leader; the leader itself crosses no label either."""
from __future__ import annotations

import ezdxf
import pytest

from drawings.sheets import available_sheets
from reportgen.commands.pipeline import draw_sheet
from reportgen.project import Project
from reportgen.taskfile import load_task

from .conftest import EXAMPLES, ROOT
from .notefigs import note_figures
from .readback import VECTOR_VIEWS, check_figure_crossings, check_sheet_crossings
from .test_note_labels import VECTOR_FIGURES

CRANK_ROCKER = ROOT / "tests" / "data" / "crank-rocker.toml"
TASKS = {**{name: ROOT / "examples" / name / "task.toml" for name in EXAMPLES}, "crank-rocker": CRANK_ROCKER}

#: Crossed labels still open, by (task, sheet stem or «note»): why. Each must still fail (strict).
OPEN: dict[tuple[str, str], str] = {}

_PROJECTS: dict[str, Project] = {}


def _project(name: str) -> Project:
    if name not in _PROJECTS:
        _PROJECTS.clear()
        _PROJECTS[name] = Project(load_task(TASKS[name]))
    return _PROJECTS[name]


def _param(name: str, what: str):
    reason = OPEN.get((name, what))
    return pytest.param(name, what, id=f"{name}-{what}",
                        marks=[pytest.mark.xfail(strict=True, reason=reason)] if reason else [])


def _sheet_cases():
    out = []
    for name in TASKS:
        for stem, mod in available_sheets(Project(load_task(TASKS[name]))):
            if getattr(mod, "NEEDS", None) and ("kinetostatics" in mod.NEEDS or "plans" in mod.NEEDS):
                out.append(_param(name, stem))
    return out


@pytest.mark.slow
@pytest.mark.parametrize("name,stem", _sheet_cases())
def test_no_label_on_a_sheet_is_crossed(name, stem, tmp_path):
    project = _project(name)
    todo = available_sheets(project)
    number, mod = next((i, m) for i, (s, m) in enumerate(todo, 1) if s == stem)
    sheet = draw_sheet(project, mod, number, len(todo))
    sheet.save(tmp_path / "s.dxf")
    found = check_sheet_crossings(ezdxf.readfile(tmp_path / "s.dxf"), sheet.annotations.labels, VECTOR_VIEWS)
    assert not found, "\n".join(map(str, found))


@pytest.mark.slow
@pytest.mark.parametrize("name,what", [_param(name, "note") for name in TASKS if name != "crane-hoist"])
def test_no_label_of_a_note_figure_is_crossed(name, what):
    import matplotlib.pyplot as plt
    figs = note_figures(_project(name))
    try:
        found = [f"{k}: {x}" for k, fig in sorted(figs.items()) if any(v in k for v in VECTOR_FIGURES)
                 for x in check_figure_crossings(fig)]
    finally:
        for f in figs.values():
            plt.close(f)
    assert not found, "\n".join(found)


def test_the_check_sees_a_crossed_label(tmp_path):
    """A name with another vector through it is found; one beside its own vector, and one on a
    leader that touches it, are not."""
    from shapely.geometry import LineString

    from drawings.sheet import Sheet

    sheet = Sheet.a1(_project("press").task.document, title="t", code="c", number=1, count=1)
    view = sheet.add_view("lever", 200.0, 100.0)
    x, y = view.rect.x0, view.rect.y0
    view.text_mm((x + 50.0, y + 50.0), "Fур", 3.5, "center", names=LineString([(x + 40, y + 45), (x + 60, y + 45)]))
    view.layout.add_line((x + 40, y + 45), (x + 60, y + 45))                       # its own, beside it
    view.layout.add_line((x + 45, y + 40), (x + 55, y + 60))                       # another, through it
    view.text_mm((x + 100.0, y + 50.0), "G2", 3.5, "center", names=LineString([(x + 90, y + 45), (x + 110, y + 45)]))
    view.layout.add_line((x + 90, y + 45), (x + 110, y + 45))
    view.layout.add_line((x + 100, y + 45), (x + 100, y + 48.0))                  # a leader up to its letters
    sheet.save(tmp_path / "s.dxf")
    found = check_sheet_crossings(ezdxf.readfile(tmp_path / "s.dxf"), sheet.annotations.labels, ("lever",))
    assert [f.first for f in found] == ["lever: Fур"], found
