"""The crane example as a task, and variants of it with a changed catalogue row."""
from __future__ import annotations

import dataclasses as dc
from pathlib import Path

from reportgen.taskfile import load_task

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "crane-hoist" / "task.toml"


def example_task():
    return load_task(EXAMPLE)


def example_crane():
    return example_task().crane


def with_hoist(crane, **changes):
    return dc.replace(crane, hoist=dc.replace(crane.hoist, **changes))


def with_trolley(crane, **changes):
    return dc.replace(crane, trolley=dc.replace(crane.trolley, **changes))


def example_text() -> str:
    return EXAMPLE.read_text(encoding="utf-8")
