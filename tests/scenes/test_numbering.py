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


@pytest.mark.parametrize("lang", ["ru", "uk", "en"])
def test_note_and_sheet_translate_the_diagrams_names_alike(lang):
    """One helper names the diagrams' positions in the note's table and on sheet 3: every catalogue
    key it asks for exists, and the names are the catalogue's words in the order of diagram_labels."""
    from latex_templates.render import Strings
    from reportgen.scenes.numbering import CORNER_KEY, LABEL_KEYS, translated_diagram_labels

    strings = Strings(lang)
    for key in (*LABEL_KEYS.values(), CORNER_KEY):
        assert strings.has(key), (lang, key)
    project = Project(load_task(ROOT / "examples" / "press" / "task.toml"))
    raw = diagram_labels(project.dynamics)
    seen = []
    named = translated_diagram_labels(project.dynamics, lambda key, **kw: seen.append((key, kw)) or f"<{key}>")
    assert len(named) == len(raw)
    for r, n in zip(raw, named):
        if r in LABEL_KEYS:
            assert n == f"<{LABEL_KEYS[r]}>"
        elif r.startswith("и"):
            assert n == f"<{CORNER_KEY}>"
        else:
            assert n == r
    assert any(r in LABEL_KEYS for r in raw)           # the press has its switching angles named
