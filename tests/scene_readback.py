"""Reading a sheet back for the «one construction drawn twice» tests (tests/scenes, tests/sheet1):
a note part's content and the same sheet drawn from one project, and the lengths drawn on the DXF."""
from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import ezdxf
import numpy as np

from reportgen.project import Project
from reportgen.taskfile import load_task

ROOT = Path(__file__).resolve().parents[1]


# Drawing a sheet costs seconds of CPU; the tests that read the same example's sheet back (tests/scenes,
# tests/sheet1) share one drawing per test process, so that `make check` stays within a minute. The
# objects are only read by those tests (a Project's stages are immutable, a drawn sheet is saved and
# read back, never edited).
_PROJECTS: dict[str, Project] = {}
_CONTENTS: dict[tuple[str, str], Any] = {}
_SHEETS: dict[tuple[str, str, int], tuple[Any, Any]] = {}


def example_project(example: str) -> Project:
    """The project of ``examples/<example>/task.toml``, loaded once per test process."""
    if example not in _PROJECTS:
        _PROJECTS[example] = Project(load_task(ROOT / "examples" / example / "task.toml"))
    return _PROJECTS[example]


def drawn_sheet(example: str, sheet: Any, number: int, folder: Path) -> tuple[Any, Any]:
    """(the drawn sheet, its DXF read back) of an example's sheet ``number`` of 4, drawn once per test
    process (saved into ``folder`` the first time)."""
    key = (example, sheet.__name__, number)
    if key not in _SHEETS:
        drawn = sheet.draw(example_project(example), number, 4)
        path = folder / f"sheet{number}.dxf"
        drawn.save(path)
        _SHEETS[key] = (drawn, ezdxf.readfile(path))
    return _SHEETS[key]


def part_and_sheet(example: str, part: Any, sheet: Any, number: int, folder: Path) -> tuple[Project, Any, Any]:
    """(project, the part's content, the sheet's DXF read back) of an example: both from one project."""
    project = example_project(example)
    key = (example, part.__name__)
    if key not in _CONTENTS:
        _CONTENTS[key] = part.content(project)
    return project, _CONTENTS[key], drawn_sheet(example, sheet, number, folder)[1]


def polyline_length(points) -> float:
    """The length along a polyline's points (mm)."""
    return sum(math.dist(p, q) for p, q in zip(points[:-1], points[1:]))


def dxf_vectors(doc) -> list[float]:
    """Lengths of the arrows on the sheet (:func:`dxf_arrows`): tail to the tip of its head; every
    head ahead on the line counts (collinear arrows)."""
    return [float(np.hypot(*(t - a))) for a, t in dxf_arrows(doc)]


def dxf_arrows(doc) -> list[tuple[np.ndarray, np.ndarray]]:
    """The arrows on the sheet as (tail, tip) in sheet mm: a LINE on layer «vectors» and the SOLID
    head whose tip continues it (:meth:`drawings.primitives.Canvas.arrow`)."""
    msp = doc.modelspace()
    tips = [np.array(e.dxf.vtx0)[:2] for e in msp.query("SOLID[layer=='vectors']")]
    out = []
    for ln in msp.query("LINE[layer=='vectors']"):
        a, b = np.array(ln.dxf.start)[:2], np.array(ln.dxf.end)[:2]
        u = (b - a) / (np.hypot(*(b - a)) or 1.0)
        for t in tips:
            ahead = float(np.dot(t - b, u))
            if 0 < ahead < 5.0 and float(np.hypot(*(t - b - u * ahead))) < 1e-6:
                out.append((a, t))
    return out


def common_shift(pairs: list[tuple[np.ndarray, np.ndarray]], drawn: list[tuple[np.ndarray, np.ndarray]],
                 tol: float = 0.01) -> np.ndarray | None:
    """The one translation (sheet mm) that puts every (tail, tip) of ``pairs`` (a scene's arrows,
    scene mm) onto an arrow of ``drawn`` (the sheet's), or None: the same arrows at the same places
    relative to each other."""
    if not pairs:
        return None
    a0, b0 = max(pairs, key=lambda p: float(np.hypot(*(p[1] - p[0]))))
    for ta, tb in drawn:
        t = ta - a0
        if float(np.hypot(*(tb - b0 - t))) > tol:
            continue
        if all(any(float(np.hypot(*(da - a - t))) < tol and float(np.hypot(*(db - b - t))) < tol
                   for da, db in drawn) for a, b in pairs):
            return t
    return None


def assert_marks_clear(boxes, room, teeth) -> None:
    """The meshing picture's designations (``boxes``: (name, shapely box)) lie inside ``room``,
    across no tooth's outline — off every tooth of ``teeth`` but for the names that may stand
    inside one (:data:`reportgen.scenes.meshing_marks.INSIDE_TEETH`) — and off each other (sheet
    4's scene, the note's window of it)."""
    from reportgen.scenes.meshing_marks import INSIDE_TEETH
    for i, (n1, b1) in enumerate(boxes):
        assert room.contains(b1), n1
        assert not any(b1.intersects(t.exterior) for t in teeth), f"{n1} across a tooth's outline"
        if n1 not in INSIDE_TEETH:
            assert not any(b1.intersects(t) for t in teeth), f"{n1} over a tooth"
        for n2, b2 in boxes[i + 1:]:
            assert b1.intersection(b2).area < 1e-9, f"{n1} overlaps {n2}"


def sheet_cases(examples, wanted) -> list:
    """pytest params (example, sheet stem) of the examples' sheets whose stem ``wanted(stem)`` takes."""
    import pytest

    from drawings.sheets import available_sheets
    return [pytest.param(name, stem, id=f"{name}-{stem}") for name in examples
            for stem, _ in available_sheets(example_project(name)) if wanted(stem)]


def draw_named_sheet(example: str, stem: str, folder: Path) -> tuple[Any, Any]:
    """(the drawn sheet, its DXF read back) of the example's sheet called ``stem``, drawn as a build
    draws it (its number among the example's sheets)."""
    from drawings.sheets import available_sheets
    from reportgen.commands.pipeline import draw_sheet
    todo = available_sheets(example_project(example))
    number, mod = next((i, m) for i, (s, m) in enumerate(todo, 1) if s == stem)
    sheet = draw_sheet(example_project(example), mod, number, len(todo))
    sheet.save(folder / "s.dxf")
    return sheet, ezdxf.readfile(folder / "s.dxf")
