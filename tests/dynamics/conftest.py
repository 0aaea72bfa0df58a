"""Shared fixtures: the examples with a [dynamics] section, solved once per session."""
from __future__ import annotations

from pathlib import Path

import pytest

from reportgen.dynamics import solve_dynamics
from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[2]
DYNAMIC_EXAMPLES = ("press", "conveyor", "crank-slider", "shaper")


def project_of(name: str) -> Project:
    return Project(load_task(ROOT / "examples" / name / "task.toml"))


@pytest.fixture(scope="session")
def solved() -> dict:
    """{example: (project, DynamicsResult)}."""
    out = {}
    for name in DYNAMIC_EXAMPLES:
        p = project_of(name)
        out[name] = (p, solve_dynamics(p))
    return out
