"""Fixtures of the drawing tests: the demonstration sheet and its DXF."""
from __future__ import annotations

from pathlib import Path

import pytest

from demo_scene import build_demo_sheet
from drawings import Sheet


@pytest.fixture(scope="session")
def demo_sheet() -> Sheet:
    return build_demo_sheet()


@pytest.fixture(scope="session")
def demo_dxf(tmp_path_factory, demo_sheet) -> Path:
    path = tmp_path_factory.mktemp("demo") / "demo.dxf"
    demo_sheet.save(path)
    return path
