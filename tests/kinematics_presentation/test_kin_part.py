"""Section 1 (structure and kinematics parts) rendered to LaTeX for every example: the plan
segments the text names are the ones the plans draw, every record re-evaluates."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from latex_templates import NoteBuilder
from latex_templates.compose import compose
from latex_templates.parts.kinematics import detail_position
from latex_templates.render import Strings
from reportgen.calc import evaluate_displayed
from reportgen.plans import build_plans
from reportgen.project import Project
from reportgen.taskfile import load_task

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module", params=["press", "shaper", "class3"])
def rendered(request, tmp_path_factory):
    project = Project(load_task(EXAMPLES / request.param / "task.toml"))
    sections, _ = compose(project, Strings("ru"), only=("linkage",))
    note = NoteBuilder(project.task.document)
    for s in sections:
        note.add_section(s.section)
    out = tmp_path_factory.mktemp(request.param)
    tex = note.render(out).read_text(encoding="utf-8")
    return project, note, tex


def _comma(x: float, d: int) -> str:
    return f"{x:.{d}f}".replace(".", "{,}")


def test_crank_vectors_on_the_plans(rendered):
    project, _, tex = rendered
    i = detail_position(project)
    v, a = build_plans(project.linkage, project.structure, project.kinematics, i)
    tip = project.linkage.drive_tip
    va = math.hypot(*project.kinematics.points[tip].vel[i])
    aa = math.hypot(*project.kinematics.points[tip].acc[i])
    assert f"p{tip.lower()} = {_comma(va / v.scale, 1)}" in tex
    assert rf"\pi {tip.lower()} = {_comma(aa / a.scale, 1)}" in tex


def test_records_re_evaluate_and_are_many(rendered):
    _, note, _ = rendered
    assert len(note.records) >= 8
    assert all(evaluate_displayed(r).ok for r in note.records)


def test_every_position_in_the_tables(rendered):
    project, _, tex = rendered
    for phi in project.kinematics.phi_deg:
        assert _comma(phi % 360.0, 2) in tex


def test_structural_formula_and_w(rendered):
    project, _, tex = rendered
    assert project.structure.formula in tex
    assert re.search(r"W\s*=", tex)
