"""NEEDS enforced: every part of the note and every sheet reads only the stages it declares (the
build passes a reportgen.project.Needs view); reading another stage fails."""
from __future__ import annotations

from pathlib import Path

import pytest

from latex_templates.compose import SECTIONS, part_module
from reportgen.project import STAGES, Needs, Project, UndeclaredStage
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]


def test_an_undeclared_stage_fails():
    project = Project(load_task(ROOT / "examples" / "crank-slider" / "task.toml"))
    view = Needs(project, ("structure",), "part probe")
    assert view.structure is project.structure
    assert view.task is project.task                  # not a stage: always readable
    with pytest.raises(UndeclaredStage) as exc:
        _ = view.kinematics
    assert exc.value.stage == "kinematics" and "part probe" in str(exc.value)
    with pytest.raises(ValueError):
        Needs(project, ("no-such-stage",), "part probe")


def test_every_declared_need_is_a_stage():
    from drawings.sheets import sheet_module
    from drawings.sheets import SHEETS
    for _, parts in SECTIONS:
        for name in parts:
            mod = part_module(name)
            if mod is not None:
                assert set(mod.NEEDS) <= STAGES, name
    for name in SHEETS:
        mod = sheet_module(name)
        assert set(mod.NEEDS) <= STAGES, name


@pytest.mark.parametrize("example", ["press", "shaper", "conveyor", "crank-slider", "class3"])
def test_parts_read_only_what_they_declare(example):
    project = Project(load_task(ROOT / "examples" / example / "task.toml"))
    for _, parts in SECTIONS:
        for name in parts:
            mod = part_module(name)
            if mod is None or not mod.available(project):
                continue
            mod.content(Needs(project, mod.NEEDS, f"part {name}"))      # raises UndeclaredStage otherwise
